/* Interpolation and the chapter-4 curves (src/interp.c,
** src/interp-spline.c). This file has the first sections; the others are in
** test_interp_catmull_rom.c and test_interp_bad_input.c, the shared helpers
** in test_interp.h. */
#include "test_interp.h"

/* ---- parameters --------------------------------------------------------- */

static void
test_parameters_by_hand(void **state)
{
    /* chords |(3,4)| = 5 and |(0,9)| = 9, closing chord sqrt(3^2 + 13^2)
    ** = sqrt(178) */
    const double P[] = { 0, 0, 3, 4, 3, 13 };
    double u[4];
    (void)state;
    assert_int_equal(cf_interp_parameters(2, P, 3, CF_PARAM_CHORD, 0, false,
                                          u, NULL), CF_STATUS_OK);
    assert_true(u[0] == 0.0 && u[2] == 1.0);
    tu_assert_close(u[1], 5.0 / 14.0, 4 * DBL_EPSILON, 0.0);
    assert_int_equal(cf_interp_parameters(2, P, 3, CF_PARAM_UNIFORM, 0,
                                          false, u, NULL), CF_STATUS_OK);
    assert_true(u[1] == 0.5);
    assert_int_equal(cf_interp_parameters(2, P, 3, CF_PARAM_CENTRIPETAL, 0,
                                          false, u, NULL), CF_STATUS_OK);
    tu_assert_close(u[1], sqrt(5.0) / (sqrt(5.0) + 3.0), 4 * DBL_EPSILON,
                    0.0);
    /* power 0.5 is centripetal */
    {
        double v[3];
        assert_int_equal(cf_interp_parameters(2, P, 3, CF_PARAM_POWER, 0.5,
                                              false, v, NULL), CF_STATUS_OK);
        tu_assert_close(v[1], u[1], 4 * DBL_EPSILON, 0.0);
    }
    assert_int_equal(cf_interp_parameters(2, P, 3, CF_PARAM_CHORD, 0, true,
                                          u, NULL), CF_STATUS_OK);
    tu_assert_close(u[1], 5.0 / (14.0 + sqrt(178.0)), 4 * DBL_EPSILON, 0.0);
    tu_assert_close(u[2], 14.0 / (14.0 + sqrt(178.0)), 4 * DBL_EPSILON, 0.0);
    assert_true(u[3] == 1.0);
    /* no overflow for huge coordinates: chords 3e300 and 4e300 */
    {
        const double H[] = { 0, 0, 3e300, 0, 3e300, 4e300 };
        assert_int_equal(cf_interp_parameters(2, H, 3, CF_PARAM_CHORD, 0,
                                              false, u, NULL), CF_STATUS_OK);
        tu_assert_close(u[1], 3.0 / 7.0, 4 * DBL_EPSILON, 0.0);
    }
}

