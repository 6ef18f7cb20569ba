/*
** The errors of a degree reduction: a certified bound, the measured
** maximum and the L2 distance of a curve P of degree n and its reduction Q
** of degree m <= n (homogeneous control points, reduce-private.h).
**
** The bound.  Polynomial curves: Q elevated to degree n has control points
** Q'_i, and P(t) - Q(t) = sum_i (P_i - Q'_i) B_i^n(t) is a convex
** combination, so |P(t) - Q(t)| <= max_i |P_i - Q'_i|.  Rational curves
** (homogeneous A/w and B/v): A/w - B/v = (A v - B w) / (w v); the
** numerator N (degree n + m) is bounded by max_i |N_i| and the denominator
** w v from below by its smallest Bernstein coefficient (positive when all
** weights are), so max_i |N_i| / min_i (w v)_i bounds the distance.  A
** rounding allowance of 8 (n + m + 1) eps times the size of the numbers
** that entered is added, so that the bound is never below the exact
** maximum by rounding.
**
** That is the polygon bound (reported as such).  The same holds on every
** piece of the difference curve split by de Casteljau, so the bound
** reported as certified is the largest over 2^BOUND_LEVELS halves, which
** is much closer to the true maximum.
*/
#include <float.h>
#include <math.h>
#include <string.h>

#include "bpoly-private.h"
#include "core-private.h"
#include "reduce-private.h"

/* The bound is refined by halving the difference curve this many times
** (32 pieces): on each piece the control points bound the curve too, and
** they converge to it quadratically in the piece's length. */
#define BOUND_LEVELS 5

static double
norm(const double *x, size_t dim)
{
    double s = 0.0;
    for (size_t c = 0; c < dim; c++)
        s += x[c] * x[c];
    return sqrt(s);
}

/* max |N_i| / min D_i over the points of one piece (s doubles a point,
** N the first dim, D the last when rational, else 1) */
static double
piece_bound(const double *E, int d, size_t dim, size_t s, bool rational)
{
    double num = 0.0, den = INFINITY;
    for (int i = 0; i <= d; i++) {
        num = fmax(num, norm(E + (size_t)i * s, dim));
        den = fmin(den, rational ? E[(size_t)i * s + dim] : 1.0);
    }
    return num / den;
}

cf_status_t
cf__reduce_bound(const double *P, int n, const double *Q, int m, size_t dim,
                 bool rational, double enough, double *bound, double *polygon)
{
    size_t h = dim + rational, s = dim + rational;
    int d = rational ? n + m : n;
    size_t pt = (size_t)(d + 1) * s, pieces = (size_t)1 << BOUND_LEVELS;
    double *E, *work, size = 0.0, allowance, best, first;
    /* E: room for every piece of the last level, then one piece of work */
    E = cf__alloc_array((pieces + 1) * pt, sizeof *E);
    if (E == NULL)
        return CF_STATUS_NO_MEMORY;
    work = E + pieces * pt;
    for (size_t i = 0; i < (size_t)(n + 1) * h; i++)
        size = fmax(size, fabs(P[i]));
    for (size_t i = 0; i < (size_t)(m + 1) * h; i++)
        size = fmax(size, fabs(Q[i]));
    if (!rational) {
        /* E = P - Q elevated to degree n */
        memcpy(E, Q, (size_t)(m + 1) * h * sizeof *E);
        cf__bp_elevate(E, h, m, n - m);
        for (size_t i = 0; i < (size_t)(n + 1) * h; i++)
            E[i] = P[i] - E[i];
        size *= 2.0;
    } else {
        /* N = A v - B w, D = w v (degree n + m) */
        double dmin = INFINITY;
        for (size_t c = 0; c < dim; c++) {
            cf__bp_mul(P + c, n, h, Q + dim, m, h, E + c, s, 1.0, false);
            cf__bp_mul(Q + c, m, h, P + dim, n, h, E + c, s, -1.0, true);
        }
        cf__bp_mul(P + dim, n, h, Q + dim, m, h, E + dim, s, 1.0, false);
        for (int i = 0; i <= d; i++)
            dmin = fmin(dmin, E[(size_t)i * s + dim]);
        size = 2.0 * size * size / dmin;
    }
    allowance = 8.0 * (double)(n + m + 1) * DBL_EPSILON * size;
    best = first = piece_bound(E, d, dim, s, rational);
    /* halve every piece, level by level (piece i of a level at E + i pt,
    ** spread out from the back so that no piece is overwritten before it
    ** is split); the bound of a level is the largest of its pieces' */
    for (int lev = 1; lev <= BOUND_LEVELS && first + allowance > enough;
         lev++) {
        size_t have = (size_t)1 << (lev - 1);
        double b = 0.0;
        for (size_t i = have; i-- > 0;) {
            memcpy(work, E + i * pt, pt * sizeof *E);
            cf__bp_split(work, s, d, 0.5, E + 2 * i * pt,
                         E + (2 * i + 1) * pt);
        }
        for (size_t i = 0; i < 2 * have; i++)
            b = fmax(b, piece_bound(E + i * pt, d, dim, s, rational));
        best = fmin(best, b);
    }
    cf__free(E);
    /* the halving rounds relative to the difference itself: d levels of
    ** convex combinations a halving, eps each */
    best += allowance + 2.0 * BOUND_LEVELS * (double)(d + 1) * DBL_EPSILON *
                            first;
    first += allowance;
    if (polygon != NULL)
        *polygon = first;
    *bound = fmin(best, first);
    return CF_STATUS_OK;
}

