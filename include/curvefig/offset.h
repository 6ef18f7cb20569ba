/*
** Offset (parallel) curves of planar Bézier, rational Bézier, B-spline and
** NURBS curves.
**
** The offset of c at signed distance d is o(t) = c(t) + d n(t), with n the
** unit normal turned +90 degrees from the direction of travel: d > 0 lies
** LEFT of the direction of travel, d < 0 right.  Where c'(t) = 0 the
** direction comes from the first non-vanishing higher derivative (the limit
** from the right, and from the left at t = 1), never NaN.
**
** Cusps.  o'(t) = c'(t) (1 - d kappa(t)) with kappa the signed curvature, so
** the offset has a cusp where the radius of curvature equals |d| on the side
** of d: d (c' x c'') = |c'|^3.  For a polynomial curve of degree n these are
** roots of the Bernstein polynomial |c'|^6 - d^2 (c' x c'')^2 (degree 6n - 6,
** 12 for a cubic) with d (c' x c'') > 0.  For a rational curve with
** homogeneous H = (P, W) the same condition reads
** |D|^6 - d^2 (D x D')^2 W^4 = 0 with D = P'W - PW' (c' = D / W^2,
** c' x c'' = D x D' / W^4), degree 12n - 6.  The roots are isolated in
** Bernstein form by subdivision with Descartes' rule of signs (a close pair
** of roots is separated, not missed as a sign-change scan would) and
** polished by Newton's method on the curve itself.
**
** Approximation.  The offset is returned as a chain of polynomial cubic
** Béziers within an absolute tolerance.  The curve is split at the cusps and
** at the points where c' = 0; each cusp-free interval is covered greedily by
** the longest pieces whose fit is within tolerance.  CF_OFFSET_LEVIEN fits
** each piece with matching end points and end tangents plus the signed area
** and the x-moment of the exact piece (Levien's parallel-curve fit, error
** O(h^6)); the candidates (roots of the moment equation, a Hermite cubic and
** an equal-arm area fit) are compared by their measured error.
** CF_OFFSET_TILLER_HANSON translates the legs of the control polygon by d and
** intersects consecutive legs (error O(h^2)); it is the baseline, for
** polynomial pieces of degree <= 3 only.
**
** Error.  Every piece's error is measured as a two-sided Hausdorff estimate
** against the exact offset on its parameter range (dense sampling, local
** refinement of every nearest distance and of the maximum).  The report
** gives the largest over everything returned, the raw pieces and (when
** trimming) the trimmed ones; if a piece cannot reach the tolerance above
** a minimum parameter width (1e-9 of its interval) it is kept and
** report.converged is false.  A tolerance below what doubles resolve,
** 4096 DBL_EPSILON times the largest of |d| and the control points'
** coordinates (about 9e-13 of that size), is refused (INVALID_ARG), and
** so are coordinates or distances beyond 1e100 (the fits' cubes of them
** overflow).  A cover that would take more than 20,000 pieces of one
** cusp-free interval, or 2,000,000 in all, ends with NO_CONVERGENCE.
**
** Joins.  Where c' = 0 inside a curve (a cusp of the base curve, e.g.
** (0,0) (128,128) (128,0) (0,128)) and between Bézier pieces of a spline
** that meet at an angle, the two offset ends are joined by a circular arc of
** radius |d| about the base point, turning with the curve (a round join), so
** the raw offset is always one continuous chain.
**
** Trimming.  The raw offset of a curve whose curvature radius drops below |d|
** on the side of d has swallowtails and loops.  The trimmed offset (the
** boundary of the swept disk on that side) is obtained by splitting the raw
** chain at its self-intersections and dropping the parts whose distance to
** the base curve is smaller than |d| - tolerance.  It is a list of chains.
** A raw piece that is cut is fitted again (Levien's fit, whatever the
** method; split in two if it must be) on the parameter range of the exact
** offset it keeps: from the crossing of the exact offset (Newton's method
** from the raw crossing; both chains end at that point) or from where the
** exact offset's distance to the curve reaches |d| - 0.03 tolerance.  The
** trimmed offset is so within the tolerance of the exact one on the same
** ranges, at most one piece more per cut end than the raw pieces it
** overlaps.
*/
#ifndef CURVEFIG_OFFSET_H
#define CURVEFIG_OFFSET_H

#include "curvefig/core.h"
#include "curvefig/bezier.h"
#include "curvefig/bspline.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum cf_offset_method {
    CF_OFFSET_LEVIEN = 0,       /* area + moment fit, O(h^6) */
    CF_OFFSET_TILLER_HANSON     /* translated control polygon, O(h^2) */
} cf_offset_method_t;

typedef struct cf_offset_options {
    double tolerance;           /* absolute, > 0; default 1e-3 */
    cf_offset_method_t method;  /* default CF_OFFSET_LEVIEN */
    bool trim;                  /* also compute the trimmed offset */
} cf_offset_options_t;

