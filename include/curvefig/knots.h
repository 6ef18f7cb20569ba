/*
** Knot vectors and B-spline basis functions.
**
** A knot vector U = {u_0, ..., u_m} (m + 1 = nknots doubles, non-decreasing,
** finite) and a degree p >= 0 define the basis functions N_0^p ... N_n^p
** with m = n + p + 1 (Cox-de Boor recursion, 0/0 taken as 0).  A curve of
** degree p with n + 1 control points lives on the domain [u_p, u_{m-p}].
**
** Conventions.
**  - N_i^p is right-continuous: on a span [u_k, u_{k+1}) the nonzero
**    functions are N_{k-p}^p ... N_k^p.
**  - At the right end of the domain (u = u_{m-p}) the left limit is taken,
**    so a clamped curve ends at P_n.  For cf_basis_one (which works on the
**    whole vector [u_0, u_m]) the left limit is taken at u = u_m.
**  - Spans are indices k with u_k < u_{k+1} (non-empty); a "span search"
**    on the domain returns p <= k <= n.
**
** Every function that checks its input reports through the trailing
** optional cf_diag_t with a message naming the knot and the rule, e.g.
** "knot 4 (0.30) is smaller than knot 3 (0.50)".
*/
#ifndef CURVEFIG_KNOTS_H
#define CURVEFIG_KNOTS_H

#include "curvefig/core.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest B-spline degree accepted anywhere (stack scratch is sized by
** it, so evaluation never allocates). */
#define CF_BSPLINE_MAX_DEGREE 32

/* The shape of a knot vector for degree p. */
typedef enum cf_knot_kind {
    CF_KNOTS_OPEN = 0,   /* no special end structure ("otevřená") */
    CF_KNOTS_CLAMPED,    /* u_0 = ... = u_p and u_{m-p} = ... = u_m
                            ("plovoucí"; the curve ends at P_0, P_n) */
    CF_KNOTS_PERIODIC    /* the first 2p knot intervals repeat the last 2p
                            (u_{i+1} - u_i = u_{i+n-p+2} - u_{i+n-p+1},
                            i < 2p); with P_{n-p+1+i} = P_i the curve is
                            closed ("uzavřená") */
} cf_knot_kind_t;

/* ---- validation and generators ----------------------------------------- */

/* Number of knots a curve of degree p with npoints control points needs:
** npoints + p + 1. */
CF_API size_t cf_knots_count(int degree, size_t npoints);

/*
** Check a knot vector for a curve of the given degree and number of control
** points.  Rules, in the order checked (the message names the first
** violation):
**   0 <= degree <= CF_BSPLINE_MAX_DEGREE            (BAD_DEGREE)
**   npoints >= degree + 1                           (TOO_FEW_POINTS)
**   nknots == npoints + degree + 1                  (BAD_KNOTS: "bspline: 10
**        knots given, degree 2 with 8 points needs 11")
**   every knot finite                               (NOT_FINITE: "knot 3 is
**        nan; knots must be finite")
**   non-decreasing                                  (BAD_KNOTS: "knot 4 (0.30)
**        is smaller than knot 3 (0.50)")
**   multiplicity <= degree + 1                      (BAD_KNOTS: "knot 3 (0.50)
**        has multiplicity 4; degree 2 allows at most 3")
**   non-empty domain u_p < u_{m-p}                  (BAD_KNOTS: "the domain
**        [u_2, u_3] = [0.5, 0.5] is empty")
** An interior knot of multiplicity p + 1 is accepted: the curve may jump
** there (it splits into two independent curves).
*/
CF_API cf_status_t cf_knots_validate(int degree, size_t npoints,
                                     const double *knots, size_t nknots,
                                     cf_diag_t *diag);

/* Uniform (open) knots: out[i] = a + i (b - a) / m, i = 0..m, with
** m = npoints + degree; a < b.  The curve's domain is then [u_p, u_{m-p}],
** a sub-interval of [a, b].  out needs cf_knots_count() doubles. */
CF_API cf_status_t cf_knots_uniform(int degree, size_t npoints, double a,
                                    double b, double *out, cf_diag_t *diag);

/* Clamped uniform knots: p + 1 copies of a, the n - p interior knots
** a + j (b - a) / (n - p + 1), j = 1..n-p, and p + 1 copies of b
** (n + 1 = npoints >= p + 1; a < b).  The domain is [a, b]. */
CF_API cf_status_t cf_knots_clamped_uniform(int degree, size_t npoints,
                                            double a, double b, double *out,
                                            cf_diag_t *diag);

/* Clamped knots averaged from data parameters t_0 < ... < t_n
** (npoints of them, strictly increasing, finite): u_0..u_p = t_0,
** u_{j+p} = (t_j + ... + t_{j+p-1}) / p for j = 1..n-p, u_{m-p}..u_m = t_n
** (The NURBS Book eq. 9.8).  degree >= 1. */
CF_API cf_status_t cf_knots_clamped_averaged(int degree, size_t npoints,
                                             const double *params, double *out,
                                             cf_diag_t *diag);

