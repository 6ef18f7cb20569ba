/*
** Constructions on B-spline and NURBS curves: knot insertion (thesis §3.1,
** A5.1), refinement (A5.4), removal (A5.8), split and segment (§3.3),
** decomposition into Bézier segments (A5.6), degree elevation (decompose,
** elevate the pieces, remove the extra knots), derivative curves (§2.9),
** reversal and affine maps.  All run on the stored (homogeneous) points.
*/
#include <math.h>
#include <string.h>

#include "bezier-private.h"
#include "bspline-private.h"

static cf_status_t
no_memory(cf_diag_t *diag)
{
    return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "bspline: out of memory");
}

static cf_status_t
check_in(const cf_bspline_t *c, cf_bspline_t **out, cf_diag_t *diag)
{
    if (out != NULL)
        *out = NULL;
    if (c == NULL || out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "bspline: NULL argument");
    return CF_STATUS_OK;
}

/* dst = (1 - a) x + a y over hdim doubles. */
static inline void
lerp(double *dst, const double *x, const double *y, double a, size_t hd)
{
    for (size_t d = 0; d < hd; d++)
        dst[d] = (1.0 - a) * x[d] + a * y[d];
}

/* dst = src over hdim doubles (a loop: hdim is small, a libc call per
** point costs more than the copy). */
static inline void
copy_pt(double *dst, const double *src, size_t hd)
{
    for (size_t d = 0; d < hd; d++)
        dst[d] = src[d];
}

