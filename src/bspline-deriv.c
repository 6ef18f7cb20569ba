/*
** Derivatives of B-spline and NURBS curves (one parameter and batches),
** the de Boor net and the nonzero basis functions at a parameter.
*/
#include <math.h>
#include <string.h>

#include "bspline-private.h"

cf_status_t
cf_bspline_eval_derivs(const cf_bspline_t *c, double u, int k, double *out)
{
    double v[CF_BSPLINE_MAX_DEGREE + 1], wd[CF_BSPLINE_MAX_DEGREE + 1];
    cf_status_t st;
    size_t kk, p, dim;
    if (c == NULL || out == NULL || k < 0)
        return cf__error(NULL, CF_STATUS_INVALID_ARG, -1, "bad argument");
    st = cf__bspline_param(c, &u);
    if (st != CF_STATUS_OK)
        return st;
    kk = cf__bspline_span(c, u);
    p = (size_t)c->p;
    dim = c->dim;
    for (int j = 0; j <= k; j++) {
        const double *q = c->P + (kk - p) * c->hdim;
        cf__basis_deriv(c->p, c->U, c->nknots, NULL, kk, u, j, v);
        for (size_t d = 0; d < dim; d++) {
            double s = 0.0;
            for (size_t i = 0; i <= p; i++)
                s += v[i] * q[i * c->hdim + d];
            out[(size_t)j * dim + d] = s;
        }
        if (c->rational && j <= c->p) {
            double s = 0.0;
            for (size_t i = 0; i <= p; i++)
                s += v[i] * q[i * c->hdim + dim];
            wd[j] = s;
        }
    }
    if (c->rational) {
        /* C^(j) = (A^(j) - sum_{i=1}^{j} binom(j, i) w^(i) C^(j-i)) / w */
        for (int j = 0; j <= k; j++) {
            int top = j < c->p ? j : c->p;
            for (size_t d = 0; d < dim; d++) {
                double s = out[(size_t)j * dim + d];
                for (int i = 1; i <= top; i++)
                    s -= cf__binomial(j, i) * wd[i]
                         * out[(size_t)(j - i) * dim + d];
                out[(size_t)j * dim + d] = s / wd[0];
            }
        }
    }
    return CF_STATUS_OK;
}

/* First derivative of a polynomial curve: N^{p-1} with the reciprocals,
** then C' = sum p (P_i - P_{i-1}) / (u_{i+p} - u_i) N_i^{p-1}. */
CF__INLINE void
deriv1_fast(const cf_bspline_t *c, size_t kk, double u, int p, size_t hd,
            size_t dim, double *out)
{
    double N[CF_BSPLINE_MAX_DEGREE + 1];
    const double *rk = c->rk + (size_t)(p - 1) * c->nknots;
    const double *q = c->P + (kk - (size_t)p) * hd;
    cf__bspline_basis_rk(c->U, c->rk, c->nknots, kk, p - 1, u, N);
    for (size_t d = 0; d < dim; d++) {
        double s = 0.0;
        for (int j = 1; j <= p; j++) {
            size_t i = kk - (size_t)p + (size_t)j;
            s += N[j - 1] * rk[i] * (q[(size_t)j * hd + d]
                                     - q[(size_t)(j - 1) * hd + d]);
        }
        out[d] = (double)p * s;
    }
}

