/* Triangular Bézier patches (curvefig/surface-triangle.h). */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "core-private.h"
#include "curvefig/surface-triangle.h"
#include "numtext-private.h"

struct cf_bezier_triangle {
    size_t dim, hdim;
    int n;
    bool rational;
    double pts[];   /* (n + 1)(n + 2) / 2 points of hdim doubles */
};

static size_t
tri(int m)
{
    return m < 0 ? 0 : ((size_t)m + 1) * ((size_t)m + 2) / 2;
}

/* Index of b_ijk (k = m - i - j) in the order of the header. */
static size_t
idx(int m, int i, int j)
{
    size_t r = (size_t)(m - i);
    return r * (r + 1) / 2 + (r - (size_t)j);
}

static cf_bezier_triangle_t *
alloc(size_t dim, int n, bool rational)
{
    size_t h = dim + rational;
    cf_bezier_triangle_t *t;
    if (dim == 0 || dim > SIZE_MAX / 64 ||
        h > (SIZE_MAX - sizeof *t) / sizeof(double) / tri(n))
        return NULL;
    t = cf__malloc(sizeof *t + tri(n) * h * sizeof(double));
    if (t == NULL)
        return NULL;
    t->dim = dim;
    t->hdim = h;
    t->n = n;
    t->rational = rational;
    return t;
}

cf_status_t
cf_bezier_triangle_create(size_t dim, int n, const double *points,
                          const double *weights, cf_bezier_triangle_t **out,
                          cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bezier_triangle_t *t;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    if (points == NULL || dim < 1)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "points is NULL or the dimension is 0");
    if (n < 0 || n > CF_BEZIER_TRIANGLE_MAX_DEGREE)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "degree %d is outside 0..%d", n,
                         CF_BEZIER_TRIANGLE_MAX_DEGREE);
    t = alloc(dim, n, weights != NULL);
    if (t == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    for (int i = n; i >= 0; i--)
        for (int j = n - i; j >= 0; j--) {
            size_t f = idx(n, i, j);
            double w = weights ? weights[f] : 1.0;
            if (!isfinite(w) || !(w > 0.0)) {
                cf__free(t);
                return cf__error(diag, CF_STATUS_BAD_WEIGHT, (long)f,
                                 "weight of b_%d%d%d is %s; weights must be "
                                 "finite and positive", i, j, n - i - j,
                                 CF__NUM(w));
            }
            for (size_t c = 0; c < dim; c++) {
                double x = points[f * dim + c];
                if (!isfinite(x) || !isfinite(w * x)) {
                    cf__free(t);
                    return cf__error(diag, CF_STATUS_NOT_FINITE, (long)f,
                                     "point b_%d%d%d has coordinate %zu = "
                                     "%s; coordinates must be finite", i, j,
                                     n - i - j, c + 1, CF__NUM(x));
                }
                t->pts[f * t->hdim + c] = w * x;
            }
            if (weights != NULL)
                t->pts[f * t->hdim + dim] = w;
        }
    *out = t;
    return CF_STATUS_OK;
}

void
cf_bezier_triangle_destroy(cf_bezier_triangle_t *t)
{
    cf__free(t);
}

size_t cf_bezier_triangle_dim(const cf_bezier_triangle_t *t)
{
    return t ? t->dim : 0;
}
int cf_bezier_triangle_degree(const cf_bezier_triangle_t *t)
{
    return t ? t->n : 0;
}
bool cf_bezier_triangle_is_rational(const cf_bezier_triangle_t *t)
{
    return t ? t->rational : false;
}
size_t cf_bezier_triangle_count(const cf_bezier_triangle_t *t)
{
    return t ? tri(t->n) : 0;
}

void
cf_bezier_triangle_get_points(const cf_bezier_triangle_t *t, double *out)
{
    if (t == NULL || out == NULL)
        return;
    for (size_t f = 0; f < tri(t->n); f++)
        for (size_t c = 0; c < t->dim; c++)
            out[f * t->dim + c] = t->pts[f * t->hdim + c] /
                                  (t->rational ? t->pts[f * t->hdim +
                                                        t->dim]
                                               : 1.0);
}

void
cf_bezier_triangle_get_weights(const cf_bezier_triangle_t *t, double *out)
{
    if (t == NULL || out == NULL)
        return;
    for (size_t f = 0; f < tri(t->n); f++)
        out[f] = t->rational ? t->pts[f * t->hdim + t->dim] : 1.0;
}

