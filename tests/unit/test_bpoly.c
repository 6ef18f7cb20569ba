/*
** The one kernel of Bernstein coefficient arrays (src/bpoly.c), with the
** cases of each of its callers: the subdivision of curves and of
** root intervals, the elevation of curves and of the cusp polynomial, the
** products of the rational derivative, the bounding box and the cusp
** polynomial, the power basis of the Levien moments (degree 6, scaled) and
** of the public conversion (any degree, also n >= 64), and the roots of
** extremes, closest points and cusps with one idea of zero; and the one
** evaluator of curve points and derivatives.
** References are independent: the Bernstein basis (and its derivatives by
** Leibniz's rule) summed in long double.
*/
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/bernstein.h"
#include "../../src/bpoly-private.h"
#include "testutil.h"

#define NMAX 160

/* C(n, k) t^k (1-t)^(n-k) summed in long double: an independent value. */
static long double
ref_eval(const double *a, size_t stride, int n, double t)
{
    long double s = 0.0L, c = 1.0L;
    for (int k = 0; k <= n; k++) {
        s += c * powl(t, k) * powl(1.0L - t, n - k) * a[(size_t)k * stride];
        c = c * (long double)(n - k) / (long double)(k + 1);
    }
    return s;
}

static double
amax_of(const double *a, int n)
{
    double m = 0.0;
    for (int i = 0; i <= n; i++)
        m = fmax(m, fabs(a[i]));
    return m;
}

static void
random_poly(tu_rng *r, double *a, int n)
{
    for (int i = 0; i <= n; i++)
        a[i] = tu_rng_range(r, -2.0, 2.0);
}

static void
test_decasteljau_and_eval(void **state)
{
    tu_rng r;
    double a[NMAX + 1], v[NMAX + 1];
    (void)state;
    tu_rng_seed(&r, 1);
    for (int n = 0; n <= 40; n++) {
        random_poly(&r, a, n);
        for (int j = 0; j <= 8; j++) {
            double t = j / 8.0;
            double ref = (double)ref_eval(a, 1, n, t);
            memcpy(v, a, ((size_t)n + 1) * sizeof *v);
            tu_assert_close(cf__bp_decasteljau(v, n, t), ref, 1e-12, 1.0);
            tu_assert_close(cf__bp_eval(a, n, t), ref, 1e-12, 1.0);
        }
    }
    /* the ends are the end coefficients exactly */
    random_poly(&r, a, 7);
    assert_true(cf__bp_eval(a, 7, 0.0) == a[0]);
    assert_true(cf__bp_eval(a, 7, 1.0) == a[7]);
}

/* Split at stride 1 (root intervals), 2 (planar curves, the unrolled
** path) and 3 (rational planar curves): both halves reparametrise the
** polynomial, with left and right separate, right in place, left only. */
static void
test_split(void **state)
{
    tu_rng r;
    double src[3 * 21], left[3 * 21], right[3 * 21], only[3 * 21];
    (void)state;
    tu_rng_seed(&r, 2);
    for (size_t stride = 1; stride <= 3; stride++)
        for (int n = 0; n <= 20; n++) {
            double s = tu_rng_range(&r, 0.1, 0.9);
            for (size_t i = 0; i < ((size_t)n + 1) * stride; i++)
                src[i] = tu_rng_range(&r, -3.0, 3.0);
            cf__bp_split(src, stride, n, s, left, right);
            for (size_t k = 0; k < stride; k++)
                for (int j = 0; j <= 4; j++) {
                    double u = j / 4.0;
                    double whole = (double)ref_eval(src + k, stride, n, s * u);
                    double whole_r =
                        (double)ref_eval(src + k, stride, n, s + (1 - s) * u);
                    tu_assert_close((double)ref_eval(left + k, stride, n, u),
                                    whole, 1e-12, 1.0);
                    tu_assert_close((double)ref_eval(right + k, stride, n, u),
                                    whole_r, 1e-12, 1.0);
                }
            /* in place (right aliases src) and left only agree bit for bit */
            memcpy(only, src, ((size_t)n + 1) * stride * sizeof *only);
            cf__bp_split(only, stride, n, s, NULL, only);
            assert_memory_equal(only, right,
                                ((size_t)n + 1) * stride * sizeof *only);
            cf__bp_split(src, stride, n, s, only, NULL);
            assert_memory_equal(only, left,
                                ((size_t)n + 1) * stride * sizeof *only);
        }
}

