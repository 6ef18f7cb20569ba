/*
** The drawing methods of figures: curves, polygons and points with their
** labels, lines, labels, arrows and tangents, knot marks, and the nets of
** de Casteljau and de Boor.  Each checks its options (lschema.h), reads
** them (lstyle.h), draws through one cf_figure_add_* call and labels the
** points it marks (llabels.h).
*/
#include <string.h>

#include "curvefig/bspline.h"
#include "curvefig/figure.h"
#include "curvefig/figure3d.h"
#include "lbezier.h"
#include "lbspline.h"
#include "lcommon.h"
#include "ldraw.h"
#include "llabels.h"
#include "lschema.h"
#include "lstyle.h"
#include "lsurface-draw.h"

#define check(L, fn, call, diag) cf__lua_fig_check((L), (fn), fig, (call), \
                                                   (diag))

/* The range = {a, b} option of f:curve ({0, 0}: the whole curve). */
static void
read_range(lua_State *L, int opts, double *a, double *b)
{
    size_t n;
    double *r;
    *a = *b = 0.0;
    if (cf__lua_field(L, opts, "range") != LUA_TNIL) {
        r = cf__lua_check_numbers(L, -1, "curve", "range", &n);
        if (n != 2)
            luaL_error(L, "curve: range is {a, b}");
        *a = r[0];
        *b = r[1];
    }
}

static cf_status_t
add_curve(lua_State *L, cf_figure_t *fig, int idx, double a, double b,
          const cf_style_t *st)
{
    cf_bspline_t *bs = cf__lua_to_bspline(L, idx);
    if (a == 0.0 && b == 0.0 && cf__lua_space_curve(L, fig, idx, 3, st))
        return CF_STATUS_OK;
    if (bs != NULL)
        return cf_figure_add_bspline(fig, bs, a, b, st);
    if (a != 0.0 || b != 0.0)
        return cf_figure_add_bezier_range(fig, cf__lua_check_bezier(L, idx),
                                          a, b, st);
    return cf_figure_add_bezier(fig, cf__lua_check_bezier(L, idx), st);
}

/* f:curve(c, {range = {a, b}, style...}); c a Bézier, a B-spline or a list
** of them. */
static int
m_curve(lua_State *L)
{
    cf_figure_t *fig = cf__lua_check_figure(L);
    double a, b;
    cf_style_t st;
    cf_diag_t diag;
    lua_settop(L, 3);
    cf__lua_check_table(L, 3, CF__KEYS_CURVE);
    cf__lua_read_style(L, 3, "curve", fig, &st);
    read_range(L, 3, &a, &b);
    if (!cf__lua_to_bezier(L, 2) && !cf__lua_to_bspline(L, 2) &&
        lua_istable(L, 2)) {
        /* a list of curves */
        for (lua_Integer i = 1; i <= luaL_len(L, 2); i++) {
            lua_pushcfunction(L, m_curve);
            lua_pushvalue(L, 1);
            lua_geti(L, 2, i);
            lua_pushvalue(L, 3);
            lua_call(L, 3, 0);
        }
    } else {
        cf_diag_clear(&diag);
        check(L, "curve", add_curve(L, fig, 2, a, b, &st), &diag);
    }
    lua_settop(L, 1);
    return 1;
}

/* The label integers of n points: 0, 1, ..., n - 1. */
static lua_Integer *
point_indices(lua_State *L, size_t n)
{
    lua_Integer *a = lua_newuserdatauv(L, (n ? n : 1) * sizeof *a, 0);
    for (size_t i = 0; i < n; i++)
        a[i] = (lua_Integer)i;
    return a;
}

typedef cf_status_t (*pts_fn)(cf_figure_t *, const double *, size_t,
                              const cf_style_t *);

