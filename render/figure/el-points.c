/*
** Point elements: control polygons, polylines, point markers, knot marks,
** convex hulls, filled polygons and de Casteljau / de Boor nets.  One
** record (the points) serves the first six kinds; a net adds its levels.
*/
#include <math.h>
#include <string.h>

#include "curvefig/geometry.h"
#include "model.h"

typedef struct pts_el {
    cf__element_t base;
    double *pts;             /* 2D points (knots: then n tangents) */
    size_t n;
    bool closed, has_dirs;
} pts_el_t;

typedef struct net_el {
    pts_el_t p;              /* every level's points, in order */
    size_t *counts;          /* points per level */
    size_t levels;
    cf_color_t *colors;      /* per level, or NULL (palette) */
} net_el_t;

static void
pts_fini(cf__element_t *el)
{
    cf_free(((pts_el_t *)el)->pts);
}

static void
pts_bounds(const cf__element_t *el, cf__bounds_t *b)
{
    const pts_el_t *e = (const pts_el_t *)el;
    size_t i;
    for (i = 0; i < e->n; i++)
        cf__bounds_add(b, e->pts[2 * i], e->pts[2 * i + 1]);
}

/* ---- drawing ------------------------------------------------------------ */

static void
lines_path(cf__dl_t *dl, const cf__layout_t *l, const double *pts, size_t n,
           bool closed)
{
    size_t i;
    cf__dl_path_begin(dl);
    for (i = 0; i < n; i++) {
        double px, py;
        cf__map(l, pts[2 * i], pts[2 * i + 1], &px, &py);
        if (i == 0)
            cf__dl_move(dl, px, py);
        else
            cf__dl_line(dl, px, py);
    }
    if (closed)
        cf__dl_close(dl);
}

/* The paint of lines in a resolved style: none when invisible; with a
** fill colour first when fill. */
static void
lines_paint(const cf_style_t *s, bool fill, cf__dl_t *dl)
{
    cf__paint_t paint;
    memset(&paint, 0, sizeof paint);
    if (fill) {
        paint.fill = true;
        paint.fill_color = s->fill;
        paint.fill_opacity = s->opacity;
    }
    if (s->color.a > 0 && s->width > 0) {
        paint.stroke = true;
        cf__stroke_from_style(s, &paint.line);
    }
    cf__dl_path_paint(dl, &paint);
}

static void
markers(cf__dl_t *dl, const cf__layout_t *l, const cf_style_t *s,
        const double *pts, size_t n, const double *dirs)
{
    size_t i;
    for (i = 0; i < n; i++) {
        double px, py, d[2];
        cf__marker_op_t m;
        if (!cf__in_window(l, pts[2 * i], pts[2 * i + 1]))
            continue;
        cf__map(l, pts[2 * i], pts[2 * i + 1], &px, &py);
        if (dirs != NULL) {
            /* a data direction on the page (y flips) */
            d[0] = l->sx * dirs[2 * i];
            d[1] = -l->sy * dirs[2 * i + 1];
        }
        cf__marker_from_style(s, s->marker, px, py,
                              dirs != NULL ? d : NULL, &m);
        cf__dl_marker(dl, &m);
    }
}

static double
line_pad(const cf_style_t *s)
{
    return s->width > 0 ? s->width : 0;
}

/* Polygons and polylines: the lines (clipped to the window), then the
** vertex markers. */
static cf_status_t
lines_draw(cf_figure_t *fig, cf__element_t *el, const cf__layout_t *l,
           const cf_style_t *s, cf__dl_t *dl)
{
    pts_el_t *e = (pts_el_t *)el;
    (void)fig;
    if (e->n >= 2) {
        cf__clip_to_window(l, line_pad(s), dl);
        lines_path(dl, l, e->pts, e->n, e->closed);
        lines_paint(s, false, dl);
        cf__dl_unclip(dl);
    }
    markers(dl, l, s, e->pts, e->n, NULL);
    return CF_STATUS_OK;
}

