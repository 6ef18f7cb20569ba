/* B-spline and NURBS surfaces: construction, queries and evaluation
** (curvefig/surface.h). */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "surface-private.h"
#include "bspline-private.h"

cf_bspline_surface_t *
cf__bsurf_new(size_t dim, bool rational, int p, int q, size_t nu, size_t nv)
{
    size_t hdim = dim + rational, head, doubles, nU, nV;
    cf_bspline_surface_t *s;
    if (dim == 0 || dim > SIZE_MAX / 64 || p < 0 || q < 0 || nu == 0 ||
        nv == 0 || nu > SIZE_MAX / 64 || nv > SIZE_MAX / 64 ||
        nu > SIZE_MAX / nv || nu * nv > SIZE_MAX / 8 / hdim)
        return NULL;
    nU = nu + (size_t)p + 1;
    nV = nv + (size_t)q + 1;
    head = (sizeof *s + sizeof(double) - 1) / sizeof(double);
    doubles = nu * nv * hdim;
    if (doubles > SIZE_MAX / sizeof(double) - head - nU - nV)
        return NULL;
    s = cf__alloc_array(head + nU + nV + doubles, sizeof(double));
    if (s == NULL)
        return NULL;
    memset(s, 0, sizeof *s);
    s->dim = dim;
    s->hdim = hdim;
    s->p = p;
    s->q = q;
    s->rational = rational;
    s->nu = nu;
    s->nv = nv;
    s->nU = nU;
    s->nV = nV;
    s->U = (double *)(void *)s + head;
    s->V = s->U + nU;
    s->P = s->V + nV;
    return s;
}

void
cf__bsurf_finish(cf_bspline_surface_t *s)
{
    cf_knots_domain(s->p, s->U, s->nU, &s->ua, &s->ub);
    cf_knots_domain(s->q, s->V, s->nV, &s->va, &s->vb);
}

/* One knot vector, its message prefixed "knots U: ". */
static cf_status_t
check_knots(const char *name, int deg, size_t n, const double *K, size_t nK,
            cf_diag_t *diag)
{
    cf_diag_t d;
    cf_status_t st;
    if (K == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "knots %s is NULL",
                         name);
    st = cf_knots_validate(deg, n, K, nK, &d);
    if (st != CF_STATUS_OK) {
        /* the curve check names knots u_i: those of V are v_j */
        if (name[0] == 'V')
            for (char *c = d.msg; (c = strstr(c, " u_")) != NULL; c += 3)
                c[1] = 'v';
        return cf__error(diag, st, d.index, "knots %s: %s", name, d.msg);
    }
    return CF_STATUS_OK;
}

