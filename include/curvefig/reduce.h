/*
** Degree reduction of Bézier and B-spline curves (docs/approximation.md,
** "Degree reduction").
**
** A Bézier curve c of degree n is replaced by a curve r of degree
** m = n - by that keeps the derivatives of order 0 .. continuity at both
** ends (C^k end continuity, k = continuity; -1 keeps nothing) and is best
**
**   CF_REDUCE_L2       in the least-squares sense: r minimises the integral
**                      of |c(t) - r(t)|^2 over [0, 1] among all curves of
**                      degree m with those end derivatives (the closed form
**                      through Jacobi polynomials, exact up to rounding);
**   CF_REDUCE_UNIFORM  near-best in the uniform sense (the maximum of
**                      |c(t) - r(t)|): least squares with the Chebyshev
**                      weight, then Lawson's reweighting towards the
**                      minimax solution on a fine Chebyshev grid.
**
** Rational curves are reduced through their homogeneous form (the weights
** are reduced with the points, the distances the methods minimise are
** homogeneous); a reduced weight that is not positive is an error.
**
** Every reduction reports, beside the curve, the measured maximum distance
** |c(t) - r(t)| and a certified bound: r is elevated back to degree n and
** the largest distance between the two control polygons is an upper bound
** of the distance between the curves (for rational curves the difference
** c - r = (P v - Q w) / (w v) is bounded through its Bernstein
** coefficients).  The same bound on the 32 pieces of the difference split
** by de Casteljau is reported too: certified as well, and close to the
** measured maximum.
*/
#ifndef CURVEFIG_REDUCE_H
#define CURVEFIG_REDUCE_H

#include "curvefig/bezier.h"
#include "curvefig/bspline.h"
#include "curvefig/core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum cf_reduce_method {
    CF_REDUCE_L2 = 0,
    CF_REDUCE_UNIFORM = 1
} cf_reduce_method_t;

typedef struct cf_reduce_options {
    int by;            /* degrees to drop, 1 <= by < degree (default 1):
                          the reduced curve has degree >= 1 */
    int continuity;    /* k >= -1: C^k at both ends (default 0: the end
                          points are kept); 2 (k + 1) <= degree - by + 1 */
    cf_reduce_method_t method;   /* default CF_REDUCE_L2 */
    double tolerance;  /* B-splines only: the largest error allowed
                          (> 0; default 1e-3), checked on the certified
                          bound */
} cf_reduce_options_t;

typedef struct cf_reduce_report {
    double max_error;  /* measured max |c(t) - r(t)| (dense samples, each
                          local maximum refined) */
    double bound;      /* certified upper bound of max |c(t) - r(t)|: the
                          polygon bound on 32 de Casteljau halves of the
                          difference (much tighter, still certified) */
    double polygon_bound;  /* certified, the textbook way: r elevated to
                              degree n, the largest distance between the
                              two control polygons */
    double l2_error;   /* sqrt of the integral of |c - r|^2 over the
                          parameter domain (homogeneous for rational
                          curves; the quantity CF_REDUCE_L2 minimises) */
    int continuity;    /* B-splines: the smallest continuity kept at an
                          interior knot (-1 for a Bézier curve) */
    size_t knots_removed;  /* B-splines: knots removed after the pieces
                              were reduced */
} cf_reduce_report_t;

/* Defaults: by = 1, continuity = 0, CF_REDUCE_L2, tolerance = 1e-3. */
CF_API void cf_reduce_options_init(cf_reduce_options_t *opt);

/*
** Reduce c by opt->by degrees (opt NULL: the defaults).  report (may be
** NULL) receives the errors.  BAD_DEGREE when by is not in 1 .. degree - 1,
** INVALID_ARG when the continuity is below -1 or more than the reduced
** degree can hold at both ends (2 (k + 1) > m + 1; the message names the
** largest k), DEGENERATE when a reduced weight is not positive,
** NOT_FINITE when a reduced point overflows (coordinates near DBL_MAX).
*/
CF_API cf_status_t cf_bezier_reduce(const cf_bezier_t *c,
                                    const cf_reduce_options_t *opt,
                                    cf_bezier_t **out,
                                    cf_reduce_report_t *report,
                                    cf_diag_t *diag);

/*
** Degree reduction of a B-spline curve (p -> q = p - by, q >= 1) within
** opt->tolerance (The NURBS Book A5.11, with best piecewise reductions):
** the curve is decomposed into Bézier pieces, each piece is reduced with
** the continuity of the original at its ends (as much of it as the reduced
** degree can hold: k <= (q - 1) / 2 at both ends, so that the pieces join
** C^k; the method is opt->method, opt->continuity is not used), and knots
** are then removed (A5.8) while the certified error stays within the
** tolerance, back to the original continuity C^(p - s) at a knot of
** multiplicity s where the reduced degree allows it (at most C^(q - 1)).
** When even C^0 joins exceed the tolerance the reduction is refused
** (CF_STATUS_NO_CONVERGENCE) and the message gives the smallest error reached
** (in report->bound as well).  An open curve comes back clamped to its
** domain.
*/
CF_API cf_status_t cf_bspline_reduce(const cf_bspline_t *c,
                                     const cf_reduce_options_t *opt,
                                     cf_bspline_t **out,
                                     cf_reduce_report_t *report,
                                     cf_diag_t *diag);

#ifdef __cplusplus
}
#endif

#endif
