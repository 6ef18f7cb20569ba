/*
** curvefig overlay steps: elements of a figure shown on some steps only,
** as beamer's \visible<2->{...} shows them on slides (library
** curvefig-render; included by curvefig/figure.h).
**
** A specification is beamer's: ranges separated by commas, each "N"
** (step N), "N-M" (steps N to M), "N-" (N to the last step) or "-M"
** (1 to M); steps count from 1 and go up to 999.  The figure's number
** of steps is the largest step any element names (an open range "N-"
** counts N); a figure without specifications has one.
**
** Every step has the same page and the same layout: the window is fitted
** to every element and a cropped page (tight) is the ink of every step
** together.  What the outputs give (docs/overlays.md): PDF and PS one page
** per step, SVG one file animated step by step (SMIL), PNG and EPS the
** last step, or any one step through cf_write_options_t.step.
*/
#ifndef CURVEFIG_OVERLAY_H
#define CURVEFIG_OVERLAY_H

#include <stddef.h>

#include "curvefig/core.h"
#include "curvefig/export.h"
#include "curvefig/output.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Elements added from now on are shown only on the steps of spec, as
** inside beamer's \visible<spec>{...}; spec NULL: on every step again.
** A bad specification is INVALID_ARG saying what is wrong ("visible =
** \"2-x\": unexpected \"x\" ..."), recorded in the figure as its other
** errors are. */
CF_API cf_status_t cf_figure_set_overlay(cf_figure_t *fig, const char *spec);

/* The number of steps (1 without specifications; 0 for NULL). */
CF_API unsigned cf_figure_steps(const cf_figure_t *fig);

/* Whether element i is shown on step k (false out of range). */
CF_API bool cf_figure_visible_at(const cf_figure_t *fig, size_t i,
                                 unsigned k);

#ifdef __cplusplus
}
#endif

#endif