/* Points in R^3 of a figure with a view: split and hidden by its surfaces
** (space: 0 polygon, 1 points, 2 polyline, 3 closed polyline, 4 hull, 5
** fill); false for any other points. */
static bool
space_points(lua_State *L, cf_figure_t *fig, const char *fn, int space,
             const cf_style_t *st)
{
    size_t n;
    double *p3 = space >= 0 ? cf__lua_check_points3d(L, fig, 2, fn, &n)
                            : NULL, *p2;
    cf_hidden_t hidden;
    cf_diag_t diag;
    if (p3 == NULL)
        return false;
    hidden = cf__lua_read_hidden(L, 3, fn, "dashed");
    cf_diag_clear(&diag);
    check(L, fn, space == 0 ? cf_figure_add_space_polygon(fig, p3, n, hidden,
                                                          st)
                 : space == 1 ? cf_figure_add_space_points(fig, p3, n, hidden,
                                                           st)
                 : space == 4 ? cf_figure_add_space_hull(fig, p3, n, hidden,
                                                         st)
                 : space == 5 ? cf_figure_add_space_fill(fig, p3, n, hidden,
                                                         st)
                 : cf_figure_add_space_polyline(fig, p3, n, space == 3,
                                                hidden, st), &diag);
    p2 = cf__lua_buffer(L, 2 * n);
    check(L, fn, cf_figure_project(fig, p3, n, 3, p2), NULL);
    cf__lua_label_space_items(L, fig, 3, "labels", p2, p3, hidden, n,
                              point_indices(L, n), 1, fn);
    return true;
}

static int
draw_points(lua_State *L, const char *fn, cf__lua_keys_t keys, pts_fn add,
            int space)
{
    cf_figure_t *fig = cf__lua_check_figure(L);
    size_t n;
    double *p;
    cf_style_t st;
    cf_diag_t diag;
    lua_settop(L, 3);
    cf__lua_check_table(L, 3, keys);
    cf__lua_read_style(L, 3, fn, fig, &st);
    if (!space_points(L, fig, fn, space, &st)) {
        if (space >= 4 && !cf_figure_get_view(fig, NULL)
            && cf__lua_field(L, 3, "hidden") != LUA_TNIL)
            luaL_error(L, "%s: hidden needs a region in R^3 in a figure "
                       "with a view; give figure{view = {azimuth, "
                       "elevation}, ...}", fn);
        p = cf__lua_check_points2d(L, fig, 2, fn, &n);
        cf_diag_clear(&diag);
        check(L, fn, add(fig, p, n, &st), &diag);
        cf__lua_label_items(L, fig, 3, "labels", p, n, point_indices(L, n),
                            1, fn);
    }
    lua_settop(L, 1);
    return 1;
}

static int
m_polygon(lua_State *L)
{
    return draw_points(L, "polygon", CF__KEYS_POLYGON, cf_figure_add_polygon,
                       0);
}

static int
m_points(lua_State *L)
{
    return draw_points(L, "points", CF__KEYS_POINTS, cf_figure_add_points, 1);
}

static int
m_hull(lua_State *L)
{
    return draw_points(L, "hull", CF__KEYS_HULL, cf_figure_add_hull, 4);
}

static int
m_fill(lua_State *L)
{
    return draw_points(L, "fill", CF__KEYS_FILL, cf_figure_add_fill, 5);
}

static cf_status_t
add_open(cf_figure_t *fig, const double *p, size_t n, const cf_style_t *st)
{
    return cf_figure_add_polyline(fig, p, n, false, st);
}

static cf_status_t
add_closed(cf_figure_t *fig, const double *p, size_t n, const cf_style_t *st)
{
    return cf_figure_add_polyline(fig, p, n, true, st);
}

/* f:polyline(points, {closed = false, ...}) */
static int
m_polyline(lua_State *L)
{
    bool closed;
    lua_settop(L, 3);
    closed = cf__lua_opt_bool(L, 3, "closed", "polyline", false);
    return draw_points(L, "polyline", CF__KEYS_POLYLINE,
                       closed ? add_closed : add_open, closed ? 3 : 2);
}

