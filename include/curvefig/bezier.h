/*
** Bézier curves in R^N, polynomial and rational.
**
** Storage.  A curve of degree n has n + 1 control points.  A polynomial curve
** stores them Cartesian, `dim` doubles each.  A rational curve stores them
** homogeneously, (w*x_1 ... w*x_N, w), `dim + 1` doubles each; every
** construction (de Casteljau, subdivision, elevation, ...) runs unchanged on
** these, and division by w happens only when a point is returned.  Points
** passed in and returned are interleaved: x_0 y_0 x_1 y_1 ...
**
** Objects are immutable: every operation returns a new curve which the
** caller releases with cf_bezier_destroy (destroy(NULL) is harmless).
** Evaluation (eval*, decasteljau, tangent, normal, curvature) never
** allocates; bbox, length, closest and flatten use a work buffer and may
** return CF_STATUS_NO_MEMORY.
**
** Parameters.  The domain is [0, 1].  Evaluators (eval*, decasteljau,
** tangent, normal, curvature, the offset points, the Bernstein basis)
** accept any t in [0, 1], and t that misses an end by at most
** 8 DBL_EPSILON (rounding) as that end; they return CF_STATUS_NOT_FINITE
** for NaN or infinite t and CF_STATUS_DOMAIN for t further out (core.h,
** "Parameters"); split points must lie in the open interval (0, 1).  Functions without a diag argument report NULL
** pointers and negative orders as CF_STATUS_INVALID_ARG.
*/
#ifndef CURVEFIG_BEZIER_H
#define CURVEFIG_BEZIER_H

#include "curvefig/core.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest degree accepted by the constructors. */
#define CF_BEZIER_MAX_DEGREE 1024

typedef struct cf_bezier cf_bezier_t;

/* ---- construction ------------------------------------------------------- */

/* Create a curve of the given degree (>= 0) in R^dim (dim >= 1) from
** degree + 1 Cartesian points.  weights == NULL makes a polynomial curve;
** otherwise degree + 1 finite positive weights make a rational one. */
CF_API cf_status_t cf_bezier_create(size_t dim, int degree,
                                    const double *points,
                                    const double *weights, cf_bezier_t **out,
                                    cf_diag_t *diag);

/* Create a rational curve from homogeneous points (w*x, w), dim + 1 doubles
** each; the weights (last coordinates) must be finite and positive. */
CF_API cf_status_t cf_bezier_create_homogeneous(size_t dim, int degree,
                                                const double *hpoints,
                                                cf_bezier_t **out,
                                                cf_diag_t *diag);

CF_API cf_status_t cf_bezier_copy(const cf_bezier_t *c, cf_bezier_t **out,
                                  cf_diag_t *diag);
CF_API void cf_bezier_destroy(cf_bezier_t *c);

/* ---- queries (never fail on a valid curve; 0 / false on NULL) ----------- */

CF_API size_t cf_bezier_dim(const cf_bezier_t *c);       /* Cartesian N */
CF_API int cf_bezier_degree(const cf_bezier_t *c);
CF_API bool cf_bezier_is_rational(const cf_bezier_t *c);
/* The stored control points: (degree + 1) * (dim + rational) doubles. */
CF_API const double *cf_bezier_hpoints(const cf_bezier_t *c);
/* Cartesian control points into out[(degree + 1) * dim]. */
CF_API void cf_bezier_get_points(const cf_bezier_t *c, double *out);
/* Weights into out[degree + 1] (all 1 for a polynomial curve). */
CF_API void cf_bezier_get_weights(const cf_bezier_t *c, double *out);

/* ---- evaluation --------------------------------------------------------- */

/* out[dim] = c(t), by de Casteljau. */
CF_API cf_status_t cf_bezier_eval(const cf_bezier_t *c, double t, double *out);

/* out[n * dim] = c(t[0]) ... c(t[n-1]); allocates nothing.  May use a faster
** scheme than de Casteljau that agrees with it to a few ulps of the curve's
** size (tested). */
CF_API cf_status_t cf_bezier_eval_many(const cf_bezier_t *c, const double *t,
                                       size_t n, double *out);

/* out[(k + 1) * dim] = c(t), c'(t), ..., c^(k)(t).  Exact for rational
** curves (quotient rule on the homogeneous derivatives).
** 0 <= k <= CF_BEZIER_MAX_DEGREE (BAD_DEGREE above). */
CF_API cf_status_t cf_bezier_eval_derivs(const cf_bezier_t *c, double t, int k,
                                         double *out);

