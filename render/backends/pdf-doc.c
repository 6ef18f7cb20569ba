/*
** The PDF writer's document (render/backends/backend.h): the pages
** written by backend-pdfw.c as one PDF 1.5 file, its objects in a fixed
** order, each "N 0 obj", a classic xref table of 20-byte entries:
**   1 the catalog: /Pages, /StructTreeRoot, /MarkInfo << /Marked true
**     >>, /Lang (the page's language, when said), /ViewerPreferences
**     << /DisplayDocTitle true >>;
**   2 the page tree; 3 the structure tree's root (its /ParentTree maps
**   each page's marked content to the Figure); 4 its Document element;
**   5 the Figure, /Alt the alt text and the description (UTF-16BE), its
**   kids the marked content of every page (MCID 0 of each);
**   6 the document info: /Title, /Subject (UTF-16BE), /CreationDate and
**   /ModDate, /Producer;
**   7 the resources every page shares: the opacities' ExtGStates and the
**   meshes' shadings;
**   then each page (a transparency group when it paints translucently)
**   and its content stream, then each shading, then the fonts.
** Streams are compressed (Flate, level 3, a window and hash table sized
** for small streams: the same bytes for the same input), but for those
** under 512 bytes and the font programs under 4 KiB (PLAIN_BELOW,
** PROGRAM_PLAIN_BELOW).  The trailer's /ID is a hash of the file before
** it, so that two renders of a figure are the same bytes.
*/
#include <stdio.h>
#include <string.h>

#include <zlib.h>

#include "backend.h"
#include "buffer.h"
#include "decimals.h"
#include "pdf-fonts.h"
#include "pdf-strings.h"

#define FIXED_OBJECTS 7

static int
put(cf__buf_t *b, const char *s)
{
    return cf__buf_append(b, s, strlen(s));
}

static int
putf_num(cf__buf_t *b, double v)
{
    char t[48];
    size_t n = cf__decimals(t, v, 3);
    return cf__buf_append(b, t, n);
}

static voidpf
zalloc(voidpf opaque, uInt items, uInt size)
{
    (void)opaque;
    return cf_alloc_array(items, size);
}

static void
zfree(voidpf opaque, voidpf ptr)
{
    (void)opaque;
    cf_free(ptr);
}

/* data compressed into z (empty); 0, or -1 out of memory. */
static int
deflate_buf(const cf__buf_t *data, cf__buf_t *z)
{
    z_stream s;
    uLong bound;
    int r;
    memset(&s, 0, sizeof s);
    s.zalloc = zalloc;
    s.zfree = zfree;
    int bits = 9;
    /* a window no larger than the data, and a hash table of 2^13
    ** entries (memLevel 6: zlib clears it for every stream; measured on
    ** markova-2.17, 4 % fewer instructions in the writer than memLevel 8,
    ** the same bytes within 0.1 %); level 3, zlib's fast matcher: 2.4 %
    ** fewer instructions for the whole render of markova-2.17 than level
    ** 6, for 1.0 % more bytes over the figures' PDFs */
    while (bits < 15 && ((size_t)1 << bits) < data->size)
        bits++;
    if (deflateInit2(&s, 3, Z_DEFLATED, bits, 6,
                     Z_DEFAULT_STRATEGY) != Z_OK)
        return -1;
    bound = deflateBound(&s, (uLong)data->size);
    z->data = cf_malloc(bound);
    if (z->data == NULL) {
        deflateEnd(&s);
        return -1;
    }
    z->cap = bound;
    s.next_in = data->data;
    s.avail_in = (uInt)data->size;
    s.next_out = z->data;
    s.avail_out = (uInt)bound;
    r = deflate(&s, Z_FINISH);
    z->size = s.total_out;
    deflateEnd(&s);
    return r == Z_STREAM_END ? 0 : -1;
}

typedef struct doc {
    cf__buf_t *out;
    size_t *offsets;     /* offsets[k]: object k+1 */
    size_t nobjects;
} doc_t;

/* "N 0 obj\n" of object n (1 and up), its offset noted. */
static int
begin_obj(doc_t *d, size_t n)
{
    char b[40];
    d->offsets[n - 1] = d->out->size;
    snprintf(b, sizeof b, "%zu 0 obj\n", n);
    return put(d->out, b);
}

