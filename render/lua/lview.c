/*
** The view of a 3D figure in the figure language (include/curvefig/
** figure3d.h): figure{ view = {azimuth, elevation}, projection =
** "orthographic" | "perspective", distance = D, target = {x, y, z} } and
** f:view(azimuth, elevation, {projection = ..., distance = ...,
** target = ...}) for a figure made without one.  A page that rotates the
** figure (curvefig live, -f html) gives the angles to use in the script's
** place (params.h, cf__params_view): the script runs with them, so that
** everything it draws and projects follows the rotated view.
*/
#include <math.h>
#include <string.h>

#include "curvefig/figure3d.h"
#include "lcommon.h"
#include "lfigure.h"
#include "lparams.h"
#include "lstyle.h"
#include "lview.h"

/* The view of options table opts (angles az_el, unless the page gave the
** figure named name others); fn names the function in messages. */
static void
make_view(lua_State *L, cf_figure_t *fig, const char *name, int opts,
          double az_el[2], const char *fn)
{
    cf_view_t view;
    cf_diag_t diag;
    const char *proj = "orthographic";
    double dist = 0, *target = NULL;
    size_t n;
    cf_status_t st;
    if (opts != 0 && cf__lua_field(L, opts, "projection") == LUA_TSTRING)
        proj = lua_tostring(L, -1);
    if (strcmp(proj, "orthographic") != 0 && strcmp(proj, "perspective") != 0)
        cf__lua_error(L, "%s: projection = \"%s\" is unknown; give "
                      "\"orthographic\" or \"perspective\"", fn, proj);
    if (opts != 0 && cf__lua_field(L, opts, "distance") != LUA_TNIL) {
        if (!lua_isnumber(L, -1) || !(lua_tonumber(L, -1) > 0)
            || !isfinite(lua_tonumber(L, -1)))
            cf__lua_error(L, "%s: distance must be a positive number (the "
                          "eye's distance from the target), got %s", fn,
                          lua_isnumber(L, -1) ? lua_tostring(L, -1)
                                              : luaL_typename(L, -1));
        dist = lua_tonumber(L, -1);
        if (proj[0] == 'o')
            cf__lua_error(L, "%s: distance is for projection = "
                          "\"perspective\"", fn);
    } else if (proj[0] == 'p') {
        cf__lua_error(L, "%s: projection = \"perspective\" needs distance "
                      "(the eye's distance from the target)", fn);
    }
    if (opts != 0 && cf__lua_field(L, opts, "target") != LUA_TNIL) {
        target = cf__lua_check_numbers(L, -1, fn, "target", &n);
        if (n != 3)
            cf__lua_error(L, "%s: target is a point {x, y, z}, got %zu "
                          "numbers", fn, n);
    }
    cf__params_view(cf__lua_params(L), name, az_el);
    cf_diag_clear(&diag);
    if (proj[0] == 'o')
        st = cf_view_orthographic(&view, az_el[0], az_el[1], &diag);
    else
        st = cf_view_perspective(&view, az_el[0], az_el[1], dist, target,
                                 &diag);
    if (st != CF_STATUS_OK)
        cf__lua_error(L, "%s: view: %s", fn, diag.msg);
    cf__lua_fig_check(L, fn, fig, cf_figure_set_view(fig, &view), &diag);
}

/* {azimuth, elevation}: exactly two finite numbers. */
static void
check_angles(lua_State *L, int idx, const char *fn, double az_el[2])
{
    size_t n;
    double *v;
    if (!lua_istable(L, idx))
        cf__lua_error(L, "%s: view is {azimuth, elevation} in degrees, got "
                      "%s", fn, luaL_typename(L, idx));
    v = cf__lua_check_numbers(L, idx, fn, "view angle", &n);
    if (n != 2)
        cf__lua_error(L, "%s: view is two numbers {azimuth, elevation} in "
                      "degrees, got %zu", fn, n);
    for (int k = 0; k < 2; k++)
        if (!isfinite(v[k]))
            cf__lua_error(L, "%s: view: %s = %g is not finite", fn,
                          k == 0 ? "azimuth" : "elevation", v[k]);
    az_el[0] = v[0];
    az_el[1] = v[1];
}

void
cf__lua_read_view(lua_State *L, cf_figure_t *fig, const char *name, int opts)
{
    int top = lua_gettop(L);
    double az_el[2];
    bool string_proj;
    cf__lua_field(L, opts, "view");
    string_proj = cf__lua_field(L, opts, "projection") == LUA_TSTRING;
    if (lua_isnil(L, top + 1)) {
        if (string_proj || cf__lua_field(L, opts, "distance") != LUA_TNIL
            || cf__lua_field(L, opts, "target") != LUA_TNIL)
            cf__lua_error(L, "figure: projection, distance and target "
                          "belong to a view; give view = {azimuth, "
                          "elevation} too");
        lua_settop(L, top);
        return;
    }
    check_angles(L, top + 1, "figure", az_el);
    make_view(L, fig, name, opts, az_el, "figure");
    lua_settop(L, top);
}

/* f:view(azimuth, elevation, {projection = ..., distance = ...}) */
static int
m_view(lua_State *L)
{
    cf_figure_t *fig = cf__lua_check_figure(L);
    double az_el[2];
    lua_settop(L, 4);
    az_el[0] = cf__lua_check_finite(L, 2, "view", "azimuth");
    az_el[1] = cf__lua_check_finite(L, 3, "view", "elevation");
    if (!lua_isnil(L, 4))
        luaL_checktype(L, 4, LUA_TTABLE);
    lua_getiuservalue(L, 1, 1);     /* the figure's name (5) */
    make_view(L, fig, lua_tostring(L, 5), lua_isnil(L, 4) ? 0 : 4, az_el,
              "view");
    lua_settop(L, 1);
    return 1;
}

const luaL_Reg cf__lua_view_methods[] = {
    { "view", m_view },
    { NULL, NULL },
};
