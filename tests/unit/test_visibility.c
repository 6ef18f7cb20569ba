/* Views and hidden lines (curvefig/visibility.h), against an independent
** ray caster (raycast-ref.c: long double Newton on the line of sight):
** every sample of a line must be hidden or visible as the reference says,
** except within the tolerance of a split point. */
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

/* Samples of each line checked against the reference. */
#define SAMPLES 200

typedef struct world {
    cf_view_t view;
    cf_scene_t *sc;
    rc_scene_t *rc;
    double tol;
    long checked, hidden, visible, near_split;
} world;

static void
world_init(world *w, const cf_view_t *view, double tol)
{
    memset(w, 0, sizeof *w);
    w->view = *view;
    w->tol = tol;
    assert_int_equal(cf_scene_create(view, tol, &w->sc, NULL), 0);
    w->rc = rc_create(view);
    assert_non_null(w->rc);
}

static void
world_fini(world *w)
{
    cf_scene_destroy(w->sc);
    rc_destroy(w->rc);
}

static size_t
add_bspline(world *w, const cf_bspline_surface_t *s)
{
    size_t id;
    cf_diag_t d;
    assert_int_equal(cf_scene_add_bspline(w->sc, s, &id, &d), 0);
    assert_true(rc_add_bspline(w->rc, s));
    return id;
}

static size_t
add_bezier(world *w, const cf_bezier_surface_t *s)
{
    size_t id;
    assert_int_equal(cf_scene_add_bezier(w->sc, s, &id, NULL), 0);
    assert_true(rc_add_bezier(w->rc, s));
    return id;
}

/* Image of p. */
static void
image(const world *w, const double *p, double *q)
{
    assert_int_equal(cf_view_project(&w->view, p, q, NULL), 0);
}

/*
** The visibility of c (on may be NULL) against the reference at SAMPLES
** parameters.  A mismatch is allowed only where the sample's image is
** within 2 tol of the image of a split point.
*/
static void
check_line(world *w, const cf_bspline_t *c, const cf_vis_on_t *on,
           const char *what)
{
    cf_visibility_t *vis = NULL;
    cf_diag_t d;
    double a, b, split[64][2];
    size_t ns = 0;
    assert_int_equal(cf_scene_bspline_visibility(w->sc, c, on, &vis, &d), 0);
    cf_bspline_domain(c, &a, &b);
    assert_true(vis->n >= 1);
    assert_true(fabs(vis->items[0].t0 - a) <= 1e-12 * (fabs(a) + 1));
    assert_true(fabs(vis->items[vis->n - 1].t1 - b) <= 1e-12 * (fabs(b) + 1));
    for (size_t i = 0; i + 1 < vis->n; i++) {
        double p[3];
        assert_true(vis->items[i].t1 == vis->items[i + 1].t0);
        assert_true(vis->items[i].visible != vis->items[i + 1].visible);
        assert_int_equal(cf_bspline_eval(c, vis->items[i].t1, p), 0);
        assert_true(ns < 64);
        image(w, p, split[ns++]);
    }
    size_t k = 0;
    for (int i = 0; i <= SAMPLES; i++) {
        double t = a + (b - a) * i / SAMPLES, p[3], q[2];
        while (k + 1 < vis->n && t > vis->items[k].t1)
            k++;
        bool ours = !vis->items[k].visible;
        assert_int_equal(cf_bspline_eval(c, t, p), 0);
        /* without a wider long double (valgrind) there is no reference:
        ** the library still runs, under memcheck */
        bool ref = rc_long_double() ? rc_hidden(w->rc, p, w->tol, NULL)
                                    : ours;
        w->checked++;
        if (ref)
            w->hidden++;
        else
            w->visible++;
        if (ours == ref)
            continue;
        image(w, p, q);
        double near = HUGE_VAL;
        for (size_t j = 0; j < ns; j++)
            near = fmin(near, hypot(q[0] - split[j][0], q[1] - split[j][1]));
        if (near > 2.0 * w->tol)
            fail_msg("%s: t = %.9g (%g %g %g) is %s, the reference says %s; "
                     "nearest split %g away (tol %g)", what, t, p[0], p[1],
                     p[2], ours ? "hidden" : "visible",
                     ref ? "hidden" : "visible", near, w->tol);
        w->near_split++;
    }
    cf_visibility_destroy(vis);
}