static cf_status_t
points_draw(cf_figure_t *fig, cf__element_t *el, const cf__layout_t *l,
            const cf_style_t *s, cf__dl_t *dl)
{
    pts_el_t *e = (pts_el_t *)el;
    (void)fig;
    markers(dl, l, s, e->pts, e->n, e->has_dirs ? e->pts + 2 * e->n : NULL);
    return CF_STATUS_OK;
}

static cf_status_t
fill_draw(cf_figure_t *fig, cf__element_t *el, const cf__layout_t *l,
          const cf_style_t *s, cf__dl_t *dl)
{
    pts_el_t *e = (pts_el_t *)el;
    (void)fig;
    cf__clip_to_window(l, line_pad(s), dl);
    lines_path(dl, l, e->pts, e->n, true);
    lines_paint(s, true, dl);
    cf__dl_unclip(dl);
    return CF_STATUS_OK;
}

static cf_status_t
hull_draw(cf_figure_t *fig, cf__element_t *el, const cf__layout_t *l,
          const cf_style_t *s, cf__dl_t *dl)
{
    pts_el_t *e = (pts_el_t *)el;
    size_t *idx = cf_alloc_array(e->n, sizeof *idx), h = 0, i;
    double *hull = cf_alloc_array(2 * e->n, sizeof *hull);
    cf_status_t st = CF_STATUS_OK;
    if (idx == NULL || hull == NULL)
        st = cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                         "out of memory drawing a hull");
    if (st == CF_STATUS_OK)
        st = cf_convex_hull_2d(e->pts, e->n, 2, idx, &h, &fig->err);
    if (st == CF_STATUS_OK) {
        for (i = 0; i < h; i++) {
            hull[2 * i] = e->pts[2 * idx[i]];
            hull[2 * i + 1] = e->pts[2 * idx[i] + 1];
        }
        cf__clip_to_window(l, line_pad(s), dl);
        lines_path(dl, l, hull, h, true);
        lines_paint(s, true, dl);
        cf__dl_unclip(dl);
    }
    cf_free(idx);
    cf_free(hull);
    return st;
}

static const cf__kind_t polygon_kind = {
    "polygon", 0, pts_fini, pts_bounds, lines_draw, NULL, NULL, NULL
};
static const cf__kind_t polyline_kind = {
    "polyline", 0, pts_fini, pts_bounds, lines_draw, NULL, NULL, NULL
};
static const cf__kind_t points_kind = {
    "points", 0, pts_fini, pts_bounds, points_draw, NULL, NULL, NULL
};
static const cf__kind_t knots_kind = {
    "knot marks", 0, pts_fini, pts_bounds, points_draw, NULL, NULL, NULL
};
static const cf__kind_t hull_kind = {
    "hull", CF__KIND_SHADING, pts_fini, pts_bounds, hull_draw, NULL, NULL, NULL
};
static const cf__kind_t fill_kind = {
    "fill", CF__KIND_SHADING, pts_fini, pts_bounds, fill_draw, NULL, NULL, NULL
};

/* ---- nets --------------------------------------------------------------- */

static void
net_fini(cf__element_t *el)
{
    net_el_t *e = (net_el_t *)el;
    pts_fini(el);
    cf_free(e->counts);
    cf_free(e->colors);
}

/* The colour of level j: given, or the polygon's for level 0 and the
** palette's after it. */
static cf_color_t
level_color(const cf_figure_t *fig, const net_el_t *e, size_t j,
            const cf_color_t *own, unsigned own_bits, bool marker)
{
    const cf_style_t *poly = &fig->theme.role[CF_ROLE_POLYGON];
    if (e->colors != NULL)
        return e->colors[j];
    if (e->p.base.style.set & own_bits)
        return *own;
    if (j == 0)
        return marker ? poly->marker_color : poly->color;
    return fig->theme.palette[(j - 1) % fig->theme.palette_size];
}