/* Elevation in place: curves (stride 2 and 3, by a few degrees), the cubic
** chains (degree 0..3 raised to 3) and the cusp polynomial (4m - 2 raised by
** 2m + 2, stride 1, up to degree 6m = 96). */
static void
test_elevate(void **state)
{
    tu_rng r;
    double a[3 * (NMAX + 1)], orig[3 * (NMAX + 1)];
    (void)state;
    tu_rng_seed(&r, 3);
    for (size_t stride = 1; stride <= 3; stride++)
        for (int m = 0; m <= 12; m++)
            for (int e = 0; e <= 5; e++) {
                for (size_t i = 0; i < ((size_t)m + 1) * stride; i++)
                    orig[i] = a[i] = tu_rng_range(&r, -1.0, 1.0);
                cf__bp_elevate(a, stride, m, e);
                for (size_t k = 0; k < stride; k++) {
                    assert_true(a[k] == orig[k]);
                    assert_true(a[(size_t)(m + e) * stride + k] ==
                                orig[(size_t)m * stride + k]);
                    for (int j = 0; j <= 6; j++) {
                        double t = j / 6.0;
                        tu_assert_close(
                            (double)ref_eval(a + k, stride, m + e, t),
                            (double)ref_eval(orig + k, stride, m, t), 1e-13,
                            1.0);
                    }
                }
            }
    for (int m = 2; m <= 16; m++) {
        int from = 4 * m - 2, by = 2 * m + 2;
        random_poly(&r, orig, from);
        memcpy(a, orig, ((size_t)from + 1) * sizeof *a);
        cf__bp_elevate(a, 1, from, by);
        for (int j = 0; j <= 10; j++) {
            double t = j / 10.0;
            tu_assert_close(cf__bp_eval(a, from + by, t),
                            (double)ref_eval(orig, 1, from, t), 1e-11, 1.0);
        }
    }
}

/* Products: strided operands (coordinates of homogeneous points, as in the
** rational derivative), sign and accumulation (A' w - A w'), and the
** unstrided products of the cusp polynomial up to degree 6m. */
static void
test_product(void **state)
{
    tu_rng r;
    double f[3 * 41], g[3 * 41], h[3 * 81], h0[3 * 81];
    (void)state;
    tu_rng_seed(&r, 4);
    for (int nf = 0; nf <= 12; nf++)
        for (int ng = 0; ng <= 12; ng += 3) {
            size_t sf = 1 + (size_t)(nf % 3), sg = 1 + (size_t)(ng % 2),
                   sh = 3;
            for (size_t i = 0; i < 3 * 41; i++) {
                f[i] = tu_rng_range(&r, -1.0, 1.0);
                g[i] = tu_rng_range(&r, -1.0, 1.0);
            }
            for (size_t i = 0; i < 3 * 81; i++)
                h0[i] = h[i] = tu_rng_range(&r, -1.0, 1.0);
            cf__bp_mul(f, nf, sf, g, ng, sg, h, sh, 1.0, false);
            for (int j = 0; j <= 6; j++) {
                double t = j / 6.0;
                long double p = ref_eval(f, sf, nf, t) * ref_eval(g, sg, ng, t);
                tu_assert_close((double)ref_eval(h, sh, nf + ng, t),
                                (double)p, 1e-13, 1.0);
            }
            /* only every sh-th value is written */
            for (size_t i = 0; i < 3 * 81; i++)
                if (i % sh != 0 || i / sh > (size_t)(nf + ng))
                    assert_true(h[i] == h0[i]);
            /* h - f g  = 0 */
            cf__bp_mul(f, nf, sf, g, ng, sg, h, sh, -1.0, true);
            for (int k = 0; k <= nf + ng; k++)
                assert_true(fabs(h[(size_t)k * sh]) <= 1e-15 * (nf + ng + 1));
        }
    for (int m = 2; m <= 16; m++) {
        double a[2 * 16 + 1], b[4 * 16 + 1], c[6 * 16 + 1];
        random_poly(&r, a, 2 * m);
        random_poly(&r, b, 4 * m);
        cf__bp_mul(b, 4 * m, 1, a, 2 * m, 1, c, 1, 1.0, false);
        for (int j = 0; j <= 10; j++) {
            double t = j / 10.0;
            tu_assert_close(
                cf__bp_eval(c, 6 * m, t),
                (double)(ref_eval(a, 1, 2 * m, t) * ref_eval(b, 1, 4 * m, t)),
                1e-11, 1.0);
        }
    }
}

