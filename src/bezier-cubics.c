/*
** Conversion of a Bézier curve to a chain of polynomial cubic segments (for
** path output: SVG `C`, PDF `c`, cairo_curve_to).
**
** Degree <= 3 polynomial curves are converted exactly (degree raised to 3).
** Planar curves otherwise go through the cubic fitting at d = 0
** (cf__fit_plain, fit-chain.c / fit-piece.c): split at the zeros of c', each
** piece covered by the longest cubics matching end points, end tangents,
** signed area and x-moment (Levien), accepted by their measured two-sided
** Hausdorff distance.
** Curves in other dimensions are fitted piece by piece: on [a, b] the cubic
** Hermite
** interpolant of the end points and end derivatives (scaled by b - a), i.e.
** P1 = c(a) + (b-a)/3 c'(a), P2 = c(b) - (b-a)/3 c'(b).  Its distance to the
** curve is measured as max |H(u) - c(a + u (b-a))| over SAMPLES + 1 evenly
** spaced u, which bounds the distance between the two curves from above at
** those samples (a parametric correspondence); pieces above tol are halved.
**
** cf_bezier_to_cubics_bounded (polynomial curves of degree >= 4, any
** dimension) measures nothing: cubic Hermite interpolation on a piece of
** parameter length h errs by at most (t-a)^2 (t-b)^2 / 4! max|c^(4)| <=
** h^4 / 384 max|c^(4)| in every coordinate (the classical remainder), and
** max|c^(4)| is bounded by the hull of the fourth-difference control
** points; so N = ceil((max|c^(4)| / (384 tol))^(1/4)) uniform pieces are
** within tol, parameter for parameter, hence also in Hausdorff distance.
** More pieces than the Levien fit, a thousand times less work: for drawing.
** Rational curves, which have no such cheap bound, are drawn from the
** measured Hermite halving above (in the plane too): about four times the
** pieces of the Levien fit for some fifteen times less work.
*/
#include <math.h>
#include <string.h>

#include "bezier-private.h"
#include "fit-private.h"
#include "numtext-private.h"

#define SAMPLES 48        /* samples per piece for the error measure */
#define MAX_DEPTH 40      /* halvings of [0, 1] */
#define MAX_SEGMENTS 1000000

typedef struct fit {
    const cf_bezier_t *c;
    double tol;
    size_t dim;
    double *pts, *t;      /* growing result arrays */
    size_t count, cap;
    double max_error;
    double *work;         /* d0, d1, q, seg (4 dim), scratch (2 dim) */
} fit;

/* The point p[dim] and derivative d[dim] of c at t, through
** scratch[2 * dim]. */
static void
point_and_deriv(const cf_bezier_t *c, double t, double *p, double *d,
                double *scratch)
{
    cf__bezier_derivs(c, t, 1, scratch);
    memcpy(p, scratch, c->dim * sizeof *p);
    memcpy(d, scratch + c->dim, c->dim * sizeof *d);
}

static cf_status_t
push(fit *f, const double *seg, double a, double b)
{
    if (f->count == f->cap) {
        size_t cap = f->cap;
        double *p = cf__grow(f->pts, &cap, f->count + 1,
                             4 * f->dim * sizeof *p, 16);
        double *t;
        if (p == NULL)
            return CF_STATUS_NO_MEMORY;
        f->pts = p;
        t = cf__realloc_array(f->t, cap + 1, sizeof *t);
        if (t == NULL)
            return CF_STATUS_NO_MEMORY;
        f->t = t;
        f->cap = cap;
    }
    memcpy(f->pts + f->count * 4 * f->dim, seg, 4 * f->dim * sizeof *seg);
    if (f->count == 0)
        f->t[0] = a;
    f->t[f->count + 1] = b;
    f->count++;
    return CF_STATUS_OK;
}

/* The fitted cubic on [a, b] into seg[4 * dim]; its measured error. */
static double
fit_piece(fit *f, double a, double b, double *seg)
{
    size_t dim = f->dim;
    double *d0 = f->work, *d1 = f->work + dim, *q = f->work + 2 * dim;
    double h = b - a, err = 0.0;

    point_and_deriv(f->c, a, seg, d0, f->work + 7 * dim);
    point_and_deriv(f->c, b, seg + 3 * dim, d1, f->work + 7 * dim);
    for (size_t k = 0; k < dim; k++) {
        seg[dim + k] = seg[k] + h / 3.0 * d0[k];
        seg[2 * dim + k] = seg[3 * dim + k] - h / 3.0 * d1[k];
    }
    for (int i = 1; i < SAMPLES; i++) {
        double u = (double)i / SAMPLES, e2 = 0.0, *hu = f->work + 7 * dim;
        cf__bezier_eval_point(f->c, a + u * h, q);
        cf__bp_curve_derivs(seg, NULL, dim, dim, 3, u, 0, hu);
        for (size_t k = 0; k < dim; k++)
            e2 += (hu[k] - q[k]) * (hu[k] - q[k]);
        err = fmax(err, sqrt(e2));
    }
    return err;
}

