/*
** Filled polygons and convex hulls in R^3 in a figure with a view
** (curvefig/figure3d.h): the region is kept in space as triangles
** (region-tri.c); when drawn, the parts of them that the figure's
** occluding surfaces hide are found (region-vis.c) and the seen part is
** filled in the element's fill, the hidden part faded to 0.4 of its
** opacity (hidden "dashed"), left out ("remove") or filled alike
** ("show").  The outline is a polygon in space split exactly as the
** polylines are (el-space.c).  Both are painted where the element comes,
** after the surfaces' shading when it comes after them: a seen part has
** no surface in front of it, so painting it over what lies behind is the
** painter's order split exactly.
*/
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "region.h"
#include "surface-lines.h"

typedef struct region_el {
    cf__element_t base;
    cf_figure_t *fig;
    double *p2;              /* the images of the points (bounds) */
    size_t n;
    cf__tris_t tris;         /* the region in space */
    bool positive;           /* not planar: every part counter-clockwise
                                (their union), else with its sign */
    cf__element_t *outline;  /* a polygon in space, or NULL */
    cf_hidden_t hidden;
    double cache_tol;        /* the parts below are for this layout
                                tolerance (0: none) */
    cf__polys_t seen, unseen;
} region_el_t;

static void
drop_cache(region_el_t *e)
{
    cf__polys_fini(&e->seen);
    cf__polys_fini(&e->unseen);
    e->cache_tol = 0;
}

static void
region_fini(cf__element_t *el)
{
    region_el_t *e = (region_el_t *)el;
    drop_cache(e);
    cf__tris_fini(&e->tris);
    cf_free(e->p2);
    if (e->outline != NULL) {
        e->outline->kind->fini(e->outline);
        cf_free(e->outline);
    }
}

static void
region_bounds(const cf__element_t *el, cf__bounds_t *b)
{
    const region_el_t *e = (const region_el_t *)el;
    for (size_t i = 0; i < e->n; i++)
        cf__bounds_add(b, e->p2[2 * i], e->p2[2 * i + 1]);
}

/* The cells of the region are at most CELL times the scene's tolerance
** long in the image (8 x 0.2 bp by default), the change points on their
** edges found to half that tolerance. */
enum { CELL = 8 };

/* The element's index in the figure. */
static size_t
index_of(const cf_figure_t *fig, const region_el_t *e)
{
    size_t i = 0;
    while (i < fig->count && fig->els[i] != &e->base)
        i++;
    return i;
}

/* A warning about the element: "fill 3 (line 12): ..." (counted from 1,
** as the labels' warnings count). */
static void
warn(cf_figure_t *fig, const region_el_t *e, const char *what)
{
    char at[CF__LINE_NOTE_SIZE];
    cf__figure_warn(fig, "%s %zu%s %s", e->base.kind->name,
                    index_of(fig, e) + 1, cf__line_note(e->base.line, at),
                    what);
}

/* The seen and hidden parts for layout l. */
static cf_status_t
build(cf_figure_t *fig, region_el_t *e, const cf__layout_t *l)
{
    cf_scene_t *sc = NULL;
    cf_status_t st = CF_STATUS_OK;
    double vtol = 20 * l->tol, win[4];
    cf__region_grid_t g;
    if (e->cache_tol > 0 && e->cache_tol <= l->tol)
        return CF_STATUS_OK;
    drop_cache(e);
    win[0] = l->xmin;
    win[1] = l->xmax;
    win[2] = l->ymin;
    win[3] = l->ymax;
    g.cell = CELL * vtol;
    g.split = 0.5 * vtol;
    g.positive = e->positive;
    g.window = l->clip ? win : NULL;
    if (e->hidden != CF_HIDDEN_SHOW)
        st = cf__figure_scene(fig, vtol, &sc);
    if (st == CF_STATUS_OK)
        st = cf__region_parts(fig, sc, &e->tris, &g, &e->seen, &e->unseen,
                              NULL);
    if (st != CF_STATUS_OK) {
        drop_cache(e);
        return cf__fig_fail(fig, st, "a region in space");
    }
    /* (what the rough first ink refit made serves nothing after it:
    ** cf__tol_make) */
    e->cache_tol = fig->refit_rough ? 0 : l->tol;
    return CF_STATUS_OK;
}

/* A shaded surface added after the region paints its shading over it. */
static void
check_order(cf_figure_t *fig, const region_el_t *e)
{
    cf_surface_shading_t sh;
    for (size_t i = index_of(fig, e) + 1; i < fig->count; i++)
        if (cf__surface_shading(fig, i, &sh)) {
            char what[160];
            snprintf(what, sizeof what, "lies under the shading of surface "
                     "%zu, added after it: add the %s after the shaded "
                     "surfaces", i + 1, e->base.kind->name);
            warn(fig, e, what);
            return;
        }
}

/* The polygons as one path filled in colour c at opacity a (nonzero: the
** union of parts turning one way). */
static void
fill_polys(const cf__polys_t *p, const cf__layout_t *l, const cf_color_t *c,
           double a, cf__dl_t *dl)
{
    cf__paint_t paint;
    size_t at = 0;
    if (p->n == 0 || !(a > 0) || !(c->a > 0))
        return;
    cf__dl_path_begin(dl);
    for (size_t i = 0; i < p->n; i++) {
        for (size_t k = 0; k < p->len[i]; k++) {
            double x, y;
            cf__map(l, p->xy[2 * (at + k)], p->xy[2 * (at + k) + 1], &x, &y);
            if (k == 0)
                cf__dl_move(dl, x, y);
            else
                cf__dl_line(dl, x, y);
        }
        cf__dl_close(dl);
        at += p->len[i];
    }
    memset(&paint, 0, sizeof paint);
    paint.fill = true;
    paint.fill_color = *c;
    paint.fill_opacity = a;
    cf__dl_path_paint(dl, &paint);
}