static cf_status_t
create(size_t dim, int p, int q, const double *U, size_t nU, const double *V,
       size_t nV, const double *pts, size_t nu, size_t nv,
       const double *weights, bool homogeneous, cf_bspline_surface_t **out,
       cf_diag_t *diag)
{
    cf_bspline_surface_t *s;
    cf_status_t st;
    cf_diag_clear(diag);
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    if (pts == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "points is NULL");
    if (dim < 1)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "dimension is 0; it must be at least 1");
    st = check_knots("U", p, nu, U, nU, diag);
    if (st == CF_STATUS_OK)
        st = check_knots("V", q, nv, V, nV, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (homogeneous) {
        st = cf__surf_check_h(dim, pts, nu, nv, diag);
        if (st != CF_STATUS_OK)
            return st;
    }
    s = cf__bsurf_new(dim, homogeneous || weights != NULL, p, q, nu, nv);
    if (s == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory for the surface");
    memcpy(s->U, U, nU * sizeof *U);
    memcpy(s->V, V, nV * sizeof *V);
    if (homogeneous)
        memcpy(s->P, pts, nu * nv * s->hdim * sizeof *pts);
    else
        st = cf__surf_fill(dim, pts, weights, nu, nv, s->P, diag);
    if (st != CF_STATUS_OK) {
        cf__free(s);
        return st;
    }
    cf__bsurf_finish(s);
    *out = s;
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_surface_create(size_t dim, int p, int q, const double *U,
                          size_t nU, const double *V, size_t nV,
                          const double *points, size_t nu, size_t nv,
                          const double *weights, cf_bspline_surface_t **out,
                          cf_diag_t *diag)
{
    cf_diag_clear(diag);
    return create(dim, p, q, U, nU, V, nV, points, nu, nv, weights, false,
                  out, diag);
}

cf_status_t
cf_bspline_surface_create_homogeneous(size_t dim, int p, int q,
                                      const double *U, size_t nU,
                                      const double *V, size_t nV,
                                      const double *hpoints, size_t nu,
                                      size_t nv, cf_bspline_surface_t **out,
                                      cf_diag_t *diag)
{
    cf_diag_clear(diag);
    return create(dim, p, q, U, nU, V, nV, hpoints, nu, nv, NULL, true, out,
                  diag);
}

cf_status_t
cf_bspline_surface_from_bezier(const cf_bezier_surface_t *b,
                               cf_bspline_surface_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    int m, n;
    cf_bspline_surface_t *s;
    cf_diag_clear(diag);
    if (out == NULL || b == NULL) {
        if (out != NULL)
            *out = NULL;
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "surface or out is NULL");
    }
    *out = NULL;
    m = b->m;
    n = b->n;
    if (m > CF_BSPLINE_MAX_DEGREE || n > CF_BSPLINE_MAX_DEGREE)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "degrees (%d, %d): a B-spline allows at most %d",
                         m, n, CF_BSPLINE_MAX_DEGREE);
    s = cf__bsurf_new(b->dim, b->rational, m, n, (size_t)m + 1,
                      (size_t)n + 1);
    if (s == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    for (size_t i = 0; i < s->nU; i++)
        s->U[i] = i <= (size_t)m ? 0.0 : 1.0;
    for (size_t i = 0; i < s->nV; i++)
        s->V[i] = i <= (size_t)n ? 0.0 : 1.0;
    memcpy(s->P, b->pts, s->nu * s->nv * s->hdim * sizeof(double));
    cf__bsurf_finish(s);
    *out = s;
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_surface_copy(const cf_bspline_surface_t *s,
                        cf_bspline_surface_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    if (s == NULL) {
        if (out != NULL)
            *out = NULL;
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "surface is NULL");
    }
    if (s->rational)
        return cf_bspline_surface_create_homogeneous(
            s->dim, s->p, s->q, s->U, s->nU, s->V, s->nV, s->P, s->nu, s->nv,
            out, diag);
    return cf_bspline_surface_create(s->dim, s->p, s->q, s->U, s->nU, s->V,
                                     s->nV, s->P, s->nu, s->nv, NULL, out,
                                     diag);
}

void
cf_bspline_surface_destroy(cf_bspline_surface_t *s)
{
    cf__free(s);
}

size_t cf_bspline_surface_dim(const cf_bspline_surface_t *s)
{
    return s ? s->dim : 0;
}
int cf_bspline_surface_degree_u(const cf_bspline_surface_t *s)
{
    return s ? s->p : 0;
}
int cf_bspline_surface_degree_v(const cf_bspline_surface_t *s)
{
    return s ? s->q : 0;
}
size_t cf_bspline_surface_count_u(const cf_bspline_surface_t *s)
{
    return s ? s->nu : 0;
}
size_t cf_bspline_surface_count_v(const cf_bspline_surface_t *s)
{
    return s ? s->nv : 0;
}
bool cf_bspline_surface_is_rational(const cf_bspline_surface_t *s)
{
    return s ? s->rational : false;
}

const double *
cf_bspline_surface_knots(const cf_bspline_surface_t *s, cf_dir_t dir,
                         size_t *n)
{
    if (n != NULL)
        *n = s == NULL ? 0 : dir == CF_DIR_U ? s->nU : s->nV;
    return s == NULL ? NULL : dir == CF_DIR_U ? s->U : s->V;
}

const double *
cf_bspline_surface_hpoints(const cf_bspline_surface_t *s)
{
    return s ? s->P : NULL;
}

void
cf_bspline_surface_get_points(const cf_bspline_surface_t *s, double *out)
{
    if (s != NULL && out != NULL)
        cf__surf_points(s->P, s->nu * s->nv, s->dim, s->rational, out);
}

void
cf_bspline_surface_get_weights(const cf_bspline_surface_t *s, double *out)
{
    if (s != NULL && out != NULL)
        cf__surf_weights(s->P, s->nu * s->nv, s->dim, s->rational, out);
}

void
cf_bspline_surface_domain(const cf_bspline_surface_t *s, cf_dir_t dir,
                          double *a, double *b)
{
    if (a != NULL)
        *a = s == NULL ? 0.0 : dir == CF_DIR_U ? s->ua : s->va;
    if (b != NULL)
        *b = s == NULL ? 0.0 : dir == CF_DIR_U ? s->ub : s->vb;
}

/* Both parameters by the domain rule; the spans. */
static cf_status_t
params(const cf_bspline_surface_t *s, const void *out, double *u, double *v,
       size_t *su, size_t *sv)
{
    cf_status_t st;
    if (s == NULL || out == NULL)
        return CF_STATUS_INVALID_ARG;
    st = cf__surf_param(s->ua, s->ub, u, CF_DIR_U, NULL);
    if (st == CF_STATUS_OK)
        st = cf__surf_param(s->va, s->vb, v, CF_DIR_V, NULL);
    if (st != CF_STATUS_OK)
        return st;
    *su = cf_knots_find_span(s->p, s->U, s->nU, *u);
    *sv = cf_knots_find_span(s->q, s->V, s->nV, *v);
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_surface_eval(const cf_bspline_surface_t *s, double u, double v,
                        double *out)
{
    double Nu[CF_BSPLINE_MAX_DEGREE + 1], Nv[CF_BSPLINE_MAX_DEGREE + 1];
    size_t su, sv, h;
    cf_status_t st = params(s, out, &u, &v, &su, &sv);
    if (st != CF_STATUS_OK)
        return st;
    h = s->hdim;
    cf__basis_deriv(s->p, s->U, s->nU, NULL, su, u, 0, Nu);
    cf__basis_deriv(s->q, s->V, s->nV, NULL, sv, v, 0, Nv);
    cf__surf_tensor_point(s->P + ((su - (size_t)s->p) * s->nv + sv -
                                  (size_t)s->q) * h,
                          s->nv * h, h, s->dim, Nu, (size_t)s->p + 1, Nv,
                          (size_t)s->q + 1, out);
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_surface_eval_derivs(const cf_bspline_surface_t *s, double u,
                               double v, int k, double *out)
{
    size_t su, sv, K, h, pu, qv, need;
    double small[512], *work, *Nu, *Nv, *R, *A;
    cf_status_t st = params(s, out, &u, &v, &su, &sv);
    if (st != CF_STATUS_OK)
        return st;
    if (k < 0 || k > CF__BSPLINE_MAX_RATIONAL_DERIV)
        return CF_STATUS_INVALID_ARG;
    K = (size_t)k + 1;
    h = s->hdim;
    pu = (size_t)s->p + 1;
    qv = (size_t)s->q + 1;
    need = K * pu + K * qv + qv * h + K * K * h;
    /* low orders of small surfaces on the stack, the rest allocated */
    work = need <= sizeof small / sizeof *small
               ? small
               : cf__alloc_array(need, sizeof *work);
    if (work == NULL)
        return CF_STATUS_NO_MEMORY;
    Nu = work;
    Nv = Nu + K * pu;
    R = Nv + K * qv;
    A = R + qv * h;
    for (size_t d = 0; d < K; d++) {
        cf__basis_deriv(s->p, s->U, s->nU, NULL, su, u, (int)d, Nu + d * pu);
        cf__basis_deriv(s->q, s->V, s->nV, NULL, sv, v, (int)d, Nv + d * qv);
    }
    cf__surf_tensor_derivs(s->P + ((su - (size_t)s->p) * s->nv + sv -
                                   (size_t)s->q) * h,
                           s->nv * h, h, Nu, pu, Nv, qv, K, R, A);
    cf__surf_rational_derivs(A, s->dim, h, k, out);
    if (work != small)
        cf__free(work);
    return CF_STATUS_OK;
}

size_t
cf_bspline_surface_deboor_size(const cf_bspline_surface_t *s)
{
    size_t p, q;
    if (s == NULL)
        return 0;
    p = (size_t)s->p;
    q = (size_t)s->q;
    return ((q + 1) * (p + 1) * (p + 2) / 2 + (q + 1) * (q + 2) / 2) * s->dim;
}

/* The de Boor net of degree p on span k at t: from the p + 1 homogeneous
** points src (stride), into net (homogeneous), Cartesian into out. */
static void
net(const double *src, size_t stride, size_t h, size_t dim, bool rational,
    const double *U, int p, size_t k, double t, double *w, double *out)
{
    size_t cnt = (size_t)p + 1, at = cnt, prev = 0;
    for (size_t i = 0; i < cnt; i++)
        memcpy(w + i * h, src + i * stride, h * sizeof *w);
    for (size_t j = 1; j < cnt; j++) {
        for (size_t l = 0; l + j < cnt; l++) {
            size_t i = k - (size_t)p + j + l;
            double a = (t - U[i]) / (U[i + (size_t)p + 1 - j] - U[i]);
            for (size_t c = 0; c < h; c++)
                w[(at + l) * h + c] = (1.0 - a) * w[(prev + l) * h + c] +
                                      a * w[(prev + l + 1) * h + c];
        }
        prev = at;
        at += cnt - j;
    }
    cf__surf_points(w, at, dim, rational, out);
}

cf_status_t
cf_bspline_surface_deboor(const cf_bspline_surface_t *s, double u, double v,
                          double *out, size_t span[2])
{
    size_t su, sv, h, tu, tv, big, qv;
    double *w, *row;
    cf_status_t st = params(s, out, &u, &v, &su, &sv);
    if (st != CF_STATUS_OK)
        return st;
    h = s->hdim;
    qv = (size_t)s->q + 1;
    tu = ((size_t)s->p + 1) * ((size_t)s->p + 2) / 2;
    tv = qv * (qv + 1) / 2;
    big = tu > tv ? tu : tv;
    w = cf__alloc_array(big + qv, h * sizeof *w);
    if (w == NULL)
        return CF_STATUS_NO_MEMORY;
    row = w + big * h;
    for (size_t c = 0; c < qv; c++) {
        const double *src = s->P + ((su - (size_t)s->p) * s->nv + sv -
                                    (size_t)s->q + c) * h;
        net(src, s->nv * h, h, s->dim, s->rational, s->U, s->p, su, u, w,
            out + c * tu * s->dim);
        memcpy(row + c * h, w + (tu - 1) * h, h * sizeof *row);
    }
    net(row, h, h, s->dim, s->rational, s->V, s->q, sv, v, w,
        out + qv * tu * s->dim);
    if (span != NULL) {
        span[0] = su;
        span[1] = sv;
    }
    cf__free(w);
    return CF_STATUS_OK;
}

static cf_status_t
second(const cf_bspline_surface_t *s, double u, double v, double D[27])
{
    if (s == NULL || s->dim != 3)
        return CF_STATUS_INVALID_ARG;
    return cf_bspline_surface_eval_derivs(s, u, v, 2, D);
}

cf_status_t
cf_bspline_surface_normal(const cf_bspline_surface_t *s, double u, double v,
                          double *out)
{
    double D[27];
    cf_status_t st = out == NULL ? CF_STATUS_INVALID_ARG
                                 : second(s, u, v, D);
    return st != CF_STATUS_OK ? st : cf__surf_normal(D, out);
}

cf_status_t
cf_bspline_surface_curvature(const cf_bspline_surface_t *s, double u,
                             double v, double *gauss, double *mean)
{
    double D[27];
    cf_status_t st = second(s, u, v, D);
    return st != CF_STATUS_OK ? st : cf__surf_curvature(D, gauss, mean);
}
