/*
** Trimming the raw offset: its self-intersections (pairs of cubics, found on
** fine polylines and polished by Newton's method on the cubics), then the
** parts whose distance to the base curve is at least |d| - tol are kept.
** Between two consecutive split points the classification is constant
** except where the offset leaves the swept disk without crossing itself (at
** the ends of an open curve); such transitions are located by bisection on
** the distance.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core-private.h"
#include "bezier-private.h"
#include "offset-private.h"

#define POLY_N 64       /* polyline samples per cubic */
#define BASE_N 256      /* samples of each base piece */
#define CLASS_N 16      /* distance samples per trimmed interval */

/* A split point of the raw chain; at a self-intersection, p is the
** crossing of the exact offset (when found) that the trimmed pieces end
** at. */
typedef struct split {
    double g;
    double p[2];
    bool exact;
} split;

typedef struct trim {
    const cf_bezier_t *const *base;
    size_t nbase;
    double *bsmp;           /* BASE_N + 1 samples per base piece */
    double d, tol;
    const cf_cubics_t *raw;
    double *poly;           /* POLY_N + 1 samples per raw cubic */
    split *splits;          /* at global parameters i + s */
    size_t nsplit, capsplit;
    size_t nisect;
} trim;

static void
base_fn(const void *ctx, double u, double *p, double *dp)
{
    double v[4];
    cf_bezier_eval_derivs(ctx, u, 1, v);
    p[0] = v[0];
    p[1] = v[1];
    dp[0] = v[2];
    dp[1] = v[3];
}

/* Distance of q to the base curve (all pieces). */
static double
base_dist(const trim *tr, const double *q)
{
    double best = INFINITY;
    for (size_t i = 0; i < tr->nbase; i++)
        best = fmin(best, cf__dist_sampled(base_fn, tr->base[i],
                                           tr->bsmp + 2 * (BASE_N + 1) * i,
                                           BASE_N, q));
    return best;
}

/* Point of the raw chain at global parameter g = i + s. */
static void
chain_point(const trim *tr, double g, double *p)
{
    size_t i = (size_t)floor(g);
    double s;
    if (i >= tr->raw->count)
        i = tr->raw->count - 1;
    s = g - (double)i;
    cf__cubic_pd(tr->raw->pts + 8 * i, fmin(1.0, fmax(0.0, s)), p, NULL);
}

static cf_status_t
add_split(trim *tr, double g, const double *p)
{
    if (tr->nsplit == tr->capsplit) {
        size_t cap = tr->capsplit ? 2 * tr->capsplit : 16;
        split *n = cf__realloc_array(tr->splits, cap, sizeof *n);
        if (n == NULL)
            return CF_STATUS_NO_MEMORY;
        tr->splits = n;
        tr->capsplit = cap;
    }
    tr->splits[tr->nsplit].g = g;
    tr->splits[tr->nsplit].exact = p != NULL;
    if (p != NULL) {
        tr->splits[tr->nsplit].p[0] = p[0];
        tr->splits[tr->nsplit].p[1] = p[1];
    }
    tr->nsplit++;
    return CF_STATUS_OK;
}

/* The crossing of the exact offset near the crossing of raw pieces i (at
** s) and j (at u): Newton on o(t1) - o(t2) = 0 from the pieces' parameter
** ranges (one base curve only).  Returns 0 and the point in x. */
static int
exact_crossing(const trim *tr, size_t i, double s, size_t j, double u,
               const double *approx, double *x)
{
    const cf_cubics_t *raw = tr->raw;
    cf__osrc_t src;
    double t1, t2, p1[2], d1[2], p2[2], d2[2];
    if (tr->nbase != 1 || !(raw->t[i + 1] > raw->t[i]) ||
        !(raw->t[j + 1] > raw->t[j]))
        return -1;
    cf__osrc_init_offset(&src, tr->base[0], tr->d);
    t1 = raw->t[i] + s * (raw->t[i + 1] - raw->t[i]);
    t2 = raw->t[j] + u * (raw->t[j + 1] - raw->t[j]);
    for (int it = 0; it < 30; it++) {
        double fx, fy, det, dt1, dt2;
        cf__osrc_deriv(&src, t1, p1, d1);
        cf__osrc_deriv(&src, t2, p2, d2);
        fx = p1[0] - p2[0];
        fy = p1[1] - p2[1];
        det = d1[0] * (-d2[1]) - d1[1] * (-d2[0]);
        if (det == 0.0)
            return -1;
        dt1 = (fx * (-d2[1]) - fy * (-d2[0])) / det;
        dt2 = (d1[0] * fy - d1[1] * fx) / det;
        t1 -= dt1;
        t2 -= dt2;
        if (!(t1 >= 0.0 && t1 <= 1.0 && t2 >= 0.0 && t2 <= 1.0))
            return -1;
        if (fabs(dt1) + fabs(dt2) < 1e-15)
            break;
    }
    cf__osrc_deriv(&src, t1, p1, d1);
    cf__osrc_deriv(&src, t2, p2, d2);
    if (!(hypot(p1[0] - p2[0], p1[1] - p2[1]) <= 1e-9 * (1.0 + fabs(tr->d))))
        return -1;
    x[0] = 0.5 * (p1[0] + p2[0]);
    x[1] = 0.5 * (p1[1] + p2[1]);
    /* it must be the crossing the raw chain approximates */
    if (!(hypot(x[0] - approx[0], x[1] - approx[1]) <= 4.0 * tr->tol))
        return -1;
    return 0;
}

