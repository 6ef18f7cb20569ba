/*
** Degree reduction (curvefig/reduce.h): identities (an elevated curve comes
** back), an independent least-squares solve in long double, the certified
** bound against dense measurement, the uniform method against the L2 one,
** values known in closed form, B-splines, bad input and out of memory.
*/
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/reduce.h"
#include "testutil.h"

static cf_bezier_t *
random_curve(tu_rng *r, size_t dim, int degree, bool rational)
{
    double pts[3 * 24], w[24];
    cf_bezier_t *c;
    assert_true(dim <= 3 && degree < 24);
    for (size_t i = 0; i < ((size_t)degree + 1) * dim; i++)
        pts[i] = tu_rng_range(r, -1.0, 1.0);
    for (int i = 0; i <= degree; i++)
        w[i] = tu_rng_range(r, 0.5, 2.0);
    assert_int_equal(cf_bezier_create(dim, degree, pts, rational ? w : NULL,
                                      &c, NULL), CF_STATUS_OK);
    return c;
}

/* max |a(t) - b(t)| at samples + 1 even parameters (public evaluator) */
static double
dense_dist(const cf_bezier_t *a, const cf_bezier_t *b, int samples)
{
    double m = 0.0;
    for (int j = 0; j <= samples; j++) {
        double p[3], q[3], d2 = 0.0;
        cf_bezier_eval(a, (double)j / samples, p);
        cf_bezier_eval(b, (double)j / samples, q);
        for (size_t k = 0; k < cf_bezier_dim(a); k++)
            d2 += (p[k] - q[k]) * (p[k] - q[k]);
        m = fmax(m, sqrt(d2));
    }
    return m;
}

static cf_reduce_options_t
opts(int by, int k, cf_reduce_method_t method)
{
    cf_reduce_options_t o;
    cf_reduce_options_init(&o);
    o.by = by;
    o.continuity = k;
    o.method = method;
    return o;
}

/* Reducing an elevated curve gives the curve back (both methods, every
** continuity the degree allows, polynomial and rational). */
static void
test_elevated_back(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 310);
    for (int it = 0; it < 120; it++) {
        int n = 1 + it % 9, by = 1 + it % 3;
        bool rat = it % 4 == 3;
        size_t dim = 1 + (size_t)it % 3, h = dim + rat;
        cf_bezier_t *c = random_curve(&r, dim, n, rat), *e, *red;
        int kmax = (n + 1) / 2 - 1;
        assert_int_equal(cf_bezier_elevate(c, by, &e, NULL), CF_STATUS_OK);
        for (int k = -1; k <= kmax; k++)
            for (int meth = 0; meth <= 1; meth++) {
                cf_reduce_options_t o = opts(by, k, (cf_reduce_method_t)meth);
                cf_reduce_report_t rep;
                const double *a, *b;
                assert_int_equal(cf_bezier_reduce(e, &o, &red, &rep, NULL),
                                 CF_STATUS_OK);
                assert_int_equal(cf_bezier_degree(red), n);
                a = cf_bezier_hpoints(c);
                b = cf_bezier_hpoints(red);
                /* points of size <= 2 (weights <= 2): 1e-14 absolute */
                assert_true(tu_max_diff(a, b, (size_t)(n + 1) * h) <= 1e-14);
                /* the bound's rounding allowance, 8 (n + m + 1) eps times
                ** the size (below 16 here): under 1e-12 */
                assert_true(rep.bound <= 1e-12);
                assert_true(rep.polygon_bound <= 1e-12);
                assert_true(rep.max_error <= 1e-14);
                cf_bezier_destroy(red);
            }
        cf_bezier_destroy(e);
        cf_bezier_destroy(c);
    }
}

/* ---- an independent least-squares solve, in long double ---------------- */

static long double
lbinom(int n, int k)
{
    long double v = 1.0L;
    if (k < 0 || k > n)
        return 0.0L;
    for (int i = 1; i <= k; i++)
        v = v * (long double)(n - k + i) / (long double)i;
    return v;
}

