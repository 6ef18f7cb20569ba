/*
** The pango fonts of labels (render/backends/font-pango.c): the fonts of
** the runs the native fonts (render/backends/font-native.c) hand to
** pango, and a reference for their tests.  A run is described as its
** glyphs (render/labels/font.h), which is all the backends see of it.
*/
#ifndef CURVEFIG_RENDER_FONT_PANGO_H
#define CURVEFIG_RENDER_FONT_PANGO_H

#include "font.h"

extern const cf__fonts_t cf__pango_fonts;

#endif
