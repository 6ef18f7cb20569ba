/* The helpers the bezier tests share (test_bezier.c, test_bezier_convert.c,
** test_bezier_queries.c); static inline, as not every file uses each. */
#ifndef CURVEFIG_TESTS_TEST_BEZIER_H
#define CURVEFIG_TESTS_TEST_BEZIER_H

#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/bezier.h"
#include "testutil.h"

/* Seed 003: P0..P4 = (0,5) (1,-1) (3,0) (4,3) (6,10). */
static const double seed_pts[] = { 0, 5, 1, -1, 3, 0, 4, 3, 6, 10 };

/* A random curve: coordinates in [-1, 1] (times scale), weights in
** [0.2, 5] when rational. */
static inline cf_bezier_t *
random_curve(tu_rng *r, size_t dim, int degree, bool rational, double scale)
{
    double pts[(CF_BEZIER_MAX_DEGREE + 1) * 4], w[CF_BEZIER_MAX_DEGREE + 1];
    cf_bezier_t *c = NULL;
    assert_true(dim <= 4 && degree <= CF_BEZIER_MAX_DEGREE);
    for (size_t i = 0; i < ((size_t)degree + 1) * dim; i++)
        pts[i] = scale * tu_rng_range(r, -1.0, 1.0);
    for (int i = 0; i <= degree; i++)
        w[i] = exp(tu_rng_range(r, log(0.2), log(5.0)));
    assert_int_equal(cf_bezier_create(dim, degree, pts, rational ? w : NULL,
                                      &c, NULL), CF_STATUS_OK);
    return c;
}

/* Largest |coordinate| of the Cartesian control points. */
static inline double
curve_size(const cf_bezier_t *c)
{
    double pts[(CF_BEZIER_MAX_DEGREE + 1) * 4], m = 0.0;
    size_t n = ((size_t)cf_bezier_degree(c) + 1) * cf_bezier_dim(c);
    cf_bezier_get_points(c, pts);
    for (size_t i = 0; i < n; i++)
        m = fmax(m, fabs(pts[i]));
    return m;
}

#endif
