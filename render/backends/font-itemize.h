/*
** The text of a run of the native fonts in pango's items
** (render/backends/font-itemize.c), for the shaping
** (render/backends/font-native.c).
*/
#ifndef CURVEFIG_RENDER_FONT_ITEMIZE_H
#define CURVEFIG_RENDER_FONT_ITEMIZE_H

#include "font-native-private.h"

/* Whether the native fonts shape text[0..len) themselves rather than
** hand it to pango (the rule in font-itemize.c; a face without the
** characters is only known once fonts are chosen). */
bool cf__native_fonts_handles(const char *text, size_t len);

/* pango's default language, canonical ("c" when the program never set
** the locale), read once as pango reads it (pango_language_get_default):
** one per process, as pango's is. */
const char *cf__native_language(void);

/* The items of text[0..len) in the fonts of set, into r->items (a font
** and a script each, in order); false when a character has no font
** (pango's then) or out of memory (r->oom). */
bool cf__native_itemize(native_run_t *r, cf__nfontset_t *set,
                        const char *text, size_t len);

#endif
