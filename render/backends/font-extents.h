/*
** Where the glyphs of a run of the native fonts sit and what they cover,
** in pango's numbers (render/backends/font-extents.c), for the shaping
** (render/backends/font-native.c).
*/
#ifndef CURVEFIG_RENDER_FONT_EXTENTS_H
#define CURVEFIG_RENDER_FONT_EXTENTS_H

#include "font-native-private.h"

/* pango's baseline shifts of r's shaped items: the first item's script
** names the baseline (roman, hanging, ideographic), each item's font says
** where that baseline is for its script; each span's shift the
** difference. */
void cf__native_baseline_shifts(native_run_t *r);

/* The layout's extents from r's spans of glyphs (pango's glyph string,
** line and layout extents, one line, left to right), into out. */
void cf__native_extents(native_run_t *r, cf__font_shape_t *out);

#endif
