/*
** Cusps of offset curves and zeros of c'.
**
** o(t) = c(t) + d n(t) has o'(t) = c'(t) (1 - d kappa(t)), kappa = c' x c'' /
** |c'|^3, so o has a cusp where d (c' x c'') = |c'|^3.  Squaring gives a
** polynomial condition P(t) = |c'|^6 - d^2 (c' x c'')^2 = 0, kept in
** Bernstein form and built from the control points by products of Bernstein
** polynomials:
**
**   polynomial curve of degree n: D = c' (the hodograph, degree n - 1),
**     c' x c'' = D x D' (degree 2n - 3), P = |D|^6 - d^2 (D x D')^2,
**     degree 6n - 6 (12 for a cubic);
**   rational curve with homogeneous H = (X, Y, W): c = P/W with P = (X, Y),
**     c' = D / W^2 with D = P'W - PW' (as a product of degree 2n - 1), and
**     c'' = (D'W - 2DW') / W^3, so c' x c'' = (D x D') W / W^5
**     = D x D' / W^4.  Then |c'|^6 = d^2 (c' x c'')^2 becomes
**     P = |D|^6 - d^2 (D x D')^2 W^4, degree 12n - 6.
**
** The square admits the roots of d (c' x c'') = -|c'|^3 (the cusps of the
** offset on the other side) and the zeros of c' (where both terms vanish):
** each root is polished by Newton's method on f(t) = d (c' x c'') - |c'|^3
** evaluated on the curve and kept only if d (c' x c'') > 0 and c' != 0.
** Roots are isolated in Bernstein form (bpoly.c) so that two close
** cusps, where P touches or barely crosses zero twice, are not missed.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core-private.h"
#include "bezier-private.h"
#include "fit-private.h"
#include "numtext-private.h"

double
cf__deriv_scale(const cf_bezier_t *c)
{
    int n = cf_bezier_degree(c);
    double s = 0.0, p0[2], p[2];
    cf__bezier_eval_point(c, 0.0, p0);
    for (int i = 0; i <= n; i++) {
        const double *h = cf_bezier_hpoints(c) + (size_t)i * c->hdim;
        if (c->rational) {
            p[0] = h[0] / h[2];
            p[1] = h[1] / h[2];
        } else {
            p[0] = h[0];
            p[1] = h[1];
        }
        s = fmax(s, hypot(p[0] - p0[0], p[1] - p0[1]));
    }
    return (double)(n > 0 ? n : 1) * s;
}

/* Normalised homogeneous coordinates: X, Y, W arrays (degree n) of the
** curve translated by -c(0) and scaled by 1/s. */
static void
normalised_coords(const cf_bezier_t *c, double s, double *X, double *Y,
                  double *W)
{
    int n = c->degree;
    double p0[2];
    cf__bezier_eval_point(c, 0.0, p0);
    for (int i = 0; i <= n; i++) {
        const double *h = c->pts + (size_t)i * c->hdim;
        double w = c->rational ? h[2] : 1.0;
        X[i] = (h[0] - w * p0[0]) / s;
        Y[i] = (h[1] - w * p0[1]) / s;
        W[i] = w;
    }
}

/*
** The vector D (c' = D / W^2) and its derivative, Bernstein form:
** Dx, Dy of degree *m, DDx, DDy of degree *m - 1.  Work arrays sized
** 2n + 1 each.
*/
static void
build_d(const cf_bezier_t *c, const double *X, const double *Y,
        const double *W, double *Dx, double *Dy, double *DDx, double *DDy,
        double *tmp1, double *tmp2, int *m)
{
    int n = c->degree;
    if (!c->rational) {
        cf__bp_deriv(X, n, Dx);
        cf__bp_deriv(Y, n, Dy);
        *m = n - 1;
    } else {
        /* D = P'W - PW', each product of degree 2n - 1 */
        double *dp = tmp1, *dw = tmp2 + (2 * n + 2);
        const double *coord[2] = { X, Y };
        double *dst[2] = { Dx, Dy };
        cf__bp_deriv(W, n, dw);
        for (int k = 0; k < 2; k++) {
            cf__bp_deriv(coord[k], n, dp);
            cf__bp_mul(dp, n - 1, 1, W, n, 1, dst[k], 1, 1.0, false);
            cf__bp_mul(coord[k], n, 1, dw, n - 1, 1, tmp2, 1, 1.0, false);
            for (int i = 0; i <= 2 * n - 1; i++)
                dst[k][i] -= tmp2[i];
        }
        *m = 2 * n - 1;
    }
    cf__bp_deriv(Dx, *m, DDx);
    cf__bp_deriv(Dy, *m, DDy);
}

