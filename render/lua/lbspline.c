/*
** Lua binding of B-spline and NURBS curves (include/curvefig/bspline.h);
** knot vectors and basis functions are in lknots.c.
**
**   bspline{ degree = 2, knots = {...}, points = {...}, weights = {...} }
**   bspline{ degree = 2, points = {...}, kind = "clamped" | "closed" |
**            "uniform" }                 (knots generated on [0, 1])
**   coons{ points = {...}, ends = "plain" | "tripled" | "closed" }
**   nurbs_circle(center, r), nurbs_arc{ center, x, y, r, from, to }
**
** Indices of control points and knots are the mathematical ones (P_0,
** u_0); Lua arrays returned by points() and knots() start at [1] = P_0.
*/
#include <string.h>

#include "curvefig/bspline.h"
#include "lbezier.h"
#include "lbspline.h"
#include "lcommon.h"
#include "lschema.h"

/* nresults, or the error of a failed status */
#define done cf__lua_done

typedef struct box {
    cf_bspline_t *c;
} box;

cf_bspline_t **
cf__lua_new_bspline(lua_State *L)
{
    box *b = lua_newuserdatauv(L, sizeof *b, 0);
    b->c = NULL;
    luaL_setmetatable(L, CF__LUA_BSPLINE);
    return &b->c;
}

cf_bspline_t *
cf__lua_check_bspline(lua_State *L, int idx)
{
    box *b = idx == 1 ? cf__lua_check_self(L, CF__LUA_BSPLINE, "curve")
                      : luaL_checkudata(L, idx, CF__LUA_BSPLINE);
    if (b->c == NULL)
        luaL_error(L, "bspline: the curve was closed");
    return b->c;
}

cf_bspline_t *
cf__lua_to_bspline(lua_State *L, int idx)
{
    box *b = luaL_testudata(L, idx, CF__LUA_BSPLINE);
    return b != NULL ? b->c : NULL;
}

static int
gc(lua_State *L)
{
    box *b = luaL_checkudata(L, 1, CF__LUA_BSPLINE);
    cf_bspline_destroy(b->c);
    b->c = NULL;
    return 0;
}

static int
tostring(lua_State *L)
{
    box *b = luaL_checkudata(L, 1, CF__LUA_BSPLINE);
    if (b->c == NULL) {
        lua_pushliteral(L, "bspline (closed)");
        return 1;
    }
    lua_pushfstring(L, "%s of degree %d with %d points in R^%d",
                    cf_bspline_is_rational(b->c) ? "nurbs" : "bspline",
                    cf_bspline_degree(b->c), (int)cf_bspline_count(b->c),
                    (int)cf_bspline_dim(b->c));
    return 1;
}

/* ---- constructors ------------------------------------------------------- */