/* (u, v, 1 - u - v) by the domain rule of the header. */
static cf_status_t
bary(double u, double v, double b[3])
{
    const double s = 8.0 * DBL_EPSILON;
    if (!isfinite(u) || !isfinite(v))
        return CF_STATUS_NOT_FINITE;
    b[0] = u;
    b[1] = v;
    b[2] = 1.0 - u - v;
    for (int i = 0; i < 3; i++) {
        if (b[i] < -s)
            return CF_STATUS_DOMAIN;
        if (b[i] < 0.0)
            b[i] = 0.0;
    }
    return CF_STATUS_OK;
}

/* One de Casteljau step from degree m to m - 1 with the weights a. */
static void
step(const double *src, int m, const double a[3], size_t h, double *dst)
{
    for (int i = m - 1; i >= 0; i--)
        for (int j = m - 1 - i; j >= 0; j--) {
            const double *p = src + idx(m, i + 1, j) * h;
            const double *q = src + idx(m, i, j + 1) * h;
            const double *r = src + idx(m, i, j) * h;
            double *d = dst + idx(m - 1, i, j) * h;
            for (size_t c = 0; c < h; c++)
                d[c] = a[0] * p[c] + a[1] * q[c] + a[2] * r[c];
        }
}

/* Homogeneous point: n steps into work (2 tri(n) h doubles); returns the
** pointer to the h doubles of the result. */
static double *
run(const cf_bezier_triangle_t *t, const double a[3], const double *d,
    int nd, double *work)
{
    size_t h = t->hdim, T = tri(t->n);
    double *x = work, *y = work + T * h;
    memcpy(x, t->pts, T * h * sizeof *x);
    for (int m = t->n; m > 0; m--) {
        double *z;
        step(x, m, t->n - m < nd ? d : a, h, y);
        z = x;
        x = y;
        y = z;
    }
    return x;
}

/* Doubles of the evaluator's work kept on the stack: degree 10 in R^3,
** rational (2 x 66 points of 4), and every lower degree or dimension. */
#define POINT_STACK 528

