/*
** Labels drawn with cairo (render/label.c), for the backends that draw
** through cairo: the cairo backend, the PGF backend's outlines and the
** glyph outlines of the SVG writer.
*/
#ifndef CURVEFIG_RENDER_LABEL_CAIRO_H
#define CURVEFIG_RENDER_LABEL_CAIRO_H

#include <cairo.h>

#include "label-private.h"

/* Draw with the baseline origin at (x, y) (page units, y down). */
void cf__label_draw(const cf_label_t *label, cairo_t *cr, double x,
                    double y, const cf_color_t *color, double opacity);
/* The outlines of the glyphs (and fraction rules) appended to cr's path,
** baseline origin at (x, y). */
void cf__label_path(const cf_label_t *label, cairo_t *cr, double x,
                    double y);
/* The same glyphs stroked with width 2 * halo in colour halo_color (a
** border that keeps the label legible over lines); drawn first. */
void cf__label_draw_halo(const cf_label_t *label, cairo_t *cr, double x,
                         double y, const cf_color_t *halo_color,
                         double halo);

/* The glyphs of the label one by one, baseline origin at (x, y), where
** cf__label_path puts them (render/labels/label-glyph-runs.c): glyph
** gets each glyph's scaled font, index and origin on the page, rule each
** fraction rule (x y w h), in drawing order.  1, and no call, when a
** glyph is missing from its font (pango draws a box for it, which has no
** outline of the font: take the label's path whole); else the first
** nonzero result of a call, or 0. */
typedef struct cf__label_glyph_fns {
    int (*glyph)(void *ctx, cairo_scaled_font_t *font, unsigned long index,
                 double x, double y);
    int (*rule)(void *ctx, const double rect[4]);
} cf__label_glyph_fns_t;

int cf__label_glyphs(const cf_label_t *label, double x, double y,
                     const cf__label_glyph_fns_t *fns, void *ctx);

#endif
