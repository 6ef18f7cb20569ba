/*
** The rasterizer of the measuring seam (render/backends/measure.c): paths of a
** display list turned into polygons — curves and arcs flattened to a
** tolerance, strokes as the union of a quadrilateral a segment with their
** joins and caps, all wound alike — and polygons turned into coverage
** (anti-aliased: 4 sub-scanlines a pixel, exact coverage along each) or
** into their bounding box.  Plain C without any library, the same in the
** tool and in the browser module.
*/
#ifndef CURVEFIG_RENDER_RASTER_H
#define CURVEFIG_RENDER_RASTER_H

#include "dlist.h"

typedef struct cf__edge {
    double x0, y0, x1, y1;    /* y0 < y1 */
    double dxdy;
    int dir;                  /* +1 drawn downwards, -1 upwards */
} cf__edge_t;

/* A polygon: edges, the box of every point added (box[2] < box[0]:
** none) and whether an allocation or a coordinate failed. */
typedef struct cf__poly {
    cf__edge_t *e;
    size_t n, cap;
    double box[4];
    bool failed;
    bool box_only;            /* only the box is wanted (an ink box): no
                                 edges are kept (cf__poly_reset keeps
                                 this) */
    void *scratch;            /* cf__poly_paint's, kept for the next */
    size_t scratch_size;
} cf__poly_t;

/* Where a path goes: device = page * scale + (dx, dy); curves and arcs
** flattened to within tol device units. */
typedef struct cf__xform {
    double scale, dx, dy, tol;
} cf__xform_t;

/* How a path is stroked (in page units, like the display list). */
typedef struct cf__pen {
    double width;
    cf__cap_t cap;
    cf__join_t join;
    const double *dash;
    size_t ndash;
} cf__pen_t;

void cf__poly_init(cf__poly_t *pl);
void cf__poly_free(cf__poly_t *pl);
/* Empty it again (keeps the memory). */
void cf__poly_reset(cf__poly_t *pl);

/* The inside of path p (each subpath closed) added to pl. */
void cf__poly_fill(cf__poly_t *pl, const cf__path_t *p, const cf__xform_t *m);
/* The stroke of path p with pen pen added to pl; its dashes as the pen's
** pattern, unless cf__pen_solid: then solid, and *coverage (when not
** NULL) the part of it the pattern inks, by which the caller weighs it
** (1 for a stroke as the pen says). */
void cf__poly_stroke(cf__poly_t *pl, const cf__path_t *p,
                     const cf__xform_t *m, const cf__pen_t *pen,
                     double *coverage);
/* Whether a dashed pen strokes p solid: its pattern's period under m is
** below the flattening tolerance (cairo draws such a pattern as one of
** the same coverage at that period), or p would take more than
** CF__DASH_MAX dashes (a path far off the page, or a fine pattern along a
** long one: no raster or ink box is worth that work).  *coverage: the
** part of the line the pattern inks, cairo's estimate (round caps add a
** quarter disc's worth); 1 when the pen is solid anyway. */
bool cf__pen_solid(const cf__path_t *p, const cf__xform_t *m,
                   const cf__pen_t *pen, double *coverage);
#define CF__DASH_MAX 100000.0


/* The nonzero (evenodd: even-odd) coverage of pl times alpha painted over
** the A8 pixels px (row j at px + j * stride), within the pixel box
** clip (i0 j0 i1 j1, 0 <= i0); only the rows j with rows[j] != 0 when
** rows is not NULL (each as it comes out painting all: what a row's
** coverage depends on, the order of the edges along it, is followed
** through the rows left out); -1 out of memory. */
int cf__poly_paint(cf__poly_t *pl, unsigned char *px, int stride,
                   const int clip[4], double alpha, bool evenodd,
                   const unsigned char *rows);

#endif
