/* Conics as quadratic rational Béziers: implicit equations, constant
** radius, continuity, parameter ranges, errors, out of memory. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/conic.h"
#include "testutil.h"

#define PI 3.14159265358979323846

/* the pieces join: end of i == start of i + 1 exactly, and the parameter
** ranges chain */
static void
check_chain(const cf_bezier_list_t *l)
{
    assert_non_null(l->t0);
    assert_non_null(l->t1);
    for (size_t i = 0; i < l->count; i++) {
        assert_int_equal(cf_bezier_degree(l->items[i]), 2);
        assert_int_equal(cf_bezier_dim(l->items[i]), 2);
        if (i > 0) {
            double a[2], b[2];
            cf_bezier_eval(l->items[i - 1], 1.0, a);
            cf_bezier_eval(l->items[i], 0.0, b);
            assert_true(a[0] == b[0] && a[1] == b[1]);
            assert_true(l->t1[i - 1] == l->t0[i]);
        }
    }
}

static void
test_circle_radius_constant(void **state)
{
    /* |c(t) - center| = r to 1e-15 relative.  The rational quadratic is
    ** evaluated by de Casteljau on (w x, w) and one division: a few
    ** roundings of relative size 2^-53 each. */
    const double centers[][2] = { { 0, 0 }, { 0.25, -0.5 } };
    const double radii[] = { 1.0, 3.5, 1e-3, 1e5 };
    (void)state;
    for (int ci = 0; ci < 2; ci++)
        for (int ri = 0; ri < 4; ri++) {
            double cx = centers[ci][0] * radii[ri];
            double cy = centers[ci][1] * radii[ri], r = radii[ri];
            cf_bezier_list_t *l;
            assert_int_equal(cf_conic_circle(cx, cy, r, &l, NULL),
                             CF_STATUS_OK);
            assert_int_equal(l->count, 4);
            check_chain(l);
            {
                double a[2], b[2];
                cf_bezier_eval(l->items[0], 0.0, a);
                cf_bezier_eval(l->items[3], 1.0, b);
                assert_true(a[0] == b[0] && a[1] == b[1]);   /* closed */
                assert_true(a[0] == cx + r && a[1] == cy);
            }
            for (size_t i = 0; i < 4; i++) {
                double w[3];
                cf_bezier_get_weights(l->items[i], w);
                tu_assert_close(w[1], sqrt(0.5), DBL_EPSILON, 0.0);
                for (int j = 0; j <= 1000; j++) {
                    double p[2], d;
                    cf_bezier_eval(l->items[i], j / 1000.0, p);
                    d = hypot(p[0] - cx, p[1] - cy);
                    tu_assert_close(d, r, 1e-15, 0.0);
                }
            }
            cf_bezier_list_destroy(l);
        }
}

