/*
** Linear solvers for interpolation: Sherman-Morrison (cyclic tridiagonal,
** around Thomas eliminations), banded LU with partial pivoting and Givens
** least squares.  See linsolve-private.h for the contracts.
*/
#include <assert.h>
#include <float.h>
#include <math.h>
#include <string.h>

#include "core-private.h"
#include "linsolve-private.h"
#include "numtext-private.h"

/* ---- tridiagonal -------------------------------------------------------- */

/*
** Thomas elimination with caller scratch c[n] (the modified super-diagonal).
** The pivot m_i = mid_i - sub_i c_{i-1} is called negligible when it is
** below a few ulps of the terms it was computed from.
*/
static cf_status_t
thomas(size_t n, const double *sub, const double *mid, const double *sup,
       double *rhs, size_t nrhs, double *c, cf_diag_t *diag)
{
    for (size_t i = 0; i < n; i++) {
        double lower = i > 0 ? sub[i] : 0.0;
        double prev = i > 0 ? c[i - 1] : 0.0;
        double m = mid[i] - lower * prev;
        double scale = fabs(mid[i]) + fabs(lower * prev);
        if (!(fabs(m) > 8.0 * DBL_EPSILON * scale) || !isfinite(m))
            return cf__error(diag, CF_STATUS_DEGENERATE, (long)i,
                             "tridiagonal system is singular at row %zu "
                             "(pivot %s)", i, CF__NUM(m));
        c[i] = i + 1 < n ? sup[i] / m : 0.0;
        for (size_t k = 0; k < nrhs; k++) {
            double r = rhs[i * nrhs + k];
            if (i > 0)
                r -= lower * rhs[(i - 1) * nrhs + k];
            rhs[i * nrhs + k] = r / m;
        }
    }
    for (size_t i = n - 1; i-- > 0;) {
        for (size_t k = 0; k < nrhs; k++)
            rhs[i * nrhs + k] -= c[i] * rhs[(i + 1) * nrhs + k];
    }
    return CF_STATUS_OK;
}

/*
** A = T + u v^T where A has the corner entries beta = A[0][n-1] = sub[0]
** and alpha = A[n-1][0] = sup[n-1].  With gamma = -mid[0] (or -1):
**     u = (gamma, 0, ..., 0, alpha),  v = (1, 0, ..., 0, beta / gamma),
** T is tridiagonal with T[0][0] = mid[0] - gamma and
** T[n-1][n-1] = mid[n-1] - alpha beta / gamma.  Then
**     x = y - z (v.y) / (1 + v.z),  T y = rhs,  T z = u.
*/
cf_status_t
cf__solve_cyclic_tridiagonal(size_t n, const double *sub, const double *mid,
                             const double *sup, double *rhs, size_t nrhs,
                             cf_diag_t *diag)
{
    double *work, *mid2, *z, *c;
    double alpha, beta, gamma, denom;
    cf_status_t st;
    if (n < 3 || nrhs == 0)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "cyclic tridiagonal system needs size >= 3, "
                         "got %zu (with %zu right-hand sides)", n, nrhs);
    work = cf__alloc_array(n, 3 * sizeof *work);
    if (work == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "no memory for a cyclic system of size %zu", n);
    mid2 = work;
    z = work + n;
    c = work + 2 * n;
    alpha = sup[n - 1];
    beta = sub[0];
    gamma = mid[0] != 0.0 ? -mid[0] : -1.0;
    memcpy(mid2, mid, n * sizeof *mid2);
    mid2[0] = mid[0] - gamma;
    mid2[n - 1] = mid[n - 1] - alpha * beta / gamma;
    st = thomas(n, sub, mid2, sup, rhs, nrhs, c, diag);
    if (st == CF_STATUS_OK) {
        memset(z, 0, n * sizeof *z);
        z[0] = gamma;
        z[n - 1] = alpha;
        st = thomas(n, sub, mid2, sup, z, 1, c, diag);
    }
    if (st == CF_STATUS_OK) {
        denom = 1.0 + z[0] + beta / gamma * z[n - 1];
        if (!(fabs(denom) > 8.0 * DBL_EPSILON * (1.0 + fabs(z[0]) +
                                                  fabs(beta / gamma *
                                                       z[n - 1]))))
            st = cf__error(diag, CF_STATUS_DEGENERATE, 0,
                           "cyclic tridiagonal system is singular");
    }
    if (st == CF_STATUS_OK) {
        for (size_t k = 0; k < nrhs; k++) {
            double vy = rhs[k] + beta / gamma * rhs[(n - 1) * nrhs + k];
            double f = vy / denom;
            for (size_t i = 0; i < n; i++)
                rhs[i * nrhs + k] -= f * z[i];
        }
    }
    cf__free(work);
    return st;
}

