/*
** Output: SVG, PDF, PS, EPS and PNG through cairo's stream surfaces into
** memory, made deterministic there, then written to a temporary file in
** the target directory and renamed over the target.
*/
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cairo-pdf.h>
#include <cairo-ps.h>
#include <cairo-svg.h>

#include "png-private.h"
#include "render-private.h"

static const char *const format_names[CF_FORMAT_LAST_] = {
    "svg", "pdf", "ps", "eps", "png"
};

cf_status_t
cf_format_from_name(const char *name, cf_format_t *out, cf_diag_t *diag)
{
    int i;
    if (name == NULL || out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "format name or output is NULL");
    for (i = 0; i < CF_FORMAT_LAST_; i++) {
        if (strcmp(name, format_names[i]) == 0) {
            *out = (cf_format_t)i;
            return CF_STATUS_OK;
        }
    }
    return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                     "unknown format \"%s\" (use svg, pdf, ps, eps or png)",
                     name);
}

const char *
cf_format_extension(cf_format_t format)
{
    if ((unsigned)format >= CF_FORMAT_LAST_)
        return "";
    return format_names[format];
}

void
cf_write_options_init(cf_write_options_t *options)
{
    if (options == NULL)
        return;
    memset(options, 0, sizeof *options);
    options->dpi = 150;
    options->tight = false;
    options->padding = 0;
}

/* ---- buffers ------------------------------------------------------------ */

int
cf__buf_append(cf__buf_t *b, const void *data, size_t n)
{
    if (b->failed)
        return -1;
    if (b->size + n > b->cap) {
        size_t cap = b->cap ? b->cap : 4096;
        unsigned char *d;
        while (cap < b->size + n)
            cap *= 2;
        d = cf__realloc_array(b->data, cap, 1);
        if (d == NULL) {
            b->failed = 1;
            return -1;
        }
        b->data = d;
        b->cap = cap;
    }
    if (n > 0)
        memcpy(b->data + b->size, data, n);
    b->size += n;
    return 0;
}

void
cf__buf_free(cf__buf_t *b)
{
    cf__free(b->data);
    memset(b, 0, sizeof *b);
}

static cairo_status_t
stream_write(void *closure, const unsigned char *data, unsigned int length)
{
    return cf__buf_append(closure, data, length) == 0
        ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

/* ---- page geometry ------------------------------------------------------ */

typedef struct page {
    double w, h;      /* page size, bp */
    double ink[4];    /* ink box at the physical size (x0 y0 x1 y1) */
} page_t;

static cf_status_t
check_options(const cf_write_options_t *o, cf_diag_t *diag)
{
    if (!(isfinite(o->dpi) && o->dpi >= 1 && o->dpi <= 2400))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "resolution %g dpi must lie in [1, 2400]", o->dpi);
    if (!(isfinite(o->padding) && o->padding >= 0 && o->padding <= 1000))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "padding %g bp must lie in [0, 1000]", o->padding);
    return CF_STATUS_OK;
}

/* The figure's first error, copied into diag. */
static cf_status_t
figure_error(cf_figure_t *fig, cf_diag_t *diag)
{
    return cf_figure_status(fig, diag);
}

