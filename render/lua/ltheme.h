/*
** The fonts of a set of figures (ltheme.c): the theme{} function, the
** tool's choice, and their application to a new figure.
*/
#ifndef CURVEFIG_RENDER_LUA_LTHEME_H
#define CURVEFIG_RENDER_LUA_LTHEME_H

#include <lua.h>

#include "curvefig/figure.h"

/* The global theme{}. */
void cf__lua_open_theme(lua_State *L);
/* The tool's fonts (NULL, 0: none), over every theme{} of the script. */
void cf__lua_set_tool_fonts(lua_State *L, const char *family,
                            double size_bp);
/* The fonts of theme{}, the tool, and the font and font_size keys of the
** figure{} table at opts, into fig's theme. */
void cf__lua_apply_fonts(lua_State *L, int opts, cf_figure_t *fig);

#endif
