/*
** Geometry of Bézier curves: tight bounding box, arc length, closest point,
** flattening to a polyline, degree reduction.
**
** Extremes and closest points are roots of polynomials in the Bernstein
** form (cf__bp_roots, by subdivision with Descartes' rule of signs).
*/
#include <float.h>
#include <math.h>
#include <string.h>

#include "bezier-private.h"

#define MAXN CF_BEZIER_MAX_DEGREE

/* Room for the roots of a polynomial of degree m. */
#define ROOTS_CAP(m) (2 * ((size_t)(m) + 1) + 8)

/*
** Coefficients (degree returned) of the numerator of the derivative of
** Cartesian coordinate k: polynomial n (P_{i+1} - P_i) (degree n - 1);
** rational A' w - A w' (degree 2n - 1), whose sign is that of x'.
*/
static int
deriv_numerator(const cf_bezier_t *c, size_t k, double *out, double *tmp)
{
    int n = c->degree;
    size_t h = c->hdim;
    if (!c->rational) {
        for (int i = 0; i < n; i++)
            out[i] = (double)n * (c->pts[(size_t)(i + 1) * h + k] -
                                  c->pts[(size_t)i * h + k]);
        return n - 1;
    }
    /* tmp: A' then w' (degree n - 1 each) */
    for (int i = 0; i < n; i++) {
        tmp[i] = (double)n * (c->pts[(size_t)(i + 1) * h + k] -
                              c->pts[(size_t)i * h + k]);
        tmp[n + i] = (double)n * (c->pts[(size_t)(i + 1) * h + c->dim] -
                                  c->pts[(size_t)i * h + c->dim]);
    }
    cf__bp_mul(tmp, n - 1, 1, c->pts + c->dim, n, h, out, 1, 1.0, false);
    cf__bp_mul(c->pts + k, n, h, tmp + n, n - 1, 1, out, 1, -1.0, true);
    return 2 * n - 1;
}

/* ---- bounding box ----------------------------------------------------------- */

static double
coord_at(const cf_bezier_t *c, size_t k, double t)
{
    double v;
    cf__bezier_coord_derivs(c, k, t, 0, &v);
    return v;
}

cf_status_t
cf_bezier_bbox(const cf_bezier_t *c, double *lo, double *hi)
{
    double *coef, *rt;
    size_t nr;
    int n, m;
    if (c == NULL || lo == NULL || hi == NULL)
        return CF_STATUS_INVALID_ARG;
    n = c->degree;
    for (size_t k = 0; k < c->dim; k++) {
        double a = coord_at(c, k, 0.0), b = coord_at(c, k, 1.0);
        lo[k] = fmin(a, b);
        hi[k] = fmax(a, b);
    }
    if (n < 2 && !c->rational)
        return CF_STATUS_OK;   /* a segment or a point: the ends */
    if (n < 1)
        return CF_STATUS_OK;
    m = c->rational ? 2 * n - 1 : n - 1;
    if (m > MAXN)
        return CF_STATUS_BAD_DEGREE;
    coef = cf__alloc_array(((size_t)m + 1) + 2 * (size_t)n + ROOTS_CAP(m),
                           sizeof *coef);
    if (coef == NULL)
        return CF_STATUS_NO_MEMORY;
    rt = coef + ((size_t)m + 1) + 2 * (size_t)n;
    for (size_t k = 0; k < c->dim; k++) {
        deriv_numerator(c, k, coef, coef + m + 1);
        if (cf__bp_roots(coef, m, rt, ROOTS_CAP(m), &nr) != CF_STATUS_OK) {
            cf__free(coef);
            return CF_STATUS_NO_MEMORY;
        }
        for (size_t i = 0; i < nr; i++) {
            double v = coord_at(c, k, rt[i]);
            lo[k] = fmin(lo[k], v);
            hi[k] = fmax(hi[k], v);
        }
    }
    cf__free(coef);
    return CF_STATUS_OK;
}

/* ---- arc length ------------------------------------------------------------- */

/* Gauss-Legendre nodes (positive half) and weights on [-1, 1]. */
static const double gl8[4][2] = {
    { 0.960289856497536231684, 0.101228536290376259153 },
    { 0.796666477413626739592, 0.222381034453374470544 },
    { 0.525532409916328985818, 0.313706645877887287338 },
    { 0.183434642495649804939, 0.362683783378361982965 },
};
static const double gl16[8][2] = {
    { 0.989400934991649932596, 0.0271524594117540948518 },
    { 0.944575023073232576078, 0.0622535239386478928628 },
    { 0.86563120238783174388, 0.0951585116824927848099 },
    { 0.755404408355003033895, 0.124628971255533872052 },
    { 0.617876244402643748447, 0.149595988816576732082 },
    { 0.458016777657227386342, 0.169156519395002538189 },
    { 0.28160355077925891323, 0.182603415044923588867 },
    { 0.0950125098376374401853, 0.189450610455068496285 },
};

