/*
** The chain driver of the offsets and of the planar cubic fit: a piece is
** split at its offset cusps and at the zeros of c', each part covered by
** the longest fitted cubics within tolerance (Levien, greedy from either
** end) or by bisection (Tiller-Hanson), with round joins where the tangent
** turns.  The fits themselves are in fit-piece.c, the cusps in
** fit-cusp.c.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core-private.h"
#include "bezier-private.h"
#include "fit-private.h"



static double
map_t(const cf__driver_t *dr, double t)
{
    return dr->T0 + (dr->T1 - dr->T0) * t;
}

static cf_status_t
emit(cf__driver_t *dr, const cf__fit_t *f, double a, double b)
{
    if (dr->rep.segments >= CF__OFFSET_MAX_PIECES)
        return CF_STATUS_NO_CONVERGENCE;
    dr->rep.segments++;
    dr->rep.max_error = fmax(dr->rep.max_error, f->err);
    if (!(f->err <= dr->tol))
        dr->rep.converged = false;
    return cf__chain_push(&dr->chain, f->pts, map_t(dr, a), map_t(dr, b));
}

#define ACCEPT 0.97     /* accept a piece at 97% of the tolerance */
#define MIN_WIDTH 1e-12 /* no piece narrower than this (relative) */

/* Tiller-Hanson: bisection until within tolerance. */
static cf_status_t
fit_bisect(cf__driver_t *dr, const cf__osrc_t *s, double a, double b,
           double w0, int depth)
{
    cf__fit_t f;
    cf_status_t st =
        cf__fit_piece(s, a, b, dr->method, ACCEPT * dr->tol, &f);
    if (st != CF_STATUS_OK)
        return st;
    if (f.err <= ACCEPT * dr->tol || depth >= 40 || b - a < MIN_WIDTH * w0)
        return emit(dr, &f, a, b);
    st = fit_bisect(dr, s, a, 0.5 * (a + b), w0, depth + 1);
    if (st != CF_STATUS_OK)
        return st;
    return fit_bisect(dr, s, 0.5 * (a + b), b, w0, depth + 1);
}

typedef struct piece {
    cf__fit_t f;
    double a, b;
} piece;

typedef struct plist {
    piece *p;
    size_t n, cap;
} plist;

static cf_status_t
plist_add(plist *l, const cf__fit_t *f, double a, double b)
{
    piece *np;
    if (l->n >= CF__OFFSET_MAX_COVER)
        return CF_STATUS_NO_CONVERGENCE;
    np = cf__grow(l->p, &l->cap, l->n + 1, sizeof *np, 8);
    if (np == NULL)
        return CF_STATUS_NO_MEMORY;
    l->p = np;
    l->p[l->n].f = *f;
    l->p[l->n].a = a;
    l->p[l->n].b = b;
    l->n++;
    return CF_STATUS_OK;
}

static cf_status_t
fit_range(cf__driver_t *dr, const cf__osrc_t *s, double x, double y,
          cf__fit_t *f)
{
    return cf__fit_piece(s, fmin(x, y), fmax(x, y), dr->method,
                         ACCEPT * dr->tol, f);
}

