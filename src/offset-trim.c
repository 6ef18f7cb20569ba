/*
** Trimming the raw offset: its self-intersections (pairs of cubics, found on
** fine polylines and polished by Newton's method on the cubics), then the
** parts whose distance to the base curve is at least |d| - tol are kept.
** Between two consecutive split points the classification is constant
** except where the offset leaves the swept disk without crossing itself (at
** the ends of an open curve); such transitions are located by bisection on
** the distance.  A kept piece whose end moved (to a crossing or a
** transition) is fitted again on the parameter range it now offsets, so
** that the trimmed chains carry measured errors like the raw one.
*/
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core-private.h"
#include "bezier-private.h"
#include "offset-private.h"

#define POLY_N 64       /* polyline samples per cubic */
#define BASE_N 256      /* samples of each base piece */
#define CLASS_N 16      /* distance samples per trimmed interval */
#define ACCEPT 0.97     /* a refitted piece is accepted at 97% of tol, as
                        ** the raw pieces are */
#define KEEP 0.03       /* a transition of the exact offset is where its
                        ** distance reaches |d| - KEEP tol: its refitted
                        ** piece (within ACCEPT tol) stays at >= |d| - tol */

/* A split point of the raw chain; at a self-intersection, p is the
** crossing of the exact offset (when found) that the trimmed pieces end
** at, and T the source parameter of that crossing on this branch. */
typedef struct split {
    double g;
    double p[2];
    double T;
    bool exact;
} split;

/* The end of a kept part: the exact offset's parameter T there (when
** known) and the point it must end at (an exact crossing, or NULL). */
typedef struct cut {
    bool has_T;
    double T;
    const double *snap;
} cut;

typedef struct trim {
    const cf_bezier_t *const *base;
    size_t nbase;
    const double *t0, *t1;  /* source parameters of the base pieces */
    double *bsmp;           /* BASE_N + 1 samples per base piece */
    double d, tol;
    const cf_cubics_t *raw;
    double *poly;           /* POLY_N + 1 samples per raw cubic */
    split *splits;          /* at global parameters i + s */
    size_t nsplit, capsplit;
    size_t nisect;
} trim;

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
static double
base_dist(const trim *tr, const double *q)
{
    double best = INFINITY;
    for (size_t i = 0; i < tr->nbase; i++)
        best = fmin(best, cf__dist_sampled(base_fn, tr->base[i],
                                           tr->bsmp + 2 * (BASE_N + 1) * i,
                                           BASE_N, q));
    return best;
}

/* Point of the raw chain at global parameter g = i + s. */
static void
chain_point(const trim *tr, double g, double *p)
{
    size_t i = (size_t)floor(g);
    double s;
    if (i >= tr->raw->count)
        i = tr->raw->count - 1;
    s = g - (double)i;
    cf__cubic_pd(tr->raw->pts + 8 * i, fmin(1.0, fmax(0.0, s)), p, NULL);
}

static cf_status_t
add_split(trim *tr, double g, const double *p, double T)
{
    if (tr->nsplit == tr->capsplit) {
        size_t cap = tr->capsplit ? 2 * tr->capsplit : 16;
        split *n = cf__realloc_array(tr->splits, cap, sizeof *n);
        if (n == NULL)
            return CF_STATUS_NO_MEMORY;
        tr->splits = n;
        tr->capsplit = cap;
    }
    tr->splits[tr->nsplit].g = g;
    tr->splits[tr->nsplit].exact = p != NULL;
    tr->splits[tr->nsplit].T = T;
    if (p != NULL) {
        tr->splits[tr->nsplit].p[0] = p[0];
        tr->splits[tr->nsplit].p[1] = p[1];
    }
    tr->nsplit++;
    return CF_STATUS_OK;
}

/* The raw piece holding global parameter g. */
static size_t
piece_at(const trim *tr, double g)
{
    size_t i = (size_t)floor(fmax(0.0, g));
    return i < tr->raw->count ? i : tr->raw->count - 1;
}

/* Source parameters of base piece k (those of the raw chain's t). */
static double
base_T0(const trim *tr, size_t k)
{
    return tr->t0 != NULL ? tr->t0[k] : (double)k;
}

static double
base_T1(const trim *tr, size_t k)
{
    return tr->t1 != NULL ? tr->t1[k] : (double)k + 1.0;
}