/* int_0^1 B_p^a B_q^b: the Beta integral C(a,p) C(b,q) B(p+q+1, a+b-p-q+1) */
static long double
lgram(int a, int p, int b, int q)
{
    return lbinom(a, p) * lbinom(b, q) /
           ((long double)(a + b + 1) * lbinom(a + b, p + q));
}

/* The free points of Q (indices k0 + 1 .. m - k1 - 1) minimising
** int |P - Q|^2 with the other points of Q given (taken from the curve
** under test after its end derivatives were checked), by the normal
** equations solved with Gaussian elimination (partial pivoting) in long
** double; returns the L2 distance of that solution. */
static long double
lsq_reference(const double *P, int n, const double *Qfix, int m, int k,
              size_t h, long double *Q)
{
    int lo = k + 1, hi = m - k - 1, u = hi - lo + 1;
    long double G[24][25 * 3], s = 0.0L;
    for (int i = 0; i <= m; i++)
        for (size_t c = 0; c < h; c++)
            Q[i * (int)h + (int)c] = Qfix[i * (int)h + (int)c];
    for (size_t c = 0; c < h && u > 0; c++) {
        for (int i = 0; i < u; i++) {
            long double rhs = 0.0L;
            for (int l = 0; l <= n; l++)
                rhs += lgram(m, lo + i, n, l) * P[l * (int)h + (int)c];
            for (int j = 0; j <= m; j++)
                if (j < lo || j > hi)
                    rhs -= lgram(m, lo + i, m, j) * Q[j * (int)h + (int)c];
            for (int j = 0; j < u; j++)
                G[i][j] = lgram(m, lo + i, m, lo + j);
            G[i][u] = rhs;
        }
        for (int col = 0; col < u; col++) {
            int piv = col;
            for (int i = col + 1; i < u; i++)
                if (fabsl(G[i][col]) > fabsl(G[piv][col]))
                    piv = i;
            for (int j = 0; j <= u; j++) {
                long double t = G[col][j];
                G[col][j] = G[piv][j];
                G[piv][j] = t;
            }
            for (int i = col + 1; i < u; i++) {
                long double f = G[i][col] / G[col][col];
                for (int j = col; j <= u; j++)
                    G[i][j] -= f * G[col][j];
            }
        }
        for (int i = u - 1; i >= 0; i--) {
            long double v = G[i][u];
            for (int j = i + 1; j < u; j++)
                v -= G[i][j] * Q[(lo + j) * (int)h + (int)c];
            Q[(lo + i) * (int)h + (int)c] = v / G[i][i];
        }
    }
    /* |P - Q|^2 = e^T G e with e = P - Q elevated to degree n:
    ** Q'_i = sum_j C(m,j) C(n-m,i-j) / C(n,i) Q_j */
    for (size_t c = 0; c < h; c++) {
        long double e[24];
        for (int i = 0; i <= n; i++) {
            long double q = 0.0L;
            for (int j = 0; j <= m; j++)
                q += lbinom(m, j) * lbinom(n - m, i - j) / lbinom(n, i) *
                     Q[j * (int)h + (int)c];
            e[i] = P[i * (int)h + (int)c] - q;
        }
        for (int a = 0; a <= n; a++)
            for (int b = 0; b <= n; b++)
                s += lgram(n, a, n, b) * e[a] * e[b];
    }
    return sqrtl(fmaxl(s, 0.0L));
}

/* Whether long double is wider than double here (x87: 64-bit mantissa;
** not under valgrind, which computes it as double, nor on platforms where
** the two are one type). */
static bool
long_double_is_wider(void)
{
    volatile long double one = 1.0L, tiny = 0x1p-60L;
    return one + tiny != one;
}

