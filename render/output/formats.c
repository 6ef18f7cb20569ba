/*
** The output formats: PS, EPS and PNG pages drawn from a display list by
** the cairo backend into memory, and made deterministic there (no
** creation dates; title and caption as metadata); SVG pages by the SVG
** writer, PDF documents by the PDF writer, PGF pages by the PGF backend.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cairo-ps.h>

#include "backend.h"
#include "output-private.h"
#include "png-private.h"

static const char *const format_names[CF_FORMAT_LAST_] = {
    "svg", "pdf", "ps", "eps", "png", "pgf"
};

cf_status_t
cf_format_from_name(const char *name, cf_format_t *out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    int i;
    if (name == NULL || out == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "format name or output is NULL");
    for (i = 0; i < CF_FORMAT_LAST_; i++) {
        if (strcmp(name, format_names[i]) == 0) {
            *out = (cf_format_t)i;
            return CF_STATUS_OK;
        }
    }
    return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                       "unknown format \"%s\" (use svg, pdf, ps, eps, png or pgf)",
                       name);
}

const char *
cf_format_extension(cf_format_t format)
{
    if ((unsigned)format >= CF_FORMAT_LAST_)
        return "";
    return format_names[format];
}


/* ---- buffers ------------------------------------------------------------ */

static cairo_status_t
stream_write(void *closure, const unsigned char *data, unsigned int length)
{
    return cf__buf_append(closure, data, length) == 0
        ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

/* ---- deterministic post-processing -------------------------------------- */

static int
buf_append_str(cf__buf_t *b, const char *s)
{
    return cf__buf_append(b, s, strlen(s));
}

/* PS/EPS: drop the %%CreationDate line. */
static int
ps_fix(const cf__buf_t *in, cf__buf_t *out)
{
    const unsigned char *p = in->data, *end = in->data + in->size;
    while (p < end) {
        const unsigned char *nl = memchr(p, '\n', (size_t)(end - p));
        const unsigned char *next = nl != NULL ? nl + 1 : end;
        size_t n = (size_t)(next - p);
        if (!(n >= 15 && memcmp(p, "%%CreationDate:", 15) == 0))
            if (cf__buf_append(out, p, n) != 0)
                return -1;
        p = next;
    }
    return out->failed ? -1 : 0;
}

/* EPS from PS.  cairo's PostScript writer (cairo 1.16) emits the same
** program for PS and EPS except for a few header and setup lines, and a
** PS page with translucent elements costs a fallback image at 300 dpi
** (half the time of the whole figure set went into PS and EPS).  So when
** both are written, the EPS is derived from the PS:
**   line 1 "%!PS-Adobe-3.0" gets " EPSF-3.0";
**   "%%DocumentMedia:", "%%PageMedia:" and "W H cairo_set_page_size" go;
**   the language-level check after "%%BeginProlog" (5 lines) becomes
**   "50 dict begin", and "end" follows "%%Trailer";
**   the definition "/cairo_set_page_size { ... } def" goes.
** Every piece must be found exactly once, else -1 and the caller renders
** the EPS through cairo; only used with cairo 1.16.0, the version the
** test (tests/render/test_output.c) compares against byte for byte.
** 0 on success, -1 unexpected input, -2 out of memory. */
static bool
line_is(const unsigned char *p, size_t n, const char *s)
{
    return n == strlen(s) && memcmp(p, s, n) == 0;
}

static bool
line_starts(const unsigned char *p, size_t n, const char *s)
{
    return n >= strlen(s) && memcmp(p, s, strlen(s)) == 0;
}

/* "W H cairo_set_page_size\n" with W and H unsigned numbers. */
static bool
is_set_page_size(const unsigned char *p, size_t n)
{
    static const char tail[] = " cairo_set_page_size\n";
    size_t t = sizeof tail - 1, i, spaces = 0;
    if (n <= t || memcmp(p + n - t, tail, t) != 0)
        return false;
    for (i = 0; i < n - t; i++) {
        if (p[i] == ' ')
            spaces++;
        else if (!((p[i] >= '0' && p[i] <= '9') || p[i] == '.'))
            return false;
    }
    return spaces == 1 && p[0] != ' ' && p[n - t - 1] != ' ';
}

int
cf__eps_from_ps(const cf__buf_t *ps, cf__buf_t *eps)
{
    const unsigned char *p = ps->data, *end = ps->data + ps->size;
    int media = 0, level = 0, setpage_def = 0, page_media = 0;
    int setpage_call = 0, trailer = 0, in_def = 0, line_no = 0;
    int in_header = 1, skip_level = 0;

    /* the PS of other cairo versions is not checked against this */
    if (cairo_version() != CAIRO_VERSION_ENCODE(1, 16, 0))
        return -1;
    while (p < end) {
        const unsigned char *nl = memchr(p, '\n', (size_t)(end - p));
        size_t n;
        int r = 0;
        if (nl == NULL)
            return -1;
        n = (size_t)(nl + 1 - p);
        line_no++;
        if (line_no == 1) {
            if (!line_is(p, n, "%!PS-Adobe-3.0\n"))
                return -1;
            r = buf_append_str(eps, "%!PS-Adobe-3.0 EPSF-3.0\n");
        } else if (skip_level > 0) {
            /* the language-level check: 4 more lines */
            static const char *const check[] = {
                "{ pop languagelevel } { 1 } ifelse\n",
                (" lt { /Helvetica findfont 12 scalefont setfont 50 500 "
                 "moveto\n"),
                "  (This print job requires a PostScript Language Level ",
                "  showpage quit } if\n",
            };
            const char *want = check[4 - skip_level];
            bool ok = skip_level == 3
                ? n > strlen(want) && p[0] >= '1' && p[0] <= '3'
                      && line_is(p + 1, n - 1, want)
                : skip_level == 2 ? line_starts(p, n, want)
                                  : line_is(p, n, want);
            if (!ok)
                return -1;
            skip_level--;
        } else if (in_def) {
            if (line_is(p, n, "} def\n"))
                in_def = 0;
        } else if (in_header && line_starts(p, n, "%%DocumentMedia: ")) {
            media++;
        } else if (line_is(p, n, "%%EndComments\n")) {
            in_header = 0;
            r = cf__buf_append(eps, p, n);
        } else if (line_is(p, n, "/languagelevel where\n")) {
            level++;
            skip_level = 4;
            r = buf_append_str(eps, "50 dict begin\n");
        } else if (line_is(p, n, "/cairo_set_page_size {\n")) {
            setpage_def++;
            in_def = 1;
        } else if (line_starts(p, n, "%%PageMedia: ")) {
            page_media++;
        } else if (is_set_page_size(p, n)) {
            setpage_call++;
        } else if (line_is(p, n, "%%Trailer\n")) {
            trailer++;
            r = buf_append_str(eps, "%%Trailer\nend\n");
        } else {
            r = cf__buf_append(eps, p, n);
        }
        if (r != 0)
            return -2;
        p = nl + 1;
    }
    if (media != 1 || level != 1 || setpage_def != 1 || page_media != 1
        || setpage_call != 1 || trailer != 1 || in_def || skip_level > 0)
        return -1;
    return 0;
}

void
cf__pdf_date(char *buf, size_t cap)
{
    const char *e = getenv("SOURCE_DATE_EPOCH");
    long long t = 946684800;   /* 2000-01-01T00:00:00Z */
    long long days, secs, y, m, d, era, doe, yoe, doy, mp;
    if (e != NULL && *e != '\0') {
        char *endp;
        long long v = strtoll(e, &endp, 10);
        if (*endp == '\0' && v >= 0 && v < 253402300800LL)
            t = v;
    }
    days = t / 86400;
    secs = t % 86400;
    /* civil from days (H. Hinnant's algorithm) */
    days += 719468;
    era = days / 146097;
    doe = days - era * 146097;
    yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    y = yoe + era * 400;
    doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    mp = (5 * doy + 2) / 153;
    d = doy - (153 * mp + 2) / 5 + 1;
    m = mp < 10 ? mp + 3 : mp - 9;
    if (m <= 2)
        y++;
    snprintf(buf, cap, "%04lld-%02lld-%02lldT%02lld:%02lld:%02lldZ", y, m, d,
             secs / 3600, secs / 60 % 60, secs % 60);
}

/* ---- one page in one format -------------------------------------------- */

/* SVG: the SVG writer (render/backends/backend-svgw.c) into out, labels
** as uses of their glyphs' outlines (render/output/svg-glyphs.c); one
** page, of overlay step pg->first_step (0: every operation). */
static cf_status_t
svg_render(const cf__dl_t *dl, const cf__page_t *pg, const char *title,
           const char *caption, cf__buf_t *out, cf_diag_t *diag)
{
    cf__svg_glyphs_t sg;
    cf__svgw_t w;
    int r;
    memset(&sg, 0, sizeof sg);
    memset(&w, 0, sizeof w);
    w.out = out;
    w.title = title;
    w.caption = caption;
    cf__svg_glyphs_attach(&sg, &w);
    cf__svgw_backend.begin_page(&w, pg);
    cf__dl_play_step(dl, pg, pg->first_step, &cf__svgw_backend, &w);
    r = cf__svgw_backend.end_page(&w);
    cf__svg_glyphs_fini(&sg);
    if (r == 0)
        return CF_STATUS_OK;
    cf__buf_free(out);
    return cf__svgw_fault(&w, "svg", diag);
}

void
cf__pdf_writer_init(cf__pdfw_t *w, cf__glyph_outliner_t *o)
{
    w->outline = cf__glyph_outline;
    w->glyphs = cf__pdf_glyphs;
    w->outline_ctx = o;
}

/* PDF: the PDF writer (render/backends/backend-pdfw.c) into out, one
** page, or one per overlay step of pg's; labels as text
** (render/output/pdf-glyphs.c), else the outlines of their glyphs; played
** again when a font was refused (its labels then as outlines). */
static cf_status_t
pdf_render(const cf__dl_t *dl, const cf__page_t *pg, const char *title,
           const char *caption, cf__buf_t *out, cf_diag_t *diag)
{
    cf__glyph_outliner_t outliner;
    cf__pdfw_t w;
    char date[40];
    unsigned k, first = pg->first_step, last = first ? pg->last_step : 0;
    cf_status_t st;
    int r = 0;
    memset(&outliner, 0, sizeof outliner);
    memset(&w, 0, sizeof w);
    cf__pdf_writer_init(&w, &outliner);
    cf__pdf_date(date, sizeof date);
    do {
        r = 0;
        for (k = first; k <= last && r == 0; k++) {
            cf__pdfw_backend.begin_page(&w, pg);
            cf__dl_play_step(dl, pg, k, &cf__pdfw_backend, &w);
            r = cf__pdfw_backend.end_page(&w);
        }
        if (r != 0)
            break;
        r = cf__pdfw_document(&w, title, caption, date, out);
        if (r == 1)
            cf__pdfw_restart(&w);
    } while (r == 1);
    cf__glyph_outliner_fini(&outliner);
    if (r == 0) {
        cf__pdfw_fini(&w);
        return CF_STATUS_OK;
    }
    cf__buf_free(out);
    st = w.sc.bad ? cf__pdfw_fault(&w, diag)
               : cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                             "out of memory writing pdf");
    cf__pdfw_fini(&w);
    return st;
}

