/*
** Image files for `compare` and `test`; see imgfile.h.
*/
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef CF_TOOL_HAVE_RSVG
#include <librsvg/rsvg.h>
#endif

#include "imgfile.h"
#include "tool.h"

/* the renderer's own bound on a PNG side */
#define MAX_SIDE 32000

typedef enum kind { KIND_UNREADABLE, KIND_UNKNOWN, KIND_PNG, KIND_SVG,
                    KIND_PDF } kind;

/* The kind of file by its first bytes; errno is kept when unreadable. */
static kind
sniff(const char *path)
{
    unsigned char head[4096];
    size_t n, i = 0;
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        return KIND_UNREADABLE;
    n = fread(head, 1, sizeof head - 1, f);
    if (ferror(f)) {
        int e = errno;
        fclose(f);
        errno = e != 0 ? e : EIO;
        return KIND_UNREADABLE;
    }
    fclose(f);
    head[n] = '\0';
    if (n >= 8 && memcmp(head, "\x89PNG\r\n\x1a\n", 8) == 0)
        return KIND_PNG;
    if (n >= 5 && memcmp(head, "%PDF-", 5) == 0)
        return KIND_PDF;
    if (n >= 3 && memcmp(head, "\xef\xbb\xbf", 3) == 0)
        i = 3;
    while (i < n && (head[i] == ' ' || head[i] == '\t' || head[i] == '\r' ||
                     head[i] == '\n'))
        i++;
    if (i < n && head[i] == '<' && memchr(head, '\0', n) == NULL &&
        strstr((const char *)head, "<svg") != NULL)
        return KIND_SVG;
    return KIND_UNKNOWN;
}

const char *
cf__tool_image_kind(const char *path)
{
    switch (sniff(path)) {
    case KIND_PNG: return "PNG";
    case KIND_SVG: return "SVG";
    case KIND_PDF: return "PDF";
    default: return "?";
    }
}

/* A copy in ARGB32 (cairo reads a PNG without alpha as RGB24). */
static cairo_surface_t *
to_argb32(cairo_surface_t *s)
{
    cairo_surface_t *img = cairo_image_surface_create(
        CAIRO_FORMAT_ARGB32, cairo_image_surface_get_width(s),
        cairo_image_surface_get_height(s));
    cairo_t *cr = cairo_create(img);
    cairo_set_source_surface(cr, s, 0, 0);
    cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
    cairo_paint(cr);
    cairo_destroy(cr);
    cairo_surface_flush(img);
    if (cairo_surface_status(img) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(img);
        return NULL;
    }
    return img;
}

static cairo_surface_t *
read_png(const char *path, char *err, size_t errsize)
{
    cairo_surface_t *s = cairo_image_surface_create_from_png(path), *img;
    cairo_status_t st = cairo_surface_status(s);
    if (st != CAIRO_STATUS_SUCCESS) {
        snprintf(err, errsize, "%s: not a readable PNG file (%s)", path,
                 cairo_status_to_string(st));
        cairo_surface_destroy(s);
        return NULL;
    }
    img = to_argb32(s);
    cairo_surface_destroy(s);
    if (img == NULL)
        snprintf(err, errsize, "%s: out of memory", path);
    return img;
}