static double
speed(const cf_bezier_t *c, double t)
{
    double res[2], s = 0.0;
    for (size_t k = 0; k < c->dim; k++) {
        cf__bezier_coord_derivs(c, k, t, 1, res);
        s += res[1] * res[1];
    }
    return sqrt(s);
}

static double
gauss(const cf_bezier_t *c, double a, double b, const double (*g)[2],
      int half)
{
    double m = 0.5 * (a + b), h = 0.5 * (b - a), s = 0.0;
    for (int i = 0; i < half; i++)
        s += g[i][1] * (speed(c, m - h * g[i][0]) + speed(c, m + h * g[i][0]));
    return s * h;
}

/* Adds the length of [a, b] to *sum with error <= tol (estimated by the
** difference of the 8- and 16-point rules, the latter being much more
** accurate). */
static cf_status_t
length_rec(const cf_bezier_t *c, double a, double b, double tol, int depth,
           double *sum)
{
    double g16 = gauss(c, a, b, gl16, 8), g8 = gauss(c, a, b, gl8, 4);
    cf_status_t st;
    if (fabs(g16 - g8) <= tol) {
        *sum += g16;
        return CF_STATUS_OK;
    }
    if (depth >= 50)
        return CF_STATUS_NO_CONVERGENCE;
    st = length_rec(c, a, 0.5 * (a + b), 0.5 * tol, depth + 1, sum);
    if (st != CF_STATUS_OK)
        return st;
    return length_rec(c, 0.5 * (a + b), b, 0.5 * tol, depth + 1, sum);
}

cf_status_t
cf_bezier_length(const cf_bezier_t *c, double tol, double *length)
{
    double sum = 0.0;
    cf_status_t st = CF_STATUS_OK;
    if (c == NULL || length == NULL || !(tol > 0.0) || !isfinite(tol))
        return CF_STATUS_INVALID_ARG;
    /* four starting pieces keep a lucky agreement of the two rules on the
    ** whole interval from ending the refinement too early */
    for (int i = 0; i < 4 && st == CF_STATUS_OK; i++)
        st = length_rec(c, i / 4.0, (i + 1) / 4.0, tol / 4.0, 0, &sum);
    if (st != CF_STATUS_OK)
        return st;
    *length = sum;
    return CF_STATUS_OK;
}

/* ---- closest point ---------------------------------------------------------- */

cf_status_t
cf_bezier_closest(const cf_bezier_t *c, const double *p, double *t,
                  double *distance)
{
    int n, m;
    size_t h, dim, n1;
    double *buf, *coef, *num, *e, *tmp, *q, *rt, best_t = 0.0,
           best = INFINITY;
    size_t nr = 0;

    if (c == NULL || p == NULL)
        return CF_STATUS_INVALID_ARG;
    dim = c->dim;
    for (size_t k = 0; k < dim; k++)
        if (!isfinite(p[k]))
            return CF_STATUS_NOT_FINITE;
    n = c->degree;
    h = c->hdim;
    n1 = (size_t)n + 1;
    /* f(t) = (c(t) - p) . c'(t) vanishes at every interior local minimum of
    ** the distance.  Its numerator: polynomial sum_k (P_k - p_k) x_k',
    ** degree 2n - 1; rational sum_k (A_k - p_k w)(A_k' w - A_k w'), degree
    ** 3n - 1 (f = that / w^3, w > 0). */
    m = n == 0 ? 0 : (c->rational ? 3 * n - 1 : 2 * n - 1);
    if (m > MAXN)
        return CF_STATUS_BAD_DEGREE;
    buf = cf__alloc_array((size_t)m + 1 + 2 * (size_t)m + 2 + n1 + 2 * n1 +
                              dim + ROOTS_CAP(m), sizeof *buf);
    if (buf == NULL)
        return CF_STATUS_NO_MEMORY;
    coef = buf;                    /* m + 1 */
    num = coef + m + 1;            /* 2n (derivative numerator) */
    e = num + 2 * (size_t)m + 2;   /* n + 1 */
    tmp = e + n1;                  /* 2n */
    q = tmp + 2 * n1;              /* dim */
    rt = q + dim;                  /* the roots */
    if (n >= 1) {
        memset(coef, 0, ((size_t)m + 1) * sizeof *coef);
        for (size_t k = 0; k < dim; k++) {
            int dn = deriv_numerator(c, k, num, tmp);
            for (int i = 0; i <= n; i++)
                e[i] = c->pts[(size_t)i * h + k] -
                       p[k] * (c->rational ? c->pts[(size_t)i * h + dim]
                                           : 1.0);
            cf__bp_mul(e, n, 1, num, dn, 1, coef, 1, 1.0, true);
        }
        if (cf__bp_roots(coef, m, rt, ROOTS_CAP(m), &nr) != CF_STATUS_OK) {
            cf__free(buf);
            return CF_STATUS_NO_MEMORY;
        }
    }
    for (size_t i = 0; i < nr + 2; i++) {
        double tt = i == 0 ? 0.0 : i == 1 ? 1.0 : rt[i - 2], d2 = 0.0;
        cf__bezier_eval_point(c, tt, q);
        for (size_t k = 0; k < dim; k++)
            d2 += (q[k] - p[k]) * (q[k] - p[k]);
        if (d2 < best) {
            best = d2;
            best_t = tt;
        }
    }
    cf__free(buf);
    if (t != NULL)
        *t = best_t;
    if (distance != NULL)
        *distance = sqrt(best);
    return CF_STATUS_OK;
}

