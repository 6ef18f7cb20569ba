/*
** Polylines, polygons and points in R^3 in a figure with a view, split by
** the figure's occluding surfaces (curvefig/figure3d.h).  A segment in
** space is a Bézier curve of degree 1: cf_scene_curve_visibility splits it
** as it splits the surfaces' lines; a vertex or a point is seen or not by
** cf_scene_point_visible.  The image of a segment in front of the eye is a
** segment (under a perspective view too), so the pieces are drawn as line
** segments of the images of their ends.  Hidden pieces are dashed, left
** out or drawn as visible ones (hidden); hidden markers are faded to 0.4
** of their opacity, left out or drawn alike.  An arrow in space is such a
** segment with a head at its tip in place of markers: its shaft is split
** as any segment and its head follows the tip as a marker does.
*/
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "surface-lines.h"

typedef struct space_el {
    cf__element_t base;
    cf_figure_t *fig;
    double *p3;              /* the points in space */
    double *p2;              /* their images */
    size_t n;
    bool lines, closed;      /* polyline or polygon; else points */
    bool arrow;              /* one segment with a head at p3[3..5] */
    double t_end;            /* the shaft ends here (under the head) */
    cf_hidden_t hidden;
    double cache_tol;        /* the visibility below is for this layout
                                tolerance (0: none) */
    cf_visibility_t **vis;   /* per segment (NULL: whole and visible) */
    bool *seen;              /* per point */
} space_el_t;

static size_t
segments(const space_el_t *e)
{
    if (!e->lines || e->n < 2)
        return 0;
    return e->closed ? e->n : e->n - 1;
}

static void
drop_cache(space_el_t *e)
{
    for (size_t i = 0; e->vis != NULL && i < segments(e); i++)
        cf_visibility_destroy(e->vis[i]);
    cf_free(e->vis);
    cf_free(e->seen);
    e->vis = NULL;
    e->seen = NULL;
    e->cache_tol = 0;
}

static void
space_fini(cf__element_t *el)
{
    space_el_t *e = (space_el_t *)el;
    drop_cache(e);
    cf_free(e->p3);
    cf_free(e->p2);
}

static void
space_bounds(const cf__element_t *el, cf__bounds_t *b)
{
    const space_el_t *e = (const space_el_t *)el;
    for (size_t i = 0; i < e->n; i++)
        cf__bounds_add(b, e->p2[2 * i], e->p2[2 * i + 1]);
}

/* Segment i as a curve of degree 1 in R^3 (new). */
static cf_status_t
segment(space_el_t *e, size_t i, cf_bezier_t **out)
{
    double pts[6];
    memcpy(pts, e->p3 + 3 * i, 3 * sizeof *pts);
    memcpy(pts + 3, e->p3 + 3 * ((i + 1) % e->n), 3 * sizeof *pts);
    return cf_bezier_create(3, 1, pts, NULL, out, &e->fig->err);
}

/* The visibility of every segment and point for layout tolerance tol. */
static cf_status_t
build(cf_figure_t *fig, space_el_t *e, double tol)
{
    cf_scene_t *sc = NULL;
    cf_status_t st = CF_STATUS_OK;
    size_t ns = segments(e);
    if (e->cache_tol > 0 && e->cache_tol <= tol)
        return CF_STATUS_OK;
    drop_cache(e);
    e->vis = cf_calloc(ns > 0 ? ns : 1, sizeof *e->vis);
    e->seen = cf_alloc_array(e->n, sizeof *e->seen);
    if (e->vis == NULL || e->seen == NULL) {
        drop_cache(e);
        return cf__fig_nomem(fig, "a line in space");
    }
    for (size_t i = 0; i < e->n; i++)
        e->seen[i] = true;
    if (e->hidden != CF_HIDDEN_SHOW)
        st = cf__figure_scene(fig, 20 * tol, &sc);
    for (size_t i = 0; st == CF_STATUS_OK && sc != NULL && i < e->n; i++)
        st = cf_scene_point_visible(sc, e->p3 + 3 * i, NULL, &e->seen[i],
                                    NULL, &fig->err);
    for (size_t i = 0; st == CF_STATUS_OK && sc != NULL && i < ns; i++) {
        cf_bezier_t *seg = NULL;
        st = segment(e, i, &seg);
        if (st == CF_STATUS_OK)
            st = cf_scene_curve_visibility(sc, seg, NULL, &e->vis[i],
                                           &fig->err);
        cf_bezier_destroy(seg);
    }
    if (st != CF_STATUS_OK) {
        drop_cache(e);
        return cf__fig_fail(fig, st, "a line in space");
    }
    /* (what the rough first ink refit made serves nothing after it:
    ** cf__tol_make) */
    e->cache_tol = fig->refit_rough ? 0 : tol;
    return CF_STATUS_OK;
}