/* Work space of the cusp computations: the normalised coordinates, D and
** D' (see build_d) and `extra` more arrays of deg_max doubles. */
typedef struct dwork {
    double *buf, *X, *Y, *W, *Dx, *Dy, *DDx, *DDy, *t1, *t2, *extra;
    size_t deg_max;
    int m;
    double s;
} dwork;

/* 0: ready; 1: nothing to do (constant curve); -1: out of memory. */
static int
dwork_begin(const cf_bezier_t *c, size_t deg_max, size_t extra, dwork *w)
{
    int n = c->degree;
    w->s = cf__deriv_scale(c) / (double)n;
    if (!(w->s > 0.0))
        return 1;
    w->deg_max = deg_max;
    w->buf = cf__alloc_array((11 + extra) * deg_max, sizeof(double));
    if (w->buf == NULL)
        return -1;
    w->X = w->buf;
    w->Y = w->X + deg_max;
    w->W = w->Y + deg_max;
    w->Dx = w->W + deg_max;
    w->Dy = w->Dx + deg_max;
    w->DDx = w->Dy + deg_max;
    w->DDy = w->DDx + deg_max;
    w->t1 = w->DDy + deg_max;
    w->t2 = w->t1 + deg_max;    /* 2 * deg_max */
    w->extra = w->t2 + 2 * deg_max;
    normalised_coords(c, w->s, w->X, w->Y, w->W);
    build_d(c, w->X, w->Y, w->W, w->Dx, w->Dy, w->DDx, w->DDy, w->t1, w->t2,
            &w->m);
    return 0;
}

/* Copy the kept roots into a new array and free the work buffer. */
static cf_status_t
hand_over(double *buf, const double *roots, size_t kept, double **ts,
          size_t *nout)
{
    if (kept > 0) {
        *ts = cf__alloc_array(kept, sizeof(double));
        if (*ts == NULL) {
            cf__free(buf);
            return CF_STATUS_NO_MEMORY;
        }
        memcpy(*ts, roots, kept * sizeof(double));
        *nout = kept;
    }
    cf__free(buf);
    return CF_STATUS_OK;
}

/* f(t) = d (c' x c'') - |c'|^3 and f'(t), from the curve. */
static void
cusp_f(const cf_bezier_t *c, double d, double t, double *f, double *df,
       double *cross, double *speed)
{
    double v[8];
    double cr, sp;
    cf_bezier_eval_derivs(c, t, 3, v);
    cr = v[2] * v[5] - v[3] * v[4];
    sp = hypot(v[2], v[3]);
    *f = d * cr - sp * sp * sp;
    *df = d * (v[2] * v[7] - v[3] * v[6]) -
          3.0 * sp * (v[2] * v[4] + v[3] * v[5]);
    *cross = cr;
    *speed = sp;
}

