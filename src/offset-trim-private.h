/*
** Internals shared by the files of the trim (prefix cf__trim_):
**   offset-trim-map.c  the raw chain against its exact offsets: parameter
**                      maps, projections, distances to the base curve
**   offset-refit.c     kept parts of the raw chain, cut pieces fitted again
**   offset-trim.c      self-intersections, classification, the driver
** The trim state, the split points and cuts, and the tolerances that tie
** the classification to the refit.
*/
#ifndef CURVEFIG_OFFSET_TRIM_PRIVATE_H
#define CURVEFIG_OFFSET_TRIM_PRIVATE_H

#include <math.h>
#include <stdbool.h>
#include <stddef.h>

#include "fit-private.h"

#define CF__TRIM_POLY_N 64      /* polyline samples per raw cubic */
#define CF__TRIM_BASE_N 256     /* samples of each base piece */
/* A refitted piece is accepted at CF__TRIM_ACCEPT tol (as the raw pieces
** are); a transition of the exact offset is where its distance to the base
** reaches |d| - CF__TRIM_KEEP tol, so that its refitted piece stays at
** distance >= |d| - tol. */
#define CF__TRIM_ACCEPT 0.97
#define CF__TRIM_KEEP 0.03

/* A split point of the raw chain; at a self-intersection, p is the
** crossing of the exact offset (when found) that the trimmed pieces end
** at, and T the source parameter of that crossing on this branch. */
typedef struct cf__trim_split {
    double g;
    double p[2];
    double T;
    bool exact;
} cf__trim_split_t;

/* The end of a kept part: the exact offset's parameter T there (when
** known) and the point it must end at (an exact crossing, or NULL). */
typedef struct cf__trim_cut {
    bool has_T;
    double T;
    const double *snap;
} cf__trim_cut_t;

/* The state of one trim: the base pieces and their samples, the raw
** chain and its polylines, the split points found so far. */
typedef struct cf__trim {
    const cf_bezier_t *const *base;
    size_t nbase;
    const double *t0, *t1;  /* source parameters of the base pieces */
    double *bsmp;           /* CF__TRIM_BASE_N + 1 samples per base piece */
    double d, tol;
    const cf_cubics_t *raw;
    double *poly;           /* CF__TRIM_POLY_N + 1 samples per raw cubic */
    cf__trim_split_t *splits; /* at global parameters i + s */
    size_t nsplit, capsplit;
    size_t nisect;
} cf__trim_t;

/* ---- parameter maps (g: the raw chain's i + s; T: the source's
** parameter; t: base piece k's own parameter) ---------------------------- */

/* The raw piece holding global parameter g. */
static inline size_t
cf__trim_piece_at(const cf__trim_t *tr, double g)
{
    size_t i = (size_t)floor(fmax(0.0, g));
    return i < tr->raw->count ? i : tr->raw->count - 1;
}

/* Source parameters of base piece k (those of the raw chain's t). */
static inline double
cf__trim_base_T0(const cf__trim_t *tr, size_t k)
{
    return tr->t0 != NULL ? tr->t0[k] : (double)k;
}

static inline double
cf__trim_base_T1(const cf__trim_t *tr, size_t k)
{
    return tr->t1 != NULL ? tr->t1[k] : (double)k + 1.0;
}

/* The base piece whose range holds T (the first at a shared end). */
static inline size_t
cf__trim_base_of(const cf__trim_t *tr, double T)
{
    for (size_t k = 0; k + 1 < tr->nbase; k++)
        if (T <= cf__trim_base_T1(tr, k))
            return k;
    return tr->nbase - 1;
}

/* Source parameter T to the parameter of base piece k and back. */
static inline double
cf__trim_to_local(const cf__trim_t *tr, size_t k, double T)
{
    double T0 = cf__trim_base_T0(tr, k), T1 = cf__trim_base_T1(tr, k);
    return T1 > T0 ? fmin(1.0, fmax(0.0, (T - T0) / (T1 - T0))) : 0.0;
}

