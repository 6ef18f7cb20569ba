/*
** The domain rule of every evaluator (docs/library.md, "Parameters at the
** ends of a domain"): a parameter that misses an end of [a, b] by at most
** 8 DBL_EPSILON max(|a|, |b|) is that end; one further out is
** CF_STATUS_DOMAIN, NaN and infinities are CF_STATUS_NOT_FINITE.
**
** cf__param_clamp is the rule; a batch evaluator runs it only for a
** parameter that failed its own (branch-free) a <= u <= b test, so the
** parameters inside the domain never pay for it.
*/
#ifndef CURVEFIG_DOMAIN_PRIVATE_H
#define CURVEFIG_DOMAIN_PRIVATE_H

#include <float.h>
#include <math.h>

#include "core-private.h"

/* How far outside [a, b] a parameter is still the end. */
#define CF__PARAM_SLACK(a, b) (8.0 * DBL_EPSILON * fmax(fabs(a), fabs(b)))

/* *u inside [a, b]: OK; within the slack outside: *u becomes that end,
** OK; otherwise DOMAIN or NOT_FINITE (*u unchanged). */
static inline cf_status_t
cf__param_clamp(double a, double b, double *u)
{
    double x = *u, s;
    if (x >= a && x <= b)
        return CF_STATUS_OK;
    if (!isfinite(x))
        return CF_STATUS_NOT_FINITE;
    s = CF__PARAM_SLACK(a, b);
    if (x < a && x >= a - s) {
        *u = a;
        return CF_STATUS_OK;
    }
    if (x > b && x <= b + s) {
        *u = b;
        return CF_STATUS_OK;
    }
    return CF_STATUS_DOMAIN;
}

/* cf__param_clamp, and on failure the message into diag (may be NULL):
** "parameter 1.0000000000000222 is outside the domain [0, 1]" (numbers
** with the digits that tell them apart), "parameter is nan". */
cf_status_t cf__param_check(double a, double b, double *u, cf_diag_t *diag);

#endif