void
cf__space_marker(const cf__layout_t *l, const cf_style_t *s,
                 const double *xy, bool seen, cf_hidden_t hidden,
                 cf__dl_t *dl)
{
    cf__marker_op_t m;
    cf_style_t ms = *s;
    double px, py;
    if (!seen && hidden == CF_HIDDEN_REMOVE)
        return;
    if (!seen && hidden == CF_HIDDEN_DASHED)
        ms.opacity *= 0.4;
    if (!cf__in_window(l, xy[0], xy[1]))
        return;
    cf__map(l, xy[0], xy[1], &px, &py);
    cf__marker_from_style(&ms, ms.marker, px, py, NULL, &m);
    cf__dl_marker(dl, &m);
}

/* The page point of segment i at t. */
static void
at(const space_el_t *e, const cf__layout_t *l, size_t i, double t,
   double *px, double *py)
{
    const double *a = e->p3 + 3 * i, *b = e->p3 + 3 * ((i + 1) % e->n);
    double p[3], q[2];
    for (int k = 0; k < 3; k++)
        p[k] = (1 - t) * a[k] + t * b[k];
    cf__fig_project1(e->fig, p, 3, q);
    cf__map(l, q[0], q[1], px, py);
}

/* The pieces of the segments that are visible (or hidden), one path: a
** piece that starts where the last one ended continues it.  Whether any
** was drawn. */
static bool
pieces_path(const space_el_t *e, const cf__layout_t *l, bool visible,
            cf__dl_t *dl)
{
    bool any = false, open = false, whole = true;
    size_t ns = segments(e);
    double t_end = e->arrow ? e->t_end : 1.0;
    cf__dl_path_begin(dl);
    for (size_t i = 0; i < ns; i++) {
        const cf_visibility_t *v = e->vis[i];
        cf_vis_interval_t one;
        one.t0 = 0.0;
        one.t1 = 1.0;
        one.visible = true;
        one.occluder = SIZE_MAX;
        size_t n = v != NULL ? v->n : 1;
        for (size_t k = 0; k < n; k++) {
            const cf_vis_interval_t *iv = v != NULL ? &v->items[k] : &one;
            double x, y;
            if (iv->visible != visible || iv->t0 >= t_end) {
                open = false;
                whole = false;
                continue;
            }
            if (!open || iv->t0 > 0) {
                at(e, l, i, iv->t0, &x, &y);
                cf__dl_move(dl, x, y);
            }
            at(e, l, i, fmin(iv->t1, t_end), &x, &y);
            cf__dl_line(dl, x, y);
            open = iv->t1 >= 1;
            any = true;
        }
    }
    if (any && whole && e->closed)
        cf__dl_close(dl);
    return any;
}

/* End the path: stroked in s (NULL: not painted), butt-capped for the
** shaft of an arrow. */
static void
stroke(const space_el_t *e, const cf_style_t *s, cf__dl_t *dl)
{
    cf__paint_t paint;
    memset(&paint, 0, sizeof paint);
    if (s != NULL && s->color.a > 0 && s->width > 0) {
        paint.stroke = true;
        cf__stroke_from_style(s, &paint.line);
        if (e->arrow)
            paint.line.cap = CF__CAP_BUTT;
    }
    cf__dl_path_paint(dl, &paint);
}