/* ---- banded LU ---------------------------------------------------------- */

static double *
band_at(const cf__band_t *b, size_t i, size_t j)
{
    assert(j + b->kl >= i && j <= i + b->ku + b->kl);
    return &b->a[i * b->width + (j + b->kl - i)];
}

cf_status_t
cf__band_init(cf__band_t *b, size_t n, size_t kl, size_t ku, cf_diag_t *diag)
{
    memset(b, 0, sizeof *b);
    if (n == 0)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "banded system of size 0");
    b->n = n;
    b->kl = kl;
    b->ku = ku;
    b->width = 2 * kl + ku + 1;
    b->a = cf__calloc(n, b->width * sizeof *b->a);
    b->lower = kl > 0 ? cf__calloc(n, kl * sizeof *b->lower) : NULL;
    b->pivot = cf__alloc_array(n, sizeof *b->pivot);
    if (b->a == NULL || (kl > 0 && b->lower == NULL) || b->pivot == NULL) {
        cf__band_fini(b);
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "no memory for a banded system of size %zu", n);
    }
    return CF_STATUS_OK;
}

void
cf__band_fini(cf__band_t *b)
{
    if (b == NULL)
        return;
    cf__free(b->a);
    cf__free(b->lower);
    cf__free(b->pivot);
    memset(b, 0, sizeof *b);
}

void
cf__band_set(cf__band_t *b, size_t i, size_t j, double v)
{
    assert(!b->factored && i < b->n && j < b->n);
    assert(j + b->kl >= i && j <= i + b->ku);
    *band_at(b, i, j) = v;
}

cf_status_t
cf__band_factor(cf__band_t *b, cf_diag_t *diag)
{
    size_t n = b->n, kl = b->kl, reach = b->ku + b->kl;
    double scale = 0.0;
    for (size_t i = 0; i < n * b->width; i++) {
        if (!isfinite(b->a[i]))
            return cf__error(diag, CF_STATUS_NOT_FINITE, (long)(i / b->width),
                             "banded system has a non-finite entry in "
                             "row %zu", i / b->width);
        if (fabs(b->a[i]) > scale)
            scale = fabs(b->a[i]);
    }
    for (size_t k = 0; k < n; k++) {
        size_t last = k + kl < n ? k + kl : n - 1;
        size_t jend = k + reach < n ? k + reach : n - 1;
        size_t p = k;
        double big = fabs(*band_at(b, k, k)), piv;
        for (size_t i = k + 1; i <= last; i++) {
            if (fabs(*band_at(b, i, k)) > big) {
                big = fabs(*band_at(b, i, k));
                p = i;
            }
        }
        if (!(big > DBL_EPSILON * scale))
            return cf__error(diag, CF_STATUS_DEGENERATE, (long)k,
                             "banded system is singular at row %zu "
                             "(largest pivot %s)", k, CF__NUM(big));
        b->pivot[k] = p;
        if (p != k) {
            for (size_t j = k; j <= jend; j++) {
                double t = *band_at(b, k, j);
                *band_at(b, k, j) = *band_at(b, p, j);
                *band_at(b, p, j) = t;
            }
        }
        piv = *band_at(b, k, k);
        for (size_t i = k + 1; i <= last; i++) {
            double l = *band_at(b, i, k) / piv;
            b->lower[k * kl + (i - k - 1)] = l;
            *band_at(b, i, k) = 0.0;
            if (l == 0.0)
                continue;
            for (size_t j = k + 1; j <= jend; j++)
                *band_at(b, i, j) -= l * *band_at(b, k, j);
        }
    }
    b->factored = 1;
    return CF_STATUS_OK;
}

void
cf__band_solve(const cf__band_t *b, double *rhs, size_t nrhs)
{
    size_t n = b->n, kl = b->kl, reach = b->ku + b->kl;
    assert(b->factored);
    for (size_t k = 0; k < n; k++) {
        size_t p = b->pivot[k];
        size_t last = k + kl < n ? k + kl : n - 1;
        if (p != k) {
            for (size_t c = 0; c < nrhs; c++) {
                double t = rhs[k * nrhs + c];
                rhs[k * nrhs + c] = rhs[p * nrhs + c];
                rhs[p * nrhs + c] = t;
            }
        }
        for (size_t i = k + 1; i <= last; i++) {
            double l = b->lower[k * kl + (i - k - 1)];
            for (size_t c = 0; c < nrhs; c++)
                rhs[i * nrhs + c] -= l * rhs[k * nrhs + c];
        }
    }
    for (size_t i = n; i-- > 0;) {
        size_t jend = i + reach < n ? i + reach : n - 1;
        double d = *band_at(b, i, i);
        for (size_t c = 0; c < nrhs; c++) {
            double s = rhs[i * nrhs + c];
            for (size_t j = i + 1; j <= jend; j++)
                s -= *band_at(b, i, j) * rhs[j * nrhs + c];
            rhs[i * nrhs + c] = s / d;
        }
    }
}

