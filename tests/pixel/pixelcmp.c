/*
** Image comparison for the pixel tests; see pixelcmp.h.
**
** The colour distance is the YIQ measure of Kotsarenko & Ramos (2010), as
** used by pixelmatch: delta = 0.5053 dY^2 + 0.299 dI^2 + 0.1957 dQ^2 on
** 0..255 channels, whose largest value (black against white) is 35215.  We
** report sqrt(delta / 35215), so a threshold t here means what pixelmatch's
** `threshold` means.
*/
#include <math.h>
#include <string.h>

#include "pixelcmp.h"

#define YIQ_MAX 35215.0

static void
on_white(uint32_t p, double *r, double *g, double *b)
{
    /* premultiplied ARGB32: composite over white: c + (255 - a) */
    double a = (double)((p >> 24) & 0xff);
    *r = (double)((p >> 16) & 0xff) + 255.0 - a;
    *g = (double)((p >> 8) & 0xff) + 255.0 - a;
    *b = (double)(p & 0xff) + 255.0 - a;
}

double
pc_pixel_delta(uint32_t a, uint32_t b)
{
    double r1, g1, b1, r2, g2, b2, y, i, q, d;
    if (a == b)
        return 0.0;
    on_white(a, &r1, &g1, &b1);
    on_white(b, &r2, &g2, &b2);
    y = 0.29889531 * (r1 - r2) + 0.58662247 * (g1 - g2) +
        0.11448223 * (b1 - b2);
    i = 0.59597799 * (r1 - r2) - 0.27417610 * (g1 - g2) -
        0.32180189 * (b1 - b2);
    q = 0.21147017 * (r1 - r2) - 0.52261711 * (g1 - g2) +
        0.31114694 * (b1 - b2);
    d = 0.5053 * y * y + 0.299 * i * i + 0.1957 * q * q;
    return sqrt(fmin(d / YIQ_MAX, 1.0));
}

static uint32_t
px(const pc_image *im, int x, int y)
{
    uint32_t v;
    memcpy(&v, im->data + (size_t)y * (size_t)im->stride + 4 * (size_t)x,
           sizeof v);
    return v;
}

/*
** Anti-aliasing allowance: is colour c (composited on white) inside the
** range of colours of im's (2r+1)^2 neighbourhood of (x, y), channel by
** channel, widened by t * 255?  An edge that another rasteriser placed a
** fraction of a pixel elsewhere gives intermediate colours between its
** neighbours' colours; a moved or recoloured stroke gives colours that are
** not there at all.
*/
static int
near_match(const pc_image *im, int x, int y, int r, uint32_t c, double t)
{
    double lo[3] = { 1e9, 1e9, 1e9 }, hi[3] = { -1e9, -1e9, -1e9 }, v[3];
    double slack = t * 255.0;
    for (int dy = -r; dy <= r; dy++) {
        int yy = y + dy;
        if (yy < 0 || yy >= im->height)
            continue;
        for (int dx = -r; dx <= r; dx++) {
            int xx = x + dx;
            if (xx < 0 || xx >= im->width)
                continue;
            on_white(px(im, xx, yy), &v[0], &v[1], &v[2]);
            for (int k = 0; k < 3; k++) {
                if (v[k] < lo[k])
                    lo[k] = v[k];
                if (v[k] > hi[k])
                    hi[k] = v[k];
            }
        }
    }
    on_white(c, &v[0], &v[1], &v[2]);
    for (int k = 0; k < 3; k++)
        if (v[k] < lo[k] - slack || v[k] > hi[k] + slack)
            return 0;
    return 1;
}

/* Mean colour (on white) of the (2r+1)^2 neighbourhood of (x, y). */
static void
box_mean(const pc_image *im, int x, int y, int r, double *m)
{
    double v[3];
    int n = 0;
    m[0] = m[1] = m[2] = 0.0;
    for (int dy = -r; dy <= r; dy++) {
        int yy = y + dy;
        if (yy < 0 || yy >= im->height)
            continue;
        for (int dx = -r; dx <= r; dx++) {
            int xx = x + dx;
            if (xx < 0 || xx >= im->width)
                continue;
            on_white(px(im, xx, yy), &v[0], &v[1], &v[2]);
            m[0] += v[0];
            m[1] += v[1];
            m[2] += v[2];
            n++;
        }
    }
    m[0] /= n;
    m[1] /= n;
    m[2] /= n;
}

