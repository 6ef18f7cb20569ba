/*
** Surfaces as lines: boundary, silhouette, iso- and knot lines and the
** control net of a surface in R^3, each an exact curve in space split
** where it passes behind a surface of the figure (curvefig/visibility.h),
** projected exactly and drawn through plane curve elements (el-curve.c),
** which turn the pieces into cubic segments within the tolerance.
**
** The lines in space are made when the surface is added; the scene of
** occluding surfaces, the silhouette and the visibility need the layout's
** tolerance and are made when the figure is drawn, kept for that
** tolerance (a fit within a smaller one serves a larger one, as for the
** curves' cubic segments).
*/
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "curvefig/surface.h"
#include "grow.h"
#include "surface-lines.h"

enum {
    OUTLINE = CF__LINE_OUTLINE,
    ISO = CF__LINE_ISO,
    NET = CF__LINE_NET,
    NFAMILIES = CF__LINE_FAMILIES
};

typedef struct surface_el {
    cf__element_t base;
    cf_figure_t *fig;
    cf_bspline_surface_t *s;      /* one of the two */
    cf_bezier_triangle_t *tri;
    double *cpts;                 /* the control points, Cartesian */
    size_t ncpts;
    cf_surface_lines_t opt;       /* the arrays dropped */
    cf__lines3_t lines;
    size_t scene_id;              /* SIZE_MAX: not in the scene */
    /* the drawing for a tolerance: curve elements per family, visible
    ** [f][1] and hidden [f][0]; the net's vertices in the plane */
    double cache_tol;
    cf__element_t *curves[NFAMILIES][2];
    cf__surface_piece_fn probe;   /* tests: told every piece */
    void *probe_ctx;
    size_t index;
    double *verts;
    bool *vert_visible;
    size_t nverts;
} surface_el_t;

static void
drop_cache(surface_el_t *e)
{
    for (int f = 0; f < NFAMILIES; f++)
        for (int k = 0; k < 2; k++)
            if (e->curves[f][k] != NULL) {
                e->curves[f][k]->kind->fini(e->curves[f][k]);
                cf_free(e->curves[f][k]);
                e->curves[f][k] = NULL;
            }
    cf_free(e->verts);
    cf_free(e->vert_visible);
    e->verts = NULL;
    e->vert_visible = NULL;
    e->nverts = 0;
    e->cache_tol = 0;
}

static void
surface_fini(cf__element_t *el)
{
    surface_el_t *e = (surface_el_t *)el;
    drop_cache(e);
    cf__lines3_fini(&e->lines);
    cf_bspline_surface_destroy(e->s);
    cf_bezier_triangle_destroy(e->tri);
    cf_free(e->cpts);
}

static void
add_projected(const cf_figure_t *fig, const double *p, cf__bounds_t *b)
{
    double q[2];
    cf__fig_project1(fig, p, 3, q);
    if (!isnan(q[0]))
        cf__bounds_add(b, q[0], q[1]);
}