/* Largest index k with U[k] <= u (u >= U[0]). */
static size_t
last_le(const double *U, size_t nk, double u)
{
    size_t lo = 0, hi = nk;   /* U[lo] <= u; answer < hi */
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (U[mid] <= u)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

/* ---- knot insertion ----------------------------------------------------- */

/*
** Insert u (a <= u <= b) r times where k is the largest index with
** U[k] <= u and s the multiplicity of u (s + r <= p + 1).  A5.1: only
** the p - s + 1 points P_{k-p} .. P_{k-s} take part; column j of the
** thesis' scheme uses a_{i,j} = (u - u_i) / (u_{i+p-j+1} - u_i).
*/
static cf_bspline_t *
insert_raw(const cf_bspline_t *c, double u, size_t k, int s, int r)
{
    size_t p = (size_t)c->p, hd = c->hdim, n = c->count - 1;
    size_t nk = c->nknots, R = (size_t)r, S = (size_t)s;
    const double *U = c->U, *P = c->P;
    double *Rw;
    size_t L;
    cf_bspline_t *q = cf__bspline_alloc(c->dim, c->rational, c->p,
                                        c->count + R);
    if (q == NULL)
        return NULL;
    Rw = cf__alloc_array(p - S + 1, hd * sizeof *Rw);
    if (Rw == NULL) {
        cf__free(q);
        return NULL;
    }
    /* knots */
    memcpy(q->U, U, (k + 1) * sizeof *U);
    for (size_t i = 1; i <= R; i++)
        q->U[k + i] = u;
    memcpy(q->U + k + 1 + R, U + k + 1, (nk - k - 1) * sizeof *U);
    /* unchanged points */
    memcpy(q->P, P, (k - p + 1) * hd * sizeof *P);
    memcpy(q->P + (k - S + R) * hd, P + (k - S) * hd,
           (n - (k - S) + 1) * hd * sizeof *P);
    /* the working column R_0 .. R_{p-s} = P_{k-p} .. P_{k-s} */
    L = k - p + 1;
    {
        size_t need = (p - S + 1) * hd;
        memcpy(Rw, P + (k - p) * hd, need * sizeof *P);
        for (size_t j = 1; j <= R; j++) {
            L = k - p + j;
            for (size_t i = 0; i + j + S <= p; i++) {
                double al = (u - U[L + i]) / (U[i + k + 1] - U[L + i]);
                lerp(Rw + i * hd, Rw + i * hd, Rw + (i + 1) * hd, al, hd);
            }
            memcpy(q->P + L * hd, Rw, hd * sizeof *P);
            if (j + S <= p)
                memcpy(q->P + (k + R - j - S) * hd, Rw + (p - j - S) * hd,
                       hd * sizeof *P);
        }
        for (size_t i = L + 1; i + 1 + S <= k; i++)
            memcpy(q->P + i * hd, Rw + (i - L) * hd, hd * sizeof *P);
    }
    cf__free(Rw);
    cf__bspline_finish(q);
    return q;
}

/* Check u for insertion and find k and s. */
static cf_status_t
insert_check(const cf_bspline_t *c, double u, int r, size_t *k, int *s,
             cf_diag_t *diag)
{
    cf_status_t st = cf__bspline_check_param(c, u, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (r < 1)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "insert: the knot must be inserted at least once, "
                         "not %d times", r);
    *k = last_le(c->U, c->nknots, u);
    *s = cf__knots_mult(c->U, c->nknots, u);
    if (*s + r > c->p + 1)
        return cf__error(diag, CF_STATUS_BAD_KNOTS, (long)*k,
                         "insert: knot %g has multiplicity %d; inserting it "
                         "%d more times exceeds degree + 1 = %d", u, *s, r,
                         c->p + 1);
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_insert_knot(const cf_bspline_t *c, double u, int r,
                       cf_bspline_t **out, cf_bspline_insert_info_t *info,
                       cf_diag_t *diag)
{
    cf_status_t st = check_in(c, out, diag);
    size_t k = 0, p;
    int s = 0;
    if (st != CF_STATUS_OK)
        return st;
    st = insert_check(c, u, r, &k, &s, diag);
    if (st != CF_STATUS_OK)
        return st;
    *out = insert_raw(c, u, k, s, r);
    if (*out == NULL)
        return no_memory(diag);
    if (info != NULL) {
        p = (size_t)c->p;
        info->span = k;
        info->multiplicity = s;
        info->times = r;
        info->cut_first = k - p + 1;
        info->cut_count = p > (size_t)s + 1 ? p - (size_t)s - 1 : 0;
        info->new_first = k - p + 1;
        info->new_count = p + (size_t)r - (size_t)s - 1;
    }
    return CF_STATUS_OK;
}

/* ---- refinement --------------------------------------------------------- */

/* The heart of A5.4, from the right: the old points above the next new
** knot move up, then p points are recomputed (inlined with a constant
** hd for the common dimensions). */
CF__INLINE void
refine_loop(const double *U, const double *P, double *V, double *Q,
            const double *X, size_t nx, size_t p, size_t a, size_t b,
            size_t hd)
{
    size_t i = b + p - 1, kk = b + p + nx - 1;
    for (size_t jj = nx; jj-- > 0;) {
        double x = X[jj];
        while (x <= U[i] && i > a) {
            copy_pt(Q + (kk - p - 1) * hd, P + (i - p - 1) * hd, hd);
            V[kk] = U[i];
            kk--;
            i--;
        }
        copy_pt(Q + (kk - p - 1) * hd, Q + (kk - p) * hd, hd);
        for (size_t l = 1; l <= p; l++) {
            size_t ind = kk - p + l;
            double al = V[kk + l] - x;
            if (al == 0.0) {
                copy_pt(Q + (ind - 1) * hd, Q + ind * hd, hd);
            } else {
                al /= V[kk + l] - U[i - p + l];
                lerp(Q + (ind - 1) * hd, Q + ind * hd, Q + (ind - 1) * hd,
                     al, hd);
            }
        }
        V[kk] = x;
        kk--;
    }
}

cf_status_t
cf_bspline_refine(const cf_bspline_t *c, const double *X, size_t nx,
                  cf_bspline_t **out, cf_diag_t *diag)
{
    cf_status_t st = check_in(c, out, diag);
    size_t p, hd, n, m, a, b;
    const double *U, *P;
    cf_bspline_t *q;
    if (st != CF_STATUS_OK)
        return st;
    if (nx == 0)
        return cf_bspline_copy(c, out, diag);
    if (X == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "refine: knots are NULL");
    for (size_t j = 0; j < nx; j++) {
        st = cf__bspline_check_param(c, X[j], diag);
        if (st != CF_STATUS_OK)
            return st;
    }
    st = cf__check_knot_order(X, nx, "new knot", diag);
    if (st != CF_STATUS_OK)
        return st;
    /* final multiplicities: walk the sorted new knots and the knot vector
    ** together */
    {
        size_t at = 0;
        for (size_t j = 0; j < nx;) {
            size_t e = j, s = 0;
            while (e + 1 < nx && X[e + 1] == X[j])
                e++;
            while (at < c->nknots && c->U[at] < X[j])
                at++;
            while (at + s < c->nknots && c->U[at + s] == X[j])
                s++;
            if (s + (e - j + 1) > (size_t)c->p + 1)
                return cf__error(diag, CF_STATUS_BAD_KNOTS, (long)j,
                                 "refine: knot %g would get multiplicity "
                                 "%zu; degree %d allows at most %d", X[j],
                                 s + (e - j + 1), c->p, c->p + 1);
            j = e + 1;
        }
    }
    if (nx > ((size_t)1 << 30))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "refine: too many knots");
    q = cf__bspline_alloc(c->dim, c->rational, c->p, c->count + nx);
    if (q == NULL)
        return no_memory(diag);
    p = (size_t)c->p;
    hd = c->hdim;
    n = c->count - 1;
    m = n + p + 1;
    U = c->U;
    P = c->P;
    /* A5.4: the points outside [a - p, b - 1] are copied, the others
    ** rebuilt from the right, one new knot at a time */
    a = cf__bspline_span(c, X[0]);
    b = cf__bspline_span(c, X[nx - 1]) + 1;
    memcpy(q->P, P, (a - p + 1) * hd * sizeof *P);
    memcpy(q->P + (b + nx - 1) * hd, P + (b - 1) * hd,
           (n - b + 2) * hd * sizeof *P);
    memcpy(q->U, U, (a + 1) * sizeof *U);
    memcpy(q->U + b + p + nx, U + b + p, (m - b - p + 1) * sizeof *U);
    if (hd == 2)
        refine_loop(U, P, q->U, q->P, X, nx, p, a, b, 2);
    else if (hd == 3)
        refine_loop(U, P, q->U, q->P, X, nx, p, a, b, 3);
    else
        refine_loop(U, P, q->U, q->P, X, nx, p, a, b, hd);
    cf__bspline_finish(q);
    *out = q;
    return CF_STATUS_OK;
}

/* ---- removal ------------------------------------------------------------ */

static double
hdist(const double *x, const double *y, size_t n)
{
    double s = 0.0;
    for (size_t d = 0; d < n; d++)
        s += (x[d] - y[d]) * (x[d] - y[d]);
    return sqrt(s);
}

cf_status_t
cf_bspline_remove_knot(const cf_bspline_t *c, double u, int num, double tol,
                       cf_bspline_t **out, int *removed, cf_diag_t *diag)
{
    cf_status_t st = check_in(c, out, diag);
    size_t p, hd, n, m, r, nk;
    long first, last, off, fout;
    int s, t;
    double TOL, *Pw = NULL, *temp = NULL;
    cf_bspline_t *q;
    if (removed != NULL)
        *removed = 0;
    if (st != CF_STATUS_OK)
        return st;
    if (num < 1)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "remove: count %d must be at least 1", num);
    if (!isfinite(tol) || tol < 0.0)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "remove: tolerance %g must be finite and >= 0", tol);
    if (!isfinite(u))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "remove: knot is %g", u);
    s = cf__knots_mult(c->U, c->nknots, u);
    if (s == 0 || !(u > c->a && u < c->b))
        return cf__error(diag, CF_STATUS_BAD_KNOTS, -1,
                         "remove: %g is not an interior knot of the domain "
                         "[%g, %g]", u, c->a, c->b);
    p = (size_t)c->p;
    hd = c->hdim;
    n = c->count - 1;
    m = n + p + 1;
    nk = c->nknots;
    r = last_le(c->U, nk, u);   /* last index of the run */
    if (num > s)
        num = s;
    TOL = tol;
    if (c->rational) {
        /* NURBS Book (5.30): homogeneous tolerance tol w_min / (1 + |P|max) */
        double wmin = INFINITY, pmax = 0.0;
        for (size_t i = 0; i <= n; i++) {
            double w = c->P[i * hd + c->dim], s2 = 0.0;
            for (size_t d = 0; d < c->dim; d++)
                s2 += (c->P[i * hd + d] / w) * (c->P[i * hd + d] / w);
            wmin = fmin(wmin, w);
            pmax = fmax(pmax, sqrt(s2));
        }
        TOL = tol * wmin / (1.0 + pmax);
    }
    Pw = cf__alloc_array(c->count, hd * sizeof *Pw);
    /* temp[0 .. last + 1 - off]: last + 1 - off = p - s + 2 + 2t with
    ** t < num <= s, so at most p + s <= 2p + 1 (s = p + 1, a knot where
    ** the curve may jump, removed p + 1 times).  The NURBS Book sizes it
    ** 2p + 1, which is one short in that case (found by the fuzzer). */
    temp = cf__alloc_array(2 * p + 2, hd * sizeof *temp);
    if (Pw == NULL || temp == NULL) {
        cf__free(Pw);
        cf__free(temp);
        return no_memory(diag);
    }
    memcpy(Pw, c->P, c->count * hd * sizeof *Pw);
    fout = (long)(2 * r - (size_t)s - p) / 2;
    last = (long)r - s;
    first = (long)r - (long)p;
    for (t = 0; t < num; t++) {
        long i, j, ii, jj;
        bool ok = false;
        off = first - 1;
        memcpy(temp, Pw + off * (long)hd, hd * sizeof *temp);
        memcpy(temp + (last + 1 - off) * (long)hd, Pw + (last + 1) * (long)hd,
               hd * sizeof *temp);
        i = first;
        j = last;
        ii = 1;
        jj = last - off;
        /* solve for the new points from both ends inwards */
        while (j - i > t) {
            double ai = (u - c->U[i]) / (c->U[i + (long)p + 1 + t] - c->U[i]);
            double aj = (u - c->U[j - t]) / (c->U[j + (long)p + 1]
                                             - c->U[j - t]);
            for (size_t d = 0; d < hd; d++) {
                temp[ii * (long)hd + (long)d] =
                    (Pw[i * (long)hd + (long)d]
                     - (1.0 - ai) * temp[(ii - 1) * (long)hd + (long)d]) / ai;
                temp[jj * (long)hd + (long)d] =
                    (Pw[j * (long)hd + (long)d]
                     - aj * temp[(jj + 1) * (long)hd + (long)d])
                    / (1.0 - aj);
            }
            i++;
            ii++;
            j--;
            jj--;
        }
        if (j - i < t) {
            ok = hdist(temp + (ii - 1) * (long)hd, temp + (jj + 1) * (long)hd,
                       hd) <= TOL;
        } else {
            double ai = (u - c->U[i]) / (c->U[i + (long)p + 1 + t] - c->U[i]);
            double x[CF_BSPLINE_MAX_DEGREE + 2];
            double *tmpx = hd <= CF_BSPLINE_MAX_DEGREE + 2 ? x : NULL;
            double dd = 0.0;
            for (size_t d = 0; d < hd; d++) {
                double v = ai * temp[(ii + t + 1) * (long)hd + (long)d]
                           + (1.0 - ai) * temp[(ii - 1) * (long)hd + (long)d];
                double e = Pw[i * (long)hd + (long)d] - v;
                dd += e * e;
                if (tmpx != NULL)
                    tmpx[d] = v;
            }
            ok = sqrt(dd) <= TOL;
        }
        if (!ok)
            break;
        i = first;
        j = last;
        while (j - i > t) {
            memcpy(Pw + i * (long)hd, temp + (i - off) * (long)hd,
                   hd * sizeof *Pw);
            memcpy(Pw + j * (long)hd, temp + (j - off) * (long)hd,
                   hd * sizeof *Pw);
            i++;
            j--;
        }
        first--;
        last++;
    }
    cf__free(temp);
    if (t == 0) {
        cf__free(Pw);
        return cf_bspline_copy(c, out, diag);
    }
    q = cf__bspline_alloc(c->dim, c->rational, c->p, c->count - (size_t)t);
    if (q == NULL) {
        cf__free(Pw);
        return no_memory(diag);
    }
    /* knots: drop t copies of u */
    memcpy(q->U, c->U, (r + 1 - (size_t)t) * sizeof *q->U);
    memcpy(q->U + r + 1 - (size_t)t, c->U + r + 1,
           (m - r) * sizeof *q->U);
    {
        /* points: the block that lost t points is closed up */
        long jj = fout, ii = fout;
        for (int k2 = 1; k2 < t; k2++) {
            if (k2 % 2 == 1)
                ii++;
            else
                jj--;
        }
        memcpy(q->P, Pw, (size_t)jj * hd * sizeof *Pw);
        memcpy(q->P + (size_t)jj * hd, Pw + (size_t)(ii + 1) * hd,
               (n - (size_t)ii) * hd * sizeof *Pw);
    }
    cf__free(Pw);
    cf__bspline_finish(q);
    *out = q;
    if (removed != NULL)
        *removed = t;
    return CF_STATUS_OK;
}

