/*
** animate{} of the figure language (docs/animations.md): how `curvefig
** render` animates the script's figures when an animation format is asked
** for (or --animate):
**
**   animate{ slider = "t", from = 0, to = 1, seconds = 4, fps = 25,
**            frames = N, ease = "linear" | "in-out", bounce = false,
**            step_seconds = 1.5 }
**   animate{ { slider = "t", from = 0, to = 1 },
**            { slider = "w", from = 1, to = 3 }, seconds = 4 }
**
** The sliders are checked against the script's slider{} declarations when
** the tool animates (anim-spec.h); a static render ignores animate{}.
*/
#include <string.h>

#include "anim-spec.h"
#include "lanimate.h"
#include "lcommon.h"
#include "lcount.h"
#include "lpairs.h"

#define REGISTRY_KEY "curvefig.animate"

static const char *const keys[] = {
    "slider", "from", "to", "seconds", "fps", "frames", "ease", "bounce",
    "step_seconds",
};
static const char *const sweep_keys[] = { "slider", "from", "to" };

void
cf__lua_set_animation(lua_State *L, cf__anim_spec_t *spec, bool *declared)
{
    lua_pushlightuserdata(L, spec);
    lua_setfield(L, LUA_REGISTRYINDEX, REGISTRY_KEY);
    lua_pushlightuserdata(L, declared);
    lua_setfield(L, LUA_REGISTRYINDEX, REGISTRY_KEY ".declared");
}

static void *
registry(lua_State *L, const char *key)
{
    void *p;
    lua_getfield(L, LUA_REGISTRYINDEX, key);
    p = lua_touserdata(L, -1);
    lua_pop(L, 1);
    if (p == NULL)
        cf__lua_error(L, "animate: not available in this state");
    return p;
}

/* Every string key of the table at idx one of names[n]. */
static void
check_keys(lua_State *L, int idx, const char *what, const char *const *names,
           size_t n)
{
    idx = lua_absindex(L, idx);
    cf__lua_sorted_keys(L, idx);   /* the same key named at every run */
    for (lua_Integer j = 1, m = (lua_Integer)lua_rawlen(L, -1); j <= m;
         j++, lua_pop(L, 1)) {
        lua_rawgeti(L, -1, j);
        if (lua_type(L, -1) == LUA_TSTRING) {
            const char *k = lua_tostring(L, -1);
            const char *near;
            size_t i;
            for (i = 0; i < n && strcmp(k, names[i]) != 0; i++)
                ;
            if (i == n) {
                near = cf__lua_nearest_name(L, k, names, n);
                cf__lua_error(L, "%s: unknown key '%s'%s%s%s", what, k,
                              near ? " (did you mean " : "",
                              near ? near : "", near ? "?)" : "");
            }
        } else if (!lua_isinteger(L, -1)) {
            cf__lua_error(L, "%s: a key must be a name or a list index",
                          what);
        }
    }
    lua_pop(L, 1);
}

static double
opt_number(lua_State *L, int idx, const char *what, const char *key,
           double def)
{
    double v = def;
    if (cf__lua_field(L, idx, key) != LUA_TNIL)
        v = cf__lua_check_finite(L, -1, what, key);
    lua_pop(L, 1);
    return v;
}

static void
read_sweep(lua_State *L, int idx, cf__anim_spec_t *spec, const char *what)
{
    cf__anim_sweep_t *sw;
    const char *name;
    if (spec->nsweeps >= CF__ANIM_MAX_SWEEPS)
        cf__lua_error(L, "animate: at most %d sliders move together",
                      CF__ANIM_MAX_SWEEPS);
    sw = &spec->sweep[spec->nsweeps];
    cf__lua_field(L, idx, "slider");
    name = cf__lua_opt_text(L, -1, what, "slider", NULL);
    if (name == NULL)   /* never: a missing name raised an error */
        return;
    if (strlen(name) >= sizeof sw->name)
        cf__lua_error(L, "%s: slider name '%.20s...' is too long", what, name);
    for (size_t i = 0; i < spec->nsweeps; i++)
        if (strcmp(spec->sweep[i].name, name) == 0)
            cf__lua_error(L, "%s: slider '%s' is swept twice", what, name);
    strcpy(sw->name, name);
    lua_pop(L, 1);
    if (cf__lua_field(L, idx, "from") == LUA_TNIL
        || cf__lua_field(L, idx, "to") == LUA_TNIL)
        cf__lua_error(L, "%s: slider '%s' needs from and to", what, name);
    lua_pop(L, 2);
    sw->from = opt_number(L, idx, what, "from", 0);
    sw->to = opt_number(L, idx, what, "to", 0);
    spec->nsweeps++;
}

