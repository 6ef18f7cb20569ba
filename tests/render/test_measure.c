/* The measuring seam (render/backends/measure.h) against independent answers.
**
** Shapes of known area: the coverage a raster sums (bp^2: the sum of its
** pixels / 255 / res^2) is the area of a rectangle, a disc, two discs
** wound alike (nonzero: the larger), a stroked line with and without its
** round caps and a cubic arch (3/5 of its hull), within the
** error of 4 sub-scanlines (at most an eighth of a pixel per pixel of the
** boundary, a row's coverage being exact across it) and of the
** flattening (0.1 pixel at most, inside the curve).
**
** Every shipped figure (the scripts in figures/): the ink box of its
** display list and of each element's group equals cairo's (a recording
** surface's ink extents, rounded out to 1/64 bp as both do) within 0.1
** bp (cairo's round joins at the corners of closed polygons reach up to
** 0.08 bp past the exact disc); and its raster at 2 pixels a bp, drawn by
** cairo's A8 image surface through the cairo backend, sums to the seam's
** ink within 3 %, with at most 3 % of the inked pixels off by more than
** half of full ink (anti-aliased edges of lines thinner than a pixel, and
** glyphs, which cairo puts at whole pixels and the seam where they are;
** the shipped figures measure at most 1.8 % and 1.4 %).
**
** A raster whose rows are made ready where used (cf__raster_ready)
** paints and clears as one cleared whole, and leaves alone the rows
** nothing used. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <cairo.h>

#include "backend.h"
#include "measure.h"
#include "layout-private.h"
#include "shipped.h"

#define PI 3.14159265358979323846
#define RES 2.0
#define UNIT (1.0 / 64)      /* bp: the ink boxes' rounding */
#define INK_MAX 0.1          /* bp: an ink box from cairo's */
#define OFF_MAX 0.03         /* pixels off by more than half, of the inked */
#define SUM_MAX 0.03         /* the whole ink, relative */

/* The coverage of r in bp^2. */
static double
covered(const cf__raster_t *r)
{
    double s = 0;
    int i, j;
    for (j = 0; j < r->h; j++)
        for (i = 0; i < r->w; i++)
            s += r->px[(size_t)j * (size_t)r->stride + (size_t)i];
    return s / 255 / (r->res * r->res);
}

static void
painted(cf__dl_t *dl, double res, double *area, double ink[4])
{
    cf__raster_t r;
    assert_int_equal(cf__raster_open(&r, (int)(100 * res), (int)(100 * res),
                                     res, 0, 0), 0);
    assert_int_equal(cf__raster_paint(&r, dl, 0, dl->count), 0);
    *area = covered(&r);
    cf__raster_close(&r);
    assert_int_equal(cf__dl_ink(dl, 0, dl->count, ink), 0);
    assert_false(dl->failed);
}

static cf__paint_t
solid_fill(void)
{
    cf__paint_t p;
    memset(&p, 0, sizeof p);
    p.fill = true;
    p.fill_color.a = 1;
    p.fill_opacity = 1;
    return p;
}

