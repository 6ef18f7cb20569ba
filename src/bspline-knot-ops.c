/*
** Knot insertion (thesis §3.1, A5.1), refinement (A5.4) and removal (A5.8)
** on B-spline and NURBS curves, on the stored (homogeneous) points.
*/
#include <math.h>
#include <string.h>

#include "bspline-private.h"
#include "numtext-private.h"

/* ---- knot insertion ----------------------------------------------------- */

/*
** Insert u (a <= u <= b) r times where k is the largest index with
** U[k] <= u and s the multiplicity of u (s + r <= p + 1).  A5.1: only
** the p - s + 1 points P_{k-p} .. P_{k-s} take part; column j of the
** thesis' scheme uses a_{i,j} = (u - u_i) / (u_{i+p-j+1} - u_i).
*/
cf_bspline_t *
cf__bspline_insert_raw(const cf_bspline_t *c, double u, size_t k, int s, int r)
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
                cf__bspline_lerp(Rw + i * hd, Rw + i * hd, Rw + (i + 1) * hd,
                                 al, hd);
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
                         "the knot must be inserted at least once, "
                         "not %d times", r);
    *k = cf__knots_last_le(c->U, c->nknots, u);
    *s = cf__knots_mult(c->U, c->nknots, u);
    if (*s + r > c->p + 1)
        return cf__error(diag, CF_STATUS_BAD_KNOTS, (long)*k,
                         "knot %s has multiplicity %d; inserting it "
                         "%d more times exceeds degree + 1 = %d", CF__NUM(u),
                         *s, r, c->p + 1);
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_insert_knot(const cf_bspline_t *c, double u, int r,
                       cf_bspline_t **out, cf_bspline_insert_info_t *info,
                       cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = cf__bspline_check_in(c, out, diag);
    size_t k = 0, p;
    int s = 0;
    if (st != CF_STATUS_OK)
        return st;
    st = insert_check(c, u, r, &k, &s, diag);
    if (st != CF_STATUS_OK)
        return st;
    *out = cf__bspline_insert_raw(c, u, k, s, r);
    if (*out == NULL)
        return cf__bspline_no_memory(diag);
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
** knot move up, then p points are recomputed (the points stored and read
** back from Q; inlined with a constant hd for the common dimensions). */
CF__INLINE void
refine_loop(const double *U, const double *P, double *V, double *Q,
            const double *X, size_t nx, size_t p, size_t a, size_t b,
            size_t hd)
{
    size_t i = b + p - 1, kk = b + p + nx - 1;
    for (size_t jj = nx; jj-- > 0;) {
        double x = X[jj];
        while (x <= U[i] && i > a) {
            cf__bspline_copy_pt(Q + (kk - p - 1) * hd, P + (i - p - 1) * hd,
                                hd);
            V[kk] = U[i];
            kk--;
            i--;
        }
        cf__bspline_copy_pt(Q + (kk - p - 1) * hd, Q + (kk - p) * hd, hd);
        for (size_t l = 1; l <= p; l++) {
            size_t ind = kk - p + l;
            double al = V[kk + l] - x;
            if (al == 0.0) {
                cf__bspline_copy_pt(Q + (ind - 1) * hd, Q + ind * hd, hd);
            } else {
                al /= V[kk + l] - U[i - p + l];
                cf__bspline_lerp(Q + (ind - 1) * hd, Q + ind * hd,
                                 Q + (ind - 1) * hd, al, hd);
            }
        }
        V[kk] = x;
        kk--;
    }
}

#if defined(CF__HAVE_PAIRS)
/* Planar cubics, the common case: the same steps and the same arithmetic
** (so the same values), with the four points the recurrence works on,
** Q[kk - 3 .. kk], and the three knots right of the current one,
** V[kk + 1 .. kk + 3], held in registers (pairs of doubles, GCC's and
** clang's vector extension) instead of being stored and read back: one
** new knot waits for one interpolation of the last, not for a store and
** a load per point.  The highest point is final when a step begins: each
** step writes it out (the first steps of a curve refined near its end
** start above Q's last index, qlast; those are old points moving up, and
** are not written) and shifts the window down by one.  One copy per
** x86-64 level (CF__CLONED; no contraction in this file, so every copy
** rounds alike). */
CF__INLINE void
refine_cubic2_body(const double *U, const double *P, double *V, double *Q,
                   const double *X, size_t nx, size_t a, size_t b,
                   size_t qlast)
{
    size_t i = b + 2, kk = b + nx + 2, vlast = qlast + 4;
    cf__v2 w0, w1, w2, w3, t12, t34, zero = { 0.0, 0.0 };
    w0 = kk - 3 <= qlast ? CF__LOAD2(Q + (kk - 3) * 2) : zero;
    w1 = kk - 2 <= qlast ? CF__LOAD2(Q + (kk - 2) * 2) : zero;
    w2 = kk - 1 <= qlast ? CF__LOAD2(Q + (kk - 1) * 2) : zero;
    w3 = kk <= qlast ? CF__LOAD2(Q + kk * 2) : zero;
    t12 = (cf__v2){ kk + 1 <= vlast ? V[kk + 1] : 0.0,
                    kk + 2 <= vlast ? V[kk + 2] : 0.0 };
    t34 = (cf__v2){ kk + 3 <= vlast ? V[kk + 3] : 0.0, 1.0 };
    for (size_t jj = nx; jj-- > 0;) {
        double x = X[jj];
        cf__v2 xv = { x, x }, u34, n12, n34, a12, a34;
        while (x <= U[i] && i > a) {
            /* Q[kk - 4] = P[i - 4], V[kk] = U[i] */
            if (kk <= qlast)
                CF__STORE2(Q + kk * 2, w3);
            w3 = w2;
            w2 = w1;
            w1 = w0;
            w0 = CF__LOAD2(P + (i - 4) * 2);
            t34 = (cf__v2){ t12[1], 1.0 };
            t12 = (cf__v2){ U[i], t12[0] };
            V[kk] = U[i];
            kk--;
            i--;
        }
        if (kk <= qlast)
            CF__STORE2(Q + kk * 2, w3);
        /* alpha_l = (V[kk + l] - x) / (V[kk + l] - U[i - 3 + l]), 0 where
        ** the numerator is (x is that knot: the point is copied) */
        u34 = (cf__v2){ U[i], 0.0 };
        n12 = t12 - xv;
        n34 = t34 - xv;
        a12 = (cf__v2)((cf__m2)(n12 / (t12 - CF__LOAD2(U + i - 2)))
                       & (cf__m2)(n12 != zero));
        a34 = (cf__v2)((cf__m2)(n34 / (t34 - u34))
                       & (cf__m2)(n34 != zero));
        w3 = cf__lerp2(w3, w2, a34[0]);
        w2 = cf__lerp2(w2, w1, a12[1]);
        w1 = cf__lerp2(w1, w0, a12[0]);
        t34 = (cf__v2){ t12[1], 1.0 };
        t12 = (cf__v2){ x, t12[0] };
        V[kk] = x;
        kk--;
    }
    CF__STORE2(Q + (kk - 3) * 2, w0);
    CF__STORE2(Q + (kk - 2) * 2, w1);
    CF__STORE2(Q + (kk - 1) * 2, w2);
    CF__STORE2(Q + kk * 2, w3);
}

/* each copy CF__LOOP_ALIGNED */
typedef void refine_cubic2_fn(const double *U, const double *P, double *V,
                              double *Q, const double *X, size_t nx,
                              size_t a, size_t b, size_t qlast);
#if defined(CF__LEVELS)
static refine_cubic2_fn refine_cubic2_v4 CF__LOOP_ALIGNED;
static refine_cubic2_fn refine_cubic2_v3 CF__LOOP_ALIGNED;
static refine_cubic2_fn refine_cubic2_v1 CF__LOOP_ALIGNED;
#else
static refine_cubic2_fn refine_cubic2 CF__LOOP_ALIGNED;
#endif
CF__CLONED(void, refine_cubic2,
           (const double *U, const double *P, double *V, double *Q,
            const double *X, size_t nx, size_t a, size_t b, size_t qlast),
           (U, P, V, Q, X, nx, a, b, qlast), )
#endif

#if defined(CF__HAVE_PAIRS)
/* Whether X[j - 1] < X[j] for j = 1 .. 2 m: two comparisons per step, no
** branch (the vectoriser leaves this loop scalar); a function of its own,
** CF__LOOP_ALIGNED (W5ins was 2 % slower in three of the four places
** modulo 64 the code before it could put it). */
CF__LOOP_ALIGNED __attribute__((noinline)) static bool
increasing_pairs(const double *X, size_t m)
{
    cf__m2 all = { -1, -1 };
    for (size_t i = 0; i < m; i++)
        all &= (cf__m2)(CF__LOAD2(X + 2 * i + 1) > CF__LOAD2(X + 2 * i));
    return all[0] & all[1];
}

/* Whether A[i] == B[i] for some i < 2 m, without a branch. */
CF__LOOP_ALIGNED __attribute__((noinline)) static bool
equal_pairs(const double *A, const double *B, size_t m)
{
    cf__m2 any = { 0, 0 };
    for (size_t i = 0; i < m; i++)
        any |= (cf__m2)(CF__LOAD2(A + 2 * i) == CF__LOAD2(B + 2 * i));
    return any[0] | any[1];
}
#endif

/* Whether X[0] < X[1] < ... < X[n - 1] (false on a NaN). */
static bool
strictly_increasing(const double *X, size_t n)
{
    size_t j = 1;
#if defined(CF__HAVE_PAIRS)
    size_t m = n > 1 ? (n - 1) / 2 : 0;
    if (!increasing_pairs(X, m))
        return false;
    j += 2 * m;
#endif
    for (; j < n; j++)
        if (!(X[j] > X[j - 1]))
            return false;
    return true;
}

/* Whether a knot of multiplicity > p (U[k] = U[k + p]) lies in
** [lo, hi] (U[0] <= lo <= hi): the range of k by bisection, then one
** comparison per knot. */
static bool
full_knot_in(const double *U, size_t nk, size_t p, double lo, double hi)
{
    size_t k = cf__knots_last_le(U, nk, lo), end;
    while (k > 0 && U[k - 1] >= lo)
        k--;
    k += U[k] < lo;
    end = cf__knots_last_le(U, nk, hi) + 1;   /* U[k] <= hi for k < end */
    if (end + p > nk)
        end = nk - p;
#if defined(CF__HAVE_PAIRS)
    {
        size_t m = end >= k + 2 ? (end - k) / 2 : 0;
        if (equal_pairs(U + k, U + k + p, m))
            return true;
        k += 2 * m;
    }
#endif
    for (; k < end; k++)
        if (U[k] == U[k + p])
            return true;
    return false;
}

/* The new knots X: finite, inside the domain, sorted, and no knot's
** final multiplicity above p + 1.  Two branch-free passes for the usual
** case (X strictly increasing, and no knot of U in [X[0], X[nx - 1]]
** already of multiplicity p + 1: then none gets more than p + 1); a
** merge of X and U counts the multiplicities otherwise, and the messages
** (which knot, why) come from the detailed checks only when a pass finds
** something wrong. */
static cf_status_t
refine_check(const cf_bspline_t *c, const double *X, size_t nx,
             cf_diag_t *diag)
{
    const double *U = c->U;
    size_t nk = c->nknots, at = 0, p1 = (size_t)c->p + 1;
    double prev = c->a;
    bool ok = true;
    cf_status_t st;
    /* a NaN fails every comparison; an infinity leaves the domain */
    if (X[0] >= c->a && X[nx - 1] <= c->b && strictly_increasing(X, nx)
        && !full_knot_in(U, nk, p1 - 1, X[0], X[nx - 1]))
        return CF_STATUS_OK;
    for (size_t j = 0; j < nx; j++) {
        ok &= X[j] >= prev;
        prev = X[j];
    }
    if (ok && prev <= c->b) {
        for (size_t j = 0; j < nx;) {
            size_t e = j + 1, s = 0;
            while (e < nx && X[e] == X[j])
                e++;
            while (at < nk && U[at] < X[j])
                at++;
            while (at + s < nk && U[at + s] == X[j])
                s++;
            if (s + (e - j) > p1)
                return cf__error(diag, CF_STATUS_BAD_KNOTS, (long)j,
                                 "knot %s would get multiplicity "
                                 "%zu; degree %d allows at most %d",
                                 CF__NUM(X[j]),
                                 s + (e - j), c->p, c->p + 1);
            j = e;
        }
        return CF_STATUS_OK;
    }
    for (size_t j = 0; j < nx; j++) {
        st = cf__bspline_check_param(c, X[j], diag);
        if (st != CF_STATUS_OK)
            return st;
    }
    return cf__check_knot_order(X, nx, "new knot", diag);
}

cf_status_t
cf_bspline_refine(const cf_bspline_t *c, const double *X, size_t nx,
                  cf_bspline_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = cf__bspline_check_in(c, out, diag);
    size_t p, hd, n, m, a, b;
    const double *U, *P;
    cf_bspline_t *q;
    if (st != CF_STATUS_OK)
        return st;
    if (nx == 0)
        return cf_bspline_copy(c, out, diag);
    if (X == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "knots are NULL");
    st = refine_check(c, X, nx, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (nx > ((size_t)1 << 30))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "too many knots");
    q = cf__bspline_alloc(c->dim, c->rational, c->p, c->count + nx);
    if (q == NULL)
        return cf__bspline_no_memory(diag);
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
#if defined(CF__HAVE_PAIRS)
    if (p == 3 && hd == 2)
        refine_cubic2(U, P, q->U, q->P, X, nx, a, b, q->count - 1);
    else
#endif
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
    cf_diag_clear(diag);
    cf_status_t st = cf__bspline_check_in(c, out, diag);
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
                         "count %d must be at least 1", num);
    if (!isfinite(tol) || tol < 0.0)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "tolerance %s must be finite and >= 0",
                         CF__NUM(tol));
    if (!isfinite(u))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "knot is %s", CF__NUM(u));
    s = cf__knots_mult(c->U, c->nknots, u);
    if (s == 0 || !(u > c->a && u < c->b))
        return cf__error(diag, CF_STATUS_BAD_KNOTS, -1,
                         "%s is not an interior knot of the domain "
                         "[%s, %s]", CF__NUM(u), CF__NUM(c->a),
                         CF__NUM(c->b));
    p = (size_t)c->p;
    hd = c->hdim;
    n = c->count - 1;
    m = n + p + 1;
    nk = c->nknots;
    r = cf__knots_last_le(c->U, nk, u);   /* last index of the run */
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
    ** 2p + 1, which is one short in that case. */
    temp = cf__alloc_array(2 * p + 2, hd * sizeof *temp);
    if (Pw == NULL || temp == NULL) {
        cf__free(Pw);
        cf__free(temp);
        return cf__bspline_no_memory(diag);
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
            double dd = 0.0;
            for (size_t d = 0; d < hd; d++) {
                double v = ai * temp[(ii + t + 1) * (long)hd + (long)d]
                           + (1.0 - ai) * temp[(ii - 1) * (long)hd + (long)d];
                double e = Pw[i * (long)hd + (long)d] - v;
                dd += e * e;
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
        return cf__bspline_no_memory(diag);
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
