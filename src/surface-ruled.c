/* Extrusion and ruled surfaces (curvefig/surface-make.h). */
#include <math.h>
#include <string.h>

#include "surface-private.h"
#include "curvefig/surface-make.h"

static const double LINEAR[4] = { 0, 0, 1, 1 };

static cf_status_t
no_memory(cf_diag_t *diag)
{
    return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
}

cf_status_t
cf_surface_extrude(const cf_bspline_t *curve, const double *d,
                   cf_bspline_surface_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    size_t dim, h, n;
    const double *P;
    double *grid;
    cf_status_t st;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    if (curve == NULL || d == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "curve or direction is NULL");
    dim = cf_bspline_dim(curve);
    st = cf__check_finite_points(d, 1, dim, dim, "direction", diag);
    if (st != CF_STATUS_OK)
        return st;
    h = dim + cf_bspline_is_rational(curve);
    n = cf_bspline_count(curve);
    P = cf_bspline_hpoints(curve);
    grid = cf__alloc_array(2 * n, h * sizeof *grid);
    if (grid == NULL)
        return no_memory(diag);
    for (size_t i = 0; i < n; i++) {
        double w = h > dim ? P[i * h + dim] : 1.0;
        memcpy(grid + 2 * i * h, P + i * h, h * sizeof *grid);
        memcpy(grid + (2 * i + 1) * h, P + i * h, h * sizeof *grid);
        for (size_t k = 0; k < dim; k++)
            grid[(2 * i + 1) * h + k] += w * d[k];
    }
    if (h > dim)
        st = cf_bspline_surface_create_homogeneous(
            dim, cf_bspline_degree(curve), 1, cf_bspline_knots(curve),
            cf_bspline_nknots(curve), LINEAR, 4, grid, n, 2, out, diag);
    else
        st = cf_bspline_surface_create(dim, cf_bspline_degree(curve), 1,
                                       cf_bspline_knots(curve),
                                       cf_bspline_nknots(curve), LINEAR, 4,
                                       grid, n, 2, NULL, out, diag);
    cf__free(grid);
    return st;
}

/* c clamped to its domain, mapped to [0, 1], elevated to degree p. */
static cf_status_t
normalise(const cf_bspline_t *c, int p, cf_bspline_t **out, cf_diag_t *diag)
{
    cf_bspline_t *s = NULL, *m = NULL;
    double a, b, *K;
    size_t nk;
    cf_status_t st;
    cf_bspline_domain(c, &a, &b);
    st = cf_bspline_segment(c, a, b, &s, diag);
    if (st != CF_STATUS_OK)
        return st;
    nk = cf_bspline_nknots(s);
    K = cf__alloc_array(nk, sizeof *K);
    if (K == NULL) {
        cf_bspline_destroy(s);
        return no_memory(diag);
    }
    for (size_t i = 0; i < nk; i++)
        K[i] = (cf_bspline_knots(s)[i] - a) / (b - a);
    K[0] = 0.0;
    K[nk - 1] = 1.0;
    for (size_t i = 1; i < nk - 1; i++)
        K[i] = fmin(fmax(K[i], 0.0), 1.0);
    if (cf_bspline_is_rational(s))
        st = cf_bspline_create_homogeneous(
            cf_bspline_dim(s), cf_bspline_degree(s), K, nk,
            cf_bspline_hpoints(s), cf_bspline_count(s), &m, diag);
    else
        st = cf_bspline_create(cf_bspline_dim(s), cf_bspline_degree(s), K, nk,
                               cf_bspline_hpoints(s), cf_bspline_count(s),
                               NULL, &m, diag);
    cf__free(K);
    cf_bspline_destroy(s);
    if (st == CF_STATUS_OK && p > cf_bspline_degree(m)) {
        st = cf_bspline_elevate(m, p - cf_bspline_degree(m), out, diag);
        cf_bspline_destroy(m);
        return st;
    }
    *out = m;
    return st;
}

