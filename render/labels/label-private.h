/*
** Internals of labels (render/label.c) for the layout and the cairo
** backend.
*/
#ifndef CURVEFIG_RENDER_LABEL_PRIVATE_H
#define CURVEFIG_RENDER_LABEL_PRIVATE_H

#include <stdbool.h>

#include <cairo.h>

#include "curvefig/label.h"
#include "curvefig/style.h"

#define CF__DEFAULT_FAMILY "Latin Modern Roman,CMU Serif,Noto Serif CJK SC"
#define CF__SANS_FAMILY "Latin Modern Sans,CMU Sans Serif,Noto Sans CJK SC"

/* Ink box of the label relative to its origin (bp, y DOWN like cairo):
** x0 y0 x1 y1. */
void cf__label_ink(const cf_label_t *label, double box[4]);
/* True when the label was laid out with this family list and size. */
bool cf__label_matches(const cf_label_t *label, const char *family,
                       double size_bp);
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

/* The label source src as TeX (render/label-tex.c) appended to out: 0,
** 1 when pdflatex could not set it (Cyrillic, CJK, other scripts), -1
** out of memory. */
struct cf__buf;
int cf__label_tex(const char *src, struct cf__buf *out);


#endif
