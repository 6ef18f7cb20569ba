/*
** curvefig figure layouts: legends, panels and zoom insets (library
** curvefig-render; included by curvefig/figure.h).
**
** All three are laid out when the figure is written, like everything
** else, and reach every output format through the same drawing
** operations as the elements.
*/
#ifndef CURVEFIG_LAYOUT_H
#define CURVEFIG_LAYOUT_H

#include <stdbool.h>
#include <stddef.h>

#include "curvefig/core.h"
#include "curvefig/export.h"
#include "curvefig/output.h"
#include "curvefig/style.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- legends ------------------------------------------------------------ */

/* A legend entry for the element added last: a sample of its line, fill
** and marker as drawn (the first path and the first marker it draws)
** beside the label text (TeX-like syntax, curvefig/label.h), in the order
** the entries are given.  INVALID_ARG when no element was added yet or it
** already has an entry; a syntax error names the byte. */
CF_API cf_status_t cf_figure_add_legend(cf_figure_t *fig, const char *text);
/* The same for element `element` (0 for the first added; below
** cf_figure_element_count). */
CF_API cf_status_t cf_figure_add_legend_at(cf_figure_t *fig, size_t element,
                                           const char *text);

/* Where the legend goes: CF_PLACE_AUTO (the default) tries the corners
** and sides of the drawing's ink box, in the order ne nw se sw n s e w,
** and takes the first whose box covers no ink (with none clear, the
** drawing is made smaller to leave room for it beside the drawing, at
** the right or below, whichever keeps the larger scale); another place
** puts it at that corner or side of the drawing's ink.  The legend is
** part of the ink a page of CF_PAGE_INK is fitted around.  CF_PLACE_CENTER is INVALID_ARG.  frame: a thin frame on a
** background-filled box (default true). */
CF_API cf_status_t cf_figure_set_legend_place(cf_figure_t *fig,
                                              cf_place_t place, bool frame);

/* ---- zoom insets -------------------------------------------------------- */

/* A magnified view of a region of the data window, drawn again from the
** elements (not a bitmap) in a framed box, with the region framed in the
** main drawing and two connector lines from the region's frame to the
** inset's.  Labels are not repeated inside. */
typedef struct cf_inset {
    double region[4];   /* x0 y0 x1 y1, data units, x0 < x1, y0 < y1,
                           inside the figure's window */
    cf_place_t place;   /* CF_PLACE_AUTO: where the box covers no ink
                           and its connectors cross the least: a corner
                           or side of the drawing's ink box, or beside
                           the drawing (at its right, left, above or
                           below it: the drawing is made smaller to leave
                           room on a fixed page) when that crosses less;
                           else that corner or side of the drawing's
                           ink */
    bool beside;        /* place is a side (N, S, E, W): the inset goes
                           beside the drawing's ink, outside it (above,
                           below, right, left), not inside its edge */
    bool has_rect;      /* rect given: it overrides place and size */
    double rect[4];     /* x y w h, page bp from the top left */
    double scale;       /* magnification over the main drawing (> 0), or 0:
                           the inset is `size` bp wide */
    double size;        /* width in bp when scale is 0 (default: a third of
                           the page width) */
} cf_inset_t;

/* place CF_PLACE_AUTO, no rect, scale 0, size 0 (a third of the page). */
CF_API void cf_inset_init(cf_inset_t *inset);

/* Add an inset (copied).  The region is checked against the window when
** the figure is laid out: one outside it is INVALID_ARG then, naming the
** inset and the window. */
CF_API cf_status_t cf_figure_add_inset(cf_figure_t *fig,
                                       const cf_inset_t *inset);

/* ---- panels ------------------------------------------------------------- */

/* Panel sharing: the panels of a column use one x mapping (the same data
** x at the same page x: the union of their x windows over the narrowest
** of their page spans), the panels of a row one y mapping. */
enum {
    CF_PANELS_SHARE_X = 1u << 0,
    CF_PANELS_SHARE_Y = 1u << 1,
    CF_PANELS_NO_TITLES = 1u << 2    /* no automatic (a), (b), ... */
};

/* Split the page into rows x cols (1..8 each) cells of equal size, gap_bp
** apart, and make a panel figure for each, row by row, into out[rows *
** cols].  A panel is a figure of its cell's size that takes every
** cf_figure_* call (elements, window, fit, legends, insets); it belongs
** to fig (cf_figure_destroy(fig) releases it; never destroy a panel).
** Panels are titled (a), (b), ... at their top left unless
** CF_PANELS_NO_TITLES.  A figure is split once. */
CF_API cf_status_t cf_figure_add_panels(cf_figure_t *fig, int rows, int cols,
                                        double gap_bp, unsigned flags,
                                        cf_figure_t **out);

/* The title of a panel, in place of its automatic letter (label syntax;
** "" or NULL: none).  INVALID_ARG for a figure that is not a panel. */
CF_API cf_status_t cf_figure_set_panel_title(cf_figure_t *panel,
                                             const char *title);

#ifdef __cplusplus
}
#endif

#endif
