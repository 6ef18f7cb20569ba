/*
** Internals of labels (render/labels/label.c) for the layout; drawing them
** with cairo is render/backends/label-cairo.h.  Labels know fonts only
** through render/labels/font.h.
*/
#ifndef CURVEFIG_RENDER_LABEL_PRIVATE_H
#define CURVEFIG_RENDER_LABEL_PRIVATE_H

#include <stdbool.h>

#include "curvefig/label.h"
#include "curvefig/style.h"
#include "dlist.h"

#define CF__DEFAULT_FAMILY "Latin Modern Roman,CMU Serif,Noto Serif CJK SC"
#define CF__SANS_FAMILY "Latin Modern Sans,CMU Sans Serif,Noto Sans CJK SC"

/* cf_label_create in the fonts fonts (render/labels/font.h): the layers
** above pass the fonts down (a figure's, cf__figure_create's); the public
** function is render/output/create.c's, which chooses them. */
struct cf__fonts;
cf_status_t cf__label_create(const struct cf__fonts *fonts, const char *text,
                             const char *family, double size_bp,
                             cf_label_t **out, cf_diag_t *diag);
/* Ink box of the label relative to its origin (bp, y DOWN like cairo):
** x0 y0 x1 y1. */
void cf__label_ink(const cf_label_t *label, double box[4]);
/* The outlines of the glyphs and fraction rules, baseline origin at
** (0, 0) (bp, y down like cairo): a path to fill by the nonzero rule,
** valid while the label is. */
void cf__label_outline(const cf_label_t *label, cf__path_t *out);
/* The exact box of that outline, curves by their extremes (cf__path_box,
** x0 y0 x1 y1; x1 < x0 when it draws nothing): the ink box of the label
** filled, as cairo's recording surface measures it. */
void cf__label_outline_box(const cf_label_t *label, double box[4]);
/* The bytes of text the fonts shaped to lay the label out: linear in the
** label's length (each run is measured once, its growing tail again). */
size_t cf__label_shaped_bytes(const cf_label_t *label);
/* True when the label was laid out with this family list and size. */
bool cf__label_matches(const cf_label_t *label, const char *family,
                       double size_bp);
/* The label source src as TeX (render/labels/label-tex.c) appended to out: 0,
** 1 when pdflatex could not set it (Cyrillic, CJK, other scripts), -1
** out of memory. */
struct cf__buf;
int cf__label_tex(const char *src, struct cf__buf *out);


#endif