/* f:line(p, q, {...}): the segment pq */
static int
m_line(lua_State *L)
{
    cf_figure_t *fig = cf__lua_check_figure(L);
    double *p, *q, pq[4];
    size_t n;
    cf_style_t st;
    cf_diag_t diag;
    lua_settop(L, 4);
    cf__lua_check_table(L, 4, CF__KEYS_LINE);
    cf__lua_read_style(L, 4, "line", fig, &st);
    p = cf__lua_check_points3d(L, fig, 2, "line", &n);
    q = p != NULL ? cf__lua_check_points3d(L, fig, 3, "line", &n) : NULL;
    cf_diag_clear(&diag);
    if (q != NULL) {
        /* a segment in space, split by the surfaces */
        double pq3[6];
        memcpy(pq3, p, 3 * sizeof *p);
        memcpy(pq3 + 3, q, 3 * sizeof *q);
        check(L, "line", cf_figure_add_space_polyline(
                  fig, pq3, 2, false,
                  cf__lua_read_hidden(L, 4, "line", "dashed"), &st), &diag);
        lua_settop(L, 1);
        return 1;
    }
    p = cf__lua_check_points2d(L, fig, 2, "line", &n);
    q = cf__lua_check_points2d(L, fig, 3, "line", &n);
    memcpy(pq, p, 2 * sizeof *p);
    memcpy(pq + 2, q, 2 * sizeof *q);
    check(L, "line", cf_figure_add_polyline(fig, pq, 2, false, &st), &diag);
    lua_settop(L, 1);
    return 1;
}

/* f:label(p, text, {place = "ne", ...}) */
static int
m_label(lua_State *L)
{
    cf_figure_t *fig = cf__lua_check_figure(L);
    size_t n;
    double *p, *p3;
    const char *text;
    cf_style_t st;
    cf_diag_t diag;
    lua_settop(L, 4);
    p3 = cf__lua_check_points3d(L, fig, 2, "label", &n);
    p = cf__lua_check_points2d(L, fig, 2, "label", &n);
    text = cf__lua_check_text(L, 3, "label", "the text");
    cf__lua_check_table(L, 4, CF__KEYS_LABEL);
    cf__lua_read_style(L, 4, "label", fig, &st);
    if (cf__lua_labels_on(L)) {
        cf_diag_clear(&diag);
        /* a label at a point in R^3 follows it behind a surface */
        check(L, "label", p3 != NULL
              ? cf_figure_add_space_label(fig, p3, text,
                                          cf__lua_read_hidden(L, 4, "label",
                                                              "dashed"), &st)
              : cf_figure_add_label(fig, p[0], p[1], text, &st), &diag);
    }
    lua_settop(L, 1);
    return 1;
}

/* The arrow from pd[0..1] to pd[2..3] with its label at the tip. */
static void
draw_arrow(lua_State *L, cf_figure_t *fig, int opts, const double pd[4],
           const char *fn)
{
    cf_style_t st;
    cf_diag_t diag;
    cf__lua_read_style(L, opts, fn, fig, &st);
    cf_diag_clear(&diag);
    check(L, fn, cf_figure_add_arrow(fig, pd[0], pd[1], pd[2] - pd[0],
                                     pd[3] - pd[1], &st), &diag);
    cf__lua_label_items(L, fig, opts, "label", pd + 2, 1, NULL, 0, fn);
}