#ifdef CF_TOOL_HAVE_RSVG
static cairo_surface_t *
read_svg(const char *path, double dpi, char *err, size_t errsize)
{
    GError *gerr = NULL;
    RsvgHandle *hd = rsvg_handle_new_from_file(path, &gerr);
    cairo_surface_t *img;
    cairo_t *cr;
    gdouble sw, sh;
    double wpx, hpx;
    RsvgRectangle vp;
    if (hd == NULL) {
        snprintf(err, errsize, "%s: librsvg cannot read the SVG: %s", path,
                 gerr != NULL ? gerr->message : "unknown error");
        if (gerr != NULL)
            g_error_free(gerr);
        return NULL;
    }
    rsvg_handle_set_dpi(hd, dpi);
    if (!rsvg_handle_get_intrinsic_size_in_pixels(hd, &sw, &sh) ||
        !(sw > 0 && sh > 0)) {
        snprintf(err, errsize, "%s: the SVG has no width and height in "
                 "absolute units, so it has no size at %g dpi", path, dpi);
        g_object_unref(hd);
        return NULL;
    }
    wpx = ceil(sw - 1e-6);
    hpx = ceil(sh - 1e-6);
    if (wpx > MAX_SIDE || hpx > MAX_SIDE) {
        snprintf(err, errsize, "%s: %.0fx%.0f pixels at %g dpi is too large "
                 "(at most %d a side); lower the dpi", path, wpx, hpx, dpi,
                 MAX_SIDE);
        g_object_unref(hd);
        return NULL;
    }
    img = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, (int)wpx, (int)hpx);
    cr = cairo_create(img);
    vp.x = 0;
    vp.y = 0;
    vp.width = sw;
    vp.height = sh;
    if (!rsvg_handle_render_document(hd, cr, &vp, &gerr)) {
        snprintf(err, errsize, "%s: librsvg cannot render the SVG: %s", path,
                 gerr != NULL ? gerr->message : "unknown error");
        if (gerr != NULL)
            g_error_free(gerr);
        cairo_destroy(cr);
        cairo_surface_destroy(img);
        g_object_unref(hd);
        return NULL;
    }
    cairo_destroy(cr);
    g_object_unref(hd);
    cairo_surface_flush(img);
    return img;
}
#endif

double
cf__tool_png_dpi(const char *path)
{
    static const unsigned char sig[8] = { 0x89, 'P', 'N', 'G', '\r', '\n',
                                          0x1a, '\n' };
    unsigned char head[8], chunk[8], body[9];
    double dpi = 0;
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        return 0;
    if (fread(head, 1, 8, f) != 8 || memcmp(head, sig, 8) != 0) {
        fclose(f);
        return 0;
    }
    /* the chunks before the image data: length, type, body, CRC */
    while (fread(chunk, 1, 8, f) == 8 && memcmp(chunk + 4, "IDAT", 4) != 0) {
        unsigned long n = (unsigned long)chunk[0] << 24 | chunk[1] << 16
                        | chunk[2] << 8 | chunk[3];
        if (memcmp(chunk + 4, "pHYs", 4) == 0 && n == 9) {
            if (fread(body, 1, 9, f) == 9 && body[8] == 1) {
                unsigned long ppm = (unsigned long)body[0] << 24
                                  | body[1] << 16 | body[2] << 8 | body[3];
                dpi = (double)ppm * 0.0254;
                if (fabs(dpi - floor(dpi + 0.5)) < 0.05)
                    dpi = floor(dpi + 0.5);
            }
            break;
        }
        if (n > 0x7fffffffUL || fseek(f, (long)n + 4, SEEK_CUR) != 0)
            break;
    }
    fclose(f);
    return dpi;
}

cairo_surface_t *
cf__tool_image_read(const char *path, double dpi, char *err, size_t errsize)
{
    switch (sniff(path)) {
    case KIND_UNREADABLE:
        snprintf(err, errsize, "%s: cannot read it: %s", path,
                 strerror(errno));
        return NULL;
    case KIND_PNG:
        return read_png(path, err, errsize);
    case KIND_SVG:
#ifdef CF_TOOL_HAVE_RSVG
        return read_svg(path, dpi, err, errsize);
#else
        snprintf(err, errsize, "%s: an SVG, but this curvefig was built "
                 "without librsvg and cannot rasterise SVG; compare PNGs",
                 path);
        return NULL;
#endif
    case KIND_PDF:
        snprintf(err, errsize, "%s: a PDF; curvefig compares PNG and SVG "
                 "files only (it has no PDF rasteriser): compare the "
                 "figure's SVG or PNG instead", path);
        return NULL;
    default:
        snprintf(err, errsize, "%s: not an image curvefig can read (a PNG "
                 "or an SVG file)", path);
        return NULL;
    }
}

