/*
** Lua binding of Bézier curves (include/curvefig/bezier.h).
**
**   bezier{ {x, y}, ... }                   polynomial, points in R^N
**   bezier{ points = {...}, weights = {...} }   rational
**
** Every method returns new values; none modifies its receiver.
*/
#include <stdlib.h>
#include <string.h>

#include "curvefig/bezier.h"
#include "lbezier.h"
#include "lcommon.h"
#include "lschema.h"

typedef struct box {
    cf_bezier_t *c;
} box;

cf_bezier_t **
cf__lua_new_bezier(lua_State *L)
{
    box *b = lua_newuserdatauv(L, sizeof *b, 0);
    b->c = NULL;
    luaL_setmetatable(L, CF__LUA_BEZIER);
    return &b->c;
}

cf_bezier_t *
cf__lua_check_bezier(lua_State *L, int idx)
{
    box *b = idx == 1 ? cf__lua_check_self(L, CF__LUA_BEZIER, "curve")
                      : luaL_checkudata(L, idx, CF__LUA_BEZIER);
    if (b->c == NULL)
        luaL_error(L, "bezier: the curve was closed");
    return b->c;
}

cf_bezier_t *
cf__lua_to_bezier(lua_State *L, int idx)
{
    box *b = luaL_testudata(L, idx, CF__LUA_BEZIER);
    return b != NULL ? b->c : NULL;
}

void
cf__lua_push_bezier_list(lua_State *L, cf_bezier_list_t *list)
{
    /* The caller holds list in a holder at the top of the stack; items are
    ** moved into boxes one by one so that nothing leaks on an error. */
    lua_createtable(L, (int)list->count, 0);
    for (size_t i = 0; i < list->count; i++) {
        cf_bezier_t **slot = cf__lua_new_bezier(L);
        *slot = list->items[i];
        list->items[i] = NULL;
        lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
}

void
cf__lua_push_cubics(lua_State *L, const cf_cubics_t *cu)
{
    lua_createtable(L, (int)cu->count, 0);
    for (size_t i = 0; i < cu->count; i++) {
        cf_bezier_t **out = cf__lua_new_bezier(L);
        cf_diag_t diag;
        cf_status_t st;
        cf_diag_clear(&diag);
        st = cf_bezier_create(cu->dim, 3, cu->pts + 4 * cu->dim * i, NULL,
                              out, &diag);
        if (st != CF_STATUS_OK)
            cf__lua_fail(L, "cubics", st, &diag);
        lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
}

static int
gc(lua_State *L)
{
    box *b = luaL_checkudata(L, 1, CF__LUA_BEZIER);
    cf_bezier_destroy(b->c);
    b->c = NULL;
    return 0;
}

static int
tostring(lua_State *L)
{
    box *b = luaL_checkudata(L, 1, CF__LUA_BEZIER);
    if (b->c == NULL) {
        lua_pushliteral(L, "bezier (closed)");
        return 1;
    }
    lua_pushfstring(L, "%sbezier of degree %d in R^%d",
                    cf_bezier_is_rational(b->c) ? "rational " : "",
                    cf_bezier_degree(b->c), (int)cf_bezier_dim(b->c));
    return 1;
}

/* bezier{ P0, P1, ... } or bezier{ points = {...} }, either with
** weights = {...} (rational) */
static int
l_bezier(lua_State *L)
{
    size_t n, dim, nw = 0;
    double *pts, *w = NULL;
    cf_bezier_t **out;
    cf_diag_t diag;
    cf_status_t st;
    int pidx = 1;
    luaL_checktype(L, 1, LUA_TTABLE);
    cf__lua_check_table(L, 1, CF__KEYS_BEZIER);
    if (cf__lua_field(L, 1, "points") != LUA_TNIL) {
        if (lua_rawlen(L, 1) > 0)
            return luaL_error(L, "bezier: give the points either as the "
                              "list, bezier{ {x, y}, ... }, or as points = "
                              "{...}, not both");
        pidx = lua_gettop(L);
    }
    if (cf__lua_field(L, 1, "weights") != LUA_TNIL)
        w = cf__lua_check_numbers(L, -1, "bezier", "weight", &nw);
    pts = pidx == 1
              ? cf__lua_check_point_list(L, 1, "bezier", "point", 1, &n, &dim)
              : cf__lua_check_points(L, pidx, "bezier", "point", 1, &n, &dim);
    if (w != NULL && nw != n)
        return cf__lua_error(L, "bezier: %zu weights given for %zu points",
                             nw, n);
    if (n - 1 > CF_BEZIER_MAX_DEGREE)
        return cf__lua_error(L, "bezier: %zu points; at most %d (degree %d)",
                             n, CF_BEZIER_MAX_DEGREE + 1,
                             CF_BEZIER_MAX_DEGREE);
    out = cf__lua_new_bezier(L);
    cf_diag_clear(&diag);
    st = cf_bezier_create(dim, (int)n - 1, pts, w, out, &diag);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "bezier", st, &diag);
    return 1;
}

/* Parameters t: a number or an array of numbers. */
static int
m_eval(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    size_t dim = cf_bezier_dim(c), n;
    cf_status_t st;
    if (lua_istable(L, 2)) {
        double *t = cf__lua_check_numbers(L, 2, "eval", "parameter", &n);
        double *out = cf__lua_buffer(L, n * dim);
        st = cf_bezier_eval_many(c, t, n, out);
        if (st != CF_STATUS_OK)
            return cf__lua_fail(L, "eval", st, NULL);
        cf__lua_push_points(L, out, n, dim);
    } else {
        double t = cf__lua_check_finite(L, 2, "eval", "t");
        double *out = cf__lua_buffer(L, dim);
        st = cf_bezier_eval(c, t, out);
        if (st != CF_STATUS_OK)
            return cf__lua_error(L, "eval: t = %g is outside [0, 1]", t);
        cf__lua_push_point(L, out, dim);
    }
    return 1;
}

/* c:derivs(t, k) -> { c(t), c'(t), ..., c^(k)(t) } */
static int
m_derivs(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    double t = cf__lua_check_finite(L, 2, "derivs", "t");
    int k = cf__lua_opt_int(L, 3, "derivs", "k", 0, CF__LUA_MAX_DERIV, 1);
    size_t dim = cf_bezier_dim(c);
    double *out = cf__lua_buffer(L, (size_t)(k + 1) * dim);
    cf_status_t st = cf_bezier_eval_derivs(c, t, k, out);
    if (st != CF_STATUS_OK)
        return cf__lua_error(L, "derivs: t = %g is outside [0, 1]", t);
    cf__lua_push_points(L, out, (size_t)k + 1, dim);
    return 1;
}

typedef cf_status_t (*vec_fn)(const cf_bezier_t *, double, double *);

static int
vector_at(lua_State *L, const char *name, vec_fn fn)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    double t = cf__lua_check_finite(L, 2, name, "t");
    size_t dim = cf_bezier_dim(c);
    double *out = cf__lua_buffer(L, dim);
    cf_status_t st = fn(c, t, out);
    if (st == CF_STATUS_DOMAIN)
        return cf__lua_error(L, "%s: t = %g is outside [0, 1]", name, t);
    if (st != CF_STATUS_OK)
        return cf__lua_error(L, "%s: %s at t = %g", name,
                             cf_status_to_string(st), t);
    cf__lua_push_point(L, out, dim);
    return 1;
}

