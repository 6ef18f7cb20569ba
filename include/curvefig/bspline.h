/*
** B-spline and NURBS curves in R^N.
**
** A curve of degree p has n + 1 = count control points P_0..P_n and a knot
** vector of m + 1 = count + p + 1 knots (see curvefig/knots.h for the rules
** and the conventions of the basis functions).  C(u) = sum N_i^p(u) P_i on
** the domain [u_p, u_{m-p}]; at the right end the left limit is taken, so a
** clamped curve starts at P_0 and ends at P_n.
**
** Storage.  Like Bézier curves (curvefig/bezier.h): a polynomial curve
** stores Cartesian points, `dim` doubles each; a rational curve (NURBS)
** stores homogeneous points (w*x_1 ... w*x_N, w), `dim + 1` doubles each.
** Every construction (de Boor, knot insertion, refinement, decomposition,
** elevation) runs unchanged on the homogeneous points; division by w
** happens only when a point is returned.  Points passed in and returned are
** interleaved (x_0 y_0 x_1 y_1 ...).
**
** Objects are immutable: every operation returns a new curve that the
** caller releases with cf_bspline_destroy (destroy(NULL) is harmless).
** Evaluation never allocates.
**
** Parameters.  The evaluators (eval*, deboor, basis, active_points, and
** cf_basis_funs / cf_basis_ders on a knot vector) take u in the domain
** [a, b] = [u_p, u_{m-p}]; a u that misses an end by at most
** 8 DBL_EPSILON max(|a|, |b|) is that end (the last value of the loop
** a + (b - a) i / (N - 1) may overshoot b by rounding), further out is
** DOMAIN, NaN and infinities NOT_FINITE.  No parameter is ever moved onto
** a nearby interior knot.  Constructions (insert_knot, refine, split,
** segment) take their parameters exactly: inside [a, b] or DOMAIN.
*/
#ifndef CURVEFIG_BSPLINE_H
#define CURVEFIG_BSPLINE_H

#include "curvefig/core.h"
#include "curvefig/knots.h"
#include "curvefig/bezier.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cf_bspline cf_bspline_t;

/* ---- construction ------------------------------------------------------- */

/*
** A curve of the given degree in R^dim (dim >= 1) from count Cartesian
** points and nknots = count + degree + 1 knots (checked by
** cf_knots_validate, so the messages name the offending knot).
** weights == NULL makes a polynomial B-spline; otherwise count finite
** positive weights make a NURBS.  Inputs are copied.
*/
CF_API cf_status_t cf_bspline_create(size_t dim, int degree,
                                     const double *knots, size_t nknots,
                                     const double *points, size_t count,
                                     const double *weights, cf_bspline_t **out,
                                     cf_diag_t *diag);

/* A NURBS from homogeneous points (w*x, w), dim + 1 doubles each; every
** weight (last coordinate) must be finite and positive. */
CF_API cf_status_t cf_bspline_create_homogeneous(size_t dim, int degree,
                                                 const double *knots,
                                                 size_t nknots,
                                                 const double *hpoints,
                                                 size_t count,
                                                 cf_bspline_t **out,
                                                 cf_diag_t *diag);

/* Clamped curve with uniform interior knots on the domain [0, 1]
** (cf_knots_clamped_uniform); weights may be NULL.  count >= degree + 1. */
CF_API cf_status_t cf_bspline_create_clamped(size_t dim, int degree,
                                             const double *points,
                                             size_t count,
                                             const double *weights,
                                             cf_bspline_t **out,
                                             cf_diag_t *diag);

/*
** Closed (periodic) curve through wrapping: the count given points
** (count >= degree + 1, degree >= 1) are followed by copies of the first
** `degree` of them, P_0..P_{c-1}, P_0..P_{p-1}, and the knots are uniform,
** u_i = (i - p) / c, i = 0..c+2p, so the domain is [0, 1] and the curve is
** C^{p-1} at C(0) = C(1).  weights (count of them) may be NULL.
*/
CF_API cf_status_t cf_bspline_create_closed(size_t dim, int degree,
                                            const double *points, size_t count,
                                            const double *weights,
                                            cf_bspline_t **out,
                                            cf_diag_t *diag);

