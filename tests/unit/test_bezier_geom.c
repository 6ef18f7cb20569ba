/* Geometry of Bézier curves: bounding box, arc length, closest point,
** flattening, degree reduction. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/bezier.h"
#include "testutil.h"

static cf_bezier_t *
random_curve(tu_rng *r, size_t dim, int degree, bool rational)
{
    double pts[4 * 16], w[16];
    cf_bezier_t *c;
    assert_true(dim <= 4 && degree < 16);
    for (size_t i = 0; i < ((size_t)degree + 1) * dim; i++)
        pts[i] = tu_rng_range(r, -1.0, 1.0);
    for (int i = 0; i <= degree; i++)
        w[i] = tu_rng_range(r, 0.3, 3.0);
    assert_int_equal(cf_bezier_create(dim, degree, pts, rational ? w : NULL,
                                      &c, NULL), CF_STATUS_OK);
    return c;
}

static double
coord(const cf_bezier_t *c, size_t k, double t)
{
    double p[4];
    cf_bezier_eval(c, t, p);
    return p[k];
}

/* min over [0, 1] of sign * x_k(t): dense samples, then golden section
** around the best sample (an independent check of the bbox). */
static double
min_coord(const cf_bezier_t *c, size_t k, double sign)
{
    const int N = 4000;
    const double g = 0.6180339887498949;
    double best = INFINITY, a, b;
    int jb = 0;
    for (int j = 0; j <= N; j++) {
        double v = sign * coord(c, k, (double)j / N);
        if (v < best) {
            best = v;
            jb = j;
        }
    }
    a = fmax(0.0, (jb - 1.0) / N);
    b = fmin(1.0, (jb + 1.0) / N);
    for (int it = 0; it < 100; it++) {
        double x1 = b - g * (b - a), x2 = a + g * (b - a);
        if (sign * coord(c, k, x1) < sign * coord(c, k, x2))
            b = x2;
        else
            a = x1;
    }
    return fmin(best, sign * coord(c, k, 0.5 * (a + b)));
}

static void
test_bbox(void **state)
{
    const double q[] = { 0, 0, 1, 2, 2, 0 };
    double lo[4], hi[4];
    cf_bezier_t *c;
    tu_rng r;
    (void)state;
    /* y = 2 * 2 t (1 - t): top at t = 1/2, y = 1 */
    assert_int_equal(cf_bezier_create(2, 2, q, NULL, &c, NULL), CF_STATUS_OK);
    assert_int_equal(cf_bezier_bbox(c, lo, hi), CF_STATUS_OK);
    assert_true(lo[0] == 0 && hi[0] == 2 && lo[1] == 0);
    tu_assert_close(hi[1], 1.0, 1e-15, 1.0);
    cf_bezier_destroy(c);
    tu_rng_seed(&r, 31);
    for (int it = 0; it < 120; it++) {
        int n = 1 + it % 9;
        bool rat = it % 2 == 1;
        size_t dim = 1 + (size_t)it % 3;
        c = random_curve(&r, dim, n, rat);
        assert_int_equal(cf_bezier_bbox(c, lo, hi), CF_STATUS_OK);
        for (int j = 0; j <= 1000; j++) {
            double p[4];
            cf_bezier_eval(c, j / 1000.0, p);
            for (size_t k = 0; k < dim; k++) {
                assert_true(p[k] >= lo[k] - 1e-14);
                assert_true(p[k] <= hi[k] + 1e-14);
            }
        }
        /* every side is attained: the true extremes (found independently)
        ** agree with the box to ~1e-13 (the golden-section search stops at
        ** ~1e-8 in t, where the derivative vanishes: error ~1e-16) */
        for (size_t k = 0; k < dim; k++) {
            tu_assert_close(lo[k], min_coord(c, k, 1.0), 1e-13, 1.0);
            tu_assert_close(hi[k], -min_coord(c, k, -1.0), 1e-13, 1.0);
        }
        cf_bezier_destroy(c);
    }
}

