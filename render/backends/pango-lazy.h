/*
** pango, opened on the first label (render/backends/pango-lazy.c).
*/
#ifndef CURVEFIG_RENDER_PANGO_LAZY_H
#define CURVEFIG_RENDER_PANGO_LAZY_H

/* fn runs once, before any font is looked up, by pango or by the native
** fonts (render/backends/font-config.h): a program's font configuration,
** which a figure without text then never pays for.  Call it before the
** first figure is drawn. */
void cf__pango_before_open(void (*fn)(void));

#endif