/* The box of the surface in the plane: a grid of 17 x 17 of its points
** (the silhouette and every iso-line lie on it), and the net when drawn. */
static void
surface_bounds(const cf__element_t *el, cf__bounds_t *b)
{
    const surface_el_t *e = (const surface_el_t *)el;
    enum { N = 17 };
    double uv[2 * N], pts[N * N * 3], a, c;
    if (e->s == NULL && e->tri == NULL) {
        /* space curves: their control points (the curves lie in their
        ** hull, and so do their images) */
        for (size_t i = 0; i < e->lines.n; i++) {
            const cf_bezier_t *line = e->lines.items[i].bez;
            int deg = cf_bezier_degree(line);
            double *p = cf_alloc_array(3 * ((size_t)deg + 1), sizeof *p);
            if (p == NULL) {
                b->nomem = true;   /* the layout's error */
                continue;
            }
            cf_bezier_get_points(line, p);
            for (int k = 0; k <= deg; k++)
                add_projected(e->fig, p + 3 * k, b);
            cf_free(p);
        }
    } else if (e->tri != NULL) {
        for (int i = 0; i < N; i++)
            for (int j = 0; i + j < N; j++) {
                cf_status_t st = cf_bezier_triangle_eval(
                    e->tri, (double)i / (N - 1), (double)j / (N - 1), pts);
                if (st == CF_STATUS_OK)
                    add_projected(e->fig, pts, b);
                else if (st == CF_STATUS_NO_MEMORY)
                    b->nomem = true;
            }
    } else {
        cf_bspline_surface_domain(e->s, CF_DIR_U, &a, &c);
        for (int k = 0; k < N; k++)
            uv[k] = a + (c - a) * k / (N - 1);
        cf_bspline_surface_domain(e->s, CF_DIR_V, &a, &c);
        for (int k = 0; k < N; k++)
            uv[N + k] = a + (c - a) * k / (N - 1);
        cf_status_t st = cf_bspline_surface_eval_grid(e->s, uv, N, N, pts,
                                                      NULL, NULL);
        if (st == CF_STATUS_OK)
            for (size_t i = 0; i < (size_t)N * N; i++)
                add_projected(e->fig, pts + 3 * i, b);
        else if (st == CF_STATUS_NO_MEMORY)
            b->nomem = true;
    }
    for (size_t i = 0; e->opt.net && i < e->ncpts; i++)
        add_projected(e->fig, e->cpts + 3 * i, b);
}

/* ---- the scene and visibility ------------------------------------------ */

static bool
is_surface(const cf__element_t *e)
{
    return e->kind->fini == surface_fini;
}

bool
cf__surface_shading(const cf_figure_t *fig, size_t i,
                    cf_surface_shading_t *out)
{
    const surface_el_t *e;
    if (i >= fig->count || !is_surface(fig->els[i]))
        return false;
    e = (const surface_el_t *)fig->els[i];
    if (e->opt.shading.shade == CF_SHADE_NONE)
        return false;
    *out = e->opt.shading;
    return true;
}

/* The shading of every shaded surface, painted by the figure's first
** surface element before any line: the visibility scene's facets within
** 250 times the fitting tolerance (2.5 bp by default; at 0.3 bp a vase
** took 4 s, the ordering is quadratic), cut in four when smooth. */
static cf_status_t
draw_shading(cf_figure_t *fig, const surface_el_t *self,
             const cf__layout_t *l, cf__dl_t *dl)
{
    const cf_surface_shading_t **by_id;
    cf_scene_t *sc = NULL;
    size_t first = SIZE_MAX, n = 0;
    bool any = false;
    cf_status_t st;
    for (size_t i = 0; i < fig->count; i++)
        if (is_surface(fig->els[i])) {
            const surface_el_t *e = (const surface_el_t *)fig->els[i];
            first = first == SIZE_MAX ? i : first;
            any = any || (e->opt.occludes
                          && e->opt.shading.shade != CF_SHADE_NONE);
        }
    if (!any || first == SIZE_MAX || fig->els[first] != &self->base)
        return CF_STATUS_OK;
    st = cf__figure_scene(fig, 20 * l->tol, &sc);
    if (st != CF_STATUS_OK || sc == NULL)
        return st;
    by_id = cf_calloc(fig->count, sizeof *by_id);
    if (by_id == NULL)
        return cf__fig_nomem(fig, "shading");
    for (size_t i = 0; i < fig->count; i++) {
        const surface_el_t *e = (const surface_el_t *)fig->els[i];
        if (is_surface(fig->els[i]) && e->scene_id != SIZE_MAX) {
            by_id[e->scene_id] = &e->opt.shading;
            n = e->scene_id + 1 > n ? e->scene_id + 1 : n;
        }
    }
    cf__clip_to_window(l, 0, dl);
    st = cf__shade_facets(fig, sc, 250 * l->tol, by_id, n, l, dl);
    cf__dl_unclip(dl);
    cf_free((void *)by_id);
    return st;
}