static void
test_parameters_errors(void **state)
{
    const double P[] = { 0, 0, 1, 2, 1, 2 }, Q[] = { 0, 0, 1, NAN };
    const double R[] = { 1, 2, 3, 4, 1, 2 };
    double u[4];
    cf_diag_t d;
    (void)state;
    cf_diag_clear(&d);
    expect_error(cf_interp_parameters(2, P, 3, CF_PARAM_CHORD, 0, false, u,
                                      &d),
                 CF_STATUS_DEGENERATE, &d,
                 "points 1 and 2 coincide (1, 2); chord-length parameters "
                 "need distinct consecutive points");
    assert_int_equal(d.index, 2);
    cf_diag_clear(&d);
    expect_error(cf_interp_parameters(2, P, 3, CF_PARAM_CENTRIPETAL, 0,
                                      false, u, &d),
                 CF_STATUS_DEGENERATE, &d,
                 "points 1 and 2 coincide (1, 2); centripetal parameters "
                 "need distinct consecutive points");
    cf_diag_clear(&d);
    /* closed: the last point and the first are consecutive too */
    expect_error(cf_interp_parameters(2, R, 3, CF_PARAM_UNIFORM, 0, true, u,
                                      &d),
                 CF_STATUS_DEGENERATE, &d,
                 "points 2 and 0 coincide (1, 2); interpolation needs "
                 "distinct consecutive points");
    cf_diag_clear(&d);
    expect_error(cf_interp_parameters(2, Q, 2, CF_PARAM_CHORD, 0, false, u,
                                      &d),
                 CF_STATUS_NOT_FINITE, &d,
                 "point P_1 has coordinate 2 = NaN; coordinates must be "
                 "finite");
    cf_diag_clear(&d);
    expect_error(cf_interp_parameters(2, P, 1, CF_PARAM_CHORD, 0, false, u,
                                      &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "parameters need at least 2 points, got 1");
    cf_diag_clear(&d);
    expect_error(cf_interp_parameters(2, R, 3, CF_PARAM_POWER, 1.5, false,
                                      u, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "parameter exponent 1.5 is outside [0, 1]");
    cf_diag_clear(&d);
    expect_error(cf_interp_parameters(2, NULL, 3, CF_PARAM_CHORD, 0, false,
                                      u, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "points and out must not be NULL");
    cf_diag_clear(&d);
    expect_error(cf_interp_parameters(0, R, 3, CF_PARAM_CHORD, 0, false, u,
                                      &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "dimension must be at least 1, got 0");
    cf_diag_clear(&d);
    expect_error(cf_interp_parameters(2, R, 3, (cf_param_t)42, 0, false, u,
                                      &d),
                 CF_STATUS_INVALID_ARG, &d, "unknown parametrisation 42");
}

static void
test_names(void **state)
{
    cf_interp_method_t m;
    cf_param_t p;
    cf_diag_t d;
    static const char *const names[] = { "natural", "clamped", "not-a-knot",
                                         "periodic", "catmull-rom",
                                         "global" };
    (void)state;
    for (int i = 0; i < 6; i++) {
        assert_int_equal(cf_interp_method_from_string(names[i], &m, NULL),
                         CF_STATUS_OK);
        assert_int_equal((int)m, i);
        assert_string_equal(cf_interp_method_to_string(m), names[i]);
    }
    assert_string_equal(cf_interp_method_to_string((cf_interp_method_t)9),
                        "unknown");
    assert_int_equal(cf_param_from_string("centripetal", &p, NULL),
                     CF_STATUS_OK);
    assert_int_equal(p, CF_PARAM_CENTRIPETAL);
    assert_int_equal(cf_param_from_string("chord", &p, NULL), CF_STATUS_OK);
    assert_int_equal(p, CF_PARAM_CHORD);
    assert_int_equal(cf_param_from_string("uniform", &p, NULL),
                     CF_STATUS_OK);
    assert_int_equal(p, CF_PARAM_UNIFORM);
    cf_diag_clear(&d);
    expect_error(cf_interp_method_from_string("cubic", &m, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "unknown interpolation method \"cubic\"; expected natural, "
                 "clamped, not-a-knot, periodic, catmull-rom or global");
    cf_diag_clear(&d);
    expect_error(cf_param_from_string("arc", &p, &d), CF_STATUS_INVALID_ARG,
                 &d, "unknown parametrisation \"arc\"; expected uniform, "
                     "chord or centripetal");
    cf_diag_clear(&d);
    expect_error(cf_param_from_string(NULL, &p, &d), CF_STATUS_INVALID_ARG,
                 &d, "NULL argument");
    cf_diag_clear(&d);
    expect_error(cf_interp_method_from_string("x", NULL, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "NULL argument");
}

/* ---- the interpolants pass through their points ------------------------- */

static void
test_all_methods_interpolate(void **state)
{
    static const cf_interp_method_t methods[] = {
        CF_INTERP_NATURAL, CF_INTERP_CLAMPED, CF_INTERP_NOT_A_KNOT,
        CF_INTERP_PERIODIC, CF_INTERP_CATMULL_ROM, CF_INTERP_GLOBAL
    };
    static const cf_param_t params[] = { CF_PARAM_UNIFORM, CF_PARAM_CHORD,
                                         CF_PARAM_CENTRIPETAL };
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 801);
    for (int trial = 0; trial < 12; trial++) {
        size_t dim = 1 + (size_t)trial % 3;
        size_t n = 4 + (size_t)(tu_rng_u01(&r) * 20);
        double P[MAXP * 3], u[MAXP + 1], d0[3], d1[3];
        random_points(&r, n, dim, P);
        random_points(&r, 1, dim, d0);
        random_points(&r, 1, dim, d1);
        for (size_t mi = 0; mi < 6; mi++) {
            for (size_t pi = 0; pi < 3; pi++) {
                cf_interp_method_t m = methods[mi];
                bool closed = m == CF_INTERP_PERIODIC ||
                              (m == CF_INTERP_CATMULL_ROM && trial % 2);
                int degree = m == CF_INTERP_GLOBAL ? 1 + trial % 5 : 3;
                bool tangents = m == CF_INTERP_CLAMPED ||
                                (m == CF_INTERP_GLOBAL && degree > 1 &&
                                 trial % 3 == 0);
                cf_bspline_t *c = interp(dim, P, n, m, params[pi], degree,
                                         tangents ? d0 : NULL,
                                         tangents ? d1 : NULL, closed);
                double a, b;
                assert_int_equal(cf_interp_parameters(dim, P, n, params[pi],
                                                      0, closed, u, NULL),
                                 CF_STATUS_OK);
                cf_bspline_domain(c, &a, &b);
                assert_true(a == 0.0 && b == 1.0);
                /* 1e-13 relative: the systems are well conditioned
                ** (diagonally dominant or totally positive), a few
                ** hundred ulps of the data */
                assert_true(interp_error(c, P, n, dim, u) <= 1e-13);
                if (closed) {
                    double q[3];
                    assert_int_equal(cf_bspline_eval(c, 1.0, q),
                                     CF_STATUS_OK);
                    assert_true(dist(q, P, dim) <=
                                1e-13 * size_of(P, n * dim));
                }
                assert_int_equal(cf_bspline_degree(c), degree);
                cf_bspline_destroy(c);
            }
        }
    }
}

/* ---- continuity, measured ----------------------------------------------- */

static void
test_continuity_as_promised(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 802);
    for (int trial = 0; trial < 8; trial++) {
        size_t n = 7 + (size_t)(tu_rng_u01(&r) * 15), dim = 2;
        double P[MAXP * 2], d0[2] = { 3, -1 }, d1[2] = { 0, 5 };
        double jump, scale;
        struct {
            cf_interp_method_t m;
            int degree, smooth;
        } cases[] = {
            { CF_INTERP_NATURAL, 3, 2 },  { CF_INTERP_CLAMPED, 3, 2 },
            { CF_INTERP_NOT_A_KNOT, 3, 2 }, { CF_INTERP_PERIODIC, 3, 2 },
            { CF_INTERP_CATMULL_ROM, 3, 1 }, { CF_INTERP_GLOBAL, 4, 3 },
            { CF_INTERP_GLOBAL, 2, 1 },
        };
        random_points(&r, n, dim, P);
        for (size_t ci = 0; ci < sizeof cases / sizeof cases[0]; ci++) {
            bool cl = cases[ci].m == CF_INTERP_CLAMPED;
            cf_bspline_t *c = interp(dim, P, n, cases[ci].m, CF_PARAM_CHORD,
                                     cases[ci].degree, cl ? d0 : NULL,
                                     cl ? d1 : NULL, false);
            for (int k = 0; k <= cases[ci].smooth; k++) {
                size_t nb = derivative_jumps(c, k, &jump, &scale);
                if (nb < 1)
                    fail_msg("%s: %zu break points",
                             cf_interp_method_to_string(cases[ci].m), nb);
                /* Bézier pieces carry the rounding of the solve and of the
                ** decomposition, ~1e-15 of the data; a k-th derivative
                ** amplifies it by about (p / h)^k, which the scale (the
                ** largest |C^(k)|, itself ~ size / h^k) absorbs: 1e-10 */
                if (!(jump <= 1e-10 * scale))
                    fail_msg("%s: C^%d jump %g (scale %g)",
                             cf_interp_method_to_string(cases[ci].m), k,
                             jump, scale);
            }
            /* the next derivative does jump: the promise is sharp */
            derivative_jumps(c, cases[ci].smooth + 1, &jump, &scale);
            assert_true(jump > 1e-6 * scale);
            cf_bspline_destroy(c);
        }
    }
}

/* ---- end conditions ----------------------------------------------------- */

static void
test_natural_ends(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 803);
    for (int trial = 0; trial < 10; trial++) {
        size_t n = 2 + (size_t)(tu_rng_u01(&r) * 20), dim = 3;
        double P[MAXP * 3], D0[9], D1[9], s0 = 0, s1 = 0;
        cf_bspline_t *c;
        random_points(&r, n, dim, P);
        c = interp(dim, P, n, CF_INTERP_NATURAL, CF_PARAM_CHORD, 3, NULL,
                   NULL, false);
        derivs(c, 0.0, 2, D0);
        derivs(c, 1.0, 2, D1);
        {
            double jump, scale;
            derivative_jumps(c, 2, &jump, &scale);
            s0 = s1 = scale;
        }
        /* C'' = 0 at both ends, relative to the largest |C''| */
        assert_true(norm(D0 + 6, 3) <= 1e-12 * fmax(s0, 1.0));
        assert_true(norm(D1 + 6, 3) <= 1e-12 * fmax(s1, 1.0));
        cf_bspline_destroy(c);
    }
    /* two points: C'' = 0 at both ends makes the segment straight */
    {
        const double P[] = { 1, 2, 4, 6 };
        double q[2];
        cf_bspline_t *c = interp(2, P, 2, CF_INTERP_NATURAL, CF_PARAM_CHORD,
                                 3, NULL, NULL, false);
        assert_int_equal(cf_bspline_eval(c, 0.25, q), CF_STATUS_OK);
        tu_assert_close(q[0], 1.75, 8 * DBL_EPSILON, 1.0);
        tu_assert_close(q[1], 3.0, 8 * DBL_EPSILON, 1.0);
        cf_bspline_destroy(c);
    }
}

static void
test_clamped_tangents_honoured(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 804);
    for (int trial = 0; trial < 10; trial++) {
        size_t n = 2 + (size_t)(tu_rng_u01(&r) * 20), dim = 2;
        double P[MAXP * 2], d0[2], d1[2], D0[4], D1[4];
        cf_bspline_t *c;
        random_points(&r, n, dim, P);
        random_points(&r, 1, dim, d0);
        random_points(&r, 1, dim, d1);
        c = interp(dim, P, n, CF_INTERP_CLAMPED, CF_PARAM_CENTRIPETAL, 3,
                   d0, d1, false);
        derivs(c, 0.0, 1, D0);
        derivs(c, 1.0, 1, D1);
        /* the end rows of the system state exactly these derivatives */
        for (int k = 0; k < 2; k++) {
            tu_assert_close(D0[2 + k], d0[k], 1e-12, 10.0);
            tu_assert_close(D1[2 + k], d1[k], 1e-12, 10.0);
        }
        cf_bspline_destroy(c);
    }
}

static void
test_global_end_derivatives(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 805);
    for (int p = 2; p <= 6; p++) {
        size_t n = 8, dim = 2;
        double P[16], d0[2], d1[2], D[4];
        cf_bspline_t *c;
        random_points(&r, n, dim, P);
        random_points(&r, 1, dim, d0);
        random_points(&r, 1, dim, d1);
        /* start only, end only, both */
        for (int which = 1; which <= 3; which++) {
            const double *a = which & 1 ? d0 : NULL, *b = which & 2 ? d1
                                                                   : NULL;
            double u[8];
            c = interp(dim, P, n, CF_INTERP_GLOBAL, CF_PARAM_CHORD, p, a, b,
                       false);
            assert_int_equal(cf_bspline_count(c), n + (which == 3 ? 2 : 1));
            assert_int_equal(cf_interp_parameters(dim, P, n, CF_PARAM_CHORD,
                                                  0, false, u, NULL),
                             CF_STATUS_OK);
            assert_true(interp_error(c, P, n, dim, u) <= 1e-13);
            if (a != NULL) {
                derivs(c, 0.0, 1, D);
                tu_assert_close(D[2], a[0], 1e-12, 10.0);
                tu_assert_close(D[3], a[1], 1e-12, 10.0);
            }
            if (b != NULL) {
                derivs(c, 1.0, 1, D);
                tu_assert_close(D[2], b[0], 1e-12, 10.0);
                tu_assert_close(D[3], b[1], 1e-12, 10.0);
            }
            cf_bspline_destroy(c);
        }
    }
}

static void
test_periodic_closes_c2(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 806);
    for (int trial = 0; trial < 10; trial++) {
        size_t n = 3 + (size_t)(tu_rng_u01(&r) * 20), dim = 2;
        double P[MAXP * 2], A[6], B[6], jump, scale;
        cf_bspline_t *c;
        random_points(&r, n, dim, P);
        c = interp(dim, P, n, CF_INTERP_PERIODIC,
                   trial % 2 ? CF_PARAM_CHORD : CF_PARAM_UNIFORM, 3, NULL,
                   NULL, false);
        assert_int_equal(cf_bspline_knot_kind(c), CF_KNOTS_PERIODIC);
        derivative_jumps(c, 2, &jump, &scale);
        derivs(c, 0.0, 2, A); /* first piece */
        derivs(c, 1.0, 2, B); /* last piece */
        /* value, C' and C'' agree across the seam; the periodic knots and
        ** wrapped control points make this exact up to rounding */
        for (int k = 0; k < 2; k++) {
            tu_assert_close(A[k], B[k], 1e-13, 10.0);
            tu_assert_close(A[k], P[k], 1e-13, 10.0);
        }
        assert_true(dist(A + 2, B + 2, 2) <= 1e-12 * scale);
        assert_true(dist(A + 4, B + 4, 2) <= 1e-12 * scale);
        cf_bspline_destroy(c);
    }
}

