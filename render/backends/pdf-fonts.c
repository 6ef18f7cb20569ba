/*
** The fonts of the PDF writer's document (render/backends/pdf-fonts.h).
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fontfile.h"
#include "grow.h"
#include "pdf-fonts.h"
#include "pdf-strings.h"

/* The text a glyph stands for (the first cluster it began). */
typedef struct unicode {
    unsigned gid;
    size_t off, len;     /* in the font's text */
} unicode_t;

struct cf__pdfw_font {
    const char *file;
    unsigned index;
    const char *psname;      /* the face's PostScript name, or NULL */
    bool refused;
    unsigned *gids;          /* used, in order of first use */
    size_t ngids, gids_cap;
    unicode_t *uni;          /* sorted by gid at subset */
    size_t nuni, uni_cap;
    cf__buf_t text;
    cf__fontfile_subset_t sub;
    bool subset;             /* sub is filled */
    char tag[8];
};

int
cf__pdfw_font_use(cf__pdfw_t *w, const cf__pdfw_glyph_t *g)
{
    struct cf__pdfw_font *f = NULL;
    size_t i;
    for (i = 0; i < w->nfonts; i++)
        if (w->fonts[i].index == g->index
            && strcmp(w->fonts[i].file, g->file) == 0) {
            f = &w->fonts[i];
            break;
        }
    if (f == NULL) {
        f = cf__grow_array(w->fonts, &w->fonts_cap, w->nfonts + 1,
                           sizeof *f, 4);
        if (f == NULL)
            return -1;
        w->fonts = f;
        f += w->nfonts++;
        memset(f, 0, sizeof *f);
        f->file = g->file;
        f->index = g->index;
        f->psname = g->psname;
        if (w->probe) {
            char why[160];
            int r = cf__fontfile_subset(f->file, f->index, &g->gid, 1,
                                        &f->sub, why, sizeof why);
            cf__fontfile_subset_fini(&f->sub);
            if (r < 0)
                return -1;
            f->refused = r == 1;
        }
    }
    if (f->refused)
        return -2;
    for (i = 0; i < f->ngids && f->gids[i] != g->gid; i++)
        ;
    if (i == f->ngids) {
        unsigned *u = cf__grow_array(f->gids, &f->gids_cap, f->ngids + 1,
                                     sizeof *u, 64);
        if (u == NULL)
            return -1;
        f->gids = u;
        u[f->ngids++] = g->gid;
        if (g->len > 0) {
            unicode_t *n = cf__grow_array(f->uni, &f->uni_cap, f->nuni + 1,
                                          sizeof *n, 64);
            if (n == NULL)
                return -1;
            f->uni = n;
            n[f->nuni].gid = g->gid;
            n[f->nuni].off = f->text.size;
            n[f->nuni].len = g->len;
            f->nuni++;
            if (cf__buf_append(&f->text, g->text, g->len) != 0)
                return -1;
        }
    }
    return (int)(f - w->fonts);
}

static int
by_gid(const void *a, const void *b)
{
    unsigned x = ((const unicode_t *)a)->gid, y = ((const unicode_t *)b)->gid;
    return (x > y) - (x < y);
}

static int
by_value(const void *a, const void *b)
{
    unsigned x = *(const unsigned *)a, y = *(const unsigned *)b;
    return (x > y) - (x < y);
}

/* The face's PostScript name for the subset's (a face of a collection:
** its own, where the program's is the collection's), when fontconfig
** has one, only the characters a PDF name holds unescaped. */
static void
face_name(struct cf__pdfw_font *f)
{
    size_t k = 0;
    if (f->psname == NULL)
        return;
    for (const char *s = f->psname; *s != '\0' && k + 1 < sizeof
         f->sub.ps_name; s++)
        if ((*s >= 'A' && *s <= 'Z') || (*s >= 'a' && *s <= 'z')
            || (*s >= '0' && *s <= '9') || *s == '-' || *s == '_'
            || *s == '.')
            f->sub.ps_name[k++] = *s;
    if (k > 0)
        f->sub.ps_name[k] = '\0';
}