static cf_status_t
space_draw(cf_figure_t *fig, cf__element_t *el, const cf__layout_t *l,
           const cf_style_t *s, cf__dl_t *dl)
{
    space_el_t *e = (space_el_t *)el;
    cf_status_t st = build(fig, e, l->tol);
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0, len = 0, head = 0;
    if (st != CF_STATUS_OK)
        return st;
    if (e->arrow) {
        /* the image of the shaft is a segment: the head points along it
        ** and the shaft stops at the head's notch */
        cf__map(l, e->p2[0], e->p2[1], &x0, &y0);
        cf__map(l, e->p2[2], e->p2[3], &x1, &y1);
        len = hypot(x1 - x0, y1 - y0);
        if (!(len > 1e-9))
            return CF_STATUS_OK;
        head = fmin(s->arrow_size, len);
        e->t_end = 1 - 0.8 * head / len;
    }
    if (segments(e) > 0) {
        cf_style_t h = cf__hidden_style(s);
        cf__clip_to_window(l, s->width > 0 ? s->width : 0, dl);
        if (e->hidden == CF_HIDDEN_DASHED)
            stroke(e, pieces_path(e, l, false, dl) ? &h : NULL, dl);
        stroke(e, pieces_path(e, l, true, dl) ? s : NULL, dl);
        cf__dl_unclip(dl);
    }
    if (e->arrow) {
        /* the head as a marker at the tip: faded, left out or drawn */
        double opacity = s->opacity;
        if (!e->seen[1] && e->hidden == CF_HIDDEN_REMOVE)
            return CF_STATUS_OK;
        if (!e->seen[1] && e->hidden == CF_HIDDEN_DASHED)
            opacity *= 0.4;
        if (head > 0)
            cf__arrow_head(dl, x1, y1, (x1 - x0) / len, (y1 - y0) / len,
                           head, &s->color, opacity);
        return CF_STATUS_OK;
    }
    for (size_t i = 0; i < e->n; i++)
        cf__space_marker(l, s, e->p2 + 2 * i, e->seen[i], e->hidden, dl);
    return CF_STATUS_OK;
}

static const cf__kind_t polyline_kind = {
    "polyline", 0, space_fini, space_bounds, space_draw, NULL, NULL, NULL
};
static const cf__kind_t polygon_kind = {
    "polygon", 0, space_fini, space_bounds, space_draw, NULL, NULL, NULL
};
static const cf__kind_t arrow_kind = {
    "arrow", 0, space_fini, space_bounds, space_draw, NULL, NULL, NULL
};
static const cf__kind_t points_kind = {
    "points", 0, space_fini, space_bounds, space_draw, NULL, NULL, NULL
};

static bool
is_space(const cf__element_t *el)
{
    return el->kind->fini == space_fini;
}

cf_status_t
cf__space_point_visible(cf_figure_t *fig, const double *p, double tol,
                        bool *seen)
{
    cf_scene_t *sc = NULL;
    cf_status_t st = cf__figure_scene(fig, 20 * tol, &sc);
    *seen = true;
    if (st == CF_STATUS_OK && sc != NULL)
        st = cf_scene_point_visible(sc, p, NULL, seen, NULL, &fig->err);
    return st;
}

cf_status_t
cf__space_pieces(cf_figure_t *fig, cf__element_t *el, size_t index,
                 double tol, cf__surface_piece_fn fn, void *closure)
{
    space_el_t *e = (space_el_t *)el;
    cf_status_t st;
    if (!is_space(el) || e->hidden == CF_HIDDEN_SHOW)
        return CF_STATUS_OK;
    drop_cache(e);
    st = build(fig, e, tol);
    for (size_t i = 0; st == CF_STATUS_OK && i < segments(e); i++) {
        cf_bezier_t *seg = NULL;
        st = segment(e, i, &seg);
        for (size_t k = 0; st == CF_STATUS_OK && e->vis[i] != NULL
             && k < e->vis[i]->n; k++)
            fn(closure, index, CF__LINE_SPACE, seg, NULL, 0.0,
               e->vis[i]->items[k].t0, e->vis[i]->items[k].t1,
               e->vis[i]->items[k].visible);
        cf_bezier_destroy(seg);
    }
    for (size_t i = 0; st == CF_STATUS_OK && i < e->n; i++) {
        /* a point as a segment of length 0 */
        double pts[6];
        cf_bezier_t *pt = NULL;
        memcpy(pts, e->p3 + 3 * i, 3 * sizeof *pts);
        memcpy(pts + 3, e->p3 + 3 * i, 3 * sizeof *pts);
        st = cf_bezier_create(3, 1, pts, NULL, &pt, &fig->err);
        if (st == CF_STATUS_OK)
            fn(closure, index, CF__LINE_SPACE_POINT, pt, NULL, 0.0, 0.0,
               1.0, e->seen[i]);
        cf_bezier_destroy(pt);
    }
    drop_cache(e);
    return st;
}

/* ---- adding ------------------------------------------------------------- */

