/*
** B-spline and NURBS curves: allocation and the span accelerators,
** construction, queries and the figure helpers.  Evaluation is in
** bspline-eval.c, derivatives and the de Boor net in bspline-deriv.c,
** closed and Coons curves in bspline-closed.c, NURBS arcs with the conics
** in conic.c.
*/
#include <math.h>
#include <string.h>

#include "bspline-private.h"
#include "numtext-private.h"


/* ---- allocation and the accelerators ------------------------------------ */

static size_t
grid_cells(size_t count, int p)
{
    return 4 * (count - (size_t)p) + 4;
}

cf_bspline_t *
cf__bspline_alloc(size_t dim, bool rational, int p, size_t count)
{
    size_t hdim = dim + (rational ? 1 : 0);
    size_t nknots = count + (size_t)p + 1, ngrid, doubles;
    size_t head = (sizeof(cf_bspline_t) + sizeof(double) - 1)
                  / sizeof(double);
    cf_bspline_t *c;
    char *base;
    if (count < (size_t)p + 1 || count > CF__BSPLINE_MAX_COUNT || hdim > CF__BSPLINE_MAX_COUNT)
        return NULL;
    ngrid = grid_cells(count, p);
    /* knots, points, reciprocals, grid (as doubles, rounded up) */
    doubles = head + nknots + count * hdim + (size_t)p * nknots + ngrid
              + (ngrid * sizeof(uint32_t) + sizeof(double) - 1)
                / sizeof(double);
    base = cf__alloc_array(doubles, sizeof(double));
    if (base == NULL)
        return NULL;
    c = (cf_bspline_t *)(void *)base;
    memset(c, 0, sizeof *c);
    c->dim = dim;
    c->hdim = hdim;
    c->p = p;
    c->rational = rational;
    c->count = count;
    c->nknots = nknots;
    c->U = (double *)(void *)base + head;
    c->P = c->U + nknots;
    c->rk = c->P + count * hdim;
    c->gsplit = c->rk + (size_t)p * nknots;
    c->grid = (uint32_t *)(void *)(c->gsplit + ngrid);
    c->ngrid = ngrid;
    return c;
}

void
cf__bspline_finish(cf_bspline_t *c)
{
    const double *U = c->U;
    size_t p = (size_t)c->p, n = c->count - 1, k;
    c->a = U[p];
    c->b = U[n + 1];
    k = p;
    while (!(U[k + 1] > U[k]))
        k++;
    c->first_span = k;
    k = n;
    while (!(U[k] < U[n + 1]))
        k--;
    c->last_span = k;
    atomic_init(&c->accel, 0);
}

