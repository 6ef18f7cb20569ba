/*
** Constructions on B-spline and NURBS curves: split and segment (§3.3),
** decomposition into Bézier segments (A5.6), degree elevation (decompose,
** elevate the pieces, remove the extra knots), derivative curves (§2.9),
** reversal and affine maps.  All run on the stored (homogeneous) points;
** knot insertion, refinement and removal are in bspline-knot-ops.c.
*/
#include <math.h>
#include <string.h>

#include "bezier-private.h"
#include "bspline-private.h"
#include "numtext-private.h"

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
    k = cf__knots_last_le(c->U, c->nknots, u);
    s = cf__knots_mult(c->U, c->nknots, u);
    if ((size_t)s < p + 1) {
        ins = cf__bspline_insert_raw(c, u, k, s, c->p + 1 - s);
        if (ins == NULL)
            return cf__bspline_no_memory(diag);
        w = ins;
    }
    k = cf__knots_last_le(w->U, w->nknots, u);
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
    return cf__bspline_no_memory(diag);
}

cf_status_t
cf_bspline_split(const cf_bspline_t *c, double u, cf_bspline_t **left,
                 cf_bspline_t **right, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st;
    if (left != NULL)
        *left = NULL;
    if (right != NULL)
        *right = NULL;
    if (c == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "NULL curve");
    st = cf__bspline_check_param(c, u, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (!(u > c->a && u < c->b))
        return cf__error(diag, CF_STATUS_DOMAIN, -1,
                         "%s must lie strictly inside the domain [%s, %s]",
                         CF__NUM(u), CF__NUM(c->a), CF__NUM(c->b));
    return cut(c, u, left, right, diag);
}

cf_status_t
cf_bspline_segment(const cf_bspline_t *c, double a, double b,
                   cf_bspline_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = cf__bspline_check_in(c, out, diag);
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
                         "[%s, %s] is empty", CF__NUM(a), CF__NUM(b));
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

/* The heart of A5.6 (p >= 1): one pass over the knots, each piece's
** points written in place (piece s at Q + s * stride), the next piece's
** first points saved as they are made (inlined with constant p and hd
** for the common cases). */
CF__INLINE void
decompose_loop(const double *U, const double *P, size_t m, size_t p,
               size_t hd, double *Q, size_t stride, double *breaks)
{
    size_t seg = (p + 1) * hd, a = p, b = p + 1, nb = 0;
    double alphas[CF_BSPLINE_MAX_DEGREE + 1];
    for (size_t k = 0; k < seg; k++)
        Q[k] = P[k];
    if (breaks != NULL)
        breaks[0] = U[p];
    while (b < m) {
        size_t i = b, mult;
        double *cur = Q + nb * stride;
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
                    cf__bspline_lerp(cur + k * hd, cur + (k - 1) * hd,
                                     cur + k * hd, alphas[k - s], hd);
                if (b < m)
                    cf__bspline_copy_pt(cur + stride + save * hd,
                                        cur + p * hd, hd);
            }
        }
        nb++;
        if (breaks != NULL)
            breaks[nb] = U[b];
        if (b < m) {
            size_t from = mult < p ? p - mult : 0;
            for (size_t ii = from; ii <= p; ii++)
                cf__bspline_copy_pt(Q + nb * stride + ii * hd,
                                    P + (b - p + ii) * hd, hd);
            a = b;
            b++;
        }
    }
}

/* The pieces of c into Q (piece s at Q + s * stride), breaks (may be
** NULL) nseg + 1 parameters: cubics from the blossom, any knot vector
** (bspline-cubic-pieces.c); other degrees by A5.6 on the clamped curve. */
static void
decompose(const cf_bspline_t *c, double *Q, size_t stride, double *breaks)
{
    size_t p = (size_t)c->p, hd = c->hdim, m = c->nknots - 1;
    const double *U = c->U, *P = c->P;
    if (p == 3) {
        cf__bspline_cubic_pieces(c, Q, stride, breaks);
    } else if (p == 0) {
        /* every point is a constant piece on its span */
        for (size_t i = 0; i < c->count; i++)
            cf__bspline_copy_pt(Q + i * stride, P + i * hd, hd);
        if (breaks != NULL)
            memcpy(breaks, U, c->nknots * sizeof *U);
    } else if (p == 2 && hd == 2) {
        decompose_loop(U, P, m, 2, 2, Q, stride, breaks);
    } else {
        decompose_loop(U, P, m, p, hd, Q, stride, breaks);
    }
}

