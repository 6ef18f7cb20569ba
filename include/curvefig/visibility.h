/*
** 3D views of curves and surfaces: hidden lines, silhouettes and facets
** ordered for painting.
**
** A view (cf_view_t of curvefig/view.h, included here: its conventions,
** the projection of points and the exact projection of curves) maps R^3
** to the plane of the figure.  A scene (cf_scene_t) is a view plus
** surfaces (Bézier, B-spline/NURBS, triangular Bézier) and a tolerance; it
** answers, on the exact surfaces:
**
**   - which parts of a 3D curve are visible and which hidden
**     (cf_scene_curve_visibility), and whether a point is
**     (cf_scene_point_visible);
**   - the silhouette (contour) of a surface, traced in (u, v) and in space
**     as cubic pieces with a measured error (cf_scene_silhouette);
**   - facets for shading, in painting order (cf_scene_facets).
**
** ---- Scenes --------------------------------------------------------------
**
** cf_scene_create copies the view and the tolerance; each add function
** copies its surface (a B-spline surface is decomposed into its Bézier
** patches), so the caller may destroy the surfaces at once.  Surfaces are
** numbered 0, 1, 2 ... in the order added; the number is the `surface`
** field of the results.  Every surface must be in R^3, with finite
** coordinates, and under a perspective view its control points must be in
** front of the eye (D - z >= D / 1000): else the add function fails with
** a message naming the surface and the point.
**
** Tolerance.  tol > 0 is a length in the units of the image (the figure's
** units: for a perspective view, measured in the plane of the target).
** It bounds:
**   - the image distance between a reported split point of a curve and the
**     true change of visibility;
**   - the image distance between a silhouette piece and the exact contour
**     (also reported in space);
**   - the deviation of a facet from the surface, in space.
** A tolerance that is zero, negative, not finite, or below 1e-12 of the
** scene's size (the box of the control points; checked as surfaces are
** added) is refused with CF_STATUS_INVALID_ARG ("tolerance 0 must be
** positive and finite").
**
** Exactness.  Visibility is decided on the exact surfaces: each patch is
** subdivided (de Casteljau on its control net, projected) into pieces kept
** in a 2D box tree: pieces that are nearly bilinear and whose image does
** not fold, or, where it folds (near a silhouette), pieces flat within
** tol / 4 or smaller than tol.  A ray from a point towards the eye is
** tested against the pieces whose image box contains the point's image
** (and the ranges of their control points across their two sides: outside
** them no point of the piece can be) and whose depth range reaches in
** front of it, by Newton's method on the exact patch from the piece's
** middle (and its corners, for a folding piece, or where Newton from the
** middle ends off the patch); a folding piece smaller than tol where Newton finds nothing hides the
** point if it lies wholly in front of it.  No facets, no raster.  Along a
** curve, visibility is sampled at image steps of at most 16 tol (and at
** least 64 samples per Bézier piece), and every change is located by
** bisection to tol.  The part of a curve between two visible samples is
** certified: the box of its control points in view space meets no piece
** in front of it, or it is halved down to image steps of tol, so no
** occlusion wider than tol is missed.  For a curve on a surface
** (cf_vis_on_t with its (u, v) curve) the pieces of that surface whose
** parameters meet the box of the part's (u, v) (the (u, v) curve's
** control points there), or that box widened by the widest of those
** pieces, are not counted when, offset 0, none of them folds and all turn
** the same way in the image (the surface is one-to-one onto its image
** around the part, so it cannot hide it there); any other piece must lie
** behind the part's box.  With offset > 0 (a curve only near its
** surface) and for silhouettes, those pieces of the sheet are not counted
** at all: a fold of that sheet within them is seen at the samples only
** (16 tol).  A curve said to lie on a surface without its (u, v) curve is
** not certified: an occlusion shorter than 16 tol can be missed.
**
** Self-occlusion.  A point of a curve drawn on a surface (an iso-line, a
** boundary, a silhouette) is not hidden by the surface at itself: hits
** within depth tol of the point are ignored, and when the caller says
** which surface and which (u, v) the curve lies on (cf_vis_on_t), hits on
** that surface within tol (in space) of that point are ignored too, which
** keeps a curve visible along a grazing view.
**
** Errors.  NULL where an object is required, a zero count, a tolerance
** that is not positive and finite: CF_STATUS_INVALID_ARG.  A NaN or
** infinite angle, distance, coordinate or parameter: CF_STATUS_NOT_FINITE.
** A curve or surface not in R^3: CF_STATUS_DIM_MISMATCH.  A degenerate
** patch (all its control points within 1e-12 of the scene's size of one
** point) is refused by the add functions: CF_STATUS_DEGENERATE
** ("surface 2: patch (1, 0) is degenerate: all its points coincide").
** The message always names the argument (and surface, patch, point).
**
** Ownership.  Objects (cf_scene_t, cf_visibility_t, cf_silhouette_t,
** cf_facets_t) are released with their destroy function (NULL is
** harmless); the arrays inside them belong to them.  A scene is read-only
** after its last add: its query functions may run concurrently from
** several threads (each allocates its own work space).
*/
#ifndef CURVEFIG_VISIBILITY_H
#define CURVEFIG_VISIBILITY_H