/* PGF: the PGF backend into out, without cairo surfaces. */
static cf_status_t
pgf_render(const cf__dl_t *dl, const cf__page_t *page, const char *title,
           const char *desc, cf__buf_t *out, cf_diag_t *diag)
{
    cf__pgf_t g;
    int r;
    memset(&g, 0, sizeof g);
    g.out = out;
    g.title = title;
    g.desc = desc;
    r = cf__dl_play_page(dl, page, &cf__pgf_backend, &g);
    cf__pgf_fini(&g);
    if (r == 0)
        return CF_STATUS_OK;
    cf__buf_free(out);
    if (g.range_error)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "pgf: coordinate %g bp lies beyond what TeX can "
                           "hold (%g bp)", g.bad_value, CF__PGF_MAX_BP);
    return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                       "out of memory rendering pgf");
}

/* DSC header comments of a PS or EPS: %%Title (the alt text) and the
** description in %%Description lines; each line of at most 255 bytes
** (DSC's limit), cut at UTF-8 character boundaries, line breaks as
** spaces. */
static void
ps_comment(cairo_surface_t *surf, const char *key, const char *text)
{
    char line[256];
    size_t k = (size_t)snprintf(line, sizeof line, "%%%%%s: ", key), i;
    const size_t max = 240;
    for (i = 0; text[i] != '\0'; i++) {
        unsigned char c = (unsigned char)text[i];
        /* a new line at a space, or at any character past 250 bytes */
        if ((k >= max && c == ' ') || (k >= max + 10 && (c & 0xc0) != 0x80)) {
            line[k] = '\0';
            cairo_ps_surface_dsc_comment(surf, line);
            k = (size_t)snprintf(line, sizeof line, "%%%%+ ");
        }
        line[k++] = c == '\n' || c == '\r' ? ' ' : (char)c;
    }
    line[k] = '\0';
    cairo_ps_surface_dsc_comment(surf, line);
}

