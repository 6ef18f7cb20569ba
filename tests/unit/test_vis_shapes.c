/* Silhouettes and facets (curvefig/visibility.h): the silhouettes of the
** NURBS sphere and torus against their closed-form contours, split into
** visible and hidden parts as the independent ray caster (raycast-ref.c)
** says; the facets' painting order by the depth test. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/surface-make.h"
#include "curvefig/visibility.h"
#include "raycast-ref.h"
#include "testutil.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* ---- silhouettes --------------------------------------------------------- */

/* Distance of x from the exact contour, closed forms (kind 0: sphere of
** radius r about 0, orthographic; 1: the same, perspective; 2: torus
** R, r about the z axis, orthographic). */
typedef struct exact {
    int kind;
    double R, r;
    const cf_view_t *v;
} exact;

/* The contour points of the torus on the meridian at angle f: theta with
** cos(theta) (e_r . d) + sin(theta) d_z = 0. */
static void
torus_contour(const exact *ex, double f, int branch, double *x)
{
    const double *d = ex->v->dir;
    double er = cos(f) * d[0] + sin(f) * d[1];
    double th = atan2(-er, d[2]) + (branch ? M_PI : 0.0);
    double rho = ex->R + ex->r * cos(th);
    x[0] = rho * cos(f);
    x[1] = rho * sin(f);
    x[2] = ex->r * sin(th);
}

/* The exact contour point of the torus nearest x (a search over the
** meridians near x's). */
static void
torus_nearest(const exact *ex, const double *x, double *best_y)
{
    double f0 = atan2(x[1], x[0]), best = HUGE_VAL;
    for (int b = 0; b < 2; b++)
        for (int i = -400; i <= 400; i++) {
            double y[3];
            torus_contour(ex, f0 + 0.3 * i / 400.0, b, y);
            double d = sqrt((x[0] - y[0]) * (x[0] - y[0]) +
                            (x[1] - y[1]) * (x[1] - y[1]) +
                            (x[2] - y[2]) * (x[2] - y[2]));
            if (d < best) {
                best = d;
                memcpy(best_y, y, sizeof y);
            }
        }
}

static double
dist_exact(const exact *ex, const double *x)
{
    if (ex->kind == 0 || ex->kind == 1) {
        /* the circle: |p| = r on the plane p . n = h */
        double n[3], h, len = 0.0;
        if (ex->kind == 0) {
            memcpy(n, ex->v->dir, sizeof n);
            h = 0.0;
        } else {
            double E = 0.0;
            for (int k = 0; k < 3; k++)
                E += ex->v->eye[k] * ex->v->eye[k];
            E = sqrt(E);
            for (int k = 0; k < 3; k++)
                n[k] = ex->v->eye[k] / E;
            h = ex->r * ex->r / E;
        }
        double a = x[0] * n[0] + x[1] * n[1] + x[2] * n[2];
        double q[3], rc = sqrt(ex->r * ex->r - h * h);
        for (int k = 0; k < 3; k++)
            q[k] = x[k] - a * n[k];
        for (int k = 0; k < 3; k++)
            len += q[k] * q[k];
        len = sqrt(len);
        return hypot(a - h, len - rc);
    }
    double y[3];
    torus_nearest(ex, x, y);
    return sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                (x[2] - y[2]) * (x[2] - y[2]));
}

static void
cubic(const double *cp, int dim, double l, double *out)
{
    double a = 1.0 - l;
    for (int k = 0; k < dim; k++)
        out[k] = a * a * a * cp[k] + 3 * a * a * l * cp[dim + k] +
                 3 * a * l * l * cp[2 * dim + k] + l * l * l * cp[3 * dim + k];
}