/* Layout and page size.  The ink box needs a drawing pass into a
** recording surface; it is made only when asked for (need_ink) or when
** the page is cropped to it (tight); otherwise pg->ink is left zero. */
static cf_status_t
make_page(cf_figure_t *fig, const cf_write_options_t *o, bool need_ink,
          cf__layout_t *lay, page_t *pg, cf_diag_t *diag)
{
    cairo_surface_t *rec;
    cairo_t *cr;
    double x, y, w, h;

    if (cf__figure_layout(fig, lay, NULL) != CF_STATUS_OK)
        return figure_error(fig, diag);
    memset(pg->ink, 0, sizeof pg->ink);
    cf_figure_get_size(fig, &pg->w, &pg->h);
    if (!need_ink && !o->tight)
        return CF_STATUS_OK;
    rec = cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, NULL);
    cr = cairo_create(rec);
    cf__figure_draw(fig, lay, cr, NULL);
    cairo_destroy(cr);
    cairo_recording_surface_ink_extents(rec, &x, &y, &w, &h);
    if (cairo_surface_status(rec) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(rec);
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "cairo: %s", cairo_status_to_string(
                             cairo_surface_status(rec)));
    }
    cairo_surface_destroy(rec);
    if (cf_figure_status(fig, NULL) != CF_STATUS_OK)
        return figure_error(fig, diag);
    pg->ink[0] = x;
    pg->ink[1] = y;
    pg->ink[2] = x + w;
    pg->ink[3] = y + h;
    if (o->tight && w > 0 && h > 0) {
        /* the shift goes into the data -> page map, so that the files
        ** carry plain coordinates (no SVG transform attributes) */
        pg->w = w + 2 * o->padding;
        pg->h = h + 2 * o->padding;
        lay->ox += o->padding - x;
        lay->oy += o->padding - y;
    }
    return CF_STATUS_OK;
}

static void
draw_page(cf_figure_t *fig, const cf__layout_t *lay, const page_t *pg,
          bool raster, cairo_t *cr)
{
    const cf_color_t *bg = cf__figure_background(fig);
    if (bg->a > 0) {
        cairo_save(cr);
        cairo_set_source_rgba(cr, bg->r, bg->g, bg->b, bg->a);
        /* A raster has whole pixels: the page (8 cm at 150 dpi is 472.4
        ** px) is rounded up, and the background covers the last column
        ** and row too instead of leaving them partly transparent; an
        ** opaque background then gives an opaque image (an RGB PNG). */
        if (raster) {
            cairo_paint(cr);
        } else {
            cairo_rectangle(cr, 0, 0, pg->w, pg->h);
            cairo_fill(cr);
        }
        cairo_restore(cr);
    }
    cf__figure_draw(fig, lay, cr, NULL);
}

/* ---- deterministic post-processing -------------------------------------- */

static int
buf_append_str(cf__buf_t *b, const char *s)
{
    return cf__buf_append(b, s, strlen(s));
}

static int
append_xml_escaped(cf__buf_t *b, const char *s)
{
    for (; *s != '\0'; s++) {
        int r;
        switch (*s) {
        case '<':
            r = buf_append_str(b, "&lt;");
            break;
        case '>':
            r = buf_append_str(b, "&gt;");
            break;
        case '&':
            r = buf_append_str(b, "&amp;");
            break;
        case '"':
            r = buf_append_str(b, "&quot;");
            break;
        default:
            r = cf__buf_append(b, s, 1);
        }
        if (r != 0)
            return r;
    }
    return 0;
}

static const unsigned char *
find_bytes(const unsigned char *h, size_t n, const char *needle)
{
    size_t m = strlen(needle), i;
    if (m > n)
        return NULL;
    for (i = 0; i + m <= n; i++)
        if (h[i] == (unsigned char)needle[0] && memcmp(h + i, needle, m) == 0)
            return h + i;
    return NULL;
}

