/*
** Bézier curves as Lua values, for the other binding files.
*/
#ifndef CURVEFIG_RENDER_LUA_LBEZIER_H
#define CURVEFIG_RENDER_LUA_LBEZIER_H

#include <lauxlib.h>
#include <lua.h>

#include "curvefig/bezier.h"

/* Push an empty curve value; the caller stores the curve in the slot. */
cf_bezier_t **cf__lua_new_bezier(lua_State *L);
cf_bezier_t *cf__lua_check_bezier(lua_State *L, int idx);
/* The curve at idx or NULL when it is not a Bézier curve. */
cf_bezier_t *cf__lua_to_bezier(lua_State *L, int idx);
/* Push a Lua array of the list's curves, moving them out of the list
** (the list stays valid, with NULL items). */
void cf__lua_push_bezier_list(lua_State *L, cf_bezier_list_t *list);
/* Push a Lua array of cubic Bézier curves, one per segment of cu. */
void cf__lua_push_cubics(lua_State *L, const cf_cubics_t *cu);
/* Add methods to Bézier curve values. */
void cf__lua_add_bezier_methods(lua_State *L, const luaL_Reg *more);

#endif