/* The piece [t0, t1] of line c, projected, into the curve element. */
static cf_status_t
add_piece(cf_figure_t *fig, cf__element_t **slot, const cf_bezier_t *c,
          double t0, double t1)
{
    cf_bezier_t *seg = NULL, *plane = NULL;
    cf_status_t st = CF_STATUS_OK;
    if (!(t1 > t0))
        return CF_STATUS_OK;
    if (*slot == NULL) {
        *slot = cf__curve_new(fig, CF_ROLE_CURVE, NULL);
        if (*slot == NULL)
            return fig->err.status;
    }
    if (t0 > 0 || t1 < 1)
        st = cf_bezier_segment(c, t0, t1, &seg, &fig->err);
    if (st == CF_STATUS_OK)
        st = cf__fig_planar_bezier(fig, seg != NULL ? seg : c, &plane);
    cf_bezier_destroy(seg);
    if (st == CF_STATUS_OK)
        st = cf__curve_add(fig, *slot, plane, NULL);
    return st;
}

/* One line split by the scene (sc NULL or hidden lines shown: whole). */
static cf_status_t
draw_line(cf_figure_t *fig, surface_el_t *e, const cf_scene_t *sc,
          const cf_bezier_t *bez, const cf_bezier_t *uv, double offset,
          int family)
{
    cf_visibility_t *vis = NULL;
    cf_vis_on_t on;
    cf_status_t st;
    if (sc == NULL || e->opt.hidden == CF_HIDDEN_SHOW) {
        /* no claim about visibility: the probe is not told */
        return add_piece(fig, &e->curves[family][1], bez, 0.0, 1.0);
    }
    memset(&on, 0, sizeof on);
    on.surface = e->scene_id;
    on.uv_bezier = uv;
    on.offset = offset;
    st = cf_scene_curve_visibility(sc, bez, e->scene_id != SIZE_MAX
                                   && uv != NULL ? &on : NULL, &vis,
                                   &fig->err);
    if (st != CF_STATUS_OK)
        return cf__fig_fail(fig, st, "surface line visibility");
    for (size_t k = 0; st == CF_STATUS_OK && k < vis->n; k++) {
        const cf_vis_interval_t *iv = &vis->items[k];
        if (e->probe != NULL)
            e->probe(e->probe_ctx, e->index, family, bez, uv, offset,
                     iv->t0, iv->t1, iv->visible);
        if (!iv->visible && e->opt.hidden == CF_HIDDEN_REMOVE)
            continue;
        st = add_piece(fig, &e->curves[family][iv->visible ? 1 : 0], bez,
                       iv->t0, iv->t1);
    }
    cf_visibility_destroy(vis);
    return st;
}

/* The silhouette of the surface: its pieces as cubics in space, each with
** its (u, v) cubic. */
static cf_status_t
draw_silhouette(cf_figure_t *fig, surface_el_t *e, const cf_scene_t *sc)
{
    cf_silhouette_t *sil = NULL;
    cf_status_t st;
    if (sc == NULL || e->scene_id == SIZE_MAX)
        return CF_STATUS_OK;   /* a surface that hides nothing shows no
                                  contour of its own in this design */
    st = cf_scene_silhouette(sc, e->scene_id, &sil, &fig->err);
    if (st != CF_STATUS_OK)
        return cf__fig_fail(fig, st, "silhouette");
    for (size_t k = 0; st == CF_STATUS_OK && k < sil->n; k++) {
        cf_bezier_t *bez = NULL, *uv = NULL;
        st = cf_bezier_create(3, 3, sil->items[k].space, NULL, &bez,
                              &fig->err);
        if (st == CF_STATUS_OK)
            st = cf_bezier_create(2, 3, sil->items[k].uv, NULL, &uv,
                                  &fig->err);
        if (st == CF_STATUS_OK)
            st = draw_line(fig, e, sc, bez, uv, sil->items[k].error_space,
                           OUTLINE);
        cf_bezier_destroy(bez);
        cf_bezier_destroy(uv);
    }
    cf_silhouette_destroy(sil);
    return st;
}

