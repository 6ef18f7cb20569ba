/*
** Lua binding of interpolation and the curves of the thesis' chapter 4
** (include/curvefig/interp.h):
**
**   interpolate{ points = {...}, method = "natural" | "clamped" |
**                "not-a-knot" | "periodic" | "catmull-rom" | "global",
**                degree = 3, param = "uniform" | "chord" | "centripetal",
**                exponent = e, params = {...}, start_tangent = {...},
**                end_tangent = {...}, closed = false }      -> B-spline
**   approximate{ points = {...}, count = n, degree = 3, param = ...,
**                fix_ends = true }                 -> B-spline, residual
**   parameters(points, param, closed)              -> { u_0, ... }
**   ferguson(P0, P1, T0, T1)                       -> Bézier cubic
**   ferguson_chain(points, tangents)               -> list of cubics
**   coons_cubic{ P0, P1, P2, P3 }                  -> Bézier cubic
**   coons_chain{ points = {...}, ends = "plain" | "tripled" | "closed" }
*/
#include <string.h>

#include "curvefig/interp.h"
#include "lbezier.h"
#include "lbspline.h"
#include "lcommon.h"
#include "lschema.h"

/* The options shared by interpolate and approximate; tangents and params
** stay in Lua-owned buffers on the stack. */
static void
read_options(lua_State *L, const char *fn, size_t dim, size_t count,
             cf_interp_options_t *opt)
{
    cf_diag_t diag;
    cf_interp_options_init(opt);
    cf_diag_clear(&diag);
    if (cf__lua_field(L, 1, "method") != LUA_TNIL &&
        cf_interp_method_from_string(
            cf__lua_opt_text(L, -1, fn, "method", NULL), &opt->method, &diag))
        luaL_error(L, "%s: method: %s", fn, diag.msg);
    if (cf__lua_field(L, 1, "param") != LUA_TNIL &&
        cf_param_from_string(cf__lua_opt_text(L, -1, fn, "param", NULL),
                             &opt->param, &diag))
        luaL_error(L, "%s: param: %s", fn, diag.msg);
    if (cf__lua_field(L, 1, "degree") != LUA_TNIL)
        opt->degree = cf__lua_check_int(L, -1, fn, "degree", 0,
                                        CF_BSPLINE_MAX_DEGREE);
    if (cf__lua_field(L, 1, "exponent") != LUA_TNIL) {
        opt->exponent = cf__lua_check_finite(L, -1, fn, "exponent");
        opt->param = CF_PARAM_POWER;
    }
    if (cf__lua_field(L, 1, "closed") != LUA_TNIL)
        opt->closed = cf__lua_opt_bool_arg(L, -1, fn, "closed", false);
    if (cf__lua_field(L, 1, "params") != LUA_TNIL) {
        size_t n;
        opt->params = cf__lua_check_numbers(L, -1, fn, "parameter", &n);
        if (n < count)
            cf__lua_error(L, "%s: %zu parameters for %zu points", fn, n,
                          count);
    }
    if (cf__lua_field(L, 1, "start_tangent") != LUA_TNIL)
        opt->start_tangent = cf__lua_check_point(L, -1, fn, "start_tangent",
                                                 &dim);
    if (cf__lua_field(L, 1, "end_tangent") != LUA_TNIL)
        opt->end_tangent = cf__lua_check_point(L, -1, fn, "end_tangent",
                                               &dim);
}

static int
l_interpolate(lua_State *L)
{
    size_t n, dim;
    double *pts;
    cf_interp_options_t opt;
    cf_bspline_t **out;
    cf_diag_t diag;
    lua_settop(L, 1);
    luaL_checktype(L, 1, LUA_TTABLE);
    cf__lua_check_table(L, 1, CF__KEYS_INTERPOLATE);
    cf__lua_field(L, 1, "points");
    pts = cf__lua_check_points(L, -1, "interpolate", "point", 1, &n, &dim);
    read_options(L, "interpolate", dim, n, &opt);
    out = cf__lua_new_bspline(L);
    cf_diag_clear(&diag);
    if (cf_interpolate(dim, pts, n, &opt, out, &diag) != CF_STATUS_OK)
        return cf__lua_fail(L, "interpolate", diag.status, &diag);
    return 1;
}

static int
l_approximate(lua_State *L)
{
    size_t n, dim;
    double *pts, residual = 0.0;
    cf_interp_options_t opt;
    cf_bspline_t **out;
    cf_diag_t diag;
    int ncontrol;
    bool fix = true;
    lua_settop(L, 1);
    luaL_checktype(L, 1, LUA_TTABLE);
    cf__lua_check_table(L, 1, CF__KEYS_APPROXIMATE);
    cf__lua_field(L, 1, "points");
    pts = cf__lua_check_points(L, -1, "approximate", "point", 1, &n, &dim);
    cf__lua_field(L, 1, "count");
    ncontrol = cf__lua_check_int(L, -1, "approximate", "count", 1, 1 << 20);
    if (cf__lua_field(L, 1, "fix_ends") != LUA_TNIL)
        fix = cf__lua_opt_bool_arg(L, -1, "approximate", "fix_ends", true);
    read_options(L, "approximate", dim, n, &opt);
    out = cf__lua_new_bspline(L);
    cf_diag_clear(&diag);
    if (cf_approximate_lsq(dim, pts, n, (size_t)ncontrol, &opt, fix, out,
                           &residual, &diag) != CF_STATUS_OK)
        return cf__lua_fail(L, "approximate", diag.status, &diag);
    lua_pushnumber(L, residual);
    return 2;
}

