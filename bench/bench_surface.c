/*
** bench-surface: a bicubic B-spline surface (40 x 40 random control points
** in [0, 1]^3, clamped uniform knots, splitmix64 seed 2701) evaluated on
** the 1000 x 1000 grid u_a = (a + 1/2) / 1000, v_b = (b + 1/2) / 1000:
** points and first partials.  Beside it, in the same run and on the same
** inputs: SISL's s1421 (point, first partials and normal per call) and
** s1424 (derivatives up to (1, 1)) when the build found SISL (option
** `sisl`), and memset / memcpy of the result's size (three arrays of 1e6
** points of 3 doubles: 72 MB), the memory bandwidth the grid evaluation
** needs just to write its result.  Prints the median of 5 runs per line,
** and the checksums (sums of every coordinate of S, Su, Sv), which agree
** between curvefig and SISL to 1e-9 relative.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifdef CF_HAVE_SISL
#include <sisl.h>
#endif

#include "bench.h"
#include "curvefig/surface.h"
#include "bench-time.h"

enum { NC = 40, NG = 1000, RUNS = 5 };

static double
median(double *t)
{
    qsort(t, RUNS, sizeof *t, cmp_double);
    return t[RUNS / 2];
}

static double U[NC + 4], P[NC * NC * 3], uv[2 * NG];

static double
sum(const double *x, size_t n)
{
    double s = 0.0;
    for (size_t i = 0; i < n; i++)
        s += x[i];
    return s;
}

static void
line(const char *what, double t, double s[3])
{
    printf("%-40s %9.3f ns/point  (median %.4f s)", what,
           t / (NG * (double)NG) * 1e9, t);
    if (s != NULL)
        printf("  checksum %.9f %.9f %.9f", s[0], s[1], s[2]);
    printf("\n");
}

#ifdef CF_HAVE_SISL
/* s1421 (ider 1) or s1424 (1, 1) at every grid point; sums of S, Su, Sv. */
static double
run_sisl(SISLSurf *s, int which, double out[3])
{
    double d[12], n[3], par[2], t0 = now_s(), a = 0, b = 0, c = 0;
    int l1 = 0, l2 = 0, stat = 0;
    for (int i = 0; i < NG; i++)
        for (int j = 0; j < NG; j++) {
            par[0] = uv[i];
            par[1] = uv[NG + j];
            if (which == 0)
                s1421(s, 1, par, &l1, &l2, d, n, &stat);
            else
                s1424(s, 1, 1, par, &l1, &l2, d, &stat);
            if (stat < 0) {
                fprintf(stderr, "SISL failed (%d)\n", stat);
                exit(1);
            }
            /* d: S, S_u, S_v (s1421); S, S_u, S_v, S_uv (s1424) */
            a += d[0] + d[1] + d[2];
            b += d[3] + d[4] + d[5];
            c += d[6] + d[7] + d[8];
        }
    out[0] = a;
    out[1] = b;
    out[2] = c;
    return now_s() - t0;
}
#endif

