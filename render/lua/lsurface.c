/*
** Lua binding of tensor-product surfaces (include/curvefig/surface.h):
**
**   bezier_surface{ points = P, weights = W }
**   bspline_surface{ degree = {p, q}, knots = {U, V}, points = P,
**                    weights = W }
**
** P[i][j] with i along u.  The methods, and the opener that makes the
** class, are in lsurface-methods.c.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "lbezier.h"
#include "lbspline.h"
#include "lcommon.h"
#include "lschema.h"
#include "lsurface.h"

static cf__lua_surface_t *
new_box(lua_State *L)
{
    cf__lua_surface_t *b = lua_newuserdatauv(L, sizeof *b, 0);
    b->bz = NULL;
    b->bs = NULL;
    luaL_setmetatable(L, CF__LUA_SURFACE);
    return b;
}

cf_bezier_surface_t **
cf__lua_new_bezier_surface(lua_State *L)
{
    return &new_box(L)->bz;
}

cf_bspline_surface_t **
cf__lua_new_bspline_surface(lua_State *L)
{
    return &new_box(L)->bs;
}

cf__lua_surface_t *
cf__lua_check_surface(lua_State *L)
{
    cf__lua_surface_t *b = cf__lua_check_self(L, CF__LUA_SURFACE, "surface");
    if (b->bz == NULL && b->bs == NULL)
        luaL_error(L, "surface: the surface was closed");
    return b;
}

int
cf__lua_surface_gc(lua_State *L)
{
    cf__lua_surface_t *b = luaL_checkudata(L, 1, CF__LUA_SURFACE);
    cf_bezier_surface_destroy(b->bz);
    cf_bspline_surface_destroy(b->bs);
    b->bz = NULL;
    b->bs = NULL;
    return 0;
}

int
cf__lua_surface_tostring(lua_State *L)
{
    cf__lua_surface_t *b = luaL_checkudata(L, 1, CF__LUA_SURFACE);
    char text[256];
    if (b->bz != NULL) {
        snprintf(text, sizeof text,
                 "%sbezier surface of degrees (%d, %d) in R^%zu",
                 cf_bezier_surface_is_rational(b->bz) ? "rational " : "",
                 cf_bezier_surface_degree_u(b->bz),
                 cf_bezier_surface_degree_v(b->bz),
                 cf_bezier_surface_dim(b->bz));
    } else if (b->bs != NULL) {
        double ua, ub, va, vb;
        cf_bspline_surface_domain(b->bs, CF_DIR_U, &ua, &ub);
        cf_bspline_surface_domain(b->bs, CF_DIR_V, &va, &vb);
        snprintf(text, sizeof text,
                 "%s surface of degrees (%d, %d), %zu x %zu points in R^%zu "
                 "on [%g, %g] x [%g, %g]",
                 cf_bspline_surface_is_rational(b->bs) ? "nurbs" : "bspline",
                 cf_bspline_surface_degree_u(b->bs),
                 cf_bspline_surface_degree_v(b->bs),
                 cf_bspline_surface_count_u(b->bs),
                 cf_bspline_surface_count_v(b->bs),
                 cf_bspline_surface_dim(b->bs), ua, ub, va, vb);
    } else {
        snprintf(text, sizeof text, "surface (closed)");
    }
    lua_pushstring(L, text);
    return 1;
}

/* ---- reading grids ------------------------------------------------------ */

/* The row i (1-based) of the grid at idx, pushed; its length. */
static size_t
row_at(lua_State *L, int idx, size_t i, const char *fn, const char *what)
{
    lua_geti(L, idx, (lua_Integer)i);
    if (!lua_istable(L, -1))
        cf__lua_error(L, "%s: row %zu of the %s must be a table, got %s", fn,
                      i, what, luaL_typename(L, -1));
    return (size_t)lua_rawlen(L, -1);
}

