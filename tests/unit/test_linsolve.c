/* The linear solvers behind interpolation (src/linsolve.c). */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/core.h"
#include "../../src/core-private.h"
#include "../../src/linsolve-private.h"
#include "testutil.h"

/*
** Independent reference: dense Gaussian elimination with partial pivoting
** on a copy (n <= 40), solving A x = b for nrhs columns.
*/
#define NMAX 40
static void
dense_solve(size_t n, const double *A, const double *b, size_t nrhs,
            double *x)
{
    double M[NMAX][NMAX], R[NMAX][4];
    assert_true(n <= NMAX && nrhs <= 4);
    for (size_t i = 0; i < n; i++) {
        for (size_t j = 0; j < n; j++)
            M[i][j] = A[i * n + j];
        for (size_t c = 0; c < nrhs; c++)
            R[i][c] = b[i * nrhs + c];
    }
    for (size_t k = 0; k < n; k++) {
        size_t p = k;
        for (size_t i = k + 1; i < n; i++)
            if (fabs(M[i][k]) > fabs(M[p][k]))
                p = i;
        for (size_t j = 0; j < n; j++) {
            double t = M[k][j];
            M[k][j] = M[p][j];
            M[p][j] = t;
        }
        for (size_t c = 0; c < nrhs; c++) {
            double t = R[k][c];
            R[k][c] = R[p][c];
            R[p][c] = t;
        }
        for (size_t i = k + 1; i < n; i++) {
            double l = M[i][k] / M[k][k];
            for (size_t j = k; j < n; j++)
                M[i][j] -= l * M[k][j];
            for (size_t c = 0; c < nrhs; c++)
                R[i][c] -= l * R[k][c];
        }
    }
    for (size_t i = n; i-- > 0;) {
        for (size_t c = 0; c < nrhs; c++) {
            double s = R[i][c];
            for (size_t j = i + 1; j < n; j++)
                s -= M[i][j] * x[j * nrhs + c];
            x[i * nrhs + c] = s / M[i][i];
        }
    }
}

/* Scale of a solution vector, for relative comparisons. */
static double
max_abs(const double *v, size_t n)
{
    double m = 0.0;
    for (size_t i = 0; i < n; i++)
        if (fabs(v[i]) > m)
            m = fabs(v[i]);
    return m;
}

/*
** Independent reference of the banded least squares: dense Householder QR
** (below, checked against the normal equations) on the full matrix.
*/
/*
** Column k: v = a_k(k..m-1) - alpha e_1 with alpha = -sign(a_kk) |a_k|, so
** that H = I - 2 v v^T / (v^T v) maps a_k onto alpha e_1 without
** cancellation.  H is applied to the remaining columns of A and to B.
*/
static cf_status_t
dense_lsq(size_t m, size_t n, double *A, double *B, size_t nrhs, double *x,
          cf_diag_t *diag)
{
    double *v, maxnorm = 0.0;
    if (n == 0 || m < n || nrhs == 0)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                         "least squares with %zu rows and %zu unknowns "
                         "(need rows >= unknowns >= 1)", m, n);
    for (size_t j = 0; j < n; j++) {
        double s = 0.0;
        for (size_t i = 0; i < m; i++)
            s += A[i * n + j] * A[i * n + j];
        if (!isfinite(s))
            return cf_diag_set(diag, CF_STATUS_NOT_FINITE, (long)j,
                             "least-squares matrix column %zu is not "
                             "finite", j);
        if (sqrt(s) > maxnorm)
            maxnorm = sqrt(s);
    }
    v = malloc(m * sizeof *v);
    if (v == NULL)
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                         "no memory for least squares with %zu rows", m);
    for (size_t k = 0; k < n; k++) {
        double norm2 = 0.0, norm, alpha, vv;
        for (size_t i = k; i < m; i++)
            norm2 += A[i * n + k] * A[i * n + k];
        norm = sqrt(norm2);
        if (!(norm > (double)m * DBL_EPSILON * maxnorm)) {
            free(v);
            return cf_diag_set(diag, CF_STATUS_DEGENERATE, (long)k,
                             "least-squares matrix is rank deficient: "
                             "column %zu depends on the previous ones", k);
        }
        alpha = A[k * n + k] > 0.0 ? -norm : norm;
        for (size_t i = k; i < m; i++)
            v[i] = A[i * n + k];
        v[k] -= alpha;
        vv = norm2 - A[k * n + k] * A[k * n + k] + v[k] * v[k];
        for (size_t j = k + 1; j < n; j++) {
            double s = 0.0;
            for (size_t i = k; i < m; i++)
                s += v[i] * A[i * n + j];
            s *= 2.0 / vv;
            for (size_t i = k; i < m; i++)
                A[i * n + j] -= s * v[i];
        }
        for (size_t c = 0; c < nrhs; c++) {
            double s = 0.0;
            for (size_t i = k; i < m; i++)
                s += v[i] * B[i * nrhs + c];
            s *= 2.0 / vv;
            for (size_t i = k; i < m; i++)
                B[i * nrhs + c] -= s * v[i];
        }
        A[k * n + k] = alpha;
        for (size_t i = k + 1; i < m; i++)
            A[i * n + k] = 0.0;
    }
    for (size_t i = n; i-- > 0;) {
        for (size_t c = 0; c < nrhs; c++) {
            double s = B[i * nrhs + c];
            for (size_t j = i + 1; j < n; j++)
                s -= A[i * n + j] * x[j * nrhs + c];
            x[i * nrhs + c] = s / A[i * n + i];
        }
    }
    free(v);
    return CF_STATUS_OK;
}

