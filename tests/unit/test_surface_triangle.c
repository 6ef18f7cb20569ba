/* Triangular Bézier patches (curvefig/surface-triangle.h), against the
** Bernstein form n! / (i! j! k!) u^i v^j w^k summed in long double, and its
** directional derivative n sum (du B_(i-1)jk + dv B_i(j-1)k + dw B_ij(k-1))
** b_ijk with the quotient rule for rational patches. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/surface-triangle.h"
#include "testutil.h"

#define EPS 2.220446049250313e-16
typedef long double ld;

static size_t
idx(int n, int i, int j)
{
    size_t r = (size_t)(n - i);
    return r * (r + 1) / 2 + (r - (size_t)j);
}

static ld
fact(int n)
{
    ld f = 1;
    for (int i = 2; i <= n; i++)
        f *= i;
    return f;
}

/* B^n_ijk (0 for a negative index). */
static ld
bern(int n, int i, int j, int k, ld u, ld v, ld w)
{
    if (i < 0 || j < 0 || k < 0)
        return 0;
    return fact(n) / (fact(i) * fact(j) * fact(k)) * powl(u, i) * powl(v, j) *
           powl(w, k);
}

/* Value (der 0) or first directional derivative along d (der 1). */
static void
reference(int n, const double *P, const double *W, double u, double v,
          const double *d, double *val, double *der)
{
    ld w = 1.0L - u - v, A[3] = { 0, 0, 0 }, Aw = 0, D[3] = { 0, 0, 0 },
       Dw = 0;
    for (int i = n; i >= 0; i--)
        for (int j = n - i; j >= 0; j--) {
            int k = n - i - j;
            size_t f = idx(n, i, j);
            ld wt = W ? W[f] : 1.0L;
            ld b = bern(n, i, j, k, u, v, w);
            ld db = n > 0 ? n * (d[0] * bern(n - 1, i - 1, j, k, u, v, w) +
                                 d[1] * bern(n - 1, i, j - 1, k, u, v, w) +
                                 d[2] * bern(n - 1, i, j, k - 1, u, v, w))
                          : 0;
            for (int c = 0; c < 3; c++) {
                A[c] += b * wt * P[f * 3 + c];
                D[c] += db * wt * P[f * 3 + c];
            }
            Aw += b * wt;
            Dw += db * wt;
        }
    for (int c = 0; c < 3; c++) {
        val[c] = (double)(A[c] / Aw);
        der[c] = (double)((D[c] - Dw * (A[c] / Aw)) / Aw);
    }
}

static cf_bezier_triangle_t *
random_patch(tu_rng *r, int n, int rational, double *P, double *W)
{
    cf_bezier_triangle_t *t = NULL;
    size_t cnt = ((size_t)n + 1) * ((size_t)n + 2) / 2;
    for (size_t i = 0; i < 3 * cnt; i++)
        P[i] = tu_rng_range(r, -5, 5);
    for (size_t i = 0; i < cnt; i++)
        W[i] = tu_rng_range(r, 0.4, 2.5);
    assert_int_equal(cf_bezier_triangle_create(3, n, P, rational ? W : NULL,
                                               &t, NULL), 0);
    return t;
}

static void
test_eval_derivs(void **state)
{
    static const double d[3] = { 0.3, -1.0, 0.7 };
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 61);
    for (int t = 0; t < 100; t++) {
        double P[3 * 66], W[66], x[3], y[3], D[9], ref[3], rder[3];
        int n = t % 8;
        cf_bezier_triangle_t *T = random_patch(&r, n, t % 2, P, W);
        double u = tu_rng_u01(&r), v = tu_rng_u01(&r) * (1 - u);
        double *net = malloc(cf_bezier_triangle_decasteljau_size(T) *
                             sizeof *net);
        size_t last = cf_bezier_triangle_decasteljau_size(T) / 3 - 1;
        if (t % 5 == 0)
            u = 1.0, v = 0.0;   /* a corner */
        reference(n, P, t % 2 ? W : NULL, u, v, d, ref, rder);
        assert_int_equal(cf_bezier_triangle_eval(T, u, v, x), 0);
        assert_true(tu_max_diff(x, ref, 3) <= 1e-13 * 5);
        assert_int_equal(cf_bezier_triangle_decasteljau(T, u, v, net), 0);
        assert_true(tu_max_diff(net + 3 * last, x, 3) == 0.0);
        assert_true(tu_max_diff(net, P, 3) <= 4 * EPS * 5);
        assert_int_equal(cf_bezier_triangle_eval_derivs(T, d, u, v, 2, D), 0);
        assert_true(tu_max_diff(D, x, 3) <= 4 * EPS * 5);
        for (int c = 0; c < 3; c++)
            tu_assert_close(D[3 + c], rder[c], 1e-11, 5.0 * (n + 1));
        /* the second derivative against a central difference of the first
        ** along d (error O(h^2) of the third derivative: 1e-5 relative) */
        if (u > 0.1 && v > 0.1 && 1 - u - v > 0.1) {
            double h = 1e-4, Dp[6], Dm[6];
            assert_int_equal(cf_bezier_triangle_eval_derivs(
                                 T, d, u + h * d[0], v + h * d[1], 1, Dp), 0);
            assert_int_equal(cf_bezier_triangle_eval_derivs(
                                 T, d, u - h * d[0], v - h * d[1], 1, Dm), 0);
            for (int c = 0; c < 3; c++)
                tu_assert_close(D[6 + c], (Dp[3 + c] - Dm[3 + c]) / (2 * h),
                                1e-5, 5.0 * (n + 1) * (n + 1));
        }
        (void)y;
        free(net);
        cf_bezier_triangle_destroy(T);
    }
}

