/*
** Lua binding of offset curves (include/curvefig/offset.h), as methods of
** Bézier and B-spline curves:
**
**   c:offset(d, { tolerance = 1e-3, trim = false,
**                 method = "levien" | "tiller-hanson" })
**       -> list of cubic Béziers (the trimmed offset when trim = true)
**          with two fields: .report = { segments, max_error, converged,
**          cusps, joins, self_intersections, trimmed_chains,
**          trimmed_segments } and, with trim = true, .chains = the trimmed
**          chains (each a list); the report and the chains are also
**          returned as second and third values (wrap the call in
**          parentheses to pass only the list: f:curve((c:offset(d))))
**   c:offset_point(t, d), c:offset_cusps(d)
*/
#include <string.h>

#include "curvefig/bspline.h"
#include "curvefig/offset.h"
#include "lbezier.h"
#include "lbspline.h"
#include "lcommon.h"
#include "lparams.h"
#include "lschema.h"
#include "params.h"

/* The highest degree offset by c:offset: the work of an offset grows
** steeply with the degree (a degree-32 curve takes seconds, degree 1024
** minutes) and no instruction counts it.  Course figures offset cubics
** and curves of a few degrees more. */
#define MAX_OFFSET_DEGREE 24

static void
read_options(lua_State *L, int idx, cf_offset_options_t *opt)
{
    static const char *const methods[] = { "levien", "tiller-hanson", NULL };
    cf_offset_options_init(opt);
    if (!lua_isnoneornil(L, idx)) {
        cf__lua_check_table(L, idx, CF__KEYS_OFFSET);
        if (cf__lua_field(L, idx, "tolerance") != LUA_TNIL)
            opt->tolerance = cf__lua_check_finite(L, -1, "offset",
                                                  "tolerance");
        if (cf__lua_field(L, idx, "trim") != LUA_TNIL)
            opt->trim = cf__lua_opt_bool_arg(L, -1, "offset", "trim",
                                             false);
        if (cf__lua_field(L, idx, "method") != LUA_TNIL &&
            cf__lua_opt_text(L, -1, "offset", "method", NULL) != NULL)
            opt->method = (cf_offset_method_t)luaL_checkoption(L, -1, NULL,
                                                               methods);
        lua_pop(L, 3);
    }
    /* a draft of an interactive page (params.h): looser */
    if (cf__params_draft(cf__lua_params(L)))
        opt->tolerance *= CF__PARAMS_DRAFT_FACTOR;
}

static void
free_cubics(void *p)
{
    cf_cubics_destroy(p);
}

static void
free_cubics_list(void *p)
{
    cf_cubics_list_destroy(p);
}

static void
free_bezier_list(void *p)
{
    cf_bezier_list_destroy(p);
}

static void
set_count(lua_State *L, const char *key, size_t v)
{
    lua_pushinteger(L, (lua_Integer)v);
    lua_setfield(L, -2, key);
}

static void
push_report(lua_State *L, const cf_offset_report_t *r)
{
    lua_createtable(L, 0, 8);
    set_count(L, "segments", r->segments);
    lua_pushnumber(L, r->max_error);
    lua_setfield(L, -2, "max_error");
    lua_pushboolean(L, r->converged);
    lua_setfield(L, -2, "converged");
    set_count(L, "cusps", r->cusps);
    set_count(L, "joins", r->joins);
    set_count(L, "self_intersections", r->self_intersections);
    set_count(L, "trimmed_chains", r->trimmed_chains);
    set_count(L, "trimmed_segments", r->trimmed_segments);
}

/* The offset of the B-spline at 1, through its Bézier pieces. */
static cf_status_t
bspline_offset(lua_State *L, double d, const cf_offset_options_t *opt,
               cf_cubics_t **raw, cf_cubics_list_t **trimmed,
               cf_offset_report_t *rep, cf_diag_t *diag)
{
    cf_bspline_t *s = cf__lua_check_bspline(L, 1);
    void **slot = cf__lua_holder(L, free_bezier_list);
    cf_bezier_list_t *list = NULL;
    cf_status_t st = cf_bspline_to_beziers(s, &list, diag);
    *slot = list;
    if (st != CF_STATUS_OK)
        return st;
    return cf_bezier_list_offset(list, d, opt, raw, trimmed, rep, diag);
}