/* ---- flattening ------------------------------------------------------------- */

typedef struct flat {
    const cf_bezier_t *c;
    double tol;
    cf_point_func_t func;
    void *closure;
    double *work;      /* per depth: two curves; then Cartesian points */
    double *cart;
    int stopped;
} flat;

#define FLAT_DEPTH 50

/* Cartesian control points of stored points src into f->cart; returns
** the largest distance of a control point from the chord P0 Pn. */
static double
flatness(flat *f, const double *src)
{
    const cf_bezier_t *c = f->c;
    size_t dim = c->dim, h = c->hdim;
    int n = c->degree;
    double vv = 0.0, worst = 0.0, *P = f->cart;
    for (int i = 0; i <= n; i++) {
        double w = c->rational ? src[(size_t)i * h + dim] : 1.0;
        for (size_t k = 0; k < dim; k++)
            P[(size_t)i * dim + k] = src[(size_t)i * h + k] / w;
    }
    for (size_t k = 0; k < dim; k++) {
        double v = P[(size_t)n * dim + k] - P[k];
        vv += v * v;
    }
    for (int i = 1; i < n; i++) {
        /* distance of P_i from the segment: u = clamp(w.v / v.v) */
        double wv = 0.0, u, d2 = 0.0;
        for (size_t k = 0; k < dim; k++)
            wv += (P[(size_t)i * dim + k] - P[k]) *
                  (P[(size_t)n * dim + k] - P[k]);
        u = vv > 0.0 ? fmin(fmax(wv / vv, 0.0), 1.0) : 0.0;
        for (size_t k = 0; k < dim; k++) {
            double d = P[(size_t)i * dim + k] - P[k] -
                       u * (P[(size_t)n * dim + k] - P[k]);
            d2 += d * d;
        }
        worst = fmax(worst, d2);
    }
    return sqrt(worst);
}

static void
flat_rec(flat *f, const double *pts, double a, double b, int depth)
{
    size_t sz = ((size_t)f->c->degree + 1) * f->c->hdim;
    double *left, *right;
    if (f->stopped)
        return;
    if (depth >= FLAT_DEPTH || flatness(f, pts) <= f->tol) {
        /* f->cart holds the Cartesian points of this piece; emit its end */
        if (depth >= FLAT_DEPTH)
            flatness(f, pts);
        f->stopped = f->func(f->closure,
                             f->cart + (size_t)f->c->degree * f->c->dim, b);
        return;
    }
    left = f->work + (size_t)depth * 2 * sz;
    right = left + sz;
    cf__bp_split(pts, f->c->hdim, f->c->degree, 0.5, left, right);
    flat_rec(f, left, a, 0.5 * (a + b), depth + 1);
    flat_rec(f, right, 0.5 * (a + b), b, depth + 1);
}

cf_status_t
cf_bezier_flatten(const cf_bezier_t *c, double tol, cf_point_func_t func,
                  void *closure)
{
    flat f;
    size_t sz;
    if (c == NULL || func == NULL || !(tol > 0.0) || !isfinite(tol))
        return CF_STATUS_INVALID_ARG;
    sz = ((size_t)c->degree + 1) * c->hdim;
    f.c = c;
    f.tol = tol;
    f.func = func;
    f.closure = closure;
    f.stopped = 0;
    f.work = cf__alloc_array((FLAT_DEPTH + 1) * 2 * sz +
                                 ((size_t)c->degree + 1) * c->dim,
                             sizeof *f.work);
    if (f.work == NULL)
        return CF_STATUS_NO_MEMORY;
    f.cart = f.work + (FLAT_DEPTH + 1) * 2 * sz;
    flatness(&f, c->pts);
    f.stopped = func(closure, f.cart, 0.0);
    if (!f.stopped)
        flat_rec(&f, c->pts, 0.0, 1.0, 0);
    cf__free(f.work);
    return f.stopped ? CF_STATUS_INVALID_ARG : CF_STATUS_OK;
}