/* Newton on B_i(s) - B_j(u) = 0 from (s, u); returns 0 on convergence. */
static int
polish_isect(const double *Pi, const double *Pj, double *s, double *u)
{
    for (int it = 0; it < 20; it++) {
        double a[2], da[2], b[2], db[2], fx, fy, det, ds, du;
        cf__cubic_pd(Pi, *s, a, da);
        cf__cubic_pd(Pj, *u, b, db);
        fx = a[0] - b[0];
        fy = a[1] - b[1];
        /* J = [da, -db] */
        det = da[0] * (-db[1]) - da[1] * (-db[0]);
        if (det == 0.0)
            return -1;
        ds = (fx * (-db[1]) - fy * (-db[0])) / det;
        du = (da[0] * fy - da[1] * fx) / det;
        *s -= ds;
        *u -= du;
        if (!(*s >= -1e-9 && *s <= 1 + 1e-9 && *u >= -1e-9 && *u <= 1 + 1e-9))
            return -1;
        if (fabs(ds) + fabs(du) < 1e-14)
            break;
    }
    *s = fmin(1.0, fmax(0.0, *s));
    *u = fmin(1.0, fmax(0.0, *u));
    return 0;
}

static void
ctrl_box(const double *P, double *lo, double *hi)
{
    lo[0] = hi[0] = P[0];
    lo[1] = hi[1] = P[1];
    for (int k = 1; k < 4; k++) {
        lo[0] = fmin(lo[0], P[2 * k]);
        hi[0] = fmax(hi[0], P[2 * k]);
        lo[1] = fmin(lo[1], P[2 * k + 1]);
        hi[1] = fmax(hi[1], P[2 * k + 1]);
    }
}

/* Proper crossing of segments ab and cd: parameters in *x, *y. */
static int
seg_cross(const double *a, const double *b, const double *c,
          const double *d, double *x, double *y)
{
    double r[2] = { b[0] - a[0], b[1] - a[1] };
    double s[2] = { d[0] - c[0], d[1] - c[1] };
    double den = r[0] * s[1] - r[1] * s[0];
    double q[2] = { c[0] - a[0], c[1] - a[1] };
    if (den == 0.0)
        return 0;
    *x = (q[0] * s[1] - q[1] * s[0]) / den;
    *y = (q[0] * r[1] - q[1] * r[0]) / den;
    return *x >= 0.0 && *x < 1.0 && *y >= 0.0 && *y < 1.0;
}

/* Is the crossing (gi, gj) already recorded (splits come in pairs)? */
static bool
known(const trim *tr, double gi, double gj)
{
    for (size_t k = 0; k + 1 < tr->nsplit; k += 2)
        if (fabs(tr->splits[k].g - gi) < 1e-9 &&
            fabs(tr->splits[k + 1].g - gj) < 1e-9)
            return true;
    return false;
}

static cf_status_t
find_intersections(trim *tr)
{
    const cf_cubics_t *raw = tr->raw;
    size_t n = raw->count;
    for (size_t i = 0; i < n; i++) {
        double loi[2], hii[2];
        ctrl_box(raw->pts + 8 * i, loi, hii);
        for (size_t j = i + 1; j < n; j++) {
            double loj[2], hij[2];
            const double *pi = tr->poly + 2 * (POLY_N + 1) * i;
            const double *pj = tr->poly + 2 * (POLY_N + 1) * j;
            ctrl_box(raw->pts + 8 * j, loj, hij);
            if (loi[0] > hij[0] || loj[0] > hii[0] || loi[1] > hij[1] ||
                loj[1] > hii[1])
                continue;
            for (int a = 0; a < POLY_N; a++) {
                for (int b = 0; b < POLY_N; b++) {
                    double x, y, s, u;
                    if (j == i + 1 && a == POLY_N - 1 && b == 0)
                        continue;   /* the shared end point */
                    if (!seg_cross(pi + 2 * a, pi + 2 * a + 2, pj + 2 * b,
                                   pj + 2 * b + 2, &x, &y))
                        continue;
                    s = (a + x) / POLY_N;
                    u = (b + y) / POLY_N;
                    if (polish_isect(raw->pts + 8 * i, raw->pts + 8 * j, &s,
                                     &u) != 0) {
                        s = (a + x) / POLY_N;
                        u = (b + y) / POLY_N;
                    }
                    if (j == i + 1 && s > 1.0 - 1e-7 && u < 1e-7)
                        continue;
                    if (known(tr, (double)i + s, (double)j + u))
                        continue;   /* found from a neighbouring pair */
                    {
                        double ap[2], xc[2];
                        const double *xp = NULL;
                        cf_status_t st;
                        cf__cubic_pd(raw->pts + 8 * i, s, ap, NULL);
                        if (exact_crossing(tr, i, s, j, u, ap, xc) == 0)
                            xp = xc;
                        st = add_split(tr, (double)i + s, xp);
                        if (st == CF_STATUS_OK)
                            st = add_split(tr, (double)j + u, xp);
                        if (st != CF_STATUS_OK)
                            return st;
                    }
                    tr->nisect++;
                }
            }
        }
    }
    return CF_STATUS_OK;
}