/* A theme's redundant = true: level j's dash pattern and marker shape
** (cf_theme_level_style) where the element sets none, the dashes for the
** lines, the shape for the markers; a level drawn without markers stays
** so. */
static void
level_redundant(const cf_figure_t *fig, const net_el_t *e, size_t j,
                bool marker, cf_style_t *ls)
{
    cf_style_t t = e->p.base.style;
    unsigned added;
    cf_theme_level_style(&fig->theme, j, &t);
    added = t.set & ~e->p.base.style.set;
    if (!marker && (added & CF_STYLE_DASH)) {
        ls->dash_count = t.dash_count;
        memcpy(ls->dash, t.dash, sizeof ls->dash);
    }
    if (marker && (added & CF_STYLE_MARKER) && ls->marker != CF_MARKER_NONE)
        ls->marker = t.marker;
}

/* Lines of every level first (clipped to the window), then the markers
** on top. */
static cf_status_t
net_draw(cf_figure_t *fig, cf__element_t *el, const cf__layout_t *l,
         const cf_style_t *s, cf__dl_t *dl)
{
    net_el_t *e = (net_el_t *)el;
    size_t j, off;
    cf__clip_to_window(l, line_pad(s), dl);
    for (j = 0, off = 0; j < e->levels; off += e->counts[j], j++) {
        cf_style_t ls = *s;
        ls.color = level_color(fig, e, j, &s->color, CF_STYLE_COLOR, false);
        level_redundant(fig, e, j, false, &ls);
        if (e->counts[j] >= 2) {
            lines_path(dl, l, e->p.pts + 2 * off, e->counts[j], false);
            lines_paint(&ls, false, dl);
        }
    }
    cf__dl_unclip(dl);
    for (j = 0, off = 0; j < e->levels; off += e->counts[j], j++) {
        cf_style_t ls = *s;
        ls.marker_color = level_color(fig, e, j, &s->marker_color,
                                      CF_STYLE_COLOR | CF_STYLE_MARKER_COLOR,
                                      true);
        level_redundant(fig, e, j, true, &ls);
        markers(dl, l, &ls, e->p.pts + 2 * off, e->counts[j], NULL);
    }
    return CF_STATUS_OK;
}

static const cf__kind_t net_kind = {
    "net", 0, net_fini, pts_bounds, net_draw, NULL, NULL, NULL
};

/* ---- adding ------------------------------------------------------------- */

