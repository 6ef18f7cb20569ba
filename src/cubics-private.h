/*
** Chains of cubic segments shared by the fitters (prefix cf__): the growing
** chain and the exact conversion of polynomial curves of degree <= 3.
*/
#ifndef CURVEFIG_CUBICS_PRIVATE_H
#define CURVEFIG_CUBICS_PRIVATE_H

#include <stddef.h>

#include "curvefig/bezier.h"
#include "bpoly-private.h"

/* A growing chain of cubics (dim 2). */
typedef struct cf__chain {
    cf_cubics_t *cubics;
    size_t cap;
} cf__chain_t;

cf_status_t cf__chain_init(cf__chain_t *ch);
/* Append a cubic covering source parameters [t0, t1] (t0 must equal the
** last end parameter; the first call sets the start). */
cf_status_t cf__chain_push(cf__chain_t *ch, const double *pts, double t0,
                           double t1);
/* Hand the chain over (NULL on an empty chain is not an error). */
cf_cubics_t *cf__chain_take(cf__chain_t *ch);
void cf__chain_fini(cf__chain_t *ch);

/* A polynomial curve of degree <= 3 as one cubic segment on [0, 1],
** exactly (degree raised to 3; max_error 0).  NO_MEMORY only. */
cf_status_t cf__cubics_exact(const cf_bezier_t *c, cf_cubics_t **out);

/* Point p[2] and derivative dp[2] (dp may be NULL) at s of the planar
** cubic segment pts[8] (four interleaved control points), by the curve
** evaluator of bpoly.c. */
static inline void
cf__cubic_pd(const double *pts, double s, double *p, double *dp)
{
    double v[4];
    cf__bp_curve_derivs(pts, NULL, 2, 2, 3, s, dp != NULL ? 1 : 0, v);
    p[0] = v[0];
    p[1] = v[1];
    if (dp != NULL) {
        dp[0] = v[2];
        dp[1] = v[3];
    }
}

#endif
