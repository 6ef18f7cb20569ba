/*
** The W3 spline and the W5 workloads through SISL (Debian libsisl-dev),
** shared by bench_sisl.c and bench_w5_sisl.c; the checksums add the
** points as curvefig-bench's do (bench_sum_add).
*/
#ifndef CURVEFIG_BENCH_SISL_W5_H
#define CURVEFIG_BENCH_SISL_W5_H

#include <sisl.h>

#include "bench.h"

/* The W3 spline as a SISL curve (order 4, copied coefficients). */
static inline SISLCurve *
sisl_w3_curve(void)
{
    double U[BENCH_W3_POINTS + 4], P[2 * BENCH_W3_POINTS];
    bench_w3_data(U, P);
    return newCurve(BENCH_W3_POINTS, 4, U, P, 1, 2, 1);
}

/* W5ins: s1018 inserts the knots X into c, new curve; 0 on success. */
static inline int
sisl_w5ins_run(SISLCurve *c, double *X, double sum[2])
{
    SISLCurve *q = NULL;
    double acc[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
    int stat = 0;
    s1018(c, X, BENCH_W5_KNOTS, &q, &stat);
    if (stat < 0 || q == NULL)
        return 1;
    bench_sum_add(q->ecoef, (size_t)q->in, acc);
    freeCurve(q);
    bench_sum_finish(acc, sum);
    return 0;
}

/* W5bez: s1730, the Bézier form as a new curve; 0 on success.  With
** knots of multiplicity 4 every piece has its own 4 points, with
** multiplicity 3 neighbours share one. */
static inline int
sisl_w5bez_run(SISLCurve *c, double sum[2])
{
    SISLCurve *q = NULL;
    double acc[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
    int stat = 0, step;
    s1730(c, &q, &stat);
    if (stat < 0 || q == NULL)
        return 1;
    step = q->in == 4 * 997 ? 4 : 3;
    for (int s = 0; s + 3 < q->in; s += step)
        bench_sum_add4(q->ecoef + 2 * s, acc);
    freeCurve(q);
    bench_sum_finish(acc, sum);
    return 0;
}

#endif