/* Every piece within max_error <= tol of the exact contour (space, which
** is the image's unit here), and every exact contour point near a piece. */
static void
check_silhouette(const cf_scene_t *sc, const exact *ex, double tol)
{
    cf_silhouette_t *sil = NULL;
    cf_diag_t d;
    double worst = 0.0;
    assert_int_equal(cf_scene_silhouette(sc, 0, &sil, &d), 0);
    assert_true(sil->n > 0);
    assert_true(sil->converged);
    assert_true(sil->max_error <= tol);
    size_t ns = sil->n * 33;
    double *samp = malloc(ns * 3 * sizeof(double));
    assert_non_null(samp);
    for (size_t i = 0; i < sil->n; i++) {
        const cf_silhouette_piece_t *pc = &sil->items[i];
        assert_true(pc->error_image <= sil->max_error);
        assert_true(pc->chain < sil->nchains);
        for (int k = 0; k <= 32; k++) {
            double x[3], im[2], pim[2];
            cubic(pc->space, 3, k / 32.0, x);
            cubic(pc->image, 2, k / 32.0, im);
            memcpy(samp + 3 * (i * 33 + (size_t)k), x, sizeof x);
            worst = fmax(worst, dist_exact(ex, x));
            /* the image cubic is the image of the space cubic within tol */
            assert_int_equal(cf_view_project(ex->v, x, pim, NULL), 0);
            assert_true(hypot(pim[0] - im[0], pim[1] - im[1]) <= tol);
        }
    }
    printf("# silhouette: %zu pieces in %zu chains, stated %.3g, measured "
           "%.3g against the closed form (tol %g)\n", sil->n, sil->nchains,
           sil->max_error, worst, tol);
    assert_true(worst <= tol);
    /* coverage: the exact contour, 720 points, each near a sample */
    for (int i = 0; i < 720; i++) {
        double y[3], f = 2.0 * M_PI * i / 720.0, best = HUGE_VAL;
        if (ex->kind == 2) {
            torus_contour(ex, f, i % 2, y);
        } else {
            /* a point of the circle: centre h n, radius rc, axes u, w */
            double n[3], h = 0.0, E = 0.0, u[3], w[3];
            if (ex->kind == 0) {
                memcpy(n, ex->v->dir, sizeof n);
            } else {
                for (int k = 0; k < 3; k++)
                    E += ex->v->eye[k] * ex->v->eye[k];
                E = sqrt(E);
                for (int k = 0; k < 3; k++)
                    n[k] = ex->v->eye[k] / E;
                h = ex->r * ex->r / E;
            }
            double rc = sqrt(ex->r * ex->r - h * h);
            memcpy(u, ex->v->ex, sizeof u);
            w[0] = n[1] * u[2] - n[2] * u[1];
            w[1] = n[2] * u[0] - n[0] * u[2];
            w[2] = n[0] * u[1] - n[1] * u[0];
            for (int k = 0; k < 3; k++)
                y[k] = h * n[k] + rc * (cos(f) * u[k] + sin(f) * w[k]);
        }
        for (size_t j = 0; j < ns; j++)
            best = fmin(best, sqrt((samp[3 * j] - y[0]) * (samp[3 * j] - y[0]) +
                                   (samp[3 * j + 1] - y[1]) *
                                       (samp[3 * j + 1] - y[1]) +
                                   (samp[3 * j + 2] - y[2]) *
                                       (samp[3 * j + 2] - y[2])));
        /* samples are at most 1/32 of a piece apart */
        if (best > 0.02)
            fail_msg("contour point %d (%g %g %g) is %g from the silhouette",
                     i, y[0], y[1], y[2], best);
    }
    free(samp);
    cf_silhouette_destroy(sil);
}

