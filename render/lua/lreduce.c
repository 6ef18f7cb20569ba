/*
** Lua binding of degree reduction (include/curvefig/reduce.h), as methods
** of Bézier and B-spline curves:
**
**   c:reduce()  c:reduce(r)
**   c:reduce{ by = 1, continuity = 0, method = "l2" | "uniform" }
**       -> curve of degree n - by, report
**   s:reduce{ by = 1, tolerance = 1e-3, method = "l2" | "uniform" }
**       -> B-spline of degree p - by, report
**
** report = { max_error, bound, polygon_bound, l2_error } (and for a
** B-spline continuity, knots_removed): the measured maximum distance, the
** certified bounds (refined, and of the control polygons), the L2 distance
** (see docs/approximation.md, "Degree reduction").
*/
#include "curvefig/reduce.h"
#include "lbezier.h"
#include "lbspline.h"
#include "lcommon.h"
#include "lschema.h"

/* The options at idx: nil, a number (by) or a table of schema k. */
static void
read_options(lua_State *L, int idx, cf__lua_keys_t k,
             cf_reduce_options_t *opt)
{
    static const char *const methods[] = { "l2", "uniform", NULL };
    cf_reduce_options_init(opt);
    if (lua_isnoneornil(L, idx))
        return;
    if (lua_type(L, idx) == LUA_TNUMBER) {
        opt->by = cf__lua_check_int(L, idx, "reduce", "by", 1,
                                    CF_BEZIER_MAX_DEGREE);
        return;
    }
    cf__lua_check_table(L, idx, k);
    if (cf__lua_field(L, idx, "by") != LUA_TNIL)
        opt->by = cf__lua_check_int(L, -1, "reduce", "by", 1,
                                    CF_BEZIER_MAX_DEGREE);
    if (k == CF__KEYS_REDUCE &&
        cf__lua_field(L, idx, "continuity") != LUA_TNIL)
        opt->continuity = cf__lua_check_int(L, -1, "reduce", "continuity",
                                            -1, CF_BEZIER_MAX_DEGREE);
    if (k == CF__KEYS_REDUCE_BSPLINE &&
        cf__lua_field(L, idx, "tolerance") != LUA_TNIL) {
        opt->tolerance = cf__lua_check_finite(L, -1, "reduce", "tolerance");
        if (!(opt->tolerance > 0.0))
            cf__lua_error(L, "reduce: tolerance is %g; it must be > 0",
                          opt->tolerance);
    }
    if (cf__lua_field(L, idx, "method") != LUA_TNIL &&
        cf__lua_opt_text(L, -1, "reduce", "method", NULL) != NULL)
        opt->method = (cf_reduce_method_t)luaL_checkoption(L, -1, NULL,
                                                           methods);
    lua_pop(L, 3);
}

static void
push_report(lua_State *L, const cf_reduce_report_t *r, bool spline)
{
    lua_createtable(L, 0, 6);
    lua_pushnumber(L, r->max_error);
    lua_setfield(L, -2, "max_error");
    lua_pushnumber(L, r->bound);
    lua_setfield(L, -2, "bound");
    lua_pushnumber(L, r->polygon_bound);
    lua_setfield(L, -2, "polygon_bound");
    lua_pushnumber(L, r->l2_error);
    lua_setfield(L, -2, "l2_error");
    if (!spline)
        return;
    lua_pushinteger(L, r->continuity);
    lua_setfield(L, -2, "continuity");
    lua_pushinteger(L, (lua_Integer)r->knots_removed);
    lua_setfield(L, -2, "knots_removed");
}

static int
m_bezier_reduce(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    cf_reduce_options_t opt;
    cf_reduce_report_t rep;
    cf_bezier_t **out;
    cf_diag_t diag;
    cf_status_t st;
    read_options(L, 2, CF__KEYS_REDUCE, &opt);
    out = cf__lua_new_bezier(L);
    cf_diag_clear(&diag);
    st = cf_bezier_reduce(c, &opt, out, &rep, &diag);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "reduce", st, &diag);
    push_report(L, &rep, false);
    return 2;
}

static int
m_bspline_reduce(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    cf_reduce_options_t opt;
    cf_reduce_report_t rep;
    cf_bspline_t **out;
    cf_diag_t diag;
    cf_status_t st;
    read_options(L, 2, CF__KEYS_REDUCE_BSPLINE, &opt);
    out = cf__lua_new_bspline(L);
    cf_diag_clear(&diag);
    st = cf_bspline_reduce(c, &opt, out, &rep, &diag);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "reduce", st, &diag);
    push_report(L, &rep, true);
    return 2;
}

static const luaL_Reg bezier_methods[] = {
    { "reduce", m_bezier_reduce },
    { NULL, NULL },
};

static const luaL_Reg bspline_methods[] = {
    { "reduce", m_bspline_reduce },
    { NULL, NULL },
};

void
cf__lua_open_reduce(lua_State *L)
{
    cf__lua_add_bezier_methods(L, bezier_methods);
    luaL_getmetatable(L, CF__LUA_BSPLINE);
    lua_getfield(L, -1, "__index");
    luaL_setfuncs(L, bspline_methods, 0);
    lua_pop(L, 2);
}
