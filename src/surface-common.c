/* Helpers shared by the surface modules: grids, parameters, the quotient
** rule, normals and curvatures (surface-private.h). */
#include <float.h>
#include <math.h>
#include <string.h>

#include "surface-private.h"
#include "numtext-private.h"

cf_status_t
cf__surf_fill(size_t dim, const double *points, const double *weights,
              size_t nu, size_t nv, double *hpts, cf_diag_t *diag)
{
    size_t hdim = dim + (weights != NULL);
    for (size_t i = 0; i < nu; i++) {
        for (size_t j = 0; j < nv; j++) {
            size_t f = i * nv + j;
            const double *p = points + f * dim;
            double w = 1.0;
            if (weights != NULL) {
                w = weights[f];
                if (!isfinite(w) || !(w > 0.0))
                    return cf__error(diag, CF_STATUS_BAD_WEIGHT, (long)f,
                                     "weight W[%zu][%zu] is %s; weights "
                                     "must be finite and positive",
                                     i, j, CF__NUM(w));
            }
            for (size_t k = 0; k < dim; k++) {
                if (!isfinite(p[k]))
                    return cf__error(diag, CF_STATUS_NOT_FINITE, (long)f,
                                     "point P[%zu][%zu] has coordinate "
                                     "%zu = %s; coordinates must be finite",
                                     i, j, k + 1, CF__NUM(p[k]));
                hpts[f * hdim + k] = w * p[k];
            }
            if (weights != NULL)
                hpts[f * hdim + dim] = w;
        }
    }
    /* w x may overflow for huge finite x and w */
    return weights != NULL ? cf__surf_check_h(dim, hpts, nu, nv, diag)
                           : CF_STATUS_OK;
}

cf_status_t
cf__surf_check_h(size_t dim, const double *hpts, size_t nu, size_t nv,
                 cf_diag_t *diag)
{
    size_t hdim = dim + 1;
    for (size_t f = 0; f < nu * nv; f++) {
        const double *p = hpts + f * hdim;
        if (!isfinite(p[dim]) || !(p[dim] > 0.0))
            return cf__error(diag, CF_STATUS_BAD_WEIGHT, (long)f,
                             "weight W[%zu][%zu] is %s; weights must be "
                             "finite and positive", f / nv, f % nv,
                             CF__NUM(p[dim]));
        for (size_t k = 0; k < dim; k++)
            if (!isfinite(p[k]))
                return cf__error(diag, CF_STATUS_NOT_FINITE, (long)f,
                                 "point P[%zu][%zu] has homogeneous "
                                 "coordinate %zu = %s; coordinates must be "
                                 "finite", f / nv, f % nv, k + 1,
                                 CF__NUM(p[k]));
    }
    return CF_STATUS_OK;
}

void
cf__surf_transpose(const double *src, size_t nu, size_t nv, size_t h,
                   double *dst)
{
    for (size_t i = 0; i < nu; i++)
        for (size_t j = 0; j < nv; j++)
            memcpy(dst + (j * nu + i) * h, src + (i * nv + j) * h,
                   h * sizeof *dst);
}

void
cf__surf_points(const double *hpts, size_t cnt, size_t dim, bool rational,
                double *out)
{
    size_t hdim = dim + rational;
    for (size_t f = 0; f < cnt; f++) {
        double w = rational ? hpts[f * hdim + dim] : 1.0;
        for (size_t k = 0; k < dim; k++)
            out[f * dim + k] = hpts[f * hdim + k] / w;
    }
}

void
cf__surf_weights(const double *hpts, size_t cnt, size_t dim, bool rational,
                 double *out)
{
    for (size_t f = 0; f < cnt; f++)
        out[f] = rational ? hpts[f * (dim + 1) + dim] : 1.0;
}

cf_status_t
cf__surf_param(double a, double b, double *x, cf_dir_t dir, cf_diag_t *diag)
{
    double given = *x;
    cf_status_t st = cf__param_clamp(a, b, x);
    if (st == CF_STATUS_NOT_FINITE)
        return cf__error(diag, st, -1, "parameter %s is %s",
                         dir == CF_DIR_U ? "u" : "v", CF__NUM(given));
    if (st != CF_STATUS_OK)
        return cf__error(diag, st, -1,
                         "parameter %s = %s is outside the domain [%s, %s]",
                         dir == CF_DIR_U ? "u" : "v", CF__NUM(given),
                         CF__NUM(a), CF__NUM(b));
    return CF_STATUS_OK;
}

void
cf__surf_rational_derivs(const double *A, size_t dim, size_t hdim, int k,
                         double *out)
{
    size_t K = (size_t)k + 1;
    memset(out, 0, K * K * dim * sizeof *out);
    for (int a = 0; a <= k; a++) {
        for (int b = 0; a + b <= k; b++) {
            const double *Aab = A + ((size_t)a * K + (size_t)b) * hdim;
            double *S = out + ((size_t)a * K + (size_t)b) * dim;
            if (hdim == dim) {
                memcpy(S, Aab, dim * sizeof *S);
                continue;
            }
            for (size_t c = 0; c < dim; c++) {
                double v = Aab[c];
                for (int j = 1; j <= b; j++)
                    v -= cf__binomial(b, j) *
                         A[((size_t)j) * hdim + dim] *
                         out[((size_t)a * K + (size_t)(b - j)) * dim + c];
                for (int i = 1; i <= a; i++) {
                    double ci = cf__binomial(a, i), v2 = 0.0;
                    v -= ci * A[((size_t)i * K) * hdim + dim] *
                         out[((size_t)(a - i) * K + (size_t)b) * dim + c];
                    for (int j = 1; j <= b; j++)
                        v2 += cf__binomial(b, j) *
                              A[((size_t)i * K + (size_t)j) * hdim + dim] *
                              out[((size_t)(a - i) * K + (size_t)(b - j)) *
                                      dim + c];
                    v -= ci * v2;
                }
                S[c] = v / A[dim];
            }
        }
    }
}