/* f:arrow(p, v, {label = "v", ...}): from p to p + v; arrow_to(p, q) */
static int
arrow(lua_State *L, bool to)
{
    cf_figure_t *fig = cf__lua_check_figure(L);
    const char *fn = to ? "arrow_to" : "arrow";
    size_t n;
    double *p, *v, pd[4];
    lua_settop(L, 4);
    cf__lua_check_table(L, 4, to ? CF__KEYS_ARROW_TO : CF__KEYS_ARROW);
    p = cf__lua_check_points3d(L, fig, 2, fn, &n);
    v = p != NULL ? cf__lua_check_points3d(L, fig, 3, fn, &n) : NULL;
    if (v != NULL) {
        /* an arrow in space: its shaft split by the surfaces */
        double pq3[6], q2[2];
        cf_style_t st;
        cf_diag_t diag;
        cf_hidden_t hidden = cf__lua_read_hidden(L, 4, fn, "dashed");
        for (int k = 0; k < 3; k++) {
            pq3[k] = p[k];
            pq3[3 + k] = to ? v[k] : p[k] + v[k];
        }
        cf__lua_read_style(L, 4, fn, fig, &st);
        cf_diag_clear(&diag);
        check(L, fn, cf_figure_add_space_arrow(fig, pq3, pq3 + 3, hidden,
                                               &st), &diag);
        check(L, fn, cf_figure_project(fig, pq3 + 3, 1, 3, q2), NULL);
        cf__lua_label_space_items(L, fig, 4, "label", q2, pq3 + 3, hidden, 1,
                                  NULL, 0, fn);
        lua_settop(L, 1);
        return 1;
    }
    p = cf__lua_check_points2d(L, fig, 2, fn, &n);
    v = cf__lua_check_points2d(L, fig, 3, fn, &n);
    pd[0] = p[0];
    pd[1] = p[1];
    pd[2] = to ? v[0] : p[0] + v[0];
    pd[3] = to ? v[1] : p[1] + v[1];
    draw_arrow(L, fig, 4, pd, fn);
    lua_settop(L, 1);
    return 1;
}

static int
m_arrow(lua_State *L)
{
    return arrow(L, false);
}

static int
m_arrow_to(lua_State *L)
{
    return arrow(L, true);
}

/* f:tangent(c, t, {scale = 1/degree, label = ...}): the arrow c(t) ->
** c(t) + scale * c'(t) (scale 1/n: a Bézier's end legs). */
static int
m_tangent(lua_State *L)
{
    cf_figure_t *fig = cf__lua_check_figure(L);
    cf_bezier_t *bz;
    double t, scale, tip[2];
    bool given;
    cf_style_t st;
    lua_settop(L, 4);
    t = cf__lua_check_finite(L, 3, "tangent", "t");
    cf__lua_check_table(L, 4, CF__KEYS_TANGENT);
    cf__lua_read_style(L, 4, "tangent", fig, &st);
    scale = cf__lua_opt_number(L, 4, "scale", "tangent", 0.0, &given);
    if (given && !(scale > 0.0))
        return cf__lua_error(L, "tangent: scale = %g; it must be > 0", scale);
    bz = cf__lua_to_bezier(L, 2);
    if (bz != NULL)
        check(L, "tangent", cf_figure_add_bezier_tangent(fig, bz, t, scale,
                                                         &st, tip), NULL);
    else
        check(L, "tangent", cf_figure_add_bspline_tangent(
                                fig, cf__lua_check_bspline(L, 2), t, scale,
                                &st, tip), NULL);
    cf__lua_label_items(L, fig, 4, "label", tip, 1, NULL, 0, "tangent");
    lua_settop(L, 1);
    return 1;
}

/* The distinct knots of s in its domain at their points (*pts, 2D) with
** the label integers (index of the first copy, multiplicity) in *args;
** buffers pushed on the stack.  Returns how many. */
static size_t
knot_marks(lua_State *L, cf_figure_t *fig, const cf_bspline_t *s,
           double **pts, lua_Integer **args)
{
    size_t m = cf_bspline_nknots(s), n = 0;
    size_t *first = lua_newuserdatauv(L, 2 * (m ? m : 1) * sizeof *first, 0);
    size_t *mult = first + (m ? m : 1);
    *pts = cf__lua_buffer(L, 2 * m);
    check(L, "knots", cf_figure_bspline_knots(fig, s, NULL, first, mult,
                                              *pts, &n), NULL);
    *args = lua_newuserdatauv(L, 2 * (n ? n : 1) * sizeof **args, 0);
    for (size_t k = 0; k < n; k++) {
        (*args)[2 * k] = (lua_Integer)first[k];
        (*args)[2 * k + 1] = (lua_Integer)mult[k];
    }
    return n;
}

