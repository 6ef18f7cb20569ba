/*
** Knot vectors and B-spline basis functions (thesis chapter 1 and §2.5;
** The NURBS Book A2.1-A2.4).
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "bspline-private.h"
#include "numtext-private.h"

size_t
cf_knots_count(int degree, size_t npoints)
{
    if (degree < 0)
        return 0;
    return npoints + (size_t)degree + 1;
}

/* Print two different values so that they read as different: two
** decimals when that suffices ("0.30" and "0.50"), more otherwise. */
static void
format_pair(double x, double y, char *bx, char *by, size_t size)
{
    for (int prec = 2; prec <= 17; prec++) {
        snprintf(bx, size, "%.*f", prec, x);
        snprintf(by, size, "%.*f", prec, y);
        if (strcmp(bx, by) != 0 || x == y)
            return;
    }
}

cf_status_t
cf__check_knot_order(const double *U, size_t n, const char *what,
                     cf_diag_t *diag)
{
    char b1[64], b2[64];
    /* a curve's knots by their index u_i, another list's by position */
    const char *u = strcmp(what, "knot") == 0 ? "u_" : "";
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(U[i]))
            return cf__error(diag, CF_STATUS_NOT_FINITE, (long)i,
                             "%s %s%zu is %s; knots must be finite", what, u,
                             i, CF__NUM(U[i]));
    }
    for (size_t i = 1; i < n; i++) {
        if (U[i] < U[i - 1]) {
            format_pair(U[i], U[i - 1], b1, b2, sizeof b1);
            return cf__error(diag, CF_STATUS_BAD_KNOTS, (long)i,
                             "%s %s%zu (%s) is smaller than %s %s%zu (%s)",
                             what, u, i, b1, what, u, i - 1, b2);
        }
    }
    return CF_STATUS_OK;
}

/* The degree and the number of points (or parameters) for a curve. */
static cf_status_t
check_degree_count(int lo, int degree, size_t npoints, const char *what,
                   cf_diag_t *diag)
{
    if (degree < lo || degree > CF_BSPLINE_MAX_DEGREE)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "degree %d is outside %d..%d", degree, lo,
                         CF_BSPLINE_MAX_DEGREE);
    if (npoints < (size_t)degree + 1)
        return cf__error(diag, CF_STATUS_TOO_FEW_POINTS, -1,
                         "degree %d needs at least %d %s, %zu given",
                         degree, degree + 1, what, npoints);
    return CF_STATUS_OK;
}

cf_status_t
cf_knots_validate(int degree, size_t npoints, const double *knots,
                  size_t nknots, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    size_t need, m;
    cf_status_t st = check_degree_count(0, degree, npoints,
                                        "points", diag);

    if (st != CF_STATUS_OK)
        return st;
    need = npoints + (size_t)degree + 1;
    if (knots == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "knots are NULL");
    if (nknots != need)
        return cf__error(diag, CF_STATUS_BAD_KNOTS, -1,
                         "%zu knots given, degree %d with %zu "
                         "points needs %zu", nknots, degree, npoints, need);
    st = cf__check_knot_order(knots, nknots, "knot", diag);
    if (st != CF_STATUS_OK)
        return st;
    for (size_t i = 0; i < nknots;) {
        size_t j = i;
        while (j + 1 < nknots && knots[j + 1] == knots[i])
            j++;
        if (j - i + 1 > (size_t)degree + 1) {
            return cf__error(diag, CF_STATUS_BAD_KNOTS, (long)i,
                             "knot u_%zu (%s) has multiplicity %zu; degree %d "
                             "allows at most %d", i, CF__NUM(knots[i]),
                             j - i + 1, degree,
                             degree + 1);
        }
        i = j + 1;
    }
    m = nknots - 1;
    if (!(knots[degree] < knots[m - (size_t)degree]))
        return cf__error(diag, CF_STATUS_BAD_KNOTS, (long)degree,
                         "the domain [u_%d, u_%zu] = [%s, %s] is empty",
                         degree, m - (size_t)degree, CF__NUM(knots[degree]),
                         CF__NUM(knots[m - (size_t)degree]));
    return CF_STATUS_OK;
}

