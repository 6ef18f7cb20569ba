/* Tensor-product surfaces (curvefig/surface.h): curvatures of a Monge
** patch against their closed forms in long double, a surface closed in u,
** and the errors in the user's terms. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/surface.h"
#include "testutil.h"

#define EPS 2.220446049250313e-16
typedef long double ld;

/* Curvature of a Monge patch z = f(x, y), f = a x^2 + b x y + c y^2 + d x
** + e y (a Bézier surface of degrees (2, 2) with x = u, y = v), against
** K = (f_xx f_yy - f_xy^2) / (1 + |grad f|^2)^2 and
** H = ((1 + f_x^2) f_yy - 2 f_x f_y f_xy + (1 + f_y^2) f_xx)
**     / (2 (1 + |grad f|^2)^{3/2}) (upward normal). */
static void
test_curvature_monge(void **state)
{
    const double a = 0.7, bb = -0.4, c = 1.3, d = 0.2, e = -0.5;
    double P[27];
    cf_bezier_surface_t *s = NULL;
    (void)state;
    /* Bernstein coefficients of f on [0,1]^2 by polar forms:
    ** f(u,v) blossom with x-values 0,0 / 0,1 / 1,1 */
    for (int i = 0; i <= 2; i++)
        for (int j = 0; j <= 2; j++) {
            double xs[2] = { i >= 1 ? 1.0 : 0.0, i >= 2 ? 1.0 : 0.0 };
            double ys[2] = { j >= 1 ? 1.0 : 0.0, j >= 2 ? 1.0 : 0.0 };
            double xx = xs[0] * xs[1], yy = ys[0] * ys[1];
            double x = (xs[0] + xs[1]) / 2, y = (ys[0] + ys[1]) / 2;
            P[(i * 3 + j) * 3 + 0] = x;
            P[(i * 3 + j) * 3 + 1] = y;
            P[(i * 3 + j) * 3 + 2] = a * xx + bb * x * y + c * yy + d * x +
                                     e * y;
        }
    assert_int_equal(cf_bezier_surface_create(3, 2, 2, P, NULL, &s, NULL), 0);
    for (int t = 0; t <= 10; t++) {
        ld x = t / 10.0L, y = 1.0L - t / 13.0L;
        ld fx = 2 * a * x + bb * y + d, fy = bb * x + 2 * c * y + e;
        ld fxx = 2 * a, fyy = 2 * c, fxy = bb, g = 1 + fx * fx + fy * fy;
        ld K = (fxx * fyy - fxy * fxy) / (g * g);
        ld H = ((1 + fx * fx) * fyy - 2 * fx * fy * fxy +
                (1 + fy * fy) * fxx) / (2 * powl(g, 1.5L));
        double k, h, n[3], z[3];
        assert_int_equal(cf_bezier_surface_eval(s, (double)x, (double)y, z),
                         0);
        tu_assert_close(z[2], (double)(a * x * x + bb * x * y + c * y * y +
                                       d * x + e * y), 32 * EPS, 1.0);
        assert_int_equal(cf_bezier_surface_curvature(s, (double)x, (double)y,
                                                     &k, &h), 0);
        assert_int_equal(cf_bezier_surface_normal(s, (double)x, (double)y, n),
                         0);
        tu_assert_close(k, (double)K, 1e-13, 1.0);
        tu_assert_close(h, (double)H, 1e-13, 1.0);
        tu_assert_close(n[2], (double)(1.0L / sqrtl(g)), 1e-14, 1.0);
    }
    cf_bezier_surface_destroy(s);
}

/* A surface closed in u (rows wrapped, periodic uniform knots, as
** cf_bspline_create_closed makes curves): S and S_u, S_uu agree at u = a
** and u = b; knot insertion keeps it. */
static void
test_periodic(void **state)
{
    enum { C = 6, P = 3, NV = 4 };
    double U[C + 2 * P + 1], V[NV + 3], G[(C + P) * NV * 3];
    cf_bspline_surface_t *s = NULL, *k = NULL;
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 34);
    for (int i = 0; i <= C + 2 * P; i++)
        U[i] = (double)(i - P) / C;
    for (int i = 0; i < NV + 3; i++)
        V[i] = i < 3 ? 0.0 : i >= NV ? 1.0 : 0.5;
    for (int i = 0; i < C; i++)
        for (int j = 0; j < NV * 3; j++)
            G[i * NV * 3 + j] = tu_rng_range(&r, -1, 1);
    memcpy(G + C * NV * 3, G, P * NV * 3 * sizeof *G);
    assert_int_equal(cf_bspline_surface_create(3, P, 2, U, C + 2 * P + 1, V,
                                               NV + 3, G, C + P, NV, NULL,
                                               &s, NULL), 0);
    assert_int_equal(cf_bspline_surface_insert_knot(s, CF_DIR_U, 0.3, 1, &k,
                                                    NULL), 0);
    for (int j = 0; j <= 8; j++) {
        double a[27], b[27], x[3], y[3];
        assert_int_equal(cf_bspline_surface_eval_derivs(s, 0.0, j / 8.0, 2,
                                                        a), 0);
        assert_int_equal(cf_bspline_surface_eval_derivs(s, 1.0, j / 8.0, 2,
                                                        b), 0);
        /* S, S_u, S_uu: entries (0, 0), (1, 0), (2, 0) */
        assert_true(tu_max_diff(a, b, 3) <= 1e-14 * 4);
        assert_true(tu_max_diff(a + 9, b + 9, 3) <= 1e-12 * 40);
        assert_true(tu_max_diff(a + 18, b + 18, 3) <= 1e-11 * 400);
        for (int i = 0; i <= 8; i++) {
            assert_int_equal(cf_bspline_surface_eval(s, i / 8.0, j / 8.0, x),
                             0);
            assert_int_equal(cf_bspline_surface_eval(k, i / 8.0, j / 8.0, y),
                             0);
            assert_true(tu_max_diff(x, y, 3) <= 1e-14 * 8);
        }
    }
    cf_bspline_surface_destroy(k);
    cf_bspline_surface_destroy(s);
}

