/* Bézier curves: construction, evaluation, derivatives, subdivision,
** elevation, reversal, affine maps, conversion to cubics, errors, OOM. This
** file has the first sections; the others are in test_bezier_convert.c and
** test_bezier_queries.c, the shared helpers in test_bezier.h. */
#include "test_bezier.h"

#define EPS DBL_EPSILON

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
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