static cf_status_t
check_gen(int degree, size_t npoints, double a, double b, const double *out,
          cf_diag_t *diag)
{
    cf_status_t st = check_degree_count(0, degree, npoints,
                                        "points", diag);
    if (st != CF_STATUS_OK)
        return st;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "output is NULL");
    if (!isfinite(a) || !isfinite(b))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "interval [%s, %s] is not finite", CF__NUM(a),
                         CF__NUM(b));
    if (!(a < b))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "interval [%s, %s] is empty", CF__NUM(a),
                         CF__NUM(b));
    return CF_STATUS_OK;
}

/* a + i (b - a) / n, exact at both ends. */
static double
lerp_index(double a, double b, size_t i, size_t n)
{
    if (i == 0)
        return a;
    if (i == n)
        return b;
    return a + (b - a) * ((double)i / (double)n);
}

cf_status_t
cf_knots_uniform(int degree, size_t npoints, double a, double b, double *out,
                 cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = check_gen(degree, npoints, a, b, out, diag);
    size_t m;
    if (st != CF_STATUS_OK)
        return st;
    m = npoints + (size_t)degree;
    for (size_t i = 0; i <= m; i++)
        out[i] = lerp_index(a, b, i, m);
    return CF_STATUS_OK;
}

cf_status_t
cf_knots_clamped_uniform(int degree, size_t npoints, double a, double b,
                         double *out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = check_gen(degree, npoints, a, b, out, diag);
    size_t p, n, inner;
    if (st != CF_STATUS_OK)
        return st;
    p = (size_t)degree;
    n = npoints - 1;
    inner = n - p + 1;   /* number of spans */
    for (size_t i = 0; i <= p; i++) {
        out[i] = a;
        out[n + 1 + i] = b;
    }
    for (size_t j = 1; j <= n - p; j++)
        out[p + j] = lerp_index(a, b, j, inner);
    return CF_STATUS_OK;
}

cf_status_t
cf_knots_clamped_averaged(int degree, size_t npoints, const double *params,
                          double *out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    size_t p, n;
    cf_status_t st = check_degree_count(1, degree, npoints,
                                        "parameters", diag);
    if (st != CF_STATUS_OK)
        return st;
    if (params == NULL || out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "parameters or output are NULL");
    for (size_t i = 0; i < npoints; i++) {
        if (!isfinite(params[i]))
            return cf__error(diag, CF_STATUS_NOT_FINITE, (long)i,
                             "parameter %zu is %s; parameters must be "
                             "finite", i, CF__NUM(params[i]));
        if (i > 0 && !(params[i] > params[i - 1]))
            return cf__error(diag, CF_STATUS_INVALID_ARG, (long)i,
                             "parameter %zu (%s) is not larger than "
                             "parameter %zu (%s)", i, CF__NUM(params[i]),
                             i - 1, CF__NUM(params[i - 1]));
    }
    p = (size_t)degree;
    n = npoints - 1;
    for (size_t i = 0; i <= p; i++) {
        out[i] = params[0];
        out[n + 1 + i] = params[n];
    }
    for (size_t j = 1; j <= n - p; j++) {
        double s = 0.0;
        for (size_t i = j; i < j + p; i++)
            s += params[i];
        out[j + p] = s / (double)p;
    }
    return CF_STATUS_OK;
}

/* The unchecked queries still refuse what would make them read outside
** the vector: NULL, a degree out of range, fewer than 2p + 2 knots (API
** misuse test). */
static bool
queryable(int degree, const double *knots, size_t nknots)
{
    return knots != NULL && degree >= 0 && degree <= CF_BSPLINE_MAX_DEGREE &&
           nknots >= 2 * (size_t)degree + 2;
}

