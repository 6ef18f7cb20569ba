/*
** A program's font configuration, made before the first font of a label
** is looked up (render/backends/font-config.c), by the native fonts or by
** pango, whichever comes first.
*/
#ifndef CURVEFIG_RENDER_FONT_CONFIG_H
#define CURVEFIG_RENDER_FONT_CONFIG_H

#include <stdbool.h>
#include <stddef.h>

#include "font-match.h"

/* fn runs once, before any font is looked up (render/tool/fonts.c: the
** tool's fontconfig configuration, which a figure without text then never
** pays for).  Call it before the first figure is drawn. */
void cf__fonts_before_open(void (*fn)(void));

/* Run that function, once (every font lookup calls this first). */
void cf__fonts_configure(void);

/* fn runs once, after that one, before fontconfig's configuration is
** first used (pango's fonts): the tool sets it when its own faces need no
** fontconfig (render/tool/faces.c), so that fontconfig's configuration is
** made only for a run pango shapes. */
void cf__fonts_before_fontconfig(void (*fn)(void));

/* cf__fonts_configure, then that function, once (pango opens with this). */
void cf__fonts_configure_fontconfig(void);

/* The native fonts choose the faces of the font directories dirs[0..n-1]
** accepting the families themselves, without fontconfig (render/
** backends/font-faces.h: cf__nfaces_use_dirs); false when the matcher
** declines them or out of memory. */
bool cf__fonts_own_faces(const cf__fm_source_t *dirs, size_t n,
                         const char *const *families, size_t nfamilies);

#endif
