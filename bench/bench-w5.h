/*
** The W5 workloads through curvefig (curvefig-bench's W5ins and W5bez and
** bench_w5_sisl.c): make the result, add its points into the checksum
** (bench_sum_add, as SISL's are in bench-sisl-w5.h), free it; 0 on
** success.
*/
#ifndef CURVEFIG_BENCH_W5_H
#define CURVEFIG_BENCH_W5_H

#include <string.h>

#include "bench.h"
#include "curvefig/bspline.h"

/* W5ins: cf_bspline_refine with the knots X. */
static inline int
cf_w5ins_run(const cf_bspline_t *c, const double *X, double sum[2])
{
    cf_bspline_t *q = NULL;
    double acc[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
    if (cf_bspline_refine(c, X, BENCH_W5_KNOTS, &q, NULL) != CF_STATUS_OK)
        return 1;
    bench_sum_add(cf_bspline_hpoints(q), cf_bspline_count(q), acc);
    cf_bspline_destroy(q);
    bench_sum_finish(acc, sum);
    return 0;
}

/* W5bez as one array of points: cf_bspline_bezier_points. */
static inline int
cf_w5bez_flat_run(const cf_bspline_t *c, double sum[2])
{
    double *H = NULL, acc[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
    size_t n = 0;
    if (cf_bspline_bezier_points(c, &H, NULL, &n, NULL) != CF_STATUS_OK)
        return 1;
    bench_sum_add(H, 4 * n, acc);
    cf_free(H);
    bench_sum_finish(acc, sum);
    return 0;
}

/* W5bez as curves: cf_bspline_to_beziers. */
static inline int
cf_w5bez_curves_run(const cf_bspline_t *c, double sum[2])
{
    cf_bezier_list_t *list = NULL;
    double acc[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
    if (cf_bspline_to_beziers(c, &list, NULL) != CF_STATUS_OK)
        return 1;
    /* the points of 64 curves side by side, then their sums: no call
    ** between the additions, whose partial sums then stay in registers */
    for (size_t i = 0; i < list->count; i += 64) {
        double buf[64 * 8];
        size_t m = list->count - i < 64 ? list->count - i : 64;
        for (size_t j = 0; j < m; j++)
            memcpy(buf + 8 * j, cf_bezier_hpoints(list->items[i + j]),
                   8 * sizeof buf[0]);
        bench_sum_add(buf, 4 * m, acc);
    }
    cf_bezier_list_destroy(list);
    bench_sum_finish(acc, sum);
    return 0;
}

#endif