static void
test_shapes(void **state)
{
    cf__dl_t dl;
    cf__paint_t p = solid_fill();
    double area, ink[4], res;
    (void)state;
    cf__dl_init(&dl);
    for (res = 1; res <= 4; res *= 2) {
        /* a rectangle off the pixel grid: 30.3 x 20.7 */
        cf__dl_reset(&dl);
        cf__dl_path_begin(&dl);
        cf__dl_rect(&dl, 10.1, 20.2, 30.3, 20.7);
        cf__dl_path_paint(&dl, &p);
        painted(&dl, res, &area, ink);
        /* boundary pixels: 2 (30.3 + 20.7) res, each off by 1/8 at most */
        assert_true(fabs(area - 30.3 * 20.7) <= 0.25 * (30.3 + 20.7) / res);
        assert_true(fabs(ink[0] - 10.1) <= UNIT && fabs(ink[3] - 40.9) <= UNIT);
        /* a disc of radius 15 (an arc from 0 to 2 pi) */
        cf__dl_reset(&dl);
        cf__dl_path_begin(&dl);
        cf__dl_arc(&dl, 50, 50, 15, 0, 2 * PI);
        cf__dl_close(&dl);
        cf__dl_path_paint(&dl, &p);
        painted(&dl, res, &area, ink);
        assert_true(fabs(area - PI * 225) <= 2 * PI * 15 * (0.25 + 0.1) / res);
        assert_true(fabs(ink[0] - 35) <= UNIT && fabs(ink[2] - 65) <= UNIT
                    && fabs(ink[1] - 35) <= UNIT && fabs(ink[3] - 65) <= UNIT);
    }
    /* a ring: two discs the same way round; nonzero fills the inner one,
    ** the cubic's ink box reaches its extremes, not its control points */
    cf__dl_reset(&dl);
    cf__dl_path_begin(&dl);
    cf__dl_arc(&dl, 50, 50, 20, 0, 2 * PI);
    cf__dl_close(&dl);
    cf__dl_arc(&dl, 50, 50, 10, 0, 2 * PI);
    cf__dl_close(&dl);
    cf__dl_path_paint(&dl, &p);
    painted(&dl, 2, &area, ink);
    assert_true(fabs(area - PI * 400) <= 2 * PI * 20 * 0.35 / 2);
    /* a stroke of width 4 from (20, 50) to (80, 50), round caps: a 60 x 4
    ** band and a disc of radius 2 */
    cf__dl_reset(&dl);
    cf__dl_path_begin(&dl);
    cf__dl_move(&dl, 20, 50);
    cf__dl_line(&dl, 80, 50);
    memset(&p, 0, sizeof p);
    p.stroke = true;
    p.line.color.a = 1;
    p.line.opacity = 1;
    p.line.width = 4;
    p.line.cap = CF__CAP_ROUND;
    p.line.join = CF__JOIN_ROUND;
    cf__dl_path_paint(&dl, &p);
    painted(&dl, 2, &area, ink);
    assert_true(fabs(area - (240 + PI * 4)) <= (2 * 60 + 2 * PI * 2) * 0.35 / 2);
    assert_true(fabs(ink[0] - 18) <= UNIT && fabs(ink[2] - 82) <= UNIT
                && fabs(ink[1] - 48) <= UNIT && fabs(ink[3] - 52) <= UNIT);
    /* butt caps: the band alone */
    dl.ops[0].u.path.paint.line.cap = CF__CAP_BUTT;
    dl.ops[0].u.path.paint.line.join = CF__JOIN_MITER;
    painted(&dl, 2, &area, ink);
    assert_true(fabs(area - 240) <= 2 * 64 * 0.35 / 2);
    assert_true(fabs(ink[0] - 20) <= UNIT && fabs(ink[2] - 80) <= UNIT);
    /* a cubic's box: (0,0) (0,40) (40,40) (40,0) reaches y = 30 */
    cf__dl_reset(&dl);
    cf__dl_path_begin(&dl);
    cf__dl_move(&dl, 10, 10);
    cf__dl_curve(&dl, 10, 50, 50, 50, 50, 10);
    cf__dl_close(&dl);
    p = solid_fill();
    cf__dl_path_paint(&dl, &p);
    painted(&dl, 2, &area, ink);
    assert_true(fabs(ink[3] - 40) <= UNIT && fabs(ink[2] - 50) <= UNIT);
    /* 40 x 30 under the cubic: 2/3 of its hull's height for a parabola-
    ** like arch: the area of this cubic segment is 40 * 40 * 3/5 = 960 */
    assert_true(fabs(area - 960) <= 2 * 120 * 0.35 / 2);
    cf__dl_free(&dl);
}

/* ---- rows made ready where used ---------------------------------------- */

#define JUNK 0xAB

