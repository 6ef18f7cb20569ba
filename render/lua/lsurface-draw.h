/*
** The methods of figures that draw surfaces (lsurface-draw.c: f:surface;
** lsurface-scheme.c: the constructions as figures), and the surface
** argument they take.
*/
#ifndef CURVEFIG_RENDER_LUA_LSURFACE_DRAW_H
#define CURVEFIG_RENDER_LUA_LSURFACE_DRAW_H

#include <lauxlib.h>

#include "curvefig/figure.h"
#include "curvefig/figure3d.h"
#include "curvefig/surface.h"

/* The surface at idx as a B-spline surface (a Bézier one converted, the
** conversion held on the stack), or an error naming fn. */
const cf_bspline_surface_t *cf__lua_surface_arg(lua_State *L, int idx,
                                                const char *fn);

/* f:curve of a curve in R^3 (at idx; a Bézier or B-spline) in a figure
** with a view: drawn split by the figure's surfaces, hidden = "dashed"
** (default), "remove" or "show" from the options at opts.  false (nothing
** done) for any other curve or figure. */
bool cf__lua_space_curve(lua_State *L, cf_figure_t *fig, int idx, int opts,
                         const cf_style_t *st);

/* The hidden = "remove" | "dashed" | "show" option at opts (def when
** absent). */
cf_hidden_t cf__lua_read_hidden(lua_State *L, int opts, const char *fn,
                                const char *def);

extern const luaL_Reg cf__lua_surface_draw_methods[];
extern const luaL_Reg cf__lua_surface_scheme_methods[];

#endif
