/*
** 1-D polynomials in Bernstein form on [0, 1] (coefficient arrays), the
** arithmetic the cusp polynomial and the fit need, and real-root isolation
** by subdivision with Descartes' rule of signs.
*/
#include <math.h>
#include <string.h>

#include "core-private.h"
#include "bezier-private.h"
#include "offset-private.h"

double
cf__bp_eval(const double *a, int n, double t)
{
    /* de Casteljau (the Bézier module's) on a stack copy; a Horner-like
    ** form only beyond the library's maximum degree */
    double buf[CF_BEZIER_MAX_DEGREE + 1];
    if (n < 0)
        return 0.0;
    if (n <= CF_BEZIER_MAX_DEGREE) {
        memcpy(buf, a, (size_t)(n + 1) * sizeof *buf);
        return cf__decasteljau_1(buf, n, t);
    }
    {
        /* Bernstein-Horner: sum a_i C(n,i) t^i (1-t)^(n-i). */
        double s = 1.0 - t, acc = a[0], tn = 1.0, bc = 1.0;
        if (t > 0.5) {
            /* evaluate reversed for stability */
            double acc2 = a[n], bc2 = 1.0, sn = 1.0;
            for (int i = 1; i <= n; i++) {
                sn *= s;
                bc2 = bc2 * (double)(n - i + 1) / (double)i;
                acc2 = acc2 * t + bc2 * sn * a[n - i];
            }
            return acc2;
        }
        for (int i = 1; i <= n; i++) {
            tn *= t;
            bc = bc * (double)(n - i + 1) / (double)i;
            acc = acc * s + bc * tn * a[i];
        }
        return acc;
    }
}

void
cf__bp_mul(const double *a, int m, const double *b, int n, double *out)
{
    /* c_k = sum_{i+j=k} C(m,i) C(n,j) / C(m+n,k) a_i b_j (not the Bézier
    ** module's cf__bernstein_product: that one is limited to degree
    ** CF_BEZIER_MAX_DEGREE, which cusp polynomials of high-degree curves
    ** exceed) */
    for (int k = 0; k <= m + n; k++)
        out[k] = 0.0;
    for (int i = 0; i <= m; i++) {
        double ci = cf__binomial(m, i) * a[i];
        if (ci == 0.0)
            continue;
        for (int j = 0; j <= n; j++)
            out[i + j] += ci * cf__binomial(n, j) * b[j];
    }
    for (int k = 0; k <= m + n; k++)
        out[k] /= cf__binomial(m + n, k);
}

void
cf__bp_elevate(const double *a, int m, int r, double *out)
{
    if (r == 0) {
        memcpy(out, a, (size_t)(m + 1) * sizeof *out);
        return;
    }
    /* multiply by 1 = sum_j B_j^r */
    {
        int n = m + r;
        for (int k = 0; k <= n; k++)
            out[k] = 0.0;
        for (int i = 0; i <= m; i++)
            for (int j = 0; j <= r; j++)
                out[i + j] += cf__binomial(m, i) * cf__binomial(r, j) * a[i];
        for (int k = 0; k <= n; k++)
            out[k] /= cf__binomial(n, k);
    }
}

void
cf__bp_deriv(const double *a, int m, double *out)
{
    for (int i = 0; i < m; i++)
        out[i] = (double)m * (a[i + 1] - a[i]);
}

void
cf__bp_from_power(const double *p, int n, double h, double *out)
{
    /* x = h s: q_k = p_k h^k; b_j = sum_{k <= j} C(j,k) / C(n,k) q_k */
    double hk = 1.0;
    double q[64];
    for (int k = 0; k <= n && k < 64; k++) {
        q[k] = p[k] * hk;
        hk *= h;
    }
    for (int j = 0; j <= n; j++) {
        double s = 0.0;
        for (int k = 0; k <= j; k++)
            s += cf__binomial(j, k) / cf__binomial(n, k) * q[k];
        out[j] = s;
    }
}

/* ---- root isolation ------------------------------------------------------ */

#define ROOT_MAX_DEPTH 56

typedef struct root_ctx {
    int n;
    double *work;           /* 2 * (ROOT_MAX_DEPTH + 2) * (n + 1) */
    double *roots;
    size_t cap, count;
    double zero;            /* absolute size below which a value is 0 */
} root_ctx;

static int
sign_variations(const double *a, int n, double zero)
{
    int v = 0, prev = 0;
    for (int i = 0; i <= n; i++) {
        int s = a[i] > zero ? 1 : (a[i] < -zero ? -1 : 0);
        if (s == 0)
            continue;
        if (prev != 0 && s != prev)
            v++;
        prev = s;
    }
    return v;
}

