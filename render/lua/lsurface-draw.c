/*
** f:surface(s, {...}): a surface in a 3D figure as lines -- boundary,
** silhouette, iso-lines, knot lines, the control net with its points and
** labels -- with hidden lines removed, dashed or shown
** (include/curvefig/figure3d.h).
*/
#include <string.h>

#include "curvefig/figure3d.h"
#include "lbezier.h"
#include "lbspline.h"
#include "lcommon.h"
#include "lpairs.h"
#include "llabels.h"
#include "lschema.h"
#include "lstyle.h"
#include "lsurface-draw.h"
#include "lsurface.h"

#define check(L, fn, call, diag) cf__lua_fig_check((L), (fn), fig, (call), \
                                                   (diag))

static void
free_bspline_surface(void *p)
{
    cf_bspline_surface_destroy(p);
}

const cf_bspline_surface_t *
cf__lua_surface_arg(lua_State *L, int idx, const char *fn)
{
    cf__lua_surface_t *b = luaL_testudata(L, idx, CF__LUA_SURFACE);
    cf_bspline_surface_t **slot;
    cf_diag_t diag;
    if (b == NULL || (b->bz == NULL && b->bs == NULL))
        cf__lua_error(L, "%s: argument 1 must be a surface (bezier_surface"
                      "{...}, bspline_surface{...}, nurbs_torus{...}, ...), "
                      "got %s", fn, b == NULL ? luaL_typename(L, idx)
                                              : "a closed surface");
    if (b->bs != NULL)
        return b->bs;
    slot = (cf_bspline_surface_t **)cf__lua_holder(L, free_bspline_surface);
    cf_diag_clear(&diag);
    if (cf_bspline_surface_from_bezier(b->bz, slot, &diag) != CF_STATUS_OK)
        cf__lua_error(L, "%s: %s", fn, diag.msg);
    return *slot;
}

