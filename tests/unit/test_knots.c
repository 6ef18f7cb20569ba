/* Knot vectors and B-spline basis functions (curvefig/knots.h). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/knots.h"
#include "curvefig/bspline.h"
#include "testutil.h"

#define EPS 2.220446049250313e-16

/*
** U = {0, 1, 3, 6, 10} (thesis, example 1), worked out by hand with the
** Cox-de Boor recursion:
**   N_0^1 = u on [0,1),  (3-u)/2 on [1,3)
**   N_1^1 = (u-1)/2 on [1,3),  (6-u)/3 on [3,6)
**   N_2^1 = (u-3)/3 on [3,6),  (10-u)/4 on [6,10)
**   N_0^2 = u^2/3 on [0,1),  u(3-u)/6 + (6-u)(u-1)/10 on [1,3),
**           (6-u)^2/15 on [3,6)
**   N_1^2 = (u-1)^2/10 on [1,3),  (u-1)(6-u)/15 + (10-u)(u-3)/21 on [3,6),
**           (10-u)^2/28 on [6,10)
**   N_0^3 = u/6 N_0^2 + (10-u)/9 N_1^2:  u^3/18 on [0,1), ...,
**           (10-u)^3/252 on [6,10)
** Values used below (exact fractions):
**   u = 2:   N_0^1 = 1/2, N_1^1 = 1/2, N_0^2 = 1/3 + 2/5 = 11/15,
**            N_1^2 = 1/10, N_0^3 = (2/6)(11/15) + (8/9)(1/10) = 1/3
**   u = 4:   N_0^2 = 4/15, N_1^2 = 2/5 + 2/7 = 24/35,
**            N_0^3 = (4/6)(4/15) + (6/9)(24/35) = 40/63
**   u = 0.5: N_0^2 = 1/12, N_0^3 = 1/144
**   u = 8:   N_2^1 = 1/2, N_1^2 = 1/7, N_0^3 = 8/252 = 2/63
**   u = 1:   N_0^3 = 1/18 (both pieces agree)
*/
static void
test_basis_by_hand(void **state)
{
    static const double U[] = { 0, 1, 3, 6, 10 };
    struct {
        int i, p;
        double u, want;
    } cases[] = {
        { 0, 1, 2.0, 0.5 },        { 1, 1, 2.0, 0.5 },
        { 0, 1, 0.25, 0.25 },      { 2, 1, 8.0, 0.5 },
        { 1, 1, 4.5, 0.5 },        { 0, 2, 2.0, 11.0 / 15 },
        { 1, 2, 2.0, 0.1 },        { 0, 2, 4.0, 4.0 / 15 },
        { 1, 2, 4.0, 24.0 / 35 },  { 0, 2, 0.5, 1.0 / 12 },
        { 1, 2, 8.0, 1.0 / 7 },    { 0, 3, 2.0, 1.0 / 3 },
        { 0, 3, 4.0, 40.0 / 63 },  { 0, 3, 0.5, 1.0 / 144 },
        { 0, 3, 8.0, 2.0 / 63 },   { 0, 3, 1.0, 1.0 / 18 },
        /* outside the support */
        { 1, 1, 0.5, 0.0 },        { 2, 1, 2.0, 0.0 },
        { 0, 1, 3.0, 0.0 },        { 0, 3, -1.0, 0.0 },
        { 0, 3, 11.0, 0.0 },
    };
    (void)state;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        double v = -1.0;
        assert_int_equal(cf_basis_one(cases[c].i, cases[c].p, U, 5,
                                      cases[c].u, &v, NULL),
                         CF_STATUS_OK);
        /* a handful of roundings of values <= 1 */
        tu_assert_close(v, cases[c].want, 8 * EPS, 1.0);
    }
}