static void
push_root(root_ctx *ctx, double t)
{
    if (ctx->count > 0 && fabs(ctx->roots[ctx->count - 1] - t) < 1e-12)
        return;
    if (ctx->count < ctx->cap)
        ctx->roots[ctx->count++] = t;
}

/* de Casteljau halves of a at s: left into l, right into r. */
static void
split_at(const double *a, int n, double s, double *l, double *r)
{
    memcpy(r, a, (size_t)(n + 1) * sizeof *r);
    l[0] = r[0];
    for (int k = 1; k <= n; k++) {
        for (int i = 0; i <= n - k; i++)
            r[i] = (1.0 - s) * r[i] + s * r[i + 1];
        l[k] = r[0];
    }
}

/* One sign change of a on [lo, hi] with a[0], a[n] of opposite signs:
** bisection in the local variable to full precision. */
static double
polish(const double *a, int n, double lo, double hi)
{
    double u0 = 0.0, u1 = 1.0, f0 = a[0];
    for (int it = 0; it < 80 && u1 - u0 > 1e-17; it++) {
        double um = 0.5 * (u0 + u1), fm = cf__bp_eval(a, n, um);
        if (fm == 0.0)
            return lo + (hi - lo) * um;
        if ((fm < 0) == (f0 < 0)) {
            u0 = um;
            f0 = fm;
        } else {
            u1 = um;
        }
    }
    return lo + (hi - lo) * 0.5 * (u0 + u1);
}

static void
isolate(root_ctx *ctx, const double *a, double lo, double hi, int depth)
{
    int n = ctx->n;
    int v = sign_variations(a, n, ctx->zero);
    double *l, *r;
    double s = 0.5;

    if (v == 0)
        return;
    if (v == 1 && fabs(a[0]) > ctx->zero && fabs(a[n]) > ctx->zero) {
        push_root(ctx, polish(a, n, lo, hi));
        return;
    }
    if (depth >= ROOT_MAX_DEPTH || hi - lo < 1e-13) {
        /* a cluster (multiple root): one root where |p| is smallest */
        double best = 0.5, bv = fabs(cf__bp_eval(a, n, 0.5));
        for (int k = 0; k <= 4; k++) {
            double u = 0.25 * k, fv = fabs(cf__bp_eval(a, n, u));
            if (fv < bv) {
                bv = fv;
                best = u;
            }
        }
        if (bv <= 1e3 * ctx->zero)
            push_root(ctx, lo + (hi - lo) * best);
        return;
    }
    /* avoid splitting exactly on a root: pick the split with the largest
    ** |p| among a few near the middle */
    {
        static const double cand[3] = { 0.5, 0.4609375, 0.5390625 };
        double bv = -1.0;
        for (int k = 0; k < 3; k++) {
            double fv = fabs(cf__bp_eval(a, n, cand[k]));
            if (fv > bv) {
                bv = fv;
                s = cand[k];
            }
        }
    }
    l = ctx->work + (size_t)(2 * depth) * (size_t)(n + 1);
    r = l + (n + 1);
    split_at(a, n, s, l, r);
    {
        double mid = lo + (hi - lo) * s;
        /* an exact zero at the split point is a root */
        bool zero_mid = fabs(r[0]) <= ctx->zero;
        isolate(ctx, l, lo, mid, depth + 1);
        if (zero_mid)
            push_root(ctx, mid);
        isolate(ctx, r, mid, hi, depth + 1);
    }
}

cf_status_t
cf__bp_roots(const double *a, int n, double *roots, size_t cap,
             size_t *count)
{
    root_ctx ctx;
    double amax = 0.0;
    *count = 0;
    if (n < 1)
        return CF_STATUS_OK;
    for (int i = 0; i <= n; i++)
        amax = fmax(amax, fabs(a[i]));
    if (amax == 0.0)
        return CF_STATUS_OK;
    ctx.n = n;
    ctx.roots = roots;
    ctx.cap = cap;
    ctx.count = 0;
    /* values below ~ n * eps * max|a| are rounding noise */
    ctx.zero = 64.0 * (double)n * 2.220446049250313e-16 * amax;
    ctx.work = cf__alloc_array((size_t)(2 * (ROOT_MAX_DEPTH + 2)) *
                               (size_t)(n + 1), sizeof(double));
    if (ctx.work == NULL)
        return CF_STATUS_NO_MEMORY;
    if (fabs(a[0]) <= ctx.zero)
        push_root(&ctx, 0.0);
    isolate(&ctx, a, 0.0, 1.0, 0);
    if (fabs(a[n]) <= ctx.zero)
        push_root(&ctx, 1.0);
    cf__free(ctx.work);
    *count = ctx.count;
    return CF_STATUS_OK;
}
