/*
** Polynomials in Bernstein form on [0, 1] (prefix cf__bp_): coefficient
** arrays a[0..n], read at a stride where the signature has one (a[i * s],
** so one coordinate of interleaved control points is a polynomial too).
** The one copy of de Casteljau, subdivision, degree elevation, products,
** derivatives, the power -> Bernstein conversion and real-root isolation
** that the Bézier, B-spline, geometry and offset files share.
*/
#ifndef CURVEFIG_BPOLY_PRIVATE_H
#define CURVEFIG_BPOLY_PRIVATE_H

#include <stdbool.h>
#include <stddef.h>

#include "curvefig/core.h"

/* de Casteljau on v[0..n] (destroyed) at t; returns the value.  Inline:
** it is the inner loop of every evaluation. */
static inline double
cf__bp_decasteljau(double *v, int n, double t)
{
    double s = 1.0 - t;
    for (int r = n; r > 0; r--)
        for (int i = 0; i < r; i++)
            v[i] = s * v[i] + t * v[i + 1];
    return v[0];
}

/* The value at t of a[0..n] (not modified; any degree n >= 0). */
double cf__bp_eval(const double *a, int n, double t);

/* Split src (degree n, `stride` doubles per point, all of them split) at t
** into left and right (either may be NULL; left may not alias src, right
** may). */
void cf__bp_split(const double *src, size_t stride, int n, double t,
                  double *left, double *right);

/* Elevate pts (degree m, stored with room for degree m + r, `stride`
** doubles per point) r times, in place:
** Q_i = i/(m+1) P_{i-1} + (1 - i/(m+1)) P_i. */
void cf__bp_elevate(double *pts, size_t stride, int m, int r);

/* Product: f (degree nf, stride sf) times g (degree ng, stride sg) into h
** (degree nf + ng, stride sh; h may not alias f or g), times sign, added
** to h when accumulate:
** h_k = sum_{i+j=k} C(nf,i) C(ng,j) / C(nf+ng,k) f_i g_j. */
void cf__bp_mul(const double *f, int nf, size_t sf, const double *g, int ng,
                size_t sg, double *h, size_t sh, double sign,
                bool accumulate);

/* out[0..m-1]: the derivative of a[0..m], degree m - 1 (m >= 1). */
void cf__bp_deriv(const double *a, int m, double *out);

/* Power basis p(x) = sum p[k] x^k (k = 0..n) on [0, h] to Bernstein
** coefficients out[0..n] on [0, 1] in the variable s = x / h (any n;
** out may not alias p). */
void cf__bp_from_power(const double *p, int n, double h, double *out);

/* Points and derivatives 0..k (0 <= k <= CF_BEZIER_MAX_DEGREE) at t of the
** curve of degree n whose coordinate c of control point i is
** p[i * stride + c] (c < nc), into out[j * nc + c] (the j-th derivative of
** coordinate c; zero for j > n).  w == NULL: a polynomial curve.
** Otherwise w[i * stride] is the weight of point i, p holds the weighted
** coordinates w x, and out the Cartesian derivatives (quotient rule).  The
** one evaluator of curve points and derivatives: de Casteljau down to level
** n - k, forward differences for the derivatives (see bpoly.c). */
void cf__bp_curve_derivs(const double *p, const double *w, size_t stride,
                         size_t nc, int n, double t, int k, double *out);

/* The real roots in [0, 1] of a[0..n], ascending, isolated by subdivision
** with Descartes' rule of signs and polished by bisection.  One idea of
** zero: a value of size <= 64 n DBL_EPSILON max|a_i| is zero (so the ends
** are roots when |a_0| or |a_n| is that small, and a cluster narrower than
** 1e-13 is one root).  Writes at most cap roots and sets *count to the
** number written.  NO_MEMORY only. */
cf_status_t cf__bp_roots(const double *a, int n, double *roots, size_t cap,
                         size_t *count);

#endif