static int
l_animate(lua_State *L)
{
    cf__anim_spec_t *spec = registry(L, REGISTRY_KEY);
    bool *declared = registry(L, REGISTRY_KEY ".declared");
    cf__anim_spec_t s;
    lua_Debug ar;
    const char *ease;
    double frames;
    luaL_checktype(L, 1, LUA_TTABLE);
    if (*declared)
        cf__lua_error(L, "animate: called twice (one animate{} per script; "
                      "several sliders go in one list)");
    check_keys(L, 1, "animate", keys, sizeof keys / sizeof keys[0]);
    memset(&s, 0, sizeof s);
    if (cf__lua_field(L, 1, "slider") != LUA_TNIL) {
        lua_pop(L, 1);
        read_sweep(L, 1, &s, "animate");
    } else {
        lua_pop(L, 1);
    }
    for (lua_Integer i = 1;; i++) {
        char what[48];
        if (lua_geti(L, 1, i) == LUA_TNIL) {
            lua_pop(L, 1);
            break;
        }
        snprintf(what, sizeof what, "animate: sweep %lld", (long long)i);
        if (!lua_istable(L, -1))
            cf__lua_error(L, "%s must be a table { slider = ..., from = ..., "
                          "to = ... }", what);
        check_keys(L, lua_gettop(L), what, sweep_keys,
                   sizeof sweep_keys / sizeof sweep_keys[0]);
        read_sweep(L, lua_gettop(L), &s, what);
        lua_pop(L, 1);
    }
    s.fps = opt_number(L, 1, "animate", "fps", 0);
    s.seconds = opt_number(L, 1, "animate", "seconds", 0);
    s.step_seconds = opt_number(L, 1, "animate", "step_seconds", 0);
    if (cf__lua_field(L, 1, "fps") != LUA_TNIL && !(s.fps > 0))
        cf__lua_error(L, "animate: fps %g must be positive", s.fps);
    if (cf__lua_field(L, 1, "seconds") != LUA_TNIL && !(s.seconds > 0))
        cf__lua_error(L, "animate: seconds %g must be positive", s.seconds);
    if (cf__lua_field(L, 1, "step_seconds") != LUA_TNIL
        && !(s.step_seconds > 0))
        cf__lua_error(L, "animate: step_seconds %g must be positive",
                      s.step_seconds);
    lua_pop(L, 3);
    frames = opt_number(L, 1, "animate", "frames", 0);
    if (cf__lua_field(L, 1, "frames") != LUA_TNIL
        && !(frames >= 1 && frames <= CF__ANIM_MAX_FRAMES
             && frames == (double)(unsigned)frames))
        cf__lua_error(L, "animate: frames %g must be a whole number from 1 "
                      "to %d", frames, CF__ANIM_MAX_FRAMES);
    lua_pop(L, 1);
    s.frames = (unsigned)frames;
    cf__lua_field(L, 1, "ease");
    ease = cf__lua_opt_text(L, -1, "animate", "ease", "linear");
    if (strcmp(ease, "in-out") == 0)
        s.ease_in_out = true;
    else if (strcmp(ease, "linear") != 0)
        cf__lua_error(L, "animate: ease \"%s\" is unknown (use \"linear\" "
                      "or \"in-out\")", ease);
    lua_pop(L, 1);
    cf__lua_field(L, 1, "bounce");
    s.bounce = cf__lua_opt_bool_arg(L, -1, "animate", "bounce", false);
    lua_pop(L, 1);
    s.line_no = lua_getstack(L, 1, &ar) && lua_getinfo(L, "l", &ar)
                    && ar.currentline > 0 ? ar.currentline : 0;
    *spec = s;
    *declared = true;
    return 0;
}

void
cf__lua_open_animate(lua_State *L)
{
    lua_pushcfunction(L, l_animate);
    lua_setglobal(L, "animate");
}
