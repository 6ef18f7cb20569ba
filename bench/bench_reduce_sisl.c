/*
** bench-reduce-sisl: B-spline degree reduction beside SISL's (Debian
** libsisl-dev), one process, the same inputs: cf_bspline_reduce (least
** squares and uniform pieces, knot removal within the tolerance) against
** SISL's s1343, which approximates a spline curve by a cubic spline within
** a tolerance per coordinate (knot removal on the curve's cubic
** approximation).  SISL's s1348 / s1349 are surface and curve-list
** routines, not degree reduction, so s1343 is the counterpart.
**
** For each curve and method: the median time of 5 runs after a warm-up,
** the control points of the result, and its largest distance from the
** original measured the same way for both (SISL's own evaluator s1221 at
** 20001 even parameters).  The tolerance is Euclidean for curvefig;
** SISL gets tol / sqrt(2) per coordinate, so that both promise the same
** Euclidean distance.  Built only when SISL is found.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <sisl.h>

#include "bench.h"
#include "curvefig/reduce.h"
#include "bench-time.h"

/* in SISL's private header only */
void s1343(SISLCurve *pc, double eeps[], int ilend, int irend, double aepsco,
           int itmax, SISLCurve **rc, int *jstat);

enum { RUNS = 5, SAMPLES = 20000 };

/* max |a(u) - b(u)| at SAMPLES + 1 even parameters, both through s1221 */
static double
sisl_dist(SISLCurve *a, SISLCurve *b)
{
    double lo = a->et[a->ik - 1], hi = a->et[a->in], m = 0.0;
    int la = 0, lb = 0, st = 0;
    for (int j = 0; j <= SAMPLES; j++) {
        double u = lo + (hi - lo) * j / SAMPLES, p[2], q[2];
        s1221(a, 0, u, &la, p, &st);
        s1221(b, 0, u, &lb, q, &st);
        m = fmax(m, hypot(p[0] - q[0], p[1] - q[1]));
    }
    return m;
}

static SISLCurve *
to_sisl(const cf_bspline_t *c)
{
    return newCurve((int)cf_bspline_count(c), cf_bspline_degree(c) + 1,
                    (double *)cf_bspline_knots(c),
                    (double *)cf_bspline_hpoints(c), 1, 2, 1);
}

typedef struct input {
    const char *name;
    cf_bspline_t *c;
    SISLCurve *s;
    double tol;
} input;

static void
run_curvefig(const input *in, cf_reduce_method_t method, const char *label)
{
    double t[RUNS], dist;
    cf_reduce_options_t o;
    cf_reduce_report_t rep;
    cf_bspline_t *r = NULL;
    SISLCurve *rs;
    cf_diag_t d;
    cf_reduce_options_init(&o);
    o.by = cf_bspline_degree(in->c) - 3;
    o.tolerance = in->tol;
    o.method = method;
    for (int k = -1; k < RUNS; k++) {
        double t0 = now_s();
        cf_bspline_destroy(r);
        r = NULL;
        if (cf_bspline_reduce(in->c, &o, &r, &rep, &d) != CF_STATUS_OK) {
            printf("%-22s %-14s refused: %s\n", in->name, label, d.msg);
            return;
        }
        if (k >= 0)
            t[k] = now_s() - t0;
    }
    qsort(t, RUNS, sizeof t[0], cmp_double);
    rs = to_sisl(r);
    dist = sisl_dist(in->s, rs);
    printf("%-22s %-14s %10.3f ms %5zu points  max %.3g  (bound %.3g)\n",
           in->name, label, t[RUNS / 2] * 1e3, cf_bspline_count(r), dist,
           rep.bound);
    freeCurve(rs);
    cf_bspline_destroy(r);
}

static void
run_sisl(const input *in)
{
    double t[RUNS], eps[2] = { in->tol / sqrt(2.0), in->tol / sqrt(2.0) };
    SISLCurve *r = NULL;
    int st = 0;
    for (int k = -1; k < RUNS; k++) {
        double t0 = now_s();
        if (r != NULL)
            freeCurve(r);
        r = NULL;
        s1343(in->s, eps, 1, 1, 1e-12, 10, &r, &st);
        if (st < 0 || r == NULL) {
            printf("%-22s %-14s failed (status %d)\n", in->name, "SISL s1343",
                   st);
            return;
        }
        if (k >= 0)
            t[k] = now_s() - t0;
    }
    qsort(t, RUNS, sizeof t[0], cmp_double);
    printf("%-22s %-14s %10.3f ms %5d points  max %.3g\n", in->name,
           "SISL s1343", t[RUNS / 2] * 1e3, r->in, sisl_dist(in->s, r));
    freeCurve(r);
}

/* A clamped curve of degree p with uniform knots on [0, 1]: a smooth
** wave (x = i / (count - 1), y = sin(3 pi x) + noise / 20). */
static input
make(const char *name, int p, size_t count, double tol, int elevate_from)
{
    input in = { name, NULL, NULL, tol };
    bench_rng r = { 3100 + count };
    double *P = malloc(2 * count * sizeof *P);
    int q = elevate_from > 0 ? elevate_from : p;
    cf_bspline_t *c;
    for (size_t i = 0; i < count; i++) {
        double x = (double)i / (double)(count - 1);
        P[2 * i] = x;
        P[2 * i + 1] = sin(3.0 * acos(-1.0) * x) + 0.05 * bench_rng_u01(&r);
    }
    cf_bspline_create_clamped(2, q, P, count, NULL, &c, NULL);
    if (elevate_from > 0) {
        cf_bspline_elevate(c, p - q, &in.c, NULL);
        cf_bspline_destroy(c);
    } else {
        in.c = c;
    }
    in.s = to_sisl(in.c);
    free(P);
    return in;
}

int
main(void)
{
    input ins[7];
    ins[0] = make("quintic Bezier", 5, 6, 0.3, 0);
    ins[1] = make("deg 5, 40 pts, 1e-2", 5, 40, 1e-2, 0);
    ins[2] = make("deg 5, 40 pts, 1e-3", 5, 40, 1e-3, 0);
    ins[3] = make("deg 5, 400 pts, 1e-2", 5, 400, 1e-2, 0);
    ins[4] = make("deg 5, 400 pts, 1e-4", 5, 400, 1e-4, 0);
    ins[5] = make("deg 7, 400 pts, 1e-2", 7, 400, 1e-2, 0);
    ins[6] = make("cubic elevated to 5", 5, 12, 1e-9, 3);
    printf("curve                  method          median      points "
           "      measured max\n");
    for (int i = 0; i < 7; i++) {
        if (ins[i].c == NULL)
            continue;
        run_curvefig(&ins[i], CF_REDUCE_L2, "curvefig L2");
        run_curvefig(&ins[i], CF_REDUCE_UNIFORM, "curvefig unif");
        run_sisl(&ins[i]);
        freeCurve(ins[i].s);
        cf_bspline_destroy(ins[i].c);
    }
    return 0;
}
