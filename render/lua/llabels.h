/*
** The labels of the points a drawing method marks (polygon, points, hull,
** fill, polyline, knots, the nets of decasteljau and deboor, the end of an
** arrow), one meaning of every label option on every method:
**
**   labels       a format ("P_%d") given the label's integers, a table of
**                strings (false or nil: no label) indexed by the label's
**                number 1, 2, ..., or a function(integers...) returning a
**                string or nil
**   label_start  added to the first integer (default 0)
**   label_place  a place ("ne"), a table of places indexed like labels, or
**                a function(integers..., x, y) returning a place or nil
**   label_style  the labels' text style (color, font_size, place, ...)
**
** The integers: (i) for the points of polygon, points, ...; (i, j) for
** point i of level j of a net; (i, multiplicity) for a knot, i the index
** of its first copy; none for an arrow (labels is then its text).  In a
** format, a number of several digits substituted right after _ or ^ is
** grouped: "u_%d" of 10 gives u_{10} (a subscript 10), not u_1 followed
** by 0.
*/
#ifndef CURVEFIG_RENDER_LUA_LLABELS_H
#define CURVEFIG_RENDER_LUA_LLABELS_H

#include <lauxlib.h>
#include <lua.h>

#include "curvefig/figure.h"
#include "curvefig/figure3d.h"

/* Add the labels of n items at the 2D points pts (2n doubles) from the
** options table at opts; item k gets args[k * nargs .. k * nargs + nargs -
** 1].  labels_key names the labels option ("labels"; "label" for an
** arrow).  Nothing when the option is absent or false, or labels are off. */
void cf__lua_label_items(lua_State *L, cf_figure_t *fig, int opts,
                         const char *labels_key, const double *pts, size_t n,
                         const lua_Integer *args, int nargs, const char *fn);

/* The same for items at points p3 (3n doubles) in R^3 of a figure with a
** view (pts their images): a label follows its point, faded when the point
** is hidden behind a surface (hidden dashed), left out (remove) or drawn
** alike (show). */
void cf__lua_label_space_items(lua_State *L, cf_figure_t *fig, int opts,
                               const char *labels_key, const double *pts,
                               const double *p3, cf_hidden_t hidden,
                               size_t n, const lua_Integer *args, int nargs,
                               const char *fn);

/* The text of item k from the labels value at idx (a format, a table, a
** function, as above): pushed, and returned (NULL: no label). */
const char *cf__lua_item_label(lua_State *L, int idx, size_t k,
                               const lua_Integer *args, int nargs,
                               const char *fn);

#endif