static void
test_deriv(void **state)
{
    tu_rng r;
    double a[21], d[20];
    (void)state;
    tu_rng_seed(&r, 5);
    for (int m = 1; m <= 20; m++) {
        random_poly(&r, a, m);
        cf__bp_deriv(a, m, d);
        for (int j = 1; j < 8; j++) {
            double t = j / 8.0, hstep = 1e-6;
            double num = (double)(ref_eval(a, 1, m, t + hstep) -
                                  ref_eval(a, 1, m, t - hstep)) /
                         (2 * hstep);
            tu_assert_close(cf__bp_eval(d, m - 1, t), num, 1e-6, 1.0);
        }
    }
}

/* Power -> Bernstein: the Levien moments (degree 6 on [0, h]) and the
** public conversion (h = 1) for every degree up to 100 (also n >= 64,
** beyond any fixed table of 64 entries). */
static void
test_from_power(void **state)
{
    tu_rng r;
    double p[101], b[101];
    (void)state;
    tu_rng_seed(&r, 6);
    for (int n = 0; n <= 100; n++) {
        double h = n == 6 ? 1.7 : (n % 3 == 0 ? 1.0 : 0.5);
        for (int k = 0; k <= n; k++)
            p[k] = tu_rng_range(&r, -1.0, 1.0) / (1.0 + k);
        cf__bp_from_power(p, n, h, b);
        for (int j = 0; j <= 8; j++) {
            double s = j / 8.0;
            long double x = (long double)h * s, pw = 0.0L;
            for (int k = n; k >= 0; k--)
                pw = pw * x + p[k];
            tu_assert_close(cf__bp_eval(b, n, s), (double)pw, 1e-10, 1.0);
        }
    }
    {
        /* the public conversion is this kernel at h = 1, bit for bit */
        double b2[65];
        for (int k = 0; k <= 64; k++)
            p[k] = tu_rng_range(&r, -1.0, 1.0);
        cf__bp_from_power(p, 64, 1.0, b);
        assert_int_equal(cf_bernstein_from_power(64, p, b2, NULL),
                         CF_STATUS_OK);
        assert_memory_equal(b, b2, 65 * sizeof *b);
    }
}

/* Bernstein coefficients of lead * prod (t - r_i), built in the Bernstein
** form (well conditioned): the linear factor t - r is (-r, 1 - r). */
static int
from_roots(const double *rts, int nr, double lead, double *out)
{
    double p[NMAX + 1], q[NMAX + 1];
    p[0] = lead;
    for (int i = 0; i < nr; i++) {
        double lin[2] = { -rts[i], 1.0 - rts[i] };
        cf__bp_mul(p, i, 1, lin, 1, 1, q, 1, 1.0, false);
        memcpy(p, q, ((size_t)i + 2) * sizeof *p);
    }
    memcpy(out, p, ((size_t)nr + 1) * sizeof *p);
    return nr;
}

static void
expect_roots(const double *a, int n, const double *want, size_t nwant,
             double tol)
{
    double got[64];
    size_t count = 99;
    assert_int_equal(cf__bp_roots(a, n, got, 64, &count), CF_STATUS_OK);
    assert_int_equal(count, nwant);
    for (size_t i = 0; i < nwant; i++)
        assert_true(fabs(got[i] - want[i]) <= tol);
    for (size_t i = 1; i < count; i++)
        assert_true(got[i] > got[i - 1]);
}