static int
m_tangent(lua_State *L)
{
    return vector_at(L, "tangent", cf_bezier_tangent);
}

static int
m_normal(lua_State *L)
{
    return vector_at(L, "normal", cf_bezier_normal);
}

static int
m_curvature(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    double t = cf__lua_check_finite(L, 2, "curvature", "t"), k;
    cf_status_t st = cf_bezier_curvature(c, t, &k);
    if (st != CF_STATUS_OK)
        return cf__lua_error(L, "curvature: %s at t = %g",
                             cf_status_to_string(st), t);
    lua_pushnumber(L, k);
    return 1;
}

static int
m_derivative(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    int k = cf__lua_opt_int(L, 2, "derivative", "k", 0, CF__LUA_MAX_DERIV, 1);
    cf_bezier_t **out = cf__lua_new_bezier(L);
    cf_diag_t diag;
    cf_status_t st;
    cf_diag_clear(&diag);
    st = cf_bezier_derivative(c, k, out, &diag);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "derivative", st, &diag);
    return 1;
}

static int
m_split(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    double t = cf__lua_check_finite(L, 2, "split", "t");
    cf_bezier_t **left, **right;
    cf_diag_t diag;
    cf_status_t st;
    if (!(t > 0.0 && t < 1.0))
        return cf__lua_error(L, "split: t = %g; it must lie in (0, 1)", t);
    left = cf__lua_new_bezier(L);
    right = cf__lua_new_bezier(L);
    cf_diag_clear(&diag);
    st = cf_bezier_split(c, t, left, right, &diag);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "split", st, &diag);
    return 2;
}

static int
m_segment(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    double a = cf__lua_check_finite(L, 2, "segment", "a");
    double b = cf__lua_check_finite(L, 3, "segment", "b");
    cf_bezier_t **out = cf__lua_new_bezier(L);
    cf_diag_t diag;
    cf_status_t st;
    cf_diag_clear(&diag);
    st = cf_bezier_segment(c, a, b, out, &diag);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "segment", st, &diag);
    return 1;
}

