/*
** Allocation failure in the surface half (test_alloc.c does the curves):
** for the surface constructions, the triangular patches, the scene's
** hidden lines, silhouettes and facets, and (with the renderer) a figure
** in space with every kind of element, the k-th allocation from the start
** of the operation fails, for k = 1, 2, ... until the operation succeeds
** (tu_fail_loop).  Every failing run must return CF_STATUS_NO_MEMORY with
** the diag saying so and leak nothing; ASan and valgrind check the frees.
**
** A script reaches every one of these failure points: its memory limit
** (--max-memory) is the allocator of the library and of the rendering,
** and a script chooses how much it holds before it draws.
*/
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/curvefig.h"
#include "testutil.h"
#ifdef CF_TEST_RENDER
#include "curvefig/figure.h"
#include "curvefig/figure3d.h"
#endif

/* Shared inputs, made once with the default allocator. */
static cf_bspline_t *profile, *rail, *edge[4];
static cf_bspline_surface_t *torus, *bent, *flat;
static cf_bezier_surface_t *patch;
static cf_bezier_triangle_t *tri;
static cf_view_t view;
static long total_points;

/* A bent rational patch of degree (2, 3), 3 x 4 points. */
static const double PATCH[] = {
    -1, -1, 0,    -1, -0.3, 0.8,  -1, 0.3, 0.8,  -1, 1, 0,
     0, -1, 0.4,   0, -0.3, 1.2,   0, 0.3, 1.2,   0, 1, 0.4,
     1, -1, 0,     1, -0.3, 0.8,   1, 0.3, 0.8,   1, 1, 0,
};
static const double PATCH_W[] = { 1, 1.5, 1.5, 1, 1, 2, 2, 1, 1, 1.5, 1.5, 1 };

/* A cubic triangle in front of the patch, rational. */
static const double TRI[] = {
    -0.8, -0.8, 1.6,   -0.2, -0.8, 1.8,   0.4, -0.8, 1.7,   1.0, -0.8, 1.6,
    -0.8, -0.2, 1.8,   -0.2, -0.2, 2.2,   0.4, -0.2, 1.9,
    -0.8, 0.4, 1.7,    -0.2, 0.4, 1.9,
    -0.8, 1.0, 1.6,
};
static const double TRI_W[] = { 1, 1, 1, 1, 1, 2, 1, 1, 1, 1 };

static long
fail_loop(const char *name, tu_alloc_op op, bool takes_diag)
{
    long points = tu_fail_loop(name, op, takes_diag);
    total_points += points;
    return points;
}

/* ---- the surfaces themselves -------------------------------------------- */

static cf_status_t
op_bezier_surface(cf_diag_t *diag)
{
    cf_bezier_surface_t *s = NULL, *lo = NULL, *hi = NULL, *e = NULL;
    cf_bezier_t *iso = NULL;
    cf_status_t st = cf_bezier_surface_create(3, 2, 3, PATCH, PATCH_W, &s,
                                              diag);
    if (st == CF_STATUS_OK)
        st = cf_bezier_surface_split(s, CF_DIR_U, 0.3, &lo, &hi, diag);
    if (st == CF_STATUS_OK)
        st = cf_bezier_surface_elevate(hi, 1, 2, &e, diag);
    if (st == CF_STATUS_OK)
        st = cf_bezier_surface_iso(e, CF_DIR_V, 0.6, &iso, diag);
    cf_bezier_destroy(iso);
    cf_bezier_surface_destroy(e);
    cf_bezier_surface_destroy(hi);
    cf_bezier_surface_destroy(lo);
    cf_bezier_surface_destroy(s);
    return st;
}