static void
ps_comments(cairo_surface_t *surf, const char *title, const char *desc)
{
    if (title != NULL)
        ps_comment(surf, "Title", title);
    if (desc != NULL && desc[0] != '\0')
        ps_comment(surf, "Description", desc);
}

static cairo_surface_t *
make_surface(cf_format_t format, const cf__page_t *pg, double dpi,
             const char *title, const char *caption, cf__buf_t *raw,
             unsigned char **pixels, cf_diag_t *diag)
{
    cairo_surface_t *surf = NULL;
    switch (format) {
    case CF_FORMAT_PS:
    case CF_FORMAT_EPS:
        surf = cairo_ps_surface_create_for_stream(stream_write, raw,
                                                  pg->width, pg->height);
        cairo_ps_surface_set_eps(surf, format == CF_FORMAT_EPS);
        ps_comments(surf, title, caption);
        break;
    case CF_FORMAT_PNG: {
        double k = dpi / 72.0;
        double wpx = ceil(pg->width * k - 1e-6);
        double hpx = ceil(pg->height * k - 1e-6);
        if (wpx > 32000 || hpx > 32000) {
            cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                        "PNG of %.0f x %.0f pixels is too large (at most "
                        "32000 a side); lower the dpi", wpx, hpx);
            return NULL;
        }
        /* the image's memory: 4 bytes a pixel, 256 MiB at most */
        if (wpx * hpx > CF_PNG_MAX_PIXELS) {
            cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                        "PNG of %.0f x %.0f pixels is too large (at most "
                        "%.0f million pixels, 256 MiB); lower the dpi",
                        wpx, hpx, CF_PNG_MAX_PIXELS / 1e6);
            return NULL;
        }
        /* the pixels from the current allocator: under the tool, the
        ** script's memory budget (they are most of a large PNG's memory) */
        {
            int w = (int)fmax(1, wpx), h = (int)fmax(1, hpx);
            int stride = cairo_format_stride_for_width(CAIRO_FORMAT_ARGB32,
                                                       w);
            *pixels = cf_calloc((size_t)h, (size_t)stride);
            if (*pixels == NULL) {
                cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                            "out of memory for the PNG's %d x %d pixels "
                            "(%.0f MiB)", w, h,
                            (double)h * stride / 1048576.0);
                return NULL;
            }
            surf = cairo_image_surface_create_for_data(
                *pixels, CAIRO_FORMAT_ARGB32, w, h, stride);
        }
        break;
    }
    default:
        cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1, "unknown format %d",
                    (int)format);
        return NULL;
    }
    return surf;
}