/* f:knots(s, {labels = "u_%d", ...}): marks at C(u_i) for the distinct
** knots in the domain; labels get (i, multiplicity), i the index of the
** knot's first copy. */
static int
m_knots(lua_State *L)
{
    cf_figure_t *fig = cf__lua_check_figure(L);
    cf_bspline_t *s;
    double *pts;
    lua_Integer *args;
    size_t n;
    cf_style_t st;
    cf_diag_t diag;
    lua_settop(L, 3);
    s = cf__lua_check_bspline(L, 2);
    cf__lua_check_table(L, 3, CF__KEYS_KNOTS);
    cf__lua_read_style(L, 3, "knots", fig, &st);
    cf_diag_clear(&diag);
    check(L, "knots", cf_figure_add_bspline_knots(fig, s, &st), &diag);
    n = knot_marks(L, fig, s, &pts, &args);
    cf__lua_label_items(L, fig, 3, "labels", pts, n, args, 2, "knots");
    lua_settop(L, 1);
    return 1;
}

/* The colours of the levels of a net from opts.colors (NULL: none given);
** a buffer pushed on the stack. */
static cf_color_t *
level_colors(lua_State *L, const cf_figure_t *fig, size_t levels,
             const char *fn)
{
    cf_color_t *colors;
    int t = cf__lua_field(L, 4, "colors");
    if (t == LUA_TNIL)
        return NULL;
    if (t != LUA_TTABLE)
        luaL_error(L, "%s: colors is a list of colours, one per level (color "
                   "gives all levels one)", fn);
    if ((size_t)luaL_len(L, -1) < levels)
        luaL_error(L, "%s: %d colours for %d levels", fn,
                   (int)luaL_len(L, -1), (int)levels);
    colors = lua_newuserdatauv(L, levels * sizeof *colors, 0);
    for (size_t j = 0; j < levels; j++) {
        lua_geti(L, -2, (lua_Integer)j + 1);
        colors[j] = cf__lua_read_color(L, -1, fn, "colors", fig);
        lua_pop(L, 1);
    }
    return colors;
}

/* Draw a net (levels of counts[j] points, dim-D, in pts): colours from
** opts.colors, labels of (index, level), the final point from opts.point
** (a style table or true). */
static void
draw_net(lua_State *L, cf_figure_t *fig, const double *pts,
         const size_t *counts, size_t levels, size_t dim,
         const size_t *first_index, const char *fn)
{
    size_t total = 0, k = 0;
    double *p2;
    lua_Integer *args;
    cf_color_t *colors;
    cf_style_t st, ps;
    cf_diag_t diag;
    cf__lua_read_style(L, 4, fn, fig, &st);
    if (cf__lua_field(L, 4, "levels") != LUA_TNIL)
        levels = (size_t)cf__lua_check_int(L, -1, fn, "levels", 1,
                                           (int)levels);
    for (size_t j = 0; j < levels; j++)
        total += counts[j];
    p2 = cf__lua_buffer(L, 2 * total);
    check(L, fn, cf_figure_project(fig, pts, total, dim, p2), NULL);
    colors = level_colors(L, fig, levels, fn);
    cf_diag_clear(&diag);
    check(L, fn, cf_figure_add_net(fig, p2, counts, levels, colors, &st),
          &diag);
    args = lua_newuserdatauv(L, 2 * total * sizeof *args, 0);
    for (size_t j = 0; j < levels; j++)
        for (size_t i = 0; i < counts[j]; i++, k++) {
            args[2 * k] = (lua_Integer)(first_index[j] + i);
            args[2 * k + 1] = (lua_Integer)j;
        }
    cf__lua_label_items(L, fig, 4, "labels", p2, total, args, 2, fn);
    if (cf__lua_read_sub_style(L, 4, "point", fn, fig, &ps))
        check(L, fn, cf_figure_add_points(fig, p2 + 2 * (total - 1), 1, &ps),
              &diag);
}

