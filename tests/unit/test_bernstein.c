/* The Bernstein basis: identities, derivatives, conversion matrices and
** Bernstein's approximation. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/bernstein.h"
#include "testutil.h"

#define EPS DBL_EPSILON

static void
test_partition_of_unity_and_positivity(void **state)
{
    /* sum_i B_i^n(t) = 1: each recurrence step is a convex combination,
    ** so the sum keeps ~n ulps */
    double b[CF_BEZIER_MAX_DEGREE + 1];
    int degrees[] = { 0, 1, 2, 3, 5, 10, 40, 200, CF_BEZIER_MAX_DEGREE };
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 1);
    for (size_t d = 0; d < sizeof degrees / sizeof degrees[0]; d++) {
        int n = degrees[d];
        for (int j = 0; j < 50; j++) {
            double t = j < 2 ? (double)j : tu_rng_u01(&r), s = 0.0;
            assert_int_equal(cf_bernstein_all(n, t, b), CF_STATUS_OK);
            for (int i = 0; i <= n; i++) {
                assert_true(b[i] >= 0.0);
                s += b[i];
            }
            tu_assert_close(s, 1.0, (n + 2) * EPS, 1.0);
        }
    }
}

static void
test_symmetry_and_closed_form(void **state)
{
    /* B_i^n(t) = B_{n-i}^n(1-t), and = C(n,i) t^i (1-t)^(n-i) computed
    ** directly with pow (an independent formula; small n so that the
    ** binomials are exact) */
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 2);
    for (int n = 0; n <= 30; n++) {
        for (int j = 0; j < 20; j++) {
            double t = tu_rng_u01(&r), a[31], b[31], binom = 1.0;
            /* 1 - (1 - t) can differ from t by an ulp: the comparison
            ** uses t' = 1 - t exactly for both sides */
            double tm = 1.0 - t, tp = 1.0 - tm;
            cf_bernstein_all(n, tp, a);
            cf_bernstein_all(n, tm, b);
            for (int i = 0; i <= n; i++) {
                double direct = binom * pow(tp, i) * pow(tm, n - i);
                tu_assert_close(a[i], b[n - i], 4 * (n + 1) * EPS, 1e-300);
                tu_assert_close(a[i], direct, 4 * (n + 1) * EPS, 1e-300);
                binom = binom * (n - i) / (i + 1);
            }
        }
    }
    {
        double v;
        assert_int_equal(cf_bernstein_value(4, 2, 0.5, &v), CF_STATUS_OK);
        assert_true(v == 6.0 / 16.0);
        assert_int_equal(cf_bernstein_value(4, -1, 0.5, &v), CF_STATUS_OK);
        assert_true(v == 0.0);
        assert_int_equal(cf_bernstein_value(4, 5, 0.5, &v), CF_STATUS_OK);
        assert_true(v == 0.0);
    }
}

static void
test_maximum_at_i_over_n(void **state)
{
    /* For n > 0, B_i^n has its only maximum on [0, 1] at t = i/n: the
    ** derivative vanishes there (to rounding), and the value at i/n is
    ** not exceeded anywhere on a fine grid. */
    (void)state;
    for (int n = 1; n <= 12; n++) {
        for (int i = 0; i <= n; i++) {
            double peak, d[13], v;
            double ti = (double)i / n;
            cf_bernstein_value(n, i, ti, &peak);
            cf_bernstein_all_deriv(n, ti, 1, d);
            if (i > 0 && i < n)
                assert_true(fabs(d[i]) <= 64 * n * EPS);
            for (int j = 0; j <= 2000; j++) {
                double t = j / 2000.0;
                cf_bernstein_value(n, i, t, &v);
                assert_true(v <= peak * (1 + 4 * n * EPS));
            }
            /* strictly smaller a little away from i/n */
            if (i > 0) {
                cf_bernstein_value(n, i, ti - 0.01, &v);
                assert_true(v < peak);
            }
            if (i < n) {
                cf_bernstein_value(n, i, ti + 0.01, &v);
                assert_true(v < peak);
            }
        }
    }
}

