/*
** The spline constructions behind cf_interpolate and cf_approximate_lsq:
** collocation systems in the B-spline basis (natural, clamped, not-a-knot,
** global of any degree), the cyclic system of the periodic cubic, the
** Catmull-Rom tangents, and least squares.  Basis functions come from
** knots.h, curves are built by bspline.h; the systems are solved by
** linsolve.c.
*/
#include <math.h>
#include <string.h>

#include "bspline-private.h"
#include "interp-private.h"
#include "linsolve-private.h"
#include "numtext-private.h"

/*
** The ord-th derivatives of the p + 1 nonzero basis functions at u into
** v[p + 1], and their span.  The knot vector is validated once by the
** caller (cf_knots_validate), so the unchecked evaluator of the B-spline
** module is used: the public cf_basis_ders validates the whole vector on
** every call, which would make a system of n rows cost O(n^2).
*/
static size_t
basis_at(int p, const double *knots, size_t nknots, double u, int ord,
         double *v)
{
    size_t span = cf_knots_find_span(p, knots, nknots, u);
    cf__basis_deriv(p, knots, nknots, NULL, span, u, ord, v);
    return span;
}

/*
** Solve for n B-spline coefficients of degree p on the given knots such
** that row r holds: the ord[r]-th derivative at ru[r] equals rhs[r] (dim
** doubles).  Row r involves the columns span - p .. span of its parameter,
** so the matrix is banded; the band widths are measured first.  rhs is
** replaced by the coefficients.  ord[r] <= 2.
*/
static cf_status_t
collocate(size_t dim, int p, const double *knots, size_t nknots, size_t n,
          const double *ru, const int *ord, double *rhs, cf_diag_t *diag)
{
    double v[CF_BSPLINE_MAX_DEGREE + 1];
    size_t kl = 0, ku = 0;
    cf__band_t band;
    cf_status_t st = cf_knots_validate(p, n, knots, nknots, diag);
    if (st != CF_STATUS_OK)
        return st;
    for (size_t r = 0; r < n; r++) {
        size_t k = cf_knots_find_span(p, knots, nknots, ru[r]);
        size_t first = k - (size_t)p;
        if (r > first && r - first > kl)
            kl = r - first;
        if (k > r && k - r > ku)
            ku = k - r;
    }
    st = cf__band_init(&band, n, kl, ku, diag);
    if (st != CF_STATUS_OK)
        return st;
    for (size_t r = 0; r < n; r++) {
        size_t span = basis_at(p, knots, nknots, ru[r], ord[r], v);
        double big = 0.0;
        /* equilibrate: derivative rows are ~ 1/h^ord times larger than
        ** point rows, which would hide small pivots among large entries */
        for (int j = 0; j <= p; j++)
            big = fmax(big, fabs(v[j]));
        if (big == 0.0)
            big = 1.0;
        for (int j = 0; j <= p; j++)
            if (v[j] != 0.0)
                cf__band_set(&band, r, span - (size_t)p + (size_t)j,
                             v[j] / big);
        for (size_t k = 0; k < dim; k++)
            rhs[r * dim + k] /= big;
    }
    if (st == CF_STATUS_OK) {
        cf_diag_t local;
        cf_diag_clear(&local);
        st = cf__band_factor(&band, &local);
        if (st == CF_STATUS_DEGENERATE)
            st = cf__error(diag, st, local.index,
                           "the interpolation system of degree %d is "
                           "numerically singular at row %ld; the parameters "
                           "are too unevenly spaced for it (try a lower "
                           "degree or centripetal parameters)", p,
                           local.index);
        else if (st != CF_STATUS_OK)
            st = cf__error(diag, st, local.index, "%s", local.msg);
    }
    if (st == CF_STATUS_OK)
        cf__band_solve(&band, rhs, dim);
    cf__band_fini(&band);
    return st;
}

/* Work arrays of one collocation problem, freed together. */
typedef struct colloc {
    double *knots, *ru, *rhs;
    int *ord;
} colloc_t;