/* The curve of kind (clamped, closed, uniform) with its own knots. */
static cf_status_t
create_kind(lua_State *L, const char *kind, size_t dim, int p,
            const double *pts, size_t n, const double *w, cf_bspline_t **out,
            cf_diag_t *diag)
{
    cf_status_t st;
    double *u;
    if (strcmp(kind, "clamped") == 0)
        return cf_bspline_create_clamped(dim, p, pts, n, w, out, diag);
    if (strcmp(kind, "closed") == 0)
        return cf_bspline_create_closed(dim, p, pts, n, w, out, diag);
    if (strcmp(kind, "uniform") != 0)
        return luaL_error(L, "bspline: kind \"%s\": use \"clamped\", "
                          "\"closed\" or \"uniform\" (or give knots)", kind);
    u = cf__lua_buffer(L, cf_knots_count(p, n));
    st = cf_knots_uniform(p, n, 0.0, 1.0, u, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_create(dim, p, u, cf_knots_count(p, n), pts, n, w,
                               out, diag);
    lua_pop(L, 1);
    return st;
}

/* bspline{ degree = p, points = {...}, weights = {...}, knots = {...} or
** kind = "clamped" | "closed" | "uniform" } */
static int
l_bspline(lua_State *L)
{
    size_t n, dim, nk = 0, nw = 0;
    double *pts, *knots = NULL, *w = NULL;
    const char *kind;
    int p;
    cf_bspline_t **out;
    cf_diag_t diag;
    luaL_checktype(L, 1, LUA_TTABLE);
    cf__lua_check_table(L, 1, CF__KEYS_BSPLINE);
    cf__lua_field(L, 1, "degree");
    p = cf__lua_check_int(L, -1, "bspline", "degree", 0,
                          CF_BSPLINE_MAX_DEGREE);
    cf__lua_field(L, 1, "points");
    pts = cf__lua_check_points(L, -1, "bspline", "point", 1, &n, &dim);
    if (cf__lua_field(L, 1, "weights") != LUA_TNIL)
        w = cf__lua_check_numbers(L, -1, "bspline", "weight", &nw);
    if (w != NULL && nw != n)
        return cf__lua_error(L, "bspline: %zu weights given for %zu points",
                             nw, n);
    if (cf__lua_field(L, 1, "knots") != LUA_TNIL)
        knots = cf__lua_check_numbers(L, -1, "bspline", "knot", &nk);
    if (cf__lua_field(L, 1, "kind") != LUA_TNIL && knots != NULL)
        return luaL_error(L, "bspline: give either knots or kind");
    kind = cf__lua_opt_text(L, -1, "bspline", "kind", "clamped");
    out = cf__lua_new_bspline(L);
    cf_diag_clear(&diag);
    if (knots != NULL)
        return done(L, "bspline", cf_bspline_create(dim, p, knots, nk, pts, n,
                                                    w, out, &diag), &diag, 1);
    return done(L, "bspline", create_kind(L, kind, dim, p, pts, n, w, out,
                                          &diag), &diag, 1);
}

/* coons{ points = {...}, ends = "plain" | "tripled" | "closed" } */
static int
l_coons(lua_State *L)
{
    static const char *const ends[] = { "plain", "tripled", "closed", NULL };
    size_t n, dim;
    double *pts;
    int e;
    cf_bspline_t **out;
    cf_diag_t diag;
    luaL_checktype(L, 1, LUA_TTABLE);
    cf__lua_check_table(L, 1, CF__KEYS_COONS);
    cf__lua_field(L, 1, "points");
    pts = cf__lua_check_points(L, -1, "coons", "point", 1, &n, &dim);
    cf__lua_field(L, 1, "ends");
    cf__lua_opt_text(L, -1, "coons", "ends", "plain");
    e = luaL_checkoption(L, -1, "plain", ends);
    out = cf__lua_new_bspline(L);
    cf_diag_clear(&diag);
    return done(L, "coons", cf_bspline_create_coons(dim, pts, n,
                                                    (cf_coons_ends_t)e, out,
                                                    &diag), &diag, 1);
}

/* nurbs_circle({cx, cy}, r) */
static int
l_nurbs_circle(lua_State *L)
{
    size_t dim = 2;
    double *c = cf__lua_check_point(L, 1, "nurbs_circle", "center", &dim);
    double r = cf__lua_check_finite(L, 2, "nurbs_circle", "radius");
    cf_bspline_t **out = cf__lua_new_bspline(L);
    cf_diag_t diag;
    cf_diag_clear(&diag);
    return done(L, "nurbs_circle", cf_nurbs_circle(c, r, out, &diag), &diag,
                1);
}

/* nurbs_arc{ center = {...}, x = {...}, y = {...}, r = 1, from = 0,
** to = math.pi / 2 } (x, y default to the coordinate axes of the plane) */
static int
l_nurbs_arc(lua_State *L)
{
    size_t dim = 0, d2;
    double *o, *x, *y, r, a0, a1;
    cf_bspline_t **out;
    cf_diag_t diag;
    luaL_checktype(L, 1, LUA_TTABLE);
    cf__lua_check_table(L, 1, CF__KEYS_NURBS_ARC);
    cf__lua_field(L, 1, "center");
    o = cf__lua_check_point(L, -1, "nurbs_arc", "center", &dim);
    if (dim < 2)
        return luaL_error(L, "nurbs_arc: the center needs 2 or more "
                          "coordinates");
    x = cf__lua_buffer(L, dim);
    y = cf__lua_buffer(L, dim);
    memset(x, 0, dim * sizeof *x);
    memset(y, 0, dim * sizeof *y);
    x[0] = y[1] = 1.0;
    d2 = dim;
    if (cf__lua_field(L, 1, "x") != LUA_TNIL)
        x = cf__lua_check_point(L, -1, "nurbs_arc", "x", &d2);
    if (cf__lua_field(L, 1, "y") != LUA_TNIL)
        y = cf__lua_check_point(L, -1, "nurbs_arc", "y", &d2);
    cf__lua_field(L, 1, "r");
    r = cf__lua_check_finite(L, -1, "nurbs_arc", "r");
    cf__lua_field(L, 1, "from");
    a0 = lua_isnil(L, -1) ? 0.0
                          : cf__lua_check_finite(L, -1, "nurbs_arc", "from");
    cf__lua_field(L, 1, "to");
    a1 = cf__lua_check_finite(L, -1, "nurbs_arc", "to");
    out = cf__lua_new_bspline(L);
    cf_diag_clear(&diag);
    return done(L, "nurbs_arc", cf_nurbs_arc(dim, o, x, y, r, a0, a1, out,
                                             &diag), &diag, 1);
}

/* ---- evaluation --------------------------------------------------------- */

static int
m_eval(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    size_t dim = cf_bspline_dim(c), n;
    if (lua_istable(L, 2)) {
        double *u = cf__lua_check_numbers(L, 2, "eval", "parameter", &n);
        double *out = cf__lua_buffer(L, n * dim);
        cf_status_t st = cf_bspline_eval_many(c, u, n, out);
        if (st != CF_STATUS_OK)
            return cf__lua_error(L, "eval: a parameter is outside the "
                                 "domain");
        cf__lua_push_points(L, out, n, dim);
    } else {
        double u = cf__lua_check_finite(L, 2, "eval", "u"), a, b;
        double *out = cf__lua_buffer(L, dim);
        if (cf_bspline_eval(c, u, out) != CF_STATUS_OK) {
            cf_bspline_domain(c, &a, &b);
            return cf__lua_error(L, "eval: u = %g is outside the domain "
                                 "[%g, %g]", u, a, b);
        }
        cf__lua_push_point(L, out, dim);
    }
    return 1;
}

static int
m_derivs(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    double u = cf__lua_check_finite(L, 2, "derivs", "u");
    int k = cf__lua_opt_int(L, 3, "derivs", "k", 0, CF__LUA_MAX_DERIV, 1);
    size_t dim = cf_bspline_dim(c);
    double *out = cf__lua_buffer(L, (size_t)(k + 1) * dim);
    if (cf_bspline_eval_derivs(c, u, k, out) != CF_STATUS_OK)
        return cf__lua_error(L, "derivs: u = %g is outside the domain", u);
    cf__lua_push_points(L, out, (size_t)k + 1, dim);
    return 1;
}

/* s:basis(u) -> first, { N_first^p(u), ..., N_{first+p}^p(u) } */
static int
m_basis(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    double u = cf__lua_check_finite(L, 2, "basis", "u");
    size_t first;
    double *N = cf__lua_buffer(L, (size_t)cf_bspline_degree(c) + 1);
    if (cf_bspline_basis(c, u, &first, N) != CF_STATUS_OK)
        return cf__lua_error(L, "basis: u = %g is outside the domain", u);
    lua_pushinteger(L, (lua_Integer)first);
    cf__lua_push_numbers(L, N, (size_t)cf_bspline_degree(c) + 1);
    return 2;
}

/* s:deboor(u) -> levels, span k, multiplicity s */
static int
m_deboor(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    double u = cf__lua_check_finite(L, 2, "deboor", "u");
    size_t p = (size_t)cf_bspline_degree(c), dim = cf_bspline_dim(c), span;
    double *out = cf__lua_buffer(L, cf_bspline_deboor_size(c));
    int mult;
    if (cf_bspline_deboor(c, u, out, &span, &mult) != CF_STATUS_OK)
        return cf__lua_error(L, "deboor: u = %g is outside the domain", u);
    lua_createtable(L, (int)p + 1, 0);
    for (size_t j = 0; j <= p; j++) {
        cf__lua_push_points(L, out, p + 1 - j, dim);
        lua_rawseti(L, -2, (lua_Integer)j + 1);
        out += (p + 1 - j) * dim;
    }
    lua_pushinteger(L, (lua_Integer)span);
    lua_pushinteger(L, mult);
    return 3;
}

/* ---- constructions ------------------------------------------------------ */

static int
m_derivative(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    int k = cf__lua_opt_int(L, 2, "derivative", "k", 0, CF__LUA_MAX_DERIV, 1);
    cf_bspline_t **out = cf__lua_new_bspline(L);
    cf_diag_t diag;
    cf_diag_clear(&diag);
    return done(L, "derivative", cf_bspline_derivative(c, k, out, &diag),
                &diag, 1);
}

static void
set_int(lua_State *L, const char *key, lua_Integer v)
{
    lua_pushinteger(L, v);
    lua_setfield(L, -2, key);
}

/* s:insert_knot(u, r) -> curve, { span, multiplicity, times, cut_first,
** cut_count, new_first, new_count } */
static int
m_insert_knot(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    double u = cf__lua_check_finite(L, 2, "insert_knot", "u");
    int r = cf__lua_opt_int(L, 3, "insert_knot", "r", 1,
                            CF_BSPLINE_MAX_DEGREE + 1, 1);
    cf_bspline_insert_info_t info;
    cf_bspline_t **out = cf__lua_new_bspline(L);
    cf_diag_t diag;
    cf_status_t st;
    cf_diag_clear(&diag);
    st = cf_bspline_insert_knot(c, u, r, out, &info, &diag);
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "insert_knot", st, &diag);
    lua_createtable(L, 0, 7);
    set_int(L, "span", (lua_Integer)info.span);
    set_int(L, "multiplicity", info.multiplicity);
    set_int(L, "times", info.times);
    set_int(L, "cut_first", (lua_Integer)info.cut_first);
    set_int(L, "cut_count", (lua_Integer)info.cut_count);
    set_int(L, "new_first", (lua_Integer)info.new_first);
    set_int(L, "new_count", (lua_Integer)info.new_count);
    return 2;
}

