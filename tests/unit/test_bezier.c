/* Bézier curves: construction, evaluation, derivatives, subdivision,
** elevation, reversal, affine maps, conversion to cubics, errors, OOM. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/bezier.h"
#include "testutil.h"

#define EPS DBL_EPSILON

/* Seed 003: P0..P4 = (0,5) (1,-1) (3,0) (4,3) (6,10). */
static const double seed_pts[] = { 0, 5, 1, -1, 3, 0, 4, 3, 6, 10 };

/* A random curve: coordinates in [-1, 1] (times scale), weights in
** [0.2, 5] when rational. */
static cf_bezier_t *
random_curve(tu_rng *r, size_t dim, int degree, bool rational, double scale)
{
    double pts[(CF_BEZIER_MAX_DEGREE + 1) * 4], w[CF_BEZIER_MAX_DEGREE + 1];
    cf_bezier_t *c = NULL;
    assert_true(dim <= 4 && degree <= CF_BEZIER_MAX_DEGREE);
    for (size_t i = 0; i < ((size_t)degree + 1) * dim; i++)
        pts[i] = scale * tu_rng_range(r, -1.0, 1.0);
    for (int i = 0; i <= degree; i++)
        w[i] = exp(tu_rng_range(r, log(0.2), log(5.0)));
    assert_int_equal(cf_bezier_create(dim, degree, pts, rational ? w : NULL,
                                      &c, NULL), CF_STATUS_OK);
    return c;
}

/* Largest |coordinate| of the Cartesian control points. */
static double
curve_size(const cf_bezier_t *c)
{
    double pts[(CF_BEZIER_MAX_DEGREE + 1) * 4], m = 0.0;
    size_t n = ((size_t)cf_bezier_degree(c) + 1) * cf_bezier_dim(c);
    cf_bezier_get_points(c, pts);
    for (size_t i = 0; i < n; i++)
        m = fmax(m, fabs(pts[i]));
    return m;
}

/* ---- seed 003: the de Casteljau triangle in exact fractions ------------- */

