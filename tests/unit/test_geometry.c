/* Planar convex hull (Andrew's monotone chain) and the hull of a Bézier
** curve's control points. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/geometry.h"
#include "testutil.h"

/* Is q inside or on the convex polygon (CCW vertices) up to tol? */
static bool
inside(const double *pts, size_t stride, const size_t *idx, size_t n,
       const double *q, double tol)
{
    for (size_t i = 0; i < n; i++) {
        const double *a = pts + idx[i] * stride;
        const double *b = pts + idx[(i + 1) % n] * stride;
        double ex = b[0] - a[0], ey = b[1] - a[1];
        double len = hypot(ex, ey);
        double cr = ex * (q[1] - a[1]) - ey * (q[0] - a[0]);
        if (len > 0 && cr / len < -tol)
            return false;
    }
    return true;
}

static void
test_hull_square_with_extras(void **state)
{
    /* corners (0,0) (2,0) (2,2) (0,2); inside (1,1); on edges (1,0) (2,1);
    ** repeated corner (2,2) at index 7 and (0,0) at index 8 */
    const double pts[] = { 1, 1, 2, 2, 1, 0, 0, 0, 2, 0, 2, 1, 0, 2,
                           2, 2, 0, 0 };
    size_t idx[9], n;
    (void)state;
    assert_int_equal(cf_convex_hull_2d(pts, 9, 2, idx, &n, NULL),
                     CF_STATUS_OK);
    assert_int_equal(n, 4);
    /* CCW from the lowest x then lowest y: (0,0) (2,0) (2,2) (0,2), and
    ** of repeated points the smallest index */
    assert_int_equal(idx[0], 3);
    assert_int_equal(idx[1], 4);
    assert_int_equal(idx[2], 1);
    assert_int_equal(idx[3], 6);
}

static void
test_hull_degenerate(void **state)
{
    const double same[] = { 3, 4, 3, 4, 3, 4 };
    const double line[] = { 1, 1, 3, 3, 0, 0, 2, 2, 3, 3 };
    /* stride 3: the third value is ignored */
    const double tri[] = { 0, 0, 99, 1, 0, 99, 0, 1, 99 };
    size_t idx[5], n;
    (void)state;
    assert_int_equal(cf_convex_hull_2d(same, 3, 2, idx, &n, NULL),
                     CF_STATUS_OK);
    assert_int_equal(n, 1);
    assert_int_equal(idx[0], 0);
    assert_int_equal(cf_convex_hull_2d(line, 5, 2, idx, &n, NULL),
                     CF_STATUS_OK);
    assert_int_equal(n, 2);
    assert_int_equal(idx[0], 2);
    assert_int_equal(idx[1], 1);
    assert_int_equal(cf_convex_hull_2d(tri, 3, 3, idx, &n, NULL),
                     CF_STATUS_OK);
    assert_int_equal(n, 3);
    assert_int_equal(idx[0], 0);
    assert_int_equal(idx[1], 1);
    assert_int_equal(idx[2], 2);
    assert_int_equal(cf_convex_hull_2d(tri, 1, 3, idx, &n, NULL),
                     CF_STATUS_OK);
    assert_int_equal(n, 1);
}

static void
test_hull_random(void **state)
{
    /* every point inside, every vertex a strict left turn */
    double pts[2 * 300];
    size_t idx[300], n;
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 21);
    for (int it = 0; it < 50; it++) {
        size_t count = 3 + (size_t)(tu_rng_next(&r) % 298);
        for (size_t i = 0; i < 2 * count; i++)
            /* a coarse grid makes repeats and collinear triples common */
            pts[i] = it % 2 ? floor(tu_rng_range(&r, 0, 8))
                            : tu_rng_range(&r, -1, 1);
        assert_int_equal(cf_convex_hull_2d(pts, count, 2, idx, &n, NULL),
                         CF_STATUS_OK);
        assert_true(n >= 1 && n <= count);
        for (size_t i = 0; i < count; i++)
            assert_true(inside(pts, 2, idx, n, pts + 2 * i, 1e-12));
        if (n >= 3)
            for (size_t i = 0; i < n; i++) {
                const double *a = pts + 2 * idx[i];
                const double *b = pts + 2 * idx[(i + 1) % n];
                const double *c = pts + 2 * idx[(i + 2) % n];
                double cr = (b[0] - a[0]) * (c[1] - a[1]) -
                            (b[1] - a[1]) * (c[0] - a[0]);
                assert_true(cr > 0.0);
            }
    }
}