/* out[n * dim] = c^(k)(t[i]) for each i; allocates nothing. */
CF_API cf_status_t cf_bezier_eval_deriv_many(const cf_bezier_t *c,
                                             const double *t, size_t n, int k,
                                             double *out);

/* The whole de Casteljau triangle at t, Cartesian, level by level: level 0
** is the control polygon (n + 1 points), level j has n + 1 - j points, level
** n is c(t).  out needs cf_bezier_decasteljau_size(c) doubles. */
CF_API size_t cf_bezier_decasteljau_size(const cf_bezier_t *c);
CF_API cf_status_t cf_bezier_decasteljau(const cf_bezier_t *c, double t,
                                         double *out);

/* Unit tangent c'/|c'| (at a point where c' = 0 the first non-zero higher
** derivative gives the direction; CF_STATUS_DEGENERATE if all vanish). */
CF_API cf_status_t cf_bezier_tangent(const cf_bezier_t *c, double t,
                                     double *out);
/* Unit normal.  dim == 2: the tangent turned +90 degrees (left of travel).
** dim >= 3: the principal normal (DEGENERATE where the curvature is 0).
** dim == 1: INVALID_ARG. */
CF_API cf_status_t cf_bezier_normal(const cf_bezier_t *c, double t,
                                    double *out);
/* Curvature.  dim == 2: signed (positive turning left);
** dim >= 3: |c' x c''| / |c'|^3 (non-negative). */
CF_API cf_status_t cf_bezier_curvature(const cf_bezier_t *c, double t,
                                       double *kappa);

/* ---- constructions returning curves ------------------------------------- */

/* The k-th derivative as a curve: polynomial: the hodograph of degree n - k
** with Q_i = n (P_{i+1} - P_i) (applied k times; a single zero point when
** k > n).  Rational: an exact rational curve of degree 2n (per derivative)
** with weights w(t)^2, so that its evaluation is c'(t); BAD_DEGREE when
** n 2^k exceeds CF_BEZIER_MAX_DEGREE. */
CF_API cf_status_t cf_bezier_derivative(const cf_bezier_t *c, int k,
                                        cf_bezier_t **out, cf_diag_t *diag);

/* Subdivide at t in (0, 1): left on [0, t], right on [t, 1], both
** reparametrised to [0, 1], same degree.  Either output may be NULL. */
CF_API cf_status_t cf_bezier_split(const cf_bezier_t *c, double t,
                                   cf_bezier_t **left, cf_bezier_t **right,
                                   cf_diag_t *diag);

/* Allocation-free split into caller buffers of (degree + 1) * (dim +
** rational) doubles each (homogeneous layout, like cf_bezier_hpoints).
** The two buffers must be different (INVALID_ARG otherwise). */
CF_API cf_status_t cf_bezier_split_into(const cf_bezier_t *c, double t,
                                        double *left_hpoints,
                                        double *right_hpoints);

/* The piece on [a, b] (0 <= a < b <= 1), reparametrised to [0, 1]. */
CF_API cf_status_t cf_bezier_segment(const cf_bezier_t *c, double a, double b,
                                     cf_bezier_t **out, cf_diag_t *diag);

/* Reversal: control points in opposite order, r(t) = c(1 - t). */
CF_API cf_status_t cf_bezier_reverse(const cf_bezier_t *c, cf_bezier_t **out,
                                     cf_diag_t *diag);

/* Affine image x -> A x + b with A a dim x dim row-major matrix and b a
** dim vector (b may be NULL for 0). */
CF_API cf_status_t cf_bezier_transform(const cf_bezier_t *c, const double *A,
                                       const double *b, cf_bezier_t **out,
                                       cf_diag_t *diag);

/* Degree elevation by r >= 0: the same curve with degree n + r. */
CF_API cf_status_t cf_bezier_elevate(const cf_bezier_t *c, int r,
                                     cf_bezier_t **out, cf_diag_t *diag);

/* Degree reduction: cf_bezier_reduce in curvefig/reduce.h. */

/* ---- geometry ----------------------------------------------------------- */

