/*
** The methods of figures that draw surfaces (lsurface-draw.c: f:surface;
** lsurface-scheme.c: the constructions as figures), and the surface
** argument they take.
*/
#ifndef CURVEFIG_RENDER_LUA_LSURFACE_DRAW_H
#define CURVEFIG_RENDER_LUA_LSURFACE_DRAW_H

#include <lauxlib.h>

#include "curvefig/surface.h"

/* The surface at idx as a B-spline surface (a Bézier one converted, the
** conversion held on the stack), or an error naming fn. */
const cf_bspline_surface_t *cf__lua_surface_arg(lua_State *L, int idx,
                                                const char *fn);

extern const luaL_Reg cf__lua_surface_draw_methods[];
extern const luaL_Reg cf__lua_surface_scheme_methods[];

#endif
