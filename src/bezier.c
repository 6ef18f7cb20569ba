/*
** Bézier curves in R^N, polynomial and rational: construction, queries,
** subdivision, reversal, affine maps, degree
** elevation and the derivative as a curve.  Evaluation is in
** bezier-eval.c, tangents and curvature in bezier-geometry.c.
**
** Rational curves are stored homogeneously, (w x, w); every construction
** below runs on the stored points unchanged and divides by w only when a
** Cartesian point is returned.
*/
#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <string.h>

#include "bezier-private.h"
#include "numtext-private.h"

#define MAXN CF_BEZIER_MAX_DEGREE

/* ---- allocation ----------------------------------------------------------- */

cf_bezier_t *
cf__bezier_new(size_t dim, int degree, bool rational)
{
    size_t hdim, npts, bytes;
    cf_bezier_t *c;

    if (dim == 0 || degree < 0 || dim > SIZE_MAX / 16)
        return NULL;
    hdim = dim + (rational ? 1u : 0u);
    npts = (size_t)degree + 1;
    if (hdim > (SIZE_MAX - sizeof *c) / sizeof(double) / npts)
        return NULL;
    bytes = sizeof *c + npts * hdim * sizeof(double);
    c = cf__malloc(bytes);
    if (c == NULL)
        return NULL;
    c->dim = dim;
    c->hdim = hdim;
    c->degree = degree;
    c->rational = rational;
    c->block = NULL;
    return c;
}

/* The shared block of cf__bezier_new_many: the count of its live curves,
** then the curves one stride apart (a stride is a multiple of the
** header's alignment, so every header is aligned). */
struct cf__bezier_block {
    atomic_size_t live;
};

#define BLOCK_HEAD                                                         \
    ((sizeof(cf__bezier_block_t) + _Alignof(cf_bezier_t) - 1)             \
     / _Alignof(cf_bezier_t) * _Alignof(cf_bezier_t))

bool
cf__bezier_new_many(size_t n, size_t dim, int degree, bool rational,
                    cf_bezier_t **out, size_t *stride)
{
    size_t hdim, npts, bytes, al = _Alignof(cf_bezier_t);
    cf__bezier_block_t *b;
    char *base;
    if (n == 0 || dim == 0 || degree < 0 || dim > SIZE_MAX / 16)
        return false;
    hdim = dim + (rational ? 1u : 0u);
    npts = (size_t)degree + 1;
    if (hdim > (SIZE_MAX / 2 - sizeof(cf_bezier_t)) / sizeof(double) / npts)
        return false;
    bytes = (sizeof(cf_bezier_t) + npts * hdim * sizeof(double) + al - 1)
            / al * al;
    if (n > (SIZE_MAX - BLOCK_HEAD) / bytes)
        return false;
    b = cf__malloc(BLOCK_HEAD + n * bytes);
    if (b == NULL)
        return false;
    atomic_init(&b->live, n);
    base = (char *)b + BLOCK_HEAD;
    for (size_t i = 0; i < n; i++) {
        cf_bezier_t *c = (cf_bezier_t *)(void *)(base + i * bytes);
        c->dim = dim;
        c->hdim = hdim;
        c->degree = degree;
        c->rational = rational;
        c->block = b;
        out[i] = c;
    }
    *stride = bytes / sizeof(double);
    return true;
}

/* k curves of block b are gone; the last frees it. */
static void
block_release(cf__bezier_block_t *b, size_t k)
{
    if (atomic_fetch_sub_explicit(&b->live, k, memory_order_acq_rel) == k)
        cf__free(b);
}

/* A curve whose stored points are copied from hpts ((degree + 1) * hdim
** doubles, homogeneous when rational), no checks of the values.  Reports
** NO_MEMORY only. */
static cf_status_t
from_hpoints(size_t dim, int degree, bool rational, const double *hpts,
             cf_bezier_t **out, cf_diag_t *diag)
{
    cf_bezier_t *c = cf__bezier_new(dim, degree, rational);
    if (c == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory for a curve of degree %d in R^%zu",
                         degree, dim);
    memcpy(c->pts, hpts, ((size_t)degree + 1) * c->hdim * sizeof(double));
    *out = c;
    return CF_STATUS_OK;
}

static cf_status_t
no_memory(cf_diag_t *diag, const char *what)
{
    return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory (%s)",
                     what);
}