/*
** The silhouette split into visible and hidden parts
** (cf_scene_silhouette_visibility, at the exact contour): the sphere's is
** all visible; the torus's as the reference says at the exact
** contour point nearest each sample, except within 2 tol of a split.
*/
static void
check_silhouette_visibility(const cf_scene_t *sc, const rc_scene_t *rc,
                            const exact *ex, double tol)
{
    cf_silhouette_t *sil = NULL;
    long hidden = 0, total = 0;
    assert_int_equal(cf_scene_silhouette(sc, 0, &sil, NULL), 0);
    for (size_t i = 0; i < sil->n; i++) {
        const cf_silhouette_piece_t *pc = &sil->items[i];
        cf_bezier_t *c = NULL, *uv = NULL;
        cf_visibility_t *vis = NULL;
        double split[16][2];
        size_t ns = 0, k = 0;
        assert_int_equal(cf_bezier_create(3, 3, pc->space, NULL, &c, NULL), 0);
        assert_int_equal(cf_bezier_create(2, 3, pc->uv, NULL, &uv, NULL), 0);
        assert_int_equal(cf_scene_silhouette_visibility(sc, sil, i, &vis,
                                                        NULL), 0);
        for (size_t j = 0; j + 1 < vis->n && ns < 16; j++)
            cubic(pc->image, 2, vis->items[j].t1, split[ns++]);
        for (int s = 0; s <= 40; s++) {
            double t = s / 40.0, x[3], y[3], q[2];
            while (k + 1 < vis->n && t > vis->items[k].t1)
                k++;
            bool ours = !vis->items[k].visible;
            cubic(pc->space, 3, t, x);
            if (ex->kind == 2)
                torus_nearest(ex, x, y);
            else
                memcpy(y, x, sizeof y);
            /* the line of sight touches the surface at y: the reference
            ** starts 10 tol away (it would subdivide along the touching
            ** sheet for long, and where that sheet curves little along the
            ** line, long double rounded to double, as under valgrind,
            ** meets it); a sheet nearer than that is checked by the
            ** lines' tests */
            bool ref = ex->kind == 2 ? rc_hidden(rc, y, 10 * tol, NULL)
                                     : false;
            if (ex->kind == 2 && !rc_long_double())
                ref = ours;   /* no reference: see rc_long_double */
            total++;
            hidden += ours;
            if (ours == ref)
                continue;
            cubic(pc->image, 2, t, q);
            double near = HUGE_VAL;
            for (size_t j = 0; j < ns; j++)
                near = fmin(near, hypot(q[0] - split[j][0], q[1] - split[j][1]));
            if (near > 2.0 * tol)
                fail_msg("silhouette piece %zu at %g (%g %g %g): %s, the "
                         "reference says %s", i, t, x[0], x[1], x[2],
                         ours ? "hidden" : "visible",
                         ref ? "hidden" : "visible");
        }
        cf_visibility_destroy(vis);
        cf_bezier_destroy(c);
        cf_bezier_destroy(uv);
    }
    printf("# silhouette visibility: %ld samples, %ld hidden%s\n", total,
           hidden, rc_long_double() ? "" : " (long double is double here: "
                                           "not compared)");
    if (ex->kind == 2)
        assert_true(hidden > total / 20 && hidden < total);
    cf_silhouette_destroy(sil);
}

/* A scene of the one surface s. */
static cf_scene_t *
scene_of(const cf_view_t *v, const cf_bspline_surface_t *s, double tol)
{
    cf_scene_t *sc = NULL;
    assert_int_equal(cf_scene_create(v, tol, &sc, NULL), 0);
    assert_int_equal(cf_scene_add_bspline(sc, s, NULL, NULL), 0);
    return sc;
}

static void
test_silhouette_sphere(void **state)
{
    (void)state;
    double c[3] = {0, 0, 0};
    cf_bspline_surface_t *s = NULL;
    cf_scene_t *sc = NULL;
    cf_view_t v;
    assert_int_equal(cf_nurbs_sphere(c, 1.0, &s, NULL), 0);
    for (int persp = 0; persp < 2; persp++) {
        double tol = 1e-3;
        if (persp)
            assert_int_equal(cf_view_perspective(&v, 35, 20, 5.0, NULL, NULL),
                             0);
        else
            assert_int_equal(cf_view_orthographic(&v, 35, 20, NULL), 0);
        sc = scene_of(&v, s, tol);
        exact ex = {persp, 0.0, 1.0, &v};
        check_silhouette(sc, &ex, tol);
        check_silhouette_visibility(sc, NULL, &ex, tol);
        cf_scene_destroy(sc);
    }
    cf_bspline_surface_destroy(s);
}

static void
test_silhouette_torus(void **state)
{
    (void)state;
    double c[3] = {0, 0, 0};
    cf_bspline_surface_t *s = NULL;
    cf_scene_t *sc = NULL;
    cf_view_t v;
    assert_int_equal(cf_nurbs_torus(c, 1.0, 0.4, &s, NULL), 0);
    assert_int_equal(cf_view_orthographic(&v, -50, 35, NULL), 0);
    sc = scene_of(&v, s, 1e-3);
    exact ex = {2, 1.0, 0.4, &v};
    check_silhouette(sc, &ex, 1e-3);
    rc_scene_t *rc = rc_create(&v);
    assert_true(rc_add_bspline(rc, s));
    check_silhouette_visibility(sc, rc, &ex, 1e-3);
    rc_destroy(rc);
    cf_scene_destroy(sc);
    cf_bspline_surface_destroy(s);
}

