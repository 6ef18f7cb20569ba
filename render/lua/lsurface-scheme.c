/*
** The surface constructions as figures: f:decasteljau_surface(s, u, v)
** draws the intermediate nets of de Casteljau's algorithm on a Bézier
** patch, f:triangle_scheme(t, u, v) those of a triangular patch; each
** level in its own colour (the theme's palette, or colors = {...}), the
** point S(u, v) marked (point = {...}).  The patch itself and its net are
** drawn with f:surface.
*/
#include "curvefig/figure3d.h"
#include "lcommon.h"
#include "lschema.h"
#include "lstyle.h"
#include "lsurface-draw.h"
#include "lsurface.h"

#define check(L, fn, call, diag) cf__lua_fig_check((L), (fn), fig, (call), \
                                                   (diag))

/* The style of level l: the options' style in colour l (colors[l - 1] or
** the palette's), dashed and marked its own way under the theme's
** redundant = true. */
static cf_style_t
level_style(lua_State *L, cf_figure_t *fig, int opts, const cf_style_t *st,
            int l, const char *fn)
{
    cf_style_t s = *st;
    cf_theme_t th;
    cf_figure_get_theme(fig, &th);
    s.set |= CF_STYLE_COLOR | CF_STYLE_MARKER_COLOR;
    s.color = th.palette[(size_t)l % (th.palette_size ? th.palette_size : 1)];
    if (cf__lua_field(L, opts, "colors") != LUA_TNIL) {
        if (!lua_istable(L, -1))
            cf__lua_error(L, "%s: colors is a list of colours, one per level",
                          fn);
        if (lua_geti(L, -1, l) == LUA_TNIL)
            cf__lua_error(L, "%s: colors has %d colours; level %d needs one",
                          fn, (int)lua_rawlen(L, -2), l);
        s.color = cf__lua_read_color(L, -1, fn, "colors", fig);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    s.marker_color = s.color;
    cf_theme_level_style(&th, (size_t)l, &s);   /* redundant = true */
    return s;
}

/* A polygon through n points of pts3 (3D, stride step points). */
static void
polygon3(lua_State *L, cf_figure_t *fig, const double *pts3, size_t n,
         size_t step, const cf_style_t *s, const char *fn)
{
    double *q = cf__lua_buffer(L, 3 * n), *p2 = cf__lua_buffer(L, 2 * n);
    cf_diag_t diag;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            q[3 * i + k] = pts3[3 * i * step + k];
    cf_diag_clear(&diag);
    check(L, fn, cf_figure_project(fig, q, n, 3, p2), &diag);
    check(L, fn, cf_figure_add_polygon(fig, p2, n, s), &diag);
    lua_pop(L, 2);
}

static void
final_point(lua_State *L, cf_figure_t *fig, int opts, const double *p,
            const char *fn)
{
    cf_style_t ps;
    double q[2];
    if (!cf__lua_read_sub_style(L, opts, "point", fn, fig, &ps)) {
        cf_style_init(&ps);
        ps.set = CF_STYLE_MARKER;
        ps.marker = CF_MARKER_STAR;
    }
    check(L, fn, cf_figure_project(fig, p, 1, 3, q), NULL);
    check(L, fn, cf_figure_add_points(fig, q, 1, &ps), NULL);
}

/* f:decasteljau_surface(s, u, v, {colors = {...}, point = {...}}): level
** l = 1..m of the columns' schemes in u, a grid of (m + 1 - l) x (n + 1)
** points joined along both directions, then levels 1..n of the scheme in
** v on the n + 1 points reached, then S(u, v). */
static int
m_decasteljau_surface(lua_State *L)
{
    const char *fn = "decasteljau_surface";
    cf_figure_t *fig = cf__lua_check_figure(L);
    cf__lua_surface_t *b;
    double u, v, *pts;
    int m, n;
    size_t tri, vbase;
    cf_style_t st;
    lua_settop(L, 5);
    cf__lua_check_table(L, 5, CF__KEYS_DECASTELJAU_SURFACE);
    b = luaL_testudata(L, 2, CF__LUA_SURFACE);
    if (b == NULL || b->bz == NULL || cf_bezier_surface_dim(b->bz) != 3)
        return cf__lua_error(L, "%s: argument 1 must be a Bézier surface in "
                             "R^3 (bezier_surface{...})", fn);
    u = cf__lua_check_finite(L, 3, fn, "u");
    v = cf__lua_check_finite(L, 4, fn, "v");
    cf__lua_read_style(L, 5, fn, fig, &st);
    m = cf_bezier_surface_degree_u(b->bz);
    n = cf_bezier_surface_degree_v(b->bz);
    pts = cf__lua_buffer(L, cf_bezier_surface_decasteljau_size(b->bz));
    if (cf_bezier_surface_decasteljau(b->bz, u, v, pts) != CF_STATUS_OK)
        return cf__lua_error(L, "%s: (u, v) = (%g, %g) is outside [0, 1] x "
                             "[0, 1]", fn, u, v);
    tri = (size_t)(m + 1) * (size_t)(m + 2) / 2;
    for (int l = 1; l <= m; l++) {
        cf_style_t s = level_style(L, fig, 5, &st, l, fn);
        /* level l of column j starts at j tri + (sum of the longer
        ** levels); its point i is that + i */
        size_t first = (size_t)l * (size_t)(2 * m + 3 - l) / 2;
        for (int i = 0; i <= m - l; i++)   /* along v: across columns */
            polygon3(L, fig, pts + 3 * (first + (size_t)i), (size_t)n + 1,
                     tri, &s, fn);
        for (int j = 0; j <= n; j++)       /* along u: in one column */
            polygon3(L, fig, pts + 3 * ((size_t)j * tri + first),
                     (size_t)(m - l + 1), 1, &s, fn);
    }
    vbase = (size_t)(n + 1) * tri;
    for (int l = 1; l <= n; l++) {
        cf_style_t s = level_style(L, fig, 5, &st, m + l, fn);
        size_t first = (size_t)l * (size_t)(2 * n + 3 - l) / 2;
        polygon3(L, fig, pts + 3 * (vbase + first), (size_t)(n - l + 1), 1,
                 &s, fn);
    }
    final_point(L, fig, 5, pts + 3 * (vbase + (size_t)(n + 1)
                                      * (size_t)(n + 2) / 2 - 1), fn);
    lua_settop(L, 1);
    return 1;
}

/* f:triangle_scheme(t, u, v, {colors = {...}, point = {...}}): levels
** 1..n - 1 of the triangular scheme, each a triangular net (the small
** triangles b_(i+1)jk b_i(j+1)k b_ij(k+1) outlined), then T(u, v). */
static int
m_triangle_scheme(lua_State *L)
{
    const char *fn = "triangle_scheme";
    cf_figure_t *fig = cf__lua_check_figure(L);
    cf_bezier_triangle_t *t = cf__lua_to_triangle(L, 2);
    double u, v, *pts;
    int n;
    size_t base = 0;
    cf_style_t st;
    lua_settop(L, 5);
    cf__lua_check_table(L, 5, CF__KEYS_DECASTELJAU_SURFACE);
    if (t == NULL || cf_bezier_triangle_dim(t) != 3)
        return cf__lua_error(L, "%s: argument 1 must be a triangular patch "
                             "in R^3 (bezier_triangle{...})", fn);
    u = cf__lua_check_finite(L, 3, fn, "u");
    v = cf__lua_check_finite(L, 4, fn, "v");
    cf__lua_read_style(L, 5, fn, fig, &st);
    n = cf_bezier_triangle_degree(t);
    pts = cf__lua_buffer(L, cf_bezier_triangle_decasteljau_size(t));
    if (cf_bezier_triangle_decasteljau(t, u, v, pts) != CF_STATUS_OK)
        return cf__lua_error(L, "%s: (u, v) = (%g, %g) is outside the "
                             "triangle u, v, 1 - u - v >= 0", fn, u, v);
    for (int l = 0; l < n; l++) {
        int d = n - l;   /* the degree of level l's points */
        size_t count = (size_t)(d + 1) * (size_t)(d + 2) / 2;
        if (l > 0) {
            cf_style_t s = level_style(L, fig, 5, &st, l, fn);
            for (int i = d - 1; i >= 0; i--)
                for (int j = d - 1 - i; j >= 0; j--) {
                    /* b_(i+1)jk, b_i(j+1)k, b_ij(k+1), back to the first */
                    int r0 = d - i - 1, r1 = d - i;
                    size_t idx[4] = {
                        (size_t)(r0 * (r0 + 1) / 2 + (r0 - j)),
                        (size_t)(r1 * (r1 + 1) / 2 + (r1 - j - 1)),
                        (size_t)(r1 * (r1 + 1) / 2 + (r1 - j)), 0
                    };
                    double tri3[12];
                    idx[3] = idx[0];
                    for (int c = 0; c < 4; c++)
                        for (int k = 0; k < 3; k++)
                            tri3[3 * c + k] = pts[3 * (base + idx[c]) + k];
                    polygon3(L, fig, tri3, 4, 1, &s, fn);
                }
        }
        base += count;
    }
    final_point(L, fig, 5, pts + 3 * base, fn);
    lua_settop(L, 1);
    return 1;
}

const luaL_Reg cf__lua_surface_scheme_methods[] = {
    { "decasteljau_surface", m_decasteljau_surface },
    { "triangle_scheme", m_triangle_scheme },
    { NULL, NULL },
};