/* The net's vertices in the plane and whether each is seen. */
static cf_status_t
net_vertices(cf_figure_t *fig, surface_el_t *e, const cf_scene_t *sc)
{
    size_t n = e->ncpts;
    cf_status_t st = CF_STATUS_OK;
    e->verts = cf_alloc_array(2 * n, sizeof *e->verts);
    e->vert_visible = cf_alloc_array(n, sizeof *e->vert_visible);
    if (e->verts == NULL || e->vert_visible == NULL)
        return cf__fig_nomem(fig, "net vertices");
    e->nverts = n;
    for (size_t i = 0; i < n && st == CF_STATUS_OK; i++) {
        const double *p = e->cpts + 3 * i;
        cf__fig_project1(fig, p, 3, e->verts + 2 * i);
        if (isnan(e->verts[2 * i]))
            st = cf__fig_behind_eye(fig, p, "a net vertex");
        e->vert_visible[i] = true;
        if (st == CF_STATUS_OK && sc != NULL
            && e->opt.hidden != CF_HIDDEN_SHOW)
            st = cf_scene_point_visible(sc, p, NULL, &e->vert_visible[i],
                                        NULL, &fig->err);
    }
    return st;
}

/* Everything the element draws for tolerance tol. */
static cf_status_t
build(cf_figure_t *fig, surface_el_t *e, double tol)
{
    cf_scene_t *sc = NULL;
    cf_status_t st;
    bool need = e->opt.hidden != CF_HIDDEN_SHOW || e->opt.silhouette;
    if (cf__tol_serves(fig, e->cache_tol, tol))
        return CF_STATUS_OK;
    drop_cache(e);
    /* split points to 20 times the fitting tolerance: 0.2 bp (0.07 mm) by
    ** default, where 0.05 bp took 5 times as long on a torus; the scene
    ** makes its own (cf__tol_make: at the refits' factor as the lines,
    ** not its square; at the rough first refit a hundred times tol, as
    ** before) */
    double made = cf__tol_make(fig, tol);
    st = need ? cf__figure_scene(fig, 20 * (fig->refit_rough ? made : tol),
                                 &sc)
              : CF_STATUS_OK;
    tol = made;
    for (size_t i = 0; st == CF_STATUS_OK && i < e->lines.n; i++)
        st = draw_line(fig, e, sc, e->lines.items[i].bez,
                       e->lines.items[i].uv, 0.0, e->lines.items[i].family);
    if (st == CF_STATUS_OK && e->opt.silhouette)
        st = draw_silhouette(fig, e, sc);
    if (st == CF_STATUS_OK && e->opt.net)
        st = net_vertices(fig, e, sc);
    if (st != CF_STATUS_OK) {
        drop_cache(e);
        return cf__fig_fail(fig, st, "surface");
    }
    e->cache_tol = tol;
    return CF_STATUS_OK;
}

/* ---- drawing ------------------------------------------------------------ */

/* The styles of the families: the outline is the element's, iso-lines the
** curve style at half width under their overrides, the net the polygon
** style under its own. */
static void
family_styles(const cf_figure_t *fig, const surface_el_t *e,
              const cf_style_t *s, cf_style_t out[NFAMILIES])
{
    cf_style_t iso = e->opt.iso_style;
    out[OUTLINE] = *s;
    if (!(iso.set & CF_STYLE_WIDTH)) {
        iso.set |= CF_STYLE_WIDTH;
        iso.width = 0.5 * s->width;
    }
    if (!(iso.set & CF_STYLE_COLOR)) {
        iso.set |= CF_STYLE_COLOR;
        iso.color = s->color;
    }
    cf__style_resolve(&fig->theme, CF_ROLE_CURVE, &iso, &out[ISO]);
    cf__style_resolve(&fig->theme, CF_ROLE_POLYGON, &e->opt.net_style,
                      &out[NET]);
}

