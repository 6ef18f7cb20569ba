/* The interp tests, continued: Catmull-Rom; least squares; Ferguson and
** Coons (the helpers the files share: test_interp.h). */
#include "test_interp.h"

/* ---- Catmull-Rom -------------------------------------------------------- */

static void
test_catmull_rom_uniform_formula(void **state)
{
    /* Uniform Catmull-Rom: the middle of segment P1 P2 is
    ** (-P0 + 9 P1 + 9 P2 - P3) / 16 (the classic matrix form with tangents
    ** (P_{i+1} - P_{i-1}) / 2). */
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 807);
    for (int trial = 0; trial < 10; trial++) {
        double P[8], q[2];
        cf_bspline_t *c;
        random_points(&r, 4, 2, P);
        c = interp(2, P, 4, CF_INTERP_CATMULL_ROM, CF_PARAM_UNIFORM, 3, NULL,
                   NULL, false);
        assert_int_equal(cf_bspline_eval(c, 0.5, q), CF_STATUS_OK);
        for (int k = 0; k < 2; k++)
            tu_assert_close(q[k],
                            (-P[k] + 9 * P[2 + k] + 9 * P[4 + k] - P[6 + k]) /
                                16.0,
                            1e-14, 10.0);
        cf_bspline_destroy(c);
    }
}

static bool
segments_cross(const double *a, const double *b, const double *c,
               const double *d)
{
#define CROSS(o, p, q) \
    (((p)[0] - (o)[0]) * ((q)[1] - (o)[1]) - ((p)[1] - (o)[1]) * ((q)[0] - (o)[0]))
    return CROSS(a, b, c) * CROSS(a, b, d) < 0 &&
           CROSS(c, d, a) * CROSS(c, d, b) < 0;
#undef CROSS
}

/* Does the Bézier curve, sampled at 401 points, cross itself? */
static bool
self_intersects(const cf_bezier_t *b)
{
    double pts[402 * 2];
    for (int i = 0; i <= 400; i++)
        assert_int_equal(cf_bezier_eval(b, i / 400.0, pts + 2 * i),
                         CF_STATUS_OK);
    for (int i = 0; i < 400; i++)
        for (int j = i + 2; j < 400; j++)
            if (segments_cross(pts + 2 * i, pts + 2 * i + 2, pts + 2 * j,
                               pts + 2 * j + 2))
                return true;
    return false;
}

static void
test_catmull_rom_centripetal_no_cusp(void **state)
{
    /*
    ** The long-short-long example of Yuksel, Schaefer & Keyser ("On the
    ** parameterization of Catmull-Rom curves", 2009): with uniform
    ** parameters the short middle segment (0,0)-(1,0) gets the tangents
    ** (9, 3) and (9, -3) and forms a loop (Bézier points (0,0), (1.5,0.5),
    ** (-0.5,0.5), (1,0)); centripetal parameters give neither a loop nor a
    ** cusp (|C'| stays well away from 0).
    */
    const double P[] = { -8, -3, 0, 0, 1, 0, 9, -3 };
    cf_bezier_list_t *l = NULL;
    cf_bspline_t *c;
    (void)state;
    c = interp(2, P, 4, CF_INTERP_CATMULL_ROM, CF_PARAM_UNIFORM, 3, NULL,
               NULL, false);
    assert_int_equal(cf_bspline_to_beziers(c, &l, NULL), CF_STATUS_OK);
    assert_int_equal(l->count, 3);
    assert_true(self_intersects(l->items[1]));
    cf_bezier_list_destroy(l);
    cf_bspline_destroy(c);
    /* CF_PARAM_DEFAULT is centripetal for Catmull-Rom */
    c = interp(2, P, 4, CF_INTERP_CATMULL_ROM, CF_PARAM_DEFAULT, 3, NULL,
               NULL, false);
    assert_int_equal(cf_bspline_to_beziers(c, &l, NULL), CF_STATUS_OK);
    assert_false(self_intersects(l->items[1]));
    for (int i = 0; i <= 200; i++) {
        double d[4];
        assert_int_equal(cf_bezier_eval_derivs(l->items[1], i / 200.0, 1, d),
                         CF_STATUS_OK);
        /* the chord is 1; its speed never drops below a fifth of it */
        assert_true(norm(d + 2, 2) > 0.2);
    }
    cf_bezier_list_destroy(l);
    cf_bspline_destroy(c);
}

