/*
** Interpolation and the curves of chapter 4 of the Marková thesis:
** Ferguson (Hermite) cubics, Coons cubics, cubic spline interpolation
** (natural, clamped, not-a-knot, periodic), global B-spline interpolation of
** any degree (The NURBS Book A9.1, with optional end derivatives),
** Catmull-Rom splines, and least-squares approximation by a B-spline.
**
** Every result is a curve of the library: single cubics and their chains
** are Bézier curves (cf_bezier_t, cf_bezier_list_t), everything that passes
** through a list of points is a B-spline (cf_bspline_t), so evaluation,
** derivatives, splitting, Bézier decomposition and the renderer work on it.
**
** Points are interleaved (x_0 y_0 x_1 y_1 ...) in R^dim, dim >= 1.  Every
** function checks its input and reports through the trailing optional
** cf_diag_t: too few points ("natural cubic spline needs at least 2 points,
** got 1"), a NaN ("point 2 has coordinate 1 = nan; coordinates must be
** finite"), coincident consecutive points ("points 3 and 4 coincide (1, 2);
** chord-length parameters need distinct consecutive points"), a bad degree.
*/
#ifndef CURVEFIG_INTERP_H
#define CURVEFIG_INTERP_H

#include "curvefig/core.h"
#include "curvefig/bezier.h"
#include "curvefig/bspline.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- parameters --------------------------------------------------------- */

/*
** How the data points P_0..P_n get their parameters u_0 < ... < u_n:
** u_0 = 0, u_{i+1} = u_i + |P_{i+1} - P_i|^e, then divided by the total so
** that u_n = 1, with e = 0 (uniform), 1 (chord length), 1/2 (centripetal)
** or any e in [0, 1] (CF_PARAM_POWER with the option `exponent`).
** For Catmull-Rom, e is the classic alpha (0 uniform, 0.5 centripetal,
** 1 chordal).  CF_PARAM_DEFAULT is chord length for the splines and
** centripetal for Catmull-Rom (the choice that never forms cusps or
** self-intersections inside a segment).
*/
typedef enum cf_param {
    CF_PARAM_DEFAULT = 0,
    CF_PARAM_UNIFORM,
    CF_PARAM_CHORD,
    CF_PARAM_CENTRIPETAL,
    CF_PARAM_POWER
} cf_param_t;

/*
** The parameters of count points: out[count] values from 0 to 1, or, when
** closed, out[count + 1] values where the last one belongs to the closing
** chord P_{count-1} -> P_0.  CF_PARAM_DEFAULT means chord length here.
** Consecutive points must be distinct (DEGENERATE, naming both points and
** their coordinates), also P_{count-1} and P_0 when closed.  count >= 2.
** exponent is used by CF_PARAM_POWER only and must lie in [0, 1].
*/
CF_API cf_status_t cf_interp_parameters(size_t dim, const double *points,
                                        size_t count, cf_param_t param,
                                        double exponent, bool closed,
                                        double *out, cf_diag_t *diag);

/* ---- interpolation through points --------------------------------------- */

typedef enum cf_interp_method {
    CF_INTERP_NATURAL = 0, /* cubic, C^2, C'' = 0 at both ends */
    CF_INTERP_CLAMPED,     /* cubic, C^2, given end tangents */
    CF_INTERP_NOT_A_KNOT,  /* cubic, C^3 across u_1 and u_{n-1} */
    CF_INTERP_PERIODIC,    /* cubic, closed, C^2 everywhere (also at P_0) */
    CF_INTERP_CATMULL_ROM, /* cubic, C^1, local; open or closed */
    CF_INTERP_GLOBAL       /* any degree p, C^{p-1} (The NURBS Book A9.1) */
} cf_interp_method_t;

