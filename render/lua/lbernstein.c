/*
** Lua binding of the Bernstein basis (include/curvefig/bernstein.h) and of
** the planar geometry helpers (include/curvefig/geometry.h).
**
**   bernstein(n, i, t)         B_i^n(t)
**   bernstein_all(n, t [, k])  { B_0^n(t), ..., B_n^n(t) } (k-th derivatives)
**   bernstein_approx(f, n)     the graph t -> (t, f_n(t)) as a Bézier curve
**   bernstein_from_power(a), bernstein_to_power(b)  coefficient conversion
**   bernstein_matrix(n), power_matrix(n)            the conversion matrices
**   convex_hull(points)        hull vertices (counter-clockwise), indices
*/
#include <math.h>

#include "curvefig/bernstein.h"
#include "curvefig/geometry.h"
#include "lbezier.h"
#include "lcommon.h"

static int
l_bernstein(lua_State *L)
{
    int n = cf__lua_check_int(L, 1, "bernstein", "n", 0, CF_BEZIER_MAX_DEGREE);
    int i = cf__lua_check_int(L, 2, "bernstein", "i", -(1 << 20), 1 << 20);
    double t = cf__lua_check_finite(L, 3, "bernstein", "t"), v;
    if (cf_bernstein_value(n, i, t, &v) != CF_STATUS_OK)
        return cf__lua_error(L, "bernstein: t = %g is outside [0, 1]", t);
    lua_pushnumber(L, v);
    return 1;
}

static int
l_bernstein_all(lua_State *L)
{
    lua_settop(L, 3);
    int n = cf__lua_check_int(L, 1, "bernstein_all", "n", 0,
                              CF_BEZIER_MAX_DEGREE);
    double t = cf__lua_check_finite(L, 2, "bernstein_all", "t");
    int k = cf__lua_opt_int(L, 3, "bernstein_all", "k", 0, CF__LUA_MAX_DERIV,
                            0);
    double *v = cf__lua_buffer(L, (size_t)n + 1);
    if (cf_bernstein_all_deriv(n, t, k, v) != CF_STATUS_OK)
        return cf__lua_error(L, "bernstein_all: t = %g is outside [0, 1]", t);
    cf__lua_push_numbers(L, v, (size_t)n + 1);
    return 1;
}

typedef struct func_ctx {
    lua_State *L;
    int failed;
} func_ctx;

/* Called by the library: the Lua function (at index 1) runs protected and
** its error is raised again after the library returned. */
static double
call_f(double t, void *ud)
{
    func_ctx *c = ud;
    int isnum;
    double y;
    if (c->failed)
        return NAN;
    lua_pushvalue(c->L, 1);
    lua_pushnumber(c->L, t);
    if (lua_pcall(c->L, 1, 1, 0) != LUA_OK) {
        c->failed = 1;
        return NAN;
    }
    y = (double)lua_tonumberx(c->L, -1, &isnum);
    lua_pop(c->L, 1);
    if (!isnum) {
        lua_pushfstring(c->L, "bernstein_approx: f(%f) is not a number", t);
        c->failed = 1;
        return NAN;
    }
    return y;
}

/* bernstein_approx(f, n) -> Bézier curve t -> (t, f_n(t)), coefficients */
static int
l_bernstein_approx(lua_State *L)
{
    lua_settop(L, 2);
    luaL_checktype(L, 1, LUA_TFUNCTION);
    int n = cf__lua_check_int(L, 2, "bernstein_approx", "n", 1,
                              CF_BEZIER_MAX_DEGREE);
    cf_bezier_t **out = cf__lua_new_bezier(L);
    func_ctx c;
    cf_diag_t diag;
    cf_status_t st;
    c.L = L;
    c.failed = 0;
    cf_diag_clear(&diag);
    st = cf_bernstein_approx_curve(call_f, &c, n, out, &diag);
    if (c.failed)
        return lua_error(L);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "bernstein_approx", st, &diag);
    return 1;
}

typedef cf_status_t (*convert_fn)(int, const double *, double *,
                                  cf_diag_t *);

static int
convert(lua_State *L, const char *fn, convert_fn f)
{
    size_t n;
    double *a = cf__lua_check_numbers(L, 1, fn, "coefficient", &n);
    double *b = cf__lua_buffer(L, n);
    cf_diag_t diag;
    cf_status_t st;
    if (n < 1)
        return luaL_error(L, "%s: no coefficients", fn);
    cf_diag_clear(&diag);
    st = f((int)n - 1, a, b, &diag);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, fn, st, &diag);
    cf__lua_push_numbers(L, b, n);
    return 1;
}

static int
l_from_power(lua_State *L)
{
    return convert(L, "bernstein_from_power", cf_bernstein_from_power);
}

static int
l_to_power(lua_State *L)
{
    return convert(L, "bernstein_to_power", cf_bernstein_to_power);
}

typedef cf_status_t (*matrix_fn)(int, double *, cf_diag_t *);

static int
matrix(lua_State *L, const char *fn, matrix_fn f)
{
    int n = cf__lua_check_int(L, 1, fn, "n", 0,
                              CF_BERNSTEIN_MATRIX_MAX_DEGREE);
    size_t k = (size_t)n + 1;
    double *m = cf__lua_buffer(L, k * k);
    cf_diag_t diag;
    cf_status_t st;
    cf_diag_clear(&diag);
    st = f(n, m, &diag);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, fn, st, &diag);
    cf__lua_push_points(L, m, k, k);
    return 1;
}

/* rows of M: [B_0^n ... B_n^n] = [1 t ... t^n] M */
static int
l_bernstein_matrix(lua_State *L)
{
    return matrix(L, "bernstein_matrix", cf_bernstein_to_power_matrix);
}

static int
l_power_matrix(lua_State *L)
{
    return matrix(L, "power_matrix", cf_power_to_bernstein_matrix);
}

/* convex_hull(points) -> hull points (counter-clockwise), their indices
** (0-based, as P_i) */
static int
l_convex_hull(lua_State *L)
{
    size_t n, dim, h;
    double *p = cf__lua_check_points(L, 1, "convex_hull", "point", 1, &n,
                                     &dim);
    size_t *idx = lua_newuserdatauv(L, n * sizeof *idx, 0);
    cf_diag_t diag;
    cf_status_t st;
    if (dim != 2)
        return cf__lua_error(L, "convex_hull: points in R^%zu; give planar "
                             "points", dim);
    cf_diag_clear(&diag);
    st = cf_convex_hull_2d(p, n, 2, idx, &h, &diag);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "convex_hull", st, &diag);
    lua_createtable(L, (int)h, 0);
    lua_createtable(L, (int)h, 0);
    for (size_t i = 0; i < h; i++) {
        cf__lua_push_point(L, p + 2 * idx[i], 2);
        lua_rawseti(L, -3, (lua_Integer)i + 1);
        lua_pushinteger(L, (lua_Integer)idx[i]);
        lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
    return 2;
}

static const luaL_Reg globals[] = {
    { "bernstein", l_bernstein },
    { "bernstein_all", l_bernstein_all },
    { "bernstein_approx", l_bernstein_approx },
    { "bernstein_from_power", l_from_power },
    { "bernstein_to_power", l_to_power },
    { "bernstein_matrix", l_bernstein_matrix },
    { "power_matrix", l_power_matrix },
    { "convex_hull", l_convex_hull },
    { NULL, NULL },
};

void
cf__lua_open_bernstein(lua_State *L)
{
    lua_pushglobaltable(L);
    luaL_setfuncs(L, globals, 0);
    lua_pop(L, 1);
}
