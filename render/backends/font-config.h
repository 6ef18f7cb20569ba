/*
** A program's font configuration, made before the first font of a label
** is looked up (render/backends/font-config.c), by the native fonts or by
** pango, whichever comes first.
*/
#ifndef CURVEFIG_RENDER_FONT_CONFIG_H
#define CURVEFIG_RENDER_FONT_CONFIG_H

/* fn runs once, before any font is looked up (render/tool/fonts.c: the
** tool's fontconfig configuration, which a figure without text then never
** pays for).  Call it before the first figure is drawn. */
void cf__fonts_before_open(void (*fn)(void));

/* Run that function, once (every font lookup calls this first). */
void cf__fonts_configure(void);

#endif