static void
test_catmull_rom_closed(void **state)
{
    const double P[] = { 0, 0, 4, 0, 5, 3, 1, 4 };
    double A[4], B[4], jump, scale, u[5];
    cf_bspline_t *c = interp(2, P, 4, CF_INTERP_CATMULL_ROM, CF_PARAM_CHORD,
                             3, NULL, NULL, true);
    (void)state;
    assert_int_equal(cf_interp_parameters(2, P, 4, CF_PARAM_CHORD, 0, true,
                                          u, NULL), CF_STATUS_OK);
    assert_true(interp_error(c, P, 4, 2, u) <= 1e-14);
    derivs(c, 0.0, 1, A);
    derivs(c, 1.0, 1, B);
    /* C^1 across the seam: the tangent at P_0 is used at both ends */
    derivative_jumps(c, 1, &jump, &scale);
    assert_true(dist(A, B, 2) <= 1e-14 * 5);
    assert_true(dist(A + 2, B + 2, 2) <= 1e-13 * scale);
    assert_true(jump <= 1e-12 * scale);
    cf_bspline_destroy(c);
}

/* ---- least squares ------------------------------------------------------ */

/* sqrt(sum |C(u_k) - P_k|^2) of a curve with the given control points. */
static double
residual_of(const cf_bspline_t *c, const double *ctrl, const double *P,
            const double *u, size_t n, size_t dim)
{
    cf_bspline_t *d = NULL;
    double s = 0.0, q[3];
    assert_int_equal(cf_bspline_create(dim, cf_bspline_degree(c),
                                       cf_bspline_knots(c),
                                       cf_bspline_nknots(c), ctrl,
                                       cf_bspline_count(c), NULL, &d, NULL),
                     CF_STATUS_OK);
    for (size_t k = 0; k < n; k++) {
        assert_int_equal(cf_bspline_eval(d, u[k], q), CF_STATUS_OK);
        s += pow(dist(q, P + k * dim, dim), 2);
    }
    cf_bspline_destroy(d);
    return sqrt(s);
}

static void
test_lsq_beats_perturbations(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 808);
    for (int trial = 0; trial < 12; trial++) {
        size_t n = 20 + (size_t)(tu_rng_u01(&r) * 30), dim = 2;
        int p = 1 + trial % 4;
        size_t nc = (size_t)p + 1 + (size_t)(tu_rng_u01(&r) * 8);
        bool fix = trial % 2 == 0;
        double P[MAXP * 2], u[MAXP], ctrl[64], pert[64], res, res2;
        cf_interp_options_t o;
        cf_bspline_t *c = NULL;
        /* noisy samples of a spiral */
        for (size_t k = 0; k < n; k++) {
            double t = 6.0 * (double)k / (double)n;
            P[2 * k] = t * cos(t) + tu_rng_range(&r, -0.3, 0.3);
            P[2 * k + 1] = t * sin(t) + tu_rng_range(&r, -0.3, 0.3);
        }
        cf_interp_options_init(&o);
        o.degree = p;
        o.param = CF_PARAM_CENTRIPETAL;
        assert_int_equal(cf_approximate_lsq(dim, P, n, nc, &o, fix, &c, &res,
                                            NULL),
                         CF_STATUS_OK);
        assert_int_equal(cf_bspline_count(c), nc);
        assert_int_equal(cf_interp_parameters(dim, P, n,
                                              CF_PARAM_CENTRIPETAL, 0, false,
                                              u, NULL), CF_STATUS_OK);
        cf_bspline_get_points(c, ctrl);
        /* the reported residual is the one of the curve */
        tu_assert_close(res, residual_of(c, ctrl, P, u, n, dim), 1e-12,
                        0.0);
        if (fix) {
            assert_true(dist(ctrl, P, 2) == 0.0);
            assert_true(dist(ctrl + 2 * (nc - 1), P + 2 * (n - 1), 2) == 0.0);
        }
        /* any perturbation of the free control points is no better:
        ** the residual is a convex quadratic at its minimum, so it can
        ** only grow (up to rounding, 1e-12 relative) */
        for (int rep = 0; rep < 30; rep++) {
            double eps = rep < 10 ? 1e-6 : rep < 20 ? 1e-3 : 0.1;
            memcpy(pert, ctrl, nc * dim * sizeof *ctrl);
            for (size_t j = fix ? 1 : 0; j < (fix ? nc - 1 : nc); j++)
                for (size_t k = 0; k < dim; k++)
                    pert[j * dim + k] += tu_rng_range(&r, -eps, eps);
            res2 = residual_of(c, pert, P, u, n, dim);
            assert_true(res2 >= res * (1 - 1e-12));
        }
        cf_bspline_destroy(c);
    }
}

