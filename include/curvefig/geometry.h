/*
** Planar geometry helpers for figures: the convex hull of a point set (the
** convex hull property of Bézier curves is a standard illustration).
*/
#ifndef CURVEFIG_GEOMETRY_H
#define CURVEFIG_GEOMETRY_H

#include "curvefig/bezier.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
** Convex hull of count points in the plane (x, y at pts[i * stride],
** pts[i * stride + 1]; stride >= 2), by Andrew's monotone chain.
** idx[0 .. *hull_count - 1] receives the indices of the hull's vertices in
** counter-clockwise order, starting with the lowest-x (then lowest-y)
** point.  Points inside the hull or on its edges are left out, and of
** repeated points only the one with the smallest index appears.  All points
** equal: one vertex; all on a line: its two ends.  idx needs room for count
** entries.  count >= 1; coordinates must be finite.
*/
CF_API cf_status_t cf_convex_hull_2d(const double *pts, size_t count,
                                     size_t stride, size_t *idx,
                                     size_t *hull_count, cf_diag_t *diag);

/* The hull of a planar Bézier curve's (Cartesian) control points, which
** contains the curve (also for rational curves: weights are positive).
** idx needs room for degree + 1 entries.  DIM_MISMATCH unless dim == 2. */
CF_API cf_status_t cf_bezier_hull(const cf_bezier_t *c, size_t *idx,
                                  size_t *hull_count, cf_diag_t *diag);

/*
** Check that count points of dim coordinates (point i at pts[i * stride])
** are finite.  NOT_FINITE names the first bad one: "<what> 3 has
** coordinate 2 = nan; coordinates must be finite", where `what` names the
** array ("point", "vertex").
*/
CF_API cf_status_t cf_check_finite_points(const double *pts, size_t count,
                                          size_t dim, size_t stride,
                                          const char *what, cf_diag_t *diag);

#ifdef __cplusplus
}
#endif

#endif