/* The base piece whose range holds T (the first at a shared end). */
static size_t
base_of(const trim *tr, double T)
{
    for (size_t k = 0; k + 1 < tr->nbase; k++)
        if (T <= base_T1(tr, k))
            return k;
    return tr->nbase - 1;
}

/* Source parameter T to the parameter of base piece k and back. */
static double
to_local(const trim *tr, size_t k, double T)
{
    double T0 = base_T0(tr, k), T1 = base_T1(tr, k);
    return T1 > T0 ? fmin(1.0, fmax(0.0, (T - T0) / (T1 - T0))) : 0.0;
}

static double
to_global(const trim *tr, size_t k, double t)
{
    double T0 = base_T0(tr, k), T1 = base_T1(tr, k);
    return T0 + t * (T1 - T0);
}

/* The exact offset that raw piece i approximates (on base piece *k, with
** its travel direction); -1 for a join arc (an empty range). */
static int
piece_source(const trim *tr, size_t i, cf__osrc_t *src, size_t *k)
{
    const cf_cubics_t *raw = tr->raw;
    double mid = 0.5 * (raw->t[i] + raw->t[i + 1]), p[2], dp[2], u[2], t;
    if (!(raw->t[i + 1] > raw->t[i]))
        return -1;
    *k = base_of(tr, mid);
    t = to_local(tr, *k, mid);
    cf__osrc_init_offset(src, tr->base[*k], tr->d);
    /* o' = c' (1 - d kappa): o runs against c' past a cusp */
    cf__osrc_deriv(src, t, p, dp);
    if (cf__bezier_unit_tangent(src->c, t, 1, src->scale, NULL, u) == 0 &&
        dp[0] * u[0] + dp[1] * u[1] < 0.0)
        src->sgn = -1.0;
    return 0;
}

/* Source parameter T of the raw chain's g on a non-arc piece i (linear in
** the piece). */
static double
g_to_T(const trim *tr, size_t i, double g)
{
    const cf_cubics_t *raw = tr->raw;
    double s = fmin(1.0, fmax(0.0, g - (double)i));
    return raw->t[i] + s * (raw->t[i + 1] - raw->t[i]);
}

/* The point of an offset source at t (the limit from the left at t = 1). */
static void
osrc_point(const cf__osrc_t *s, double t, double *p)
{
    (void)cf__osrc_point_dir(s, t, t >= 1.0 ? -1 : 1, p, NULL);
}

/* The source parameter of the point of the exact offset of raw piece i
** (src, on base piece k) nearest q: samples, then golden-section search. */
static double
project(const trim *tr, size_t i, const cf__osrc_t *src, size_t k,
        const double *q)
{
    enum { N = 32 };
    const double gr = 0.6180339887498949;
    double la = to_local(tr, k, tr->raw->t[i]);
    double lb = to_local(tr, k, tr->raw->t[i + 1]), best = INFINITY, p[2];
    double lo, hi;
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
    return to_global(tr, k, 0.5 * (lo + hi));
}

/* Is T on the parameter range of raw piece i (to rounding)? */
static bool
on_range(const trim *tr, size_t i, double T)
{
    double a = tr->raw->t[i], b = tr->raw->t[i + 1], e = 1e-12 * (b - a);
    return T >= a - e && T <= b + e;
}

