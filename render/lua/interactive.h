/*
** One run of an interactive figure: a script run in a fresh sandbox with
** the values a reader set, answered as one JSON text that a page (the
** live server's, or the one -f html writes) draws from.  docs/
** interactive.md describes the page; the JSON is
**
**   { "params":  [ { "kind": "slider", "name": "t", "label": "t",
**                    "min": 0, "max": 1, "step": 0.01, "default": 0.75,
**                    "value": 0.75 },
**                  { "kind": "points", "name": "P", "figure": "",
**                    "value": [[x, y], ...], "default": [[x, y], ...],
**                    "constrain": null | { "grid": g }
**                                 | { "line": [[x0, y0], [x1, y1]] } } ],
**     "figures": [ { "name": "...", "caption": "...",
**                    "width": W, "height": H,         (bp)
**                    "view": null | [azimuth, elevation], (a 3D figure's,
**                                          degrees: params.h, "@view:")
**                    "svg": "<svg ...>...</svg>",
**                    "to_svg": [a, b, c, d, e, f],    (data -> SVG units)
**                    "handles": [ { "param": "P", "index": 0, "x": ..,
**                                   "y": .., "sx": .., "sy": .. } ],
**                    "labels": [ { "text": "P_0", "place": 1, "x": ..,
**                                  "y": .., "anchor_x": ..,
**                                  "anchor_y": .. } ] } ],
**     "error":   null | { "message": "...", "line": N },
**     "lua":     "values = { t = 0.75, P = { {0, 0}, ... } }" }
**
** The values may hold "@view:FIGURE": [[azimuth, elevation]], the view a
** page rotated a 3D figure to, which replaces the script's (params.h).
** handles are the points of every points{} list dragged in that figure;
** sx, sy their place in the figure's SVG; labels the places the layout
** chose (cf_figure_render_places).  On a script error the figures
** are left out and params holds what was declared before the error.
*/
#ifndef CURVEFIG_RENDER_LUA_INTERACTIVE_H
#define CURVEFIG_RENDER_LUA_INTERACTIVE_H

#include <stddef.h>
#include <stdio.h>

#include "script.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Run code (the script's text; name, its file name, is used in messages)
** with the values in the JSON text values[0..values_len-1] (NULL: every
** default) under limits (NULL: the defaults of script.h); what the script
** prints goes to out (NULL: stderr).  *json (NUL-terminated, *len bytes;
** free()) is the JSON above.  CF_STATUS_OK when the script ran or failed
** (its error is then in the JSON); CF_STATUS_INVALID_ARG when values is
** not the JSON of values (*json then holds {"error": {"message": ...,
** "line": 0}} and nothing ran); CF_STATUS_NO_MEMORY (*json NULL). */
cf_status_t cf_interactive_run(const char *code, const char *name,
                               const char *values, size_t values_len,
                               const cf_script_limits_t *limits, FILE *out,
                               char **json, size_t *len);

/* cf_interactive_run, and the error of the run (the JSON's message: the
** script's file:line first for an error in the script; "" when it ran)
** into error[0..error_len-1] (NULL: not asked for). */
cf_status_t cf_interactive_run_error(const char *code, const char *name,
                                     const char *values, size_t values_len,
                                     const cf_script_limits_t *limits,
                                     FILE *out, char **json, size_t *len,
                                     char *error, size_t error_len);

/* A points{} list whose figure = names no figure the script defined:
** the message (with the nearest figure's name) into err[0..errlen-1] and
** the points{} line; -1 when every name is a figure's.  live refuses such
** a script; render, list and check too (the typo would show only later,
** in the lecture hall, when the points cannot be dragged). */
int cf_interactive_check_figures(const cf_script_t *s, char *err,
                                 size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