/* U = {0, 1, 1, 3, 6, 10}: the double knot cuts N_0^1 off at 1
** (C^{-1}: degree 1, multiplicity 2) and N_0^2 = u^2 ... is C^0 there. */
static void
test_basis_double_knot(void **state)
{
    static const double U[] = { 0, 1, 1, 3, 6, 10 };
    double v;
    (void)state;
    assert_int_equal(cf_basis_one(0, 1, U, 6, 0.999999, &v, NULL), 0);
    tu_assert_close(v, 0.999999, 4 * EPS, 1.0);
    assert_int_equal(cf_basis_one(0, 1, U, 6, 1.0, &v, NULL), 0);
    assert_true(v == 0.0);
    /* N_2^0 is zero everywhere ([1, 1) is empty) */
    for (double u = 0; u <= 10; u += 0.5) {
        assert_int_equal(cf_basis_one(1, 0, U, 6, u, &v, NULL), 0);
        assert_true(v == 0.0);
    }
    /* N_1^1 = (3 - u)/2 on [1, 3): jumps from 0 to 1 at the double knot */
    assert_int_equal(cf_basis_one(1, 1, U, 6, 1.0, &v, NULL), 0);
    tu_assert_close(v, 1.0, 4 * EPS, 1.0);
    /* N_0^2 = u^2 on [0,1) ((u/1) u + 0), then (3-u)^2/4 on [1,3): C^0 */
    assert_int_equal(cf_basis_one(0, 2, U, 6, 0.5, &v, NULL), 0);
    tu_assert_close(v, 0.25, 4 * EPS, 1.0);
    assert_int_equal(cf_basis_one(0, 2, U, 6, 2.0, &v, NULL), 0);
    tu_assert_close(v, 0.25, 4 * EPS, 1.0);
    assert_int_equal(cf_basis_one(0, 2, U, 6, 1.0, &v, NULL), 0);
    tu_assert_close(v, 1.0, 4 * EPS, 1.0);
}

/* Left limit at the last knot: on {0,0,0,1,1,1} the basis is Bernstein's,
** N_2^2(1) = 1 and the curve functions agree. */
static void
test_last_knot_left_limit(void **state)
{
    static const double U[] = { 0, 0, 0, 1, 1, 1 };
    double v, N[3];
    size_t span;
    (void)state;
    assert_int_equal(cf_basis_one(2, 2, U, 6, 1.0, &v, NULL), 0);
    assert_true(v == 1.0);
    assert_int_equal(cf_basis_one(0, 2, U, 6, 0.0, &v, NULL), 0);
    assert_true(v == 1.0);
    assert_int_equal(cf_basis_funs(2, U, 6, 1.0, &span, N, NULL), 0);
    assert_int_equal(span, 2);
    assert_true(N[0] == 0.0 && N[1] == 0.0 && N[2] == 1.0);
    /* Bernstein at 0.3: (0.49, 0.42, 0.09) */
    assert_int_equal(cf_basis_funs(2, U, 6, 0.3, &span, N, NULL), 0);
    tu_assert_close(N[0], 0.49, 4 * EPS, 1.0);
    tu_assert_close(N[1], 0.42, 4 * EPS, 1.0);
    tu_assert_close(N[2], 0.09, 4 * EPS, 1.0);
}

/* Random knot vectors for degree p and npts points: runs of equal knots
** of multiplicity 1..p (1 for p = 0), p + 1 at the ends when clamped. */
static size_t
random_knots(tu_rng *r, int p, size_t npts, double *U, bool clamp)
{
    size_t m = npts + (size_t)p, i = 0, end = m + 1;
    double x = 0.0;
    if (clamp) {
        for (; i <= (size_t)p; i++)
            U[i] = 0.0;
        end = m - (size_t)p;
        x = tu_rng_range(r, 0.05, 1.0);
    }
    while (i < end) {
        size_t run = 1;
        if (p > 1 && tu_rng_u01(r) < 0.25)
            run = 1 + (size_t)(tu_rng_u01(r) * (double)p);
        for (size_t j = 0; j < run && i < end; j++)
            U[i++] = x;
        x += tu_rng_range(r, 0.05, 1.0);
    }
    for (; i <= m; i++)
        U[i] = x;
    return m + 1;
}

