/*
** Evaluation of B-spline and NURBS curves: de Boor at one parameter, the
** batch evaluators (the span walk, the planar cubic fast path) and the
** general path of points and derivatives one parameter at a time.
*/
#include <math.h>
#include <string.h>

#include "bspline-private.h"

/* ---- evaluation --------------------------------------------------------- */

/* Plain de Boor for homogeneous coordinate d on span k. */
static double
deboor_coord(const cf_bspline_t *c, size_t k, double u, size_t d)
{
    double t[CF_BSPLINE_MAX_DEGREE + 1];
    size_t p = (size_t)c->p;
    const double *U = c->U;
    for (size_t j = 0; j <= p; j++)
        t[j] = c->P[(k - p + j) * c->hdim + d];
    for (size_t r = 1; r <= p; r++) {
        for (size_t j = p; j >= r; j--) {
            size_t i = k - p + j;
            double al = (u - U[i]) / (U[i + p + 1 - r] - U[i]);
            t[j] = (1.0 - al) * t[j - 1] + al * t[j];
        }
    }
    return t[p];
}

cf_status_t
cf_bspline_eval(const cf_bspline_t *c, double u, double *out)
{
    cf_status_t st;
    size_t k;
    double w = 1.0;
    if (c == NULL || out == NULL)
        return cf__error(NULL, CF_STATUS_INVALID_ARG, -1, "NULL argument");
    st = cf__bspline_param(c, &u);
    if (st != CF_STATUS_OK)
        return st;
    k = cf__bspline_span(c, u);
    if (c->rational)
        w = deboor_coord(c, k, u, c->dim);
    for (size_t d = 0; d < c->dim; d++) {
        double v = deboor_coord(c, k, u, d);
        out[d] = c->rational ? v / w : v;
    }
    return CF_STATUS_OK;
}

/* C(u) on span k from the basis: out[dim]. */
CF__INLINE void
combine(const double *P, size_t hdim, size_t dim, bool rational, int p,
        size_t k, const double *N, double *out)
{
    const double *q = P + (k - (size_t)p) * hdim;
    if (!rational) {
        for (size_t d = 0; d < dim; d++) {
            double s = 0.0;
            for (int j = 0; j <= p; j++)
                s += N[j] * q[(size_t)j * hdim + d];
            out[d] = s;
        }
    } else {
        double w = 0.0;
        for (int j = 0; j <= p; j++)
            w += N[j] * q[(size_t)j * hdim + dim];
        for (size_t d = 0; d < dim; d++) {
            double s = 0.0;
            for (int j = 0; j <= p; j++)
                s += N[j] * q[(size_t)j * hdim + d];
            out[d] = s / w;
        }
    }
}

CF__INLINE cf_status_t
eval_many_impl(const cf_bspline_t *c, const double *u, size_t n, double *out,
               int p, size_t hdim, size_t dim, bool rational)
{
    double N[CF_BSPLINE_MAX_DEGREE + 1];
    const double *U = c->U, *rk = c->rk, *P = c->P;
    size_t nk = c->nknots, k = c->first_span;
    double a = c->a, b = c->b;
    for (size_t i = 0; i < n; i++) {
        double x = u[i];
        if (CF__UNLIKELY(!(x >= a && x <= b))) {
            cf_status_t st = cf__param_clamp(a, b, &x);
            if (st != CF_STATUS_OK)
                return st;
        }
        k = cf__bspline_next_span(c, k, x, true);
        cf__bspline_basis_rk(U, rk, nk, k, p, x, N);
        combine(P, hdim, dim, rational, p, k, N, out + i * dim);
    }
    return CF_STATUS_OK;
}

