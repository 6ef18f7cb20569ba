/*
** Lua methods of surfaces (include/curvefig/surface.h; the class and the
** constructors are in lsurface.c):
**
**   s:eval(u, v) or s:eval{ {u, v}, ... }, s:derivs(u, v, k), s:normal(u, v),
**   s:curvature(u, v), s:iso("u" | "v", value), s:split("u" | "v", value),
**   s:insert_knot("u" | "v", value, r), s:elevate(ru, rv),
**   s:decasteljau(u, v), s:deboor(u, v), s:to_bezier(), s:to_bspline(),
**   s:points(), s:weights(), s:degree(), s:knots(), s:knot_lines("u"),
**   s:dim(), s:is_rational().
**
** Every method returns new values; none modifies its receiver.
*/
#include <string.h>

#include "lbezier.h"
#include "lbspline.h"
#include "lcommon.h"
#include "lschema.h"
#include "lsurface.h"
#include "../../src/numtext-private.h"

#define check cf__lua_check_surface

static size_t
dim_of(const cf__lua_surface_t *b)
{
    return b->bz ? cf_bezier_surface_dim(b->bz) : cf_bspline_surface_dim(b->bs);
}

/* A parameter-domain error in the user's terms. */
static int
param_error(lua_State *L, const cf__lua_surface_t *b, const char *fn, double u, double v,
            cf_status_t st)
{
    double ua = 0, ub = 1, va = 0, vb = 1;
    if (b->bs != NULL) {
        cf_bspline_surface_domain(b->bs, CF_DIR_U, &ua, &ub);
        cf_bspline_surface_domain(b->bs, CF_DIR_V, &va, &vb);
    }
    if (st == CF_STATUS_DOMAIN)
        return cf__lua_error(L, "%s: (u, v) = (%s, %s) is outside the "
                             "domain [%s, %s] x [%s, %s]", fn,
                             CF__NUM(u), CF__NUM(v), CF__NUM(ua),
                             CF__NUM(ub), CF__NUM(va), CF__NUM(vb));
    return cf__lua_fail(L, fn, st, NULL);
}

static cf_status_t
eval_one(const cf__lua_surface_t *b, double u, double v, double *out)
{
    return b->bz ? cf_bezier_surface_eval(b->bz, u, v, out)
                 : cf_bspline_surface_eval(b->bs, u, v, out);
}

/* s:eval(u, v) -> point; s:eval{ {u, v}, ... } -> list of points */
static int
m_eval(lua_State *L)
{
    cf__lua_surface_t *b = check(L);
    size_t dim = dim_of(b), n, d = 2;
    double *out;
    if (lua_istable(L, 2)) {
        double *uv = cf__lua_check_points(L, 2, "eval", "parameter pair", 1,
                                          &n, &d);
        if (d != 2)
            return cf__lua_error(L, "eval: parameter pairs are {u, v}; got "
                                 "%zu numbers each", d);
        out = cf__lua_buffer(L, n * dim);
        for (size_t i = 0; i < n; i++) {
            cf_status_t st = eval_one(b, uv[2 * i], uv[2 * i + 1],
                                      out + i * dim);
            if (st != CF_STATUS_OK)
                return param_error(L, b, "eval", uv[2 * i], uv[2 * i + 1],
                                   st);
        }
        cf__lua_push_points(L, out, n, dim);
        return 1;
    } else {
        double u = cf__lua_check_finite(L, 2, "eval", "u");
        double v = cf__lua_check_finite(L, 3, "eval", "v");
        cf_status_t st;
        out = cf__lua_buffer(L, dim);
        st = eval_one(b, u, v, out);
        if (st != CF_STATUS_OK)
            return param_error(L, b, "eval", u, v, st);
        cf__lua_push_point(L, out, dim);
        return 1;
    }
}

