/*
** curvefig-offset-bench: segment counts, errors and times of offset
** curves.  Unlike curvefig-bench (fixed-checksum workloads), it prints
** one JSON line per curve, distance, method and tolerance:
**
**   {"curve": "arch", "d": -45, "method": "levien", "tol": 0.001,
**    "segments": 6, "target": 6, "reported_error": ..., "measured_error": ...,
**    "cusps": 2, "median_s": ...}
**
** and one summary line per curve and method with the log-log slope of the
** segment count against the tolerance.  "measured_error" is the
** independent two-sided Hausdorff measure cf_offset_measure with dense
** sampling (about 40,000 exact samples per curve, at least 16 per piece).
** Exit status 1 if a measured error exceeds its tolerance (a count above
** its target is reported as "target_met": false, not a failure).
**
**   curvefig-offset-bench [--runs N] [--no-th]
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "curvefig/curvefig.h"
#include "bench-time.h"

typedef struct bcase {
    const char *name;
    double pts[8];
    double d;
    int target[3];          /* Levien segments for 1e-2, 1e-3, 1e-4 */
} bcase;

static const bcase cases[] = {
    { "arch-inner", { 0, 0, 0, 100, 100, 100, 100, 0 }, -45, { 6, 6, 9 } },
    { "arch-outer", { 0, 0, 0, 100, 100, 100, 100, 0 }, 45, { 2, 3, 5 } },
    { "s-curve+40", { 67, 237, 374, 471, 321, 189, 633, 65 }, 40,
      { 3, 4, 6 } },
    { "s-curve-40", { 67, 237, 374, 471, 321, 189, 633, 65 }, -40,
      { 3, 4, 6 } },
    { "overstroke+250", { 0, 0, 25, 75, 75, -50, 100, 0 }, 250,
      { 7, 9, 14 } },
    { "overstroke-250", { 0, 0, 25, 75, 75, -50, 100, 0 }, -250,
      { 7, 9, 14 } },
};

int
main(int argc, char **argv)
{
    static const double tols[3] = { 1e-2, 1e-3, 1e-4 };
    int runs = 3, with_th = 1, failed = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--runs") == 0 && i + 1 < argc) {
            runs = atoi(argv[++i]);
            if (runs < 1 || runs > 32)
                runs = 3;
        } else if (strcmp(argv[i], "--no-th") == 0) {
            with_th = 0;
        } else if (strcmp(argv[i], "--json") == 0) {
            /* JSON is the only output format */
        } else {
            fprintf(stderr, "usage: %s [--runs N] [--no-th]\n", argv[0]);
            return 2;
        }
    }
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const bcase *bc = &cases[k];
        cf_bezier_t *c = NULL;
        if (cf_bezier_create(2, 3, bc->pts, NULL, &c, NULL) != CF_STATUS_OK)
            return 1;
        for (int m = 0; m < (with_th ? 2 : 1); m++) {
            size_t segs[3] = { 0, 0, 0 };
            for (int j = 0; j < 3; j++) {
                cf_offset_options_t opt;
                cf_offset_report_t rep;
                cf_cubics_t *raw = NULL;
                double times[32], err = -1.0;
                size_t samples;
                cf_offset_options_init(&opt);
                opt.tolerance = tols[j];
                opt.method = m == 0 ? CF_OFFSET_LEVIEN
                                    : CF_OFFSET_TILLER_HANSON;
                for (int r = 0; r < runs; r++) {
                    double t0 = now_s();
                    cf_cubics_destroy(raw);
                    raw = NULL;
                    if (cf_bezier_offset(c, bc->d, &opt, &raw, NULL, &rep,
                                         NULL) != CF_STATUS_OK) {
                        fprintf(stderr, "%s: offset failed\n", bc->name);
                        return 1;
                    }
                    times[r] = now_s() - t0;
                }
                qsort(times, (size_t)runs, sizeof times[0], cmp_double);
                samples = 40000 / raw->count;
                if (samples < 16)
                    samples = 16;
                if (samples > 2000)
                    samples = 2000;
                cf_offset_measure(c, bc->d, raw, samples, &err, NULL);
                segs[j] = rep.segments;
                if (err > tols[j])
                    failed = 1;
                printf("{\"curve\": \"%s\", \"d\": %g, \"method\": \"%s\", "
                       "\"tol\": %g, \"segments\": %zu, \"target\": %d, "
                       "\"reported_error\": %.4g, \"measured_error\": %.4g, "
                       "\"cusps\": %zu, \"median_s\": %.6f, "
                       "\"target_met\": %s}\n",
                       bc->name, bc->d, m == 0 ? "levien" : "tiller-hanson",
                       tols[j], rep.segments, m == 0 ? bc->target[j] : -1,
                       rep.max_error, err, rep.cusps, times[runs / 2],
                       m != 0 ? "null"
                       : (int)rep.segments <= bc->target[j] ? "true"
                                                            : "false");
                fflush(stdout);
                cf_cubics_destroy(raw);
            }
            printf("{\"curve\": \"%s\", \"d\": %g, \"method\": \"%s\", "
                   "\"loglog_slope\": %.3f}\n",
                   bc->name, bc->d, m == 0 ? "levien" : "tiller-hanson",
                   log((double)segs[2] / (double)segs[0]) / log(100.0));
        }
        cf_bezier_destroy(c);
    }
    return failed;
}