static cf_status_t
check_window(cf_figure_t *fig, const surface_el_t *e, const cf__layout_t *l)
{
    cf__bounds_t b;
    if (!l->clip)
        return CF_STATUS_OK;
    memset(&b, 0, sizeof b);
    surface_bounds(&e->base, &b);
    if (b.any && (b.x1 < l->xmin || b.x0 > l->xmax || b.y1 < l->ymin
                  || b.y0 > l->ymax))
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "the surface (seen in [%g, %g] x "
                           "[%g, %g]) lies wholly outside the window "
                           "{%g, %g, %g, %g}; widen window or leave it to "
                           "be fitted", b.x0, b.x1, b.y0, b.y1, l->xmin,
                           l->xmax, l->ymin, l->ymax);
    return CF_STATUS_OK;
}

static cf_status_t
surface_draw(cf_figure_t *fig, cf__element_t *el, const cf__layout_t *l,
             const cf_style_t *s, cf__dl_t *dl)
{
    surface_el_t *e = (surface_el_t *)el;
    cf_style_t fs[NFAMILIES];
    static const int order[NFAMILIES] = { NET, ISO, OUTLINE };
    cf_status_t st = check_window(fig, e, l);
    if (st == CF_STATUS_OK)
        st = draw_shading(fig, e, l, dl);
    if (st == CF_STATUS_OK)
        st = build(fig, e, l->tol);
    if (st != CF_STATUS_OK)
        return st;
    family_styles(fig, e, s, fs);
    /* hidden pieces under everything, then the net, iso-lines, outline */
    for (int k = 0; k < NFAMILIES && st == CF_STATUS_OK; k++) {
        cf__element_t *c = e->curves[order[k]][0];
        cf_style_t h = cf__hidden_style(&fs[order[k]]);
        if (c != NULL)
            st = c->kind->draw(fig, c, l, &h, dl);
    }
    for (int k = 0; k < NFAMILIES && st == CF_STATUS_OK; k++) {
        cf__element_t *c = e->curves[order[k]][1];
        if (c != NULL)
            st = c->kind->draw(fig, c, l, &fs[order[k]], dl);
    }
    for (size_t i = 0; i < e->nverts && st == CF_STATUS_OK; i++)
        cf__space_marker(l, &fs[NET], e->verts + 2 * i, e->vert_visible[i],
                         e->opt.hidden, dl);
    return st;
}

static bool
surface_occludes(const cf__element_t *el)
{
    return ((const surface_el_t *)el)->opt.occludes;
}

/* In the figure's scene (figure-scene.c) when it occludes, numbered there. */
static cf_status_t
surface_occlude(cf__element_t *el, cf_scene_t *sc, cf_diag_t *err)
{
    surface_el_t *e = (surface_el_t *)el;
    e->scene_id = SIZE_MAX;
    if (!e->opt.occludes)
        return CF_STATUS_OK;
    if (e->tri != NULL)
        return cf_scene_add_triangle(sc, e->tri, &e->scene_id, err);
    return cf_scene_add_bspline(sc, e->s, &e->scene_id, err);
}

static const cf__kind_t surface_kind = {
    "surface", 0, surface_fini, surface_bounds, surface_draw, NULL, surface_occludes, surface_occlude
};

/* ---- adding ------------------------------------------------------------- */

void
cf_surface_lines_init(cf_surface_lines_t *lines)
{
    memset(lines, 0, sizeof *lines);
    lines->boundary = true;
    lines->silhouette = true;
    lines->occludes = true;
    lines->hidden = CF_HIDDEN_REMOVE;
    cf_style_init(&lines->iso_style);
    cf_style_init(&lines->net_style);
    lines->shading.opacity = 1.0;
}