/* ---- values computed independently -------------------------------------- */

static void
test_natural_by_hand(void **state)
{
    /*
    ** Natural spline through y = 0, 1, 0, 1 at u = 0, 1/3, 2/3, 1 (uniform
    ** parameters, dim 1).  Independent computation in the second-derivative
    ** form (de Boor, A Practical Guide to Splines, ch. IV; Burden & Faires
    ** §3.5): with h = 1/3, M_0 = M_3 = 0 and
    **   h/6 M_{i-1} + 2h/3 M_i + h/6 M_{i+1} = (y_{i+1} - 2 y_i + y_{i-1})/h
    ** i = 1: 2/9 M_1 + 1/18 M_2 = -6;  i = 2: 1/18 M_1 + 2/9 M_2 = 6.
    ** Times 18: 4 M_1 + M_2 = -108, M_1 + 4 M_2 = 108, so M_1 = -36,
    ** M_2 = 36.  On [u_i, u_{i+1}]:
    **   S = M_i (u_{i+1}-u)^3/(6h) + M_{i+1} (u-u_i)^3/(6h)
    **       + (y_i/h - M_i h/6)(u_{i+1}-u) + (y_{i+1}/h - M_{i+1} h/6)(u-u_i)
    ** S(1/6) = -36 (1/6)^3 / 2 + (3 + 2)/6 = -1/12 + 5/6 = 3/4;
    ** S(1/2) = -1/12 + 1/12 + 5/6 - 2/6 = 1/2;  S'(0) = 3 + 2 = 5;
    ** S''(1/3) = M_1 = -36.
    */
    const double y[] = { 0, 1, 0, 1 };
    double q[3];
    cf_bspline_t *c = interp(1, y, 4, CF_INTERP_NATURAL, CF_PARAM_UNIFORM, 3,
                             NULL, NULL, false);
    (void)state;
    assert_int_equal(cf_bspline_eval(c, 1.0 / 6.0, q), CF_STATUS_OK);
    tu_assert_close(q[0], 0.75, 1e-14, 1.0);
    assert_int_equal(cf_bspline_eval(c, 0.5, q), CF_STATUS_OK);
    tu_assert_close(q[0], 0.5, 1e-14, 1.0);
    derivs(c, 0.0, 1, q);
    tu_assert_close(q[1], 5.0, 1e-14, 1.0);
    derivs(c, 1.0 / 3.0, 2, q);
    tu_assert_close(q[2], -36.0, 1e-13, 1.0);
    cf_bspline_destroy(c);
}