/* Push all the pieces of the trimmed chains (with .chains and .report),
** the report and the chains. */
static int
push_trimmed(lua_State *L, const cf_cubics_list_t *trimmed,
             const cf_offset_report_t *rep)
{
    lua_newtable(L);                                     /* all pieces */
    lua_createtable(L, (int)trimmed->count, 0);          /* chains */
    for (size_t i = 0; i < trimmed->count; i++) {
        cf__lua_push_cubics(L, trimmed->chains[i]);
        for (lua_Integer k = 1; k <= (lua_Integer)lua_rawlen(L, -1); k++) {
            lua_rawgeti(L, -1, k);
            lua_rawseti(L, -4, (lua_Integer)lua_rawlen(L, -4) + 1);
        }
        lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
    lua_pushvalue(L, -1);
    lua_setfield(L, -3, "chains");                       /* all.chains */
    push_report(L, rep);
    lua_pushvalue(L, -1);
    lua_setfield(L, -4, "report");                       /* all.report */
    lua_insert(L, -2);
    return 3;                                  /* all, report, chains */
}

/* c:offset(d, opts) for a Bézier (c at 1) or a B-spline (its pieces). */
static int
m_offset(lua_State *L)
{
    lua_settop(L, 3);
    cf_bezier_t *bz = cf__lua_to_bezier(L, 1);
    double d = cf__lua_check_finite(L, 2, "offset", "d");
    cf_offset_options_t opt;
    cf_offset_report_t rep;
    cf_cubics_t *raw = NULL;
    cf_cubics_list_t *trimmed = NULL;
    void **raw_slot, **trim_slot;
    cf_diag_t diag;
    cf_status_t st;
    read_options(L, 3, &opt);
    {
        int deg = bz != NULL ? cf_bezier_degree(bz)
                             : cf_bspline_degree(cf__lua_check_bspline(L, 1));
        if (deg > MAX_OFFSET_DEGREE)
            return cf__lua_error(L, "offset: the curve has degree %d; "
                                 "offsets are made of curves of degree at "
                                 "most %d (its work grows steeply with the "
                                 "degree)", deg, MAX_OFFSET_DEGREE);
    }
    raw_slot = cf__lua_holder(L, free_cubics);           /* 4 */
    trim_slot = cf__lua_holder(L, free_cubics_list);     /* 5 */
    cf_diag_clear(&diag);
    if (bz != NULL)
        st = cf_bezier_offset(bz, d, &opt, &raw, opt.trim ? &trimmed : NULL,
                              &rep, &diag);
    else
        st = bspline_offset(L, d, &opt, &raw, opt.trim ? &trimmed : NULL,
                            &rep, &diag);
    *raw_slot = raw;
    *trim_slot = trimmed;
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "offset", st, &diag);
    if (!opt.trim) {
        cf__lua_push_cubics(L, raw);
        push_report(L, &rep);
        lua_pushvalue(L, -1);
        lua_setfield(L, -3, "report");
        return 2;
    }
    return push_trimmed(L, trimmed, &rep);
}

/* c:offset_point(t, d) -> c(t) + d n(t) */
static int
m_offset_point(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    double t = cf__lua_check_finite(L, 2, "offset_point", "t");
    double d = cf__lua_check_finite(L, 3, "offset_point", "d"), p[2];
    cf_status_t st = cf_offset_point(c, t, d, p);
    if (st != CF_STATUS_OK)
        return cf__lua_error(L, "offset_point: %s at t = %g",
                             cf_status_to_string(st), t);
    cf__lua_push_point(L, p, 2);
    return 1;
}

/* c:offset_cusps(d) -> { t, ... } where the offset at d has cusps */
static int
m_offset_cusps(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    double d = cf__lua_check_finite(L, 2, "offset_cusps", "d"), *ts;
    size_t count = 0;
    cf_diag_t diag;
    cf_diag_clear(&diag);
    if (cf_offset_cusps(c, d, NULL, 0, &count, &diag) != CF_STATUS_OK)
        return cf__lua_fail(L, "offset_cusps", diag.status, &diag);
    ts = cf__lua_buffer(L, count);
    if (cf_offset_cusps(c, d, ts, count, &count, &diag) != CF_STATUS_OK)
        return cf__lua_fail(L, "offset_cusps", diag.status, &diag);
    cf__lua_push_numbers(L, ts, count);
    return 1;
}

static const luaL_Reg bezier_methods[] = {
    { "offset", m_offset },
    { "offset_point", m_offset_point },
    { "offset_cusps", m_offset_cusps },
    { NULL, NULL },
};

static const luaL_Reg bspline_methods[] = {
    { "offset", m_offset },
    { NULL, NULL },
};

void
cf__lua_open_offset(lua_State *L)
{
    cf__lua_add_bezier_methods(L, bezier_methods);
    luaL_getmetatable(L, CF__LUA_BSPLINE);
    lua_getfield(L, -1, "__index");
    luaL_setfuncs(L, bspline_methods, 0);
    lua_pop(L, 2);
}
