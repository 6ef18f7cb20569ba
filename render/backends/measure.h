/*
** The measuring seam: every question the layout asks about ink — the ink
** box of some operations of a display list, and a coarse coverage raster
** of the page's ink for label places, collisions and the room of legends
** and insets — is answered here, from the display list alone.  Nothing
** that calls these functions knows how the answer is drawn
** (docs/library.md, "Measuring ink").
*/
#ifndef CURVEFIG_RENDER_MEASURE_H
#define CURVEFIG_RENDER_MEASURE_H

#include "dlist.h"

/* A coverage raster: w x h pixels of one byte (0 no ink, 255 covered
** wholly), row j at px + j * stride; pixel (i, j) is the page box of
** side 1 / res bp whose top left is (ox + i / res, oy + j / res). */
typedef struct cf__raster {
    unsigned char *px;
    int w, h, stride;
    double res, ox, oy;
    void *impl;               /* the drawing's own state */
    /* a pixel box (i0 j0 i1 j1; empty: i1 <= i0) holding every pixel
    ** painted since it was set empty (a raster opened sets it so): what
    ** a user keeping the pixels for another use must make empty again */
    int dirty[4];
    /* whether a polygon painted since this was last set false reached
    ** beyond the pixel box it was painted within (a raster opened sets
    ** it false) */
    bool cut;
    /* whether every ink drawn counts whole, whatever its opacity (a
    ** label's own footprint: a faded label on a line is as unreadable as
    ** any; render/layout/place.c) */
    bool solid;
    /* NULL, or one byte a row: only the rows j with rows[j] != 0 are
    ** painted (cf__poly_paint), each as it comes out painting all */
    const unsigned char *rows;
    /* NULL (every row empty or as painted), or one byte a row: a row j
    ** with ready[j] == 0 holds anything, and is made empty where it is
    ** first painted (cf__raster_paint_in) or read (cf__raster_ready): a
    ** raster read near a few labels only need not clear its memory whole,
    ** nor bring in the system's fresh pages for it */
    unsigned char *ready;
} cf__raster_t;

/* A raster of the page box (ox, oy) .. (ox + w / res, oy + h / res),
** empty; 0, or -1 out of memory (r then closed). */
int cf__raster_open(cf__raster_t *r, int w, int h, double res, double ox,
                    double oy);
void cf__raster_close(cf__raster_t *r);
/* The pixels of the pixel box b (i0 j0 i1 j1, cut to the raster; NULL:
** all, and the dirty box then empty) made empty (those of rows not
** ready are left: they are emptied when they are used). */
void cf__raster_clear(cf__raster_t *r, const int *b);
/* The rows j0 <= j < j1 (cut to the raster) of a raster with ready
** rows made ready to be read (emptied unless ready already); painted
** rows are made ready by the painting, the rows left out (rows) are
** not. */
void cf__raster_ready(cf__raster_t *r, int j0, int j1);
/* Ops [from, to) of dl painted over the raster: a paint of coverage c
** times its colour's alpha and opacity a over a pixel's v gives
** v + a c (1 - v); 0, or -1 out of memory. */
int cf__raster_paint(cf__raster_t *r, const cf__dl_t *dl, size_t from,
                     size_t to);
/* The same within the pixel box b (i0 j0 i1 j1) only: its pixels come out
** as cf__raster_paint's, the others are left as they are. */
int cf__raster_paint_in(cf__raster_t *r, const cf__dl_t *dl, size_t from,
                        size_t to, const int b[4]);

/* The ink box (page bp: x0 y0 x1 y1, empty: x1 <= x0) of ops [from, to)
** of dl; 0, or -1 out of memory. */
int cf__dl_ink(const cf__dl_t *dl, size_t from, size_t to, double ink[4]);

#endif
