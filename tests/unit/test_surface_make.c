/* Constructions of surfaces (curvefig/surface-make.h): the exact NURBS
** sphere, torus, cylinder and cone on their implicit surfaces, surfaces of
** revolution, extrusions, ruled surfaces, and interpolation of a grid,
** checked in long double. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/surface-make.h"
#include "testutil.h"

#define EPS 2.220446049250313e-16
typedef long double ld;

/* S on an n x n grid of its domain plus every knot line: calls f with the
** point, its parameters and the closure. */
typedef void (*visit_fn)(const double *x, double u, double v, void *ud);

static void
visit(const cf_bspline_surface_t *s, int n, visit_fn f, void *ud)
{
    double ua, ub, va, vb, x[3];
    cf_bspline_surface_domain(s, CF_DIR_U, &ua, &ub);
    cf_bspline_surface_domain(s, CF_DIR_V, &va, &vb);
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++) {
            double u = ua + (ub - ua) * i / n, v = va + (vb - va) * j / n;
            assert_int_equal(cf_bspline_surface_eval(s, u, v, x), 0);
            f(x, u, v, ud);
        }
}

typedef struct quad {
    double c[3], r, R, h;
    double worst;
} quad;

static void
on_sphere(const double *x, double u, double v, void *ud)
{
    quad *q = ud;
    ld d = 0.0L;
    (void)u, (void)v;
    for (int k = 0; k < 3; k++)
        d += ((ld)x[k] - q->c[k]) * ((ld)x[k] - q->c[k]);
    q->worst = fmax(q->worst, fabs((double)(sqrtl(d) - q->r)) / q->r);
}

static void
on_torus(const double *x, double u, double v, void *ud)
{
    quad *q = ud;
    ld dx = (ld)x[0] - q->c[0], dy = (ld)x[1] - q->c[1];
    ld dz = (ld)x[2] - q->c[2], rho = sqrtl(dx * dx + dy * dy) - q->R;
    (void)u, (void)v;
    q->worst = fmax(q->worst, fabs((double)(sqrtl(rho * rho + dz * dz) -
                                             q->r)) / q->R);
}

static void
on_cylinder(const double *x, double u, double v, void *ud)
{
    quad *q = ud;
    ld dx = (ld)x[0] - q->c[0], dy = (ld)x[1] - q->c[1];
    (void)u;
    q->worst = fmax(q->worst,
                    fabs((double)(sqrtl(dx * dx + dy * dy) - q->r)) / q->r);
    /* z is linear in v: c_z + v h */
    q->worst = fmax(q->worst,
                    fabs(x[2] - (q->c[2] + v * q->h)) / q->h);
}

static void
on_cone(const double *x, double u, double v, void *ud)
{
    quad *q = ud;
    ld dx = (ld)x[0] - q->c[0], dy = (ld)x[1] - q->c[1];
    ld z = (ld)x[2] - q->c[2];
    (void)u, (void)v;
    q->worst = fmax(q->worst, fabs((double)(sqrtl(dx * dx + dy * dy) -
                                             q->r * (1.0L - z / q->h))) /
                                  q->r);
}