/* The iso-line of s at value in dir, with its (u, v) line. */
static void
check_iso(world *w, const cf_bspline_surface_t *s, size_t id, cf_dir_t dir,
          double value, bool use_on, const char *what)
{
    cf_bspline_t *c = NULL, *uv = NULL;
    double a, b, kn[4], pts[4];
    cf_vis_on_t on;
    assert_int_equal(cf_bspline_surface_iso(s, dir, value, &c, NULL), 0);
    cf_bspline_domain(c, &a, &b);
    kn[0] = kn[1] = a;
    kn[2] = kn[3] = b;
    if (dir == CF_DIR_U) {
        pts[0] = pts[2] = value;
        pts[1] = a;
        pts[3] = b;
    } else {
        pts[1] = pts[3] = value;
        pts[0] = a;
        pts[2] = b;
    }
    assert_int_equal(cf_bspline_create(2, 1, kn, 4, pts, 2, NULL, &uv, NULL),
                     0);
    memset(&on, 0, sizeof on);
    on.surface = id;
    on.uv_bspline = uv;
    check_line(w, c, use_on ? &on : NULL, what);
    cf_bspline_destroy(c);
    cf_bspline_destroy(uv);
}

/* Every iso-line of a grid nu x nv of the surface's domain. */
static void
check_isos(world *w, const cf_bspline_surface_t *s, size_t id, int nu,
           int nv)
{
    double ua, ub, va, vb;
    char what[64];
    cf_bspline_surface_domain(s, CF_DIR_U, &ua, &ub);
    cf_bspline_surface_domain(s, CF_DIR_V, &va, &vb);
    for (int i = 0; i <= nu; i++) {
        double u = ua + (ub - ua) * (i + 0.37) / (nu + 1);
        snprintf(what, sizeof what, "iso u = %g", u);
        check_iso(w, s, id, CF_DIR_U, u, i % 2 == 0, what);
    }
    for (int j = 0; j <= nv; j++) {
        double v = va + (vb - va) * (j + 0.61) / (nv + 1);
        snprintf(what, sizeof what, "iso v = %g", v);
        check_iso(w, s, id, CF_DIR_V, v, j % 2 == 1, what);
    }
}

/* A straight segment as a B-spline of degree 1. */
static cf_bspline_t *
segment(const double *p0, const double *p1)
{
    double kn[4] = {0, 0, 1, 1}, pts[6];
    cf_bspline_t *c = NULL;
    memcpy(pts, p0, 3 * sizeof(double));
    memcpy(pts + 3, p1, 3 * sizeof(double));
    assert_int_equal(cf_bspline_create(3, 1, kn, 4, pts, 2, NULL, &c, NULL),
                     0);
    return c;
}

static void
report(const world *w, const char *what)
{
    printf("# %s: %ld samples, %ld hidden, %ld visible, %ld differ within "
           "2 tol of a split%s\n", what, w->checked, w->hidden, w->visible,
           w->near_split, rc_long_double() ? "" : " (no reference: long "
                                                  "double is double here)");
    /* the scene must show both, or the test shows nothing */
    assert_true(w->hidden > w->checked / 20);
    assert_true(w->visible > w->checked / 20);
}

static void
test_sphere(void **state)
{
    (void)state;
    double c[3] = {0, 0, 0};
    cf_bspline_surface_t *s = NULL;
    cf_view_t v;
    world w;
    assert_int_equal(cf_view_orthographic(&v, 30, 25, NULL), 0);
    world_init(&w, &v, 1e-3);
    assert_int_equal(cf_nurbs_sphere(c, 1.0, &s, NULL), 0);
    size_t id = add_bspline(&w, s);
    check_isos(&w, s, id, 3, 3);
    /* a line through the sphere, not on it */
    double p0[3] = {-2, 0.3, 0.2}, p1[3] = {2, -0.2, 0.1};
    cf_bspline_t *l = segment(p0, p1);
    check_line(&w, l, NULL, "segment through the sphere");
    cf_bspline_destroy(l);
    report(&w, "sphere");
    cf_bspline_surface_destroy(s);
    world_fini(&w);
}