/* Defaults: tolerance 1e-3, Levien fit, no trimming. */
CF_API void cf_offset_options_init(cf_offset_options_t *opt);

typedef struct cf_offset_report {
    size_t segments;            /* cubics in the raw offset */
    double max_error;           /* largest measured error of a returned
                                ** piece (raw, and trimmed when trimming) */
    bool converged;             /* every piece within tolerance */
    size_t cusps;               /* offset cusps found (split points) */
    size_t joins;               /* round joins (c' = 0 inside, corners) */
    size_t self_intersections;  /* of the raw offset (when trimming) */
    size_t trimmed_chains;      /* chains of the trimmed offset */
    size_t trimmed_segments;    /* cubics in the trimmed offset */
} cf_offset_report_t;

/* A list of cubic chains (the trimmed offset).  Each chain is continuous;
** chains[i]->t holds parameters of the source curve (see below). */
typedef struct cf_cubics_list {
    size_t count;
    cf_cubics_t **chains;
} cf_cubics_list_t;

CF_API void cf_cubics_list_destroy(cf_cubics_list_t *list);

/* ---- exact offset ------------------------------------------------------- */

/* out[2] = c(t) + d n(t) for a planar (dim 2) curve, polynomial or
** rational; t in [0, 1] (the rule of bezier.h).  Never allocates.  DEGENERATE if every derivative
** vanishes (a single point) and d != 0. */
CF_API cf_status_t cf_offset_point(const cf_bezier_t *c, double t, double d,
                                   double *out);

/* out[2 * n]: the offset at n parameters (allocation-free batch form). */
CF_API cf_status_t cf_offset_point_many(const cf_bezier_t *c, const double *t,
                                        size_t n, double d, double *out);

/* The cusp parameters of the offset at d inside (0, 1), ascending: the
** parameters where the radius of curvature equals |d| on the side of d.
** Writes min(count, cap) of them into ts (ts may be NULL when cap == 0) and
** the total into *count. */
CF_API cf_status_t cf_offset_cusps(const cf_bezier_t *c, double d, double *ts,
                                   size_t cap, size_t *count, cf_diag_t *diag);

/* ---- approximation by cubics -------------------------------------------- */

/*
** The offset of a planar curve as a chain of cubics.  opt may be NULL for
** the defaults.  *raw (may be NULL) receives the raw offset: one continuous
** chain, raw->t[i] .. raw->t[i + 1] the parameter range of c that piece i
** offsets (equal for a join arc), raw->max_error the largest measured error.
** *trimmed (may be NULL; computed when opt->trim) receives the trimmed
** offset; its chains carry the parameters of c that their pieces offset
** (a cut piece the part of its raw range it keeps) and their measured
** max_error.  rep may be NULL.  d == 0 gives the curve
** itself (cf_bezier_to_cubics).  Release with cf_cubics_destroy and
** cf_cubics_list_destroy.
*/
CF_API cf_status_t cf_bezier_offset(const cf_bezier_t *c, double d,
                                    const cf_offset_options_t *opt,
                                    cf_cubics_t **raw,
                                    cf_cubics_list_t **trimmed,
                                    cf_offset_report_t *rep, cf_diag_t *diag);

/*
** The same for a piecewise curve given as consecutive Bézier pieces (the
** result of a B-spline's or NURBS's conversion to Béziers; consecutive pieces
** must meet).  Parameters in the output are those of list->t0/t1 when given
** (the spline's knots), otherwise piece i covers [i, i + 1].
*/
CF_API cf_status_t cf_bezier_list_offset(const cf_bezier_list_t *list,
                                         double d,
                                         const cf_offset_options_t *opt,
                                         cf_cubics_t **raw,
                                         cf_cubics_list_t **trimmed,
                                         cf_offset_report_t *rep,
                                         cf_diag_t *diag);

/* A B-spline or NURBS curve (dim 2): its Bézier pieces
** (cf_bspline_to_beziers) through cf_bezier_list_offset; parameters in the
** output are the spline's. */
CF_API cf_status_t cf_bspline_offset(const cf_bspline_t *s, double d,
                                     const cf_offset_options_t *opt,
                                     cf_cubics_t **raw,
                                     cf_cubics_list_t **trimmed,
                                     cf_offset_report_t *rep, cf_diag_t *diag);

/*
** Independent check of an offset approximation of c at d: the two-sided
** Hausdorff distance between every piece of `approx` whose range
** [t[i], t[i+1]] is non-empty and the exact offset on that range, by dense
** uniform sampling of both (samples per piece, >= 16) and refinement of the
** nearest distances on a polyline of the other curve.  Join arcs (empty
** ranges) are measured against the circle of radius |d| about c(t[i]).
** An upper bound, up to sampling, of the Hausdorff distance of the unions.
*/
CF_API cf_status_t cf_offset_measure(const cf_bezier_t *c, double d,
                                     const cf_cubics_t *approx, size_t samples,
                                     double *error, cf_diag_t *diag);

#ifdef __cplusplus
}
#endif

#endif