static int
m_refine(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    size_t n;
    double *x = cf__lua_check_numbers(L, 2, "refine", "knot", &n);
    cf_bspline_t **out = cf__lua_new_bspline(L);
    cf_diag_t diag;
    cf_diag_clear(&diag);
    return done(L, "refine", cf_bspline_refine(c, x, n, out, &diag), &diag,
                1);
}

/* s:remove_knot(u, r, tol) -> curve, times removed */
static int
m_remove_knot(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    double u = cf__lua_check_finite(L, 2, "remove_knot", "u");
    int r = cf__lua_opt_int(L, 3, "remove_knot", "r", 1,
                            CF_BSPLINE_MAX_DEGREE + 1, 1), removed = 0;
    double tol = luaL_optnumber(L, 4, 1e-9);
    cf_bspline_t **out = cf__lua_new_bspline(L);
    cf_diag_t diag;
    cf_diag_clear(&diag);
    if (done(L, "remove_knot", cf_bspline_remove_knot(c, u, r, tol, out,
                                                      &removed, &diag),
             &diag, 1) != 1)
        return 0;
    lua_pushinteger(L, removed);
    return 2;
}

static int
m_split(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    double u = cf__lua_check_finite(L, 2, "split", "u");
    cf_bspline_t **left = cf__lua_new_bspline(L);
    cf_bspline_t **right = cf__lua_new_bspline(L);
    cf_diag_t diag;
    cf_diag_clear(&diag);
    return done(L, "split", cf_bspline_split(c, u, left, right, &diag),
                &diag, 2);
}