static void
test_torus(void **state)
{
    (void)state;
    double c[3] = {0, 0, 0};
    cf_bspline_surface_t *s = NULL;
    cf_view_t v;
    world w;
    assert_int_equal(cf_view_orthographic(&v, -50, 35, NULL), 0);
    world_init(&w, &v, 1e-3);
    assert_int_equal(cf_nurbs_torus(c, 1.0, 0.4, &s, NULL), 0);
    size_t id = add_bspline(&w, s);
    check_isos(&w, s, id, 5, 3);
    report(&w, "torus");
    cf_bspline_surface_destroy(s);
    world_fini(&w);
}

static void
test_torus_perspective(void **state)
{
    (void)state;
    double c[3] = {0, 0, 0}, T[3] = {0.1, 0, 0};
    cf_bspline_surface_t *s = NULL;
    cf_view_t v;
    world w;
    assert_int_equal(cf_view_perspective(&v, 20, 30, 4.0, T, NULL), 0);
    world_init(&w, &v, 1e-3);
    assert_int_equal(cf_nurbs_torus(c, 1.0, 0.4, &s, NULL), 0);
    size_t id = add_bspline(&w, s);
    check_isos(&w, s, id, 3, 2);
    report(&w, "torus in perspective");
    cf_bspline_surface_destroy(s);
    world_fini(&w);
}

/* z = x^2 - y^2 on [-1, 1]^2 as a Bézier patch of degrees (2, 2), seen
** from low: the saddle hides part of itself. */
static cf_status_t
make_saddle(cf_bezier_surface_t **s)
{
    double P[27];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double *p = P + 3 * (3 * i + j);
            p[0] = -1.0 + i;
            p[1] = -1.0 + j;
            /* x^2 on control points: 1, -1, 1 (the middle of the
            ** quadratic's polygon); likewise y^2 */
            double x2 = i == 1 ? -1.0 : 1.0, y2 = j == 1 ? -1.0 : 1.0;
            p[2] = x2 - y2;
        }
    return cf_bezier_surface_create(3, 2, 2, P, NULL, s, NULL);
}

static cf_bezier_surface_t *
saddle(void)
{
    cf_bezier_surface_t *s = NULL;
    assert_int_equal(make_saddle(&s), 0);
    return s;
}

static void
test_saddle(void **state)
{
    (void)state;
    cf_bezier_surface_t *b = saddle();
    cf_bspline_surface_t *s = NULL;
    cf_view_t v;
    world w;
    double x[3];
    /* the patch is the saddle: S(u, v) = (x, y, x^2 - y^2) */
    assert_int_equal(cf_bezier_surface_eval(b, 0.8, 0.3, x), 0);
    assert_true(fabs(x[2] - (x[0] * x[0] - x[1] * x[1])) < 1e-14);
    assert_int_equal(cf_bspline_surface_from_bezier(b, &s, NULL), 0);
    assert_int_equal(cf_view_orthographic(&v, 10, 12, NULL), 0);
    world_init(&w, &v, 1e-3);
    size_t id = add_bspline(&w, s);
    check_isos(&w, s, id, 4, 4);
    report(&w, "saddle");
    cf_bezier_surface_destroy(b);
    cf_bspline_surface_destroy(s);
    world_fini(&w);
}

/* A flat square and a bent patch that passes through it: lines on both
** are hidden by the other, and cross where the patches interpenetrate. */
static void
test_two_patches(void **state)
{
    (void)state;
    double Q[12] = {-1, -1, 0, -1, 1, 0, 1, -1, 0, 1, 1, 0};
    double P[27];
    cf_bezier_surface_t *a = NULL, *b = NULL;
    cf_bspline_surface_t *sa = NULL, *sb = NULL;
    cf_view_t v;
    world w;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double *p = P + 3 * (3 * i + j);
            p[0] = -0.6 + 0.6 * i;
            p[1] = -1.4 + 1.4 * j;
            p[2] = (i == 1 ? 1.2 : -0.5) + 0.3 * (j - 1);
        }
    assert_int_equal(cf_bezier_surface_bilinear(3, Q, &a, NULL), 0);
    assert_int_equal(cf_bezier_surface_create(3, 2, 2, P, NULL, &b, NULL), 0);
    assert_int_equal(cf_bspline_surface_from_bezier(a, &sa, NULL), 0);
    assert_int_equal(cf_bspline_surface_from_bezier(b, &sb, NULL), 0);
    assert_int_equal(cf_view_orthographic(&v, 60, 30, NULL), 0);
    world_init(&w, &v, 1e-3);
    size_t ia = add_bezier(&w, a), ib = add_bezier(&w, b);
    check_isos(&w, sa, ia, 3, 3);
    check_isos(&w, sb, ib, 3, 3);
    report(&w, "two patches");
    cf_bezier_surface_destroy(a);
    cf_bezier_surface_destroy(b);
    cf_bspline_surface_destroy(sa);
    cf_bspline_surface_destroy(sb);
    world_fini(&w);
}