static void
test_seed003_triangle(void **state)
{
    /* t = 3/4: b^r_j = 1/4 b^{r-1}_j + 3/4 b^{r-1}_{j+1}, worked out by
    ** hand.  All values are dyadic fractions, exactly representable, and
    ** every de Casteljau step on them is exact in double (products by
    ** 1/4, 3/4 and sums of dyadics with few bits), so equality is exact. */
    static const double want[] = {
        /* level 0 */
        0, 5, 1, -1, 3, 0, 4, 3, 6, 10,
        /* level 1 */
        3.0 / 4, 1.0 / 2, 5.0 / 2, -1.0 / 4, 15.0 / 4, 9.0 / 4,
        11.0 / 2, 33.0 / 4,
        /* level 2 */
        33.0 / 16, -1.0 / 16, 55.0 / 16, 13.0 / 8, 81.0 / 16, 27.0 / 4,
        /* level 3 */
        99.0 / 32, 77.0 / 64, 149.0 / 32, 175.0 / 32,
        /* level 4: c(3/4) = (273/64, 1127/256) */
        273.0 / 64, 1127.0 / 256,
    };
    double tri[30], p[2];
    cf_bezier_t *c;
    (void)state;
    assert_int_equal(cf_bezier_create(2, 4, seed_pts, NULL, &c, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_bezier_decasteljau_size(c), 30);
    assert_int_equal(cf_bezier_decasteljau(c, 0.75, tri), CF_STATUS_OK);
    for (int i = 0; i < 30; i++)
        assert_true(tri[i] == want[i]);
    assert_int_equal(cf_bezier_eval(c, 0.75, p), CF_STATUS_OK);
    assert_true(p[0] == 273.0 / 64 && p[1] == 1127.0 / 256);
    assert_int_equal(cf_bezier_eval_many(c, (double[]){ 0.75 }, 1, p),
                     CF_STATUS_OK);
    tu_assert_close(p[0], 273.0 / 64, 4 * EPS, 10.0);
    tu_assert_close(p[1], 1127.0 / 256, 4 * EPS, 10.0);
    /* the halves of a split are the triangle's sides (seed 000) */
    {
        cf_bezier_t *l, *r;
        const double *lp, *rp;
        assert_int_equal(cf_bezier_split(c, 0.75, &l, &r, NULL),
                         CF_STATUS_OK);
        lp = cf_bezier_hpoints(l);
        rp = cf_bezier_hpoints(r);
        assert_true(lp[2] == 3.0 / 4 && lp[3] == 1.0 / 2);
        assert_true(lp[4] == 33.0 / 16 && lp[5] == -1.0 / 16);
        assert_true(lp[8] == 273.0 / 64 && rp[0] == 273.0 / 64);
        assert_true(rp[2] == 149.0 / 32 && rp[3] == 175.0 / 32);
        assert_true(rp[6] == 11.0 / 2 && rp[7] == 33.0 / 4);
        cf_bezier_destroy(l);
        cf_bezier_destroy(r);
    }
    cf_bezier_destroy(c);
}

/* ---- degree 40 against an exact rational reference ----------------------- */

/* Non-negative multiprecision integers, base 2^32, enough for 2^288. */
#define LIMBS 9
typedef struct big {
    uint64_t l[LIMBS];
} big;

static void
big_set(big *a, uint64_t v)
{
    memset(a, 0, sizeof *a);
    a->l[0] = v & 0xffffffffu;
    a->l[1] = v >> 32;
}

/* a = p * x + q * y for small p, q */
static void
big_lincomb(big *a, uint64_t p, const big *x, uint64_t q, const big *y)
{
    uint64_t carry = 0;
    for (int i = 0; i < LIMBS; i++) {
        uint64_t v = p * x->l[i] + q * y->l[i] + carry;
        a->l[i] = v & 0xffffffffu;
        carry = v >> 32;
    }
    assert_true(carry == 0);
}

static double
big_to_double(const big *a, int exp2)
{
    /* sum from the top: each limb < 2^32 is exact in double, so the only
    ** roundings are those of the few additions (< 2 ulp overall) */
    double s = 0.0;
    for (int i = LIMBS - 1; i >= 0; i--)
        s += ldexp((double)a->l[i], 32 * i + exp2);
    return s;
}

static void
test_degree40_exact(void **state)
{
    /* Integer control points in [-1000, 1000] and dyadic t = k/64: with the
    ** points shifted by +1000 (non-negative) the de Casteljau recurrence
    ** b^r_i = ((64-k) b^{r-1}_i + k b^{r-1}_{i+1}) / 64 stays exact as
    ** integers N^r_i / 64^r, so c(t) = N^40_0 / 2^240 - 1000 exactly; the
    ** integers need < 2^(11 + 240) and are kept in 288-bit numbers. */
    enum { N = 40 };
    double pts[(N + 1) * 2], got[2], many[2];
    big num[N + 1];
    tu_rng r;
    cf_bezier_t *c;
    (void)state;
    tu_rng_seed(&r, 40);
    for (int i = 0; i < (N + 1) * 2; i++)
        pts[i] = (double)((int)(tu_rng_next(&r) % 2001) - 1000);
    assert_int_equal(cf_bezier_create(2, N, pts, NULL, &c, NULL),
                     CF_STATUS_OK);
    for (int k = 0; k <= 64; k++) {
        double t = k / 64.0;
        assert_int_equal(cf_bezier_eval(c, t, got), CF_STATUS_OK);
        assert_int_equal(cf_bezier_eval_many(c, &t, 1, many), CF_STATUS_OK);
        for (int d = 0; d < 2; d++) {
            double exact;
            for (int i = 0; i <= N; i++)
                big_set(&num[i], (uint64_t)(pts[2 * i + d] + 1000.0));
            for (int lev = 1; lev <= N; lev++)
                for (int i = 0; i <= N - lev; i++)
                    big_lincomb(&num[i], (uint64_t)(64 - k), &num[i],
                                (uint64_t)k, &num[i + 1]);
            exact = big_to_double(&num[0], -6 * N) - 1000.0;
            /* de Casteljau's forward error is at most n u max|P| (each of
            ** the n levels is a convex combination); 1000 is max|P|. */
            assert_true(fabs(got[d] - exact) <= N * EPS * 1000.0);
            assert_true(fabs(many[d] - exact) <= N * EPS * 1000.0);
        }
    }
    cf_bezier_destroy(c);
}

/* ---- the fast batch evaluator against de Casteljau ----------------------- */

static void
test_eval_many_matches_decasteljau(void **state)
{
    /* Horner in Bernstein form with powers of 1 - t (src/bezier-eval.c):
    ** every term is a Bernstein value times a point with O(n) relative
    ** roundings.  Over 40,000 random curves (sizes 2^-20 .. 2^20) and 16
    ** parameters each (some at 0, 1/2, 1 and next to 1/2), the difference
    ** from de Casteljau was measured at <= 4.1 eps max|P| for degrees
    ** 0..10 without FMA and <= 3.0 with it (the x86-64-v3/v4 clones); the
    ** test allows 8 eps max|P| (< 8 ulp of max |P|). */
    static double t[16];
    double fast[16 * 4], ref[4];
    double worst = 0.0;
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 2024);
    for (int it = 0; it < 40000; it++) {
        int n = it % 11;
        size_t dim = 1 + (size_t)(it / 11) % 4;
        double scale = ldexp(1.0, (int)(tu_rng_next(&r) % 41) - 20);
        cf_bezier_t *c = random_curve(&r, dim, n, false, scale);
        double m = curve_size(c);
        for (int j = 0; j < 16; j++)
            t[j] = tu_rng_u01(&r);
        t[0] = 0.0;
        t[1] = 1.0;
        t[2] = 0.5;
        t[3] = nextafter(0.5, 1.0);
        t[4] = nextafter(0.5, 0.0);
        assert_int_equal(cf_bezier_eval_many(c, t, 16, fast), CF_STATUS_OK);
        for (int j = 0; j < 16; j++) {
            assert_int_equal(cf_bezier_eval(c, t[j], ref), CF_STATUS_OK);
            for (size_t d = 0; d < dim; d++) {
                double e = fabs(fast[(size_t)j * dim + d] - ref[d]) /
                           (EPS * m);
                if (e > worst)
                    worst = e;
            }
        }
        cf_bezier_destroy(c);
    }
    assert_true(worst <= 8.0);
}

static void
test_eval_many_large_dim_and_blocks(void **state)
{
    /* dims above the 16-coordinate chunk and more than one 256-block */
    enum { DIM = 37, DEG = 5, NT = 600 };
    double pts[(DEG + 1) * DIM], *t, *out, ref[DIM];
    cf_bezier_t *c;
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 37);
    for (int i = 0; i < (DEG + 1) * DIM; i++)
        pts[i] = tu_rng_range(&r, -3.0, 3.0);
    assert_int_equal(cf_bezier_create(DIM, DEG, pts, NULL, &c, NULL),
                     CF_STATUS_OK);
    t = malloc(NT * sizeof *t);
    out = malloc(NT * DIM * sizeof *out);
    for (int j = 0; j < NT; j++)
        t[j] = tu_rng_u01(&r);
    assert_int_equal(cf_bezier_eval_many(c, t, NT, out), CF_STATUS_OK);
    for (int j = 0; j < NT; j++) {
        cf_bezier_eval(c, t[j], ref);
        for (int d = 0; d < DIM; d++)
            assert_true(fabs(out[j * DIM + d] - ref[d]) <= 8 * EPS * 3.0);
    }
    /* first derivatives the same way, against the hodograph curve */
    {
        cf_bezier_t *h;
        assert_int_equal(cf_bezier_derivative(c, 1, &h, NULL), CF_STATUS_OK);
        assert_int_equal(cf_bezier_eval_deriv_many(c, t, NT, 1, out),
                         CF_STATUS_OK);
        for (int j = 0; j < NT; j++) {
            cf_bezier_eval(h, t[j], ref);
            for (int d = 0; d < DIM; d++)
                assert_true(fabs(out[j * DIM + d] - ref[d]) <=
                            8 * EPS * 6.0 * DEG);
        }
        cf_bezier_destroy(h);
    }
    free(t);
    free(out);
    cf_bezier_destroy(c);
}