/* parameters(points, param = "chord", closed = false) */
static int
l_parameters(lua_State *L)
{
    size_t n, dim;
    double *pts, *u;
    cf_param_t param = CF_PARAM_CHORD;
    bool closed;
    cf_diag_t diag;
    lua_settop(L, 3);
    pts = cf__lua_check_points(L, 1, "parameters", "point", 2, &n, &dim);
    cf_diag_clear(&diag);
    if (!lua_isnil(L, 2) &&
        cf_param_from_string(luaL_checkstring(L, 2), &param, &diag))
        return luaL_error(L, "parameters: %s", diag.msg);
    closed = cf__lua_opt_bool_arg(L, 3, "parameters", "closed", false);
    u = cf__lua_buffer(L, n + 1);
    if (cf_interp_parameters(dim, pts, n, param, 0.5, closed, u, &diag))
        return cf__lua_fail(L, "parameters", diag.status, &diag);
    cf__lua_push_numbers(L, u, closed ? n + 1 : n);
    return 1;
}

/* ferguson(P0, P1, T0, T1) */
static int
l_ferguson(lua_State *L)
{
    size_t dim = 0;
    double *p0, *p1, *t0, *t1;
    cf_bezier_t **out;
    cf_diag_t diag;
    lua_settop(L, 4);
    p0 = cf__lua_check_point(L, 1, "ferguson", "P0", &dim);
    p1 = cf__lua_check_point(L, 2, "ferguson", "P1", &dim);
    t0 = cf__lua_check_point(L, 3, "ferguson", "T0", &dim);
    t1 = cf__lua_check_point(L, 4, "ferguson", "T1", &dim);
    out = cf__lua_new_bezier(L);
    cf_diag_clear(&diag);
    if (cf_ferguson_cubic(dim, p0, p1, t0, t1, out, &diag) != CF_STATUS_OK)
        return cf__lua_fail(L, "ferguson", diag.status, &diag);
    return 1;
}

static void
free_list(void *p)
{
    cf_bezier_list_destroy(p);
}

/* ferguson_chain(points, tangents) */
static int
l_ferguson_chain(lua_State *L)
{
    size_t n, dim, nt, dt;
    double *p, *t;
    void **slot;
    cf_bezier_list_t *list = NULL;
    cf_diag_t diag;
    cf_status_t st;
    lua_settop(L, 2);
    p = cf__lua_check_points(L, 1, "ferguson_chain", "point", 2, &n, &dim);
    t = cf__lua_check_points(L, 2, "ferguson_chain", "tangent", 2, &nt, &dt);
    if (nt != n || dt != dim)
        return cf__lua_error(L, "ferguson_chain: %zu tangents in R^%zu for "
                             "%zu points in R^%zu", nt, dt, n, dim);
    slot = cf__lua_holder(L, free_list);
    cf_diag_clear(&diag);
    st = cf_ferguson_chain(dim, p, t, n, &list, &diag);
    *slot = list;
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "ferguson_chain", st, &diag);
    cf__lua_push_bezier_list(L, list);
    return 1;
}

/* coons_cubic{ P0, P1, P2, P3 } */
static int
l_coons_cubic(lua_State *L)
{
    size_t n, dim;
    double *p;
    cf_bezier_t **out;
    cf_diag_t diag;
    lua_settop(L, 1);
    p = cf__lua_check_points(L, 1, "coons_cubic", "point", 4, &n, &dim);
    if (n != 4)
        return cf__lua_error(L, "coons_cubic: %zu points given; it takes 4",
                             n);
    out = cf__lua_new_bezier(L);
    cf_diag_clear(&diag);
    if (cf_coons_cubic(dim, p, out, &diag) != CF_STATUS_OK)
        return cf__lua_fail(L, "coons_cubic", diag.status, &diag);
    return 1;
}

/* coons_chain{ points = {...}, ends = "plain" | "tripled" | "closed" } */
static int
l_coons_chain(lua_State *L)
{
    static const char *const ends[] = { "plain", "tripled", "closed", NULL };
    size_t n, dim;
    double *p;
    int e;
    void **slot;
    cf_bezier_list_t *list = NULL;
    cf_diag_t diag;
    cf_status_t st;
    lua_settop(L, 1);
    luaL_checktype(L, 1, LUA_TTABLE);
    cf__lua_check_table(L, 1, CF__KEYS_COONS_CHAIN);
    cf__lua_field(L, 1, "points");
    p = cf__lua_check_points(L, -1, "coons_chain", "point", 1, &n, &dim);
    cf__lua_field(L, 1, "ends");
    cf__lua_opt_text(L, -1, "coons_chain", "ends", "plain");
    e = luaL_checkoption(L, -1, "plain", ends);
    slot = cf__lua_holder(L, free_list);
    cf_diag_clear(&diag);
    st = cf_coons_chain(dim, p, n, (cf_coons_ends_t)e, &list, &diag);
    *slot = list;
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "coons_chain", st, &diag);
    cf__lua_push_bezier_list(L, list);
    return 1;
}

static const luaL_Reg globals[] = {
    { "interpolate", l_interpolate },
    { "approximate", l_approximate },
    { "parameters", l_parameters },
    { "ferguson", l_ferguson },
    { "ferguson_chain", l_ferguson_chain },
    { "coons_cubic", l_coons_cubic },
    { "coons_chain", l_coons_chain },
    { NULL, NULL },
};

void
cf__lua_open_interp(lua_State *L)
{
    lua_pushglobaltable(L);
    luaL_setfuncs(L, globals, 0);
    lua_pop(L, 1);
}