/* Streams shorter than this are written as they are: deflate's fixed
** cost (its hash table cleared, three Huffman trees built for the block)
** is some 100,000 instructions a stream, for a few dozen bytes saved on
** a ToUnicode map of a few glyphs (markova-2.17: 342 and 436 bytes,
** deflated to 266 and 306; 1.8 % of the render's instructions, for
** 2.1 % more bytes over the figures' PDFs). */
#define PLAIN_BELOW 512
/* The same for a font's program below this: a subset's CFF of a label's
** glyphs (Type 2 charstrings, already compact) deflates by some 12 %
** (the 335 font programs of the figures' PDFs: 438,610 bytes, 385,583
** deflated), a few dozen bytes, for deflate's fixed cost each (a
** seventh of orazem-decasteljau's PDF for its three faces); larger
** programs (a page of Chinese, TrueType) are deflated. */
#define PROGRAM_PLAIN_BELOW 4096

/* A stream object n: dict (its entries but /Length and /Filter) and the
** data, deflated unless it is short (plain_below). */
static int
stream_obj(doc_t *d, size_t n, const char *dict, const cf__buf_t *data,
           size_t plain_below)
{
    cf__buf_t z;
    const cf__buf_t *body = data;
    char b[64];
    int r;
    memset(&z, 0, sizeof z);
    if (data->size >= plain_below) {
        if (deflate_buf(data, &z) != 0) {
            cf__buf_free(&z);
            return -1;
        }
        body = &z;
    }
    snprintf(b, sizeof b, "%s /Length %zu >>\nstream\n",
             body == &z ? " /Filter /FlateDecode" : "", body->size);
    r = begin_obj(d, n) || put(d->out, "<< ") || put(d->out, dict)
        || put(d->out, b) || cf__buf_append(d->out, body->data, body->size)
        || put(d->out, "\nendstream\nendobj\n");
    cf__buf_free(&z);
    return r ? -1 : 0;
}

static int
ref(cf__buf_t *b, size_t n)
{
    char t[32];
    snprintf(t, sizeof t, "%zu 0 R ", n);
    return put(b, t);
}

static size_t
page_obj(size_t i)
{
    return FIXED_OBJECTS + 1 + 2 * i;
}

static int
catalog(doc_t *d, const cf__pdfw_t *w)
{
    int r = begin_obj(d, 1)
            || put(d->out, "<< /Type /Catalog /Pages 2 0 R "
                           "/StructTreeRoot 3 0 R\n"
                           "   /MarkInfo << /Marked true >>\n");
    if (w->lang != NULL)
        r = r || put(d->out, "   /Lang ")
            || cf__pdf_put_string(d->out, w->lang) || put(d->out, "\n");
    return r || put(d->out, "   /ViewerPreferences << /DisplayDocTitle "
                            "true >> >>\nendobj\n");
}

static int
page_tree(doc_t *d, const cf__pdfw_t *w)
{
    char b[64];
    int r = begin_obj(d, 2) || put(d->out, "<< /Type /Pages /Kids [ ");
    for (size_t i = 0; i < w->npages && !r; i++)
        r = ref(d->out, page_obj(i));
    snprintf(b, sizeof b, "] /Count %zu >>\nendobj\n", w->npages);
    return r || put(d->out, b);
}

/* The structure tree: root, Document, Figure. */
static int
structure(doc_t *d, const cf__pdfw_t *w, const char *title,
          const char *caption)
{
    char b[96];
    int r = begin_obj(d, 3)
            || put(d->out, "<< /Type /StructTreeRoot /K [ 4 0 R ]\n"
                           "   /ParentTree << /Nums [ ");
    for (size_t i = 0; i < w->npages && !r; i++) {
        snprintf(b, sizeof b, "%zu [ 5 0 R ] ", i);
        r = put(d->out, b);
    }
    snprintf(b, sizeof b, "] >> /ParentTreeNextKey %zu >>\nendobj\n",
             w->npages);
    r = r || put(d->out, b)
        || begin_obj(d, 4)
        || put(d->out, "<< /Type /StructElem /S /Document /P 3 0 R "
                       "/K 5 0 R >>\nendobj\n")
        || begin_obj(d, 5)
        || put(d->out, "<< /Type /StructElem /S /Figure /P 4 0 R\n");
    if (title != NULL)
        r = r || put(d->out, "   /Alt ")
            || cf__pdf_put_text(d->out, title, caption)
            || put(d->out, "\n");
    r = r || put(d->out, "   /K [ ");
    for (size_t i = 0; i < w->npages && !r; i++) {
        snprintf(b, sizeof b, "<< /Type /MCR /Pg %zu 0 R /MCID 0 >> ",
                 page_obj(i));
        r = put(d->out, b);
    }
    return r || put(d->out, "] >>\nendobj\n");
}