/* The knots of b missing from a (with multiplicity), into x; count. */
static size_t
missing(const cf_bspline_t *a, const cf_bspline_t *b, double *x)
{
    const double *A = cf_bspline_knots(a), *B = cf_bspline_knots(b);
    size_t na = cf_bspline_nknots(a), nb = cf_bspline_nknots(b), n = 0;
    for (size_t i = 0; i < nb;) {
        size_t j = i;
        int ma;
        while (j < nb && B[j] == B[i])
            j++;
        ma = cf_knots_multiplicity(A, na, B[i]);
        if (B[i] > 0.0 && B[i] < 1.0)
            for (int r = ma; r < (int)(j - i); r++)
                x[n++] = B[i];
        i = j;
    }
    return n;
}

cf_status_t
cf_surface_ruled(const cf_bspline_t *c1, const cf_bspline_t *c2,
                 cf_bspline_surface_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bspline_t *a = NULL, *b = NULL, *ra = NULL, *rb = NULL;
    double *x = NULL, *grid = NULL;
    size_t dim, n, h;
    int p;
    bool rat;
    cf_status_t st;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    if (c1 == NULL || c2 == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "a curve is NULL");
    dim = cf_bspline_dim(c1);
    if (cf_bspline_dim(c2) != dim)
        return cf__error(diag, CF_STATUS_DIM_MISMATCH, -1,
                         "the curves have dimensions %zu and %zu",
                         dim, cf_bspline_dim(c2));
    p = cf_bspline_degree(c1) > cf_bspline_degree(c2) ? cf_bspline_degree(c1)
                                                      : cf_bspline_degree(c2);
    st = normalise(c1, p, &a, diag);
    if (st == CF_STATUS_OK)
        st = normalise(c2, p, &b, diag);
    if (st == CF_STATUS_OK) {
        x = cf__alloc_array(cf_bspline_nknots(a) + cf_bspline_nknots(b),
                            sizeof *x);
        if (x == NULL)
            st = no_memory(diag);
    }
    if (st == CF_STATUS_OK)
        st = cf_bspline_refine(a, x, missing(a, b, x), &ra, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_refine(b, x, missing(b, a, x), &rb, diag);
    if (st != CF_STATUS_OK)
        goto done;
    n = cf_bspline_count(ra);
    if (cf_bspline_count(rb) != n) {
        st = cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                       "internal: %zu and %zu points after merging "
                       "the knots", n, cf_bspline_count(rb));
        goto done;
    }
    rat = cf_bspline_is_rational(ra) || cf_bspline_is_rational(rb);
    h = dim + rat;
    grid = cf__alloc_array(2 * n, h * sizeof *grid);
    if (grid == NULL) {
        st = no_memory(diag);
        goto done;
    }
    for (size_t i = 0; i < n; i++)
        for (int v = 0; v < 2; v++) {
            const cf_bspline_t *c = v == 0 ? ra : rb;
            size_t ch = dim + cf_bspline_is_rational(c);
            const double *P = cf_bspline_hpoints(c) + i * ch;
            double *g = grid + (2 * i + (size_t)v) * h;
            memcpy(g, P, ch * sizeof *g);
            if (rat && ch == dim)
                g[dim] = 1.0;
        }
    if (rat)
        st = cf_bspline_surface_create_homogeneous(
            dim, p, 1, cf_bspline_knots(ra), cf_bspline_nknots(ra), LINEAR, 4,
            grid, n, 2, out, diag);
    else
        st = cf_bspline_surface_create(dim, p, 1, cf_bspline_knots(ra),
                                       cf_bspline_nknots(ra), LINEAR, 4, grid,
                                       n, 2, NULL, out, diag);
done:
    cf__free(x);
    cf__free(grid);
    cf_bspline_destroy(a);
    cf_bspline_destroy(b);
    cf_bspline_destroy(ra);
    cf_bspline_destroy(rb);
    return st;
}