static cf_status_t
add_points_el(cf_figure_t *fig, const cf__kind_t *kind, cf_role_t role,
              const double *pts, size_t n, size_t min, bool closed,
              const cf_style_t *style, const char *what)
{
    pts_el_t *e;
    CF__FIG_CHECK(fig);
    if (cf__fig_check_points(fig, pts, n, min, what) != CF_STATUS_OK
        || cf__fig_check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    e = cf__element_new(fig, kind, sizeof *e, role, style);
    if (e == NULL)
        return fig->err.status;
    e->pts = cf__copy_doubles(pts, 2 * n);
    e->n = n;
    e->closed = closed;
    if (e->pts == NULL)
        return cf__element_commit(fig, e, cf__fig_nomem(fig, what));
    if (cf__element_commit(fig, e, CF_STATUS_OK) != CF_STATUS_OK)
        return fig->err.status;
    return cf__fact_marks(fig, pts, n);
}

cf_status_t
cf_figure_add_polygon(cf_figure_t *fig, const double *pts, size_t n,
                      const cf_style_t *style)
{
    return add_points_el(fig, &polygon_kind, CF_ROLE_POLYGON, pts, n, 1, false,
                         style, "control polygon");
}

cf_status_t
cf_figure_add_polyline(cf_figure_t *fig, const double *pts, size_t n,
                       bool closed, const cf_style_t *style)
{
    return add_points_el(fig, &polyline_kind, CF_ROLE_POLYLINE, pts, n, 2,
                         closed, style, "polyline");
}

cf_status_t
cf_figure_add_hull(cf_figure_t *fig, const double *pts, size_t n,
                   const cf_style_t *style)
{
    return add_points_el(fig, &hull_kind, CF_ROLE_HULL, pts, n, 1, true, style,
                         "convex hull");
}

cf_status_t
cf_figure_add_fill(cf_figure_t *fig, const double *pts, size_t n,
                   const cf_style_t *style)
{
    return add_points_el(fig, &fill_kind, CF_ROLE_FILL, pts, n, 3, true, style,
                         "filled polygon");
}

cf_status_t
cf_figure_add_points(cf_figure_t *fig, const double *pts, size_t n,
                     const cf_style_t *style)
{
    return add_points_el(fig, &points_kind, CF_ROLE_POINTS, pts, n, 1, false,
                         style, "points");
}

cf_status_t
cf_figure_add_knot_marks(cf_figure_t *fig, const double *pts,
                         const double *tangents, size_t n,
                         const cf_style_t *style)
{
    pts_el_t *e;
    CF__FIG_CHECK(fig);
    if (cf__fig_check_points(fig, pts, n, 1, "knot mark") != CF_STATUS_OK
        || cf__fig_check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    if (tangents != NULL
        && cf_check_finite_points(tangents, n, 2, 2, "knot tangent",
                                  &fig->err) != CF_STATUS_OK)
        return fig->err.status;
    e = cf__element_new(fig, &knots_kind, sizeof *e, CF_ROLE_KNOTS, style);
    if (e == NULL)
        return fig->err.status;
    e->pts = cf_alloc_array(4 * n, sizeof *e->pts);
    if (e->pts == NULL)
        return cf__element_commit(fig, e, cf__fig_nomem(fig, "knot marks"));
    memcpy(e->pts, pts, 2 * n * sizeof *pts);
    if (tangents != NULL)
        memcpy(e->pts + 2 * n, tangents, 2 * n * sizeof *pts);
    e->has_dirs = tangents != NULL;
    e->n = n;
    return cf__element_commit(fig, e, CF_STATUS_OK);
}
cf_status_t
cf_figure_add_net(cf_figure_t *fig, const double *pts, const size_t *counts,
                  size_t levels, const cf_color_t *colors,
                  const cf_style_t *style)
{
    net_el_t *e;
    size_t total = 0, j;
    CF__FIG_CHECK(fig);
    if (counts == NULL || levels == 0)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "net: counts NULL or no level");
    for (j = 0; j < levels; j++) {
        if (counts[j] == 0 || counts[j] > ((size_t)1 << 24))
            return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, (long)j,
                               "net level %zu has %zu points", j, counts[j]);
        total += counts[j];
    }
    if (cf__fig_check_points(fig, pts, total, 1, "net point") != CF_STATUS_OK
        || cf__fig_check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    if (colors != NULL) {
        for (j = 0; j < levels; j++) {
            cf_style_t t;
            cf_style_init(&t);
            t.set = CF_STYLE_COLOR;
            t.color = colors[j];
            if (cf__style_check(&t, &fig->err) != CF_STATUS_OK)
                return fig->err.status;
        }
    }
    e = cf__element_new(fig, &net_kind, sizeof *e, CF_ROLE_NET, style);
    if (e == NULL)
        return fig->err.status;
    e->p.pts = cf__copy_doubles(pts, 2 * total);
    e->p.n = total;
    e->levels = levels;
    e->counts = cf_alloc_array(levels, sizeof *e->counts);
    if (colors != NULL) {
        e->colors = cf_alloc_array(levels, sizeof *e->colors);
        if (e->colors != NULL)
            memcpy(e->colors, colors, levels * sizeof *colors);
    }
    if (e->p.pts == NULL || e->counts == NULL
        || (colors != NULL && e->colors == NULL))
        return cf__element_commit(fig, e, cf__fig_nomem(fig, "a net"));
    memcpy(e->counts, counts, levels * sizeof *counts);
    if (cf__element_commit(fig, e, CF_STATUS_OK) != CF_STATUS_OK)
        return fig->err.status;
    return cf__fact_marks(fig, pts, total);
}

/* ---- axes --------------------------------------------------------------- */
