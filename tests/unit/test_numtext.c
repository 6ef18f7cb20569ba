/*
** Numbers in the core's messages (src/numtext.c): the text reads back as
** the same double (bit for bit, -0 included) and has the fewest
** significant digits that do (one fewer, as %.*g writes it, reads back as
** another double); and the messages of the files that use it show the
** short text (0.17, not 0.17000000000000001; 1/3 in full, not 0.333333;
** 0.3 and 0.30000000000000004 told apart, not both 0.3; 1.0000001, not
** 1), one test for each source file.
*/
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

#include "curvefig/curvefig.h"
#include "../../src/linsolve-private.h"
#include "../../src/numtext-private.h"
#include "testutil.h"

/* The significant digits of a number's text: the digits of its mantissa
** without leading zeros and, in an integer written out, without the
** trailing zeros that only place it (1000000 has 1, 0.17 has 2, 0 has 1). */
static int
significant(const char *t)
{
    char d[40];
    int n = 0, first = 0;
    for (const char *s = t; *s != '\0' && *s != 'e'; s++)
        if (*s >= '0' && *s <= '9')
            d[n++] = *s;
    while (first < n && d[first] == '0')
        first++;
    while (n > first && d[n - 1] == '0')
        n--;
    return n > first ? n - first : 1;
}