/* s:derivs(u, v, k) -> D with D[a+1][b+1] = d^(a+b) S / du^a dv^b,
** a + b <= k */
static int
m_derivs(lua_State *L)
{
    cf__lua_surface_t *b = check(L);
    double u = cf__lua_check_finite(L, 2, "derivs", "u");
    double v = cf__lua_check_finite(L, 3, "derivs", "v");
    int k = cf__lua_opt_int(L, 4, "derivs", "k", 0, 16, 1);
    size_t dim = dim_of(b), K = (size_t)k + 1;
    double *out = cf__lua_buffer(L, K * K * dim);
    cf_status_t st = b->bz
                         ? cf_bezier_surface_eval_derivs(b->bz, u, v, k, out)
                         : cf_bspline_surface_eval_derivs(b->bs, u, v, k, out);
    if (st != CF_STATUS_OK)
        return param_error(L, b, "derivs", u, v, st);
    lua_createtable(L, (int)K, 0);
    for (size_t a = 0; a < K; a++) {
        cf__lua_push_points(L, out + a * K * dim, K - a, dim);
        lua_rawseti(L, -2, (lua_Integer)a + 1);
    }
    return 1;
}

static int
m_normal(lua_State *L)
{
    cf__lua_surface_t *b = check(L);
    double u = cf__lua_check_finite(L, 2, "normal", "u");
    double v = cf__lua_check_finite(L, 3, "normal", "v");
    double n[3];
    cf_status_t st;
    if (dim_of(b) != 3)
        return cf__lua_error(L, "normal: the surface lies in R^%zu; normals "
                             "need R^3", dim_of(b));
    st = b->bz ? cf_bezier_surface_normal(b->bz, u, v, n)
               : cf_bspline_surface_normal(b->bs, u, v, n);
    if (st == CF_STATUS_DEGENERATE)
        return cf__lua_error(L, "normal: S_u x S_v = 0 at (u, v) = (%g, %g): "
                             "no normal there", u, v);
    if (st != CF_STATUS_OK)
        return param_error(L, b, "normal", u, v, st);
    cf__lua_push_point(L, n, 3);
    return 1;
}

/* s:curvature(u, v) -> K, H (Gaussian, mean) */
static int
m_curvature(lua_State *L)
{
    cf__lua_surface_t *b = check(L);
    double u = cf__lua_check_finite(L, 2, "curvature", "u");
    double v = cf__lua_check_finite(L, 3, "curvature", "v");
    double K, H;
    cf_status_t st;
    if (dim_of(b) != 3)
        return cf__lua_error(L, "curvature: the surface lies in R^%zu; "
                             "curvatures need R^3", dim_of(b));
    st = b->bz ? cf_bezier_surface_curvature(b->bz, u, v, &K, &H)
               : cf_bspline_surface_curvature(b->bs, u, v, &K, &H);
    if (st == CF_STATUS_DEGENERATE)
        return cf__lua_error(L, "curvature: S_u x S_v = 0 at (u, v) = "
                             "(%g, %g)", u, v);
    if (st != CF_STATUS_OK)
        return param_error(L, b, "curvature", u, v, st);
    lua_pushnumber(L, K);
    lua_pushnumber(L, H);
    return 2;
}

static cf_dir_t
check_dir(lua_State *L, int idx, const char *fn)
{
    static const char *const names[] = { "u", "v", NULL };
    const char *s = cf__lua_opt_text(L, idx, fn, "direction", NULL);
    if (strcmp(s, "u") == 0)
        return CF_DIR_U;
    if (strcmp(s, "v") == 0)
        return CF_DIR_V;
    {
        const char *near = cf_nearest_name(s, names, 2);
        cf__lua_error(L, "%s: direction \"%s\" is neither \"u\" nor \"v\"%s%s"
                      "%s", fn, s, near ? " (did you mean \"" : "",
                      near ? near : "", near ? "\"?)" : "");
    }
    return CF_DIR_U;
}

/* s:iso("u", u0) -> the curve v -> S(u0, v) (a bezier or bspline) */
static int
m_iso(lua_State *L)
{
    cf__lua_surface_t *b = check(L);
    cf_dir_t dir = check_dir(L, 2, "iso");
    double x = cf__lua_check_finite(L, 3, "iso", "value");
    cf_diag_t diag;
    if (b->bz != NULL) {
        cf_bezier_t **out = cf__lua_new_bezier(L);
        return cf__lua_done(L, "iso",
                            cf_bezier_surface_iso(b->bz, dir, x, out, &diag),
                            &diag, 1);
    } else {
        cf_bspline_t **out = cf__lua_new_bspline(L);
        return cf__lua_done(L, "iso",
                            cf_bspline_surface_iso(b->bs, dir, x, out, &diag),
                            &diag, 1);
    }
}