void
cf_knots_domain(int degree, const double *knots, size_t nknots, double *a,
                double *b)
{
    size_t m = nknots - 1, p = (size_t)degree;
    if (!queryable(degree, knots, nknots)) {
        if (a != NULL)
            *a = NAN;
        if (b != NULL)
            *b = NAN;
        return;
    }
    if (a != NULL)
        *a = knots[p];
    if (b != NULL)
        *b = knots[m - p];
}

size_t
cf_knots_find_span(int degree, const double *U, size_t nknots, double u)
{
    size_t p = (size_t)degree, n, lo, hi;
    if (!queryable(degree, U, nknots))
        return degree > 0 ? (size_t)degree : 0;
    n = nknots - p - 2;
    if (!(u < U[n + 1])) {
        /* right end of the domain (or beyond): last non-empty span */
        size_t k = n;
        while (k > p && !(U[k] < U[n + 1]))
            k--;
        return k;
    }
    if (!(u > U[p]))
        u = U[p];
    lo = p;
    hi = n + 1;   /* U[lo] <= u < U[hi] */
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (u < U[mid])
            hi = mid;
        else
            lo = mid;
    }
    return lo;
}

int
cf__knots_mult(const double *U, size_t nknots, double u)
{
    size_t lo = 0, hi = nknots;
    int s = 0;
    /* first index with U[i] >= u */
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (U[mid] < u)
            lo = mid + 1;
        else
            hi = mid;
    }
    while (lo < nknots && U[lo] == u) {
        s++;
        lo++;
    }
    return s;
}

int
cf_knots_multiplicity(const double *knots, size_t nknots, double u)
{
    if (knots == NULL)
        return 0;
    return cf__knots_mult(knots, nknots, u);
}

cf_knot_kind_t
cf_knots_classify(int degree, const double *U, size_t nknots)
{
    size_t p = (size_t)degree, m = nknots - 1, n = m - p - 1, period;
    double tol;
    bool periodic = true;
    if (!queryable(degree, U, nknots))
        return CF_KNOTS_OPEN;
    if (U[0] == U[p] && U[m - p] == U[m])
        return CF_KNOTS_CLAMPED;
    if (n + 1 < p + 1)
        return CF_KNOTS_OPEN;
    period = n - p + 1;
    tol = 1e-12 * (U[m] - U[0]);
    for (size_t i = 0; i < 2 * p && periodic; i++) {
        double d0 = U[i + 1] - U[i];
        double d1 = U[i + 1 + period] - U[i + period];
        if (fabs(d0 - d1) > tol)
            periodic = false;
    }
    return periodic ? CF_KNOTS_PERIODIC : CF_KNOTS_OPEN;
}

const char *
cf_knot_kind_to_string(cf_knot_kind_t kind)
{
    switch (kind) {
    case CF_KNOTS_OPEN:
        return "open";
    case CF_KNOTS_CLAMPED:
        return "clamped";
    case CF_KNOTS_PERIODIC:
        return "periodic";
    }
    return "unknown";
}

/* ---- basis functions ---------------------------------------------------- */

/* 1 / (U[a + j] - U[a]), 0 for a zero difference. */
static inline double
recip(const double *U, size_t nknots, const double *rk, size_t a, int j)
{
    double d;
    if (rk != NULL)
        return rk[(size_t)(j - 1) * nknots + a];
    d = U[a + (size_t)j] - U[a];
    return d != 0.0 ? 1.0 / d : 0.0;
}