typedef struct cf_interp_options {
    cf_interp_method_t method;
    /* Degree (0 means 3): 3 for every method but GLOBAL, which takes
    ** 1 .. CF_BSPLINE_MAX_DEGREE. */
    int degree;
    cf_param_t param;
    double exponent;       /* CF_PARAM_POWER only: e in [0, 1] */
    /* Optional explicit parameters overriding `param`: count finite,
    ** strictly increasing values (count + 1 for PERIODIC and closed
    ** Catmull-Rom: the last closes the curve; just count when the points
    ** already end with a copy of the first, which is then dropped).  They are used as given
    ** (not normalised): the curve's domain is [params[0], params[last]]. */
    const double *params;
    /* End derivatives dC/du (dim doubles each, with respect to the curve's
    ** parameter, whose domain is [0, 1] unless `params` is given; so a unit
    ** direction times the total chord length gives a natural speed).
    ** CLAMPED needs both; GLOBAL takes either, both or none; the other
    ** methods take none. */
    const double *start_tangent;
    const double *end_tangent;
    /* Closed Catmull-Rom (the last point joins the first).  PERIODIC is
    ** always closed; any other method rejects closed = true. */
    bool closed;
} cf_interp_options_t;

/* Defaults: NATURAL, degree 3, CF_PARAM_DEFAULT, no tangents, open. */
CF_API void cf_interp_options_init(cf_interp_options_t *opt);

/*
** The curve through count points (opt NULL = defaults).  The result is a
** polynomial B-spline on [0, 1] (or on the explicit parameters) with
** C(u_i) = P_i for every point:
**
**  NATURAL, CLAMPED  cubic, clamped knots {u_0 x4, u_1, ..., u_{n-1},
**                    u_n x4}, n + 3 control points; count >= 2.
**  NOT_A_KNOT        cubic, knots u_1 and u_{n-1} left out (so the first two
**                    and the last two pieces are one cubic each); count
**                    >= 4 (with 4 points the single cubic through them).
**  PERIODIC          cubic through P_0..P_n and back to P_0, C^2 also at
**                    P_0: a periodic B-spline (knot kind CF_KNOTS_PERIODIC,
**                    control points wrapped: the last 3 repeat the first 3)
**                    on [0, 1] with C(0) = C(1) = P_0; count >= 3.  A last
**                    point equal to the first is taken as the closing point
**                    and dropped.
**  CATMULL_ROM       cubic, C^1: on [u_i, u_{i+1}] the Hermite cubic with
**                    the Barry-Goldman tangents
**                      m_i = (P_i - P_{i-1}) / (u_i - u_{i-1})
**                          - (P_{i+1} - P_{i-1}) / (u_{i+1} - u_{i-1})
**                          + (P_{i+1} - P_i) / (u_{i+1} - u_i),
**                    stored as a clamped B-spline with double interior knots
**                    (control points: P_0, then the two inner Bézier points
**                    of every piece, then P_n; cf_bspline_to_beziers gives
**                    the pieces).  Open curves take m_0 = (P_1 - P_0) /
**                    (u_1 - u_0) and likewise at P_n (phantom end points
**                    reflected through P_0 and P_n); count >= 2.  Closed:
**                    indices wrap, count >= 3 (a repeated first point at
**                    the end is dropped), C^1 also at P_0.
**  GLOBAL            degree p, clamped, knots averaged from the parameters
**                    (The NURBS Book eq. 9.8; with end derivatives the end
**                    parameters are repeated in the average, eq. 9.22);
**                    count + number of end derivatives >= p + 1.
**
** The cubic methods solve banded (or, PERIODIC, cyclic tridiagonal)
** collocation systems; they are exact interpolants up to rounding.
** Parameters made from the points must increase strictly: a distance lost
** in the rounding of their running sum (below about 1e-16 of the chords
** before it) gives two points one parameter, DEGENERATE naming both.
*/
CF_API cf_status_t cf_interpolate(size_t dim, const double *points,
                                  size_t count, const cf_interp_options_t *opt,
                                  cf_bspline_t **out, cf_diag_t *diag);

/* Names used by the figure language: "natural", "clamped", "not-a-knot",
** "periodic", "catmull-rom", "global"; and "uniform", "chord",
** "centripetal" (also "default").  INVALID_ARG with the list of valid
** names otherwise. */
CF_API cf_status_t cf_interp_method_from_string(const char *name,
                                                cf_interp_method_t *out,
                                                cf_diag_t *diag);
CF_API cf_status_t cf_param_from_string(const char *name, cf_param_t *out,
                                        cf_diag_t *diag);
CF_API const char *cf_interp_method_to_string(cf_interp_method_t method);

