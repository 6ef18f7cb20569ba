/*
** The rasters of the label placement (render/layout/place.c): the page's
** ink, one element's and a label's mask, w x h bytes each at 2 pixels a
** bp (coarser for large pages), in the figure's memory kept from one
** placement to the next and emptied only where painted; the sums of the
** page's raster over a label's candidates; what is read of them.
** Drawing into them is the measuring seam's (render/backends/measure.h).
*/
#ifndef CURVEFIG_RENDER_LAYOUT_PLACE_RASTER_H
#define CURVEFIG_RENDER_LAYOUT_PLACE_RASTER_H

#include <stdint.h>

#include "layout-private.h"
#include "measure.h"

#define CF__PLACE_HIT 127     /* a pixel inked more than half */

/* Sums of the page's raster over a pixel box b (i0 j0 i1 j1): at[(j -
** j0) * (i1 - i0 + 1) + i - i0] the sum of the pixels (i', j') with i0
** <= i' < i and j0 <= j' < j (the first row and column zero). */
typedef struct cf__place_sums {
    uint32_t *at;
    size_t cap;
    int b[4];
} cf__place_sums_t;

typedef struct cf__place_raster {
    cf__raster_t img, one;   /* the page's ink; one element's */
    unsigned char *mask;     /* a label's pixels, laid out as one's */
    bool draft;              /* no search for labels on ink */
    double res;
    cf__dl_t dl;
    cf__place_sums_t sums;   /* of img, for one label's candidates */
    unsigned char *rows;     /* the rows of img read, when every label is
                                placed by hand (read_box); NULL: all */
} cf__place_raster_t;

/* The geometry of the page's rasters (their memory:
** cf__place_raster_memory). */
void cf__place_raster_open(cf_figure_t *fig, cf__place_raster_t *r);
/* The three rasters of the page, w x h each, in the figure's memory kept
** from the last placement (a layout places the labels once per refit of
** its ink box; fresh pages of memory for each would cost more than the
** painting).  The page's raster comes with ready rows (measure.h): a row
** is emptied when it is first painted or read (cf__raster_ready), once
** for all the placements of the memory, as cf__place_raster_close
** empties again what a placement painted.  Most rows of a page whose
** labels are all placed by hand are never used: clearing the raster
** whole had been a tenth of a figure's time, most of it the system's
** fresh pages.  The other two need no clearing: every pixel read of them
** is written first (place.c: check_label, what_is_under). */
cf_status_t cf__place_raster_memory(cf_figure_t *fig,
                                    cf__place_raster_t *r);
/* The page's raster made empty again for the next placement; the rest
** freed. */
void cf__place_raster_close(cf_figure_t *fig, cf__place_raster_t *r);

/* The pixel box cf__place_ink sums for page box b (x0 y0 x1 y1), cut to
** the raster: px (i0 j0 i1 j1); its whole extent, off the page too, as
** doubles into whole. */
void cf__place_ink_pixels(const cf__raster_t *img, double res,
                          const double b[4], int px[4], double whole[4]);
/* The sums of img over the pixel box b (cut to the raster) into s; -1
** out of memory. */
int cf__place_sums(cf__place_sums_t *s, const cf__raster_t *img,
                   const int b[4]);
/* Ink in the page box x0 y0 x1 y1 (bp) of the page's raster, in bp^2 of
** full ink; pixels off the page count as full ink.  The pixels are
** summed as whole numbers (exact in a double), from r->sums when they
** hold them. */
double cf__place_ink(cf__place_raster_t *r, const double b[4]);

/* Pixels inked more than half both in one and in b (laid out as one),
** within the pixel box px (x0 y0 x1 y1; NULL: everywhere). */
long cf__place_common(const cf__raster_t *one, const unsigned char *b,
                      const int *px);
/* The label just painted into r->one within the pixel box px (none of
** it beyond) added to the page's raster, when no pixel of it lies on a
** pixel of ink: painted over empty pixels, its pixels are those it
** leaves in r->one, and where it left r->one empty, painting it would
** leave the raster as it is (each paint rounds v + a c (255 - v) to the
** nearest byte: under half over 0, then under half over v).  False
** (nothing changed) when some pixel of it lies on ink. */
bool cf__place_add_apart(cf__place_raster_t *r, const int px[4]);

/* The rows of r->img that page box b (bp) takes, as read_box takes a
** box's pixels (a pixel more each way), marked in r->rows. */
void cf__place_mark_rows(cf__place_raster_t *r, const double b[4]);

#endif