CF__INLINE cf_status_t
deriv1_many(const cf_bspline_t *c, const double *u, size_t n, double *out,
            int p, size_t hd, size_t dim)
{
    size_t k = c->first_span;
    for (size_t i = 0; i < n; i++) {
        double x = u[i];
        if (CF__UNLIKELY(!(x >= c->a && x <= c->b))) {
            cf_status_t st = cf__bspline_param(c, &x);
            if (st != CF_STATUS_OK)
                return st;
        }
        k = cf__bspline_next_span(c, k, x, true);
        deriv1_fast(c, k, x, p, hd, dim, out + i * dim);
    }
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_eval_deriv_many(const cf_bspline_t *c, const double *u, size_t n,
                           int k, double *out)
{
    bool ready;
    const double *rk;
    if (c == NULL || k < 0 || (n > 0 && (u == NULL || out == NULL)))
        return cf__error(NULL, CF_STATUS_INVALID_ARG, -1, "bad argument");
    ready = cf__bspline_accel(c);
    rk = ready ? c->rk : NULL;
    if (k == 0 && ready)
        return cf_bspline_eval_many(c, u, n, out);
    if (ready && !c->rational && k == 1 && c->p >= 1) {
        if (c->dim == 2 && c->p == 3)
            return cf__bspline_eval_cubic2(c, u, n, out, 1);
        return deriv1_many(c, u, n, out, c->p, c->hdim, c->dim);
    }
    if (c->rational && k > CF__BSPLINE_MAX_RATIONAL_DERIV)
        return cf__error(NULL, CF_STATUS_INVALID_ARG, -1,
                         "derivative order %d of a NURBS is above "
                         "%d", k, CF__BSPLINE_MAX_RATIONAL_DERIV);
    return cf__bspline_derivs_general(c, k, rk, u, n, out);
}

size_t
cf_bspline_deboor_size(const cf_bspline_t *c)
{
    size_t p;
    if (c == NULL)
        return 0;
    p = (size_t)c->p;
    return (p + 1) * (p + 2) / 2 * c->dim;
}

/* The scalar de Boor triangle of homogeneous coordinate d into T
** (level after level). */
static void
deboor_triangle(const cf_bspline_t *c, size_t k, double u, size_t d,
                double *T)
{
    size_t p = (size_t)c->p, off = 0;
    const double *U = c->U;
    for (size_t j = 0; j <= p; j++)
        T[j] = c->P[(k - p + j) * c->hdim + d];
    for (size_t r = 1; r <= p; r++) {
        size_t prev = off;
        off += p + 2 - r;
        for (size_t l = 0; l + r <= p; l++) {
            size_t i = k - p + r + l;
            double al = (u - U[i]) / (U[i + p + 1 - r] - U[i]);
            T[off + l] = (1.0 - al) * T[prev + l] + al * T[prev + l + 1];
        }
    }
}

cf_status_t
cf_bspline_deboor(const cf_bspline_t *c, double u, double *out, size_t *span,
                  int *mult)
{
    double T[(CF_BSPLINE_MAX_DEGREE + 1) * (CF_BSPLINE_MAX_DEGREE + 2) / 2];
    double W[(CF_BSPLINE_MAX_DEGREE + 1) * (CF_BSPLINE_MAX_DEGREE + 2) / 2];
    size_t k, tot;
    cf_status_t st;
    if (c == NULL || out == NULL)
        return cf__error(NULL, CF_STATUS_INVALID_ARG, -1, "NULL argument");
    st = cf__bspline_param(c, &u);
    if (st != CF_STATUS_OK)
        return st;
    k = cf__bspline_span(c, u);
    tot = ((size_t)c->p + 1) * ((size_t)c->p + 2) / 2;
    if (c->rational)
        deboor_triangle(c, k, u, c->dim, W);
    for (size_t d = 0; d < c->dim; d++) {
        deboor_triangle(c, k, u, d, T);
        for (size_t i = 0; i < tot; i++)
            out[i * c->dim + d] = c->rational ? T[i] / W[i] : T[i];
    }
    if (span != NULL)
        *span = k;
    if (mult != NULL)
        *mult = cf__knots_mult(c->U, c->nknots, u);
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_basis(const cf_bspline_t *c, double u, size_t *first, double *N)
{
    cf_status_t st;
    size_t k;
    if (c == NULL || N == NULL)
        return cf__error(NULL, CF_STATUS_INVALID_ARG, -1, "NULL argument");
    st = cf__bspline_param(c, &u);
    if (st != CF_STATUS_OK)
        return st;
    k = cf__bspline_span(c, u);
    cf__basis_deriv(c->p, c->U, c->nknots, NULL, k, u, 0, N);
    if (first != NULL)
        *first = k - (size_t)c->p;
    return CF_STATUS_OK;
}
