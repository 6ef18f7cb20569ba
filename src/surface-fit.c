/* Interpolation and least-squares approximation of a grid of points by a
** tensor-product B-spline surface (curvefig/surface-make.h): the curve
** methods of interp.h on the grid read as a curve of rows, then on the
** transposed result. */
#include <math.h>
#include <string.h>

#include "surface-private.h"
#include "curvefig/surface-make.h"

static cf_status_t
no_memory(cf_diag_t *diag)
{
    return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
}

/* The parameters of the nu lines of a grid (line l: Q[0][l] ..
** Q[nu-1][l], rows nv points apart) averaged over the nv lines. */
static cf_status_t
average_params(size_t dim, const double *Q, size_t nu, size_t nv,
               const cf_interp_options_t *opt, double *out, cf_diag_t *diag)
{
    double *line = cf__alloc_array(nu * dim + nu, sizeof *line), *t;
    cf_status_t st = CF_STATUS_OK;
    if (line == NULL)
        return no_memory(diag);
    t = line + nu * dim;
    memset(out, 0, nu * sizeof *out);
    for (size_t l = 0; l < nv && st == CF_STATUS_OK; l++) {
        for (size_t k = 0; k < nu; k++)
            memcpy(line + k * dim, Q + (k * nv + l) * dim,
                   dim * sizeof *line);
        st = cf_interp_parameters(dim, line, nu, opt->param, opt->exponent,
                                  false, t, diag);
        for (size_t k = 0; k < nu && st == CF_STATUS_OK; k++)
            out[k] += t[k] / (double)nv;
    }
    out[0] = 0.0;
    out[nu - 1] = 1.0;
    cf__free(line);
    return st;
}

/* One pass: the grid Q (n lines along the direction, each m points of
** dim) fitted by a curve of dimension m dim; the result's points
** transposed into *grid (m x count), its knots and degree kept. */
typedef struct pass {
    cf_bspline_t *curve;
    double *grid;   /* transposed control points, count x ... */
} pass_t;

static cf_status_t
fit(size_t dim, const double *Q, size_t n, size_t m, const double *params,
    const cf_interp_options_t *opt, size_t ncontrol, bool fix_ends,
    pass_t *out, cf_diag_t *diag)
{
    cf_interp_options_t o = *opt;
    cf_status_t st;
    size_t cnt;
    o.params = params;
    if (ncontrol == 0)
        st = cf_interpolate(m * dim, Q, n, &o, &out->curve, diag);
    else
        st = cf_approximate_lsq(m * dim, Q, n, ncontrol, &o, fix_ends,
                                &out->curve, NULL, diag);
    if (st != CF_STATUS_OK)
        return st;
    cnt = cf_bspline_count(out->curve);
    out->grid = cf__alloc_array(cnt * m, dim * sizeof(double));
    if (out->grid == NULL)
        return no_memory(diag);
    cf__surf_transpose(cf_bspline_hpoints(out->curve), cnt, m, dim,
                       out->grid);
    return CF_STATUS_OK;
}