static cf_status_t
colloc_alloc(colloc_t *c, size_t nknots, size_t n, size_t dim,
             cf_diag_t *diag)
{
    c->knots = cf__alloc_array(nknots, sizeof *c->knots);
    c->ru = cf__alloc_array(n, sizeof *c->ru);
    c->rhs = cf__calloc(n, dim * sizeof *c->rhs);
    c->ord = cf__calloc(n, sizeof *c->ord);
    if (c->knots == NULL || c->ru == NULL || c->rhs == NULL ||
        c->ord == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "no memory for an interpolation system of %zu "
                         "rows", n);
    return CF_STATUS_OK;
}

static void
colloc_free(colloc_t *c)
{
    cf__free(c->knots);
    cf__free(c->ru);
    cf__free(c->rhs);
    cf__free(c->ord);
}

/* Knots: p + 1 copies of a, then nint interior knots, p + 1 copies of b. */
static size_t
put_clamped(double *knots, int p, double a, const double *interior,
            size_t nint, double b)
{
    size_t m = 0;
    for (int i = 0; i <= p; i++)
        knots[m++] = a;
    for (size_t i = 0; i < nint; i++)
        knots[m++] = interior[i];
    for (int i = 0; i <= p; i++)
        knots[m++] = b;
    return m;
}

/* Row r: derivative `ord` at u equals v (dim doubles, or 0 when NULL). */
static void
put_row(colloc_t *c, size_t dim, size_t r, double u, int ord,
        const double *v)
{
    c->ru[r] = u;
    c->ord[r] = ord;
    if (v != NULL)
        memcpy(c->rhs + r * dim, v, dim * sizeof *v);
}

