/* NURBS, closed and Coons curves, the errors of the B-spline API and its
** behaviour out of memory; the helpers shared with test_bspline.c and
** test_bspline_ops.c are in test_bspline.h. */
#include "test_bspline.h"

/* ---- NURBS -------------------------------------------------------------- */

/* With all weights 1 a NURBS is the B-spline. */
static void
test_nurbs_unit_weights(void **state)
{
    double W[8] = { 1, 1, 1, 1, 1, 1, 1, 1 }, x[6], y[6];
    cf_bspline_t *c = sample(), *n = NULL;
    (void)state;
    assert_int_equal(cf_bspline_create(2, 2, SAMPLE_U, 11, SAMPLE_P, 8, W, &n,
                                       NULL), 0);
    assert_true(cf_bspline_is_rational(n));
    for (int i = 0; i <= 500; i++) {
        double u = i / 500.0;
        assert_int_equal(cf_bspline_eval_derivs(c, u, 2, x), 0);
        assert_int_equal(cf_bspline_eval_derivs(n, u, 2, y), 0);
        /* w = sum N_i = 1 up to rounding: the quotient rule changes the
        ** values by a few ulps (derivatives are ~ 2/0.17 and 4/0.17^2
        ** times the size 5) */
        assert_true(tu_max_diff(x, y, 2) <= 8 * EPS * 5);
        assert_true(tu_max_diff(x + 2, y + 2, 2) <= 32 * EPS * 5 * 12);
        assert_true(tu_max_diff(x + 4, y + 4, 2) <= 128 * EPS * 5 * 140);
    }
    cf_bspline_get_weights(n, W);
    assert_true(W[3] == 1.0);
    cf_bspline_destroy(n);
    cf_bspline_destroy(c);
}