static void
test_deriv_many_matches(void **state)
{
    /* eval_deriv_many (fast path on the hodograph, de Casteljau for
    ** rational or high degree) against eval_derivs at random parameters */
    double t[8], many[8 * 3], d[16 * 3];
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 77);
    for (int it = 0; it < 600; it++) {
        int n = it % 14;
        bool rat = (it / 14) % 2 == 1;
        int k = 1 + it % 4;
        size_t dim = 1 + (size_t)it % 3;
        cf_bezier_t *c = random_curve(&r, dim, n, rat, 1.0);
        double scale = 0.0;
        for (int j = 0; j < 8; j++)
            t[j] = tu_rng_u01(&r);
        assert_int_equal(cf_bezier_eval_deriv_many(c, t, 8, k, many),
                         CF_STATUS_OK);
        for (int j = 0; j < 8; j++) {
            assert_int_equal(cf_bezier_eval_derivs(c, t[j], k, d),
                             CF_STATUS_OK);
            for (size_t q = 0; q < dim; q++)
                scale = fmax(scale, fabs(d[(size_t)k * dim + q]));
        }
        for (int j = 0; j < 8; j++) {
            cf_bezier_eval_derivs(c, t[j], k, d);
            for (size_t q = 0; q < dim; q++)
                /* both exact up to rounding; the hodograph's coefficients
                ** grow like n^k, so compare relative to the largest value
                ** with slack for the differences (1e-11) */
                assert_true(fabs(many[(size_t)j * dim + q] -
                                 d[(size_t)k * dim + q]) <=
                            1e-11 * fmax(scale, 1.0) * pow(n + 1, k));
        }
        cf_bezier_destroy(c);
    }
}

/* ---- derivatives ------------------------------------------------------------ */

static void
test_derivs_central_differences(void **state)
{
    /* c^(j+1)(t) ~ (c^(j)(t+h) - c^(j)(t-h)) / 2h with error h^2/6 c^(j+3);
    ** h = 1e-4 gives ~1e-9 relative, rounding ~1e-12: tolerance 1e-6 */
    double d[5 * 3], dp[5 * 3], dm[5 * 3];
    const double h = 1e-4;
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 5);
    for (int it = 0; it < 200; it++) {
        int n = 1 + it % 7;
        bool rat = it % 2 == 1;
        size_t dim = 1 + (size_t)it % 3;
        cf_bezier_t *c = random_curve(&r, dim, n, rat, 1.0);
        double t = tu_rng_range(&r, 0.01, 0.99), scale = 0.0;
        assert_int_equal(cf_bezier_eval_derivs(c, t, 4, d), CF_STATUS_OK);
        cf_bezier_eval_derivs(c, t + h, 4, dp);
        cf_bezier_eval_derivs(c, t - h, 4, dm);
        for (size_t i = 0; i < 5 * dim; i++)
            scale = fmax(scale, fabs(d[i]));
        for (int j = 0; j < 3; j++)
            for (size_t q = 0; q < dim; q++) {
                double cd = (dp[(size_t)j * dim + q] -
                             dm[(size_t)j * dim + q]) / (2 * h);
                assert_true(fabs(cd - d[(size_t)(j + 1) * dim + q]) <=
                            1e-6 * fmax(scale, 1.0));
            }
        cf_bezier_destroy(c);
    }
}

static void
test_derivative_curve(void **state)
{
    /* The derivative as a curve evaluates to eval_derivs: polynomial
    ** (hodograph) and rational (exact quotient, degree 2n, weights w^2). */
    double a[3], d[4 * 3], w[32];
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 9);
    for (int it = 0; it < 120; it++) {
        int n = it % 6;
        bool rat = it % 2 == 1;
        size_t dim = 1 + (size_t)it % 3;
        int k = 1 + it % 3;
        cf_bezier_t *c = random_curve(&r, dim, n, rat, 1.0), *dc;
        double scale = 1.0;
        assert_int_equal(cf_bezier_derivative(c, k, &dc, NULL), CF_STATUS_OK);
        assert_int_equal(cf_bezier_is_rational(dc), rat);
        if (!rat)
            assert_int_equal(cf_bezier_degree(dc), k > n ? 0 : n - k);
        else
            assert_int_equal(cf_bezier_degree(dc), n << k);
        if (rat && n > 0 && k == 1) {
            /* weights are the Bernstein coefficients of w^2, so they are
            ** positive and the end weights are w_0^2 and w_n^2 */
            double cw[8];
            cf_bezier_get_weights(c, cw);
            cf_bezier_get_weights(dc, w);
            tu_assert_close(w[0], cw[0] * cw[0], 4 * EPS, 0.0);
            tu_assert_close(w[2 * n], cw[n] * cw[n], 4 * EPS, 0.0);
        }
        for (int j = 0; j <= 50; j++) {
            double t = j / 50.0;
            cf_bezier_eval(dc, t, a);
            cf_bezier_eval_derivs(c, t, k, d);
            for (size_t q = 0; q < dim; q++)
                scale = fmax(scale, fabs(d[(size_t)k * dim + q]));
            for (size_t q = 0; q < dim; q++)
                assert_true(fabs(a[q] - d[(size_t)k * dim + q]) <=
                            1e-12 * scale);
        }
        cf_bezier_destroy(dc);
        cf_bezier_destroy(c);
    }
}

/* ---- shape-preserving constructions -------------------------------------- */

static double
max_dist_param(const cf_bezier_t *a, double a0, double a1,
               const cf_bezier_t *b, int samples)
{
    /* max over u of |a(a0 + u (a1 - a0)) - b(u)| */
    double pa[4], pb[4], m = 0.0;
    size_t dim = cf_bezier_dim(a);
    for (int j = 0; j <= samples; j++) {
        double u = (double)j / samples;
        cf_bezier_eval(a, a0 + u * (a1 - a0), pa);
        cf_bezier_eval(b, u, pb);
        for (size_t q = 0; q < dim; q++)
            m = fmax(m, fabs(pa[q] - pb[q]));
    }
    return m;
}

