/*
** bench-w5-sisl: W5ins and W5bez (docs/benchmarks.md) through curvefig and
** through SISL (Debian libsisl-dev) side by side in one process, on the
** same inputs:
**   W5ins  cf_bspline_refine             beside s1018
**   W5bez  cf_bspline_bezier_points      beside s1730
**          cf_bspline_to_beziers (curves) beside s1730
** Each run makes its result, adds its points into the checksum (the same
** code for both libraries, bench.h) and frees the result.  One warm-up
** round, then ROUNDS rounds, each running every variant once in an order
** that rotates from round to round, so that a change of load falls on all
** alike; the median of each variant and the ratio of the medians, SISL's
** over curvefig's (issue #28's target: at least 4).  Exit status 1 on a
** wrong checksum, 77 (skipped) when built without SISL.
**
**   bench-w5-sisl [--rounds N] [--json]
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#ifdef CF_HAVE_SISL
#include "bench-sisl-w5.h"
#include "bench-w5.h"

enum { NVAR = 5, MAXROUNDS = 10001 };

typedef struct inputs {
    cf_bspline_t *cf;
    SISLCurve *sisl;
    double X[BENCH_W5_KNOTS];
} inputs;

static int
cf_refine(inputs *in, double sum[2])
{
    return cf_w5ins_run(in->cf, in->X, sum);
}

static int
cf_flat(inputs *in, double sum[2])
{
    return cf_w5bez_flat_run(in->cf, sum);
}

static int
cf_curves(inputs *in, double sum[2])
{
    return cf_w5bez_curves_run(in->cf, sum);
}

static int
sisl_ins(inputs *in, double sum[2])
{
    return sisl_w5ins_run(in->sisl, in->X, sum);
}

static int
sisl_bez(inputs *in, double sum[2])
{
    return sisl_w5bez_run(in->sisl, sum);
}

static const struct variant {
    const char *id, *what;
    int (*run)(inputs *, double[2]);
    double expect[2];
} variants[NVAR] = {
    { "W5ins", "curvefig cf_bspline_refine", cf_refine,
      { 1002.976852, 1013.838807 } },
    { "W5ins", "SISL s1018", sisl_ins, { 1002.976852, 1013.838807 } },
    { "W5bez", "curvefig cf_bspline_bezier_points", cf_flat,
      { 2002.057641, 2013.674594 } },
    { "W5bez", "curvefig cf_bspline_to_beziers", cf_curves,
      { 2002.057641, 2013.674594 } },
    { "W5bez", "SISL s1730", sisl_bez, { 2002.057641, 2013.674594 } },
};

/* SISL's variant over curvefig's: the ratios printed. */
static const int pairs[][2] = { { 1, 0 }, { 4, 2 }, { 4, 3 } };

static int
checksum_ok(const double got[2], const double want[2])
{
    for (int d = 0; d < 2; d++)
        if (!(fabs(got[d] - want[d]) <= 1e-9 * fmax(1.0, fabs(want[d]))))
            return 0;
    return 1;
}

int
main(int argc, char **argv)
{
    static double t[NVAR][MAXROUNDS];
    double med[NVAR], sum[NVAR][2];
    int rounds = 1001, json = 0, failed = 0;
    inputs in;
    double U[BENCH_W3_POINTS + 4], P[2 * BENCH_W3_POINTS];

    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--rounds") == 0 && i + 1 < argc) {
            rounds = atoi(argv[++i]);
        } else if (strcmp(argv[i], "--json") == 0) {
            json = 1;
        } else {
            fprintf(stderr, "usage: %s [--rounds N] [--json]\n", argv[0]);
            return 2;
        }
    }
    if (rounds < 5)
        rounds = 5;
    if (rounds > MAXROUNDS)
        rounds = MAXROUNDS;
    bench_w3_data(U, P);
    bench_w5_knots(in.X);
    in.cf = NULL;
    in.sisl = sisl_w3_curve();
    if (in.sisl == NULL
        || cf_bspline_create(2, 3, U, BENCH_W3_POINTS + 4, P,
                             BENCH_W3_POINTS, NULL, &in.cf, NULL)
           != CF_STATUS_OK) {
        fprintf(stderr, "bench-w5-sisl: the W3 spline was not made\n");
        return 1;
    }
    for (int r = -1; r < rounds; r++) {
        for (int k = 0; k < NVAR; k++) {
            int v = (k + (r < 0 ? 0 : r)) % NVAR;
            double t0 = now_s();
            if (variants[v].run(&in, sum[v]) != 0) {
                fprintf(stderr, "%s %s: failed\n", variants[v].id,
                        variants[v].what);
                return 1;
            }
            if (r >= 0)
                t[v][r] = now_s() - t0;
        }
    }
    for (int v = 0; v < NVAR; v++) {
        int ok = checksum_ok(sum[v], variants[v].expect);
        qsort(t[v], (size_t)rounds, sizeof t[v][0], cmp_double);
        med[v] = t[v][rounds / 2];
        failed |= !ok;
        if (json)
            printf("{\"workload\": \"%s\", \"variant\": \"%s\", "
                   "\"rounds\": %d, \"median_us\": %.3f, "
                   "\"checksum\": [%.6f, %.6f], \"checksum_ok\": %s}\n",
                   variants[v].id, variants[v].what, rounds, med[v] * 1e6,
                   sum[v][0], sum[v][1], ok ? "true" : "false");
        else
            printf("%-6s %-34s median %9.3f us  checksum %.6f %.6f %s\n",
                   variants[v].id, variants[v].what, med[v] * 1e6,
                   sum[v][0], sum[v][1], ok ? "ok" : "MISMATCH");
    }
    for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; i++) {
        const struct variant *s = &variants[pairs[i][0]],
                             *c = &variants[pairs[i][1]];
        double ratio = med[pairs[i][0]] / med[pairs[i][1]];
        if (json)
            printf("{\"workload\": \"%s\", \"ratio\": \"%s / %s\", "
                   "\"times_faster\": %.2f, \"target_4x\": %s}\n",
                   s->id, s->what, c->what, ratio,
                   ratio >= 4.0 ? "true" : "false");
        else
            printf("%-6s %s / %s: %.2f (target >= 4: %s)\n", s->id,
                   s->what, c->what, ratio, ratio >= 4.0 ? "met" : "NOT met");
    }
    cf_bspline_destroy(in.cf);
    freeCurve(in.sisl);
    return failed;
}

#else

int
main(void)
{
    printf("bench-w5-sisl: built without SISL (Debian libsisl-dev, option "
           "sisl): skipped\n");
    return 77;
}

#endif