/* Partition of unity and non-negativity on every span, and agreement of
** cf_basis_funs with the single-function recursion. */
static void
test_partition_of_unity(void **state)
{
    tu_rng r;
    double U[64], N[8], v;
    (void)state;
    tu_rng_seed(&r, 31);
    for (int trial = 0; trial < 200; trial++) {
        int p = (int)(trial % 6);
        size_t npts = (size_t)p + 1 + (size_t)(tu_rng_u01(&r) * 12);
        size_t nk;
        double a, b;
        cf_diag_t d;
        /* an open vector may come out with an empty domain: draw again */
        do {
            nk = random_knots(&r, p, npts, U, trial % 2 == 0);
            cf_diag_clear(&d);
        } while (cf_knots_validate(p, npts, U, nk, &d) != CF_STATUS_OK
                 && strstr(d.msg, "is empty") != NULL);
        if (d.status != CF_STATUS_OK)
            fail_msg("trial %d: %s", trial, d.msg);
        a = U[p];
        b = U[nk - 1 - (size_t)p];
        for (int s = 0; s <= 60; s++) {
            double u = s == 60 ? b : a + (b - a) * s / 60.0, sum = 0.0;
            size_t span, k2;
            assert_int_equal(cf_basis_funs(p, U, nk, u, &span, N, NULL), 0);
            k2 = cf_knots_find_span(p, U, nk, u);
            assert_int_equal(span, k2);
            assert_true(U[span] < U[span + 1]);
            for (int j = 0; j <= p; j++) {
                assert_true(N[j] >= 0.0);
                sum += N[j];
                /* the single-function recursion agrees (same value up
                ** to a few roundings; it takes the left limit only at
                ** the last knot, so compare inside the domain) */
                if (u < b) {
                    assert_int_equal(cf_basis_one((int)span - p + j, p, U,
                                                  nk, u, &v, NULL), 0);
                    tu_assert_close(v, N[j], 64 * EPS, 1.0);
                }
            }
            /* p + 1 terms, each rounded a few times */
            tu_assert_close(sum, 1.0, 16 * EPS, 1.0);
        }
    }
}

/* Local support: N_i^p vanishes outside [u_i, u_{i+p+1}) and is positive
** inside (between distinct knots). */
static void
test_local_support(void **state)
{
    static const double U[] = { 0, 0, 0, 1, 2, 2, 3, 4, 5, 5, 5 };
    const int p = 2;
    double v;
    (void)state;
    for (int i = 0; i + p + 1 < 11; i++) {
        for (double u = -0.5; u <= 5.5; u += 0.125) {
            assert_int_equal(cf_basis_one(i, p, U, 11, u, &v, NULL), 0);
            if (u < U[i] || u >= U[i + p + 1]) {
                if (!(u == 5.0 && U[i + p + 1] == 5.0))
                    assert_true(v == 0.0);
            } else {
                assert_true(v > 0.0 || u == U[i]);
            }
        }
    }
}

/* Derivatives of the nonzero basis functions against central differences
** and against cf_basis_one_ders; the sum of derivatives is 0. */
static void
test_basis_derivatives(void **state)
{
    static const double U[] = { 0, 0, 0, 0, 0.2, 0.5, 0.5, 0.7, 1, 1, 1, 1 };
    const int p = 3;
    double D[4 * 4], one[5];
    (void)state;
    for (double u = 0.03; u < 1.0; u += 0.0937) {
        size_t span;
        double h = 1e-6;
        assert_int_equal(cf_basis_ders(p, U, 12, u, 3, &span, D, NULL), 0);
        for (int d = 1; d <= 3; d++) {
            double s = 0.0;
            for (int j = 0; j <= p; j++)
                s += D[d * 4 + j];
            /* derivatives reach ~1e3 here (knot spacing 0.2) */
            tu_assert_close(s, 0.0, 1e-12, 1e3);
        }
        for (int j = 0; j <= p; j++) {
            int i = (int)span - p + j;
            double lo, hi;
            /* stay inside the span for the difference quotient */
            if (u - h < U[span] || u + h >= U[span + 1])
                continue;
            assert_int_equal(cf_basis_one(i, p, U, 12, u - h, &lo, NULL), 0);
            assert_int_equal(cf_basis_one(i, p, U, 12, u + h, &hi, NULL), 0);
            /* O(h^2) truncation, 1e-16/h rounding */
            tu_assert_close(D[4 + j], (hi - lo) / (2 * h), 1e-6, 10.0);
            assert_int_equal(cf_basis_one_ders(i, p, U, 12, u, 4, one, NULL),
                             0);
            for (int d = 0; d <= 3; d++)
                tu_assert_close(one[d], D[d * 4 + j], 1e-12, 1e3);
            assert_true(one[4] == 0.0);
        }
    }
}