static void
test_cyclic_by_hand(void **state)
{
    /* [4 1 1; 1 4 1; 1 1 4] x = (6, 6, 6) has x = (1, 1, 1) (each row sums
    ** to 6); the second column (4, 1, 1) is A (1, 0, 0).  The corners
    ** A[0][2] = sub[0] and A[2][0] = sup[2] are what makes it cyclic. */
    const double sub[] = { 1, 1, 1 }, mid[] = { 4, 4, 4 },
                 sup[] = { 1, 1, 1 };
    double rhs[] = { 6, 4, 6, 1, 6, 1 };
    const double want[] = { 1, 1, 1, 0, 1, 0 };
    (void)state;
    assert_int_equal(cf__solve_cyclic_tridiagonal(3, sub, mid, sup, rhs, 2,
                                                  NULL), CF_STATUS_OK);
    for (int i = 0; i < 6; i++)
        tu_assert_close(rhs[i], want[i], 16 * DBL_EPSILON, 1.0);
}

static void
test_cyclic_random_against_dense(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 82);
    for (int trial = 0; trial < 50; trial++) {
        size_t n = 3 + (size_t)(tu_rng_u01(&r) * 30);
        double sub[NMAX], mid[NMAX], sup[NMAX], A[NMAX * NMAX] = { 0 };
        double rhs[NMAX * 3], b[NMAX * 3], x[NMAX * 3];
        for (size_t i = 0; i < n; i++) {
            sub[i] = tu_rng_range(&r, -1, 1);
            sup[i] = tu_rng_range(&r, -1, 1);
            mid[i] = (tu_rng_u01(&r) < 0.5 ? -1 : 1) *
                     (2.0 + tu_rng_u01(&r));
            A[i * n + (i + n - 1) % n] += sub[i];
            A[i * n + i] += mid[i];
            A[i * n + (i + 1) % n] += sup[i];
            for (int c = 0; c < 3; c++)
                b[3 * i + c] = rhs[3 * i + c] = tu_rng_range(&r, -5, 5);
        }
        assert_int_equal(cf__solve_cyclic_tridiagonal(n, sub, mid, sup, rhs,
                                                      3, NULL),
                         CF_STATUS_OK);
        dense_solve(n, A, b, 3, x);
        /* dominant again; Sherman-Morrison adds a few roundings */
        assert_true(tu_max_diff(rhs, x, 3 * n) <=
                    256 * DBL_EPSILON * max_abs(x, 3 * n));
    }
}