/*
** Polynomial cubic curves in the plane, the common case, written out: the
** triangular scheme with the reciprocals (the same operations in the same
** order as basis_rk), then the sum over the four points.  The parameters
** u[0..m-1] all lie on span k: the span's knots, reciprocals and points
** are loop constants, so that the loop is straight-line code the compiler
** vectorises over the parameters.
*/
CF__INLINE void
cubic2_run(const double *U, const double *R1, const double *R2,
           const double *R3, const double *P, size_t k,
           const double *restrict u, size_t m, double *restrict out,
           int deriv)
{
    const double *q = P + 2 * (k - 3);
    const double um2 = U[k - 2], um1 = U[k - 1], u0 = U[k];
    const double u1 = U[k + 1], u2 = U[k + 2], u3 = U[k + 3];
    const double r1 = R1[k], r2a = R2[k - 1], r2b = R2[k];
    const double r3a = R3[k - 2], r3b = R3[k - 1], r3c = R3[k];
    const double q0 = q[0], q1 = q[1], q2 = q[2], q3 = q[3];
    const double q4 = q[4], q5 = q[5], q6 = q[6], q7 = q[7];
    if (!deriv) {
        for (size_t i = 0; i < m; i++) {
            double x = u[i];
            double d1 = x - u0, d2 = x - um1, d3 = x - um2;
            double e1 = u1 - x, e2 = u2 - x, e3 = u3 - x;
            double n0 = e1 * r1, n1 = d1 * r1, t0, t1, t2, m0, m1, m2;
            double N0, N1, N2, N3;
            t0 = n0 * r2a;
            t1 = n1 * r2b;
            m0 = e1 * t0;
            m1 = d2 * t0 + e2 * t1;
            m2 = d1 * t1;
            t0 = m0 * r3a;
            t1 = m1 * r3b;
            t2 = m2 * r3c;
            N0 = e1 * t0;
            N1 = d3 * t0 + e2 * t1;
            N2 = d2 * t1 + e3 * t2;
            N3 = d1 * t2;
            out[2 * i] = N0 * q0 + N1 * q2 + N2 * q4 + N3 * q6;
            out[2 * i + 1] = N0 * q1 + N1 * q3 + N2 * q5 + N3 * q7;
        }
    } else {
        /* C' = 3 sum N_i^2 (P_i - P_{i-1}) / (u_{i+3} - u_i) */
        const double g0 = q2 - q0, g1 = q4 - q2, g2 = q6 - q4;
        const double h0 = q3 - q1, h1 = q5 - q3, h2 = q7 - q5;
        for (size_t i = 0; i < m; i++) {
            double x = u[i];
            double d1 = x - u0, d2 = x - um1;
            double e1 = u1 - x, e2 = u2 - x;
            double n0 = e1 * r1, n1 = d1 * r1, t0, t1, f0, f1, f2;
            t0 = n0 * r2a;
            t1 = n1 * r2b;
            f0 = 3.0 * (e1 * t0) * r3a;
            f1 = 3.0 * (d2 * t0 + e2 * t1) * r3b;
            f2 = 3.0 * (d1 * t1) * r3c;
            out[2 * i] = f0 * g0 + f1 * g1 + f2 * g2;
            out[2 * i + 1] = f0 * h0 + f1 * h1 + f2 * h2;
        }
    }
}

/* parameters per block of span searches (random parameters) */
#define RBLK 32

/* The spans of u[0..m-1], each clamped into [a, b], into ks, without
** branches; whether all of them lie in [a, b].  split is a constant at
** each call: c->splitok is tested once per block, not per parameter.
** With both lookups (the one-break-point cell and the binary search) in
** one loop GCC ran short of registers there, and what it put on the stack
** hung on incidental details: CF__CLONED's x86-64-v4 copy kept the loop
** counter there (a store and two loads per parameter, 3-4 % of W3r and
** W4, docs/performance.md), target_clones' copy of the same code did not.
*/
CF__INLINE int
block_spans(const cf_bspline_t *c, const double *u, size_t m, double a,
            double b, bool split, size_t *ks)
{
    int ok = 1;
    for (size_t l = 0; l < m; l++) {
        double y = u[l], yc = y >= a ? y : a;
        ok &= (y >= a) & (y <= b);
        yc = yc <= b ? yc : b;
        ks[l] = split ? cf__bspline_split_span(c, yc)
                      : cf__bspline_grid_span(c, yc);
    }
    return ok;
}