static void
test_arcs(void **state)
{
    /* arcs of many spans, both directions: the piece count, the end
    ** points, the radius, and that every point lies in the swept angle */
    const double spans[] = { 0.1, PI / 2, PI / 2 + 1e-9, 2.0, PI, 5.0,
                             2 * PI, 7.5, -0.3, -PI, -4 * PI };
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 41);
    for (size_t s = 0; s < sizeof spans / sizeof spans[0]; s++) {
        double a0 = tu_rng_range(&r, -PI, PI), a1 = a0 + spans[s];
        double rad = 2.0, cx = 1.0, cy = -1.0;
        /* pieces of at most 90 degrees */
        size_t want = (size_t)ceil(fabs(spans[s]) / (PI / 2) - 1e-12);
        cf_bezier_list_t *l;
        double p[2], prev_angle = a0;
        assert_int_equal(cf_conic_arc(cx, cy, rad, a0, a1, &l, NULL),
                         CF_STATUS_OK);
        assert_int_equal(l->count, want < 1 ? 1 : want);
        check_chain(l);
        assert_true(l->t0[0] == a0 && l->t1[l->count - 1] == a1);
        cf_bezier_eval(l->items[0], 0.0, p);
        tu_assert_close(p[0], cx + rad * cos(a0), 1e-15, 1.0);
        tu_assert_close(p[1], cy + rad * sin(a0), 1e-15, 1.0);
        cf_bezier_eval(l->items[l->count - 1], 1.0, p);
        tu_assert_close(p[0], cx + rad * cos(a1), 1e-15, 1.0);
        tu_assert_close(p[1], cy + rad * sin(a1), 1e-15, 1.0);
        for (size_t i = 0; i < l->count; i++) {
            double w[3];
            cf_bezier_get_weights(l->items[i], w);
            assert_true(w[1] >= sqrt(0.5) - 1e-15);   /* <= 90 degrees */
            for (int j = 0; j <= 200; j++) {
                double ang, unwrapped;
                cf_bezier_eval(l->items[i], j / 200.0, p);
                tu_assert_close(hypot(p[0] - cx, p[1] - cy), rad, 1e-15,
                                0.0);
                /* the angle moves monotonically in the arc's direction */
                ang = atan2(p[1] - cy, p[0] - cx);
                unwrapped = ang + 2 * PI * round((prev_angle - ang) /
                                                 (2 * PI));
                if (spans[s] > 0)
                    assert_true(unwrapped >= prev_angle - 1e-12);
                else
                    assert_true(unwrapped <= prev_angle + 1e-12);
                prev_angle = unwrapped;
            }
        }
        tu_assert_close(prev_angle, a1, 1e-12, 1.0);
        cf_bezier_list_destroy(l);
    }
}

static void
test_ellipse_implicit(void **state)
{
    /* rotated back to the axes, (x/a)^2 + (y/b)^2 = 1 */
    const double a = 3.0, b = 1.25, rot = 0.4, cx = -2.0, cy = 0.5;
    cf_bezier_list_t *l;
    double p[2];
    (void)state;
    assert_int_equal(cf_conic_ellipse(cx, cy, a, b, rot, 0.3, 0.3 + 2 * PI,
                                      &l, NULL), CF_STATUS_OK);
    assert_int_equal(l->count, 4);
    check_chain(l);
    for (size_t i = 0; i < l->count; i++)
        for (int j = 0; j <= 500; j++) {
            double x, y;
            cf_bezier_eval(l->items[i], j / 500.0, p);
            x = cos(rot) * (p[0] - cx) + sin(rot) * (p[1] - cy);
            y = -sin(rot) * (p[0] - cx) + cos(rot) * (p[1] - cy);
            /* the rotation back adds a few roundings of size |p| ~ 5 */
            assert_true(fabs((x / a) * (x / a) + (y / b) * (y / b) - 1.0) <=
                        1e-14);
        }
    /* the start is the point of eccentric anomaly t0 */
    cf_bezier_eval(l->items[0], 0.0, p);
    tu_assert_close(p[0], cx + cos(rot) * a * cos(0.3) - sin(rot) * b *
                                                              sin(0.3),
                    1e-15, 1.0);
    cf_bezier_list_destroy(l);
}