static void
test_quadrics(void **state)
{
    quad q = { { 1.0, -2.0, 0.5 }, 2.5, 4.0, 3.0, 0.0 };
    cf_bspline_surface_t *s = NULL;
    (void)state;
    assert_int_equal(cf_nurbs_sphere(q.c, q.r, &s, NULL), 0);
    visit(s, 40, on_sphere, &q);
    assert_true(q.worst <= 1e-14);
    /* K = 1 / r^2 and |H| = 1 / r away from the poles */
    for (int i = 0; i <= 12; i++)
        for (int j = 1; j < 12; j++) {
            double K, H, n[3], x[3];
            assert_int_equal(cf_bspline_surface_curvature(s, i / 12.0,
                                                          j / 12.0, &K, &H),
                             0);
            tu_assert_close(K, 1.0 / (q.r * q.r), 1e-12, 0.0);
            tu_assert_close(fabs(H), 1.0 / q.r, 1e-12, 0.0);
            /* the normal is radial */
            assert_int_equal(cf_bspline_surface_normal(s, i / 12.0, j / 12.0,
                                                       n), 0);
            assert_int_equal(cf_bspline_surface_eval(s, i / 12.0, j / 12.0,
                                                     x), 0);
            for (int k = 0; k < 3; k++)
                tu_assert_close(fabs(n[k]), fabs(x[k] - q.c[k]) / q.r, 1e-12,
                                1.0);
        }
    /* at the poles (v = 0, 1) S_v vanishes but for rounding: no normal and
    ** no curvature, never the numbers of that noise */
    for (int i = 0; i <= 12; i++)
        for (int j = 0; j <= 12; j += 12) {
            double K, H, n[3];
            assert_int_equal(cf_bspline_surface_curvature(s, i / 12.0,
                                                          j / 12.0, &K, &H),
                             CF_STATUS_DEGENERATE);
            assert_int_equal(cf_bspline_surface_normal(s, i / 12.0, j / 12.0,
                                                       n),
                             CF_STATUS_DEGENERATE);
        }
    cf_bspline_surface_destroy(s);
    /* a small sphere about the origin (about q.c it would round to its
    ** centre): the forms are scaled, so nothing underflows */
    assert_int_equal(cf_nurbs_sphere((const double[3]){ 0.0, 0.0, 0.0 },
                                     1e-100, &s, NULL), 0);
    {
        double K, H;
        assert_int_equal(cf_bspline_surface_curvature(s, 0.3, 0.4, &K, &H),
                         0);
        tu_assert_close(K, 1e200, 1e-12, 0.0);
        tu_assert_close(fabs(H), 1e100, 1e-12, 0.0);
    }
    cf_bspline_surface_destroy(s);
    q.worst = 0.0;
    q.r = 1.25;
    assert_int_equal(cf_nurbs_torus(q.c, q.R, q.r, &s, NULL), 0);
    visit(s, 40, on_torus, &q);
    assert_true(q.worst <= 1e-14);
    cf_bspline_surface_destroy(s);
    q.worst = 0.0;
    assert_int_equal(cf_nurbs_cylinder(q.c, q.r, q.h, &s, NULL), 0);
    visit(s, 40, on_cylinder, &q);
    assert_true(q.worst <= 1e-14);
    cf_bspline_surface_destroy(s);
    q.worst = 0.0;
    assert_int_equal(cf_nurbs_cone(q.c, q.r, q.h, &s, NULL), 0);
    visit(s, 40, on_cone, &q);
    assert_true(q.worst <= 1e-14);
    cf_bspline_surface_destroy(s);
    /* errors */
    assert_int_equal(cf_nurbs_torus(q.c, 1.0, 2.0, &s, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_null(s);
    assert_int_equal(cf_nurbs_sphere(q.c, -1.0, &s, NULL),
                     CF_STATUS_INVALID_ARG);
}

/* A random curve in R^3, clamped on [0, 1]. */
static cf_bspline_t *
random_curve(tu_rng *r, int p, size_t n, bool rational)
{
    double P[30], W[10];
    cf_bspline_t *c = NULL;
    for (size_t i = 0; i < 3 * n; i++)
        P[i] = tu_rng_range(r, -3.0, 3.0);
    for (size_t i = 0; i < n; i++)
        W[i] = tu_rng_range(r, 0.5, 2.0);
    assert_int_equal(cf_bspline_create_clamped(3, p, P, n,
                                               rational ? W : NULL, &c, NULL),
                     0);
    return c;
}

/* Every point of a revolution keeps the axial coordinate and the distance
** to the axis of the curve point it comes from (u round the axis). */
static void
test_revolve(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 51);
    for (int t = 0; t < 20; t++) {
        double O[3] = { 0.5, -1.0, 2.0 }, A[3] = { 1.0, 2.0, -0.5 };
        double a0 = tu_rng_range(&r, -3, 3), a1 = a0 + tu_rng_range(&r, 0.2,
                                                                     6.28);
        cf_bspline_t *c = random_curve(&r, 1 + t % 3, 6, t % 2);
        cf_bspline_surface_t *s = NULL;
        ld al = sqrtl(1.0L + 4.0L + 0.25L);
        assert_int_equal(cf_surface_revolve(c, O, A, a0, a1, &s, NULL), 0);
        for (int i = 0; i <= 10; i++)
            for (int j = 0; j <= 10; j++) {
                double x[3], y[3], x0[3];
                ld ax = 0, ay = 0, dx = 0, dy = 0, ang;
                assert_int_equal(cf_bspline_surface_eval(s, i / 10.0,
                                                         j / 10.0, x), 0);
                assert_int_equal(cf_bspline_eval(c, j / 10.0, y), 0);
                assert_int_equal(cf_bspline_surface_eval(s, 0.0, j / 10.0,
                                                         x0), 0);
                for (int k = 0; k < 3; k++) {
                    ax += ((ld)x[k] - O[k]) * A[k] / al;
                    ay += ((ld)y[k] - O[k]) * A[k] / al;
                }
                for (int k = 0; k < 3; k++) {
                    ld px = (ld)x[k] - O[k] - ax * A[k] / al;
                    ld py = (ld)y[k] - O[k] - ay * A[k] / al;
                    dx += px * px;
                    dy += py * py;
                }
                tu_assert_close((double)ax, (double)ay, 1e-13, 3.0);
                tu_assert_close((double)sqrtl(dx), (double)sqrtl(dy), 1e-13,
                                3.0);
                (void)ang;
            }
        /* u = 0 is the curve turned by a0: at a0 = 0 it is the curve */
        cf_bspline_surface_destroy(s);
        assert_int_equal(cf_surface_revolve(c, O, A, 0.0, 1.0, &s, NULL), 0);
        for (int j = 0; j <= 10; j++) {
            double x[3], y[3];
            assert_int_equal(cf_bspline_surface_eval(s, 0.0, j / 10.0, x), 0);
            assert_int_equal(cf_bspline_eval(c, j / 10.0, y), 0);
            assert_true(tu_max_diff(x, y, 3) <= 1e-14 * 8);
        }
        cf_bspline_surface_destroy(s);
        cf_bspline_destroy(c);
    }
}

static void
test_extrude_ruled(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 52);
    for (int t = 0; t < 20; t++) {
        cf_bspline_t *c1 = random_curve(&r, 1 + t % 3, 5, t % 2);
        cf_bspline_t *c2 = random_curve(&r, 1 + (t / 3) % 4, 7, t % 4 == 1);
        cf_bspline_surface_t *e = NULL, *s = NULL;
        double d[3] = { 0.3, -1.0, 2.0 };
        assert_int_equal(cf_surface_extrude(c1, d, &e, NULL), 0);
        assert_int_equal(cf_surface_ruled(c1, c2, &s, NULL), 0);
        for (int i = 0; i <= 10; i++)
            for (int j = 0; j <= 4; j++) {
                double u = i / 10.0, v = j / 4.0, x[3], a[3], b[3], y[3];
                assert_int_equal(cf_bspline_surface_eval(e, u, v, x), 0);
                assert_int_equal(cf_bspline_eval(c1, u, a), 0);
                for (int k = 0; k < 3; k++)
                    tu_assert_close(x[k], a[k] + v * d[k], 16 * EPS, 4.0);
                /* ruled: row v = 0 is c1, v = 1 is c2 (same domains
                ** [0, 1]), and each v-line is the straight segment */
                assert_int_equal(cf_bspline_eval(c2, u, b), 0);
                assert_int_equal(cf_bspline_surface_eval(s, u, v, y), 0);
                if (j == 0)
                    assert_true(tu_max_diff(y, a, 3) <= 1e-13 * 4);
                if (j == 4)
                    assert_true(tu_max_diff(y, b, 3) <= 1e-13 * 4);
                {
                    /* y - a parallel to b - a */
                    ld cx = ((ld)y[1] - a[1]) * ((ld)b[2] - a[2]) -
                            ((ld)y[2] - a[2]) * ((ld)b[1] - a[1]);
                    ld cy = ((ld)y[2] - a[2]) * ((ld)b[0] - a[0]) -
                            ((ld)y[0] - a[0]) * ((ld)b[2] - a[2]);
                    assert_true(fabsl(cx) + fabsl(cy) <= 1e-12L * 36);
                }
            }
        cf_bspline_surface_destroy(e);
        cf_bspline_surface_destroy(s);
        cf_bspline_destroy(c1);
        cf_bspline_destroy(c2);
    }
}