static void
test_l2_independent(void **state)
{
    tu_rng r;
    int cases = 0;
    /* the reference and the library's L2 distance are each as good as
    ** the rounding of the error's coefficients relative to the error
    ** (errors down to 1e-3 of the curve here): with extended precision
    ** 1e-12 holds; in double, 1e-16 / 1e-3 = 1e-13 per coefficient,
    ** summed over a dozen, 1e-10 */
    double rel = long_double_is_wider() ? 1e-12 : 1e-10;
    (void)state;
    tu_rng_seed(&r, 311);
    for (int it = 0; it < 80; it++) {
        int n = 3 + it % 10, by = 1 + it % 3 < n ? 1 + it % 3 : n - 1;
        int m = n - by;
        size_t dim = 1 + (size_t)it % 3;
        cf_bezier_t *c = random_curve(&r, dim, n, false), *red;
        for (int k = -1; 2 * (k + 1) <= m + 1; k++) {
            cf_reduce_options_t o = opts(by, k, CF_REDUCE_L2);
            cf_reduce_report_t rep;
            long double Q[25 * 3], ref;
            double dp[16 * 3], dq[16 * 3], scale = 1.0;
            assert_int_equal(cf_bezier_reduce(c, &o, &red, &rep, NULL),
                             CF_STATUS_OK);
            /* the end derivatives of orders <= k agree (their size grows
            ** like n!/(n-j)!, hence the scale) */
            for (int end = 0; end <= 1 && k >= 0; end++) {
                cf_bezier_eval_derivs(c, end, k, dp);
                cf_bezier_eval_derivs(red, end, k, dq);
                for (int j = 0; j <= k; j++) {
                    if (j > 0)
                        scale *= n - j + 1;
                    for (size_t d = 0; d < dim; d++)
                        assert_true(fabs(dp[(size_t)j * dim + d] -
                                         dq[(size_t)j * dim + d]) <=
                                    1e-12 * scale);
                }
            }
            ref = lsq_reference(cf_bezier_hpoints(c), n,
                                cf_bezier_hpoints(red), m, k, dim, Q);
            /* the error is stationary at the optimum: equal to 1e-12 */
            tu_assert_close(rep.l2_error, (double)ref, rel, 0.0);
            /* and the points agree within the Gram matrix's condition
            ** (below 1e5 for m <= 11) times the rounding of double */
            for (int i = 0; i <= m; i++)
                for (size_t d = 0; d < dim; d++)
                    assert_true(fabsl(Q[(size_t)i * dim + d] -
                                      cf_bezier_hpoints(red)[(size_t)i * dim +
                                                             d]) <= 1e-9L);
            cases++;
            cf_bezier_destroy(red);
        }
        cf_bezier_destroy(c);
    }
    assert_true(cases > 200);
}