static void
test_roots(void **state)
{
    double a[NMAX + 1];
    (void)state;
    {
        /* simple roots (extremes of a curve: derivative numerators) */
        double r3[3] = { 0.1, 0.45, 0.8 };
        from_roots(r3, 3, 1.0, a);
        expect_roots(a, 3, r3, 3, 1e-14);
    }
    {
        /* a root exactly at a split point (0.5) and one near it */
        double r2[2] = { 0.25, 0.5 };
        from_roots(r2, 2, -2.0, a);
        expect_roots(a, 2, r2, 2, 1e-14);
    }
    {
        /* roots at the ends count (cusps at t = 0, 1), found by the noise
        ** floor even when rounding leaves a tiny end coefficient */
        double r2[2] = { 0.0, 1.0 }, rw[2] = { 0.0, 1.0 };
        from_roots(r2, 2, 1.0, a);
        expect_roots(a, 2, rw, 2, 0.0);
        a[0] = 1e-18;
        expect_roots(a, 2, rw, 2, 0.0);
    }
    {
        /* a double root (a tangency of the closest-point function):
        ** rounding may split it into two, both within the square root of
        ** the rounding */
        double rr[2] = { 0.3, 0.3 }, got[4];
        size_t count;
        from_roots(rr, 2, 1.0, a);
        assert_int_equal(cf__bp_roots(a, 2, got, 4, &count), CF_STATUS_OK);
        assert_true(count >= 1 && count <= 2);
        for (size_t i = 0; i < count; i++)
            assert_true(fabs(got[i] - 0.3) <= 1e-6);
    }
    {
        /* no sign change, no root; the zero polynomial has none */
        double pos[4] = { 1.0, 0.5, 0.25, 2.0 }, zero[4] = { 0 };
        expect_roots(pos, 3, NULL, 0, 0.0);
        expect_roots(zero, 3, NULL, 0, 0.0);
        expect_roots(pos, 0, NULL, 0, 0.0);
    }
    {
        /* many roots at high degree (cusp polynomials of long curves) */
        double rs[24], got[8];
        size_t count;
        for (int i = 0; i < 24; i++)
            rs[i] = (i + 0.5) / 24.0;
        from_roots(rs, 24, 1e6, a);
        expect_roots(a, 24, rs, 24, 1e-7);
        /* cap: at most cap roots written, the first ones */
        assert_int_equal(cf__bp_roots(a, 24, got, 8, &count), CF_STATUS_OK);
        assert_int_equal(count, 8);
        for (int i = 0; i < 8; i++)
            assert_true(fabs(got[i] - rs[i]) <= 1e-7);
    }
    {
        /* one idea of zero, relative to the coefficients: scaling the
        ** polynomial by any power of two changes nothing */
        double r3[3] = { 0.2, 0.6, 0.61 }, g1[8], g2[8];
        size_t c1, c2;
        from_roots(r3, 3, 1.0, a);
        assert_int_equal(cf__bp_roots(a, 3, g1, 8, &c1), CF_STATUS_OK);
        for (int i = 0; i <= 3; i++)
            a[i] = ldexp(a[i], -600);
        assert_true(amax_of(a, 3) < 1e-170);
        assert_int_equal(cf__bp_roots(a, 3, g2, 8, &c2), CF_STATUS_OK);
        assert_int_equal(c1, 3);
        assert_int_equal(c2, 3);
        assert_memory_equal(g1, g2, 3 * sizeof *g1);
    }
}

/* The j-th derivative at t of sum_k a[k * stride] B_k^n, each basis
** function differentiated by Leibniz's rule on t^k (1-t)^(n-k), summed in
** long double: independent of de Casteljau and of control-point
** differences. */
static long double
ref_deriv(const double *a, size_t stride, int n, double t, int j)
{
    long double sum = 0.0L, c = 1.0L, tl = t, sl = 1.0L - (long double)t;
    for (int k = 0; k <= n; k++) {
        long double d = 0.0L, cji = 1.0L;
        for (int i = 0; i <= j; i++) {
            int e1 = k - i, e2 = n - k - (j - i);
            if (e1 >= 0 && e2 >= 0) {
                long double f1 = 1.0L, f2 = 1.0L;
                for (int q = 0; q < i; q++)
                    f1 *= (long double)(k - q);
                for (int q = 0; q < j - i; q++)
                    f2 *= -(long double)(n - k - q);
                d += cji * f1 * f2 * powl(tl, e1) * powl(sl, e2);
            }
            cji = cji * (long double)(j - i) / (long double)(i + 1);
        }
        sum += c * d * a[(size_t)k * stride];
        c = c * (long double)(n - k) / (long double)(k + 1);
    }
    return sum;
}