/* Greedy cover of [a, b] by the longest pieces within tolerance, walking
** forward from a (dir > 0) or backward from b (dir < 0); each piece's far
** end is found by bisection. */
static cf_status_t
greedy_dir(cf__driver_t *dr, const cf__osrc_t *s, double a, double b, int dir,
           plist *out)
{
    double t = dir > 0 ? a : b, end = dir > 0 ? b : a, w0 = b - a;
    cf__fit_t f, best;
    cf_status_t st;
    while (dir > 0 ? t < b : t > a) {
        double near, far, e_near = 0.0, e_far;
        bool have = false;
        st = fit_range(dr, s, t, end, &f);
        if (st != CF_STATUS_OK)
            return st;
        if (f.err <= ACCEPT * dr->tol)
            return plist_add(out, &f, fmin(t, end), fmax(t, end));
        near = t;
        far = end;
        e_far = f.err;
        for (int it = 0; it < 60; it++) {
            double mid = 0.5 * (near + far), target = 0.99 * ACCEPT * dr->tol;
            /* the curve itself (d = 0, for path output) needs no more
            ** than 2 % of the piece: it is fitted on every rendering */
            if (have && fabs(far - near) <=
                            (dr->d == 0.0 ? 2e-2 : 2e-3) * fabs(far - t))
                break;
            if (fabs(far - t) < MIN_WIDTH * w0)
                break;
            /* the error grows about as a power of the length: the next
            ** trial where the model (log error linear in log length,
            ** through the bracket ends; slope 6 with one end) reaches the
            ** target, kept inside the middle 80 % of the bracket */
            if (e_far > 0.0 && isfinite(e_far)) {
                double lf = log(fabs(far - t)), slope = 6.0, h;
                if (have && e_near > 0.0 && fabs(near - t) > 0.0) {
                    double ln = log(fabs(near - t));
                    if (lf - ln > 1e-12)
                        slope = fmax(1.0, (log(e_far) - log(e_near)) /
                                              (lf - ln));
                }
                h = exp(lf + (log(target) - log(e_far)) / slope);
                mid = t + (far > t ? h : -h);
                {
                    double lo = near + 0.1 * (far - near),
                           hi = near + 0.9 * (far - near);
                    if (far > near)
                        mid = fmin(hi, fmax(lo, mid));
                    else
                        mid = fmax(hi, fmin(lo, mid));
                }
            }
            st = fit_range(dr, s, t, mid, &f);
            if (st != CF_STATUS_OK)
                return st;
            if (f.err <= ACCEPT * dr->tol) {
                near = mid;
                best = f;
                e_near = f.err;
                have = true;
            } else {
                far = mid;
                e_far = f.err;
            }
        }
        if (!have) {
            /* cannot reach the tolerance: keep the narrowest piece */
            st = fit_range(dr, s, t, far, &best);
            if (st != CF_STATUS_OK)
                return st;
            near = far;
        }
        st = plist_add(out, &best, fmin(t, near), fmax(t, near));
        if (st != CF_STATUS_OK)
            return st;
        t = near;
    }
    return CF_STATUS_OK;
}

/* Levien: the greedy cover from either end, whichever needs fewer
** pieces. */
static cf_status_t
fit_greedy(cf__driver_t *dr, const cf__osrc_t *s, double a, double b)
{
    plist fw = { NULL, 0, 0 }, bw = { NULL, 0, 0 };
    cf_status_t st = greedy_dir(dr, s, a, b, 1, &fw);
    /* the backward cover can save a piece only when the forward one ends
    ** with a short remainder */
    if (st == CF_STATUS_OK && fw.n > 1 &&
        fw.p[fw.n - 1].b - fw.p[fw.n - 1].a < 0.5 * (b - a) / (double)fw.n)
        st = greedy_dir(dr, s, a, b, -1, &bw);
    if (st == CF_STATUS_OK) {
        if (bw.n > 0 && bw.n < fw.n) {
            for (size_t i = bw.n; i-- > 0 && st == CF_STATUS_OK;)
                st = emit(dr, &bw.p[i].f, bw.p[i].a, bw.p[i].b);
        } else {
            for (size_t i = 0; i < fw.n && st == CF_STATUS_OK; i++)
                st = emit(dr, &fw.p[i].f, fw.p[i].a, fw.p[i].b);
        }
    }
    cf__free(fw.p);
    cf__free(bw.p);
    return st;
}

/* Round join: arc of radius |d| about centre from `from` turning by phi. */
static cf_status_t
join_arc(cf__driver_t *dr, const double *centre, const double *from,
         double phi, double tpar)
{
    cf__osrc_t arc;
    double r = hypot(from[0] - centre[0], from[1] - centre[1]);
    double a0 = atan2(from[1] - centre[1], from[0] - centre[0]);
    cf_offset_method_t m = dr->method;
    double T0 = dr->T0, T1 = dr->T1;
    cf_status_t st;
    if (!(r > 0.0) || phi == 0.0)
        return CF_STATUS_OK;
    cf__osrc_init_arc(&arc, centre[0], centre[1], r, a0, phi);
    dr->rep.joins++;
    /* the arc's pieces all carry the parameter tpar */
    dr->method = CF_OFFSET_LEVIEN;
    dr->T0 = dr->T1 = tpar;
    st = fit_greedy(dr, &arc, 0.0, 1.0);
    dr->method = m;
    dr->T0 = T0;
    dr->T1 = T1;
    return st;
}