/* The checks every surface takes, then a new element (NULL on failure). */
static surface_el_t *
new_surface(cf_figure_t *fig, size_t dim, const cf_surface_lines_t *lines,
            const cf_style_t *style)
{
    surface_el_t *e;
    if (dim != 3) {
        cf_diag_set(&fig->err, CF_STATUS_DIM_MISMATCH, -1,
                    "a surface in R^%zu; a figure draws surfaces "
                    "in R^3", dim);
        return NULL;
    }
    if (!fig->has_view) {
        cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                    "the figure has no view; give figure{view = "
                    "{azimuth, elevation}, ...}");
        return NULL;
    }
    if ((lines->u_count > 0 && lines->u_values == NULL)
        || (lines->v_count > 0 && lines->v_values == NULL)
        || (unsigned)lines->hidden > CF_HIDDEN_REMOVE) {
        cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                    "iso-line values are NULL or hidden is not "
                    "show, dashed or remove");
        return NULL;
    }
    if (lines->shading.shade != CF_SHADE_NONE
        && !(lines->occludes && isfinite(lines->shading.opacity)
             && lines->shading.opacity >= 0 && lines->shading.opacity <= 1)) {
        cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                    "a shaded surface must occlude and its opacity "
                    "(%g) lie in [0, 1]", lines->shading.opacity);
        return NULL;
    }
    if (cf__fig_check_style(fig, style) != CF_STATUS_OK
        || cf__fig_check_style(fig, &lines->iso_style) != CF_STATUS_OK
        || cf__fig_check_style(fig, &lines->net_style) != CF_STATUS_OK)
        return NULL;
    e = cf__element_new(fig, &surface_kind, sizeof *e, CF_ROLE_CURVE, style);
    if (e == NULL)
        return NULL;
    e->fig = fig;
    e->opt = *lines;
    e->opt.u_values = e->opt.v_values = NULL;
    e->opt.u_count = e->opt.v_count = 0;
    e->scene_id = SIZE_MAX;
    return e;
}

/* The control points of e, Cartesian, into e->cpts; checked. */
static cf_status_t
control_points(cf_figure_t *fig, surface_el_t *e, size_t n)
{
    e->cpts = cf_alloc_array(3 * n, sizeof *e->cpts);
    if (e->cpts == NULL)
        return cf__fig_nomem(fig, "a surface");
    e->ncpts = n;
    if (e->tri != NULL)
        cf_bezier_triangle_get_points(e->tri, e->cpts);
    else
        cf_bspline_surface_get_points(e->s, e->cpts);
    /* the scene takes control points at least D / 1000 in front of the
    ** eye (W = (D - z) / D >= 0.001) */
    for (size_t i = 0; i < n && cf__fig_is_central(fig, 3); i++) {
        double h[3];
        if (!cf__fig_project_h(fig, e->cpts + 3 * i, 3, false, h)
            || h[2] < 1e-3)
            return cf__fig_behind_eye(fig, e->cpts + 3 * i,
                                      "the surface's control point");
    }
    return cf__check_degenerate(fig, e->cpts, n);
}

cf_status_t
cf_figure_add_surface(cf_figure_t *fig, const cf_bspline_surface_t *s,
                      const cf_surface_lines_t *lines,
                      const cf_style_t *style)
{
    surface_el_t *e;
    cf_status_t st;
    CF__FIG_CHECK(fig);
    if (s == NULL || lines == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "the surface or its lines are NULL");
    e = new_surface(fig, cf_bspline_surface_dim(s), lines, style);
    if (e == NULL)
        return fig->err.status;
    st = cf_bspline_surface_copy(s, &e->s, &fig->err);
    if (st == CF_STATUS_OK)
        st = control_points(fig, e, cf_bspline_surface_count_u(s)
                            * cf_bspline_surface_count_v(s));
    if (st == CF_STATUS_OK)
        st = cf__bspline_lines(fig, e->s, e->cpts, lines, &e->lines);
    if (cf__element_commit(fig, e, st) != CF_STATUS_OK)
        return fig->err.status;
    return cf__fact_surface(
        fig, CF__FACT_SURFACE, cf_bspline_surface_degree_u(s),
        cf_bspline_surface_degree_v(s), cf_bspline_surface_count_u(s),
        cf_bspline_surface_count_v(s), cf_bspline_surface_is_rational(s),
        cf_bspline_surface_count_u(s)
                == (size_t)cf_bspline_surface_degree_u(s) + 1
            && cf_bspline_surface_count_v(s)
                == (size_t)cf_bspline_surface_degree_v(s) + 1);
}

