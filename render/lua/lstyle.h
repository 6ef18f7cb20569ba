/*
** Reading a figure method's arguments (for lfigure.c, ldraw.c, lplot.c):
** the figure itself, styles, colours, lengths, 2D points, and turning a
** failed figure call into a Lua error.  The keys of the options tables
** are checked before any of this, by cf__lua_check_table (lschema.h).
*/
#ifndef CURVEFIG_RENDER_LUA_LSTYLE_H
#define CURVEFIG_RENDER_LUA_LSTYLE_H

#include <stdbool.h>

#include <lauxlib.h>
#include <lua.h>

#include "curvefig/figure.h"

/* The userdata of a figure value. */
typedef struct cf__lua_fbox {
    cf_figure_t *fig;
    bool borrowed;   /* a panel: its figure belongs to its parent's */
} cf__lua_fbox_t;

/* The figure a method is called on (argument 1); the hint to write
** f:method(...) when it was called with '.'. */
cf_figure_t *cf__lua_check_figure(lua_State *L);

/* False under `curvefig render --no-labels` (the label-free layer of the
** pixel tests): every label, tick label and axis label is left out. */
bool cf__lua_labels_on(lua_State *L);

/* Nothing when st is OK; otherwise raise an error: the message of diag if
** it has one, otherwise the figure's (which keeps its message, like
** cairo).  fig may be NULL. */
int cf__lua_fig_check(lua_State *L, const char *fn, const cf_figure_t *fig,
                      cf_status_t st, const cf_diag_t *diag);

/* A colour: a name, "#rrggbb", {r, g, b[, a]} or a palette number (of
** fig's theme; fig may be NULL: no palette). */
cf_color_t cf__lua_read_color(lua_State *L, int idx, const char *fn,
                              const char *what, const cf_figure_t *fig);
/* Field key of the table at idx as a finite number (def when absent;
** *given, if not NULL, tells which). */
double cf__lua_opt_number(lua_State *L, int idx, const char *key,
                          const char *fn, double def, bool *given);
bool cf__lua_opt_bool(lua_State *L, int idx, const char *key,
                      const char *fn, bool def);
/* The style fields of a method's options table at idx (nil: none set),
** and its visible = "2-" as the figure's overlay for what the method adds
** next (none: none). */
void cf__lua_read_style(lua_State *L, int idx, const char *fn,
                        cf_figure_t *fig, cf_style_t *s);
/* A nested style table (label_style = {...}): true when the key is given
** and not false (point = true: a default style). */
bool cf__lua_read_sub_style(lua_State *L, int idx, const char *key,
                            const char *fn, const cf_figure_t *fig,
                            cf_style_t *s);
/* A length: "8cm", "3 in", ... (bp, pt, texpt, mm, cm, in), or 0; def_bp
** when nil.  A bare number other than 0 is refused ("width = 8: give a
** unit, e.g. "8cm""). */
double cf__lua_read_length(lua_State *L, int idx, const char *fn,
                           const char *what, double def_bp);

/* Points given as a curve (its control points), a list of points or one
** point, projected to 2D by the figure: a buffer pushed on the stack. */
double *cf__lua_check_points2d(lua_State *L, cf_figure_t *fig, int idx,
                               const char *fn, size_t *count);
/* The same points in R^3 when the figure has a view and they are in R^3
** (a buffer pushed on the stack), else NULL (and nothing pushed). */
double *cf__lua_check_points3d(lua_State *L, cf_figure_t *fig, int idx,
                               const char *fn, size_t *count);

#endif