static cf_status_t
check_common(size_t dim, int degree, const void *pts, cf_bezier_t **out,
             cf_diag_t *diag)
{
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "the output pointer is NULL");
    *out = NULL;
    if (dim < 1)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "dimension is 0; it must be at least 1");
    if (degree < 0 || degree > MAXN)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "degree %d is outside 0..%d", degree, MAXN);
    if (pts == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "the point array is NULL");
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_create(size_t dim, int degree, const double *points,
                 const double *weights, cf_bezier_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = check_common(dim, degree, points, out, diag);
    size_t np;
    cf_bezier_t *c;

    if (st != CF_STATUS_OK)
        return st;
    np = (size_t)degree + 1;
    st = cf__check_finite_points(points, np, dim, dim, "point", diag);
    if (st != CF_STATUS_OK)
        return st;
    if (weights != NULL) {
        st = cf__check_weights(weights, np, diag);
        if (st != CF_STATUS_OK)
            return st;
    }
    c = cf__bezier_new(dim, degree, weights != NULL);
    if (c == NULL)
        return no_memory(diag, "curve");
    for (size_t i = 0; i < np; i++) {
        double w = weights != NULL ? weights[i] : 1.0;
        for (size_t k = 0; k < dim; k++)
            c->pts[i * c->hdim + k] = w * points[i * dim + k];
        if (weights != NULL)
            c->pts[i * c->hdim + dim] = w;
    }
    /* w * x may overflow although both are finite */
    st = cf__check_finite_points(c->pts, np, c->hdim, c->hdim,
                                 "weighted point", diag);
    if (st != CF_STATUS_OK) {
        cf__free(c);
        return st;
    }
    *out = c;
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_create_homogeneous(size_t dim, int degree, const double *hpoints,
                             cf_bezier_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = check_common(dim, degree, hpoints, out, diag);
    size_t np;

    if (st != CF_STATUS_OK)
        return st;
    if (dim > SIZE_MAX / 16)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "dimension %zu is too large", dim);
    np = (size_t)degree + 1;
    st = cf__check_finite_points(hpoints, np, dim + 1, dim + 1, "point",
                                 diag);
    if (st != CF_STATUS_OK)
        return st;
    for (size_t i = 0; i < np; i++) {
        double w = hpoints[i * (dim + 1) + dim];
        if (!(w > 0.0))
            return cf__error(diag, CF_STATUS_BAD_WEIGHT, (long)i,
                             "weight w_%zu is %s; weights must be finite "
                             "and positive", i, CF__NUM(w));
    }
    return from_hpoints(dim, degree, true, hpoints, out, diag);
}

cf_status_t
cf_bezier_copy(const cf_bezier_t *c, cf_bezier_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    if (out == NULL || c == NULL) {
        if (out != NULL)
            *out = NULL;
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "the curve or the output pointer is NULL");
    }
    *out = NULL;
    return from_hpoints(c->dim, c->degree, c->rational, c->pts, out, diag);
}

void
cf_bezier_destroy(cf_bezier_t *c)
{
    if (c != NULL && c->block != NULL)
        block_release(c->block, 1);
    else
        cf__free(c);
}

/* ---- queries ------------------------------------------------------------- */

size_t
cf_bezier_dim(const cf_bezier_t *c)
{
    return c != NULL ? c->dim : 0;
}

int
cf_bezier_degree(const cf_bezier_t *c)
{
    return c != NULL ? c->degree : 0;
}

bool
cf_bezier_is_rational(const cf_bezier_t *c)
{
    return c != NULL && c->rational;
}

const double *
cf_bezier_hpoints(const cf_bezier_t *c)
{
    return c != NULL ? c->pts : NULL;
}

void
cf_bezier_get_points(const cf_bezier_t *c, double *out)
{
    if (c == NULL || out == NULL)
        return;
    for (int i = 0; i <= c->degree; i++) {
        const double *p = c->pts + (size_t)i * c->hdim;
        double w = c->rational ? p[c->dim] : 1.0;
        for (size_t k = 0; k < c->dim; k++)
            out[(size_t)i * c->dim + k] = c->rational ? p[k] / w : p[k];
    }
}

void
cf_bezier_get_weights(const cf_bezier_t *c, double *out)
{
    if (c == NULL || out == NULL)
        return;
    for (int i = 0; i <= c->degree; i++)
        out[i] = c->rational ? c->pts[(size_t)i * c->hdim + c->dim] : 1.0;
}

