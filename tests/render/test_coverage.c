/* The coverage of the measuring seam's rasterizer (render/backends/coverage.c)
** against an independent computation of the same sampling, and painting
** within a box (cf__raster_paint_in).
**
** Random polygons of 3 to 60 points (self-intersecting, wound either way,
** some reaching past the raster) filled by the nonzero rule: on each of
** the 4 sub-scanlines of a pixel row the test finds every edge's crossing
** in long double, sorts them, walks the winding number and adds the
** length of each covered interval inside each pixel; a pixel's byte is
** then 255 times the sum (a quarter per sub-scanline), clamped to 1.  The
** rasterizer sums the same fractions in float: its bytes may differ by
** one level from rounding, never more.
**
** cf__raster_paint_in: the pixels inside the box are those of a paint of
** the whole raster, the ones outside keep what they had; the raster's
** dirty box holds every pixel changed, and its cut flag says whether the
** polygon reached beyond the box.  A paint of some rows only (the
** raster's rows): those rows are a paint of the whole raster's, the
** others keep what they had, polygons of many equal crossings (points
** on a coarse grid, vertical edges along each other) included.
**
** A polygon kept for its box alone (box_only, the ink boxes' mode) has
** the box of the same polygon with its edges kept, to the last bit, and
** fails alike: random strokes of lines, cubics, rectangles and arcs, open
** and closed, with each cap and join, dashed or not, some with a point
** at infinity.  A pattern too fine to measure is stroked solid and
** reports the part of the line it inks (cairo's estimate: a half for
** equal on and off with butt caps, a quarter disc more a dash with round
** caps), one along too long a path too; a pattern as usual reports 1. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "measure.h"
#include "raster.h"

#define W 64
#define H 48
#define SUB 4
#define MAXP 60

/* A small reproducible generator (xorshift64*). */
static uint64_t rng_state = 0x9e3779b97f4a7c15u;

static double
uniform(double lo, double hi)
{
    uint64_t x = rng_state;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    rng_state = x;
    return lo + (hi - lo) * (double)((x * 0x2545f4914f6cdd1du) >> 11)
                * (1.0 / 9007199254740992.0);
}

typedef struct xing { long double x; int dir; } xing_t;

static int
cmp_xing(const void *a, const void *b)
{
    long double d = ((const xing_t *)a)->x - ((const xing_t *)b)->x;
    return d < 0 ? -1 : d > 0;
}

/* The expected bytes of polygon p (n points, pixel units) into out. */
static void
reference(const double *p, int n, unsigned char *out)
{
    static long double cov[W];
    xing_t xs[MAXP];
    int y, k, i, m, e;
    for (y = 0; y < H; y++) {
        memset(cov, 0, sizeof cov);
        for (k = 0; k < SUB; k++) {
            long double sy = y + (k + 0.5L) / SUB;
            int wind = 0;
            long double start = 0;
            for (m = 0, e = 0; e < n; e++) {
                long double x0 = p[2 * e], y0 = p[2 * e + 1];
                long double x1 = p[2 * ((e + 1) % n)];
                long double y1 = p[2 * ((e + 1) % n) + 1];
                int dir = y1 > y0 ? 1 : -1;
                if (y1 < y0) {
                    long double t = x0;
                    x0 = x1;
                    x1 = t;
                    t = y0;
                    y0 = y1;
                    y1 = t;
                }
                if (!(y0 <= sy && sy < y1))
                    continue;
                xs[m].x = x0 + (sy - y0) * (x1 - x0) / (y1 - y0);
                xs[m++].dir = dir;
            }
            qsort(xs, (size_t)m, sizeof *xs, cmp_xing);
            for (e = 0; e < m; e++) {
                bool was = wind != 0;
                wind += xs[e].dir;
                if (!was && wind != 0) {
                    start = xs[e].x;
                } else if (was && wind == 0) {
                    for (i = 0; i < W; i++) {
                        long double a = fmaxl(start, i);
                        long double b = fminl(xs[e].x, i + 1);
                        if (b > a)
                            cov[i] += (b - a) / SUB;
                    }
                }
            }
        }
        for (i = 0; i < W; i++)
            out[y * W + i] = (unsigned char)(255 * fminl(cov[i], 1) + 0.5L);
    }
}