/*
** Uniform cubic (Coons) B-spline of the thesis, chapter 4: degree 3,
** knots u_i = i - 3 (integers) so that segment Q_j (j = 3..N-1) is driven
** by P_{j-3}..P_j and covers [j - 3, j - 2]; the domain is [0, N - 3] where
** N is the number of points after the end treatment:
**   CF_COONS_PLAIN:   the points as given (count >= 4);
**   CF_COONS_TRIPLED: P_0,P_0,P_0,P_1,...,P_{n-1},P_n,P_n,P_n (count >= 2):
**                     the curve starts at P_0 and ends at P_n;
**   CF_COONS_CLOSED:  P_0,...,P_n,P_0,P_1,P_2 (count >= 3): closed, C^2.
*/
typedef enum cf_coons_ends {
    CF_COONS_PLAIN = 0,
    CF_COONS_TRIPLED,
    CF_COONS_CLOSED
} cf_coons_ends_t;

CF_API cf_status_t cf_bspline_create_coons(size_t dim, const double *points,
                                           size_t count, cf_coons_ends_t ends,
                                           cf_bspline_t **out,
                                           cf_diag_t *diag);

/* The closed form of one Coons segment (chapter 4):
** Q(t) = 1/6 [ (1-t)^3 P0 + (3t^3 - 6t^2 + 4) P1
**              + (-3t^3 + 3t^2 + 3t + 1) P2 + t^3 P3 ],  t in [0, 1].
** b[4] receives the four weights; cf_coons_eval writes out[dim] from the
** four points p4[4 * dim].  Independent of the de Boor code (tests compare
** the two). */
CF_API void cf_coons_basis(double t, double b[4]);
CF_API void cf_coons_eval(size_t dim, const double *p4, double t, double *out);

CF_API cf_status_t cf_bspline_copy(const cf_bspline_t *c, cf_bspline_t **out,
                                   cf_diag_t *diag);
CF_API void cf_bspline_destroy(cf_bspline_t *c);

/* ---- NURBS conics (exact) ----------------------------------------------- */

/*
** Circular arc (The NURBS Book A7.1): centre O[dim], orthonormal directions
** X[dim], Y[dim] (dim >= 2) spanning its plane, radius r > 0, from angle a0
** to a1 (radians, 0 < a1 - a0 <= 2 pi), C(theta) = O + r cos(theta) X
** + r sin(theta) Y.  Quadratic NURBS with one rational Bézier piece per
** quarter turn or less (double interior knots), clamped on [0, 1].
*/
CF_API cf_status_t cf_nurbs_arc(size_t dim, const double *O, const double *X,
                                const double *Y, double r, double a0,
                                double a1, cf_bspline_t **out,
                                cf_diag_t *diag);

/* Full circle in the plane: centre[2], radius r > 0, counter-clockwise
** from (cx + r, cy); 9 control points, weights 1, sqrt(2)/2, ...,
** knots {0,0,0,1/4,1/4,1/2,1/2,3/4,3/4,1,1,1}. */
CF_API cf_status_t cf_nurbs_circle(const double *centre, double r,
                                   cf_bspline_t **out, cf_diag_t *diag);

/* ---- queries (never fail on a valid curve; 0 / NULL / false on NULL) ---- */