static cf_status_t
solve_and_create(colloc_t *c, size_t dim, int p, size_t nknots, size_t n,
                 cf_bspline_t **out, cf_diag_t *diag)
{
    cf_status_t st = collocate(dim, p, c->knots, nknots, n, c->ru, c->ord,
                               c->rhs, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_create(dim, p, c->knots, nknots, c->rhs, n, NULL,
                               out, diag);
    colloc_free(c);
    return st;
}

/*
** Natural / clamped cubic: knots {u_0 x4, u_1 .. u_{n-1}, u_n x4}, n + 3
** coefficients.  Rows in band order: C(u_0) = P_0, the start condition
** (C'(u_0) = D_0 or C''(u_0) = 0), C(u_i) = P_i, the end condition,
** C(u_n) = P_n.
*/
cf_status_t
cf__interp_cubic_ends(size_t dim, const double *points, size_t count,
                      const double *u, const double *d0, const double *d1,
                      cf_bspline_t **out, cf_diag_t *diag)
{
    size_t n = count + 2, nknots = count + 6, last = count - 1;
    colloc_t c = { 0 };
    cf_status_t st = colloc_alloc(&c, nknots, n, dim, diag);
    if (st != CF_STATUS_OK) {
        colloc_free(&c);
        return st;
    }
    put_clamped(c.knots, 3, u[0], u + 1, count - 2, u[last]);
    put_row(&c, dim, 0, u[0], 0, points);
    put_row(&c, dim, 1, u[0], d0 != NULL ? 1 : 2, d0);
    for (size_t i = 1; i < last; i++)
        put_row(&c, dim, i + 1, u[i], 0, points + i * dim);
    put_row(&c, dim, count, u[last], d1 != NULL ? 1 : 2, d1);
    put_row(&c, dim, count + 1, u[last], 0, points + last * dim);
    return solve_and_create(&c, dim, 3, nknots, n, out, diag);
}

/*
** Not-a-knot: the cubic spline whose third derivative is continuous at u_1
** and u_{n-1}, i.e. those two are not knots at all: knots {u_0 x4, u_2 ..
** u_{n-2}, u_n x4} and exactly count coefficients, one row per point.
*/
cf_status_t
cf__interp_not_a_knot(size_t dim, const double *points, size_t count,
                      const double *u, cf_bspline_t **out, cf_diag_t *diag)
{
    size_t nknots = count + 4;
    colloc_t c = { 0 };
    cf_status_t st = colloc_alloc(&c, nknots, count, dim, diag);
    if (st != CF_STATUS_OK) {
        colloc_free(&c);
        return st;
    }
    put_clamped(c.knots, 3, u[0], u + 2, count - 4, u[count - 1]);
    for (size_t i = 0; i < count; i++)
        put_row(&c, dim, i, u[i], 0, points + i * dim);
    return solve_and_create(&c, dim, 3, nknots, count, out, diag);
}

/*
** Global interpolation (The NURBS Book A9.1, and §9.2.2 for end
** derivatives).  With v the parameters with u_0 repeated when D_0 is given
** and u_n repeated when D_n is given (N = count + #derivatives values),
** the interior knots are the averages u_{j+p} = (v_j + ... + v_{j+p-1}) / p,
** j = 1 .. N - p - 1 (eq. 9.8; with both derivatives this is eq. 9.22), and
** row r is the condition at v_r: a point, or a derivative for the repeated
** parameter.
*/
cf_status_t
cf__interp_global(size_t dim, const double *points, size_t count,
                  const double *u, int p, const double *d0, const double *d1,
                  cf_bspline_t **out, cf_diag_t *diag)
{
    size_t n = count + (d0 != NULL) + (d1 != NULL);
    size_t nknots = n + (size_t)p + 1, r = 0, last = count - 1;
    colloc_t c = { 0 };
    cf_status_t st = colloc_alloc(&c, nknots, n, dim, diag);
    if (st != CF_STATUS_OK) {
        colloc_free(&c);
        return st;
    }
    put_row(&c, dim, r++, u[0], 0, points);
    if (d0 != NULL)
        put_row(&c, dim, r++, u[0], 1, d0);
    for (size_t i = 1; i < last; i++)
        put_row(&c, dim, r++, u[i], 0, points + i * dim);
    if (d1 != NULL)
        put_row(&c, dim, r++, u[last], 1, d1);
    put_row(&c, dim, r++, u[last], 0, points + last * dim);
    /* knots: the row parameters are exactly v */
    for (int i = 0; i <= p; i++) {
        c.knots[i] = u[0];
        c.knots[nknots - 1 - (size_t)i] = u[last];
    }
    for (size_t j = 1; j + (size_t)p < n; j++) {
        double s = 0.0;
        for (size_t i = j; i < j + (size_t)p; i++)
            s += c.ru[i];
        c.knots[j + (size_t)p] = s / p;
    }
    return solve_and_create(&c, dim, p, nknots, n, out, diag);
}

/*
** Periodic cubic through P_0..P_{n-1} (n = count), closing at u_n.  The
** knots continue the parameters periodically with period L = u_n - u_0:
** k_j = u_{j-3} for j = 0 .. n + 6 (u_{-i} = u_{n-i} - L, u_{n+i} = u_i
** + L), and the n + 3 control points wrap, Q_{j+n} = Q_j (j < 3).  At
** u_i = k_{i+3} only N_i, N_{i+1}, N_{i+2} are nonzero, so with E_i =
** Q_{i+1} (indices mod n) the conditions C(u_i) = P_i read
**     N_i(u_i) E_{i-1} + N_{i+1}(u_i) E_i + N_{i+2}(u_i) E_{i+1} = P_i:
** a cyclic tridiagonal system.
*/
cf_status_t
cf__interp_periodic(size_t dim, const double *points, size_t count,
                    const double *u, cf_bspline_t **out, cf_diag_t *diag)
{
    size_t n = count, nknots = count + 7, ncoef = count + 3;
    double L = u[n] - u[0], N[4];
    double *knots, *sub, *mid, *sup, *rhs, *ctrl;
    cf_status_t st = CF_STATUS_OK;
    knots = cf__alloc_array(nknots, sizeof *knots);
    sub = cf__alloc_array(n, 3 * sizeof *sub);
    rhs = cf__alloc_array(n, dim * sizeof *rhs);
    ctrl = cf__alloc_array(ncoef, dim * sizeof *ctrl);
    if (knots == NULL || sub == NULL || rhs == NULL || ctrl == NULL) {
        st = cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                       "no memory for a periodic spline of %zu points", n);
        goto done;
    }
    mid = sub + n;
    sup = sub + 2 * n;
    for (size_t j = 0; j < nknots; j++) {
        if (j < 3)
            knots[j] = u[n - 3 + j] - L;
        else if (j <= n + 3)
            knots[j] = u[j - 3];
        else
            knots[j] = u[j - 3 - n] + L;
    }
    st = cf_knots_validate(3, ncoef, knots, nknots, diag);
    if (st != CF_STATUS_OK)
        goto done;
    for (size_t i = 0; i < n; i++) {
        size_t span = basis_at(3, knots, nknots, u[i], 0, N);
        /* u_i = k_{i+3} < k_{i+4}: the parameters increase strictly (given
        ** ones are checked, made ones too: cf__interp_prepare_params), so
        ** this does not fail; kept because a wrong span would make a wrong
        ** system and a wrong curve without a word */
        if (span != i + 3) {
            st = cf__error(diag, CF_STATUS_DEGENERATE, (long)i,
                           "parameter %zu (%s) is not in its own knot span",
                           i, CF__NUM(u[i]));
            goto done;
        }
        sub[i] = N[0];
        mid[i] = N[1];
        sup[i] = N[2];
    }
    memcpy(rhs, points, n * dim * sizeof *rhs);
    st = cf__solve_cyclic_tridiagonal(n, sub, mid, sup, rhs, dim, diag);
    if (st != CF_STATUS_OK)
        goto done;
    for (size_t j = 0; j < ncoef; j++)
        memcpy(ctrl + j * dim, rhs + ((j + n - 1) % n) * dim,
               dim * sizeof *ctrl);
    st = cf_bspline_create(dim, 3, knots, nknots, ctrl, ncoef, NULL, out,
                           diag);
done:
    cf__free(knots);
    cf__free(sub);
    cf__free(rhs);
    cf__free(ctrl);
    return st;
}

