/*
** Batch evaluation of Bézier curves: the fast path behind
** cf_bezier_eval_many and cf_bezier_eval_deriv_many.
**
** For a polynomial curve of degree n <= FAST_MAX each coordinate is
** evaluated by Horner's rule in the Bernstein form, mirrored so that the
** ratio stays in [0, 1]:
**
**   t <= 1/2:  c(t) = (1-t)^n  sum_i C(n,i) P_i s^i,      s = t / (1-t)
**   t >  1/2:  c(t) = t^n      sum_i C(n,i) P_i s^(n-i),  s = (1-t) / t
**
** Every term C(n,i) s^i (1-t)^n is a Bernstein value B_i^n(t) <= 1 computed
** with O(n) relative rounding errors, so the result differs from de
** Casteljau by O(n) ulps of max |P_i| (tests/unit/test_bezier.c measures
** it).  The loops have a constant degree after inlining and no branches, so
** the compiler vectorises them over the parameters.  Rational curves and
** higher degrees use de Casteljau per point.
*/
#include <math.h>
#include <string.h>

#include "bezier-private.h"

/* The selects below (t <= 1/2 ? ... : ...) are only turned into branch-free
** vector code when GCC may assume that comparisons do not trap; curvefig
** never inspects floating-point exception flags, and results are unchanged. */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("no-trapping-math")
#endif

#define FAST_MAX 10
#define BLK 256

#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__) && \
    !defined(__SANITIZE_ADDRESS__)
#define CF__CLONES __attribute__((target_clones("avx2", "default")))
#else
#define CF__CLONES
#endif

#if defined(__GNUC__)
#define CF__INLINE static inline __attribute__((always_inline))
#else
#define CF__INLINE static inline
#endif

/* Binomial coefficients C(n, i) times the coefficients of one coordinate,
** in both orders: fwd[k] = a[n-k] (for t <= 1/2), rev[k] = a[k]. */
static void
scaled_coeffs(const double *p, size_t stride, int n, double *fwd,
              double *rev)
{
    double b = 1.0;
    for (int i = 0; i <= n; i++) {
        double a = b * p[(size_t)i * stride];
        rev[i] = a;
        fwd[n - i] = a;
        b = b * (double)(n - i) / (double)(i + 1);
    }
}

/*
** The Horner steps are written out (no inner loop) so that, with n a
** constant after inlining, the loop over the parameters is straight-line
** code that the compiler vectorises.  The coefficients are loaded before
** the loop and selected per parameter by t <= 1/2.
*/
#define LOADC(a, k) double a##k = n >= k ? a[k] : 0.0
#define LOAD11(a) LOADC(a, 0); LOADC(a, 1); LOADC(a, 2); LOADC(a, 3); \
    LOADC(a, 4); LOADC(a, 5); LOADC(a, 6); LOADC(a, 7); LOADC(a, 8); \
    LOADC(a, 9); LOADC(a, 10)
#define STEP(acc, f, r, k) \
    if (n >= k) acc = acc * s + (lo ? f##k : r##k)
#define HORNER(acc, f, r) do { \
        acc = lo ? f##0 : r##0; \
        STEP(acc, f, r, 1); STEP(acc, f, r, 2); STEP(acc, f, r, 3); \
        STEP(acc, f, r, 4); STEP(acc, f, r, 5); STEP(acc, f, r, 6); \
        STEP(acc, f, r, 7); STEP(acc, f, r, 8); STEP(acc, f, r, 9); \
        STEP(acc, f, r, 10); \
    } while (0)
/* v^n by repeated multiplication (n - 1 products; 1 for n = 0) */
#define POWK(sc, v, k) if (n >= k) { sc *= v; }
#define POWN(sc, v) do { \
        sc = n == 0 ? 1.0 : v; \
        POWK(sc, v, 2) POWK(sc, v, 3) POWK(sc, v, 4) POWK(sc, v, 5) \
        POWK(sc, v, 6) POWK(sc, v, 7) POWK(sc, v, 8) POWK(sc, v, 9) \
        POWK(sc, v, 10) \
    } while (0)

/* 2D: both coordinates in one loop (interleaved store). */
CF__INLINE void
horner2(int n, const double *fx, const double *rx, const double *fy,
        const double *ry, const double *restrict t, size_t m,
        double *restrict out)
{
    LOAD11(fx);
    LOAD11(rx);
    LOAD11(fy);
    LOAD11(ry);
    for (size_t j = 0; j < m; j++) {
        double tj = t[j], om = 1.0 - tj, ax, ay, sc;
        int lo = tj <= 0.5;
        double u = lo ? tj : om;
        double v = lo ? om : tj;
        double s = u / v;
        HORNER(ax, fx, rx);
        HORNER(ay, fy, ry);
        POWN(sc, v);
        out[2 * j] = ax * sc;
        out[2 * j + 1] = ay * sc;
    }
}

/* Any dimension: per block, the ratios and scales first, then one
** coordinate at a time (strided store). */
CF__INLINE void
hornerd(int n, const double *fwd, const double *rev, size_t dim,
        const double *restrict t, size_t m, double *restrict out)
{
    double sv[BLK], scv[BLK];
    for (size_t j0 = 0; j0 < m; j0 += BLK) {
        size_t mb = m - j0 < BLK ? m - j0 : BLK;
        for (size_t j = 0; j < mb; j++) {
            double tj = t[j0 + j], om = 1.0 - tj, sc;
            int lo = tj <= 0.5;
            double u = lo ? tj : om;
            double v = lo ? om : tj;
            POWN(sc, v);
            sv[j] = u / v;
            scv[j] = sc;
        }
        for (size_t d = 0; d < dim; d++) {
            const double *f = fwd + d * (FAST_MAX + 1);
            const double *r = rev + d * (FAST_MAX + 1);
            LOAD11(f);
            LOAD11(r);
            for (size_t j = 0; j < mb; j++) {
                int lo = t[j0 + j] <= 0.5;
                double s = sv[j], a;
                HORNER(a, f, r);
                out[(j0 + j) * dim + d] = a * scv[j];
            }
        }
    }
}

