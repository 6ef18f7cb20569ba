/*
** The C side of bench/python_eval.py: 10^6 parameters evaluated on a
** cubic Bézier curve and a cubic B-spline by the batch evaluators, the
** median of several runs, in ns per point, as one JSON line.  The curves
** and parameters are the ones the Python side evaluates (python_eval.py
** passes them as arguments: the B-spline's number of control points).
**
**   eval-points N_POINTS RUNS SPLINE_COUNT
*/
#include <stdio.h>
#include <stdlib.h>

#include "bench-time.h"
#include "curvefig/curvefig.h"

/* The B-spline's control points: P_i = (i, sin(i)), as python_eval.py. */
#include <math.h>

static double
median_ns(double *t, int runs, size_t n)
{
    qsort(t, (size_t)runs, sizeof t[0], cmp_double);
    return t[runs / 2] / (double)n * 1e9;
}

int
main(int argc, char **argv)
{
    size_t n = argc > 1 ? (size_t)atol(argv[1]) : 1000000;
    int runs = argc > 2 ? atoi(argv[2]) : 9;
    size_t count = argc > 3 ? (size_t)atol(argv[3]) : 20;
    static const double B[] = { 0, 0, 1, 2, 3, 2, 4, 0 };
    double *u = malloc(n * sizeof *u), *out = malloc(2 * n * sizeof *out);
    double *P = malloc(2 * count * sizeof *P), *tb, *ts;
    cf_bezier_t *bz = NULL;
    cf_bspline_t *bs = NULL;
    if (u == NULL || out == NULL || P == NULL || runs < 1 || n < 2)
        return 1;
    tb = malloc((size_t)runs * sizeof *tb);
    ts = malloc((size_t)runs * sizeof *ts);
    for (size_t i = 0; i < count; i++) {
        P[2 * i] = (double)i;
        P[2 * i + 1] = sin((double)i);
    }
    for (size_t i = 0; i < n; i++)
        u[i] = (double)i / (double)(n - 1);
    if (tb == NULL || ts == NULL ||
        cf_bezier_create(2, 3, B, NULL, &bz, NULL) != CF_STATUS_OK ||
        cf_bspline_create_clamped(2, 3, P, count, NULL, &bs, NULL) !=
            CF_STATUS_OK)
        return 1;
    for (int r = 0; r < runs; r++) {
        double t0 = now_s();
        if (cf_bezier_eval_many(bz, u, n, out) != CF_STATUS_OK)
            return 1;
        tb[r] = now_s() - t0;
        t0 = now_s();
        if (cf_bspline_eval_many(bs, u, n, out) != CF_STATUS_OK)
            return 1;
        ts[r] = now_s() - t0;
    }
    printf("{\"points\": %zu, \"runs\": %d, \"bezier_ns\": %.4f, "
           "\"bspline_ns\": %.4f}\n", n, runs, median_ns(tb, runs, n),
           median_ns(ts, runs, n));
    cf_bezier_destroy(bz);
    cf_bspline_destroy(bs);
    free(u);
    free(out);
    free(P);
    free(tb);
    free(ts);
    return 0;
}
