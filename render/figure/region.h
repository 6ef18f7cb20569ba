/*
** Filled regions in space (curvefig/figure3d.h): a filled polygon or a
** convex hull given points in R^3, cut into triangles in space
** (region-tri.c), each triangle's seen and hidden parts found against the
** figure's scene (region-vis.c), drawn by the region element
** (el-region.c).
*/
#ifndef CURVEFIG_RENDER_REGION_H
#define CURVEFIG_RENDER_REGION_H

#include "model.h"

/* Triangles in space, 9 doubles each (three corners x y z). */
typedef struct cf__tris {
    double *p;
    size_t n, cap;
} cf__tris_t;

cf_status_t cf__tris_add(cf__tris_t *t, const double *a, const double *b,
                         const double *c);
void cf__tris_fini(cf__tris_t *t);

/* A polygon's triangles: *planar says whether its points lie in one plane
** (within 1e-9 of its size); the triangles are ear-clipped in that plane
** (in the plane of Newell's normal when it is not planar), or, when the
** polygon crosses itself, the fan of its first vertex (each triangle then
** counts with its sign: the nonzero rule of the polygon).  Error (naming
** what) when the points coincide or lie on one line. */
cf_status_t cf__region_polygon(cf_figure_t *fig, const double *p, size_t n,
                               const char *what, cf__tris_t *out,
                               bool *planar);

/* The faces of the convex hull of p that face the viewer of fig's view:
** they cover the hull's image once.  *outline (cf_free) gets the indices
** of the hull's outline in the image, in order (*nout of them; 2: the
** points lie on one line, the segment between its ends; 1: they
** coincide; no triangles then). */
cf_status_t cf__region_hull(cf_figure_t *fig, const double *p, size_t n,
                            cf__tris_t *out, size_t **outline, size_t *nout);

/* Polygons in the image (data units), each with a sign kept or not. */
typedef struct cf__polys {
    double *xy;              /* the vertices, 2 doubles each */
    size_t nxy, xycap;
    size_t *len;             /* vertices of each polygon */
    size_t n, lcap;
} cf__polys_t;

void cf__polys_fini(cf__polys_t *p);

/* How a region is cut: cells at most `cell` long in the image, change
** points bisected to `split`; positive: every polygon turns counter-
** clockwise in the image (else as its triangle); window (xmin xmax ymin
** ymax, or NULL): points more than two cells outside it are not asked
** (taken as seen: no cell of them shows). */
typedef struct cf__region_grid {
    double cell, split;
    bool positive;
    const double *window;
} cf__region_grid_t;

/* The parts of the triangles tris that are seen (into *seen) and hidden
** (into *hidden) in scene sc (NULL: all seen), as polygons in the image:
** each triangle is cut into a grid of cells (g), a cell whose corners
** agree is whole, a run of whole cells of one kind along a row is one
** polygon, and a cell whose corners differ is cut straight between the
** points where its edges change (a triangle larger than 1024 cells
** is cut in four first; a triangle outside the window is taken whole).
** *queries counts the points asked. */
cf_status_t cf__region_parts(cf_figure_t *fig, const struct cf_scene *sc,
                             const cf__tris_t *tris,
                             const cf__region_grid_t *g, cf__polys_t *seen,
                             cf__polys_t *hidden, size_t *queries);

/* For tests (el-region.c): the triangles in space of element i of fig
** when it is a region in space, its hidden mode and the opacity of its
** fill; false otherwise. */
bool cf__region_triangles(const cf_figure_t *fig, size_t i,
                          const cf__tris_t **tris, cf_hidden_t *hidden,
                          double *opacity);

#endif