/* ---- facets -------------------------------------------------------------- */

/* A depth growing towards the viewer that is affine on every plane's
** image: d . p (orthographic), D z / (D - z) (perspective). */
static double
affine_depth(const cf_view_t *v, const double *p)
{
    double z, q[2];
    assert_int_equal(cf_view_project(v, p, q, &z), 0);
    if (v->projection == CF_PROJECTION_PERSPECTIVE)
        return v->distance * z / (v->distance - z);
    return z;
}

/*
** The painting order by the depth test: at random image points, the facets
** whose images contain the point, in painting order, must come nearer and
** nearer (a facet never hides one painted after it).
*/
static void
check_order(const cf_scene_t *sc, const cf_view_t *v, double tol,
            bool want_splits)
{
    cf_facets_t *f = NULL;
    double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
    tu_rng r;
    long overlaps = 0;
    assert_int_equal(cf_scene_facets_tol(sc, tol, &f, NULL), 0);
    assert_true(f->n > 100);
    assert_true(f->deviation <= tol);
    if (want_splits)
        assert_true(f->splits > 0);
    double *zc = malloc(f->n * 3 * sizeof(double));
    assert_non_null(zc);
    for (size_t i = 0; i < f->n; i++) {
        const cf_facet_t *x = &f->items[i];
        double gn[3], u[3], w[3], to[3], cen[3] = {0, 0, 0};
        for (int k = 0; k < 3; k++) {
            double q[2];
            assert_int_equal(cf_view_project(v, x->p + 3 * k, q, NULL), 0);
            assert_true(fabs(q[0] - x->image[2 * k]) < 1e-9);
            assert_true(fabs(q[1] - x->image[2 * k + 1]) < 1e-9);
            zc[3 * i + k] = affine_depth(v, x->p + 3 * k);
            lo[0] = fmin(lo[0], q[0]);
            lo[1] = fmin(lo[1], q[1]);
            hi[0] = fmax(hi[0], q[0]);
            hi[1] = fmax(hi[1], q[1]);
            double nl = sqrt(x->normal[3 * k] * x->normal[3 * k] +
                             x->normal[3 * k + 1] * x->normal[3 * k + 1] +
                             x->normal[3 * k + 2] * x->normal[3 * k + 2]);
            assert_true(fabs(nl - 1.0) < 1e-9);
            for (int e = 0; e < 3; e++)
                cen[e] += x->p[3 * k + e] / 3;
        }
        for (int e = 0; e < 3; e++) {
            u[e] = x->p[3 + e] - x->p[e];
            w[e] = x->p[6 + e] - x->p[e];
        }
        gn[0] = u[1] * w[2] - u[2] * w[1];
        gn[1] = u[2] * w[0] - u[0] * w[2];
        gn[2] = u[0] * w[1] - u[1] * w[0];
        assert_int_equal(cf_view_towards_eye(v, cen, to), 0);
        assert_true(x->front == (gn[0] * to[0] + gn[1] * to[1] +
                                 gn[2] * to[2] > 0.0));
    }
    tu_rng_seed(&r, 11);
    for (int s = 0; s < 600; s++) {
        double pt[2] = {tu_rng_range(&r, lo[0], hi[0]),
                        tu_rng_range(&r, lo[1], hi[1])};
        double last = -HUGE_VAL;
        size_t lasti = 0;
        for (size_t i = 0; i < f->n; i++) {
            const double *im = f->items[i].image;
            double d = (im[2] - im[0]) * (im[5] - im[1]) -
                       (im[3] - im[1]) * (im[4] - im[0]);
            if (fabs(d) < 1e-14)
                continue;
            double b = ((pt[0] - im[0]) * (im[5] - im[1]) -
                        (pt[1] - im[1]) * (im[4] - im[0])) / d;
            double c = ((im[2] - im[0]) * (pt[1] - im[1]) -
                        (im[3] - im[1]) * (pt[0] - im[0])) / d;
            if (b < 1e-9 || c < 1e-9 || b + c > 1 - 1e-9)
                continue;
            double z = (1 - b - c) * zc[3 * i] + b * zc[3 * i + 1] +
                       c * zc[3 * i + 2];
            if (last > -HUGE_VAL) {
                overlaps++;
                if (z < last - 1e-7)
                    fail_msg("at (%g %g) facet %zu (depth %.9g) is painted "
                             "after facet %zu that is nearer (%.9g)", pt[0],
                             pt[1], i, z, lasti, last);
            }
            last = z;
            lasti = i;
        }
    }
    printf("# facets: %zu (%zu splits), deviation %.3g, %ld overlaps in "
           "order\n", f->n, f->splits, f->deviation, overlaps);
    assert_true(overlaps > 20);
    free(zc);
    cf_facets_destroy(f);
}

