/*
** Figures as Lua values: the figure{} constructor and the figure list the
** tool renders.
*/
#ifndef CURVEFIG_RENDER_LUA_LFIGURE_H
#define CURVEFIG_RENDER_LUA_LFIGURE_H

#include <lua.h>

#include "curvefig/figure.h"

void cf__lua_open_figure(lua_State *L);

/* The page of every figure made from now on (the tool's --width and
** --height), in bp; 0: the script's.  One of them alone keeps the
** proportions of the page the script asks for. */
void cf__lua_set_tool_page(lua_State *L, double width_bp, double height_bp);

/* The figures defined so far, in order; which = 1 name, 2 caption. */
size_t cf__lua_figure_count(lua_State *L);
cf_figure_t *cf__lua_figure_at(lua_State *L, size_t i);
const char *cf__lua_figure_string(lua_State *L, size_t i, int which);

/* alt, description and lang of the figure{} table at index 1 (laccess.c). */
void cf__lua_read_access(lua_State *L, cf_figure_t *fig);

#endif