static void
test_lsq_exact_cases(void **state)
{
    /* ncontrol == count interpolates (residual ~ 0); data on a cubic
    ** polynomial is fitted exactly by any cubic B-spline (ncontrol >= 4) */
    double P[20 * 2], res;
    cf_bspline_t *c = NULL;
    cf_interp_options_t o;
    (void)state;
    for (int k = 0; k < 20; k++) {
        double t = k / 19.0;
        P[2 * k] = t;
        P[2 * k + 1] = t * t * t - 2 * t;
    }
    cf_interp_options_init(&o);
    o.param = CF_PARAM_UNIFORM;
    assert_int_equal(cf_approximate_lsq(2, P, 20, 20, &o, true, &c, &res,
                                        NULL), CF_STATUS_OK);
    assert_true(res <= 1e-13);
    cf_bspline_destroy(c);
    assert_int_equal(cf_approximate_lsq(2, P, 20, 6, &o, false, &c, &res,
                                        NULL), CF_STATUS_OK);
    assert_true(res <= 1e-13);
    cf_bspline_destroy(c);
    /* degree 1 with 2 control points and fixed ends: the chord */
    o.degree = 1;
    assert_int_equal(cf_approximate_lsq(2, P, 20, 2, &o, true, &c, NULL,
                                        NULL), CF_STATUS_OK);
    assert_int_equal(cf_bspline_count(c), 2);
    cf_bspline_destroy(c);
}