static void
test_clamped_by_hand(void **state)
{
    /* Two points 0 and 1 with zero end tangents: the cubic with C(0) = 0,
    ** C(1) = 1, C'(0) = C'(1) = 0 is 3u^2 - 2u^3 (smoothstep), so
    ** C(1/4) = 3/16 - 2/64 = 5/32.  The Ferguson cubic with the same data
    ** is the same curve (compared at several parameters). */
    const double y[] = { 0, 1 }, z = 0.0;
    double q[1], f[1];
    cf_bezier_t *fc = NULL;
    cf_bspline_t *c = interp(1, y, 2, CF_INTERP_CLAMPED, CF_PARAM_CHORD, 3,
                             &z, &z, false);
    (void)state;
    assert_int_equal(cf_bspline_eval(c, 0.25, q), CF_STATUS_OK);
    tu_assert_close(q[0], 5.0 / 32.0, 1e-15, 1.0);
    assert_int_equal(cf_ferguson_cubic(1, y, y + 1, &z, &z, &fc, NULL),
                     CF_STATUS_OK);
    for (int i = 0; i <= 8; i++) {
        double t = i / 8.0;
        assert_int_equal(cf_bspline_eval(c, t, q), CF_STATUS_OK);
        assert_int_equal(cf_bezier_eval(fc, t, f), CF_STATUS_OK);
        tu_assert_close(q[0], f[0], 1e-15, 1.0);
        tu_assert_close(q[0], 3 * t * t - 2 * t * t * t, 1e-15, 1.0);
    }
    cf_bezier_destroy(fc);
    cf_bspline_destroy(c);
}

