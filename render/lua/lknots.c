/*
** Lua binding of knot vectors and basis functions
** (include/curvefig/knots.h): the global table `knots` (uniform, clamped,
** averaged, validate, multiplicity, span, domain, kind, count) and the
** globals basis(i, p, U, u) and basis_funs(p, U, u).
*/
#include "curvefig/bspline.h"
#include "curvefig/knots.h"
#include "lcommon.h"

/* nresults, or the error of a failed status */
#define done cf__lua_done


static int
k_generate(lua_State *L, int clamped)
{
    const char *fn = clamped ? "knots.clamped" : "knots.uniform";
    int p = cf__lua_check_int(L, 1, fn, "degree", 0, CF_BSPLINE_MAX_DEGREE);
    int n = cf__lua_check_int(L, 2, fn, "number of points", 1, 1 << 20);
    double a = luaL_optnumber(L, 3, 0.0), b = luaL_optnumber(L, 4, 1.0);
    size_t m = cf_knots_count(p, (size_t)n);
    double *u = cf__lua_buffer(L, m);
    cf_diag_t diag;
    cf_status_t st;
    cf_diag_clear(&diag);
    st = clamped ? cf_knots_clamped_uniform(p, (size_t)n, a, b, u, &diag)
                 : cf_knots_uniform(p, (size_t)n, a, b, u, &diag);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, fn, st, &diag);
    cf__lua_push_numbers(L, u, m);
    return 1;
}

static int
k_uniform(lua_State *L)
{
    return k_generate(L, 0);
}

static int
k_clamped(lua_State *L)
{
    return k_generate(L, 1);
}

/* knots.averaged(p, params) */
static int
k_averaged(lua_State *L)
{
    int p = cf__lua_check_int(L, 1, "knots.averaged", "degree", 1,
                              CF_BSPLINE_MAX_DEGREE);
    size_t n;
    double *t = cf__lua_check_numbers(L, 2, "knots.averaged", "parameter",
                                      &n);
    double *u = cf__lua_buffer(L, cf_knots_count(p, n));
    cf_diag_t diag;
    cf_diag_clear(&diag);
    if (done(L, "knots.averaged", cf_knots_clamped_averaged(p, n, t, u,
                                                            &diag),
             &diag, 1) != 1)
        return 0;
    cf__lua_push_numbers(L, u, cf_knots_count(p, n));
    return 1;
}

/* knots.validate(p, npoints, U) -> true or false, message */
static int
k_validate(lua_State *L)
{
    int p = (int)luaL_checkinteger(L, 1);
    lua_Integer np = luaL_checkinteger(L, 2);
    size_t m;
    double *u = cf__lua_check_numbers(L, 3, "knots.validate", "knot", &m);
    cf_diag_t diag;
    cf_diag_clear(&diag);
    if (np < 0 || cf_knots_validate(p, (size_t)np, u, m, &diag)) {
        lua_pushboolean(L, 0);
        lua_pushstring(L, np < 0 ? "negative number of points" : diag.msg);
        return 2;
    }
    lua_pushboolean(L, 1);
    return 1;
}

static int
k_multiplicity(lua_State *L)
{
    size_t m;
    double *u = cf__lua_check_numbers(L, 1, "knots.multiplicity", "knot", &m);
    double x = cf__lua_check_finite(L, 2, "knots.multiplicity", "u");
    lua_pushinteger(L, cf_knots_multiplicity(u, m, x));
    return 1;
}

/* A knot vector valid for degree p (for the queries that do not check). */
static double *
valid_knots(lua_State *L, int pidx, int uidx, const char *fn, int *p,
            size_t *m)
{
    double *u;
    cf_diag_t diag;
    *p = cf__lua_check_int(L, pidx, fn, "degree", 0, CF_BSPLINE_MAX_DEGREE);
    u = cf__lua_check_numbers(L, uidx, fn, "knot", m);
    cf_diag_clear(&diag);
    if (*m < 2 * (size_t)*p + 2)
        cf__lua_error(L, "%s: %zu knots; degree %d needs at least %d", fn, *m,
                      *p, 2 * *p + 2);
    if (cf_knots_validate(*p, *m - (size_t)*p - 1, u, *m, &diag))
        cf__lua_fail(L, fn, diag.status, &diag);
    return u;
}