/* |sin| of the angle between the unit tangents 1e-6 before and after a
** reversal below which the curve runs straight back: a curve that turns
** through its cusp turns them by about 1e-6 of its curvature scale, far
** above the rounding of straight data (1e-16). */
#define STRAIGHT_BACK 1e-12

/* Signed turning angle from direction u to direction v. */
static double
turn(const double *u, const double *v)
{
    return atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1]);
}

/* The join at a zero of c' inside the piece: the tangent reverses (turn of
** +-pi); its sense from the tangents just before and after, with the
** curve.  Where the curve runs straight back over itself (the tangents
** before and after are parallel: no sense to turn with), the arc goes
** round the tip, through c(t) + |d| times the incoming tangent, on either
** side: both sides are then outside, and the swept disk's boundary caps
** the tip. */
static cf_status_t
base_cusp_join(cf__driver_t *dr, const cf__osrc_t *s, double t)
{
    double p[2], ul[2], ur[2], from[2], a[2], b[2];
    double h = 1e-6, phi;
    const cf_bezier_t *c = s->c;
    cf__bezier_unit_tangent(c, t, -1, s->scale, p, ul);
    cf__bezier_unit_tangent(c, t, 1, s->scale, NULL, ur);
    phi = turn(ul, ur);
    if (fabs(fabs(phi) - CF__PI) < 1e-6) {
        double cr;
        cf__bezier_unit_tangent(c, fmax(0.0, t - h), -1, s->scale, NULL, a);
        cf__bezier_unit_tangent(c, fmin(1.0, t + h), 1, s->scale, NULL, b);
        cr = a[0] * b[1] - a[1] * b[0];
        if (fabs(cr) < STRAIGHT_BACK)
            phi = s->d > 0 ? -CF__PI : CF__PI;
        else
            phi = cr < 0 ? -CF__PI : CF__PI;
    }
    from[0] = p[0] - s->d * ul[1];
    from[1] = p[1] + s->d * ul[0];
    return join_arc(dr, p, from, phi, map_t(dr, t));
}

static bool
in_list(const double *v, size_t n, double x)
{
    for (size_t i = 0; i < n; i++)
        if (v[i] == x)
            return true;
    return false;
}