/* The certified bound is above the densely measured maximum, and the
** reported maximum is the dense one (within its refinement); on every
** curve, the uniform reduction's maximum is at most the L2 one's. */
static void
test_bound_and_uniform(void **state)
{
    tu_rng r;
    double ratio_sum = 0.0;
    int polys = 0, skipped = 0, rats = 0;
    (void)state;
    tu_rng_seed(&r, 312);
    for (int it = 0; it < 90; it++) {
        int n = 2 + it % 9, by = n > 2 ? 1 + it % 2 : 1, m = n - by;
        bool rat = it % 3 == 2;
        size_t dim = 1 + (size_t)it % 3;
        cf_bezier_t *c = random_curve(&r, dim, n, rat), *red;
        for (int k = -1; 2 * (k + 1) <= m + 1; k++) {
            double emax[2];
            for (int meth = 0; meth <= 1; meth++) {
                cf_reduce_options_t o = opts(by, k, (cf_reduce_method_t)meth);
                cf_reduce_report_t rep;
                double dense;
                cf_status_t st = cf_bezier_reduce(c, &o, &red, &rep, NULL);
                rats += rat;
                if (rat && st == CF_STATUS_DEGENERATE) {
                    /* a homogeneous reduction may make a weight <= 0 */
                    skipped++;
                    emax[meth] = NAN;
                    continue;
                }
                assert_int_equal(st, CF_STATUS_OK);
                dense = dense_dist(c, red, 20000);
                assert_true(rep.bound >= dense);
                assert_true(rep.bound >= rep.max_error);
                assert_true(rep.polygon_bound >= rep.bound);
                /* the refined maximum is at least every dense sample's,
                ** and not above it by more than the samples' spacing
                ** allows (0.1 % of the error) */
                assert_true(rep.max_error >= dense * (1.0 - 1e-12));
                assert_true(rep.max_error <= dense * 1.001 + 1e-15);
                emax[meth] = dense;
                cf_bezier_destroy(red);
            }
            if (!rat) {
                assert_true(emax[1] <= emax[0] * (1.0 + 1e-9) + 1e-15);
                ratio_sum += emax[1] / emax[0];
                polys++;
            }
        }
        cf_bezier_destroy(c);
    }
    /* and it is a real improvement, not an equal copy */
    assert_true(polys > 100);
    /* random weights in [0.5, 2]: about a third of the homogeneous
    ** reductions make a weight <= 0 (refused, tested above) */
    assert_true(2 * skipped < rats);
    assert_true(ratio_sum / polys < 0.9);
}

/* t^2 on [0, 1] by a line: least squares t - 1/6 (L2 error sqrt(1/180)),
** minimax t - 1/8 (error 1/8); keeping the ends, the chord (error 1/4). */
static void
test_known_values(void **state)
{
    const double P[] = { 0.0, 0.0, 1.0 };
    cf_bezier_t *c, *red;
    cf_reduce_options_t o;
    cf_reduce_report_t rep;
    const double *q;
    (void)state;
    assert_int_equal(cf_bezier_create(1, 2, P, NULL, &c, NULL), CF_STATUS_OK);
    o = opts(1, -1, CF_REDUCE_L2);
    assert_int_equal(cf_bezier_reduce(c, &o, &red, &rep, NULL), CF_STATUS_OK);
    q = cf_bezier_hpoints(red);
    tu_assert_close(q[0], -1.0 / 6.0, 1e-15, 0.0);
    tu_assert_close(q[1], 5.0 / 6.0, 1e-15, 0.0);
    tu_assert_close(rep.l2_error, sqrt(1.0 / 180.0), 1e-14, 0.0);
    tu_assert_close(rep.max_error, 1.0 / 6.0, 1e-12, 0.0);
    cf_bezier_destroy(red);
    /* the uniform method: the grid's minimax within Lawson's stop (1e-4)
    ** and the grid's spacing */
    o.method = CF_REDUCE_UNIFORM;
    assert_int_equal(cf_bezier_reduce(c, &o, &red, &rep, NULL), CF_STATUS_OK);
    q = cf_bezier_hpoints(red);
    tu_assert_close(q[0], -1.0 / 8.0, 2e-3, 0.0);
    tu_assert_close(q[1], 7.0 / 8.0, 2e-3, 0.0);
    tu_assert_close(rep.max_error, 1.0 / 8.0, 2e-3, 0.0);
    cf_bezier_destroy(red);
    o = opts(1, 0, CF_REDUCE_L2);
    assert_int_equal(cf_bezier_reduce(c, &o, &red, &rep, NULL), CF_STATUS_OK);
    q = cf_bezier_hpoints(red);
    assert_true(q[0] == 0.0 && q[1] == 1.0);
    tu_assert_close(rep.max_error, 0.25, 1e-12, 0.0);
    /* the polygon bound |P_1 - 1/2|; on the 32 pieces of the difference
    ** t^2 - t, the two that end at 1/2 have the points (e(a), -1/4, -1/4)
    ** and their mirror: exactly the maximum 1/4 */
    tu_assert_close(rep.polygon_bound, 0.5, 1e-12, 0.0);
    tu_assert_close(rep.bound, 0.25, 1e-12, 0.0);
    cf_bezier_destroy(red);
    cf_bezier_destroy(c);
}

