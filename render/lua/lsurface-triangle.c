/*
** Lua binding of triangular Bézier patches (include/curvefig/
** surface-triangle.h):
**
**   t = bezier_triangle{ degree = n, points = {...}, weights = {...} }
**
** the (n + 1)(n + 2) / 2 points in the order b_n00, b_(n-1)10, b_(n-1)01,
** b_(n-2)20, ... (by i downwards, then j downwards).  A point of the
** domain is (u, v), w = 1 - u - v.  Methods: t:eval(u, v),
** t:derivs(u, v, {du, dv, dw}, k), t:normal(u, v), t:decasteljau(u, v)
** (levels), t:subdivide(u, v) (three patches), t:elevate(),
** t:boundary(e) (e = 1: w = 0, 2: u = 0, 3: v = 0; a bezier curve),
** t:points(), t:weights(), t:degree(), t:dim().
*/
#include "curvefig/surface-triangle.h"
#include "lbezier.h"
#include "lcommon.h"
#include "lschema.h"
#include "lsurface.h"

#define CF__LUA_TRIANGLE "curvefig.triangle"

typedef struct box {
    cf_bezier_triangle_t *t;
} box;

static cf_bezier_triangle_t **
new_triangle(lua_State *L)
{
    box *b = lua_newuserdatauv(L, sizeof *b, 0);
    b->t = NULL;
    luaL_setmetatable(L, CF__LUA_TRIANGLE);
    return &b->t;
}

static cf_bezier_triangle_t *
check(lua_State *L)
{
    box *b = cf__lua_check_self(L, CF__LUA_TRIANGLE, "triangle");
    if (b->t == NULL)
        luaL_error(L, "bezier_triangle: the patch was closed");
    return b->t;
}

cf_bezier_triangle_t *
cf__lua_to_triangle(lua_State *L, int idx)
{
    box *b = luaL_testudata(L, idx, CF__LUA_TRIANGLE);
    return b != NULL ? b->t : NULL;
}

static int
gc(lua_State *L)
{
    box *b = luaL_checkudata(L, 1, CF__LUA_TRIANGLE);
    cf_bezier_triangle_destroy(b->t);
    b->t = NULL;
    return 0;
}

static int
tostring(lua_State *L)
{
    box *b = luaL_checkudata(L, 1, CF__LUA_TRIANGLE);
    if (b->t == NULL)
        lua_pushliteral(L, "bezier triangle (closed)");
    else
        lua_pushfstring(L, "%sbezier triangle of degree %d in R^%d",
                        cf_bezier_triangle_is_rational(b->t) ? "rational "
                                                             : "",
                        cf_bezier_triangle_degree(b->t),
                        (int)cf_bezier_triangle_dim(b->t));
    return 1;
}

static int
l_bezier_triangle(lua_State *L)
{
    static const char *fn = "bezier_triangle";
    size_t n, dim, nw = 0, need;
    double *P, *W = NULL;
    int deg;
    cf_bezier_triangle_t **out;
    cf_diag_t diag;
    luaL_checktype(L, 1, LUA_TTABLE);
    cf__lua_check_table(L, 1, CF__KEYS_BEZIER_TRIANGLE);
    cf__lua_field(L, 1, "degree");
    deg = cf__lua_check_int(L, -1, fn, "degree", 0,
                            CF_BEZIER_TRIANGLE_MAX_DEGREE);
    if (cf__lua_field(L, 1, "points") == LUA_TNIL)
        return cf__lua_error(L, "%s: points = {...} is missing", fn);
    P = cf__lua_check_points(L, -1, fn, "point", 1, &n, &dim);
    need = ((size_t)deg + 1) * ((size_t)deg + 2) / 2;
    if (n != need)
        return cf__lua_error(L, "%s: degree %d needs %zu points "
                             "((n + 1)(n + 2) / 2), got %zu", fn, deg, need,
                             n);
    if (cf__lua_field(L, 1, "weights") != LUA_TNIL) {
        W = cf__lua_check_numbers(L, -1, fn, "weight", &nw);
        if (nw != n)
            return cf__lua_error(L, "%s: %zu weights given for %zu points",
                                 fn, nw, n);
        for (size_t i = 0; i < nw; i++)
            if (!(W[i] > 0.0))
                return cf__lua_error(L, "%s: weight %zu is %g; weights must "
                                     "be positive", fn, i + 1, W[i]);
    }
    out = new_triangle(L);
    return cf__lua_done(L, fn,
                        cf_bezier_triangle_create(dim, deg, P, W, out, &diag),
                        &diag, 1);
}