/* A sheet curled over itself (its profile a loop in x z), seen from the
** side of the loop: the front of the curl hides its back. */
static void
test_curl(void **state)
{
    (void)state;
    double prof[4][2] = {{0, 0}, {3, 0}, {-1.5, 2}, {1.2, 1.2}};
    double P[24];
    cf_bezier_surface_t *b = NULL;
    cf_bspline_surface_t *s = NULL;
    cf_view_t v;
    world w;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 2; j++) {
            double *p = P + 3 * (2 * i + j);
            p[0] = prof[i][0];
            p[1] = 2.0 * j + 0.3 * i;
            p[2] = prof[i][1];
        }
    assert_int_equal(cf_bezier_surface_create(3, 3, 1, P, NULL, &b, NULL), 0);
    assert_int_equal(cf_bspline_surface_from_bezier(b, &s, NULL), 0);
    assert_int_equal(cf_view_orthographic(&v, -75, 20, NULL), 0);
    world_init(&w, &v, 1e-3);
    size_t id = add_bezier(&w, b);
    check_isos(&w, s, id, 5, 3);
    report(&w, "curl");
    cf_bezier_surface_destroy(b);
    cf_bspline_surface_destroy(s);
    world_fini(&w);
}

/* A triangular patch in front of lines. */
static void
test_triangle(void **state)
{
    (void)state;
    /* quadratic: corners and edge midpoints lifted */
    double P[18] = {1, 0, 0.5,  0.5, 0.5, 1.2, 0.5, 0, 0.8,
                    0, 1, 0.2,  0, 0.5, 0.9,   0, 0, 0.3};
    cf_bezier_triangle_t *t = NULL;
    cf_view_t v;
    world w;
    size_t id;
    assert_int_equal(cf_bezier_triangle_create(3, 2, P, NULL, &t, NULL), 0);
    assert_int_equal(cf_view_orthographic(&v, 0, 90, NULL), 0);
    world_init(&w, &v, 1e-3);
    assert_int_equal(cf_scene_add_triangle(w.sc, t, &id, NULL), 0);
    assert_true(rc_add_triangle(w.rc, t));
    for (int k = 0; k < 8; k++) {
        double p0[3] = {-0.3, -0.2 + 0.17 * k, 0.0};
        double p1[3] = {1.3, 1.1 - 0.15 * k, 1.5 - 0.2 * k};
        cf_bspline_t *l = segment(p0, p1);
        check_line(&w, l, NULL, "segment under the triangle");
        cf_bspline_destroy(l);
    }
    report(&w, "triangle");
    cf_bezier_triangle_destroy(t);
    world_fini(&w);
}

/* Points: visible or hidden as the reference says, away from the
** silhouette. */
static void
test_points(void **state)
{
    (void)state;
    double c[3] = {0, 0, 0};
    cf_bspline_surface_t *s = NULL;
    cf_view_t v;
    world w;
    tu_rng r;
    int hid = 0;
    tu_rng_seed(&r, 7);
    assert_int_equal(cf_view_orthographic(&v, 140, -20, NULL), 0);
    world_init(&w, &v, 1e-4);
    assert_int_equal(cf_nurbs_torus(c, 1.0, 0.35, &s, NULL), 0);
    add_bspline(&w, s);
    for (int i = 0; i < 400; i++) {
        double p[3], dist;
        bool vis;
        for (int k = 0; k < 3; k++)
            p[k] = tu_rng_range(&r, -1.5, 1.5);
        assert_int_equal(cf_scene_point_visible(w.sc, p, NULL, &vis, NULL,
                                                NULL), 0);
        bool ref = rc_long_double() ? rc_hidden(w.rc, p, w.tol, &dist)
                                    : !vis;
        if (vis == ref)
            fail_msg("point (%g %g %g): %s, the reference says %s",
                     p[0], p[1], p[2], vis ? "visible" : "hidden",
                     ref ? "hidden" : "visible");
        hid += !vis;
    }
    assert_true(hid > 40 && hid < 360);
    cf_bspline_surface_destroy(s);
    world_fini(&w);
}