static void
test_bad_input(void **state)
{
    tu_rng r;
    cf_bezier_t *c, *red = (cf_bezier_t *)&red;
    cf_reduce_options_t o;
    cf_diag_t d;
    (void)state;
    tu_rng_seed(&r, 313);
    c = random_curve(&r, 2, 5, false);
    assert_int_equal(cf_bezier_reduce(NULL, NULL, &red, NULL, &d),
                     CF_STATUS_INVALID_ARG);
    assert_null(red);
    assert_int_equal(cf_bezier_reduce(c, NULL, NULL, NULL, &d),
                     CF_STATUS_INVALID_ARG);
    o = opts(0, 0, CF_REDUCE_L2);
    assert_int_equal(cf_bezier_reduce(c, &o, &red, NULL, &d),
                     CF_STATUS_BAD_DEGREE);
    assert_non_null(strstr(d.msg, "by must be 1 .. 4"));
    /* to degree 0, a point: refused */
    o = opts(5, -1, CF_REDUCE_L2);
    assert_int_equal(cf_bezier_reduce(c, &o, &red, NULL, &d),
                     CF_STATUS_BAD_DEGREE);
    /* degree 5 -> 3 holds C^1 at both ends, not C^2 */
    o = opts(2, 2, CF_REDUCE_UNIFORM);
    assert_int_equal(cf_bezier_reduce(c, &o, &red, NULL, &d),
                     CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(d.msg, "k must be -1 .. 1"));
    o = opts(1, -2, CF_REDUCE_L2);
    assert_int_equal(cf_bezier_reduce(c, &o, &red, NULL, &d),
                     CF_STATUS_INVALID_ARG);
    o = opts(1, 0, (cf_reduce_method_t)7);
    assert_int_equal(cf_bezier_reduce(c, &o, &red, NULL, &d),
                     CF_STATUS_INVALID_ARG);
    assert_null(red);
    cf_bezier_destroy(c);
    /* a line cannot be reduced */
    {
        const double s[] = { 0, 0, 2, 4 };
        cf_bezier_create(2, 1, s, NULL, &c, NULL);
        assert_int_equal(cf_bezier_reduce(c, NULL, &red, NULL, &d),
                         CF_STATUS_BAD_DEGREE);
        assert_non_null(strstr(d.msg, "degree 1 cannot be reduced"));
        assert_null(red);
        cf_bezier_destroy(c);
    }
}

/* A polynomial quartic whose reduction overflows: keeping C^1 at both
** ends fixes Q_1 = P_0 + (4/3)(P_1 - P_0) = -(5/3) DBL_MAX for the points
** DBL_MAX, -DBL_MAX, ..., beyond the largest double, whichever method.
** The message names the point and the coordinate (it once said "the
** reduced curve's weight 1 is 1; the rational curve cannot be reduced"). */
static void
test_overflow(void **state)
{
    const double M = DBL_MAX, P[] = { M, -M, M, -M, M };
    cf_bezier_t *c, *red = (cf_bezier_t *)&red;
    cf_diag_t d;
    (void)state;
    assert_int_equal(cf_bezier_create(1, 4, P, NULL, &c, NULL), CF_STATUS_OK);
    for (int meth = 0; meth <= 1; meth++) {
        cf_reduce_options_t o = opts(1, 1, (cf_reduce_method_t)meth);
        assert_int_equal(cf_bezier_reduce(c, &o, &red, NULL, &d),
                         CF_STATUS_NOT_FINITE);
        assert_int_equal(d.index, 1);
        assert_string_equal(d.msg, "the reduced curve's point 1 has "
                                   "coordinate 1 = -inf: the curve's "
                                   "coordinates are too large to reduce it "
                                   "to degree 3");
        assert_null(red);
    }
    cf_bezier_destroy(c);
}

