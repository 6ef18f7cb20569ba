/*
** B-spline and NURBS curves: construction, queries, evaluation (de Boor,
** the fast batch evaluators, derivatives), the de Boor net, closed and
** Coons curves, NURBS arcs and the figure helpers.
*/
#include <math.h>
#include <string.h>

#include "bspline-private.h"

/* Largest count of control points (the span grid stores 32-bit spans). */
#define MAX_COUNT ((size_t)1 << 30)

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
    if (count < (size_t)p + 1 || count > MAX_COUNT || hdim > MAX_COUNT)
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

/* The grid cell of u (the same expression at build and query time). */
static inline size_t
cell_of(const cf_bspline_t *c, double u)
{
    long G = (long)c->ngrid;
    /* a signed conversion (cvttsd2si) and clamps, no branches */
    long g = (long)((u - c->a) * c->ginv);
    g = g < 0 ? 0 : g;
    g = g < G - 1 ? g : G - 1;
    return (size_t)g;
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
            gj = cell_of(c, U[j]);
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

/* Branch-free span search through the grid (the conventions of
** cf_knots_find_span for u in the domain). */
/* With one break point per cell at most: the span below the cell's break
** point, plus one when u has reached it; two independent loads, exact
** (see build_accel). */
CF__INLINE size_t
split_span(const cf_bspline_t *c, double u)
{
    size_t g = cell_of(c, u);
    return c->grid[g] + (size_t)(u >= c->gsplit[g]);
}

CF__INLINE size_t
grid_span(const cf_bspline_t *c, double u)
{
    const double *U = c->U;
    size_t last = c->last_span, k, s;
    long G = (long)c->ngrid, g;
    if (c->splitok)
        return split_span(c, u);
    /* a signed conversion (cvttsd2si) and clamps, no branches */
    g = (long)((u - c->a) * c->ginv);
    g = g < 0 ? 0 : g;
    g = g < G - 1 ? g : G - 1;
    k = c->grid[g];
    for (s = ((size_t)1 << c->gsteps) >> 1; s != 0; s >>= 1) {
        size_t t = k + s, m;
        t = t < last ? t : last;
        /* all ones when U[t] <= u: a select without a branch */
        m = (size_t)0 - (size_t)(U[t] <= u);
        k = (t & m) | (k & ~m);
    }
    return k;
}

size_t
cf__bspline_span(const cf_bspline_t *c, double u)
{
    return cf_knots_find_span(c->p, c->U, c->nknots, u);
}

cf_status_t
cf__bspline_check_param(const cf_bspline_t *c, double u, cf_diag_t *diag)
{
    if (!isfinite(u))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "bspline: parameter is %g", u);
    if (u < c->a || u > c->b)
        return cf__error(diag, CF_STATUS_DOMAIN, -1,
                         "bspline: parameter %.17g is outside the domain "
                         "[%.17g, %.17g]", u, c->a, c->b);
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
                         "bspline: output pointer is NULL");
    *out = NULL;
    if (dim < 1)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "bspline: dimension must be at least 1");
    if (pts == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "bspline: points are NULL");
    if (count > MAX_COUNT || dim > MAX_COUNT)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "bspline: %zu points of dimension %zu are too many",
                         count, dim);
    return cf_knots_validate(degree, count, knots, nknots, diag);
}

cf_status_t
cf_bspline_create(size_t dim, int degree, const double *knots, size_t nknots,
                  const double *points, size_t count, const double *weights,
                  cf_bspline_t **out, cf_diag_t *diag)
{
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
                         "bspline: out of memory");
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
                             "weight %zu is %g; weights must be finite and "
                             "positive", i, w);
    }
    c = cf__bspline_alloc(dim, true, degree, count);
    if (c == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "bspline: out of memory");
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
    double *U;
    cf_status_t st;
    size_t nk;
    if (out != NULL)
        *out = NULL;
    if (degree < 0 || degree > CF_BSPLINE_MAX_DEGREE)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "bspline: degree %d is outside 0..%d", degree,
                         CF_BSPLINE_MAX_DEGREE);
    if (count < (size_t)degree + 1 || count > MAX_COUNT)
        return cf__error(diag, CF_STATUS_TOO_FEW_POINTS, -1,
                         "bspline: degree %d needs at least %d points, %zu "
                         "given", degree, degree + 1, count);
    nk = count + (size_t)degree + 1;
    U = cf__alloc_array(nk, sizeof *U);
    if (U == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "bspline: out of memory");
    st = cf_knots_clamped_uniform(degree, count, 0.0, 1.0, U, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_create(dim, degree, U, nk, points, count, weights,
                               out, diag);
    cf__free(U);
    return st;
}