static void
assert_msg(cf_status_t st, cf_status_t want, const cf_diag_t *d,
           const char *msg)
{
    assert_int_equal(st, want);
    assert_int_equal(d->status, want);
    assert_string_equal(d->msg, msg);
}

/* Every invalid knot vector is rejected with its message. */
static void
test_validate_messages(void **state)
{
    double good[] = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 };
    double U[11];
    cf_diag_t d;
    (void)state;
    cf_diag_clear(&d);
    assert_int_equal(cf_knots_validate(2, 8, good, 11, &d), CF_STATUS_OK);
    assert_int_equal(d.status, CF_STATUS_OK);

    cf_diag_clear(&d);
    assert_msg(cf_knots_validate(2, 8, good, 10, &d), CF_STATUS_BAD_KNOTS, &d,
               "10 knots given, degree 2 with 8 points needs 11");

    memcpy(U, good, sizeof U);
    U[4] = 0.3;
    U[3] = 0.5;
    cf_diag_clear(&d);
    assert_msg(cf_knots_validate(2, 8, U, 11, &d), CF_STATUS_BAD_KNOTS, &d,
               "knot u_4 (0.30) is smaller than knot u_3 (0.50)");
    assert_int_equal(d.index, 4);

    /* values that agree to two decimals get more digits */
    memcpy(U, good, sizeof U);
    U[4] = 0.501;
    U[5] = 0.5;
    cf_diag_clear(&d);
    assert_msg(cf_knots_validate(2, 8, U, 11, &d), CF_STATUS_BAD_KNOTS, &d,
               "knot u_5 (0.500) is smaller than knot u_4 (0.501)");

    memcpy(U, good, sizeof U);
    U[5] = NAN;
    cf_diag_clear(&d);
    assert_msg(cf_knots_validate(2, 8, U, 11, &d), CF_STATUS_NOT_FINITE, &d,
               "knot u_5 is NaN; knots must be finite");

    memcpy(U, good, sizeof U);
    U[3] = U[4] = U[5] = U[6] = 0.5;
    cf_diag_clear(&d);
    assert_msg(cf_knots_validate(2, 8, U, 11, &d), CF_STATUS_BAD_KNOTS, &d,
               "knot u_3 (0.5) has multiplicity 4; degree 2 allows at most 3");

    {
        double e[] = { 0, 0, 0, 0, 1, 1, 1, 1 };
        double z[] = { 0, 0.5, 0.5, 0.5, 0.5, 1 };
        cf_diag_clear(&d);
        /* degree 1, 6 points: domain [u_1, u_6] fine; degree 2 with 5
        ** points on z: multiplicity rule first */
        assert_msg(cf_knots_validate(3, 3, e, 7, &d),
                   CF_STATUS_TOO_FEW_POINTS, &d,
                   "degree 3 needs at least 4 points, 3 given");
        cf_diag_clear(&d);
        assert_msg(cf_knots_validate(1, 4, z, 6, &d), CF_STATUS_BAD_KNOTS,
                   &d, "knot u_1 (0.5) has multiplicity 4; degree 1 allows at "
                   "most 2");
    }
    {
        /* an empty domain: degree 2, 3 points, [u_2, u_3] = [0.5, 0.5] */
        double e[] = { 0, 0.25, 0.5, 0.5, 0.75, 1 };
        cf_diag_clear(&d);
        assert_msg(cf_knots_validate(2, 3, e, 6, &d), CF_STATUS_BAD_KNOTS,
                   &d, "the domain [u_2, u_3] = [0.5, 0.5] is empty");
    }
    cf_diag_clear(&d);
    assert_msg(cf_knots_validate(-1, 8, good, 11, &d), CF_STATUS_BAD_DEGREE,
               &d, "degree -1 is outside 0..32");
    cf_diag_clear(&d);
    assert_msg(cf_knots_validate(2, 8, NULL, 11, &d), CF_STATUS_INVALID_ARG,
               &d, "knots are NULL");
    /* an interior knot of multiplicity p + 1 is allowed (the curve splits) */
    {
        double s[] = { 0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1 };
        assert_int_equal(cf_knots_validate(2, 6, s, 9, NULL), CF_STATUS_OK);
    }
}