/* ---- views, projections, errors ----------------------------------------- */

/* The axes are those of figure{view = ...} (render/lua/lfigure.c), the
** image of a curve is the curve of the images (same degree; rational in
** perspective), points behind the eye are refused. */
static void
test_projection(void **state)
{
    (void)state;
    cf_view_t v;
    double a = 0.7, e = 0.3;   /* radians of 40.107 and 17.188 degrees */
    assert_int_equal(cf_view_orthographic(&v, a * 180 / M_PI,
                                          e * 180 / M_PI, NULL), 0);
    assert_true(fabs(v.ex[0] + sin(a)) < 1e-15 && fabs(v.ex[1] - cos(a)) < 1e-15);
    assert_true(fabs(v.ey[0] + cos(a) * sin(e)) < 1e-15 &&
                fabs(v.ey[1] + sin(a) * sin(e)) < 1e-15 &&
                fabs(v.ey[2] - cos(e)) < 1e-15);
    double P[12] = {0, 0, 0, 1, 2, 0.5, 2, -1, 1, 3, 0, -0.5};
    double W[4] = {1, 2, 0.5, 1};
    for (int persp = 0; persp < 2; persp++)
        for (int rat = 0; rat < 2; rat++) {
            cf_bezier_t *c = NULL, *img = NULL;
            double T[3] = {1, 0, 0};
            if (persp)
                assert_int_equal(cf_view_perspective(&v, 30, 20, 8.0, T,
                                                     NULL), 0);
            else
                assert_int_equal(cf_view_orthographic(&v, 30, 20, NULL), 0);
            assert_int_equal(cf_bezier_create(3, 3, P, rat ? W : NULL, &c,
                                              NULL), 0);
            assert_int_equal(cf_view_project_bezier(&v, c, &img, NULL), 0);
            assert_int_equal(cf_bezier_degree(img), 3);
            assert_int_equal(cf_bezier_dim(img), 2);
            assert_true(cf_bezier_is_rational(img) == (persp || rat));
            for (int i = 0; i <= 20; i++) {
                double x[3], q[2], r[2];
                assert_int_equal(cf_bezier_eval(c, i / 20.0, x), 0);
                assert_int_equal(cf_view_project(&v, x, q, NULL), 0);
                assert_int_equal(cf_bezier_eval(img, i / 20.0, r), 0);
                assert_true(hypot(q[0] - r[0], q[1] - r[1]) < 1e-13);
            }
            cf_bezier_destroy(c);
            cf_bezier_destroy(img);
        }
    /* the target is drawn where the orthographic view draws it */
    cf_view_t o;
    double T[3] = {0.3, -0.2, 0.5}, q1[2], q2[2], z;
    assert_int_equal(cf_view_orthographic(&o, 30, 20, NULL), 0);
    assert_int_equal(cf_view_perspective(&v, 30, 20, 3.0, T, NULL), 0);
    assert_int_equal(cf_view_project(&o, T, q1, NULL), 0);
    assert_int_equal(cf_view_project(&v, T, q2, &z), 0);
    assert_true(hypot(q1[0] - q2[0], q1[1] - q2[1]) < 1e-15 && z == 0.0);
    assert_int_equal(cf_view_project(&v, v.eye, q1, NULL), CF_STATUS_DOMAIN);
}

static void
expect(cf_status_t got, const cf_diag_t *d, cf_status_t want,
       const char *words)
{
    assert_int_equal(got, want);
    assert_int_equal(d->status, want);
    if (strstr(d->msg, words) == NULL)
        fail_msg("message \"%s\" does not say \"%s\"", d->msg, words);
}