cf_status_t
cf_figure_add_triangle_surface(cf_figure_t *fig,
                               const cf_bezier_triangle_t *t,
                               const cf_surface_lines_t *lines,
                               const cf_style_t *style)
{
    surface_el_t *e;
    cf_status_t st;
    CF__FIG_CHECK(fig);
    if (t == NULL || lines == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "the patch or its lines are NULL");
    e = new_surface(fig, cf_bezier_triangle_dim(t), lines, style);
    if (e == NULL)
        return fig->err.status;
    st = cf__triangle_copy(fig, t, &e->tri);
    if (st == CF_STATUS_OK)
        st = control_points(fig, e, cf_bezier_triangle_count(t));
    if (st == CF_STATUS_OK)
        st = cf__triangle_lines(fig, t, lines, &e->lines);
    if (cf__element_commit(fig, e, st) != CF_STATUS_OK)
        return fig->err.status;
    return cf__fact_surface(fig, CF__FACT_TRIANGLE,
                            cf_bezier_triangle_degree(t), 0, 0, 0,
                            cf_bezier_triangle_is_rational(t), true);
}

cf_status_t
cf__figure_surface_pieces(cf_figure_t *fig, double tol,
                          cf__surface_piece_fn fn, cf__surface_fn surf,
                          void *closure)
{
    cf_status_t st = CF_STATUS_OK;
    CF__FIG_CHECK(fig);
    for (size_t i = 0; i < fig->count && st == CF_STATUS_OK; i++) {
        surface_el_t *e = (surface_el_t *)fig->els[i];
        if (!is_surface(&e->base)) {
            st = cf__space_pieces(fig, fig->els[i], i, tol, fn, closure);
            continue;
        }
        drop_cache(e);
        e->probe = fn;
        e->probe_ctx = closure;
        e->index = i;
        st = build(fig, e, tol);
        e->probe = NULL;
        drop_cache(e);
        if (surf != NULL)
            surf(closure, i, e->s, e->tri, e->opt.occludes);
    }
    return st;
}

cf_status_t
cf_figure_add_space_curves(cf_figure_t *fig, const cf_bezier_list_t *list,
                           cf_hidden_t hidden, const cf_style_t *style)
{
    surface_el_t *e;
    cf_surface_lines_t lines;
    cf_status_t st = CF_STATUS_OK;
    CF__FIG_CHECK(fig);
    if (list == NULL || (list->count > 0 && list->items == NULL))
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "space curve: the list is NULL");
    cf_surface_lines_init(&lines);
    lines.boundary = lines.silhouette = lines.occludes = false;
    lines.hidden = hidden;
    e = new_surface(fig, 3, &lines, style);
    if (e == NULL)
        return fig->err.status;
    for (size_t i = 0; i < list->count && st == CF_STATUS_OK; i++) {
        cf_bezier_t *c = NULL;
        if (list->items[i] == NULL || cf_bezier_dim(list->items[i]) != 3) {
            st = cf_diag_set(&fig->err, CF_STATUS_DIM_MISMATCH, (long)i,
                             "space curve: item %zu is not a curve in R^3",
                             i);
            break;
        }
        st = cf_bezier_copy(list->items[i], &c, &fig->err);
        if (st == CF_STATUS_OK)
            st = cf__lines3_add(fig, &e->lines, OUTLINE, c, NULL);
    }
    return cf__element_commit(fig, e, st);
}
