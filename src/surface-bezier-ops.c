/* Tensor-product Bézier surfaces: iso-curves, split, sub-patch, degree
** elevation (curvefig/surface.h).  Each operation in u is the curve
** operation on the grid read as a curve whose points are rows; in v the
** same on the transposed grid. */
#include <string.h>

#include "surface-private.h"
#include "curvefig/bernstein.h"
#include "numtext-private.h"

static size_t
count_of(const cf_bezier_surface_t *s)
{
    return ((size_t)s->m + 1) * ((size_t)s->n + 1);
}

/* The grid as a polynomial Bézier curve along dir. */
static cf_status_t
as_curve(const cf_bezier_surface_t *s, cf_dir_t dir, cf_bezier_t **out,
         cf_diag_t *diag)
{
    size_t nu = (size_t)s->m + 1, nv = (size_t)s->n + 1;
    double *t;
    cf_status_t st;
    if (dir == CF_DIR_U)
        return cf_bezier_create(nv * s->hdim, s->m, s->pts, NULL, out, diag);
    t = cf__alloc_array(count_of(s), s->hdim * sizeof *t);
    if (t == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    cf__surf_transpose(s->pts, nu, nv, s->hdim, t);
    st = cf_bezier_create(nu * s->hdim, s->n, t, NULL, out, diag);
    cf__free(t);
    return st;
}

/* The surface whose grid, read along dir, is the curve c (like s
** otherwise). */
static cf_status_t
from_curve(const cf_bezier_surface_t *s, cf_dir_t dir, const cf_bezier_t *c,
           cf_bezier_surface_t **out, cf_diag_t *diag)
{
    int deg = cf_bezier_degree(c);
    int m = dir == CF_DIR_U ? deg : s->m, n = dir == CF_DIR_U ? s->n : deg;
    cf_bezier_surface_t *r = cf__bsurf_bezier_new(s->dim, m, n, s->rational);
    *out = NULL;
    if (r == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    if (dir == CF_DIR_U)
        memcpy(r->pts, cf_bezier_hpoints(c),
               count_of(r) * r->hdim * sizeof(double));
    else
        cf__surf_transpose(cf_bezier_hpoints(c), (size_t)n + 1,
                           (size_t)m + 1, r->hdim, r->pts);
    *out = r;
    return CF_STATUS_OK;
}

static cf_status_t
check_dir(const cf_bezier_surface_t *s, cf_dir_t dir, cf_diag_t *diag)
{
    if (s == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "surface is NULL");
    if (dir != CF_DIR_U && dir != CF_DIR_V)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "direction %d is neither u (0) nor v (1)", (int)dir);
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_surface_iso(const cf_bezier_surface_t *s, cf_dir_t dir,
                      double value, cf_bezier_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    double B[CF_BEZIER_MAX_DEGREE + 1], *row;
    size_t nu, nv, len, h;
    cf_status_t st;
    cf_diag_clear(diag);
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    st = check_dir(s, dir, diag);
    if (st == CF_STATUS_OK)
        st = cf__surf_param(0.0, 1.0, &value, dir, diag);
    if (st != CF_STATUS_OK)
        return st;
    nu = (size_t)s->m + 1;
    nv = (size_t)s->n + 1;
    h = s->hdim;
    len = dir == CF_DIR_U ? nv : nu;
    row = cf__calloc(len * h, sizeof *row);
    if (row == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    (void)cf_bernstein_all(dir == CF_DIR_U ? s->m : s->n, value, B);
    for (size_t i = 0; i < nu; i++)
        for (size_t j = 0; j < nv; j++) {
            double b = B[dir == CF_DIR_U ? i : j];
            double *d = row + (dir == CF_DIR_U ? j : i) * h;
            const double *p = s->pts + (i * nv + j) * h;
            for (size_t c = 0; c < h; c++)
                d[c] += b * p[c];
        }
    if (s->rational)
        st = cf_bezier_create_homogeneous(s->dim, (int)len - 1, row, out,
                                          diag);
    else
        st = cf_bezier_create(s->dim, (int)len - 1, row, NULL, out, diag);
    cf__free(row);
    return st;
}

cf_status_t
cf_bezier_surface_split(const cf_bezier_surface_t *s, cf_dir_t dir,
                        double value, cf_bezier_surface_t **lo,
                        cf_bezier_surface_t **hi, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bezier_t *c = NULL, *l = NULL, *r = NULL;
    cf_status_t st;
    cf_diag_clear(diag);
    if (lo != NULL)
        *lo = NULL;
    if (hi != NULL)
        *hi = NULL;
    st = check_dir(s, dir, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (!(value > 0.0 && value < 1.0))
        return cf__error(diag, CF_STATUS_DOMAIN, -1,
                         "split parameter %s = %s is not inside (0, 1)",
                         dir == CF_DIR_U ? "u" : "v", CF__NUM(value));
    st = as_curve(s, dir, &c, diag);
    if (st == CF_STATUS_OK)
        st = cf_bezier_split(c, value, lo ? &l : NULL, hi ? &r : NULL, diag);
    if (st == CF_STATUS_OK && lo != NULL)
        st = from_curve(s, dir, l, lo, diag);
    if (st == CF_STATUS_OK && hi != NULL)
        st = from_curve(s, dir, r, hi, diag);
    if (st != CF_STATUS_OK && lo != NULL) {
        cf_bezier_surface_destroy(*lo);
        *lo = NULL;
    }
    cf_bezier_destroy(c);
    cf_bezier_destroy(l);
    cf_bezier_destroy(r);
    return st;
}

/* One direction of segment / elevate: *cur replaced by the result. */
static cf_status_t
segment_dir(const cf_bezier_surface_t *s, cf_dir_t dir, double a, double b,
            int r, cf_bezier_surface_t **out, cf_diag_t *diag)
{
    cf_bezier_t *c = NULL, *d = NULL;
    cf_status_t st = as_curve(s, dir, &c, diag);
    if (st == CF_STATUS_OK)
        st = r < 0 ? cf_bezier_segment(c, a, b, &d, diag)
                   : cf_bezier_elevate(c, r, &d, diag);
    if (st == CF_STATUS_OK)
        st = from_curve(s, dir, d, out, diag);
    cf_bezier_destroy(c);
    cf_bezier_destroy(d);
    return st;
}

static cf_status_t
two_steps(const cf_bezier_surface_t *s, const double ab[4], int ru, int rv,
          cf_bezier_surface_t **out, cf_diag_t *diag)
{
    cf_bezier_surface_t *t = NULL;
    cf_status_t st = segment_dir(s, CF_DIR_U, ab[0], ab[1], ru, &t, diag);
    if (st == CF_STATUS_OK)
        st = segment_dir(t, CF_DIR_V, ab[2], ab[3], rv, out, diag);
    cf_bezier_surface_destroy(t);
    return st;
}

cf_status_t
cf_bezier_surface_segment(const cf_bezier_surface_t *s, double u0,
                          double u1, double v0, double v1,
                          cf_bezier_surface_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    double ab[4] = { u0, u1, v0, v1 };
    cf_diag_clear(diag);
    if (out == NULL || s == NULL) {
        if (out != NULL)
            *out = NULL;
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "surface or out is NULL");
    }
    *out = NULL;
    for (int d = 0; d < 2; d++)
        if (!(ab[2 * d] >= 0.0 && ab[2 * d] < ab[2 * d + 1] &&
              ab[2 * d + 1] <= 1.0))
            return cf__error(diag, CF_STATUS_DOMAIN, -1,
                             "sub-patch interval of %s [%s, %s] is not "
                             "inside [0, 1] with its ends in order",
                             d == 0 ? "u" : "v", CF__NUM(ab[2 * d]),
                             CF__NUM(ab[2 * d + 1]));
    return two_steps(s, ab, -1, -1, out, diag);
}

cf_status_t
cf_bezier_surface_elevate(const cf_bezier_surface_t *s, int ru, int rv,
                          cf_bezier_surface_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    static const double ab[4] = { 0.0, 1.0, 0.0, 1.0 };
    cf_diag_clear(diag);
    if (out == NULL || s == NULL) {
        if (out != NULL)
            *out = NULL;
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "surface or out is NULL");
    }
    *out = NULL;
    if (ru < 0 || rv < 0)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "elevation (%d, %d) is negative", ru, rv);
    return two_steps(s, ab, ru, rv, out, diag);
}
