/* B-spline and NURBS surfaces: iso-curves, knot lines, knot insertion and
** refinement, split, degree elevation and Bézier decomposition
** (curvefig/surface.h).  Each operation in u is the curve operation of
** bspline.h on the grid read as a curve whose points are rows; in v the
** same on the transposed grid. */
#include <string.h>

#include "surface-private.h"
#include "bspline-private.h"

static cf_status_t
check_in(const cf_bspline_surface_t *s, cf_dir_t dir, cf_diag_t *diag)
{
    if (s == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "surface is NULL");
    if (dir != CF_DIR_U && dir != CF_DIR_V)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "direction %d is neither u (0) nor v (1)", (int)dir);
    return CF_STATUS_OK;
}

static cf_status_t
no_memory(cf_diag_t *diag)
{
    return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
}

/* The grid as a polynomial B-spline curve along dir. */
static cf_status_t
as_curve(const cf_bspline_surface_t *s, cf_dir_t dir, cf_bspline_t **out,
         cf_diag_t *diag)
{
    double *t;
    cf_status_t st;
    if (dir == CF_DIR_U)
        return cf_bspline_create(s->nv * s->hdim, s->p, s->U, s->nU, s->P,
                                 s->nu, NULL, out, diag);
    t = cf__alloc_array(s->nu * s->nv, s->hdim * sizeof *t);
    if (t == NULL)
        return no_memory(diag);
    cf__surf_transpose(s->P, s->nu, s->nv, s->hdim, t);
    st = cf_bspline_create(s->nu * s->hdim, s->q, s->V, s->nV, t, s->nv,
                           NULL, out, diag);
    cf__free(t);
    return st;
}