/*
** The second allowance: the same ink, placed up to a pixel differently.
** A one-pixel line that one rasteriser puts on one row and the other
** spreads over two half-covered rows has the same mean over the
** neighbourhood; a stroke moved by two pixels or recoloured does not.
*/
static int
same_ink(const pc_image *a, const pc_image *b, int x, int y, int r, double t)
{
    double ma[3], mb[3], d;
    uint32_t pa, pb;
    box_mean(a, x, y, r, ma);
    box_mean(b, x, y, r, mb);
    /* back to opaque pixels, to measure with the YIQ distance */
    pa = 0xff000000u | ((uint32_t)lrint(ma[0]) << 16) |
         ((uint32_t)lrint(ma[1]) << 8) | (uint32_t)lrint(ma[2]);
    pb = 0xff000000u | ((uint32_t)lrint(mb[0]) << 16) |
         ((uint32_t)lrint(mb[1]) << 8) | (uint32_t)lrint(mb[2]);
    d = pc_pixel_delta(pa, pb);
    return d <= t;
}

static void
put(unsigned char *diff, int w, int x, int y, uint32_t v)
{
    memcpy(diff + ((size_t)y * (size_t)w + (size_t)x) * 4, &v, sizeof v);
}

int
pc_compare(const pc_image *actual, const pc_image *expected,
           const pc_options *opt, pc_result *res, unsigned char *diff)
{
    int w = actual->width, h = actual->height, rows_equal = 1;

    memset(res, 0, sizeof *res);
    if (w != expected->width || h != expected->height)
        return -1;

    for (int y = 0; y < h && rows_equal; y++)
        rows_equal = memcmp(actual->data + (size_t)y * (size_t)actual->stride,
                            expected->data +
                                (size_t)y * (size_t)expected->stride,
                            (size_t)w * 4) == 0;
    if (rows_equal) {
        res->identical = 1;
        res->match = 1;
        if (diff != NULL)
            for (int y = 0; y < h; y++)
                for (int x = 0; x < w; x++)
                    put(diff, w, x, y, 0xffffffffu);
        return 0;
    }

    for (int y = 0; y < h; y++) {
        for (int x = 0; x < w; x++) {
            uint32_t a = px(actual, x, y), e = px(expected, x, y);
            double d = pc_pixel_delta(a, e);
            uint32_t out;
            if (d > res->max_delta)
                res->max_delta = d;
            if (d <= opt->threshold) {
                /* faded expected image: grey level of e, mostly white */
                double r, g, b, l;
                on_white(e, &r, &g, &b);
                l = 255.0 - 0.1 * (255.0 - (0.299 * r + 0.587 * g + 0.114 * b));
                unsigned v = (unsigned)lrint(l);
                out = 0xff000000u | (v << 16) | (v << 8) | v;
            } else if (opt->aa_radius > 0 &&
                       ((near_match(expected, x, y, opt->aa_radius, a,
                                    opt->threshold) &&
                         near_match(actual, x, y, opt->aa_radius, e,
                                    opt->threshold)) ||
                        same_ink(actual, expected, x, y, opt->aa_radius,
                                 opt->threshold))) {
                res->aa_pixels++;
                out = 0xffffd700u;  /* yellow: forgiven */
            } else {
                if (res->bad_pixels < 4) {
                    res->bad_x[res->bad_pixels] = x;
                    res->bad_y[res->bad_pixels] = y;
                }
                res->bad_pixels++;
                out = 0xffff0000u;  /* red: a real difference */
            }
            if (diff != NULL)
                put(diff, w, x, y, out);
        }
    }
    res->match = res->bad_pixels <= opt->max_bad_pixels;
    return 0;
}