/* ---- queries (no checking; the vector must be valid for the degree) ----
** Misuse is harmless: NULL, a degree outside [0, CF_BSPLINE_MAX_DEGREE] or
** fewer than 2p + 2 knots give a NaN domain, span max(p, 0) and OPEN. */

/* The domain [u_p, u_{m-p}] of a curve of degree p. */
CF_API void cf_knots_domain(int degree, const double *knots, size_t nknots,
                            double *a, double *b);

/* Span search by bisection: the k with u_k <= u < u_{k+1}, p <= k <= n
** (n = nknots - p - 2).  u below the domain gives p; u at or beyond the
** right end of the domain gives the last non-empty span (left limit). */
CF_API size_t cf_knots_find_span(int degree, const double *knots,
                                 size_t nknots, double u);

/* How many knots equal u exactly (0 when u is not a knot). */
CF_API int cf_knots_multiplicity(const double *knots, size_t nknots, double u);

/* Classification for degree p (see cf_knot_kind_t; relative tolerance
** 1e-12 of the knot range for "equal" intervals of PERIODIC; CLAMPED wins
** when both apply, which happens only for p = 0). */
CF_API cf_knot_kind_t cf_knots_classify(int degree, const double *knots,
                                        size_t nknots);

/* A static name: "open", "clamped", "periodic". */
CF_API const char *cf_knot_kind_to_string(cf_knot_kind_t kind);

/* ---- basis functions ---------------------------------------------------- */

/*
** All nonzero basis functions at u (the triangular scheme of the thesis,
** §2.5; The NURBS Book A2.2): N[j] = N_{k-p+j}^p(u), j = 0..p, where
** k = *span (may be NULL) is the span of u found by cf_knots_find_span.
** The vector is validated for a curve (nknots >= 2p + 2); u must lie in the
** domain [u_p, u_{m-p}] (DOMAIN otherwise, naming it; within
** 8 DBL_EPSILON max(|u_p|, |u_{m-p}|) of an end it is that end, as in
** bspline.h).  N has p + 1 doubles.
*/
CF_API cf_status_t cf_basis_funs(int degree, const double *knots,
                                 size_t nknots, double u, size_t *span,
                                 double *N, cf_diag_t *diag);

/*
** Derivatives of the nonzero basis functions (A2.3): ders[d * (p + 1) + j]
** = d^d/du^d N_{s-p+j}^p(u) for d = 0..k, s = *span (rows beyond p are 0).
** ders has (k + 1) * (p + 1) doubles; k >= 0.
*/
CF_API cf_status_t cf_basis_ders(int degree, const double *knots,
                                 size_t nknots, double u, int k,
                                 size_t *span, double *ders, cf_diag_t *diag);

/*
** One basis function N_i^p(u) anywhere on the real line, for plots
** (figures 1.1-1.15): the knot vector needs only i + p + 2 <= nknots (it
** need not be long enough for a curve, e.g. N_0^3 on {0,1,3,6,10}); knots
** non-decreasing and finite.  Outside [u_i, u_{i+p+1}) the value is 0;
** at u = u_m (the last knot) the left limit is taken.
*/
CF_API cf_status_t cf_basis_one(int i, int degree, const double *knots,
                                size_t nknots, double u, double *value,
                                cf_diag_t *diag);

/*
** One basis function over the whole knot vector, as a curve to draw: *out
** is a 1-D B-spline of degree p whose domain is [u_0, u_{m-1}] (the first
** and last of the nknots = m knots) and whose value there is N_i^p(u) of
** the given knots, with the conventions of cf_basis_one (0 outside
** [u_i, u_{i+p+1}), the left limit at u_{m-1}).  The knots are padded with
** p knots on either side at spacing u_{m-1} - u_0, and every coefficient
** is 0 except that of N_i^p, which is 1.  cf_bspline_to_beziers gives its
** polynomial pieces.  Needs 0 <= i, i + p + 2 <= m, knots finite and
** non-decreasing with u_{m-1} > u_0, no knot of multiplicity above p + 1
** (BAD_KNOTS, as for a curve).  Destroy with cf_bspline_destroy.
*/
struct cf_bspline;   /* cf_bspline_t, curvefig/bspline.h */
CF_API cf_status_t cf_basis_one_spline(int i, int degree,
                                       const double *knots, size_t nknots,
                                       struct cf_bspline **out,
                                       cf_diag_t *diag);

/* Derivatives of one basis function: out[d] = d^d/du^d N_i^p(u),
** d = 0..k (0 for d > p); the same conventions as cf_basis_one
** (one-sided: the derivative of the polynomial piece that owns u). */
CF_API cf_status_t cf_basis_one_ders(int i, int degree, const double *knots,
                                     size_t nknots, double u, int k,
                                     double *out, cf_diag_t *diag);

#ifdef __cplusplus
}
#endif

#endif
