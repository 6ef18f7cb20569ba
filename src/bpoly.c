/*
** Polynomials in Bernstein form on [0, 1]: evaluation, subdivision, degree
** elevation, products, derivatives, the power -> Bernstein conversion and
** real-root isolation by subdivision with Descartes' rule of signs (see
** bpoly-private.h).
*/
#include <float.h>
#include <math.h>
#include <string.h>

#include "curvefig/bezier.h"
#include "core-private.h"
#include "bpoly-private.h"

#define MAXN CF_BEZIER_MAX_DEGREE

double
cf__bp_eval(const double *a, int n, double t)
{
    /* de Casteljau on a stack copy; a Horner-like form only beyond the
    ** library's maximum degree */
    double buf[CF_BEZIER_MAX_DEGREE + 1];
    if (n < 0)
        return 0.0;
    if (n <= CF_BEZIER_MAX_DEGREE) {
        memcpy(buf, a, (size_t)(n + 1) * sizeof *buf);
        return cf__bp_decasteljau(buf, n, t);
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

/* The planar split on a local interleaved array (the same operations as
** below), with the degree a constant after inlining so that the loops
** unroll.  x and y stay together: the compiler pairs them in one vector
** register, and every load meets a store of the same width (separate x
** and y arrays made it pair neighbours and stall on store forwarding). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void
split2(int n, const double *src, double t, double *left, double *right)
{
    double q[32], s = 1.0 - t;
    memcpy(q, src, 2 * ((size_t)n + 1) * sizeof *q);
    for (int r = 1; r <= n; r++) {
        left[2 * (r - 1)] = q[0];
        left[2 * (r - 1) + 1] = q[1];
        for (int i = 0; i <= n - r; i++) {
            q[2 * i] = s * q[2 * i] + t * q[2 * i + 2];
            q[2 * i + 1] = s * q[2 * i + 1] + t * q[2 * i + 3];
        }
    }
    left[2 * n] = q[0];
    left[2 * n + 1] = q[1];
    memcpy(right, q, 2 * ((size_t)n + 1) * sizeof *q);
}

static void
split2_const(int n, const double *src, double t, double *left,
             double *right)
{
    switch (n) {
    case 0: split2(0, src, t, left, right); break;
    case 1: split2(1, src, t, left, right); break;
    case 2: split2(2, src, t, left, right); break;
    case 3: split2(3, src, t, left, right); break;
    case 4: split2(4, src, t, left, right); break;
    case 5: split2(5, src, t, left, right); break;
    case 6: split2(6, src, t, left, right); break;
    case 7: split2(7, src, t, left, right); break;
    default: split2(n, src, t, left, right); break;
    }
}

void
cf__bp_split(const double *src, size_t hdim, int n, double t, double *left,
             double *right)
{
    double s = 1.0 - t;
    size_t np = (size_t)n + 1;
    if (hdim == 2 && n >= 0 && n <= 15 && left != NULL && right != NULL) {
        split2_const(n, src, t, left, right);
        return;
    }
    if (right != NULL) {
        /* in place in right: after level r, right[0] = P_{r,0} and
        ** right[n-r] = P_{r,n-r} stays fixed from then on */
        if (right != src)
            memmove(right, src, np * hdim * sizeof *right);
        for (int r = 1; r <= n; r++) {
            if (left != NULL)
                memcpy(left + (size_t)(r - 1) * hdim, right,
                       hdim * sizeof *right);
            for (size_t i = 0; i + (size_t)r <= (size_t)n; i++) {
                double *a = right + i * hdim, *b = a + hdim;
                for (size_t k = 0; k < hdim; k++)
                    a[k] = s * a[k] + t * b[k];
            }
        }
        if (left != NULL)
            memcpy(left + (size_t)n * hdim, right, hdim * sizeof *right);
    } else if (left != NULL) {
        /* in place in left, from the top: after level r, left[r] = P_{r,0} */
        if (left != src)
            memmove(left, src, np * hdim * sizeof *left);
        for (int r = 1; r <= n; r++) {
            for (size_t i = (size_t)n; i >= (size_t)r; i--) {
                double *b = left + i * hdim, *a = b - hdim;
                for (size_t k = 0; k < hdim; k++)
                    b[k] = s * a[k] + t * b[k];
            }
        }
    }
}