int
main(void)
{
    size_t n = (size_t)NG * NG * 3;
    double *pts = malloc(n * sizeof *pts), *su = malloc(n * sizeof *su);
    double *sv = malloc(n * sizeof *sv), *src = malloc(3 * n * sizeof *src);
    double *dst = malloc(3 * n * sizeof *dst), t[RUNS], s[3], tg, tp, tm;
    cf_bspline_surface_t *surf = NULL;
    bench_rng r = { 2701 };
    cf_diag_t d;
    if (!pts || !su || !sv || !src || !dst)
        return 1;
    for (int i = 0; i < NC + 4; i++)
        U[i] = i < 4 ? 0.0 : i >= NC ? 1.0 : (i - 3) / (double)(NC - 3);
    for (int i = 0; i < NC * NC * 3; i++)
        P[i] = bench_rng_u01(&r);
    for (int i = 0; i < NG; i++)
        uv[i] = uv[NG + i] = (i + 0.5) / NG;
    if (cf_bspline_surface_create(3, 3, 3, U, NC + 4, U, NC + 4, P, NC, NC,
                                  NULL, &surf, &d) != CF_STATUS_OK) {
        fprintf(stderr, "%s\n", d.msg);
        return 1;
    }
    printf("bicubic B-spline surface, %d x %d control points, %d x %d grid\n",
           NC, NC, NG, NG);

    /* memory bandwidth: write (memset) and copy (memcpy) 72 MB */
    memset(src, 1, 3 * n * sizeof *src);
    for (int k = 0; k < RUNS; k++) {
        double t0 = now_s();
        memset(dst, k, 3 * n * sizeof *dst);
        t[k] = now_s() - t0;
    }
    tm = median(t);
    printf("%-40s %9.3f ns/point  (median %.4f s, %.2f GB/s)\n",
           "memset of the result (72 MB)", tm / (NG * (double)NG) * 1e9, tm,
           3 * n * sizeof *dst / tm * 1e-9);
    for (int k = 0; k < RUNS; k++) {
        double t0 = now_s();
        memcpy(dst, src, 3 * n * sizeof *dst);
        t[k] = now_s() - t0;
    }
    tp = median(t);
    printf("%-40s %9.3f ns/point  (median %.4f s, %.2f GB/s)\n",
           "memcpy of the result (72 MB)", tp / (NG * (double)NG) * 1e9, tp,
           3 * n * sizeof *dst / tp * 1e-9);

    for (int k = 0; k < RUNS; k++) {
        double t0 = now_s();
        if (cf_bspline_surface_eval_grid(surf, uv, NG, NG, pts, su, sv))
            return 1;
        t[k] = now_s() - t0;
    }
    tg = median(t);
    s[0] = sum(pts, n);
    s[1] = sum(su, n);
    s[2] = sum(sv, n);
    line("curvefig eval_grid S, Su, Sv", tg, s);
    printf("%-40s %9.2f x the memset\n", "  grid evaluation / bandwidth",
           tg / tm);
    for (int k = 0; k < RUNS; k++) {
        double t0 = now_s();
        if (cf_bspline_surface_eval_grid(surf, uv, NG, NG, pts, NULL, NULL))
            return 1;
        t[k] = now_s() - t0;
    }
    line("curvefig eval_grid S only", median(t), NULL);
    for (int k = 0; k < RUNS; k++) {
        double t0 = now_s(), D[12], a = 0, b = 0, c = 0;
        for (int i = 0; i < NG; i++)
            for (int j = 0; j < NG; j++) {
                if (cf_bspline_surface_eval_derivs(surf, uv[i], uv[NG + j], 1,
                                                   D))
                    return 1;
                a += D[0] + D[1] + D[2];
                b += D[6] + D[7] + D[8];
                c += D[3] + D[4] + D[5];
            }
        t[k] = now_s() - t0;
        s[0] = a, s[1] = b, s[2] = c;
    }
    tp = median(t);
    line("curvefig eval_derivs k=1 per point", tp, s);
#ifdef CF_HAVE_SISL
    {
        double *c = malloc(NC * NC * 3 * sizeof *c), ts;
        SISLSurf *ss;
        /* SISL: the first parameter runs fastest */
        for (int i = 0; i < NC; i++)
            for (int j = 0; j < NC; j++)
                memcpy(c + (j * NC + i) * 3, P + (i * NC + j) * 3,
                       3 * sizeof *c);
        ss = newSurf(NC, NC, 4, 4, U, U, c, 1, 3, 1);
        if (ss == NULL)
            return 1;
        for (int k = 0; k < RUNS; k++)
            t[k] = run_sisl(ss, 0, s);
        ts = median(t);
        line("SISL s1421 (S, Su, Sv, normal)", ts, s);
        printf("%-40s %9.1f x (eval_grid), %.1f x (per point)\n",
               "  SISL s1421 / curvefig", ts / tg, ts / tp);
        for (int k = 0; k < RUNS; k++)
            t[k] = run_sisl(ss, 1, s);
        ts = median(t);
        line("SISL s1424 (derivatives to (1, 1))", ts, s);
        printf("%-40s %9.1f x (eval_grid)\n", "  SISL s1424 / curvefig",
               ts / tg);
        freeSurf(ss);
        free(c);
    }
#else
    printf("(SISL not found by the build: no comparison)\n");
#endif
    cf_bspline_surface_destroy(surf);
    free(pts);
    free(su);
    free(sv);
    free(src);
    free(dst);
    return 0;
}
