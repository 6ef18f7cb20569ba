/* The bezier tests, continued: conversion to cubics (the helpers the files
** share: test_bezier.h). */
#include "test_bezier.h"

/* ---- conversion to cubics ------------------------------------------------- */

/* Distance from q to the curve c on [a, b], given its samples smp[0..k]
** at a + (b - a) i / k: the nearest sample, then Newton's method on
** g(t) = (c(t) - q) . c'(t) from there (the smallest distance seen is
** kept, so the result never understates the true distance by more than
** the sampling misses). */
static double
dist_curve(const cf_bezier_t *c, double a, double b, const double *smp,
           int k, const double *q)
{
    size_t dim = cf_bezier_dim(c);
    double best = INFINITY, t, v[3 * 4];
    int ib = 0;
    for (int i = 0; i <= k; i++) {
        double e2 = 0.0;
        for (size_t j = 0; j < dim; j++)
            e2 += (smp[dim * i + j] - q[j]) * (smp[dim * i + j] - q[j]);
        if (e2 < best) {
            best = e2;
            ib = i;
        }
    }
    best = sqrt(best);
    t = a + (b - a) * ib / k;
    for (int it = 0; it < 12; it++) {
        double g = 0.0, dg = 0.0, e2 = 0.0, lo = a + (b - a) * (ib - 1) / k,
               hi = a + (b - a) * (ib + 1) / k;
        assert_int_equal(cf_bezier_eval_derivs(c, t, 2, v), CF_STATUS_OK);
        for (size_t j = 0; j < dim; j++) {
            double e = v[j] - q[j];
            e2 += e * e;
            g += e * v[dim + j];
            dg += v[dim + j] * v[dim + j] + e * v[2 * dim + j];
        }
        best = fmin(best, sqrt(e2));
        if (!(dg > 0.0))
            break;
        {
            double tn = fmin(fmin(hi, b), fmax(fmax(lo, a), t - g / dg));
            if (fabs(tn - t) <= 1e-16 * (b - a))
                break;
            t = tn;
        }
    }
    return best;
}

static void
check_cubics(const cf_bezier_t *c, const cf_cubics_t *cu, double bound)
{
    /* independent check: the two-sided distance between each segment and
    ** its part of the curve, from 256 samples of each (refined by Newton
    ** foot points), and continuity of the chain */
    enum { K = 256 };
    size_t dim = cf_bezier_dim(c);
    double *cs = malloc((K + 1) * dim * sizeof *cs);
    double *ss = malloc((K + 1) * dim * sizeof *ss);
    assert_int_equal(cu->dim, dim);
    assert_true(cu->t[0] == 0.0 && cu->t[cu->count] == 1.0);
    for (size_t i = 0; i < cu->count; i++) {
        const double *s = cu->pts + 4 * dim * i;
        double a = cu->t[i], b = cu->t[i + 1];
        cf_bezier_t *seg;
        assert_true(a < b);
        if (i > 0)
            for (size_t q = 0; q < dim; q++)
                assert_true(s[q] == s[q - dim]);
        assert_int_equal(cf_bezier_create(dim, 3, s, NULL, &seg, NULL),
                         CF_STATUS_OK);
        for (int j = 0; j <= K; j++) {
            cf_bezier_eval(c, a + (b - a) * j / K, cs + dim * j);
            cf_bezier_eval(seg, (double)j / K, ss + dim * j);
        }
        for (int j = 0; j <= K; j++) {
            assert_true(dist_curve(c, a, b, cs, K, ss + dim * j) <= bound);
            assert_true(dist_curve(seg, 0.0, 1.0, ss, K, cs + dim * j) <=
                        bound);
        }
        cf_bezier_destroy(seg);
    }
    free(cs);
    free(ss);
}

