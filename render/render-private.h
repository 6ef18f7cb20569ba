/*
** Internals shared between the files of the renderer (prefix cf__).
*/
#ifndef CURVEFIG_RENDER_PRIVATE_H
#define CURVEFIG_RENDER_PRIVATE_H

#include <cairo.h>

#include "curvefig/figure.h"
#include "curvefig/geometry.h"

/* The core's public allocation and error functions under the names the
** renderer's files still use (the core's internals are not exported). */
#define CF__PI 3.14159265358979323846
#define cf__error cf_diag_set
#define cf__malloc cf_malloc
#define cf__calloc cf_calloc
#define cf__alloc_array cf_alloc_array
#define cf__realloc_array cf_realloc_array
#define cf__free cf_free
#define cf__check_finite_points cf_check_finite_points

#define CF__DEFAULT_FAMILY "Latin Modern Roman,CMU Serif,Noto Serif CJK SC"

/* ---- style.c ------------------------------------------------------------ */

/* The effective style of an element: the theme's role style with the
** element's set fields applied over it. */
void cf__style_resolve(const cf_theme_t *theme, cf_role_t role,
                       const cf_style_t *over, cf_style_t *out);
/* Check the fields an element sets (finite, in range); names `what`. */
cf_status_t cf__style_check(const cf_style_t *style, cf_diag_t *diag);
/* Source colour with the style's opacity applied. */
void cf__set_color(cairo_t *cr, const cf_color_t *c, double opacity);
/* Apply width and dash of a resolved style. */
void cf__set_line(cairo_t *cr, const cf_style_t *s);
/* Draw a marker of a resolved style centred at (x, y) in page units; dir
** (may be NULL) is the curve direction for CF_MARKER_TICK. */
void cf__draw_marker(cairo_t *cr, const cf_style_t *s, cf_marker_t marker,
                     double x, double y, const double *dir);

/* ---- label.c ------------------------------------------------------------ */

/* Ink box of the label relative to its origin (bp, y DOWN like cairo):
** x0 y0 x1 y1. */
void cf__label_ink(const cf_label_t *label, double box[4]);
/* True when the label was laid out with this family list and size. */
bool cf__label_matches(const cf_label_t *label, const char *family,
                       double size_bp);
/* Draw with the baseline origin at (x, y) (page units, y down). */
void cf__label_draw(const cf_label_t *label, cairo_t *cr, double x,
                    double y, const cf_color_t *color, double opacity);
/* The same glyphs stroked with width 2 * halo in colour halo_color (a
** border that keeps the label legible over lines); drawn first. */
void cf__label_draw_halo(const cf_label_t *label, cairo_t *cr, double x,
                         double y, const cf_color_t *halo_color,
                         double halo);

/* ---- output.c ----------------------------------------------------------- */

/* A growable byte buffer. */
typedef struct cf__buf {
    unsigned char *data;
    size_t size, cap;
    int failed;   /* an allocation failed */
} cf__buf_t;

int cf__buf_append(cf__buf_t *b, const void *data, size_t n);
void cf__buf_free(cf__buf_t *b);

/* ---- figure.c ----------------------------------------------------------- */

/* The page layout of one rendering. */
typedef struct cf__layout {
    double xmin, xmax, ymin, ymax;   /* data window */
    double sx, sy;                   /* bp per data unit */
    double ox, oy;                   /* page position of (xmin, ymin) */
    double tol;                      /* fitting tolerance, data units */
    bool clip;                       /* explicit window: lines clipped to
                                        it, points outside it left out */
} cf__layout_t;

/* Compute the layout for the figure's page (fills fig status on error). */
cf_status_t cf__figure_layout(cf_figure_t *fig, cf__layout_t *lay,
                              cf_diag_t *diag);
/* Draw every element onto cr (page units, y down, origin top left). */
cf_status_t cf__figure_draw(cf_figure_t *fig, const cf__layout_t *lay,
                            cairo_t *cr, cf_diag_t *diag);
/* Background colour, title and caption for the writers. */
const cf_color_t *cf__figure_background(const cf_figure_t *fig);
const char *cf__figure_title(const cf_figure_t *fig);
const char *cf__figure_caption(const cf_figure_t *fig);

#endif