static void
build_accel(cf_bspline_t *c)
{
    const double *U = c->U;
    size_t p = (size_t)c->p, nk = c->nknots, k, G = c->ngrid, maxw = 0;
    double h;
    for (size_t j = 1; j <= p; j++) {
        double *r = c->rk + (j - 1) * nk;
        for (size_t a = 0; a + j < nk; a++) {
            /* knots are sorted: d >= 0, and 1/0 = inf becomes 0 */
            double d = U[a + j] - U[a], q = 1.0 / d;
            r[a] = d > 0.0 ? q : 0.0;
        }
    }
    /* grid[g] = span of a + (g - 1/2) h; the window of cell g ends at the
    ** span of a + (g + 2) h (the computed cell may be off by one where
    ** rounding meets a boundary); the widest window fixes the steps */
    h = (c->b - c->a) / (double)G;
    c->ginv = (double)G / (c->b - c->a);
    k = c->first_span;
    for (size_t g = 0; g < G; g++) {
        double x = c->a + ((double)g - 0.5) * h;
        while (k < c->last_span && U[k + 1] <= x)
            k++;
        c->grid[g] = (uint32_t)k;
    }
    k = c->first_span;
    for (size_t g = 0; g < G; g++) {
        double x = c->a + ((double)g + 2.0) * h;
        while (k < c->last_span && U[k + 1] <= x)
            k++;
        if (k - c->grid[g] > maxw)
            maxw = k - c->grid[g];
    }
    c->gsteps = 0;
    while (((size_t)1 << c->gsteps) <= maxw)
        c->gsteps++;
    /* exact cells: cell_of is monotone in u, so an interior break point
    ** (a knot strictly inside the domain, multiplicity 1 required here)
    ** in an earlier cell lies below every u of cell g, one in a later
    ** cell above it; only a break point in cell g itself is compared with
    ** u, and at most one may fall in each cell */
    c->splitok = true;
    {
        size_t g = 0, kk = c->first_span;
        for (size_t j = c->first_span + 1; j <= c->last_span; j++) {
            size_t gj;
            if (U[j] == U[j - 1]) {
                c->splitok = false;
                break;
            }
            gj = cf__bspline_cell(c, U[j]);
            if (gj < g) {   /* a second break point in cell gj */
                c->splitok = false;
                break;
            }
            for (; g < gj; g++) {
                c->grid[g] = (uint32_t)kk;
                c->gsplit[g] = INFINITY;
            }
            c->grid[gj] = (uint32_t)kk;
            c->gsplit[gj] = U[j];
            g = gj + 1;
            kk = j;
        }
        for (; c->splitok && g < G; g++) {
            c->grid[g] = (uint32_t)kk;
            c->gsplit[g] = INFINITY;
        }
    }
    if (!c->splitok) {
        /* back to the windows of the general search */
        k = c->first_span;
        for (size_t g = 0; g < G; g++) {
            double x = c->a + ((double)g - 0.5) * h;
            while (k < c->last_span && U[k + 1] <= x)
                k++;
            c->grid[g] = (uint32_t)k;
        }
    }
}

bool
cf__bspline_accel(const cf_bspline_t *cc)
{
    /* the object is logically const: only the lazily filled accelerator
    ** part of its block is written, once, under the flag */
    cf_bspline_t *c = (cf_bspline_t *)cc;
    int expected = 0;
    int st = atomic_load_explicit(&c->accel, memory_order_acquire);
    if (st == 2)
        return true;
    if (st == 0 && atomic_compare_exchange_strong_explicit(
                       &c->accel, &expected, 1, memory_order_acq_rel,
                       memory_order_acquire)) {
        build_accel(c);
        atomic_store_explicit(&c->accel, 2, memory_order_release);
        return true;
    }
    return atomic_load_explicit(&c->accel, memory_order_acquire) == 2;
}

cf_status_t
cf__bspline_check_param(const cf_bspline_t *c, double u, cf_diag_t *diag)
{
    if (!isfinite(u))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "parameter is %s", CF__NUM(u));
    if (u < c->a || u > c->b)
        return cf__error(diag, CF_STATUS_DOMAIN, -1,
                         "parameter %s is outside the domain [%s, %s]",
                         CF__NUM(u), CF__NUM(c->a), CF__NUM(c->b));
    return CF_STATUS_OK;
}

cf_status_t
cf__bspline_no_memory(cf_diag_t *diag)
{
    return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
}

cf_status_t
cf__bspline_check_in(const cf_bspline_t *c, cf_bspline_t **out, cf_diag_t *diag)
{
    if (out != NULL)
        *out = NULL;
    if (c == NULL || out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "NULL argument");
    return CF_STATUS_OK;
}

/* ---- construction ------------------------------------------------------- */

static cf_status_t
check_common(size_t dim, int degree, const double *knots, size_t nknots,
             const double *pts, size_t count, cf_bspline_t **out,
             cf_diag_t *diag)
{
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "output pointer is NULL");
    *out = NULL;
    if (dim < 1)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "dimension must be at least 1");
    if (pts == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "points are NULL");
    if (count > CF__BSPLINE_MAX_COUNT || dim > CF__BSPLINE_MAX_COUNT)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "%zu points of dimension %zu are too many",
                         count, dim);
    return cf_knots_validate(degree, count, knots, nknots, diag);
}

