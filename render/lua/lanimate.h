/*
** animate{} of the figure language (lanimate.c): the script's animation,
** declared into a spec its host owns (render/lua/anim-spec.h).
*/
#ifndef CURVEFIG_RENDER_LUA_LANIMATE_H
#define CURVEFIG_RENDER_LUA_LANIMATE_H

#include <stdbool.h>

#include <lua.h>

#include "anim-spec.h"

/* Where animate{} declares (owned by the caller, alive while the state
** runs): the spec, and *declared set once it was called. */
void cf__lua_set_animation(lua_State *L, cf__anim_spec_t *spec,
                           bool *declared);
/* Set the global animate. */
void cf__lua_open_animate(lua_State *L);

#endif
