/*
** The raw offset chain against the exact offsets it approximates, for the
** trim: points of the chain, the exact offset behind each raw piece, the
** projection onto it, distances to the base curve and where they reach
** |d| - CF__TRIM_KEEP tol.
*/
#include <math.h>

#include "core-private.h"
#include "bezier-private.h"
#include "offset-trim-private.h"

static void
base_fn(const void *ctx, double u, double *p, double *dp)
{
    double v[4];
    cf_bezier_eval_derivs(ctx, u, 1, v);
    p[0] = v[0];
    p[1] = v[1];
    dp[0] = v[2];
    dp[1] = v[3];
}

/* Distance of q to the base curve (all pieces). */
double
cf__trim_base_dist(const cf__trim_t *tr, const double *q)
{
    double best = INFINITY;
    for (size_t i = 0; i < tr->nbase; i++)
        best = fmin(best,
                    cf__dist_sampled(base_fn, tr->base[i],
                                     tr->bsmp + 2 * (CF__TRIM_BASE_N + 1) * i,
                                     CF__TRIM_BASE_N, q));
    return best;
}

/* Point of the raw chain at global parameter g = i + s. */
void
cf__trim_chain_point(const cf__trim_t *tr, double g, double *p)
{
    size_t i = (size_t)floor(g);
    double s;
    if (i >= tr->raw->count)
        i = tr->raw->count - 1;
    s = g - (double)i;
    cf__cubic_pd(tr->raw->pts + 8 * i, fmin(1.0, fmax(0.0, s)), p, NULL);
}

/* The exact offset that raw piece i approximates (on base piece *k, with
** its travel direction); -1 for a join arc (an empty range). */
int
cf__trim_piece_source(const cf__trim_t *tr, size_t i, cf__osrc_t *src,
                      size_t *k)
{
    const cf_cubics_t *raw = tr->raw;
    double mid = 0.5 * (raw->t[i] + raw->t[i + 1]), p[2], dp[2], u[2], t;
    if (!(raw->t[i + 1] > raw->t[i]))
        return -1;
    *k = cf__trim_base_of(tr, mid);
    t = cf__trim_to_local(tr, *k, mid);
    cf__osrc_init_offset(src, tr->base[*k], tr->d);
    /* o' = c' (1 - d kappa): o runs against c' past a cusp */
    cf__osrc_deriv(src, t, p, dp);
    if (cf__bezier_unit_tangent(src->c, t, 1, src->scale, NULL, u) == 0 &&
        dp[0] * u[0] + dp[1] * u[1] < 0.0)
        src->sgn = -1.0;
    return 0;
}

/* The point of an offset source at t (the limit from the left at t = 1). */
static void
osrc_point(const cf__osrc_t *s, double t, double *p)
{
    (void)cf__osrc_point_dir(s, t, t >= 1.0 ? -1 : 1, p, NULL);
}

/* The source parameter of the point of the exact offset of raw piece i
** (src, on base piece k) nearest q: samples, then golden-section search. */
double
cf__trim_project(const cf__trim_t *tr, size_t i, const cf__osrc_t *src,
                 size_t k, const double *q)
{
    enum { N = 32 };
    const double gr = 0.6180339887498949;
    double la = cf__trim_to_local(tr, k, tr->raw->t[i]);
    double lb = cf__trim_to_local(tr, k, tr->raw->t[i + 1]);
    double best = INFINITY, p[2], lo, hi;
    int jb = 0;
    for (int j = 0; j <= N; j++) {
        double dd;
        osrc_point(src, la + (lb - la) * j / N, p);
        dd = hypot(p[0] - q[0], p[1] - q[1]);
        if (dd < best) {
            best = dd;
            jb = j;
        }
    }
    lo = la + (lb - la) * (jb > 0 ? jb - 1 : 0) / N;
    hi = la + (lb - la) * (jb < N ? jb + 1 : N) / N;
    for (int it = 0; it < 60; it++) {
        double x1 = hi - gr * (hi - lo), x2 = lo + gr * (hi - lo), p1[2],
               p2[2];
        osrc_point(src, x1, p1);
        osrc_point(src, x2, p2);
        if (hypot(p1[0] - q[0], p1[1] - q[1]) <
            hypot(p2[0] - q[0], p2[1] - q[1]))
            hi = x2;
        else
            lo = x1;
    }
    return cf__trim_to_global(tr, k, 0.5 * (lo + hi));
}

/* Inside on the source at its parameter t (by |d| - CF__TRIM_KEEP tol). */
static bool
src_inside(const cf__trim_t *tr, const cf__osrc_t *src, double t)
{
    double p[2];
    osrc_point(src, t, p);
    return cf__trim_base_dist(tr, p) < fabs(tr->d) - CF__TRIM_KEEP * tr->tol;
}

/* The same at source parameter T of base piece k's exact offset. */
bool
cf__trim_exact_inside(const cf__trim_t *tr, const cf__osrc_t *src, size_t k,
                      double T)
{
    return src_inside(tr, src, cf__trim_to_local(tr, k, T));
}

/* Bisection between t_in (inside) and t_out (kept) on the source: the
** kept end of the last bracket. */
double
cf__trim_bisect_keep(const cf__trim_t *tr, const cf__osrc_t *src,
                     double t_in, double t_out)
{
    for (int it = 0; it < 60; it++) {
        double mid = 0.5 * (t_in + t_out);
        if (src_inside(tr, src, mid))
            t_in = mid;
        else
            t_out = mid;
    }
    return t_out;
}

/* A cut at u_cut of the source, kept towards u_kept, moved (bisection) to
** where the source's distance reaches |d| - CF__TRIM_KEEP tol; unchanged
** if it is not inside or u_kept is inside too. */
double
cf__trim_src_keep(const cf__trim_t *tr, const cf__osrc_t *src, double u_cut,
                  double u_kept)
{
    if (!src_inside(tr, src, u_cut) ||
        src_inside(tr, src, u_kept))
        return u_cut;
    return cf__trim_bisect_keep(tr, src, u_cut, u_kept);
}
