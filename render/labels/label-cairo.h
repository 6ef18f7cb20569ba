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

#endif
