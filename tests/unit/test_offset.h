/* The helpers the offset tests share (test_offset.c,
** test_offset_degenerate.c, test_offset_errors.c); static inline, as not
** every file uses each. */
#ifndef CURVEFIG_TESTS_TEST_OFFSET_H
#define CURVEFIG_TESTS_TEST_OFFSET_H

#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/curvefig.h"
#include "testutil.h"

/* ---- independent helpers (not the library's measuring code) ------------ */

static inline cf_bezier_t *
cubic(const double *p)
{
    cf_bezier_t *c = NULL;
    assert_int_equal(cf_bezier_create(2, 3, p, NULL, &c, NULL),
                     CF_STATUS_OK);
    return c;
}

/* Point of a planar cubic pts[8] at s, by the power form (a different
** scheme from the library's de Casteljau). */
static inline void
cubic_at(const double *P, double s, double *out)
{
    double u = 1.0 - s;
    double b0 = u * u * u, b1 = 3 * u * u * s, b2 = 3 * u * s * s,
           b3 = s * s * s;
    out[0] = b0 * P[0] + b1 * P[2] + b2 * P[4] + b3 * P[6];
    out[1] = b0 * P[1] + b1 * P[3] + b2 * P[5] + b3 * P[7];
}

typedef void (*pfn)(const void *ctx, double u, double *p);

static inline void
cubic_fn(const void *ctx, double u, double *p)
{
    cubic_at(ctx, u, p);
}

typedef struct ofs_ctx {
    const cf_bezier_t *c;
    double d, a, b;
} ofs_ctx;

/* the exact offset from the definition: c + d * rot90(c' / |c'|) */
static inline void
offset_fn(const void *vctx, double u, double *p)
{
    const ofs_ctx *x = vctx;
    double v[6], t = x->a + (x->b - x->a) * u, l;
    assert_int_equal(cf_bezier_eval_derivs(x->c, t, 2, v), CF_STATUS_OK);
    l = hypot(v[2], v[3]);
    if (l <= 1e-12 * hypot(v[4], v[5])) {
        /* c' = 0 (a cusp of the curve, to rounding) at an end of the
        ** range: the direction is that of c'' from the right, of -c''
        ** from the left (c'(t + h) = h c''(t) + O(h^2)) */
        double sg = u >= 0.5 ? -1.0 : 1.0;
        l = hypot(v[4], v[5]);
        if (l == 0.0) {
            assert_int_equal(cf_offset_point(x->c, t, x->d, p),
                             CF_STATUS_OK);
            return;
        }
        v[2] = sg * v[4];
        v[3] = sg * v[5];
    }
    p[0] = v[0] - x->d * v[3] / l;
    p[1] = v[1] + x->d * v[2] / l;
}

/* Distance from q to the curve f on [0, 1]: n samples, then golden-section
** search around the nearest one. */
static inline double
dist_to(pfn f, const void *ctx, int n, const double *q)
{
    double best = INFINITY, p[2];
    int jbest = 0;
    for (int j = 0; j <= n; j++) {
        double dd;
        f(ctx, (double)j / n, p);
        dd = hypot(p[0] - q[0], p[1] - q[1]);
        if (dd < best) {
            best = dd;
            jbest = j;
        }
    }
    {
        const double g = 0.6180339887498949;
        double lo = fmax(0.0, (double)(jbest - 1) / n);
        double hi = fmin(1.0, (double)(jbest + 1) / n);
        for (int it = 0; it < 60; it++) {
            double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), p1[2],
                   p2[2], d1, d2;
            f(ctx, x1, p1);
            f(ctx, x2, p2);
            d1 = hypot(p1[0] - q[0], p1[1] - q[1]);
            d2 = hypot(p2[0] - q[0], p2[1] - q[1]);
            best = fmin(best, fmin(d1, d2));
            if (d1 < d2)
                hi = x2;
            else
                lo = x1;
        }
    }
    return best;
}

/* Source parameters of piece k of a list (list->t0/t1, else [k, k + 1]). */
static inline double
item_T(const cf_bezier_list_t *l, size_t k, int end)
{
    const double *t = end ? l->t1 : l->t0;
    return t != NULL ? t[k] : (double)k + end;
}

/* The piece of the list whose range holds T (the first at a shared end). */
static inline size_t
item_of(const cf_bezier_list_t *l, double T)
{
    for (size_t k = 0; k + 1 < l->count; k++)
        if (T <= item_T(l, k, 1))
            return k;
    return l->count - 1;
}

/* Two-sided distance between every piece of a chain of the offset of the
** pieces of l and the exact offset on its parameter range (n samples per
** piece and side); a join arc (an empty range) by the distance of n of
** its points to the circle of radius |d| about the base point. */
static inline double
list_chain_error(const cf_bezier_list_t *l, double d, const cf_cubics_t *ch,
                 int n)
{
    double e = 0.0;
    for (size_t i = 0; i < ch->count; i++) {
        const double *P = ch->pts + 8 * i;
        double Ta = ch->t[i], Tb = ch->t[i + 1];
        size_t k = item_of(l, 0.5 * (Ta + Tb));
        double T0 = item_T(l, k, 0), w = item_T(l, k, 1) - T0;
        ofs_ctx x = { l->items[k], d, (Ta - T0) / w, (Tb - T0) / w };
        if (!(Tb > Ta)) {
            double c[2], p[2];
            assert_int_equal(cf_bezier_eval(l->items[k], fmin(1.0, x.a), c),
                             CF_STATUS_OK);
            for (int j = 0; j <= n; j++) {
                cubic_at(P, (double)j / n, p);
                e = fmax(e, fabs(hypot(p[0] - c[0], p[1] - c[1]) - fabs(d)));
            }
            continue;
        }
        x.a = fmax(0.0, x.a);
        x.b = fmin(1.0, x.b);
        for (int j = 0; j <= n; j++) {
            double p[2], u = (double)j / n;
            offset_fn(&x, u, p);
            e = fmax(e, dist_to(cubic_fn, P, 4 * n, p));
            cubic_at(P, u, p);
            e = fmax(e, dist_to(offset_fn, &x, 4 * n, p));
        }
    }
    return e;
}

/* The same for the offset of one curve c (parameters in [0, 1]). */
static inline double
chain_error(const cf_bezier_t *c, double d, const cf_cubics_t *ch, int n)
{
    cf_bezier_t *items[1] = { (cf_bezier_t *)c };
    cf_bezier_list_t l = { 1, items, NULL, NULL };
    return list_chain_error(&l, d, ch, n);
}

static inline void
assert_chain_sane(const cf_cubics_t *ch, double gap)
{
    assert_non_null(ch);
    assert_int_equal(ch->dim, 2);
    for (size_t i = 0; i < 8 * ch->count; i++)
        assert_true(isfinite(ch->pts[i]));
    for (size_t i = 1; i < ch->count; i++) {
        assert_true(hypot(ch->pts[8 * i] - ch->pts[8 * i - 2],
                          ch->pts[8 * i + 1] - ch->pts[8 * i - 1]) <= gap);
        assert_true(ch->t[i] >= ch->t[i - 1]);
    }
}

static const double arch[8] = { 0, 0, 0, 100, 100, 100, 100, 0 };

/* Skia's "overstroke" cubic: at d = +-250 the offset has one cusp. */
static const double overstroke[8] = { 0, 0, 25, 75, 75, -50, 100, 0 };

#endif