static void
test_generators(void **state)
{
    double U[16], par[6] = { 0, 1, 3, 4, 8, 10 };
    cf_diag_t d;
    (void)state;
    assert_int_equal(cf_knots_count(2, 8), 11);
    assert_int_equal(cf_knots_uniform(2, 5, 0.0, 1.0, U, NULL), 0);
    for (int i = 0; i <= 7; i++)
        tu_assert_close(U[i], i / 7.0, 2 * EPS, 1.0);
    assert_int_equal(cf_knots_classify(2, U, 8), CF_KNOTS_PERIODIC);
    assert_int_equal(cf_knots_clamped_uniform(3, 6, 0.0, 3.0, U, NULL), 0);
    {
        double want[] = { 0, 0, 0, 0, 1, 2, 3, 3, 3, 3 };
        for (int i = 0; i < 10; i++)
            tu_assert_close(U[i], want[i], 2 * EPS, 1.0);
    }
    assert_int_equal(cf_knots_classify(3, U, 10), CF_KNOTS_CLAMPED);
    assert_string_equal(cf_knot_kind_to_string(CF_KNOTS_CLAMPED), "clamped");
    assert_string_equal(cf_knot_kind_to_string(CF_KNOTS_OPEN), "open");
    assert_string_equal(cf_knot_kind_to_string(CF_KNOTS_PERIODIC),
                        "periodic");
    /* averaging (NURBS Book 9.8): p = 2: u_3 = (1+3)/2, u_4 = 3.5,
    ** u_5 = 6 */
    assert_int_equal(cf_knots_clamped_averaged(2, 6, par, U, NULL), 0);
    {
        double want[] = { 0, 0, 0, 2, 3.5, 6, 10, 10, 10 };
        for (int i = 0; i < 9; i++)
            tu_assert_close(U[i], want[i], 2 * EPS, 1.0);
    }
    cf_diag_clear(&d);
    par[2] = 1.0;
    assert_int_equal(cf_knots_clamped_averaged(2, 6, par, U, &d),
                     CF_STATUS_INVALID_ARG);
    assert_string_equal(d.msg,
                        "parameter 2 (1) is not larger than parameter 1 (1)");
    cf_diag_clear(&d);
    assert_int_equal(cf_knots_uniform(2, 5, 1.0, 1.0, U, &d),
                     CF_STATUS_INVALID_ARG);
    assert_string_equal(d.msg, "interval [1, 1] is empty");
    assert_int_equal(cf_knots_clamped_uniform(3, 2, 0, 1, U, NULL),
                     CF_STATUS_TOO_FEW_POINTS);
    assert_int_equal(cf_knots_clamped_averaged(0, 6, par, U, NULL),
                     CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_knots_uniform(2, 5, 0, INFINITY, U, NULL),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_knots_uniform(2, 5, 0, 1, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
}

static void
test_span_mult_classify(void **state)
{
    static const double S[] = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1,
                                1 };
    static const double H[] = { 0, 0.07, 0.14, 0.21, 0.28, 0.35, 0.42, 0.5,
                                0.58, 0.65, 0.72, 0.79, 0.86, 0.93, 1 };
    static const double O[] = { 0, 0.1, 0.3, 0.35, 0.6, 0.8, 0.9, 1.0 };
    double a, b;
    (void)state;
    assert_int_equal(cf_knots_find_span(2, S, 11, 0.0), 2);
    assert_int_equal(cf_knots_find_span(2, S, 11, 0.17), 3);
    assert_int_equal(cf_knots_find_span(2, S, 11, 0.169), 2);
    assert_int_equal(cf_knots_find_span(2, S, 11, 0.6), 5);
    assert_int_equal(cf_knots_find_span(2, S, 11, 1.0), 7);
    assert_int_equal(cf_knots_find_span(2, S, 11, 2.0), 7);
    assert_int_equal(cf_knots_find_span(2, S, 11, -1.0), 2);
    assert_int_equal(cf_knots_multiplicity(S, 11, 1.0), 3);
    assert_int_equal(cf_knots_multiplicity(S, 11, 0.5), 1);
    assert_int_equal(cf_knots_multiplicity(S, 11, 0.4), 0);
    assert_int_equal(cf_knots_multiplicity(NULL, 11, 0.4), 0);
    cf_knots_domain(2, S, 11, &a, &b);
    assert_true(a == 0.0 && b == 1.0);
    assert_int_equal(cf_knots_classify(2, S, 11), CF_KNOTS_CLAMPED);
    /* the heart of figure 2.18: 12 points, p = 2, the first 4 intervals
    ** (0.07 each) repeat at the end */
    assert_int_equal(cf_knots_classify(2, H, 15), CF_KNOTS_PERIODIC);
    assert_int_equal(cf_knots_classify(2, O, 8), CF_KNOTS_OPEN);
    cf_knots_domain(2, H, 15, &a, &b);
    assert_true(a == 0.14 && b == 0.86);
}

static void
test_basis_errors(void **state)
{
    static const double U[] = { 0, 1, 3, 6, 10 };
    static const double B[] = { 0, 3, 1, 6, 10 };
    double v, N[4];
    cf_diag_t d;
    (void)state;
    cf_diag_clear(&d);
    assert_int_equal(cf_basis_one(1, 3, U, 5, 1.0, &v, &d),
                     CF_STATUS_BAD_KNOTS);
    assert_string_equal(d.msg, "N_1^3 needs knots u_1..u_5, 5 given");
    cf_diag_clear(&d);
    assert_int_equal(cf_basis_one(0, 3, B, 5, 1.0, &v, &d),
                     CF_STATUS_BAD_KNOTS);
    assert_string_equal(d.msg, "knot u_2 (1.00) is smaller than knot u_1 (3.00)");
    assert_int_equal(cf_basis_one(0, 3, U, 5, NAN, &v, NULL),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_basis_one(0, 3, U, 5, 1.0, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_basis_one(0, 40, U, 5, 1.0, &v, NULL),
                     CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_basis_one_ders(0, 1, U, 5, 1.0, -1, N, NULL),
                     CF_STATUS_INVALID_ARG);
    /* curve basis: needs 2p + 2 knots and u in the domain */
    cf_diag_clear(&d);
    assert_int_equal(cf_basis_funs(3, U, 5, 1.0, NULL, N, &d),
                     CF_STATUS_BAD_KNOTS);
    assert_string_equal(d.msg,
                        "degree 3 needs at least 8 knots, 5 given");
    cf_diag_clear(&d);
    assert_int_equal(cf_basis_funs(1, U, 5, 0.5, NULL, N, &d),
                     CF_STATUS_DOMAIN);
    assert_string_equal(d.msg,
                        "parameter 0.5 is outside the domain [1, 6]");
    assert_int_equal(cf_basis_funs(1, U, 5, INFINITY, NULL, N, NULL),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_basis_funs(1, U, 5, 2.0, NULL, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_basis_ders(1, U, 5, 2.0, 1, NULL, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_basis_ders(-2, U, 5, 2.0, 1, NULL, N, NULL),
                     CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_basis_funs(1, B, 5, 2.0, NULL, N, NULL),
                     CF_STATUS_BAD_KNOTS);
}

/* Cox-de Boor by the recursion itself (0/0 = 0), half-open intervals: an
** independent N_i^p(u). */
static double
cox_de_boor(const double *U, int i, int p, double u)
{
    double a = 0.0, b = 0.0;
    if (p == 0)
        return U[i] <= u && u < U[i + 1] ? 1.0 : 0.0;
    if (U[i + p] > U[i])
        a = (u - U[i]) / (U[i + p] - U[i]) * cox_de_boor(U, i, p - 1, u);
    if (U[i + p + 1] > U[i + 1])
        b = (U[i + p + 1] - u) / (U[i + p + 1] - U[i + 1]) *
            cox_de_boor(U, i + 1, p - 1, u);
    return a + b;
}

/* N_i^p over the whole knot vector: the padded spline equals the basis
** function everywhere on [u_0, u_{m-1}], zero outside its support, the left
** limit at the last knot; its pieces are the graph. */
static void
test_basis_one_spline(void **state)
{
    static const double U1[] = { 0, 1, 3, 6, 10 };
    static const double U2[] = { 0, 0, 0, 0.5, 0.5, 1, 2, 2, 2 };
    static const double U3[] = { -1, 0, 0.25, 0.25, 0.25, 1.5, 2, 3 };
    static const struct { const double *U; size_t m; } vecs[] = {
        { U1, 5 }, { U2, 9 }, { U3, 8 },
    };
    cf_diag_t d;
    (void)state;
    for (size_t v = 0; v < 3; v++) {
        const double *U = vecs[v].U;
        size_t m = vecs[v].m;
        for (int p = 0; p <= 3; p++)
            for (int i = 0; (size_t)i + (size_t)p + 2 <= m; i++) {
                cf_bspline_t *s = NULL;
                cf_bezier_list_t *list = NULL;
                double a, b;
                int mult = 0;
                for (size_t k = 0; k < m; k++) {
                    int mk = cf_knots_multiplicity(U, m, U[k]);
                    mult = mk > mult ? mk : mult;
                }
                if (mult > p + 1) {
                    /* a knot of too high a multiplicity for a curve */
                    assert_int_equal(
                        cf_basis_one_spline(i, p, U, m, &s, NULL),
                        CF_STATUS_BAD_KNOTS);
                    assert_null(s);
                    continue;
                }
                assert_int_equal(cf_basis_one_spline(i, p, U, m, &s, NULL),
                                 CF_STATUS_OK);
                assert_int_equal(cf_bspline_dim(s), 1);
                assert_int_equal(cf_bspline_degree(s), p);
                cf_bspline_domain(s, &a, &b);
                assert_true(a == U[0] && b == U[m - 1]);
                for (int k = 0; k <= 200; k++) {
                    double u = U[0] + (U[m - 1] - U[0]) * k / 200.0, y, ref,
                           one;
                    assert_int_equal(cf_bspline_eval(s, u, &y), CF_STATUS_OK);
                    assert_int_equal(cf_basis_one(i, p, U, m, u, &one, NULL),
                                     CF_STATUS_OK);
                    tu_assert_close(y, one, 1e-12, 1.0);
                    if (k < 200) {
                        ref = cox_de_boor(U, i, p, u);
                        tu_assert_close(y, ref, 1e-12, 1.0);
                    }
                    if (u < U[i] || u > U[i + p + 1])
                        assert_true(fabs(y) <= 1e-15);
                }
                assert_int_equal(cf_bspline_to_beziers(s, &list, NULL),
                                 CF_STATUS_OK);
                assert_true(list->count >= 1);
                cf_bezier_list_destroy(list);
                cf_bspline_destroy(s);
            }
    }
    {
        /* errors name what is wrong */
        static const double bad[] = { 0, 1, 0.5, 2 }, flat[] = { 1, 1, 1 };
        cf_bspline_t *s = (cf_bspline_t *)&d;
        cf_diag_clear(&d);
        assert_int_equal(cf_basis_one_spline(0, 2, bad, 4, &s, &d),
                         CF_STATUS_BAD_KNOTS);
        assert_null(s);
        assert_string_equal(d.msg, "knot u_2 (0.50) is smaller than knot u_1 "
                                   "(1.00)");
        cf_diag_clear(&d);
        assert_int_equal(cf_basis_one_spline(1, 3, U1, 5, &s, &d),
                         CF_STATUS_INVALID_ARG);
        assert_string_equal(d.msg, "N_1^3 needs knots u_1..u_5, 5 given");
        cf_diag_clear(&d);
        assert_int_equal(cf_basis_one_spline(0, 0, flat, 3, &s, &d),
                         CF_STATUS_BAD_KNOTS);
        assert_string_equal(d.msg, "the knots span no interval (all 1)");
        assert_int_equal(cf_basis_one_spline(0, -1, U1, 5, &s, NULL),
                         CF_STATUS_BAD_DEGREE);
        assert_int_equal(cf_basis_one_spline(-1, 1, U1, 5, &s, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_basis_one_spline(0, 1, NULL, 5, &s, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_basis_one_spline(0, 1, U1, 5, NULL, NULL),
                         CF_STATUS_INVALID_ARG);
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_basis_by_hand),
        cmocka_unit_test(test_basis_one_spline),
        cmocka_unit_test(test_basis_double_knot),
        cmocka_unit_test(test_last_knot_left_limit),
        cmocka_unit_test(test_partition_of_unity),
        cmocka_unit_test(test_local_support),
        cmocka_unit_test(test_basis_derivatives),
        cmocka_unit_test(test_validate_messages),
        cmocka_unit_test(test_generators),
        cmocka_unit_test(test_span_mult_classify),
        cmocka_unit_test(test_basis_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
