/*
** The native fonts of labels (render/backends/font-native.c): HarfBuzz's
** shaping in the faces pango would choose, the same numbers as pango's;
** runs it does not handle are pango's (render/backends/font-pango.c).
*/
#ifndef CURVEFIG_RENDER_FONT_NATIVE_H
#define CURVEFIG_RENDER_FONT_NATIVE_H

#include <stdbool.h>
#include <stddef.h>

#include "font.h"

extern const cf__fonts_t cf__native_fonts;

/* Whether these fonts shape text[0..len) themselves rather than hand it
** to pango (the rule in font-itemize.c; a face without the characters is
** only known once fonts are chosen). */
bool cf__native_fonts_handles(const char *text, size_t len);

/* Whether a run of these fonts was last shaped by pango. */
bool cf__native_fonts_used_pango(void *run);

#endif
