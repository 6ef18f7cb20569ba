/* The helpers the B-spline tests share (test_bspline.c, test_bspline_ops.c,
** test_bspline_nurbs.c): the thesis's sample curve, random curves and their
** checks; static inline, as not every file uses each. */
#ifndef CURVEFIG_TESTS_TEST_BSPLINE_H
#define CURVEFIG_TESTS_TEST_BSPLINE_H

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/bspline.h"
#include "../../src/bspline-private.h"
#include "testutil.h"

#define EPS 2.220446049250313e-16

/* The thesis's sample curve (§2.10, figure 2.17). */
static const double SAMPLE_P[16] = { 3, 1, 3.75, 2, 5, 3, 4, 4,
                                     3, 3, 2, 4, 1, 3, 2.25, 2 };

static const double SAMPLE_U[11] = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83,
                                     1, 1, 1 };

static inline cf_bspline_t *
sample(void)
{
    cf_bspline_t *c = NULL;
    assert_int_equal(cf_bspline_create(2, 2, SAMPLE_U, 11, SAMPLE_P, 8, NULL,
                                       &c, NULL), CF_STATUS_OK);
    return c;
}

/* Largest |Cartesian coordinate| of the control points: the curve's size
** for relative tolerances. */
static inline double
size_of(const cf_bspline_t *c)
{
    size_t n = cf_bspline_count(c) * cf_bspline_dim(c);
    double *pts = malloc(n * sizeof *pts), s = 0.0;
    cf_bspline_get_points(c, pts);
    for (size_t i = 0; i < n; i++)
        s = fmax(s, fabs(pts[i]));
    free(pts);
    return s;
}

/* count random points in [-10, 10]^dim into P, weights in [0.3, 3] into
** W. */
static inline void
random_points(tu_rng *r, size_t count, size_t dim, double *P, double *W)
{
    for (size_t j = 0; j < count * dim; j++)
        P[j] = tu_rng_range(r, -10.0, 10.0);
    for (size_t j = 0; j < count; j++)
        W[j] = tu_rng_range(r, 0.3, 3.0);
}

/* A random curve: degree p, count points in R^dim, random knots with
** repeated interior knots (multiplicity <= p), clamped or open, rational
** or not. */
static inline cf_bspline_t *
random_curve(tu_rng *r, size_t dim, int p, size_t count, bool clamp,
             bool rational)
{
    size_t nk = count + (size_t)p + 1, i = 0, end = nk;
    double *U = malloc(nk * sizeof *U), *P = malloc(count * dim * sizeof *P);
    double *W = malloc(count * sizeof *W), x = 0.0;
    cf_bspline_t *c = NULL;
    cf_diag_t d;
    if (clamp) {
        for (; i <= (size_t)p; i++)
            U[i] = 0.0;
        end = nk - (size_t)p - 1;
        x = tu_rng_range(r, 0.1, 1.0);
    }
    while (i < end) {
        size_t run = 1;
        if (p > 1 && tu_rng_u01(r) < 0.2)
            run = 1 + (size_t)(tu_rng_u01(r) * (double)p);
        for (size_t j = 0; j < run && i < end; j++)
            U[i++] = x;
        x += tu_rng_range(r, 0.1, 1.0);
    }
    for (; i < nk; i++)
        U[i] = x;
    random_points(r, count, dim, P, W);
    cf_diag_clear(&d);
    if (cf_bspline_create(dim, p, U, nk, P, count, rational ? W : NULL, &c,
                          &d) != CF_STATUS_OK) {
        /* an open vector can have an empty domain: nudge the middle */
        U[p] = U[nk - 1 - (size_t)p] - 0.5;
        for (int j = p - 1; j >= 0; j--)
            if (U[j] > U[j + 1])
                U[j] = U[j + 1];
        cf_diag_clear(&d);
        if (cf_bspline_create(dim, p, U, nk, P, count, rational ? W : NULL,
                              &c, &d) != CF_STATUS_OK)
            fail_msg("random curve: %s", d.msg);
    }
    free(U);
    free(P);
    free(W);
    return c;
}

/* ---- evaluation --------------------------------------------------------- */

static inline int
cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

#endif