/* The Coons patch of the four boundaries of a surface: the boundaries
** again, and inside (1 - v) c0 + v c1 + (1 - u) d0 + u d1 - bilinear
** corners, in long double from the curves. */
static void
test_coons(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 54);
    for (int t = 0; t < 12; t++) {
        cf_bspline_t *c[4] = { NULL, NULL, NULL, NULL };
        cf_bspline_surface_t *s = NULL, *src = NULL;
        double P[5 * 4 * 3], U[9], V[8];
        int p = 1 + t % 3, q = 1 + (t / 3) % 3;
        cf_diag_t d;
        for (int i = 0; i < 5 * 4 * 3; i++)
            P[i] = tu_rng_range(&r, -2.0, 2.0);
        assert_int_equal(cf_knots_clamped_uniform(p, 5, 0.0, 1.0, U, NULL),
                         0);
        assert_int_equal(cf_knots_clamped_uniform(q, 4, 0.0, 1.0, V, NULL),
                         0);
        assert_int_equal(cf_bspline_surface_create(3, p, q, U, 5 + (size_t)p
                                                   + 1, V, 4 + (size_t)q + 1,
                                                   P, 5, 4, NULL, &src, NULL),
                         0);
        assert_int_equal(cf_bspline_surface_iso(src, CF_DIR_V, 0.0, &c[0],
                                                NULL), 0);
        assert_int_equal(cf_bspline_surface_iso(src, CF_DIR_V, 1.0, &c[1],
                                                NULL), 0);
        assert_int_equal(cf_bspline_surface_iso(src, CF_DIR_U, 0.0, &c[2],
                                                NULL), 0);
        assert_int_equal(cf_bspline_surface_iso(src, CF_DIR_U, 1.0, &c[3],
                                                NULL), 0);
        assert_int_equal(cf_surface_coons(c[0], c[1], c[2], c[3], &s, &d), 0);
        for (int i = 0; i <= 8; i++)
            for (int j = 0; j <= 8; j++) {
                double u = i / 8.0, v = j / 8.0, x[3], a[3], b[3], e[3],
                       f[3], k[4][3];
                assert_int_equal(cf_bspline_surface_eval(s, u, v, x), 0);
                assert_int_equal(cf_bspline_eval(c[0], u, a), 0);
                assert_int_equal(cf_bspline_eval(c[1], u, b), 0);
                assert_int_equal(cf_bspline_eval(c[2], v, e), 0);
                assert_int_equal(cf_bspline_eval(c[3], v, f), 0);
                assert_int_equal(cf_bspline_eval(c[0], 0.0, k[0]), 0);
                assert_int_equal(cf_bspline_eval(c[0], 1.0, k[1]), 0);
                assert_int_equal(cf_bspline_eval(c[1], 0.0, k[2]), 0);
                assert_int_equal(cf_bspline_eval(c[1], 1.0, k[3]), 0);
                for (int m = 0; m < 3; m++) {
                    ld want = (1 - (ld)v) * a[m] + (ld)v * b[m] +
                              (1 - (ld)u) * e[m] + (ld)u * f[m] -
                              ((1 - (ld)u) * (1 - (ld)v) * k[0][m] +
                               (ld)u * (1 - (ld)v) * k[1][m] +
                               (1 - (ld)u) * (ld)v * k[2][m] +
                               (ld)u * (ld)v * k[3][m]);
                    tu_assert_close(x[m], (double)want, 1e-13, 2.0);
                }
            }
        cf_bspline_surface_destroy(s);
        /* corners that do not meet are named */
        cf_bspline_destroy(c[3]);
        c[3] = NULL;
        assert_int_equal(cf_bspline_surface_iso(src, CF_DIR_U, 0.5, &c[3],
                                                NULL), 0);
        assert_int_equal(cf_surface_coons(c[0], c[1], c[2], c[3], &s, &d),
                         CF_STATUS_DEGENERATE);
        assert_non_null(strstr(d.msg, "c0(1)"));
        for (int i = 0; i < 4; i++)
            cf_bspline_destroy(c[i]);
        cf_bspline_surface_destroy(src);
    }
}

