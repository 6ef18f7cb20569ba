/*
** Layouts in the figure language (llayout.c): the legend key of the
** drawing methods, and f:legend, f:inset and f:panels.
*/
#ifndef CURVEFIG_RENDER_LUA_LLAYOUT_H
#define CURVEFIG_RENDER_LUA_LLAYOUT_H

#include <lauxlib.h>
#include <lua.h>

#include "curvefig/figure.h"

/* Set the methods into the table on the top of the stack, each taking a
** legend = "..." option for the first element it draws. */
void cf__lua_set_legend_methods(lua_State *L, const luaL_Reg *methods);
/* legend_place and legend_frame of figure{...} (argument 1). */
void cf__lua_read_figure_legend(lua_State *L, cf_figure_t *fig);

extern const luaL_Reg cf__lua_layout_methods[];

#endif