static void
test_to_cubics(void **state)
{
    tu_rng r;
    cf_cubics_t *cu;
    (void)state;
    tu_rng_seed(&r, 17);
    /* exact for polynomial degree <= 3 */
    for (int n = 0; n <= 3; n++) {
        cf_bezier_t *c = random_curve(&r, 2, n, false, 5.0);
        assert_int_equal(cf_bezier_to_cubics(c, 1e-3, &cu, NULL),
                         CF_STATUS_OK);
        assert_int_equal(cu->count, 1);
        assert_true(cu->max_error == 0.0);
        check_cubics(c, cu, 1e-14 * 5.0);
        cf_cubics_destroy(cu);
        cf_bezier_destroy(c);
    }
    /* fitted: degree 4..9 and rational, planar (the Levien fit of the
    ** offset module at d = 0) and in R^3 (Hermite halving); the reported
    ** error is what was measured (<= tol); the independent two-sided check
    ** allows 5 % more because both measures sample */
    for (int it = 0; it < 24; it++) {
        int n = 2 + it % 8;
        bool rat = it % 2 == 1 || n <= 3;
        double tol = it % 3 == 0 ? 1e-2 : it % 3 == 1 ? 1e-5 : 1e-8;
        cf_bezier_t *c = random_curve(&r, 2 + (size_t)it % 2, n, rat, 10.0);
        assert_int_equal(cf_bezier_to_cubics(c, tol, &cu, NULL),
                         CF_STATUS_OK);
        assert_true(cu->max_error <= tol);
        assert_true(cu->max_error > 0.0);
        check_cubics(c, cu, 1.05 * tol);
        cf_cubics_destroy(cu);
        cf_bezier_destroy(c);
    }
    cf_cubics_destroy(NULL);
}

/* Largest distance between segment i of cu at u and the curve at the
** corresponding parameter (the parametric error the bound promises). */
static double
parametric_error(const cf_bezier_t *c, const cf_cubics_t *cu, size_t i,
                 double u)
{
    size_t dim = cf_bezier_dim(c);
    const double *s = cu->pts + 4 * dim * i;
    double q[4], v = 1.0 - u, e2 = 0.0;
    double b[4] = { v * v * v, 3 * v * v * u, 3 * v * u * u, u * u * u };
    cf_bezier_eval(c, cu->t[i] + u * (cu->t[i + 1] - cu->t[i]), q);
    for (size_t k = 0; k < dim; k++) {
        double h = b[0] * s[k] + b[1] * s[dim + k] + b[2] * s[2 * dim + k]
                   + b[3] * s[3 * dim + k];
        e2 += (h - q[k]) * (h - q[k]);
    }
    return sqrt(e2);
}

