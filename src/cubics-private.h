/*
** Chains of cubic segments shared by the fitters (prefix cf__): the growing
** chain and the exact conversion of polynomial curves of degree <= 3.
*/
#ifndef CURVEFIG_CUBICS_PRIVATE_H
#define CURVEFIG_CUBICS_PRIVATE_H

#include "curvefig/bezier.h"

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

#endif