/* s:split("u", u0) -> lo, hi */
static int
m_split(lua_State *L)
{
    cf__lua_surface_t *b = check(L);
    cf_dir_t dir = check_dir(L, 2, "split");
    double x = cf__lua_check_finite(L, 3, "split", "value");
    cf_diag_t diag;
    cf_status_t st;
    if (b->bz != NULL) {
        cf_bezier_surface_t **lo = cf__lua_new_bezier_surface(L);
        cf_bezier_surface_t **hi = cf__lua_new_bezier_surface(L);
        st = cf_bezier_surface_split(b->bz, dir, x, lo, hi, &diag);
    } else {
        cf_bspline_surface_t **lo = cf__lua_new_bspline_surface(L);
        cf_bspline_surface_t **hi = cf__lua_new_bspline_surface(L);
        st = cf_bspline_surface_split(b->bs, dir, x, lo, hi, &diag);
    }
    return cf__lua_done(L, "split", st, &diag, 2);
}

static cf_bspline_surface_t *
need_bspline(lua_State *L, cf__lua_surface_t *b, const char *fn)
{
    if (b->bs == NULL)
        cf__lua_error(L, "%s: a bezier surface has no knots; make it a "
                      "bspline_surface (s:to_bspline())", fn);
    return b->bs;
}

/* s:insert_knot("u", x, r) */
static int
m_insert_knot(lua_State *L)
{
    cf__lua_surface_t *b = check(L);
    cf_bspline_surface_t *s = need_bspline(L, b, "insert_knot");
    cf_dir_t dir = check_dir(L, 2, "insert_knot");
    double x = cf__lua_check_finite(L, 3, "insert_knot", "value");
    int r = cf__lua_opt_int(L, 4, "insert_knot", "r", 1,
                            CF_BSPLINE_MAX_DEGREE + 1, 1);
    cf_bspline_surface_t **out = cf__lua_new_bspline_surface(L);
    cf_diag_t diag;
    return cf__lua_done(L, "insert_knot",
                        cf_bspline_surface_insert_knot(s, dir, x, r, out,
                                                       &diag),
                        &diag, 1);
}

/* s:elevate(ru, rv) */
static int
m_elevate(lua_State *L)
{
    cf__lua_surface_t *b = check(L);
    int ru = cf__lua_opt_int(L, 2, "elevate", "ru", 0, 64, 1);
    int rv = cf__lua_opt_int(L, 3, "elevate", "rv", 0, 64, ru);
    cf_diag_t diag;
    cf_status_t st;
    if (b->bz != NULL) {
        cf_bezier_surface_t **out = cf__lua_new_bezier_surface(L);
        st = cf_bezier_surface_elevate(b->bz, ru, rv, out, &diag);
    } else {
        cf_bspline_surface_t **out = cf__lua_new_bspline_surface(L);
        st = cf_bspline_surface_elevate(b->bs, ru, rv, out, &diag);
    }
    return cf__lua_done(L, "elevate", st, &diag, 1);
}

/* A scheme as data: { columns = { net, ... }, v = net }, each net a list
** of levels, each level a list of points. */
static void
push_net(lua_State *L, const double *pts, size_t n, size_t dim)
{
    size_t at = 0;
    lua_createtable(L, (int)n, 0);
    for (size_t l = 0; l < n; l++) {
        cf__lua_push_points(L, pts + at * dim, n - l, dim);
        lua_rawseti(L, -2, (lua_Integer)l + 1);
        at += n - l;
    }
}

static int
push_scheme(lua_State *L, const double *out, size_t nu, size_t nv,
            size_t dim)
{
    size_t tu = nu * (nu + 1) / 2;
    lua_createtable(L, 0, 2);
    lua_createtable(L, (int)nv, 0);
    for (size_t j = 0; j < nv; j++) {
        push_net(L, out + j * tu * dim, nu, dim);
        lua_rawseti(L, -2, (lua_Integer)j + 1);
    }
    lua_setfield(L, -2, "columns");
    push_net(L, out + nv * tu * dim, nv, dim);
    lua_setfield(L, -2, "v");
    return 1;
}