static cf_status_t
point(const cf_bezier_triangle_t *t, double u, double v, double *out)
{
    double b[3], local[POINT_STACK], *work = local, *x;
    size_t need;
    cf_status_t st;
    if (t == NULL || out == NULL)
        return CF_STATUS_INVALID_ARG;
    st = bary(u, v, b);
    if (st != CF_STATUS_OK)
        return st;
    /* no allocation for the patches figures draw: the evaluator is called
    ** thousands of times a figure (bounds, the scheme, the facets) */
    need = 2 * tri(t->n) * t->hdim;
    if (need > POINT_STACK) {
        work = cf__alloc_array(2 * tri(t->n), t->hdim * sizeof *work);
        if (work == NULL)
            return CF_STATUS_NO_MEMORY;
    }
    x = run(t, b, b, 0, work);
    for (size_t c = 0; c < t->dim; c++)
        out[c] = x[c] / (t->rational ? x[t->dim] : 1.0);
    if (work != local)
        cf__free(work);
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_triangle_eval(const cf_bezier_triangle_t *t, double u, double v,
                        double *out)
{
    return point(t, u, v, out);
}

size_t
cf_bezier_triangle_decasteljau_size(const cf_bezier_triangle_t *t)
{
    size_t s = 0;
    if (t == NULL)
        return 0;
    for (int m = t->n; m >= 0; m--)
        s += tri(m);
    return s * t->dim;
}

cf_status_t
cf_bezier_triangle_decasteljau(const cf_bezier_triangle_t *t, double u,
                               double v, double *out)
{
    double b[3], *work, *x, *y;
    size_t h, at = 0;
    cf_status_t st;
    if (t == NULL || out == NULL)
        return CF_STATUS_INVALID_ARG;
    st = bary(u, v, b);
    if (st != CF_STATUS_OK)
        return st;
    h = t->hdim;
    work = cf__alloc_array(2 * tri(t->n), h * sizeof *work);
    if (work == NULL)
        return CF_STATUS_NO_MEMORY;
    x = work;
    y = work + tri(t->n) * h;
    memcpy(x, t->pts, tri(t->n) * h * sizeof *x);
    for (int m = t->n; m >= 0; m--) {
        double *z;
        for (size_t f = 0; f < tri(m); f++, at++)
            for (size_t c = 0; c < t->dim; c++)
                out[at * t->dim + c] = x[f * h + c] /
                                       (t->rational ? x[f * h + t->dim]
                                                    : 1.0);
        if (m == 0)
            break;
        step(x, m, b, h, y);
        z = x;
        x = y;
        y = z;
    }
    cf__free(work);
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_triangle_eval_derivs(const cf_bezier_triangle_t *t,
                               const double *dir, double u, double v, int k,
                               double *out)
{
    double b[3], *work, *A, size;
    size_t h, dim;
    cf_status_t st;
    if (t == NULL || out == NULL || dir == NULL || k < 0 ||
        k > CF_BEZIER_TRIANGLE_MAX_DEGREE)
        return CF_STATUS_INVALID_ARG;
    size = fmax(fabs(dir[0]), fmax(fabs(dir[1]), fabs(dir[2])));
    if (!isfinite(size) || fabs(dir[0] + dir[1] + dir[2]) > 1e-12 * size)
        return CF_STATUS_INVALID_ARG;
    st = bary(u, v, b);
    if (st != CF_STATUS_OK)
        return st;
    h = t->hdim;
    dim = t->dim;
    work = cf__alloc_array(2 * tri(t->n) + (size_t)k + 1, h * sizeof *work);
    if (work == NULL)
        return CF_STATUS_NO_MEMORY;
    A = work + 2 * tri(t->n) * h;
    for (int j = 0; j <= k; j++) {
        double *x, f = 1.0;
        if (j > t->n) {
            memset(A + (size_t)j * h, 0, h * sizeof *A);
            continue;
        }
        x = run(t, b, dir, j, work);
        for (int i = 0; i < j; i++)
            f *= (double)(t->n - i);
        for (size_t c = 0; c < h; c++)
            A[(size_t)j * h + c] = f * x[c];
    }
    /* the quotient rule: A^(j) = sum_i C(j, i) w^(i) S^(j-i) */
    for (int j = 0; j <= k; j++)
        for (size_t c = 0; c < dim; c++) {
            double s = A[(size_t)j * h + c];
            if (t->rational) {
                for (int i = 1; i <= j; i++)
                    s -= cf__binomial(j, i) * A[(size_t)i * h + dim] *
                         out[(size_t)(j - i) * dim + c];
                s /= A[dim];
            }
            out[(size_t)j * dim + c] = s;
        }
    cf__free(work);
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_triangle_normal(const cf_bezier_triangle_t *t, double u, double v,
                          double *out)
{
    static const double d1[3] = { -1, 1, 0 }, d2[3] = { -1, 0, 1 };
    double a[6], b[6], n[3], len;
    cf_status_t st;
    if (t == NULL || out == NULL || t->dim != 3)
        return CF_STATUS_INVALID_ARG;
    st = cf_bezier_triangle_eval_derivs(t, d1, u, v, 1, a);
    if (st == CF_STATUS_OK)
        st = cf_bezier_triangle_eval_derivs(t, d2, u, v, 1, b);
    if (st != CF_STATUS_OK)
        return st;
    n[0] = a[4] * b[5] - a[5] * b[4];
    n[1] = a[5] * b[3] - a[3] * b[5];
    n[2] = a[3] * b[4] - a[4] * b[3];
    len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0.0) || !isfinite(len))
        return CF_STATUS_DEGENERATE;
    for (int c = 0; c < 3; c++)
        out[c] = n[c] / len;
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_triangle_subdivide(const cf_bezier_triangle_t *t, double u,
                             double v, cf_bezier_triangle_t *out[3],
                             cf_diag_t *diag)
{
    cf_diag_clear(diag);
    double b[3], *levels;
    size_t h, *start;
    int n;
    cf_status_t st;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    out[0] = out[1] = out[2] = NULL;
    if (t == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "patch is NULL");
    st = bary(u, v, b);
    if (st != CF_STATUS_OK)
        return cf__error(diag, st, -1, "(u, v, w) = (%s, %s, %s) is not a "
                         "point of the triangle", CF__NUM(u), CF__NUM(v),
                         CF__NUM(1.0 - u - v));
    n = t->n;
    h = t->hdim;
    /* every level, homogeneous */
    levels = cf__alloc_array(2 * tri(n) * (size_t)(n + 1), h * sizeof(double));
    start = cf__alloc_array((size_t)n + 1, sizeof *start);
    for (int s = 0; s < 3 && levels && start; s++) {
        out[s] = alloc(t->dim, n, t->rational);
        if (out[s] == NULL)
            break;
    }
    if (levels == NULL || start == NULL || out[2] == NULL) {
        for (int s = 0; s < 3; s++) {
            cf__free(out[s]);
            out[s] = NULL;
        }
        cf__free(levels);
        cf__free(start);
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    }
    start[0] = 0;
    memcpy(levels, t->pts, tri(n) * h * sizeof *levels);
    for (int l = 1; l <= n; l++) {
        start[l] = start[l - 1] + tri(n - l + 1) * h;
        step(levels + start[l - 1], n - l + 1, b, h, levels + start[l]);
    }
    /* c_ijk of the sub-triangles: b^i_0jk, b^j_i0k, b^k_ij0 */
    for (int i = n; i >= 0; i--)
        for (int j = n - i; j >= 0; j--) {
            int k = n - i - j;
            size_t f = idx(n, i, j);
            memcpy(out[0]->pts + f * h,
                   levels + start[i] + idx(n - i, 0, j) * h,
                   h * sizeof(double));
            memcpy(out[1]->pts + f * h,
                   levels + start[j] + idx(n - j, i, 0) * h,
                   h * sizeof(double));
            memcpy(out[2]->pts + f * h,
                   levels + start[k] + idx(n - k, i, j) * h,
                   h * sizeof(double));
        }
    cf__free(levels);
    cf__free(start);
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_triangle_elevate(const cf_bezier_triangle_t *t,
                           cf_bezier_triangle_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bezier_triangle_t *e;
    int n;
    size_t h;
    if (out == NULL || t == NULL) {
        if (out != NULL)
            *out = NULL;
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "patch or out is NULL");
    }
    *out = NULL;
    n = t->n;
    if (n + 1 > CF_BEZIER_TRIANGLE_MAX_DEGREE)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "degree %d: elevation would pass %d", n,
                         CF_BEZIER_TRIANGLE_MAX_DEGREE);
    e = alloc(t->dim, n + 1, t->rational);
    if (e == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    h = t->hdim;
    for (int i = n + 1; i >= 0; i--)
        for (int j = n + 1 - i; j >= 0; j--) {
            int k = n + 1 - i - j;
            double *d = e->pts + idx(n + 1, i, j) * h;
            for (size_t c = 0; c < h; c++) {
                double s = 0.0;
                if (i > 0)
                    s += i * t->pts[idx(n, i - 1, j) * h + c];
                if (j > 0)
                    s += j * t->pts[idx(n, i, j - 1) * h + c];
                if (k > 0)
                    s += k * t->pts[idx(n, i, j) * h + c];
                d[c] = s / (n + 1);
            }
        }
    *out = e;
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_triangle_boundary(const cf_bezier_triangle_t *t, int edge,
                            cf_bezier_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    double *pts;
    size_t h;
    int n;
    cf_status_t st;
    if (out == NULL || t == NULL) {
        if (out != NULL)
            *out = NULL;
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "patch or out is NULL");
    }
    *out = NULL;
    if (edge < 0 || edge > 2)
        return cf__error(diag, CF_STATUS_INVALID_ARG, edge,
                         "edge %d: the edges are 0 (w = 0), 1 (u = 0) and "
                         "2 (v = 0)", edge);
    n = t->n;
    h = t->hdim;
    pts = cf__alloc_array((size_t)n + 1, h * sizeof *pts);
    if (pts == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    for (int s = 0; s <= n; s++) {
        int i = edge == 0 ? n - s : edge == 1 ? 0 : s;
        int j = edge == 0 ? s : edge == 1 ? n - s : 0;
        memcpy(pts + (size_t)s * h, t->pts + idx(n, i, j) * h,
               h * sizeof *pts);
    }
    st = t->rational
             ? cf_bezier_create_homogeneous(t->dim, n, pts, out, diag)
             : cf_bezier_create(t->dim, n, pts, NULL, out, diag);
    cf__free(pts);
    return st;
}