static cf__imgcmp_image
view(cairo_surface_t *s)
{
    cf__imgcmp_image im;
    im.width = cairo_image_surface_get_width(s);
    im.height = cairo_image_surface_get_height(s);
    im.stride = cairo_image_surface_get_stride(s);
    im.data = cairo_image_surface_get_data(s);
    return im;
}

int
cf__tool_image_compare(cairo_surface_t *actual, cairo_surface_t *expected,
                       const cf__imgcmp_options *opt, cf__imgcmp_result *res,
                       cairo_surface_t **diff)
{
    cf__imgcmp_image a = view(actual), e = view(expected);
    cairo_surface_t *d = NULL;
    unsigned char *buf = NULL;
    int rc;
    if (diff != NULL)
        *diff = NULL;
    if (a.width != e.width || a.height != e.height) {
        memset(res, 0, sizeof *res);
        return -1;
    }
    if (diff != NULL) {
        d = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, a.width,
                                       a.height);
        if (cairo_surface_status(d) != CAIRO_STATUS_SUCCESS ||
            cairo_image_surface_get_stride(d) != 4 * a.width) {
            cairo_surface_destroy(d);
            d = NULL;
        } else {
            cairo_surface_flush(d);
            buf = cairo_image_surface_get_data(d);
        }
    }
    rc = cf__imgcmp_compare(&a, &e, opt, res, buf);
    if (d != NULL) {
        cairo_surface_mark_dirty(d);
        *diff = d;
    }
    return rc;
}

/* n with thousands separators */
static void
grouped(char *buf, size_t size, long n)
{
    char digits[32];
    int len = snprintf(digits, sizeof digits, "%ld", n), o = 0;
    for (int i = 0; i < len && (size_t)o + 2 < size; i++) {
        if (i > 0 && (len - i) % 3 == 0 && digits[0] != '-')
            buf[o++] = ',';
        buf[o++] = digits[i];
    }
    buf[o] = '\0';
}

void
cf__tool_image_verdict(char *buf, size_t size, const cf__imgcmp_result *r,
                       const cf__imgcmp_options *opt, long pixels)
{
    char bad[32], all[32], aa[32];
    double share = pixels > 0 ? 100.0 * (double)r->bad_pixels /
                                    (double)pixels : 0.0;
    grouped(bad, sizeof bad, r->bad_pixels);
    grouped(all, sizeof all, pixels);
    grouped(aa, sizeof aa, r->aa_pixels);
    if (r->identical)
        snprintf(buf, size, "same: the %s pixels are identical", all);
    else if (r->bad_pixels == 0 && r->aa_pixels == 0)
        snprintf(buf, size, "same: no pixel of %s differs by more than the "
                 "threshold %g (largest difference %.3f)", all,
                 opt->threshold, r->max_delta);
    else if (r->bad_pixels == 0)
        snprintf(buf, size, "same: %s pixels of %s differ by anti-aliasing "
                 "only (%.3f %%); largest difference %.3f", aa, all,
                 100.0 * (double)r->aa_pixels / (double)pixels,
                 r->max_delta);
    else
        snprintf(buf, size, "%s: %s of %s pixels differ (%.3f %%, %s %ld "
                 "allowed), %s more by anti-aliasing only; largest "
                 "difference %.3f", r->match ? "same" : "different", bad,
                 all, share, r->match ? "within the" : "over the",
                 opt->max_bad_pixels, aa, r->max_delta);
}

static cairo_status_t
write_stream(void *closure, const unsigned char *data, unsigned int length)
{
    return fwrite(data, 1, length, (FILE *)closure) == length
               ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

int
cf__tool_image_write_png(cairo_surface_t *s, const char *path)
{
    cf__tool_out out;
    if (cf__tool_open_atomic(&out, path) != 0)
        return -1;
    if (cairo_surface_write_to_png_stream(s, write_stream, out.f) !=
        CAIRO_STATUS_SUCCESS) {
        cf__tool_discard_atomic(&out);
        errno = EIO;
        return -1;
    }
    return cf__tool_close_atomic(&out);
}
