/*
** Image files for `compare` and `test`; see imgfile.h.
*/
#include <errno.h>
#include <stdbool.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

/* Whether the PNG's header (IHDR, the first chunk) names a size that can
** be read: else an error saying what is wrong with it, rather than the
** "out of memory" cairo gives for every file libpng refuses (a header cut
** short, 0 x 0 pixels, 100000 x 100000 pixels). */
static bool
png_header_ok(const char *path, char *err, size_t errsize)
{
    unsigned char h[24];
    unsigned long w, ht;
    FILE *f = fopen(path, "rb");
    size_t n = f != NULL ? fread(h, 1, sizeof h, f) : 0;
    if (f != NULL)
        fclose(f);
    if (n < sizeof h || memcmp(h + 12, "IHDR", 4) != 0) {
        snprintf(err, errsize, "%s: not a readable PNG file (its header, "
                 "IHDR, is %s)", path, n < sizeof h ? "cut short" : "missing");
        return false;
    }
    w = (unsigned long)h[16] << 24 | (unsigned long)h[17] << 16
      | (unsigned long)h[18] << 8 | h[19];
    ht = (unsigned long)h[20] << 24 | (unsigned long)h[21] << 16
       | (unsigned long)h[22] << 8 | h[23];
    if (w == 0 || ht == 0) {
        snprintf(err, errsize, "%s: not a readable PNG file (its header "
                 "gives %lu x %lu pixels)", path, w, ht);
        return false;
    }
    if (w > MAX_SIDE || ht > MAX_SIDE) {
        snprintf(err, errsize, "%s: not a readable PNG file (%lu x %lu "
                 "pixels, more than the %d a side curvefig writes and "
                 "compares)", path, w, ht, MAX_SIDE);
        return false;
    }
    return true;
}

cf__image *
cf__tool_image_read(const char *path, double dpi, char *err, size_t errsize)
{
    switch (sniff(path)) {
    case KIND_UNREADABLE:
        snprintf(err, errsize, "%s: cannot read it: %s", path,
                 strerror(errno));
        return NULL;
    case KIND_PNG:
        return png_header_ok(path, err, errsize)
                   ? cf__image_read_png(path, err, errsize)
                   : NULL;
    case KIND_SVG:
        return cf__image_read_svg(path, dpi, MAX_SIDE, err, errsize);
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
view(const cf__image *im)
{
    cf__imgcmp_image v;
    v.width = im->width;
    v.height = im->height;
    v.stride = im->stride;
    v.data = im->data;
    return v;
}

int
cf__tool_image_compare(const cf__image *actual, const cf__image *expected,
                       const cf__imgcmp_options *opt, cf__imgcmp_result *res,
                       cf__image **diff)
{
    cf__imgcmp_image a = view(actual), e = view(expected);
    cf__image *d = NULL;
    int rc;
    if (diff != NULL)
        *diff = NULL;
    if (a.width != e.width || a.height != e.height) {
        memset(res, 0, sizeof *res);
        return -1;
    }
    if (diff != NULL)
        d = cf__image_new(a.width, a.height);
    rc = cf__imgcmp_compare(&a, &e, opt, res, d != NULL ? d->data : NULL);
    if (diff != NULL)
        *diff = d;
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

int
cf__tool_image_write_png(const cf__image *im, const char *path)
{
    cf__tool_out out;
    if (cf__tool_open_atomic(&out, path) != 0)
        return -1;
    if (cf__image_write_png(im, out.f) != 0) {
        cf__tool_discard_atomic(&out);
        errno = EIO;
        return -1;
    }
    return cf__tool_close_atomic(&out);
}