/* c itself for a cubic (the blossom needs no clamping), else the curve
** clamped to its domain (*owned set when new); and its piece count. */
static cf_status_t
decompose_input(const cf_bspline_t *c, const cf_bspline_t **w,
                cf_bspline_t **owned, size_t *nseg, cf_diag_t *diag)
{
    cf_status_t st = CF_STATUS_OK;
    *w = c;
    *owned = NULL;
    if (c->p != 3)
        st = clamped(c, w, owned, diag);
    if (st == CF_STATUS_OK)
        *nseg = count_spans(*w);
    return st;
}

/* This and cf_bspline_to_beziers hold count_spans' loop, inlined
** (CF__LOOP_ALIGNED). */
CF__LOOP_ALIGNED cf_status_t
cf_bspline_bezier_points(const cf_bspline_t *c, double **hpoints,
                         double **breaks, size_t *count, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    const cf_bspline_t *w;
    cf_bspline_t *owned;
    cf_status_t st;
    size_t nseg, seg;
    double *Q, *B = NULL;
    if (hpoints != NULL)
        *hpoints = NULL;
    if (breaks != NULL)
        *breaks = NULL;
    if (count != NULL)
        *count = 0;
    if (c == NULL || hpoints == NULL || count == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "NULL argument");
    st = decompose_input(c, &w, &owned, &nseg, diag);
    if (st != CF_STATUS_OK)
        return st;
    seg = ((size_t)w->p + 1) * w->hdim;
    Q = cf__alloc_array(nseg, seg * sizeof *Q);
    if (breaks != NULL)
        B = cf__alloc_array(nseg + 1, sizeof *B);
    if (Q == NULL || (breaks != NULL && B == NULL)) {
        cf__free(Q);
        cf__free(B);
        cf_bspline_destroy(owned);
        return cf__bspline_no_memory(diag);
    }
    decompose(w, Q, seg, B);
    cf_bspline_destroy(owned);
    *hpoints = Q;
    if (breaks != NULL)
        *breaks = B;
    *count = nseg;
    return CF_STATUS_OK;
}

/* The pieces as curves: all in one block (cf__bezier_new_many), each
** decomposed straight into its curve. */
CF__LOOP_ALIGNED cf_status_t
cf_bspline_to_beziers(const cf_bspline_t *c, cf_bezier_list_t **out,
                      cf_diag_t *diag)
{
    cf_diag_clear(diag);
    const cf_bspline_t *w;
    cf_bspline_t *owned;
    double *B;
    size_t nseg, stride;
    cf_status_t st;
    cf_bezier_list_t *list;
    if (out != NULL)
        *out = NULL;
    if (c == NULL || out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "NULL argument");
    st = decompose_input(c, &w, &owned, &nseg, diag);
    if (st != CF_STATUS_OK)
        return st;
    list = cf__bezier_list_new(nseg, true);
    B = cf__alloc_array(nseg + 1, sizeof *B);
    if (list == NULL || B == NULL
        || !cf__bezier_new_many(nseg, c->dim, c->p, c->rational, list->items,
                                &stride)) {
        cf_bezier_list_destroy(list);
        cf__free(B);
        cf_bspline_destroy(owned);
        return cf__bspline_no_memory(diag);
    }
    decompose(w, list->items[0]->pts, stride, B);
    cf_bspline_destroy(owned);
    for (size_t i = 0; i < nseg; i++) {
        list->t0[i] = B[i];
        list->t1[i] = B[i + 1];
    }
    cf__free(B);
    *out = list;
    return CF_STATUS_OK;
}

/* ---- degree elevation --------------------------------------------------- */