/* Barry-Goldman tangent at p (parameter ui) between pp (up) and pn (un):
** the derivative at ui of the Catmull-Rom pyramid,
**   (p - pp)/(ui - up) - (pn - pp)/(un - up) + (pn - p)/(un - ui). */
static void
bg_tangent(size_t dim, const double *pp, double up, const double *p,
           double ui, const double *pn, double un, double *m)
{
    for (size_t k = 0; k < dim; k++)
        m[k] = (p[k] - pp[k]) / (ui - up) - (pn[k] - pp[k]) / (un - up) +
               (pn[k] - p[k]) / (un - ui);
}

cf_status_t
cf__interp_catmull_rom(size_t dim, const double *points, size_t count,
                       const double *u, bool closed, cf_bspline_t **out,
                       cf_diag_t *diag)
{
    size_t nseg = closed ? count : count - 1;
    size_t ncoef = 2 * nseg + 2, nknots = 2 * nseg + 6;
    double L = u[nseg] - u[0];
    double *m, *ctrl, *knots;
    cf_status_t st;
    m = cf__alloc_array(nseg + 1, dim * sizeof *m);
    ctrl = cf__alloc_array(ncoef, dim * sizeof *ctrl);
    knots = cf__alloc_array(nknots, sizeof *knots);
    if (m == NULL || ctrl == NULL || knots == NULL) {
        st = cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                       "no memory for a Catmull-Rom spline of %zu points",
                       count);
        goto done;
    }
    /* tangents at the nodes 0 .. nseg (node nseg is P_0 again if closed) */
    for (size_t i = 0; i <= nseg; i++) {
        const double *p = points + (i % count) * dim;
        if (closed) {
            size_t ip = (i + count - 1) % count, in = (i + 1) % count;
            double up = i > 0 ? u[i - 1] : u[count - 1] - L;
            double un = i < nseg ? u[i + 1] : u[1] + L;
            bg_tangent(dim, points + ip * dim, up, p, u[i],
                       points + in * dim, un, m + i * dim);
        } else if (i == 0 || i == nseg) {
            /* phantom points reflected through the ends: the chord */
            size_t a = i == 0 ? 0 : i - 1;
            for (size_t k = 0; k < dim; k++)
                m[i * dim + k] = (points[(a + 1) * dim + k] -
                                  points[a * dim + k]) /
                                 (u[a + 1] - u[a]);
        } else {
            bg_tangent(dim, p - dim, u[i - 1], p, u[i], p + dim, u[i + 1],
                       m + i * dim);
        }
    }
    memcpy(ctrl, points, dim * sizeof *ctrl);
    for (size_t s = 0; s < nseg; s++) {
        const double *a = points + s * dim;
        const double *b = points + ((s + 1) % count) * dim;
        double h = (u[s + 1] - u[s]) / 3.0;
        for (size_t k = 0; k < dim; k++) {
            ctrl[(2 * s + 1) * dim + k] = a[k] + h * m[s * dim + k];
            ctrl[(2 * s + 2) * dim + k] = b[k] - h * m[(s + 1) * dim + k];
        }
    }
    memcpy(ctrl + (ncoef - 1) * dim, points + (nseg % count) * dim,
           dim * sizeof *ctrl);
    for (size_t i = 0; i < 4; i++) {
        knots[i] = u[0];
        knots[nknots - 1 - i] = u[nseg];
    }
    for (size_t i = 1; i < nseg; i++)
        knots[2 * i + 2] = knots[2 * i + 3] = u[i];
    st = cf_bspline_create(dim, 3, knots, nknots, ctrl, ncoef, NULL, out,
                           diag);