static int
domain_error(lua_State *L, const char *fn, double u, double v,
             cf_status_t st)
{
    if (st == CF_STATUS_DOMAIN)
        return cf__lua_error(L, "%s: (u, v, w) = (%g, %g, %g) is outside "
                             "the triangle u, v, w >= 0", fn, u, v,
                             1.0 - u - v);
    return cf__lua_fail(L, fn, st, NULL);
}

static int
m_eval(lua_State *L)
{
    cf_bezier_triangle_t *t = check(L);
    double u = cf__lua_check_finite(L, 2, "eval", "u");
    double v = cf__lua_check_finite(L, 3, "eval", "v");
    size_t dim = cf_bezier_triangle_dim(t);
    double *out = cf__lua_buffer(L, dim);
    cf_status_t st = cf_bezier_triangle_eval(t, u, v, out);
    if (st != CF_STATUS_OK)
        return domain_error(L, "eval", u, v, st);
    cf__lua_push_point(L, out, dim);
    return 1;
}

/* t:derivs(u, v, {du, dv, dw}, k) -> { T, D T, ..., D^k T } */
static int
m_derivs(lua_State *L)
{
    cf_bezier_triangle_t *t = check(L);
    double u = cf__lua_check_finite(L, 2, "derivs", "u");
    double v = cf__lua_check_finite(L, 3, "derivs", "v");
    size_t three = 3, dim = cf_bezier_triangle_dim(t);
    double *d = cf__lua_check_point(L, 4, "derivs", "direction", &three);
    int k = cf__lua_opt_int(L, 5, "derivs", "k", 0, 16, 1);
    double *out = cf__lua_buffer(L, ((size_t)k + 1) * dim);
    cf_status_t st = cf_bezier_triangle_eval_derivs(t, d, u, v, k, out);
    if (st == CF_STATUS_INVALID_ARG)
        return cf__lua_error(L, "derivs: the direction {du, dv, dw} = "
                             "{%g, %g, %g} must sum to 0", d[0], d[1], d[2]);
    if (st != CF_STATUS_OK)
        return domain_error(L, "derivs", u, v, st);
    cf__lua_push_points(L, out, (size_t)k + 1, dim);
    return 1;
}

static int
m_normal(lua_State *L)
{
    cf_bezier_triangle_t *t = check(L);
    double u = cf__lua_check_finite(L, 2, "normal", "u");
    double v = cf__lua_check_finite(L, 3, "normal", "v");
    double n[3];
    cf_status_t st;
    if (cf_bezier_triangle_dim(t) != 3)
        return cf__lua_error(L, "normal: the patch lies in R^%d; normals "
                             "need R^3", (int)cf_bezier_triangle_dim(t));
    st = cf_bezier_triangle_normal(t, u, v, n);
    if (st == CF_STATUS_DEGENERATE)
        return cf__lua_error(L, "normal: no normal at (u, v) = (%g, %g)", u,
                             v);
    if (st != CF_STATUS_OK)
        return domain_error(L, "normal", u, v, st);
    cf__lua_push_point(L, n, 3);
    return 1;
}