/* ---- split, segment ----------------------------------------------------- */

/* Make u (a <= u <= b) a knot of multiplicity p + 1 and cut there; left
** and right are built only when asked for (and not empty). */
static cf_status_t
cut(const cf_bspline_t *c, double u, cf_bspline_t **left,
    cf_bspline_t **right, cf_diag_t *diag)
{
    size_t k, p = (size_t)c->p, j, hd = c->hdim;
    int s;
    const cf_bspline_t *w = c;
    cf_bspline_t *ins = NULL;
    if (left != NULL)
        *left = NULL;
    if (right != NULL)
        *right = NULL;
    k = last_le(c->U, c->nknots, u);
    s = cf__knots_mult(c->U, c->nknots, u);
    if ((size_t)s < p + 1) {
        ins = insert_raw(c, u, k, s, c->p + 1 - s);
        if (ins == NULL)
            return no_memory(diag);
        w = ins;
    }
    k = last_le(w->U, w->nknots, u);
    j = k - p;   /* the first index of the run of u */
    if (left != NULL && j >= p + 1) {
        cf_bspline_t *l = cf__bspline_alloc(c->dim, c->rational, c->p, j);
        if (l == NULL)
            goto fail;
        memcpy(l->U, w->U, (j + p + 1) * sizeof *l->U);
        memcpy(l->P, w->P, j * hd * sizeof *l->P);
        cf__bspline_finish(l);
        *left = l;
    }
    if (right != NULL && j + p + 1 < w->count + p + 1 && w->count > j + p) {
        size_t cnt = w->count - j;
        cf_bspline_t *r = cf__bspline_alloc(c->dim, c->rational, c->p, cnt);
        if (r == NULL)
            goto fail;
        memcpy(r->U, w->U + j, (cnt + p + 1) * sizeof *r->U);
        memcpy(r->P, w->P + j * hd, cnt * hd * sizeof *r->P);
        cf__bspline_finish(r);
        *right = r;
    }
    cf_bspline_destroy(ins);
    return CF_STATUS_OK;
fail:
    cf_bspline_destroy(ins);
    if (left != NULL) {
        cf_bspline_destroy(*left);
        *left = NULL;
    }
    return no_memory(diag);
}