/* Offset of one Bézier piece appended to the chain. */
cf_status_t
cf__driver_piece(cf__driver_t *dr, const cf_bezier_t *c)
{
    double *cusps = NULL, *bc = NULL, *splits = NULL;
    size_t nc = 0, nb = 0, ns = 0;
    cf__osrc_t s;
    cf_status_t st;

    if (dr->d == 0.0 && !c->rational && c->degree <= 3) {
        /* the curve itself, exactly */
        cf_cubics_t *cu = NULL;
        st = cf__cubics_exact(c, &cu);
        if (st != CF_STATUS_OK)
            return st;
        for (size_t i = 0; i < cu->count && st == CF_STATUS_OK; i++) {
            cf__fit_t f;
            memcpy(f.pts, cu->pts + 8 * i, sizeof f.pts);
            f.err = cu->max_error;
            st = emit(dr, &f, cu->t[i], cu->t[i + 1]);
        }
        cf_cubics_destroy(cu);
        return st;
    }
    /* d = 0 (the source is the curve itself): fitted like any offset,
    ** split only at the zeros of c' */
    cf__osrc_init_offset(&s, c, dr->d);
    st = dr->d != 0.0 ? cf__offset_cusps_alloc(c, dr->d, &cusps, &nc)
                      : CF_STATUS_OK;
    if (st == CF_STATUS_OK)
        st = cf__base_cusps_alloc(c, &bc, &nb);
    if (st != CF_STATUS_OK)
        goto done;
    dr->rep.cusps += nc;
    splits = cf__alloc_array(nc + nb + 2, sizeof(double));
    if (splits == NULL) {
        st = CF_STATUS_NO_MEMORY;
        goto done;
    }
    splits[ns++] = 0.0;
    for (size_t i = 0; i < nc; i++)
        splits[ns++] = cusps[i];
    for (size_t i = 0; i < nb; i++)
        splits[ns++] = bc[i];
    splits[ns++] = 1.0;
    qsort(splits, ns, sizeof(double), cf__cmp_double);
    for (size_t i = 0; i + 1 < ns; i++) {
        double a = splits[i], b = splits[i + 1];
        bool is_base = false;
        if (b - a > 1e-13) {
            /* travel direction of o relative to c' on (a, b) */
            double v[6], sp, f;
            cf_bezier_eval_derivs(c, 0.5 * (a + b), 2, v);
            sp = hypot(v[2], v[3]);
            f = sp > 0 ? 1.0 - dr->d * (v[2] * v[5] - v[3] * v[4]) /
                                   (sp * sp * sp)
                       : 1.0;
            s.sgn = f < 0 ? -1.0 : 1.0;
            s.cusp_a = in_list(cusps, nc, a) ? a : -1.0;
            s.cusp_b = in_list(cusps, nc, b) ? b : -1.0;
            if (dr->method == CF_OFFSET_TILLER_HANSON)
                st = fit_bisect(dr, &s, a, b, b - a, 0);
            else
                st = fit_greedy(dr, &s, a, b);
            if (st != CF_STATUS_OK)
                goto done;
        }
        for (size_t k = 0; k < nb; k++)
            if (bc[k] == b)
                is_base = true;
        if (is_base) {
            st = base_cusp_join(dr, &s, b);
            if (st != CF_STATUS_OK)
                goto done;
        }
    }
done:
    cf__free(cusps);
    cf__free(bc);
    cf__free(splits);
    return st;
}

cf_status_t
cf__driver_init(cf__driver_t *dr, double tol, cf_offset_method_t method,
                double d)
{
    memset(dr, 0, sizeof *dr);
    dr->tol = tol;
    dr->method = method;
    dr->d = d;
    dr->T0 = 0.0;
    dr->T1 = 1.0;
    dr->rep.converged = true;
    return cf__chain_init(&dr->chain);
}

cf_status_t
cf__fit_plain(const cf_bezier_t *c, double tol, cf_cubics_t **out,
              bool *converged)
{
    cf__driver_t dr;
    cf_status_t st;
    *out = NULL;
    st = cf__driver_init(&dr, tol, CF_OFFSET_LEVIEN, 0.0);
    if (st != CF_STATUS_OK)
        return st;
    st = cf__driver_piece(&dr, c);
    if (st == CF_STATUS_OK && dr.chain.cubics->count == 0)
        st = CF_STATUS_NO_CONVERGENCE;
    if (st != CF_STATUS_OK) {
        cf__chain_fini(&dr.chain);
        return st;
    }
    dr.chain.cubics->max_error = dr.rep.max_error;
    *converged = dr.rep.converged;
    *out = cf__chain_take(&dr.chain);
    return CF_STATUS_OK;
}

/* Join between consecutive pieces that meet at an angle. */
cf_status_t
cf__driver_join(cf__driver_t *dr, const cf_bezier_t *prev,
                const cf_bezier_t *next)
{
    cf_cubics_t *cu = dr->chain.cubics;
    double p[2], ul[2], ur[2], start[2], *end;
    double sc = fmax(cf__deriv_scale(prev), cf__deriv_scale(next));
    if (cu->count == 0 || dr->d == 0.0)
        return CF_STATUS_OK;
    end = cu->pts + 8 * cu->count - 2;
    cf__bezier_unit_tangent(prev, 1.0, -1, sc, NULL, ul);
    cf__bezier_unit_tangent(next, 0.0, 1, sc, p, ur);
    start[0] = p[0] - dr->d * ur[1];
    start[1] = p[1] + dr->d * ur[0];
    if (hypot(start[0] - end[0], start[1] - end[1]) <=
        1e-9 * fmax(sc, fabs(dr->d)))
        return CF_STATUS_OK;
    {
        double e[2] = { end[0], end[1] };
        return join_arc(dr, p, e, turn(ul, ur), dr->T0);
    }
}