/* The crossing of the exact offset near the crossing of raw pieces i (at
** s) and j (at u): Newton on o_i(t1) - o_j(t2) = 0 from the pieces'
** parameter ranges, o_i the exact offset that piece i approximates.
** Returns 0, the point in x and the two source parameters in T. */
static int
exact_crossing(const trim *tr, size_t i, double s, size_t j, double u,
               const double *approx, double *x, double *T)
{
    cf__osrc_t si, sj;
    size_t ki, kj;
    double t1, t2, p1[2], d1[2], p2[2], d2[2];
    if (piece_source(tr, i, &si, &ki) != 0 ||
        piece_source(tr, j, &sj, &kj) != 0)
        return -1;
    t1 = to_local(tr, ki, g_to_T(tr, i, (double)i + s));
    t2 = to_local(tr, kj, g_to_T(tr, j, (double)j + u));
    for (int it = 0; it < 30; it++) {
        double fx, fy, det, dt1, dt2;
        cf__osrc_deriv(&si, t1, p1, d1);
        cf__osrc_deriv(&sj, t2, p2, d2);
        fx = p1[0] - p2[0];
        fy = p1[1] - p2[1];
        det = d1[0] * (-d2[1]) - d1[1] * (-d2[0]);
        if (det == 0.0)
            return -1;
        dt1 = (fx * (-d2[1]) - fy * (-d2[0])) / det;
        dt2 = (d1[0] * fy - d1[1] * fx) / det;
        t1 -= dt1;
        t2 -= dt2;
        if (!(t1 >= 0.0 && t1 <= 1.0 && t2 >= 0.0 && t2 <= 1.0))
            return -1;
        if (fabs(dt1) + fabs(dt2) < 1e-15)
            break;
    }
    cf__osrc_deriv(&si, t1, p1, d1);
    cf__osrc_deriv(&sj, t2, p2, d2);
    if (!(hypot(p1[0] - p2[0], p1[1] - p2[1]) <= 1e-9 * (1.0 + fabs(tr->d))))
        return -1;
    x[0] = 0.5 * (p1[0] + p2[0]);
    x[1] = 0.5 * (p1[1] + p2[1]);
    /* it must be the crossing the raw chain approximates: near it, and on
    ** the ranges of the two pieces (their cut ends are fitted there) */
    if (!(hypot(x[0] - approx[0], x[1] - approx[1]) <= 4.0 * tr->tol))
        return -1;
    T[0] = to_global(tr, ki, t1);
    T[1] = to_global(tr, kj, t2);
    if (!on_range(tr, i, T[0]) || !on_range(tr, j, T[1]))
        return -1;
    return 0;
}

/* Newton on B_i(s) - B_j(u) = 0 from (s, u); returns 0 on convergence. */
static int
polish_isect(const double *Pi, const double *Pj, double *s, double *u)
{
    for (int it = 0; it < 20; it++) {
        double a[2], da[2], b[2], db[2], fx, fy, det, ds, du;
        cf__cubic_pd(Pi, *s, a, da);
        cf__cubic_pd(Pj, *u, b, db);
        fx = a[0] - b[0];
        fy = a[1] - b[1];
        /* J = [da, -db] */
        det = da[0] * (-db[1]) - da[1] * (-db[0]);
        if (det == 0.0)
            return -1;
        ds = (fx * (-db[1]) - fy * (-db[0])) / det;
        du = (da[0] * fy - da[1] * fx) / det;
        *s -= ds;
        *u -= du;
        if (!(*s >= -1e-9 && *s <= 1 + 1e-9 && *u >= -1e-9 && *u <= 1 + 1e-9))
            return -1;
        if (fabs(ds) + fabs(du) < 1e-14)
            break;
    }
    *s = fmin(1.0, fmax(0.0, *s));
    *u = fmin(1.0, fmax(0.0, *u));
    return 0;
}

static void
ctrl_box(const double *P, double *lo, double *hi)
{
    lo[0] = hi[0] = P[0];
    lo[1] = hi[1] = P[1];
    for (int k = 1; k < 4; k++) {
        lo[0] = fmin(lo[0], P[2 * k]);
        hi[0] = fmax(hi[0], P[2 * k]);
        lo[1] = fmin(lo[1], P[2 * k + 1]);
        hi[1] = fmax(hi[1], P[2 * k + 1]);
    }
}

/* Proper crossing of segments ab and cd: parameters in *x, *y. */
static int
seg_cross(const double *a, const double *b, const double *c,
          const double *d, double *x, double *y)
{
    double r[2] = { b[0] - a[0], b[1] - a[1] };
    double s[2] = { d[0] - c[0], d[1] - c[1] };
    double den = r[0] * s[1] - r[1] * s[0];
    double q[2] = { c[0] - a[0], c[1] - a[1] };
    if (den == 0.0)
        return 0;
    *x = (q[0] * s[1] - q[1] * s[0]) / den;
    *y = (q[0] * r[1] - q[1] * r[0]) / den;
    return *x >= 0.0 && *x < 1.0 && *y >= 0.0 && *y < 1.0;
}

/* Is the crossing (gi, gj) already recorded (splits come in pairs)? */
static bool
known(const trim *tr, double gi, double gj)
{
    for (size_t k = 0; k + 1 < tr->nsplit; k += 2)
        if (fabs(tr->splits[k].g - gi) < 1e-9 &&
            fabs(tr->splits[k + 1].g - gj) < 1e-9)
            return true;
    return false;
}

