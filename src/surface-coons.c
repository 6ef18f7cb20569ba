/* The bilinearly blended Coons patch of four boundary curves
** (curvefig/surface-make.h). */
#include <math.h>
#include <string.h>

#include "surface-private.h"
#include "curvefig/surface-make.h"
#include "numtext-private.h"

/* s transposed (u and v exchanged), or NULL. */
static cf_status_t
transpose(const cf_bspline_surface_t *s, cf_bspline_surface_t **out,
          cf_diag_t *diag)
{
    size_t nU, nV, nu = cf_bspline_surface_count_u(s);
    size_t nv = cf_bspline_surface_count_v(s), dim = cf_bspline_surface_dim(s);
    const double *U = cf_bspline_surface_knots(s, CF_DIR_U, &nU);
    const double *V = cf_bspline_surface_knots(s, CF_DIR_V, &nV);
    double *t = cf__alloc_array(nu * nv, dim * sizeof *t);
    cf_status_t st;
    if (t == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    cf__surf_transpose(cf_bspline_surface_hpoints(s), nu, nv, dim, t);
    st = cf_bspline_surface_create(dim, cf_bspline_surface_degree_v(s),
                                   cf_bspline_surface_degree_u(s), V, nV, U,
                                   nU, t, nv, nu, NULL, out, diag);
    cf__free(t);
    return st;
}

/* s brought to degrees (p, q) and refined with the interior knots of the
** directions of the model m (which has the final knot vectors). */
static cf_status_t
conform(const cf_bspline_surface_t *s, int p, int q,
        const cf_bspline_surface_t *mu, const cf_bspline_surface_t *mv,
        cf_bspline_surface_t **out, cf_diag_t *diag)
{
    cf_bspline_surface_t *e = NULL, *r = NULL;
    const cf_bspline_surface_t *models[2] = { mu, mv };
    cf_status_t st = cf_bspline_surface_elevate(
        s, p - cf_bspline_surface_degree_u(s),
        q - cf_bspline_surface_degree_v(s), &e, diag);
    for (int d = 0; d < 2 && st == CF_STATUS_OK; d++) {
        cf_dir_t dir = d == 0 ? CF_DIR_U : CF_DIR_V;
        int deg = d == 0 ? p : q;
        size_t nK, nE;
        const double *K = cf_bspline_surface_knots(models[d], dir, &nK);
        (void)cf_bspline_surface_knots(e, dir, &nE);
        if (nE == nK)
            continue;
        /* e has only the end knots in this direction */
        st = cf_bspline_surface_refine(e, dir, K + deg + 1,
                                       nK - 2 * ((size_t)deg + 1), &r, diag);
        cf_bspline_surface_destroy(e);
        e = r;
        r = NULL;
    }
    if (st != CF_STATUS_OK) {
        cf_bspline_surface_destroy(e);
        return st;
    }
    *out = e;
    return CF_STATUS_OK;
}

/* The corners must meet: a(ta) = b(tb) within 1e-9 of their size. */
static cf_status_t
corner(const cf_bspline_t *a, const char *an, double ta,
       const cf_bspline_t *b, const char *bn, double tb, cf_diag_t *diag)
{
    double x[64], y[64], lo, hi, size = 1.0, gap = 0.0;
    size_t dim = cf_bspline_dim(a);
    cf_bspline_domain(a, &lo, &hi);
    (void)cf_bspline_eval(a, ta == 0 ? lo : hi, x);
    cf_bspline_domain(b, &lo, &hi);
    (void)cf_bspline_eval(b, tb == 0 ? lo : hi, y);
    for (size_t k = 0; k < dim; k++) {
        size = fmax(size, fmax(fabs(x[k]), fabs(y[k])));
        gap = fmax(gap, fabs(x[k] - y[k]));
    }
    if (gap > 1e-9 * size)
        return cf__error(diag, CF_STATUS_DEGENERATE, -1,
                         "the corners do not meet: %s(%s) = "
                         "(%s, %s, ...) but %s(%s) = (%s, %s, ...)", an,
                         CF__NUM(ta), CF__NUM(x[0]),
                         CF__NUM(dim > 1 ? x[1] : 0.0), bn, CF__NUM(tb),
                         CF__NUM(y[0]), CF__NUM(dim > 1 ? y[1] : 0.0));
    return CF_STATUS_OK;
}

cf_status_t
cf_surface_coons(const cf_bspline_t *c0, const cf_bspline_t *c1,
                 const cf_bspline_t *d0, const cf_bspline_t *d1,
                 cf_bspline_surface_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    const cf_bspline_t *cs[4] = { c0, c1, d0, d1 };
    cf_bspline_surface_t *a = NULL, *b0 = NULL, *b = NULL, *ea = NULL;
    cf_bspline_surface_t *eb = NULL, *et = NULL, *t = NULL;
    double corners[4 * 64], *P = NULL;
    size_t dim, n;
    int p, q;
    cf_status_t st;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    for (int i = 0; i < 4; i++) {
        if (cs[i] == NULL)
            return cf__error(diag, CF_STATUS_INVALID_ARG, i,
                             "boundary curve %d is NULL", i);
        if (cf_bspline_is_rational(cs[i]))
            return cf__error(diag, CF_STATUS_INVALID_ARG, i,
                             "boundary curve %d is rational; "
                             "the patch of rational curves is not a NURBS "
                             "surface, give polynomial curves", i);
    }
    dim = cf_bspline_dim(c0);
    for (int i = 1; i < 4; i++)
        if (cf_bspline_dim(cs[i]) != dim)
            return cf__error(diag, CF_STATUS_DIM_MISMATCH, i,
                             "boundary curve %d has dimension "
                             "%zu, curve 0 has %zu", i, cf_bspline_dim(cs[i]),
                             dim);
    if (dim > 64)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "dimension %zu; at most 64", dim);
    st = corner(c0, "c0", 0, d0, "d0", 0, diag);
    if (st == CF_STATUS_OK)
        st = corner(c0, "c0", 1, d1, "d1", 0, diag);
    if (st == CF_STATUS_OK)
        st = corner(c1, "c1", 0, d0, "d0", 1, diag);
    if (st == CF_STATUS_OK)
        st = corner(c1, "c1", 1, d1, "d1", 1, diag);
    if (st != CF_STATUS_OK)
        return st;
    /* the two ruled surfaces and the bilinear one of the corners */
    st = cf_surface_ruled(c0, c1, &a, diag);
    if (st == CF_STATUS_OK)
        st = cf_surface_ruled(d0, d1, &b0, diag);
    if (st == CF_STATUS_OK)
        st = transpose(b0, &b, diag);
    if (st == CF_STATUS_OK) {
        static const double K[4] = { 0, 0, 1, 1 };
        for (int i = 0; i < 4; i++) {
            const cf_bspline_t *c = i < 2 ? c0 : c1;
            double lo, hi;
            cf_bspline_domain(c, &lo, &hi);
            (void)cf_bspline_eval(c, i % 2 ? hi : lo, corners + i * dim);
        }
        /* corner order P00, P01 (u = 0, v = 1), P10, P11 */
        {
            double tmp[64];
            memcpy(tmp, corners + dim, dim * sizeof *tmp);       /* c0(1) */
            memcpy(corners + dim, corners + 2 * dim, dim * sizeof *tmp);
            memcpy(corners + 2 * dim, tmp, dim * sizeof *tmp);
        }
        st = cf_bspline_surface_create(dim, 1, 1, K, 4, K, 4, corners, 2, 2,
                                       NULL, &t, diag);
    }
    if (st != CF_STATUS_OK)
        goto done;
    p = cf_bspline_surface_degree_u(a);
    q = cf_bspline_surface_degree_v(b);
    st = conform(a, p, q, a, b, &ea, diag);
    if (st == CF_STATUS_OK)
        st = conform(b, p, q, a, b, &eb, diag);
    if (st == CF_STATUS_OK)
        st = conform(t, p, q, a, b, &et, diag);
    if (st != CF_STATUS_OK)
        goto done;
    n = cf_bspline_surface_count_u(ea) * cf_bspline_surface_count_v(ea);
    if (cf_bspline_surface_count_u(eb) * cf_bspline_surface_count_v(eb) != n ||
        cf_bspline_surface_count_u(et) * cf_bspline_surface_count_v(et) != n) {
        st = cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                       "internal: the three grids differ");
        goto done;
    }
    P = cf__alloc_array(n, dim * sizeof *P);
    if (P == NULL) {
        st = cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
        goto done;
    }
    for (size_t i = 0; i < n * dim; i++)
        P[i] = cf_bspline_surface_hpoints(ea)[i] +
               cf_bspline_surface_hpoints(eb)[i] -
               cf_bspline_surface_hpoints(et)[i];
    {
        size_t nU, nV;
        const double *U = cf_bspline_surface_knots(ea, CF_DIR_U, &nU);
        const double *V = cf_bspline_surface_knots(ea, CF_DIR_V, &nV);
        st = cf_bspline_surface_create(dim, p, q, U, nU, V, nV, P,
                                       cf_bspline_surface_count_u(ea),
                                       cf_bspline_surface_count_v(ea), NULL,
                                       out, diag);
    }
done:
    cf__free(P);
    cf_bspline_surface_destroy(a);
    cf_bspline_surface_destroy(b0);
    cf_bspline_surface_destroy(b);
    cf_bspline_surface_destroy(t);
    cf_bspline_surface_destroy(ea);
    cf_bspline_surface_destroy(eb);
    cf_bspline_surface_destroy(et);
    return st;
}