cf_status_t
cf_bspline_create_closed(size_t dim, int degree, const double *points,
                         size_t count, const double *weights,
                         cf_bspline_t **out, cf_diag_t *diag)
{
    size_t p, total, nk;
    double *U = NULL, *P = NULL, *W = NULL;
    cf_status_t st;
    if (out != NULL)
        *out = NULL;
    if (degree < 1 || degree > CF_BSPLINE_MAX_DEGREE)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "bspline: closed curves need a degree in 1..%d, "
                         "not %d", CF_BSPLINE_MAX_DEGREE, degree);
    if (points == NULL || dim < 1 || dim > MAX_COUNT)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "bspline: points are NULL or dimension is 0");
    if (count < (size_t)degree + 1 || count > MAX_COUNT)
        return cf__error(diag, CF_STATUS_TOO_FEW_POINTS, -1,
                         "bspline: a closed curve of degree %d needs at "
                         "least %d points, %zu given", degree, degree + 1,
                         count);
    p = (size_t)degree;
    total = count + p;
    nk = total + p + 1;
    U = cf__alloc_array(nk, sizeof *U);
    P = cf__alloc_array(total, dim * sizeof *P);
    if (weights != NULL)
        W = cf__alloc_array(total, sizeof *W);
    if (U == NULL || P == NULL || (weights != NULL && W == NULL)) {
        st = cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                       "bspline: out of memory");
        goto done;
    }
    for (size_t i = 0; i < nk; i++)
        U[i] = ((double)i - (double)p) / (double)count;
    for (size_t i = 0; i < total; i++) {
        memcpy(P + i * dim, points + (i % count) * dim, dim * sizeof *P);
        if (W != NULL)
            W[i] = weights[i % count];
    }
    st = cf_bspline_create(dim, degree, U, nk, P, total, W, out, diag);
done:
    cf__free(U);
    cf__free(P);
    cf__free(W);
    return st;
}

cf_status_t
cf_bspline_create_coons(size_t dim, const double *points, size_t count,
                        cf_coons_ends_t ends, cf_bspline_t **out,
                        cf_diag_t *diag)
{
    size_t need, total, nk, j = 0;
    double *U = NULL, *P = NULL;
    cf_status_t st;
    if (out != NULL)
        *out = NULL;
    if (points == NULL || dim < 1 || dim > MAX_COUNT)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "coons: points are NULL or dimension is 0");
    switch (ends) {
    case CF_COONS_PLAIN:
        need = 4;
        total = count;
        break;
    case CF_COONS_TRIPLED:
        need = 2;
        total = count + 4;
        break;
    case CF_COONS_CLOSED:
        need = 3;
        total = count + 3;
        break;
    default:
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "coons: unknown end treatment %d", (int)ends);
    }
    if (count < need || count > MAX_COUNT)
        return cf__error(diag, CF_STATUS_TOO_FEW_POINTS, -1,
                         "coons: %zu points given, this end treatment "
                         "needs at least %zu", count, need);
    nk = total + 4;
    U = cf__alloc_array(nk, sizeof *U);
    P = cf__alloc_array(total, dim * sizeof *P);
    if (U == NULL || P == NULL) {
        st = cf__error(diag, CF_STATUS_NO_MEMORY, -1, "coons: out of memory");
        goto done;
    }
    for (size_t i = 0; i < nk; i++)
        U[i] = (double)i - 3.0;
    if (ends == CF_COONS_TRIPLED) {
        memcpy(P + dim * j++, points, dim * sizeof *P);
        memcpy(P + dim * j++, points, dim * sizeof *P);
    }
    memcpy(P + dim * j, points, count * dim * sizeof *P);
    j += count;
    if (ends == CF_COONS_TRIPLED) {
        memcpy(P + dim * j++, points + (count - 1) * dim, dim * sizeof *P);
        memcpy(P + dim * j++, points + (count - 1) * dim, dim * sizeof *P);
    } else if (ends == CF_COONS_CLOSED) {
        memcpy(P + dim * j, points, 3 * dim * sizeof *P);
    }
    st = cf_bspline_create(dim, 3, U, nk, P, total, NULL, out, diag);
done:
    cf__free(U);
    cf__free(P);
    return st;
}

