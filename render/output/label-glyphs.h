/*
** The glyph data of a course page (render/output/label-glyphs.c): what the
** WebAssembly module needs to lay out and draw labels without the tool's
** fonts (render/labels/font-table.c reads it; its comment gives the format).
*/
#ifndef CURVEFIG_RENDER_LABEL_GLYPHS_H
#define CURVEFIG_RENDER_LABEL_GLYPHS_H

#include <stddef.h>

#include "curvefig/figure.h"

struct cf__buf;

/* The glyph data of the labels of figs[0..n-1] as they are now (drawn at
** their size): every text as the tool shaped it (the numbers pango
** gives), and in each of their font
** descriptions the characters of printable ASCII, Greek, a few math
** symbols, and every character of those texts, so that texts a slider
** makes are composed from them.  Appended to out. */
cf_status_t cf__glyph_data(cf_figure_t *const *figs, size_t n,
                           struct cf__buf *out, cf_diag_t *diag);

#endif
