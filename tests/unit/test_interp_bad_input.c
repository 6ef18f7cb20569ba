/* The interp tests, continued: bad input to cf_interpolate; out of memory
** (the helpers the files share: test_interp.h). */
#include "test_interp.h"

/* ---- bad input to cf_interpolate ---------------------------------------- */

static cf_status_t
try_interp(size_t dim, const double *P, size_t n, cf_interp_method_t m,
           int degree, const double *d0, const double *d1, bool closed,
           cf_diag_t *d)
{
    cf_interp_options_t o;
    cf_bspline_t *c = (cf_bspline_t *)&o; /* must be reset to NULL */
    cf_status_t st;
    cf_interp_options_init(&o);
    o.method = m;
    o.degree = degree;
    o.start_tangent = d0;
    o.end_tangent = d1;
    o.closed = closed;
    cf_diag_clear(d);
    st = cf_interpolate(dim, P, n, &o, &c, d);
    assert_null(c);
    return st;
}

static void
test_interpolate_errors(void **state)
{
    const double P[] = { 0, 0, 1, 2, 3, 1, 4, 4, 6, 0 };
    const double Q[] = { 0, 0, 1, 2, 1, 2, 4, 4 };
    const double N[] = { 0, 0, 1, 2, 3, NAN };
    const double t[] = { 1, 0 }, tn[] = { INFINITY, 0 };
    cf_diag_t d;
    (void)state;
    expect_error(try_interp(2, P, 1, CF_INTERP_NATURAL, 3, NULL, NULL, false,
                            &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "natural cubic spline needs at least 2 points, got 1");
    expect_error(try_interp(2, P, 3, CF_INTERP_NOT_A_KNOT, 3, NULL, NULL,
                            false, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "not-a-knot cubic spline needs at least 4 points, got 3");
    expect_error(try_interp(2, P, 2, CF_INTERP_PERIODIC, 3, NULL, NULL,
                            false, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "periodic cubic spline needs at least 3 distinct points, "
                 "got 2");
    expect_error(try_interp(2, P, 2, CF_INTERP_CATMULL_ROM, 3, NULL, NULL,
                            true, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "closed Catmull-Rom spline needs at least 3 distinct "
                 "points, got 2");
    expect_error(try_interp(2, P, 0, CF_INTERP_CATMULL_ROM, 3, NULL, NULL,
                            false, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "Catmull-Rom spline needs at least 2 points, got 0");
    expect_error(try_interp(2, P, 4, CF_INTERP_GLOBAL, 4, NULL, NULL, false,
                            &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "global interpolation of degree 4 needs at least 5 points, "
                 "got 4");
    expect_error(try_interp(2, P, 3, CF_INTERP_GLOBAL, 4, t, NULL, false,
                            &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "global interpolation of degree 4 needs at least 5 points "
                 "and end derivatives together, got 3 + 1");
    expect_error(try_interp(2, P, 1, CF_INTERP_GLOBAL, 1, NULL, NULL, false,
                            &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "global interpolation needs at least 2 points, got 1");
    expect_error(try_interp(2, Q, 4, CF_INTERP_NATURAL, 3, NULL, NULL, false,
                            &d),
                 CF_STATUS_DEGENERATE, &d,
                 "points 1 and 2 coincide (1, 2); chord-length parameters "
                 "need distinct consecutive points");
    expect_error(try_interp(2, N, 3, CF_INTERP_CLAMPED, 3, t, t, false, &d),
                 CF_STATUS_NOT_FINITE, &d,
                 "point P_2 has coordinate 2 = NaN; coordinates must be "
                 "finite");
    expect_error(try_interp(2, P, 5, CF_INTERP_NATURAL, 5, NULL, NULL, false,
                            &d),
                 CF_STATUS_BAD_DEGREE, &d,
                 "natural cubic spline has degree 3, got degree 5; use "
                 "method global for other degrees");
    expect_error(try_interp(2, P, 5, CF_INTERP_GLOBAL, -1, NULL, NULL, false,
                            &d),
                 CF_STATUS_BAD_DEGREE, &d,
                 "global interpolation degree -1 is outside 1..32");
    expect_error(try_interp(2, P, 5, CF_INTERP_GLOBAL, 33, NULL, NULL, false,
                            &d),
                 CF_STATUS_BAD_DEGREE, &d,
                 "global interpolation degree 33 is outside 1..32");
    expect_error(try_interp(2, P, 5, CF_INTERP_GLOBAL, 1, t, NULL, false,
                            &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "global interpolation of degree 1 (a polyline) takes no end "
                 "tangents");
    expect_error(try_interp(2, P, 5, CF_INTERP_GLOBAL, 3, NULL, NULL, true,
                            &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "global interpolation cannot be closed; use method periodic "
                 "for a closed cubic spline");
    expect_error(try_interp(2, P, 5, CF_INTERP_CLAMPED, 3, t, NULL, false,
                            &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "clamped cubic spline needs start_tangent and end_tangent");
    expect_error(try_interp(2, P, 5, CF_INTERP_CLAMPED, 3, t, tn, false,
                            &d),
                 CF_STATUS_NOT_FINITE, &d,
                 "end_tangent has coordinate 1 = inf; coordinates must be "
                 "finite");
    expect_error(try_interp(2, P, 5, CF_INTERP_NATURAL, 3, t, NULL, false,
                            &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "natural cubic spline takes no end tangents; use method "
                 "clamped or global");
    expect_error(try_interp(2, P, 5, CF_INTERP_NOT_A_KNOT, 3, NULL, NULL,
                            true, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "not-a-knot cubic spline cannot be closed; use method "
                 "periodic for a closed cubic spline");
    expect_error(try_interp(2, P, 5, (cf_interp_method_t)17, 3, NULL, NULL,
                            false, &d),
                 CF_STATUS_INVALID_ARG, &d, "unknown interpolation method 17");
    expect_error(try_interp(0, P, 5, CF_INTERP_NATURAL, 3, NULL, NULL, false,
                            &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "dimension must be at least 1, got 0");
    expect_error(try_interp(2, NULL, 5, CF_INTERP_NATURAL, 3, NULL, NULL,
                            false, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "points must not be NULL");
    cf_diag_clear(&d);
    expect_error(cf_interpolate(2, P, 5, NULL, NULL, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "out must not be NULL");
}

static void
test_explicit_params(void **state)
{
    /* Explicit parameters are used as given: the domain is theirs, and a
    ** decreasing one is rejected by name. */
    const double P[] = { 0, 0, 1, 2, 3, 1, 4, 4 };
    const double u[] = { 2, 3, 5, 6 }, bad[] = { 0, 1, 1, 2 };
    cf_interp_options_t o;
    cf_bspline_t *c = NULL;
    double a, b, q[2];
    cf_diag_t d;
    (void)state;
    cf_interp_options_init(&o);
    o.params = u;
    assert_int_equal(cf_interpolate(2, P, 4, &o, &c, NULL), CF_STATUS_OK);
    cf_bspline_domain(c, &a, &b);
    assert_true(a == 2.0 && b == 6.0);
    for (int i = 0; i < 4; i++) {
        assert_int_equal(cf_bspline_eval(c, u[i], q), CF_STATUS_OK);
        assert_true(dist(q, P + 2 * i, 2) <= 1e-14 * 4);
    }
    cf_bspline_destroy(c);
    o.params = bad;
    cf_diag_clear(&d);
    expect_error(cf_interpolate(2, P, 4, &o, &c, &d), CF_STATUS_BAD_KNOTS, &d,
                 "parameter 2 (1) is not larger than parameter 1 (1); "
                 "parameters must increase strictly");
    /* periodic: the square with its closing point and 5 parameters */
    {
        const double S[] = { 1, 0, 0, 1, -1, 0, 0, -1, 1, 0 };
        const double us[] = { 0, 1, 2, 3, 4 };
        cf_interp_options_t po;
        cf_interp_options_init(&po);
        po.method = CF_INTERP_PERIODIC;
        po.params = us;
        assert_int_equal(cf_interpolate(2, S, 5, &po, &c, NULL),
                         CF_STATUS_OK);
        cf_bspline_domain(c, &a, &b);
        assert_true(a == 0.0 && b == 4.0);
        for (int i = 0; i <= 4; i++) {
            assert_int_equal(cf_bspline_eval(c, us[i], q), CF_STATUS_OK);
            assert_true(dist(q, S + 2 * i, 2) <= 1e-15 * 4);
        }
        cf_bspline_destroy(c);
    }
    /* a power parametrisation (e = 0.25) */
    o.params = NULL;
    o.param = CF_PARAM_POWER;
    o.exponent = 0.25;
    assert_int_equal(cf_interpolate(2, P, 4, &o, &c, NULL), CF_STATUS_OK);
    cf_bspline_destroy(c);
}

static void
test_smallest_cases(void **state)
{
    /* The fewest points of each method give the expected small curves. */
    const double P[] = { 0, 0, 2, 1, 3, 3, 0, 2 };
    double q[2];
    cf_bspline_t *c;
    (void)state;
    /* two-point Catmull-Rom: both end tangents are the chord, a line */
    c = interp(2, P, 2, CF_INTERP_CATMULL_ROM, CF_PARAM_CHORD, 3, NULL, NULL,
               false);
    assert_int_equal(cf_bspline_eval(c, 0.25, q), CF_STATUS_OK);
    tu_assert_close(q[0], 0.5, 1e-15, 1.0);
    tu_assert_close(q[1], 0.25, 1e-15, 1.0);
    cf_bspline_destroy(c);
    /* global with count = p + 1: one Bézier piece, count control points */
    c = interp(2, P, 4, CF_INTERP_GLOBAL, CF_PARAM_CHORD, 3, NULL, NULL,
               false);
    assert_int_equal(cf_bspline_count(c), 4);
    assert_int_equal(cf_bspline_nknots(c), 8);
    cf_bspline_destroy(c);
    /* periodic through a triangle: closed, 3 + 3 control points */
    c = interp(2, P, 3, CF_INTERP_PERIODIC, CF_PARAM_CENTRIPETAL, 3, NULL,
               NULL, false);
    assert_int_equal(cf_bspline_count(c), 6);
    cf_bspline_destroy(c);
}

static void
test_numerically_singular(void **state)
{
    /* Four well separated points crowded into parameters 3e-12 apart:
    ** the collocation matrix has a pivot below DBL_EPSILON after row
    ** equilibration, and the message says what to do. */
    const double P[] = { 0, 0, 1, 0, 2, 1, 3, 0, 4, 2, 5, 1, 6, 0, 7, 1 };
    const double u[] = { 0, 1e-12, 2e-12, 3e-12, 1, 2, 3, 4 };
    cf_interp_options_t o;
    cf_bspline_t *c = NULL;
    cf_diag_t d;
    (void)state;
    cf_interp_options_init(&o);
    o.method = CF_INTERP_GLOBAL;
    o.params = u;
    cf_diag_clear(&d);
    expect_error(cf_interpolate(2, P, 8, &o, &c, &d), CF_STATUS_DEGENERATE,
                 &d,
                 "the interpolation system of degree 3 is numerically "
                 "singular at row 6; the parameters are too unevenly spaced "
                 "for it (try a lower degree or centripetal parameters)");
    assert_null(c);
}

/*
** Chord-length parameters that coincide.  The closed polygon (0, 0),
** (1, 0), (1, 2^-60), (1, 0.5), (0, 0.5) has chords 1, 2^-60, 0.5, 1 and
** 0.5: the second is lost in the running sum (1 + 2^-60 = 1), so points 1
** and 2 would both get 1/3.  No curve passes through two points at one
** parameter: the periodic spline once said "parameter 1 (0.333333) is not
** in its own knot span", Catmull-Rom divided by the zero step and blamed a
** NaN coordinate of the point (1, 2^-60).  cf_interp_parameters still
** gives them (they are what the rule makes), and least squares, which
** need not pass through each point, takes them.  Centripetal parameters
** (square roots of the chords) keep the step: 2^-30 counts beside 1.
*/
static void
test_lost_chord(void **state)
{
    const double e = ldexp(1.0, -60);
    const double P[] = { 0, 0, 1, 0, 1, e, 1, 0.5, 0, 0.5 };
    const char *msg = "points 1 and 2 get the same chord-length parameter "
                      "0.3333333333333333 (their distance is lost in "
                      "rounding beside the others'); use centripetal or "
                      "uniform parameters";
    double u[6];
    cf_interp_options_t o;
    cf_bspline_t *c = NULL;
    cf_diag_t d;
    (void)state;
    assert_int_equal(cf_interp_parameters(2, P, 5, CF_PARAM_CHORD, 0.0, true,
                                          u, NULL),
                     CF_STATUS_OK);
    assert_true(u[1] == 1.0 / 3.0 && u[2] == u[1]);
    expect_error(try_interp(2, P, 5, CF_INTERP_PERIODIC, 3, NULL, NULL, true,
                            &d),
                 CF_STATUS_DEGENERATE, &d, msg);
    assert_int_equal(d.index, 2);
    cf_interp_options_init(&o);
    o.method = CF_INTERP_CATMULL_ROM;
    o.closed = true;
    o.param = CF_PARAM_CHORD;
    expect_error(cf_interpolate(2, P, 5, &o, &c, &d), CF_STATUS_DEGENERATE,
                 &d, msg);
    assert_null(c);
    o.param = CF_PARAM_CENTRIPETAL;
    assert_int_equal(cf_interp_parameters(2, P, 5, CF_PARAM_CENTRIPETAL, 0.0,
                                          true, u, NULL),
                     CF_STATUS_OK);
    for (int i = 0; i < 5; i++)
        assert_true(u[i + 1] > u[i]);
    assert_int_equal(cf_interpolate(2, P, 5, &o, &c, NULL), CF_STATUS_OK);
    cf_bspline_destroy(c);
    c = NULL;
    cf_interp_options_init(&o);
    o.param = CF_PARAM_CHORD;
    assert_int_equal(cf_approximate_lsq(2, P, 5, 4, &o, true, &c, NULL, NULL),
                     CF_STATUS_OK);
    cf_bspline_destroy(c);
}

/* ---- out of memory ------------------------------------------------------ */

static void
test_out_of_memory(void **state)
{
    const double P[] = { 0, 0, 1, 2, 3, 1, 4, 4, 6, 0, 7, 3 };
    const double t[] = { 1, 0 };
    (void)state;
    for (int what = 0; what < 10; what++) {
        for (long k = 1;; k++) {
            cf_interp_options_t o;
            cf_bspline_t *c = NULL;
            cf_bezier_list_t *l = NULL;
            cf_status_t st;
            cf_interp_options_init(&o);
            if (what < 6)
                o.method = (cf_interp_method_t)what;
            if (o.method == CF_INTERP_CLAMPED ||
                o.method == CF_INTERP_GLOBAL) {
                o.start_tangent = t;
                o.end_tangent = t;
            }
            tu_fail_alloc_after(k);
            if (what < 6)
                st = cf_interpolate(2, P, 6, &o, &c, NULL);
            else if (what == 6)
                st = cf_approximate_lsq(2, P, 6, 4, &o, true, &c, NULL,
                                        NULL);
            else if (what == 7)
                st = cf_approximate_lsq(2, P, 6, 5, &o, false, &c, &(double){0},
                                        NULL);
            else if (what == 8)
                st = cf_ferguson_chain(2, P, P, 6, &l, NULL);
            else
                st = cf_coons_chain(2, P, 6, CF_COONS_TRIPLED, &l, NULL);
            cf_bspline_destroy(c);
            cf_bezier_list_destroy(l);
            tu_fail_alloc_reset();
            assert_int_equal(tu_alloc_live(), 0);
            if (st == CF_STATUS_OK)
                break;
            assert_int_equal(st, CF_STATUS_NO_MEMORY);
            assert_true(k < 200);
        }
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_interpolate_errors),
        cmocka_unit_test(test_explicit_params),
        cmocka_unit_test(test_smallest_cases),
        cmocka_unit_test(test_numerically_singular),
        cmocka_unit_test(test_lost_chord),
        cmocka_unit_test(test_out_of_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
