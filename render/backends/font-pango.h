/*
** The pango fonts of labels (render/backends/font-pango.c): the native
** renderer's choice (render/output/fonts-native.c), and for the native
** files that reach past the font seam (render/labels/font.h): the cairo
** backend draws a run as pango's layout, and a course page's glyph data
** is pango's shaping (render/output/label-glyphs.c).
*/
#ifndef CURVEFIG_RENDER_FONT_PANGO_H
#define CURVEFIG_RENDER_FONT_PANGO_H

#include <pango/pangocairo.h>

#include "font.h"

extern const cf__fonts_t cf__pango_fonts;

/* The pango context of a label's font context (cf__fonts_t.open). */
PangoContext *cf__pango_fonts_context(void *ctx);

/* The outline of glyph id of font per bp of size (from the glyph's
** origin, y down), each coordinate as a course page's glyph data holds it
** (cairo's glyph path at the font's size over that size, to 5 significant
** digits): op 'M', 'L', 'C' or 'Z' with its 1, 1, 3 or 0 points handed to
** f.  The native
** outlines and the page's are made of these same numbers, so that a
** label's ink is the same double in the tool and in the page.  cr: any
** context (its path is replaced); 0, or -1 when cairo failed. */
int cf__pango_glyph_outline(cairo_t *cr, PangoFont *font, PangoGlyph id,
                            void (*f)(void *u, char op, const double *v),
                            void *u);

#endif
