/*
** Lua binding of the surface constructions (include/curvefig/
** surface-make.h):
**
**   revolve(curve, { axis = {0, 0, 1}, center = {0, 0, 0}, from = 0,
**                    to = 2 * math.pi })
**   extrude(curve, {dx, dy, dz})
**   ruled{ c1, c2 }
**   coons_patch{ c0, c1, d0, d1 }   S(u, 0), S(u, 1), S(0, v), S(1, v)
**   nurbs_sphere{ center = {...}, r = 1 }
**   nurbs_cylinder{ center = {...}, r = 1, h = 1 }
**   nurbs_cone{ center = {...}, r = 1, h = 1 }
**   nurbs_torus{ center = {...}, R = 2, r = 1 }
**   interpolate_surface{ points = Q, method = "natural", param = "chord",
**                        degree = 3, count = {cu, cv}, fix_ends = true }
**
** A curve argument is a bspline or a bezier value (a Bézier curve is taken
** as the B-spline with the same points on [0, 1]).
*/
#include <string.h>

#include "curvefig/surface-make.h"
#include "lbezier.h"
#include "lbspline.h"
#include "lcommon.h"
#include "lschema.h"
#include "lsurface.h"

/* The curve at idx as a B-spline (a converted Bézier curve is left on the
** stack, owned by Lua). */
static cf_bspline_t *
curve_at(lua_State *L, int idx, const char *fn)
{
    cf_bspline_t *c = cf__lua_to_bspline(L, idx), **slot;
    cf_bezier_t *b;
    double K[2 * CF_BSPLINE_MAX_DEGREE + 2];
    cf_diag_t diag;
    cf_status_t st;
    int n;
    if (c != NULL)
        return c;
    b = cf__lua_to_bezier(L, idx);
    if (b == NULL)
        cf__lua_error(L, "%s: argument %d must be a curve (bspline or "
                      "bezier), got %s", fn, idx, luaL_typename(L, idx));
    n = cf_bezier_degree(b);
    if (n > CF_BSPLINE_MAX_DEGREE)
        cf__lua_error(L, "%s: a bezier curve of degree %d; at most %d here",
                      fn, n, CF_BSPLINE_MAX_DEGREE);
    for (int i = 0; i < 2 * n + 2; i++)
        K[i] = i <= n ? 0.0 : 1.0;
    slot = cf__lua_new_bspline(L);
    st = cf_bezier_is_rational(b)
             ? cf_bspline_create_homogeneous(cf_bezier_dim(b), n, K,
                                             (size_t)(2 * n + 2),
                                             cf_bezier_hpoints(b),
                                             (size_t)n + 1, slot, &diag)
             : cf_bspline_create(cf_bezier_dim(b), n, K, (size_t)(2 * n + 2),
                                 cf_bezier_hpoints(b), (size_t)n + 1, NULL,
                                 slot, &diag);
    if (st != CF_STATUS_OK)
        cf__lua_fail(L, fn, st, &diag);
    return *slot;
}

/* A 3-D point field of the options at idx (def when absent). */
static const double *
point3(lua_State *L, int idx, const char *key, const char *fn,
       const double *def)
{
    size_t dim = 3;
    char what[64];
    if (cf__lua_field(L, idx, key) == LUA_TNIL)
        return def;
    snprintf(what, sizeof what, "%s", key);
    return cf__lua_check_point(L, -1, fn, what, &dim);
}

static double
number(lua_State *L, int idx, const char *key, const char *fn, double def)
{
    if (cf__lua_field(L, idx, key) == LUA_TNIL)
        return def;
    return cf__lua_check_finite(L, -1, fn, key);
}

