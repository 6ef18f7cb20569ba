/*
** The drawing methods of figures (f:curve, f:polygon, ..., f:deboor) and
** the plot methods (f:plot, f:func, f:graph, f:basis, f:bernstein), for
** the figure class (lfigure.c).
*/
#ifndef CURVEFIG_RENDER_LUA_LDRAW_H
#define CURVEFIG_RENDER_LUA_LDRAW_H

#include <lauxlib.h>

extern const luaL_Reg cf__lua_draw_methods[];
extern const luaL_Reg cf__lua_plot_methods[];

#endif