/* Six capital letters from the font's name and glyphs (FNV-1a). */
static void
make_tag(struct cf__pdfw_font *f)
{
    unsigned long long h = 0xcbf29ce484222325ull;
    for (const char *s = f->sub.ps_name; *s != '\0'; s++)
        h = (h ^ (unsigned char)*s) * 0x100000001b3ull;
    for (size_t i = 0; i < f->ngids; i++)
        for (int k = 0; k < 4; k++)
            h = (h ^ ((f->gids[i] >> (8 * k)) & 0xffu)) * 0x100000001b3ull;
    for (int k = 0; k < 6; k++) {
        f->tag[k] = (char)('A' + h % 26);
        h /= 26;
    }
    f->tag[6] = '\0';
}

int
cf__pdfw_fonts_subset(cf__pdfw_t *w)
{
    int refused = 0;
    for (size_t i = 0; i < w->nfonts; i++) {
        struct cf__pdfw_font *f = &w->fonts[i];
        char why[160];
        int r;
        if (f->refused || f->ngids == 0 || f->subset)
            continue;
        qsort(f->gids, f->ngids, sizeof *f->gids, by_value);
        if (f->nuni > 0)
            qsort(f->uni, f->nuni, sizeof *f->uni, by_gid);
        r = cf__fontfile_subset(f->file, f->index, f->gids, f->ngids,
                                &f->sub, why, sizeof why);
        if (r < 0)
            return -1;
        if (r == 1) {
            f->refused = true;
            refused = 1;
            continue;
        }
        f->subset = true;
        face_name(f);
        make_tag(f);
    }
    return refused;
}

static bool
used(const struct cf__pdfw_font *f)
{
    return f->subset && !f->refused;
}

size_t
cf__pdfw_fonts_objects(const cf__pdfw_t *w)
{
    size_t n = 0;
    for (size_t i = 0; i < w->nfonts; i++)
        n += used(&w->fonts[i]) ? 5 : 0;
    return n;
}

static int
put(cf__buf_t *b, const char *s)
{
    return cf__buf_append(b, s, strlen(s));
}

int
cf__pdfw_fonts_resources(const cf__pdfw_t *w, size_t first, cf__buf_t *out)
{
    char b[64];
    int r = put(out, "   /Font << ");
    for (size_t i = 0; i < w->nfonts && !r; i++)
        if (used(&w->fonts[i])) {
            snprintf(b, sizeof b, "/F%zu %zu 0 R ", i, first);
            r = put(out, b);
            first += 5;
        }
    return r || put(out, ">>\n") ? -1 : 0;
}

/* Font units as 1/1000 em, rounded. */
static long
thousandths(const cf__fontfile_subset_t *s, double v)
{
    return lround(v * 1000.0 / (s->units_per_em > 0 ? s->units_per_em
                                                     : 1000));
}

static int
tounicode(const struct cf__pdfw_font *f, cf__buf_t *cmap)
{
    char b[64];
    int r = put(cmap, "/CIDInit /ProcSet findresource begin\n"
                      "12 dict begin\nbegincmap\n"
                      "/CIDSystemInfo << /Registry (Adobe) /Ordering (UCS) "
                      "/Supplement 0 >> def\n"
                      "/CMapName /Adobe-Identity-UCS def\n/CMapType 2 def\n"
                      "1 begincodespacerange\n<0000> <FFFF>\n"
                      "endcodespacerange\n");
    size_t i = 0;
    while (i < f->nuni && !r) {
        size_t n = f->nuni - i < 100 ? f->nuni - i : 100, k;
        snprintf(b, sizeof b, "%zu beginbfchar\n", n);
        r = put(cmap, b);
        for (k = i; k < i + n && !r; k++) {
            snprintf(b, sizeof b, "<%04X> <", f->uni[k].gid & 0xffffu);
            r = put(cmap, b)
                || cf__pdf_put_utf16(cmap, (const char *)f->text.data
                                               + f->uni[k].off,
                                     f->uni[k].len)
                || put(cmap, ">\n");
        }
        r = r || put(cmap, "endbfchar\n");
        i += n;
    }
    return r || put(cmap, "endcmap\nCMapName currentdict /CMap "
                          "defineresource pop\nend\nend\n") ? -1 : 0;
}