/* ---- banded least squares by Givens rotations --------------------------- */

cf_status_t
cf__lsq_band_init(cf__lsq_band_t *b, size_t n, size_t w, size_t nrhs,
                  cf_diag_t *diag)
{
    memset(b, 0, sizeof *b);
    if (n == 0 || w == 0 || nrhs == 0)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "banded least squares with %zu unknowns, band %zu "
                         "and %zu right-hand sides", n, w, nrhs);
    b->n = n;
    b->w = w;
    b->nrhs = nrhs;
    b->R = cf__calloc(n, w * sizeof *b->R);
    b->qb = cf__calloc(n, nrhs * sizeof *b->qb);
    b->row = cf__alloc_array(w + nrhs, sizeof *b->row);
    if (b->R == NULL || b->qb == NULL || b->row == NULL) {
        cf__lsq_band_fini(b);
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "no memory for banded least squares with %zu "
                         "unknowns", n);
    }
    return CF_STATUS_OK;
}

void
cf__lsq_band_fini(cf__lsq_band_t *b)
{
    if (b == NULL)
        return;
    cf__free(b->R);
    cf__free(b->qb);
    cf__free(b->row);
    memset(b, 0, sizeof *b);
}

/*
** The new row a (columns first .. first + w - 1) is rotated against R's rows
** k = first, first + 1, ...: with r = hypot(R_kk, a_k), c = R_kk / r,
** s = a_k / r, row k becomes c R_k + s a and a becomes -s R_k + c a, whose
** entry k is 0.  An empty row k of R (R_kk = 0 so far) simply takes a.
** Since earlier rows started no later, R_k has no entries beyond
** first + w - 1, so a stays inside its window, shifted by one each step.
*/
void
cf__lsq_band_add(cf__lsq_band_t *b, size_t first, const double *v,
                 const double *rhs)
{
    size_t w = b->w, nrhs = b->nrhs;
    double *a = b->row, *y = b->row + w;
    assert(first >= b->last_first && first < b->n);
    b->last_first = first;
    memcpy(a, v, w * sizeof *a);
    memcpy(y, rhs, nrhs * sizeof *y);
    for (size_t j = 0; j < w; j++)
        b->scale = fmax(b->scale, fabs(a[j]));
    /* a[j] is the entry in column k + j for the current k */
    for (size_t k = first; k < b->n && k < first + w; k++) {
        double *Rk = b->R + k * w, *qk = b->qb + k * nrhs;
        size_t width = first + w - k; /* live entries of a */
        double r, c, s;
        if (a[0] != 0.0) {
            if (Rk[0] == 0.0) {
                /* take the row as it is */
                for (size_t j = 0; j < width; j++)
                    Rk[j] = a[j];
                memcpy(qk, y, nrhs * sizeof *y);
                return;
            }
            r = hypot(Rk[0], a[0]);
            c = Rk[0] / r;
            s = a[0] / r;
            for (size_t j = 0; j < width; j++) {
                double rk = Rk[j], aj = a[j];
                Rk[j] = c * rk + s * aj;
                a[j] = -s * rk + c * aj;
            }
            for (size_t j = 0; j < nrhs; j++) {
                double q = qk[j], yj = y[j];
                qk[j] = c * q + s * yj;
                y[j] = -s * q + c * yj;
            }
        }
        /* shift the window: a[0] is now 0 */
        memmove(a, a + 1, (width - 1) * sizeof *a);
        a[width - 1] = 0.0;
    }
}

cf_status_t
cf__lsq_band_solve(const cf__lsq_band_t *b, double *x, cf_diag_t *diag)
{
    size_t n = b->n, w = b->w, nrhs = b->nrhs;
    for (size_t i = n; i-- > 0;) {
        const double *Ri = b->R + i * w;
        if (!(fabs(Ri[0]) > (double)n * DBL_EPSILON * b->scale))
            return cf__error(diag, CF_STATUS_DEGENERATE, (long)i,
                             "least-squares matrix is rank deficient: "
                             "column %zu depends on the others", i);
        for (size_t c = 0; c < nrhs; c++) {
            double s = b->qb[i * nrhs + c];
            for (size_t j = 1; j < w && i + j < n; j++)
                s -= Ri[j] * x[(i + j) * nrhs + c];
            x[i * nrhs + c] = s / Ri[0];
        }
    }
    return CF_STATUS_OK;
}