static int
l_revolve(lua_State *L)
{
    static const double z[3] = { 0, 0, 1 }, o[3] = { 0, 0, 0 };
    cf_bspline_t *c = curve_at(L, 1, "revolve");
    const double *A, *O;
    double a0, a1;
    cf_bspline_surface_t **out;
    cf_diag_t diag;
    if (!lua_isnoneornil(L, 2))
        luaL_checktype(L, 2, LUA_TTABLE);
    cf__lua_check_table(L, 2, CF__KEYS_REVOLVE);
    A = point3(L, 2, "axis", "revolve", z);
    O = point3(L, 2, "center", "revolve", o);
    a0 = number(L, 2, "from", "revolve", 0.0);
    a1 = number(L, 2, "to", "revolve", a0 + 2.0 * 3.14159265358979323846);
    out = cf__lua_new_bspline_surface(L);
    return cf__lua_done(L, "revolve",
                        cf_surface_revolve(c, O, A, a0, a1, out, &diag),
                        &diag, 1);
}

static int
l_extrude(lua_State *L)
{
    cf_bspline_t *c = curve_at(L, 1, "extrude");
    size_t dim = cf_bspline_dim(c);
    const double *d = cf__lua_check_point(L, 2, "extrude", "direction", &dim);
    cf_bspline_surface_t **out = cf__lua_new_bspline_surface(L);
    cf_diag_t diag;
    return cf__lua_done(L, "extrude", cf_surface_extrude(c, d, out, &diag),
                        &diag, 1);
}

/* The n curves of the list argument 1 (pushed when converted). */
static void
curve_list(lua_State *L, const char *fn, cf__lua_keys_t keys,
           const char *form, int n, cf_bspline_t **c)
{
    luaL_checktype(L, 1, LUA_TTABLE);
    cf__lua_check_table(L, 1, keys);
    if ((int)lua_rawlen(L, 1) != n)
        cf__lua_error(L, "%s: give %d curves, %s; got %d", fn, n, form,
                      (int)lua_rawlen(L, 1));
    for (int i = 0; i < n; i++) {
        lua_geti(L, 1, i + 1);
        c[i] = curve_at(L, lua_gettop(L), fn);
    }
}

static int
l_ruled(lua_State *L)
{
    cf_bspline_t *c[2];
    cf_bspline_surface_t **out;
    cf_diag_t diag;
    curve_list(L, "ruled", CF__KEYS_RULED, "ruled{ c1, c2 }", 2, c);
    out = cf__lua_new_bspline_surface(L);
    return cf__lua_done(L, "ruled", cf_surface_ruled(c[0], c[1], out, &diag),
                        &diag, 1);
}

static int
l_coons_patch(lua_State *L)
{
    cf_bspline_t *c[4];
    cf_bspline_surface_t **out;
    cf_diag_t diag;
    curve_list(L, "coons_patch", CF__KEYS_COONS_PATCH,
               "coons_patch{ c0, c1, d0, d1 }", 4, c);
    out = cf__lua_new_bspline_surface(L);
    return cf__lua_done(L, "coons_patch",
                        cf_surface_coons(c[0], c[1], c[2], c[3], out, &diag),
                        &diag, 1);
}

typedef cf_status_t (*quadric_fn)(const double *, double, double,
                                  cf_bspline_surface_t **, cf_diag_t *);

static cf_status_t
sphere(const double *c, double r, double h, cf_bspline_surface_t **out,
       cf_diag_t *diag)
{
    (void)h;
    return cf_nurbs_sphere(c, r, out, diag);
}

static int
quadric(lua_State *L, const char *fn, cf__lua_keys_t keys, quadric_fn make,
        const char *big, const char *small)
{
    static const double o[3] = { 0, 0, 0 };
    const double *c;
    double a, b;
    cf_bspline_surface_t **out;
    cf_diag_t diag;
    if (!lua_isnoneornil(L, 1))
        luaL_checktype(L, 1, LUA_TTABLE);
    cf__lua_check_table(L, 1, keys);
    c = point3(L, 1, "center", fn, o);
    a = number(L, 1, big, fn, keys == CF__KEYS_NURBS_TORUS ? 2.0 : 1.0);
    b = number(L, 1, small, fn, 1.0);
    out = cf__lua_new_bspline_surface(L);
    return cf__lua_done(L, fn, make(c, a, b, out, &diag), &diag, 1);
}

static int
l_sphere(lua_State *L)
{
    return quadric(L, "nurbs_sphere", CF__KEYS_NURBS_SPHERE, sphere, "r",
                   "h");
}