static void
test_cyclic_errors(void **state)
{
    /* too small; and all ones (3 x 3 of ones: rank 1) */
    const double one[] = { 1, 1, 1, 1 };
    double rhs[] = { 1, 2, 3, 4 };
    cf_diag_t d;
    (void)state;
    cf_diag_clear(&d);
    assert_int_equal(cf__solve_cyclic_tridiagonal(2, one, one, one, rhs, 1,
                                                  &d),
                     CF_STATUS_INVALID_ARG);
    assert_string_equal(d.msg, "cyclic tridiagonal system needs size >= 3, "
                               "got 2 (with 1 right-hand sides)");
    cf_diag_clear(&d);
    assert_int_equal(cf__solve_cyclic_tridiagonal(3, one, one, one, rhs, 1,
                                                  &d),
                     CF_STATUS_DEGENERATE);
    assert_non_null(strstr(d.msg, "singular"));
}

static void
fill_band(cf__band_t *b, double *A, size_t n, size_t kl, size_t ku,
          tu_rng *r, int zero_diagonal)
{
    memset(A, 0, n * n * sizeof *A);
    for (size_t i = 0; i < n; i++) {
        for (size_t j = i >= kl ? i - kl : 0; j <= i + ku && j < n; j++) {
            double v = tu_rng_range(r, -1, 1);
            if (j == i)
                v = zero_diagonal ? 0.0
                                  : (v < 0 ? -1.0 : 1.0) * (double)(kl + ku + 1);
            A[i * n + j] = v;
            cf__band_set(b, i, j, v);
        }
    }
}

static void
test_band_random_against_dense(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 83);
    for (int trial = 0; trial < 60; trial++) {
        size_t n = 2 + (size_t)(tu_rng_u01(&r) * 25);
        size_t kl = (size_t)(tu_rng_u01(&r) * 4), ku = (size_t)(tu_rng_u01(&r) * 4);
        double A[NMAX * NMAX], b[NMAX * 2], rhs[NMAX * 2], x[NMAX * 2];
        cf__band_t band;
        if (kl == 0)
            kl = 1; /* a zero diagonal needs somewhere to pivot from */
        assert_int_equal(cf__band_init(&band, n, kl, ku, NULL), CF_STATUS_OK);
        /* zero diagonal on every third trial: partial pivoting is needed;
        ** otherwise a strictly dominant diagonal */
        fill_band(&band, A, n, kl, ku, &r, trial % 3 == 0);
        for (size_t i = 0; i < 2 * n; i++)
            b[i] = rhs[i] = tu_rng_range(&r, -3, 3);
        if (cf__band_factor(&band, NULL) != CF_STATUS_OK) {
            /* a random zero-diagonal band can be singular: skip it */
            cf__band_fini(&band);
            continue;
        }
        cf__band_solve(&band, rhs, 2);
        dense_solve(n, A, b, 2, x);
        /* Random matrices can be ill-conditioned, so compare backward
        ** errors: the normwise residual |A x - b| / (|A| |x| + |b|) (max
        ** norms) of partial pivoting is a small multiple of n eps times
        ** the growth factor, which a band of width <= 7 keeps small. */
        for (size_t c = 0; c < 2; c++) {
            double res = 0.0, anorm = 0.0, xnorm = 0.0, bnorm = 0.0;
            for (size_t i = 0; i < n; i++) {
                double s = -b[i * 2 + c], rowsum = 0.0;
                for (size_t j = 0; j < n; j++) {
                    s += A[i * n + j] * rhs[j * 2 + c];
                    rowsum += fabs(A[i * n + j]);
                }
                res = fmax(res, fabs(s));
                anorm = fmax(anorm, rowsum);
                xnorm = fmax(xnorm, fabs(rhs[i * 2 + c]));
                bnorm = fmax(bnorm, fabs(b[i * 2 + c]));
            }
            assert_true(res <= 64 * (double)n * DBL_EPSILON *
                                   (anorm * xnorm + bnorm));
        }
        /* with a dominant diagonal (no zero-diagonal trial) the matrix is
        ** well conditioned (|A^-1| <= 1), and the solution agrees with
        ** dense elimination to a few dozen ulps */
        if (trial % 3 != 0)
            assert_true(tu_max_diff(rhs, x, 2 * n) <=
                        64 * DBL_EPSILON * max_abs(x, 2 * n));
        cf__band_fini(&band);
    }
}