#include "curvefig/bezier.h"
#include "curvefig/bspline.h"
#include "curvefig/core.h"
#include "curvefig/surface-triangle.h"
#include "curvefig/surface.h"
#include "curvefig/view.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ==== Scenes ============================================================ */

typedef struct cf_scene cf_scene_t;

/* A scene for a view (copied) and a tolerance (above). */
CF_API cf_status_t cf_scene_create(const cf_view_t *view, double tol,
                                   cf_scene_t **out, cf_diag_t *diag);
CF_API void cf_scene_destroy(cf_scene_t *scene);

/* Add a surface (copied; decomposed into Bézier patches); *id (may be
** NULL) receives its number. */
CF_API cf_status_t cf_scene_add_bezier(cf_scene_t *scene,
                                       const cf_bezier_surface_t *s,
                                       size_t *id, cf_diag_t *diag);
CF_API cf_status_t cf_scene_add_bspline(cf_scene_t *scene,
                                        const cf_bspline_surface_t *s,
                                        size_t *id, cf_diag_t *diag);
CF_API cf_status_t cf_scene_add_triangle(cf_scene_t *scene,
                                         const cf_bezier_triangle_t *t,
                                         size_t *id, cf_diag_t *diag);

/* Queries. */
CF_API size_t cf_scene_count(const cf_scene_t *scene);     /* surfaces */
CF_API const cf_view_t *cf_scene_view(const cf_scene_t *scene);
CF_API double cf_scene_tolerance(const cf_scene_t *scene);

/* ==== Visibility ======================================================== */

/* Where a curve or point lies on a surface of the scene, so that surface
** does not hide it at itself.  surface is the number from the add
** function.  For a curve, the (u, v) curve (uv_bezier or uv_bspline, one
** of them, in R^2, on the parameter domain of the curve: (u, v)(t) is
** where the curve's point at t lies; parameters of the surface as given
** to the add function, the B-spline's knot domain or [0, 1]^2, or (u, v)
** of a triangular patch).  For a point, uv[2].  offset >= 0 is how far
** (in space) the curve or point may be from the surface: 0 for exact
** curves (iso-lines, boundaries), a silhouette piece's error_space.  A
** NULL cf_vis_on_t, or uv_bezier and uv_bspline both NULL, means "not
** known": the depth rule alone then keeps the curve from hiding itself.
** Zero-initialise the struct (fields may be added at its end). */
typedef struct cf_vis_on {
    size_t surface;
    const cf_bezier_t *uv_bezier;
    const cf_bspline_t *uv_bspline;
    double uv[2];
    double offset;
} cf_vis_on_t;

/* One interval [t0, t1] of a curve's parameter, visible or hidden;
** occluder is the number of a surface that hides the interval's middle
** (SIZE_MAX when visible). */
typedef struct cf_vis_interval {
    double t0, t1;
    bool visible;
    size_t occluder;
} cf_vis_interval_t;

