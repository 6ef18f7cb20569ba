/* Tensor-product Bézier surfaces: construction, queries and evaluation
** (curvefig/surface.h). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "surface-private.h"
#include "curvefig/bernstein.h"

cf_bezier_surface_t *
cf__bsurf_bezier_new(size_t dim, int m, int n, bool rational)
{
    size_t hdim = dim + rational, cnt;
    cf_bezier_surface_t *s;
    if (dim == 0 || dim > SIZE_MAX / 64 || m < 0 || n < 0)
        return NULL;
    cnt = ((size_t)m + 1) * ((size_t)n + 1);
    if (hdim > (SIZE_MAX - sizeof *s) / sizeof(double) / cnt)
        return NULL;
    s = cf__malloc(sizeof *s + cnt * hdim * sizeof(double));
    if (s == NULL)
        return NULL;
    s->dim = dim;
    s->hdim = hdim;
    s->m = m;
    s->n = n;
    s->rational = rational;
    return s;
}

static cf_status_t
check_args(size_t dim, int m, int n, const void *pts,
           cf_bezier_surface_t **out, cf_diag_t *diag)
{
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    if (pts == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "points is NULL");
    if (dim < 1)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "dimension is 0; it must be at least 1");
    if (m < 0 || m > CF_BEZIER_MAX_DEGREE || n < 0 ||
        n > CF_BEZIER_MAX_DEGREE)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "degrees (%d, %d): each must be in 0..%d", m, n,
                         CF_BEZIER_MAX_DEGREE);
    return CF_STATUS_OK;
}

static cf_status_t
no_memory(cf_diag_t *diag)
{
    return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                     "out of memory for the surface");
}

cf_status_t
cf_bezier_surface_create(size_t dim, int m, int n, const double *points,
                         const double *weights, cf_bezier_surface_t **out,
                         cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bezier_surface_t *s;
    cf_status_t st;
    cf_diag_clear(diag);
    st = check_args(dim, m, n, points, out, diag);
    if (st != CF_STATUS_OK)
        return st;
    s = cf__bsurf_bezier_new(dim, m, n, weights != NULL);
    if (s == NULL)
        return no_memory(diag);
    st = cf__surf_fill(dim, points, weights, (size_t)m + 1, (size_t)n + 1,
                       s->pts, diag);
    if (st != CF_STATUS_OK) {
        cf__free(s);
        return st;
    }
    *out = s;
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_surface_create_homogeneous(size_t dim, int m, int n,
                                     const double *hpoints,
                                     cf_bezier_surface_t **out,
                                     cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bezier_surface_t *s;
    cf_status_t st;
    cf_diag_clear(diag);
    st = check_args(dim, m, n, hpoints, out, diag);
    if (st != CF_STATUS_OK)
        return st;
    st = cf__surf_check_h(dim, hpoints, (size_t)m + 1, (size_t)n + 1, diag);
    if (st != CF_STATUS_OK)
        return st;
    s = cf__bsurf_bezier_new(dim, m, n, true);
    if (s == NULL)
        return no_memory(diag);
    memcpy(s->pts, hpoints,
           ((size_t)m + 1) * ((size_t)n + 1) * s->hdim * sizeof(double));
    *out = s;
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_surface_bilinear(size_t dim, const double *corners,
                           cf_bezier_surface_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    return cf_bezier_surface_create(dim, 1, 1, corners, NULL, out, diag);
}

cf_status_t
cf_bezier_surface_copy(const cf_bezier_surface_t *s,
                       cf_bezier_surface_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bezier_surface_t *c;
    cf_diag_clear(diag);
    if (out == NULL || s == NULL) {
        if (out != NULL)
            *out = NULL;
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "surface or out is NULL");
    }
    *out = NULL;
    c = cf__bsurf_bezier_new(s->dim, s->m, s->n, s->rational);
    if (c == NULL)
        return no_memory(diag);
    memcpy(c->pts, s->pts,
           ((size_t)s->m + 1) * ((size_t)s->n + 1) * s->hdim *
               sizeof(double));
    *out = c;
    return CF_STATUS_OK;
}

void
cf_bezier_surface_destroy(cf_bezier_surface_t *s)
{
    cf__free(s);
}

size_t cf_bezier_surface_dim(const cf_bezier_surface_t *s)
{
    return s ? s->dim : 0;
}

int cf_bezier_surface_degree_u(const cf_bezier_surface_t *s)
{
    return s ? s->m : 0;
}

int cf_bezier_surface_degree_v(const cf_bezier_surface_t *s)
{
    return s ? s->n : 0;
}

bool cf_bezier_surface_is_rational(const cf_bezier_surface_t *s)
{
    return s ? s->rational : false;
}

const double *
cf_bezier_surface_hpoints(const cf_bezier_surface_t *s)
{
    return s ? s->pts : NULL;
}

static size_t
npts(const cf_bezier_surface_t *s)
{
    return ((size_t)s->m + 1) * ((size_t)s->n + 1);
}

void
cf_bezier_surface_get_points(const cf_bezier_surface_t *s, double *out)
{
    if (s != NULL && out != NULL)
        cf__surf_points(s->pts, npts(s), s->dim, s->rational, out);
}

void
cf_bezier_surface_get_weights(const cf_bezier_surface_t *s, double *out)
{
    if (s != NULL && out != NULL)
        cf__surf_weights(s->pts, npts(s), s->dim, s->rational, out);
}

/* The parameters by the domain rule on [0, 1]. */
static cf_status_t
params(const cf_bezier_surface_t *s, const void *out, double *u, double *v)
{
    cf_status_t st;
    if (s == NULL || out == NULL)
        return CF_STATUS_INVALID_ARG;
    st = cf__surf_param(0.0, 1.0, u, CF_DIR_U, NULL);
    return st != CF_STATUS_OK ? st : cf__surf_param(0.0, 1.0, v, CF_DIR_V,
                                                    NULL);
}