static int
m_segment(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    double a = cf__lua_check_finite(L, 2, "segment", "a");
    double b = cf__lua_check_finite(L, 3, "segment", "b");
    cf_bspline_t **out = cf__lua_new_bspline(L);
    cf_diag_t diag;
    cf_diag_clear(&diag);
    return done(L, "segment", cf_bspline_segment(c, a, b, out, &diag), &diag,
                1);
}

static void
free_list(void *p)
{
    cf_bezier_list_destroy(p);
}

/* s:to_beziers() -> { Bézier pieces }, one per non-empty span of the
** domain in order (one value, so that f:curve(s:to_beziers()) works) */
static int
m_to_beziers(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    void **slot = cf__lua_holder(L, free_list);
    cf_bezier_list_t *list = NULL;
    cf_diag_t diag;
    cf_status_t st;
    cf_diag_clear(&diag);
    st = cf_bspline_to_beziers(c, &list, &diag);
    *slot = list;
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, "to_beziers", st, &diag);
    cf__lua_push_bezier_list(L, list);
    return 1;
}

static int
m_elevate(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    int t = cf__lua_opt_int(L, 2, "elevate", "t", 0, CF_BSPLINE_MAX_DEGREE,
                            1);
    cf_bspline_t **out = cf__lua_new_bspline(L);
    cf_diag_t diag;
    cf_diag_clear(&diag);
    return done(L, "elevate", cf_bspline_elevate(c, t, out, &diag), &diag,
                1);
}