void
cf_coons_basis(double t, double b[4])
{
    double s = 1.0 - t, t2 = t * t, t3 = t2 * t;
    b[0] = s * s * s / 6.0;
    b[1] = (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0;
    b[2] = (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0;
    b[3] = t3 / 6.0;
}

void
cf_coons_eval(size_t dim, const double *p4, double t, double *out)
{
    double b[4];
    cf_coons_basis(t, b);
    for (size_t d = 0; d < dim; d++)
        out[d] = b[0] * p4[d] + b[1] * p4[dim + d] + b[2] * p4[2 * dim + d]
                 + b[3] * p4[3 * dim + d];
}

cf_status_t
cf_bspline_copy(const cf_bspline_t *c, cf_bspline_t **out, cf_diag_t *diag)
{
    cf_bspline_t *r;
    if (out == NULL || c == NULL) {
        if (out != NULL)
            *out = NULL;
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "bspline: copy of NULL");
    }
    r = cf__bspline_alloc(c->dim, c->rational, c->p, c->count);
    if (r == NULL) {
        *out = NULL;
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "bspline: out of memory");
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

/* ---- NURBS conics ------------------------------------------------------- */

cf_status_t
cf_nurbs_arc(size_t dim, const double *O, const double *X, const double *Y,
             double r, double a0, double a1, cf_bspline_t **out,
             cf_diag_t *diag)
{
    double sweep = a1 - a0, dth, w1;
    size_t narcs, count, nk;
    double *U = NULL, *H = NULL;
    cf_status_t st;
    if (out != NULL)
        *out = NULL;
    if (out == NULL || O == NULL || X == NULL || Y == NULL || dim < 2
        || dim > MAX_COUNT)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "arc: NULL argument or dimension below 2");
    if (!isfinite(r) || !isfinite(a0) || !isfinite(a1))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "arc: radius or angles are not finite");
    if (!(r > 0.0))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "arc: radius %g must be positive", r);
    if (!(sweep > 0.0) || sweep > 2.0 * CF__PI * (1.0 + 1e-15))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "arc: sweep %g must be in (0, 2 pi]", sweep);
    /* one quadratic rational piece per quarter turn or less */
    narcs = (size_t)ceil(sweep / (0.5 * CF__PI) - 1e-12);
    if (narcs < 1)
        narcs = 1;
    if (narcs > 4)
        narcs = 4;
    dth = sweep / (double)narcs;
    w1 = cos(0.5 * dth);
    count = 2 * narcs + 1;
    nk = count + 3;
    U = cf__alloc_array(nk, sizeof *U);
    H = cf__alloc_array(count, (dim + 1) * sizeof *H);
    if (U == NULL || H == NULL) {
        st = cf__error(diag, CF_STATUS_NO_MEMORY, -1, "arc: out of memory");
        goto done;
    }
    for (size_t i = 0; i < 3; i++) {
        U[i] = 0.0;
        U[nk - 1 - i] = 1.0;
    }
    for (size_t i = 1; i < narcs; i++)
        U[1 + 2 * i] = U[2 + 2 * i] = (double)i / (double)narcs;
    for (size_t i = 0; i < count; i++) {
        /* even points on the circle, odd points at the intersection of the
        ** end tangents, at distance r / cos(dth / 2) from O */
        double th = a0 + 0.5 * dth * (double)i;
        double w = (i % 2 == 0) ? 1.0 : w1;
        double rr = (i % 2 == 0) ? r : r / w1;
        double cs = cos(th), sn = sin(th);
        if (i == count - 1) {
            cs = cos(a1);
            sn = sin(a1);
        }
        for (size_t d = 0; d < dim; d++)
            H[i * (dim + 1) + d] = w * (O[d] + rr * (cs * X[d] + sn * Y[d]));
        H[i * (dim + 1) + dim] = w;
    }
    st = cf_bspline_create_homogeneous(dim, 2, U, nk, H, count, out, diag);
done:
    cf__free(U);
    cf__free(H);
    return st;
}

cf_status_t
cf_nurbs_circle(const double *centre, double r, cf_bspline_t **out,
                cf_diag_t *diag)
{
    static const double U[12] = { 0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75,
                                  1, 1, 1 };
    static const double dx[9] = { 1, 1, 0, -1, -1, -1, 0, 1, 1 };
    static const double dy[9] = { 0, 1, 1, 1, 0, -1, -1, -1, 0 };
    double P[18], W[9];
    if (out != NULL)
        *out = NULL;
    if (centre == NULL || out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "circle: NULL argument");
    if (!isfinite(r) || !isfinite(centre[0]) || !isfinite(centre[1]))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "circle: centre or radius is not finite");
    if (!(r > 0.0))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "circle: radius %g must be positive", r);
    for (int i = 0; i < 9; i++) {
        P[2 * i] = centre[0] + r * dx[i];
        P[2 * i + 1] = centre[1] + r * dy[i];
        W[i] = (i % 2 == 0) ? 1.0 : sqrt(0.5);
    }
    return cf_bspline_create(2, 2, U, 12, P, 9, W, out, diag);
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

/* ---- evaluation --------------------------------------------------------- */

