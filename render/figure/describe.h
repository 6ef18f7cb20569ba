/*
** A figure's accessible text, for the output layer and the tool: its alt
** text and its long description (render/figure/describe.c,
** render/figure/access.c; docs/accessibility.md).
*/
#ifndef CURVEFIG_RENDER_DESCRIBE_H
#define CURVEFIG_RENDER_DESCRIBE_H

#include <stdbool.h>

#include "curvefig/figure.h"

/* The description written from what fig shows, in its language: the
** summary sentence alone, or the whole.  *out from cf_malloc (cf_free);
** fails the figure when out of memory. */
cf_status_t cf__figure_describe(cf_figure_t *fig, bool summary, char **out);

#endif