void
cf__surf_tensor_point(const double *P, size_t stride, size_t h, size_t dim,
                      const double *Nu, size_t pu, const double *Nv,
                      size_t qv, double *out)
{
    double acc[64], w = 1.0;
    if (h > dim) {
        w = 0.0;
        for (size_t i = 0; i < pu; i++)
            for (size_t j = 0; j < qv; j++)
                w += Nu[i] * Nv[j] * P[i * stride + j * h + dim];
    }
    /* coordinates in blocks of 64 (no allocation for any dimension) */
    for (size_t c0 = 0; c0 < dim; c0 += 64) {
        size_t n = dim - c0 < 64 ? dim - c0 : 64;
        memset(acc, 0, sizeof acc);
        for (size_t i = 0; i < pu; i++) {
            const double *row = P + i * stride + c0;
            for (size_t j = 0; j < qv; j++) {
                double b = Nu[i] * Nv[j];
                for (size_t c = 0; c < n; c++)
                    acc[c] += b * row[j * h + c];
            }
        }
        for (size_t c = 0; c < n; c++)
            out[c0 + c] = acc[c] / w;
    }
}

void
cf__surf_tensor_derivs(const double *P, size_t stride, size_t h,
                       const double *Nu, size_t pu, const double *Nv,
                       size_t qv, size_t K, double *R, double *A)
{
    memset(A, 0, K * K * h * sizeof *A);
    /* A3.6: R_j = sum_i N_i^(a)(u) P[i][j], then A_ab = sum_j N_j^(b)(v)
    ** R_j */
    for (size_t a = 0; a < K; a++) {
        memset(R, 0, qv * h * sizeof *R);
        for (size_t i = 0; i < pu; i++) {
            double b = Nu[a * pu + i];
            const double *row = P + i * stride;
            for (size_t x = 0; x < qv * h; x++)
                R[x] += b * row[x];
        }
        for (size_t b = 0; a + b < K; b++) {
            double *Aab = A + (a * K + b) * h;
            for (size_t j = 0; j < qv; j++)
                for (size_t c = 0; c < h; c++)
                    Aab[c] += Nv[b * qv + j] * R[j * h + c];
        }
    }
}

static void
cross(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static double
dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Layout of order-2 derivatives: (a 3 + b) 3. */
#define D_(a, b) (D + ((a) * 3 + (b)) * 3)

/* A tangent shorter than this times the other one, or two tangents whose
** angle has a sine below it, is rounding noise: at a pole of a sphere S_v
** is zero but for rounding, and the normal of such noise is arbitrary. */
#define SURF_TINY (64.0 * DBL_EPSILON)

static double
norm3(const double *a)
{
    return sqrt(dot(a, a));
}

/* The unit normal, and the larger tangent length in *scale. */
static cf_status_t
unit_normal(const double *D, double *out, double *scale)
{
    double su[3], sv[3], n[3], a = norm3(D_(1, 0)), b = norm3(D_(0, 1)), len;
    if (!(a > 0.0) || !(b > 0.0) || !isfinite(a) || !isfinite(b)
        || b <= SURF_TINY * a || a <= SURF_TINY * b)
        return CF_STATUS_DEGENERATE;
    for (int c = 0; c < 3; c++) {
        su[c] = D_(1, 0)[c] / a;
        sv[c] = D_(0, 1)[c] / b;
    }
    cross(su, sv, n);
    len = norm3(n);
    if (!(len > SURF_TINY))
        return CF_STATUS_DEGENERATE;
    for (int c = 0; c < 3; c++)
        out[c] = n[c] / len;
    *scale = a > b ? a : b;
    return CF_STATUS_OK;
}

cf_status_t
cf__surf_normal(const double *D, double *out)
{
    double scale;
    return unit_normal(D, out, &scale);
}

/* The fundamental forms of the surface scaled by 1/s (s the larger tangent
** length, so that neither underflows nor overflows): K = K'/s^2, H = H'/s. */
cf_status_t
cf__surf_curvature(const double *D, double *gauss, double *mean)
{
    double n[3], s, E, F, G, L, M, N, g;
    double Su[3], Sv[3], Suu[3], Suv[3], Svv[3];
    cf_status_t st = unit_normal(D, n, &s);
    if (st != CF_STATUS_OK)
        return st;
    for (int c = 0; c < 3; c++) {
        Su[c] = D_(1, 0)[c] / s;
        Sv[c] = D_(0, 1)[c] / s;
        Suu[c] = D_(2, 0)[c] / s;
        Suv[c] = D_(1, 1)[c] / s;
        Svv[c] = D_(0, 2)[c] / s;
    }
    E = dot(Su, Su);
    F = dot(Su, Sv);
    G = dot(Sv, Sv);
    L = dot(Suu, n);
    M = dot(Suv, n);
    N = dot(Svv, n);
    g = E * G - F * F;
    if (!(g > 0.0))
        return CF_STATUS_DEGENERATE;
    if (gauss != NULL)
        *gauss = (L * N - M * M) / g / (s * s);
    if (mean != NULL)
        *mean = (E * N - 2.0 * F * M + G * L) / (2.0 * g) / s;
    return CF_STATUS_OK;
}