static cf_status_t
find_intersections(trim *tr)
{
    const cf_cubics_t *raw = tr->raw;
    size_t n = raw->count;
    for (size_t i = 0; i < n; i++) {
        double loi[2], hii[2];
        ctrl_box(raw->pts + 8 * i, loi, hii);
        for (size_t j = i + 1; j < n; j++) {
            double loj[2], hij[2];
            const double *pi = tr->poly + 2 * (POLY_N + 1) * i;
            const double *pj = tr->poly + 2 * (POLY_N + 1) * j;
            ctrl_box(raw->pts + 8 * j, loj, hij);
            if (loi[0] > hij[0] || loj[0] > hii[0] || loi[1] > hij[1] ||
                loj[1] > hii[1])
                continue;
            for (int a = 0; a < POLY_N; a++) {
                for (int b = 0; b < POLY_N; b++) {
                    double x, y, s, u;
                    if (j == i + 1 && a == POLY_N - 1 && b == 0)
                        continue;   /* the shared end point */
                    if (!seg_cross(pi + 2 * a, pi + 2 * a + 2, pj + 2 * b,
                                   pj + 2 * b + 2, &x, &y))
                        continue;
                    s = (a + x) / POLY_N;
                    u = (b + y) / POLY_N;
                    if (polish_isect(raw->pts + 8 * i, raw->pts + 8 * j, &s,
                                     &u) != 0) {
                        s = (a + x) / POLY_N;
                        u = (b + y) / POLY_N;
                    }
                    if (j == i + 1 && s > 1.0 - 1e-7 && u < 1e-7)
                        continue;
                    if (known(tr, (double)i + s, (double)j + u))
                        continue;   /* found from a neighbouring pair */
                    {
                        double ap[2], xc[2], T[2] = { 0.0, 0.0 };
                        const double *xp = NULL;
                        cf_status_t st;
                        cf__cubic_pd(raw->pts + 8 * i, s, ap, NULL);
                        if (exact_crossing(tr, i, s, j, u, ap, xc, T) == 0)
                            xp = xc;
                        st = add_split(tr, (double)i + s, xp, T[0]);
                        if (st == CF_STATUS_OK)
                            st = add_split(tr, (double)j + u, xp, T[1]);
                        if (st != CF_STATUS_OK)
                            return st;
                    }
                    tr->nisect++;
                }
            }
        }
    }
    return CF_STATUS_OK;
}

static int
cmp_split(const void *x, const void *y)
{
    double a = ((const split *)x)->g, b = ((const split *)y)->g;
    return (a > b) - (a < b);
}

/* Inside the swept disk: closer to the curve than |d| - margin.  Pieces
** are classified with margin 2 tol (the raw chain is within tol of the
** exact offset, which is at distance >= |d| where it is kept); the cut
** between a kept and a dropped sample is placed where the distance reaches
** |d| - tol, so that what is kept stays at distance >= |d| - tol. */
static bool
inside(const trim *tr, double g, double margin)
{
    double p[2];
    chain_point(tr, g, p);
    return base_dist(tr, p) < fabs(tr->d) - margin * tr->tol;
}

/* Inside on the source at its parameter t (by |d| - KEEP tol). */
static bool
src_inside(const trim *tr, const cf__osrc_t *src, double t)
{
    double p[2];
    osrc_point(src, t, p);
    return base_dist(tr, p) < fabs(tr->d) - KEEP * tr->tol;
}

/* The same at source parameter T of base piece k's exact offset. */
static bool
exact_inside(const trim *tr, const cf__osrc_t *src, size_t k, double T)
{
    return src_inside(tr, src, to_local(tr, k, T));
}

/* Bisection between t_in (inside) and t_out (kept) on the source: the
** kept end of the last bracket. */
static double
bisect_keep(const trim *tr, const cf__osrc_t *src, double t_in,
            double t_out)
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
** where the source's distance reaches |d| - KEEP tol; unchanged if it is
** not inside or u_kept is inside too. */
static double
src_keep(const trim *tr, const cf__osrc_t *src, double u_cut, double u_kept)
{
    if (!src_inside(tr, src, u_cut) || src_inside(tr, src, u_kept))
        return u_cut;
    return bisect_keep(tr, src, u_cut, u_kept);
}

/* The raw chain's g of source parameter T on raw piece i. */
static double
T_to_g(const trim *tr, size_t i, double T)
{
    const cf_cubics_t *raw = tr->raw;
    return (double)i + fmin(1.0, fmax(0.0, (T - raw->t[i]) /
                                               (raw->t[i + 1] - raw->t[i])));
}