static int
m_decasteljau(lua_State *L)
{
    cf__lua_surface_t *b = check(L);
    double u = cf__lua_check_finite(L, 2, "decasteljau", "u");
    double v = cf__lua_check_finite(L, 3, "decasteljau", "v");
    double *out;
    cf_status_t st;
    if (b->bz == NULL)
        return cf__lua_error(L, "decasteljau: a bspline surface evaluates "
                             "by de Boor (s:deboor(u, v)), or split it into "
                             "Bézier patches (s:to_bezier())");
    out = cf__lua_buffer(L, cf_bezier_surface_decasteljau_size(b->bz));
    st = cf_bezier_surface_decasteljau(b->bz, u, v, out);
    if (st != CF_STATUS_OK)
        return param_error(L, b, "decasteljau", u, v, st);
    return push_scheme(L, out, (size_t)cf_bezier_surface_degree_u(b->bz) + 1,
                       (size_t)cf_bezier_surface_degree_v(b->bz) + 1,
                       dim_of(b));
}

/* s:deboor(u, v) -> scheme, span_u, span_v (spans 0-based knot indices,
** as the curves' deboor) */
static int
m_deboor(lua_State *L)
{
    cf__lua_surface_t *b = check(L);
    cf_bspline_surface_t *s = need_bspline(L, b, "deboor");
    double u = cf__lua_check_finite(L, 2, "deboor", "u");
    double v = cf__lua_check_finite(L, 3, "deboor", "v");
    double *out = cf__lua_buffer(L, cf_bspline_surface_deboor_size(s));
    size_t span[2];
    cf_status_t st = cf_bspline_surface_deboor(s, u, v, out, span);
    if (st != CF_STATUS_OK)
        return param_error(L, b, "deboor", u, v, st);
    push_scheme(L, out, (size_t)cf_bspline_surface_degree_u(s) + 1,
                (size_t)cf_bspline_surface_degree_v(s) + 1, dim_of(b));
    lua_pushinteger(L, (lua_Integer)span[0]);
    lua_pushinteger(L, (lua_Integer)span[1]);
    return 3;
}

static void
free_list(void *p)
{
    cf_bezier_surface_list_destroy(p);
}

/* s:to_bezier() -> grid of Bézier patches T[i][j] */
static int
m_to_bezier(lua_State *L)
{
    cf__lua_surface_t *b = check(L);
    cf_bezier_surface_list_t *list = NULL;
    void **slot;
    cf_diag_t diag;
    cf_status_t st;
    if (b->bz != NULL) {
        cf_bezier_surface_t **one;
        lua_createtable(L, 1, 0);
        lua_createtable(L, 1, 0);
        one = cf__lua_new_bezier_surface(L);
        st = cf_bezier_surface_copy(b->bz, one, &diag);
        if (st != CF_STATUS_OK)
            return cf__lua_fail(L, "to_bezier", st, &diag);
        lua_rawseti(L, -2, 1);
        lua_rawseti(L, -2, 1);
        return 1;
    }
    slot = cf__lua_holder(L, free_list);
    st = cf_bspline_surface_to_beziers(b->bs, &list, &diag);
    *slot = list;
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "to_bezier", st, &diag);
    lua_createtable(L, (int)list->nu, 0);
    for (size_t i = 0; i < list->nu; i++) {
        lua_createtable(L, (int)list->nv, 0);
        for (size_t j = 0; j < list->nv; j++) {
            cf_bezier_surface_t **o = cf__lua_new_bezier_surface(L);
            *o = list->items[i * list->nv + j];
            list->items[i * list->nv + j] = NULL;
            lua_rawseti(L, -2, (lua_Integer)j + 1);
        }
        lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
    return 1;
}

/* s:to_bspline(): the same surface as a B-spline */
static int
m_to_bspline(lua_State *L)
{
    cf__lua_surface_t *b = check(L);
    cf_bspline_surface_t **out = cf__lua_new_bspline_surface(L);
    cf_diag_t diag;
    cf_status_t st = b->bz
                         ? cf_bspline_surface_from_bezier(b->bz, out, &diag)
                         : cf_bspline_surface_copy(b->bs, out, &diag);
    return cf__lua_done(L, "to_bspline", st, &diag, 1);
}

static void
counts(const cf__lua_surface_t *b, size_t *nu, size_t *nv)
{
    if (b->bz != NULL) {
        *nu = (size_t)cf_bezier_surface_degree_u(b->bz) + 1;
        *nv = (size_t)cf_bezier_surface_degree_v(b->bz) + 1;
    } else {
        *nu = cf_bspline_surface_count_u(b->bs);
        *nv = cf_bspline_surface_count_v(b->bs);
    }
}