#define CASES(X) X(0) X(1) X(2) X(3) X(4) X(5) X(6) X(7) X(8) X(9) X(10)

CF__CLONES static void
run_horner2(int n, const double *fx, const double *rx, const double *fy,
            const double *ry, const double *t, size_t m, double *out)
{
    switch (n) {
#define X(N) case N: horner2(N, fx, rx, fy, ry, t, m, out); break;
    CASES(X)
#undef X
    default:
        break;
    }
}

/* At most 16 coordinates per call of the generic path (stack tables). */
#define DIM_CHUNK 16

CF__CLONES static void
run_hornerd(int n, const double *fwd, const double *rev, size_t dim,
            const double *t, size_t m, double *out)
{
    switch (n) {
#define X(N) case N: hornerd(N, fwd, rev, dim, t, m, out); break;
    CASES(X)
#undef X
    default:
        break;
    }
}

/*
** Evaluate the polynomial with Bernstein coefficients coef (degree n, point
** stride `stride`, dim coordinates) at t[0..m-1] into out (dim per point).
*/
static void
fast_poly(const double *coef, size_t stride, int n, size_t dim,
          const double *t, size_t m, double *out)
{
    if (dim == 2) {
        double fx[FAST_MAX + 1], rx[FAST_MAX + 1];
        double fy[FAST_MAX + 1], ry[FAST_MAX + 1];
        scaled_coeffs(coef, stride, n, fx, rx);
        scaled_coeffs(coef + 1, stride, n, fy, ry);
        run_horner2(n, fx, rx, fy, ry, t, m, out);
        return;
    }
    for (size_t d0 = 0; d0 < dim; d0 += DIM_CHUNK) {
        double fwd[DIM_CHUNK * (FAST_MAX + 1)];
        double rev[DIM_CHUNK * (FAST_MAX + 1)];
        double buf[BLK * DIM_CHUNK];
        size_t dc = dim - d0 < DIM_CHUNK ? dim - d0 : DIM_CHUNK;
        for (size_t d = 0; d < dc; d++)
            scaled_coeffs(coef + d0 + d, stride, n,
                          fwd + d * (FAST_MAX + 1), rev + d * (FAST_MAX + 1));
        if (dc == dim) {
            run_hornerd(n, fwd, rev, dim, t, m, out);
            continue;
        }
        for (size_t j0 = 0; j0 < m; j0 += BLK) {
            size_t mb = m - j0 < BLK ? m - j0 : BLK;
            run_hornerd(n, fwd, rev, dc, t + j0, mb, buf);
            for (size_t j = 0; j < mb; j++)
                memcpy(out + (j0 + j) * dim + d0, buf + j * dc,
                       dc * sizeof *buf);
        }
    }
}

cf_status_t
cf__bezier_eval_many_fast(const cf_bezier_t *c, const double *t, size_t n,
                          double *out)
{
    if (!c->rational && c->degree <= FAST_MAX) {
        fast_poly(c->pts, c->hdim, c->degree, c->dim, t, n, out);
        return CF_STATUS_OK;
    }
    for (size_t i = 0; i < n; i++)
        cf__bezier_eval_point(c, t[i], out + i * c->dim);
    return CF_STATUS_OK;
}

bool
cf__bezier_deriv_many_fast(const cf_bezier_t *c, int k, const double *t,
                           size_t n, double *out)
{
    double q[(FAST_MAX + 1) * DIM_CHUNK];
    int deg = c->degree;
    size_t dim = c->dim;

    if (c->rational || deg > FAST_MAX || k < 1)
        return false;
    if (k > deg) {
        memset(out, 0, n * dim * sizeof *out);
        return true;
    }
    for (size_t d0 = 0; d0 < dim; d0 += DIM_CHUNK) {
        size_t dc = dim - d0 < DIM_CHUNK ? dim - d0 : DIM_CHUNK;
        /* hodograph k times: Q_i = (n - j) (P_{i+1} - P_i) */
        for (int i = 0; i <= deg; i++)
            for (size_t d = 0; d < dc; d++)
                q[(size_t)i * dc + d] = c->pts[(size_t)i * dim + d0 + d];
        for (int j = 0; j < k; j++)
            for (int i = 0; i < deg - j; i++)
                for (size_t d = 0; d < dc; d++)
                    q[(size_t)i * dc + d] =
                        (double)(deg - j) * (q[(size_t)(i + 1) * dc + d] -
                                             q[(size_t)i * dc + d]);
        if (dc == dim) {
            fast_poly(q, dc, deg - k, dc, t, n, out);
        } else {
            double buf[BLK * DIM_CHUNK];
            for (size_t j0 = 0; j0 < n; j0 += BLK) {
                size_t mb = n - j0 < BLK ? n - j0 : BLK;
                fast_poly(q, dc, deg - k, dc, t + j0, mb, buf);
                for (size_t j = 0; j < mb; j++)
                    memcpy(out + (j0 + j) * dim + d0, buf + j * dc,
                           dc * sizeof *buf);
            }
        }
    }
    return true;
}