/* SVG: <title>/<desc> after the opening <svg ...> tag, and the ids cairo
** numbers per process ("surface123") renumbered in order of appearance. */
static int
svg_fix(cf_figure_t *fig, const cf__buf_t *in, cf__buf_t *out)
{
    const unsigned char *p = in->data, *end = in->data + in->size, *svg, *gt;
    long map_from[64];
    size_t nmap = 0;
    const char *title = cf__figure_title(fig), *cap = cf__figure_caption(fig);

    svg = find_bytes(p, in->size, "<svg");
    gt = svg != NULL ? memchr(svg, '>', (size_t)(end - svg)) : NULL;
    if (gt == NULL)
        return -1;
    if (cf__buf_append(out, p, (size_t)(gt + 1 - p)) != 0)
        return -1;
    if (title != NULL || cap != NULL) {
        if (buf_append_str(out, "\n<title>") != 0
            || append_xml_escaped(out, title != NULL ? title : cap) != 0
            || buf_append_str(out, "</title>") != 0)
            return -1;
        if (cap != NULL
            && (buf_append_str(out, "\n<desc>") != 0
                || append_xml_escaped(out, cap) != 0
                || buf_append_str(out, "</desc>") != 0))
            return -1;
    }
    p = gt + 1;
    while (p < end) {
        const unsigned char *s = find_bytes(p, (size_t)(end - p), "surface");
        const unsigned char *d;
        long v = 0;
        size_t k;
        char num[32];
        if (s == NULL) {
            if (cf__buf_append(out, p, (size_t)(end - p)) != 0)
                return -1;
            break;
        }
        d = s + 7;
        if (d >= end || *d < '0' || *d > '9') {
            if (cf__buf_append(out, p, (size_t)(d - p)) != 0)
                return -1;
            p = d;
            continue;
        }
        while (d < end && *d >= '0' && *d <= '9' && v < 100000000)
            v = v * 10 + (*d++ - '0');
        for (k = 0; k < nmap && map_from[k] != v; k++)
            ;
        if (k == nmap) {
            if (nmap == sizeof map_from / sizeof map_from[0])
                return -1;
            map_from[nmap++] = v;
        }
        snprintf(num, sizeof num, "surface%zu", k + 1);
        if (cf__buf_append(out, p, (size_t)(s - p)) != 0
            || buf_append_str(out, num) != 0)
            return -1;
        p = d;
    }
    return out->failed ? -1 : 0;
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

static int
eps_from_ps(const cf__buf_t *ps, cf__buf_t *eps)
{
    const unsigned char *p = ps->data, *end = ps->data + ps->size;
    int media = 0, level = 0, setpage_def = 0, page_media = 0;
    int setpage_call = 0, trailer = 0, in_def = 0, line_no = 0;
    int in_header = 1, skip_level = 0;

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

/* PDF dates: from SOURCE_DATE_EPOCH (ISO 8601, UTC), else 2000-01-01 so
** that the clock never enters the file. */
static void
pdf_date(char *buf, size_t cap)
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

/* ---- rendering to memory ------------------------------------------------ */

/* One format of a page laid out by make_page, into out. */
static cf_status_t
render_page(cf_figure_t *fig, cf_format_t format,
            const cf_write_options_t *o, const cf__layout_t *layout,
            const page_t *page, cf__buf_t *out, cf_diag_t *diag)
{
    cf__layout_t lay = *layout;
    page_t pg = *page;
    cf__buf_t raw;
    cairo_surface_t *surf = NULL;
    cairo_t *cr;
    cairo_status_t cst;
    cf_status_t st;

    memset(&raw, 0, sizeof raw);
    switch (format) {
    case CF_FORMAT_SVG:
        surf = cairo_svg_surface_create_for_stream(stream_write, &raw, pg.w,
                                                   pg.h);
        cairo_svg_surface_restrict_to_version(surf, CAIRO_SVG_VERSION_1_1);
        cairo_svg_surface_set_document_unit(surf, CAIRO_SVG_UNIT_PT);
        break;
    case CF_FORMAT_PDF: {
        char date[40];
        surf = cairo_pdf_surface_create_for_stream(stream_write, &raw, pg.w,
                                                   pg.h);
        pdf_date(date, sizeof date);
        cairo_pdf_surface_set_metadata(surf, CAIRO_PDF_METADATA_CREATE_DATE,
                                       date);
        cairo_pdf_surface_set_metadata(surf, CAIRO_PDF_METADATA_MOD_DATE,
                                       date);
        if (cf__figure_title(fig) != NULL)
            cairo_pdf_surface_set_metadata(surf, CAIRO_PDF_METADATA_TITLE,
                                           cf__figure_title(fig));
        if (cf__figure_caption(fig) != NULL)
            cairo_pdf_surface_set_metadata(surf, CAIRO_PDF_METADATA_SUBJECT,
                                           cf__figure_caption(fig));
        break;
    }
    case CF_FORMAT_PS:
    case CF_FORMAT_EPS:
        surf = cairo_ps_surface_create_for_stream(stream_write, &raw, pg.w,
                                                  pg.h);
        cairo_ps_surface_set_eps(surf, format == CF_FORMAT_EPS);
        break;
    case CF_FORMAT_PNG: {
        double k = o->dpi / 72.0;
        double wpx = ceil(pg.w * k - 1e-6), hpx = ceil(pg.h * k - 1e-6);
        if (wpx > 32000 || hpx > 32000)
            return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                             "PNG of %.0f x %.0f pixels is too large "
                             "(at most 32000 a side); lower the dpi", wpx,
                             hpx);
        surf = cairo_image_surface_create(CAIRO_FORMAT_ARGB32,
                                          (int)fmax(1, wpx),
                                          (int)fmax(1, hpx));
        break;
    }
    default:
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "unknown format %d", (int)format);
    }
    cr = cairo_create(surf);
    if (format == CF_FORMAT_PNG)
        cairo_scale(cr, o->dpi / 72.0, o->dpi / 72.0);
    draw_page(fig, &lay, &pg, format == CF_FORMAT_PNG, cr);
    cst = cairo_status(cr);
    cairo_destroy(cr);
    if (format == CF_FORMAT_PNG && cst == CAIRO_STATUS_SUCCESS
        && cf_figure_status(fig, NULL) == CF_STATUS_OK) {
        st = cf__png_encode(surf, o->dpi, &raw, diag);
        if (st != CF_STATUS_OK) {
            cairo_surface_destroy(surf);
            cf__buf_free(&raw);
            return st;
        }
    }
    cairo_surface_finish(surf);
    if (cst == CAIRO_STATUS_SUCCESS)
        cst = cairo_surface_status(surf);
    cairo_surface_destroy(surf);
    if (cf_figure_status(fig, NULL) != CF_STATUS_OK) {
        cf__buf_free(&raw);
        return figure_error(fig, diag);
    }
    if (cst != CAIRO_STATUS_SUCCESS || raw.failed) {
        cf__buf_free(&raw);
        if (cst == CAIRO_STATUS_NO_MEMORY || cst == CAIRO_STATUS_WRITE_ERROR
            || raw.failed)
            return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                             "out of memory rendering %s",
                             format_names[format]);
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "cairo failed rendering %s: %s",
                         format_names[format], cairo_status_to_string(cst));
    }
    if (format == CF_FORMAT_SVG || format == CF_FORMAT_PS
        || format == CF_FORMAT_EPS) {
        int r = format == CF_FORMAT_SVG ? svg_fix(fig, &raw, out)
                                        : ps_fix(&raw, out);
        cf__buf_free(&raw);
        if (r != 0) {
            cf__buf_free(out);
            return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                             "out of memory post-processing %s",
                             format_names[format]);
        }
    } else {
        *out = raw;
    }
    return CF_STATUS_OK;
}