/* ---- errors in the user's terms ---- */

static void
test_errors(void **state)
{
    double U[7] = { 0, 0, 0, 0.5, 1, 1, 1 }, V[6] = { 0, 0, 0, 1, 1, 1 };
    double P[4 * 3 * 3], W[12], x[3];
    cf_bspline_surface_t *s = (void *)&x;
    cf_bezier_surface_t *b = (void *)&x;
    cf_diag_t d;
    (void)state;
    for (int i = 0; i < 36; i++)
        P[i] = i;
    for (int i = 0; i < 12; i++)
        W[i] = 1.0;
    assert_int_equal(cf_bspline_surface_create(3, 2, 2, U, 7, V, 6, P, 4, 3,
                                               NULL, &s, &d), 0);
    assert_int_equal(cf_bspline_surface_eval(s, 1.0 + 4 * EPS, 0.5, x), 0);
    assert_int_equal(cf_bspline_surface_eval(s, 1.0 + 1e-9, 0.5, x),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_bspline_surface_eval(s, 0.5, NAN, x),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bspline_surface_iso(s, CF_DIR_V, 1.5, NULL, &d),
                     CF_STATUS_INVALID_ARG);
    {
        cf_bspline_t *c = NULL;
        assert_int_equal(cf_bspline_surface_iso(s, CF_DIR_V, 1.5, &c, &d),
                         CF_STATUS_DOMAIN);
        assert_non_null(strstr(d.msg, "parameter v = 1.5"));
    }
    cf_bspline_surface_destroy(s);
    /* a grid that does not match degree and knots */
    assert_int_equal(cf_bspline_surface_create(3, 2, 2, U, 7, V, 6, P, 3, 4,
                                               NULL, &s, &d),
                     CF_STATUS_BAD_KNOTS);
    assert_null(s);
    assert_non_null(strstr(d.msg, "knots U: 7 knots given, degree 2 with 3 "
                                  "points needs 6"));
    V[1] = 0.7;
    assert_int_equal(cf_bspline_surface_create(3, 2, 2, U, 7, V, 6, P, 4, 3,
                                               NULL, &s, &d),
                     CF_STATUS_BAD_KNOTS);
    assert_non_null(strstr(d.msg, "knots V: knot v_2 (0.00) is smaller "
                                  "than knot v_1"));
    V[1] = 0.0;
    P[(3 * 3 + 2) * 3 + 1] = NAN;
    assert_int_equal(cf_bspline_surface_create(3, 2, 2, U, 7, V, 6, P, 4, 3,
                                               NULL, &s, &d),
                     CF_STATUS_NOT_FINITE);
    assert_non_null(strstr(d.msg, "point P[3][2] has coordinate 2 = NaN"));
    assert_int_equal(d.index, 3 * 3 + 2);
    P[(3 * 3 + 2) * 3 + 1] = 0.0;
    W[1 * 3 + 2] = -1.0;
    assert_int_equal(cf_bspline_surface_create(3, 2, 2, U, 7, V, 6, P, 4, 3,
                                               W, &s, &d),
                     CF_STATUS_BAD_WEIGHT);
    assert_non_null(strstr(d.msg, "weight W[1][2] is -1"));
    assert_int_equal(cf_bezier_surface_create(3, 1, 2, P, W, &b, &d),
                     CF_STATUS_BAD_WEIGHT);
    assert_null(b);
    assert_non_null(strstr(d.msg, "weight W[1][2] is -1"));
    assert_int_equal(cf_bezier_surface_create(3, -1, 2, P, NULL, &b, &d),
                     CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bezier_surface_create(3, 1, 2, P, NULL, &b, &d), 0);
    assert_int_equal(cf_bezier_surface_split(b, CF_DIR_U, 1.0, NULL, NULL,
                                             &d), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_surface_eval(b, -0.5, 0.5, x),
                     CF_STATUS_DOMAIN);
    /* the points 0, 1, ..., 17 lie on one line: no normal */
    assert_int_equal(cf_bezier_surface_normal(b, 0.5, 0.5, x),
                     CF_STATUS_DEGENERATE);
    cf_bezier_surface_destroy(b);
    /* NULLs are harmless */
    cf_bezier_surface_destroy(NULL);
    cf_bspline_surface_destroy(NULL);
    cf_bezier_surface_list_destroy(NULL);
    assert_int_equal(cf_bezier_surface_dim(NULL), 0);
    assert_int_equal(cf_bspline_surface_eval(NULL, 0, 0, x),
                     CF_STATUS_INVALID_ARG);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_curvature_monge),
        cmocka_unit_test(test_periodic),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