/* The intervals cover the curve's domain in order, consecutive ones
** differ in visibility and share their ends (the split points). */
typedef struct cf_visibility {
    size_t n;
    cf_vis_interval_t *items;
} cf_visibility_t;

CF_API void cf_visibility_destroy(cf_visibility_t *vis);

/* Visibility of a 3D curve (polynomial or rational) in the scene; on
** (may be NULL) says the surface and (u, v) curve it lies on.  A part of
** the curve at or behind the eye (perspective) is hidden. */
CF_API cf_status_t cf_scene_curve_visibility(const cf_scene_t *scene,
                                             const cf_bezier_t *c,
                                             const cf_vis_on_t *on,
                                             cf_visibility_t **out,
                                             cf_diag_t *diag);
CF_API cf_status_t cf_scene_bspline_visibility(const cf_scene_t *scene,
                                               const cf_bspline_t *c,
                                               const cf_vis_on_t *on,
                                               cf_visibility_t **out,
                                               cf_diag_t *diag);

/* Whether the point p[3] is visible (no surface between it and the eye,
** beyond the depth tolerance); occluder (may be NULL) receives a surface
** that hides it, or SIZE_MAX. */
CF_API cf_status_t cf_scene_point_visible(const cf_scene_t *scene,
                                          const double *p,
                                          const cf_vis_on_t *on,
                                          bool *visible, size_t *occluder,
                                          cf_diag_t *diag);

/* ==== Silhouettes ======================================================= */

/*
** The contour of a surface: the points where the normal is perpendicular
** to the line of sight, n . d = 0 (orthographic) or n . (E - S) = 0
** (perspective), i.e. det[H, H_u, H_v, e] = 0 on the homogeneous surface H
** and the homogeneous eye e ((d, 0) for an orthographic view), so rational
** surfaces are exact too.  Patch boundaries are not part of it (draw them
** as boundaries); a contour that runs along a boundary is reported where
** it crosses the patch, which includes its ends.
**
** It is traced on each Bézier patch: the signs of (S_u x S_v) . d (or
** . (E - S)) on a 16 x 16 grid of the patch (triangles of it), the roots
** on the grid's edges by bisection on the exact surface, joined into
** chains across the cells of the patch (chains of neighbouring patches
** meet at their ends), and each chain cut into pieces fitted by cubic
** Hermite curves (in (u, v), in space and in the image) from the exact
** points and tangents.  Each piece's error is measured against the exact
** contour at 16 points (Newton from the piece's point to the contour, the
** distance between them): in space (error_space) and in the image
** (error_image), and a piece is halved until both are at most tol / 4;
** max_error is the largest error_image returned.  A piece that cannot
** reach that in 30 halvings (or past a bound on the work, 400,000 fits),
** or whose middle's contour point does not split it, is kept and
** converged is false; one that cannot be fitted at all (no tangent) with
** its ends within tol / 4 of each other is left out (converged false).  A contour loop smaller than a cell of
** the grid (1/16 of a patch) can be missed.
*/
typedef struct cf_silhouette_piece {
    size_t surface;        /* number of the surface */
    size_t chain;          /* pieces of one chain are consecutive */
    double uv[8];          /* cubic in (u, v): 4 points (u v) */
    double space[12];      /* cubic in space: 4 points (x y z) */
    double image[8];       /* cubic in the image: 4 points (x y) */
    double error_space;    /* measured distance to the contour, space */
    double error_image;    /* the same in the image */
} cf_silhouette_piece_t;

typedef struct cf_silhouette {
    size_t n;                        /* pieces */
    cf_silhouette_piece_t *items;
    size_t nchains;
    bool *closed;                    /* nchains flags: chain is a loop */
    double max_error;                /* largest error_image */
    bool converged;
} cf_silhouette_t;

CF_API void cf_silhouette_destroy(cf_silhouette_t *sil);

