/*
** Degree reduction of B-spline curves (include/curvefig/reduce.h), after
** The NURBS Book A5.11 with the best piecewise reductions of reduce-l2.c /
** reduce-uniform.c in place of the one-degree formula:
**
**   1. decompose into Bézier pieces (degree p, clamped to the domain);
**   2. reduce each piece to q = p - by, keeping at each break the
**      derivatives the original has there, up to k = min(p - s, (q - 1) / 2)
**      (s the break's multiplicity; (q - 1) / 2 so that both ends of a
**      piece fit), at the curve's ends the end points; both pieces at a
**      break then have the same derivatives of order <= k (the original's,
**      scaled by the same interval lengths), so they join C^k;
**      if a piece's certified error exceeds the tolerance, the pieces are
**      reduced again with C^0 breaks, and if that too exceeds it the
**      reduction is refused with that smallest error;
**   3. put the pieces side by side (every break of multiplicity q + 1),
**      then remove each break (A5.8, cf_bspline_remove_knot) one copy at a
**      time, down to the original's continuity C^(p - s) where degree q
**      allows it (at most C^(q - 1)), keeping a removal only when the
**      certified error of the whole curve stays within the tolerance.
**
** The certified error of a candidate is measured piece by piece against
** the original: the candidate is refined to the original's breaks, and
** each of its Bézier pieces is bounded against the original's piece
** (reduce-error.c); after a removal, only the pieces the removal can
** reach (q + 2 on either side).
*/
#include <math.h>
#include <string.h>

#include "bspline-private.h"
#include "core-private.h"
#include "reduce-private.h"
#include "numtext-private.h"

typedef struct orig {
    double *hp;        /* count pieces of (p + 1) * h doubles */
    double *breaks;    /* count + 1 */
    size_t count, h, dim;
    int p;
    bool rational;
} orig;