static void
test_to_cubics_bounded(void **state)
{
    tu_rng r;
    cf_cubics_t *cu, *ref;
    cf_bezier_t *c;
    cf_diag_t d;
    (void)state;
    tu_rng_seed(&r, 29);
    /* degree 4: c^(4) is the constant 24 Delta^4 P, and the Hermite
    ** remainder f^(4)/4! (t-a)^2 (t-b)^2 is exactly h^4/384 |c^(4)| at every
    ** piece's midpoint -- the bound is attained there (by hand, the
    ** classical remainder), so the reported bound must equal the measured
    ** midpoint error to rounding (1e-9 relative) */
    for (size_t dim = 1; dim <= 3; dim++) {
        c = random_curve(&r, dim, 4, false, 10.0);
        assert_int_equal(cf_bezier_to_cubics_bounded(c, 1e-4, &cu, NULL),
                         CF_STATUS_OK);
        assert_true(cu->count >= 2 && cu->max_error <= 1e-4);
        for (size_t i = 0; i < cu->count; i++)
            tu_assert_close(parametric_error(c, cu, i, 0.5), cu->max_error,
                            1e-9, 1e-15);
        /* and N is the smallest count: N - 1 pieces would exceed tol */
        assert_true(cu->max_error * pow((double)cu->count /
                                        (double)(cu->count - 1), 4.0)
                    > 1e-4);
        cf_cubics_destroy(cu);
        cf_bezier_destroy(c);
    }
    /* degrees 4..12, dims 1..3, tolerances 1e-2..1e-8: within the bound
    ** parameter for parameter (1e-12 of the size for rounding), within tol
    ** two-sided (check_cubics: independent sampling), C1 at the joins */
    for (int it = 0; it < 27; it++) {
        int n = 4 + it % 9;
        size_t dim = 1 + (size_t)(it / 3) % 3;
        double tol = it % 3 == 0 ? 1e-2 : it % 3 == 1 ? 1e-5 : 1e-8;
        c = random_curve(&r, dim, n, false, 10.0);
        assert_int_equal(cf_bezier_to_cubics_bounded(c, tol, &cu, NULL),
                         CF_STATUS_OK);
        assert_true(cu->max_error <= tol && cu->max_error > 0.0);
        for (size_t i = 0; i < cu->count; i++)
            for (int j = 0; j <= 32; j++)
                assert_true(parametric_error(c, cu, i, j / 32.0)
                            <= cu->max_error + 1e-12 * curve_size(c));
        /* the two-sided check costs count x 257^2 foot points: on the
        ** chains of up to 60 pieces (the parametric bound above already
        ** implies it) */
        if (cu->count <= 60)
            check_cubics(c, cu, tol + 1e-12 * curve_size(c));
        for (size_t i = 1; i < cu->count; i++) {
            /* c'(t_i) from both sides: 3 (P1 - P0) / h and 3 (P3 - P2) / h */
            const double *s0 = cu->pts + 4 * dim * (i - 1);
            const double *s1 = cu->pts + 4 * dim * i;
            double h0 = cu->t[i] - cu->t[i - 1], h1 = cu->t[i + 1] - cu->t[i];
            for (size_t k = 0; k < dim; k++)
                tu_assert_close(3 * (s0[3 * dim + k] - s0[2 * dim + k]) / h0,
                                3 * (s1[dim + k] - s1[k]) / h1, 1e-9,
                                1e-9 * curve_size(c) * n);
        }
        cf_cubics_destroy(cu);
        cf_bezier_destroy(c);
    }
    /* polynomial curves of degree <= 3: exactly cf_bezier_to_cubics */
    for (int n = 0; n <= 3; n++) {
        c = random_curve(&r, 2, n, false, 5.0);
        assert_int_equal(cf_bezier_to_cubics_bounded(c, 1e-3, &cu, NULL),
                         CF_STATUS_OK);
        assert_int_equal(cf_bezier_to_cubics(c, 1e-3, &ref, NULL),
                         CF_STATUS_OK);
        assert_int_equal(cu->count, ref->count);
        assert_memory_equal(cu->pts, ref->pts,
                            8 * cu->count * sizeof *cu->pts);
        cf_cubics_destroy(cu);
        cf_cubics_destroy(ref);
        cf_bezier_destroy(c);
    }
    /* rational curves, degrees 2..9 in the plane and in R^3, weights 0.2..5
    ** and Example 5.4.1's (seed 001: eight points, one weight of 100):
    ** Hermite pieces halved on their measured parametric error, so the
    ** chain is C1 (the curve's own derivative at every join) and within
    ** tol at 257 parameters of every piece (independent of the 47 the
    ** fit measures; 5 % more allowed because both sample) and two-sided */
    for (int it = 0; it < 18; it++) {
        static const double P[] = { -10.0, 0.0, -3.0, 7.0, 1.1, -7.2, 4.3,
                                    -8.5, -16.0, 12.0, -2.1, 1.7, -8.2, 1.4,
                                    12.2, 5.4 };
        double w[8] = { 1, 1, 1, 1, 1, 1, 1, 1 }, d0[6], d1[6];
        int n = 2 + it % 8;
        size_t dim = 2 + (size_t)(it / 8) % 2;
        double tol = it % 3 == 0 ? 1e-2 : it % 3 == 1 ? 1e-4 : 1e-6;
        if (it >= 16) {
            w[it == 16 ? 3 : 6] = 100.0;
            assert_int_equal(cf_bezier_create(2, 7, P, w, &c, NULL),
                             CF_STATUS_OK);
            dim = 2;
            n = 7;
        } else {
            c = random_curve(&r, dim, n, true, 10.0);
        }
        assert_int_equal(cf_bezier_to_cubics_bounded(c, tol, &cu, NULL),
                         CF_STATUS_OK);
        assert_true(cu->max_error <= tol && cu->max_error > 0.0);
        for (size_t i = 0; i < cu->count; i++) {
            const double *sg = cu->pts + 4 * dim * i;
            double h = cu->t[i + 1] - cu->t[i];
            for (int j = 0; j <= 256; j++)
                assert_true(parametric_error(c, cu, i, j / 256.0)
                            <= 1.05 * tol);
            cf_bezier_eval_derivs(c, cu->t[i], 1, d0);
            cf_bezier_eval_derivs(c, cu->t[i + 1], 1, d1);
            for (size_t k = 0; k < dim; k++) {
                double sc = 1e-12 * curve_size(c) * 1e3;
                tu_assert_close(sg[k], d0[k], 0, sc);
                tu_assert_close(sg[3 * dim + k], d1[k], 0, sc);
                tu_assert_close(3 * (sg[dim + k] - sg[k]) / h, d0[dim + k],
                                1e-9, sc);
                tu_assert_close(3 * (sg[3 * dim + k] - sg[2 * dim + k]) / h,
                                d1[dim + k], 1e-9, sc);
            }
        }
        if (cu->count <= 60)
            check_cubics(c, cu, 1.05 * tol);
        cf_cubics_destroy(cu);
        cf_bezier_destroy(c);
    }
    /* errors: NULL, a bad tolerance, a fourth derivative that overflows;
    ** and out of memory at every allocation, without leaks */
    c = random_curve(&r, 2, 6, false, 1.0);
    assert_int_equal(cf_bezier_to_cubics_bounded(c, 1e-3, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_to_cubics_bounded(NULL, 1e-3, &cu, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_to_cubics_bounded(c, 0.0, &cu, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_to_cubics_bounded(c, NAN, &cu, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_null(cu);
    for (long k = 0;; k++) {
        long live = tu_alloc_live();
        cf_status_t st;
        tu_fail_alloc_after(k);
        st = cf_bezier_to_cubics_bounded(c, 1e-3, &cu, NULL);
        tu_fail_alloc_reset();
        if (st == CF_STATUS_OK) {
            cf_cubics_destroy(cu);
            break;
        }
        assert_int_equal(st, CF_STATUS_NO_MEMORY);
        assert_null(cu);
        assert_int_equal(tu_alloc_live(), live);
    }
    cf_bezier_destroy(c);
    {
        double huge_pts[14];
        for (int i = 0; i < 14; i++)
            huge_pts[i] = (i % 2 ? 1.0 : -1.0) * 1e306;
        assert_int_equal(cf_bezier_create(2, 6, huge_pts, NULL, &c, NULL),
                         CF_STATUS_OK);
        cf_diag_clear(&d);
        assert_int_equal(cf_bezier_to_cubics_bounded(c, 1e-3, &cu, &d),
                         CF_STATUS_NOT_FINITE);
        assert_non_null(strstr(d.msg, "fourth derivative"));
        cf_bezier_destroy(c);
    }
}

static void
test_to_cubics_counts(void **state)
{
    /* the renderer's cases at its default tolerance 0.01 pt: a rational
    ** quarter circle of radius 300 (one cubic is off by 2.7e-4 r = 0.08,
    ** two by 300 * 4.2e-6 = 1.3e-3 < 0.01) and a degree-5 curve 190 x 300
    ** across */
    double Q[] = { 300, 0, 300, 300, 0, 300 }, w[] = { 1, sqrt(0.5), 1 };
    double P[] = { 0, 0, 1, 4, 2, -3, 3, 5, 4, -2, 5, 1 };
    cf_bezier_t *c;
    cf_cubics_t *cu;
    (void)state;
    assert_int_equal(cf_bezier_create(2, 2, Q, w, &c, NULL), CF_STATUS_OK);
    assert_int_equal(cf_bezier_to_cubics(c, 0.01, &cu, NULL), CF_STATUS_OK);
    assert_int_equal(cu->count, 2);
    assert_true(cu->max_error <= 0.01);
    check_cubics(c, cu, 1.05 * 0.01);
    /* independently: every point of the chain lies on the circle */
    for (size_t i = 0; i < cu->count; i++)
        for (int j = 0; j <= 64; j++) {
            double u = j / 64.0, v = 1 - u, x = 0.0, y = 0.0;
            const double *s = cu->pts + 8 * i;
            double b[4] = { v * v * v, 3 * v * v * u, 3 * v * u * u,
                            u * u * u };
            for (int k = 0; k < 4; k++) {
                x += b[k] * s[2 * k];
                y += b[k] * s[2 * k + 1];
            }
            assert_true(fabs(hypot(x, y) - 300.0) <= 1.05 * 0.01);
        }
    cf_cubics_destroy(cu);
    cf_bezier_destroy(c);
    for (int i = 0; i < 12; i++)
        P[i] *= 37.5;
    assert_int_equal(cf_bezier_create(2, 5, P, NULL, &c, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_bezier_to_cubics(c, 0.01, &cu, NULL), CF_STATUS_OK);
    assert_true(cu->count <= 5);     /* measured: 5 */
    assert_true(cu->max_error <= 0.01);
    check_cubics(c, cu, 1.05 * 0.01);
    cf_cubics_destroy(cu);
    cf_bezier_destroy(c);
    /* a single point (rational, all control points equal): one constant
    ** segment, exact */
    {
        double R[] = { 2, 3, 2, 3, 2, 3 }, wr[] = { 1, 2, 3 };
        assert_int_equal(cf_bezier_create(2, 2, R, wr, &c, NULL),
                         CF_STATUS_OK);
        assert_int_equal(cf_bezier_to_cubics(c, 0.01, &cu, NULL),
                         CF_STATUS_OK);
        assert_int_equal(cu->count, 1);
        assert_true(cu->max_error == 0.0);
        for (int k = 0; k < 4; k++)
            assert_true(cu->pts[2 * k] == 2.0 && cu->pts[2 * k + 1] == 3.0);
        cf_cubics_destroy(cu);
        cf_bezier_destroy(c);
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_to_cubics),
        cmocka_unit_test(test_to_cubics_counts),
        cmocka_unit_test(test_to_cubics_bounded),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
