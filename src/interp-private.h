/*
** Internals shared by interp.c (checks, parameters, chapter-4 cubics,
** dispatch) and interp-spline.c (the spline constructions).
*/
#ifndef CURVEFIG_INTERP_PRIVATE_H
#define CURVEFIG_INTERP_PRIVATE_H

#include "curvefig/interp.h"
#include "core-private.h"

/*
** The constructions below get checked input: points finite, count large
** enough for the method, u[] strictly increasing (count values, or count + 1
** when closed), tangents finite (or NULL).
*/

/* NATURAL / CLAMPED: cubic with knots at u; an end with a tangent (d0 or
** d1 non-NULL) is clamped, an end without one has C'' = 0. */
cf_status_t cf__interp_cubic_ends(size_t dim, const double *points,
                                  size_t count, const double *u,
                                  const double *d0, const double *d1,
                                  cf_bspline_t **out, cf_diag_t *diag);

/* NOT_A_KNOT, count >= 4. */
cf_status_t cf__interp_not_a_knot(size_t dim, const double *points,
                                  size_t count, const double *u,
                                  cf_bspline_t **out, cf_diag_t *diag);

/* GLOBAL of degree p with optional end derivatives (count + #derivs >=
** p + 1). */
cf_status_t cf__interp_global(size_t dim, const double *points, size_t count,
                              const double *u, int p, const double *d0,
                              const double *d1, cf_bspline_t **out,
                              cf_diag_t *diag);

/* PERIODIC: count >= 3 distinct points, u[count + 1]. */
cf_status_t cf__interp_periodic(size_t dim, const double *points,
                                size_t count, const double *u,
                                cf_bspline_t **out, cf_diag_t *diag);

/* CATMULL_ROM: open (u[count]) or closed (u[count + 1]). */
cf_status_t cf__interp_catmull_rom(size_t dim, const double *points,
                                   size_t count, const double *u,
                                   bool closed, cf_bspline_t **out,
                                   cf_diag_t *diag);

/* Checks of interp.c used by the least-squares code: dim, points, options
** and the parameters (u receives count values, count + 1 closed).
** strict (interpolation, which passes through each point at its
** parameter): parameters made from the points must increase strictly,
** which a chord lost in the rounding of their running sum breaks; given
** ones are always checked. */
cf_status_t cf__interp_prepare_params(size_t dim, const double *points,
                                      size_t count,
                                      const cf_interp_options_t *opt,
                                      bool closed, bool strict, double *u,
                                      cf_diag_t *diag);

#endif