/* One copy per x86-64 level (CF__CLONED); the file is compiled without
** contraction, so every copy rounds alike. */
CF__INLINE cf_status_t
eval_cubic2_body(const cf_bspline_t *c, const double *u, size_t n,
                 double *out, int deriv)
{
    const double *U = c->U, *P = c->P, *R1 = c->rk;
    const double *R2 = R1 + c->nknots, *R3 = R2 + c->nknots;
    size_t k = c->first_span, i = 0;
    double a = c->a, b = c->b, lo = U[k], hi = U[k + 1];
    while (i < n) {
        double x = u[i];
        size_t j = i + 1;
        if (CF__UNLIKELY(!(x >= a && x <= b))) {
            /* by the domain rule: the end it misses by rounding, alone */
            cf_status_t st = cf__param_clamp(a, b, &x);
            if (st != CF_STATUS_OK)
                return st;
            k = cf__bspline_grid_span(c, x);
            cubic2_run(U, R1, R2, R3, P, k, &x, 1, out + 2 * i, deriv);
            lo = U[k];
            hi = U[k + 1];
            i++;
            continue;
        }
        /* one branch, predictable both for sorted parameters (mostly
        ** inside) and random ones (mostly outside): `&&` would make the
        ** first comparison a coin toss for random parameters; no "next
        ** span" shortcut for the same reason */
        if ((int)(x >= lo) + (int)(x < hi) != 2) {
            /* a new span (random parameters): the spans of the next
            ** RBLK parameters first, without branches, then the points,
            ** so that the table loads do not wait for the search */
            size_t ks[RBLK], mb = n - i < RBLK ? n - i : RBLK;
            int ok = c->splitok
                         ? block_spans(c, u + i, mb, a, b, true, ks)
                         : block_spans(c, u + i, mb, a, b, false, ks);
            if (!ok)
                mb = 1; /* the bad parameter is found above */
            else
                for (size_t l = 0; l < mb; l++)
                    cubic2_run(U, R1, R2, R3, P, ks[l], u + i + l, 1,
                               out + 2 * (i + l), deriv);
            if (!ok) {
                k = cf__bspline_grid_span(c, x);
                cubic2_run(U, R1, R2, R3, P, k, u + i, 1, out + 2 * i,
                           deriv);
            } else {
                k = ks[mb - 1];
            }
            lo = U[k];
            hi = U[k + 1];
            i += mb;
            continue;
        }
        /* still on span k (sorted parameters): the run of parameters
        ** on it, eight at a time first ([lo, hi) lies in the domain, and
        ** NaN ends the run), evaluated by the vectorised loop */
        for (; j + 8 <= n; j += 8) {
            int in = 1;
            for (size_t l = 0; l < 8; l++)
                in &= (u[j + l] >= lo) & (u[j + l] < hi);
            if (!in)
                break;
        }
        while (j < n && (int)(u[j] >= lo) + (int)(u[j] < hi) == 2)
            j++;
        cubic2_run(U, R1, R2, R3, P, k, u + i, j - i, out + 2 * i, deriv);
        i = j;
    }
    return CF_STATUS_OK;
}

CF__CLONED(cf_status_t, eval_cubic2,
           (const cf_bspline_t *c, const double *u, size_t n, double *out,
            int deriv),
           (c, u, n, out, deriv), return)

/* The copies are static (CF__CLONED): this is the other files' way in. */
cf_status_t
cf__bspline_eval_cubic2(const cf_bspline_t *c, const double *u, size_t n,
                        double *out, int deriv)
{
    return eval_cubic2(c, u, n, out, deriv);
}

/* ---- any derivative, one parameter at a time --------------------------- */

