/*
** B-spline workloads of docs/benchmarks.md: W3s, W3r, W4, W5ins, W5bez.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench-w5.h"

const bench_workload *bench_bspline_table(void);

enum {
    W3S_COUNT = 10000000,
    W3R_COUNT = 1000000,
    W5_KNOTS = BENCH_W5_KNOTS,
    CHUNK = 4096
};

typedef struct w3_state {
    cf_bspline_t *curve;
    double *u;          /* parameters */
    size_t n;
    double *out;        /* CHUNK points */
    double x[W5_KNOTS]; /* W5ins knots */
} w3_state;

/* The W3 spline (bench.h). */
static cf_bspline_t *
w3_curve(void)
{
    double U[BENCH_W3_POINTS + 4], P[2 * BENCH_W3_POINTS];
    cf_bspline_t *c = NULL;
    bench_w3_data(U, P);
    if (cf_bspline_create(2, 3, U, BENCH_W3_POINTS + 4, P, BENCH_W3_POINTS,
                          NULL, &c, NULL) != CF_STATUS_OK)
        return NULL;
    return c;
}

static w3_state *
w3_new(size_t n)
{
    w3_state *s = calloc(1, sizeof *s);
    if (s == NULL)
        return NULL;
    s->curve = w3_curve();
    s->n = n;
    s->u = n ? malloc(n * sizeof *s->u) : NULL;
    s->out = malloc(2 * CHUNK * sizeof *s->out);
    if (s->curve == NULL || (n && s->u == NULL) || s->out == NULL) {
        cf_bspline_destroy(s->curve);
        free(s->u);
        free(s->out);
        free(s);
        return NULL;
    }
    return s;
}

static void
w3_teardown(void *st)
{
    w3_state *s = st;
    cf_bspline_destroy(s->curve);
    free(s->u);
    free(s->out);
    free(s);
}

static void *
w3s_setup(void)
{
    w3_state *s = w3_new(W3S_COUNT);
    if (s != NULL)
        for (size_t j = 0; j < W3S_COUNT; j++)
            s->u[j] = ((double)j + 0.5) / 1e7;
    return s;
}

static void *
w3r_setup(void)
{
    w3_state *s = w3_new(W3R_COUNT);
    bench_rng r = { 1004 };
    if (s != NULL)
        for (size_t j = 0; j < W3R_COUNT; j++)
            s->u[j] = bench_rng_u01(&r);
    return s;
}

/* Evaluate (k = 0) or differentiate (k = 1) in chunks into a reused
** buffer (the output is written point after point) and sum. */
static int
w3_run_k(w3_state *s, int k, double sum[2])
{
    double acc[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
    for (size_t j = 0; j < s->n; j += CHUNK) {
        size_t m = s->n - j < CHUNK ? s->n - j : CHUNK;
        cf_status_t st = k == 0
            ? cf_bspline_eval_many(s->curve, s->u + j, m, s->out)
            : cf_bspline_eval_deriv_many(s->curve, s->u + j, m, 1, s->out);
        if (st != CF_STATUS_OK)
            return 1;
        bench_sum_add(s->out, m, acc);
    }
    bench_sum_finish(acc, sum);
    return 0;
}

static int
w3_run(void *st, double sum[2])
{
    return w3_run_k(st, 0, sum);
}

static int
w4_run(void *st, double sum[2])
{
    return w3_run_k(st, 1, sum);
}

static void *
w5ins_setup(void)
{
    w3_state *s = w3_new(0);
    if (s != NULL)
        bench_w5_knots(s->x);
    return s;
}

/* The W5 runs are those of bench-w5.h (bench_w5_sisl.c runs them beside
** SISL). */
static int
w5ins_run(void *st, double sum[2])
{
    w3_state *s = st;
    return cf_w5ins_run(s->curve, s->x, sum);
}

static void *
w5bez_setup(void)
{
    return w3_new(0);
}

static int
w5bez_run(void *st, double sum[2])
{
    return cf_w5bez_curves_run(((w3_state *)st)->curve, sum);
}

static int
w5bez_flat_run(void *st, double sum[2])
{
    return cf_w5bez_flat_run(((w3_state *)st)->curve, sum);
}

static const bench_workload table[] = {
    { "W3s", "eval_many sorted", "point", W3S_COUNT, w3s_setup, w3_run,
      w3_teardown, { 5020204.715661, 5049334.488977 } },
    { "W3r", "eval_many random", "point", W3R_COUNT, w3r_setup, w3_run,
      w3_teardown, { 502008.160451, 505020.365304 } },
    { "W4", "eval_deriv_many k=1", "point", W3R_COUNT, w3r_setup, w4_run,
      w3_teardown, { -317171.322680, 18485.071557 } },
    { "W5ins", "refine 1000 knots", "run", 1, w5ins_setup, w5ins_run,
      w3_teardown, { 1002.976852, 1013.838807 } },
    { "W5bez", "to_beziers (objects)", "run", 1, w5bez_setup, w5bez_run,
      w3_teardown, { 2002.057641, 2013.674594 } },
    { "W5bez", "bezier_points (flat)", "run", 1, w5bez_setup,
      w5bez_flat_run, w3_teardown, { 2002.057641, 2013.674594 } },
    { NULL, NULL, NULL, 0, NULL, NULL, NULL, { 0, 0 } },
};

const bench_workload *
bench_bspline_table(void)
{
    return table;
}