/* Tight axis-aligned box of the curve (not of the control points): from the
** end points and the roots of the derivative (of its numerator A'w - Aw'
** for rational curves; BAD_DEGREE for rational degree > 512).
** lo[dim], hi[dim]. */
CF_API cf_status_t cf_bezier_bbox(const cf_bezier_t *c, double *lo,
                                  double *hi);

/* Arc length on [0, 1] with absolute error <= tol (tol > 0): adaptive
** 8/16-point Gauss-Legendre, the difference of the two rules as the error
** estimate.  NO_CONVERGENCE after 50 halvings. */
CF_API cf_status_t cf_bezier_length(const cf_bezier_t *c, double tol,
                                    double *length);

/* Closest point of the curve to p[dim]: parameter, and distance (either
** pointer may be NULL).  Global: the end points and every root of
** (c(t) - p) . c'(t) (found in the Bernstein form by subdivision) are
** compared.  BAD_DEGREE above degree 512 (rational: 341). */
CF_API cf_status_t cf_bezier_closest(const cf_bezier_t *c, const double *p,
                                     double *t, double *distance);

/* Flatten to a polyline whose distance from the curve is <= tol.  The
** callback receives each vertex (dim doubles, Cartesian) and its parameter,
** starting with c(0) and ending with c(1); a non-zero return stops the walk
** and is returned as CF_STATUS_INVALID_ARG.  Pieces are halved (de
** Casteljau) until every control point is within tol of the chord, which
** bounds the curve's distance by the convex hull property (rational curves
** too: their Cartesian control points are used). */
typedef int (*cf_point_func_t)(void *closure, const double *point, double t);
CF_API cf_status_t cf_bezier_flatten(const cf_bezier_t *c, double tol,
                                     cf_point_func_t func, void *closure);

/* ---- conversion to cubic segments (for path output) --------------------- */

/* A chain of polynomial cubic Bézier segments in R^dim: segment i has
** control points pts[4 * dim * i ...] and covers parameters
** [t[i], t[i + 1]] of the source curve. */
typedef struct cf_cubics {
    size_t dim;
    size_t count;
    double *pts;       /* 4 * dim * count */
    double *t;         /* count + 1 */
    double max_error;  /* achieved distance to the source (0 if exact) */
} cf_cubics_t;

/* Polynomial curves of degree <= 3: exact (one segment, degree raised).
** Other planar curves (dim 2): split at the zeros of c', then covered by
** the longest cubics matching end points, end tangents, signed area and
** moment (Levien's fit) whose measured two-sided Hausdorff distance to the
** curve is <= tol (tol > 0).  Other
** dimensions: cubic Hermite pieces halved until the distance measured at
** 47 interior parameters is <= tol.  max_error is the largest measured
** distance; NO_CONVERGENCE when tol cannot be reached. */
CF_API cf_status_t cf_bezier_to_cubics(const cf_bezier_t *c, double tol,
                                       cf_cubics_t **out, cf_diag_t *diag);

/* The same chain for drawing, without measuring: polynomial curves of
** degree >= 4 (any dim) become N uniform cubic Hermite pieces (C1, end
** points and derivatives of the curve), N the smallest with
** max|c^(4)| / (384 N^4) <= tol, max|c^(4)| bounded by the hull of the
** fourth differences; max_error is that bound (a guarantee, parameter for
** parameter).  Cheaper than cf_bezier_to_cubics by orders of magnitude,
** usually with a few more pieces.  Rational curves (any dim): cubic
** Hermite pieces halved until the distance measured at 47 interior
** parameters is <= tol (parameter for parameter, so also two-sided; C1;
** some 15 times faster than the planar fit of cf_bezier_to_cubics, with
** about four times its pieces).  Polynomial curves of degree <= 3: as
** cf_bezier_to_cubics.  NOT_FINITE when the fourth derivative overflows. */
CF_API cf_status_t cf_bezier_to_cubics_bounded(const cf_bezier_t *c,
                                               double tol, cf_cubics_t **out,
                                               cf_diag_t *diag);
CF_API void cf_cubics_destroy(cf_cubics_t *cubics);

/* ---- lists of curves (results of conic and B-spline operations) --------- */

typedef struct cf_bezier_list {
    size_t count;
    cf_bezier_t **items;
    double *t0, *t1;   /* optional parameter range of each item in its
                          source (NULL when not meaningful) */
} cf_bezier_list_t;

CF_API void cf_bezier_list_destroy(cf_bezier_list_t *list);

#ifdef __cplusplus
}
#endif

#endif