/* The silhouette of surface number `surface` of the scene (SIZE_MAX: of
** every surface).  An empty silhouette (n = 0) is a valid answer (a
** patch seen face-on). */
CF_API cf_status_t cf_scene_silhouette(const cf_scene_t *scene,
                                       size_t surface,
                                       cf_silhouette_t **out,
                                       cf_diag_t *diag);

/*
** The visibility of silhouette piece `piece` of sil (made by this scene):
** intervals of its parameter [0, 1], each point classified at the exact
** contour point nearest the piece's (Newton from its (u, v)), so the
** sheet it lies on never hides it, while a fold of the same surface in
** front of it does (where the contour runs behind the surface).  Prefer it
** to cf_scene_curve_visibility with a cf_vis_on_t for silhouettes: that
** one must ignore the sheet within 2 error_space of the line of sight, and
** near the cusps of a contour that lets a hidden stretch pass as visible.
*/
CF_API cf_status_t cf_scene_silhouette_visibility(const cf_scene_t *scene,
                                                  const cf_silhouette_t *sil,
                                                  size_t piece,
                                                  cf_visibility_t **out,
                                                  cf_diag_t *diag);

/* ==== Facets ============================================================ */

/*
** Triangles for shading, in painting order: a facet never hides a facet
** drawn before it.  Each patch is subdivided until its triangles deviate
** from the surface by at most tol (in space; cf_scene_facets_tol below);
** facets whose images overlap are ordered by the depths of their planes
** over the overlap, and those that must be painted in a cycle (cyclic
** overlaps, interpenetrations) by a BSP tree built on them (facets split
** by the planes they cross), traversed back to front from the eye.  A
** facet split by the tree keeps
** its surface, its (u, v) and interpolated normals.  Triangles of zero
** area (the pole of a sphere) are left out.
*/
typedef struct cf_facet {
    double p[9];        /* corners in space (x y z, three times) */
    double image[6];    /* their images */
    double normal[9];   /* unit surface normals at the corners (exact
                           where the surface has one, else the facet's) */
    double uv[6];       /* parameters of the corners on their patch's
                           surface (as in cf_vis_on_t) */
    double depth;       /* depth of the centroid */
    size_t surface;
    bool front;         /* the facet's side towards the viewer is the
                           surface's normal side (Su x Sv) */
} cf_facet_t;

typedef struct cf_facets {
    size_t n;
    cf_facet_t *items;  /* painting order: back first */
    size_t splits;      /* facets cut by the BSP tree */
    double deviation;   /* bound of the distance from the surfaces, by
                           the control nets (exact for polynomial
                           patches; rational ones up to their weights'
                           variation) */
} cf_facets_t;

CF_API void cf_facets_destroy(cf_facets_t *facets);

/* The facets of every surface of the scene, in painting order, within the
** scene's tolerance. */
CF_API cf_status_t cf_scene_facets(const cf_scene_t *scene,
                                   cf_facets_t **out, cf_diag_t *diag);

/*
** The same within tol (> 0, in space; a coarser one than the lines' is
** usual for shading).  Each patch is cut into a uniform grid of 2^a x 2^b
** quads (2^a x 2^a triangles for a triangular patch), the levels found by
** halving its control net until every piece is within tol of the two
** triangles of its corners (net against the bilinear map of the corners,
** plus a quarter of the twist), the same levels for every patch of one
** surface so that neighbours share their edges; at most 2^7 per
** direction (then deviation says what was reached).  More than
** 1,000,000 facets before ordering (about half a gigabyte) is refused
** (INVALID_ARG, naming the count: a larger tolerance is needed).  Only
** facets whose image boxes overlap are compared (a grid of the boxes), so
** the ordering costs about linear time for facets of similar size: 2 x
** 10^5 facets of a torus take about a second (bench/bench_facet_order.c).
*/
CF_API cf_status_t cf_scene_facets_tol(const cf_scene_t *scene, double tol,
                                       cf_facets_t **out, cf_diag_t *diag);

#ifdef __cplusplus
}
#endif

#endif