/* The transition between g_in (inside) and g_out (kept) of the raw chain
** located on the exact offset: bisection in its parameter (the raw
** pieces' ranges mapped linearly) on the distance |d| - KEEP tol.  On
** success the cut is *g (on the raw chain) and *T; -1 if the bracket is
** not one of the exact offset (a join arc between, another base piece, or
** the classes differ there). */
static int
exact_transition(const trim *tr, double g_in, double g_out, double *g,
                 double *T)
{
    const cf_cubics_t *raw = tr->raw;
    size_t i_in = piece_at(tr, g_in), i_out = piece_at(tr, g_out), k, k2, i;
    cf__osrc_t src, s2;
    double T_in, T_out;
    if (piece_source(tr, i_in, &src, &k) != 0 ||
        piece_source(tr, i_out, &s2, &k2) != 0 || k != k2 ||
        (i_in > i_out ? i_in - i_out : i_out - i_in) > 1)
        return -1;
    T_in = g_to_T(tr, i_in, g_in);
    T_out = g_to_T(tr, i_out, g_out);
    if (!exact_inside(tr, &src, k, T_in) || exact_inside(tr, &src, k, T_out))
        return -1;
    T_out = to_global(tr, k, bisect_keep(tr, &src, to_local(tr, k, T_in),
                                         to_local(tr, k, T_out)));
    i = T_out >= raw->t[i_out] && T_out <= raw->t[i_out + 1] ? i_out : i_in;
    *T = T_out;
    *g = T_to_g(tr, i, T_out);
    return 0;
}

/* The transition at the raw chain's cut g (kept side towards g_out) when
** its bracket is not one of the exact offset: from the projection of the
** cut onto the exact offset of its piece, bisection towards the kept end
** of that piece until the distance is |d| - KEEP tol.  -1 on a join arc
** or if that end is inside too. */
static int
exact_cut(const trim *tr, double g_cut, double g_out, double *g, double *T)
{
    const cf_cubics_t *raw = tr->raw;
    size_t i = piece_at(tr, g_cut), k;
    cf__osrc_t src;
    double q[2], T_in, T_out;
    if (piece_source(tr, i, &src, &k) != 0)
        return -1;
    chain_point(tr, g_cut, q);
    T_in = project(tr, i, &src, k, q);
    if (exact_inside(tr, &src, k, T_in)) {
        T_out = g_out > g_cut ? raw->t[i + 1] : raw->t[i];
        if (exact_inside(tr, &src, k, T_out))
            return -1;
        T_in = to_global(tr, k, bisect_keep(tr, &src, to_local(tr, k, T_in),
                                            to_local(tr, k, T_out)));
    }
    *T = T_in;
    *g = T_to_g(tr, i, T_in);
    return 0;
}

/* The circle that join arc i of the raw chain approximates, as an arc
** source from the radial projection of seg's first point to that of its
** last, turning as seg does. */
static void
arc_source(const trim *tr, size_t i, const double *seg, cf__osrc_t *arc)
{
    double T = tr->raw->t[i], c[2], p[2], dp[2], a0, sweep;
    size_t k = base_of(tr, T);
    cf__bezier_eval_point(tr->base[k], to_local(tr, k, T), c);
    a0 = atan2(seg[1] - c[1], seg[0] - c[0]);
    sweep = atan2(seg[7] - c[1], seg[6] - c[0]) - a0;
    cf__cubic_pd(seg, 0.5, p, dp);
    if ((p[0] - c[0]) * dp[1] - (p[1] - c[1]) * dp[0] >= 0.0) {
        while (sweep < 0.0)
            sweep += 2.0 * CF__PI;
    } else {
        while (sweep > 0.0)
            sweep -= 2.0 * CF__PI;
    }
    cf__osrc_init_arc(arc, c[0], c[1], fabs(tr->d), a0, sweep);
}

/* Move an end of the cubic pts to snap (with its neighbouring control
** point); the error grows by at most the distance moved. */
static void
snap_end(double *pts, int end, const double *snap, double *err)
{
    double *e = pts + (end ? 6 : 0), *n = pts + (end ? 4 : 2);
    double dx = snap[0] - e[0], dy = snap[1] - e[1];
    e[0] = snap[0];
    e[1] = snap[1];
    n[0] += dx;
    n[1] += dy;
    *err += hypot(dx, dy);
}