CF__INLINE void
deriv_poly_point(const cf_bspline_t *c, const double *rk, size_t kk,
                 double u, int k, double *out)
{
    double v[CF_BSPLINE_MAX_DEGREE + 1];
    size_t p = (size_t)c->p, hd = c->hdim;
    const double *q = c->P + (kk - p) * hd;
    cf__basis_deriv(c->p, c->U, c->nknots, rk, kk, u, k, v);
    for (size_t d = 0; d < c->dim; d++) {
        double s = 0.0;
        for (size_t i = 0; i <= p; i++)
            s += v[i] * q[i * hd + d];
        out[d] = s;
    }
}

cf_status_t
cf__bspline_derivs_general(const cf_bspline_t *c, int k, const double *rk,
                           const double *u, size_t n, double *out)
{
    size_t kk;
    kk = c->first_span;
    for (size_t i = 0; i < n; i++) {
        double x = u[i];
        cf_status_t st = cf__bspline_param(c, &x);
        if (st != CF_STATUS_OK)
            return st;
        kk = cf__bspline_next_span(c, kk, x, rk != NULL);
        if (!c->rational) {
            deriv_poly_point(c, rk, kk, x, k, out + i * c->dim);
        } else {
            /* one coordinate at a time: C_d^(j), j = 0..k, by the
            ** quotient rule (A^(j) = w^(j) = 0 for j > p) */
            double A[CF_BSPLINE_MAX_DEGREE + 1], W[CF_BSPLINE_MAX_DEGREE + 1];
            double Cd[CF__BSPLINE_MAX_RATIONAL_DERIV + 1];
            double vv[(CF_BSPLINE_MAX_DEGREE + 1) * (CF_BSPLINE_MAX_DEGREE + 1)];
            size_t p = (size_t)c->p, hd = c->hdim;
            const double *q = c->P + (kk - p) * hd;
            int top = k < c->p ? k : c->p;
            for (int j = 0; j <= top; j++)
                cf__basis_deriv(c->p, c->U, c->nknots, rk, kk, x, j,
                                vv + (size_t)j * (p + 1));
            for (int j = 0; j <= top; j++) {
                double s = 0.0;
                for (size_t l = 0; l <= p; l++)
                    s += vv[(size_t)j * (p + 1) + l] * q[l * hd + c->dim];
                W[j] = s;
            }
            for (size_t d = 0; d < c->dim; d++) {
                for (int j = 0; j <= top; j++) {
                    double s = 0.0;
                    for (size_t l = 0; l <= p; l++)
                        s += vv[(size_t)j * (p + 1) + l] * q[l * hd + d];
                    A[j] = s;
                }
                for (int j = 0; j <= k; j++) {
                    double s = j <= top ? A[j] : 0.0;
                    int lim = j < c->p ? j : c->p;
                    for (int l = 1; l <= lim; l++)
                        s -= cf__binomial(j, l) * W[l] * Cd[j - l];
                    Cd[j] = s / W[0];
                }
                out[i * c->dim + d] = Cd[k];
            }
        }
    }
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_eval_many(const cf_bspline_t *c, const double *u, size_t n,
                     double *out)
{
    if (c == NULL || (n > 0 && (u == NULL || out == NULL)))
        return cf__error(NULL, CF_STATUS_INVALID_ARG, -1, "NULL argument");
    if (!cf__bspline_accel(c))
        return cf__bspline_derivs_general(c, 0, NULL, u, n, out);
    if (!c->rational && c->dim == 2) {
        switch (c->p) {
        case 1:
            return eval_many_impl(c, u, n, out, 1, 2, 2, false);
        case 2:
            return eval_many_impl(c, u, n, out, 2, 2, 2, false);
        case 3:
            return eval_cubic2(c, u, n, out, 0);
        default:
            break;
        }
    }
    if (c->rational && c->dim == 2 && c->p == 2)
        return eval_many_impl(c, u, n, out, 2, 3, 2, true);
    return eval_many_impl(c, u, n, out, c->p, c->hdim, c->dim, c->rational);
}