/* isolines = {nu, nv} (evenly spaced) or {u = {...}, v = {...}} (values) */
static void
read_isolines(lua_State *L, int opts, cf_surface_lines_t *o)
{
    int t = cf__lua_field(L, opts, "isolines"), top = lua_gettop(L);
    if (t == LUA_TNIL)
        return;
    if (t != LUA_TTABLE)
        cf__lua_error(L, "surface: isolines is {nu, nv} or {u = {...}, v = "
                      "{...}}, got %s", lua_typename(L, t));
    if (lua_rawlen(L, top) > 0) {
        size_t n;
        double *v = cf__lua_check_numbers(L, top, "surface", "isolines", &n);
        if (n != 2 || !(v[0] >= 0 && v[0] <= 1000 && v[1] >= 0
                        && v[1] <= 1000) || v[0] != (double)(size_t)v[0]
            || v[1] != (double)(size_t)v[1])
            cf__lua_error(L, "surface: isolines = {nu, nv} takes two whole "
                          "numbers 0..1000 (lines of u = const and of v = "
                          "const)");
        o->nu = (size_t)v[0];
        o->nv = (size_t)v[1];
        return;
    }
    cf__lua_sorted_keys(L, top);   /* the same entry named every run */
    for (lua_Integer i = 1, m = (lua_Integer)lua_rawlen(L, -1); i <= m;
         i++) {
        int kt = lua_rawgeti(L, -1, i);
        const char *k = kt == LUA_TSTRING ? lua_tostring(L, -1) : "";
        if (strcmp(k, "u") != 0 && strcmp(k, "v") != 0)
            cf__lua_error(L, "surface: isolines has an entry '%s'; give "
                          "{nu, nv} or {u = {...}, v = {...}}",
                          kt == LUA_TSTRING ? k : "(a number)");
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    if (cf__lua_field(L, top, "u") != LUA_TNIL)
        o->u_values = cf__lua_check_numbers(L, -1, "surface", "isolines.u",
                                            &o->u_count);
    if (cf__lua_field(L, top, "v") != LUA_TNIL)
        o->v_values = cf__lua_check_numbers(L, -1, "surface", "isolines.v",
                                            &o->v_count);
}

cf_hidden_t
cf__lua_read_hidden(lua_State *L, int opts, const char *fn, const char *def)
{
    const char *h;
    cf__lua_field(L, opts, "hidden");
    h = cf__lua_opt_text(L, -1, fn, "hidden", def);
    lua_pop(L, 1);
    return h[0] == 's' ? CF_HIDDEN_SHOW
        : h[0] == 'd' ? CF_HIDDEN_DASHED : CF_HIDDEN_REMOVE;
}

/* fill = colour (the style's) shades the surface: shade = "smooth" |
** "flat", back = colour of the back side (default: the front's, paler),
** light = {x, y, z}, the style's opacity. */
static void
read_shading(lua_State *L, int opts, const cf_figure_t *fig,
             const cf_style_t *st, cf_surface_shading_t *sh)
{
    const char *mode;
    cf__lua_field(L, opts, "shade");
    mode = cf__lua_opt_text(L, -1, "surface", "shade", "smooth");
    lua_pop(L, 1);
    if (!(st->set & CF_STYLE_FILL)) {
        if (cf__lua_field(L, opts, "shade") != LUA_TNIL
            || cf__lua_field(L, opts, "back") != LUA_TNIL
            || cf__lua_field(L, opts, "light") != LUA_TNIL)
            cf__lua_error(L, "surface: shade, back and light shade a "
                          "surface; give its colour too (fill = ...)");
        return;
    }
    sh->shade = mode[0] == 'f' ? CF_SHADE_FLAT : CF_SHADE_SMOOTH;
    sh->front = st->fill;
    sh->back = st->fill;
    sh->back.r = 0.5 + 0.5 * sh->back.r;
    sh->back.g = 0.5 + 0.5 * sh->back.g;
    sh->back.b = 0.5 + 0.5 * sh->back.b;
    if (cf__lua_field(L, opts, "back") != LUA_TNIL)
        sh->back = cf__lua_read_color(L, -1, "surface", "back", fig);
    lua_pop(L, 1);
    sh->opacity = st->set & CF_STYLE_OPACITY ? st->opacity : 1.0;
    if (cf__lua_field(L, opts, "light") != LUA_TNIL) {
        size_t n;
        double *v = cf__lua_check_numbers(L, -1, "surface", "light", &n);
        if (n != 3 || !(v[0] != 0 || v[1] != 0 || v[2] != 0))
            cf__lua_error(L, "surface: light is a direction {x, y, z} "
                          "towards the light, not zero");
        memcpy(sh->light, v, sizeof sh->light);
        sh->has_light = true;
    }
    lua_pop(L, 1);
}

static void
free_list(void *p)
{
    cf_bezier_list_destroy(p);
}

bool
cf__lua_space_curve(lua_State *L, cf_figure_t *fig, int idx, int opts,
                    const cf_style_t *st)
{
    cf_bezier_t *bz = cf__lua_to_bezier(L, idx);
    cf_bspline_t *bs = cf__lua_to_bspline(L, idx);
    cf_bezier_list_t one, *list = &one, **slot;
    cf_hidden_t hidden;
    cf_diag_t diag;
    if (!cf_figure_get_view(fig, NULL)
        || !((bz != NULL && cf_bezier_dim(bz) == 3)
             || (bs != NULL && cf_bspline_dim(bs) == 3)))
        return false;
    hidden = cf__lua_read_hidden(L, opts, "curve", "dashed");
    cf_diag_clear(&diag);
    memset(&one, 0, sizeof one);
    if (bz != NULL) {
        one.count = 1;
        one.items = &bz;
    } else {
        slot = (cf_bezier_list_t **)cf__lua_holder(L, free_list);
        if (cf_bspline_to_beziers(bs, slot, &diag) != CF_STATUS_OK)
            cf__lua_error(L, "curve: %s", diag.msg);
        list = *slot;
    }
    check(L, "curve", cf_figure_add_space_curves(fig, list, hidden, st),
          &diag);
    return true;
}

/* The labels of the net's points: labels = "P_{%d%d}" gets (i, j) of a
** tensor-product surface, (i, j, k) of a triangular patch, as the curves'
** nets. */
static void
net_labels(lua_State *L, cf_figure_t *fig, int opts,
           const cf_bspline_surface_t *s, const cf_bezier_triangle_t *t)
{
    size_t nu = 0, nv = 0, n, k = 0;
    double *p3, *p2;
    lua_Integer *args;
    int deg = t != NULL ? cf_bezier_triangle_degree(t) : 0;
    if (t != NULL) {
        n = cf_bezier_triangle_count(t);
    } else {
        nu = cf_bspline_surface_count_u(s);
        nv = cf_bspline_surface_count_v(s);
        n = nu * nv;
    }
    p3 = cf__lua_buffer(L, 3 * n);
    p2 = cf__lua_buffer(L, 2 * n);
    args = lua_newuserdatauv(L, 3 * n * sizeof *args, 0);
    if (t != NULL) {
        cf_bezier_triangle_get_points(t, p3);
        /* the order of surface-triangle.h: i from n down, j from n - i
        ** down */
        for (int i = deg; i >= 0; i--)
            for (int j = deg - i; j >= 0; j--, k++) {
                args[3 * k] = i;
                args[3 * k + 1] = j;
                args[3 * k + 2] = deg - i - j;
            }
    } else {
        cf_bspline_surface_get_points(s, p3);
        for (size_t i = 0; i < nu; i++)
            for (size_t j = 0; j < nv; j++, k++) {
                args[3 * k] = (lua_Integer)i;
                args[3 * k + 1] = (lua_Integer)j;
            }
    }
    check(L, "surface", cf_figure_project(fig, p3, n, 3, p2), NULL);
    if (t == NULL)   /* pairs, packed */
        for (k = 0; k < n; k++) {
            args[2 * k] = args[3 * k];
            args[2 * k + 1] = args[3 * k + 1];
        }
    cf__lua_label_items(L, fig, opts, "labels", p2, n, args,
                        t != NULL ? 3 : 2, "surface");
}

/* f:surface(s, {isolines = {4, 4}, net = true, hidden = "dashed", ...}) */
static int
m_surface(lua_State *L)
{
    cf_figure_t *fig = cf__lua_check_figure(L);
    const cf_bspline_surface_t *s = NULL;
    cf_bezier_triangle_t *tri;
    cf_surface_lines_t o;
    cf_style_t st;
    cf_diag_t diag;
    lua_settop(L, 3);
    cf__lua_check_table(L, 3, CF__KEYS_SURFACE);
    tri = cf__lua_to_triangle(L, 2);
    if (tri == NULL)
        s = cf__lua_surface_arg(L, 2, "surface");
    cf_surface_lines_init(&o);
    cf__lua_read_style(L, 3, "surface", fig, &st);
    o.boundary = cf__lua_opt_bool(L, 3, "boundary", "surface", true);
    o.silhouette = cf__lua_opt_bool(L, 3, "silhouette", "surface", true);
    o.knot_lines = cf__lua_opt_bool(L, 3, "knot_lines", "surface", false);
    o.occludes = cf__lua_opt_bool(L, 3, "occludes", "surface", true);
    o.hidden = cf__lua_read_hidden(L, 3, "surface", "remove");
    read_isolines(L, 3, &o);
    read_shading(L, 3, fig, &st, &o.shading);
    cf__lua_read_sub_style(L, 3, "iso_style", "surface", fig, &o.iso_style);
    o.net = cf__lua_read_sub_style(L, 3, "net", "surface", fig,
                                   &o.net_style);
    cf_diag_clear(&diag);
    if (tri != NULL)
        check(L, "surface", cf_figure_add_triangle_surface(fig, tri, &o, &st),
              &diag);
    else
        check(L, "surface", cf_figure_add_surface(fig, s, &o, &st), &diag);
    if (o.net)
        net_labels(L, fig, 3, s, tri);
    lua_settop(L, 1);
    return 1;
}

const luaL_Reg cf__lua_surface_draw_methods[] = {
    { "surface", m_surface },
    { NULL, NULL },
};