/* A record of a space element (not in the figure), or NULL (the error in
** fig). */
static space_el_t *
make_space(cf_figure_t *fig, const cf__kind_t *kind, cf_role_t role,
           const double *pts, size_t n, size_t min, bool lines, bool closed,
           cf_hidden_t hidden, const cf_style_t *style, const char *what,
           cf_status_t *st)
{
    space_el_t *e;
    *st = CF_STATUS_OK;
    if (!fig->has_view)
        *st = cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                          "%s in space: the figure has no view; give "
                          "figure{view = {azimuth, elevation}, ...}", what);
    else if ((unsigned)hidden > CF_HIDDEN_REMOVE)
        *st = cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                          "%s: hidden is not show, dashed or remove", what);
    else if (pts == NULL || n < min)
        *st = cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                          "%s: %zu points, at least %zu needed", what,
                          pts == NULL ? 0 : n, min);
    else if (cf_check_finite_points(pts, n, 3, 3, what, &fig->err)
             != CF_STATUS_OK
             || cf__fig_check_style(fig, style) != CF_STATUS_OK)
        *st = fig->err.status;
    if (*st != CF_STATUS_OK)
        return NULL;
    e = cf__element_new(fig, kind, sizeof *e, role, style);
    if (e == NULL) {
        *st = fig->err.status;
        return NULL;
    }
    e->fig = fig;
    e->n = n;
    e->lines = lines;
    e->closed = closed;
    e->hidden = hidden;
    e->p3 = cf__copy_doubles(pts, 3 * n);
    e->p2 = cf_alloc_array(2 * n, sizeof *e->p2);
    if (e->p3 == NULL || e->p2 == NULL)
        *st = cf__fig_nomem(fig, what);
    for (size_t i = 0; i < n && *st == CF_STATUS_OK; i++) {
        cf__fig_project1(fig, pts + 3 * i, 3, e->p2 + 2 * i);
        if (isnan(e->p2[2 * i]))
            *st = cf__fig_behind_eye(fig, pts + 3 * i, what);
    }
    return e;
}

static cf_status_t
add_space(cf_figure_t *fig, const cf__kind_t *kind, cf_role_t role,
          const double *pts, size_t n, size_t min, bool lines, bool closed,
          cf_hidden_t hidden, const cf_style_t *style, const char *what)
{
    cf_status_t st;
    space_el_t *e;
    CF__FIG_CHECK(fig);
    e = make_space(fig, kind, role, pts, n, min, lines, closed, hidden,
                   style, what, &st);
    return e == NULL ? st : cf__element_commit(fig, e, st);
}

cf__element_t *
cf__space_outline_new(cf_figure_t *fig, const double *pts, size_t n,
                      bool closed, cf_hidden_t hidden, const char *what)
{
    cf_status_t st;
    space_el_t *e = make_space(fig, &polyline_kind, CF_ROLE_POLYLINE, pts,
                               n, 2, true, closed, hidden, NULL, what, &st);
    if (e != NULL && st != CF_STATUS_OK) {
        space_fini(&e->base);
        cf_free(e);
        e = NULL;
    }
    return e != NULL ? &e->base : NULL;
}

cf_status_t
cf_figure_add_space_polyline(cf_figure_t *fig, const double *pts, size_t n,
                             bool closed, cf_hidden_t hidden,
                             const cf_style_t *style)
{
    return add_space(fig, &polyline_kind, CF_ROLE_POLYLINE, pts, n, 2, true,
                     closed, hidden, style, "polyline");
}

cf_status_t
cf_figure_add_space_polygon(cf_figure_t *fig, const double *pts, size_t n,
                            cf_hidden_t hidden, const cf_style_t *style)
{
    return add_space(fig, &polygon_kind, CF_ROLE_POLYGON, pts, n, 1, true,
                     false, hidden, style, "control polygon");
}

cf_status_t
cf_figure_add_space_arrow(cf_figure_t *fig, const double *p, const double *q,
                          cf_hidden_t hidden, const cf_style_t *style)
{
    double pq[6];
    cf_status_t st;
    if (p == NULL || q == NULL)
        return add_space(fig, &arrow_kind, CF_ROLE_ARROW, NULL, 0, 2, true,
                         false, hidden, style, "arrow");
    memcpy(pq, p, 3 * sizeof *pq);
    memcpy(pq + 3, q, 3 * sizeof *pq);
    st = add_space(fig, &arrow_kind, CF_ROLE_ARROW, pq, 2, 2, true, false,
                   hidden, style, "arrow");
    if (st == CF_STATUS_OK)
        ((space_el_t *)fig->els[fig->count - 1])->arrow = true;
    return st;
}

cf_status_t
cf_figure_add_space_points(cf_figure_t *fig, const double *pts, size_t n,
                           cf_hidden_t hidden, const cf_style_t *style)
{
    return add_space(fig, &points_kind, CF_ROLE_POINTS, pts, n, 1, false,
                     false, hidden, style, "points");
}
