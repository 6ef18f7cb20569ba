/*
** The view of 3D figures in the figure language (lview.c): read from
** figure{...} and set by f:view.
*/
#ifndef CURVEFIG_RENDER_LUA_LVIEW_H
#define CURVEFIG_RENDER_LUA_LVIEW_H

#include <lauxlib.h>

#include "curvefig/figure.h"

/* view, projection (a name), distance and target of the figure{} table
** at opts of the figure named name (whose view a page may have rotated:
** params.h); nothing when view is absent. */
void cf__lua_read_view(lua_State *L, cf_figure_t *fig, const char *name,
                       int opts);

/* f:view(...) */
extern const luaL_Reg cf__lua_view_methods[];

#endif