static void
test_band_needs_pivoting(void **state)
{
    /* [0 1 0; 2 0 1; 0 3 1] x = (1, 3, 4): row 1 gives x1 = 1, then
    ** 2 x0 + x2 = 3 and 3 + x2 = 4 give x2 = 1, x0 = 1.  The first pivot
    ** is zero, so this only works with the row interchange. */
    cf__band_t b;
    double rhs[] = { 1, 3, 4 };
    (void)state;
    assert_int_equal(cf__band_init(&b, 3, 1, 1, NULL), CF_STATUS_OK);
    cf__band_set(&b, 0, 1, 1);
    cf__band_set(&b, 1, 0, 2);
    cf__band_set(&b, 1, 2, 1);
    cf__band_set(&b, 2, 1, 3);
    cf__band_set(&b, 2, 2, 1);
    assert_int_equal(cf__band_factor(&b, NULL), CF_STATUS_OK);
    cf__band_solve(&b, rhs, 1);
    for (int i = 0; i < 3; i++)
        tu_assert_close(rhs[i], 1.0, 4 * DBL_EPSILON, 1.0);
    cf__band_fini(&b);
    cf__band_fini(NULL);
}

static void
test_band_errors(void **state)
{
    cf__band_t b;
    cf_diag_t d;
    (void)state;
    cf_diag_clear(&d);
    assert_int_equal(cf__band_init(&b, 0, 1, 1, &d), CF_STATUS_INVALID_ARG);
    assert_string_equal(d.msg, "banded system of size 0");
    /* [1 2; 2 4] is singular */
    cf_diag_clear(&d);
    assert_int_equal(cf__band_init(&b, 2, 1, 1, NULL), CF_STATUS_OK);
    cf__band_set(&b, 0, 0, 1);
    cf__band_set(&b, 0, 1, 2);
    cf__band_set(&b, 1, 0, 2);
    cf__band_set(&b, 1, 1, 4);
    assert_int_equal(cf__band_factor(&b, &d), CF_STATUS_DEGENERATE);
    assert_int_equal(d.index, 1);
    assert_non_null(strstr(d.msg, "banded system is singular at row 1"));
    cf__band_fini(&b);
    /* a NaN entry */
    cf_diag_clear(&d);
    assert_int_equal(cf__band_init(&b, 2, 0, 1, NULL), CF_STATUS_OK);
    cf__band_set(&b, 0, 0, 1);
    cf__band_set(&b, 1, 1, NAN);
    assert_int_equal(cf__band_factor(&b, &d), CF_STATUS_NOT_FINITE);
    assert_string_equal(d.msg, "banded system has a non-finite entry in row 1");
    cf__band_fini(&b);
}

static void
test_lsq_by_hand(void **state)
{
    /* Fit y = a + b x to (0, 0), (1, 1), (2, 1).  Normal equations
    ** [3 3; 3 5] (a, b) = (2, 3): a = (10 - 9) / 6 = 1/6, b = (9 - 6) / 6
    ** = 1/2.  Second column: exact data y = 1 + 2 x gives (1, 2). */
    double A[] = { 1, 0, 1, 1, 1, 2 };
    double B[] = { 0, 1, 1, 3, 1, 5 };
    double x[4] = { 0 };
    (void)state;
    assert_int_equal(dense_lsq(3, 2, A, B, 2, x, NULL), CF_STATUS_OK);
    /* Householder QR is backward stable; this matrix has condition ~ 4 */
    tu_assert_close(x[0], 1.0 / 6.0, 16 * DBL_EPSILON, 1.0);
    tu_assert_close(x[2], 0.5, 16 * DBL_EPSILON, 1.0);
    tu_assert_close(x[1], 1.0, 16 * DBL_EPSILON, 1.0);
    tu_assert_close(x[3], 2.0, 16 * DBL_EPSILON, 1.0);
}

