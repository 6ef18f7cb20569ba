/*
** The fonts the figures and labels the public functions make are set in
** (render/labels/font.h; render/output/create.c hands them down):
** HarfBuzz natively, pango for what it does not shape (render/output/
** fonts-native.c: render/backends/font-native.c),
** the page's glyph table in the browser module (render/web/engine.c).
*/
#ifndef CURVEFIG_RENDER_FONTS_DEFAULT_H
#define CURVEFIG_RENDER_FONTS_DEFAULT_H

#include "font.h"

const cf__fonts_t *cf__fonts_default(void);

#endif