static void
test_derivatives(void **state)
{
    /* k-th derivative against central differences of the (k-1)-th:
    ** truncation h^2/6 |f'''| with h = 1e-5 and |f'''| <= ~n^3 2^n keeps
    ** the error below 1e-6 relative for n <= 12 */
    const double h = 1e-5;
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 3);
    for (int n = 0; n <= 12; n++) {
        for (int k = 1; k <= 4; k++) {
            for (int j = 0; j < 10; j++) {
                double t = tu_rng_range(&r, 0.01, 0.99);
                double dk[13], lp[13], lm[13], scale = 1.0;
                assert_int_equal(cf_bernstein_all_deriv(n, t, k, dk),
                                 CF_STATUS_OK);
                cf_bernstein_all_deriv(n, t + h, k - 1, lp);
                cf_bernstein_all_deriv(n, t - h, k - 1, lm);
                for (int i = 0; i <= n; i++)
                    scale = fmax(scale, fabs(dk[i]));
                for (int i = 0; i <= n; i++)
                    assert_true(fabs((lp[i] - lm[i]) / (2 * h) - dk[i]) <=
                                1e-6 * scale);
                if (k > n)
                    for (int i = 0; i <= n; i++)
                        assert_true(dk[i] == 0.0);
            }
        }
    }
    /* seed 004, property 5: d/dt B_i^n = n (B_{i-1}^{n-1} - B_i^{n-1}) and
    ** the second derivative formula n(n-1)(B_{i-2} - 2 B_{i-1} + B_i) */
    {
        double d1[8], d2[8], b6[7], b5[6], t = 0.3;
        cf_bernstein_all_deriv(7, t, 1, d1);
        cf_bernstein_all_deriv(7, t, 2, d2);
        cf_bernstein_all(6, t, b6);
        cf_bernstein_all(5, t, b5);
        for (int i = 0; i <= 7; i++) {
            double a = (i >= 1 ? b6[i - 1] : 0) - (i <= 6 ? b6[i] : 0);
            double b = (i >= 2 ? b5[i - 2] : 0) - 2 * (i >= 1 && i <= 6 ?
                                                       b5[i - 1] : 0) +
                       (i <= 5 ? b5[i] : 0);
            tu_assert_close(d1[i], 7 * a, 1e-14, 1.0);
            tu_assert_close(d2[i], 42 * b, 1e-14, 1.0);
        }
    }
}

static void
test_conversion_matrices(void **state)
{
    /* M M^-1 = I (exact integers / quotients for small n), and
    ** [1 t .. t^n] M = [B_0 .. B_n] at random t */
    static double M[65 * 65], Mi[65 * 65];
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 4);
    for (int n = 0; n <= 20; n++) {
        size_t n1 = (size_t)n + 1;
        assert_int_equal(cf_bernstein_to_power_matrix(n, M, NULL),
                         CF_STATUS_OK);
        assert_int_equal(cf_power_to_bernstein_matrix(n, Mi, NULL),
                         CF_STATUS_OK);
        for (size_t i = 0; i < n1; i++)
            for (size_t j = 0; j < n1; j++) {
                double s = 0.0, mag = 0.0;
                for (size_t k = 0; k < n1; k++) {
                    s += M[i * n1 + k] * Mi[k * n1 + j];
                    mag += fabs(M[i * n1 + k] * Mi[k * n1 + j]);
                }
                /* terms up to ~3^n cancel: rounding relative to their
                ** magnitudes (exact integers times quotients) */
                assert_true(fabs(s - (i == j)) <= 4 * n1 * DBL_EPSILON * mag);
            }
        for (int j = 0; j < 5; j++) {
            double t = tu_rng_u01(&r), b[21], pw = 1.0, row[21] = { 0 };
            double mag[21] = { 0 };
            for (size_t k = 0; k < n1; k++) {
                for (size_t i = 0; i < n1; i++) {
                    row[i] += pw * M[k * n1 + i];
                    mag[i] += fabs(pw * M[k * n1 + i]);
                }
                pw *= t;
            }
            cf_bernstein_all(n, t, b);
            /* the power form cancels terms up to ~3^n: compare relative to
            ** the sum of their magnitudes */
            for (size_t i = 0; i < n1; i++)
                assert_true(fabs(row[i] - b[i]) <= 8 * n1 * DBL_EPSILON *
                                                       mag[i]);
        }
    }
    /* cubic, written out (seed 004): B_0 = 1 - 3t + 3t^2 - t^3, ... */
    {
        const double want[16] = { 1, 0, 0, 0, -3, 3, 0, 0, 3, -6, 3, 0,
                                  -1, 3, -3, 1 };
        cf_bernstein_to_power_matrix(3, M, NULL);
        assert_true(tu_max_diff(M, want, 16) == 0.0);
        cf_power_to_bernstein_matrix(3, Mi, NULL);
        /* t = (B_1 + 2 B_2 + 3 B_3)/3: column 1 is 0, 1/3, 2/3, 1 */
        assert_true(Mi[0 * 4 + 1] == 0.0 && Mi[1 * 4 + 1] == 1.0 / 3 &&
                    Mi[2 * 4 + 1] == 2.0 / 3 && Mi[3 * 4 + 1] == 1.0);
    }
    /* coefficient conversion round trip */
    for (int n = 0; n <= 15; n++) {
        double a[16], b[16], a2[16], t = tu_rng_u01(&r), pv = 0.0, bv;
        for (int i = 0; i <= n; i++)
            a[i] = tu_rng_range(&r, -1, 1);
        assert_int_equal(cf_bernstein_from_power(n, a, b, NULL), CF_STATUS_OK);
        assert_int_equal(cf_bernstein_to_power(n, b, a2, NULL), CF_STATUS_OK);
        for (int i = 0; i <= n; i++)
            assert_true(fabs(a2[i] - a[i]) <= 1e-9);
        for (int i = n; i >= 0; i--)
            pv = pv * t + a[i];
        cf_bernstein_eval(n, b, t, &bv);
        assert_true(fabs(pv - bv) <= 1e-12);
    }
}