static cf_status_t
options_or_default(const cf_write_options_t *options, cf_write_options_t *o,
                   cf_diag_t *diag)
{
    if (options != NULL)
        *o = *options;
    else
        cf_write_options_init(o);
    return check_options(o, diag);
}

static cf_status_t
check_fig_format(cf_figure_t *fig, cf_format_t format, cf_diag_t *diag)
{
    if (fig == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "figure is NULL");
    if (cf_figure_status(fig, NULL) != CF_STATUS_OK)
        return figure_error(fig, diag);
    if ((unsigned)format >= CF_FORMAT_LAST_)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "unknown format %d (use CF_FORMAT_SVG .. PNG)",
                         (int)format);
    return CF_STATUS_OK;
}

/* Lay out and render one format into buf (checked options). */
static cf_status_t
render_buf(cf_figure_t *fig, cf_format_t format,
           const cf_write_options_t *o, cf__buf_t *buf, cf_diag_t *diag)
{
    cf__layout_t lay;
    page_t pg;
    cf_status_t st = make_page(fig, o, false, &lay, &pg, diag);
    if (st != CF_STATUS_OK)
        return st;
    return render_page(fig, format, o, &lay, &pg, buf, diag);
}

/* Check the arguments and render into buf. */
static cf_status_t
render_checked(cf_figure_t *fig, cf_format_t format,
               const cf_write_options_t *options, cf__buf_t *buf,
               cf_diag_t *diag)
{
    cf_write_options_t o;
    cf_status_t st = check_fig_format(fig, format, diag);
    memset(buf, 0, sizeof *buf);
    if (st == CF_STATUS_OK)
        st = options_or_default(options, &o, diag);
    if (st != CF_STATUS_OK)
        return st;
    return render_buf(fig, format, &o, buf, diag);
}

