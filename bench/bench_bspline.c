/*
** B-spline workloads of docs/benchmarks.md: W3s, W3r, W4, W5ins, W5bez.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "curvefig/bspline.h"
#include "bench-time.h"

const bench_workload *bench_bspline_table(void);

enum {
    W3_POINTS = 1000,
    W3S_COUNT = 10000000,
    W3R_COUNT = 1000000,
    W5_KNOTS = 1000,
    CHUNK = 4096
};

typedef struct w3_state {
    cf_bspline_t *curve;
    double *u;          /* parameters */
    size_t n;
    double *out;        /* CHUNK points */
    double x[W5_KNOTS]; /* W5ins knots */
} w3_state;

/* The W3 spline: seed 1003, point by point (x then y), clamped cubic with
** interior knots i / 997.0. */
static cf_bspline_t *
w3_curve(void)
{
    double U[W3_POINTS + 4], P[2 * W3_POINTS];
    bench_rng r = { 1003 };
    cf_bspline_t *c = NULL;
    for (int i = 0; i < 4; i++) {
        U[i] = 0.0;
        U[W3_POINTS + i] = 1.0;
    }
    for (int i = 1; i <= 996; i++)
        U[3 + i] = i / 997.0;
    for (int i = 0; i < 2 * W3_POINTS; i++)
        P[i] = bench_rng_u01(&r);
    if (cf_bspline_create(2, 3, U, W3_POINTS + 4, P, W3_POINTS, NULL, &c,
                          NULL) != CF_STATUS_OK)
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
    /* four partial sums per coordinate, so that the checksum's additions
    ** do not form one long dependency chain beside the evaluation */
    double acc[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
    for (size_t j = 0; j < s->n; j += CHUNK) {
        size_t m = s->n - j < CHUNK ? s->n - j : CHUNK, i = 0;
        cf_status_t st = k == 0
            ? cf_bspline_eval_many(s->curve, s->u + j, m, s->out)
            : cf_bspline_eval_deriv_many(s->curve, s->u + j, m, 1, s->out);
        if (st != CF_STATUS_OK)
            return 1;
        for (; i + 4 <= m; i += 4)
            for (size_t l = 0; l < 8; l++)
                acc[l] += s->out[2 * i + l];
        for (; i < m; i++) {
            acc[0] += s->out[2 * i];
            acc[1] += s->out[2 * i + 1];
        }
    }
    sum[0] = (acc[0] + acc[2]) + (acc[4] + acc[6]);
    sum[1] = (acc[1] + acc[3]) + (acc[5] + acc[7]);
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
    bench_rng r = { 1005 };
    size_t got = 0;
    if (s == NULL)
        return NULL;
    while (got < W5_KNOTS) {
        double v = bench_rng_u01(&r);
        bool ok = true;
        /* the W3 knots are i / 997 (i = 0..997) */
        for (int i = 0; i <= 997 && ok; i++) {
            double k = i == 0 ? 0.0 : i == 997 ? 1.0 : i / 997.0;
            if (fabs(v - k) < 2e-4)
                ok = false;
        }
        for (size_t i = 0; i < got && ok; i++)
            if (fabs(v - s->x[i]) < 2e-4)
                ok = false;
        if (ok)
            s->x[got++] = v;
    }
    qsort(s->x, W5_KNOTS, sizeof s->x[0], cmp_double);
    return s;
}

static int
w5ins_run(void *st, double sum[2])
{
    w3_state *s = st;
    cf_bspline_t *q = NULL;
    const double *P;
    double sx = 0.0, sy = 0.0;
    size_t n;
    if (cf_bspline_refine(s->curve, s->x, W5_KNOTS, &q, NULL)
        != CF_STATUS_OK)
        return 1;
    P = cf_bspline_hpoints(q);
    n = cf_bspline_count(q);   /* once: a call per point is not the work */
    for (size_t i = 0; i < n; i++) {
        sx += P[2 * i];
        sy += P[2 * i + 1];
    }
    cf_bspline_destroy(q);
    sum[0] = sx;
    sum[1] = sy;
    return 0;
}

static void *
w5bez_setup(void)
{
    return w3_new(0);
}

static int
w5bez_run(void *st, double sum[2])
{
    w3_state *s = st;
    cf_bezier_list_t *list = NULL;
    double sx = 0.0, sy = 0.0;
    if (cf_bspline_to_beziers(s->curve, &list, NULL) != CF_STATUS_OK)
        return 1;
    for (size_t i = 0; i < list->count; i++) {
        const double *P = cf_bezier_hpoints(list->items[i]);
        for (int j = 0; j < 4; j++) {
            sx += P[2 * j];
            sy += P[2 * j + 1];
        }
    }
    cf_bezier_list_destroy(list);
    sum[0] = sx;
    sum[1] = sy;
    return 0;
}

static int
w5bez_flat_run(void *st, double sum[2])
{
    w3_state *s = st;
    double *H = NULL, sx = 0.0, sy = 0.0;
    size_t n = 0;
    if (cf_bspline_bezier_points(s->curve, &H, NULL, &n, NULL)
        != CF_STATUS_OK)
        return 1;
    for (size_t i = 0; i < 4 * n; i++) {
        sx += H[2 * i];
        sy += H[2 * i + 1];
    }
    cf_free(H);
    sum[0] = sx;
    sum[1] = sy;
    return 0;
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