static void
polygon_dl(cf__dl_t *dl, const double *p, int n)
{
    cf__paint_t paint;
    int i;
    memset(&paint, 0, sizeof paint);
    paint.fill = true;
    paint.fill_color.a = 1;
    paint.fill_opacity = 1;
    cf__dl_reset(dl);
    cf__dl_path_begin(dl);
    for (i = 0; i < n; i++) {
        /* page bp: the raster has 2 pixels a bp */
        if (i == 0)
            cf__dl_move(dl, p[0] / 2, p[1] / 2);
        else
            cf__dl_line(dl, p[2 * i] / 2, p[2 * i + 1] / 2);
    }
    cf__dl_close(dl);
    cf__dl_path_paint(dl, &paint);
}

static void
test_random_polygons(void **state)
{
    static unsigned char want[W * H];
    double p[2 * MAXP];
    cf__dl_t dl;
    int t, i, worst = 0;
    (void)state;
    cf__dl_init(&dl);
    for (t = 0; t < 300; t++) {
        cf__raster_t r;
        int n = 3 + (int)uniform(0, MAXP - 3);
        for (i = 0; i < n; i++) {
            /* points on the pixel grid's quarters now and then: crossings
            ** through vertices and edges along sub-scanlines */
            p[2 * i] = uniform(-8, W + 8);
            p[2 * i + 1] = uniform(-8, H + 8);
            if (t % 3 == 0) {
                p[2 * i] = floor(4 * p[2 * i]) / 4;
                p[2 * i + 1] = floor(8 * p[2 * i + 1]) / 8;
            }
        }
        polygon_dl(&dl, p, n);
        assert_int_equal(cf__raster_open(&r, W, H, 2.0, 0, 0), 0);
        assert_int_equal(cf__raster_paint(&r, &dl, 0, dl.count), 0);
        reference(p, n, want);
        for (i = 0; i < W * H; i++) {
            int d = abs((int)r.px[i] - (int)want[i]);
            worst = d > worst ? d : worst;
        }
        cf__raster_close(&r);
    }
    cf__dl_free(&dl);
    assert_true(worst <= 1);
}

/* Whether polygon p (n points, pixel units) has a pixel outside box b
** (i0 j0 i1 j1): its points' box, rounded out, not inside b. */
static bool
reaches_beyond(const double *p, int n, const int b[4])
{
    double x0 = p[0], y0 = p[1], x1 = p[0], y1 = p[1];
    int i, c[4];
    for (i = 1; i < n; i++) {
        x0 = fmin(x0, p[2 * i]);
        x1 = fmax(x1, p[2 * i]);
        y0 = fmin(y0, p[2 * i + 1]);
        y1 = fmax(y1, p[2 * i + 1]);
    }
    /* the box measure.c paints within: b cut to the raster */
    c[0] = b[0] > 0 ? b[0] : 0;
    c[1] = b[1] > 0 ? b[1] : 0;
    c[2] = b[2] < W ? b[2] : W;
    c[3] = b[3] < H ? b[3] : H;
    if (c[2] <= c[0] || c[3] <= c[1])
        return false;   /* nothing painted */
    return floor(x0) < c[0] || floor(y0) < c[1] || ceil(x1) > c[2]
           || ceil(y1) > c[3];
}

