/*
** Lua binding of exact conics (include/curvefig/conic.h): each returns a
** list of quadratic (rational) Bézier curves joined end to end (one value,
** so that f:curve(conic.circle(0, 0, 1), {...}) works).
**
**   conic.arc(cx, cy, r, a0, a1)
**   conic.circle(cx, cy, r)
**   conic.ellipse(cx, cy, a, b, rotation, t0, t1)
**   conic.parabola(vx, vy, f, axis, u0, u1)
**   conic.hyperbola(cx, cy, a, b, rotation, s0, s1)
*/
#include "curvefig/conic.h"
#include "lbezier.h"
#include "lcommon.h"

static void
free_list(void *p)
{
    cf_bezier_list_destroy(p);
}

/* Read nargs finite numbers into v (names for messages). */
static void
numbers(lua_State *L, const char *fn, const char *const *names, int nargs,
        double *v)
{
    for (int k = 0; k < nargs; k++)
        v[k] = cf__lua_check_finite(L, k + 1, fn, names[k]);
}

static int
push_result(lua_State *L, const char *fn, cf_status_t st,
            cf_bezier_list_t *list, const cf_diag_t *diag)
{
    if (st != CF_STATUS_OK)
        return cf__lua_fail(L, fn, st, diag);
    cf__lua_push_bezier_list(L, list);
    return 1;
}

static int
c_arc(lua_State *L)
{
    static const char *const names[] = { "cx", "cy", "r", "a0", "a1" };
    double v[5];
    void **slot;
    cf_bezier_list_t *list = NULL;
    cf_diag_t diag;
    cf_status_t st;
    numbers(L, "conic.arc", names, 5, v);
    slot = cf__lua_holder(L, free_list);
    cf_diag_clear(&diag);
    st = cf_conic_arc(v[0], v[1], v[2], v[3], v[4], &list, &diag);
    *slot = list;
    return push_result(L, "conic.arc", st, list, &diag);
}

static int
c_circle(lua_State *L)
{
    static const char *const names[] = { "cx", "cy", "r" };
    double v[3];
    void **slot;
    cf_bezier_list_t *list = NULL;
    cf_diag_t diag;
    cf_status_t st;
    numbers(L, "conic.circle", names, 3, v);
    slot = cf__lua_holder(L, free_list);
    cf_diag_clear(&diag);
    st = cf_conic_circle(v[0], v[1], v[2], &list, &diag);
    *slot = list;
    return push_result(L, "conic.circle", st, list, &diag);
}

static int
c_ellipse(lua_State *L)
{
    static const char *const names[] = { "cx", "cy", "a", "b", "rotation",
                                         "t0", "t1" };
    double v[7];
    void **slot;
    cf_bezier_list_t *list = NULL;
    cf_diag_t diag;
    cf_status_t st;
    numbers(L, "conic.ellipse", names, 7, v);
    slot = cf__lua_holder(L, free_list);
    cf_diag_clear(&diag);
    st = cf_conic_ellipse(v[0], v[1], v[2], v[3], v[4], v[5], v[6], &list,
                          &diag);
    *slot = list;
    return push_result(L, "conic.ellipse", st, list, &diag);
}

static int
c_parabola(lua_State *L)
{
    static const char *const names[] = { "vx", "vy", "f", "axis", "u0",
                                         "u1" };
    double v[6];
    void **slot;
    cf_bezier_list_t *list = NULL;
    cf_diag_t diag;
    cf_status_t st;
    numbers(L, "conic.parabola", names, 6, v);
    slot = cf__lua_holder(L, free_list);
    cf_diag_clear(&diag);
    st = cf_conic_parabola(v[0], v[1], v[2], v[3], v[4], v[5], &list, &diag);
    *slot = list;
    return push_result(L, "conic.parabola", st, list, &diag);
}

static int
c_hyperbola(lua_State *L)
{
    static const char *const names[] = { "cx", "cy", "a", "b", "rotation",
                                         "s0", "s1" };
    double v[7];
    void **slot;
    cf_bezier_list_t *list = NULL;
    cf_diag_t diag;
    cf_status_t st;
    numbers(L, "conic.hyperbola", names, 7, v);
    slot = cf__lua_holder(L, free_list);
    cf_diag_clear(&diag);
    st = cf_conic_hyperbola(v[0], v[1], v[2], v[3], v[4], v[5], v[6], &list,
                            &diag);
    *slot = list;
    return push_result(L, "conic.hyperbola", st, list, &diag);
}

static const luaL_Reg conic_lib[] = {
    { "arc", c_arc },
    { "circle", c_circle },
    { "ellipse", c_ellipse },
    { "parabola", c_parabola },
    { "hyperbola", c_hyperbola },
    { NULL, NULL },
};

void
cf__lua_open_conic(lua_State *L)
{
    luaL_newlib(L, conic_lib);
    lua_setglobal(L, "conic");
}