/* f:decasteljau(c, t, {colors = {...}, labels = "P_{%d,%d}", point =
** {marker = "star"}}); labels get (i, j): point i of level j. */
static int
m_decasteljau(lua_State *L)
{
    cf_figure_t *fig = cf__lua_check_figure(L);
    cf_bezier_t *c;
    double t, *pts;
    size_t n, *counts, *first;
    lua_settop(L, 4);
    c = cf__lua_check_bezier(L, 2);
    t = cf__lua_check_finite(L, 3, "decasteljau", "t");
    cf__lua_check_table(L, 4, CF__KEYS_DECASTELJAU);
    n = (size_t)cf_bezier_degree(c) + 1;
    pts = cf__lua_buffer(L, cf_bezier_decasteljau_size(c));
    if (cf_bezier_decasteljau(c, t, pts) != CF_STATUS_OK)
        return cf__lua_error(L, "decasteljau: t = %g is outside [0, 1]", t);
    counts = lua_newuserdatauv(L, 2 * n * sizeof *counts, 0);
    first = counts + n;
    for (size_t j = 0; j < n; j++) {
        counts[j] = n - j;
        first[j] = 0;
    }
    draw_net(L, fig, pts, counts, n, cf_bezier_dim(c), first, "decasteljau");
    lua_settop(L, 1);
    return 1;
}

/* f:deboor(s, u, {...}): the de Boor net; labels get (i, j) with i the
** index of P_{i,j} as in the thesis. */
static int
m_deboor(lua_State *L)
{
    cf_figure_t *fig = cf__lua_check_figure(L);
    cf_bspline_t *s;
    double u, *pts, a, b;
    size_t p, span, *counts, *first;
    int mult;
    lua_settop(L, 4);
    s = cf__lua_check_bspline(L, 2);
    u = cf__lua_check_finite(L, 3, "deboor", "u");
    cf__lua_check_table(L, 4, CF__KEYS_DEBOOR);
    p = (size_t)cf_bspline_degree(s);
    pts = cf__lua_buffer(L, cf_bspline_deboor_size(s));
    cf_bspline_domain(s, &a, &b);
    if (cf_bspline_deboor(s, u, pts, &span, &mult) != CF_STATUS_OK)
        return cf__lua_error(L, "deboor: u = %g is outside the domain "
                             "[%g, %g]", u, a, b);
    counts = lua_newuserdatauv(L, 2 * (p + 1) * sizeof *counts, 0);
    first = counts + p + 1;
    for (size_t j = 0; j <= p; j++) {
        counts[j] = p + 1 - j;
        first[j] = span - p + j;
    }
    draw_net(L, fig, pts, counts, p + 1, cf_bspline_dim(s), first, "deboor");
    lua_settop(L, 1);
    return 1;
}

const luaL_Reg cf__lua_draw_methods[] = {
    { "curve", m_curve },
    { "polygon", m_polygon },
    { "points", m_points },
    { "polyline", m_polyline },
    { "line", m_line },
    { "hull", m_hull },
    { "fill", m_fill },
    { "label", m_label },
    { "arrow", m_arrow },
    { "arrow_to", m_arrow_to },
    { "tangent", m_tangent },
    { "knots", m_knots },
    { "decasteljau", m_decasteljau },
    { "deboor", m_deboor },
    { NULL, NULL },
};