static void
test_lsq_random_normal_equations(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 84);
    for (int trial = 0; trial < 40; trial++) {
        size_t n = 1 + (size_t)(tu_rng_u01(&r) * 8);
        size_t m = n + (size_t)(tu_rng_u01(&r) * 20);
        double A[40 * 10], A2[40 * 10], B[40 * 2], B2[40 * 2], x[20];
        double N[10 * 10], rhs[10 * 2], xn[20];
        for (size_t i = 0; i < m * n; i++)
            A[i] = A2[i] = tu_rng_range(&r, -1, 1);
        for (size_t i = 0; i < m * 2; i++)
            B[i] = B2[i] = tu_rng_range(&r, -1, 1);
        assert_int_equal(dense_lsq(m, n, A, B, 2, x, NULL), CF_STATUS_OK);
        /* the residual is orthogonal to the columns: A^T (A x - B) = 0 */
        for (size_t j = 0; j < n; j++) {
            for (size_t c = 0; c < 2; c++) {
                double s = 0.0, scale = 0.0;
                for (size_t i = 0; i < m; i++) {
                    double res = -B2[i * 2 + c];
                    for (size_t k = 0; k < n; k++)
                        res += A2[i * n + k] * x[k * 2 + c];
                    s += A2[i * n + j] * res;
                    scale += fabs(A2[i * n + j]) * (fabs(B2[i * 2 + c]) + 1);
                }
                assert_true(fabs(s) <= 1e3 * DBL_EPSILON * scale);
            }
        }
        /* and agrees with the normal equations A^T A x = A^T B solved
        ** densely, when those are well conditioned (m >= n + 3 random) */
        if (m < n + 3)
            continue;
        for (size_t j = 0; j < n; j++) {
            for (size_t k = 0; k < n; k++) {
                double s = 0.0;
                for (size_t i = 0; i < m; i++)
                    s += A2[i * n + j] * A2[i * n + k];
                N[j * n + k] = s;
            }
            for (size_t c = 0; c < 2; c++) {
                double s = 0.0;
                for (size_t i = 0; i < m; i++)
                    s += A2[i * n + j] * B2[i * 2 + c];
                rhs[j * 2 + c] = s;
            }
        }
        dense_solve(n, N, rhs, 2, xn);
        /* normal equations square the condition number: loose bound */
        assert_true(tu_max_diff(x, xn, 2 * n) <= 1e-8 * (1 + max_abs(xn, 2 * n)));
    }
}

static void
test_lsq_band_against_dense(void **state)
{
    /* Random banded rows with non-decreasing first columns (as B-spline
    ** fitting produces them), some of them starting beyond the previous
    ** start and some clipped at the last column: the Givens solution must
    ** equal the Householder one of the same dense matrix. */
    tu_rng r;
    int compared = 0;
    (void)state;
    tu_rng_seed(&r, 85);
    for (int trial = 0; trial < 40; trial++) {
        size_t n = 1 + (size_t)(tu_rng_u01(&r) * 12);
        size_t w = 1 + (size_t)(tu_rng_u01(&r) * 4);
        size_t m = n + (size_t)(tu_rng_u01(&r) * 25), first = 0;
        double A[40 * 13] = { 0 }, B[40 * 2], x[13 * 2], xd[13 * 2];
        cf__lsq_band_t lb;
        assert_int_equal(cf__lsq_band_init(&lb, n, w, 2, NULL), CF_STATUS_OK);
        for (size_t i = 0; i < m; i++) {
            double v[5] = { 0 };
            /* cover every column: advance the start on a schedule */
            size_t want = (i * n) / m;
            if (want > first)
                first = want;
            for (size_t j = 0; j < w && first + j < n; j++) {
                v[j] = tu_rng_range(&r, -1, 1);
                A[i * n + first + j] = v[j];
            }
            B[2 * i] = tu_rng_range(&r, -2, 2);
            B[2 * i + 1] = tu_rng_range(&r, -2, 2);
            cf__lsq_band_add(&lb, first, v, B + 2 * i);
        }
        if (cf__lsq_band_solve(&lb, x, NULL) != CF_STATUS_OK) {
            /* a random sparse matrix may be rank deficient: then the
            ** dense solver must agree that it is */
            assert_int_equal(dense_lsq(m, n, A, B, 2, xd, NULL),
                             CF_STATUS_DEGENERATE);
            cf__lsq_band_fini(&lb);
            continue;
        }
        if (dense_lsq(m, n, A, B, 2, xd, NULL) == CF_STATUS_OK) {
            /* both backward stable; random matrices of this size have
            ** condition numbers below ~1e4: agreement to 1e-10 */
            assert_true(tu_max_diff(x, xd, 2 * n) <=
                        1e-10 * (1 + max_abs(xd, 2 * n)));
            compared++;
        }
        cf__lsq_band_fini(&lb);
    }
    /* most random trials are of full rank: the comparison is real */
    assert_true(compared >= 30);
}