static void
test_errors(void **state)
{
    (void)state;
    cf_view_t v;
    cf_diag_t d;
    cf_scene_t *sc = NULL;
    expect(cf_view_orthographic(&v, NAN, 10, &d), &d, CF_STATUS_NOT_FINITE,
           "azimuth");
    expect(cf_view_perspective(&v, 10, 10, 0.0, NULL, &d), &d,
           CF_STATUS_INVALID_ARG, "distance 0");
    assert_int_equal(cf_view_orthographic(&v, 10, 20, NULL), 0);
    expect(cf_scene_create(&v, 0.0, &sc, &d), &d, CF_STATUS_INVALID_ARG,
           "tolerance 0 must be positive");
    assert_null(sc);
    expect(cf_scene_create(&v, NAN, &sc, &d), &d, CF_STATUS_NOT_FINITE,
           "tolerance");
    assert_int_equal(cf_scene_create(&v, 1e-3, &sc, &d), 0);
    /* a patch whose points coincide */
    double same[12] = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
    cf_bezier_surface_t *b = NULL;
    assert_int_equal(cf_bezier_surface_bilinear(3, same, &b, NULL), 0);
    expect(cf_scene_add_bezier(sc, b, NULL, &d), &d, CF_STATUS_DEGENERATE,
           "surface 0: the patch is degenerate");
    cf_bezier_surface_destroy(b);
    /* a surface in the plane */
    double flat[8] = {0, 0, 0, 1, 1, 0, 1, 1};
    assert_int_equal(cf_bezier_surface_bilinear(2, flat, &b, NULL), 0);
    expect(cf_scene_add_bezier(sc, b, NULL, &d), &d, CF_STATUS_DIM_MISMATCH,
           "R^2");
    cf_bezier_surface_destroy(b);
    /* degree 0 in v: a curve */
    double line[6] = {0, 0, 0, 1, 0, 0};
    assert_int_equal(cf_bezier_surface_create(3, 1, 0, line, NULL, &b, NULL),
                     0);
    expect(cf_scene_add_bezier(sc, b, NULL, &d), &d, CF_STATUS_DEGENERATE,
           "degree 0 in v");
    cf_bezier_surface_destroy(b);
    /* a tolerance too fine for the scene's size */
    double big[12] = {0, 0, 0, 0, 1e10, 0, 1e10, 0, 0, 1e10, 1e10, 1};
    assert_int_equal(cf_bezier_surface_bilinear(3, big, &b, NULL), 0);
    expect(cf_scene_add_bezier(sc, b, NULL, &d), &d, CF_STATUS_INVALID_ARG,
           "below 1e-12 of the scene's size");
    assert_int_equal(cf_scene_count(sc), 0);
    cf_bezier_surface_destroy(b);
    /* a scene whose diagonal overflows (each side finite): refused as
    ** too large, not as a tolerance below 1e-12 of an infinite size */
    double huge[12] = {0, 0, 0, 0, 1e200, 0, 1e200, 0, 0, 1e200, 1e200, 1};
    assert_int_equal(cf_bezier_surface_bilinear(3, huge, &b, NULL), 0);
    expect(cf_scene_add_bezier(sc, b, NULL, &d), &d, CF_STATUS_NOT_FINITE,
           "the scene spans 1e+200 x 1e+200 x 1, too large for its hidden "
           "lines");
    assert_int_equal(cf_scene_count(sc), 0);
    cf_bezier_surface_destroy(b);
    /* a curve not in R^3, a surface number out of range, a NaN point */
    cf_bezier_t *c2 = NULL;
    cf_visibility_t *vis = NULL;
    double p2[4] = {0, 0, 1, 1};
    assert_int_equal(cf_bezier_create(2, 1, p2, NULL, &c2, NULL), 0);
    expect(cf_scene_curve_visibility(sc, c2, NULL, &vis, &d), &d,
           CF_STATUS_DIM_MISMATCH, "R^2");
    assert_null(vis);
    cf_bezier_destroy(c2);
    double pt[3] = {0, NAN, 0};
    bool visible;
    cf_vis_on_t on = {5, NULL, NULL, {0, 0}, 0.0};
    expect(cf_scene_point_visible(sc, pt, NULL, &visible, NULL, &d), &d,
           CF_STATUS_NOT_FINITE, "coordinate 1");
    pt[1] = 0.0;
    expect(cf_scene_point_visible(sc, pt, &on, &visible, NULL, &d), &d,
           CF_STATUS_INVALID_ARG, "surface 5 is not in the scene");
    cf_silhouette_t *sil = NULL;
    expect(cf_scene_silhouette(sc, 3, &sil, &d), &d, CF_STATUS_INVALID_ARG,
           "surface 3");
    cf_facets_t *f = NULL;
    expect(cf_scene_facets_tol(sc, -1.0, &f, &d), &d, CF_STATUS_INVALID_ARG,
           "tolerance -1");
    cf_scene_destroy(sc);
    /* behind the eye */
    double near[12] = {-1, -1, 0, -1, 1, 0, 1, -1, 0, 1, 1, 0};
    assert_int_equal(cf_view_perspective(&v, 0, 90, 0.5, NULL, NULL), 0);
    assert_int_equal(cf_scene_create(&v, 1e-3, &sc, NULL), 0);
    near[2] = 0.7;   /* above the eye at z = 0.5 */
    assert_int_equal(cf_bezier_surface_bilinear(3, near, &b, NULL), 0);
    expect(cf_scene_add_bezier(sc, b, NULL, &d), &d, CF_STATUS_DOMAIN,
           "control point 0 is not in front of the eye");
    cf_bezier_surface_destroy(b);
    cf_scene_destroy(sc);
}

