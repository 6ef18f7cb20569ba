/*
** Internals of the cubic fitting (prefix cf__) that both the drawing of
** curves (bezier-cubics.c: cf__fit_plain) and the offsets (offset.c) use:
**   fit-cusp.c      cusp polynomial, cusps and zeros of c'
**   fit-source.c    the exact curves a piece approximates (an offset of a
**                   Bézier curve, the curve itself at d = 0, a join arc)
**                   and the error measurement
**   fit-piece.c     Levien and Tiller-Hanson fits of one piece, cusp pieces
**   fit-chain.c     the chain driver: splits, greedy covers, joins
** The offsets alone: offset.c (public entry points and the independent
** measure), offset-trim.c with offset-trim-map.c and offset-refit.c
** (self-intersections of the raw chain and trimming:
** offset-trim-private.h).
*/
#ifndef CURVEFIG_FIT_PRIVATE_H
#define CURVEFIG_FIT_PRIVATE_H

#include <stdbool.h>
#include <stddef.h>

#include "curvefig/offset.h"
#include "bpoly-private.h"
#include "cubics-private.h"

/* ---- sources: the exact curves that pieces approximate ----------------- */

typedef struct cf__osrc {
    int kind;               /* 0: offset of a Bézier, 1: circular arc */
    const cf_bezier_t *c;
    double d;
    double sgn;             /* travel direction of o relative to c' (+-1) */
    double scale;           /* size of c' (for "vanishes" tests) */
    double cx, cy, r, a0, sweep;   /* arc: centre, radius, angles */
    /* offset cusps at the ends of the interval being covered (-1: none);
    ** a piece that ends exactly at one is fitted with both arms optimised
    ** on the measured error (the offset is a semicubical cusp there) */
    double cusp_a, cusp_b;
} cf__osrc_t;

/* Initialise an offset source of c at d (dim 2); scale from the points. */
void cf__osrc_init_offset(cf__osrc_t *s, const cf_bezier_t *c, double d);
void cf__osrc_init_arc(cf__osrc_t *s, double cx, double cy, double r,
                       double a0, double sweep);
/* Point at t (side: which limit where c' = 0) and travel direction u (may
** be NULL).  Returns -1 where the direction is undefined (u = 0). */
int cf__osrc_point_dir(const cf__osrc_t *s, double t, int side, double *p,
                       double *u);
/* Point and derivative with respect to t (for quadrature). */
int cf__osrc_deriv(const cf__osrc_t *s, double t, double *p, double *dp);

/* Unit tangent of c at t (side < 0: limit from the left, else from the
** right) using higher derivatives where c' vanishes; base point in p (may
** be NULL).  Returns 0, or -1 if every derivative vanishes. */
int cf__bezier_unit_tangent(const cf_bezier_t *c, double t, int side,
                            double scale, double *p, double *u);

/* A parametrised curve on [0, 1]: point and derivative at u. */
typedef void (*cf__pd_fn)(const void *ctx, double u, double *p, double *dp);
/* Distance from q to the curve fn, given its samples smp[0..k] at u = i/k:
** the nearest sample, then foot points in the neighbouring intervals. */
double cf__dist_sampled(cf__pd_fn fn, const void *ctx, const double *smp,
                        int k, const double *q);

/* ---- fitting ----------------------------------------------------------- */

typedef struct cf__fit {
    double pts[8];          /* the cubic */
    double err;             /* its measured error */
} cf__fit_t;

/* Fit the source on [a, b] by `method`, measuring the error (two-sided
** Hausdorff estimate).  A fit whose coarse estimate already exceeds
** `reject` is returned with that estimate only. */
cf_status_t cf__fit_piece(const cf__osrc_t *s, double a, double b,
                          cf_offset_method_t method, double reject,
                          cf__fit_t *out);

/* Sample counts of the error estimates: quick screening, coarse, fine. */
#define CF__FIT_K_QUICK 4
#define CF__FIT_K_COARSE 12
#define CF__FIT_K_FINE 40

/* Two-sided Hausdorff estimate between the source on [a, b] and the cubic
** pts[8], with k samples each side (k >= 4). */
cf_status_t cf__fit_error(const cf__osrc_t *s, double a, double b,
                          const double *pts, int k, double *err);

/* ---- cusps --------------------------------------------------------------- */

/* Interior offset cusps of c at d (sorted) into a new array (cf__free). */
cf_status_t cf__offset_cusps_alloc(const cf_bezier_t *c, double d,
                                   double **ts, size_t *n);
/* Interior zeros of c' (cusps of the base curve), sorted, new array. */
cf_status_t cf__base_cusps_alloc(const cf_bezier_t *c, double **ts,
                                 size_t *n);
/* A size of c' for relative tests: degree * max |P_i - P_0|. */
double cf__deriv_scale(const cf_bezier_t *c);

/* ---- the chain driver (fit-chain.c) ---------------------------------- */

/* The most pieces the greedy cover of one cusp-free interval takes, and
** one offset chain in all: far beyond what a reachable tolerance needs (a
** cubic at 1e-9 of its size takes some tens), so that a fit that cannot
** converge ends with NO_CONVERGENCE instead of covering its interval with
** pieces of the minimum width for ever. */
#define CF__OFFSET_MAX_COVER 20000
#define CF__OFFSET_MAX_PIECES 2000000

/* The cover of pieces by fitted cubics: splits at offset cusps and zeros
** of c', greedy longest pieces (Levien) or bisection (Tiller-Hanson), round
** joins; the report accumulates. */
typedef struct cf__driver {
    cf__chain_t chain;
    double tol;
    cf_offset_method_t method;
    double d;
    double T0, T1;              /* parameter range of the current piece */
    cf_offset_report_t rep;
} cf__driver_t;

/* A driver with an empty chain (NO_MEMORY only). */
cf_status_t cf__driver_init(cf__driver_t *dr, double tol,
                            cf_offset_method_t method, double d);
/* Append the offset of the planar piece c (parameters [T0, T1]). */
cf_status_t cf__driver_piece(cf__driver_t *dr, const cf_bezier_t *c);
/* The round join between consecutive pieces that meet at an angle. */
cf_status_t cf__driver_join(cf__driver_t *dr, const cf_bezier_t *prev,
                            const cf_bezier_t *next);

/* The planar curve c itself (not a polynomial of degree <= 3) as a chain
** of cubics fitted by the offset machinery at d = 0 (split at the zeros of
** c', greedy longest Levien fits); max_error set, *converged false if some
** piece could not reach tol.  NO_MEMORY, NO_CONVERGENCE (empty chain). */
cf_status_t cf__fit_plain(const cf_bezier_t *c, double tol,
                          cf_cubics_t **out, bool *converged);

#endif