static cf_status_t
region_draw(cf_figure_t *fig, cf__element_t *el, const cf__layout_t *l,
            const cf_style_t *s, cf__dl_t *dl)
{
    region_el_t *e = (region_el_t *)el;
    cf_status_t st = build(fig, e, l);
    if (st != CF_STATUS_OK)
        return st;
    check_order(fig, e);
    cf__clip_to_window(l, 0, dl);
    if (e->hidden == CF_HIDDEN_DASHED)
        fill_polys(&e->unseen, l, &s->fill, 0.4 * s->opacity, dl);
    fill_polys(&e->seen, l, &s->fill, s->opacity, dl);
    cf__dl_unclip(dl);
    if (e->outline != NULL && s->color.a > 0 && s->width > 0) {
        cf_style_t os = *s;
        os.marker = CF_MARKER_NONE;
        st = e->outline->kind->draw(fig, e->outline, l, &os, dl);
    }
    return st;
}

static const cf__kind_t fill_kind = {
    "fill", CF__KIND_SHADING, region_fini, region_bounds, region_draw, NULL,
    NULL, NULL
};
static const cf__kind_t hull_kind = {
    "hull", CF__KIND_SHADING, region_fini, region_bounds, region_draw, NULL,
    NULL, NULL
};

bool
cf__region_triangles(const cf_figure_t *fig, size_t i,
                     const cf__tris_t **tris, cf_hidden_t *hidden,
                     double *opacity)
{
    const region_el_t *e;
    cf_style_t s;
    if (fig == NULL || i >= fig->count
        || fig->els[i]->kind->fini != region_fini)
        return false;
    e = (const region_el_t *)fig->els[i];
    cf__style_resolve(&fig->theme, e->base.role, &e->base.style, &s);
    *tris = &e->tris;
    *hidden = e->hidden;
    *opacity = s.opacity;
    return true;
}

/* ---- adding ------------------------------------------------------------- */

static cf_status_t
add_region(cf_figure_t *fig, bool hull, const double *pts, size_t n,
           cf_hidden_t hidden, const cf_style_t *style)
{
    const char *what = hull ? "hull" : "fill";
    region_el_t *e;
    size_t *outline = NULL, nout = 0;
    double *op = NULL;
    bool planar = true;
    cf_status_t st = CF_STATUS_OK;
    CF__FIG_CHECK(fig);
    if (!fig->has_view)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "%s in space: the figure has no view; give "
                           "figure{view = {azimuth, elevation}, ...}", what);
    if ((unsigned)hidden > CF_HIDDEN_REMOVE)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "%s: hidden is not show, dashed or remove", what);
    if (pts == NULL || n < (hull ? 1u : 3u))
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "%s: %zu points, at least %u needed", what,
                           pts == NULL ? 0 : n, hull ? 1u : 3u);
    if (cf_check_finite_points(pts, n, 3, 3, what, &fig->err) != CF_STATUS_OK
        || cf__fig_check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    e = cf__element_new(fig, hull ? &hull_kind : &fill_kind, sizeof *e,
                        hull ? CF_ROLE_HULL : CF_ROLE_FILL, style);
    if (e == NULL)
        return fig->err.status;
    e->fig = fig;
    e->n = n;
    e->hidden = hidden;
    e->p2 = cf_alloc_array(2 * n, sizeof *e->p2);
    if (e->p2 == NULL)
        return cf__element_commit(fig, e, cf__fig_nomem(fig, what));
    for (size_t i = 0; i < n && st == CF_STATUS_OK; i++) {
        cf__fig_project1(fig, pts + 3 * i, 3, e->p2 + 2 * i);
        if (isnan(e->p2[2 * i]))
            st = cf__fig_behind_eye(fig, pts + 3 * i, what);
    }
    if (st == CF_STATUS_OK && hull)
        st = cf__region_hull(fig, pts, n, &e->tris, &outline, &nout);
    else if (st == CF_STATUS_OK)
        st = cf__region_polygon(fig, pts, n, what, &e->tris, &planar);
    e->positive = !planar;
    if (st == CF_STATUS_OK && hull && nout >= 2) {
        op = cf_alloc_array(3 * nout, sizeof *op);
        if (op == NULL)
            st = cf__fig_nomem(fig, what);
        for (size_t i = 0; st == CF_STATUS_OK && i < nout; i++)
            memcpy(op + 3 * i, pts + 3 * outline[i], 3 * sizeof *op);
    }
    if (st == CF_STATUS_OK && (op != NULL || !hull)) {
        e->outline = cf__space_outline_new(fig, op != NULL ? op : pts,
                                           op != NULL ? nout : n, nout != 2,
                                           hidden, what);
        if (e->outline == NULL)
            st = fig->err.status;
    }
    cf_free(outline);
    cf_free(op);
    return cf__element_commit(fig, e, st);
}

cf_status_t
cf_figure_add_space_fill(cf_figure_t *fig, const double *pts, size_t n,
                         cf_hidden_t hidden, const cf_style_t *style)
{
    return add_region(fig, false, pts, n, hidden, style);
}

cf_status_t
cf_figure_add_space_hull(cf_figure_t *fig, const double *pts, size_t n,
                         cf_hidden_t hidden, const cf_style_t *style)
{
    return add_region(fig, true, pts, n, hidden, style);
}
