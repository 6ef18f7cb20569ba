/*
** The image comparator; see imgcmp.h.
**
** The colour distance is the YIQ measure of Kotsarenko & Ramos (2010), as
** used by pixelmatch: delta = 0.5053 dY^2 + 0.299 dI^2 + 0.1957 dQ^2 on
** 0..255 channels, whose largest value (black against white) is 35215.  We
** report sqrt(delta / 35215), so a threshold t here means what pixelmatch's
** `threshold` means.
*/
#include <math.h>
#include <string.h>

#include "imgcmp.h"

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
cf__imgcmp_pixel_delta(uint32_t a, uint32_t b)
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
px(const cf__imgcmp_image *im, int x, int y)
{
    uint32_t v;
    memcpy(&v, im->data + (size_t)y * (size_t)im->stride + 4 * (size_t)x,
           sizeof v);
    return v;
}

/* The colours (on white) of im's (2r+1)^2 neighbourhood of (x, y), cut
** at the edges: their range channel by channel, and their mean. */
typedef struct neighbourhood {
    double lo[3], hi[3], mean[3];
} neighbourhood;

static void
survey(const cf__imgcmp_image *im, int x, int y, int r, neighbourhood *nb)
{
    double v[3];
    int n = 0;
    for (int k = 0; k < 3; k++) {
        nb->lo[k] = 1e9;
        nb->hi[k] = -1e9;
        nb->mean[k] = 0.0;
    }
    for (int yy = y - r; yy <= y + r; yy++) {
        if (yy < 0 || yy >= im->height)
            continue;
        for (int xx = x - r; xx <= x + r; xx++) {
            if (xx < 0 || xx >= im->width)
                continue;
            on_white(px(im, xx, yy), &v[0], &v[1], &v[2]);
            for (int k = 0; k < 3; k++) {
                nb->lo[k] = fmin(nb->lo[k], v[k]);
                nb->hi[k] = fmax(nb->hi[k], v[k]);
                nb->mean[k] += v[k];
            }
            n++;
        }
    }
    for (int k = 0; k < 3; k++)
        nb->mean[k] /= n;
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
near_match(const cf__imgcmp_image *im, int x, int y, int r, uint32_t c,
           double t)
{
    neighbourhood nb;
    double v[3], slack = t * 255.0;
    survey(im, x, y, r, &nb);
    on_white(c, &v[0], &v[1], &v[2]);
    for (int k = 0; k < 3; k++)
        if (v[k] < nb.lo[k] - slack || v[k] > nb.hi[k] + slack)
            return 0;
    return 1;
}

/*
** The second allowance: the same ink, placed up to a pixel differently.
** A one-pixel line that one rasteriser puts on one row and the other
** spreads over two half-covered rows has the same mean over the
** neighbourhood; a stroke moved by two pixels or recoloured does not.
*/
static int
same_ink(const cf__imgcmp_image *a, const cf__imgcmp_image *b, int x, int y,
         int r, double t)
{
    neighbourhood na, nb;
    double *ma = na.mean, *mb = nb.mean, d;
    uint32_t pa, pb;
    survey(a, x, y, r, &na);
    survey(b, x, y, r, &nb);
    /* back to opaque pixels, to measure with the YIQ distance */
    pa = 0xff000000u | ((uint32_t)lrint(ma[0]) << 16) |
         ((uint32_t)lrint(ma[1]) << 8) | (uint32_t)lrint(ma[2]);
    pb = 0xff000000u | ((uint32_t)lrint(mb[0]) << 16) |
         ((uint32_t)lrint(mb[1]) << 8) | (uint32_t)lrint(mb[2]);
    d = cf__imgcmp_pixel_delta(pa, pb);
    return d <= t;
}

/* The expected pixel faded: its grey level, mostly white. */
static uint32_t
faded(uint32_t e)
{
    double r, g, b, l;
    unsigned v;
    on_white(e, &r, &g, &b);
    l = 255.0 - 0.1 * (255.0 - (0.299 * r + 0.587 * g + 0.114 * b));
    v = (unsigned)lrint(l);
    return 0xff000000u | (v << 16) | (v << 8) | v;
}

static void
put(unsigned char *diff, int w, int x, int y, uint32_t v)
{
    memcpy(diff + ((size_t)y * (size_t)w + (size_t)x) * 4, &v, sizeof v);
}

int
cf__imgcmp_compare(const cf__imgcmp_image *actual,
                   const cf__imgcmp_image *expected,
                   const cf__imgcmp_options *opt, cf__imgcmp_result *res,
                   unsigned char *diff)
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
                    put(diff, w, x, y, faded(px(expected, x, y)));
        return 0;
    }

    for (int y = 0; y < h; y++) {
        for (int x = 0; x < w; x++) {
            uint32_t a = px(actual, x, y), e = px(expected, x, y);
            double d = cf__imgcmp_pixel_delta(a, e);
            uint32_t out;
            if (d > res->max_delta)
                res->max_delta = d;
            if (d <= opt->threshold) {
                out = faded(e);
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