/* A 200 x 200 raster at 2 pixels a bp: its memory full of JUNK and its
** rows not ready when ready, else zero; rows (NULL: all) painted. */
static void
junk_raster(cf__raster_t *r, bool ready, const unsigned char *rows)
{
    assert_int_equal(cf__raster_open(r, 200, 200, 2, 0, 0), 0);
    if (ready) {
        memset(r->px, JUNK, 200 * 200);
        r->ready = calloc(200, 1);
        assert_non_null(r->ready);
    }
    r->rows = rows;
}

/* A disc and a stroke across the middle, painted within the pixel box
** 20 .. 180 each way. */
static void
two_shapes(cf__dl_t *dl)
{
    cf__paint_t p = solid_fill();
    cf__dl_reset(dl);
    cf__dl_path_begin(dl);
    cf__dl_arc(dl, 40, 30, 12.3, 0, 2 * PI);
    cf__dl_close(dl);
    cf__dl_path_paint(dl, &p);
    memset(&p, 0, sizeof p);
    p.stroke = true;
    p.line.color.a = 1;
    p.line.opacity = 0.6;
    p.line.width = 3;
    cf__dl_path_begin(dl);
    cf__dl_move(dl, 5, 70);
    cf__dl_curve(dl, 30, 20, 60, 90, 95, 40);
    cf__dl_path_paint(dl, &p);
}

/* A raster whose rows are made ready where they are first painted or
** read (cf__raster_t.ready: the label placement's, render/layout/
** place-raster.c) has, in every row painted or read, the pixels of a
** raster cleared whole; the rows neither painted nor read keep what the
** memory held (nothing cleared them); clearing the dirty box leaves the
** rows not ready as they are and empties the ready ones.  With only some
** rows painted (rows), only those are made ready. */
static void
test_ready_rows(void **state)
{
    static const int box[4] = { 20, 20, 180, 180 };
    unsigned char rows[200];
    cf__raster_t a, b;
    cf__dl_t dl;
    int i, j, pass;
    (void)state;
    cf__dl_init(&dl);
    two_shapes(&dl);
    memset(rows, 0, sizeof rows);
    for (j = 40; j < 70; j++)
        rows[j] = 1;
    for (j = 150; j < 160; j++)
        rows[j] = 1;
    for (pass = 0; pass < 2; pass++) {
        const unsigned char *only = pass == 0 ? NULL : rows;
        long painted = 0, kept = 0;
        junk_raster(&a, false, only);
        junk_raster(&b, true, only);
        assert_int_equal(cf__raster_paint_in(&a, &dl, 0, dl.count, box), 0);
        assert_int_equal(cf__raster_paint_in(&b, &dl, 0, dl.count, box), 0);
        b.rows = NULL;
        cf__raster_ready(&b, 150, 160);   /* read there */
        for (j = 0; j < 200; j++) {
            const unsigned char *pa = a.px + (size_t)j * 200;
            const unsigned char *pb = b.px + (size_t)j * 200;
            if (b.ready[j]) {
                assert_memory_equal(pa, pb, 200);
                for (i = 0; i < 200; i++)
                    painted += pb[i] != 0;
            } else {
                /* never painted: no ink of the shapes in the raster
                ** cleared whole either (a row beside them, or left out) */
                for (i = 0; i < 200; i++) {
                    assert_int_equal(pb[i], JUNK);
                    assert_int_equal(pa[i], 0);
                }
                kept++;
            }
            if (only != NULL && !rows[j])
                assert_int_equal(b.ready[j], 0);
        }
        assert_true(painted > 200);   /* the shapes are there */
        assert_true(kept > 50);       /* and not every row was cleared */
        cf__raster_clear(&b, b.dirty);
        for (j = 0; j < 200; j++)
            for (i = 0; i < 200; i++) {
                unsigned char v = b.px[(size_t)j * 200 + (size_t)i];
                assert_int_equal(v, b.ready[j] ? 0 : JUNK);
            }
        free(b.ready);
        b.ready = NULL;
        cf__raster_close(&a);
        cf__raster_close(&b);
    }
    cf__dl_free(&dl);
}

/* ---- the shipped figures ------------------------------------------------ */