/* cairo allocates with malloc, outside the current allocator (the
** script's budget under the tool), and what it holds while it draws grows
** with the path it strokes or fills: its path, stroker, polygon and, for
** rasters, its edges.  That memory is bounded through its input: a block
** of CAIRO_SEG_BYTES per segment of the longest path of the list is taken
** from the current allocator while cairo draws and released after; it is
** never written, so it is never resident, but a budget without room for
** cairo's work fails before cairo does that work.  CAIRO_SEG_BYTES: the
** peak resident size of a 10^5-segment B-spline drawn to PNG less that
** of the same list written as PGF (no cairo), per segment, rounded up:
** about 280 bytes a segment for PNG measured with cairo 1.16; a vector
** surface neither flattens nor rasterises, but holds the page's content
** stream before compressing it (about 100 bytes a segment for PDF). */
#define CAIRO_SEG_BYTES 384
#define CAIRO_SEG_BYTES_VECTOR 160

static size_t
longest_path(const cf__dl_t *dl)
{
    size_t longest = 0;
    for (size_t i = 0; i < dl->count; i++)
        if (dl->ops[i].kind == CF__OP_PATH &&
            dl->ops[i].u.path.nsegs > longest)
            longest = dl->ops[i].u.path.nsegs;
    return longest;
}