static void
test_parabola(void **state)
{
    /* focus/directrix: |p - F| = distance to the directrix, and the
    ** vertex form y = x^2 / 4f for axis = pi/2; polynomial quadratic */
    const double f = 0.75, vx = 1.0, vy = 2.0;
    const double axes[] = { PI / 2, 0.0, 2.0, -1.0 };
    (void)state;
    for (int ai = 0; ai < 4; ai++) {
        double ax = axes[ai], F[2], p[2];
        cf_bezier_list_t *l;
        F[0] = vx + f * cos(ax);
        F[1] = vy + f * sin(ax);
        assert_int_equal(cf_conic_parabola(vx, vy, f, ax, -2.0, 3.0, &l,
                                           NULL), CF_STATUS_OK);
        assert_int_equal(l->count, 1);
        assert_false(cf_bezier_is_rational(l->items[0]));
        assert_true(l->t0[0] == -2.0 && l->t1[0] == 3.0);
        for (int j = 0; j <= 500; j++) {
            double dF, dD;
            cf_bezier_eval(l->items[0], j / 500.0, p);
            dF = hypot(p[0] - F[0], p[1] - F[1]);
            /* directrix: the line through V - f e_axis, normal e_axis */
            dD = (p[0] - vx) * cos(ax) + (p[1] - vy) * sin(ax) + f;
            tu_assert_close(dF, dD, 1e-14, 1.0);
            if (ai == 0)
                tu_assert_close(p[1] - vy,
                                (p[0] - vx) * (p[0] - vx) / (4 * f), 1e-14,
                                1.0);
        }
        /* the parameter is the coordinate along the vertex tangent */
        cf_bezier_eval(l->items[0], 0.0, p);
        tu_assert_close(p[0], vx + -2.0 * sin(ax) + 4.0 / (4 * f) * cos(ax),
                        1e-15, 1.0);
        cf_bezier_list_destroy(l);
    }
}

static void
test_hyperbola(void **state)
{
    /* x^2/a^2 - y^2/b^2 = 1 on the branch x > 0 (local frame) */
    const double a = 2.0, b = 0.5, rot = -0.7, cx = 0.5, cy = 1.0;
    const double ranges[][2] = { { -1.0, 1.0 }, { -3.0, 2.5 }, { 0.2, 0.3 },
                                 { -6.0, 6.0 } };
    (void)state;
    for (int ri = 0; ri < 4; ri++) {
        double s0 = ranges[ri][0], s1 = ranges[ri][1], p[2], w[3];
        size_t want = (size_t)ceil((s1 - s0) / 2 - 1e-9);
        cf_bezier_list_t *l;
        assert_int_equal(cf_conic_hyperbola(cx, cy, a, b, rot, s0, s1, &l,
                                            NULL), CF_STATUS_OK);
        assert_int_equal(l->count, want < 1 ? 1 : want);
        check_chain(l);
        for (size_t i = 0; i < l->count; i++) {
            cf_bezier_get_weights(l->items[i], w);
            tu_assert_close(w[1], cosh((l->t1[i] - l->t0[i]) / 2), 1e-15,
                            0.0);
            for (int j = 0; j <= 300; j++) {
                double x, y, scale;
                cf_bezier_eval(l->items[i], j / 300.0, p);
                x = cos(rot) * (p[0] - cx) + sin(rot) * (p[1] - cy);
                y = -sin(rot) * (p[0] - cx) + cos(rot) * (p[1] - cy);
                assert_true(x > 0.0);
                /* the two squares grow like cosh^2 s and cancel: the
                ** residual is relative to them */
                scale = (x / a) * (x / a) + (y / b) * (y / b);
                assert_true(fabs((x / a) * (x / a) - (y / b) * (y / b) -
                                 1.0) <= 1e-14 * scale);
            }
        }
        /* ends at s0 and s1 */
        cf_bezier_eval(l->items[0], 0.0, p);
        tu_assert_close(p[0], cx + cos(rot) * a * cosh(s0) -
                                  sin(rot) * b * sinh(s0), 1e-14, 1.0);
        cf_bezier_list_destroy(l);
    }
}