void
cf__basis_deriv(int p, const double *U, size_t nknots, const double *rk,
                size_t k, double u, int d, double *v)
{
    int q = p - d;
    double left[CF_BSPLINE_MAX_DEGREE + 1], right[CF_BSPLINE_MAX_DEGREE + 1];
    double N[CF_BSPLINE_MAX_DEGREE + 1];
    if (d > p) {
        for (int j = 0; j <= p; j++)
            v[j] = 0.0;
        return;
    }
    /* the triangular scheme up to degree q: N[j] = N_{k-q+j}^q(u) */
    N[0] = 1.0;
    for (int j = 1; j <= q; j++) {
        double saved = 0.0;
        left[j] = u - U[k + 1 - (size_t)j];
        right[j] = U[k + (size_t)j] - u;
        for (int r = 0; r < j; r++) {
            /* denominator U[k+r+1] - U[k+1-j+r], positive on a span */
            double t = N[r] * recip(U, nknots, rk, k + 1 - (size_t)j
                                    + (size_t)r, j);
            N[r] = saved + right[r + 1] * t;
            saved = left[j - r] * t;
        }
        N[j] = saved;
    }
    /* v over the indices k-p .. k: zeros, then the degree-q values */
    for (int j = 0; j < d; j++)
        v[j] = 0.0;
    for (int j = 0; j <= q; j++)
        v[d + j] = N[j];
    /* N_i^{r (e)} = r (N_i^{r-1 (e-1)} / (u_{i+r} - u_i)
    **               - N_{i+1}^{r-1 (e-1)} / (u_{i+r+1} - u_{i+1})),
    ** 0/0 = 0; N_{k+1}^{r-1} vanishes on the span. */
    for (int r = q + 1; r <= p; r++) {
        for (int j = 0; j <= p; j++) {
            size_t i = k - (size_t)p + (size_t)j;
            double next = j < p ? v[j + 1] : 0.0;
            double a = v[j] * recip(U, nknots, rk, i, r);
            double b = j < p ? next * recip(U, nknots, rk, i + 1, r) : 0.0;
            v[j] = (double)r * (a - b);
        }
    }
}

static cf_status_t
check_curve_knots(int degree, const double *U, size_t nknots, double u,
                  cf_diag_t *diag)
{
    cf_status_t st;
    size_t p;
    if (degree < 0 || degree > CF_BSPLINE_MAX_DEGREE)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "degree %d is outside 0..%d", degree,
                         CF_BSPLINE_MAX_DEGREE);
    p = (size_t)degree;
    if (U == NULL || nknots < 2 * p + 2)
        return cf__error(diag, CF_STATUS_BAD_KNOTS, -1,
                         "degree %d needs at least %zu knots, %zu "
                         "given", degree, 2 * p + 2, U ? nknots : 0);
    st = cf_knots_validate(degree, nknots - p - 1, U, nknots, diag);
    if (st != CF_STATUS_OK)
        return st;
    return cf__param_check(U[p], U[nknots - 1 - p], &u, diag);
}

cf_status_t
cf_basis_funs(int degree, const double *knots, size_t nknots, double u,
              size_t *span, double *N, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = check_curve_knots(degree, knots, nknots, u, diag);
    size_t k;
    if (st != CF_STATUS_OK)
        return st;
    if (N == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "output is NULL");
    /* the end u misses by rounding, if it does (checked above) */
    (void)cf__param_clamp(knots[degree], knots[nknots - 1 - (size_t)degree],
                          &u);
    k = cf_knots_find_span(degree, knots, nknots, u);
    cf__basis_deriv(degree, knots, nknots, NULL, k, u, 0, N);
    if (span != NULL)
        *span = k;
    return CF_STATUS_OK;
}

cf_status_t
cf_basis_ders(int degree, const double *knots, size_t nknots, double u,
              int nder, size_t *span, double *ders, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = check_curve_knots(degree, knots, nknots, u, diag);
    size_t k, w = (size_t)degree + 1;
    if (st != CF_STATUS_OK)
        return st;
    if (ders == NULL || nder < 0)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "output is NULL or derivative order %d < 0",
                         nder);
    (void)cf__param_clamp(knots[degree], knots[nknots - 1 - (size_t)degree],
                          &u);
    k = cf_knots_find_span(degree, knots, nknots, u);
    for (int d = 0; d <= nder; d++)
        cf__basis_deriv(degree, knots, nknots, NULL, k, u, d,
                        ders + (size_t)d * w);
    if (span != NULL)
        *span = k;
    return CF_STATUS_OK;
}