static void
test_facets(void **state)
{
    (void)state;
    double c[3] = {0, 0, 0};
    double Q[12] = {-1.6, -1.6, 0.1, -1.6, 1.6, -0.1, 1.6, -1.6, 0.2,
                    1.6, 1.6, 0.0};
    cf_bspline_surface_t *s = NULL;
    cf_bezier_surface_t *b = NULL;
    cf_scene_t *sc = NULL;
    cf_view_t v;
    assert_int_equal(cf_nurbs_torus(c, 1.0, 0.4, &s, NULL), 0);
    assert_int_equal(cf_bezier_surface_bilinear(3, Q, &b, NULL), 0);
    for (int persp = 0; persp < 2; persp++) {
        if (persp)
            assert_int_equal(cf_view_perspective(&v, 25, 30, 6.0, NULL, NULL),
                             0);
        else
            assert_int_equal(cf_view_orthographic(&v, -40, 25, NULL), 0);
        assert_int_equal(cf_scene_create(&v, 1e-3, &sc, NULL), 0);
        assert_int_equal(cf_scene_add_bspline(sc, s, NULL, NULL), 0);
        /* a plane through the torus: interpenetration, cut by the tree */
        assert_int_equal(cf_scene_add_bezier(sc, b, NULL, NULL), 0);
        check_order(sc, &v, 2e-2, true);
        cf_scene_destroy(sc);
    }
    /* a sheet curled over itself: its profile a loop in x z */
    double prof[4][2] = {{0, 0}, {3, 0}, {-1.5, 2}, {1.2, 1.2}}, P[24];
    cf_bezier_surface_t *cu = NULL;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 2; j++) {
            P[3 * (2 * i + j)] = prof[i][0];
            P[3 * (2 * i + j) + 1] = 2.0 * j + 0.3 * i;
            P[3 * (2 * i + j) + 2] = prof[i][1];
        }
    assert_int_equal(cf_bezier_surface_create(3, 3, 1, P, NULL, &cu, NULL),
                     0);
    assert_int_equal(cf_view_orthographic(&v, -75, 20, NULL), 0);
    assert_int_equal(cf_scene_create(&v, 1e-3, &sc, NULL), 0);
    assert_int_equal(cf_scene_add_bezier(sc, cu, NULL, NULL), 0);
    check_order(sc, &v, 1e-3, false);
    cf_scene_destroy(sc);
    /* two spheres, one through the other, finely cut (about 3 x 10^4
    ** facets): the grid of the ordering with many facets a cell near the
    ** silhouettes, crossing facets where the spheres meet */
    cf_bspline_surface_t *s1 = NULL, *s2 = NULL;
    double c1[3] = {0, 0, 0}, c2[3] = {0.9, 0.3, 0.2};
    assert_int_equal(cf_nurbs_sphere(c1, 1.0, &s1, NULL), 0);
    assert_int_equal(cf_nurbs_sphere(c2, 0.7, &s2, NULL), 0);
    assert_int_equal(cf_view_orthographic(&v, 30, 20, NULL), 0);
    assert_int_equal(cf_scene_create(&v, 1e-3, &sc, NULL), 0);
    assert_int_equal(cf_scene_add_bspline(sc, s1, NULL, NULL), 0);
    assert_int_equal(cf_scene_add_bspline(sc, s2, NULL, NULL), 0);
    check_order(sc, &v, 4e-3, true);
    cf_scene_destroy(sc);
    cf_bspline_surface_destroy(s1);
    cf_bspline_surface_destroy(s2);
    cf_bezier_surface_destroy(cu);
    cf_bezier_surface_destroy(b);
    cf_bspline_surface_destroy(s);
}


int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_silhouette_sphere),
        cmocka_unit_test(test_silhouette_torus),
        cmocka_unit_test(test_facets),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