static cf_status_t
op_bspline_surface(cf_diag_t *diag)
{
    static const double x[] = { 0.1, 0.2, 0.7 };
    cf_bspline_surface_t *k = NULL, *r = NULL, *lo = NULL, *hi = NULL,
                         *e = NULL;
    cf_bspline_t *iso = NULL;
    cf_bezier_surface_list_t *L = NULL;
    cf_status_t st = cf_bspline_surface_insert_knot(torus, CF_DIR_U, 0.3, 2,
                                                    &k, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_surface_refine(k, CF_DIR_V, x, 3, &r, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_surface_split(r, CF_DIR_V, 0.45, &lo, &hi, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_surface_elevate(lo, 1, 0, &e, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_surface_iso(e, CF_DIR_U, 0.6, &iso, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_surface_to_beziers(bent, &L, diag);
    cf_bezier_surface_list_destroy(L);
    cf_bspline_destroy(iso);
    cf_bspline_surface_destroy(e);
    cf_bspline_surface_destroy(hi);
    cf_bspline_surface_destroy(lo);
    cf_bspline_surface_destroy(r);
    cf_bspline_surface_destroy(k);
    return st;
}

static cf_status_t
op_constructions(cf_diag_t *diag)
{
    static const double O[] = { 0, 0, 0 }, A[] = { 0, 0, 1 },
                        d[] = { 0.2, 0.1, 1.5 };
    cf_bspline_surface_t *s[8] = { NULL };
    cf_status_t st = cf_surface_revolve(profile, O, A, 0.3, 5.0, &s[0],
                                        diag);
    if (st == CF_STATUS_OK)
        st = cf_surface_extrude(rail, d, &s[1], diag);
    if (st == CF_STATUS_OK)
        st = cf_surface_ruled(rail, profile, &s[2], diag);
    if (st == CF_STATUS_OK)
        st = cf_surface_coons(edge[0], edge[1], edge[2], edge[3], &s[3],
                              diag);
    if (st == CF_STATUS_OK)
        st = cf_nurbs_sphere(O, 1.5, &s[4], diag);
    if (st == CF_STATUS_OK)
        st = cf_nurbs_cylinder(O, 1, 2, &s[5], diag);
    if (st == CF_STATUS_OK)
        st = cf_nurbs_cone(O, 1, 2, &s[6], diag);
    if (st == CF_STATUS_OK)
        st = cf_nurbs_torus(O, 2, 0.5, &s[7], diag);
    for (size_t i = 0; i < 8; i++)
        cf_bspline_surface_destroy(s[i]);
    return st;
}

static cf_status_t
op_interpolate(cf_diag_t *diag)
{
    double Q[6 * 5 * 3], residual = 0;
    cf_bspline_surface_t *a = NULL, *b = NULL;
    cf_interp_options_t opt;
    cf_status_t st;
    for (size_t i = 0; i < 6; i++)
        for (size_t j = 0; j < 5; j++) {
            double *q = Q + 3 * (5 * i + j);
            q[0] = (double)i + 0.1 * (double)j * (double)j;
            q[1] = (double)j;
            q[2] = sin(0.9 * (double)i) * cos(0.7 * (double)j);
        }
    cf_interp_options_init(&opt);
    st = cf_interpolate_surface(3, Q, 6, 5, &opt, &a, NULL, diag);
    if (st == CF_STATUS_OK)
        st = cf_approximate_surface(3, Q, 6, 5, 5, 4, &opt, true, &b,
                                    &residual, diag);
    cf_bspline_surface_destroy(b);
    cf_bspline_surface_destroy(a);
    return st;
}

static cf_status_t
op_triangle(cf_diag_t *diag)
{
    cf_bezier_triangle_t *t = NULL, *sub[3] = { NULL }, *e = NULL;
    cf_bezier_t *b = NULL;
    cf_status_t st = cf_bezier_triangle_create(3, 3, TRI, TRI_W, &t, diag);
    if (st == CF_STATUS_OK)
        st = cf_bezier_triangle_subdivide(t, 0.2, 0.5, sub, diag);
    if (st == CF_STATUS_OK)
        st = cf_bezier_triangle_elevate(sub[1], &e, diag);
    if (st == CF_STATUS_OK)
        st = cf_bezier_triangle_boundary(e, 2, &b, diag);
    /* degree 11: past the evaluator's work on the stack (degree 10) */
    for (int d = 4; st == CF_STATUS_OK && d < 11; d++) {
        cf_bezier_triangle_t *up = NULL;
        st = cf_bezier_triangle_elevate(e, &up, diag);
        cf_bezier_triangle_destroy(e);
        e = up;
    }
    if (st == CF_STATUS_OK) {
        double p[3];
        st = cf_bezier_triangle_eval(e, 0.2, 0.3, p);
        if (st == CF_STATUS_NO_MEMORY)
            cf_diag_set(diag, st, -1, "out of memory");
    }
    cf_bezier_destroy(b);
    cf_bezier_triangle_destroy(e);
    for (size_t i = 0; i < 3; i++)
        cf_bezier_triangle_destroy(sub[i]);
    cf_bezier_triangle_destroy(t);
    return st;
}

/* ---- the scene: hidden lines, silhouettes, facets ------------------------ */

/* The patch, the triangle in front of it and the torus behind them. */
static cf_status_t
make_scene(cf_scene_t **sc, cf_diag_t *diag)
{
    size_t id;
    cf_status_t st = cf_scene_create(&view, 2e-3, sc, diag);
    if (st == CF_STATUS_OK)
        st = cf_scene_add_bezier(*sc, patch, &id, diag);
    if (st == CF_STATUS_OK)
        st = cf_scene_add_triangle(*sc, tri, &id, diag);
    if (st == CF_STATUS_OK)
        st = cf_scene_add_bspline(*sc, torus, &id, diag);
    return st;
}

static cf_status_t
op_scene_lines(cf_diag_t *diag)
{
    static const double seg[] = { -1.5, -0.2, -0.5, 1.4, 0.3, 2.5 };
    static const double behind[] = { 0.1, 0.1, -0.6 };
    cf_scene_t *sc = NULL;
    cf_bspline_t *iso = NULL;
    cf_bezier_t *line = NULL;
    cf_visibility_t *v1 = NULL, *v2 = NULL;
    bool visible = true;
    size_t occluder = 0;
    cf_status_t st = make_scene(&sc, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_surface_iso(torus, CF_DIR_U, 0.3, &iso, diag);
    if (st == CF_STATUS_OK)
        st = cf_scene_bspline_visibility(sc, iso, NULL, &v1, diag);
    if (st == CF_STATUS_OK)
        st = cf_bezier_create(3, 1, seg, NULL, &line, diag);
    if (st == CF_STATUS_OK)
        st = cf_scene_curve_visibility(sc, line, NULL, &v2, diag);
    if (st == CF_STATUS_OK)
        st = cf_scene_point_visible(sc, behind, NULL, &visible, &occluder,
                                    diag);
    if (st == CF_STATUS_OK) {
        /* the segment pierces the patch: seen, then hidden, then seen */
        assert_true(v2->n >= 2);
        assert_false(visible);
    }
    cf_visibility_destroy(v2);
    cf_visibility_destroy(v1);
    cf_bezier_destroy(line);
    cf_bspline_destroy(iso);
    cf_scene_destroy(sc);
    return st;
}

static cf_status_t
op_silhouette(cf_diag_t *diag)
{
    cf_scene_t *sc = NULL;
    cf_silhouette_t *sil = NULL;
    cf_status_t st = make_scene(&sc, diag);
    if (st == CF_STATUS_OK)
        st = cf_scene_silhouette(sc, 2, &sil, diag);
    /* two pieces' visibility: each piece's is the same work (the
    ** torus's 20-odd pieces would take 10 s for nothing new) */
    for (size_t i = 0; st == CF_STATUS_OK && i < sil->n && i < 2; i++) {
        cf_visibility_t *v = NULL;
        st = cf_scene_silhouette_visibility(sc, sil, i, &v, diag);
        cf_visibility_destroy(v);
    }
    if (st == CF_STATUS_OK)
        assert_true(sil->n >= 2);   /* the torus's outer and inner */
    cf_silhouette_destroy(sil);
    cf_scene_destroy(sc);
    return st;
}

static cf_status_t
op_facets(cf_diag_t *diag)
{
    cf_scene_t *sc = NULL;
    cf_facets_t *f = NULL;
    cf_status_t st = make_scene(&sc, diag);
    if (st == CF_STATUS_OK)
        st = cf_scene_facets_tol(sc, 0.05, &f, diag);
    if (st == CF_STATUS_OK)
        assert_true(f->n > 0);
    cf_facets_destroy(f);
    cf_scene_destroy(sc);
    return st;
}

static void
test_core_surfaces(void **state)
{
    (void)state;
    assert_true(fail_loop("bezier surface ops", op_bezier_surface, true)
                >= 4);
    assert_true(fail_loop("bspline surface ops", op_bspline_surface, true)
                >= 6);
    assert_true(fail_loop("revolve, extrude, ... torus", op_constructions,
                          true) >= 8);
    assert_true(fail_loop("interpolate, approximate", op_interpolate, true)
                >= 2);
    assert_true(fail_loop("triangle ops", op_triangle, true) >= 4);
    assert_true(fail_loop("scene: lines, a point", op_scene_lines, true)
                >= 5);
    assert_true(fail_loop("scene: silhouette", op_silhouette, true) >= 4);
    assert_true(fail_loop("scene: facets", op_facets, true) >= 4);
}

#ifdef CF_TEST_RENDER
/* ---- a figure in space --------------------------------------------------- */

/*
** The figure made by add (its adds' failures are the figure's status,
** which the diag gets), rendered to SVG and to PGF in memory.
*/
static cf_status_t
render_both(cf_status_t (*add)(cf_figure_t *fig, const cf_style_t *style),
            cf_diag_t *diag)
{
    cf_figure_t *fig = NULL;
    cf_style_t style;
    unsigned char *data = NULL;
    size_t size = 0;
    cf_status_t st = cf_figure_create(2, 1.5, CF_UNIT_CM, &fig, diag);
    if (st != CF_STATUS_OK)
        return st;
    cf_style_init(&style);
    st = cf_figure_set_view(fig, &view);
    if (st == CF_STATUS_OK)
        st = add(fig, &style);
    if (st == CF_STATUS_OK)
        st = cf_figure_render(fig, CF_FORMAT_SVG, NULL, &data, &size, diag);
    else
        st = cf_figure_status(fig, diag);
    cf_free(data);
    data = NULL;
    if (st == CF_STATUS_OK)
        st = cf_figure_render(fig, CF_FORMAT_PGF, NULL, &data, &size, diag);
    if (st == CF_STATUS_OK)
        assert_non_null(strstr((const char *)data, "\\pgf"));
    cf_free(data);
    cf_figure_destroy(fig);
    return st;
}

/* The rational patch shaded, with an iso-line each way, its silhouette
** and net, hidden lines dashed, and the rational triangle in front. */
static cf_status_t
add_surfaces(cf_figure_t *fig, const cf_style_t *style)
{
    cf_surface_lines_t lines;
    cf_status_t st;
    cf_surface_lines_init(&lines);
    lines.nu = lines.nv = 1;
    lines.net = true;
    lines.hidden = CF_HIDDEN_DASHED;
    lines.shading.shade = CF_SHADE_SMOOTH;
    lines.shading.front = (cf_color_t){ 0.6, 0.7, 0.9, 1 };
    lines.shading.back = (cf_color_t){ 0.9, 0.8, 0.6, 1 };
    lines.shading.opacity = 1;
    st = cf_figure_add_surface(fig, bent, &lines, style);
    if (st == CF_STATUS_OK) {
        cf_surface_lines_init(&lines);
        st = cf_figure_add_triangle_surface(fig, tri, &lines, style);
    }
    return st;
}

/* Behind and through a plain bilinear patch: a closed polyline, points, a
** label, an arrow, a fill that crosses itself and a hull. */
static cf_status_t
add_elements(cf_figure_t *fig, const cf_style_t *style)
{
    static const double poly[] = { -1.4, -0.6, -0.4,  0.2, 0.1, 1.4,
                                    1.3, 0.7, -0.5,  -0.2, 1.2, -0.3 };
    static const double pts[] = { 0.2, 0.1, 1.4,  0, 0, -0.5 };
    static const double bow[] = { -1, -1, 0.2,  1, 1, 0.9,  1, -1, 0.2,
                                  -1, 1, 0.9 };
    static const double p[] = { 0.5, -0.6, -0.6 }, q[] = { -0.2, 0.3, 1.7 };
    double cloud[3 * 24];
    cf_surface_lines_t lines;
    cf_status_t st;
    for (size_t i = 0; i < 24; i++) {
        double a = 0.7 * (double)i, b = 1.3 * (double)i;
        cloud[3 * i] = 0.4 * cos(a) * sin(b) + 0.8;
        cloud[3 * i + 1] = 0.4 * sin(a) * sin(b) - 0.5;
        cloud[3 * i + 2] = 0.4 * cos(b) - 0.8;
    }
    cf_surface_lines_init(&lines);
    st = cf_figure_add_surface(fig, flat, &lines, style);
    if (st == CF_STATUS_OK)
        st = cf_figure_add_space_polyline(fig, poly, 4, true,
                                          CF_HIDDEN_DASHED, style);
    if (st == CF_STATUS_OK)
        st = cf_figure_add_space_points(fig, pts, 2, CF_HIDDEN_DASHED,
                                        style);
    if (st == CF_STATUS_OK)
        st = cf_figure_add_space_label(fig, pts + 3, "Q_1",
                                       CF_HIDDEN_DASHED, style);
    if (st == CF_STATUS_OK)
        st = cf_figure_add_space_arrow(fig, p, q, CF_HIDDEN_DASHED, style);
    if (st == CF_STATUS_OK)
        st = cf_figure_add_space_fill(fig, bow, 4, CF_HIDDEN_SHOW, style);
    if (st == CF_STATUS_OK)
        st = cf_figure_add_space_hull(fig, cloud, 24, CF_HIDDEN_DASHED,
                                      style);
    return st;
}

static cf_status_t
op_figure_surfaces(cf_diag_t *diag)
{
    return render_both(add_surfaces, diag);
}

static cf_status_t
op_figure_elements(cf_diag_t *diag)
{
    return render_both(add_elements, diag);
}

static void
test_figure_in_space(void **state)
{
    (void)state;
    assert_true(fail_loop("figure: surfaces, SVG + PGF", op_figure_surfaces,
                          true) >= 20);
    assert_true(fail_loop("figure: space elements", op_figure_elements,
                          true) >= 20);
}
#endif

static int
setup(void **state)
{
    static const double prof[] = { 1, 0, -1,  1.6, 0, -0.3,  0.8, 0, 0.4,
                                   1.2, 0, 1 };
    static const double rl[] = { 0, 0, 0,  1, 0.5, 0,  2, -0.5, 0.3 };
    static const double C0[] = { 0, 0, 0,  1, 0, 0.5,  2, 0, 0 };
    static const double C1[] = { 0, 2, 0,  1, 2, -0.5,  2, 2, 0 };
    static const double D0[] = { 0, 0, 0,  0, 1, 0.4,  0, 2, 0 };
    static const double D1[] = { 2, 0, 0,  2, 1, -0.4,  2, 2, 0 };
    static const double O[] = { 0, 0, -0.5 };
    static const double K01[] = { 0, 0, 1, 1 };
    static const double FLAT[] = { -1.2, -1.2, 0.3,  -1.2, 1.2, 0.5,
                                   1.2, -1.2, 0.5,   1.2, 1.2, 0.7 };
    const double *E[4] = { C0, C1, D0, D1 };
    (void)state;
    if (cf_view_orthographic(&view, -60, 30, NULL) != CF_STATUS_OK ||
        cf_bspline_create_clamped(3, 3, prof, 4, NULL, &profile, NULL) != 0 ||
        cf_bspline_create_clamped(3, 2, rl, 3, NULL, &rail, NULL) != 0 ||
        cf_nurbs_torus(O, 1.2, 0.35, &torus, NULL) != CF_STATUS_OK ||
        cf_bezier_surface_create(3, 2, 3, PATCH, PATCH_W, &patch, NULL) != 0 ||
        cf_bspline_surface_from_bezier(patch, &bent, NULL) != 0 ||
        cf_bspline_surface_create(3, 1, 1, K01, 4, K01, 4, FLAT, 2, 2, NULL,
                                  &flat, NULL) != 0 ||
        cf_bezier_triangle_create(3, 3, TRI, TRI_W, &tri, NULL) != 0)
        return -1;
    for (size_t i = 0; i < 4; i++)
        if (cf_bspline_create_clamped(3, 2, E[i], 3, NULL, &edge[i], NULL))
            return -1;
    return 0;
}

static int
teardown(void **state)
{
    (void)state;
    for (size_t i = 0; i < 4; i++)
        cf_bspline_destroy(edge[i]);
    cf_bezier_triangle_destroy(tri);
    cf_bspline_surface_destroy(bent);
    cf_bspline_surface_destroy(flat);
    cf_bezier_surface_destroy(patch);
    cf_bspline_surface_destroy(torus);
    cf_bspline_destroy(rail);
    cf_bspline_destroy(profile);
    print_message("%ld allocation failure points in all\n", total_points);
    return 0;
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_core_surfaces),
#ifdef CF_TEST_RENDER
        cmocka_unit_test(test_figure_in_space),
#endif
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
