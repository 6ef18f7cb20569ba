/*
** Internals of the Bézier module shared with other core modules (B-splines,
** offsets, conics): the object layout and fast constructors that skip the
** input checks of the public API.
*/
#ifndef CURVEFIG_BEZIER_PRIVATE_H
#define CURVEFIG_BEZIER_PRIVATE_H

#include <math.h>
#include <stdbool.h>
#include <stddef.h>

#include "curvefig/bezier.h"
#include "core-private.h"
#include "domain-private.h"
#include "bpoly-private.h"

/*
** One allocation: the header followed by (degree + 1) * hdim doubles.
** hdim = dim + 1 for a rational curve (homogeneous (w x, w)), dim otherwise.
** Curves made together by cf__bezier_new_many live in one shared block
** instead (block: its count of live curves); each is still destroyed on
** its own, by cf_bezier_destroy, and the block goes with the last.
*/
typedef struct cf__bezier_block cf__bezier_block_t;

struct cf_bezier {
    size_t dim;      /* Cartesian dimension N >= 1 */
    size_t hdim;     /* doubles per stored point: dim + rational */
    int degree;      /* 0 .. CF_BEZIER_MAX_DEGREE */
    bool rational;
    cf__bezier_block_t *block;   /* NULL: the curve is its own block */
    double pts[];    /* (degree + 1) * hdim */
};

/* A curve with uninitialised points (fill c->pts), or NULL when out of
** memory or when the sizes overflow.  No other checks. */
cf_bezier_t *cf__bezier_new(size_t dim, int degree, bool rational);

/* n curves of one shape with uninitialised points in one block (one
** allocation for all): out[i] is the i-th, and curve i's points start
** i * *stride doubles after out[0]->pts.  false when out of memory or
** when the sizes overflow (out untouched). */
bool cf__bezier_new_many(size_t n, size_t dim, int degree, bool rational,
                         cf_bezier_t **out, size_t *stride);

/* The status of a curve parameter *t by the domain rule on [0, 1]
** (domain-private.h; *t clamped to an end it misses by rounding). */
static inline cf_status_t
cf__bezier_check_param(double *t)
{
    return cf__param_clamp(0.0, 1.0, t);
}

/* A list of count NULL items (t0/t1 allocated when with_params). */
cf_bezier_list_t *cf__bezier_list_new(size_t count, bool with_params);

/* Derivatives 0..k (k <= CF_BEZIER_MAX_DEGREE) of c at t into
** out[j * dim + d], exact (quotient rule for rational); no checks.  The
** evaluator of bpoly.c on the stored points. */
static inline void
cf__bezier_derivs(const cf_bezier_t *c, double t, int k, double *out)
{
    cf__bp_curve_derivs(c->pts, c->rational ? c->pts + c->dim : NULL,
                        c->hdim, c->dim, c->degree, t, k, out);
}

/* The Cartesian point at t into out[dim]; no checks. */
static inline void
cf__bezier_eval_point(const cf_bezier_t *c, double t, double *out)
{
    cf__bezier_derivs(c, t, 0, out);
}

/* Derivatives 0..k (k <= CF_BEZIER_MAX_DEGREE) of Cartesian coordinate
** `coord` at t into res[k + 1], exact (quotient rule for rational). */
static inline void
cf__bezier_coord_derivs(const cf_bezier_t *c, size_t coord, double t, int k,
                        double *res)
{
    cf__bp_curve_derivs(c->pts + coord,
                        c->rational ? c->pts + c->dim : NULL, c->hdim, 1,
                        c->degree, t, k, res);
}

/* Batch evaluation of points (no checks; t already validated): a fast
** Horner-Bernstein scheme for polynomial curves of low degree, de Casteljau
** otherwise.  Never allocates. */
cf_status_t cf__bezier_eval_many_fast(const cf_bezier_t *c, const double *t,
                                      size_t n, double *out);
/* The k-th derivative (k >= 1) at many parameters by the fast scheme on the
** hodograph; returns false (doing nothing) when the fast scheme does not
** apply (rational or high degree). */
bool cf__bezier_deriv_many_fast(const cf_bezier_t *c, const double *t,
                                size_t n, int k, double *out);

/* Largest |coordinate| of the Cartesian control points (the curve's size,
** for relative tolerances). */
double cf__bezier_size(const cf_bezier_t *c);

#endif