/* Fit the source on [a, b] (covering source parameters [Ta, Tb]) with
** Levien's fit, ends snapped; a piece that misses the tolerance is split
** in two (and so on, to a minimum width).  Pushed onto ch. */
static cf_status_t
refit(trim *tr, cf__chain_t *ch, const cf__osrc_t *src, double a, double b,
      double Ta, double Tb, const double *snap0, const double *snap1,
      int depth)
{
    cf__fit_t f;
    cf_status_t st = cf__fit_piece(src, a, b, CF_OFFSET_LEVIEN,
                                   ACCEPT * tr->tol, &f);
    if (st != CF_STATUS_OK)
        return st;
    if (f.err > ACCEPT * tr->tol && depth < 12 && b - a > 1e-9) {
        double m = 0.5 * (a + b), Tm = 0.5 * (Ta + Tb);
        st = refit(tr, ch, src, a, m, Ta, Tm, snap0, NULL, depth + 1);
        if (st == CF_STATUS_OK)
            st = refit(tr, ch, src, m, b, Tm, Tb, NULL, snap1, depth + 1);
        return st;
    }
    if (snap0 != NULL)
        snap_end(f.pts, 0, snap0, &f.err);
    if (snap1 != NULL)
        snap_end(f.pts, 1, snap1, &f.err);
    ch->cubics->max_error = fmax(ch->cubics->max_error, f.err);
    return cf__chain_push(ch, f.pts, Ta, Tb);
}

/* Refit the part seg of raw piece i whose ends are the cuts c0 (NULL: the
** piece's start) and c1 (NULL: its end). */
static cf_status_t
refit_part(trim *tr, cf__chain_t *ch, size_t i, const double *seg,
           const cut *c0, const cut *c1, const double *snap0,
           const double *snap1)
{
    const cf_cubics_t *raw = tr->raw;
    cf__osrc_t src;
    size_t k;
    double Ta, Tb;
    if (piece_source(tr, i, &src, &k) != 0) {
        /* a join arc: a cut end that is not a crossing is moved along the
        ** circle to where its distance reaches |d| - KEEP tol */
        double ua = 0.0, ub = 1.0;
        arc_source(tr, i, seg, &src);
        if (c0 != NULL && snap0 == NULL)
            ua = src_keep(tr, &src, 0.0, 1.0);
        if (c1 != NULL && snap1 == NULL)
            ub = src_keep(tr, &src, 1.0, ua);
        if (!(ub > ua))
            return CF_STATUS_OK;
        cf__osrc_init_arc(&src, src.cx, src.cy, src.r,
                          src.a0 + src.sweep * ua, src.sweep * (ub - ua));
        return refit(tr, ch, &src, 0.0, 1.0, raw->t[i], raw->t[i],
                     snap0, snap1, 0);
    }
    Ta = raw->t[i];
    Tb = raw->t[i + 1];
    /* an end without a parameter (a crossing of the raw chain only): the
    ** projection of the raw cut, moved towards the kept part to where the
    ** distance reaches |d| - KEEP tol */
    if (c0 != NULL)
        Ta = c0->has_T ? c0->T
                       : to_global(tr, k, src_keep(tr, &src,
                                         to_local(tr, k, project(tr, i, &src,
                                                                 k, seg)),
                                         to_local(tr, k, Tb)));
    if (c1 != NULL)
        Tb = c1->has_T ? c1->T
                       : to_global(tr, k, src_keep(tr, &src,
                                         to_local(tr, k, project(tr, i, &src,
                                                                 k, seg + 6)),
                                         to_local(tr, k, Ta)));
    Ta = fmax(raw->t[i], fmin(raw->t[i + 1], Ta));
    Tb = fmax(raw->t[i], fmin(raw->t[i + 1], Tb));
    if (!(Tb > Ta))
        return CF_STATUS_OK;    /* both cuts at one point: nothing left */
    return refit(tr, ch, &src, to_local(tr, k, Ta), to_local(tr, k, Tb),
                 Ta, Tb, snap0, snap1, 0);
}