cf_status_t
cf_bspline_create(size_t dim, int degree, const double *knots, size_t nknots,
                  const double *points, size_t count, const double *weights,
                  cf_bspline_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = check_common(dim, degree, knots, nknots, points, count,
                                  out, diag);
    cf_bspline_t *c;
    if (st != CF_STATUS_OK)
        return st;
    st = cf__check_finite_points(points, count, dim, dim, "point", diag);
    if (st == CF_STATUS_OK && weights != NULL)
        st = cf__check_weights(weights, count, diag);
    if (st != CF_STATUS_OK)
        return st;
    c = cf__bspline_alloc(dim, weights != NULL, degree, count);
    if (c == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory");
    memcpy(c->U, knots, nknots * sizeof *knots);
    for (size_t i = 0; i < count; i++) {
        double w = weights != NULL ? weights[i] : 1.0;
        for (size_t d = 0; d < dim; d++)
            c->P[i * c->hdim + d] = w * points[i * dim + d];
        if (weights != NULL)
            c->P[i * c->hdim + dim] = w;
    }
    cf__bspline_finish(c);
    *out = c;
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_create_homogeneous(size_t dim, int degree, const double *knots,
                              size_t nknots, const double *hpoints,
                              size_t count, cf_bspline_t **out,
                              cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = check_common(dim, degree, knots, nknots, hpoints, count,
                                  out, diag);
    cf_bspline_t *c;
    if (st != CF_STATUS_OK)
        return st;
    st = cf__check_finite_points(hpoints, count, dim + 1, dim + 1, "point",
                                 diag);
    if (st != CF_STATUS_OK)
        return st;
    for (size_t i = 0; i < count; i++) {
        double w = hpoints[i * (dim + 1) + dim];
        if (!(w > 0.0))
            return cf__error(diag, CF_STATUS_BAD_WEIGHT, (long)i,
                             "weight w_%zu is %s; weights must be finite and "
                             "positive", i, CF__NUM(w));
    }
    c = cf__bspline_alloc(dim, true, degree, count);
    if (c == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory");
    memcpy(c->U, knots, nknots * sizeof *knots);
    memcpy(c->P, hpoints, count * (dim + 1) * sizeof *hpoints);
    cf__bspline_finish(c);
    *out = c;
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_create_clamped(size_t dim, int degree, const double *points,
                          size_t count, const double *weights,
                          cf_bspline_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    double *U;
    cf_status_t st;
    size_t nk;
    if (out != NULL)
        *out = NULL;
    if (degree < 0 || degree > CF_BSPLINE_MAX_DEGREE)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "degree %d is outside 0..%d", degree,
                         CF_BSPLINE_MAX_DEGREE);
    if (count < (size_t)degree + 1 || count > CF__BSPLINE_MAX_COUNT)
        return cf__error(diag, CF_STATUS_TOO_FEW_POINTS, -1,
                         "degree %d needs at least %d points, %zu "
                         "given", degree, degree + 1, count);
    nk = count + (size_t)degree + 1;
    U = cf__alloc_array(nk, sizeof *U);
    if (U == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory");
    st = cf_knots_clamped_uniform(degree, count, 0.0, 1.0, U, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_create(dim, degree, U, nk, points, count, weights,
                               out, diag);
    cf__free(U);
    return st;
}

cf_status_t
cf_bspline_copy(const cf_bspline_t *c, cf_bspline_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bspline_t *r;
    if (out == NULL || c == NULL) {
        if (out != NULL)
            *out = NULL;
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "copy of NULL");
    }
    r = cf__bspline_alloc(c->dim, c->rational, c->p, c->count);
    if (r == NULL) {
        *out = NULL;
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory");
    }
    memcpy(r->U, c->U, c->nknots * sizeof *c->U);
    memcpy(r->P, c->P, c->count * c->hdim * sizeof *c->P);
    cf__bspline_finish(r);
    *out = r;
    return CF_STATUS_OK;
}

void
cf_bspline_destroy(cf_bspline_t *c)
{
    cf__free(c);
}

/* ---- queries ------------------------------------------------------------ */

size_t
cf_bspline_dim(const cf_bspline_t *c)
{
    return c ? c->dim : 0;
}

int
cf_bspline_degree(const cf_bspline_t *c)
{
    return c ? c->p : 0;
}

size_t
cf_bspline_count(const cf_bspline_t *c)
{
    return c ? c->count : 0;
}

size_t
cf_bspline_nknots(const cf_bspline_t *c)
{
    return c ? c->nknots : 0;
}

bool
cf_bspline_is_rational(const cf_bspline_t *c)
{
    return c ? c->rational : false;
}

const double *
cf_bspline_knots(const cf_bspline_t *c)
{
    return c ? c->U : NULL;
}

const double *
cf_bspline_hpoints(const cf_bspline_t *c)
{
    return c ? c->P : NULL;
}

void
cf_bspline_get_points(const cf_bspline_t *c, double *out)
{
    if (c == NULL || out == NULL)
        return;
    for (size_t i = 0; i < c->count; i++) {
        const double *h = c->P + i * c->hdim;
        double w = c->rational ? h[c->dim] : 1.0;
        for (size_t d = 0; d < c->dim; d++)
            out[i * c->dim + d] = c->rational ? h[d] / w : h[d];
    }
}

void
cf_bspline_get_weights(const cf_bspline_t *c, double *out)
{
    if (c == NULL || out == NULL)
        return;
    for (size_t i = 0; i < c->count; i++)
        out[i] = c->rational ? c->P[i * c->hdim + c->dim] : 1.0;
}

void
cf_bspline_domain(const cf_bspline_t *c, double *a, double *b)
{
    if (a != NULL)
        *a = c ? c->a : 0.0;
    if (b != NULL)
        *b = c ? c->b : 0.0;
}

cf_knot_kind_t
cf_bspline_knot_kind(const cf_bspline_t *c)
{
    if (c == NULL)
        return CF_KNOTS_OPEN;
    return cf_knots_classify(c->p, c->U, c->nknots);
}

/* ---- figure helpers ----------------------------------------------------- */

cf_status_t
cf_bspline_support(const cf_bspline_t *c, size_t i, double *lo, double *hi)
{
    if (c == NULL)
        return cf__error(NULL, CF_STATUS_INVALID_ARG, -1, "NULL curve");
    if (i >= c->count)
        return cf__error(NULL, CF_STATUS_INVALID_ARG, (long)i,
                         "point %zu does not exist (%zu points)", i,
                         c->count);
    if (lo != NULL)
        *lo = c->U[i];
    if (hi != NULL)
        *hi = c->U[i + (size_t)c->p + 1];
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_active_points(const cf_bspline_t *c, double u, size_t *first,
                         double *span_lo, double *span_hi)
{
    cf_status_t st;
    size_t k;
    if (c == NULL)
        return cf__error(NULL, CF_STATUS_INVALID_ARG, -1, "NULL curve");
    st = cf__bspline_param(c, &u);
    if (st != CF_STATUS_OK)
        return st;
    k = cf__bspline_span(c, u);
    if (first != NULL)
        *first = k - (size_t)c->p;
    if (span_lo != NULL)
        *span_lo = c->U[k];
    if (span_hi != NULL)
        *span_hi = c->U[k + 1];
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_move_point(const cf_bspline_t *c, size_t i, const double *v,
                      cf_bspline_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st;
    if (out != NULL)
        *out = NULL;
    if (c == NULL || v == NULL || out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "NULL argument");
    if (i >= c->count)
        return cf__error(diag, CF_STATUS_INVALID_ARG, (long)i,
                         "point %zu does not exist (%zu points)", i,
                         c->count);
    st = cf__check_finite_points(v, 1, c->dim, c->dim, "vector", diag);
    if (st != CF_STATUS_OK)
        return st;
    st = cf_bspline_copy(c, out, diag);
    if (st != CF_STATUS_OK)
        return st;
    {
        double *h = (*out)->P + i * c->hdim;
        double w = c->rational ? h[c->dim] : 1.0;
        for (size_t d = 0; d < c->dim; d++)
            h[d] += w * v[d];
    }
    return CF_STATUS_OK;
}