static void
test_bezier_hull_contains_curve(void **state)
{
    /* the convex hull property, polynomial and rational */
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 22);
    for (int it = 0; it < 40; it++) {
        int deg = 1 + it % 9;
        double pts[2 * 10], w[10], q[2];
        size_t idx[10], n;
        cf_bezier_t *c;
        for (int i = 0; i < 2 * (deg + 1); i++)
            pts[i] = tu_rng_range(&r, -5, 5);
        for (int i = 0; i <= deg; i++)
            w[i] = tu_rng_range(&r, 0.1, 10);
        assert_int_equal(cf_bezier_create(2, deg, pts, it % 2 ? w : NULL, &c,
                                          NULL), CF_STATUS_OK);
        assert_int_equal(cf_bezier_hull(c, idx, &n, NULL), CF_STATUS_OK);
        for (int j = 0; j <= 500; j++) {
            cf_bezier_eval(c, j / 500.0, q);
            assert_true(inside(pts, 2, idx, n, q, 1e-12 * 5));
        }
        cf_bezier_destroy(c);
    }
}

static void
test_hull_errors(void **state)
{
    const double pts[] = { 0, 0, 1, NAN, 2, 2 };
    const double p3[] = { 0, 0, 0, 1, 1, 1 };
    size_t idx[3], n = 99;
    cf_diag_t d;
    cf_bezier_t *c;
    (void)state;
    assert_int_equal(cf_convex_hull_2d(NULL, 3, 2, idx, &n, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_convex_hull_2d(pts, 3, 2, NULL, &n, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_convex_hull_2d(pts, 3, 2, idx, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_convex_hull_2d(pts, 0, 2, idx, &n, NULL),
                     CF_STATUS_TOO_FEW_POINTS);
    assert_int_equal(n, 0);
    assert_int_equal(cf_convex_hull_2d(pts, 3, 1, idx, &n, NULL),
                     CF_STATUS_INVALID_ARG);
    cf_diag_clear(&d);
    assert_int_equal(cf_convex_hull_2d(pts, 3, 2, idx, &n, &d),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(d.index, 1);
    assert_non_null(strstr(d.msg, "point P_1"));
    assert_int_equal(cf_bezier_hull(NULL, idx, &n, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_create(3, 1, p3, NULL, &c, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_bezier_hull(c, idx, &n, NULL),
                     CF_STATUS_DIM_MISMATCH);
    cf_bezier_destroy(c);
    /* out of memory: fail each allocation in turn, no leaks */
    assert_int_equal(cf_bezier_create(2, 2, p3, NULL, &c, NULL),
                     CF_STATUS_OK);
    for (long k = 1;; k++) {
        cf_status_t st;
        tu_fail_alloc_after(k);
        st = cf_bezier_hull(c, idx, &n, NULL);
        assert_int_equal(tu_alloc_live(), 0);
        tu_fail_alloc_reset();
        if (st == CF_STATUS_OK)
            break;
        assert_int_equal(st, CF_STATUS_NO_MEMORY);
    }
    assert_int_equal(n, 3);
    cf_bezier_destroy(c);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hull_square_with_extras),
        cmocka_unit_test(test_hull_degenerate),
        cmocka_unit_test(test_hull_random),
        cmocka_unit_test(test_bezier_hull_contains_curve),
        cmocka_unit_test(test_hull_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