static cf_status_t
fit_range(fit *f, double a, double b, int depth, double *seg)
{
    double err = fit_piece(f, a, b, seg);
    cf_status_t st;
    if (err <= f->tol) {
        f->max_error = fmax(f->max_error, err);
        return push(f, seg, a, b);
    }
    if (depth >= MAX_DEPTH || f->count >= MAX_SEGMENTS)
        return CF_STATUS_NO_CONVERGENCE;
    st = fit_range(f, a, 0.5 * (a + b), depth + 1, seg);
    if (st != CF_STATUS_OK)
        return st;
    return fit_range(f, 0.5 * (a + b), b, depth + 1, seg);
}

/* The arguments of both conversions; *out = NULL when out is given. */
static cf_status_t
check_args(const cf_bezier_t *c, double tol, cf_cubics_t **out,
           cf_diag_t *diag)
{
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "the output pointer is NULL");
    *out = NULL;
    if (c == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "the curve is NULL");
    if (!(tol > 0.0) || !isfinite(tol))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "tolerance %s must be finite and positive",
                         CF__NUM(tol));
    return CF_STATUS_OK;
}

static cf_status_t hermite_halving(const cf_bezier_t *c, double tol,
                                   cf_cubics_t **out, cf_diag_t *diag);

cf_status_t
cf_bezier_to_cubics(const cf_bezier_t *c, double tol, cf_cubics_t **out,
                    cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st;

    st = check_args(c, tol, out, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (!c->rational && c->degree <= 3) {
        if (cf__cubics_exact(c, out) != CF_STATUS_OK)
            return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                             "out of memory (cubic segments)");
        return CF_STATUS_OK;
    }
    if (c->dim == 2) {
        cf_cubics_t *fit2 = NULL;
        bool converged = true;
        if (cf__deriv_scale(c) == 0.0) {
            /* a single point: one constant segment */
            double p[2], pt4[8];
            cf__chain_t ch;
            cf__bezier_eval_point(c, 0.0, p);
            for (int k = 0; k < 4; k++) {
                pt4[2 * k] = p[0];
                pt4[2 * k + 1] = p[1];
            }
            st = cf__chain_init(&ch);
            if (st == CF_STATUS_OK)
                st = cf__chain_push(&ch, pt4, 0.0, 1.0);
            if (st != CF_STATUS_OK) {
                cf__chain_fini(&ch);
                return cf__error(diag, st, -1,
                                 "out of memory (cubic segments)");
            }
            *out = cf__chain_take(&ch);
            return CF_STATUS_OK;
        }
        st = cf__fit_plain(c, tol, &fit2, &converged);
        if (st == CF_STATUS_NO_MEMORY)
            return cf__error(diag, st, -1, "out of memory (cubic segments)");
        if (st == CF_STATUS_OK && !(converged && fit2->max_error <= tol)) {
            cf_cubics_destroy(fit2);
            st = CF_STATUS_NO_CONVERGENCE;
        }
        if (st != CF_STATUS_OK)
            return cf__error(diag, st, -1,
                             "no cubic fit within %s of the curve",
                             CF__NUM(tol));
        *out = fit2;
        return CF_STATUS_OK;
    }
    return hermite_halving(c, tol, out, diag);
}