/* t:decasteljau(u, v) -> levels, level l + 1 the points b^l_ijk */
static int
m_decasteljau(lua_State *L)
{
    cf_bezier_triangle_t *t = check(L);
    double u = cf__lua_check_finite(L, 2, "decasteljau", "u");
    double v = cf__lua_check_finite(L, 3, "decasteljau", "v");
    size_t dim = cf_bezier_triangle_dim(t), at = 0;
    int n = cf_bezier_triangle_degree(t);
    double *out = cf__lua_buffer(L, cf_bezier_triangle_decasteljau_size(t));
    cf_status_t st = cf_bezier_triangle_decasteljau(t, u, v, out);
    if (st != CF_STATUS_OK)
        return domain_error(L, "decasteljau", u, v, st);
    lua_createtable(L, n + 1, 0);
    for (int m = n; m >= 0; m--) {
        size_t cnt = ((size_t)m + 1) * ((size_t)m + 2) / 2;
        cf__lua_push_points(L, out + at * dim, cnt, dim);
        lua_rawseti(L, -2, n - m + 1);
        at += cnt;
    }
    return 1;
}

static int
m_subdivide(lua_State *L)
{
    cf_bezier_triangle_t *t = check(L);
    double u = cf__lua_check_finite(L, 2, "subdivide", "u");
    double v = cf__lua_check_finite(L, 3, "subdivide", "v");
    cf_bezier_triangle_t **slot[3], *parts[3];
    cf_diag_t diag;
    cf_status_t st;
    for (int i = 0; i < 3; i++)
        slot[i] = new_triangle(L);
    st = cf_bezier_triangle_subdivide(t, u, v, parts, &diag);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "subdivide", st, &diag);
    for (int i = 0; i < 3; i++)
        *slot[i] = parts[i];
    return 3;
}

static int
m_elevate(lua_State *L)
{
    cf_bezier_triangle_t *t = check(L);
    cf_bezier_triangle_t **out = new_triangle(L);
    cf_diag_t diag;
    return cf__lua_done(L, "elevate",
                        cf_bezier_triangle_elevate(t, out, &diag), &diag, 1);
}

static int
m_boundary(lua_State *L)
{
    cf_bezier_triangle_t *t = check(L);
    int e = cf__lua_check_int(L, 2, "boundary", "edge", 1, 3);
    cf_bezier_t **out = cf__lua_new_bezier(L);
    cf_diag_t diag;
    return cf__lua_done(L, "boundary",
                        cf_bezier_triangle_boundary(t, e - 1, out, &diag),
                        &diag, 1);
}

static int
m_points(lua_State *L)
{
    cf_bezier_triangle_t *t = check(L);
    size_t n = cf_bezier_triangle_count(t), dim = cf_bezier_triangle_dim(t);
    double *P = cf__lua_buffer(L, n * dim);
    cf_bezier_triangle_get_points(t, P);
    cf__lua_push_points(L, P, n, dim);
    return 1;
}

static int
m_weights(lua_State *L)
{
    cf_bezier_triangle_t *t = check(L);
    size_t n = cf_bezier_triangle_count(t);
    double *W = cf__lua_buffer(L, n);
    cf_bezier_triangle_get_weights(t, W);
    cf__lua_push_numbers(L, W, n);
    return 1;
}

static int
m_degree(lua_State *L)
{
    lua_pushinteger(L, cf_bezier_triangle_degree(check(L)));
    return 1;
}

static int
m_dim(lua_State *L)
{
    lua_pushinteger(L, (lua_Integer)cf_bezier_triangle_dim(check(L)));
    return 1;
}

static const luaL_Reg methods[] = {
    { "eval", m_eval },
    { "derivs", m_derivs },
    { "normal", m_normal },
    { "decasteljau", m_decasteljau },
    { "subdivide", m_subdivide },
    { "elevate", m_elevate },
    { "boundary", m_boundary },
    { "points", m_points },
    { "weights", m_weights },
    { "degree", m_degree },
    { "dim", m_dim },
    { NULL, NULL },
};

void
cf__lua_open_surface_triangle(lua_State *L)
{
    cf__lua_new_class(L, CF__LUA_TRIANGLE, methods, gc, tostring);
    lua_pushcfunction(L, l_bezier_triangle);
    lua_setglobal(L, "bezier_triangle");
}
