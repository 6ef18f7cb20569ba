/*
** Evaluation of Bézier curves: points and derivatives at one parameter
** (the evaluator of bpoly.c, through bezier-private.h), the de Casteljau
** triangle, and the fast batch path behind cf_bezier_eval_many and
** cf_bezier_eval_deriv_many.
**
** For a polynomial curve of degree n <= FAST_MAX each coordinate is
** evaluated by Horner's rule in the Bernstein form, with a_i = C(n,i) P_i
** and s = 1 - t:
**
**   acc = a_n;  for i = n-1 .. 0:  acc = acc t + a_i s^(n-i)
**
** which ends with acc = sum_i a_i t^i s^(n-i) = c(t).  Every term
** a_i t^i s^(n-i) = B_i^n(t) P_i is formed with O(n) relative roundings and
** the terms are never larger than max |P_i| in sum, so the result differs
** from de Casteljau by O(n) ulps of max |P_i| (tests/unit/test_bezier.c
** measures it over random curves), with no division and no branch: 3n
** multiplications and additions per coordinate plus n for the powers of s.
** The loops have a constant degree after inlining, so the compiler
** vectorises them over the parameters.  Rational curves and higher degrees
** use de Casteljau per point.
*/
#include <math.h>
#include <string.h>

#include "bezier-private.h"

#define MAXN CF_BEZIER_MAX_DEGREE

/* ---- evaluation ---------------------------------------------------------- */