/* Append the part [g0, g1] of the raw chain to ch.  Whole raw pieces are
** kept as they are; a piece cut at c0 or c1 is fitted again on the range
** of the exact offset it now covers, an end at an exact crossing (snap)
** placed on it. */
static cf_status_t
append_part(trim *tr, cf__chain_t *ch, double g0, double g1, const cut *c0,
            const cut *c1)
{
    const cf_cubics_t *raw = tr->raw;
    size_t i0 = (size_t)floor(g0), i1, first = SIZE_MAX, last = 0;
    if (i0 >= raw->count)
        i0 = raw->count - 1;
    i1 = (size_t)ceil(g1);
    if (i1 > raw->count)
        i1 = raw->count;
    for (size_t i = i0; i < i1; i++) {
        double s0 = fmax(0.0, g0 - (double)i), s1 = fmin(1.0, g1 - (double)i);
        if (s1 - s0 <= 1e-12)
            continue;
        if (first == SIZE_MAX)
            first = i;
        last = i;
    }
    for (size_t i = first; first != SIZE_MAX && i <= last; i++) {
        double s0 = fmax(0.0, g0 - (double)i), s1 = fmin(1.0, g1 - (double)i);
        double tmp[8], seg[8], e = raw->max_error;
        const double *snap0 = i == first && c0 != NULL ? c0->snap : NULL;
        const double *snap1 = i == last && c1 != NULL ? c1->snap : NULL;
        cf_status_t st;
        if (s1 - s0 <= 1e-12)
            continue;
        if (s0 > 0.0 || s1 < 1.0) {
            cf__bp_split(raw->pts + 8 * i, 2, 3, s1, tmp, NULL);
            if (s0 > 0.0)
                cf__bp_split(tmp, 2, 3, s0 / s1, NULL, seg);
            else
                memcpy(seg, tmp, sizeof seg);
            st = refit_part(tr, ch, i, seg,
                            s0 > 0.0 ? c0 : NULL, s1 < 1.0 ? c1 : NULL,
                            snap0, snap1);
            if (st != CF_STATUS_OK)
                return st;
            continue;
        }
        memcpy(seg, raw->pts + 8 * i, sizeof seg);
        if (snap0 != NULL)
            snap_end(seg, 0, snap0, &e);
        if (snap1 != NULL)
            snap_end(seg, 1, snap1, &e);
        ch->cubics->max_error = fmax(ch->cubics->max_error, e);
        st = cf__chain_push(ch, seg, raw->t[i], raw->t[i + 1]);
        if (st != CF_STATUS_OK)
            return st;
    }
    return CF_STATUS_OK;
}

static cf_status_t
list_add(cf_cubics_list_t *list, size_t *cap, cf_cubics_t *ch)
{
    if (list->count == *cap) {
        size_t nc = *cap ? 2 * *cap : 4;
        cf_cubics_t **n = cf__realloc_array(list->chains, nc, sizeof *n);
        if (n == NULL) {
            cf_cubics_destroy(ch);
            return CF_STATUS_NO_MEMORY;
        }
        list->chains = n;
        *cap = nc;
    }
    list->chains[list->count++] = ch;
    return CF_STATUS_OK;
}