static int
cmp_split(const void *x, const void *y)
{
    double a = ((const split *)x)->g, b = ((const split *)y)->g;
    return (a > b) - (a < b);
}

/* Inside the swept disk: closer to the curve than |d| - margin.  Pieces
** are classified with margin 2 tol (the raw chain is within tol of the
** exact offset, which is at distance >= |d| where it is kept); the cut
** between a kept and a dropped sample is placed where the distance reaches
** |d| - tol, so that what is kept stays at distance >= |d| - tol. */
static bool
inside(const trim *tr, double g, double margin)
{
    double p[2];
    chain_point(tr, g, p);
    return base_dist(tr, p) < fabs(tr->d) - margin * tr->tol;
}

/* Append the part [g0, g1] of the raw chain to ch; an end with a snap
** point (an exact crossing) is moved there together with its neighbouring
** control point. */
static cf_status_t
append_part(const trim *tr, cf__chain_t *ch, double g0, double g1,
            const double *snap0, const double *snap1)
{
    const cf_cubics_t *raw = tr->raw;
    size_t i0 = (size_t)floor(g0), i1;
    bool first = true;
    if (i0 >= raw->count)
        i0 = raw->count - 1;
    i1 = (size_t)ceil(g1);
    if (i1 > raw->count)
        i1 = raw->count;
    for (size_t i = i0; i < i1; i++) {
        double s0 = fmax(0.0, g0 - (double)i), s1 = fmin(1.0, g1 - (double)i);
        double tmp[8], seg[8];
        cf_status_t st;
        if (s1 - s0 <= 1e-12)
            continue;
        cf__bp_split(raw->pts + 8 * i, 2, 3, s1, tmp, NULL);
        if (s0 > 0.0)
            cf__bp_split(tmp, 2, 3, s0 / s1, NULL, seg);
        else
            memcpy(seg, tmp, sizeof seg);
        for (int k = 0; k < 2; k++) {
            if (first && snap0 != NULL) {
                seg[2 + k] += snap0[k] - seg[k];
                seg[k] = snap0[k];
            }
            if (i + 1 == i1 && snap1 != NULL) {
                seg[4 + k] += snap1[k] - seg[6 + k];
                seg[6 + k] = snap1[k];
            }
        }
        first = false;
        st = cf__chain_push(ch, seg, raw->t[i], raw->t[i + 1]);
        if (st != CF_STATUS_OK)
            return st;
    }
    return CF_STATUS_OK;
}

static cf_status_t
list_add(cf_cubics_list_t *list, size_t *cap, cf_cubics_t *ch)
{
    if (list->count == *cap) {
        size_t nc = *cap ? 2 * *cap : 4;
        cf_cubics_t **n = cf__realloc_array(list->chains, nc, sizeof *n);
        if (n == NULL) {
            cf_cubics_destroy(ch);
            return CF_STATUS_NO_MEMORY;
        }
        list->chains = n;
        *cap = nc;
    }
    list->chains[list->count++] = ch;
    return CF_STATUS_OK;
}