static int
m_reverse(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    cf_bezier_t **out = cf__lua_new_bezier(L);
    cf_diag_t diag;
    cf_status_t st;
    cf_diag_clear(&diag);
    st = cf_bezier_reverse(c, out, &diag);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "reverse", st, &diag);
    return 1;
}

/* c:transform(A, b): x -> A x + b, A = { {a11, a12}, {a21, a22} } */
static int
m_transform(lua_State *L)
{
    lua_settop(L, 3);
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    size_t dim = cf_bezier_dim(c), rows, cols, bd = dim;
    double *A = cf__lua_check_points(L, 2, "transform", "matrix row", 1,
                                     &rows, &cols);
    double *b = lua_isnoneornil(L, 3)
                    ? NULL
                    : cf__lua_check_point(L, 3, "transform", "vector b", &bd);
    cf_bezier_t **out;
    cf_diag_t diag;
    cf_status_t st;
    if (rows != dim || cols != dim)
        return cf__lua_error(L, "transform: the matrix is %zu x %zu; the "
                             "curve lives in R^%zu", rows, cols, dim);
    out = cf__lua_new_bezier(L);
    cf_diag_clear(&diag);
    st = cf_bezier_transform(c, A, b, out, &diag);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "transform", st, &diag);
    return 1;
}

static int
m_elevate(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    int r = cf__lua_opt_int(L, 2, "elevate", "r", 0, CF_BEZIER_MAX_DEGREE, 1);
    cf_bezier_t **out = cf__lua_new_bezier(L);
    cf_diag_t diag;
    cf_status_t st;
    cf_diag_clear(&diag);
    st = cf_bezier_elevate(c, r, out, &diag);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "elevate", st, &diag);
    return 1;
}

/* c:decasteljau(t) -> { {level 0 points}, {level 1}, ..., {c(t)} } */
static int
m_decasteljau(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    double t = cf__lua_check_finite(L, 2, "decasteljau", "t");
    size_t dim = cf_bezier_dim(c), n = (size_t)cf_bezier_degree(c) + 1;
    double *out = cf__lua_buffer(L, cf_bezier_decasteljau_size(c));
    if (cf_bezier_decasteljau(c, t, out) != CF_STATUS_OK)
        return cf__lua_error(L, "decasteljau: t = %g is outside [0, 1]", t);
    lua_createtable(L, (int)n, 0);
    for (size_t j = 0; j < n; j++) {
        cf__lua_push_points(L, out, n - j, dim);
        lua_rawseti(L, -2, (lua_Integer)j + 1);
        out += (n - j) * dim;
    }
    return 1;
}

static int
m_degree(lua_State *L)
{
    lua_pushinteger(L, cf_bezier_degree(cf__lua_check_bezier(L, 1)));
    return 1;
}

static int
m_dim(lua_State *L)
{
    lua_pushinteger(L, (lua_Integer)cf_bezier_dim(cf__lua_check_bezier(L, 1)));
    return 1;
}

static int
m_is_rational(lua_State *L)
{
    lua_pushboolean(L, cf_bezier_is_rational(cf__lua_check_bezier(L, 1)));
    return 1;
}

static int
m_points(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    size_t dim = cf_bezier_dim(c), n = (size_t)cf_bezier_degree(c) + 1;
    double *out = cf__lua_buffer(L, n * dim);
    cf_bezier_get_points(c, out);
    cf__lua_push_points(L, out, n, dim);
    return 1;
}

static int
m_weights(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    size_t n = (size_t)cf_bezier_degree(c) + 1;
    double *out = cf__lua_buffer(L, n);
    cf_bezier_get_weights(c, out);
    cf__lua_push_numbers(L, out, n);
    return 1;
}

/* c:bbox() -> lo, hi (of the curve, not of its control points) */
static int
m_bbox(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    size_t dim = cf_bezier_dim(c);
    double *lo = cf__lua_buffer(L, dim), *hi = cf__lua_buffer(L, dim);
    cf_status_t st = cf_bezier_bbox(c, lo, hi);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "bbox", st, NULL);
    cf__lua_push_point(L, lo, dim);
    cf__lua_push_point(L, hi, dim);
    return 2;
}

static int
m_length(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    double tol = luaL_optnumber(L, 2, 1e-9), len;
    cf_status_t st;
    if (!(tol > 0.0))
        return cf__lua_error(L, "length: tolerance is %g; it must be > 0",
                             tol);
    st = cf_bezier_length(c, tol, &len);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "length", st, NULL);
    lua_pushnumber(L, len);
    return 1;
}

/* c:closest(p) -> t, distance */
static int
m_closest(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    size_t dim = cf_bezier_dim(c);
    double *p = cf__lua_check_point(L, 2, "closest", "point", &dim);
    double t, d;
    cf_status_t st = cf_bezier_closest(c, p, &t, &d);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "closest", st, NULL);
    lua_pushnumber(L, t);
    lua_pushnumber(L, d);
    return 2;
}

