/*
** The benchmark harness: workloads of docs/benchmarks.md register
** themselves here; bench.c times them (median of >= 5 runs after a warm-up)
** and prints one JSON line each with its checksum.
*/
#ifndef CURVEFIG_BENCH_H
#define CURVEFIG_BENCH_H

#include <stddef.h>
#include <stdint.h>

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