/* ---- B-splines ----------------------------------------------------------- */

static cf_bspline_t *
random_spline(tu_rng *r, int p, size_t count, bool rational)
{
    double pts[2 * 32], w[32];
    cf_bspline_t *s;
    assert_true(count <= 32);
    for (size_t i = 0; i < 2 * count; i++)
        pts[i] = tu_rng_range(r, -1.0, 1.0);
    for (size_t i = 0; i < count; i++)
        w[i] = tu_rng_range(r, 0.5, 2.0);
    assert_int_equal(cf_bspline_create_clamped(2, p, pts, count,
                                               rational ? w : NULL, &s, NULL),
                     CF_STATUS_OK);
    return s;
}

static double
spline_dist(const cf_bspline_t *a, const cf_bspline_t *b, int samples)
{
    double lo, hi, m = 0.0;
    cf_bspline_domain(a, &lo, &hi);
    for (int j = 0; j <= samples; j++) {
        double u = lo + (hi - lo) * j / samples, p[2], q[2];
        cf_bspline_eval(a, u, p);
        cf_bspline_eval(b, u, q);
        m = fmax(m, hypot(p[0] - q[0], p[1] - q[1]));
    }
    return m;
}

static void
test_bspline(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 314);
    for (int it = 0; it < 24; it++) {
        int p = 2 + it % 3, by = 1 + it % 2;
        bool rat = it % 4 == 3;
        size_t count = (size_t)p + 2 + (size_t)it % 5;
        cf_bspline_t *s = random_spline(&r, p, count, rat), *e, *red;
        cf_reduce_options_t o;
        cf_reduce_report_t rep;
        cf_diag_t d;
        cf_status_t st;
        /* elevated and reduced: the original, knots and points */
        cf_reduce_options_init(&o);
        o.by = by;
        o.tolerance = 1e-10;
        o.method = it % 2 ? CF_REDUCE_UNIFORM : CF_REDUCE_L2;
        assert_int_equal(cf_bspline_elevate(s, by, &e, NULL), CF_STATUS_OK);
        st = cf_bspline_reduce(e, &o, &red, &rep, &d);
        if (st != CF_STATUS_OK)
            print_message("it %d: %s\n", it, d.msg);
        assert_int_equal(st, CF_STATUS_OK);
        assert_int_equal(cf_bspline_degree(red), p);
        assert_int_equal(cf_bspline_nknots(red), cf_bspline_nknots(s));
        assert_true(tu_max_diff(cf_bspline_knots(red), cf_bspline_knots(s),
                                cf_bspline_nknots(s)) <= 1e-15);
        assert_true(tu_max_diff(cf_bspline_hpoints(red), cf_bspline_hpoints(s),
                                count * (2 + rat)) <= 1e-12);
        assert_int_equal(rep.continuity, p - 1);
        assert_true(rep.bound <= 1e-10);
        cf_bspline_destroy(red);
        cf_bspline_destroy(e);
        if (p - by < 1) {
            cf_bspline_destroy(s);
            continue;
        }
        /* a genuine reduction within a loose tolerance: the bound holds
        ** and is within the tolerance */
        o.tolerance = 10.0;
        st = cf_bspline_reduce(s, &o, &red, &rep, &d);
        if (st != CF_STATUS_OK)
            print_message("it %d: %s\n", it, d.msg);
        assert_int_equal(st, CF_STATUS_OK);
        assert_int_equal(cf_bspline_degree(red), p - by);
        assert_true(rep.bound <= o.tolerance);
        assert_true(rep.bound >= spline_dist(s, red, 5000));
        assert_true(rep.polygon_bound >= rep.bound);
        assert_true(rep.max_error >= spline_dist(s, red, 5000) *
                                         (1.0 - 1e-12));
        /* a loose tolerance: every break back to C^(q-1), the most a
        ** curve of degree q keeps at a knot (the original is C^(p-1)) */
        assert_int_equal(rep.continuity, p - by - 1);
        cf_bspline_destroy(red);
        /* a tolerance below what the pieces reach: refused, saying the
        ** smallest error (above the tolerance) */
        o.tolerance = 1e-9;
        red = (cf_bspline_t *)&red;
        st = cf_bspline_reduce(s, &o, &red, &rep, &d);
        assert_int_equal(st, CF_STATUS_NO_CONVERGENCE);
        assert_null(red);
        assert_true(rep.bound > o.tolerance);
        assert_non_null(strstr(d.msg, "needs an error of at least"));
        cf_bspline_destroy(s);
    }
}