double *
cf__lua_check_grid(lua_State *L, int idx, const char *fn, size_t *nu,
                   size_t *nv, size_t *dim)
{
    size_t rows, cols = 0, d = 0;
    double *buf;
    idx = lua_absindex(L, idx);
    if (!lua_istable(L, idx))
        cf__lua_error(L, "%s: points must be a grid { {P11, P12, ...}, "
                      "{P21, ...}, ... }, got %s", fn, luaL_typename(L, idx));
    rows = (size_t)lua_rawlen(L, idx);
    if (rows < 1)
        cf__lua_error(L, "%s: the grid of points has no rows", fn);
    /* shapes first: every row as long as row 1, every point as row 1's */
    for (size_t i = 1; i <= rows; i++) {
        size_t n = row_at(L, idx, i, fn, "points");
        if (i == 1)
            cols = n;
        else if (n != cols)
            cf__lua_error(L, "%s: row %zu has %zu point%s, row 1 has %zu", fn,
                          i, n, n == 1 ? "" : "s", cols);
        if (n < 1)
            cf__lua_error(L, "%s: row %zu has no points", fn, i);
        for (size_t j = 1; j <= n; j++) {
            size_t k;
            lua_geti(L, -1, (lua_Integer)j);
            if (!lua_istable(L, -1))
                cf__lua_error(L, "%s: point P[%zu][%zu] must be a table "
                              "{x, y, ...}, got %s", fn, i, j,
                              luaL_typename(L, -1));
            k = (size_t)lua_rawlen(L, -1);
            if (i == 1 && j == 1)
                d = k;
            if (k != d || k < 1)
                cf__lua_error(L, "%s: point P[%zu][%zu] has %zu "
                              "coordinates, P[1][1] has %zu", fn, i, j, k, d);
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    if (d > CF__LUA_MAX_DIM)
        cf__lua_error(L, "%s: points with %zu coordinates; at most %d", fn, d,
                      CF__LUA_MAX_DIM);
    buf = cf__lua_buffer(L, rows * cols * d);
    for (size_t i = 1; i <= rows; i++) {
        lua_geti(L, idx, (lua_Integer)i);
        for (size_t j = 1; j <= cols; j++) {
            lua_geti(L, -1, (lua_Integer)j);
            for (size_t k = 1; k <= d; k++) {
                int isnum;
                double x;
                lua_geti(L, -1, (lua_Integer)k);
                x = (double)lua_tonumberx(L, -1, &isnum);
                if (!isnum)
                    cf__lua_error(L, "%s: point P[%zu][%zu] has coordinate "
                                  "%zu = %s, not a number", fn, i, j, k,
                                  luaL_typename(L, -1));
                if (!isfinite(x))
                    cf__lua_error(L, "%s: point P[%zu][%zu] has coordinate "
                                  "%zu = %g; coordinates must be finite", fn,
                                  i, j, k, x);
                buf[((i - 1) * cols + j - 1) * d + k - 1] = x;
                lua_pop(L, 1);
            }
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    *nu = rows;
    *nv = cols;
    *dim = d;
    return buf;
}

/* The weights grid at idx, of the points' shape (positive, finite). */
static double *
check_weights(lua_State *L, int idx, const char *fn, size_t nu, size_t nv)
{
    double *w;
    idx = lua_absindex(L, idx);
    if (!lua_istable(L, idx) || lua_rawlen(L, idx) != nu)
        cf__lua_error(L, "%s: weights must be a grid of %zu row%s like the "
                      "points, got %s", fn, nu, nu == 1 ? "" : "s",
                      lua_istable(L, idx) ? "another number of rows"
                                          : luaL_typename(L, idx));
    w = cf__lua_buffer(L, nu * nv);
    for (size_t i = 1; i <= nu; i++) {
        size_t n = row_at(L, idx, i, fn, "weights");
        if (n != nv)
            cf__lua_error(L, "%s: weights row %zu has %zu value%s, the "
                          "points' rows have %zu", fn, i, n,
                          n == 1 ? "" : "s", nv);
        for (size_t j = 1; j <= nv; j++) {
            int isnum;
            double x;
            lua_geti(L, -1, (lua_Integer)j);
            x = (double)lua_tonumberx(L, -1, &isnum);
            if (!isnum || !isfinite(x) || !(x > 0.0))
                cf__lua_error(L, "%s: weight W[%zu][%zu] is %s; weights "
                              "must be finite and positive", fn, i, j,
                              isnum ? lua_tostring(L, -1)
                                    : luaL_typename(L, -1));
            w[(i - 1) * nv + j - 1] = x;
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    return w;
}

static double *
opt_weights(lua_State *L, const char *fn, size_t nu, size_t nv)
{
    if (cf__lua_field(L, 1, "weights") == LUA_TNIL)
        return NULL;
    return check_weights(L, -1, fn, nu, nv);
}

/* ---- constructors ------------------------------------------------------- */

int
cf__lua_bezier_surface(lua_State *L)
{
    size_t nu, nv, dim;
    double *P, *W;
    cf_bezier_surface_t **out;
    cf_diag_t diag;
    luaL_checktype(L, 1, LUA_TTABLE);
    cf__lua_check_table(L, 1, CF__KEYS_BEZIER_SURFACE);
    if (cf__lua_field(L, 1, "points") == LUA_TNIL)
        return cf__lua_error(L, "bezier_surface: points = { {P11, P12, ...}, "
                             "... } is missing");
    P = cf__lua_check_grid(L, -1, "bezier_surface", &nu, &nv, &dim);
    W = opt_weights(L, "bezier_surface", nu, nv);
    if (nu - 1 > CF_BEZIER_MAX_DEGREE || nv - 1 > CF_BEZIER_MAX_DEGREE)
        return cf__lua_error(L, "bezier_surface: %zu x %zu points; at most %d "
                             "per direction", nu, nv, CF_BEZIER_MAX_DEGREE + 1);
    out = cf__lua_new_bezier_surface(L);
    return cf__lua_done(L, "bezier_surface",
                        cf_bezier_surface_create(dim, (int)nu - 1,
                                                 (int)nv - 1, P, W, out,
                                                 &diag),
                        &diag, 1);
}

/* Clamped uniform knots for n points of degree p (a scratch buffer). */
static double *
clamped(lua_State *L, int p, size_t n, const char *fn)
{
    double *K = cf__lua_buffer(L, n + (size_t)p + 1);
    cf_diag_t diag;
    cf_status_t st = cf_knots_clamped_uniform(p, n, 0.0, 1.0, K, &diag);
    if (st != CF_STATUS_OK)
        cf__lua_fail(L, fn, st, &diag);
    return K;
}

int
cf__lua_bspline_surface(lua_State *L)
{
    static const char *fn = "bspline_surface";
    size_t nu, nv, dim, nU, nV;
    int p, q;
    double *P, *W, *U, *V;
    cf_bspline_surface_t **out;
    cf_diag_t diag;
    luaL_checktype(L, 1, LUA_TTABLE);
    cf__lua_check_table(L, 1, CF__KEYS_BSPLINE_SURFACE);
    if (cf__lua_field(L, 1, "points") == LUA_TNIL)
        return cf__lua_error(L, "%s: points = { {P11, P12, ...}, ... } is "
                             "missing", fn);
    P = cf__lua_check_grid(L, -1, fn, &nu, &nv, &dim);
    W = opt_weights(L, fn, nu, nv);
    if (cf__lua_field(L, 1, "degree") == LUA_TTABLE) {
        lua_geti(L, -1, 1);
        p = cf__lua_check_int(L, -1, fn, "degree p", 0,
                              CF_BSPLINE_MAX_DEGREE);
        lua_geti(L, -2, 2);
        q = cf__lua_check_int(L, -1, fn, "degree q", 0,
                              CF_BSPLINE_MAX_DEGREE);
    } else {
        p = q = cf__lua_opt_int(L, -1, fn, "degree", 0, CF_BSPLINE_MAX_DEGREE,
                                3);
    }
    if (cf__lua_field(L, 1, "knots") != LUA_TNIL) {
        int k = lua_gettop(L);
        if (!lua_istable(L, k) || lua_rawlen(L, k) != 2)
            return cf__lua_error(L, "%s: knots must be { U, V }, two lists "
                                 "of numbers", fn);
        lua_geti(L, k, 1);
        U = cf__lua_check_numbers(L, -1, fn, "knot of U", &nU);
        lua_geti(L, k, 2);
        V = cf__lua_check_numbers(L, -1, fn, "knot of V", &nV);
    } else {
        U = clamped(L, p, nu, fn);
        V = clamped(L, q, nv, fn);
        nU = nu + (size_t)p + 1;
        nV = nv + (size_t)q + 1;
    }
    out = cf__lua_new_bspline_surface(L);
    return cf__lua_done(L, fn,
                        cf_bspline_surface_create(dim, p, q, U, nU, V, nV, P,
                                                  nu, nv, W, out, &diag),
                        &diag, 1);
}