void
cf__bp_elevate(double *pts, size_t hdim, int m, int r)
{
    for (int step = 0; step < r; step++, m++) {
        double inv = 1.0 / (double)(m + 1);
        memcpy(pts + (size_t)(m + 1) * hdim, pts + (size_t)m * hdim,
               hdim * sizeof *pts);
        for (int i = m; i >= 1; i--) {
            double a = (double)i * inv, b = (double)(m + 1 - i) * inv;
            double *q = pts + (size_t)i * hdim;
            for (size_t k = 0; k < hdim; k++)
                q[k] = a * q[(ptrdiff_t)k - (ptrdiff_t)hdim] + b * q[k];
        }
    }
}

static void
binomial_row(int n, double *row)
{
    row[0] = 1.0;
    for (int i = 1; i <= n; i++)
        row[i] = nearbyint(row[i - 1] * (double)(n - i + 1) / (double)i);
}

void
cf__bp_mul(const double *f, int nf, size_t sf, const double *g, int ng,
           size_t sg, double *h, size_t sh, double sign, bool accumulate)
{
    double bf[MAXN + 1], bg[MAXN + 1], bh[MAXN + 1];
    bool rows = nf + ng <= MAXN;
    if (rows) {
        binomial_row(nf, bf);
        binomial_row(ng, bg);
        binomial_row(nf + ng, bh);
    }
    for (int k = 0; k <= nf + ng; k++) {
        double s = 0.0;
        int i0 = k - ng > 0 ? k - ng : 0, i1 = k < nf ? k : nf;
        for (int i = i0; i <= i1; i++) {
            double c = rows ? bf[i] * bg[k - i] / bh[k]
                            : cf__binomial(nf, i) * cf__binomial(ng, k - i) /
                                  cf__binomial(nf + ng, k);
            s += c * f[(size_t)i * sf] * g[(size_t)(k - i) * sg];
        }
        if (accumulate)
            h[(size_t)k * sh] += sign * s;
        else
            h[(size_t)k * sh] = sign * s;
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
    for (int j = 0; j <= n; j++) {
        double s = 0.0, hk = 1.0;
        for (int k = 0; k <= j; k++) {
            s += cf__binomial(j, k) / cf__binomial(n, k) * (p[k] * hk);
            hk *= h;
        }
        out[j] = s;
    }
}

/* ---- points and derivatives of curves ------------------------------------ */

/* The small path: at most this many coordinates reduced together (x, y
** and a weight), up to this degree and derivative order, on small stack
** tables. */
#define GROUP_MAX 3
#define GROUP_MAX_DEGREE 24

/* The kk + 1 points b (hc doubles each) of de Casteljau level n - kk at t
** of the points p[0..n] (stride doubles apart); kk <= n. */
CF__INLINE void
reduce(const double *p, size_t stride, size_t hc, int n, double t, int kk,
       double *b)
{
    double s = 1.0 - t;
    if (n > kk) {
        for (int i = 0; i < n; i++)
            for (size_t c = 0; c < hc; c++)
                b[(size_t)i * hc + c] = s * p[(size_t)i * stride + c] +
                                        t * p[(size_t)(i + 1) * stride + c];
        for (int r = n - 1; r > kk; r--)
            for (int i = 0; i < r; i++)
                for (size_t c = 0; c < hc; c++)
                    b[(size_t)i * hc + c] = s * b[(size_t)i * hc + c] +
                                            t * b[(size_t)(i + 1) * hc + c];
    } else {
        /* n == kk */
        for (int i = 0; i <= kk; i++)
            for (size_t c = 0; c < hc; c++)
                b[(size_t)i * hc + c] = p[(size_t)i * stride + c];
    }
}

/*
** Derivatives 0..kk (kk <= n) of hc coordinates of the points p[0..n]
** (stride doubles apart) at t into res[j * rs + c]: de Casteljau down to
** level n - kk, then the j-th derivative is n!/(n-j)! times de Casteljau
** of the j-th forward differences of those kk + 1 points (differences
** commute with de Casteljau's convex combinations).  b and tmp hold
** (n + 1) * hc doubles.  Inlined with constant hc (and kk, n) so that the
** coordinates share vector registers and the loops unroll.
*/
CF__INLINE void
derivs_group(const double *p, size_t stride, size_t hc, int n, double t,
             int kk, double *b, double *tmp, double *res, size_t rs)
{
    double s = 1.0 - t, fac = 1.0;
    reduce(p, stride, hc, n, t, kk, b);
    for (int j = 0; j <= kk; j++) {
        int m = kk - j;
        for (size_t i = 0; i < (size_t)(m + 1) * hc; i++)
            tmp[i] = b[i];
        for (int r = m; r > 0; r--)
            for (int i = 0; i < r; i++)
                for (size_t c = 0; c < hc; c++)
                    tmp[(size_t)i * hc + c] =
                        s * tmp[(size_t)i * hc + c] +
                        t * tmp[(size_t)(i + 1) * hc + c];
        for (size_t c = 0; c < hc; c++)
            res[(size_t)j * rs + c] = fac * tmp[c];
        fac *= (double)(n - j);
        for (int i = 0; i < m; i++)
            for (size_t c = 0; c < hc; c++)
                b[(size_t)i * hc + c] =
                    b[(size_t)(i + 1) * hc + c] - b[(size_t)i * hc + c];
    }
}

/*
** The Cartesian derivatives x[m * xs], m = 0..k, of one coordinate
** x = A / w from those of A = w x (a[j * as]) and of w (wd[j * ws]), both
** known for j <= kk and zero above:
**   x^(m) = (A^(m) - sum_{j=1..m} C(m,j) w^(j) x^(m-j)) / w,
** with binom[0..k] for the rows of Pascal's triangle.
*/
CF__INLINE void
quotient(const double *a, size_t as, const double *wd, size_t ws, int k,
         int kk, double *x, size_t xs, double *binom)
{
    binom[0] = 1.0;
    for (int m = 0; m <= k; m++) {
        double v = m <= kk ? a[(size_t)m * as] : 0.0;
        int jmax = m < kk ? m : kk;
        if (m > 0) {
            binom[m] = 1.0;
            for (int j = m - 1; j > 0; j--)
                binom[j] += binom[j - 1];
        }
        for (int j = 1; j <= jmax; j++)
            v -= binom[j] * wd[(size_t)j * ws] * x[(size_t)(m - j) * xs];
        x[(size_t)m * xs] = v / wd[0];
    }
}

/*
** derivs_group for kk <= 2 with the last kk + 1 points q0..q2 in
** registers: the same operations in the same order (de Casteljau of the
** differences written out), without the tables of the general loop.
*/
CF__INLINE void
derivs_low(const double *p, size_t stride, size_t hc, int n, double t,
           int kk, double *b, double *res)
{
    double s = 1.0 - t, f1 = 1.0 * (double)n, f2 = f1 * (double)(n - 1);
    reduce(p, stride, hc, n, t, kk, b);
    for (size_t c = 0; c < hc; c++) {
        double q0 = b[c];
        if (kk == 0) {
            res[c] = 1.0 * q0;
        } else if (kk == 1) {
            double q1 = b[hc + c];
            res[c] = 1.0 * (s * q0 + t * q1);
            res[hc + c] = f1 * (q1 - q0);
        } else {
            double q1 = b[hc + c], q2 = b[2 * hc + c];
            double d0 = q1 - q0, d1 = q2 - q1;
            res[c] = 1.0 * (s * (s * q0 + t * q1) + t * (s * q1 + t * q2));
            res[hc + c] = f1 * (s * d0 + t * d1);
            res[2 * hc + c] = f2 * (d1 - d0);
        }
    }
}

/* derivs_group with constant hc = stride and kk in 0..2 (the orders the
** offsets and fits ask for) on registers, any kk on the tables. */
#define GROUP_CASES(HC, N)                                                  \
    do {                                                                    \
        switch (kk) {                                                       \
        case 0: derivs_low(p, HC, HC, N, t, 0, b, res); break;              \
        case 1: derivs_low(p, HC, HC, N, t, 1, b, res); break;              \
        case 2: derivs_low(p, HC, HC, N, t, 2, b, res); break;              \
        default: derivs_group(p, HC, HC, N, t, kk, b, tmp, res, HC); break; \
        }                                                                   \
    } while (0)

/* The small path: hc = nc + rational <= GROUP_MAX coordinates side by
** side (the weight right after the coordinates), n and k at most
** GROUP_MAX_DEGREE. */
CF__INLINE void
curve_derivs_small(const double *p, bool rational, size_t stride, size_t nc,
                   int n, double t, int k, double *out)
{
    double b[GROUP_MAX * (GROUP_MAX_DEGREE + 1)];
    double tmp[GROUP_MAX * (GROUP_MAX_DEGREE + 1)];
    double res[GROUP_MAX * (GROUP_MAX_DEGREE + 1)];
    double binom[GROUP_MAX_DEGREE + 2];
    size_t hc = nc + (rational ? 1 : 0);
    int kk = k < n ? k : n;
    if (hc == 2 && stride == 2 && n == 3)
        GROUP_CASES(2, 3);
    else if (hc == 2 && stride == 2)
        GROUP_CASES(2, n);
    else if (hc == 3 && stride == 3)
        GROUP_CASES(3, n);
    else
        derivs_group(p, stride, hc, n, t, kk, b, tmp, res, hc);
    if (rational) {
        for (size_t c = 0; c < nc; c++)
            quotient(res + c, hc, res + nc, hc, k, kk, out + c, nc, binom);
        return;
    }
    for (int j = 0; j <= k; j++)
        for (size_t c = 0; c < nc; c++)
            out[(size_t)j * nc + c] = j <= kk ? res[(size_t)j * hc + c] : 0.0;
}

/* Any degree and order: one coordinate at a time, on tables of the
** maximum degree. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void
curve_derivs_any(const double *p, const double *w, size_t stride, size_t nc,
                 int n, double t, int k, double *out)
{
    double b[MAXN + 1], tmp[MAXN + 1], a[MAXN + 1], wd[MAXN + 1];
    double binom[MAXN + 2];
    int kk = k < n ? k : n;
    if (w != NULL)
        derivs_group(w, stride, 1, n, t, kk, b, tmp, wd, 1);
    for (size_t c = 0; c < nc; c++) {
        if (w != NULL) {
            derivs_group(p + c, stride, 1, n, t, kk, b, tmp, a, 1);
            quotient(a, 1, wd, 1, k, kk, out + c, nc, binom);
            continue;
        }
        derivs_group(p + c, stride, 1, n, t, kk, b, tmp, out + c, nc);
        for (int j = kk + 1; j <= k; j++)
            out[(size_t)j * nc + c] = 0.0;
    }
}

/* One coordinate at a time on small tables (n and k at most
** GROUP_MAX_DEGREE): any number of coordinates, the weight anywhere. */
CF__INLINE void
curve_derivs_coords(const double *p, const double *w, size_t stride,
                    size_t nc, int n, double t, int k, double *out)
{
    double b[GROUP_MAX_DEGREE + 1], tmp[GROUP_MAX_DEGREE + 1];
    double a[GROUP_MAX_DEGREE + 1], wd[GROUP_MAX_DEGREE + 1];
    double binom[GROUP_MAX_DEGREE + 2];
    int kk = k < n ? k : n;
    if (w != NULL)
        derivs_group(w, stride, 1, n, t, kk, b, tmp, wd, 1);
    for (size_t c = 0; c < nc; c++) {
        if (kk <= 2 && n == 3)
            derivs_low(p + c, stride, 1, 3, t, kk, b, a);
        else if (kk <= 2)
            derivs_low(p + c, stride, 1, n, t, kk, b, a);
        else
            derivs_group(p + c, stride, 1, n, t, kk, b, tmp, a, 1);
        if (w != NULL) {
            quotient(a, 1, wd, 1, k, kk, out + c, nc, binom);
            continue;
        }
        for (int j = 0; j <= k; j++)
            out[(size_t)j * nc + c] = j <= kk ? a[j] : 0.0;
    }
}

void
cf__bp_curve_derivs(const double *p, const double *w, size_t stride,
                    size_t nc, int n, double t, int k, double *out)
{
    if (n > GROUP_MAX_DEGREE || k > GROUP_MAX_DEGREE)
        curve_derivs_any(p, w, stride, nc, n, t, k, out);
    else if (nc + (w != NULL) <= GROUP_MAX && (w == NULL || w == p + nc))
        curve_derivs_small(p, w != NULL, stride, nc, n, t, k, out);
    else
        curve_derivs_coords(p, w, stride, nc, n, t, k, out);
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
    cf__bp_split(a, 1, n, s, l, r);
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
    ctx.zero = 64.0 * (double)n * DBL_EPSILON * amax;
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
