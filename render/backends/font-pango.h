/*
** The pango fonts of labels (render/backends/font-pango.c): the native
** renderer's choice (render/output/fonts-native.c), and for the native
** files that reach past the font seam (render/labels/font.h): the cairo
** backend draws a run as pango's layout, and a course page's glyph data
** is pango's shaping (render/output/label-glyphs.c).
*/
#ifndef CURVEFIG_RENDER_FONT_PANGO_H
#define CURVEFIG_RENDER_FONT_PANGO_H

#include <pango/pango.h>

#include "font.h"

extern const cf__fonts_t cf__pango_fonts;

/* The pango context of a label's font context (cf__fonts_t.open). */
PangoContext *cf__pango_fonts_context(void *ctx);

#endif
