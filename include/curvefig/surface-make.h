/*
** Surfaces built from curves and data (constructions on curvefig/surface.h):
** extrusion, ruled surfaces, surfaces of revolution, the exact quadrics and
** the torus as NURBS, and tensor-product interpolation and least-squares
** approximation of a grid of points.
**
** Every result is an ordinary B-spline or NURBS surface, exact where the
** construction is (no fitting), with the conventions of surface.h: grid
** P[i][j], i along u.
*/
#ifndef CURVEFIG_SURFACE_MAKE_H
#define CURVEFIG_SURFACE_MAKE_H

#include "curvefig/bspline.h"
#include "curvefig/interp.h"
#include "curvefig/surface.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Extrusion S(u, v) = C(u) + v d, v in [0, 1]: the curve's degree and
** knots in u, degree 1 with knots {0, 0, 1, 1} in v; d[dim] finite. */
CF_API cf_status_t cf_surface_extrude(const cf_bspline_t *curve,
                                      const double *d,
                                      cf_bspline_surface_t **out,
                                      cf_diag_t *diag);

/*
** Ruled surface between two curves of one dimension: S(u, v) =
** (1 - v) C1(u) + v C2(u) on their points, v in [0, 1], degree 1 in v.
** The curves are made compatible first: both taken to the domain [0, 1]
** (knots mapped affinely), the lower degree elevated, and each refined with
** the other's knots, so that row 0 is C1 and row 1 is C2 exactly.  For
** NURBS the combination is homogeneous (the lines v -> S(u, v) are still
** straight segments from C1(u) to C2(u); their speed depends on the
** weights).
*/
CF_API cf_status_t cf_surface_ruled(const cf_bspline_t *c1,
                                    const cf_bspline_t *c2,
                                    cf_bspline_surface_t **out,
                                    cf_diag_t *diag);

/*
** The bilinearly blended Coons patch of four polynomial boundary curves
** (INVALID_ARG for rational ones, whose patch is no NURBS surface), each
** taken on [0, 1] (knots mapped affinely): c0 = S(u, 0), c1 = S(u, 1),
** d0 = S(0, v), d1 = S(1, v);
**   S = (1 - v) c0(u) + v c1(u) + (1 - u) d0(v) + u d1(v)
**       - the bilinear interpolant of the four corners,
** exactly, as a B-spline surface (the two ruled surfaces and the bilinear
** one brought to common degrees and knots, then combined point by point).
** The corners must meet: c0(0) = d0(0), c0(1) = d1(0), c1(0) = d0(1),
** c1(1) = d1(1) within 1e-9 of their size (DEGENERATE naming them).
*/
CF_API cf_status_t cf_surface_coons(const cf_bspline_t *c0,
                                    const cf_bspline_t *c1,
                                    const cf_bspline_t *d0,
                                    const cf_bspline_t *d1,
                                    cf_bspline_surface_t **out,
                                    cf_diag_t *diag);

/*
** Surface of revolution (The NURBS Book §8.5, exact): the curve C (NURBS
** or polynomial, dim 3) turned about the axis through O[3] with direction
** A[3] (not zero) from angle a0 to a1 (radians, 0 < a1 - a0 <= 2 pi,
** counter-clockwise seen from the tip of A).  u runs round the axis (the
** quadratic rational arcs of cf_nurbs_arc, domain [0, 1]), v along the
** curve (its degree and knots).  A point of C on the axis stays put.
*/
CF_API cf_status_t cf_surface_revolve(const cf_bspline_t *curve,
                                      const double *O, const double *A,
                                      double a0, double a1,
                                      cf_bspline_surface_t **out,
                                      cf_diag_t *diag);

/* Exact NURBS quadrics and torus about the z axis through centre[3]
** (r, R, h > 0), u round the axis on [0, 1]:
**   sphere   |x - centre| = r; v from the south pole (v = 0) to the north
**            pole (v = 1) along a half circle;
**   cylinder radius r, from z = c_z to c_z + h (v along z);
**   cone     apex at centre + (0, 0, h), base circle of radius r in
**            z = c_z (v from the base to the apex);
**   torus    the circle of radius r (tube) about the circle of radius R
**            (R > r) in z = c_z; v round the tube. */
CF_API cf_status_t cf_nurbs_sphere(const double *centre, double r,
                                   cf_bspline_surface_t **out,
                                   cf_diag_t *diag);
CF_API cf_status_t cf_nurbs_cylinder(const double *centre, double r,
                                     double h, cf_bspline_surface_t **out,
                                     cf_diag_t *diag);
CF_API cf_status_t cf_nurbs_cone(const double *centre, double r, double h,
                                 cf_bspline_surface_t **out,
                                 cf_diag_t *diag);
CF_API cf_status_t cf_nurbs_torus(const double *centre, double R, double r,
                                  cf_bspline_surface_t **out,
                                  cf_diag_t *diag);

/*
** Interpolation of a grid Q[k][l] of nu x nv points (The NURBS Book §9.2.5):
** the parameters of each column (opt->param, cf_interp_parameters) are
** averaged over the columns to give u_k, those of each row over the rows to
** give v_l; then every column is interpolated in u with the parameters u_k
** by cf_interpolate (opt->method and opt->degree: every method whose knots
** depend on the parameters only — NATURAL, NOT_A_KNOT, GLOBAL,
** CATMULL_ROM; not CLAMPED (tangents) nor closed ones), which gives the
** same knots for every column, and every row of the result in v with v_l.
** S(u_k, v_l) = Q[k][l].  opt->params, tangents and closed must be unset
** (INVALID_ARG).  params (may be NULL) receives u_0..u_{nu-1} then
** v_0..v_{nv-1}.
*/
CF_API cf_status_t cf_interpolate_surface(size_t dim, const double *points,
                                          size_t nu, size_t nv,
                                          const cf_interp_options_t *opt,
                                          cf_bspline_surface_t **out,
                                          double *params, cf_diag_t *diag);

/*
** Least-squares approximation of the grid by a surface of cu x cv control
** points: the parameters as above, then cf_approximate_lsq on the columns
** (cu control points, ends fixed when fix_ends) and on the rows of the
** result (cv).  *residual (may be NULL) receives the largest distance
** |S(u_k, v_l) - Q[k][l]|.
*/
CF_API cf_status_t cf_approximate_surface(size_t dim, const double *points,
                                          size_t nu, size_t nv, size_t cu,
                                          size_t cv,
                                          const cf_interp_options_t *opt,
                                          bool fix_ends,
                                          cf_bspline_surface_t **out,
                                          double *residual, cf_diag_t *diag);

#ifdef __cplusplus
}
#endif

#endif