static void
test_errors(void **state)
{
    cf_bezier_list_t *l = (cf_bezier_list_t *)&l;
    cf_diag_t d;
    (void)state;
    cf_diag_clear(&d);
    assert_int_equal(cf_conic_arc(0, 0, -1, 0, 1, &l, &d),
                     CF_STATUS_INVALID_ARG);
    assert_null(l);
    assert_string_equal(d.msg, "radius is -1; it must be positive");
    assert_int_equal(cf_conic_arc(0, 0, 1, 0.5, 0.5, &l, NULL),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_conic_arc(0, 0, 1, 0, 1e12, &l, NULL),
                     CF_STATUS_DOMAIN);
    cf_diag_clear(&d);
    assert_int_equal(cf_conic_arc(NAN, 0, 1, 0, 1, &l, &d),
                     CF_STATUS_NOT_FINITE);
    assert_non_null(strstr(d.msg, "center x"));
    assert_int_equal(cf_conic_arc(0, 0, 1, 0, INFINITY, &l, NULL),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_conic_arc(0, 0, 1, 0, 1, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_conic_circle(0, 0, 0, &l, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_conic_circle(0, NAN, 1, &l, NULL),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_conic_circle(0, 0, 1, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    /* overflow of the mapped points */
    assert_int_equal(cf_conic_circle(1e308, 0, 1e308, &l, NULL),
                     CF_STATUS_NOT_FINITE);
    assert_null(l);
    cf_diag_clear(&d);
    assert_int_equal(cf_conic_ellipse(0, 0, 1, -2, 0, 0, 1, &l, &d),
                     CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(d.msg, "semi-axis b"));
    assert_int_equal(cf_conic_ellipse(0, 0, 0, 2, 0, 0, 1, &l, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_conic_ellipse(0, 0, 1, 2, NAN, 0, 1, &l, NULL),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_conic_ellipse(0, 0, 1, 2, 0, 1, 1, &l, NULL),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_conic_ellipse(0, 0, 1, 2, 0, 0, 1, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_conic_parabola(0, 0, 0, 0, -1, 1, &l, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_conic_parabola(0, 0, 1, 0, 1, 1, &l, NULL),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_conic_parabola(0, 0, 1, 0, 2, 1, &l, NULL),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_conic_parabola(0, 0, 1, NAN, -1, 1, &l, NULL),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_conic_parabola(0, 0, 1, 0, -1, 1, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_conic_hyperbola(0, 0, 1, 0, 0, -1, 1, &l, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_conic_hyperbola(0, 0, -1, 1, 0, -1, 1, &l, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_conic_hyperbola(0, 0, 1, 1, 0, 1, -1, &l, NULL),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_conic_hyperbola(0, 0, 1, 1, 0, -1, 800, &l, NULL),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_conic_hyperbola(0, 0, 1, 1, 0, -1, NAN, &l, NULL),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_conic_hyperbola(0, 0, 1, 1, 0, -1, 1, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
}

static void
test_out_of_memory(void **state)
{
    (void)state;
    for (int which = 0; which < 5; which++) {
        for (long k = 1;; k++) {
            cf_bezier_list_t *l = NULL;
            cf_status_t st;
            tu_fail_alloc_after(k);
            switch (which) {
            case 0: st = cf_conic_arc(0, 0, 1, 0, 5, &l, NULL); break;
            case 1: st = cf_conic_circle(0, 0, 1, &l, NULL); break;
            case 2: st = cf_conic_ellipse(0, 0, 1, 2, 0, 0, 4, &l, NULL); break;
            case 3: st = cf_conic_parabola(0, 0, 1, 0, -1, 1, &l, NULL); break;
            default: st = cf_conic_hyperbola(0, 0, 1, 1, 0, -3, 3, &l, NULL);
            }
            if (st == CF_STATUS_OK) {
                cf_bezier_list_destroy(l);
                assert_int_equal(tu_alloc_live(), 0);
                tu_fail_alloc_reset();
                assert_true(k > 3);
                break;
            }
            assert_int_equal(st, CF_STATUS_NO_MEMORY);
            assert_null(l);
            assert_int_equal(tu_alloc_live(), 0);
            tu_fail_alloc_reset();
        }
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_circle_radius_constant),
        cmocka_unit_test(test_arcs),
        cmocka_unit_test(test_ellipse_implicit),
        cmocka_unit_test(test_parabola),
        cmocka_unit_test(test_hyperbola),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_out_of_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