/* The errors of F (degree q, domain of the original) against the
** original's pieces lo .. hi - 1: the certified bound, and when rep is not
** NULL the measured maximum and the L2 distance in the B-spline's
** parameter.  A piece whose polygon bound is <= enough is not refined
** (used without a report, to check a tolerance). */
static cf_status_t
errors(const orig *o, const cf_bspline_t *F, size_t lo, size_t hi,
       double enough, double *bound, cf_reduce_report_t *rep,
       cf_diag_t *diag)
{
    int q = F->p;
    size_t nx = 0, cnt = 0;
    double *x, *hp = NULL, l2 = 0.0, meas = 0.0;
    cf_bspline_t *R = NULL, *S = NULL;
    cf_status_t st;
    x = cf__alloc_array((hi - lo) * (size_t)(q + 1) + 1, sizeof *x);
    if (x == NULL)
        return cf__bspline_no_memory(diag);
    /* F on [breaks[lo], breaks[hi]], every break inside of multiplicity q */
    st = cf_bspline_segment(F, o->breaks[lo], o->breaks[hi], &S, diag);
    for (size_t i = lo + 1; i < hi && st == CF_STATUS_OK; i++)
        for (int r = cf__knots_mult(S->U, S->nknots, o->breaks[i]); r < q;
             r++)
            x[nx++] = o->breaks[i];
    if (st == CF_STATUS_OK)
        st = cf_bspline_refine(S, x, nx, &R, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_bezier_points(R, &hp, NULL, &cnt, diag);
    cf_bspline_destroy(R);
    cf_bspline_destroy(S);
    cf__free(x);
    if (st != CF_STATUS_OK)
        return st;
    *bound = 0.0;
    for (size_t i = 0; i < cnt && i < hi - lo && st == CF_STATUS_OK; i++) {
        const double *P = o->hp + (lo + i) * (size_t)(o->p + 1) * o->h;
        const double *Q = hp + i * (size_t)(q + 1) * o->h;
        double b = 0.0, pb = 0.0, d = 0.0;
        st = cf__reduce_bound(P, o->p, Q, q, o->dim, o->rational,
                              rep == NULL ? enough : 0.0, &b, &pb);
        *bound = fmax(*bound, b);
        if (rep != NULL)
            rep->polygon_bound = fmax(rep->polygon_bound, pb);
        if (st != CF_STATUS_OK || rep == NULL)
            continue;
        meas = fmax(meas, cf__reduce_measure(P, o->p, Q, q, o->dim,
                                             o->rational));
        st = cf__reduce_l2_distance(P, o->p, Q, q, o->h, &d);
        l2 += (o->breaks[lo + i + 1] - o->breaks[lo + i]) * d * d;
    }
    cf_free(hp);
    if (st != CF_STATUS_OK)
        return cf__bspline_no_memory(diag);
    if (cnt != hi - lo)
        return cf__error(diag, CF_STATUS_DEGENERATE, -1,
                         "the reduced curve has %zu pieces, the original %zu",
                         cnt, hi - lo);
    if (rep != NULL) {
        rep->max_error = meas;
        rep->l2_error = sqrt(l2);
    }
    return CF_STATUS_OK;
}

/* Every piece reduced, break i kept C^k[i] (k[0] = k[count] = 0, the
** ends); *worst: the largest certified error of a piece, *which its
** index. */
static cf_status_t
pieces(const orig *o, int q, const int *k, cf_reduce_method_t method,
       double *out, double *worst, size_t *which, cf_diag_t *diag)
{
    size_t hp = (size_t)(o->p + 1) * o->h, hq = (size_t)(q + 1) * o->h;
    *worst = 0.0;
    *which = 0;
    for (size_t i = 0; i < o->count; i++) {
        cf__reduce_job_t j = { o->hp + i * hp, o->p, q, k[i], k[i + 1],
                               o->h };
        double b;
        cf_status_t st = cf__reduce_solve(&j, o->dim, o->rational, method,
                                          out + i * hq, NULL, diag);
        if (st == CF_STATUS_OK)
            st = cf__reduce_bound(j.P, o->p, out + i * hq, q, o->dim,
                                  o->rational, 0.0, &b, NULL);
        if (st != CF_STATUS_OK)
            return st == CF_STATUS_NO_MEMORY ? cf__bspline_no_memory(diag)
                                             : st;
        if (b > *worst) {
            *worst = b;
            *which = i;
        }
    }
    return CF_STATUS_OK;
}

/* Step 3: the pieces side by side, then the greedy removals. */
static cf_status_t
assemble(const orig *o, int q, const double *Q, const int *target,
         double tol, cf_bspline_t **out, size_t *removed, cf_diag_t *diag)
{
    size_t n = o->count, hq = (size_t)(q + 1) * o->h;
    cf_bspline_t *F = cf__bspline_alloc(o->dim, o->rational, q,
                                        n * (size_t)(q + 1));
    cf_status_t st = CF_STATUS_OK;
    if (F == NULL)
        return cf__bspline_no_memory(diag);
    for (size_t s = 0; s <= n; s++)
        for (int i = 0; i <= q; i++)
            F->U[s * (size_t)(q + 1) + (size_t)i] = o->breaks[s];
    memcpy(F->P, Q, n * hq * sizeof *Q);
    cf__bspline_finish(F);
    *removed = 0;
    for (size_t s = 1; s < n && st == CF_STATUS_OK; s++) {
        double u = o->breaks[s];
        int mult = q + 1;
        while (mult > q - target[s] && st == CF_STATUS_OK) {
            cf_bspline_t *G = NULL;
            int got = 0;
            double b = INFINITY;
            st = cf_bspline_remove_knot(F, u, 1, tol, &G, &got, diag);
            /* the removal moved the points whose supports reach u: at
            ** most q + 1 pieces on either side of it */
            if (st == CF_STATUS_OK && got == 1)
                st = errors(o, G, s > (size_t)q + 2 ? s - (size_t)q - 2 : 0,
                            s + (size_t)q + 2 < n ? s + (size_t)q + 2 : n,
                            tol, &b, NULL, diag);
            if (st != CF_STATUS_OK || got != 1 || !(b <= tol)) {
                cf_bspline_destroy(G);
                break;
            }
            cf_bspline_destroy(F);
            F = G;
            mult--;
            (*removed)++;
        }
    }
    if (st != CF_STATUS_OK) {
        cf_bspline_destroy(F);
        return st;
    }
    *out = F;
    return CF_STATUS_OK;
}

static cf_status_t
check(const cf_bspline_t *c, const cf_reduce_options_t *o, cf_diag_t *diag)
{
    cf_status_t st = cf__reduce_check_degree("B-spline", c->p, o->by, 1,
                                             o->method, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (!(o->tolerance > 0.0) || !isfinite(o->tolerance))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "tolerance %s must be finite and > 0",
                         CF__NUM(o->tolerance));
    return CF_STATUS_OK;
}

cf_status_t
cf_bspline_reduce(const cf_bspline_t *c, const cf_reduce_options_t *opt,
                  cf_bspline_t **out, cf_reduce_report_t *report,
                  cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_reduce_options_t o;
    orig g = { 0 };
    cf_status_t st;
    int q, *k = NULL, *target;
    double *Q = NULL, worst;
    size_t which, removed = 0;
    cf_bspline_t *F = NULL;

    st = cf__bspline_check_in(c, out, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (opt != NULL)
        o = *opt;
    else
        cf_reduce_options_init(&o);
    st = check(c, &o, diag);
    if (st != CF_STATUS_OK)
        return st;
    q = c->p - o.by;
    st = cf_bspline_bezier_points(c, &g.hp, &g.breaks, &g.count, diag);
    if (st != CF_STATUS_OK)
        return st;
    g.h = c->hdim;
    g.dim = c->dim;
    g.p = c->p;
    g.rational = c->rational;
    k = cf__alloc_array(2 * (g.count + 1), sizeof *k);
    Q = cf__alloc_array(g.count * (size_t)(q + 1), c->hdim * sizeof *Q);
    if (k == NULL || Q == NULL) {
        st = cf__bspline_no_memory(diag);
        goto done;
    }
    target = k + g.count + 1;
    for (size_t s = 0; s <= g.count; s++) {
        int cont = s == 0 || s == g.count
                       ? 0
                       : c->p - cf__knots_mult(c->U, c->nknots, g.breaks[s]);
        target[s] = cont < q - 1 ? cont : q - 1;
        k[s] = cont < (q - 1) / 2 ? cont : (q - 1) / 2;
    }
    st = pieces(&g, q, k, o.method, Q, &worst, &which, diag);
    if (st == CF_STATUS_OK && worst > o.tolerance) {
        /* the smallest error: C^0 breaks (C^-1 where the original jumps) */
        for (size_t s = 1; s < g.count; s++)
            k[s] = k[s] < 0 ? k[s] : 0;
        st = pieces(&g, q, k, o.method, Q, &worst, &which, diag);
    }
    if (st != CF_STATUS_OK)
        goto done;
    if (worst > o.tolerance) {
        if (report != NULL) {
            memset(report, 0, sizeof *report);
            report->bound = worst;
        }
        st = cf__error(diag, CF_STATUS_NO_CONVERGENCE, (long)which,
                       "reducing degree %d to %d needs an error of at "
                       "least %.3g (piece %zu, on [%s, %s]); the tolerance "
                       "is %.3g", c->p, q, worst, which,
                       CF__NUM(g.breaks[which]),
                       CF__NUM(g.breaks[which + 1]), o.tolerance);
        goto done;
    }
    st = assemble(&g, q, Q, target, o.tolerance, &F, &removed, diag);
    if (st == CF_STATUS_OK && report != NULL) {
        memset(report, 0, sizeof *report);
        st = errors(&g, F, 0, g.count, 0.0, &report->bound, report, diag);
        report->knots_removed = removed;
        report->continuity = q;
        for (size_t s = 1; s < g.count; s++) {
            int cont = q - cf__knots_mult(F->U, F->nknots, g.breaks[s]);
            report->continuity = cont < report->continuity
                                     ? cont
                                     : report->continuity;
        }
        if (g.count == 1)
            report->continuity = -1;
    }
    if (st != CF_STATUS_OK) {
        cf_bspline_destroy(F);
        goto done;
    }
    *out = F;
done:
    cf__free(k);
    cf__free(Q);
    cf_free(g.hp);
    cf_free(g.breaks);
    return st;
}