CF_API size_t cf_bspline_dim(const cf_bspline_t *c);        /* Cartesian N */
CF_API int cf_bspline_degree(const cf_bspline_t *c);
CF_API size_t cf_bspline_count(const cf_bspline_t *c);      /* n + 1 points */
CF_API size_t cf_bspline_nknots(const cf_bspline_t *c);     /* n + p + 2 */
CF_API bool cf_bspline_is_rational(const cf_bspline_t *c);
/* The whole knot vector (cf_bspline_nknots doubles), owned by the curve. */
CF_API const double *cf_bspline_knots(const cf_bspline_t *c);
/* The stored points: count * (dim + rational) doubles, owned by the curve. */
CF_API const double *cf_bspline_hpoints(const cf_bspline_t *c);
/* Cartesian control points into out[count * dim]. */
CF_API void cf_bspline_get_points(const cf_bspline_t *c, double *out);
/* Weights into out[count] (all 1 for a polynomial curve). */
CF_API void cf_bspline_get_weights(const cf_bspline_t *c, double *out);
/* The domain [u_p, u_{m-p}] (either pointer may be NULL). */
CF_API void cf_bspline_domain(const cf_bspline_t *c, double *a, double *b);
/* cf_knots_classify of the curve's knots. */
CF_API cf_knot_kind_t cf_bspline_knot_kind(const cf_bspline_t *c);

/* ---- evaluation --------------------------------------------------------- */

/* out[dim] = C(u) by de Boor's algorithm (one coordinate at a time, no
** allocation), divided by w for a NURBS. */
CF_API cf_status_t cf_bspline_eval(const cf_bspline_t *c, double u,
                                   double *out);

/*
** out[n * dim] = C(u[0]) ... C(u[n-1]); allocates nothing.  Uses the
** nonzero basis functions with reciprocals of knot differences, computed
** once by the first batch call into space reserved in the curve (so
** constructions never pay for them; thread-safe: a concurrent first call
** evaluates without them); parameters that stay in the span of the
** previous one reuse it, others find their span branch-free through a
** grid over the domain.  Agrees with cf_bspline_eval to a few ulps of the
** size of the control points (tested).  On an invalid parameter, returns
** its status with out[0 .. i*dim) written.
*/
CF_API cf_status_t cf_bspline_eval_many(const cf_bspline_t *c, const double *u,
                                        size_t n, double *out);

/* out[(k + 1) * dim] = C(u), C'(u), ..., C^(k)(u), k >= 0 (A3.2 on the
** basis derivatives; for a NURBS the exact rational derivatives by the
** quotient rule on the homogeneous derivatives, A4.2).  At an interior
** knot the derivatives are those of the piece on the right (right
** limit); at the right end of the domain those of the last piece. */
CF_API cf_status_t cf_bspline_eval_derivs(const cf_bspline_t *c, double u,
                                          int k, double *out);

/* out[n * dim] = C^(k)(u[i]) for each i (k >= 0; for a NURBS k <= 128,
** INVALID_ARG above); allocates nothing; spans are found like
** cf_bspline_eval_many. */
CF_API cf_status_t cf_bspline_eval_deriv_many(const cf_bspline_t *c,
                                              const double *u, size_t n, int k,
                                              double *out);

/*
** The whole de Boor net at u (thesis §3.2, figures 3.5-3.7), Cartesian,
** level by level: level 0 is the p + 1 control points acting on the span
** of u, P_{k-p} .. P_k; level j (j = 1..p) has p + 1 - j points
** P_{k-p+j,j} .. P_{k,j}, each P_{i,j} = (1 - a) P_{i-1,j-1} + a P_{i,j-1}
** with a = (u - u_i) / (u_{i+p+1-j} - u_i); level p is the single point
** C(u).  Level j starts at out[dim * (j (2p + 3 - j) / 2)].  out needs
** cf_bspline_deboor_size(c) doubles.  *span (may be NULL) receives k (so
** point l of level j is P_{k-p+j+l, j}) and *mult (may be NULL) the
** multiplicity s of u as a knot: when s > 0 the last s points of each
** level are old control points repeated (the thesis uses the first p - s
** levels only).  For a NURBS the net is divided by w point by point.
*/
CF_API size_t cf_bspline_deboor_size(const cf_bspline_t *c);
CF_API cf_status_t cf_bspline_deboor(const cf_bspline_t *c, double u,
                                     double *out, size_t *span, int *mult);

/* The nonzero B-spline basis functions of the curve at u: N[j] =
** N_{first+j}^p(u), j = 0..p, *first = k - p (may be NULL).  For a NURBS
** these are the polynomial N (the rational basis is N_i w_i / sum N w). */
CF_API cf_status_t cf_bspline_basis(const cf_bspline_t *c, double u,
                                    size_t *first, double *N);