static void
test_split_segment_elevate_keep_shape(void **state)
{
    /* Subdivision, segments and elevation only take convex combinations of
    ** the control points: the curve is unchanged to ~1e-14 of its size
    ** (checked at 301 parameters). */
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 11);
    for (int it = 0; it < 80; it++) {
        int n = it % 9;
        bool rat = it % 2 == 1;
        size_t dim = 1 + (size_t)it % 4;
        cf_bezier_t *c = random_curve(&r, dim, n, rat, 10.0), *l, *rr, *s,
                    *e;
        double m = curve_size(c), t = tu_rng_range(&r, 0.01, 0.99);
        double a = tu_rng_range(&r, 0.0, 0.5), b = tu_rng_range(&r, 0.5, 1);
        int up = 1 + it % 5;
        assert_int_equal(cf_bezier_split(c, t, &l, &rr, NULL), CF_STATUS_OK);
        assert_true(max_dist_param(c, 0, t, l, 300) <= 1e-14 * m);
        assert_true(max_dist_param(c, t, 1, rr, 300) <= 1e-14 * m);
        assert_int_equal(cf_bezier_segment(c, a, b, &s, NULL), CF_STATUS_OK);
        assert_true(max_dist_param(c, a, b, s, 300) <= 1e-14 * m);
        assert_int_equal(cf_bezier_elevate(c, up, &e, NULL), CF_STATUS_OK);
        assert_int_equal(cf_bezier_degree(e), n + up);
        assert_true(max_dist_param(c, 0, 1, e, 300) <= 1e-14 * m);
        cf_bezier_destroy(l);
        cf_bezier_destroy(rr);
        cf_bezier_destroy(s);
        cf_bezier_destroy(e);
        /* only one half requested; split_into agrees with split */
        {
            double lh[9 * 5], rh[9 * 5];
            size_t hn = ((size_t)n + 1) * (dim + rat);
            assert_int_equal(cf_bezier_split(c, t, NULL, &rr, NULL),
                             CF_STATUS_OK);
            assert_int_equal(cf_bezier_split(c, t, &l, NULL, NULL),
                             CF_STATUS_OK);
            assert_int_equal(cf_bezier_split_into(c, t, lh, rh),
                             CF_STATUS_OK);
            assert_true(tu_max_diff(lh, cf_bezier_hpoints(l), hn) == 0.0);
            assert_true(tu_max_diff(rh, cf_bezier_hpoints(rr), hn) == 0.0);
            cf_bezier_destroy(l);
            cf_bezier_destroy(rr);
        }
        /* segment [0, 1] is a copy; [0, b] and [a, 1] use one split */
        assert_int_equal(cf_bezier_segment(c, 0, 1, &s, NULL), CF_STATUS_OK);
        assert_true(max_dist_param(c, 0, 1, s, 50) == 0.0);
        cf_bezier_destroy(s);
        assert_int_equal(cf_bezier_segment(c, 0, b, &s, NULL), CF_STATUS_OK);
        assert_true(max_dist_param(c, 0, b, s, 100) <= 1e-14 * m);
        cf_bezier_destroy(s);
        assert_int_equal(cf_bezier_segment(c, a, 1, &s, NULL), CF_STATUS_OK);
        assert_true(max_dist_param(c, a, 1, s, 100) <= 1e-14 * m);
        cf_bezier_destroy(s);
        cf_bezier_destroy(c);
    }
}

static void
test_reverse_and_affine(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 13);
    for (int it = 0; it < 60; it++) {
        int n = it % 8;
        bool rat = it % 2 == 1;
        size_t dim = 1 + (size_t)it % 4;
        cf_bezier_t *c = random_curve(&r, dim, n, rat, 3.0), *rv, *tr;
        double A[16], b[4], m = curve_size(c), an = 0.0, bn = 0.0;
        for (size_t i = 0; i < dim * dim; i++) {
            A[i] = tu_rng_range(&r, -2, 2);
            an = fmax(an, fabs(A[i]));
        }
        for (size_t i = 0; i < dim; i++) {
            b[i] = tu_rng_range(&r, -5, 5);
            bn = fmax(bn, fabs(b[i]));
        }
        assert_int_equal(cf_bezier_reverse(c, &rv, NULL), CF_STATUS_OK);
        assert_int_equal(cf_bezier_transform(c, A, b, &tr, NULL),
                         CF_STATUS_OK);
        for (int j = 0; j <= 200; j++) {
            double t = j / 200.0, p[4], q[4], s[4];
            cf_bezier_eval(c, t, p);
            cf_bezier_eval(rv, 1.0 - t, q);
            /* 1 - (1 - t) may differ from t by an ulp: ~1e-14 */
            for (size_t k = 0; k < dim; k++)
                assert_true(fabs(p[k] - q[k]) <= 1e-14 * m);
            cf_bezier_eval(tr, t, s);
            for (size_t k = 0; k < dim; k++) {
                double want = b[k];
                for (size_t i = 0; i < dim; i++)
                    want += A[k * dim + i] * p[i];
                assert_true(fabs(s[k] - want) <=
                            1e-14 * (dim * an * m + bn));
            }
        }
        /* b == NULL means no translation */
        cf_bezier_destroy(tr);
        assert_int_equal(cf_bezier_transform(c, A, NULL, &tr, NULL),
                         CF_STATUS_OK);
        {
            double p[4], s[4];
            cf_bezier_eval(c, 0.3, p);
            cf_bezier_eval(tr, 0.3, s);
            for (size_t k = 0; k < dim; k++) {
                double want = 0.0;
                for (size_t i = 0; i < dim; i++)
                    want += A[k * dim + i] * p[i];
                assert_true(fabs(s[k] - want) <= 1e-14 * dim * an * m);
            }
        }
        cf_bezier_destroy(rv);
        cf_bezier_destroy(tr);
        cf_bezier_destroy(c);
    }
}