static void
test_lsq_errors(void **state)
{
    double P[] = { 0, 0, 1, 1, 2, 0, 3, 1, 4, 0 };
    cf_bspline_t *c = NULL;
    cf_interp_options_t o;
    cf_diag_t d;
    (void)state;
    cf_interp_options_init(&o);
    cf_diag_clear(&d);
    expect_error(cf_approximate_lsq(2, P, 5, 3, &o, true, &c, NULL, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "a B-spline of degree 3 needs at least 4 control points, "
                 "got 3");
    cf_diag_clear(&d);
    expect_error(cf_approximate_lsq(2, P, 5, 6, &o, true, &c, NULL, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "least squares with 6 control points needs at least 6 "
                 "points, got 5");
    cf_diag_clear(&d);
    o.degree = 40;
    expect_error(cf_approximate_lsq(2, P, 5, 4, &o, true, &c, NULL, &d),
                 CF_STATUS_BAD_DEGREE, &d,
                 "least-squares degree 40 is outside 1..32");
    o.degree = 3;
    o.closed = true;
    cf_diag_clear(&d);
    expect_error(cf_approximate_lsq(2, P, 5, 4, &o, true, &c, NULL, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "least squares takes no end tangents and cannot be closed");
    o.closed = false;
    cf_diag_clear(&d);
    expect_error(cf_approximate_lsq(2, P, 5, 4, &o, true, NULL, NULL, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "out must not be NULL");
    P[5] = NAN;
    cf_diag_clear(&d);
    expect_error(cf_approximate_lsq(2, P, 5, 4, NULL, true, &c, NULL, &d),
                 CF_STATUS_NOT_FINITE, &d,
                 "point P_2 has coordinate 2 = NaN; coordinates must be "
                 "finite");
    assert_null(c);
}

/* ---- Ferguson and Coons ------------------------------------------------- */

static void
test_ferguson(void **state)
{
    /* Hermite form C(t) = F0 P0 + F1 P1 + F2 T0 + F3 T1 (thesis §4.2.1)
    ** evaluated directly, against the Bézier curve returned. */
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 809);
    for (int trial = 0; trial < 10; trial++) {
        double P[6], q[9];
        cf_bezier_t *c = NULL;
        random_points(&r, 2, 3, P);
        {
            double T[6];
            random_points(&r, 2, 3, T);
            assert_int_equal(cf_ferguson_cubic(3, P, P + 3, T, T + 3, &c,
                                               NULL), CF_STATUS_OK);
            for (int i = 0; i <= 10; i++) {
                double t = i / 10.0, t2 = t * t, t3 = t2 * t;
                double F0 = 2 * t3 - 3 * t2 + 1, F1 = -2 * t3 + 3 * t2;
                double F2 = t3 - 2 * t2 + t, F3 = t3 - t2;
                assert_int_equal(cf_bezier_eval(c, t, q), CF_STATUS_OK);
                for (int k = 0; k < 3; k++)
                    tu_assert_close(q[k],
                                    F0 * P[k] + F1 * P[3 + k] + F2 * T[k] +
                                        F3 * T[3 + k],
                                    1e-14, 10.0);
            }
            assert_int_equal(cf_bezier_eval_derivs(c, 0.0, 1, q),
                             CF_STATUS_OK);
            for (int k = 0; k < 3; k++)
                tu_assert_close(q[3 + k], T[k], 1e-14, 10.0);
            assert_int_equal(cf_bezier_eval_derivs(c, 1.0, 1, q),
                             CF_STATUS_OK);
            for (int k = 0; k < 3; k++)
                tu_assert_close(q[3 + k], T[3 + k], 1e-14, 10.0);
        }
        cf_bezier_destroy(c);
    }
}

static void
test_ferguson_chain_c1(void **state)
{
    tu_rng r;
    double P[10 * 2], T[10 * 2], a[4], b[4];
    cf_bezier_list_t *l = NULL;
    (void)state;
    tu_rng_seed(&r, 810);
    random_points(&r, 10, 2, P);
    random_points(&r, 10, 2, T);
    assert_int_equal(cf_ferguson_chain(2, P, T, 10, &l, NULL), CF_STATUS_OK);
    assert_int_equal(l->count, 9);
    for (size_t i = 0; i + 1 < l->count; i++) {
        assert_true(l->t0[i] == (double)i && l->t1[i] == (double)i + 1);
        assert_int_equal(cf_bezier_eval_derivs(l->items[i], 1.0, 1, a),
                         CF_STATUS_OK);
        assert_int_equal(cf_bezier_eval_derivs(l->items[i + 1], 0.0, 1, b),
                         CF_STATUS_OK);
        /* the joint is P_{i+1} with tangent T_{i+1} on both sides */
        for (int k = 0; k < 4; k++)
            tu_assert_close(a[k], b[k], 1e-14, 10.0);
        tu_assert_close(a[0], P[2 * (i + 1)], 1e-15, 10.0);
        tu_assert_close(a[3], T[2 * (i + 1) + 1], 1e-14, 10.0);
    }
    cf_bezier_list_destroy(l);
}

static void
test_coons(void **state)
{
    /* The Bézier form against the closed form of bspline.h
    ** (cf_coons_eval, the thesis's 1/6 [(1-t)^3, ...] basis). */
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 811);
    for (int trial = 0; trial < 10; trial++) {
        double P[8], q[2], e[2];
        cf_bezier_t *c = NULL;
        random_points(&r, 4, 2, P);
        assert_int_equal(cf_coons_cubic(2, P, &c, NULL), CF_STATUS_OK);
        for (int i = 0; i <= 10; i++) {
            double t = i / 10.0;
            assert_int_equal(cf_bezier_eval(c, t, q), CF_STATUS_OK);
            cf_coons_eval(2, P, t, e);
            tu_assert_close(q[0], e[0], 1e-14, 10.0);
            tu_assert_close(q[1], e[1], 1e-14, 10.0);
        }
        /* C(0) = (P0 + 4 P1 + P2) / 6: not P0 in general */
        assert_int_equal(cf_bezier_eval(c, 0.0, q), CF_STATUS_OK);
        tu_assert_close(q[0], (P[0] + 4 * P[2] + P[4]) / 6, 1e-15, 10.0);
        cf_bezier_destroy(c);
    }
}

static void
test_coons_chains_match_bspline(void **state)
{
    /* Each end treatment against the uniform cubic B-spline of bspline.h
    ** (de Boor on integer knots): item i covers [i, i + 1]. */
    static const size_t counts[] = { 4, 2, 3 };
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 812);
    for (int ends = 0; ends < 3; ends++) {
        for (size_t n = counts[ends]; n < 9; n++) {
            double P[9 * 2], q[2], e[2];
            cf_bezier_list_t *l = NULL;
            cf_bspline_t *s = NULL;
            random_points(&r, n, 2, P);
            assert_int_equal(cf_coons_chain(2, P, n, (cf_coons_ends_t)ends,
                                            &l, NULL), CF_STATUS_OK);
            assert_int_equal(cf_bspline_create_coons(2, P, n,
                                                     (cf_coons_ends_t)ends,
                                                     &s, NULL),
                             CF_STATUS_OK);
            assert_int_equal(l->count, ends == 0   ? n - 3
                                       : ends == 1 ? n + 1
                                                   : n);
            for (size_t i = 0; i < l->count; i++) {
                for (int j = 0; j <= 4; j++) {
                    double t = j / 4.0;
                    assert_int_equal(cf_bezier_eval(l->items[i], t, q),
                                     CF_STATUS_OK);
                    assert_int_equal(cf_bspline_eval(s, (double)i + t, e),
                                     CF_STATUS_OK);
                    tu_assert_close(q[0], e[0], 1e-14, 10.0);
                    tu_assert_close(q[1], e[1], 1e-14, 10.0);
                }
            }
            if (ends == CF_COONS_TRIPLED) {
                /* tripled end points: the curve starts at P_0, ends at P_n */
                assert_int_equal(cf_bezier_eval(l->items[0], 0.0, q),
                                 CF_STATUS_OK);
                assert_true(dist(q, P, 2) <= 1e-15 * 10);
                assert_int_equal(cf_bezier_eval(l->items[l->count - 1], 1.0,
                                                q), CF_STATUS_OK);
                assert_true(dist(q, P + 2 * (n - 1), 2) <= 1e-14 * 10);
            }
            if (ends == CF_COONS_CLOSED) {
                double a[6], b[6];
                assert_int_equal(cf_bezier_eval_derivs(l->items[0], 0.0, 2,
                                                       a), CF_STATUS_OK);
                assert_int_equal(cf_bezier_eval_derivs(l->items[l->count - 1],
                                                       1.0, 2, b),
                                 CF_STATUS_OK);
                for (int k = 0; k < 6; k++)
                    tu_assert_close(a[k], b[k], 1e-13, 10.0);
            }
            cf_bezier_list_destroy(l);
            cf_bspline_destroy(s);
        }
    }
}

static void
test_chapter4_errors(void **state)
{
    const double P[] = { 0, 0, 1, 1, 2, 0, NAN, 1 };
    cf_bezier_t *c = NULL;
    cf_bezier_list_t *l = NULL;
    cf_diag_t d;
    (void)state;
    cf_diag_clear(&d);
    expect_error(cf_ferguson_cubic(2, P, P + 2, NULL, P, &c, &d),
                 CF_STATUS_INVALID_ARG, &d, "tangent T0 must not be NULL");
    cf_diag_clear(&d);
    expect_error(cf_ferguson_cubic(2, P, P + 6, P, P, &c, &d),
                 CF_STATUS_NOT_FINITE, &d,
                 "P1 has coordinate 1 = NaN; coordinates must be finite");
    cf_diag_clear(&d);
    expect_error(cf_ferguson_cubic(0, P, P, P, P, &c, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "dimension must be at least 1, got 0");
    cf_diag_clear(&d);
    expect_error(cf_ferguson_cubic(2, P, P, P, P, NULL, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "out must not be NULL");
    cf_diag_clear(&d);
    expect_error(cf_ferguson_chain(2, P, P, 1, &l, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "Ferguson chain needs at least 2 points, got 1");
    cf_diag_clear(&d);
    expect_error(cf_ferguson_chain(2, P, P + 2, 3, &l, &d),
                 CF_STATUS_NOT_FINITE, &d,
                 "tangent 2 has coordinate 1 = NaN; coordinates must be "
                 "finite");
    cf_diag_clear(&d);
    expect_error(cf_ferguson_chain(2, NULL, P, 3, &l, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "needs dim >= 1, points and tangents");
    cf_diag_clear(&d);
    expect_error(cf_coons_cubic(2, P + 2, &c, &d), CF_STATUS_NOT_FINITE, &d,
                 "point P_2 has coordinate 1 = NaN; coordinates must be "
                 "finite");
    cf_diag_clear(&d);
    expect_error(cf_coons_cubic(2, NULL, &c, &d), CF_STATUS_INVALID_ARG, &d,
                 "needs dim >= 1 and four points");
    cf_diag_clear(&d);
    expect_error(cf_coons_chain(2, P, 3, CF_COONS_PLAIN, &l, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "plain Coons B-spline needs at least 4 points, got 3");
    cf_diag_clear(&d);
    expect_error(cf_coons_chain(2, P, 2, CF_COONS_CLOSED, &l, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "closed Coons B-spline needs at least 3 points, got 2");
    cf_diag_clear(&d);
    expect_error(cf_coons_chain(2, P, 1, CF_COONS_TRIPLED, &l, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "tripled-end Coons B-spline needs at least 2 points, got 1");
    cf_diag_clear(&d);
    expect_error(cf_coons_chain(2, P, 4, (cf_coons_ends_t)7, &l, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "unknown end treatment 7");
    cf_diag_clear(&d);
    expect_error(cf_coons_chain(2, P, 4, CF_COONS_PLAIN, NULL, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "out must not be NULL");
    assert_null(c);
    assert_null(l);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_catmull_rom_uniform_formula),
        cmocka_unit_test(test_catmull_rom_centripetal_no_cusp),
        cmocka_unit_test(test_catmull_rom_closed),
        cmocka_unit_test(test_lsq_beats_perturbations),
        cmocka_unit_test(test_lsq_exact_cases),
        cmocka_unit_test(test_lsq_errors),
        cmocka_unit_test(test_ferguson),
        cmocka_unit_test(test_ferguson_chain_c1),
        cmocka_unit_test(test_coons),
        cmocka_unit_test(test_coons_chains_match_bspline),
        cmocka_unit_test(test_chapter4_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
