/*
** The clock and the sort of the benchmarks (one copy for every bench_*.c).
*/
#ifndef CURVEFIG_BENCH_TIME_H
#define CURVEFIG_BENCH_TIME_H

#include <time.h>

/* Seconds of the monotonic clock. */
static inline double
now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* For qsort of doubles, ascending. */
static inline int
cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

#endif