/* ---- tangent, normal, curvature --------------------------------------------- */

static void
test_tangent_normal_curvature(void **state)
{
    /* quarter circle of radius 2 as a rational quadratic (w1 = cos 45) */
    const double q[] = { 2, 0, 2, 2, 0, 2 };
    const double w[] = { 1, 0.70710678118654752440, 1 };
    /* a cusp-free curve with P0 = P1: c'(0) = 0, direction from c'' */
    const double cusp[] = { 0, 0, 0, 0, 1, 0, 1, 1 };
    double tg[3], nm[3], kappa, p[3];
    cf_bezier_t *c, *c3;
    (void)state;
    assert_int_equal(cf_bezier_create(2, 2, q, w, &c, NULL), CF_STATUS_OK);
    for (int j = 0; j <= 20; j++) {
        double t = j / 20.0;
        cf_bezier_eval(c, t, p);
        assert_int_equal(cf_bezier_tangent(c, t, tg), CF_STATUS_OK);
        assert_int_equal(cf_bezier_normal(c, t, nm), CF_STATUS_OK);
        assert_int_equal(cf_bezier_curvature(c, t, &kappa), CF_STATUS_OK);
        /* counter-clockwise: tangent (-y, x)/r, normal points inward */
        tu_assert_close(tg[0], -p[1] / 2, 1e-14, 1.0);
        tu_assert_close(tg[1], p[0] / 2, 1e-14, 1.0);
        tu_assert_close(nm[0], -p[0] / 2, 1e-14, 1.0);
        tu_assert_close(nm[1], -p[1] / 2, 1e-14, 1.0);
        tu_assert_close(kappa, 0.5, 1e-14, 0.0);
    }
    /* the same arc lifted to 3D (z = 1): principal normal and |kappa| */
    {
        const double q3[] = { 2, 0, 1, 2, 2, 1, 0, 2, 1 };
        assert_int_equal(cf_bezier_create(3, 2, q3, w, &c3, NULL),
                         CF_STATUS_OK);
        cf_bezier_eval(c3, 0.3, p);
        assert_int_equal(cf_bezier_normal(c3, 0.3, nm), CF_STATUS_OK);
        tu_assert_close(nm[0], -p[0] / 2, 1e-14, 1.0);
        tu_assert_close(nm[1], -p[1] / 2, 1e-14, 1.0);
        tu_assert_close(nm[2], 0.0, 1e-14, 1.0);
        assert_int_equal(cf_bezier_curvature(c3, 0.3, &kappa), CF_STATUS_OK);
        tu_assert_close(kappa, 0.5, 1e-14, 0.0);
        cf_bezier_destroy(c3);
    }
    cf_bezier_destroy(c);
    assert_int_equal(cf_bezier_create(2, 3, cusp, NULL, &c, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_bezier_tangent(c, 0.0, tg), CF_STATUS_OK);
    tu_assert_close(tg[0], 1.0, 1e-15, 1.0);
    tu_assert_close(tg[1], 0.0, 1e-15, 1.0);
    assert_int_equal(cf_bezier_curvature(c, 0.0, &kappa),
                     CF_STATUS_DEGENERATE);
    cf_bezier_destroy(c);
    /* a point curve has no tangent; a straight 3D line no normal */
    {
        const double pt[] = { 1, 1, 1, 1 };
        const double line[] = { 0, 0, 0, 1, 1, 1, 3, 3, 3 };
        assert_int_equal(cf_bezier_create(2, 1, pt, NULL, &c, NULL),
                         CF_STATUS_OK);
        assert_int_equal(cf_bezier_tangent(c, 0.5, tg), CF_STATUS_DEGENERATE);
        assert_int_equal(cf_bezier_normal(c, 0.5, nm), CF_STATUS_DEGENERATE);
        cf_bezier_destroy(c);
        assert_int_equal(cf_bezier_create(3, 2, line, NULL, &c, NULL),
                         CF_STATUS_OK);
        assert_int_equal(cf_bezier_normal(c, 0.5, nm), CF_STATUS_DEGENERATE);
        assert_int_equal(cf_bezier_curvature(c, 0.5, &kappa), CF_STATUS_OK);
        assert_true(fabs(kappa) <= 1e-14);
        cf_bezier_destroy(c);
    }
}

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

/* ---- queries and errors --------------------------------------------------- */

static void
test_queries(void **state)
{
    const double w[] = { 1, 2, 0.5, 4, 1 };
    double pts[10], ws[5];
    cf_bezier_t *c, *d;
    (void)state;
    assert_int_equal(cf_bezier_create(2, 4, seed_pts, w, &c, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_bezier_dim(c), 2);
    assert_int_equal(cf_bezier_degree(c), 4);
    assert_true(cf_bezier_is_rational(c));
    assert_true(cf_bezier_hpoints(c)[3 * 3 + 0] == 16.0);   /* w3 x3 */
    assert_true(cf_bezier_hpoints(c)[3 * 3 + 2] == 4.0);
    cf_bezier_get_points(c, pts);
    cf_bezier_get_weights(c, ws);
    assert_true(tu_max_diff(pts, seed_pts, 10) == 0.0);
    assert_true(tu_max_diff(ws, w, 5) == 0.0);
    /* the homogeneous constructor gives the same curve */
    assert_int_equal(cf_bezier_create_homogeneous(2, 4, cf_bezier_hpoints(c),
                                                  &d, NULL), CF_STATUS_OK);
    assert_true(tu_max_diff(cf_bezier_hpoints(d), cf_bezier_hpoints(c),
                            15) == 0.0);
    cf_bezier_destroy(d);
    assert_int_equal(cf_bezier_copy(c, &d, NULL), CF_STATUS_OK);
    assert_true(tu_max_diff(cf_bezier_hpoints(d), cf_bezier_hpoints(c),
                            15) == 0.0);
    cf_bezier_destroy(d);
    cf_bezier_destroy(c);
    assert_int_equal(cf_bezier_create(2, 4, seed_pts, NULL, &c, NULL),
                     CF_STATUS_OK);
    assert_false(cf_bezier_is_rational(c));
    cf_bezier_get_weights(c, ws);
    for (int i = 0; i < 5; i++)
        assert_true(ws[i] == 1.0);
    cf_bezier_destroy(c);
    /* NULL curves */
    assert_int_equal(cf_bezier_dim(NULL), 0);
    assert_int_equal(cf_bezier_degree(NULL), 0);
    assert_false(cf_bezier_is_rational(NULL));
    assert_null(cf_bezier_hpoints(NULL));
    assert_int_equal(cf_bezier_decasteljau_size(NULL), 0);
    cf_bezier_get_points(NULL, pts);
    cf_bezier_get_weights(NULL, ws);
    cf_bezier_destroy(NULL);
    cf_bezier_list_destroy(NULL);
}

static void
test_errors_construction(void **state)
{
    double bad[10];
    const double w[] = { 1, 2, 3, -0.5, 1 };
    cf_bezier_t *c = (cf_bezier_t *)&c;
    cf_diag_t d;
    (void)state;
    memcpy(bad, seed_pts, sizeof bad);
    bad[7] = NAN;

    cf_diag_clear(&d);
    assert_int_equal(cf_bezier_create(2, 4, seed_pts, NULL, NULL, &d),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_create(0, 4, seed_pts, NULL, &c, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_null(c);
    assert_int_equal(cf_bezier_create(2, -1, seed_pts, NULL, &c, NULL),
                     CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bezier_create(2, CF_BEZIER_MAX_DEGREE + 1, seed_pts,
                                      NULL, &c, NULL), CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bezier_create(2, 4, NULL, NULL, &c, NULL),
                     CF_STATUS_INVALID_ARG);
    cf_diag_clear(&d);
    assert_int_equal(cf_bezier_create(2, 4, bad, NULL, &c, &d),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(d.index, 3);
    assert_non_null(strstr(d.msg, "point P_3"));
    cf_diag_clear(&d);
    assert_int_equal(cf_bezier_create(2, 4, seed_pts, w, &c, &d),
                     CF_STATUS_BAD_WEIGHT);
    assert_int_equal(d.index, 3);
    assert_string_equal(d.msg, "weight w_3 is -0.5; weights must be finite "
                               "and positive");
    {
        const double w0[] = { 1, 0, 1, 1, 1 };
        const double winf[] = { 1, 1, INFINITY, 1, 1 };
        const double huge[] = { 1e300, 0, 1, 1 };
        const double wbig[] = { 1e300, 1 };
        assert_int_equal(cf_bezier_create(2, 4, seed_pts, w0, &c, NULL),
                         CF_STATUS_BAD_WEIGHT);
        assert_int_equal(cf_bezier_create(2, 4, seed_pts, winf, &c, NULL),
                         CF_STATUS_BAD_WEIGHT);
        /* w x overflows */
        assert_int_equal(cf_bezier_create(2, 1, huge, wbig, &c, NULL),
                         CF_STATUS_NOT_FINITE);
    }
    /* homogeneous: weight (last coordinate) <= 0 names the index */
    {
        const double h[] = { 0, 0, 1, 1, 1, -2 };
        cf_diag_clear(&d);
        assert_int_equal(cf_bezier_create_homogeneous(2, 1, h, &c, &d),
                         CF_STATUS_BAD_WEIGHT);
        assert_int_equal(d.index, 1);
        assert_non_null(strstr(d.msg, "weight w_1 is -2"));
        assert_int_equal(cf_bezier_create_homogeneous(0, 1, h, &c, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bezier_create_homogeneous(2, 1, NULL, &c, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bezier_create_homogeneous(2, -3, h, &c, NULL),
                         CF_STATUS_BAD_DEGREE);
        assert_int_equal(cf_bezier_create_homogeneous(2, 1, h, NULL, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bezier_create_homogeneous(2, 2, bad, &c, NULL),
                         CF_STATUS_NOT_FINITE);
    }
    assert_int_equal(cf_bezier_copy(NULL, &c, NULL), CF_STATUS_INVALID_ARG);
    assert_null(c);
    assert_int_equal(cf_bezier_copy(NULL, NULL, NULL), CF_STATUS_INVALID_ARG);
}

/* Differences of coordinates near DBL_MAX overflow: the derivative is
** refused with the point named, never returned with infinite points. */
static void
test_derivative_overflow_refused(void **state)
{
    const double huge_pts[] = { -1.7e308, 0.0, 1.7e308, 0.0 };
    const double w[] = { 1.0, 1.0 };   /* larger weights overflow w x */
    cf_bezier_t *c = NULL, *d = (cf_bezier_t *)&d;
    cf_diag_t diag;
    (void)state;
    assert_int_equal(cf_bezier_create(2, 1, huge_pts, NULL, &c, NULL),
                     CF_STATUS_OK);
    cf_diag_clear(&diag);
    assert_int_equal(cf_bezier_derivative(c, 1, &d, &diag),
                     CF_STATUS_NOT_FINITE);
    assert_null(d);
    assert_string_equal(diag.msg, "control point 0 overflows "
                                  "(coordinate 1 is inf)");
    cf_bezier_destroy(c);
    /* the rational path too (its numerator has the same differences) */
    assert_int_equal(cf_bezier_create(2, 1, huge_pts, w, &c, NULL), CF_STATUS_OK);
    d = (cf_bezier_t *)&d;
    assert_int_equal(cf_bezier_derivative(c, 1, &d, NULL),
                     CF_STATUS_NOT_FINITE);
    assert_null(d);
    cf_bezier_destroy(c);
    /* a large but representable derivative is fine */
    {
        const double ok[] = { -1e300, 0.0, 1e300, 0.0 };
        assert_int_equal(cf_bezier_create(2, 1, ok, NULL, &c, NULL),
                         CF_STATUS_OK);
        assert_int_equal(cf_bezier_derivative(c, 1, &d, NULL), CF_STATUS_OK);
        cf_bezier_destroy(d);
        cf_bezier_destroy(c);
    }
}

static void
test_errors_operations(void **state)
{
    double out[64], t[2] = { 0.5, 1.5 }, A[4] = { 1, 0, 0, 1 };
    cf_bezier_t *c, *o = (cf_bezier_t *)&o, *o2;
    cf_cubics_t *cu;
    cf_diag_t d;
    (void)state;
    assert_int_equal(cf_bezier_create(2, 4, seed_pts, NULL, &c, NULL),
                     CF_STATUS_OK);
    /* evaluation: NULL, t outside [0, 1], NaN */
    assert_int_equal(cf_bezier_eval(NULL, 0.5, out), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_eval(c, 0.5, NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_eval(c, -0.01, out), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_eval(c, 1.01, out), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_eval(c, NAN, out), CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bezier_eval(c, INFINITY, out), CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bezier_eval(c, 0.0, out), CF_STATUS_OK);
    assert_true(out[0] == 0.0 && out[1] == 5.0);
    assert_int_equal(cf_bezier_eval(c, 1.0, out), CF_STATUS_OK);
    assert_true(out[0] == 6.0 && out[1] == 10.0);
    assert_int_equal(cf_bezier_eval_many(c, t, 2, out), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_eval_many(c, NULL, 2, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_eval_many(c, t, 1, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_eval_many(NULL, t, 1, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_eval_many(c, NULL, 0, NULL), CF_STATUS_OK);
    assert_int_equal(cf_bezier_eval_derivs(c, 0.5, -1, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_eval_derivs(c, 0.5, CF_BEZIER_MAX_DEGREE + 1,
                                           out), CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bezier_eval_derivs(c, 2.0, 1, out), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_eval_derivs(NULL, 0.5, 1, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_eval_deriv_many(c, t, 2, 1, out),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_eval_deriv_many(c, t, 1, -1, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_eval_deriv_many(c, NULL, 1, 1, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_eval_deriv_many(c, t, 1,
                                               CF_BEZIER_MAX_DEGREE + 1, out),
                     CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bezier_decasteljau(c, -1.0, out), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_decasteljau(NULL, 0.5, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_decasteljau(c, 0.5, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_tangent(c, 1.5, out), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_tangent(NULL, 0.5, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_normal(c, NAN, out), CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bezier_normal(NULL, 0.5, out), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_curvature(c, -2, out), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_curvature(c, 0.5, NULL),
                     CF_STATUS_INVALID_ARG);
    /* split at 0 or 1 (open interval), NaN, NULL */
    cf_diag_clear(&d);
    assert_int_equal(cf_bezier_split(c, 0.0, &o, &o2, &d), CF_STATUS_DOMAIN);
    assert_null(o);
    assert_non_null(strstr(d.msg, "split parameter 0"));
    assert_int_equal(cf_bezier_split(c, 1.0, &o, &o2, NULL),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_split(c, NAN, &o, &o2, NULL),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bezier_split(NULL, 0.5, &o, &o2, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_split(c, 0.5, NULL, NULL, NULL), CF_STATUS_OK);
    assert_int_equal(cf_bezier_split_into(c, 0.0, out, out + 10),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_split_into(c, 1.0, out, out + 10),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_split_into(c, NAN, out, out + 10),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bezier_split_into(c, 0.5, NULL, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_split_into(c, 0.5, out, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_split_into(NULL, 0.5, out, out + 10),
                     CF_STATUS_INVALID_ARG);
    /* segment: order and range of the bounds */
    assert_int_equal(cf_bezier_segment(c, 0.5, 0.5, &o, NULL),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_segment(c, -0.1, 0.5, &o, NULL),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_segment(c, 0.1, 1.5, &o, NULL),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_segment(c, NAN, 0.5, &o, NULL),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bezier_segment(NULL, 0.1, 0.5, &o, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_segment(c, 0.1, 0.5, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    /* reverse, transform, elevate, derivative, to_cubics */
    assert_int_equal(cf_bezier_reverse(NULL, &o, NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_reverse(c, NULL, NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_transform(c, NULL, NULL, &o, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_transform(NULL, A, NULL, &o, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_transform(c, A, NULL, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    A[3] = NAN;
    assert_int_equal(cf_bezier_transform(c, A, NULL, &o, NULL),
                     CF_STATUS_NOT_FINITE);
    A[3] = 1e308;   /* 10 * 1e308 overflows */
    assert_int_equal(cf_bezier_transform(c, A, (double[]){ 0, 1e300 }, &o,
                                         NULL), CF_STATUS_NOT_FINITE);
    A[3] = 1;
    assert_int_equal(cf_bezier_transform(c, A, (double[]){ 0, INFINITY }, &o,
                                         NULL), CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bezier_elevate(c, -1, &o, NULL),
                     CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bezier_elevate(c, CF_BEZIER_MAX_DEGREE, &o, NULL),
                     CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bezier_elevate(NULL, 1, &o, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_elevate(c, 1, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_derivative(c, -1, &o, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_derivative(NULL, 1, &o, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_derivative(c, 1, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    cf_diag_clear(&d);
    assert_int_equal(cf_bezier_to_cubics(c, 0.0, &cu, &d),
                     CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(d.msg, "tolerance"));
    assert_int_equal(cf_bezier_to_cubics(c, NAN, &cu, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_to_cubics(NULL, 1e-3, &cu, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_to_cubics(c, 1e-3, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    cf_bezier_destroy(c);
    /* normal in 1D, rational derivative of too high a degree */
    {
        const double p1[] = { 0, 1, 3 };
        const double w[] = { 1, 1, 1 };
        double hp[(CF_BEZIER_MAX_DEGREE / 2 + 2) * 2];
        assert_int_equal(cf_bezier_create(1, 2, p1, NULL, &c, NULL),
                         CF_STATUS_OK);
        assert_int_equal(cf_bezier_normal(c, 0.5, out),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bezier_curvature(c, 0.5, out), CF_STATUS_OK);
        assert_true(out[0] == 0.0);
        cf_bezier_destroy(c);
        assert_int_equal(cf_bezier_create(1, 2, p1, w, &c, NULL),
                         CF_STATUS_OK);
        assert_int_equal(cf_bezier_derivative(c, 10, &o, NULL),
                         CF_STATUS_BAD_DEGREE);
        cf_bezier_destroy(c);
        for (size_t i = 0; i < sizeof hp / sizeof hp[0]; i++)
            hp[i] = 1.0;
        assert_int_equal(cf_bezier_create_homogeneous(
                             1, CF_BEZIER_MAX_DEGREE / 2 + 1, hp, &c, NULL),
                         CF_STATUS_OK);
        cf_diag_clear(&d);
        assert_int_equal(cf_bezier_derivative(c, 1, &o, &d),
                         CF_STATUS_BAD_DEGREE);
        assert_non_null(strstr(d.msg, "degree"));
        cf_bezier_destroy(c);
    }
}

/* ---- out of memory ---------------------------------------------------------- */

typedef cf_status_t (*op_fn)(const cf_bezier_t *c, void **res);

static cf_status_t
op_create(const cf_bezier_t *c, void **res)
{
    const double w[] = { 1, 2, 3, 4, 5 };
    (void)c;
    return cf_bezier_create(2, 4, seed_pts, w, (cf_bezier_t **)res, NULL);
}

static cf_status_t
op_split(const cf_bezier_t *c, void **res)
{
    cf_bezier_t *l = NULL, *r = NULL;
    cf_status_t st = cf_bezier_split(c, 0.3, &l, &r, NULL);
    if (st == CF_STATUS_OK) {
        assert_non_null(l);
        assert_non_null(r);
        cf_bezier_destroy(l);
        *res = r;
    } else {
        assert_null(l);
        assert_null(r);
    }
    return st;
}

static cf_status_t
op_elevate(const cf_bezier_t *c, void **res)
{
    return cf_bezier_elevate(c, 3, (cf_bezier_t **)res, NULL);
}

static cf_status_t
op_derivative(const cf_bezier_t *c, void **res)
{
    return cf_bezier_derivative(c, 2, (cf_bezier_t **)res, NULL);
}

static cf_status_t
op_misc(const cf_bezier_t *c, void **res)
{
    cf_bezier_t *a = NULL, *b = NULL;
    const double A[] = { 0, 1, 1, 0 };
    cf_status_t st = cf_bezier_segment(c, 0.2, 0.7, &a, NULL);
    if (st == CF_STATUS_OK)
        st = cf_bezier_reverse(a, &b, NULL);
    cf_bezier_destroy(a);
    a = NULL;
    if (st == CF_STATUS_OK)
        st = cf_bezier_transform(b, A, NULL, &a, NULL);
    cf_bezier_destroy(b);
    b = NULL;
    if (st == CF_STATUS_OK)
        st = cf_bezier_copy(a, &b, NULL);
    cf_bezier_destroy(a);
    *res = b;
    return st;
}

static cf_status_t
op_cubics(const cf_bezier_t *c, void **res)
{
    cf_cubics_t *cu = NULL;
    cf_status_t st = cf_bezier_to_cubics(c, 1e-7, &cu, NULL);
    if (st == CF_STATUS_OK)
        assert_true(cu->count > 8);   /* several reallocations happened */
    cf_cubics_destroy(cu);
    *res = NULL;
    return st;
}

static void
run_oom(op_fn op, const cf_bezier_t *c, bool is_curve)
{
    /* fail the k-th allocation for k = 1, 2, ... until the operation
    ** succeeds; every failure reports NO_MEMORY and leaks nothing */
    for (long k = 1;; k++) {
        void *res = NULL;
        cf_status_t st;
        tu_fail_alloc_after(k);
        st = op(c, &res);
        if (st == CF_STATUS_OK) {
            if (is_curve)
                cf_bezier_destroy(res);
            assert_int_equal(tu_alloc_live(), 0);
            tu_fail_alloc_reset();
            assert_true(k > 1);
            return;
        }
        assert_int_equal(st, CF_STATUS_NO_MEMORY);
        assert_null(res);
        assert_int_equal(tu_alloc_live(), 0);
        tu_fail_alloc_reset();
        assert_true(k < 100000);
    }
}

static void
test_out_of_memory(void **state)
{
    cf_bezier_t *c, *cr;
    const double w[] = { 1, 2, 3, 4, 5 };
    (void)state;
    assert_int_equal(cf_bezier_create(2, 4, seed_pts, NULL, &c, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_bezier_create(2, 4, seed_pts, w, &cr, NULL),
                     CF_STATUS_OK);
    run_oom(op_create, NULL, true);
    run_oom(op_split, c, true);
    run_oom(op_split, cr, true);
    run_oom(op_elevate, c, true);
    run_oom(op_derivative, c, true);
    run_oom(op_derivative, cr, true);
    run_oom(op_misc, cr, true);
    run_oom(op_cubics, c, false);
    run_oom(op_cubics, cr, false);
    cf_bezier_destroy(c);
    cf_bezier_destroy(cr);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_seed003_triangle),
        cmocka_unit_test(test_degree40_exact),
        cmocka_unit_test(test_eval_many_matches_decasteljau),
        cmocka_unit_test(test_eval_many_large_dim_and_blocks),
        cmocka_unit_test(test_deriv_many_matches),
        cmocka_unit_test(test_derivs_central_differences),
        cmocka_unit_test(test_derivative_curve),
        cmocka_unit_test(test_split_segment_elevate_keep_shape),
        cmocka_unit_test(test_reverse_and_affine),
        cmocka_unit_test(test_tangent_normal_curvature),
        cmocka_unit_test(test_to_cubics),
        cmocka_unit_test(test_to_cubics_counts),
        cmocka_unit_test(test_to_cubics_bounded),
        cmocka_unit_test(test_queries),
        cmocka_unit_test(test_errors_construction),
        cmocka_unit_test(test_errors_operations),
        cmocka_unit_test(test_derivative_overflow_refused),
        cmocka_unit_test(test_out_of_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