/* n!/(n-j)! max|a|: the size of the j-th derivative, for tolerances. */
static double
deriv_scale(int n, int j, double amax)
{
    double f = 1.0;
    for (int q = 0; q < j; q++)
        f *= (double)(n > q ? n - q : 1) * 2.0;
    return f * amax;
}

/*
** One case: nc coordinates, degree n, derivatives 0..k, polynomial or
** rational (weights at w_off doubles after the first coordinate, stride
** doubles per point).  Polynomial: every derivative against ref_deriv.
** Rational: the Cartesian derivatives x^(m) returned must satisfy
** Leibniz's rule A^(m) = sum_i C(m,i) w^(i) x^(m-i) with A = w x and w
** differentiated by ref_deriv.  Above the degree a polynomial's
** derivatives are exactly zero.
*/
static void
check_curve(tu_rng *r, size_t nc, size_t stride, int n, int k,
            bool rational, size_t w_off)
{
    enum { PMAX = 48 * 8 };
    double p[PMAX], out[8 * 12], amax = 0.0;
    double t[] = { 0.0, 1e-9, 0.3, 0.5, 0.7734, 1.0 - 1e-9, 1.0 };
    const double *w = rational ? p + w_off : NULL;
    assert_true((size_t)(n + 1) * stride <= PMAX);
    assert_true((size_t)(k + 1) * nc <= sizeof out / sizeof out[0]);
    for (size_t i = 0; i < (size_t)(n + 1) * stride; i++)
        p[i] = tu_rng_range(r, -2.0, 2.0);
    if (rational)
        for (int i = 0; i <= n; i++) {
            double wi = tu_rng_range(r, 0.5, 2.0);
            p[(size_t)i * stride + w_off] = wi;
            for (size_t c = 0; c < nc; c++)
                p[(size_t)i * stride + c] *= wi;
        }
    for (int i = 0; i <= n; i++)
        for (size_t c = 0; c < nc; c++)
            amax = fmax(amax, fabs(p[(size_t)i * stride + c]));
    for (size_t it = 0; it < sizeof t / sizeof t[0]; it++) {
        cf__bp_curve_derivs(p, w, stride, nc, n, t[it], k, out);
        for (size_t c = 0; c < nc; c++) {
            for (int m = 0; m <= k; m++) {
                double got = out[(size_t)m * nc + c];
                double sc = deriv_scale(n, m, amax);
                if (!rational) {
                    if (m > n) {
                        assert_true(got == 0.0);
                        continue;
                    }
                    tu_assert_close(got,
                                    (double)ref_deriv(p + c, stride, n,
                                                      t[it], m),
                                    1e-13, sc);
                } else {
                    /* tolerance: relative to the terms of the sum */
                    long double lhs = 0.0L, size = 0.0L, cmi = 1.0L;
                    for (int i = 0; i <= m; i++) {
                        long double term =
                            cmi * ref_deriv(w, stride, n, t[it], i) *
                            out[(size_t)(m - i) * nc + c];
                        lhs += term;
                        size += fabsl(term);
                        cmi = cmi * (long double)(m - i) /
                              (long double)(i + 1);
                    }
                    tu_assert_close((double)lhs,
                                    (double)ref_deriv(p + c, stride, n,
                                                      t[it], m),
                                    1e-12 * (m + 1),
                                    fmax((double)size, sc));
                }
            }
        }
    }
}