/* Plain de Boor for homogeneous coordinate d on span k. */
static double
deboor_coord(const cf_bspline_t *c, size_t k, double u, size_t d)
{
    double t[CF_BSPLINE_MAX_DEGREE + 1];
    size_t p = (size_t)c->p;
    const double *U = c->U;
    for (size_t j = 0; j <= p; j++)
        t[j] = c->P[(k - p + j) * c->hdim + d];
    for (size_t r = 1; r <= p; r++) {
        for (size_t j = p; j >= r; j--) {
            size_t i = k - p + j;
            double al = (u - U[i]) / (U[i + p + 1 - r] - U[i]);
            t[j] = (1.0 - al) * t[j - 1] + al * t[j];
        }
    }
    return t[p];
}

cf_status_t
cf_bspline_eval(const cf_bspline_t *c, double u, double *out)
{
    cf_status_t st;
    size_t k;
    double w = 1.0;
    if (c == NULL || out == NULL)
        return cf__error(NULL, CF_STATUS_INVALID_ARG, -1, "NULL argument");
    st = cf__bspline_check_param(c, u, NULL);
    if (st != CF_STATUS_OK)
        return st;
    k = cf__bspline_span(c, u);
    if (c->rational)
        w = deboor_coord(c, k, u, c->dim);
    for (size_t d = 0; d < c->dim; d++) {
        double v = deboor_coord(c, k, u, d);
        out[d] = c->rational ? v / w : v;
    }
    return CF_STATUS_OK;
}

/* The nonzero basis functions on span k with the precomputed reciprocals
** (the triangular scheme, A2.2). */
CF__INLINE void
basis_rk(const double *U, const double *rk, size_t nk, size_t k, int p,
         double u, double *N)
{
    double left[CF_BSPLINE_MAX_DEGREE + 1], right[CF_BSPLINE_MAX_DEGREE + 1];
    N[0] = 1.0;
    for (int j = 1; j <= p; j++) {
        const double *r = rk + (size_t)(j - 1) * nk + (k + 1 - (size_t)j);
        double saved = 0.0;
        left[j] = u - U[k + 1 - (size_t)j];
        right[j] = U[k + (size_t)j] - u;
        for (int q = 0; q < j; q++) {
            double t = N[q] * r[q];
            N[q] = saved + right[q + 1] * t;
            saved = left[j - q] * t;
        }
        N[j] = saved;
    }
}

/* C(u) on span k from the basis: out[dim]. */
CF__INLINE void
combine(const double *P, size_t hdim, size_t dim, bool rational, int p,
        size_t k, const double *N, double *out)
{
    const double *q = P + (k - (size_t)p) * hdim;
    if (!rational) {
        for (size_t d = 0; d < dim; d++) {
            double s = 0.0;
            for (int j = 0; j <= p; j++)
                s += N[j] * q[(size_t)j * hdim + d];
            out[d] = s;
        }
    } else {
        double w = 0.0;
        for (int j = 0; j <= p; j++)
            w += N[j] * q[(size_t)j * hdim + dim];
        for (size_t d = 0; d < dim; d++) {
            double s = 0.0;
            for (int j = 0; j <= p; j++)
                s += N[j] * q[(size_t)j * hdim + d];
            out[d] = s / w;
        }
    }
}

/* Span of u: keep k (sorted runs), step to the next span, or search. */
CF__INLINE size_t
next_span(const cf_bspline_t *c, size_t k, double u, bool ready)
{
    const double *U = c->U;
    if ((u >= U[k]) & (u < U[k + 1]))
        return k;
    return ready ? grid_span(c, u) : cf__bspline_span(c, u);
}

CF__INLINE cf_status_t
eval_many_impl(const cf_bspline_t *c, const double *u, size_t n, double *out,
               int p, size_t hdim, size_t dim, bool rational)
{
    double N[CF_BSPLINE_MAX_DEGREE + 1];
    const double *U = c->U, *rk = c->rk, *P = c->P;
    size_t nk = c->nknots, k = c->first_span;
    double a = c->a, b = c->b;
    for (size_t i = 0; i < n; i++) {
        double x = u[i];
        if (CF__UNLIKELY(!(x >= a && x <= b)))
            return isfinite(x) ? CF_STATUS_DOMAIN : CF_STATUS_NOT_FINITE;
        k = next_span(c, k, x, true);
        basis_rk(U, rk, nk, k, p, x, N);
        combine(P, hdim, dim, rational, p, k, N, out + i * dim);
    }
    return CF_STATUS_OK;
}