static void
test_polynomials_reproduced(void **state)
{
    /* The spline spaces contain the polynomials of their degree, and the
    ** interpolants are unique: data from f(u) = 2u^3 - u + 1 (at uniform
    ** parameters, dim 1) give f itself for not-a-knot (whose end pieces
    ** carry no end condition), and global interpolation of degree p
    ** reproduces u^p - u^2 / 2 + u everywhere (p >= 2). */
    double y[12], q[1];
    cf_bspline_t *c;
    (void)state;
    for (int i = 0; i < 7; i++) {
        double t = i / 6.0;
        y[i] = 2 * t * t * t - t + 1;
    }
    c = interp(1, y, 7, CF_INTERP_NOT_A_KNOT, CF_PARAM_UNIFORM, 3, NULL,
               NULL, false);
    for (int i = 0; i <= 50; i++) {
        double t = i / 50.0;
        assert_int_equal(cf_bspline_eval(c, t, q), CF_STATUS_OK);
        tu_assert_close(q[0], 2 * t * t * t - t + 1, 1e-13, 1.0);
    }
    cf_bspline_destroy(c);
    /* degree 0 means 3, also for global interpolation */
    c = interp(1, y, 7, CF_INTERP_GLOBAL, CF_PARAM_UNIFORM, 0, NULL, NULL,
               false);
    assert_int_equal(cf_bspline_degree(c), 3);
    cf_bspline_destroy(c);
    /* four points: a single cubic */
    c = interp(1, y, 4, CF_INTERP_NOT_A_KNOT, CF_PARAM_UNIFORM, 3, NULL,
               NULL, false);
    assert_int_equal(cf_bspline_count(c), 4);
    cf_bspline_destroy(c);
    for (int p = 1; p <= 7; p++) {
        for (int i = 0; i < 12; i++) {
            double t = i / 11.0;
            y[i] = pow(t, p) - 0.5 * t * t + t;
        }
        c = interp(1, y, 12, CF_INTERP_GLOBAL, CF_PARAM_UNIFORM, p, NULL,
                   NULL, false);
        for (int i = 0; i <= 40; i++) {
            double t = i / 40.0;
            assert_int_equal(cf_bspline_eval(c, t, q), CF_STATUS_OK);
            /* p = 1 is the polyline, exact only at the data */
            if (p >= 2)
                tu_assert_close(q[0], pow(t, p) - 0.5 * t * t + t, 1e-12,
                                1.0);
        }
        cf_bspline_destroy(c);
    }
}