double
cf__bezier_size(const cf_bezier_t *c)
{
    double m = 0.0;
    for (int i = 0; i <= c->degree; i++) {
        const double *p = c->pts + (size_t)i * c->hdim;
        double w = c->rational ? p[c->dim] : 1.0;
        for (size_t k = 0; k < c->dim; k++)
            m = fmax(m, fabs(p[k] / w));
    }
    return m;
}

/* ---- subdivision ---------------------------------------------------------- */

static cf_status_t
check_curve(const cf_bezier_t *c, cf_diag_t *diag)
{
    if (c == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "the curve is NULL");
    return CF_STATUS_OK;
}

/* The common start of an operation returning a curve: out is set to NULL
** first, so that a failed call leaves nothing behind. */
static cf_status_t
begin_op(const cf_bezier_t *c, cf_bezier_t **out, cf_diag_t *diag)
{
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "the output pointer is NULL");
    *out = NULL;
    return check_curve(c, diag);
}

static cf_status_t
check_open_param(double t, const char *what, cf_diag_t *diag)
{
    if (!isfinite(t))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "%s %s is not finite", what, CF__NUM(t));
    if (!(t > 0.0 && t < 1.0))
        return cf__error(diag, CF_STATUS_DOMAIN, -1,
                         "%s %s is outside the open interval (0, 1)", what,
                         CF__NUM(t));
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_split(const cf_bezier_t *c, double t, cf_bezier_t **left,
                cf_bezier_t **right, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bezier_t *l = NULL, *r = NULL;
    cf_status_t st;
    if (left != NULL)
        *left = NULL;
    if (right != NULL)
        *right = NULL;
    st = check_curve(c, diag);
    if (st != CF_STATUS_OK)
        return st;
    st = check_open_param(t, "split parameter", diag);
    if (st != CF_STATUS_OK)
        return st;
    if (left != NULL) {
        l = cf__bezier_new(c->dim, c->degree, c->rational);
        if (l == NULL)
            return no_memory(diag, "left half of a split");
    }
    if (right != NULL) {
        r = cf__bezier_new(c->dim, c->degree, c->rational);
        if (r == NULL) {
            cf__free(l);
            return no_memory(diag, "right half of a split");
        }
    }
    cf__bp_split(c->pts, c->hdim, c->degree, t, l != NULL ? l->pts : NULL,
                 r != NULL ? r->pts : NULL);
    if (left != NULL)
        *left = l;
    if (right != NULL)
        *right = r;
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_split_into(const cf_bezier_t *c, double t, double *left_hpoints,
                     double *right_hpoints)
{
    if (c == NULL || left_hpoints == NULL || right_hpoints == NULL ||
        left_hpoints == right_hpoints)
        return CF_STATUS_INVALID_ARG;
    if (!isfinite(t))
        return CF_STATUS_NOT_FINITE;
    if (!(t > 0.0 && t < 1.0))
        return CF_STATUS_DOMAIN;
    cf__bp_split(c->pts, c->hdim, c->degree, t, left_hpoints, right_hpoints);
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_segment(const cf_bezier_t *c, double a, double b,
                  cf_bezier_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bezier_t *s;
    cf_status_t st;
    st = begin_op(c, out, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (!isfinite(a) || !isfinite(b))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "segment [%s, %s] has a bound that is not finite",
                         CF__NUM(a), CF__NUM(b));
    if (!(a >= 0.0 && a < b && b <= 1.0))
        return cf__error(diag, CF_STATUS_DOMAIN, -1,
                         "segment [%s, %s] does not satisfy "
                         "0 <= a < b <= 1", CF__NUM(a), CF__NUM(b));
    s = cf__bezier_new(c->dim, c->degree, c->rational);
    if (s == NULL)
        return no_memory(diag, "segment");
    memcpy(s->pts, c->pts,
           ((size_t)c->degree + 1) * c->hdim * sizeof(double));
    if (b < 1.0)
        cf__bp_split(s->pts, s->hdim, s->degree, b, s->pts, NULL);
    if (a > 0.0)
        cf__bp_split(s->pts, s->hdim, s->degree, a / b, NULL, s->pts);
    *out = s;
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_reverse(const cf_bezier_t *c, cf_bezier_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bezier_t *r;
    cf_status_t st;
    st = begin_op(c, out, diag);
    if (st != CF_STATUS_OK)
        return st;
    r = cf__bezier_new(c->dim, c->degree, c->rational);
    if (r == NULL)
        return no_memory(diag, "reversed curve");
    for (int i = 0; i <= c->degree; i++)
        memcpy(r->pts + (size_t)i * c->hdim,
               c->pts + (size_t)(c->degree - i) * c->hdim,
               c->hdim * sizeof(double));
    *out = r;
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_transform(const cf_bezier_t *c, const double *A, const double *b,
                    cf_bezier_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bezier_t *r;
    cf_status_t st;
    size_t dim;
    st = begin_op(c, out, diag);
    if (st != CF_STATUS_OK)
        return st;
    dim = c->dim;
    st = cf__check_affine(A, b, dim, diag);
    if (st != CF_STATUS_OK)
        return st;
    r = cf__bezier_new(dim, c->degree, c->rational);
    if (r == NULL)
        return no_memory(diag, "transformed curve");
    cf__affine_points(A, b, dim, c->rational, c->pts, (size_t)c->degree + 1,
                      c->hdim, r->pts);
    st = cf__check_finite_points(r->pts, (size_t)c->degree + 1, r->hdim,
                                 r->hdim, "transformed point", diag);
    if (st != CF_STATUS_OK) {
        cf__free(r);
        return st;
    }
    *out = r;
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_elevate(const cf_bezier_t *c, int r, cf_bezier_t **out,
                  cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bezier_t *e;
    cf_status_t st;
    st = begin_op(c, out, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (r < 0 || r > MAXN - c->degree)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "elevating degree %d by %d leaves 0..%d",
                         c->degree, r, MAXN);
    e = cf__bezier_new(c->dim, c->degree + r, c->rational);
    if (e == NULL)
        return no_memory(diag, "elevated curve");
    memcpy(e->pts, c->pts,
           ((size_t)c->degree + 1) * c->hdim * sizeof(double));
    cf__bp_elevate(e->pts, e->hdim, c->degree, r);
    *out = e;
    return CF_STATUS_OK;
}

/* ---- the derivative as a curve ------------------------------------------- */

/* (A/w)' = (A' w - A w') / w^2, as a rational curve of degree 2n. */
static cf_status_t
rational_derivative(const cf_bezier_t *c, cf_bezier_t **out, cf_diag_t *diag)
{
    int n = c->degree;
    size_t h = c->hdim, dim = c->dim;
    cf_bezier_t *d;
    double *diff;

    if (2 * n > MAXN)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "the derivative of a rational curve of degree %d "
                         "has degree %d > %d", n, 2 * n, MAXN);
    d = cf__bezier_new(dim, 2 * n, true);
    if (d == NULL)
        return no_memory(diag, "derivative");
    if (n == 0) {
        memset(d->pts, 0, h * sizeof(double));
        d->pts[dim] = c->pts[dim] * c->pts[dim];
        *out = d;
        return CF_STATUS_OK;
    }
    /* hodograph of the homogeneous points: n (P_{i+1} - P_i), degree n-1 */
    diff = cf__alloc_array((size_t)n * h, sizeof *diff);
    if (diff == NULL) {
        cf__free(d);
        return no_memory(diag, "derivative");
    }
    for (int i = 0; i < n; i++)
        for (size_t k = 0; k < h; k++)
            diff[(size_t)i * h + k] =
                (double)n * (c->pts[(size_t)(i + 1) * h + k] -
                             c->pts[(size_t)i * h + k]);
    /* numerator, degree 2n - 1, stored at stride h in d->pts */
    for (size_t k = 0; k < dim; k++) {
        cf__bp_mul(diff + k, n - 1, h, c->pts + dim, n, h, d->pts + k, h,
                   1.0, false);
        cf__bp_mul(c->pts + k, n, h, diff + dim, n - 1, h, d->pts + k, h,
                   -1.0, true);
    }
    for (int i = 0; i < 2 * n; i++)
        d->pts[(size_t)i * h + dim] = 1.0;   /* any value: the weights are overwritten below */
    cf__bp_elevate(d->pts, h, 2 * n - 1, 1);
    cf__bp_mul(c->pts + dim, n, h, c->pts + dim, n, h, d->pts + dim, h, 1.0,
               false);
    cf__free(diff);
    *out = d;
    return CF_STATUS_OK;
}

/* A derivative's control points are differences times the degree: they
** overflow for coordinates near DBL_MAX.  Refuse such a result (and free
** it) rather than return infinite points. */
static cf_status_t
check_derivative(cf_bezier_t *d, cf_diag_t *diag)
{
    for (int i = 0; i <= d->degree; i++)
        for (size_t k = 0; k < d->hdim; k++) {
            double v = d->pts[(size_t)i * d->hdim + k];
            if (!isfinite(v)) {
                cf__free(d);
                return cf__error(diag, CF_STATUS_NOT_FINITE, i,
                                 "control point %d overflows "
                                 "(coordinate %zu is %s)", i, k + 1,
                                 CF__NUM(v));
            }
        }
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_derivative(const cf_bezier_t *c, int k, cf_bezier_t **out,
                     cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bezier_t *cur;
    cf_status_t st;
    st = begin_op(c, out, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (k < 0)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "derivative order %d is negative", k);
    if (!c->rational) {
        int n = c->degree, m = k > n ? 0 : n - k;
        cf_bezier_t *d = cf__bezier_new(c->dim, m, false);
        size_t dim = c->dim;
        if (d == NULL)
            return no_memory(diag, "derivative");
        if (k > n) {
            memset(d->pts, 0, dim * sizeof(double));
        } else {
            /* hodograph k times, in place: level j has n - j + 1 points */
            double *tmp = cf__alloc_array(((size_t)n + 1) * dim,
                                          sizeof *tmp);
            if (tmp == NULL) {
                cf__free(d);
                return no_memory(diag, "derivative");
            }
            memcpy(tmp, c->pts, ((size_t)n + 1) * dim * sizeof *tmp);
            for (int j = 0; j < k; j++)
                for (int i = 0; i < n - j; i++)
                    for (size_t q = 0; q < dim; q++)
                        tmp[(size_t)i * dim + q] =
                            (double)(n - j) *
                            (tmp[(size_t)(i + 1) * dim + q] -
                             tmp[(size_t)i * dim + q]);
            memcpy(d->pts, tmp, ((size_t)m + 1) * dim * sizeof *tmp);
            cf__free(tmp);
        }
        st = check_derivative(d, diag);
        if (st != CF_STATUS_OK)
            return st;
        *out = d;
        return CF_STATUS_OK;
    }
    {
        /* each derivative doubles the degree */
        long deg = c->degree;
        for (int j = 0; j < k && deg > 0; j++) {
            deg *= 2;
            if (deg > MAXN)
                return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                                 "derivative %d of a rational curve of "
                                 "degree %d has degree %d * 2^%d > %d", k,
                                 c->degree, c->degree, k, MAXN);
        }
    }
    st = cf_bezier_copy(c, &cur, diag);
    if (st != CF_STATUS_OK)
        return st;
    for (int j = 0; j < k; j++) {
        cf_bezier_t *next = NULL;
        st = rational_derivative(cur, &next, diag);
        cf__free(cur);
        if (st != CF_STATUS_OK)
            return st;
        cur = next;
    }
    st = check_derivative(cur, diag);
    if (st != CF_STATUS_OK)
        return st;
    *out = cur;
    return CF_STATUS_OK;
}

/* ---- lists ----------------------------------------------------------------- */

cf_bezier_list_t *
cf__bezier_list_new(size_t count, bool with_params)
{
    cf_bezier_list_t *l = cf__calloc(1, sizeof *l);
    if (l == NULL)
        return NULL;
    l->count = count;
    l->items = cf__calloc(count > 0 ? count : 1, sizeof *l->items);
    if (l->items == NULL)
        goto fail;
    if (with_params) {
        l->t0 = cf__calloc(count > 0 ? count : 1, sizeof *l->t0);
        l->t1 = cf__calloc(count > 0 ? count : 1, sizeof *l->t1);
        if (l->t0 == NULL || l->t1 == NULL)
            goto fail;
    }
    return l;
fail:
    cf__free(l->items);
    cf__free(l->t0);
    cf__free(l->t1);
    cf__free(l);
    return NULL;
}

void
cf_bezier_list_destroy(cf_bezier_list_t *list)
{
    if (list == NULL)
        return;
    if (list->items != NULL) {
        /* the curves of one block side by side go in one release */
        cf__bezier_block_t *run = NULL;
        size_t k = 0;
        for (size_t i = 0; i < list->count; i++) {
            cf_bezier_t *c = list->items[i];
            if (c == NULL)
                continue;
            if (c->block != run && run != NULL) {
                block_release(run, k);
                k = 0;
            }
            run = c->block;
            if (run != NULL)
                k++;
            else
                cf__free(c);
        }
        if (run != NULL)
            block_release(run, k);
    }
    cf__free(list->items);
    cf__free(list->t0);
    cf__free(list->t1);
    cf__free(list);
}