static cf_status_t
check_one(int i, int degree, const double *U, size_t nknots, double u,
          cf_diag_t *diag)
{
    if (degree < 0 || degree > CF_BSPLINE_MAX_DEGREE)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "degree %d is outside 0..%d", degree,
                         CF_BSPLINE_MAX_DEGREE);
    if (U == NULL || i < 0 || (size_t)i + (size_t)degree + 2 > nknots)
        return cf__error(diag, CF_STATUS_BAD_KNOTS, i,
                         "N_%d^%d needs knots u_%d..u_%d, %zu given",
                         i, degree, i, i + degree + 1, U ? nknots : 0);
    {
        cf_status_t st = cf__check_knot_order(U, nknots, "knot", diag);
        if (st != CF_STATUS_OK)
            return st;
    }
    if (!isfinite(u))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "parameter is %s", CF__NUM(u));
    return CF_STATUS_OK;
}

/* N_{i+j}^q(u), j = 0..p-q, by the Cox-de Boor recursion from the
** indicator functions (right-continuous; left-continuous at the last
** knot). */
static void
one_triangle(int i, int p, int q, const double *U, size_t nknots, double u,
             double *N)
{
    double last = U[nknots - 1];
    for (int j = 0; j <= p; j++) {
        double lo = U[i + j], hi = U[i + j + 1];
        bool in = (u == last) ? (lo < u && u <= hi) : (lo <= u && u < hi);
        N[j] = in ? 1.0 : 0.0;
    }
    for (int r = 1; r <= q; r++) {
        for (int j = 0; j <= p - r; j++) {
            size_t a = (size_t)(i + j);
            double d0 = U[a + (size_t)r] - U[a];
            double d1 = U[a + (size_t)r + 1] - U[a + 1];
            double v = 0.0;
            if (d0 != 0.0)
                v += (u - U[a]) / d0 * N[j];
            if (d1 != 0.0)
                v += (U[a + (size_t)r + 1] - u) / d1 * N[j + 1];
            N[j] = v;
        }
    }
}

cf_status_t
cf_basis_one(int i, int degree, const double *knots, size_t nknots, double u,
             double *value, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    double N[CF_BSPLINE_MAX_DEGREE + 1];
    cf_status_t st = check_one(i, degree, knots, nknots, u, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (value == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "output is NULL");
    one_triangle(i, degree, degree, knots, nknots, u, N);
    *value = N[0];
    return CF_STATUS_OK;
}

cf_status_t
cf_basis_one_ders(int i, int degree, const double *U, size_t nknots,
                  double u, int nder, double *out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    double N[CF_BSPLINE_MAX_DEGREE + 1];
    cf_status_t st = check_one(i, degree, U, nknots, u, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (out == NULL || nder < 0)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "output is NULL or derivative order %d < 0",
                         nder);
    for (int d = 0; d <= nder; d++) {
        int q = degree - d;
        if (d > degree) {
            out[d] = 0.0;
            continue;
        }
        /* N_{i+j}^q for j = 0..d, then raise the degree d times with the
        ** derivative recursion (0/0 = 0) */
        one_triangle(i, degree, q, U, nknots, u, N);
        for (int r = q + 1; r <= degree; r++) {
            for (int j = 0; j <= degree - r; j++) {
                size_t a = (size_t)(i + j);
                double d0 = U[a + (size_t)r] - U[a];
                double d1 = U[a + (size_t)r + 1] - U[a + 1];
                double v = 0.0;
                if (d0 != 0.0)
                    v += N[j] / d0;
                if (d1 != 0.0)
                    v -= N[j + 1] / d1;
                N[j] = (double)r * v;
            }
        }
        out[d] = N[0];
    }
    return CF_STATUS_OK;
}
