/*
** One basis function N_i^p over a whole knot vector as a B-spline of its
** own (cf_basis_one_spline): the knot vector padded so that the curve's
** domain is the vector's whole range.
*/
#include <string.h>

#include "curvefig/bspline.h"
#include "bspline-private.h"
#include "numtext-private.h"

cf_status_t
cf_basis_one_spline(int i, int degree, const double *knots, size_t nknots,
                    cf_bspline_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    size_t m = nknots, p, count;
    double *pu, *coef, h;
    cf_status_t st;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "the output pointer is NULL");
    *out = NULL;
    if (knots == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "knots are NULL");
    if (degree < 0 || degree > CF_BSPLINE_MAX_DEGREE)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "degree %d is outside 0..%d", degree,
                         CF_BSPLINE_MAX_DEGREE);
    p = (size_t)degree;
    if (i < 0 || (size_t)i + p + 2 > m)
        return cf__error(diag, CF_STATUS_INVALID_ARG, i,
                         "N_%d^%d needs knots u_%d..u_%d, %zu given", i,
                         degree, i, i + degree + 1, m);
    st = cf__check_knot_order(knots, m, "knot", diag);
    if (st != CF_STATUS_OK)
        return st;
    if (!(knots[m - 1] > knots[0]))
        return cf__error(diag, CF_STATUS_BAD_KNOTS, -1,
                         "the knots span no interval (all %s)",
                         CF__NUM(knots[0]));
    h = knots[m - 1] - knots[0];
    count = m + p - 1;
    pu = cf__alloc_array(m + 2 * p, sizeof *pu);
    coef = cf__calloc(count, sizeof *coef);
    if (pu == NULL || coef == NULL) {
        cf__free(pu);
        cf__free(coef);
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory for a basis function");
    }
    for (size_t r = 0; r < p; r++) {
        pu[r] = knots[0] - h * (double)(p - r);
        pu[m + p + r] = knots[m - 1] + h * (double)(r + 1);
    }
    memcpy(pu + p, knots, m * sizeof *knots);
    coef[(size_t)i + p] = 1.0;
    /* the padded spline's domain [pu_p, pu_count] is [u_0, u_{m-1}] */
    st = cf_bspline_create(1, degree, pu, m + 2 * p, coef, count, NULL, out,
                           diag);
    cf__free(pu);
    cf__free(coef);
    return st;
}
