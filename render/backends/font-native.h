/*
** The native fonts of labels (render/backends/font-native.c): HarfBuzz's
** shaping in the faces pango would choose, the same numbers as pango's;
** runs it does not handle are pango's (render/backends/font-pango.c).
*/
#ifndef CURVEFIG_RENDER_FONT_NATIVE_H
#define CURVEFIG_RENDER_FONT_NATIVE_H

#include <stdbool.h>

#include "font.h"

extern const cf__fonts_t cf__native_fonts;

/* Whether a run of these fonts was last shaped by pango. */
bool cf__native_fonts_used_pango(void *run);

#endif