cf_status_t
cf__offset_trim(const cf_bezier_t *const *base, size_t nbase,
                const double *t0, const double *t1, double d, double tol,
                const cf_cubics_t *raw, cf_cubics_list_t **out,
                size_t *nisect)
{
    trim tr;
    cf_cubics_list_t *list;
    size_t cap = 0, nraw = raw->count;
    cf_status_t st = CF_STATUS_OK;
    cf__chain_t ch;
    bool open = false;

    *out = NULL;
    *nisect = 0;
    memset(&tr, 0, sizeof tr);
    tr.base = base;
    tr.nbase = nbase;
    tr.t0 = t0;
    tr.t1 = t1;
    tr.d = d;
    tr.tol = tol;
    tr.raw = raw;
    list = cf__calloc(1, sizeof *list);
    tr.bsmp = cf__alloc_array(2 * (BASE_N + 1) * nbase, sizeof(double));
    tr.poly = cf__alloc_array(2 * (POLY_N + 1) * (nraw ? nraw : 1),
                              sizeof(double));
    if (list == NULL || tr.bsmp == NULL || tr.poly == NULL) {
        st = CF_STATUS_NO_MEMORY;
        goto done;
    }
    for (size_t i = 0; i < nbase; i++)
        for (int k = 0; k <= BASE_N; k++)
            cf__bezier_eval_point(base[i], (double)k / BASE_N,
                                  tr.bsmp + 2 * ((BASE_N + 1) * i + k));
    for (size_t i = 0; i < nraw; i++)
        for (int k = 0; k <= POLY_N; k++)
            cf__cubic_pd(raw->pts + 8 * i, (double)k / POLY_N,
                     tr.poly + 2 * ((POLY_N + 1) * i + k), NULL);
    if (nraw == 0 || d == 0.0) {
        /* nothing to trim: the raw chain is the trimmed one */
        if (nraw > 0) {
            st = cf__chain_init(&ch);
            if (st == CF_STATUS_OK)
                st = append_part(&tr, &ch, 0.0, (double)nraw, NULL, NULL);
            if (st == CF_STATUS_OK)
                st = list_add(list, &cap, cf__chain_take(&ch));
            else
                cf__chain_fini(&ch);
        }
        goto done;
    }
    st = find_intersections(&tr);
    if (st == CF_STATUS_OK)
        st = add_split(&tr, 0.0, NULL, 0.0);
    if (st == CF_STATUS_OK)
        st = add_split(&tr, (double)nraw, NULL, 0.0);
    if (st != CF_STATUS_OK)
        goto done;
    qsort(tr.splits, tr.nsplit, sizeof(split), cmp_split);
    /* classify each interval by samples; locate transitions by bisection */
    for (size_t k = 0; k + 1 < tr.nsplit; k++) {
        double g0 = tr.splits[k].g, g1 = tr.splits[k + 1].g, start = g0;
        bool cls[CLASS_N];
        cut cstart = { tr.splits[k].exact, tr.splits[k].T,
                       tr.splits[k].exact ? tr.splits[k].p : NULL };
        if (g1 - g0 < 1e-12)
            continue;
        for (int m = 0; m < CLASS_N; m++)
            cls[m] = inside(&tr, g0 + (g1 - g0) * (m + 0.5) / CLASS_N, 2.0);
        for (int m = 0; m < CLASS_N; m++) {
            double end = g1;
            cut cend = { tr.splits[k + 1].exact, tr.splits[k + 1].T,
                         tr.splits[k + 1].exact ? tr.splits[k + 1].p : NULL };
            if (m + 1 < CLASS_N && cls[m + 1] == cls[m])
                continue;
            if (m + 1 < CLASS_N) {
                double lo = g0 + (g1 - g0) * (m + 0.5) / CLASS_N;
                double hi = g0 + (g1 - g0) * (m + 1.5) / CLASS_N;
                /* bisect on "inside by |d| - tol" from the kept side */
                double in_end = cls[m] ? lo : hi, out_end = cls[m] ? hi : lo;
                for (int it = 0; it < 50; it++) {
                    double mid = 0.5 * (in_end + out_end);
                    if (inside(&tr, mid, 0.999))
                        in_end = mid;
                    else
                        out_end = mid;
                }
                end = out_end;
                /* the same transition on the exact offset, when it can
                ** be bracketed there */
                cend.has_T = exact_transition(&tr, cls[m] ? lo : hi,
                                              cls[m] ? hi : lo, &end,
                                              &cend.T) == 0 ||
                             exact_cut(&tr, out_end, cls[m] ? hi : lo, &end,
                                       &cend.T) == 0;
                if (!(end >= start && end <= g1)) {
                    /* the exact transition is outside this interval of
                    ** the raw chain: the raw one (projected) */
                    end = out_end;
                    cend.has_T = false;
                }
                cend.snap = NULL;
            }
            if (!cls[m]) {
                if (!open) {
                    st = cf__chain_init(&ch);
                    if (st != CF_STATUS_OK)
                        goto done;
                    open = true;
                }
                st = append_part(&tr, &ch, start, end, &cstart, &cend);
                if (st != CF_STATUS_OK)
                    goto done;
            } else if (open) {
                st = list_add(list, &cap, cf__chain_take(&ch));
                open = false;
                if (st != CF_STATUS_OK)
                    goto done;
            }
            start = end;
            cstart = cend;
        }
        /* an intersection point separates chains */
        if (open && k + 2 < tr.nsplit) {
            st = list_add(list, &cap, cf__chain_take(&ch));
            open = false;
            if (st != CF_STATUS_OK)
                goto done;
        }
    }
    if (open) {
        st = list_add(list, &cap, cf__chain_take(&ch));
        open = false;
    }
done:
    if (open)
        cf__chain_fini(&ch);
    cf__free(tr.bsmp);
    cf__free(tr.poly);
    cf__free(tr.splits);
    if (st != CF_STATUS_OK) {
        cf_cubics_list_destroy(list);
        return st;
    }
    /* drop empty chains */
    {
        size_t w = 0;
        for (size_t i = 0; i < list->count; i++) {
            if (list->chains[i]->count == 0)
                cf_cubics_destroy(list->chains[i]);
            else
                list->chains[w++] = list->chains[i];
        }
        list->count = w;
    }
    *out = list;
    *nisect = tr.nisect;
    return CF_STATUS_OK;
}