cf_status_t
cf_bezier_surface_eval(const cf_bezier_surface_t *s, double u, double v,
                       double *out)
{
    double Bu[CF_BEZIER_MAX_DEGREE + 1], Bv[CF_BEZIER_MAX_DEGREE + 1];
    cf_status_t st = params(s, out, &u, &v);
    size_t nv;
    if (st != CF_STATUS_OK)
        return st;
    nv = (size_t)s->n + 1;
    (void)cf_bernstein_all(s->m, u, Bu);
    (void)cf_bernstein_all(s->n, v, Bv);
    cf__surf_tensor_point(s->pts, nv * s->hdim, s->hdim, s->dim, Bu,
                          (size_t)s->m + 1, Bv, nv, out);
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_surface_eval_derivs(const cf_bezier_surface_t *s, double u,
                              double v, int k, double *out)
{
    cf_status_t st = params(s, out, &u, &v);
    size_t K, hdim, nu, nv;
    double *work, *Bu, *Bv, *R, *A;
    if (st != CF_STATUS_OK)
        return st;
    if (k < 0 || k > CF_BEZIER_MAX_DEGREE)
        return CF_STATUS_INVALID_ARG;
    K = (size_t)k + 1;
    hdim = s->hdim;
    nu = (size_t)s->m + 1;
    nv = (size_t)s->n + 1;
    work = cf__alloc_array(K * nu + K * nv + nv * hdim + K * K * hdim,
                           sizeof *work);
    if (work == NULL)
        return CF_STATUS_NO_MEMORY;
    Bu = work;
    Bv = Bu + K * nu;
    R = Bv + K * nv;
    A = R + nv * hdim;
    for (size_t a = 0; a < K; a++) {
        (void)cf_bernstein_all_deriv(s->m, u, (int)a, Bu + a * nu);
        (void)cf_bernstein_all_deriv(s->n, v, (int)a, Bv + a * nv);
    }
    cf__surf_tensor_derivs(s->pts, nv * hdim, hdim, Bu, nu, Bv, nv, K, R, A);
    cf__surf_rational_derivs(A, s->dim, hdim, k, out);
    cf__free(work);
    return CF_STATUS_OK;
}

size_t
cf_bezier_surface_decasteljau_size(const cf_bezier_surface_t *s)
{
    size_t m, n;
    if (s == NULL)
        return 0;
    m = (size_t)s->m;
    n = (size_t)s->n;
    return ((n + 1) * (m + 1) * (m + 2) / 2 + (n + 1) * (n + 2) / 2) * s->dim;
}

/* The de Casteljau triangle of cnt homogeneous points src (stride hdim) at
** t: into tri (homogeneous, level after level), Cartesian into out. */
static void
triangle(const double *src, size_t cnt, size_t stride, size_t hdim,
         size_t dim, bool rational, double t, double *tri, double *out)
{
    size_t at = 0, prev = 0;
    for (size_t i = 0; i < cnt; i++)
        memcpy(tri + i * hdim, src + i * stride, hdim * sizeof *tri);
    at = cnt;
    for (size_t l = 1; l < cnt; l++) {
        for (size_t i = 0; i + l < cnt; i++)
            for (size_t c = 0; c < hdim; c++)
                tri[(at + i) * hdim + c] =
                    (1.0 - t) * tri[(prev + i) * hdim + c] +
                    t * tri[(prev + i + 1) * hdim + c];
        prev = at;
        at += cnt - l;
    }
    cf__surf_points(tri, at, dim, rational, out);
}

cf_status_t
cf_bezier_surface_decasteljau(const cf_bezier_surface_t *s, double u,
                              double v, double *out)
{
    cf_status_t st = params(s, out, &u, &v);
    size_t nu, nv, hdim, tu, tv;
    double *tri, *row;
    if (st != CF_STATUS_OK)
        return st;
    nu = (size_t)s->m + 1;
    nv = (size_t)s->n + 1;
    hdim = s->hdim;
    tu = nu * (nu + 1) / 2;
    tv = nv * (nv + 1) / 2;
    tri = cf__alloc_array((tu > tv ? tu : tv) + nv, hdim * sizeof *tri);
    if (tri == NULL)
        return CF_STATUS_NO_MEMORY;
    row = tri + (tu > tv ? tu : tv) * hdim;
    for (size_t j = 0; j < nv; j++) {
        triangle(s->pts + j * hdim, nu, nv * hdim, hdim, s->dim,
                 s->rational, u, tri, out + j * tu * s->dim);
        memcpy(row + j * hdim, tri + (tu - 1) * hdim, hdim * sizeof *row);
    }
    triangle(row, nv, hdim, hdim, s->dim, s->rational, v, tri,
             out + nv * tu * s->dim);
    cf__free(tri);
    return CF_STATUS_OK;
}

/* Derivatives up to order 2 for the normal and the curvatures. */
static cf_status_t
second(const cf_bezier_surface_t *s, double u, double v, double D[27])
{
    if (s == NULL)
        return CF_STATUS_INVALID_ARG;
    if (s->dim != 3)
        return CF_STATUS_INVALID_ARG;
    return cf_bezier_surface_eval_derivs(s, u, v, 2, D);
}

cf_status_t
cf_bezier_surface_normal(const cf_bezier_surface_t *s, double u, double v,
                         double *out)
{
    double D[27];
    cf_status_t st = out == NULL ? CF_STATUS_INVALID_ARG
                                 : second(s, u, v, D);
    return st != CF_STATUS_OK ? st : cf__surf_normal(D, out);
}

cf_status_t
cf_bezier_surface_curvature(const cf_bezier_surface_t *s, double u,
                            double v, double *gauss, double *mean)
{
    double D[27];
    cf_status_t st = second(s, u, v, D);
    return st != CF_STATUS_OK ? st : cf__surf_curvature(D, gauss, mean);
}

void
cf_bezier_surface_bbox(const cf_bezier_surface_t *s, double *lo, double *hi)
{
    if (s == NULL || lo == NULL || hi == NULL)
        return;
    for (size_t c = 0; c < s->dim; c++) {
        lo[c] = INFINITY;
        hi[c] = -INFINITY;
    }
    for (size_t f = 0; f < npts(s); f++) {
        const double *p = s->pts + f * s->hdim;
        double w = s->rational ? p[s->dim] : 1.0;
        for (size_t c = 0; c < s->dim; c++) {
            lo[c] = fmin(lo[c], p[c] / w);
            hi[c] = fmax(hi[c], p[c] / w);
        }
    }
}

void
cf_bezier_surface_list_destroy(cf_bezier_surface_list_t *list)
{
    if (list == NULL)
        return;
    if (list->items != NULL)
        for (size_t i = 0; i < list->nu * list->nv; i++)
            cf_bezier_surface_destroy(list->items[i]);
    cf__free(list->items);
    cf__free(list->u0);
    cf__free(list->u1);
    cf__free(list->v0);
    cf__free(list->v1);
    cf__free(list);
}