/*
** Polynomial cubic curves in the plane, the common case, written out: the
** triangular scheme with the reciprocals (the same operations in the same
** order as basis_rk), then the sum over the four points.  The parameters
** u[0..m-1] all lie on span k: the span's knots, reciprocals and points
** are loop constants, so that the loop is straight-line code the compiler
** vectorises over the parameters.
*/
CF__INLINE void
cubic2_run(const double *U, const double *R1, const double *R2,
           const double *R3, const double *P, size_t k,
           const double *restrict u, size_t m, double *restrict out,
           int deriv)
{
    const double *q = P + 2 * (k - 3);
    const double um2 = U[k - 2], um1 = U[k - 1], u0 = U[k];
    const double u1 = U[k + 1], u2 = U[k + 2], u3 = U[k + 3];
    const double r1 = R1[k], r2a = R2[k - 1], r2b = R2[k];
    const double r3a = R3[k - 2], r3b = R3[k - 1], r3c = R3[k];
    const double q0 = q[0], q1 = q[1], q2 = q[2], q3 = q[3];
    const double q4 = q[4], q5 = q[5], q6 = q[6], q7 = q[7];
    if (!deriv) {
        for (size_t i = 0; i < m; i++) {
            double x = u[i];
            double d1 = x - u0, d2 = x - um1, d3 = x - um2;
            double e1 = u1 - x, e2 = u2 - x, e3 = u3 - x;
            double n0 = e1 * r1, n1 = d1 * r1, t0, t1, t2, m0, m1, m2;
            double N0, N1, N2, N3;
            t0 = n0 * r2a;
            t1 = n1 * r2b;
            m0 = e1 * t0;
            m1 = d2 * t0 + e2 * t1;
            m2 = d1 * t1;
            t0 = m0 * r3a;
            t1 = m1 * r3b;
            t2 = m2 * r3c;
            N0 = e1 * t0;
            N1 = d3 * t0 + e2 * t1;
            N2 = d2 * t1 + e3 * t2;
            N3 = d1 * t2;
            out[2 * i] = N0 * q0 + N1 * q2 + N2 * q4 + N3 * q6;
            out[2 * i + 1] = N0 * q1 + N1 * q3 + N2 * q5 + N3 * q7;
        }
    } else {
        /* C' = 3 sum N_i^2 (P_i - P_{i-1}) / (u_{i+3} - u_i) */
        const double g0 = q2 - q0, g1 = q4 - q2, g2 = q6 - q4;
        const double h0 = q3 - q1, h1 = q5 - q3, h2 = q7 - q5;
        for (size_t i = 0; i < m; i++) {
            double x = u[i];
            double d1 = x - u0, d2 = x - um1;
            double e1 = u1 - x, e2 = u2 - x;
            double n0 = e1 * r1, n1 = d1 * r1, t0, t1, f0, f1, f2;
            t0 = n0 * r2a;
            t1 = n1 * r2b;
            f0 = 3.0 * (e1 * t0) * r3a;
            f1 = 3.0 * (d2 * t0 + e2 * t1) * r3b;
            f2 = 3.0 * (d1 * t1) * r3c;
            out[2 * i] = f0 * g0 + f1 * g1 + f2 * g2;
            out[2 * i + 1] = f0 * h0 + f1 * h1 + f2 * h2;
        }
    }
}

/* One clone per x86-64 level (an ifunc), as in bezier-eval.c; the file is
** compiled without contraction, so every clone rounds alike.  Not in
** sanitizer builds: the resolvers run before the sanitizer runtime. */
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__) && \
    !defined(__SANITIZE_ADDRESS__)
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#endif
/* parameters per block of span searches (random parameters) */
#define RBLK 32