cf_status_t
cf_bspline_split(const cf_bspline_t *c, double u, cf_bspline_t **left,
                 cf_bspline_t **right, cf_diag_t *diag)
{
    cf_status_t st;
    if (left != NULL)
        *left = NULL;
    if (right != NULL)
        *right = NULL;
    if (c == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "split: NULL curve");
    st = cf__bspline_check_param(c, u, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (!(u > c->a && u < c->b))
        return cf__error(diag, CF_STATUS_DOMAIN, -1,
                         "split: %g must lie strictly inside the domain "
                         "[%g, %g]", u, c->a, c->b);
    return cut(c, u, left, right, diag);
}

cf_status_t
cf_bspline_segment(const cf_bspline_t *c, double a, double b,
                   cf_bspline_t **out, cf_diag_t *diag)
{
    cf_status_t st = check_in(c, out, diag);
    cf_bspline_t *r = NULL, *l = NULL;
    if (st != CF_STATUS_OK)
        return st;
    st = cf__bspline_check_param(c, a, diag);
    if (st == CF_STATUS_OK)
        st = cf__bspline_check_param(c, b, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (!(a < b))
        return cf__error(diag, CF_STATUS_DOMAIN, -1,
                         "segment: [%g, %g] is empty", a, b);
    st = cut(c, a, NULL, &r, diag);
    if (st != CF_STATUS_OK)
        return st;
    st = cut(r, b, &l, NULL, diag);
    cf_bspline_destroy(r);
    if (st != CF_STATUS_OK)
        return st;
    *out = l;
    return CF_STATUS_OK;
}

/* ---- Bézier decomposition ----------------------------------------------- */

/* The curve clamped to its domain: c itself when it is, else a new one
** (*owned set). */
static cf_status_t
clamped(const cf_bspline_t *c, const cf_bspline_t **res, cf_bspline_t **owned,
        cf_diag_t *diag)
{
    size_t p = (size_t)c->p, m = c->nknots - 1;
    cf_bspline_t *r = NULL, *l = NULL;
    cf_status_t st;
    *owned = NULL;
    *res = c;
    if (c->U[0] == c->U[p] && c->U[m - p] == c->U[m])
        return CF_STATUS_OK;
    st = cut(c, c->a, NULL, &r, diag);
    if (st != CF_STATUS_OK)
        return st;
    st = cut(r, r->b, &l, NULL, diag);
    cf_bspline_destroy(r);
    if (st != CF_STATUS_OK)
        return st;
    *owned = l;
    *res = l;
    return CF_STATUS_OK;
}

static size_t
count_spans(const cf_bspline_t *c)
{
    size_t s = 0;
    for (size_t k = c->first_span; k <= c->last_span; k++)
        s += c->U[k] < c->U[k + 1];
    return s;
}

/* A5.6 on a clamped curve: Q receives nseg * (p + 1) * hd doubles,
** breaks (may be NULL) nseg + 1 parameters. */
static void
decompose(const cf_bspline_t *c, double *Q, double *breaks)
{
    size_t p = (size_t)c->p, hd = c->hdim, m = c->nknots - 1;
    size_t seg = (p + 1) * hd, a = p, b = p + 1, nb = 0;
    const double *U = c->U, *P = c->P;
    double alphas[CF_BSPLINE_MAX_DEGREE + 1];
    if (p == 0) {
        /* every point is a constant piece on its span */
        memcpy(Q, P, c->count * hd * sizeof *Q);
        if (breaks != NULL)
            memcpy(breaks, U, c->nknots * sizeof *U);
        return;
    }
    memcpy(Q, P, seg * sizeof *Q);
    if (breaks != NULL)
        breaks[0] = U[p];
    while (b < m) {
        size_t i = b, mult;
        double *cur = Q + nb * seg;
        while (b < m && U[b + 1] == U[b])
            b++;
        mult = b - i + 1;
        if (mult < p) {
            double numer = U[b] - U[a];
            size_t r = p - mult;
            for (size_t j = p; j > mult; j--)
                alphas[j - mult - 1] = numer / (U[a + j] - U[a]);
            for (size_t j = 1; j <= r; j++) {
                size_t save = r - j, s = mult + j;
                for (size_t k = p; k >= s; k--)
                    lerp(cur + k * hd, cur + (k - 1) * hd, cur + k * hd,
                         alphas[k - s], hd);
                if (b < m)
                    copy_pt(cur + seg + save * hd, cur + p * hd, hd);
            }
        }
        nb++;
        if (breaks != NULL)
            breaks[nb] = U[b];
        if (b < m) {
            size_t from = mult < p ? p - mult : 0;
            for (size_t ii = from; ii <= p; ii++)
                copy_pt(Q + nb * seg + ii * hd, P + (b - p + ii) * hd, hd);
            a = b;
            b++;
        }
    }
}

cf_status_t
cf_bspline_bezier_points(const cf_bspline_t *c, double **hpoints,
                         double **breaks, size_t *count, cf_diag_t *diag)
{
    const cf_bspline_t *w;
    cf_bspline_t *owned;
    cf_status_t st;
    size_t nseg;
    double *Q, *B = NULL;
    if (hpoints != NULL)
        *hpoints = NULL;
    if (breaks != NULL)
        *breaks = NULL;
    if (count != NULL)
        *count = 0;
    if (c == NULL || hpoints == NULL || count == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "bspline: NULL argument");
    st = clamped(c, &w, &owned, diag);
    if (st != CF_STATUS_OK)
        return st;
    nseg = count_spans(w);
    Q = cf__alloc_array(nseg * ((size_t)w->p + 1), w->hdim * sizeof *Q);
    if (breaks != NULL)
        B = cf__alloc_array(nseg + 1, sizeof *B);
    if (Q == NULL || (breaks != NULL && B == NULL)) {
        cf__free(Q);
        cf__free(B);
        cf_bspline_destroy(owned);
        return no_memory(diag);
    }
    decompose(w, Q, B);
    cf_bspline_destroy(owned);
    *hpoints = Q;
    if (breaks != NULL)
        *breaks = B;
    *count = nseg;
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_to_beziers(const cf_bspline_t *c, cf_bezier_list_t **out,
                      cf_diag_t *diag)
{
    double *Q, *B;
    size_t nseg, seg;
    cf_status_t st;
    cf_bezier_list_t *list;
    if (out != NULL)
        *out = NULL;
    if (c == NULL || out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "bspline: NULL argument");
    st = cf_bspline_bezier_points(c, &Q, &B, &nseg, diag);
    if (st != CF_STATUS_OK)
        return st;
    seg = ((size_t)c->p + 1) * c->hdim;
    list = cf__bezier_list_new(nseg, true);
    if (list == NULL)
        goto oom;
    for (size_t i = 0; i < nseg; i++) {
        cf_bezier_t *z = cf__bezier_new(c->dim, c->p, c->rational);
        if (z == NULL)
            goto oom;
        memcpy(z->pts, Q + i * seg, seg * sizeof *Q);
        list->items[i] = z;
        list->t0[i] = B[i];
        list->t1[i] = B[i + 1];
    }
    cf__free(Q);
    cf__free(B);
    *out = list;
    return CF_STATUS_OK;
oom:
    cf_bezier_list_destroy(list);
    cf__free(Q);
    cf__free(B);
    return no_memory(diag);
}

/* ---- degree elevation --------------------------------------------------- */

cf_status_t
cf_bspline_elevate(const cf_bspline_t *c, int t, cf_bspline_t **out,
                   cf_diag_t *diag)
{
    cf_status_t st = check_in(c, out, diag);
    const cf_bspline_t *w;
    cf_bspline_t *owned = NULL, *cur = NULL;
    size_t p, ph, hd, nseg, seg, count;
    double *Q = NULL, *B = NULL, size = 0.0, tol;
    if (st != CF_STATUS_OK)
        return st;
    if (t < 0 || c->p + t > CF_BSPLINE_MAX_DEGREE)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "elevate: degree %d + %d is outside 0..%d", c->p, t,
                         CF_BSPLINE_MAX_DEGREE);
    if (t == 0)
        return cf_bspline_copy(c, out, diag);
    st = clamped(c, &w, &owned, diag);
    if (st != CF_STATUS_OK)
        return st;
    st = cf_bspline_bezier_points(w, &Q, &B, &nseg, diag);
    if (st != CF_STATUS_OK)
        goto done;
    p = (size_t)c->p;
    ph = p + (size_t)t;
    hd = c->hdim;
    seg = (p + 1) * hd;
    /* the elevated pieces side by side, every break a knot of
    ** multiplicity ph + 1 (pieces of a C^-1 curve share no point) */
    count = nseg * (ph + 1);
    cur = cf__bspline_alloc(c->dim, c->rational, (int)ph, count);
    if (cur == NULL) {
        st = no_memory(diag);
        goto done;
    }
    for (size_t sI = 0; sI <= nseg; sI++)
        for (size_t i = 0; i <= ph; i++)
            cur->U[sI * (ph + 1) + i] = B[sI];
    for (size_t sI = 0; sI < nseg; sI++) {
        const double *src = Q + sI * seg;
        /* Q_i = sum_j C(p, j) C(t, i - j) / C(p + t, i) P_j */
        for (size_t i = 0; i <= ph; i++) {
            double *dst = cur->P + (sI * (ph + 1) + i) * hd;
            size_t jlo = i > (size_t)t ? i - (size_t)t : 0;
            size_t jhi = i < p ? i : p;
            double den = cf__binomial((int)ph, (int)i);
            for (size_t d = 0; d < hd; d++)
                dst[d] = 0.0;
            for (size_t j = jlo; j <= jhi; j++) {
                double f = cf__binomial((int)p, (int)j)
                           * cf__binomial(t, (int)(i - j)) / den;
                for (size_t d = 0; d < hd; d++)
                    dst[d] += f * src[j * hd + d];
            }
        }
    }
    for (size_t i = 0; i < count * hd; i++)
        size = fmax(size, fabs(cur->P[i]));
    cf__bspline_finish(cur);
    /* remove the knots the elevation does not need: a break of
    ** multiplicity s in the clamped curve keeps s + t */
    tol = 1e-9 * (1.0 + size);
    for (size_t sI = 1; sI < nseg; sI++) {
        int s = cf__knots_mult(w->U, w->nknots, B[sI]);
        int extra = (int)ph + 1 - (s + t);
        if (extra > 0) {
            cf_bspline_t *nxt;
            st = cf_bspline_remove_knot(cur, B[sI], extra, tol, &nxt, NULL,
                                        diag);
            if (st != CF_STATUS_OK)
                goto done;
            cf_bspline_destroy(cur);
            cur = nxt;
        }
    }
    *out = cur;
    cur = NULL;
done:
    cf_bspline_destroy(cur);
    cf_bspline_destroy(owned);
    cf__free(Q);
    cf__free(B);
    return st;
}

/* ---- derivative curves -------------------------------------------------- */

/* Thesis §2.9: degree p - 1, knots u_1 .. u_{m-1}, points
** Q_i = p (P_{i+1} - P_i) / (u_{i+p+1} - u_{i+1}).  A Q_i whose basis
** function N_{i+1}^{p-1} vanishes identically (u_{i+1} = u_{i+p+1}: a knot
** of multiplicity p + 1 where the curve jumps) is dropped with one copy of
** that knot, so the result stays a valid piecewise description. */
static cf_status_t
derivative_poly(const cf_bspline_t *c, cf_bspline_t **out, cf_diag_t *diag)
{
    size_t p = (size_t)c->p, n = c->count - 1, hd = c->hdim, keep = 0;
    size_t j = 0;
    cf_bspline_t *q;
    if (p == 0) {
        q = cf__bspline_alloc(c->dim, false, 0, c->count);
        if (q == NULL)
            return no_memory(diag);
        memcpy(q->U, c->U, c->nknots * sizeof *q->U);
        memset(q->P, 0, c->count * hd * sizeof *q->P);
        cf__bspline_finish(q);
        *out = q;
        return CF_STATUS_OK;
    }
    for (size_t i = 0; i < n; i++)
        keep += c->U[i + p + 1] != c->U[i + 1];
    q = cf__bspline_alloc(c->dim, false, c->p - 1, keep);
    if (q == NULL)
        return no_memory(diag);
    /* knots: u_1 .. u_{m-1} without u_{i+1} for every dropped i */
    for (size_t i = 0; i + 1 < c->nknots - 1; i++) {
        if (i < n && c->U[i + p + 1] == c->U[i + 1])
            continue;
        q->U[j++] = c->U[i + 1];
    }
    j = 0;
    for (size_t i = 0; i < n; i++) {
        double den = c->U[i + p + 1] - c->U[i + 1];
        if (den == 0.0)
            continue;
        for (size_t d = 0; d < hd; d++)
            q->P[j * hd + d] = (double)p / den
                               * (c->P[(i + 1) * hd + d] - c->P[i * hd + d]);
        j++;
    }
    cf__bspline_finish(q);
    *out = q;
    return CF_STATUS_OK;
}

static cf_status_t
derivative_rational(const cf_bspline_t *c, cf_bspline_t **out,
                    cf_diag_t *diag)
{
    cf_bezier_list_t *list = NULL;
    cf_bezier_t **der = NULL;
    cf_bspline_t *q = NULL;
    cf_status_t st;
    size_t nseg, deg, hd = c->hdim, count;
    st = cf_bspline_to_beziers(c, &list, diag);
    if (st != CF_STATUS_OK)
        return st;
    nseg = list->count;
    der = cf__calloc(nseg, sizeof *der);
    if (der == NULL) {
        st = no_memory(diag);
        goto done;
    }
    for (size_t i = 0; i < nseg; i++) {
        st = cf_bezier_derivative(list->items[i], 1, &der[i], diag);
        if (st != CF_STATUS_OK)
            goto done;
    }
    deg = (size_t)cf_bezier_degree(der[0]);
    if (deg > CF_BSPLINE_MAX_DEGREE) {
        st = cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                       "derivative: degree %zu is above %d", deg,
                       CF_BSPLINE_MAX_DEGREE);
        goto done;
    }
    /* pieces joined by knots of multiplicity deg + 1 */
    count = nseg * (deg + 1);
    q = cf__bspline_alloc(c->dim, true, (int)deg, count);
    if (q == NULL) {
        st = no_memory(diag);
        goto done;
    }
    for (size_t i = 0; i < nseg; i++) {
        const double *src = cf_bezier_hpoints(der[i]);
        double scale = 1.0 / (list->t1[i] - list->t0[i]);
        for (size_t j = 0; j <= deg; j++) {
            double *dst = q->P + (i * (deg + 1) + j) * hd;
            for (size_t d = 0; d < c->dim; d++)
                dst[d] = scale * src[j * hd + d];
            dst[c->dim] = src[j * hd + c->dim];
        }
        for (size_t j = 0; j <= deg; j++)
            q->U[i * (deg + 1) + j] = list->t0[i];
    }
    for (size_t j = 0; j <= deg; j++)
        q->U[count + j] = list->t1[nseg - 1];
    cf__bspline_finish(q);
    *out = q;
    q = NULL;
done:
    if (der != NULL)
        for (size_t i = 0; i < nseg; i++)
            cf_bezier_destroy(der[i]);
    cf__free(der);
    cf_bezier_list_destroy(list);
    cf_bspline_destroy(q);
    return st;
}

/* The points of a computed curve are finite: differences of huge
** coordinates, or quotients by tiny knot spans (p / (u_{i+p+1} - u_{i+1})
** with spans near 1e-320), overflow to inf, and an affine map with huge
** entries can too.  Such a curve is refused rather than returned (found by
** the bad-input corpus). */
static cf_status_t
check_overflow(const cf_bspline_t *q, const char *what, cf_diag_t *diag)
{
    for (size_t i = 0; i < q->count * q->hdim; i++) {
        if (!isfinite(q->P[i]))
            return cf__error(diag, CF_STATUS_NOT_FINITE,
                             (long)(i / q->hdim),
                             "%s: control point %zu overflows (coordinate "
                             "%zu is %g); the input is too large or its knot "
                             "spans too small", what, i / q->hdim,
                             i % q->hdim + 1, q->P[i]);
    }
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_derivative(const cf_bspline_t *c, int k, cf_bspline_t **out,
                      cf_diag_t *diag)
{
    cf_status_t st = check_in(c, out, diag);
    cf_bspline_t *cur = NULL;
    if (st != CF_STATUS_OK)
        return st;
    if (k < 0)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "derivative: order %d is negative", k);
    st = cf_bspline_copy(c, &cur, diag);
    for (int i = 0; i < k && st == CF_STATUS_OK; i++) {
        cf_bspline_t *nxt = NULL;
        st = cur->rational ? derivative_rational(cur, &nxt, diag)
                           : derivative_poly(cur, &nxt, diag);
        cf_bspline_destroy(cur);
        cur = nxt;
    }
    if (st == CF_STATUS_OK)
        st = check_overflow(cur, "derivative", diag);
    if (st != CF_STATUS_OK) {
        cf_bspline_destroy(cur);
        return st;
    }
    *out = cur;
    return CF_STATUS_OK;
}

/* ---- reversal, affine maps ---------------------------------------------- */

cf_status_t
cf_bspline_reverse(const cf_bspline_t *c, cf_bspline_t **out,
                   cf_diag_t *diag)
{
    cf_status_t st = check_in(c, out, diag);
    size_t m, n, hd;
    cf_bspline_t *q;
    if (st != CF_STATUS_OK)
        return st;
    q = cf__bspline_alloc(c->dim, c->rational, c->p, c->count);
    if (q == NULL)
        return no_memory(diag);
    m = c->nknots - 1;
    n = c->count - 1;
    hd = c->hdim;
    /* u'_i = (u_0 + u_m) - u_{m-i}.  Rounding is monotone, so the
    ** computed knots stay non-decreasing; the ends are then set exactly
    ** (knots equal to u_m become u_0 and vice versa), and everything else is
    ** kept inside [u_0, u_m]: forcing only u'_0 and u'_m could leave
    ** u'_1 < u'_0 by one ulp (found by the fuzzer). */
    for (size_t i = 0; i <= m; i++) {
        double u = c->U[m - i];
        if (u == c->U[m])
            q->U[i] = c->U[0];
        else if (u == c->U[0])
            q->U[i] = c->U[m];
        else
            q->U[i] = fmin(fmax((c->U[0] + c->U[m]) - u, c->U[0]),
                           c->U[m]);
        /* Knots an ulp apart may round onto one value at the scale of
        ** u_0 + u_m, which would merge two runs into one of too high a
        ** multiplicity (found by the fuzzer): keep distinct knots
        ** distinct by stepping to the next double. */
        if (i > 0 && c->U[m - i] < c->U[m - i + 1] && !(q->U[i] > q->U[i - 1]))
            q->U[i] = nextafter(q->U[i - 1], INFINITY);
    }
    for (size_t i = 1; i <= m; i++) {
        if ((c->U[m - i] < c->U[m - i + 1]) != (q->U[i] > q->U[i - 1]) ||
            q->U[i] < q->U[i - 1]) {
            cf_bspline_destroy(q);
            return cf__error(diag, CF_STATUS_BAD_KNOTS, (long)(m - i),
                             "reverse: knots %zu and %zu (%.17g, %.17g) are "
                             "too close to be reversed exactly", m - i,
                             m - i + 1, c->U[m - i], c->U[m - i + 1]);
        }
    }
    for (size_t i = 0; i <= n; i++)
        memcpy(q->P + i * hd, c->P + (n - i) * hd, hd * sizeof *q->P);
    cf__bspline_finish(q);
    *out = q;
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_transform(const cf_bspline_t *c, const double *A, const double *b,
                     cf_bspline_t **out, cf_diag_t *diag)
{
    cf_status_t st = check_in(c, out, diag);
    size_t dim;
    cf_bspline_t *q;
    if (st != CF_STATUS_OK)
        return st;
    dim = c->dim;
    st = cf__check_affine(A, b, dim, diag);
    if (st != CF_STATUS_OK)
        return st;
    q = cf__bspline_alloc(dim, c->rational, c->p, c->count);
    if (q == NULL)
        return no_memory(diag);
    memcpy(q->U, c->U, c->nknots * sizeof *q->U);
    cf__affine_points(A, b, dim, c->rational, c->P, c->count, c->hdim, q->P);
    st = check_overflow(q, "transform", diag);
    if (st != CF_STATUS_OK) {
        cf_bspline_destroy(q);
        return st;
    }
    cf__bspline_finish(q);
    *out = q;
    return CF_STATUS_OK;
}