static inline double
cf__trim_to_global(const cf__trim_t *tr, size_t k, double t)
{
    double T0 = cf__trim_base_T0(tr, k), T1 = cf__trim_base_T1(tr, k);
    return T0 + t * (T1 - T0);
}

/* Source parameter T of the raw chain's g on a non-arc piece i (linear in
** the piece). */
static inline double
cf__trim_g_to_T(const cf__trim_t *tr, size_t i, double g)
{
    const cf_cubics_t *raw = tr->raw;
    double s = fmin(1.0, fmax(0.0, g - (double)i));
    return raw->t[i] + s * (raw->t[i + 1] - raw->t[i]);
}

/* The raw chain's g of source parameter T on raw piece i. */
static inline double
cf__trim_T_to_g(const cf__trim_t *tr, size_t i, double T)
{
    const cf_cubics_t *raw = tr->raw;
    return (double)i + fmin(1.0, fmax(0.0, (T - raw->t[i]) /
                                               (raw->t[i + 1] - raw->t[i])));
}

/* ---- offset-trim-map.c ---------------------------------------------------
 */

/* Distance of q to the base curve (all pieces). */
double cf__trim_base_dist(const cf__trim_t *tr, const double *q);
/* Point of the raw chain at global parameter g = i + s. */
void cf__trim_chain_point(const cf__trim_t *tr, double g, double *p);
/* The exact offset that raw piece i approximates (on base piece *k, with
** its travel direction); -1 for a join arc (an empty range). */
int cf__trim_piece_source(const cf__trim_t *tr, size_t i, cf__osrc_t *src,
                          size_t *k);
/* The source parameter T of the point of the exact offset of raw piece i
** (src, on base piece k) nearest q. */
double cf__trim_project(const cf__trim_t *tr, size_t i, const cf__osrc_t *src,
                        size_t k, const double *q);
/* Inside the swept disk at source parameter T of base piece k's exact
** offset (closer to the base than |d| - CF__TRIM_KEEP tol). */
bool cf__trim_exact_inside(const cf__trim_t *tr, const cf__osrc_t *src,
                           size_t k, double T);
/* Bisection between t_in (inside) and t_out (kept) on the source: the
** kept end of the last bracket. */
double cf__trim_bisect_keep(const cf__trim_t *tr, const cf__osrc_t *src,
                            double t_in, double t_out);
/* A cut at u_cut of the source, kept towards u_kept, moved to where the
** source's distance reaches |d| - CF__TRIM_KEEP tol (unchanged if it is
** not inside or u_kept is inside too). */
double cf__trim_src_keep(const cf__trim_t *tr, const cf__osrc_t *src,
                         double u_cut, double u_kept);

/* ---- offset-refit.c ------------------------------------------------------
 */

/* Append the part [g0, g1] of the raw chain to ch.  Whole raw pieces are
** kept as they are; a piece cut at c0 or c1 is fitted again on the range
** of the exact offset it now covers, an end at an exact crossing (snap)
** placed on it. */
cf_status_t cf__trim_append_part(cf__trim_t *tr, cf__chain_t *ch, double g0,
                                 double g1, const cf__trim_cut_t *c0,
                                 const cf__trim_cut_t *c1);

/* Trim the raw chain of the pieces `base[0..n-1]` (source parameters
** [t0[k], t1[k]], or [k, k + 1] when NULL) at d: split at the
** self-intersections and keep the parts at distance >= |d| - tol, a cut
** piece fitted again; each chain's max_error is its measured error. */
cf_status_t cf__offset_trim(const cf_bezier_t *const *base, size_t nbase,
                            const double *t0, const double *t1, double d,
                            double tol, const cf_cubics_t *raw,
                            cf_cubics_list_t **out, size_t *nisect);

#endif