static double
f_square(double t, void *ud)
{
    (void)ud;
    return t * t;
}

static double
f_sin(double t, void *ud)
{
    (void)ud;
    return sin(6.0 * t);
}

static double
f_bad(double t, void *ud)
{
    (void)ud;
    return t > 0.5 ? NAN : t;
}

static void
test_bernstein_approximation(void **state)
{
    double coef[CF_BEZIER_MAX_DEGREE + 1], v, prev = INFINITY;
    cf_bezier_t *c;
    cf_diag_t d;
    (void)state;
    /* for f = t^2 the operator is known in closed form:
    ** f_n(t) = t^2 + t (1 - t) / n */
    for (int n = 1; n <= 30; n++) {
        assert_int_equal(cf_bernstein_approx(f_square, NULL, n, coef, NULL),
                         CF_STATUS_OK);
        for (int j = 0; j <= 20; j++) {
            double t = j / 20.0;
            cf_bernstein_eval(n, coef, t, &v);
            tu_assert_close(v, t * t + t * (1 - t) / n, 1e-14, 1.0);
        }
    }
    /* uniform convergence for sin(6t): the max error decreases with n */
    for (int n = 4; n <= 256; n *= 2) {
        double err = 0.0;
        cf_bernstein_approx(f_sin, NULL, n, coef, NULL);
        for (int j = 0; j <= 400; j++) {
            double t = j / 400.0;
            cf_bernstein_eval(n, coef, t, &v);
            err = fmax(err, fabs(v - sin(6 * t)));
        }
        assert_true(err < prev);
        prev = err;
    }
    assert_true(prev < 0.05);
    /* the graph curve is (t, f_n(t)) */
    assert_int_equal(cf_bernstein_approx_curve(f_square, NULL, 7, &c, NULL),
                     CF_STATUS_OK);
    for (int j = 0; j <= 10; j++) {
        double t = j / 10.0, p[2];
        cf_bezier_eval(c, t, p);
        tu_assert_close(p[0], t, 1e-15, 1.0);
        tu_assert_close(p[1], t * t + t * (1 - t) / 7, 1e-14, 1.0);
    }
    cf_bezier_destroy(c);
    /* errors */
    cf_diag_clear(&d);
    assert_int_equal(cf_bernstein_approx(f_bad, NULL, 4, coef, &d),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(d.index, 3);
    assert_non_null(strstr(d.msg, "f(3/4)"));
    assert_int_equal(cf_bernstein_approx(NULL, NULL, 4, coef, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bernstein_approx(f_sin, NULL, 4, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bernstein_approx(f_sin, NULL, 0, coef, NULL),
                     CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bernstein_approx(f_sin, NULL,
                                         CF_BEZIER_MAX_DEGREE + 1, coef,
                                         NULL), CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bernstein_approx_curve(f_sin, NULL, 4, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    c = (cf_bezier_t *)&c;
    assert_int_equal(cf_bernstein_approx_curve(f_bad, NULL, 4, &c, NULL),
                     CF_STATUS_NOT_FINITE);
    assert_null(c);
    /* out of memory: NO_MEMORY, nothing left behind */
    tu_fail_alloc_after(1);
    assert_int_equal(cf_bernstein_approx_curve(f_sin, NULL, 4, &c, NULL),
                     CF_STATUS_NO_MEMORY);
    assert_null(c);
    assert_int_equal(tu_alloc_live(), 0);
    tu_fail_alloc_reset();
}

static void
test_errors(void **state)
{
    double out[8], M[4];
    (void)state;
    assert_int_equal(cf_bernstein_all(-1, 0.5, out), CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bernstein_all(CF_BEZIER_MAX_DEGREE + 1, 0.5, out),
                     CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bernstein_all(3, -0.1, out), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bernstein_all(3, 1.1, out), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bernstein_all(3, NAN, out), CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bernstein_all(3, 0.5, NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bernstein_value(3, 1, 2.0, out), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bernstein_value(-2, 1, 0.5, out),
                     CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bernstein_value(3, 1, 0.5, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bernstein_all_deriv(3, 0.5, -1, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bernstein_all_deriv(3, INFINITY, 1, out),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bernstein_all_deriv(3, 0.5, 1, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bernstein_eval(3, NULL, 0.5, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bernstein_eval(3, out, 0.5, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bernstein_eval(3, out, -1, out), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bernstein_to_power_matrix(-1, M, NULL),
                     CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bernstein_to_power_matrix(
                         CF_BERNSTEIN_MATRIX_MAX_DEGREE + 1, M, NULL),
                     CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_power_to_bernstein_matrix(1, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bernstein_from_power(1, NULL, M, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bernstein_to_power(1, M, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bernstein_from_power(100, M, M + 2, NULL),
                     CF_STATUS_BAD_DEGREE);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_partition_of_unity_and_positivity),
        cmocka_unit_test(test_symmetry_and_closed_form),
        cmocka_unit_test(test_maximum_at_i_over_n),
        cmocka_unit_test(test_derivatives),
        cmocka_unit_test(test_conversion_matrices),
        cmocka_unit_test(test_bernstein_approximation),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