static void
test_periodic_square_by_hand(void **state)
{
    /*
    ** The square (1,0), (0,1), (-1,0), (0,-1) with uniform parameters: the
    ** knots are uniform, the basis at a knot is 1/6, 2/3, 1/6, and by
    ** symmetry the unknowns are E_i = c P_i with P_{i-1} + P_{i+1} = 0, so
    ** 2/3 c P_i = P_i: c = 3/2.  The control points are Q_{i+1} = 3/2 P_i.
    ** At the middle of the first span the uniform cubic weights are
    ** 1/48, 23/48, 23/48, 1/48 on Q_0..Q_3 = 3/2 (P_3, P_0, P_1, P_2):
    ** x = 3/2 (0 + 23 + 0 - 1) / 48 = 11/16, y = 3/2 (-1 + 0 + 23 + 0)/48
    ** = 11/16.
    */
    const double P[] = { 1, 0, 0, 1, -1, 0, 0, -1, 1, 0 };
    double q[2], ctrl[14];
    cf_bspline_t *c;
    (void)state;
    /* the closing point repeated at the end is accepted and dropped */
    c = interp(2, P, 5, CF_INTERP_PERIODIC, CF_PARAM_UNIFORM, 3, NULL, NULL,
               false);
    assert_int_equal(cf_bspline_count(c), 7);
    cf_bspline_get_points(c, ctrl);
    for (size_t j = 0; j < 7; j++) {
        const double *p = P + ((j + 3) % 4) * 2;
        tu_assert_close(ctrl[2 * j], 1.5 * p[0], 1e-15, 1.0);
        tu_assert_close(ctrl[2 * j + 1], 1.5 * p[1], 1e-15, 1.0);
    }
    assert_int_equal(cf_bspline_eval(c, 0.125, q), CF_STATUS_OK);
    tu_assert_close(q[0], 11.0 / 16.0, 1e-15, 1.0);
    tu_assert_close(q[1], 11.0 / 16.0, 1e-15, 1.0);
    cf_bspline_destroy(c);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_parameters_by_hand),
        cmocka_unit_test(test_parameters_errors),
        cmocka_unit_test(test_names),
        cmocka_unit_test(test_all_methods_interpolate),
        cmocka_unit_test(test_continuity_as_promised),
        cmocka_unit_test(test_natural_ends),
        cmocka_unit_test(test_clamped_tangents_honoured),
        cmocka_unit_test(test_global_end_derivatives),
        cmocka_unit_test(test_periodic_closes_c2),
        cmocka_unit_test(test_natural_by_hand),
        cmocka_unit_test(test_clamped_by_hand),
        cmocka_unit_test(test_polynomials_reproduced),
        cmocka_unit_test(test_periodic_square_by_hand),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
