/*
** bench-sisl: the B-spline workloads of docs/benchmarks.md (W3s, W3r, W4, W5ins,
** W5bez) run through SISL (Debian libsisl-dev) on the same inputs, to see
** the ratio to curvefig-bench on this machine.  Built only when SISL is
** found.  Prints one line per workload with its checksum (which must match
** the table of docs/benchmarks.md) and the median of 5 runs.  W5ins and
** W5bez beside curvefig's, in one process: bench_w5_sisl.c.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "bench-sisl-w5.h"

enum { NS = 10000000, NR = 1000000, RUNS = 5 };

/* Evaluate (der = 0) or differentiate (der = 1) at n parameters; the
** curve is evaluated from the right (s1221) with SISL's own span hint. */
static int
run_eval(SISLCurve *c, const double *u, size_t n, int der, double sum[2])
{
    double d[4], sx = 0.0, sy = 0.0;
    int left = 0, stat = 0;
    for (size_t i = 0; i < n; i++) {
        s1221(c, der, u[i], &left, d, &stat);
        if (stat < 0)
            return 1;
        sx += d[2 * der];
        sy += d[2 * der + 1];
    }
    sum[0] = sx;
    sum[1] = sy;
    return 0;
}

static void
report(const char *id, const char *what, double *t, double count,
       const double sum[2], double ex, double ey)
{
    int ok = fabs(sum[0] - ex) <= 1e-9 * fmax(1.0, fabs(ex))
             && fabs(sum[1] - ey) <= 1e-9 * fmax(1.0, fabs(ey));
    qsort(t, RUNS, sizeof t[0], cmp_double);
    printf("%-6s %-26s %12.4f ns/unit  (median %.6f s)  checksum %.6f %.6f "
           "%s\n", id, what, t[RUNS / 2] / count * 1e9, t[RUNS / 2], sum[0],
           sum[1], ok ? "ok" : "MISMATCH");
}

int
main(void)
{
    SISLCurve *c = sisl_w3_curve();
    double *u = malloc(NS * sizeof *u), t[RUNS], sum[2] = { 0, 0 };
    double X[BENCH_W5_KNOTS];
    bench_rng r;
    int failed = 0;
    if (c == NULL || u == NULL)
        return 1;

    for (size_t j = 0; j < NS; j++)
        u[j] = ((double)j + 0.5) / 1e7;
    run_eval(c, u, NS, 0, sum);
    for (int k = 0; k < RUNS; k++) {
        double t0 = now_s();
        failed |= run_eval(c, u, NS, 0, sum);
        t[k] = now_s() - t0;
    }
    report("W3s", "s1221 sorted", t, NS, sum, 5020204.715661, 5049334.488977);

    r.state = 1004;
    for (size_t j = 0; j < NR; j++)
        u[j] = bench_rng_u01(&r);
    for (int der = 0; der <= 1; der++) {
        run_eval(c, u, NR, der, sum);
        for (int k = 0; k < RUNS; k++) {
            double t0 = now_s();
            failed |= run_eval(c, u, NR, der, sum);
            t[k] = now_s() - t0;
        }
        if (der == 0)
            report("W3r", "s1221 random", t, NR, sum, 502008.160451,
                   505020.365304);
        else
            report("W4", "s1221 derivative random", t, NR, sum,
                   -317171.322680, 18485.071557);
    }

    bench_w5_knots(X);
    for (int k = 0; k < RUNS; k++) {
        double t0 = now_s();
        failed |= sisl_w5ins_run(c, X, sum);
        t[k] = now_s() - t0;
    }
    report("W5ins", "s1018 insert 1000 knots", t, 1, sum, 1002.976852,
           1013.838807);

    for (int k = 0; k < RUNS; k++) {
        double t0 = now_s();
        failed |= sisl_w5bez_run(c, sum);
        t[k] = now_s() - t0;
    }
    report("W5bez", "s1730 to Bezier form", t, 1, sum, 2002.057641,
           2013.674594);
    freeCurve(c);
    free(u);
    return failed;
}