static void
test_bspline_bad(void **state)
{
    tu_rng r;
    cf_bspline_t *s, *red = (cf_bspline_t *)&red;
    cf_reduce_options_t o;
    cf_diag_t d;
    (void)state;
    tu_rng_seed(&r, 315);
    s = random_spline(&r, 2, 6, false);
    cf_reduce_options_init(&o);
    assert_int_equal(cf_bspline_reduce(NULL, &o, &red, NULL, &d),
                     CF_STATUS_INVALID_ARG);
    o.by = 2;
    assert_int_equal(cf_bspline_reduce(s, &o, &red, NULL, &d),
                     CF_STATUS_BAD_DEGREE);
    assert_non_null(strstr(d.msg, "by must be 1 .. 1"));
    o.by = 1;
    o.tolerance = 0.0;
    assert_int_equal(cf_bspline_reduce(s, &o, &red, NULL, &d),
                     CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(d.msg, "tolerance"));
    o.tolerance = NAN;
    assert_int_equal(cf_bspline_reduce(s, &o, &red, NULL, &d),
                     CF_STATUS_INVALID_ARG);
    assert_null(red);
    cf_bspline_destroy(s);
}

/* Each allocation failing in turn: NO_MEMORY, nothing leaks. */
static void
test_oom(void **state)
{
    tu_rng r;
    cf_bezier_t *c;
    cf_bspline_t *s;
    (void)state;
    tu_rng_seed(&r, 316);
    c = random_curve(&r, 2, 7, true);
    s = random_spline(&r, 3, 7, false);
    for (int meth = 0; meth <= 1; meth++)
        for (long k = 1;; k++) {
            cf_reduce_options_t o = opts(2, 1, (cf_reduce_method_t)meth);
            cf_reduce_report_t rep;
            cf_bezier_t *red = NULL;
            cf_bspline_t *sred = NULL;
            cf_status_t s1, s2;
            o.tolerance = 1.0;
            tu_fail_alloc_after(k);
            s1 = cf_bezier_reduce(c, &o, &red, &rep, NULL);
            cf_bezier_destroy(red);
            tu_fail_alloc_after(k);
            s2 = cf_bspline_reduce(s, &o, &sred, &rep, NULL);
            cf_bspline_destroy(sred);
            tu_fail_alloc_reset();
            assert_int_equal(tu_alloc_live(), 0);
            assert_true(s1 == CF_STATUS_OK || s1 == CF_STATUS_NO_MEMORY);
            assert_true(s2 == CF_STATUS_OK || s2 == CF_STATUS_NO_MEMORY);
            if (s1 == CF_STATUS_OK && s2 == CF_STATUS_OK)
                break;
            assert_true(k < 2000);
        }
    cf_bezier_destroy(c);
    cf_bspline_destroy(s);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_elevated_back),
        cmocka_unit_test(test_l2_independent),
        cmocka_unit_test(test_bound_and_uniform),
        cmocka_unit_test(test_known_values),
        cmocka_unit_test(test_bad_input),
        cmocka_unit_test(test_overflow),
        cmocka_unit_test(test_bspline),
        cmocka_unit_test(test_bspline_bad),
        cmocka_unit_test(test_oom),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