cf_status_t
cf_bspline_elevate(const cf_bspline_t *c, int t, cf_bspline_t **out,
                   cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = cf__bspline_check_in(c, out, diag);
    const cf_bspline_t *w;
    cf_bspline_t *owned = NULL, *cur = NULL;
    size_t p, ph, hd, nseg, seg, count;
    double *Q = NULL, *B = NULL, size = 0.0, tol;
    if (st != CF_STATUS_OK)
        return st;
    if (t < 0 || c->p + t > CF_BSPLINE_MAX_DEGREE)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "degree %d + %d is outside 0..%d", c->p, t,
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
        st = cf__bspline_no_memory(diag);
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
            return cf__bspline_no_memory(diag);
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
        return cf__bspline_no_memory(diag);
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
        st = cf__bspline_no_memory(diag);
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
                       "degree %zu is above %d", deg,
                       CF_BSPLINE_MAX_DEGREE);
        goto done;
    }
    /* pieces joined by knots of multiplicity deg + 1 */
    count = nseg * (deg + 1);
    q = cf__bspline_alloc(c->dim, true, (int)deg, count);
    if (q == NULL) {
        st = cf__bspline_no_memory(diag);
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
** entries can too.  Such a curve is refused rather than returned. */
static cf_status_t
check_overflow(const cf_bspline_t *q, const char *what, cf_diag_t *diag)
{
    for (size_t i = 0; i < q->count * q->hdim; i++) {
        if (!isfinite(q->P[i]))
            return cf__error(diag, CF_STATUS_NOT_FINITE,
                             (long)(i / q->hdim),
                             "control point %zu of the %s overflows "
                             "(coordinate %zu is %s); the input is too large "
                             "or its knot spans too small", i / q->hdim, what,
                             i % q->hdim + 1, CF__NUM(q->P[i]));
    }
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_derivative(const cf_bspline_t *c, int k, cf_bspline_t **out,
                      cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = cf__bspline_check_in(c, out, diag);
    cf_bspline_t *cur = NULL;
    if (st != CF_STATUS_OK)
        return st;
    if (k < 0)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "order %d is negative", k);
    st = cf_bspline_copy(c, &cur, diag);
    for (int i = 0; i < k && st == CF_STATUS_OK; i++) {
        cf_bspline_t *nxt = NULL;
        st = cur->rational ? derivative_rational(cur, &nxt, diag)
                           : derivative_poly(cur, &nxt, diag);
        cf_bspline_destroy(cur);
        cur = nxt;
    }
    if (st == CF_STATUS_OK)
        st = check_overflow(cur, "derivative curve", diag);
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
    cf_diag_clear(diag);
    cf_status_t st = cf__bspline_check_in(c, out, diag);
    size_t m, n, hd;
    cf_bspline_t *q;
    if (st != CF_STATUS_OK)
        return st;
    q = cf__bspline_alloc(c->dim, c->rational, c->p, c->count);
    if (q == NULL)
        return cf__bspline_no_memory(diag);
    m = c->nknots - 1;
    n = c->count - 1;
    hd = c->hdim;
    /* u'_i = (u_0 + u_m) - u_{m-i}.  Rounding is monotone, so the
    ** computed knots stay non-decreasing; the ends are then set exactly
    ** (knots equal to u_m become u_0 and vice versa), and everything else is
    ** kept inside [u_0, u_m]: forcing only u'_0 and u'_m could leave
    ** u'_1 < u'_0 by one ulp. */
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
        ** multiplicity: keep distinct knots
        ** distinct by stepping to the next double. */
        if (i > 0 && c->U[m - i] < c->U[m - i + 1] && !(q->U[i] > q->U[i - 1]))
            q->U[i] = nextafter(q->U[i - 1], INFINITY);
    }
    for (size_t i = 1; i <= m; i++) {
        if ((c->U[m - i] < c->U[m - i + 1]) != (q->U[i] > q->U[i - 1]) ||
            q->U[i] < q->U[i - 1]) {
            cf_bspline_destroy(q);
            return cf__error(diag, CF_STATUS_BAD_KNOTS, (long)(m - i),
                             "knots %zu and %zu (%s, %s) are too close to "
                             "be reversed exactly", m - i, m - i + 1,
                             CF__NUM(c->U[m - i]), CF__NUM(c->U[m - i + 1]));
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
    cf_diag_clear(diag);
    cf_status_t st = cf__bspline_check_in(c, out, diag);
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
        return cf__bspline_no_memory(diag);
    memcpy(q->U, c->U, c->nknots * sizeof *q->U);
    cf__affine_points(A, b, dim, c->rational, c->P, c->count, c->hdim, q->P);
    st = check_overflow(q, "transformed curve", diag);
    if (st != CF_STATUS_OK) {
        cf_bspline_destroy(q);
        return st;
    }
    cf__bspline_finish(q);
    *out = q;
    return CF_STATUS_OK;
}
