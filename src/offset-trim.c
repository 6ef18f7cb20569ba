/*
** Trimming the raw offset: its self-intersections (pairs of cubics, found on
** fine polylines and polished by Newton's method on the cubics), then the
** parts whose distance to the base curve is at least |d| - tol are kept.
** Between two consecutive split points the classification is constant
** except where the offset leaves the swept disk without crossing itself (at
** the ends of an open curve); such transitions are located by bisection on
** the distance.  The kept parts are assembled by offset-refit.c.
*/
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core-private.h"
#include "bezier-private.h"
#include "offset-trim-private.h"

#define CLASS_N 16      /* distance samples per trimmed interval */

static cf_status_t
add_split(cf__trim_t *tr, double g, const double *p, double T)
{
    cf__trim_split_t *n = cf__grow(tr->splits, &tr->capsplit,
                                   tr->nsplit + 1, sizeof *n, 16);
    if (n == NULL)
        return CF_STATUS_NO_MEMORY;
    tr->splits = n;
    tr->splits[tr->nsplit].g = g;
    tr->splits[tr->nsplit].exact = p != NULL;
    tr->splits[tr->nsplit].T = T;
    if (p != NULL) {
        tr->splits[tr->nsplit].p[0] = p[0];
        tr->splits[tr->nsplit].p[1] = p[1];
    }
    tr->nsplit++;
    return CF_STATUS_OK;
}

/* Is T on the parameter range of raw piece i (to rounding)? */
static bool
on_range(const cf__trim_t *tr, size_t i, double T)
{
    double a = tr->raw->t[i], b = tr->raw->t[i + 1], e = 1e-12 * (b - a);
    return T >= a - e && T <= b + e;
}