/* Subdivision, elevation and the boundary curves leave every point where
** it was. */
static void
test_constructions(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 62);
    for (int t = 0; t < 40; t++) {
        double P[3 * 45], W[45];
        int n = 1 + t % 7;
        cf_bezier_triangle_t *T = random_patch(&r, n, t % 2, P, W), *S[3],
                             *E = NULL;
        double pu = tu_rng_range(&r, 0.1, 0.5), pv = tu_rng_range(&r, 0.1,
                                                                  0.4);
        double p[3] = { pu, pv, 1 - pu - pv };
        assert_int_equal(cf_bezier_triangle_subdivide(T, pu, pv, S, NULL), 0);
        assert_int_equal(cf_bezier_triangle_elevate(T, &E, NULL), 0);
        assert_int_equal(cf_bezier_triangle_degree(E), n + 1);
        for (int s = 0; s < 3; s++)
            for (int q = 0; q < 10; q++) {
                /* a point of sub-triangle s in its own coordinates */
                double a = tu_rng_u01(&r), b = tu_rng_u01(&r) * (1 - a);
                double c = 1 - a - b, bc[3] = { a, b, c }, g[3] = { 0, 0, 0 };
                double x[3], y[3];
                /* corners: s = 0: (p, e2, e3), 1: (e1, p, e3), 2: (e1,
                ** e2, p) */
                for (int m = 0; m < 3; m++)
                    for (int e = 0; e < 3; e++)
                        g[e] += bc[m] * (m == s ? p[e] : (e == m ? 1 : 0));
                assert_int_equal(cf_bezier_triangle_eval(S[s], a, b, x), 0);
                assert_int_equal(cf_bezier_triangle_eval(T, g[0], g[1], y),
                                 0);
                assert_true(tu_max_diff(x, y, 3) <= 1e-12 * 5);
                assert_int_equal(cf_bezier_triangle_eval(E, a, b, x), 0);
                assert_int_equal(cf_bezier_triangle_eval(T, a, b, y), 0);
                assert_true(tu_max_diff(x, y, 3) <= 1e-12 * 5);
            }
        for (int e = 0; e < 3; e++) {
            cf_bezier_t *c = NULL;
            assert_int_equal(cf_bezier_triangle_boundary(T, e, &c, NULL), 0);
            for (int q = 0; q <= 8; q++) {
                double s = q / 8.0, x[3], y[3];
                double uu = e == 0 ? 1 - s : e == 1 ? 0 : s;
                double vv = e == 0 ? s : e == 1 ? 1 - s : 0;
                assert_int_equal(cf_bezier_eval(c, s, x), 0);
                assert_int_equal(cf_bezier_triangle_eval(T, uu, vv, y), 0);
                assert_true(tu_max_diff(x, y, 3) <= 1e-12 * 5);
            }
            cf_bezier_destroy(c);
        }
        for (int s = 0; s < 3; s++)
            cf_bezier_triangle_destroy(S[s]);
        cf_bezier_triangle_destroy(E);
        cf_bezier_triangle_destroy(T);
    }
}

/* A flat patch: its normal is the plane's; errors. */
static void
test_normal_errors(void **state)
{
    /* degree 2 in the plane z = 2 x - y + 1, corners counter-clockwise
    ** seen from above */
    double P[6 * 3], n[3], W[6] = { 1, 1, 1, 1, -1, 1 };
    cf_bezier_triangle_t *T = NULL;
    cf_diag_t d;
    static const double xy[6][2] = { { 1, 0 }, { 0.5, 0.5 }, { 0.5, 0 },
                                     { 0, 1 }, { 0, 0.5 }, { 0, 0 } };
    (void)state;
    for (int i = 0; i < 6; i++) {
        P[3 * i] = xy[i][0] + 0.1 * xy[i][1];
        P[3 * i + 1] = xy[i][1];
        P[3 * i + 2] = 2 * P[3 * i] - P[3 * i + 1] + 1;
    }
    assert_int_equal(cf_bezier_triangle_create(3, 2, P, NULL, &T, NULL), 0);
    assert_int_equal(cf_bezier_triangle_normal(T, 0.2, 0.3, n), 0);
    tu_assert_close(n[0], -2 / sqrt(6.0), 1e-14, 1.0);
    tu_assert_close(n[1], 1 / sqrt(6.0), 1e-14, 1.0);
    tu_assert_close(n[2], 1 / sqrt(6.0), 1e-14, 1.0);
    assert_int_equal(cf_bezier_triangle_eval(T, 0.7, 0.7, n),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_triangle_eval(T, NAN, 0.2, n),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bezier_triangle_eval(T, 1.0 + 4 * EPS, 0.0, n), 0);
    cf_bezier_triangle_destroy(T);
    assert_int_equal(cf_bezier_triangle_create(3, 2, P, W, &T, &d),
                     CF_STATUS_BAD_WEIGHT);
    assert_non_null(strstr(d.msg, "weight of b_011 is -1"));
    P[4] = NAN;
    assert_int_equal(cf_bezier_triangle_create(3, 2, P, NULL, &T, &d),
                     CF_STATUS_NOT_FINITE);
    assert_non_null(strstr(d.msg, "point b_110 has coordinate 2"));
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_eval_derivs),
        cmocka_unit_test(test_constructions),
        cmocka_unit_test(test_normal_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