/* ---- least squares ------------------------------------------------------ */

/*
** Least-squares approximation (The NURBS Book §9.4.1, solved by Givens
** rotations on the banded matrix instead of normal equations: O(count p^2)
** time, O(ncontrol p) memory): the B-spline of degree p with ncontrol
** control points, clamped knots placed by eq. 9.69 (every knot span holds
** data parameters), minimising sum_k |C(u_k) - P_k|^2 over the data
** parameters u_k (opt->param, opt->exponent, opt->params as for
** cf_interpolate, CF_PARAM_DEFAULT = chord; opt->degree 0 means 3;
** opt->method is ignored; tangents and closed are rejected).  fix_ends: C(u_0) = P_0 and C(u_n) = P_n
** exactly, the rest in the least-squares sense (as in the book).
** Requirements: p + 1 <= ncontrol <= count (ncontrol == count
** interpolates).  *residual (may be NULL) receives
** sqrt(sum_k |C(u_k) - P_k|^2), evaluated on the result.
*/
CF_API cf_status_t cf_approximate_lsq(size_t dim, const double *points,
                                      size_t count, size_t ncontrol,
                                      const cf_interp_options_t *opt,
                                      bool fix_ends, cf_bspline_t **out,
                                      double *residual, cf_diag_t *diag);

/* ---- chapter 4: Ferguson and Coons cubics ------------------------------- */

/*
** Ferguson (Hermite) cubic from P_0, P_1 and the tangent vectors T_0, T_1
** (derivatives at t = 0 and t = 1):
**   C(t) = F0(t) P_0 + F1(t) P_1 + F2(t) T_0 + F3(t) T_1,
** F0 = 2t^3 - 3t^2 + 1, F1 = -2t^3 + 3t^2, F2 = t^3 - 2t^2 + t,
** F3 = t^3 - t^2; as a Bézier cubic with control points
** P_0, P_0 + T_0 / 3, P_1 - T_1 / 3, P_1.  Tangents may be zero.
*/
CF_API cf_status_t cf_ferguson_cubic(size_t dim, const double *p0,
                                     const double *p1, const double *t0,
                                     const double *t1, cf_bezier_t **out,
                                     cf_diag_t *diag);

/*
** C^1 chain of Ferguson cubics through count >= 2 points with a tangent
** vector at each (tangents[count * dim]): segment i joins P_i and P_{i+1}
** with tangents T_i and T_{i+1}; in the chain's parameter s = i + t the
** chain is C^1 (list t0[i] = i, t1[i] = i + 1).
*/
CF_API cf_status_t cf_ferguson_chain(size_t dim, const double *points,
                                     const double *tangents, size_t count,
                                     cf_bezier_list_t **out, cf_diag_t *diag);

/*
** Coons cubic: the uniform cubic B-spline segment of four points
** (p4[4 * dim]), thesis §4.3.2, as a Bézier cubic:
**   B_0 = (P_0 + 4 P_1 + P_2) / 6, B_1 = (2 P_1 + P_2) / 3,
**   B_2 = (P_1 + 2 P_2) / 3,       B_3 = (P_1 + 4 P_2 + P_3) / 6.
** It does not pass through P_0 or P_3 in general.
*/
CF_API cf_status_t cf_coons_cubic(size_t dim, const double *p4,
                                  cf_bezier_t **out, cf_diag_t *diag);

/*
** Chain of Coons cubics (the uniform cubic B-spline of §4.3.4 as Bézier
** pieces): segment Q_j from the window P_{j-3}..P_j of the point sequence
** after the end treatment of cf_coons_ends_t (bspline.h): PLAIN (count >=
** 4, count - 3 segments), TRIPLED (P_0 and P_n tripled, count >= 2, count
** + 1 segments, starts at P_0, ends at P_n), CLOSED (P_0, P_1, P_2
** repeated at the end, count >= 3, count segments, a closed C^2 curve).
** Item i covers [i, i + 1] of the B-spline parameter (t0, t1).
*/
CF_API cf_status_t cf_coons_chain(size_t dim, const double *points,
                                  size_t count, cf_coons_ends_t ends,
                                  cf_bezier_list_t **out, cf_diag_t *diag);

#ifdef __cplusplus
}
#endif

#endif