static int
l_cylinder(lua_State *L)
{
    return quadric(L, "nurbs_cylinder", CF__KEYS_NURBS_CYLINDER,
                   cf_nurbs_cylinder, "r", "h");
}

static int
l_cone(lua_State *L)
{
    return quadric(L, "nurbs_cone", CF__KEYS_NURBS_CONE, cf_nurbs_cone, "r",
                   "h");
}

static int
l_torus(lua_State *L)
{
    return quadric(L, "nurbs_torus", CF__KEYS_NURBS_TORUS, cf_nurbs_torus,
                   "R", "r");
}

static int
l_interpolate_surface(lua_State *L)
{
    static const char *fn = "interpolate_surface";
    cf_interp_options_t opt;
    size_t nu, nv, dim, cu = 0, cv = 0;
    double *Q;
    bool fix = true;
    cf_bspline_surface_t **out;
    cf_diag_t diag;
    cf_status_t st;
    luaL_checktype(L, 1, LUA_TTABLE);
    cf__lua_check_table(L, 1, CF__KEYS_INTERP_SURFACE);
    cf_interp_options_init(&opt);
    if (cf__lua_field(L, 1, "points") == LUA_TNIL)
        return cf__lua_error(L, "%s: points = { {Q11, Q12, ...}, ... } is "
                             "missing", fn);
    Q = cf__lua_check_grid(L, -1, fn, &nu, &nv, &dim);
    if (cf__lua_field(L, 1, "method") != LUA_TNIL) {
        st = cf_interp_method_from_string(lua_tostring(L, -1), &opt.method,
                                          &diag);
        if (st != CF_STATUS_OK)
            return cf__lua_fail(L, fn, st, &diag);
    }
    if (cf__lua_field(L, 1, "param") != LUA_TNIL) {
        st = cf_param_from_string(lua_tostring(L, -1), &opt.param, &diag);
        if (st != CF_STATUS_OK)
            return cf__lua_fail(L, fn, st, &diag);
    }
    cf__lua_field(L, 1, "degree");
    opt.degree = cf__lua_opt_int(L, -1, fn, "degree", 1,
                                 CF_BSPLINE_MAX_DEGREE, 0);
    opt.exponent = number(L, 1, "exponent", fn, opt.exponent);
    cf__lua_field(L, 1, "fix_ends");
    fix = cf__lua_opt_bool_arg(L, -1, fn, "fix_ends", true);
    if (cf__lua_field(L, 1, "count") != LUA_TNIL) {
        int k = lua_gettop(L);
        if (!lua_istable(L, k) || lua_rawlen(L, k) != 2)
            return cf__lua_error(L, "%s: count must be {cu, cv}, the numbers "
                                 "of control points along u and v", fn);
        lua_geti(L, k, 1);
        cu = (size_t)cf__lua_check_int(L, -1, fn, "count along u", 2, 100000);
        lua_geti(L, k, 2);
        cv = (size_t)cf__lua_check_int(L, -1, fn, "count along v", 2, 100000);
    }
    out = cf__lua_new_bspline_surface(L);
    if (cu == 0)
        st = cf_interpolate_surface(dim, Q, nu, nv, &opt, out, NULL, &diag);
    else
        st = cf_approximate_surface(dim, Q, nu, nv, cu, cv, &opt, fix, out,
                                    NULL, &diag);
    return cf__lua_done(L, fn, st, &diag, 1);
}

void
cf__lua_open_surface_make(lua_State *L)
{
    static const luaL_Reg fns[] = {
        { "revolve", l_revolve },
        { "extrude", l_extrude },
        { "ruled", l_ruled },
        { "coons_patch", l_coons_patch },
        { "nurbs_sphere", l_sphere },
        { "nurbs_cylinder", l_cylinder },
        { "nurbs_cone", l_cone },
        { "nurbs_torus", l_torus },
        { "interpolate_surface", l_interpolate_surface },
    };
    for (size_t i = 0; i < sizeof fns / sizeof fns[0]; i++) {
        lua_pushcfunction(L, fns[i].func);
        lua_setglobal(L, fns[i].name);
    }
}