done:
    cf__free(m);
    cf__free(ctrl);
    cf__free(knots);
    return st;
}

/* ---- least squares ------------------------------------------------------ */

static cf_status_t
lsq_check(size_t dim, const double *points, size_t count, size_t ncontrol,
          const cf_interp_options_t *o, cf_diag_t *diag)
{
    int p = o->degree == 0 ? 3 : o->degree;
    if (dim < 1 || points == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "needs dim >= 1 and points");
    if (o->start_tangent != NULL || o->end_tangent != NULL || o->closed)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "least squares takes no end tangents and cannot "
                         "be closed");
    if (p < 1 || p > CF_BSPLINE_MAX_DEGREE)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "least-squares degree %d is outside 1..%d", p,
                         CF_BSPLINE_MAX_DEGREE);
    if (ncontrol < (size_t)p + 1)
        return cf__error(diag, CF_STATUS_TOO_FEW_POINTS, (long)ncontrol,
                         "a B-spline of degree %d needs at least %d control "
                         "points, got %zu", p, p + 1, ncontrol);
    if (count < ncontrol)
        return cf__error(diag, CF_STATUS_TOO_FEW_POINTS, (long)count,
                         "least squares with %zu control points needs at "
                         "least %zu points, got %zu", ncontrol, ncontrol,
                         count);
    return CF_STATUS_OK;
}

/*
** Knots of eq. 9.69: with m + 1 data parameters and n + 1 control points,
** d = (m + 1) / (n - p + 1); for j = 1 .. n - p, i = floor(j d),
** a = j d - i and u_{p+j} = (1 - a) u_{i-1} + a u_i.  Since d > 1 every
** knot span holds at least one parameter (Schoenberg-Whitney), so the
** matrix has full rank.
*/
static void
lsq_knots(const double *u, size_t count, size_t ncontrol, int p,
          double *knots)
{
    size_t n = ncontrol - 1, m = count - 1, nk = ncontrol + (size_t)p + 1;
    double d = (double)(m + 1) / (double)(n - (size_t)p + 1);
    for (int i = 0; i <= p; i++) {
        knots[i] = u[0];
        knots[nk - 1 - (size_t)i] = u[m];
    }
    for (size_t j = 1; j + (size_t)p <= n; j++) {
        double jd = (double)j * d;
        size_t i = (size_t)floor(jd);
        double a = jd - (double)i;
        knots[(size_t)p + j] = (1.0 - a) * u[i - 1] + a * u[i];
    }
}

