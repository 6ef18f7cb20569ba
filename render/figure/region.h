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

/* Ear clipping of the plane polygon q (2 doubles a vertex) through its
** vertices idx[0..m), counter-clockwise, no two consecutive ones equal:
** the triangles' corners (indices into q, 3 each, room for m - 2) into
** tri, *nt of them.  An ear is a vertex whose triangle turns
** counter-clockwise and holds (closed) none of the vertices left that do
** not (in a simple polygon a triangle that holds a vertex holds one of
** those); they are found in idx's order and cut off in the order found,
** each cut asking again only its two neighbours, so that the triangles
** stay near their vertices (a convex polygon is cut into a balanced tree
** of triangles, not a fan of slivers).  When no ear is left (the polygon
** crosses itself), the rest is the fan of its first vertex left, each
** triangle with its sign.  The triangles' winding numbers add up to the
** polygon's at every point, whatever the polygon (cutting off a triangle
** a b c takes exactly its winding off), so a simple polygon is tiled.
** False when out of memory. */
bool cf__ear_clip(const double *q, const size_t *idx, size_t m, size_t *tri,
                  size_t *nt);

/* The faces of the convex hull of p that face the viewer of fig's view:
** they cover the hull's image once.  *outline (cf_free) gets the indices
** of the hull's outline in the image, in order (*nout of them; 2: the
** points lie on one line, the segment between its ends; 1: they
** coincide; no triangles then). */
cf_status_t cf__region_hull(cf_figure_t *fig, const double *p, size_t n,
                            cf__tris_t *out, size_t **outline, size_t *nout);

/* The convex hull of p (n points, 3 doubles each) from the tetrahedron of
** points t4, which must not lie in one plane: its faces (3 indices into
** p each, counter-clockwise seen from outside) into *faces (cf_free),
** *nf of them.  A point at most eps beyond every face's plane (eps times
** the length of its normal) is taken as inside.  The faces come from
** Quickhull (each face keeps the points beyond it, the farthest added
** first), or, when a point's visible faces do not meet the rest of the
** hull in one loop of edges (nearly coplanar points), from adding the
** points one at a time, each against every face; slow (for tests): that
** one always.  False when out of memory. */
bool cf__hull3(const double *p, size_t n, const size_t t4[4], double eps,
               bool slow, size_t **faces, size_t *nf);

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