/*
** The one evaluator of curve points and derivatives, with the cases of
** each caller: the offset sources (planar, polynomial and
** rational, first and second derivatives, up to the eighth for the
** tangent at a stationary point), the planar cubic segments of the
** offset chains and trims (degree 3, stride 2, points only and with the
** derivative), the Hermite fits of cf_bezier_to_cubics in any dimension,
** and the one-coordinate evaluation behind tangents, curvature, boxes and
** arc length (a coordinate read at the stored stride, its weight not next
** to it; degrees beyond the small path; orders above the degree).
*/
static void
test_curve_derivs(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 11);
    for (int n = 1; n <= 24; n++) {
        check_curve(&r, 2, 2, n, 2, false, 0);
        check_curve(&r, 2, 3, n, 2, true, 2);
        check_curve(&r, 2, 2, n, n < 8 ? n : 8, false, 0);
        check_curve(&r, 2, 3, n, n < 8 ? n : 8, true, 2);
    }
    for (int k = 0; k <= 1; k++)
        check_curve(&r, 2, 2, 3, k, false, 0);
    for (size_t dim = 1; dim <= 7; dim += 2) {
        for (int n = 4; n <= 12; n += 4) {
            check_curve(&r, dim, dim, n, 1, false, 0);
            check_curve(&r, dim, dim + 1, n, 1, true, dim);
            check_curve(&r, dim, dim, n, 0, false, 0);
            check_curve(&r, dim, dim + 1, n, 0, true, dim);
        }
    }
    for (int n = 1; n <= 40; n += 3) {
        int k = n + 2 < 10 ? n + 2 : 10;
        /* coordinate 1 of a rational curve in R^3: weight 2 doubles on */
        check_curve(&r, 1, 4, n, k, true, 2);
        check_curve(&r, 1, 3, n, k, false, 0);
    }
}

/* The small path (coordinates side by side, the orders up to 2 on
** registers) and the one-coordinate path do the same operations: the
** same bits, for rational (x, y, w), polynomial (x, y) and 3-coordinate
** points, orders 0..3. */
static void
test_curve_derivs_paths(void **state)
{
    tu_rng r;
    double p[25 * 3], both[4 * 3], one[4];
    (void)state;
    tu_rng_seed(&r, 12);
    for (int n = 1; n <= 24; n++) {
        for (int i = 0; i < 3 * (n + 1); i++)
            p[i] = tu_rng_range(&r, 0.5, 2.0);
        for (int k = 0; k <= 3; k++) {
            for (int j = 0; j <= 8; j++) {
                double t = j / 8.0;
                /* rational planar: stride 3, the weight after x and y */
                cf__bp_curve_derivs(p, p + 2, 3, 2, n, t, k, both);
                for (size_t c = 0; c < 2; c++) {
                    cf__bp_curve_derivs(p + c, p + 2, 3, 1, n, t, k, one);
                    for (int m = 0; m <= k; m++)
                        assert_memory_equal(&one[m], &both[2 * m + c],
                                            sizeof one[m]);
                }
                /* polynomial planar, stride 2 (the cubic segments) */
                cf__bp_curve_derivs(p, NULL, 2, 2, n, t, k, both);
                for (size_t c = 0; c < 2; c++) {
                    cf__bp_curve_derivs(p + c, NULL, 2, 1, n, t, k, one);
                    for (int m = 0; m <= k; m++)
                        assert_memory_equal(&one[m], &both[2 * m + c],
                                            sizeof one[m]);
                }
                /* three polynomial coordinates, stride 3 */
                cf__bp_curve_derivs(p, NULL, 3, 3, n, t, k, both);
                cf__bp_curve_derivs(p + 2, NULL, 3, 1, n, t, k, one);
                for (int m = 0; m <= k; m++)
                    assert_memory_equal(&one[m], &both[3 * m + 2],
                                        sizeof one[m]);
            }
        }
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_decasteljau_and_eval),
        cmocka_unit_test(test_split),
        cmocka_unit_test(test_elevate),
        cmocka_unit_test(test_product),
        cmocka_unit_test(test_deriv),
        cmocka_unit_test(test_from_power),
        cmocka_unit_test(test_roots),
        cmocka_unit_test(test_curve_derivs),
        cmocka_unit_test(test_curve_derivs_paths),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
