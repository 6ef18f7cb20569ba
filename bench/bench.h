/*
** The benchmark harness: workloads of docs/benchmarks.md register
** themselves here; bench.c times them (median of >= 5 runs after a warm-up)
** and prints one JSON line each with its checksum.
*/
#ifndef CURVEFIG_BENCH_H
#define CURVEFIG_BENCH_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "bench-time.h"

/* splitmix64 exactly as docs/benchmarks.md defines it. */
typedef struct bench_rng {
    uint64_t state;
} bench_rng;

static inline uint64_t
bench_rng_next(bench_rng *r)
{
    uint64_t z;
    r->state += 0x9E3779B97F4A7C15u;
    z = r->state;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

static inline double
bench_rng_u01(bench_rng *r)
{
    return (double)(bench_rng_next(r) >> 11) * 0x1p-53;
}

/* The W3 spline of docs/benchmarks.md (W3, W4, W5): a clamped cubic with
** 1000 points, interior knots i / 997 (i = 1..996), the points drawn with
** seed 1003, x then y. */
enum { BENCH_W3_POINTS = 1000, BENCH_W5_KNOTS = 1000 };

static inline void
bench_w3_data(double U[BENCH_W3_POINTS + 4], double P[2 * BENCH_W3_POINTS])
{
    bench_rng r = { 1003 };
    for (int i = 0; i < 4; i++) {
        U[i] = 0.0;
        U[BENCH_W3_POINTS + i] = 1.0;
    }
    for (int i = 1; i <= 996; i++)
        U[3 + i] = i / 997.0;
    for (int i = 0; i < 2 * BENCH_W3_POINTS; i++)
        P[i] = bench_rng_u01(&r);
}

/* The W5ins knots: u01() draws (seed 1005), each accepted when at least
** 2e-4 from every W3 knot (i / 997, i = 0..997) and every accepted one,
** until 1000; sorted. */
static inline void
bench_w5_knots(double X[BENCH_W5_KNOTS])
{
    bench_rng r = { 1005 };
    size_t got = 0;
    while (got < BENCH_W5_KNOTS) {
        double v = bench_rng_u01(&r);
        int ok = 1;
        for (int i = 0; i <= 997 && ok; i++) {
            double k = i == 0 ? 0.0 : i == 997 ? 1.0 : i / 997.0;
            if (fabs(v - k) < 2e-4)
                ok = 0;
        }
        for (size_t i = 0; i < got && ok; i++)
            if (fabs(v - X[i]) < 2e-4)
                ok = 0;
        if (ok)
            X[got++] = v;
    }
    qsort(X, BENCH_W5_KNOTS, sizeof X[0], cmp_double);
}

/* Checksums of planar points (x, y, x, y, ...): n points added into
** acc[8], four partial sums per coordinate (point 4g + j into acc[2j],
** acc[2j + 1]; the last n mod 4 into acc[0], acc[1]), so that the sums do
** not form one long chain of dependent additions beside the work timed;
** bench_sum_finish gives the two sums. */
static inline void
bench_sum_add(const double *pts, size_t n, double acc[8])
{
    size_t i = 0;
    for (; i + 4 <= n; i += 4)
        for (size_t l = 0; l < 8; l++)
            acc[l] += pts[2 * i + l];
    for (; i < n; i++) {
        acc[0] += pts[2 * i];
        acc[1] += pts[2 * i + 1];
    }
}

/* bench_sum_add of exactly 4 points (a cubic Bézier piece): the same
** sums, in a form every compiler unrolls. */
static inline void
bench_sum_add4(const double *pts, double acc[8])
{
    for (size_t l = 0; l < 8; l++)
        acc[l] += pts[l];
}

static inline void
bench_sum_finish(const double acc[8], double sum[2])
{
    sum[0] = (acc[0] + acc[2]) + (acc[4] + acc[6]);
    sum[1] = (acc[1] + acc[3]) + (acc[5] + acc[7]);
}

typedef struct bench_workload {
    const char *id;        /* "W1" */
    const char *variant;   /* what is measured ("eval_many") */
    const char *unit;      /* "point", "split", "run" */
    double count;          /* units per run */
    /* Build the inputs (outside the timing); NULL on failure. */
    void *(*setup)(void);
    /* One timed run: compute every output and its checksum. Returns 0 on
    ** success. */
    int (*run)(void *state, double checksum[2]);
    void (*teardown)(void *state);
    double expect[2];      /* the checksum of docs/benchmarks.md */
} bench_workload;

/* Each module file provides its table (terminated by an entry with id ==
** NULL). */
typedef const bench_workload *(*bench_table_fn)(void);

#endif