cf_status_t
cf__offset_cusps_alloc(const cf_bezier_t *c, double d, double **ts,
                       size_t *nout)
{
    int n = c->degree, m, pd, r;
    double dn;
    double *buf, *Dx, *Dy, *DDx, *DDy, *t1, *W, *g, *g2, *g3, *cr, *cr2, *w2,
        *w4, *poly, *roots;
    size_t deg_max, nroots = 0, kept = 0;
    dwork wk;
    cf_status_t st;

    *ts = NULL;
    *nout = 0;
    if (n < 2 || d == 0.0)
        return CF_STATUS_OK;
    deg_max = (size_t)(12 * n + 8);
    r = dwork_begin(c, deg_max, 10, &wk);
    if (r != 0)
        return r > 0 ? CF_STATUS_OK : CF_STATUS_NO_MEMORY;
    buf = wk.buf;
    Dx = wk.Dx;
    Dy = wk.Dy;
    DDx = wk.DDx;
    DDy = wk.DDy;
    W = wk.W;
    t1 = wk.t1;
    m = wk.m;
    dn = d / wk.s;
    g = wk.extra;
    g2 = g + deg_max;
    g3 = g2 + deg_max;
    cr = g3 + deg_max;
    cr2 = cr + deg_max;
    w2 = cr2 + deg_max;
    w4 = w2 + deg_max;
    poly = w4 + deg_max;
    roots = poly + deg_max;     /* 2 * deg_max */

    /* |D|^2, degree 2m; |D|^6, degree 6m */
    cf__bp_mul(Dx, m, 1, Dx, m, 1, g, 1, 1.0, false);
    cf__bp_mul(Dy, m, 1, Dy, m, 1, t1, 1, 1.0, false);
    for (int i = 0; i <= 2 * m; i++)
        g[i] += t1[i];
    cf__bp_mul(g, 2 * m, 1, g, 2 * m, 1, g2, 1, 1.0, false);
    cf__bp_mul(g2, 4 * m, 1, g, 2 * m, 1, g3, 1, 1.0, false);
    pd = 6 * m;
    /* D x D', degree 2m - 1; squared 4m - 2 */
    cf__bp_mul(Dx, m, 1, DDy, m - 1, 1, cr, 1, 1.0, false);
    cf__bp_mul(Dy, m, 1, DDx, m - 1, 1, t1, 1, 1.0, false);
    for (int i = 0; i <= 2 * m - 1; i++)
        cr[i] -= t1[i];
    cf__bp_mul(cr, 2 * m - 1, 1, cr, 2 * m - 1, 1, cr2, 1, 1.0, false);
    if (c->rational) {
        /* times W^4: degree 4m - 2 + 4n = 12n - 6 = 6m */
        cf__bp_mul(W, n, 1, W, n, 1, w2, 1, 1.0, false);
        cf__bp_mul(w2, 2 * n, 1, w2, 2 * n, 1, w4, 1, 1.0, false);
        cf__bp_mul(cr2, 4 * m - 2, 1, w4, 4 * n, 1, t1, 1, 1.0, false);
    } else {
        /* raise 4m - 2 to 6m */
        memcpy(t1, cr2, (size_t)(4 * m - 1) * sizeof *t1);
        cf__bp_elevate(t1, 1, 4 * m - 2, 2 * m + 2);
    }
    for (int i = 0; i <= pd; i++)
        poly[i] = g3[i] - dn * dn * t1[i];

    st = cf__bp_roots(poly, pd, roots, 2 * deg_max, &nroots);
    if (st != CF_STATUS_OK) {
        cf__free(buf);
        return st;
    }
    {
        double sc = cf__deriv_scale(c);
        for (size_t k = 0; k < nroots; k++) {
            double t = roots[k], f, df, crs, sp;
            if (t <= 0.0 || t >= 1.0)
                continue;
            /* Newton polish on the curve, only while it improves */
            cusp_f(c, d, t, &f, &df, &crs, &sp);
            for (int it = 0; it < 16 && df != 0.0; it++) {
                double tn = t - f / df, fn, dfn, crn, spn;
                if (!(tn > 0.0 && tn < 1.0))
                    break;
                cusp_f(c, d, tn, &fn, &dfn, &crn, &spn);
                if (!(fabs(fn) < fabs(f)))
                    break;
                t = tn;
                f = fn;
                df = dfn;
                crs = crn;
                sp = spn;
            }
            /* a true cusp: d (c' x c'') = |c'|^3 > 0 to rounding (the
            ** coefficient-level zero test of the isolation can admit
            ** points where the polynomial is merely small) */
            if (!(d * crs > 0.0) || sp <= 1e-9 * sc ||
                !(fabs(f) <= 1e-6 * sp * sp * sp))
                continue;
            {
                bool dup = false;
                for (size_t j = 0; j < kept; j++)
                    dup = dup || fabs(roots[j] - t) < 1e-12;
                if (dup)
                    continue;
            }
            roots[kept++] = t;
        }
    }
    qsort(roots, kept, sizeof(double), cf__cmp_double);
    return hand_over(buf, roots, kept, ts, nout);
}