static cf_status_t
run(size_t dim, const double *Q, size_t nu, size_t nv,
    const cf_interp_options_t *opt, size_t cu, size_t cv, bool fix_ends,
    cf_bspline_surface_t **out, double *params, double *residual,
    cf_diag_t *diag)
{
    cf_interp_options_t def;
    pass_t a = { NULL, NULL }, b = { NULL, NULL };
    double *t = NULL, *tq = NULL, *P = NULL;
    cf_status_t st;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    if (opt == NULL) {
        cf_interp_options_init(&def);
        opt = &def;
    }
    if (Q == NULL || dim == 0 || nu < 2 || nv < 2)
        return cf__error(diag, CF_STATUS_TOO_FEW_POINTS, -1,
                         "a grid of points needs at least 2 x 2 points, got "
                         "%zu x %zu", nu, nv);
    if (opt->params != NULL || opt->start_tangent != NULL ||
        opt->end_tangent != NULL || opt->closed ||
        opt->method == CF_INTERP_CLAMPED || opt->method == CF_INTERP_PERIODIC)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "a surface takes no explicit parameters, end "
                         "tangents, closed or periodic option (methods: "
                         "natural, not-a-knot, catmull-rom, global)");
    t = cf__alloc_array(nu + nv, sizeof *t);
    tq = cf__alloc_array(nu * nv, dim * sizeof *tq);
    if (t == NULL || tq == NULL) {
        st = no_memory(diag);
        goto done;
    }
    /* finite, with messages naming P[i][j] */
    st = cf__surf_fill(dim, Q, NULL, nu, nv, tq, diag);
    if (st == CF_STATUS_OK)
        st = average_params(dim, Q, nu, nv, opt, t, diag);
    if (st == CF_STATUS_OK) {
        cf__surf_transpose(Q, nu, nv, dim, tq);
        st = average_params(dim, tq, nv, nu, opt, t + nu, diag);
    }
    /* columns in u (the grid as a curve of rows), then the rows in v */
    if (st == CF_STATUS_OK)
        st = fit(dim, Q, nu, nv, t, opt, cu, fix_ends, &a, diag);
    if (st == CF_STATUS_OK)
        st = fit(dim, a.grid, nv, cf_bspline_count(a.curve), t + nu, opt, cv,
                 fix_ends, &b, diag);
    if (st != CF_STATUS_OK)
        goto done;
    /* b.grid is (count_u x count_v): row i along u */
    P = b.grid;
    st = cf_bspline_surface_create(
        dim, cf_bspline_degree(a.curve), cf_bspline_degree(b.curve),
        cf_bspline_knots(a.curve), cf_bspline_nknots(a.curve),
        cf_bspline_knots(b.curve), cf_bspline_nknots(b.curve), P,
        cf_bspline_count(a.curve), cf_bspline_count(b.curve), NULL, out,
        diag);
    if (st == CF_STATUS_OK && params != NULL)
        memcpy(params, t, (nu + nv) * sizeof *t);
    if (st == CF_STATUS_OK && residual != NULL) {
        double r = 0.0, x[64];
        *residual = 0.0;
        for (size_t i = 0; i < nu && dim <= 64; i++)
            for (size_t j = 0; j < nv; j++) {
                double d2 = 0.0;
                (void)cf_bspline_surface_eval(*out, t[i], t[nu + j], x);
                for (size_t k = 0; k < dim; k++) {
                    double e = x[k] - Q[(i * nv + j) * dim + k];
                    d2 += e * e;
                }
                r = fmax(r, sqrt(d2));
            }
        *residual = r;
    }
done:
    cf__free(t);
    cf__free(tq);
    cf__free(a.grid);
    cf__free(b.grid);
    cf_bspline_destroy(a.curve);
    cf_bspline_destroy(b.curve);
    return st;
}

cf_status_t
cf_interpolate_surface(size_t dim, const double *points, size_t nu,
                       size_t nv, const cf_interp_options_t *opt,
                       cf_bspline_surface_t **out, double *params,
                       cf_diag_t *diag)
{
    cf_diag_clear(diag);
    return run(dim, points, nu, nv, opt, 0, 0, false, out, params, NULL,
               diag);
}

cf_status_t
cf_approximate_surface(size_t dim, const double *points, size_t nu,
                       size_t nv, size_t cu, size_t cv,
                       const cf_interp_options_t *opt, bool fix_ends,
                       cf_bspline_surface_t **out, double *residual,
                       cf_diag_t *diag)
{
    cf_diag_clear(diag);
    if (cu < 2 || cv < 2) {
        if (out != NULL)
            *out = NULL;
        return cf__error(diag, CF_STATUS_TOO_FEW_POINTS, -1,
                         "least squares needs at least 2 x 2 control "
                         "points, got %zu x %zu", cu, cv);
    }
    return run(dim, points, nu, nv, opt, cu, cv, fix_ends, out, NULL,
               residual, diag);
}