/* Every allocation of a small scene's life failing in turn: NO_MEMORY,
** nothing left behind. */
static cf_status_t
small_scene(void)
{
    double Q[12] = {-1, -1, 0, -1, 1, 0.3, 1, -1, 0.2, 1, 1, 0};
    cf_bezier_surface_t *b = NULL, *sd = NULL;
    cf_scene_t *sc = NULL;
    cf_visibility_t *vis = NULL;
    cf_silhouette_t *sil = NULL;
    cf_facets_t *f = NULL;
    cf_bezier_t *c = NULL;
    cf_view_t v;
    cf_diag_t d;
    double L[6] = {-1.2, 0, -0.5, 1.2, 0.1, 0.8};
    cf_status_t st;
    cf_view_orthographic(&v, 20, 30, NULL);
    st = cf_bezier_surface_bilinear(3, Q, &b, NULL);
    if (st == CF_STATUS_OK)
        st = make_saddle(&sd);
    if (st == CF_STATUS_OK)
        st = cf_scene_create(&v, 0.1, &sc, &d);
    if (st == CF_STATUS_OK)
        st = cf_scene_add_bezier(sc, b, NULL, &d);
    if (st == CF_STATUS_OK)
        st = cf_scene_add_bezier(sc, sd, NULL, &d);
    if (st == CF_STATUS_OK)
        st = cf_bezier_create(3, 1, L, NULL, &c, NULL);
    if (st == CF_STATUS_OK)
        st = cf_scene_curve_visibility(sc, c, NULL, &vis, &d);
    if (st == CF_STATUS_OK)
        st = cf_scene_silhouette(sc, SIZE_MAX, &sil, &d);
    if (st == CF_STATUS_OK)
        st = cf_scene_facets_tol(sc, 0.3, &f, &d);
    if (st != CF_STATUS_OK && st != CF_STATUS_NO_MEMORY)
        fail_msg("status %d: %s", st, d.msg);
    cf_facets_destroy(f);
    cf_silhouette_destroy(sil);
    cf_visibility_destroy(vis);
    cf_bezier_destroy(c);
    cf_scene_destroy(sc);
    cf_bezier_surface_destroy(b);
    cf_bezier_surface_destroy(sd);
    return st;
}

static void
test_no_memory(void **state)
{
    (void)state;
    long k;
    for (k = 1; k < 100000; k++) {
        tu_fail_alloc_after(k);
        cf_status_t st = small_scene();
        long live = tu_alloc_live();
        tu_fail_alloc_reset();
        if (live != 0)
            fail_msg("allocation %ld failing: %ld blocks left", k, live);
        if (st == CF_STATUS_OK)
            break;
    }
    printf("# %ld allocations failed in turn\n", k - 1);
    assert_true(k > 10 && k < 100000);
}