static void
test_circle_and_arcs(void **state)
{
    const double O[2] = { 1.5, -2.0 }, X3[3] = { 1, 0, 0 },
                 Y3[3] = { 0, 0.6, 0.8 }, O3[3] = { 1, 2, 3 };
    cf_bspline_t *c = NULL;
    (void)state;
    assert_int_equal(cf_nurbs_circle(O, 2.5, &c, NULL), 0);
    assert_int_equal(cf_bspline_count(c), 9);
    for (int i = 0; i <= 1000; i++) {
        double u = i / 1000.0, x[2], D[4];
        assert_int_equal(cf_bspline_eval(c, u, x), 0);
        /* exact up to rounding */
        tu_assert_close(hypot(x[0] - O[0], x[1] - O[1]), 2.5, 8 * EPS, 1.0);
        /* the tangent is perpendicular to the radius */
        assert_int_equal(cf_bspline_eval_derivs(c, u, 1, D), 0);
        assert_true(fabs((D[0] - O[0]) * D[2] + (D[1] - O[1]) * D[3])
                    <= 1e-13 * 2.5 * hypot(D[2], D[3]));
    }
    cf_bspline_destroy(c);
    /* arcs of several sweeps; a 3D arc in a tilted plane */
    for (int k = 1; k <= 8; k++) {
        double a0 = -0.3, a1 = a0 + k * 2.0 * 3.141592653589793 / 8.0;
        double x[3];
        assert_int_equal(cf_nurbs_arc(3, O3, X3, Y3, 0.75, a0, a1, &c, NULL),
                         0);
        assert_int_equal(cf_bspline_count(c), 2 * (size_t)((k + 1) / 2) + 1);
        for (int i = 0; i <= 300; i++) {
            double u = i / 300.0, rr = 0.0, dot = 0.0;
            assert_int_equal(cf_bspline_eval(c, u, x), 0);
            for (int d = 0; d < 3; d++)
                rr += (x[d] - O3[d]) * (x[d] - O3[d]);
            /* in the plane: orthogonal to X x Y = (0, -0.8, 0.6) */
            dot = -0.8 * (x[1] - O3[1]) + 0.6 * (x[2] - O3[2]);
            tu_assert_close(sqrt(rr), 0.75, 16 * EPS, 1.0);
            assert_true(fabs(dot) <= 16 * EPS * 4);
        }
        assert_int_equal(cf_bspline_eval(c, 1.0, x), 0);
        tu_assert_close(x[0], O3[0] + 0.75 * cos(a1), 8 * EPS, 4.0);
        tu_assert_close(x[1], O3[1] + 0.75 * sin(a1) * 0.6, 8 * EPS, 4.0);
        cf_bspline_destroy(c);
    }
    {
        cf_diag_t d;
        cf_diag_clear(&d);
        assert_int_equal(cf_nurbs_circle(O, -1.0, &c, &d),
                         CF_STATUS_INVALID_ARG);
        assert_string_equal(d.msg, "radius -1 must be positive");
        assert_int_equal(cf_nurbs_circle(NULL, 1.0, &c, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_nurbs_circle(O, NAN, &c, NULL),
                         CF_STATUS_NOT_FINITE);
        assert_int_equal(cf_nurbs_arc(3, O3, X3, Y3, 1.0, 1.0, 1.0, &c, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_nurbs_arc(3, O3, X3, Y3, 1.0, 0.0, 7.0, &c, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_nurbs_arc(1, O3, X3, Y3, 1.0, 0.0, 1.0, &c, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_nurbs_arc(3, O3, X3, Y3, 0.0, 0.0, 1.0, &c, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_nurbs_arc(3, O3, X3, Y3, 1.0, 0.0, INFINITY, &c,
                                      NULL), CF_STATUS_NOT_FINITE);
        assert_null(c);
    }
}

/* ---- closed and Coons curves -------------------------------------------- */

static void
test_closed_curves(void **state)
{
    /* figure 2.18: the heart, 12 points, p = 2, given knots */
    static const double H[24] = { 5, 3, 4, 4, 3, 3, 3, 3, 2, 4, 1, 3,
                                  2.25, 2, 3, 1, 3, 1, 3.75, 2, 5, 3, 4, 4 };
    static const double HU[15] = { 0, 0.07, 0.14, 0.21, 0.28, 0.35, 0.42,
                                   0.5, 0.58, 0.65, 0.72, 0.79, 0.86, 0.93,
                                   1 };
    cf_bspline_t *c = NULL;
    double s0[6], s1[6], a, b;
    (void)state;
    assert_int_equal(cf_bspline_create(2, 2, HU, 15, H, 12, NULL, &c, NULL),
                     0);
    assert_int_equal(cf_bspline_knot_kind(c), CF_KNOTS_PERIODIC);
    cf_bspline_domain(c, &a, &b);
    assert_int_equal(cf_bspline_eval_derivs(c, a, 1, s0), 0);
    assert_int_equal(cf_bspline_eval_derivs(c, b, 1, s1), 0);
    /* closed and C^1 at the seam; knot values like 0.07 round */
    assert_true(tu_max_diff(s0, s1, 4) <= 1e-12 * 100);
    /* P_2 = P_3 = (3,3), p coincident points: the curve passes through
    ** it at u_4 (figure 2.15) */
    assert_int_equal(cf_bspline_eval(c, 0.28, s0), 0);
    tu_assert_close(s0[0], 3.0, 4 * EPS, 1.0);
    tu_assert_close(s0[1], 3.0, 4 * EPS, 1.0);
    cf_bspline_destroy(c);
    /* wrapping: degree 1..4, C(0) = C(1) with p - 1 derivatives */
    for (int p = 1; p <= 4; p++) {
        double W[8] = { 1, 2, 1, 0.5, 1, 1, 3, 1 };
        for (int rat = 0; rat < 2; rat++) {
            double D0[10], D1[10];
            assert_int_equal(cf_bspline_create_closed(2, p, SAMPLE_P, 8,
                                                      rat ? W : NULL, &c,
                                                      NULL), 0);
            assert_int_equal(cf_bspline_count(c), 8 + (size_t)p);
            assert_int_equal(cf_bspline_knot_kind(c), CF_KNOTS_PERIODIC);
            cf_bspline_domain(c, &a, &b);
            assert_true(a == 0.0 && b == 1.0);
            assert_int_equal(cf_bspline_eval_derivs(c, 0.0, p - 1, D0), 0);
            assert_int_equal(cf_bspline_eval_derivs(c, 1.0, p - 1, D1), 0);
            for (int d = 0; d < p; d++)
                assert_true(tu_max_diff(D0 + 2 * d, D1 + 2 * d, 2)
                            <= 1e-13 * pow(40.0, d) * 5);
            cf_bspline_destroy(c);
        }
    }
    assert_int_equal(cf_bspline_create_closed(2, 3, SAMPLE_P, 3, NULL, &c,
                                              NULL), CF_STATUS_TOO_FEW_POINTS);
    assert_int_equal(cf_bspline_create_closed(2, 0, SAMPLE_P, 8, NULL, &c,
                                              NULL), CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bspline_create_closed(0, 2, SAMPLE_P, 8, NULL, &c,
                                              NULL), CF_STATUS_INVALID_ARG);
}

static void
test_coons(void **state)
{
    cf_bspline_t *c = NULL;
    double a, b, x[2], y[2];
    (void)state;
    /* plain: segment Q_j on [j - 3, j - 2] is the closed form of
    ** P_{j-3} .. P_j */
    assert_int_equal(cf_bspline_create_coons(2, SAMPLE_P, 8, CF_COONS_PLAIN,
                                             &c, NULL), 0);
    cf_bspline_domain(c, &a, &b);
    assert_true(a == 0.0 && b == 5.0);
    for (int j = 3; j < 8; j++) {
        for (int i = 0; i <= 20; i++) {
            double t = i / 20.0;
            assert_int_equal(cf_bspline_eval(c, j - 3 + t, x), 0);
            cf_coons_eval(2, SAMPLE_P + 2 * (j - 3), t, y);
            assert_true(tu_max_diff(x, y, 2) <= 16 * EPS * 5);
        }
    }
    {
        double bsum[4];
        cf_coons_basis(0.3, bsum);
        tu_assert_close(bsum[0] + bsum[1] + bsum[2] + bsum[3], 1.0, 4 * EPS,
                        1.0);
        tu_assert_close(bsum[0], 0.343 / 6.0, 4 * EPS, 1.0);
    }
    cf_bspline_destroy(c);
    /* tripled ends: through P_0 and P_n */
    assert_int_equal(cf_bspline_create_coons(2, SAMPLE_P, 8, CF_COONS_TRIPLED,
                                             &c, NULL), 0);
    cf_bspline_domain(c, &a, &b);
    assert_int_equal(cf_bspline_eval(c, a, x), 0);
    tu_assert_close(x[0], 3.0, 4 * EPS, 1.0);
    tu_assert_close(x[1], 1.0, 4 * EPS, 1.0);
    assert_int_equal(cf_bspline_eval(c, b, x), 0);
    tu_assert_close(x[0], 2.25, 4 * EPS, 1.0);
    tu_assert_close(x[1], 2.0, 4 * EPS, 1.0);
    cf_bspline_destroy(c);
    /* closed: C^2 at the seam */
    assert_int_equal(cf_bspline_create_coons(2, SAMPLE_P, 8, CF_COONS_CLOSED,
                                             &c, NULL), 0);
    cf_bspline_domain(c, &a, &b);
    {
        double D0[6], D1[6];
        assert_int_equal(cf_bspline_eval_derivs(c, a, 2, D0), 0);
        assert_int_equal(cf_bspline_eval_derivs(c, b, 2, D1), 0);
        assert_true(tu_max_diff(D0, D1, 6) <= 64 * EPS * 5);
    }
    cf_bspline_destroy(c);
    assert_int_equal(cf_bspline_create_coons(2, SAMPLE_P, 3, CF_COONS_PLAIN,
                                             &c, NULL),
                     CF_STATUS_TOO_FEW_POINTS);
    assert_int_equal(cf_bspline_create_coons(2, SAMPLE_P, 8,
                                             (cf_coons_ends_t)7, &c, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bspline_create_coons(2, NULL, 8, CF_COONS_PLAIN, &c,
                                             NULL), CF_STATUS_INVALID_ARG);
}

/* ---- errors ------------------------------------------------------------- */

static void
test_create_errors(void **state)
{
    cf_bspline_t *c = NULL;
    cf_diag_t d;
    double W[8] = { 1, 1, 1, -0.5, 1, 1, 1, 1 }, P[16], U[11], x[4];
    (void)state;
    cf_diag_clear(&d);
    assert_int_equal(cf_bspline_create(2, 2, SAMPLE_U, 11, SAMPLE_P, 8, W, &c,
                                       &d), CF_STATUS_BAD_WEIGHT);
    assert_null(c);
    assert_string_equal(d.msg,
                        "weight w_3 is -0.5; weights must be finite and positive");
    cf_diag_clear(&d);
    assert_int_equal(cf_bspline_create(2, 2, SAMPLE_U, 10, SAMPLE_P, 8, NULL,
                                       &c, &d), CF_STATUS_BAD_KNOTS);
    assert_string_equal(d.msg, "10 knots given, degree 2 with 8 "
                        "points needs 11");
    memcpy(U, SAMPLE_U, sizeof U);
    U[4] = 0.3;
    U[3] = 0.5;
    cf_diag_clear(&d);
    assert_int_equal(cf_bspline_create(2, 2, U, 11, SAMPLE_P, 8, NULL, &c,
                                       &d), CF_STATUS_BAD_KNOTS);
    assert_string_equal(d.msg, "knot u_4 (0.30) is smaller than knot u_3 (0.50)");
    memcpy(P, SAMPLE_P, sizeof P);
    P[9] = NAN;
    cf_diag_clear(&d);
    assert_int_equal(cf_bspline_create(2, 2, SAMPLE_U, 11, P, 8, NULL, &c,
                                       &d), CF_STATUS_NOT_FINITE);
    assert_int_equal(d.index, 4);
    assert_int_equal(cf_bspline_create(0, 2, SAMPLE_U, 11, SAMPLE_P, 8, NULL,
                                       &c, NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bspline_create(2, 2, SAMPLE_U, 11, NULL, 8, NULL, &c,
                                       NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bspline_create(2, 2, SAMPLE_U, 11, SAMPLE_P, 8, NULL,
                                       NULL, NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bspline_create(2, 2, NULL, 11, SAMPLE_P, 8, NULL, &c,
                                       NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bspline_create(2, 9, SAMPLE_U, 11, SAMPLE_P, 8, NULL,
                                       &c, NULL), CF_STATUS_TOO_FEW_POINTS);
    assert_int_equal(cf_bspline_create(2, 99, SAMPLE_U, 11, SAMPLE_P, 8, NULL,
                                       &c, NULL), CF_STATUS_BAD_DEGREE);
    {
        double H[9] = { 0, 0, 1, 1, 1, 2, 2, 2, 0 };
        double K[6] = { 0, 0, 0, 1, 1, 1 };
        cf_diag_clear(&d);
        assert_int_equal(cf_bspline_create_homogeneous(2, 2, K, 6, H, 3, &c,
                                                       &d),
                         CF_STATUS_BAD_WEIGHT);
        assert_string_equal(d.msg, "weight w_2 is 0; weights must be finite "
                            "and positive");
        H[8] = 2;
        assert_int_equal(cf_bspline_create_homogeneous(2, 2, K, 6, H, 3, &c,
                                                       NULL), 0);
        assert_int_equal(cf_bspline_eval(c, 1.0, x), 0);
        assert_true(x[0] == 1.0 && x[1] == 1.0);
        cf_bspline_destroy(c);
        assert_int_equal(cf_bspline_create_clamped(2, 3, SAMPLE_P, 8, NULL,
                                                   &c, NULL), 0);
        assert_int_equal(cf_bspline_knot_kind(c), CF_KNOTS_CLAMPED);
        cf_bspline_destroy(c);
        assert_int_equal(cf_bspline_create_clamped(2, 8, SAMPLE_P, 8, NULL,
                                                   &c, NULL),
                         CF_STATUS_TOO_FEW_POINTS);
        assert_int_equal(cf_bspline_create_clamped(2, -1, SAMPLE_P, 8, NULL,
                                                   &c, NULL),
                         CF_STATUS_BAD_DEGREE);
    }
    /* evaluation errors */
    c = sample();
    assert_int_equal(cf_bspline_eval(c, 1.0000001, x), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bspline_eval(c, -1e-14, x), CF_STATUS_DOMAIN);
    {
        /* -1e-300 misses the end 0 by rounding (core.h): it is 0 */
        double x0[2];
        assert_int_equal(cf_bspline_eval(c, -1e-300, x), CF_STATUS_OK);
        assert_int_equal(cf_bspline_eval(c, 0.0, x0), CF_STATUS_OK);
        assert_memory_equal(x, x0, sizeof x0);
    }
    assert_int_equal(cf_bspline_eval(c, NAN, x), CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bspline_eval(c, 0.5, NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bspline_eval(NULL, 0.5, x), CF_STATUS_INVALID_ARG);
    {
        double u[3] = { 0.1, 2.0, 0.3 }, out[6];
        assert_int_equal(cf_bspline_eval_many(c, u, 3, out), CF_STATUS_DOMAIN);
        u[1] = INFINITY;
        assert_int_equal(cf_bspline_eval_many(c, u, 3, out),
                         CF_STATUS_NOT_FINITE);
        assert_int_equal(cf_bspline_eval_deriv_many(c, u, 3, 1, out),
                         CF_STATUS_NOT_FINITE);
        assert_int_equal(cf_bspline_eval_deriv_many(c, u, 3, 2, out),
                         CF_STATUS_NOT_FINITE);
        assert_int_equal(cf_bspline_eval_deriv_many(c, u, 3, -1, out),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bspline_eval_many(c, NULL, 3, out),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bspline_eval_many(c, NULL, 0, NULL), 0);
    }
    assert_int_equal(cf_bspline_eval_derivs(c, 0.5, -1, x),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bspline_eval_derivs(c, 3.0, 1, x), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bspline_deboor(c, 0.5, NULL, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bspline_basis(c, 0.5, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bspline_basis(c, 5.0, NULL, x), CF_STATUS_DOMAIN);
    /* construction errors */
    {
        cf_bspline_t *l = NULL, *r = NULL;
        double X[2] = { 0.6, 0.4 };
        cf_diag_clear(&d);
        assert_int_equal(cf_bspline_split(c, 1.0, &l, &r, &d),
                         CF_STATUS_DOMAIN);
        assert_string_equal(d.msg, "1 must lie strictly inside the "
                            "domain [0, 1]");
        assert_null(l);
        assert_null(r);
        assert_int_equal(cf_bspline_split(NULL, 0.5, &l, &r, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bspline_segment(c, 0.5, 0.5, &l, NULL),
                         CF_STATUS_DOMAIN);
        assert_int_equal(cf_bspline_segment(c, 0.5, 1.5, &l, NULL),
                         CF_STATUS_DOMAIN);
        cf_diag_clear(&d);
        assert_int_equal(cf_bspline_refine(c, X, 2, &l, &d),
                         CF_STATUS_BAD_KNOTS);
        assert_string_equal(d.msg, "new knot 1 (0.40) is smaller than "
                            "new knot 0 (0.60)");
        {
            double X3[3] = { 0.5, 0.5, 0.5 };
            cf_diag_clear(&d);
            assert_int_equal(cf_bspline_refine(c, X3, 3, &l, &d),
                             CF_STATUS_BAD_KNOTS);
            assert_string_equal(d.msg, "knot 0.5 would get "
                                "multiplicity 4; degree 2 allows at most 3");
        }
        assert_int_equal(cf_bspline_refine(c, NULL, 2, &l, NULL),
                         CF_STATUS_INVALID_ARG);
        X[1] = 7.0;
        assert_int_equal(cf_bspline_refine(c, X, 2, &l, NULL),
                         CF_STATUS_DOMAIN);
        /* a NaN or an infinity among sorted-looking knots: the value's
        ** own status, not an order or domain complaint */
        X[0] = 0.2;
        X[1] = NAN;
        assert_int_equal(cf_bspline_refine(c, X, 2, &l, NULL),
                         CF_STATUS_NOT_FINITE);
        X[1] = INFINITY;
        assert_int_equal(cf_bspline_refine(c, X, 2, &l, NULL),
                         CF_STATUS_NOT_FINITE);
        X[0] = -0.1;
        X[1] = 0.5;
        assert_int_equal(cf_bspline_refine(c, X, 2, &l, NULL),
                         CF_STATUS_DOMAIN);
        assert_int_equal(cf_bspline_elevate(c, -1, &l, NULL),
                         CF_STATUS_BAD_DEGREE);
        assert_int_equal(cf_bspline_elevate(c, 40, &l, NULL),
                         CF_STATUS_BAD_DEGREE);
        assert_int_equal(cf_bspline_to_beziers(c, NULL, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bspline_bezier_points(c, NULL, NULL, NULL, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bspline_reverse(NULL, &l, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bspline_copy(NULL, &l, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_null(l);
    }
    /* a knot of multiplicity p + 1 inside: the curve jumps; its
    ** derivative curve drops the vanishing basis function and is right
    ** on both pieces */
    {
        double K[] = { 0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1 };
        cf_bspline_t *s = NULL, *dd = NULL;
        assert_int_equal(cf_bspline_create(2, 2, K, 9, SAMPLE_P, 6, NULL, &s,
                                           NULL), 0);
        assert_int_equal(cf_bspline_derivative(s, 1, &dd, NULL), 0);
        assert_int_equal(cf_bspline_count(dd), 4);
        for (int i = 0; i <= 20; i++) {
            double D[4], y[2], u = i / 20.0;
            assert_int_equal(cf_bspline_eval_derivs(s, u, 1, D), 0);
            assert_int_equal(cf_bspline_eval(dd, u, y), 0);
            assert_true(tu_max_diff(D + 2, y, 2) <= 64 * EPS * 5 * 4);
        }
        cf_bspline_destroy(dd);
        cf_bspline_destroy(s);
    }
    /* queries on NULL */
    assert_int_equal(cf_bspline_dim(NULL), 0);
    assert_int_equal(cf_bspline_degree(NULL), 0);
    assert_int_equal(cf_bspline_count(NULL), 0);
    assert_int_equal(cf_bspline_nknots(NULL), 0);
    assert_false(cf_bspline_is_rational(NULL));
    assert_null(cf_bspline_knots(NULL));
    assert_null(cf_bspline_hpoints(NULL));
    assert_int_equal(cf_bspline_deboor_size(NULL), 0);
    assert_int_equal(cf_bspline_knot_kind(NULL), CF_KNOTS_OPEN);
    cf_bspline_get_points(NULL, x);
    cf_bspline_get_weights(NULL, x);
    cf_bspline_destroy(NULL);
    cf_bspline_destroy(c);
}

/* ---- out of memory ------------------------------------------------------ */

typedef cf_status_t (*op_fn)(const cf_bspline_t *c, void **res);

static cf_status_t
op_create(const cf_bspline_t *c, void **res)
{
    double W[8] = { 1, 2, 1, 1, 1, 1, 1, 1 };
    (void)c;
    return cf_bspline_create(2, 2, SAMPLE_U, 11, SAMPLE_P, 8, W,
                             (cf_bspline_t **)res, NULL);
}

static cf_status_t
op_insert(const cf_bspline_t *c, void **res)
{
    return cf_bspline_insert_knot(c, 0.6, 2, (cf_bspline_t **)res, NULL, NULL);
}

static cf_status_t
op_refine(const cf_bspline_t *c, void **res)
{
    double X[3] = { 0.1, 0.2, 0.7 };
    return cf_bspline_refine(c, X, 3, (cf_bspline_t **)res, NULL);
}

static cf_status_t
op_beziers(const cf_bspline_t *c, void **res)
{
    cf_bspline_t *o = NULL;
    cf_status_t st;
    /* an open curve: clamping allocates too */
    double U[11] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10 };
    (void)c;
    st = cf_bspline_create(2, 2, U, 11, SAMPLE_P, 8, NULL, &o, NULL);
    if (st != CF_STATUS_OK)
        return st;
    st = cf_bspline_to_beziers(o, (cf_bezier_list_t **)res, NULL);
    cf_bspline_destroy(o);
    return st;
}

static cf_status_t
op_elevate(const cf_bspline_t *c, void **res)
{
    return cf_bspline_elevate(c, 1, (cf_bspline_t **)res, NULL);
}

static cf_status_t
op_split(const cf_bspline_t *c, void **res)
{
    cf_bspline_t *l = NULL, *r = NULL;
    cf_status_t st = cf_bspline_split(c, 0.4, &l, &r, NULL);
    cf_bspline_destroy(l);
    *res = r;
    return st;
}

static cf_status_t
op_remove(const cf_bspline_t *c, void **res)
{
    return cf_bspline_remove_knot(c, 0.5, 1, 10.0, (cf_bspline_t **)res, NULL,
                                  NULL);
}

static cf_status_t
op_derivative(const cf_bspline_t *c, void **res)
{
    return cf_bspline_derivative(c, 1, (cf_bspline_t **)res, NULL);
}

static cf_status_t
op_closed(const cf_bspline_t *c, void **res)
{
    (void)c;
    return cf_bspline_create_closed(2, 3, SAMPLE_P, 8, NULL,
                                    (cf_bspline_t **)res, NULL);
}

static cf_status_t
op_arc(const cf_bspline_t *c, void **res)
{
    const double O[2] = { 0, 0 }, X[2] = { 1, 0 }, Y[2] = { 0, 1 };
    (void)c;
    return cf_nurbs_arc(2, O, X, Y, 1.0, 0.0, 4.0, (cf_bspline_t **)res,
                        NULL);
}

static void
test_out_of_memory(void **state)
{
    static const op_fn ops[] = { op_create, op_insert, op_refine, op_beziers,
                                 op_elevate, op_split, op_remove,
                                 op_derivative, op_closed, op_arc };
    double W[8] = { 1, 2, 1, 0.5, 1, 1, 3, 1 };
    cf_bspline_t *curves[2] = { NULL, NULL };
    (void)state;
    curves[0] = sample();
    assert_int_equal(cf_bspline_create(2, 2, SAMPLE_U, 11, SAMPLE_P, 8, W,
                                       &curves[1], NULL), 0);
    for (size_t o = 0; o < sizeof ops / sizeof ops[0]; o++) {
        for (int ci = 0; ci < 2; ci++) {
            for (long k = 1;; k++) {
                void *res = NULL;
                cf_status_t st;
                long live;
                tu_fail_alloc_after(k);
                st = ops[o](curves[ci], &res);
                if (st == CF_STATUS_OK) {
                    if (ops[o] == op_beziers)
                        cf_bezier_list_destroy(res);
                    else
                        cf_bspline_destroy(res);
                    live = tu_alloc_live();
                    tu_fail_alloc_reset();
                    assert_int_equal(live, 0);
                    assert_true(k > 1);
                    break;
                }
                live = tu_alloc_live();
                tu_fail_alloc_reset();
                if (st != CF_STATUS_NO_MEMORY)
                    fail_msg("op %zu curve %d k %ld: status %d", o, ci, k,
                             (int)st);
                assert_null(res);
                assert_int_equal(live, 0);
                assert_true(k < 100);
            }
        }
    }
    cf_bspline_destroy(curves[0]);
    cf_bspline_destroy(curves[1]);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nurbs_unit_weights),
        cmocka_unit_test(test_circle_and_arcs),
        cmocka_unit_test(test_closed_curves),
        cmocka_unit_test(test_coons),
        cmocka_unit_test(test_create_errors),
        cmocka_unit_test(test_out_of_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