/* The crossing of the exact offset near the crossing of raw pieces i (at
** s) and j (at u): Newton on o_i(t1) - o_j(t2) = 0 from the pieces'
** parameter ranges, o_i the exact offset that piece i approximates.
** Returns 0, the point in x and the two source parameters in T. */
static int
exact_crossing(const cf__trim_t *tr, size_t i, double s, size_t j, double u,
               const double *approx, double *x, double *T)
{
    cf__osrc_t si, sj;
    size_t ki, kj;
    double t1, t2, p1[2], d1[2], p2[2], d2[2];
    if (cf__trim_piece_source(tr, i, &si, &ki) != 0 ||
        cf__trim_piece_source(tr, j, &sj, &kj) != 0)
        return -1;
    t1 = cf__trim_to_local(tr, ki, cf__trim_g_to_T(tr, i, (double)i + s));
    t2 = cf__trim_to_local(tr, kj, cf__trim_g_to_T(tr, j, (double)j + u));
    for (int it = 0; it < 30; it++) {
        double fx, fy, det, dt1, dt2;
        cf__osrc_deriv(&si, t1, p1, d1);
        cf__osrc_deriv(&sj, t2, p2, d2);
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
    cf__osrc_deriv(&si, t1, p1, d1);
    cf__osrc_deriv(&sj, t2, p2, d2);
    if (!(hypot(p1[0] - p2[0], p1[1] - p2[1]) <= 1e-9 * (1.0 + fabs(tr->d))))
        return -1;
    x[0] = 0.5 * (p1[0] + p2[0]);
    x[1] = 0.5 * (p1[1] + p2[1]);
    /* it must be the crossing the raw chain approximates: near it, and on
    ** the ranges of the two pieces (their cut ends are fitted there) */
    if (!(hypot(x[0] - approx[0], x[1] - approx[1]) <= 4.0 * tr->tol))
        return -1;
    T[0] = cf__trim_to_global(tr, ki, t1);
    T[1] = cf__trim_to_global(tr, kj, t2);
    if (!on_range(tr, i, T[0]) || !on_range(tr, j, T[1]))
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
known(const cf__trim_t *tr, double gi, double gj)
{
    for (size_t k = 0; k + 1 < tr->nsplit; k += 2)
        if (fabs(tr->splits[k].g - gi) < 1e-9 &&
            fabs(tr->splits[k + 1].g - gj) < 1e-9)
            return true;
    return false;
}

static cf_status_t
find_intersections(cf__trim_t *tr)
{
    const cf_cubics_t *raw = tr->raw;
    size_t n = raw->count;
    for (size_t i = 0; i < n; i++) {
        double loi[2], hii[2];
        ctrl_box(raw->pts + 8 * i, loi, hii);
        for (size_t j = i + 1; j < n; j++) {
            double loj[2], hij[2];
            const double *pi = tr->poly + 2 * (CF__TRIM_POLY_N + 1) * i;
            const double *pj = tr->poly + 2 * (CF__TRIM_POLY_N + 1) * j;
            ctrl_box(raw->pts + 8 * j, loj, hij);
            if (loi[0] > hij[0] || loj[0] > hii[0] || loi[1] > hij[1] ||
                loj[1] > hii[1])
                continue;
            for (int a = 0; a < CF__TRIM_POLY_N; a++) {
                for (int b = 0; b < CF__TRIM_POLY_N; b++) {
                    double x, y, s, u;
                    if (j == i + 1 && a == CF__TRIM_POLY_N - 1 && b == 0)
                        continue;   /* the shared end point */
                    if (!seg_cross(pi + 2 * a, pi + 2 * a + 2, pj + 2 * b,
                                   pj + 2 * b + 2, &x, &y))
                        continue;
                    s = (a + x) / CF__TRIM_POLY_N;
                    u = (b + y) / CF__TRIM_POLY_N;
                    if (polish_isect(raw->pts + 8 * i, raw->pts + 8 * j, &s,
                                     &u) != 0) {
                        s = (a + x) / CF__TRIM_POLY_N;
                        u = (b + y) / CF__TRIM_POLY_N;
                    }
                    if (j == i + 1 && s > 1.0 - 1e-7 && u < 1e-7)
                        continue;
                    if (known(tr, (double)i + s, (double)j + u))
                        continue;   /* found from a neighbouring pair */
                    {
                        double ap[2], xc[2], T[2] = { 0.0, 0.0 };
                        const double *xp = NULL;
                        cf_status_t st;
                        cf__cubic_pd(raw->pts + 8 * i, s, ap, NULL);
                        if (exact_crossing(tr, i, s, j, u, ap, xc, T) == 0)
                            xp = xc;
                        st = add_split(tr, (double)i + s, xp, T[0]);
                        if (st == CF_STATUS_OK)
                            st = add_split(tr, (double)j + u, xp, T[1]);
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
    double a = ((const cf__trim_split_t *)x)->g,
           b = ((const cf__trim_split_t *)y)->g;
    return (a > b) - (a < b);
}

/* Inside the swept disk: closer to the curve than |d| - margin.  Pieces
** are classified with margin 2 tol (the raw chain is within tol of the
** exact offset, which is at distance >= |d| where it is kept); the cut
** between a kept and a dropped sample is placed where the distance reaches
** |d| - tol, so that what is kept stays at distance >= |d| - tol. */
static bool
inside(const cf__trim_t *tr, double g, double margin)
{
    double p[2];
    cf__trim_chain_point(tr, g, p);
    return cf__trim_base_dist(tr, p) < fabs(tr->d) - margin * tr->tol;
}

/* The transition between g_in (inside) and g_out (kept) of the raw chain
** located on the exact offset: bisection in its parameter (the raw
** pieces' ranges mapped linearly) on the distance |d| - CF__TRIM_KEEP
** tol.  On success the cut is *g (on the raw chain) and *T; -1 if the
** bracket is not one of the exact offset (a join arc between, another base
** piece, or the classes differ there). */
static int
exact_transition(const cf__trim_t *tr, double g_in, double g_out, double *g,
                 double *T)
{
    const cf_cubics_t *raw = tr->raw;
    size_t i_in = cf__trim_piece_at(tr, g_in),
           i_out = cf__trim_piece_at(tr, g_out), k, k2, i;
    cf__osrc_t src, s2;
    double T_in, T_out;
    if (cf__trim_piece_source(tr, i_in, &src, &k) != 0 ||
        cf__trim_piece_source(tr, i_out, &s2, &k2) != 0 || k != k2 ||
        (i_in > i_out ? i_in - i_out : i_out - i_in) > 1)
        return -1;
    T_in = cf__trim_g_to_T(tr, i_in, g_in);
    T_out = cf__trim_g_to_T(tr, i_out, g_out);
    if (!cf__trim_exact_inside(tr, &src, k, T_in) ||
        cf__trim_exact_inside(tr, &src, k, T_out))
        return -1;
    T_out = cf__trim_to_global(tr, k,
                               cf__trim_bisect_keep(
                                   tr, &src, cf__trim_to_local(tr, k, T_in),
                                   cf__trim_to_local(tr, k, T_out)));
    i = T_out >= raw->t[i_out] && T_out <= raw->t[i_out + 1] ? i_out : i_in;
    *T = T_out;
    *g = cf__trim_T_to_g(tr, i, T_out);
    return 0;
}

/* The transition at the raw chain's cut g (kept side towards g_out) when
** its bracket is not one of the exact offset: from the projection of the
** cut onto the exact offset of its piece, bisection towards the kept end
** of that piece until the distance is |d| - CF__TRIM_KEEP tol.  -1 on a
** join arc or if that end is inside too. */
static int
exact_cut(const cf__trim_t *tr, double g_cut, double g_out, double *g,
          double *T)
{
    const cf_cubics_t *raw = tr->raw;
    size_t i = cf__trim_piece_at(tr, g_cut), k;
    cf__osrc_t src;
    double q[2], T_in, T_out;
    if (cf__trim_piece_source(tr, i, &src, &k) != 0)
        return -1;
    cf__trim_chain_point(tr, g_cut, q);
    T_in = cf__trim_project(tr, i, &src, k, q);
    if (cf__trim_exact_inside(tr, &src, k, T_in)) {
        T_out = g_out > g_cut ? raw->t[i + 1] : raw->t[i];
        if (cf__trim_exact_inside(tr, &src, k, T_out))
            return -1;
        T_in = cf__trim_to_global(
            tr, k,
            cf__trim_bisect_keep(tr, &src, cf__trim_to_local(tr, k, T_in),
                                 cf__trim_to_local(tr, k, T_out)));
    }
    *T = T_in;
    *g = cf__trim_T_to_g(tr, i, T_in);
    return 0;
}

static cf_status_t
list_add(cf_cubics_list_t *list, size_t *cap, cf_cubics_t *ch)
{
    cf_cubics_t **n = cf__grow(list->chains, cap, list->count + 1,
                               sizeof *n, 4);
    if (n == NULL) {
        cf_cubics_destroy(ch);
        return CF_STATUS_NO_MEMORY;
    }
    list->chains = n;
    list->chains[list->count++] = ch;
    return CF_STATUS_OK;
}

cf_status_t
cf__offset_trim(const cf_bezier_t *const *base, size_t nbase,
                const double *t0, const double *t1, double d, double tol,
                const cf_cubics_t *raw, cf_cubics_list_t **out,
                size_t *nisect)
{
    cf__trim_t tr;
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
    tr.t0 = t0;
    tr.t1 = t1;
    tr.d = d;
    tr.tol = tol;
    tr.raw = raw;
    list = cf__calloc(1, sizeof *list);
    tr.bsmp = cf__alloc_array(2 * (CF__TRIM_BASE_N + 1) * nbase,
                              sizeof(double));
    tr.poly = cf__alloc_array(2 * (CF__TRIM_POLY_N + 1) * (nraw ? nraw : 1),
                              sizeof(double));
    if (list == NULL || tr.bsmp == NULL || tr.poly == NULL) {
        st = CF_STATUS_NO_MEMORY;
        goto done;
    }
    for (size_t i = 0; i < nbase; i++)
        for (int k = 0; k <= CF__TRIM_BASE_N; k++)
            cf__bezier_eval_point(
                base[i], (double)k / CF__TRIM_BASE_N,
                tr.bsmp + 2 * ((CF__TRIM_BASE_N + 1) * i + k));
    for (size_t i = 0; i < nraw; i++)
        for (int k = 0; k <= CF__TRIM_POLY_N; k++)
            cf__cubic_pd(raw->pts + 8 * i, (double)k / CF__TRIM_POLY_N,
                         tr.poly + 2 * ((CF__TRIM_POLY_N + 1) * i + k),
                         NULL);
    if (nraw == 0 || d == 0.0) {
        /* nothing to trim: the raw chain is the trimmed one */
        if (nraw > 0) {
            st = cf__chain_init(&ch);
            if (st == CF_STATUS_OK)
                st = cf__trim_append_part(&tr, &ch, 0.0, (double)nraw, NULL,
                                          NULL);
            if (st == CF_STATUS_OK)
                st = list_add(list, &cap, cf__chain_take(&ch));
            else
                cf__chain_fini(&ch);
        }
        goto done;
    }
    st = find_intersections(&tr);
    if (st == CF_STATUS_OK)
        st = add_split(&tr, 0.0, NULL, 0.0);
    if (st == CF_STATUS_OK)
        st = add_split(&tr, (double)nraw, NULL, 0.0);
    if (st != CF_STATUS_OK)
        goto done;
    qsort(tr.splits, tr.nsplit, sizeof(cf__trim_split_t), cmp_split);
    /* classify each interval by samples; locate transitions by bisection */
    for (size_t k = 0; k + 1 < tr.nsplit; k++) {
        double g0 = tr.splits[k].g, g1 = tr.splits[k + 1].g, start = g0;
        bool cls[CLASS_N];
        cf__trim_cut_t cstart = { tr.splits[k].exact, tr.splits[k].T,
                       tr.splits[k].exact ? tr.splits[k].p : NULL };
        if (g1 - g0 < 1e-12)
            continue;
        for (int m = 0; m < CLASS_N; m++)
            cls[m] = inside(&tr, g0 + (g1 - g0) * (m + 0.5) / CLASS_N, 2.0);
        for (int m = 0; m < CLASS_N; m++) {
            double end = g1;
            cf__trim_cut_t cend = { tr.splits[k + 1].exact, tr.splits[k + 1].T,
                         tr.splits[k + 1].exact ? tr.splits[k + 1].p : NULL };
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
                /* the same transition on the exact offset, when it can
                ** be bracketed there */
                cend.has_T = exact_transition(&tr, cls[m] ? lo : hi,
                                              cls[m] ? hi : lo, &end,
                                              &cend.T) == 0 ||
                             exact_cut(&tr, out_end, cls[m] ? hi : lo, &end,
                                       &cend.T) == 0;
                if (!(end >= start && end <= g1)) {
                    /* the exact transition is outside this interval of
                    ** the raw chain: the raw one (projected) */
                    end = out_end;
                    cend.has_T = false;
                }
                cend.snap = NULL;
            }
            if (!cls[m]) {
                if (!open) {
                    st = cf__chain_init(&ch);
                    if (st != CF_STATUS_OK)
                        goto done;
                    open = true;
                }
                st =
                    cf__trim_append_part(&tr, &ch, start, end, &cstart, &cend);
                if (st != CF_STATUS_OK)
                    goto done;
            } else if (open) {
                st = list_add(list, &cap, cf__chain_take(&ch));
                open = false;
                if (st != CF_STATUS_OK)
                    goto done;
            }
            start = end;
            cstart = cend;
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