static int
m_reverse(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    cf_bspline_t **out = cf__lua_new_bspline(L);
    cf_diag_t diag;
    cf_diag_clear(&diag);
    return done(L, "reverse", cf_bspline_reverse(c, out, &diag), &diag, 1);
}

static int
m_transform(lua_State *L)
{
    lua_settop(L, 3);
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    size_t dim = cf_bspline_dim(c), rows, cols, bd = dim;
    double *A = cf__lua_check_points(L, 2, "transform", "matrix row", 1,
                                     &rows, &cols);
    double *b = lua_isnoneornil(L, 3)
                    ? NULL
                    : cf__lua_check_point(L, 3, "transform", "vector b", &bd);
    cf_bspline_t **out;
    cf_diag_t diag;
    if (rows != dim || cols != dim)
        return cf__lua_error(L, "transform: the matrix is %zu x %zu; the "
                             "curve lives in R^%zu", rows, cols, dim);
    out = cf__lua_new_bspline(L);
    cf_diag_clear(&diag);
    return done(L, "transform", cf_bspline_transform(c, A, b, out, &diag),
                &diag, 1);
}

/* s:move_point(i, v) -> curve with P_i moved by v */
static int
m_move_point(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    int i = cf__lua_check_int(L, 2, "move_point", "i", 0,
                              (int)cf_bspline_count(c) - 1);
    size_t dim = cf_bspline_dim(c);
    double *v = cf__lua_check_point(L, 3, "move_point", "vector", &dim);
    cf_bspline_t **out = cf__lua_new_bspline(L);
    cf_diag_t diag;
    cf_diag_clear(&diag);
    return done(L, "move_point", cf_bspline_move_point(c, (size_t)i, v, out,
                                                       &diag), &diag, 1);
}

/* ---- queries ------------------------------------------------------------ */

static int
m_support(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    int i = cf__lua_check_int(L, 2, "support", "i", 0,
                              (int)cf_bspline_count(c) - 1);
    double lo, hi;
    cf_bspline_support(c, (size_t)i, &lo, &hi);
    lua_pushnumber(L, lo);
    lua_pushnumber(L, hi);
    return 2;
}

