/*
** The kept parts of the raw offset chain.  Whole raw pieces are kept as
** they are; a kept piece whose end moved (to a crossing or a transition)
** is fitted again on the parameter range it now offsets, so that the
** trimmed chains carry measured errors like the raw one.
*/
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "core-private.h"
#include "bezier-private.h"
#include "offset-trim-private.h"

/* The circle that join arc i of the raw chain approximates, as an arc
** source from the radial projection of seg's first point to that of its
** last, turning as seg does. */
static void
arc_source(const cf__trim_t *tr, size_t i, const double *seg, cf__osrc_t *arc)
{
    double T = tr->raw->t[i], c[2], p[2], dp[2], a0, sweep;
    size_t k = cf__trim_base_of(tr, T);
    cf__bezier_eval_point(tr->base[k], cf__trim_to_local(tr, k, T), c);
    a0 = atan2(seg[1] - c[1], seg[0] - c[0]);
    sweep = atan2(seg[7] - c[1], seg[6] - c[0]) - a0;
    cf__cubic_pd(seg, 0.5, p, dp);
    if ((p[0] - c[0]) * dp[1] - (p[1] - c[1]) * dp[0] >= 0.0) {
        while (sweep < 0.0)
            sweep += 2.0 * CF__PI;
    } else {
        while (sweep > 0.0)
            sweep -= 2.0 * CF__PI;
    }
    cf__osrc_init_arc(arc, c[0], c[1], fabs(tr->d), a0, sweep);
}

/* Move an end of the cubic pts to snap (with its neighbouring control
** point); the error grows by at most the distance moved. */
static void
snap_end(double *pts, int end, const double *snap, double *err)
{
    double *e = pts + (end ? 6 : 0), *n = pts + (end ? 4 : 2);
    double dx = snap[0] - e[0], dy = snap[1] - e[1];
    e[0] = snap[0];
    e[1] = snap[1];
    n[0] += dx;
    n[1] += dy;
    *err += hypot(dx, dy);
}

/* Fit the source on [a, b] (covering source parameters [Ta, Tb]) with
** Levien's fit, ends snapped; a piece that misses the tolerance is split
** in two (and so on, to a minimum width).  Pushed onto ch. */
static cf_status_t
refit(cf__trim_t *tr, cf__chain_t *ch, const cf__osrc_t *src, double a,
      double b, double Ta, double Tb, const double *snap0, const double *snap1,
      int depth)
{
    cf__fit_t f;
    cf_status_t st = cf__fit_piece(src, a, b, CF_OFFSET_LEVIEN,
                                   CF__TRIM_ACCEPT * tr->tol, &f);
    if (st != CF_STATUS_OK)
        return st;
    if (f.err > CF__TRIM_ACCEPT * tr->tol && depth < 12 && b - a > 1e-9) {
        double m = 0.5 * (a + b), Tm = 0.5 * (Ta + Tb);
        st = refit(tr, ch, src, a, m, Ta, Tm, snap0, NULL, depth + 1);
        if (st == CF_STATUS_OK)
            st = refit(tr, ch, src, m, b, Tm, Tb, NULL, snap1, depth + 1);
        return st;
    }
    if (snap0 != NULL)
        snap_end(f.pts, 0, snap0, &f.err);
    if (snap1 != NULL)
        snap_end(f.pts, 1, snap1, &f.err);
    ch->cubics->max_error = fmax(ch->cubics->max_error, f.err);
    return cf__chain_push(ch, f.pts, Ta, Tb);
}

/* The source parameter of a cut end q of raw piece i (src, on base piece
** k) that has none: the projection of q, moved towards T_kept to where the
** distance reaches |d| - CF__TRIM_KEEP tol. */
static double
cut_T(const cf__trim_t *tr, size_t i, const cf__osrc_t *src, size_t k,
      const double *q, double T_kept)
{
    double u = cf__trim_to_local(tr, k, cf__trim_project(tr, i, src, k, q));
    double kept = cf__trim_to_local(tr, k, T_kept);
    return cf__trim_to_global(tr, k, cf__trim_src_keep(tr, src, u, kept));
}