static bool
same_double(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* x's text reads back as x, with the fewest significant digits, and in
** exponent form exactly when x is below 1e-4 or from 1e17 on. */
static void
check_shortest(double x)
{
    char buf[CF__NUM_TEXT], shorter[512];
    const char *t = cf__num_text(x, buf);
    int sig = significant(t);
    double ax = fabs(x);
    if (!same_double(strtod(t, NULL), x))
        fail_msg("%a: \"%s\" reads back as %a", x, t, strtod(t, NULL));
    assert_true(sig >= 1 && sig <= 17);
    assert_true(strlen(t) < CF__NUM_TEXT);
    if (sig > 1) {
        snprintf(shorter, sizeof shorter, "%.*g", sig - 1, x);
        if (strtod(shorter, NULL) == x)
            fail_msg("%a: \"%s\" has %d digits but \"%s\" reads back too",
                     x, t, sig, shorter);
    }
    if (x != 0.0 && (ax < 1e-4 || ax >= 1e17))
        assert_non_null(strchr(t, 'e'));
    else
        assert_null(strchr(t, 'e'));
}

static void
expect_text(double x, const char *want)
{
    char buf[CF__NUM_TEXT];
    assert_string_equal(cf__num_text(x, buf), want);
}

static void
test_values(void **state)
{
    (void)state;
    static const double xs[] = {
        0.1, 0.17, 1.0 / 3.0, 2.0 / 3.0, 0.1 + 0.2, 1e300, -1e300, 5e-324,
        -5e-324, DBL_MIN, DBL_MAX, -DBL_MAX, 0.0, -0.0, 1.0, -1.0, 100.0,
        1e6, 123456789.0, 9007199254740993.0, 1e16, 1e17, 1.5e17, 1e-4,
        1e-5, 0.00012345, 1.7, 1e23, 0.3, 2.5e-300, 1.0 + DBL_EPSILON,
        1.0 - DBL_EPSILON / 2
    };
    for (size_t i = 0; i < sizeof xs / sizeof *xs; i++)
        check_shortest(xs[i]);
    expect_text(0.1, "0.1");
    expect_text(0.17, "0.17");
    expect_text(1.0 / 3.0, "0.3333333333333333");
    expect_text(0.1 + 0.2, "0.30000000000000004");
    expect_text(1e300, "1e+300");
    expect_text(5e-324, "5e-324");
    expect_text(-0.0, "-0");
    expect_text(0.0, "0");
    expect_text(DBL_MAX, "1.7976931348623157e+308");
    expect_text(100.0, "100");
    expect_text(1e6, "1000000");
    expect_text(-2.5, "-2.5");
    expect_text(1e16, "10000000000000000");
    expect_text(1e17, "1e+17");
    expect_text(1e-4, "0.0001");
    expect_text(1e-5, "1e-05");
    expect_text(NAN, "NaN");
    expect_text(-NAN, "NaN");
    expect_text(INFINITY, "inf");
    expect_text(-INFINITY, "-inf");
}

/* Random bit patterns (every exponent) and random short decimals. */
static void
test_random(void **state)
{
    (void)state;
    tu_rng r;
    tu_rng_seed(&r, 20261204);
    for (int i = 0; i < 20000; i++) {
        uint64_t bits = tu_rng_next(&r);
        double x;
        memcpy(&x, &bits, sizeof x);
        if (isfinite(x))
            check_shortest(x);
        /* k / 10^e: the text is k's digits, however the double rounds */
        x = (double)(tu_rng_next(&r) % 100000) /
            pow(10.0, (double)(tu_rng_next(&r) % 8));
        check_shortest(x);
    }
}

/* ---- the messages ---------------------------------------------------- */

/* The line from (x0, y0) to (x1, y1) as a B-spline on [0, b] (knots 0, 0,
** b, b). */
static cf_bspline_t *
line_on(double b, double x0, double y0, double x1, double y1)
{
    const double U[] = { 0.0, 0.0, b, b }, P[] = { x0, y0, x1, y1 };
    cf_bspline_t *c = NULL;
    assert_int_equal(cf_bspline_create(2, 1, U, 4, P, 2, NULL, &c, NULL),
                     CF_STATUS_OK);
    return c;
}

/* The line from (0, 0) to (1, 1) on [0, 0.17]. */
static cf_bspline_t *
short_line(void)
{
    return line_on(0.17, 0, 0, 1, 1);
}

/* src/domain.c: the domain rule's message */
static void
test_message_domain(void **state)
{
    (void)state;
    static const double U[] = { 0.0, 0.0, 0.17, 0.17 };
    double N[2];
    cf_diag_t d;
    assert_int_equal(cf_basis_funs(1, U, 4, 0.3, NULL, N, &d),
                     CF_STATUS_DOMAIN);
    assert_string_equal(d.msg, "parameter 0.3 is outside the domain "
                               "[0, 0.17]");
}

/* src/bspline.c: the parameter of an operation, a homogeneous weight */
static void
test_message_bspline(void **state)
{
    (void)state;
    static const double U[] = { 0.0, 0.0, 0.17, 0.17 };
    const double H[] = { 0.0, 0.0, 1.0, 1.0, 1.0, -1.0 / 3.0 };
    cf_bspline_t *c = short_line(), *l = NULL, *q = NULL;
    cf_diag_t d;
    assert_int_equal(cf_bspline_split(c, 0.3, &l, &q, &d), CF_STATUS_DOMAIN);
    assert_string_equal(d.msg, "parameter 0.3 is outside the domain "
                               "[0, 0.17]");
    cf_bspline_destroy(c);
    c = NULL;
    assert_int_equal(cf_bspline_create_homogeneous(2, 1, U, 4, H, 2, &c, &d),
                     CF_STATUS_BAD_WEIGHT);
    assert_string_equal(d.msg, "weight w_1 is -0.3333333333333333; weights "
                               "must be finite and positive");
    assert_null(c);
}

/* src/core.c: the checks of every constructor (weights, points) */
static void
test_message_core(void **state)
{
    (void)state;
    static const double U[] = { 0.0, 0.0, 0.17, 0.17 };
    static const double P[] = { 0.0, 0.0, 1.0, 1.0 };
    const double w[] = { 1.0, -1.0 / 3.0 }, inf[] = { 0, 0, 1, -INFINITY };
    cf_bspline_t *c = NULL;
    cf_diag_t d;
    assert_int_equal(cf_bspline_create(2, 1, U, 4, P, 2, w, &c, &d),
                     CF_STATUS_BAD_WEIGHT);
    assert_string_equal(d.msg, "weight w_1 is -0.3333333333333333; weights "
                               "must be finite and positive");
    assert_int_equal(cf_bspline_create(2, 1, U, 4, inf, 2, NULL, &c, &d),
                     CF_STATUS_NOT_FINITE);
    assert_string_equal(d.msg, "point P_1 has coordinate 2 = -inf; "
                               "coordinates must be finite");
    assert_null(c);
}

/* src/bspline-ops.c: split at an end, an empty segment */
static void
test_message_bspline_ops(void **state)
{
    (void)state;
    cf_bspline_t *c = short_line(), *l = NULL, *q = NULL;
    cf_diag_t d;
    assert_int_equal(cf_bspline_split(c, 0.17, &l, &q, &d), CF_STATUS_DOMAIN);
    assert_string_equal(d.msg, "0.17 must lie strictly inside the domain "
                               "[0, 0.17]");
    assert_int_equal(cf_bspline_segment(c, 0.1, 1.0 / 30.0, &q, &d),
                     CF_STATUS_DOMAIN);
    assert_string_equal(d.msg, "[0.1, 0.03333333333333333] is empty");
    cf_bspline_destroy(c);
}

/* The bilinear Bézier patch of the unit square (weights w or NULL). */
static cf_status_t
square(const double *w, cf_bezier_surface_t **s, cf_diag_t *d)
{
    static const double P[] = { 0, 0, 0, 1, 1, 0, 1, 1 };
    return cf_bezier_surface_create(2, 1, 1, P, w, s, d);
}

/* src/surface-common.c: a surface's weight and parameter */
static void
test_message_surface_common(void **state)
{
    (void)state;
    static const double U[] = { 0.0, 0.0, 0.17, 0.17 };
    static const double V[] = { 0.0, 0.0, 1.0, 1.0 };
    static const double P[] = { 0, 0, 0, 1, 1, 0, 1, 1 };
    const double w[] = { 1.0, 1.0, 1.0, -1.0 / 3.0 };
    cf_bezier_surface_t *s = NULL;
    cf_bspline_surface_t *b = NULL;
    cf_bspline_t *iso = NULL;
    cf_diag_t d;
    assert_int_equal(square(w, &s, &d), CF_STATUS_BAD_WEIGHT);
    assert_string_equal(d.msg, "weight W[1][1] is -0.3333333333333333; "
                               "weights must be finite and positive");
    assert_int_equal(cf_bspline_surface_create(2, 1, 1, U, 4, V, 4, P, 2, 2,
                                               NULL, &b, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_bspline_surface_iso(b, CF_DIR_U, 0.3, &iso, &d),
                     CF_STATUS_DOMAIN);
    assert_string_equal(d.msg, "parameter u = 0.3 is outside the domain "
                               "[0, 0.17]");
    cf_bspline_surface_destroy(b);
}

/* src/surface-bezier-ops.c: a split parameter, a sub-patch interval */
static void
test_message_surface_bezier_ops(void **state)
{
    (void)state;
    cf_bezier_surface_t *s = NULL, *lo = NULL, *hi = NULL;
    cf_diag_t d;
    assert_int_equal(square(NULL, &s, NULL), CF_STATUS_OK);
    assert_int_equal(cf_bezier_surface_split(s, CF_DIR_V, 1.7, &lo, &hi, &d),
                     CF_STATUS_DOMAIN);
    assert_string_equal(d.msg, "split parameter v = 1.7 is not inside "
                               "(0, 1)");
    assert_int_equal(cf_bezier_surface_segment(s, 0.7, 0.1, 0.0, 1.0, &lo,
                                               &d),
                     CF_STATUS_DOMAIN);
    assert_string_equal(d.msg, "sub-patch interval of u [0.7, 0.1] is not "
                               "inside [0, 1] with its ends in order");
    cf_bezier_surface_destroy(s);
}

/* src/bezier.c: a parameter just outside (0, 1), which %g wrote as 1 */
static void
test_message_bezier(void **state)
{
    (void)state;
    static const double P[] = { 0, 0, 1, 2, 3, 0 };
    cf_bezier_t *c = NULL, *l = NULL, *r = NULL;
    cf_diag_t d;
    assert_int_equal(cf_bezier_create(2, 2, P, NULL, &c, NULL), CF_STATUS_OK);
    assert_int_equal(cf_bezier_split(c, 1.0000001, &l, &r, &d),
                     CF_STATUS_DOMAIN);
    assert_string_equal(d.msg, "split parameter 1.0000001 is outside the "
                               "open interval (0, 1)");
    cf_bezier_destroy(c);
}

/* src/bspline-knot-ops.c: a knot to remove that is not one */
static void
test_message_bspline_knot_ops(void **state)
{
    (void)state;
    static const double U[] = { 0, 0, 0, 0.5, 1, 1, 1 };
    static const double P[] = { 0, 0, 1, 2, 2, 2, 3, 0 };
    cf_bspline_t *c = NULL, *q = NULL;
    cf_diag_t d;
    assert_int_equal(cf_bspline_create(2, 2, U, 7, P, 4, NULL, &c, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_bspline_remove_knot(c, 1.0 / 3.0, 1, 0.0, &q, NULL,
                                            &d),
                     CF_STATUS_BAD_KNOTS);
    assert_string_equal(d.msg, "0.3333333333333333 is not an interior knot "
                               "of the domain [0, 1]");
    cf_bspline_destroy(c);
}

/* src/knots.c: two parameters that %g wrote alike (both 0.3) */
static void
test_message_knots(void **state)
{
    (void)state;
    const double t[] = { 0.0, 0.1 + 0.2, 0.3, 1.0 };
    double U[8];
    cf_diag_t d;
    assert_int_equal(cf_knots_clamped_averaged(2, 4, t, U, &d),
                     CF_STATUS_INVALID_ARG);
    assert_string_equal(d.msg, "parameter 2 (0.3) is not larger than "
                               "parameter 1 (0.30000000000000004)");
}

/* src/interp-params.c: the same for interpolation's own parameters */
static void
test_message_interp_params(void **state)
{
    (void)state;
    static const double P[] = { 0, 0, 1, 1, 2, 0, 3, 1 };
    const double u[] = { 0.0, 0.1 + 0.2, 0.3, 1.0 };
    cf_interp_options_t o;
    cf_bspline_t *c = NULL;
    cf_diag_t d;
    cf_interp_options_init(&o);
    o.params = u;
    assert_int_equal(cf_interpolate(2, P, 4, &o, &c, &d),
                     CF_STATUS_BAD_KNOTS);
    assert_string_equal(d.msg, "parameter 2 (0.3) is not larger than "
                               "parameter 1 (0.30000000000000004); "
                               "parameters must increase strictly");
    assert_null(c);
}

/* src/conic.c: an empty parameter range */
static void
test_message_conic(void **state)
{
    (void)state;
    cf_bezier_list_t *l = NULL;
    cf_diag_t d;
    assert_int_equal(cf_conic_parabola(0, 0, 1, 0, 2.0 / 3.0, 0.1 + 0.2, &l,
                                       &d),
                     CF_STATUS_DOMAIN);
    assert_string_equal(d.msg, "parameter range [0.6666666666666666, "
                               "0.30000000000000004] is empty");
}

/* src/surface-triangle.c: a point outside the triangle; w = 1 - u - v as
** computed (Python's repr of 1 - (0.1 + 0.2) - 0.8, the shortest text) */
static void
test_message_surface_triangle(void **state)
{
    (void)state;
    static const double P[] = { 0, 0, 1, 0, 0, 1 };
    cf_bezier_triangle_t *t = NULL, *out[3];
    cf_diag_t d;
    assert_int_equal(cf_bezier_triangle_create(2, 1, P, NULL, &t, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_bezier_triangle_subdivide(t, 0.1 + 0.2, 0.8, out,
                                                  &d),
                     CF_STATUS_DOMAIN);
    assert_string_equal(d.msg, "(u, v, w) = (0.30000000000000004, 0.8, "
                               "-0.10000000000000009) is not a point of "
                               "the triangle");
    cf_bezier_triangle_destroy(t);
}

/* src/basis-spline.c: knots that span no interval */
static void
test_message_basis_spline(void **state)
{
    (void)state;
    const double U[] = { 1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0 };
    cf_bspline_t *b = NULL;
    cf_diag_t d;
    assert_int_equal(cf_basis_one_spline(0, 1, U, 3, &b, &d),
                     CF_STATUS_BAD_KNOTS);
    assert_string_equal(d.msg, "the knots span no interval (all "
                               "0.3333333333333333)");
}

static double
pole(double t, void *ud)
{
    (void)ud;
    return 1.0 / (t - 0.5);
}

/* src/bernstein.c: f(i/n) not finite */
static void
test_message_bernstein(void **state)
{
    (void)state;
    double coef[3];
    cf_diag_t d;
    assert_int_equal(cf_bernstein_approx(pole, NULL, 2, coef, &d),
                     CF_STATUS_NOT_FINITE);
    assert_string_equal(d.msg, "f(1/2) = inf is not finite");
}

/* A quadratic Bézier curve of the plane. */
static cf_bezier_t *
arch(void)
{
    static const double P[] = { 0, 0, 1, 2, 3, 0 };
    cf_bezier_t *c = NULL;
    assert_int_equal(cf_bezier_create(2, 2, P, NULL, &c, NULL), CF_STATUS_OK);
    return c;
}

/* src/bezier-cubics.c, src/fit-cusp.c, src/offset.c: a tolerance, an
** offset distance */
static void
test_message_cubics_offsets(void **state)
{
    (void)state;
    cf_bezier_t *c = arch();
    cf_cubics_t *k = NULL;
    cf_offset_options_t o;
    double ts[8];
    size_t n;
    cf_diag_t d;
    assert_int_equal(cf_bezier_to_cubics(c, -1.0 / 3.0, &k, &d),
                     CF_STATUS_INVALID_ARG);
    assert_string_equal(d.msg, "tolerance -0.3333333333333333 must be finite "
                               "and positive");
    assert_int_equal(cf_offset_cusps(c, -INFINITY, ts, 8, &n, &d),
                     CF_STATUS_NOT_FINITE);
    assert_string_equal(d.msg, "offset distance -inf is not finite");
    cf_offset_options_init(&o);
    o.tolerance = -1.0 / 3.0;
    assert_int_equal(cf_bezier_offset(c, 0.1, &o, &k, NULL, NULL, &d),
                     CF_STATUS_INVALID_ARG);
    assert_string_equal(d.msg, "offset tolerance -0.3333333333333333 must be "
                               "finite and positive");
    cf_bezier_destroy(c);
}

/* src/interp.c: an end tangent that is not finite */
static void
test_message_interp(void **state)
{
    (void)state;
    static const double P[] = { 0, 0, 1, 1, 2, 0 };
    const double t0[] = { 1.0, 0.0 }, t1[] = { 0.17, -INFINITY };
    cf_interp_options_t o;
    cf_bspline_t *c = NULL;
    cf_diag_t d;
    cf_interp_options_init(&o);
    o.method = CF_INTERP_CLAMPED;
    o.start_tangent = t0;
    o.end_tangent = t1;
    assert_int_equal(cf_interpolate(2, P, 3, &o, &c, &d),
                     CF_STATUS_NOT_FINITE);
    assert_string_equal(d.msg, "end_tangent has coordinate 2 = -inf; "
                               "coordinates must be finite");
}

/*
** src/reduce-bezier.c: a rational quartic reduced to a cubic keeping C^1
** at both ends: the end conditions alone fix the reduced weight
** w'_1 = w_0 + (4/3)(w_1 - w_0) = 2 + (4/3)(0.25 - 2) = -1/3, not
** positive.  As computed it is 5 units in the last place from the double
** nearest -1/3: terms of size 2 and 7/3 cancel, so it is checked to a few
** roundings of 7/3 (4 DBL_EPSILON absolute, about 4e-16 relative to 7/3).
*/
static void
test_message_reduce_bezier(void **state)
{
    (void)state;
    static const double P[] = { 0, 1, 2, 3, 4 };
    static const double w[] = { 2, 0.25, 1, 1, 1 };
    cf_bezier_t *c = NULL, *r = NULL;
    cf_reduce_options_t o;
    cf_diag_t d;
    double q;
    assert_int_equal(cf_bezier_create(1, 4, P, w, &c, NULL), CF_STATUS_OK);
    cf_reduce_options_init(&o);
    o.continuity = 1;
    assert_int_equal(cf_bezier_reduce(c, &o, &r, NULL, &d),
                     CF_STATUS_DEGENERATE);
    assert_int_equal(d.index, 1);
    assert_string_equal(d.msg, "the reduced curve's weight 1 is "
                               "-0.33333333333333304; the rational curve "
                               "cannot be reduced to degree 3");
    q = strtod(strstr(d.msg, "is ") + 3, NULL);
    assert_true(fabs(q + 1.0 / 3.0) <= 4 * DBL_EPSILON);
    check_shortest(q);
    assert_null(r);
    cf_bezier_destroy(c);
}

/* src/view.c: a perspective view's distance */
static void
test_message_view(void **state)
{
    (void)state;
    cf_view_t v;
    cf_diag_t d;
    assert_int_equal(cf_view_perspective(&v, 30, 20, -1.0 / 3.0, NULL, &d),
                     CF_STATUS_INVALID_ARG);
    assert_string_equal(d.msg, "view: distance -0.3333333333333333 must be "
                               "positive");
}

/* A scene at 1/3 of a unit of the page, seen from (30, 20), with the
** bilinear patch of corners (0, 0, 0), (0, s, 0), (s, 0, 0), (s, s, z). */
static cf_scene_t *
patch_scene(double tol, double s, double z, cf_status_t want, cf_diag_t *d)
{
    const double P[] = { 0, 0, 0, 0, s, 0, s, 0, 0, s, s, z };
    cf_view_t v;
    cf_scene_t *sc = NULL;
    cf_bezier_surface_t *b = NULL;
    assert_int_equal(cf_view_orthographic(&v, 30, 20, NULL), CF_STATUS_OK);
    assert_int_equal(cf_scene_create(&v, tol, &sc, NULL), CF_STATUS_OK);
    assert_int_equal(cf_bezier_surface_bilinear(3, P, &b, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_scene_add_bezier(sc, b, NULL, d), want);
    cf_bezier_surface_destroy(b);
    return sc;
}

/* src/scene.c: a tolerance given (in full) and the scene's size measured
** (three digits: the box's diagonal sqrt(2 10^20 + 1) = 1.41e+10) */
static void
test_message_scene(void **state)
{
    (void)state;
    cf_view_t v;
    cf_scene_t *sc = NULL;
    cf_diag_t d;
    assert_int_equal(cf_view_orthographic(&v, 30, 20, NULL), CF_STATUS_OK);
    assert_int_equal(cf_scene_create(&v, -1.0 / 3.0, &sc, &d),
                     CF_STATUS_INVALID_ARG);
    assert_string_equal(d.msg, "tolerance -0.3333333333333333 must be "
                               "positive and finite");
    assert_null(sc);
    sc = patch_scene(1e-3, 1e10, 1, CF_STATUS_INVALID_ARG, &d);
    assert_string_equal(d.msg, "tolerance 0.001 is below 1e-12 of the "
                               "scene's size 1.41e+10");
    cf_scene_destroy(sc);
}

/* src/vis-curve.c: the offset of a point on a surface */
static void
test_message_vis_curve(void **state)
{
    (void)state;
    const double p[] = { 0.5, 0.5, 0 };
    cf_vis_on_t on;
    bool vis;
    cf_diag_t d;
    cf_scene_t *sc = patch_scene(1.0 / 3.0, 1, 0, CF_STATUS_OK, NULL);
    memset(&on, 0, sizeof on);
    on.offset = -1.0 / 3.0;
    assert_int_equal(cf_scene_point_visible(sc, p, &on, &vis, NULL, &d),
                     CF_STATUS_INVALID_ARG);
    assert_string_equal(d.msg, "on: offset -0.3333333333333333 must be "
                               "finite and >= 0");
    cf_scene_destroy(sc);
}

/* src/vis-facets.c: a facets' tolerance below the scene's resolution
** (the size, measured, in three digits: the unit square's diagonal) */
static void
test_message_vis_facets(void **state)
{
    (void)state;
    cf_facets_t *f = NULL;
    cf_diag_t d;
    cf_scene_t *sc = patch_scene(1.0 / 3.0, 1, 0, CF_STATUS_OK, NULL);
    assert_int_equal(cf_scene_facets_tol(sc, 1e-13 / 3.0, &f, &d),
                     CF_STATUS_INVALID_ARG);
    assert_string_equal(d.msg, "tolerance 3.3333333333333334e-14 must be "
                               "positive and at least 1e-12 of the scene's "
                               "size 1.41");
    assert_null(f);
    cf_scene_destroy(sc);
}

/* src/linsolve.c: a singular band */
static void
test_message_linsolve(void **state)
{
    (void)state;
    cf__band_t b;
    cf_diag_t d;
    assert_int_equal(cf__band_init(&b, 2, 1, 1, NULL), CF_STATUS_OK);
    cf__band_set(&b, 0, 0, 1.0 / 3.0);
    cf__band_set(&b, 1, 0, 1.0);
    cf_diag_clear(&d);
    assert_int_equal(cf__band_factor(&b, &d), CF_STATUS_DEGENERATE);
    assert_string_equal(d.msg, "banded system is singular at row 1 "
                               "(largest pivot 0)");
    cf__band_fini(&b);
}

/* src/reduce-bspline.c: a tolerance */
static void
test_message_reduce_bspline(void **state)
{
    (void)state;
    static const double U[] = { 0, 0, 0, 0, 1, 1, 1, 1 };
    static const double P[] = { 0, 0, 1, 2, 2, 2, 3, 0 };
    cf_bspline_t *c = NULL, *r = NULL;
    cf_reduce_options_t o;
    cf_diag_t d;
    assert_int_equal(cf_bspline_create(2, 3, U, 8, P, 4, NULL, &c, NULL),
                     CF_STATUS_OK);
    cf_reduce_options_init(&o);
    o.tolerance = -1.0 / 3.0;
    assert_int_equal(cf_bspline_reduce(c, &o, &r, NULL, &d),
                     CF_STATUS_INVALID_ARG);
    assert_string_equal(d.msg, "tolerance -0.3333333333333333 must be finite "
                               "and > 0");
    cf_bspline_destroy(c);
}

/* src/surface-coons.c: corners that do not meet */
static void
test_message_surface_coons(void **state)
{
    (void)state;
    cf_bspline_t *c0 = line_on(1, 0, 0, 1, 0), *c1 = line_on(1, 0, 1, 1, 1);
    cf_bspline_t *d0 = line_on(1, 0, 1.0 / 3.0, 0, 1);
    cf_bspline_t *d1 = line_on(1, 1, 0, 1, 1);
    cf_bspline_surface_t *s = NULL;
    cf_diag_t d;
    assert_int_equal(cf_surface_coons(c0, c1, d0, d1, &s, &d),
                     CF_STATUS_DEGENERATE);
    assert_string_equal(d.msg, "the corners do not meet: c0(0) = (0, 0, ...) "
                               "but d0(0) = (0, 0.3333333333333333, ...)");
    cf_bspline_destroy(c0);
    cf_bspline_destroy(c1);
    cf_bspline_destroy(d0);
    cf_bspline_destroy(d1);
}

/* src/surface-revolve.c: a torus whose tube is the wider */
static void
test_message_surface_revolve(void **state)
{
    (void)state;
    static const double centre[] = { 0, 0, 0 };
    cf_bspline_surface_t *s = NULL;
    cf_diag_t d;
    assert_int_equal(cf_nurbs_torus(centre, 1.0 / 3.0, 0.5, &s, &d),
                     CF_STATUS_INVALID_ARG);
    assert_string_equal(d.msg, "the radius 0.3333333333333333 of the centre "
                               "circle must be larger than the tube's 0.5");
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_values),
        cmocka_unit_test(test_random),
        cmocka_unit_test(test_message_domain),
        cmocka_unit_test(test_message_bspline),
        cmocka_unit_test(test_message_core),
        cmocka_unit_test(test_message_bspline_ops),
        cmocka_unit_test(test_message_surface_common),
        cmocka_unit_test(test_message_surface_bezier_ops),
        cmocka_unit_test(test_message_bezier),
        cmocka_unit_test(test_message_bspline_knot_ops),
        cmocka_unit_test(test_message_knots),
        cmocka_unit_test(test_message_interp_params),
        cmocka_unit_test(test_message_conic),
        cmocka_unit_test(test_message_surface_triangle),
        cmocka_unit_test(test_message_basis_spline),
        cmocka_unit_test(test_message_bernstein),
        cmocka_unit_test(test_message_cubics_offsets),
        cmocka_unit_test(test_message_interp),
        cmocka_unit_test(test_message_reduce_bezier),
        cmocka_unit_test(test_message_view),
        cmocka_unit_test(test_message_scene),
        cmocka_unit_test(test_message_vis_curve),
        cmocka_unit_test(test_message_vis_facets),
        cmocka_unit_test(test_message_linsolve),
        cmocka_unit_test(test_message_reduce_bspline),
        cmocka_unit_test(test_message_surface_coons),
        cmocka_unit_test(test_message_surface_revolve),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
