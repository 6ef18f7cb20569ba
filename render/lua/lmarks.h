/*
** What the drawing methods compute on a curve before they draw: the
** tangent arrow at a parameter and the points of the distinct knots (for
** ldraw.c).  Both are in the figure's 2D coordinates (projected).
*/
#ifndef CURVEFIG_RENDER_LUA_LMARKS_H
#define CURVEFIG_RENDER_LUA_LMARKS_H

#include <lauxlib.h>
#include <lua.h>

#include "curvefig/bspline.h"
#include "curvefig/figure.h"

/* The arrow from c(t) to c(t) + scale c'(t) of the curve at idx (a Bézier
** or a B-spline) into pd[4] (x0, y0, x1, y1); scale is 1 / degree (the
** end legs of a Bézier) unless opts gives one.  Raises "tangent: t = 1.5
** is outside the domain [0, 1]". */
void cf__lua_tangent_arrow(lua_State *L, cf_figure_t *fig, int idx, double t,
                           int opts, double pd[4]);

/* The distinct knots of s in its domain: their curve points (2D, *pts)
** and, for each, the index of its first copy and its multiplicity
** (*args, two integers per knot), in buffers pushed on the stack.
** Returns how many. */
size_t cf__lua_knot_marks(lua_State *L, cf_figure_t *fig,
                          const cf_bspline_t *s, double **pts,
                          lua_Integer **args);

#endif