/* knots.span(p, U, u) -> k */
static int
k_span(lua_State *L)
{
    int p;
    size_t m;
    double *u = valid_knots(L, 1, 2, "knots.span", &p, &m);
    double x = cf__lua_check_finite(L, 3, "knots.span", "u");
    lua_pushinteger(L, (lua_Integer)cf_knots_find_span(p, u, m, x));
    return 1;
}

static int
k_domain(lua_State *L)
{
    int p;
    size_t m;
    double *u = valid_knots(L, 1, 2, "knots.domain", &p, &m), a, b;
    cf_knots_domain(p, u, m, &a, &b);
    lua_pushnumber(L, a);
    lua_pushnumber(L, b);
    return 2;
}

static int
k_kind(lua_State *L)
{
    int p;
    size_t m;
    double *u = valid_knots(L, 1, 2, "knots.kind", &p, &m);
    lua_pushstring(L, cf_knot_kind_to_string(cf_knots_classify(p, u, m)));
    return 1;
}

static int
k_count(lua_State *L)
{
    int p = cf__lua_check_int(L, 1, "knots.count", "degree", 0,
                              CF_BSPLINE_MAX_DEGREE);
    int n = cf__lua_check_int(L, 2, "knots.count", "number of points", 0,
                              1 << 20);
    lua_pushinteger(L, (lua_Integer)cf_knots_count(p, (size_t)n));
    return 1;
}

/* basis(U, i, p, u [, k]) -> N_i^p(u) (k given: { N, N', ..., N^(k) }) */
static int
l_basis(lua_State *L)
{
    lua_settop(L, 5);
    size_t m;
    double *u = cf__lua_check_numbers(L, 1, "basis", "knot", &m);
    int i = cf__lua_check_int(L, 2, "basis", "i", 0, 1 << 20);
    int p = cf__lua_check_int(L, 3, "basis", "p", 0, CF_BSPLINE_MAX_DEGREE);
    double x = cf__lua_check_finite(L, 4, "basis", "u"), v;
    cf_diag_t diag;
    cf_diag_clear(&diag);
    if (!lua_isnoneornil(L, 5)) {
        int k = cf__lua_check_int(L, 5, "basis", "k", 0, CF__LUA_MAX_DERIV);
        double *d = cf__lua_buffer(L, (size_t)k + 1);
        if (done(L, "basis", cf_basis_one_ders(i, p, u, m, x, k, d, &diag),
                 &diag, 1) != 1)
            return 0;
        cf__lua_push_numbers(L, d, (size_t)k + 1);
        return 1;
    }
    if (done(L, "basis", cf_basis_one(i, p, u, m, x, &v, &diag), &diag, 1) !=
        1)
        return 0;
    lua_pushnumber(L, v);
    return 1;
}

/* basis_funs(U, p, u) -> span k, { N_{k-p}^p(u), ..., N_k^p(u) } */
static int
l_basis_funs(lua_State *L)
{
    lua_settop(L, 3);
    size_t m, span;
    double *u = cf__lua_check_numbers(L, 1, "basis_funs", "knot", &m);
    int p = cf__lua_check_int(L, 2, "basis_funs", "p", 0,
                              CF_BSPLINE_MAX_DEGREE);
    double x = cf__lua_check_finite(L, 3, "basis_funs", "u");
    double *N = cf__lua_buffer(L, (size_t)p + 1);
    cf_diag_t diag;
    cf_diag_clear(&diag);
    if (done(L, "basis_funs", cf_basis_funs(p, u, m, x, &span, N, &diag),
             &diag, 1) != 1)
        return 0;
    lua_pushinteger(L, (lua_Integer)span);
    cf__lua_push_numbers(L, N, (size_t)p + 1);
    return 2;
}

static const luaL_Reg knots_lib[] = {
    { "uniform", k_uniform },
    { "clamped", k_clamped },
    { "averaged", k_averaged },
    { "validate", k_validate },
    { "multiplicity", k_multiplicity },
    { "span", k_span },
    { "domain", k_domain },
    { "kind", k_kind },
    { "count", k_count },
    { NULL, NULL },
};

static const luaL_Reg globals[] = {
    { "basis", l_basis },
    { "basis_funs", l_basis_funs },
    { NULL, NULL },
};

void
cf__lua_open_knots(lua_State *L)
{
    lua_pushglobaltable(L);
    luaL_setfuncs(L, globals, 0);
    lua_pop(L, 1);
    luaL_newlib(L, knots_lib);
    lua_setglobal(L, "knots");
}