/* "D:YYYYMMDDHHMMSSZ" of "YYYY-MM-DDTHH:MM:SSZ". */
static int
date_entry(cf__buf_t *out, const char *key, const char *date)
{
    char b[32];
    size_t k = 0;
    for (const char *s = date; *s != '\0' && k < 14; s++)
        if (*s >= '0' && *s <= '9')
            b[k++] = *s;
    b[k] = '\0';
    return put(out, key) || put(out, " (D:") || put(out, b)
           || put(out, "Z)\n");
}

static int
info(doc_t *d, const char *title, const char *caption, const char *date)
{
    int r = begin_obj(d, 6) || put(d->out, "<< /Producer (curvefig)\n");
    if (title != NULL)
        r = r || put(d->out, "   /Title ")
            || cf__pdf_put_text(d->out, title, NULL) || put(d->out, "\n");
    if (caption != NULL)
        r = r || put(d->out, "   /Subject ")
            || cf__pdf_put_text(d->out, caption, NULL) || put(d->out, "\n");
    return r || date_entry(d->out, "   /CreationDate", date)
           || date_entry(d->out, "   /ModDate", date)
           || put(d->out, ">>\nendobj\n");
}

static int
resources(doc_t *d, const cf__pdfw_t *w, size_t first_shading,
          size_t first_font)
{
    char b[64];
    int r = begin_obj(d, 7) || put(d->out, "<< /ExtGState << ");
    for (size_t i = 0; i < w->nalphas && !r; i++) {
        char a[48];
        cf__decimals(a, w->alphas[i], 4);
        snprintf(b, sizeof b, "/a%zu << /ca ", i);
        r = put(d->out, b) || put(d->out, a);
        snprintf(b, sizeof b, " >> /A%zu << /CA ", i);
        r = r || put(d->out, b) || put(d->out, a) || put(d->out, " >> ");
    }
    r = r || put(d->out, ">>\n   /Shading << ");
    for (size_t i = 0; i < w->nshadings && !r; i++) {
        snprintf(b, sizeof b, "/Sh%zu ", i);
        r = put(d->out, b) || ref(d->out, first_shading + i);
    }
    return r || put(d->out, ">>\n")
           || cf__pdfw_fonts_resources(w, first_font, d->out)
           || put(d->out, ">>\nendobj\n");
}

static int
page(doc_t *d, const cf__pdfw_t *w, size_t i)
{
    char b[160];
    int r = begin_obj(d, page_obj(i))
            || put(d->out, "<< /Type /Page /Parent 2 0 R /MediaBox [ 0 0 ")
            || putf_num(d->out, w->width) || put(d->out, " ")
            || putf_num(d->out, w->height);
    snprintf(b, sizeof b, " ]\n   /Resources 7 0 R /Contents %zu 0 R "
                          "/StructParents %zu", page_obj(i) + 1, i);
    r = r || put(d->out, b);
    /* a page that paints translucently composites in RGB (the group
    ** cairo gave every page; pdfTeX warns of two on one page) */
    if (w->pages[i].translucent)
        r = r || put(d->out, "\n   /Group << /Type /Group /S /Transparency "
                             "/CS /DeviceRGB >>");
    return r || put(d->out, " >>\nendobj\n")
           || stream_obj(d, page_obj(i) + 1, "", &w->pages[i].content,
                         PLAIN_BELOW);
}

static int
shading(doc_t *d, const struct cf__pdfw_shading *s, size_t n)
{
    cf__buf_t dict;
    int r;
    memset(&dict, 0, sizeof dict);
    r = put(&dict, "/ShadingType 4 /ColorSpace /DeviceRGB "
                   "/BitsPerCoordinate 32 /BitsPerComponent 16 "
                   "/BitsPerFlag 8\n   /Decode [ ");
    for (int k = 0; k < 4 && !r; k++)
        r = putf_num(&dict, s->box[k == 1 ? 2 : k == 2 ? 1 : k])
            || put(&dict, " ");
    r = r || put(&dict, "0 1 0 1 0 1 ]") || cf__buf_append(&dict, "", 1);
    r = r || dict.failed || stream_obj(d, n, (const char *)dict.data,
                                       &s->data, PLAIN_BELOW);
    cf__buf_free(&dict);
    return r ? -1 : 0;
}

