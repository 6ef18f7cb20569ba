/*
** Closed (periodic) B-splines and Coons' cubic B-spline curves.
*/
#include <math.h>
#include <string.h>

#include "bspline-private.h"

cf_status_t
cf_bspline_create_closed(size_t dim, int degree, const double *points,
                         size_t count, const double *weights,
                         cf_bspline_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    size_t p, total, nk;
    double *U = NULL, *P = NULL, *W = NULL;
    cf_status_t st;
    if (out != NULL)
        *out = NULL;
    if (degree < 1 || degree > CF_BSPLINE_MAX_DEGREE)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "closed curves need a degree in 1..%d, "
                         "not %d", CF_BSPLINE_MAX_DEGREE, degree);
    if (points == NULL || dim < 1 || dim > CF__BSPLINE_MAX_COUNT)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "points are NULL or dimension is 0");
    if (count < (size_t)degree + 1 || count > CF__BSPLINE_MAX_COUNT)
        return cf__error(diag, CF_STATUS_TOO_FEW_POINTS, -1,
                         "a closed curve of degree %d needs at "
                         "least %d points, %zu given", degree, degree + 1,
                         count);
    p = (size_t)degree;
    total = count + p;
    nk = total + p + 1;
    U = cf__alloc_array(nk, sizeof *U);
    P = cf__alloc_array(total, dim * sizeof *P);
    if (weights != NULL)
        W = cf__alloc_array(total, sizeof *W);
    if (U == NULL || P == NULL || (weights != NULL && W == NULL)) {
        st = cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                       "out of memory");
        goto done;
    }
    for (size_t i = 0; i < nk; i++)
        U[i] = ((double)i - (double)p) / (double)count;
    for (size_t i = 0; i < total; i++) {
        memcpy(P + i * dim, points + (i % count) * dim, dim * sizeof *P);
        if (W != NULL)
            W[i] = weights[i % count];
    }
    st = cf_bspline_create(dim, degree, U, nk, P, total, W, out, diag);
done:
    cf__free(U);
    cf__free(P);
    cf__free(W);
    return st;
}

cf_status_t
cf_bspline_create_coons(size_t dim, const double *points, size_t count,
                        cf_coons_ends_t ends, cf_bspline_t **out,
                        cf_diag_t *diag)
{
    cf_diag_clear(diag);
    size_t need, total, nk, j = 0;
    double *U = NULL, *P = NULL;
    cf_status_t st;
    if (out != NULL)
        *out = NULL;
    if (points == NULL || dim < 1 || dim > CF__BSPLINE_MAX_COUNT)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "points are NULL or dimension is 0");
    switch (ends) {
    case CF_COONS_PLAIN:
        need = 4;
        total = count;
        break;
    case CF_COONS_TRIPLED:
        need = 2;
        total = count + 4;
        break;
    case CF_COONS_CLOSED:
        need = 3;
        total = count + 3;
        break;
    default:
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "unknown end treatment %d", (int)ends);
    }
    if (count < need || count > CF__BSPLINE_MAX_COUNT)
        return cf__error(diag, CF_STATUS_TOO_FEW_POINTS, -1,
                         "%zu points given, this end treatment "
                         "needs at least %zu", count, need);
    nk = total + 4;
    U = cf__alloc_array(nk, sizeof *U);
    P = cf__alloc_array(total, dim * sizeof *P);
    if (U == NULL || P == NULL) {
        st = cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
        goto done;
    }
    for (size_t i = 0; i < nk; i++)
        U[i] = (double)i - 3.0;
    if (ends == CF_COONS_TRIPLED) {
        memcpy(P + dim * j++, points, dim * sizeof *P);
        memcpy(P + dim * j++, points, dim * sizeof *P);
    }
    memcpy(P + dim * j, points, count * dim * sizeof *P);
    j += count;
    if (ends == CF_COONS_TRIPLED) {
        memcpy(P + dim * j++, points + (count - 1) * dim, dim * sizeof *P);
        memcpy(P + dim * j++, points + (count - 1) * dim, dim * sizeof *P);
    } else if (ends == CF_COONS_CLOSED) {
        memcpy(P + dim * j, points, 3 * dim * sizeof *P);
    }
    st = cf_bspline_create(dim, 3, U, nk, P, total, NULL, out, diag);
done:
    cf__free(U);
    cf__free(P);
    return st;
}

void
cf_coons_basis(double t, double b[4])
{
    double s = 1.0 - t, t2 = t * t, t3 = t2 * t;
    b[0] = s * s * s / 6.0;
    b[1] = (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0;
    b[2] = (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0;
    b[3] = t3 / 6.0;
}

void
cf_coons_eval(size_t dim, const double *p4, double t, double *out)
{
    double b[4];
    cf_coons_basis(t, b);
    for (size_t d = 0; d < dim; d++)
        out[d] = b[0] * p4[d] + b[1] * p4[dim + d] + b[2] * p4[2 * dim + d]
                 + b[3] * p4[3 * dim + d];
}