/* ---- constructions returning curves ------------------------------------- */

/*
** The k-th derivative as a curve (k >= 0; k = 0 copies).
** Polynomial: degree p - 1 with the inner knots u_1..u_{m-1} and points
** Q_i = p / (u_{i+p+1} - u_{i+1}) (P_{i+1} - P_i) (thesis §2.9), applied
** k times.  Where that knot difference is 0 (a knot of multiplicity p + 1:
** the curve jumps) Q_i and one copy of the knot are left out, since their
** basis function vanishes.  Once the degree is 0, further derivatives give
** a degree-0 curve whose points are all zero.
** NURBS: an exact rational curve assembled from the rational Bézier
** derivatives (cf_bezier_derivative) of its pieces: degree 2p per
** derivative, every interior break point a knot of full multiplicity
** (the pieces share no control points).  Its evaluation equals
** cf_bspline_eval_derivs to rounding; prefer the latter for numbers.
*/
CF_API cf_status_t cf_bspline_derivative(const cf_bspline_t *c, int k,
                                         cf_bspline_t **out, cf_diag_t *diag);

/* What a knot insertion did to the control polygon (figures 3.1-3.4). */
typedef struct cf_bspline_insert_info {
    size_t span;        /* k: u_k <= u < u_{k+1} in the old knot vector
                           (the largest k with u_k <= u) */
    int multiplicity;   /* s: multiplicity of u before the insertion */
    int times;          /* r: how many times u was inserted */
    size_t cut_first;   /* old points P_{cut_first} .. P_{cut_first +    */
    size_t cut_count;   /*   cut_count - 1} were cut away (the corners
                           k-p+1 .. k-s-1; cut_count may be 0) */
    size_t new_first;   /* new points Q_{new_first} .. Q_{new_first +    */
    size_t new_count;   /*   new_count - 1} of the new polygon were
                           computed (k-p+1 .. k-s+r-1); all other Q equal
                           old points: Q_i = P_i before, Q_i = P_{i-r}
                           after */
} cf_bspline_insert_info_t;

/*
** Insert u into the knot vector r >= 1 times without changing the curve
** (thesis §3.1, A5.1): u in [u_p, u_{m-p}] and s + r <= p + 1 where s is
** the current multiplicity of u (BAD_KNOTS otherwise, with a message
** naming both).  The p + 1-th copy of an interior knot splits the curve.
** info (may be NULL) says which points were cut and which are new.
*/
CF_API cf_status_t cf_bspline_insert_knot(const cf_bspline_t *c, double u,
                                          int r, cf_bspline_t **out,
                                          cf_bspline_insert_info_t *info,
                                          cf_diag_t *diag);

/* Knot refinement (A5.4): insert all nx knots x[] (non-decreasing, inside
** the domain, final multiplicities <= p + 1) at once.  nx == 0 copies. */
CF_API cf_status_t cf_bspline_refine(const cf_bspline_t *c, const double *x,
                                     size_t nx, cf_bspline_t **out,
                                     cf_diag_t *diag);

/*
** Knot removal (A5.8): try to remove the interior knot u (a knot strictly
** inside the domain) up to r >= 1 times, stopping as soon as the curve
** would move by more than tol (>= 0; a distance in R^dim for a polynomial
** curve; for a NURBS the homogeneous bound of The NURBS Book eq. 5.30).
** *removed (may be NULL) receives how many times it was removed (0 when
** none: *out is then a copy).  BAD_KNOTS when u is not an interior knot.
*/
CF_API cf_status_t cf_bspline_remove_knot(const cf_bspline_t *c, double u,
                                          int r, double tol,
                                          cf_bspline_t **out, int *removed,
                                          cf_diag_t *diag);

/*
** Split at u strictly inside the domain (thesis §3.3): left on [a, u],
** right on [u, b], same degree and parameters as the original (no
** reparametrisation); u becomes a clamped end (multiplicity p + 1) of
** both, the other ends keep their knots.  Either output may be NULL.
*/
CF_API cf_status_t cf_bspline_split(const cf_bspline_t *c, double u,
                                    cf_bspline_t **left, cf_bspline_t **right,
                                    cf_diag_t *diag);

