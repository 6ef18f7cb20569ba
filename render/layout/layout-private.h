/*
** The layout layer (render/layout/): a figure's window and map to the
** page, its display list, label places, legends, insets, panels and the
** room beside the drawing, for the output layer above it.
*/
#ifndef CURVEFIG_RENDER_LAYOUT_PRIVATE_H
#define CURVEFIG_RENDER_LAYOUT_PRIVATE_H

#include "model.h"

/* ---- layout.c ----------------------------------------------------------- */

/* Whether layouts a and b map the data alike, page position aside. */
static inline bool
cf__layout_same_map(const cf__layout_t *a, const cf__layout_t *b)
{
    return a->xmin == b->xmin && a->xmax == b->xmax && a->ymin == b->ymin
        && a->ymax == b->ymax && a->sx == b->sx && a->sy == b->sy
        && a->ox == b->ox && a->oy == b->oy && a->tol == b->tol
        && a->clip == b->clip;
}

/* The pixel index v (a floor or a ceiling of a page coordinate times a
** raster's resolution) within [lo, hi]; NaN gives lo.  A box far off the
** page (a label's offset of 1e300 bp) has indices no int holds: the
** conversion of such a double is undefined, so every box is clamped
** before it is converted. */
static inline int
cf__pixel_within(double v, int lo, int hi)
{
    return v >= hi ? hi : v > lo ? (int)v : lo;
}

/* Compute the layout for the figure's page (errors go into fig). */
cf_status_t cf__figure_layout(cf_figure_t *fig, cf__layout_t *lay);
/* The display list of every element for a layout (automatic label places
** chosen first). */
cf_status_t cf__figure_build(cf_figure_t *fig, const cf__layout_t *lay,
                             cf__dl_t *dl);

/* The largest page side (bp): PDF's implementation limit (200 in,
** ISO 32000-1 Annex C), and near TeX's (16000 bp). */
#define CF__PAGE_MAX 14400.0

/* Whether a page cropped to the ink of dl, w x h bp, is at most
** CF__PAGE_MAX a side: else an error (in diag) naming the element whose
** ink lies farthest outside the drawing's page_w x page_h page (dl's
** coordinates are that page's, before the crop). */
cf_status_t cf__figure_check_size(const cf__dl_t *dl, double w, double h,
                                  double page_w, double page_h,
                                  cf_diag_t *diag);

/* Whether a display list on a page of w x h bp shows the figure: an error
** (in diag) when it draws nothing at all, and on a fixed page (not cropped
** to the ink) one naming the element whose ink sticks out farthest and by
** how much, unless the figure clips. */
cf_status_t cf__figure_check_page(const cf_figure_t *fig, const cf__dl_t *dl,
                                  double w, double h, bool fixed,
                                  cf_diag_t *diag);

/* ---- legend.c inset.c panel.c room.c ----------------------------------- */

/* The legend of the figure's entries, from the samples of the element
** groups drawn at ops [from, dl->count). */
cf_status_t cf__legend_draw(cf_figure_t *fig, const cf__layout_t *lay,
                            size_t from, cf__dl_t *dl);
/* Every inset: the elements drawn again in its box, frames, connectors
** (render/layout/inset.c), where render/layout/inset-place.c puts it. */
cf_status_t cf__insets_draw(cf_figure_t *fig, const cf__layout_t *lay,
                            cf__dl_t *dl);

/* ---- inset-place.c ------------------------------------------------------ */

/* Where an inset goes for a layout: the region's and the inset's page
** boxes (x0 y0 x1 y1), the magnification, and the two corners (0 top
** left, 1 top right, 2 bottom right, 3 bottom left) its connectors join
** (each a corner of the region's frame to the same of the inset's). */
typedef struct cf__inset_geom {
    double rb[4], ib[4], mag;
    int pair[2];
} cf__inset_geom_t;

/* Every inset's place for layout lay into g[fig->ninsets] (an inset
** placed automatically avoids the drawing less the labels placed
** automatically, and the insets before it; how:
** render/layout/inset-place.c).  A region outside the window is an
** error. */
cf_status_t cf__insets_place(cf_figure_t *fig, const cf__layout_t *lay,
                             cf__inset_geom_t *g);
/* What cf__inset_outline draws. */
enum {
    CF__INSET_LINES = 1u << 0,   /* the region's frame, the connectors */
    CF__INSET_FRAME = 1u << 1,   /* the inset's frame */
    CF__INSET_BOX = 1u << 2,     /* the inset's box, filled */
    CF__INSET_INK = CF__INSET_LINES | CF__INSET_BOX
};
/* Inset g's lines (what: CF__INSET_*) in the axes' colour into dl. */
cf_status_t cf__inset_outline(cf_figure_t *fig, const cf__inset_geom_t *g,
                              unsigned what, cf__dl_t *dl);
/* Every inset's ink for layout lay, as the labels must avoid it (frames,
** connectors, the box filled) into dl. */
cf_status_t cf__insets_ink(cf_figure_t *fig, const cf__layout_t *lay,
                           cf__dl_t *dl);
/* A new layout: the legend and the insets placed afresh. */
void cf__room_reset(cf_figure_t *fig);
/* Cell k of a figure split into panels: x y w h, page bp. */
void cf__panel_cell(const cf_figure_t *fig, int k, double cell[4]);
/* Make the panels' layouts agree on the shared axes (lays[rows * cols]). */
void cf__panels_share(const cf_figure_t *fig, cf__layout_t *lays);
/* The title of panel k (laid out at the label font size) into dl. */
cf_status_t cf__panel_title_draw(cf_figure_t *fig, int k,
                                 const cf__layout_t *lay, cf__dl_t *dl);
/* Where a w x h box goes beside the drawing whose ink is ops [from,
** dl->count) (laid out with lay; the raster holds all of dl): at place
** of the drawing's ink box, gap bp inside its edge (AUTO: the first of ne
** nw se sw n s e w covering no ink; with none, *band is set to a band at
** the right or below the ink box, and kept there while *band says so);
** its top left into at[2]. */
cf_status_t cf__room_find(cf_figure_t *fig, const cf__layout_t *lay,
                          const cf__dl_t *dl, size_t from, double w,
                          double h, cf_place_t place, double gap,
                          cf__room_band_t *band, double at[2]);
/* The top left of a w x h box at place (a corner or side) of box a
** (x0 y0 x1 y1), gap inside its edge. */
void cf__room_box_at(const double a[4], double w, double h,
                     cf_place_t place, double gap, double at[2]);

/* ---- place.c ------------------------------------------------------------ */

/* Choose the places of the labels placed CF_PLACE_AUTO for a layout, and
** note in the figure's warnings every label that lies on ink; a draft
** (a refit of the ink box, never the layout drawn) chooses the same
** places without looking for labels on ink, and is never reused for a
** layout drawn. */
cf_status_t cf__place_labels(cf_figure_t *fig, const cf__layout_t *lay,
                             bool draft);
/* The places chosen for the automatic labels, in order, into out[0 ..
** cap-1]; returns how many there are (the frames of an animation pass
** them on as fig->place_hint). */
size_t cf__place_chosen(cf_figure_t *fig, cf__auto_place_t *out,
                        size_t cap);
/* Forget the places chosen: the figure is laid out afresh. */
void cf__place_forget(cf_figure_t *fig);
/* Free the memory of the placement's rasters, kept between the placements
** of one layout's refits: once a layout is final its drawing needs it no
** more (and a next placement takes it afresh). */
void cf__place_release(cf_figure_t *fig);

#endif