/* s:points() -> P[i][j] */
static int
m_points(lua_State *L)
{
    cf__lua_surface_t *b = check(L);
    size_t nu, nv, dim = dim_of(b);
    double *P;
    counts(b, &nu, &nv);
    P = cf__lua_buffer(L, nu * nv * dim);
    if (b->bz != NULL)
        cf_bezier_surface_get_points(b->bz, P);
    else
        cf_bspline_surface_get_points(b->bs, P);
    lua_createtable(L, (int)nu, 0);
    for (size_t i = 0; i < nu; i++) {
        cf__lua_push_points(L, P + i * nv * dim, nv, dim);
        lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
    return 1;
}

/* s:weights() -> W[i][j] */
static int
m_weights(lua_State *L)
{
    cf__lua_surface_t *b = check(L);
    size_t nu, nv;
    double *W;
    counts(b, &nu, &nv);
    W = cf__lua_buffer(L, nu * nv);
    if (b->bz != NULL)
        cf_bezier_surface_get_weights(b->bz, W);
    else
        cf_bspline_surface_get_weights(b->bs, W);
    lua_createtable(L, (int)nu, 0);
    for (size_t i = 0; i < nu; i++) {
        cf__lua_push_numbers(L, W + i * nv, nv);
        lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
    return 1;
}

/* s:degree() -> p, q */
static int
m_degree(lua_State *L)
{
    cf__lua_surface_t *b = check(L);
    lua_pushinteger(L, b->bz ? cf_bezier_surface_degree_u(b->bz)
                             : cf_bspline_surface_degree_u(b->bs));
    lua_pushinteger(L, b->bz ? cf_bezier_surface_degree_v(b->bz)
                             : cf_bspline_surface_degree_v(b->bs));
    return 2;
}

/* s:knots() -> U, V */
static int
m_knots(lua_State *L)
{
    cf__lua_surface_t *b = check(L);
    cf_bspline_surface_t *s = need_bspline(L, b, "knots");
    size_t n;
    const double *K = cf_bspline_surface_knots(s, CF_DIR_U, &n);
    cf__lua_push_numbers(L, K, n);
    K = cf_bspline_surface_knots(s, CF_DIR_V, &n);
    cf__lua_push_numbers(L, K, n);
    return 2;
}

/* s:knot_lines("u") -> the distinct knots of the direction in its domain */
static int
m_knot_lines(lua_State *L)
{
    cf__lua_surface_t *b = check(L);
    cf_bspline_surface_t *s = need_bspline(L, b, "knot_lines");
    cf_dir_t dir = check_dir(L, 2, "knot_lines");
    size_t n;
    double *out;
    (void)cf_bspline_surface_knots(s, dir, &n);
    out = cf__lua_buffer(L, n);
    (void)cf_bspline_surface_knot_lines(s, dir, out, &n);
    cf__lua_push_numbers(L, out, n);
    return 1;
}

static int
m_dim(lua_State *L)
{
    lua_pushinteger(L, (lua_Integer)dim_of(check(L)));
    return 1;
}

static int
m_is_rational(lua_State *L)
{
    cf__lua_surface_t *b = check(L);
    lua_pushboolean(L, b->bz ? cf_bezier_surface_is_rational(b->bz)
                             : cf_bspline_surface_is_rational(b->bs));
    return 1;
}

static const luaL_Reg methods[] = {
    { "eval", m_eval },
    { "derivs", m_derivs },
    { "normal", m_normal },
    { "curvature", m_curvature },
    { "iso", m_iso },
    { "split", m_split },
    { "insert_knot", m_insert_knot },
    { "elevate", m_elevate },
    { "decasteljau", m_decasteljau },
    { "deboor", m_deboor },
    { "to_bezier", m_to_bezier },
    { "to_bspline", m_to_bspline },
    { "points", m_points },
    { "weights", m_weights },
    { "degree", m_degree },
    { "knots", m_knots },
    { "knot_lines", m_knot_lines },
    { "dim", m_dim },
    { "is_rational", m_is_rational },
    { NULL, NULL },
};


void
cf__lua_open_surface(lua_State *L)
{
    cf__lua_new_class(L, CF__LUA_SURFACE, methods, cf__lua_surface_gc,
                      cf__lua_surface_tostring);
    lua_pushcfunction(L, cf__lua_bezier_surface);
    lua_setglobal(L, "bezier_surface");
    lua_pushcfunction(L, cf__lua_bspline_surface);
    lua_setglobal(L, "bspline_surface");
}