/* s:active_points(u) -> first, span_lo, span_hi: P_first .. P_first+p act
** on the span [span_lo, span_hi) that contains u */
static int
m_active_points(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    double u = cf__lua_check_finite(L, 2, "active_points", "u"), lo, hi;
    size_t first;
    if (cf_bspline_active_points(c, u, &first, &lo, &hi) != CF_STATUS_OK)
        return cf__lua_error(L, "active_points: u = %g is outside the "
                             "domain", u);
    lua_pushinteger(L, (lua_Integer)first);
    lua_pushnumber(L, lo);
    lua_pushnumber(L, hi);
    return 3;
}

static int
m_degree(lua_State *L)
{
    lua_pushinteger(L, cf_bspline_degree(cf__lua_check_bspline(L, 1)));
    return 1;
}

static int
m_dim(lua_State *L)
{
    lua_pushinteger(L, (lua_Integer)cf_bspline_dim(cf__lua_check_bspline(L,
                                                                         1)));
    return 1;
}

static int
m_count(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    lua_pushinteger(L, (lua_Integer)cf_bspline_count(c));
    return 1;
}

static int
m_is_rational(lua_State *L)
{
    lua_pushboolean(L, cf_bspline_is_rational(cf__lua_check_bspline(L, 1)));
    return 1;
}

static int
m_points(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    size_t n = cf_bspline_count(c), dim = cf_bspline_dim(c);
    double *out = cf__lua_buffer(L, n * dim);
    cf_bspline_get_points(c, out);
    cf__lua_push_points(L, out, n, dim);
    return 1;
}

static int
m_weights(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    size_t n = cf_bspline_count(c);
    double *out = cf__lua_buffer(L, n);
    cf_bspline_get_weights(c, out);
    cf__lua_push_numbers(L, out, n);
    return 1;
}

static int
m_knots(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    cf__lua_push_numbers(L, cf_bspline_knots(c), cf_bspline_nknots(c));
    return 1;
}

static int
m_domain(lua_State *L)
{
    double a, b;
    cf_bspline_domain(cf__lua_check_bspline(L, 1), &a, &b);
    lua_pushnumber(L, a);
    lua_pushnumber(L, b);
    return 2;
}

static int
m_knot_kind(lua_State *L)
{
    cf_bspline_t *c = cf__lua_check_bspline(L, 1);
    lua_pushstring(L, cf_knot_kind_to_string(cf_bspline_knot_kind(c)));
    return 1;
}

static const luaL_Reg methods[] = {
    { "eval", m_eval },
    { "derivs", m_derivs },
    { "basis", m_basis },
    { "deboor", m_deboor },
    { "derivative", m_derivative },
    { "insert_knot", m_insert_knot },
    { "refine", m_refine },
    { "remove_knot", m_remove_knot },
    { "split", m_split },
    { "segment", m_segment },
    { "to_beziers", m_to_beziers },
    { "elevate", m_elevate },
    { "reverse", m_reverse },
    { "transform", m_transform },
    { "move_point", m_move_point },
    { "support", m_support },
    { "active_points", m_active_points },
    { "degree", m_degree },
    { "dim", m_dim },
    { "count", m_count },
    { "is_rational", m_is_rational },
    { "points", m_points },
    { "weights", m_weights },
    { "knots", m_knots },
    { "domain", m_domain },
    { "knot_kind", m_knot_kind },
    { NULL, NULL },
};

static const luaL_Reg globals[] = {
    { "bspline", l_bspline },
    { "coons", l_coons },
    { "nurbs_circle", l_nurbs_circle },
    { "nurbs_arc", l_nurbs_arc },
    { NULL, NULL },
};

void
cf__lua_open_bspline(lua_State *L)
{
    cf__lua_new_class(L, CF__LUA_BSPLINE, methods, gc, tostring);
    lua_pushglobaltable(L);
    luaL_setfuncs(L, globals, 0);
    lua_pop(L, 1);
}