/* Refit the part seg of raw piece i whose ends are the cuts c0 (NULL: the
** piece's start) and c1 (NULL: its end). */
static cf_status_t
refit_part(cf__trim_t *tr, cf__chain_t *ch, size_t i, const double *seg,
           const cf__trim_cut_t *c0, const cf__trim_cut_t *c1,
           const double *snap0, const double *snap1)
{
    const cf_cubics_t *raw = tr->raw;
    cf__osrc_t src;
    size_t k;
    double Ta, Tb;
    if (cf__trim_piece_source(tr, i, &src, &k) != 0) {
        /* a join arc: a cut end that is not a crossing is moved along the
        ** circle to where its distance reaches |d| - CF__TRIM_KEEP tol */
        double ua = 0.0, ub = 1.0;
        arc_source(tr, i, seg, &src);
        if (c0 != NULL && snap0 == NULL)
            ua = cf__trim_src_keep(tr, &src, 0.0, 1.0);
        if (c1 != NULL && snap1 == NULL)
            ub = cf__trim_src_keep(tr, &src, 1.0, ua);
        if (!(ub > ua))
            return CF_STATUS_OK;
        cf__osrc_init_arc(&src, src.cx, src.cy, src.r,
                          src.a0 + src.sweep * ua, src.sweep * (ub - ua));
        return refit(tr, ch, &src, 0.0, 1.0, raw->t[i], raw->t[i],
                     snap0, snap1, 0);
    }
    Ta = raw->t[i];
    Tb = raw->t[i + 1];
    /* an end without a parameter: a crossing of the raw chain only */
    if (c0 != NULL)
        Ta = c0->has_T ? c0->T : cut_T(tr, i, &src, k, seg, Tb);
    if (c1 != NULL)
        Tb = c1->has_T ? c1->T : cut_T(tr, i, &src, k, seg + 6, Ta);
    Ta = fmax(raw->t[i], fmin(raw->t[i + 1], Ta));
    Tb = fmax(raw->t[i], fmin(raw->t[i + 1], Tb));
    if (!(Tb > Ta))
        return CF_STATUS_OK;    /* both cuts at one point: nothing left */
    return refit(tr, ch, &src, cf__trim_to_local(tr, k, Ta),
                 cf__trim_to_local(tr, k, Tb), Ta, Tb, snap0, snap1, 0);
}

/* Append the part [g0, g1] of the raw chain to ch.  Whole raw pieces are
** kept as they are; a piece cut at c0 or c1 is fitted again on the range
** of the exact offset it now covers, an end at an exact crossing (snap)
** placed on it. */
cf_status_t
cf__trim_append_part(cf__trim_t *tr, cf__chain_t *ch, double g0, double g1,
                     const cf__trim_cut_t *c0, const cf__trim_cut_t *c1)
{
    const cf_cubics_t *raw = tr->raw;
    size_t i0 = (size_t)floor(g0), i1, first = SIZE_MAX, last = 0;
    if (i0 >= raw->count)
        i0 = raw->count - 1;
    i1 = (size_t)ceil(g1);
    if (i1 > raw->count)
        i1 = raw->count;
    for (size_t i = i0; i < i1; i++) {
        double s0 = fmax(0.0, g0 - (double)i), s1 = fmin(1.0, g1 - (double)i);
        if (s1 - s0 <= 1e-12)
            continue;
        if (first == SIZE_MAX)
            first = i;
        last = i;
    }
    for (size_t i = first; first != SIZE_MAX && i <= last; i++) {
        double s0 = fmax(0.0, g0 - (double)i), s1 = fmin(1.0, g1 - (double)i);
        double tmp[8], seg[8], e = raw->max_error;
        const double *snap0 = i == first && c0 != NULL ? c0->snap : NULL;
        const double *snap1 = i == last && c1 != NULL ? c1->snap : NULL;
        cf_status_t st;
        if (s1 - s0 <= 1e-12)
            continue;
        if (s0 > 0.0 || s1 < 1.0) {
            cf__bp_split(raw->pts + 8 * i, 2, 3, s1, tmp, NULL);
            if (s0 > 0.0)
                cf__bp_split(tmp, 2, 3, s0 / s1, NULL, seg);
            else
                memcpy(seg, tmp, sizeof seg);
            st = refit_part(tr, ch, i, seg,
                            s0 > 0.0 ? c0 : NULL, s1 < 1.0 ? c1 : NULL,
                            snap0, snap1);
            if (st != CF_STATUS_OK)
                return st;
            continue;
        }
        memcpy(seg, raw->pts + 8 * i, sizeof seg);
        if (snap0 != NULL)
            snap_end(seg, 0, snap0, &e);
        if (snap1 != NULL)
            snap_end(seg, 1, snap1, &e);
        ch->cubics->max_error = fmax(ch->cubics->max_error, e);
        st = cf__chain_push(ch, seg, raw->t[i], raw->t[i + 1]);
        if (st != CF_STATUS_OK)
            return st;
    }
    return CF_STATUS_OK;
}