static size_t
seg_bytes(cf_format_t format)
{
    return format == CF_FORMAT_PNG ? CAIRO_SEG_BYTES : CAIRO_SEG_BYTES_VECTOR;
}

/* The page, or one page per overlay step (cairo_show_page between). */
static void
play_steps(const cf__dl_t *dl, const cf__page_t *pg, cairo_t *cr)
{
    unsigned k;
    if (pg->first_step == 0) {
        cf__dl_play_page(dl, pg, &cf__cairo_backend, cr);
        return;
    }
    for (k = pg->first_step; k <= pg->last_step; k++) {
        if (k > pg->first_step)
            cairo_show_page(cr);
        cf__cairo_backend.begin_page(cr, pg);
        cf__dl_play_step(dl, pg, k, &cf__cairo_backend, cr);
        cf__cairo_backend.end_page(cr);
    }
}

cf_status_t
cf__format_render(cf_format_t format, const cf__dl_t *dl,
                  const cf__page_t *page, double dpi, const char *title,
                  const char *caption, cf__buf_t *out, cf_diag_t *diag)
{
    cf__page_t pg = *page;
    cf__buf_t raw;
    cairo_surface_t *surf;
    cairo_t *cr;
    cairo_status_t cst;
    cf_status_t st;
    unsigned char *pixels = NULL;
    void *room;
    int r;

    memset(&raw, 0, sizeof raw);
    if (format == CF_FORMAT_PGF)
        return pgf_render(dl, page, title, caption, out, diag);
    if (format == CF_FORMAT_SVG)
        return svg_render(dl, page, title, caption, out, diag);
    if (format == CF_FORMAT_PDF)
        return pdf_render(dl, page, title, caption, out, diag);
    pg.raster = format == CF_FORMAT_PNG;
    room = cf_alloc_array(longest_path(dl) + 1, seg_bytes(format));
    if (room == NULL)
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1, "out of memory "
                           "for cairo's work on a path of %zu segments "
                           "(%zu bytes each)", longest_path(dl),
                           seg_bytes(format));
    surf = make_surface(format, &pg, dpi, title, caption, &raw, &pixels,
                        diag);
    if (surf == NULL) {
        cf_free(room);
        cf_free(pixels);
        return diag != NULL && diag->status != CF_STATUS_OK
            ? diag->status : CF_STATUS_INVALID_ARG;
    }
    cr = cairo_create(surf);
    if (format == CF_FORMAT_PNG)
        cairo_scale(cr, dpi / 72.0, dpi / 72.0);
    play_steps(dl, &pg, cr);
    cst = cairo_status(cr);
    cairo_destroy(cr);
    cf_free(room);
    if (format == CF_FORMAT_PNG && cst == CAIRO_STATUS_SUCCESS) {
        st = cf__png_encode(surf, dpi, &raw, diag);
        if (st != CF_STATUS_OK) {
            cairo_surface_destroy(surf);
            cf_free(pixels);
            cf__buf_free(&raw);
            return st;
        }
    }
    cairo_surface_finish(surf);
    if (cst == CAIRO_STATUS_SUCCESS)
        cst = cairo_surface_status(surf);
    cairo_surface_destroy(surf);
    cf_free(pixels);
    if (cst != CAIRO_STATUS_SUCCESS || raw.failed) {
        cf__buf_free(&raw);
        if (cst == CAIRO_STATUS_NO_MEMORY || cst == CAIRO_STATUS_WRITE_ERROR
            || raw.failed)
            return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                               "out of memory rendering %s",
                               format_names[format]);
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "cairo failed rendering %s: %s",
                           format_names[format],
                           cairo_status_to_string(cst));
    }
    if (format != CF_FORMAT_PS && format != CF_FORMAT_EPS) {
        *out = raw;
        return CF_STATUS_OK;
    }
    r = ps_fix(&raw, out);
    cf__buf_free(&raw);
    if (r != 0) {
        cf__buf_free(out);
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory post-processing %s",
                           format_names[format]);
    }
    return CF_STATUS_OK;
}