static double
dist_at(const double *P, int n, const double *Q, int m, size_t dim,
        bool rational, double t)
{
    double a[64], b[64];
    size_t h = dim + rational, done = 0;
    double s = 0.0;
    /* in blocks of 64 coordinates (the dimension is not bounded) */
    while (done < dim) {
        size_t nc = dim - done < 64 ? dim - done : 64;
        cf__bp_curve_derivs(P + done, rational ? P + dim : NULL, h, nc, n, t,
                            0, a);
        cf__bp_curve_derivs(Q + done, rational ? Q + dim : NULL, h, nc, m, t,
                            0, b);
        for (size_t c = 0; c < nc; c++)
            s += (a[c] - b[c]) * (a[c] - b[c]);
        done += nc;
    }
    return sqrt(s);
}

/* golden-section search for the maximum of the distance on [lo, hi] */
static double
refine(const double *P, int n, const double *Q, int m, size_t dim,
       bool rational, double lo, double hi)
{
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1 = dist_at(P, n, Q, m, dim, rational, x1);
    double f2 = dist_at(P, n, Q, m, dim, rational, x2);
    for (int it = 0; it < 48; it++) {
        if (f1 > f2) {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - g * (hi - lo);
            f1 = dist_at(P, n, Q, m, dim, rational, x1);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + g * (hi - lo);
            f2 = dist_at(P, n, Q, m, dim, rational, x2);
        }
    }
    return fmax(f1, f2);
}

/* The samples' local maxima within 10 % of the largest sample are refined
** (at most REFINE_MAX of them, the largest first): the samples are so
** dense that a local maximum's sample is within a fraction of a percent of
** it, so no other can be the largest; an error of rounding size has
** maxima everywhere and would otherwise be refined everywhere. */
#define REFINE_MAX 8

double
cf__reduce_measure(const double *P, int n, const double *Q, int m, size_t dim,
                   bool rational)
{
    int S = 64 * (n + 1), top[REFINE_MAX], ntop = 0;
    double best = 0.0, vals[3], topv[REFINE_MAX];
    vals[0] = -1.0;
    vals[1] = dist_at(P, n, Q, m, dim, rational, 0.0);
    best = vals[1];
    for (int s = 1; s <= S + 1; s++) {
        vals[2] = s <= S ? dist_at(P, n, Q, m, dim, rational, (double)s / S)
                         : -1.0;
        best = fmax(best, vals[2]);
        if (vals[1] >= vals[0] && vals[1] >= vals[2]) {
            /* a local maximum at (s - 1) / S: keep the REFINE_MAX largest */
            int at = ntop < REFINE_MAX                  ? ntop++
                     : vals[1] > topv[REFINE_MAX - 1] ? REFINE_MAX - 1
                                                      : -1;
            if (at >= 0) {
                while (at > 0 && topv[at - 1] < vals[1]) {
                    topv[at] = topv[at - 1];
                    top[at] = top[at - 1];
                    at--;
                }
                topv[at] = vals[1];
                top[at] = s - 1;
            }
        }
        vals[0] = vals[1];
        vals[1] = vals[2];
    }
    for (int i = 0; i < ntop && topv[i] >= 0.9 * best; i++)
        best = fmax(best, refine(P, n, Q, m, dim, rational,
                                 fmax(0.0, (double)(top[i] - 1) / S),
                                 fmin(1.0, (double)(top[i] + 1) / S)));
    return best;
}

/* In long double: the error's coefficients are differences of nearly
** equal numbers when the reduction is good, and their rounding would be a
** large part of a small L2 distance. */
cf_status_t
cf__reduce_l2_distance(const double *P, int n, const double *Q, int m,
                       size_t h, double *out)
{
    size_t np = (size_t)(n + 1);
    long double *e = cf__alloc_array(np * h, sizeof *e), s = 0.0L;
    if (e == NULL)
        return CF_STATUS_NO_MEMORY;
    /* e = P - Q elevated: Q'_i = sum_j C(m,j) C(n-m,i-j) / C(n,i) Q_j */
    for (int i = 0; i <= n; i++)
        for (size_t c = 0; c < h; c++) {
            long double q = 0.0L;
            int lo = i - (n - m) > 0 ? i - (n - m) : 0, hi = i < m ? i : m;
            for (int jj = lo; jj <= hi; jj++)
                q += (long double)cf__binomial(m, jj) *
                     (long double)cf__binomial(n - m, i - jj) /
                     (long double)cf__binomial(n, i) *
                     (long double)Q[(size_t)jj * h + c];
            e[(size_t)i * h + c] = (long double)P[(size_t)i * h + c] - q;
        }
    for (int p = 0; p <= n; p++)
        for (int q = 0; q <= n; q++) {
            long double g = cf__reduce_gram(n, p, n, q), d = 0.0L;
            for (size_t c = 0; c < h; c++)
                d += e[(size_t)p * h + c] * e[(size_t)q * h + c];
            s += g * d;
        }
    cf__free(e);
    *out = (double)sqrtl(s > 0.0L ? s : 0.0L);
    return CF_STATUS_OK;
}