static int
check_ink(const cf__dl_t *dl, size_t from, size_t to, const char *name,
          const char *what)
{
    double a[4], b[4];
    int k;
    assert_int_equal(cf__dl_ink(dl, from, to, a), 0);
    assert_int_equal(cf__cairo_ink(dl, from, to, b), 0);
    for (k = 0; k < 4; k++)
        if (fabs(a[k] - b[k]) > INK_MAX) {
            print_message("%s: %s: ink box %.4f %.4f %.4f %.4f, cairo's "
                          "%.4f %.4f %.4f %.4f\n", name, what, a[0], a[1],
                          a[2], a[3], b[0], b[1], b[2], b[3]);
            return 1;
        }
    return 0;
}

static int
check_figure(void *ctx, const char *script, const char *name,
             cf_figure_t *fig)
{
    cf__layout_t lay;
    cf__dl_t dl;
    cf__raster_t own;
    cairo_surface_t *img;
    cairo_t *cr;
    const unsigned char *c;
    double pw, ph;
    int w, h, i, j, stride, bad = 0;
    long inked = 0, off = 0;
    double sum_own = 0, sum_cairo = 0;
    size_t k;
    (void)ctx;
    (void)script;
    cf__dl_init(&dl);
    assert_int_equal(cf__figure_layout(fig, &lay), CF_STATUS_OK);
    assert_int_equal(cf__figure_build(fig, &lay, &dl), CF_STATUS_OK);
    bad += check_ink(&dl, 0, dl.count, name, "the page");
    for (k = 0; k < dl.count; k++) {
        size_t e = k + 1;
        if (dl.ops[k].kind != CF__OP_GROUP)
            continue;
        while (e < dl.count && dl.ops[e].kind != CF__OP_END)
            e++;
        bad += check_ink(&dl, k, e, name, dl.ops[k].u.group.name);
    }
    cf_figure_get_size(fig, &pw, &ph);
    w = (int)ceil(pw * RES);
    h = (int)ceil(ph * RES);
    img = cairo_image_surface_create(CAIRO_FORMAT_A8, w, h);
    cr = cairo_create(img);
    cairo_scale(cr, RES, RES);
    cf__dl_play(&dl, 0, dl.count, &cf__cairo_backend, cr);
    cairo_destroy(cr);
    cairo_surface_flush(img);
    c = cairo_image_surface_get_data(img);
    stride = cairo_image_surface_get_stride(img);
    assert_int_equal(cf__raster_open(&own, w, h, RES, 0, 0), 0);
    assert_int_equal(cf__raster_paint(&own, &dl, 0, dl.count), 0);
    for (j = 0; j < h; j++)
        for (i = 0; i < w; i++) {
            int a = c[(size_t)j * (size_t)stride + (size_t)i];
            int b = own.px[(size_t)j * (size_t)own.stride + (size_t)i];
            inked += a > 0 || b > 0;
            off += abs(a - b) > 127;
            sum_cairo += a;
            sum_own += b;
        }
    if (getenv("CF_MEASURE_STATS") != NULL)
        print_message("%s: %.4f of the inked pixels off, ink %.4f of "
                      "cairo's\n", name, (double)off / (double)inked,
                      sum_own / sum_cairo);
    if (off > OFF_MAX * (double)inked
        || fabs(sum_own - sum_cairo) > SUM_MAX * sum_cairo) {
        print_message("%s: %ld of %ld inked pixels differ from cairo's by "
                      "more than half; ink %.4f of cairo's\n", name, off,
                      inked, sum_own / sum_cairo);
        bad++;
    }
    cf__raster_close(&own);
    cairo_surface_destroy(img);
    cf__dl_free(&dl);
    return bad;
}

static void
test_shipped(void **state)
{
    size_t failed = 0, n;
    (void)state;
    n = tu_each_shipped_figure(CF_SOURCE_ROOT, check_figure, NULL, &failed);
    print_message("%zu figures, %zu off\n", n, failed);
    assert_true(n > 50);
    assert_int_equal(failed, 0);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shapes),
        cmocka_unit_test(test_ready_rows),
        cmocka_unit_test(test_shipped),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