static void
test_lsq_band_by_hand_and_errors(void **state)
{
    /* The line fit of test_lsq_by_hand with rows of width 2 starting at
    ** column 0: (a, b) = (1/6, 1/2).  Then a zero column: rank deficient. */
    const double rows[3][2] = { { 1, 0 }, { 1, 1 }, { 1, 2 } };
    const double y[3] = { 0, 1, 1 };
    double x[3];
    cf__lsq_band_t lb;
    cf_diag_t d;
    (void)state;
    assert_int_equal(cf__lsq_band_init(&lb, 2, 2, 1, NULL), CF_STATUS_OK);
    for (int i = 0; i < 3; i++)
        cf__lsq_band_add(&lb, 0, rows[i], y + i);
    assert_int_equal(cf__lsq_band_solve(&lb, x, NULL), CF_STATUS_OK);
    tu_assert_close(x[0], 1.0 / 6.0, 16 * DBL_EPSILON, 1.0);
    tu_assert_close(x[1], 0.5, 16 * DBL_EPSILON, 1.0);
    cf__lsq_band_fini(&lb);
    /* column 1 of 3 never used */
    assert_int_equal(cf__lsq_band_init(&lb, 3, 1, 1, NULL), CF_STATUS_OK);
    cf__lsq_band_add(&lb, 0, rows[0], y);
    cf__lsq_band_add(&lb, 2, rows[0], y);
    cf_diag_clear(&d);
    assert_int_equal(cf__lsq_band_solve(&lb, x, &d), CF_STATUS_DEGENERATE);
    assert_string_equal(d.msg, "least-squares matrix is rank deficient: "
                               "column 1 depends on the others");
    cf__lsq_band_fini(&lb);
    cf__lsq_band_fini(NULL);
    cf_diag_clear(&d);
    assert_int_equal(cf__lsq_band_init(&lb, 0, 1, 1, &d),
                     CF_STATUS_INVALID_ARG);
    assert_string_equal(d.msg, "banded least squares with 0 unknowns, band "
                               "1 and 1 right-hand sides");
}

/* Every allocation of every solver fails in turn; nothing leaks. */
static void
test_out_of_memory(void **state)
{
    const double sub[] = { 1, 1, 1 }, mid[] = { 4, 4, 4 },
                 sup[] = { 1, 1, 1 };
    (void)state;
    for (long k = 1;; k++) {
        double rhs[] = { 6, 6, 6 };
        cf__band_t b;
        cf_status_t s2, s3, s4;
        cf_diag_t d;
        tu_fail_alloc_after(k);
        s2 = cf__solve_cyclic_tridiagonal(3, sub, mid, sup, rhs, 1, NULL);
        cf_diag_clear(&d);
        s3 = cf__band_init(&b, 3, 1, 1, &d);
        if (s3 == CF_STATUS_OK)
            cf__band_fini(&b);
        else
            assert_string_equal(d.msg,
                                "no memory for a banded system of size 3");
        {
            cf__lsq_band_t lb;
            s4 = cf__lsq_band_init(&lb, 4, 2, 2, NULL);
            cf__lsq_band_fini(&lb);
        }
        tu_fail_alloc_reset();
        assert_int_equal(tu_alloc_live(), 0);
        assert_true(s2 == CF_STATUS_OK || s2 == CF_STATUS_NO_MEMORY);
        assert_true(s3 == CF_STATUS_OK || s3 == CF_STATUS_NO_MEMORY);
        assert_true(s4 == CF_STATUS_OK || s4 == CF_STATUS_NO_MEMORY);
        if (s2 == CF_STATUS_OK && s3 == CF_STATUS_OK &&
            s4 == CF_STATUS_OK)
            break;
        assert_true(k < 100);
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cyclic_by_hand),
        cmocka_unit_test(test_cyclic_random_against_dense),
        cmocka_unit_test(test_cyclic_errors),
        cmocka_unit_test(test_band_random_against_dense),
        cmocka_unit_test(test_band_needs_pivoting),
        cmocka_unit_test(test_band_errors),
        cmocka_unit_test(test_lsq_by_hand),
        cmocka_unit_test(test_lsq_random_normal_equations),
        cmocka_unit_test(test_lsq_band_against_dense),
        cmocka_unit_test(test_lsq_band_by_hand_and_errors),
        cmocka_unit_test(test_out_of_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