cf_status_t
cf_approximate_lsq(size_t dim, const double *points, size_t count,
                   size_t ncontrol, const cf_interp_options_t *opt,
                   bool fix_ends, cf_bspline_t **out, double *residual,
                   cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_interp_options_t o;
    cf__lsq_band_t lb = { 0 };
    double *u = NULL, *knots = NULL, *b = NULL, *x = NULL;
    double *ctrl = NULL, *ev = NULL, N[CF_BSPLINE_MAX_DEGREE + 1];
    double v[CF_BSPLINE_MAX_DEGREE + 1];
    size_t first, unk, nk, n;
    int p;
    cf_status_t st;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "out must not be NULL");
    *out = NULL;
    if (opt != NULL)
        o = *opt;
    else
        cf_interp_options_init(&o);
    o.method = CF_INTERP_GLOBAL;
    st = lsq_check(dim, points, count, ncontrol, &o, diag);
    if (st != CF_STATUS_OK)
        return st;
    st = cf__check_finite_points(points, count, dim, dim, "point", diag);
    if (st != CF_STATUS_OK)
        return st;
    p = o.degree == 0 ? 3 : o.degree;
    n = ncontrol - 1;
    nk = ncontrol + (size_t)p + 1;
    first = fix_ends ? 1 : 0;
    unk = ncontrol - 2 * first;
    u = cf__alloc_array(count, sizeof *u);
    knots = cf__alloc_array(nk, sizeof *knots);
    b = cf__alloc_array(dim, sizeof *b);
    x = cf__alloc_array(unk > 0 ? unk : 1, dim * sizeof *x);
    ctrl = cf__alloc_array(ncontrol, dim * sizeof *ctrl);
    ev = cf__alloc_array(count, dim * sizeof *ev);
    if (u == NULL || knots == NULL || b == NULL || x == NULL ||
        ctrl == NULL || ev == NULL) {
        st = cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                       "no memory for least squares with %zu points and "
                       "%zu control points", count, ncontrol);
        goto done;
    }
    st = cf__interp_prepare_params(dim, points, count, &o, false, false, u,
                                   diag);
    if (st != CF_STATUS_OK)
        goto done;
    lsq_knots(u, count, ncontrol, p, knots);
    st = cf_knots_validate(p, ncontrol, knots, nk, diag);
    if (st != CF_STATUS_OK)
        goto done;
    /* one row per inner data point: sum_j N_j(u_k) Q_j = P_k, the fixed
    ** ends moved to the right-hand side; the p + 1 nonzeros of a row are
    ** consecutive and their spans grow with k, so Givens rotations row by
    ** row solve it in O(count p^2) time and O(ncontrol p) memory */
    if (unk > 0) {
        st = cf__lsq_band_init(&lb, unk, (size_t)p + 1, dim, diag);
        if (st != CF_STATUS_OK)
            goto done;
        for (size_t k = first; k < count - first; k++) {
            size_t span = basis_at(p, knots, nk, u[k], 0, N);
            size_t ws = span - (size_t)p;
            size_t start = ws >= first ? ws - first : 0;
            memcpy(b, points + k * dim, dim * sizeof *b);
            memset(v, 0, ((size_t)p + 1) * sizeof *v);
            for (int j = 0; j <= p; j++) {
                size_t col = ws + (size_t)j;
                if (fix_ends && (col == 0 || col == n)) {
                    const double *e = col == 0 ? points
                                               : points + (count - 1) * dim;
                    for (size_t c = 0; c < dim; c++)
                        b[c] -= N[j] * e[c];
                } else {
                    v[col - first - start] = N[j];
                }
            }
            cf__lsq_band_add(&lb, start, v, b);
        }
        st = cf__lsq_band_solve(&lb, x, diag);
        if (st != CF_STATUS_OK)
            goto done;
    }
    if (fix_ends) {
        memcpy(ctrl, points, dim * sizeof *ctrl);
        memcpy(ctrl + n * dim, points + (count - 1) * dim,
               dim * sizeof *ctrl);
    }
    if (unk > 0)
        memcpy(ctrl + first * dim, x, unk * dim * sizeof *ctrl);
    st = cf_bspline_create(dim, p, knots, nk, ctrl, ncontrol, NULL, out,
                           diag);
    if (st != CF_STATUS_OK)
        goto done;
    if (residual != NULL) {
        double s = 0.0;
        st = cf_bspline_eval_many(*out, u, count, ev);
        if (st != CF_STATUS_OK) {
            cf_bspline_destroy(*out);
            *out = NULL;
            goto done;
        }
        for (size_t i = 0; i < count * dim; i++)
            s += (ev[i] - points[i]) * (ev[i] - points[i]);
        *residual = sqrt(s);
    }
done:
    cf__lsq_band_fini(&lb);
    cf__free(u);
    cf__free(knots);
    cf__free(b);
    cf__free(x);
    cf__free(ctrl);
    cf__free(ev);
    return st;
}