cf_status_t
cf__base_cusps_alloc(const cf_bezier_t *c, double **ts, size_t *nout)
{
    /* Local minima of |D|^2 that are (numerically) zeros of c': roots of
    ** D . D' (degree 2m - 1) where |c'| <= 1e-9 of the curve's size. */
    int n = c->degree, m, r;
    double *buf, *Dx, *Dy, *DDx, *DDy, *t1, *dot, *roots;
    size_t deg_max, nroots = 0, kept = 0;
    dwork wk;
    cf_status_t st;

    *ts = NULL;
    *nout = 0;
    if (n < 2)
        return CF_STATUS_OK;
    deg_max = (size_t)(4 * n + 8);
    r = dwork_begin(c, deg_max, 3, &wk);
    if (r != 0)
        return r > 0 ? CF_STATUS_OK : CF_STATUS_NO_MEMORY;
    buf = wk.buf;
    Dx = wk.Dx;
    Dy = wk.Dy;
    DDx = wk.DDx;
    DDy = wk.DDy;
    t1 = wk.t1;
    m = wk.m;
    dot = wk.extra;
    roots = dot + deg_max;      /* 2 * deg_max */
    if (m < 1) {
        cf__free(buf);
        return CF_STATUS_OK;
    }
    cf__bp_mul(Dx, m, 1, DDx, m - 1, 1, dot, 1, 1.0, false);
    cf__bp_mul(Dy, m, 1, DDy, m - 1, 1, t1, 1, 1.0, false);
    for (int i = 0; i <= 2 * m - 1; i++)
        dot[i] += t1[i];
    st = cf__bp_roots(dot, 2 * m - 1, roots, 2 * deg_max, &nroots);
    if (st != CF_STATUS_OK) {
        cf__free(buf);
        return st;
    }
    {
        double sc = cf__deriv_scale(c);
        for (size_t k = 0; k < nroots; k++) {
            double t = roots[k], v[4];
            if (t <= 1e-12 || t >= 1.0 - 1e-12)
                continue;
            cf_bezier_eval_derivs(c, t, 1, v);
            if (hypot(v[2], v[3]) > 1e-9 * sc)
                continue;
            roots[kept++] = t;
        }
    }
    return hand_over(buf, roots, kept, ts, nout);
}

cf_status_t
cf_offset_cusps(const cf_bezier_t *c, double d, double *ts, size_t cap,
                size_t *count, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    double *all = NULL;
    size_t n = 0;
    cf_status_t st;
    if (count != NULL)
        *count = 0;
    if (c == NULL || count == NULL || (ts == NULL && cap > 0))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "curve, count or ts is NULL");
    if (cf_bezier_dim(c) != 2)
        return cf__error(diag, CF_STATUS_DIM_MISMATCH, -1,
                         "offsets are planar; the curve has dim %zu",
                         cf_bezier_dim(c));
    if (!isfinite(d))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "offset distance %s is not finite", CF__NUM(d));
    st = cf__offset_cusps_alloc(c, d, &all, &n);
    if (st != CF_STATUS_OK)
        return cf__error(diag, st, -1, "out of memory");
    for (size_t i = 0; i < n && i < cap; i++)
        ts[i] = all[i];
    *count = n;
    cf__free(all);
    return CF_STATUS_OK;
}