cf_status_t
cf_bezier_eval(const cf_bezier_t *c, double t, double *out)
{
    cf_status_t st;
    if (c == NULL || out == NULL)
        return CF_STATUS_INVALID_ARG;
    st = cf__bezier_check_param(&t);
    if (st != CF_STATUS_OK)
        return st;
    cf__bezier_eval_point(c, t, out);
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_eval_derivs(const cf_bezier_t *c, double t, int k, double *out)
{
    cf_status_t st;
    if (c == NULL || out == NULL || k < 0)
        return CF_STATUS_INVALID_ARG;
    if (k > MAXN)
        return CF_STATUS_BAD_DEGREE;
    st = cf__bezier_check_param(&t);
    if (st != CF_STATUS_OK)
        return st;
    cf__bezier_derivs(c, t, k, out);
    return CF_STATUS_OK;
}

/* The k-th derivatives (k = 0: points) at parameters in [0, 1]. */
static void
deriv_many(const cf_bezier_t *c, const double *t, size_t n, int k,
           double *out)
{
    double res[MAXN + 1];
    if (k == 0) {
        cf__bezier_eval_many_fast(c, t, n, out);
        return;
    }
    if (!c->rational && cf__bezier_deriv_many_fast(c, t, n, k, out))
        return;
    for (size_t i = 0; i < n; i++)
        for (size_t d = 0; d < c->dim; d++) {
            cf__bezier_coord_derivs(c, d, t[i], k, res);
            out[i * c->dim + d] = res[k];
        }
}

/* parameters per block of the clamped copy */
#define CLAMP_BLK 256

/*
** deriv_many after the domain rule.  A branch-free pass first (NaN and
** infinities fail the comparisons, so every bad parameter fails it): the
** parameters are used as given when it passes.  Otherwise each is checked
** by the rule (nothing is written when one is refused), then the batch is
** evaluated in blocks from a clamped copy.  Its first loop is 34 bytes
** (CF__LOOP_ALIGNED).
*/
CF__LOOP_ALIGNED static cf_status_t
checked_many(const cf_bezier_t *c, const double *t, size_t n, int k,
             double *out)
{
    int ok = 1;
    for (size_t i = 0; i < n; i++)
        ok &= (t[i] >= 0.0) & (t[i] <= 1.0);
    if (ok) {
        deriv_many(c, t, n, k, out);
        return CF_STATUS_OK;
    }
    for (size_t i = 0; i < n; i++) {
        double x = t[i];
        cf_status_t st = cf__bezier_check_param(&x);
        if (st != CF_STATUS_OK)
            return st;
    }
    for (size_t i0 = 0; i0 < n; i0 += CLAMP_BLK) {
        double tc[CLAMP_BLK];
        size_t m = n - i0 < CLAMP_BLK ? n - i0 : CLAMP_BLK;
        for (size_t j = 0; j < m; j++) {
            tc[j] = t[i0 + j];
            (void)cf__bezier_check_param(&tc[j]);
        }
        deriv_many(c, tc, m, k, out + i0 * c->dim);
    }
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_eval_deriv_many(const cf_bezier_t *c, const double *t, size_t n,
                          int k, double *out)
{
    if (c == NULL || (n > 0 && (t == NULL || out == NULL)) || k < 0)
        return CF_STATUS_INVALID_ARG;
    if (k > MAXN)
        return CF_STATUS_BAD_DEGREE;
    return checked_many(c, t, n, k, out);
}

cf_status_t
cf_bezier_eval_many(const cf_bezier_t *c, const double *t, size_t n,
                    double *out)
{
    if (c == NULL || (n > 0 && (t == NULL || out == NULL)))
        return CF_STATUS_INVALID_ARG;
    return checked_many(c, t, n, 0, out);
}

size_t
cf_bezier_decasteljau_size(const cf_bezier_t *c)
{
    size_t n1;
    if (c == NULL)
        return 0;
    n1 = (size_t)c->degree + 1;
    return n1 * (n1 + 1) / 2 * c->dim;
}

cf_status_t
cf_bezier_decasteljau(const cf_bezier_t *c, double t, double *out)
{
    double v[MAXN + 1], w[MAXN + 1], s;
    int n;
    cf_status_t st;
    if (c == NULL || out == NULL)
        return CF_STATUS_INVALID_ARG;
    st = cf__bezier_check_param(&t);
    if (st != CF_STATUS_OK)
        return st;
    n = c->degree;
    s = 1.0 - t;
    for (size_t k = 0; k < c->dim; k++) {
        size_t base = 0;   /* first point of the current level */
        for (int i = 0; i <= n; i++) {
            v[i] = c->pts[(size_t)i * c->hdim + k];
            w[i] = c->rational ? c->pts[(size_t)i * c->hdim + c->dim] : 1.0;
        }
        for (int r = 0; r <= n; r++) {
            if (r > 0) {
                for (int i = 0; i <= n - r; i++) {
                    v[i] = s * v[i] + t * v[i + 1];
                    if (c->rational)
                        w[i] = s * w[i] + t * w[i + 1];
                }
            }
            for (int i = 0; i <= n - r; i++)
                out[(base + (size_t)i) * c->dim + k] =
                    c->rational ? v[i] / w[i] : v[i];
            base += (size_t)(n - r) + 1;
        }
    }
    return CF_STATUS_OK;
}

/* ---- the fast batch path ------------------------------------------------ */

/* Fused multiply-adds where the target has them (the x86-64-v3 and v4
** clones): they only remove roundings; the accuracy test runs whichever
** clone the machine selects, and all compute the same formula. */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("fp-contract=fast")
#endif

#define FAST_MAX 10
#define BLK 256


/* a[i] = C(n, i) p[i * stride] */
static void
scaled_coeffs(const double *p, size_t stride, int n, double *a)
{
    double b = 1.0;
    for (int i = 0; i <= n; i++) {
        a[i] = b * p[(size_t)i * stride];
        b = b * (double)(n - i) / (double)(i + 1);
    }
}

/*
** The Horner steps are written out (no inner loop) so that, with n a
** constant after inlining, the loop over the parameters is straight-line
** code that the compiler vectorises.  The coefficients are loaded before
** the loop.
*/
#define LOADC(a, k) const double a##k = n >= k ? a[k] : 0.0
#define LOAD11(a) LOADC(a, 0); LOADC(a, 1); LOADC(a, 2); LOADC(a, 3); \
    LOADC(a, 4); LOADC(a, 5); LOADC(a, 6); LOADC(a, 7); LOADC(a, 8); \
    LOADC(a, 9); LOADC(a, 10)
/* powers s^(n-i), i = n-1 .. 0, as sp<i> */
#define POWERS(sj) \
    double sp9 = 1, sp8 = 1, sp7 = 1, sp6 = 1, sp5 = 1, sp4 = 1, sp3 = 1, \
           sp2 = 1, sp1 = 1, sp0 = 1; \
    if (n > 9) { sp9 = sj; } \
    if (n > 8) { sp8 = n - 1 == 8 ? sj : sp9 * sj; } \
    if (n > 7) { sp7 = n - 1 == 7 ? sj : sp8 * sj; } \
    if (n > 6) { sp6 = n - 1 == 6 ? sj : sp7 * sj; } \
    if (n > 5) { sp5 = n - 1 == 5 ? sj : sp6 * sj; } \
    if (n > 4) { sp4 = n - 1 == 4 ? sj : sp5 * sj; } \
    if (n > 3) { sp3 = n - 1 == 3 ? sj : sp4 * sj; } \
    if (n > 2) { sp2 = n - 1 == 2 ? sj : sp3 * sj; } \
    if (n > 1) { sp1 = n - 1 == 1 ? sj : sp2 * sj; } \
    if (n > 0) { sp0 = n - 1 == 0 ? sj : sp1 * sj; }
#define HSTEP(acc, a, i) if (n > i) { acc = acc * tj + a##i * sp##i; }
#define HORNER(acc, a) do { \
        acc = n == 10 ? a##10 : n == 9 ? a##9 : n == 8 ? a##8 : \
              n == 7 ? a##7 : n == 6 ? a##6 : n == 5 ? a##5 : \
              n == 4 ? a##4 : n == 3 ? a##3 : n == 2 ? a##2 : \
              n == 1 ? a##1 : a##0; \
        HSTEP(acc, a, 9) HSTEP(acc, a, 8) HSTEP(acc, a, 7) \
        HSTEP(acc, a, 6) HSTEP(acc, a, 5) HSTEP(acc, a, 4) \
        HSTEP(acc, a, 3) HSTEP(acc, a, 2) HSTEP(acc, a, 1) \
        HSTEP(acc, a, 0) \
    } while (0)

/* 2D: both coordinates in one loop (interleaved store). */
CF__INLINE void
horner2(int n, const double *ax, const double *ay, const double *restrict t,
        size_t m, double *restrict out)
{
    LOAD11(ax);
    LOAD11(ay);
    for (size_t j = 0; j < m; j++) {
        double tj = t[j], sj = 1.0 - tj, x, y;
        POWERS(sj)
        HORNER(x, ax);
        HORNER(y, ay);
        out[2 * j] = x;
        out[2 * j + 1] = y;
    }
}

/* Any dimension: one coordinate at a time (strided store). */
CF__INLINE void
hornerd(int n, const double *coef, size_t dim, const double *restrict t,
        size_t m, double *restrict out)
{
    for (size_t d = 0; d < dim; d++) {
        const double *a = coef + d * (FAST_MAX + 1);
        LOAD11(a);
        for (size_t j = 0; j < m; j++) {
            double tj = t[j], sj = 1.0 - tj, v;
            POWERS(sj)
            HORNER(v, a);
            out[j * dim + d] = v;
        }
    }
}

#define CASES(X) X(0) X(1) X(2) X(3) X(4) X(5) X(6) X(7) X(8) X(9) X(10)

CF__INLINE void
run_horner2_body(int n, const double *ax, const double *ay,
                 const double *t, size_t m, double *out)
{
    switch (n) {
#define X(N) case N: horner2(N, ax, ay, t, m, out); break;
    CASES(X)
#undef X
    default:
        break;
    }
}

CF__CLONED(void, run_horner2,
           (int n, const double *ax, const double *ay, const double *t,
            size_t m, double *out),
           (n, ax, ay, t, m, out), )

/* At most 16 coordinates per call of the generic path (stack tables). */
#define DIM_CHUNK 16

CF__INLINE void
run_hornerd_body(int n, const double *coef, size_t dim, const double *t,
                 size_t m, double *out)
{
    switch (n) {
#define X(N) case N: hornerd(N, coef, dim, t, m, out); break;
    CASES(X)
#undef X
    default:
        break;
    }
}

CF__CLONED(void, run_hornerd,
           (int n, const double *coef, size_t dim, const double *t, size_t m,
            double *out),
           (n, coef, dim, t, m, out), )

/*
** Evaluate the polynomial with Bernstein coefficients coef (degree n, point
** stride `stride`, dim coordinates) at t[0..m-1] into out (dim per point).
*/
static void
fast_poly(const double *coef, size_t stride, int n, size_t dim,
          const double *t, size_t m, double *out)
{
    if (dim == 2) {
        double ax[FAST_MAX + 1], ay[FAST_MAX + 1];
        scaled_coeffs(coef, stride, n, ax);
        scaled_coeffs(coef + 1, stride, n, ay);
        run_horner2(n, ax, ay, t, m, out);
        return;
    }
    for (size_t d0 = 0; d0 < dim; d0 += DIM_CHUNK) {
        double a[DIM_CHUNK * (FAST_MAX + 1)];
        double buf[BLK * DIM_CHUNK];
        size_t dc = dim - d0 < DIM_CHUNK ? dim - d0 : DIM_CHUNK;
        for (size_t d = 0; d < dc; d++)
            scaled_coeffs(coef + d0 + d, stride, n, a + d * (FAST_MAX + 1));
        if (dc == dim) {
            run_hornerd(n, a, dim, t, m, out);
            continue;
        }
        for (size_t j0 = 0; j0 < m; j0 += BLK) {
            size_t mb = m - j0 < BLK ? m - j0 : BLK;
            run_hornerd(n, a, dc, t + j0, mb, buf);
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
cf__bezier_deriv_many_fast(const cf_bezier_t *c, const double *t, size_t n,
                           int k, double *out)
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