/* 64-bit FNV-1a of data from seed. */
static unsigned long long
fnv(const unsigned char *p, size_t n, unsigned long long h)
{
    for (size_t i = 0; i < n; i++)
        h = (h ^ p[i]) * 0x100000001b3ull;
    return h;
}

static int
trailer(doc_t *d)
{
    char b[256];
    size_t xref = d->out->size;
    unsigned long long h1, h2;
    int r;
    snprintf(b, sizeof b, "xref\n0 %zu\n0000000000 65535 f \n",
             d->nobjects + 1);
    r = put(d->out, b);
    for (size_t i = 0; i < d->nobjects && !r; i++) {
        snprintf(b, sizeof b, "%010zu 00000 n \n", d->offsets[i]);
        r = put(d->out, b);
    }
    if (r || d->out->failed)
        return -1;
    h1 = fnv(d->out->data, d->out->size, 0xcbf29ce484222325ull);
    h2 = fnv(d->out->data, d->out->size, h1 ^ 0x9e3779b97f4a7c15ull);
    snprintf(b, sizeof b, "trailer\n<< /Size %zu /Root 1 0 R /Info 6 0 R\n"
             "   /ID [ <%016llx%016llx> <%016llx%016llx> ] >>\n"
             "startxref\n%zu\n%%%%EOF\n", d->nobjects + 1, h1, h2, h1, h2,
             xref);
    return put(d->out, b);
}

static int
objs_begin(void *d, size_t n)
{
    return begin_obj(d, n);
}

static int
objs_stream(void *d, size_t n, const char *dict, const cf__buf_t *data,
            bool program)
{
    return stream_obj(d, n, dict, data,
                      program ? PROGRAM_PLAIN_BELOW : PLAIN_BELOW);
}

int
cf__pdfw_document(cf__pdfw_t *w, const char *title, const char *caption,
                  const char *date, cf__buf_t *out)
{
    doc_t d;
    cf__pdfw_objs_t o;
    size_t first_shading = page_obj(w->npages);
    size_t first_font = first_shading + w->nshadings;
    int r = cf__pdfw_fonts_subset(w);
    if (r != 0)
        return r;
    d.out = out;
    d.nobjects = first_font - 1 + cf__pdfw_fonts_objects(w);
    o.out = out;
    o.begin_obj = objs_begin;
    o.stream = objs_stream;
    o.ctx = &d;
    d.offsets = cf_alloc_array(d.nobjects, sizeof *d.offsets);
    if (d.offsets == NULL)
        return -1;
    r = put(out, "%PDF-1.5\n%\xe2\xe3\xcf\xd3\n")
        || catalog(&d, w) || page_tree(&d, w)
        || structure(&d, w, title, caption)
        || info(&d, title, caption, date)
        || resources(&d, w, first_shading, first_font);
    for (size_t i = 0; i < w->npages && !r; i++)
        r = page(&d, w, i);
    for (size_t i = 0; i < w->nshadings && !r; i++)
        r = shading(&d, &w->shadings[i], first_shading + i);
    r = r || cf__pdfw_fonts_write(w, first_font, &o) || trailer(&d);
    cf_free(d.offsets);
    if (r || out->failed) {
        cf__buf_free(out);
        return -1;
    }
    return 0;
}

/* Everything but the fonts. */
static void
free_pages(cf__pdfw_t *w)
{
    for (size_t i = 0; i < w->npages; i++)
        cf__buf_free(&w->pages[i].content);
    cf_free(w->pages);
    for (size_t i = 0; i < w->nshadings; i++)
        cf__buf_free(&w->shadings[i].data);
    cf_free(w->shadings);
    cf_free(w->alphas);
    cf__buf_free(&w->content);
    w->pages = NULL;
    w->shadings = NULL;
    w->alphas = NULL;
    w->npages = w->nshadings = w->nalphas = 0;
    w->pages_cap = w->shadings_cap = w->alphas_cap = 0;
}

void
cf__pdfw_fini(cf__pdfw_t *w)
{
    free_pages(w);
    cf__pdfw_fonts_free(w, false);
}

void
cf__pdfw_restart(cf__pdfw_t *w)
{
    free_pages(w);
    cf__pdfw_fonts_free(w, true);
    memset(&w->sc, 0, sizeof w->sc);
}