cf_status_t
cf_figure_render(cf_figure_t *fig, cf_format_t format,
                 const cf_write_options_t *options, unsigned char **data,
                 size_t *size, cf_diag_t *diag)
{
    cf__buf_t buf;
    cf_status_t st;
    if (data == NULL || size == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "render: output pointers are NULL");
    *data = NULL;
    *size = 0;
    st = render_checked(fig, format, options, &buf, diag);
    if (st != CF_STATUS_OK)
        return st;
    *data = buf.data;
    *size = buf.size;
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_ink_box(cf_figure_t *fig, const cf_write_options_t *options,
                  double box[4], double *page_width, double *page_height,
                  cf_diag_t *diag)
{
    cf_write_options_t o;
    cf__layout_t lay;
    page_t pg;
    cf_status_t st = check_fig_format(fig, CF_FORMAT_SVG, diag);
    if (st == CF_STATUS_OK)
        st = options_or_default(options, &o, diag);
    if (st == CF_STATUS_OK)
        st = make_page(fig, &o, true, &lay, &pg, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (box != NULL)
        memcpy(box, pg.ink, sizeof pg.ink);
    if (page_width != NULL)
        *page_width = pg.w;
    if (page_height != NULL)
        *page_height = pg.h;
    return CF_STATUS_OK;
}

/* ---- files -------------------------------------------------------------- */

/* Write data to a temporary file beside path and rename it over path:
** a reader sees the old file or the new one, never a part.  No fsync:
** figures are build products (as the object files ninja writes), and a
** sync costs 4 to 20 ms of waiting per file, more than rendering it. */
static cf_status_t
write_atomic(const char *path, const unsigned char *data, size_t n,
             cf_diag_t *diag)
{
    const char *slash = strrchr(path, '/');
    size_t dlen = slash != NULL ? (size_t)(slash - path) + 1 : 0;
    char *tmp;
    int fd;
    size_t off = 0;
    cf_status_t st = CF_STATUS_OK;

    if (path[0] == '\0' || path[strlen(path) - 1] == '/')
        return cf__error(diag, CF_STATUS_IO, -1,
                         "\"%s\" is not a file name", path);
    tmp = cf__malloc(dlen + 16);
    if (tmp == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory for a file name");
    memcpy(tmp, path, dlen);
    memcpy(tmp + dlen, ".cf-tmp-XXXXXX", 15);
    fd = mkstemp(tmp);
    if (fd < 0) {
        st = cf__error(diag, CF_STATUS_IO, -1,
                       "cannot create a temporary file for \"%s\": %s",
                       path, strerror(errno));
        cf__free(tmp);
        return st;
    }
    while (off < n) {
        ssize_t w = write(fd, data + off, n - off);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0) {
            st = cf__error(diag, CF_STATUS_IO, -1,
                           "cannot write \"%s\": %s", tmp,
                           w < 0 ? strerror(errno) : "no progress");
            break;
        }
        off += (size_t)w;
    }
    if (st == CF_STATUS_OK && fchmod(fd, 0644) != 0)
        st = cf__error(diag, CF_STATUS_IO, -1, "cannot chmod \"%s\": %s",
                       tmp, strerror(errno));
    if (close(fd) != 0 && st == CF_STATUS_OK)
        st = cf__error(diag, CF_STATUS_IO, -1, "cannot close \"%s\": %s",
                       tmp, strerror(errno));
    if (st == CF_STATUS_OK && rename(tmp, path) != 0)
        st = cf__error(diag, CF_STATUS_IO, -1,
                       "cannot rename the temporary file to \"%s\": %s",
                       path, strerror(errno));
    if (st != CF_STATUS_OK)
        unlink(tmp);
    cf__free(tmp);
    return st;
}

cf_status_t
cf_figure_write(cf_figure_t *fig, const char *path, cf_format_t format,
                const cf_write_options_t *options, cf_diag_t *diag)
{
    cf__buf_t buf;
    cf_status_t st;

    if (path == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "path is NULL");
    st = render_checked(fig, format, options, &buf, diag);
    if (st != CF_STATUS_OK)
        return st;
    st = write_atomic(path, buf.data, buf.size, diag);
    cf__buf_free(&buf);
    return st;
}

cf_status_t
cf_figure_write_all(cf_figure_t *fig, const char *basename, unsigned formats,
                    const cf_write_options_t *options, cf_diag_t *diag)
{
    cf_write_options_t o;
    cf__layout_t lay;
    page_t pg;
    cf__buf_t ps;
    bool derive_eps;
    size_t n;
    int f;
    char *path;
    cf_status_t st;

    if (basename == NULL || basename[0] == '\0')
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "base name is NULL or empty");
    if (formats == 0 || (formats >> CF_FORMAT_LAST_) != 0)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "format set 0x%x is empty or has unknown bits",
                         formats);
    st = check_fig_format(fig, CF_FORMAT_SVG, diag);
    if (st == CF_STATUS_OK)
        st = options_or_default(options, &o, diag);
    /* one layout for every format: the page is the same */
    if (st == CF_STATUS_OK)
        st = make_page(fig, &o, false, &lay, &pg, diag);
    if (st != CF_STATUS_OK)
        return st;
    n = strlen(basename);
    path = cf__malloc(n + 8);
    if (path == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory for a file name");
    /* PS before EPS in format order; the EPS is derived from the PS */
    derive_eps = (formats & CF_FORMAT_BIT(CF_FORMAT_PS))
        && (formats & CF_FORMAT_BIT(CF_FORMAT_EPS))
        && cairo_version() == CAIRO_VERSION_ENCODE(1, 16, 0);
    memset(&ps, 0, sizeof ps);
    for (f = 0; f < CF_FORMAT_LAST_ && st == CF_STATUS_OK; f++) {
        cf__buf_t buf;
        int r = -1;
        if (!(formats & CF_FORMAT_BIT(f)))
            continue;
        snprintf(path, n + 8, "%s.%s", basename, format_names[f]);
        memset(&buf, 0, sizeof buf);
        if (f == CF_FORMAT_EPS && ps.data != NULL) {
            r = eps_from_ps(&ps, &buf);
            if (r == -2)
                st = cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                               "out of memory writing eps");
            else if (r == -1)
                cf__buf_free(&buf);
        }
        if (r == -1)
            st = render_page(fig, (cf_format_t)f, &o, &lay, &pg, &buf,
                             diag);
        if (st == CF_STATUS_OK)
            st = write_atomic(path, buf.data, buf.size, diag);
        if (f == CF_FORMAT_PS && derive_eps && st == CF_STATUS_OK) {
            ps = buf;
            memset(&buf, 0, sizeof buf);
        }
        cf__buf_free(&buf);
    }
    cf__buf_free(&ps);
    cf__free(path);
    return st;
}