/* Objects n .. n+4: Type0, CIDFont, FontDescriptor, font file,
** ToUnicode. */
static int
font_objects(const struct cf__pdfw_font *f, size_t n,
             const cf__pdfw_objs_t *o)
{
    const cf__fontfile_subset_t *s = &f->sub;
    bool cff = s->kind == CF__FONTFILE_CFF;
    cf__buf_t *out = o->out, cmap;
    char b[256];
    int r;
    snprintf(b, sizeof b, "<< /Type /Font /Subtype /Type0 /BaseFont /%s+%s "
             "/Encoding /Identity-H\n   /DescendantFonts [ %zu 0 R ] "
             "/ToUnicode %zu 0 R >>\nendobj\n", f->tag, s->ps_name, n + 1,
             n + 4);
    r = o->begin_obj(o->ctx, n) || put(out, b)
        || o->begin_obj(o->ctx, n + 1);
    snprintf(b, sizeof b, "<< /Type /Font /Subtype /%s /BaseFont /%s+%s\n"
             "   /CIDSystemInfo << /Registry (Adobe) /Ordering (Identity) "
             "/Supplement 0 >>\n   /FontDescriptor %zu 0 R%s\n   /W [ ",
             cff ? "CIDFontType0" : "CIDFontType2", f->tag, s->ps_name,
             n + 2, cff ? "" : " /CIDToGIDMap /Identity");
    r = r || put(out, b);
    for (size_t i = 0; i < f->ngids && !r; i++) {
        snprintf(b, sizeof b, "%u [ %ld ] ", f->gids[i],
                 thousandths(s, s->advances[i]));
        r = put(out, b);
    }
    r = r || put(out, "] >>\nendobj\n") || o->begin_obj(o->ctx, n + 2);
    snprintf(b, sizeof b, "<< /Type /FontDescriptor /FontName /%s+%s "
             "/Flags %u\n   /FontBBox [ %ld %ld %ld %ld ] /ItalicAngle %g\n"
             "   /Ascent %ld /Descent %ld /CapHeight %ld /StemV %u\n"
             "   /%s %zu 0 R >>\nendobj\n", f->tag, s->ps_name, s->flags,
             thousandths(s, s->bbox[0]), thousandths(s, s->bbox[1]),
             thousandths(s, s->bbox[2]), thousandths(s, s->bbox[3]),
             s->italic_angle, thousandths(s, s->ascent),
             thousandths(s, s->descent), thousandths(s, s->cap_height),
             s->stem_v, cff ? "FontFile3" : "FontFile2", n + 3);
    r = r || put(out, b);
    if (cff)
        snprintf(b, sizeof b, "/Subtype /CIDFontType0C");
    else
        snprintf(b, sizeof b, "/Length1 %zu", s->program.size);
    r = r || o->stream(o->ctx, n + 3, b, &s->program, true);
    if (r)
        return -1;
    memset(&cmap, 0, sizeof cmap);
    r = tounicode(f, &cmap) || cmap.failed
        || o->stream(o->ctx, n + 4, "", &cmap, false);
    cf__buf_free(&cmap);
    return r ? -1 : 0;
}

int
cf__pdfw_fonts_write(const cf__pdfw_t *w, size_t first,
                     const cf__pdfw_objs_t *o)
{
    for (size_t i = 0; i < w->nfonts; i++)
        if (used(&w->fonts[i])) {
            if (font_objects(&w->fonts[i], first, o) != 0)
                return -1;
            first += 5;
        }
    return 0;
}

void
cf__pdfw_fonts_free(cf__pdfw_t *w, bool clear)
{
    size_t i, k = 0;
    for (i = 0; i < w->nfonts; i++) {
        struct cf__pdfw_font *f = &w->fonts[i];
        cf_free(f->gids);
        cf_free(f->uni);
        cf__buf_free(&f->text);
        cf__fontfile_subset_fini(&f->sub);
        if (clear && f->refused) {
            struct cf__pdfw_font keep = { 0 };
            keep.file = f->file;
            keep.index = f->index;
            keep.refused = true;
            w->fonts[k++] = keep;
        }
    }
    w->nfonts = k;
    if (!clear || k == 0) {
        cf_free(w->fonts);
        w->fonts = NULL;
        w->nfonts = w->fonts_cap = 0;
    }
}
