/*
** B-spline curves as Lua values, for the other binding files.
*/
#ifndef CURVEFIG_RENDER_LUA_LBSPLINE_H
#define CURVEFIG_RENDER_LUA_LBSPLINE_H

#include <lua.h>

#include "curvefig/bspline.h"

cf_bspline_t **cf__lua_new_bspline(lua_State *L);
cf_bspline_t *cf__lua_check_bspline(lua_State *L, int idx);
/* The curve at idx or NULL when it is not a B-spline. */
cf_bspline_t *cf__lua_to_bspline(lua_State *L, int idx);
void cf__lua_open_bspline(lua_State *L);

#endif