static void
test_length(void **state)
{
    /* y = x^2 on [0, 1] as (0,0) (1/2,0) (1,1): (2 sqrt 5 + asinh 2) / 4 */
    const double par[] = { 0, 0, 0.5, 0, 1, 1 };
    /* quarter circle of radius 2: pi */
    const double arc[] = { 2, 0, 2, 2, 0, 2 };
    const double w[] = { 1, 0.70710678118654752440, 1 };
    /* the segment (0,0)-(3,4), unevenly parametrised, speed 0 at t = 0 */
    const double seg[] = { 0, 0, 0, 0, 3, 4, 3, 4 };
    double len, want;
    cf_bezier_t *c;
    tu_rng r;
    (void)state;
    cf_bezier_create(2, 2, par, NULL, &c, NULL);
    assert_int_equal(cf_bezier_length(c, 1e-13, &len), CF_STATUS_OK);
    want = (2 * sqrt(5.0) + asinh(2.0)) / 4;
    assert_true(fabs(len - want) <= 1e-13 + 4 * DBL_EPSILON);
    cf_bezier_destroy(c);
    cf_bezier_create(2, 2, arc, w, &c, NULL);
    assert_int_equal(cf_bezier_length(c, 1e-12, &len), CF_STATUS_OK);
    assert_true(fabs(len - 3.14159265358979323846) <= 1e-12 + 1e-15);
    cf_bezier_destroy(c);
    cf_bezier_create(2, 3, seg, NULL, &c, NULL);
    assert_int_equal(cf_bezier_length(c, 1e-10, &len), CF_STATUS_OK);
    assert_true(fabs(len - 5.0) <= 1e-10);
    cf_bezier_destroy(c);
    /* random curves against a polyline of 10^5 chords (error ~ L h^2 / 24
    ** |kappa|^2-ish, below 1e-8 here) */
    tu_rng_seed(&r, 32);
    for (int it = 0; it < 12; it++) {
        int n = 2 + it % 6;
        double poly = 0.0, a[3], b[3];
        c = random_curve(&r, 2 + (size_t)it % 2, n, it % 2 == 1);
        assert_int_equal(cf_bezier_length(c, 1e-9, &len), CF_STATUS_OK);
        cf_bezier_eval(c, 0.0, a);
        for (int j = 1; j <= 100000; j++) {
            double d2 = 0.0;
            cf_bezier_eval(c, j / 100000.0, b);
            for (size_t k = 0; k < cf_bezier_dim(c); k++)
                d2 += (b[k] - a[k]) * (b[k] - a[k]);
            poly += sqrt(d2);
            memcpy(a, b, sizeof a);
        }
        assert_true(poly <= len + 1e-9);
        assert_true(len - poly <= 1e-7);
        cf_bezier_destroy(c);
    }
}

static void
test_closest(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 33);
    for (int it = 0; it < 150; it++) {
        int n = it % 8;
        bool rat = it % 2 == 1;
        size_t dim = 1 + (size_t)it % 3;
        cf_bezier_t *c = random_curve(&r, dim, n, rat);
        double p[3], q[3], t, dist, brute = INFINITY, d2 = 0.0;
        for (size_t k = 0; k < dim; k++)
            p[k] = tu_rng_range(&r, -1.5, 1.5);
        assert_int_equal(cf_bezier_closest(c, p, &t, &dist), CF_STATUS_OK);
        /* the distance is attained at t ... */
        cf_bezier_eval(c, t, q);
        for (size_t k = 0; k < dim; k++)
            d2 += (q[k] - p[k]) * (q[k] - p[k]);
        tu_assert_close(dist, sqrt(d2), 1e-15, 1e-300);
        /* ... and no sample of the curve is closer (global minimum) */
        for (int j = 0; j <= 20000; j++) {
            double e2 = 0.0;
            cf_bezier_eval(c, j / 20000.0, q);
            for (size_t k = 0; k < dim; k++)
                e2 += (q[k] - p[k]) * (q[k] - p[k]);
            brute = fmin(brute, sqrt(e2));
        }
        assert_true(dist <= brute + 1e-12);
        /* a point of the curve is at distance ~0 */
        {
            double s = tu_rng_u01(&r), ts, ds;
            cf_bezier_eval(c, s, q);
            assert_int_equal(cf_bezier_closest(c, q, &ts, &ds), CF_STATUS_OK);
            assert_true(ds <= 1e-7);
        }
        cf_bezier_destroy(c);
    }
}

typedef struct poly {
    size_t count, dim;
    double v[20000 * 3], t[20000];
    int stop_after;
} poly;

static int
collect(void *closure, const double *p, double t)
{
    poly *pl = closure;
    if (pl->count == 20000)
        return 1;
    memcpy(pl->v + pl->count * pl->dim, p, pl->dim * sizeof *p);
    pl->t[pl->count++] = t;
    return pl->stop_after > 0 && (int)pl->count >= pl->stop_after;
}