/*
** Control-net segments (straight lines off the surface) against the
** surfaces of two of the chapter's figures, each net segment checked:
**   a biquadratic surface whose net segments leave it tangentially at its
**   corners: the surface hides part of a segment in front of it by a
**   depth of a few hundredths;
**   a bicubic surface whose net runs close to it: the surface hides the
**   net near some control points by less than a hundredth.
*/
static void
check_net(const double *P, int p, const double *U, size_t nU,
          const double *V, size_t nV, size_t nu, size_t nv, double az,
          double el, const char *what)
{
    cf_bspline_surface_t *s = NULL;
    cf_view_t v;
    world w;
    char name[64];
    assert_int_equal(cf_bspline_surface_create(3, p, p, U, nU, V, nV, P, nu,
                                               nv, NULL, &s, NULL), 0);
    assert_int_equal(cf_view_orthographic(&v, az, el, NULL), 0);
    world_init(&w, &v, 1.6e-4);
    add_bspline(&w, s);
    for (size_t i = 0; i < nu; i++)
        for (size_t j = 0; j < nv; j++) {
            const double *a = P + 3 * (i * nv + j);
            for (int e = 0; e < 2; e++) {
                const double *b = e == 0 ? a + 3 * nv : a + 3;
                if ((e == 0 && i + 1 == nu) || (e == 1 && j + 1 == nv))
                    continue;
                cf_bspline_t *c = segment(a, b);
                snprintf(name, sizeof name, "%s net %zu %zu %s", what, i, j,
                         e == 0 ? "u" : "v");
                check_line(&w, c, NULL, name);
                cf_bspline_destroy(c);
            }
        }
    report(&w, what);
    cf_bspline_surface_destroy(s);
    world_fini(&w);
}

static void
test_net(void **state)
{
    (void)state;
    double P2[16 * 3], P3[30 * 3];
    double U2[7] = {0, 0, 0, 1, 2, 2, 2};
    double U3[9] = {0, 0, 0, 0, 1, 2, 2, 2, 2};
    double V3[10] = {0, 0, 0, 0, 1, 2, 3, 3, 3, 3};
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double *x = P2 + 3 * (4 * i + j);
            x[0] = i;
            x[1] = j;
            x[2] = (i + j) % 2 == 0 ? 1.2 : 0.2;
        }
    check_net(P2, 2, U2, 7, U2, 7, 4, 4, -60, 30, "biquadratic");
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 6; j++) {
            double *x = P3 + 3 * (6 * i + j);
            x[0] = i;
            x[1] = j;
            x[2] = 0.8 * sin(i * 1.1) * cos(j * 0.9) + 0.15 * i;
        }
    check_net(P3, 3, U3, 9, V3, 10, 5, 6, -60, 35, "bicubic");
}

/* A square 4 tol wide in front of the middle of a segment, between two of
** its samples (image steps of 16 tol): found by the certified gaps. */
static void
test_small_occluder(void **state)
{
    (void)state;
    double Q[12] = {-2e-3, -2e-3, 1, -2e-3, 2e-3, 1,
                    2e-3, -2e-3, 1, 2e-3, 2e-3, 1};
    double p0[3] = {-1, 0, 0}, p1[3] = {1, 0, 0};
    cf_bezier_surface_t *a = NULL;
    cf_view_t v;
    world w;
    assert_int_equal(cf_bezier_surface_bilinear(3, Q, &a, NULL), 0);
    assert_int_equal(cf_view_orthographic(&v, 0, 90, NULL), 0);
    world_init(&w, &v, 1e-3);
    add_bezier(&w, a);
    cf_bspline_t *c = segment(p0, p1);
    check_line(&w, c, NULL, "segment behind a small square");
    assert_int_equal(w.hidden, 1);
    cf_bspline_destroy(c);
    cf_bezier_surface_destroy(a);
    world_fini(&w);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_projection),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_no_memory),
        cmocka_unit_test(test_sphere),
        cmocka_unit_test(test_torus),
        cmocka_unit_test(test_torus_perspective),
        cmocka_unit_test(test_saddle),
        cmocka_unit_test(test_two_patches),
        cmocka_unit_test(test_curl),
        cmocka_unit_test(test_triangle),
        cmocka_unit_test(test_points),
        cmocka_unit_test(test_net),
        cmocka_unit_test(test_small_occluder),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
