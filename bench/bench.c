/*
** curvefig-bench: runs the workloads of docs/benchmarks.md.
**
**   curvefig-bench [--json] [--runs N] [--only ID[,ID...]]
**
** Each workload: setup (untimed), one warm-up run, then N (>= 5) timed runs;
** reports the median.  The checksum of the last run is compared with the
** table of docs/benchmarks.md to 1e-9 relative; a mismatch makes the exit status
** 1, so `meson test --benchmark` fails on a wrong answer.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"
#include "bench-time.h"

/* Tables of the module files, in the order of docs/benchmarks.md (add the
** declaration and the entry when a module gets its workloads). */
const bench_workload *bench_bezier_table(void);
const bench_workload *bench_bspline_table(void);

static const bench_table_fn tables[] = {
    bench_bezier_table,
    bench_bspline_table,
    NULL,
};

static int
selected(const char *only, const char *id)
{
    size_t n = strlen(id);
    const char *p = only;
    if (only == NULL)
        return 1;
    while (*p) {
        const char *e = strchr(p, ',');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        if (len == n && strncmp(p, id, n) == 0)
            return 1;
        if (!e)
            break;
        p = e + 1;
    }
    return 0;
}

static int
checksum_ok(double got, double want)
{
    return fabs(got - want) <= 1e-9 * fmax(1.0, fabs(want));
}

int
main(int argc, char **argv)
{
    int json = 0, runs = 5, failed = 0;
    const char *only = NULL;

    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--json") == 0) {
            json = 1;
        } else if (strcmp(argv[i], "--runs") == 0 && i + 1 < argc) {
            runs = atoi(argv[++i]);
            if (runs < 5)
                runs = 5;
        } else if (strcmp(argv[i], "--only") == 0 && i + 1 < argc) {
            only = argv[++i];
        } else {
            fprintf(stderr,
                    "usage: %s [--json] [--runs N (>= 5)] [--only ID,...]\n",
                    argv[0]);
            return 2;
        }
    }

    for (size_t k = 0; tables[k] != NULL; k++) {
        for (const bench_workload *w = tables[k](); w->id != NULL; w++) {
            double times[64], sum[2] = { 0, 0 }, med;
            void *st;
            int ok;
            if (!selected(only, w->id))
                continue;
            if (runs > 64)
                runs = 64;
            st = w->setup();
            if (st == NULL) {
                fprintf(stderr, "%s: setup failed\n", w->id);
                failed = 1;
                continue;
            }
            if (w->run(st, sum) != 0) {
                fprintf(stderr, "%s: run failed\n", w->id);
                failed = 1;
                w->teardown(st);
                continue;
            }
            for (int r = 0; r < runs; r++) {
                double t0 = now_s();
                w->run(st, sum);
                times[r] = now_s() - t0;
            }
            w->teardown(st);
            qsort(times, (size_t)runs, sizeof times[0], cmp_double);
            med = times[runs / 2];
            ok = checksum_ok(sum[0], w->expect[0]) &&
                 checksum_ok(sum[1], w->expect[1]);
            if (!ok)
                failed = 1;
            if (json) {
                printf("{\"workload\": \"%s\", \"variant\": \"%s\", "
                       "\"count\": %.0f, \"unit\": \"%s\", "
                       "\"median_s\": %.9f, \"per_unit_ns\": %.4f, "
                       "\"checksum\": [%.6f, %.6f], \"checksum_ok\": %s}\n",
                       w->id, w->variant, w->count, w->unit, med,
                       med / w->count * 1e9, sum[0], sum[1],
                       ok ? "true" : "false");
            } else {
                printf("%-8s %-22s %12.4f ns/%s  (median %.6f s)  "
                       "checksum %.6f %.6f %s\n",
                       w->id, w->variant, med / w->count * 1e9, w->unit, med,
                       sum[0], sum[1], ok ? "ok" : "MISMATCH");
            }
            if (!ok)
                fprintf(stderr, "%s: checksum %.9f %.9f, expected %.6f %.6f\n",
                        w->id, sum[0], sum[1], w->expect[0], w->expect[1]);
            fflush(stdout);
        }
    }
    return failed;
}
