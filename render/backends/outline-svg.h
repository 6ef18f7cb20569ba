/*
** A label's outline (cf__label_outline) as SVG path data: the outline
** function of the SVG writer (render/backends/backend.h) without cairo,
** for the browser module, whose labels are set in a course page's glyph
** table (render/backends/outline-svg.c).
*/
#ifndef CURVEFIG_RENDER_OUTLINE_SVG_H
#define CURVEFIG_RENDER_OUTLINE_SVG_H

#include "backend.h"

/* Appends to d the outline of label t at its origin (t->ox, t->oy), page
** units; unused is not read.  Nonzero when d ran out of memory or a
** coordinate was not finite. */
int cf__label_outline_svg(void *unused, const cf__text_op_t *t,
                          struct cf__buf *d);

#endif