static cf_status_t
eval_cubic2(const cf_bspline_t *c, const double *u, size_t n, double *out,
            int deriv)
{
    const double *U = c->U, *P = c->P, *R1 = c->rk;
    const double *R2 = R1 + c->nknots, *R3 = R2 + c->nknots;
    size_t k = c->first_span, i = 0;
    double a = c->a, b = c->b, lo = U[k], hi = U[k + 1];
    while (i < n) {
        double x = u[i];
        size_t j = i + 1;
        if (CF__UNLIKELY(!(x >= a && x <= b)))
            return isfinite(x) ? CF_STATUS_DOMAIN : CF_STATUS_NOT_FINITE;
        /* one branch, predictable both for sorted parameters (mostly
        ** inside) and random ones (mostly outside): `&&` would make the
        ** first comparison a coin toss for random parameters; no "next
        ** span" shortcut for the same reason */
        if ((int)(x >= lo) + (int)(x < hi) != 2) {
            /* a new span (random parameters): the spans of the next
            ** RBLK parameters first, without branches, then the points,
            ** so that the table loads do not wait for the search */
            size_t ks[RBLK], mb = n - i < RBLK ? n - i : RBLK;
            int ok = 1;
            for (size_t l = 0; l < mb; l++) {
                double y = u[i + l], yc = y >= a ? y : a;
                ok &= (y >= a) & (y <= b);
                ks[l] = grid_span(c, yc <= b ? yc : b);
            }
            if (!ok)
                mb = 1; /* the bad parameter is found above */
            else
                for (size_t l = 0; l < mb; l++)
                    cubic2_run(U, R1, R2, R3, P, ks[l], u + i + l, 1,
                               out + 2 * (i + l), deriv);
            if (!ok) {
                k = grid_span(c, x);
                cubic2_run(U, R1, R2, R3, P, k, u + i, 1, out + 2 * i,
                           deriv);
            } else {
                k = ks[mb - 1];
            }
            lo = U[k];
            hi = U[k + 1];
            i += mb;
            continue;
        }
        /* still on span k (sorted parameters): the run of parameters
        ** on it, eight at a time first ([lo, hi) lies in the domain, and
        ** NaN ends the run), evaluated by the vectorised loop */
        for (; j + 8 <= n; j += 8) {
            int in = 1;
            for (size_t l = 0; l < 8; l++)
                in &= (u[j + l] >= lo) & (u[j + l] < hi);
            if (!in)
                break;
        }
        while (j < n && (int)(u[j] >= lo) + (int)(u[j] < hi) == 2)
            j++;
        cubic2_run(U, R1, R2, R3, P, k, u + i, j - i, out + 2 * i, deriv);
        i = j;
    }
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_eval_many(const cf_bspline_t *c, const double *u, size_t n,
                     double *out)
{
    if (c == NULL || (n > 0 && (u == NULL || out == NULL)))
        return cf__error(NULL, CF_STATUS_INVALID_ARG, -1, "NULL argument");
    if (!cf__bspline_accel(c))
        return cf_bspline_eval_deriv_many(c, 0, u, n, out);
    if (!c->rational && c->dim == 2) {
        switch (c->p) {
        case 1:
            return eval_many_impl(c, u, n, out, 1, 2, 2, false);
        case 2:
            return eval_many_impl(c, u, n, out, 2, 2, 2, false);
        case 3:
            return eval_cubic2(c, u, n, out, 0);
        default:
            break;
        }
    }
    if (c->rational && c->dim == 2 && c->p == 2)
        return eval_many_impl(c, u, n, out, 2, 3, 2, true);
    return eval_many_impl(c, u, n, out, c->p, c->hdim, c->dim, c->rational);
}

cf_status_t
cf_bspline_eval_derivs(const cf_bspline_t *c, double u, int k, double *out)
{
    double v[CF_BSPLINE_MAX_DEGREE + 1], wd[CF_BSPLINE_MAX_DEGREE + 1];
    cf_status_t st;
    size_t kk, p, dim;
    if (c == NULL || out == NULL || k < 0)
        return cf__error(NULL, CF_STATUS_INVALID_ARG, -1, "bad argument");
    st = cf__bspline_check_param(c, u, NULL);
    if (st != CF_STATUS_OK)
        return st;
    kk = cf__bspline_span(c, u);
    p = (size_t)c->p;
    dim = c->dim;
    for (int j = 0; j <= k; j++) {
        const double *q = c->P + (kk - p) * c->hdim;
        cf__basis_deriv(c->p, c->U, c->nknots, NULL, kk, u, j, v);
        for (size_t d = 0; d < dim; d++) {
            double s = 0.0;
            for (size_t i = 0; i <= p; i++)
                s += v[i] * q[i * c->hdim + d];
            out[(size_t)j * dim + d] = s;
        }
        if (c->rational && j <= c->p) {
            double s = 0.0;
            for (size_t i = 0; i <= p; i++)
                s += v[i] * q[i * c->hdim + dim];
            wd[j] = s;
        }
    }
    if (c->rational) {
        /* C^(j) = (A^(j) - sum_{i=1}^{j} binom(j, i) w^(i) C^(j-i)) / w */
        for (int j = 0; j <= k; j++) {
            int top = j < c->p ? j : c->p;
            for (size_t d = 0; d < dim; d++) {
                double s = out[(size_t)j * dim + d];
                for (int i = 1; i <= top; i++)
                    s -= cf__binomial(j, i) * wd[i]
                         * out[(size_t)(j - i) * dim + d];
                out[(size_t)j * dim + d] = s / wd[0];
            }
        }
    }
    return CF_STATUS_OK;
}

/* Highest derivative order of cf_bspline_eval_deriv_many for a NURBS
** (the quotient rule keeps all lower orders of one coordinate on the
** stack). */
#define MAX_RATIONAL_DERIV 128

CF__INLINE void
deriv_poly_point(const cf_bspline_t *c, const double *rk, size_t kk,
                 double u, int k, double *out)
{
    double v[CF_BSPLINE_MAX_DEGREE + 1];
    size_t p = (size_t)c->p, hd = c->hdim;
    const double *q = c->P + (kk - p) * hd;
    cf__basis_deriv(c->p, c->U, c->nknots, rk, kk, u, k, v);
    for (size_t d = 0; d < c->dim; d++) {
        double s = 0.0;
        for (size_t i = 0; i <= p; i++)
            s += v[i] * q[i * hd + d];
        out[d] = s;
    }
}

/* First derivative of a polynomial curve: N^{p-1} with the reciprocals,
** then C' = sum p (P_i - P_{i-1}) / (u_{i+p} - u_i) N_i^{p-1}. */
CF__INLINE void
deriv1_fast(const cf_bspline_t *c, size_t kk, double u, int p, size_t hd,
            size_t dim, double *out)
{
    double N[CF_BSPLINE_MAX_DEGREE + 1];
    const double *rk = c->rk + (size_t)(p - 1) * c->nknots;
    const double *q = c->P + (kk - (size_t)p) * hd;
    basis_rk(c->U, c->rk, c->nknots, kk, p - 1, u, N);
    for (size_t d = 0; d < dim; d++) {
        double s = 0.0;
        for (int j = 1; j <= p; j++) {
            size_t i = kk - (size_t)p + (size_t)j;
            s += N[j - 1] * rk[i] * (q[(size_t)j * hd + d]
                                     - q[(size_t)(j - 1) * hd + d]);
        }
        out[d] = (double)p * s;
    }
}

CF__INLINE cf_status_t
deriv1_many(const cf_bspline_t *c, const double *u, size_t n, double *out,
            int p, size_t hd, size_t dim)
{
    size_t k = c->first_span;
    for (size_t i = 0; i < n; i++) {
        double x = u[i];
        if (CF__UNLIKELY(!(x >= c->a && x <= c->b)))
            return isfinite(x) ? CF_STATUS_DOMAIN : CF_STATUS_NOT_FINITE;
        k = next_span(c, k, x, true);
        deriv1_fast(c, k, x, p, hd, dim, out + i * dim);
    }
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_eval_deriv_many(const cf_bspline_t *c, int k, const double *u,
                           size_t n, double *out)
{
    size_t kk;
    bool ready;
    const double *rk;
    if (c == NULL || k < 0 || (n > 0 && (u == NULL || out == NULL)))
        return cf__error(NULL, CF_STATUS_INVALID_ARG, -1, "bad argument");
    ready = cf__bspline_accel(c);
    rk = ready ? c->rk : NULL;
    if (k == 0 && ready)
        return cf_bspline_eval_many(c, u, n, out);
    if (ready && !c->rational && k == 1 && c->p >= 1) {
        if (c->dim == 2 && c->p == 3)
            return eval_cubic2(c, u, n, out, 1);
        return deriv1_many(c, u, n, out, c->p, c->hdim, c->dim);
    }
    if (c->rational && k > MAX_RATIONAL_DERIV)
        return cf__error(NULL, CF_STATUS_INVALID_ARG, -1,
                         "bspline: derivative order %d of a NURBS is above "
                         "%d", k, MAX_RATIONAL_DERIV);
    kk = c->first_span;
    for (size_t i = 0; i < n; i++) {
        double x = u[i];
        if (!(x >= c->a && x <= c->b))
            return isfinite(x) ? CF_STATUS_DOMAIN : CF_STATUS_NOT_FINITE;
        kk = next_span(c, kk, x, rk != NULL);
        if (!c->rational) {
            deriv_poly_point(c, rk, kk, x, k, out + i * c->dim);
        } else {
            /* one coordinate at a time: C_d^(j), j = 0..k, by the
            ** quotient rule (A^(j) = w^(j) = 0 for j > p) */
            double A[CF_BSPLINE_MAX_DEGREE + 1], W[CF_BSPLINE_MAX_DEGREE + 1];
            double Cd[MAX_RATIONAL_DERIV + 1];
            double vv[(CF_BSPLINE_MAX_DEGREE + 1) * (CF_BSPLINE_MAX_DEGREE + 1)];
            size_t p = (size_t)c->p, hd = c->hdim;
            const double *q = c->P + (kk - p) * hd;
            int top = k < c->p ? k : c->p;
            for (int j = 0; j <= top; j++)
                cf__basis_deriv(c->p, c->U, c->nknots, rk, kk, x, j,
                                vv + (size_t)j * (p + 1));
            for (int j = 0; j <= top; j++) {
                double s = 0.0;
                for (size_t l = 0; l <= p; l++)
                    s += vv[(size_t)j * (p + 1) + l] * q[l * hd + c->dim];
                W[j] = s;
            }
            for (size_t d = 0; d < c->dim; d++) {
                for (int j = 0; j <= top; j++) {
                    double s = 0.0;
                    for (size_t l = 0; l <= p; l++)
                        s += vv[(size_t)j * (p + 1) + l] * q[l * hd + d];
                    A[j] = s;
                }
                for (int j = 0; j <= k; j++) {
                    double s = j <= top ? A[j] : 0.0;
                    int lim = j < c->p ? j : c->p;
                    for (int l = 1; l <= lim; l++)
                        s -= cf__binomial(j, l) * W[l] * Cd[j - l];
                    Cd[j] = s / W[0];
                }
                out[i * c->dim + d] = Cd[k];
            }
        }
    }
    return CF_STATUS_OK;
}

size_t
cf_bspline_deboor_size(const cf_bspline_t *c)
{
    size_t p;
    if (c == NULL)
        return 0;
    p = (size_t)c->p;
    return (p + 1) * (p + 2) / 2 * c->dim;
}

/* The scalar de Boor triangle of homogeneous coordinate d into T
** (level after level). */
static void
deboor_triangle(const cf_bspline_t *c, size_t k, double u, size_t d,
                double *T)
{
    size_t p = (size_t)c->p, off = 0;
    const double *U = c->U;
    for (size_t j = 0; j <= p; j++)
        T[j] = c->P[(k - p + j) * c->hdim + d];
    for (size_t r = 1; r <= p; r++) {
        size_t prev = off;
        off += p + 2 - r;
        for (size_t l = 0; l + r <= p; l++) {
            size_t i = k - p + r + l;
            double al = (u - U[i]) / (U[i + p + 1 - r] - U[i]);
            T[off + l] = (1.0 - al) * T[prev + l] + al * T[prev + l + 1];
        }
    }
}

cf_status_t
cf_bspline_deboor(const cf_bspline_t *c, double u, double *out, size_t *span,
                  int *mult)
{
    double T[(CF_BSPLINE_MAX_DEGREE + 1) * (CF_BSPLINE_MAX_DEGREE + 2) / 2];
    double W[(CF_BSPLINE_MAX_DEGREE + 1) * (CF_BSPLINE_MAX_DEGREE + 2) / 2];
    size_t k, tot;
    cf_status_t st;
    if (c == NULL || out == NULL)
        return cf__error(NULL, CF_STATUS_INVALID_ARG, -1, "NULL argument");
    st = cf__bspline_check_param(c, u, NULL);
    if (st != CF_STATUS_OK)
        return st;
    k = cf__bspline_span(c, u);
    tot = ((size_t)c->p + 1) * ((size_t)c->p + 2) / 2;
    if (c->rational)
        deboor_triangle(c, k, u, c->dim, W);
    for (size_t d = 0; d < c->dim; d++) {
        deboor_triangle(c, k, u, d, T);
        for (size_t i = 0; i < tot; i++)
            out[i * c->dim + d] = c->rational ? T[i] / W[i] : T[i];
    }
    if (span != NULL)
        *span = k;
    if (mult != NULL)
        *mult = cf__knots_mult(c->U, c->nknots, u);
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_basis(const cf_bspline_t *c, double u, size_t *first, double *N)
{
    cf_status_t st;
    size_t k;
    if (c == NULL || N == NULL)
        return cf__error(NULL, CF_STATUS_INVALID_ARG, -1, "NULL argument");
    st = cf__bspline_check_param(c, u, NULL);
    if (st != CF_STATUS_OK)
        return st;
    k = cf__bspline_span(c, u);
    cf__basis_deriv(c->p, c->U, c->nknots, NULL, k, u, 0, N);
    if (first != NULL)
        *first = k - (size_t)c->p;
    return CF_STATUS_OK;
}

/* ---- figure helpers ----------------------------------------------------- */

cf_status_t
cf_bspline_support(const cf_bspline_t *c, size_t i, double *lo, double *hi)
{
    if (c == NULL)
        return cf__error(NULL, CF_STATUS_INVALID_ARG, -1, "NULL curve");
    if (i >= c->count)
        return cf__error(NULL, CF_STATUS_INVALID_ARG, (long)i,
                         "bspline: point %zu does not exist (%zu points)", i,
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
    st = cf__bspline_check_param(c, u, NULL);
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
    cf_status_t st;
    if (out != NULL)
        *out = NULL;
    if (c == NULL || v == NULL || out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "bspline: NULL argument");
    if (i >= c->count)
        return cf__error(diag, CF_STATUS_INVALID_ARG, (long)i,
                         "bspline: point %zu does not exist (%zu points)", i,
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