/* Interpolation passes through its points; least squares with as many
** control points as data (global method) is the interpolant. */
static void
test_interpolate(void **state)
{
    static const cf_interp_method_t methods[] = {
        CF_INTERP_NATURAL, CF_INTERP_NOT_A_KNOT, CF_INTERP_GLOBAL,
        CF_INTERP_CATMULL_ROM
    };
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 53);
    for (int t = 0; t < 16; t++) {
        size_t nu = 5 + (size_t)t % 3, nv = 4 + (size_t)t % 4;
        double Q[8 * 8 * 3], prm[16], x[3], res;
        cf_interp_options_t o;
        cf_bspline_surface_t *s = NULL, *a = NULL;
        cf_diag_t d;
        for (size_t i = 0; i < nu; i++)
            for (size_t j = 0; j < nv; j++) {
                double *q = Q + (i * nv + j) * 3;
                q[0] = (double)i + tu_rng_range(&r, -0.2, 0.2);
                q[1] = (double)j + tu_rng_range(&r, -0.2, 0.2);
                q[2] = sin(q[0]) * cos(q[1]);
            }
        cf_interp_options_init(&o);
        o.method = methods[t % 4];
        o.degree = o.method == CF_INTERP_GLOBAL ? 2 + t % 2 : 0;
        o.param = t % 2 ? CF_PARAM_CENTRIPETAL : CF_PARAM_CHORD;
        assert_int_equal(cf_interpolate_surface(3, Q, nu, nv, &o, &s, prm,
                                                &d), 0);
        for (size_t i = 0; i < nu; i++)
            for (size_t j = 0; j < nv; j++) {
                assert_int_equal(cf_bspline_surface_eval(s, prm[i],
                                                         prm[nu + j], x), 0);
                assert_true(tu_max_diff(x, Q + (i * nv + j) * 3, 3) <=
                            1e-12 * 8);
            }
        if (o.method == CF_INTERP_GLOBAL) {
            assert_int_equal(cf_approximate_surface(3, Q, nu, nv, nu, nv, &o,
                                                    true, &a, &res, &d), 0);
            assert_true(res <= 1e-10);
            cf_bspline_surface_destroy(a);
            assert_int_equal(cf_approximate_surface(3, Q, nu, nv, 4, 3, &o,
                                                    true, &a, &res, &d), 0);
            assert_true(res > 0.0 && res < 2.0);
            cf_bspline_surface_destroy(a);
        }
        cf_bspline_surface_destroy(s);
        /* a NaN is named by row and column */
        Q[(2 * nv + 1) * 3 + 2] = NAN;
        assert_int_equal(cf_interpolate_surface(3, Q, nu, nv, &o, &s, NULL,
                                                &d), CF_STATUS_NOT_FINITE);
        assert_non_null(strstr(d.msg, "P[2][1]"));
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_quadrics),
        cmocka_unit_test(test_revolve),
        cmocka_unit_test(test_extrude_ruled),
        cmocka_unit_test(test_coons),
        cmocka_unit_test(test_interpolate),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