/* The polyline is collected in a plain array (the callback must not call
** Lua: an error there would jump over the library's frames). */
typedef struct flat_ctx {
    size_t dim, n, cap;
    double *v;
    int failed;
} flat_ctx;

/* Points of one flattening: beyond this the tolerance is certainly too
** small for the curve (a million points, 16 MiB in the plane). */
#define MAX_FLAT_POINTS ((size_t)1 << 20)

static void
free_flat(void *p)
{
    flat_ctx *f = p;
    cf_free(f->v);
    free(f);
}

static int
flat_point(void *closure, const double *p, double t)
{
    flat_ctx *f = closure;
    void *v = f->v;
    (void)t;
    if (!cf__lua_grow(&v, &f->cap, f->n + 1, f->dim * sizeof *p,
                      MAX_FLAT_POINTS)) {
        f->failed = f->n + 1 > MAX_FLAT_POINTS ? 1 : 2;
        return 1;
    }
    f->v = v;
    memcpy(f->v + f->n * f->dim, p, f->dim * sizeof *p);
    f->n++;
    return 0;
}

/* c:flatten(tol) -> polyline within tol of the curve */
static int
m_flatten(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    double tol = luaL_optnumber(L, 2, 1e-3);
    flat_ctx *f;
    void **slot;
    cf_status_t st;
    if (!(tol > 0.0))
        return cf__lua_error(L, "flatten: tolerance is %g; it must be > 0",
                             tol);
    slot = cf__lua_holder(L, free_flat);
    f = calloc(1, sizeof *f);
    if (f == NULL)
        return luaL_error(L, "flatten: out of memory");
    *slot = f;
    f->dim = cf_bezier_dim(c);
    st = cf_bezier_flatten(c, tol, flat_point, f);
    if (f->failed == 1)
        return cf__lua_error(L, "flatten: more than %zu points at tolerance "
                             "%g (the tolerance is too small for the "
                             "curve)", MAX_FLAT_POINTS, tol);
    if (f->failed)
        return cf__lua_fail(L, "flatten", CF_STATUS_NO_MEMORY, NULL);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "flatten", st, NULL);
    cf__lua_push_points(L, f->v, f->n, f->dim);
    cf__lua_holder_release(L, -2);
    return 1;
}

static void
free_cubics(void *p)
{
    cf_cubics_destroy(p);
}

/* c:to_cubics(tol) -> list of cubic Béziers, achieved error */
static int
m_to_cubics(lua_State *L)
{
    cf_bezier_t *c = cf__lua_check_bezier(L, 1);
    double tol = luaL_optnumber(L, 2, 1e-3);
    void **slot;
    cf_cubics_t *cu = NULL;
    cf_diag_t diag;
    cf_status_t st;
    if (!(tol > 0.0))
        return cf__lua_error(L, "to_cubics: tolerance is %g; it must be > 0",
                             tol);
    slot = cf__lua_holder(L, free_cubics);
    cf_diag_clear(&diag);
    st = cf_bezier_to_cubics(c, tol, &cu, &diag);
    *slot = cu;
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "to_cubics", st, &diag);
    cf__lua_push_cubics(L, cu);
    lua_pushnumber(L, cu->max_error);
    return 2;
}

static const luaL_Reg methods[] = {
    { "eval", m_eval },
    { "derivs", m_derivs },
    { "tangent", m_tangent },
    { "normal", m_normal },
    { "curvature", m_curvature },
    { "derivative", m_derivative },
    { "split", m_split },
    { "segment", m_segment },
    { "reverse", m_reverse },
    { "transform", m_transform },
    { "elevate", m_elevate },
    { "decasteljau", m_decasteljau },
    { "degree", m_degree },
    { "dim", m_dim },
    { "is_rational", m_is_rational },
    { "points", m_points },
    { "weights", m_weights },
    { "bbox", m_bbox },
    { "length", m_length },
    { "closest", m_closest },
    { "flatten", m_flatten },
    { "to_cubics", m_to_cubics },
    { NULL, NULL },
};

void
cf__lua_open_bezier(lua_State *L)
{
    cf__lua_new_class(L, CF__LUA_BEZIER, methods, gc, tostring);
    lua_pushcfunction(L, l_bezier);
    lua_setglobal(L, "bezier");
}

/* Methods other modules add to Bézier curves (offset, ...) go into the
** __index table through this. */
void
cf__lua_add_bezier_methods(lua_State *L, const luaL_Reg *more)
{
    luaL_getmetatable(L, CF__LUA_BEZIER);
    lua_getfield(L, -1, "__index");
    luaL_setfuncs(L, more, 0);
    lua_pop(L, 2);
}
