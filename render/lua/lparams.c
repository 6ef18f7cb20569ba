/*
** Lua binding of the parameters of interactive figures (params.h):
**
**   slider{ name = "t", min = 0, max = 1, default = 0.5, step = 0.01,
**           label = "t", scale = "linear" | "log" } -> the slider's value
**   points{ name = "P", default = { {0, 0}, {1, 2}, ... },
**           constrain = { grid = 0.25 } | { line = { {x0, y0}, {x1, y1} } },
**           figure = "name" }                 -> a list of {x, y}
**
** A static render gives each its default; curvefig live and -f html give
** the values the reader sets.  The points are dragged in the figure named
** by figure, or in every figure of the script.
*/
#include <string.h>

#include "lcommon.h"
#include "lparams.h"
#include "lschema.h"

#define REGISTRY_KEY "curvefig.params"

void
cf__lua_set_params(lua_State *L, cf__params_t *params)
{
    lua_pushlightuserdata(L, params);
    lua_setfield(L, LUA_REGISTRYINDEX, REGISTRY_KEY);
}

cf__params_t *
cf__lua_params(lua_State *L)
{
    cf__params_t *p;
    lua_getfield(L, LUA_REGISTRYINDEX, REGISTRY_KEY);
    p = lua_touserdata(L, -1);
    lua_pop(L, 1);
    return p;
}

static cf__params_t *
store(lua_State *L)
{
    cf__params_t *p = cf__lua_params(L);
    if (p == NULL)
        cf__lua_error(L, "parameters are not available in this state");
    return p;
}

static void
read_name(lua_State *L, const char *fn, const char *key, char *out,
          size_t size, bool required)
{
    size_t len;
    const char *s;
    cf__lua_field(L, 1, key);
    s = cf__lua_opt_text(L, -1, fn, key, required ? NULL : "");
    len = strlen(s);
    if (len >= size)
        cf__lua_error(L, "%s: %s '%.20s...' is longer than %zu bytes", fn,
                      key, s, size - 1);
    memcpy(out, s, len + 1);
    lua_pop(L, 1);
}

/* The line of the script that called the binding (0 if unknown). */
static int
caller_line(lua_State *L)
{
    lua_Debug ar;
    if (lua_getstack(L, 1, &ar) && lua_getinfo(L, "l", &ar))
        return ar.currentline > 0 ? ar.currentline : 0;
    return 0;
}

static double
read_number(lua_State *L, const char *fn, const char *key, bool required,
            double def)
{
    double v = def;
    if (cf__lua_field(L, 1, key) != LUA_TNIL || required)
        v = cf__lua_check_finite(L, -1, fn, key);
    lua_pop(L, 1);
    return v;
}

static int
l_slider(lua_State *L)
{
    cf__param_t d;
    char err[300];
    double value;
    luaL_checktype(L, 1, LUA_TTABLE);
    cf__lua_check_table(L, 1, CF__KEYS_SLIDER);
    memset(&d, 0, sizeof d);
    read_name(L, "slider", "name", d.name, sizeof d.name, true);
    read_name(L, "slider", "label", d.label, sizeof d.label, false);
    d.min = read_number(L, "slider", "min", true, 0);
    d.max = read_number(L, "slider", "max", true, 0);
    d.def = read_number(L, "slider", "default", false, d.min);
    d.step = read_number(L, "slider", "step", false, 0);
    if (cf__lua_field(L, 1, "step") != LUA_TNIL && !(d.step > 0))
        cf__lua_error(L, "slider '%s': step %g must be positive", d.name,
                      d.step);
    lua_pop(L, 1);
    cf__lua_field(L, 1, "scale");
    {
        const char *sc = cf__lua_opt_text(L, -1, "slider", "scale", "linear");
        if (strcmp(sc, "log") == 0)
            d.log = true;
        else if (strcmp(sc, "linear") != 0)
            cf__lua_error(L, "slider '%s': scale \"%s\" is unknown (use "
                          "\"linear\" or \"log\")", d.name, sc);
    }
    lua_pop(L, 1);
    d.line_no = caller_line(L);
    if (cf__params_slider(store(L), &d, &value, err, sizeof err) != 0)
        cf__lua_error(L, "%s", err);
    lua_pushnumber(L, value);
    return 1;
}

/* constrain = { grid = g } or { line = { {x0, y0}, {x1, y1} } } */
static void
read_constraint(lua_State *L, cf__param_t *d)
{
    int t;
    if (cf__lua_field(L, 1, "constrain") == LUA_TNIL) {
        lua_pop(L, 1);
        return;
    }
    luaL_argexpected(L, lua_istable(L, -1), 1, "constrain = { grid = ... } "
                     "or { line = ... }");
    t = lua_gettop(L);
    if (cf__lua_field(L, t, "grid") != LUA_TNIL) {
        d->constrain = CF__CONSTRAIN_GRID;
        d->grid = cf__lua_check_finite(L, -1, "points", "constrain.grid");
    }
    if (cf__lua_field(L, t, "line") != LUA_TNIL) {
        size_t n, dim;
        const double *xy;
        if (d->constrain != CF__CONSTRAIN_NONE)
            cf__lua_error(L, "points '%s': constrain takes grid or line, "
                          "not both", d->name);
        xy = cf__lua_check_points(L, lua_gettop(L), "points",
                                  "constrain.line", 2, &n, &dim);
        if (n != 2 || dim != 2)
            cf__lua_error(L, "points '%s': constrain.line must be two points "
                          "{x, y}, got %zu of dimension %zu", d->name, n,
                          dim);
        d->constrain = CF__CONSTRAIN_LINE;
        memcpy(d->line, xy, sizeof d->line);
        lua_pop(L, 1);
    }
    if (d->constrain == CF__CONSTRAIN_NONE)
        cf__lua_error(L, "points '%s': constrain needs grid or line",
                      d->name);
    lua_settop(L, t - 1);
}

static int
l_points(lua_State *L)
{
    cf__param_t d;
    char err[300];
    size_t dim;
    const double *xy;
    luaL_checktype(L, 1, LUA_TTABLE);
    cf__lua_check_table(L, 1, CF__KEYS_PARAM_POINTS);
    memset(&d, 0, sizeof d);
    read_name(L, "points", "name", d.name, sizeof d.name, true);
    read_name(L, "points", "figure", d.figure, sizeof d.figure, false);
    cf__lua_field(L, 1, "default");
    d.def_xy = cf__lua_check_points(L, lua_gettop(L), "points", "default", 1,
                                    &d.count, &dim);
    if (dim != 2)
        cf__lua_error(L, "points '%s': default points must be {x, y}, got "
                      "%zu coordinates", d.name, dim);
    read_constraint(L, &d);
    d.line_no = caller_line(L);
    if (cf__params_points(store(L), &d, &xy, err, sizeof err) != 0)
        cf__lua_error(L, "%s", err);
    cf__lua_push_points(L, xy, d.count, 2);
    return 1;
}

void
cf__lua_open_params(lua_State *L)
{
    lua_pushcfunction(L, l_slider);
    lua_setglobal(L, "slider");
    lua_pushcfunction(L, l_points);
    lua_setglobal(L, "points");
}