/* The surface whose grid, read along dir, is the curve c. */
static cf_status_t
from_curve(const cf_bspline_surface_t *s, cf_dir_t dir, const cf_bspline_t *c,
           cf_bspline_surface_t **out, cf_diag_t *diag)
{
    int deg = cf_bspline_degree(c);
    size_t cnt = cf_bspline_count(c);
    bool u = dir == CF_DIR_U;
    cf_bspline_surface_t *r =
        cf__bsurf_new(s->dim, s->rational, u ? deg : s->p, u ? s->q : deg,
                      u ? cnt : s->nu, u ? s->nv : cnt);
    *out = NULL;
    if (r == NULL)
        return no_memory(diag);
    memcpy(r->U, u ? cf_bspline_knots(c) : s->U, r->nU * sizeof(double));
    memcpy(r->V, u ? s->V : cf_bspline_knots(c), r->nV * sizeof(double));
    if (u)
        memcpy(r->P, cf_bspline_hpoints(c),
               r->nu * r->nv * r->hdim * sizeof(double));
    else
        cf__surf_transpose(cf_bspline_hpoints(c), r->nv, r->nu, r->hdim,
                           r->P);
    cf__bsurf_finish(r);
    *out = r;
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_surface_iso(const cf_bspline_surface_t *s, cf_dir_t dir,
                       double value, cf_bspline_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    double N[CF_BSPLINE_MAX_DEGREE + 1], *line;
    size_t span, len, h;
    const double *K;
    int deg;
    cf_status_t st;
    cf_diag_clear(diag);
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    st = check_in(s, dir, diag);
    if (st == CF_STATUS_OK)
        st = dir == CF_DIR_U
                 ? cf__surf_param(s->ua, s->ub, &value, dir, diag)
                 : cf__surf_param(s->va, s->vb, &value, dir, diag);
    if (st != CF_STATUS_OK)
        return st;
    h = s->hdim;
    deg = dir == CF_DIR_U ? s->p : s->q;
    K = dir == CF_DIR_U ? s->U : s->V;
    span = cf_knots_find_span(deg, K, dir == CF_DIR_U ? s->nU : s->nV,
                              value);
    cf__basis_deriv(deg, K, dir == CF_DIR_U ? s->nU : s->nV, NULL, span,
                    value, 0, N);
    len = dir == CF_DIR_U ? s->nv : s->nu;
    line = cf__calloc(len * h, sizeof *line);
    if (line == NULL)
        return no_memory(diag);
    for (int r = 0; r <= deg; r++) {
        size_t a = span - (size_t)deg + (size_t)r;
        for (size_t b = 0; b < len; b++) {
            size_t i = dir == CF_DIR_U ? a : b, j = dir == CF_DIR_U ? b : a;
            const double *p = s->P + (i * s->nv + j) * h;
            for (size_t c = 0; c < h; c++)
                line[b * h + c] += N[r] * p[c];
        }
    }
    if (dir == CF_DIR_U)
        st = s->rational
                 ? cf_bspline_create_homogeneous(s->dim, s->q, s->V, s->nV,
                                                 line, len, out, diag)
                 : cf_bspline_create(s->dim, s->q, s->V, s->nV, line, len,
                                     NULL, out, diag);
    else
        st = s->rational
                 ? cf_bspline_create_homogeneous(s->dim, s->p, s->U, s->nU,
                                                 line, len, out, diag)
                 : cf_bspline_create(s->dim, s->p, s->U, s->nU, line, len,
                                     NULL, out, diag);
    cf__free(line);
    return st;
}

cf_status_t
cf_bspline_surface_knot_lines(const cf_bspline_surface_t *s, cf_dir_t dir,
                              double *out, size_t *count)
{
    const double *K;
    size_t nK, n = 0;
    double a, b;
    if (check_in(s, dir, NULL) != CF_STATUS_OK || out == NULL ||
        count == NULL)
        return CF_STATUS_INVALID_ARG;
    K = cf_bspline_surface_knots(s, dir, &nK);
    cf_bspline_surface_domain(s, dir, &a, &b);
    for (size_t i = 0; i < nK; i++)
        if (K[i] >= a && K[i] <= b && (n == 0 || K[i] != out[n - 1]))
            out[n++] = K[i];
    *count = n;
    return CF_STATUS_OK;
}

/* The operations along one direction on the curve of the grid. */
enum op { INSERT, REFINE, ELEVATE };

static cf_status_t
along(const cf_bspline_surface_t *s, cf_dir_t dir, enum op op, double x,
      const double *xs, size_t nx, int r, cf_bspline_surface_t **out,
      cf_diag_t *diag)
{
    cf_bspline_t *c = NULL, *d = NULL;
    cf_status_t st = as_curve(s, dir, &c, diag);
    if (st == CF_STATUS_OK) {
        if (op == INSERT)
            st = cf_bspline_insert_knot(c, x, r, &d, NULL, diag);
        else if (op == REFINE)
            st = cf_bspline_refine(c, xs, nx, &d, diag);
        else
            st = cf_bspline_elevate(c, r, &d, diag);
    }
    if (st == CF_STATUS_OK)
        st = from_curve(s, dir, d, out, diag);
    cf_bspline_destroy(c);
    cf_bspline_destroy(d);
    return st;
}

static cf_status_t
start(const cf_bspline_surface_t *s, cf_dir_t dir, cf_bspline_surface_t **out,
      cf_diag_t *diag)
{
    cf_diag_clear(diag);
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    return check_in(s, dir, diag);
}

cf_status_t
cf_bspline_surface_insert_knot(const cf_bspline_surface_t *s, cf_dir_t dir,
                               double value, int r,
                               cf_bspline_surface_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = start(s, dir, out, diag);
    return st != CF_STATUS_OK ? st
                              : along(s, dir, INSERT, value, NULL, 0, r, out,
                                      diag);
}

cf_status_t
cf_bspline_surface_refine(const cf_bspline_surface_t *s, cf_dir_t dir,
                          const double *x, size_t nx,
                          cf_bspline_surface_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = start(s, dir, out, diag);
    return st != CF_STATUS_OK ? st
                              : along(s, dir, REFINE, 0.0, x, nx, 0, out,
                                      diag);
}

cf_status_t
cf_bspline_surface_elevate(const cf_bspline_surface_t *s, int ru, int rv,
                           cf_bspline_surface_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bspline_surface_t *t = NULL;
    cf_status_t st = start(s, CF_DIR_U, out, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (ru < 0 || rv < 0)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "elevation (%d, %d) is negative", ru, rv);
    st = along(s, CF_DIR_U, ELEVATE, 0.0, NULL, 0, ru, &t, diag);
    if (st == CF_STATUS_OK)
        st = along(t, CF_DIR_V, ELEVATE, 0.0, NULL, 0, rv, out, diag);
    cf_bspline_surface_destroy(t);
    return st;
}

cf_status_t
cf_bspline_surface_split(const cf_bspline_surface_t *s, cf_dir_t dir,
                         double value, cf_bspline_surface_t **lo,
                         cf_bspline_surface_t **hi, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bspline_t *c = NULL, *l = NULL, *r = NULL;
    cf_status_t st;
    cf_diag_clear(diag);
    if (lo != NULL)
        *lo = NULL;
    if (hi != NULL)
        *hi = NULL;
    st = check_in(s, dir, diag);
    if (st == CF_STATUS_OK)
        st = as_curve(s, dir, &c, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_split(c, value, lo ? &l : NULL, hi ? &r : NULL, diag);
    if (st == CF_STATUS_OK && lo != NULL)
        st = from_curve(s, dir, l, lo, diag);
    if (st == CF_STATUS_OK && hi != NULL)
        st = from_curve(s, dir, r, hi, diag);
    if (st != CF_STATUS_OK && lo != NULL) {
        cf_bspline_surface_destroy(*lo);
        *lo = NULL;
    }
    cf_bspline_destroy(c);
    cf_bspline_destroy(l);
    cf_bspline_destroy(r);
    return st;
}

/* The patches of one strip (p + 1 rows of nv points, hdim h) in v. */
static cf_status_t
strip_patches(const cf_bspline_surface_t *s, const double *strip, size_t a,
              cf_bezier_surface_list_t *L, cf_diag_t *diag)
{
    size_t pu = (size_t)s->p + 1, qv = (size_t)s->q + 1, h = s->hdim, cnt;
    double *t = cf__alloc_array(pu * s->nv, h * sizeof *t), *hp = NULL;
    double *br = NULL;
    cf_bspline_t *c = NULL;
    cf_status_t st;
    if (t == NULL)
        return no_memory(diag);
    cf__surf_transpose(strip, pu, s->nv, h, t);
    st = cf_bspline_create(pu * h, s->q, s->V, s->nV, t, s->nv, NULL, &c,
                           diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_bezier_points(c, &hp, &br, &cnt, diag);
    if (st == CF_STATUS_OK && cnt != L->nv)
        st = cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                       "internal: %zu patches in v, expected %zu", cnt,
                       L->nv);
    for (size_t b = 0; st == CF_STATUS_OK && b < cnt; b++) {
        cf_bezier_surface_t *B =
            cf__bsurf_bezier_new(s->dim, s->p, s->q, s->rational);
        if (B == NULL) {
            st = no_memory(diag);
            break;
        }
        cf__surf_transpose(hp + b * qv * pu * h, qv, pu, h, B->pts);
        L->items[a * L->nv + b] = B;
        if (a == 0) {
            L->v0[b] = br[b];
            L->v1[b] = br[b + 1];
        }
    }
    cf__free(t);
    cf__free(hp);
    cf__free(br);
    cf_bspline_destroy(c);
    return st;
}

/* Non-empty spans of the domain of degree p on K. */
static size_t
spans(int p, const double *K, size_t nK)
{
    size_t n = 0;
    for (size_t i = (size_t)p; i + (size_t)p + 1 < nK; i++)
        n += K[i] < K[i + 1];
    return n;
}

cf_status_t
cf_bspline_surface_to_beziers(const cf_bspline_surface_t *s,
                              cf_bezier_surface_list_t **out,
                              cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bspline_t *c = NULL;
    cf_bezier_surface_list_t *L;
    double *hp = NULL, *br = NULL;
    size_t cnt = 0, strip;
    cf_status_t st;
    cf_diag_clear(diag);
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    st = check_in(s, CF_DIR_U, diag);
    if (st != CF_STATUS_OK)
        return st;
    L = cf__calloc(1, sizeof *L);
    if (L == NULL)
        return no_memory(diag);
    L->nu = spans(s->p, s->U, s->nU);
    L->nv = spans(s->q, s->V, s->nV);
    L->items = cf__calloc(L->nu * L->nv, sizeof *L->items);
    L->u0 = cf__alloc_array(L->nu, sizeof(double));
    L->u1 = cf__alloc_array(L->nu, sizeof(double));
    L->v0 = cf__alloc_array(L->nv, sizeof(double));
    L->v1 = cf__alloc_array(L->nv, sizeof(double));
    if (L->items == NULL || !L->u0 || !L->u1 || !L->v0 || !L->v1)
        st = no_memory(diag);
    if (st == CF_STATUS_OK)
        st = as_curve(s, CF_DIR_U, &c, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_bezier_points(c, &hp, &br, &cnt, diag);
    if (st == CF_STATUS_OK && cnt != L->nu)
        st = cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                       "internal: %zu patches in u, expected %zu", cnt,
                       L->nu);
    strip = ((size_t)s->p + 1) * s->nv * s->hdim;
    for (size_t a = 0; st == CF_STATUS_OK && a < cnt; a++) {
        L->u0[a] = br[a];
        L->u1[a] = br[a + 1];
        st = strip_patches(s, hp + a * strip, a, L, diag);
    }
    cf__free(hp);
    cf__free(br);
    cf_bspline_destroy(c);
    if (st != CF_STATUS_OK) {
        cf_bezier_surface_list_destroy(L);
        return st;
    }
    *out = L;
    return CF_STATUS_OK;
}