/* The piece on [a, b] (domain start <= a < b <= domain end), clamped at
** a and b, original parameters kept. */
CF_API cf_status_t cf_bspline_segment(const cf_bspline_t *c, double a,
                                      double b, cf_bspline_t **out,
                                      cf_diag_t *diag);

/*
** Decomposition into Bézier segments (cubics from the blossom, any knot
** vector; other degrees by A5.6 after clamping an open curve to its
** domain): one item per non-empty span of the domain, in order, each of
** degree p (rational when the curve is), reparametrised to [0, 1]; t0[i],
** t1[i] give its parameter range in the B-spline.  Free with
** cf_bezier_list_destroy.  An item may be taken out of the list (set its
** slot to NULL) and destroyed later with cf_bezier_destroy, in any order
** and thread; the items share one allocation, freed with the last of
** them, so an item kept long keeps the whole list's points.
*/
CF_API cf_status_t cf_bspline_to_beziers(const cf_bspline_t *c,
                                         cf_bezier_list_t **out,
                                         cf_diag_t *diag);

/* The same as flat arrays, with no per-segment object: *hpoints receives
** *count * (p + 1) * (dim + rational) doubles (segment after segment,
** homogeneous layout like cf_bspline_hpoints), *breaks the *count + 1
** break parameters.  Both arrays are freed with cf_free; breaks may be
** NULL when not wanted. */
CF_API cf_status_t cf_bspline_bezier_points(const cf_bspline_t *c,
                                            double **hpoints, double **breaks,
                                            size_t *count, cf_diag_t *diag);

/* Degree elevation by t >= 0 (p + t <= CF_BSPLINE_MAX_DEGREE): the same
** curve with degree p + t, every interior knot's multiplicity raised by t
** (continuity kept).  Works through the Bézier pieces, so an open curve
** comes back clamped to its domain. */
CF_API cf_status_t cf_bspline_elevate(const cf_bspline_t *c, int t,
                                      cf_bspline_t **out, cf_diag_t *diag);

/* Reversal: points in opposite order, knots u'_i = u_0 + u_m - u_{m-i},
** so R(u) = C(u_0 + u_m - u). */
CF_API cf_status_t cf_bspline_reverse(const cf_bspline_t *c,
                                      cf_bspline_t **out, cf_diag_t *diag);

/* Affine image x -> A x + b (A dim x dim row-major, b[dim] or NULL for 0),
** applied to the control points (weights unchanged). */
CF_API cf_status_t cf_bspline_transform(const cf_bspline_t *c, const double *A,
                                        const double *b, cf_bspline_t **out,
                                        cf_diag_t *diag);

/* ---- figure helpers ----------------------------------------------------- */

/* The interval [u_i, u_{i+p+1}) on which control point i acts (local
** control, thesis §2.3).  INVALID_ARG when i >= count. */
CF_API cf_status_t cf_bspline_support(const cf_bspline_t *c, size_t i,
                                      double *lo, double *hi);

/* The control points acting on the span that contains u (strong convex
** hull, figures 2.7-2.8): P_first .. P_{first+p}, first = k - p, and the
** span [u_k, u_{k+1}) itself (span_lo, span_hi may be NULL). */
CF_API cf_status_t cf_bspline_active_points(const cf_bspline_t *c, double u,
                                            size_t *first, double *span_lo,
                                            double *span_hi);

/* A new curve with control point i moved by v[dim] (Cartesian; weight
** kept).  Polynomial: D(u) = C(u) + N_i^p(u) v (thesis §2.6); NURBS: the
** same with the rational basis R_i. */
CF_API cf_status_t cf_bspline_move_point(const cf_bspline_t *c, size_t i,
                                         const double *v, cf_bspline_t **out,
                                         cf_diag_t *diag);

#ifdef __cplusplus
}
#endif

#endif