static void
test_flatten(void **state)
{
    static poly pl;
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 34);
    for (int it = 0; it < 40; it++) {
        int n = 1 + it % 7;
        size_t dim = 2 + (size_t)it % 2;
        double tol = it % 2 ? 1e-2 : 1e-5;
        cf_bezier_t *c = random_curve(&r, dim, n, it % 4 >= 2);
        pl.count = 0;
        pl.dim = dim;
        pl.stop_after = 0;
        assert_int_equal(cf_bezier_flatten(c, tol, collect, &pl),
                         CF_STATUS_OK);
        assert_true(pl.count >= 2);
        assert_true(pl.t[0] == 0.0 && pl.t[pl.count - 1] == 1.0);
        for (size_t i = 0; i < pl.count; i++) {
            double q[3];
            cf_bezier_eval(c, pl.t[i], q);
            for (size_t k = 0; k < dim; k++)
                assert_true(fabs(q[k] - pl.v[i * dim + k]) <= 1e-14);
            if (i > 0)
                assert_true(pl.t[i] > pl.t[i - 1]);
        }
        /* every curve point between two vertices is within tol of the
        ** chord (checked at 60 parameters per chord) */
        for (size_t i = 0; i + 1 < pl.count; i++) {
            const double *a = pl.v + i * dim, *b = a + dim;
            double vv = 0.0;
            for (size_t k = 0; k < dim; k++)
                vv += (b[k] - a[k]) * (b[k] - a[k]);
            for (int j = 1; j < 60; j++) {
                double t = pl.t[i] + (pl.t[i + 1] - pl.t[i]) * j / 60.0;
                double q[3], wv = 0.0, u, d2 = 0.0;
                cf_bezier_eval(c, t, q);
                for (size_t k = 0; k < dim; k++)
                    wv += (q[k] - a[k]) * (b[k] - a[k]);
                u = vv > 0 ? fmin(fmax(wv / vv, 0.0), 1.0) : 0.0;
                for (size_t k = 0; k < dim; k++) {
                    double e = q[k] - a[k] - u * (b[k] - a[k]);
                    d2 += e * e;
                }
                assert_true(sqrt(d2) <= tol * (1 + 1e-9));
            }
        }
        cf_bezier_destroy(c);
    }
    /* the callback stops the walk */
    {
        cf_bezier_t *c = random_curve(&r, 2, 3, false);
        pl.count = 0;
        pl.dim = 2;
        pl.stop_after = 3;
        assert_int_equal(cf_bezier_flatten(c, 1e-6, collect, &pl),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(pl.count, 3);
        pl.count = 0;
        pl.stop_after = 1;
        assert_int_equal(cf_bezier_flatten(c, 1e-6, collect, &pl),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(pl.count, 1);
        cf_bezier_destroy(c);
    }
}

static int
count_only(void *closure, const double *p, double t)
{
    (void)p;
    (void)t;
    (*(int *)closure)++;
    return 0;
}

static void
test_errors_and_oom(void **state)
{
    cf_bezier_t *c;
    double lo[2], hi[2], v, p[2] = { 0.5, NAN };
    const double pt[] = { 1, 2 };
    int cnt = 0;
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 36);
    c = random_curve(&r, 2, 4, true);
    assert_int_equal(cf_bezier_bbox(NULL, lo, hi), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_bbox(c, NULL, hi), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_bbox(c, lo, NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_length(NULL, 1e-3, &v), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_length(c, 0.0, &v), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_length(c, NAN, &v), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_length(c, 1e-3, NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_closest(NULL, p, &v, &v),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_closest(c, NULL, &v, &v),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_closest(c, p, &v, &v), CF_STATUS_NOT_FINITE);
    p[1] = 0.0;
    assert_int_equal(cf_bezier_closest(c, p, NULL, NULL), CF_STATUS_OK);
    assert_int_equal(cf_bezier_flatten(NULL, 1e-3, count_only, &cnt),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_flatten(c, -1.0, count_only, &cnt),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_flatten(c, 1e-3, NULL, &cnt),
                     CF_STATUS_INVALID_ARG);
    /* out of memory: each allocation failing in turn, nothing leaks */
    for (long k = 1;; k++) {
        cf_status_t s1, s2, s3;
        tu_fail_alloc_after(k);
        s1 = cf_bezier_bbox(c, lo, hi);
        tu_fail_alloc_after(k);
        s2 = cf_bezier_closest(c, p, &v, NULL);
        tu_fail_alloc_after(k);
        s3 = cf_bezier_flatten(c, 1e-3, count_only, &cnt);
        assert_int_equal(tu_alloc_live(), 0);
        tu_fail_alloc_reset();
        assert_true(s1 == CF_STATUS_OK || s1 == CF_STATUS_NO_MEMORY);
        assert_true(s2 == CF_STATUS_OK || s2 == CF_STATUS_NO_MEMORY);
        assert_true(s3 == CF_STATUS_OK || s3 == CF_STATUS_NO_MEMORY);
        if (s1 == CF_STATUS_OK && s2 == CF_STATUS_OK && s3 == CF_STATUS_OK)
            break;
        assert_true(k < 20);
    }
    cf_bezier_destroy(c);
    /* degree 0: a point */
    cf_bezier_create(2, 0, pt, NULL, &c, NULL);
    assert_int_equal(cf_bezier_bbox(c, lo, hi), CF_STATUS_OK);
    assert_true(lo[0] == 1 && hi[0] == 1 && lo[1] == 2 && hi[1] == 2);
    assert_int_equal(cf_bezier_length(c, 1e-9, &v), CF_STATUS_OK);
    assert_true(v == 0.0);
    assert_int_equal(cf_bezier_closest(c, (double[]){ 4, 6 }, &v, &v),
                     CF_STATUS_OK);
    assert_true(v == 5.0);
    cnt = 0;
    assert_int_equal(cf_bezier_flatten(c, 1e-3, count_only, &cnt),
                     CF_STATUS_OK);
    assert_int_equal(cnt, 2);
    cf_bezier_destroy(c);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bbox),
        cmocka_unit_test(test_length),
        cmocka_unit_test(test_closest),
        cmocka_unit_test(test_flatten),
        cmocka_unit_test(test_errors_and_oom),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