static void
test_paint_in(void **state)
{
    double p[2 * MAXP];
    cf__dl_t dl;
    int t, i, j;
    (void)state;
    cf__dl_init(&dl);
    for (t = 0; t < 50; t++) {
        cf__raster_t all, part;
        int b[4], n = 3 + (int)uniform(0, MAXP - 3);
        for (i = 0; i < n; i++) {
            p[2 * i] = uniform(-8, W + 8);
            p[2 * i + 1] = uniform(-8, H + 8);
        }
        b[0] = (int)uniform(-4, W);
        b[1] = (int)uniform(-4, H);
        b[2] = b[0] + (int)uniform(0, W);
        b[3] = b[1] + (int)uniform(0, H);
        polygon_dl(&dl, p, n);
        assert_int_equal(cf__raster_open(&all, W, H, 2.0, 0, 0), 0);
        assert_int_equal(cf__raster_open(&part, W, H, 2.0, 0, 0), 0);
        memset(part.px, 77, (size_t)W * H);
        assert_int_equal(cf__raster_paint(&all, &dl, 0, dl.count), 0);
        cf__raster_clear(&part, b);
        part.dirty[0] = part.dirty[1] = part.dirty[2] = part.dirty[3] = 0;
        part.cut = false;
        assert_int_equal(cf__raster_paint_in(&part, &dl, 0, dl.count, b), 0);
        for (j = 0; j < H; j++)
            for (i = 0; i < W; i++) {
                bool in = i >= b[0] && i < b[2] && j >= b[1] && j < b[3];
                assert_int_equal(part.px[j * W + i],
                                 in ? all.px[j * W + i] : 77);
                if (in && part.px[j * W + i] != 0)
                    assert_true(i >= part.dirty[0] && i < part.dirty[2]
                                && j >= part.dirty[1]
                                && j < part.dirty[3]);
            }
        assert_true(part.cut == reaches_beyond(p, n, b));
        cf__raster_close(&all);
        cf__raster_close(&part);
    }
    cf__dl_free(&dl);
}

static void
test_paint_rows(void **state)
{
    static unsigned char rows[H];
    double p[2 * MAXP];
    cf__dl_t dl;
    int t, i, j;
    (void)state;
    cf__dl_init(&dl);
    for (t = 0; t < 300; t++) {
        cf__raster_t all, part;
        int n = 3 + (int)uniform(0, MAXP - 3);
        for (i = 0; i < n; i++) {
            p[2 * i] = uniform(-8, W + 8);
            p[2 * i + 1] = uniform(-8, H + 8);
            if (t % 2 == 0) {
                /* a coarse grid off the pixels' edges: many edges
                ** along each other, crossing pixels part way */
                p[2 * i] = floor(p[2 * i] / 8) * 8 + 0.37;
                p[2 * i + 1] = floor(p[2 * i + 1] / 4) * 4 + 0.1;
            }
        }
        for (j = 0; j < H; j++)
            rows[j] = uniform(0, 1) < (t % 3 + 1) / 4.0;
        polygon_dl(&dl, p, n);
        assert_int_equal(cf__raster_open(&all, W, H, 2.0, 0, 0), 0);
        assert_int_equal(cf__raster_open(&part, W, H, 2.0, 0, 0), 0);
        memset(all.px, 40, (size_t)W * H);
        memset(part.px, 40, (size_t)W * H);
        assert_int_equal(cf__raster_paint(&all, &dl, 0, dl.count), 0);
        part.rows = rows;
        assert_int_equal(cf__raster_paint(&part, &dl, 0, dl.count), 0);
        for (j = 0; j < H; j++)
            for (i = 0; i < W; i++)
                assert_int_equal(part.px[j * W + i],
                                 rows[j] ? all.px[j * W + i] : 40);
        cf__raster_close(&all);
        cf__raster_close(&part);
    }
    cf__dl_free(&dl);
}

/* A random path of 1 to 6 segments into segs and v (pixel units). */
static size_t
random_path(unsigned char *segs, double *v, size_t *nv)
{
    size_t n = 1 + (size_t)uniform(0, 6), k, m = 0;
    segs[0] = CF__SEG_MOVE;
    v[m++] = uniform(-8, W + 8);
    v[m++] = uniform(-8, H + 8);
    for (k = 1; k <= n; k++) {
        int kind = (int)uniform(0, 5);
        int c;
        segs[k] = kind == 0 ? CF__SEG_CURVE : kind == 1 ? CF__SEG_RECT
                : kind == 2 ? CF__SEG_ARC : kind == 3 && k == n
                ? CF__SEG_CLOSE : CF__SEG_LINE;
        c = segs[k] == CF__SEG_CURVE ? 6 : segs[k] == CF__SEG_RECT ? 4
          : segs[k] == CF__SEG_ARC ? 5 : segs[k] == CF__SEG_CLOSE ? 0 : 2;
        for (int j = 0; j < c; j++)
            v[m++] = uniform(-8, j % 2 ? H + 8 : W + 8);
        if (segs[k] == CF__SEG_ARC) {
            v[m - 3] = uniform(0.5, 20);
            v[m - 2] = uniform(-7, 7);
            v[m - 1] = uniform(-7, 7);
        }
        if (segs[k] == CF__SEG_CLOSE)
            return (*nv = m, k + 1);
    }
    *nv = m;
    return n + 1;
}