/* The Hermite pieces of c halved until their distance measured at the
** SAMPLES - 1 interior parameters is <= tol. */
static cf_status_t
hermite_halving(const cf_bezier_t *c, double tol, cf_cubics_t **out,
                cf_diag_t *diag)
{
    cf_cubics_t *r;
    fit f;
    double *seg;
    cf_status_t st;
    r = cf__calloc(1, sizeof *r);
    if (r == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory (cubic segments)");
    r->dim = c->dim;
    memset(&f, 0, sizeof f);
    f.c = c;
    f.tol = tol;
    f.dim = c->dim;
    f.work = cf__alloc_array(9 * c->dim, sizeof *f.work);
    if (f.work == NULL) {
        cf__free(r);
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory (cubic segments)");
    }
    seg = f.work + 3 * c->dim;
    st = fit_range(&f, 0.0, 1.0, 0, seg);
    cf__free(f.work);
    if (st != CF_STATUS_OK) {
        cf__free(f.pts);
        cf__free(f.t);
        cf__free(r);
        if (st == CF_STATUS_NO_MEMORY)
            return cf__error(diag, st, -1, "out of memory (cubic segments)");
        return cf__error(diag, st, -1,
                         "no cubic fit within %s after %d halvings",
                         CF__NUM(tol), MAX_DEPTH);
    }
    r->pts = f.pts;
    r->t = f.t;
    r->count = f.count;
    r->max_error = f.max_error;
    *out = r;
    return CF_STATUS_OK;
}

/* A bound of |c^(4)| over [0, 1]: coordinate by coordinate the fourth
** derivative is the Bezier curve of the n!/(n-4)! Delta^4 P_i, inside the
** hull of those values; the maxima are combined as a vector norm.  A
** non-finite result means overflow. */
static double
fourth_derivative_bound(const cf_bezier_t *c)
{
    size_t dim = c->dim, hd = c->hdim;
    int n = c->degree;
    double k = (double)n * (n - 1) * (n - 2) * (n - 3), m2 = 0.0;
    for (size_t j = 0; j < dim; j++) {
        double mj = 0.0;
        for (int i = 0; i + 4 <= n; i++) {
            const double *p = c->pts + (size_t)i * hd + j;
            double d4 = p[0] - 4.0 * p[hd] + 6.0 * p[2 * hd]
                        - 4.0 * p[3 * hd] + p[4 * hd];
            mj = fmax(mj, fabs(d4));
        }
        m2 += (k * mj) * (k * mj);
    }
    return sqrt(m2);
}

cf_status_t
cf_bezier_to_cubics_bounded(const cf_bezier_t *c, double tol,
                            cf_cubics_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_cubics_t *r;
    size_t dim, count;
    double m4, pieces, *d0, *d1;
    cf_status_t st = check_args(c, tol, out, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (!c->rational && c->degree <= 3)
        return cf_bezier_to_cubics(c, tol, out, diag);
    if (c->rational)
        return hermite_halving(c, tol, out, diag);
    dim = c->dim;
    m4 = fourth_derivative_bound(c);
    if (!isfinite(m4))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "the fourth derivative of the curve overflows "
                         "(control points too large)");
    /* N pieces of length h = 1/N with h^4/384 * m4 <= tol */
    pieces = m4 > 0.0 ? ceil(pow(m4 / (384.0 * tol), 0.25)) : 1.0;
    if (!(pieces <= MAX_SEGMENTS))
        return cf__error(diag, CF_STATUS_NO_CONVERGENCE, -1,
                         "%.3g cubic pieces would be needed for %s "
                         "(at most %d)", pieces, CF__NUM(tol), MAX_SEGMENTS);
    count = (size_t)fmax(pieces, 1.0);
    r = cf__calloc(1, sizeof *r);
    d0 = cf__alloc_array(4 * dim, sizeof *d0);
    if (r != NULL) {
        r->pts = cf__alloc_array(count, 4 * dim * sizeof *r->pts);
        r->t = cf__alloc_array(count + 1, sizeof *r->t);
    }
    if (r == NULL || d0 == NULL || r->pts == NULL || r->t == NULL) {
        cf_cubics_destroy(r);
        cf__free(d0);
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory (%zu cubic segments)", count);
    }
    d1 = d0 + dim;
    r->dim = dim;
    r->count = count;
    r->t[0] = 0.0;
    point_and_deriv(c, 0.0, r->pts, d0, d0 + 2 * dim);
    for (size_t i = 0; i < count; i++) {
        double *seg = r->pts + 4 * dim * i;
        double b = i + 1 == count ? 1.0 : (double)(i + 1) / (double)count;
        double h = b - r->t[i];
        if (i > 0) {
            /* the previous end, shared exactly: the chain is C1 */
            memcpy(seg, seg - dim, dim * sizeof *seg);
            memcpy(d0, d1, dim * sizeof *d0);
        }
        point_and_deriv(c, b, seg + 3 * dim, d1, d0 + 2 * dim);
        for (size_t k = 0; k < dim; k++) {
            seg[dim + k] = seg[k] + h / 3.0 * d0[k];
            seg[2 * dim + k] = seg[3 * dim + k] - h / 3.0 * d1[k];
        }
        r->t[i + 1] = b;
    }
    /* the bound itself: h^4/384 max|c^(4)| with h = 1/N */
    r->max_error = m4 / (384.0 * pow((double)count, 4.0));
    cf__free(d0);
    *out = r;
    return CF_STATUS_OK;
}