cf_status_t
cf__offset_trim(const cf_bezier_t *const *base, size_t nbase, double d,
                double tol, const cf_cubics_t *raw, cf_cubics_list_t **out,
                size_t *nisect)
{
    trim tr;
    cf_cubics_list_t *list;
    size_t cap = 0, nraw = raw->count;
    cf_status_t st = CF_STATUS_OK;
    cf__chain_t ch;
    bool open = false;

    *out = NULL;
    *nisect = 0;
    memset(&tr, 0, sizeof tr);
    tr.base = base;
    tr.nbase = nbase;
    tr.d = d;
    tr.tol = tol;
    tr.raw = raw;
    list = cf__calloc(1, sizeof *list);
    tr.bsmp = cf__alloc_array(2 * (BASE_N + 1) * nbase, sizeof(double));
    tr.poly = cf__alloc_array(2 * (POLY_N + 1) * (nraw ? nraw : 1),
                              sizeof(double));
    if (list == NULL || tr.bsmp == NULL || tr.poly == NULL) {
        st = CF_STATUS_NO_MEMORY;
        goto done;
    }
    for (size_t i = 0; i < nbase; i++)
        for (int k = 0; k <= BASE_N; k++)
            cf__bezier_eval_point(base[i], (double)k / BASE_N,
                                  tr.bsmp + 2 * ((BASE_N + 1) * i + k));
    for (size_t i = 0; i < nraw; i++)
        for (int k = 0; k <= POLY_N; k++)
            cf__cubic_pd(raw->pts + 8 * i, (double)k / POLY_N,
                     tr.poly + 2 * ((POLY_N + 1) * i + k), NULL);
    if (nraw == 0 || d == 0.0) {
        /* nothing to trim: the raw chain is the trimmed one */
        if (nraw > 0) {
            st = cf__chain_init(&ch);
            if (st == CF_STATUS_OK)
                st = append_part(&tr, &ch, 0.0, (double)nraw, NULL, NULL);
            if (st == CF_STATUS_OK)
                st = list_add(list, &cap, cf__chain_take(&ch));
            else
                cf__chain_fini(&ch);
        }
        goto done;
    }
    st = find_intersections(&tr);
    if (st == CF_STATUS_OK)
        st = add_split(&tr, 0.0, NULL);
    if (st == CF_STATUS_OK)
        st = add_split(&tr, (double)nraw, NULL);
    if (st != CF_STATUS_OK)
        goto done;
    qsort(tr.splits, tr.nsplit, sizeof(split), cmp_split);
    /* classify each interval by samples; locate transitions by bisection */
    for (size_t k = 0; k + 1 < tr.nsplit; k++) {
        double g0 = tr.splits[k].g, g1 = tr.splits[k + 1].g, start = g0;
        bool cls[CLASS_N];
        if (g1 - g0 < 1e-12)
            continue;
        for (int m = 0; m < CLASS_N; m++)
            cls[m] = inside(&tr, g0 + (g1 - g0) * (m + 0.5) / CLASS_N, 2.0);
        for (int m = 0; m < CLASS_N; m++) {
            double end = g1;
            if (m + 1 < CLASS_N && cls[m + 1] == cls[m])
                continue;
            if (m + 1 < CLASS_N) {
                double lo = g0 + (g1 - g0) * (m + 0.5) / CLASS_N;
                double hi = g0 + (g1 - g0) * (m + 1.5) / CLASS_N;
                /* bisect on "inside by |d| - tol" from the kept side */
                double in_end = cls[m] ? lo : hi, out_end = cls[m] ? hi : lo;
                for (int it = 0; it < 50; it++) {
                    double mid = 0.5 * (in_end + out_end);
                    if (inside(&tr, mid, 0.999))
                        in_end = mid;
                    else
                        out_end = mid;
                }
                end = out_end;
            }
            if (!cls[m]) {
                if (!open) {
                    st = cf__chain_init(&ch);
                    if (st != CF_STATUS_OK)
                        goto done;
                    open = true;
                }
                st = append_part(&tr, &ch, start, end,
                                 start == g0 && tr.splits[k].exact
                                     ? tr.splits[k].p : NULL,
                                 end == g1 && tr.splits[k + 1].exact
                                     ? tr.splits[k + 1].p : NULL);
                if (st != CF_STATUS_OK)
                    goto done;
            } else if (open) {
                st = list_add(list, &cap, cf__chain_take(&ch));
                open = false;
                if (st != CF_STATUS_OK)
                    goto done;
            }
            start = end;
        }
        /* an intersection point separates chains */
        if (open && k + 2 < tr.nsplit) {
            st = list_add(list, &cap, cf__chain_take(&ch));
            open = false;
            if (st != CF_STATUS_OK)
                goto done;
        }
    }
    if (open) {
        st = list_add(list, &cap, cf__chain_take(&ch));
        open = false;
    }
done:
    if (open)
        cf__chain_fini(&ch);
    cf__free(tr.bsmp);
    cf__free(tr.poly);
    cf__free(tr.splits);
    if (st != CF_STATUS_OK) {
        cf_cubics_list_destroy(list);
        return st;
    }
    /* drop empty chains */
    {
        size_t w = 0;
        for (size_t i = 0; i < list->count; i++) {
            if (list->chains[i]->count == 0)
                cf_cubics_destroy(list->chains[i]);
            else
                list->chains[w++] = list->chains[i];
        }
        list->count = w;
    }
    *out = list;
    *nisect = tr.nisect;
    return CF_STATUS_OK;
}