static void
test_box_only(void **state)
{
    static const double dashes[3][2] = { { 2, 1 }, { 0.5, 3 }, { 4, 0 } };
    unsigned char segs[8];
    double v[64];
    int t, same = 0, failed = 0;
    (void)state;
    for (t = 0; t < 3000; t++) {
        cf__poly_t full, box;
        cf__path_t p;
        size_t nv;
        cf__xform_t m = { uniform(0.5, 64), uniform(-50, 50),
                          uniform(-50, 50), 0.1 };
        cf__pen_t pen = { uniform(0.01, 6), (cf__cap_t)(t % 2),
                          (cf__join_t)(t / 2 % 2), NULL, 0 };
        p.segs = segs;
        p.coords = v;
        p.nsegs = random_path(segs, v, &nv);
        if (t % 3 == 0) {
            pen.dash = dashes[t / 3 % 3];
            pen.ndash = 2;
        }
        if (t % 97 == 0)
            v[(size_t)uniform(0, (double)nv)] = INFINITY;
        cf__poly_init(&full);
        cf__poly_init(&box);
        box.box_only = true;
        cf__poly_stroke(&full, &p, &m, &pen, NULL);
        cf__poly_stroke(&box, &p, &m, &pen, NULL);
        assert_int_equal(full.failed, box.failed);
        failed += full.failed;
        if (!full.failed) {
            assert_memory_equal(full.box, box.box, sizeof full.box);
            same++;
        }
        assert_int_equal(box.n, 0);
        cf__poly_free(&full);
        cf__poly_free(&box);
    }
    printf("# %d strokes with the same box, %d failing in both\n", same,
           failed);
    assert_true(same > 2900);
    assert_true(failed > 0);
}

static void
test_fine_dash_coverage(void **state)
{
    static const unsigned char segs[] = { CF__SEG_MOVE, CF__SEG_LINE };
    static const double fine[2] = { 1e-6, 1e-6 }, usual[2] = { 2, 1 };
    double v[4] = { 0, 0, 40, 30 }, cov;
    cf__path_t p = { segs, v, 2 };
    cf__xform_t m = { 2, 0, 0, 0.1 };
    cf__pen_t pen = { 1, CF__CAP_BUTT, CF__JOIN_MITER, fine, 2 };
    cf__poly_t pl;
    (void)state;
    cf__poly_init(&pl);
    cf__poly_stroke(&pl, &p, &m, &pen, &cov);
    assert_true(cov == 0.5);
    assert_true(pl.n > 0 && pl.n <= 8);          /* one solid piece */
    cf__poly_reset(&pl);
    pen.cap = CF__CAP_ROUND;
    cf__poly_stroke(&pl, &p, &m, &pen, &cov);
    assert_true(fabs(cov - (0.5 + 3.14159265358979323846 / 8)) < 1e-12);
    cf__poly_reset(&pl);
    pen.cap = CF__CAP_BUTT;
    pen.dash = usual;
    cf__poly_stroke(&pl, &p, &m, &pen, &cov);
    assert_true(cov == 1);
    assert_true(pl.n > 8 * 4);                    /* its 16 dashes */
    cf__poly_reset(&pl);
    v[2] = 1e12;                                  /* 3e11 dashes: too many */
    cf__poly_stroke(&pl, &p, &m, &pen, &cov);
    assert_true(fabs(cov - 2.0 / 3) < 1e-15);
    assert_true(pl.n > 0 && pl.n <= 8);
    cf__poly_free(&pl);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_polygons),
        cmocka_unit_test(test_paint_in),
        cmocka_unit_test(test_paint_rows),
        cmocka_unit_test(test_box_only),
        cmocka_unit_test(test_fine_dash_coverage),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
