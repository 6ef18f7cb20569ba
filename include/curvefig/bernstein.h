/*
** The Bernstein basis of degree n on [0, 1]:
**
**   B_i^n(t) = C(n, i) t^i (1 - t)^(n - i),   i = 0 .. n,
**
** (B_i^n = 0 for i outside 0..n).  Values are computed by the recurrence
** B_i^n = (1 - t) B_i^(n-1) + t B_(i-1)^(n-1) (no large binomials, stable for
** every degree up to CF_BEZIER_MAX_DEGREE), derivatives by
** d/dt B_i^n = n (B_(i-1)^(n-1) - B_i^(n-1)) applied k times.
**
** Parameters must be finite and in [0, 1] (CF_STATUS_DOMAIN otherwise;
** within 8 DBL_EPSILON of an end they are that end, as in bezier.h).
*/
#ifndef CURVEFIG_BERNSTEIN_H
#define CURVEFIG_BERNSTEIN_H

#include "curvefig/bezier.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest degree of the power <-> Bernstein matrices (their entries grow
** like 3^n; up to n = 30 they are exact integers or exact quotients). */
#define CF_BERNSTEIN_MATRIX_MAX_DEGREE 64

/* *out = B_i^n(t) (0 when i < 0 or i > n). */
CF_API cf_status_t cf_bernstein_value(int n, int i, double t, double *out);

/* out[0..n] = B_0^n(t) ... B_n^n(t). */
CF_API cf_status_t cf_bernstein_all(int n, double t, double *out);

/* out[0..n] = the k-th derivatives (k >= 0) of B_0^n ... B_n^n at t
** (all zero when k > n). */
CF_API cf_status_t cf_bernstein_all_deriv(int n, double t, int k, double *out);

/* Evaluate sum_i coef[i] B_i^n(t) (de Casteljau); allocates nothing. */
CF_API cf_status_t cf_bernstein_eval(int n, const double *coef, double t,
                                     double *out);

/*
** The conversion matrices of seed 004, (n + 1) x (n + 1), row-major:
**
**   [B_0^n(t) ... B_n^n(t)] = [1 t ... t^n] M,
**   M[j][i] = (-1)^(j-i) C(n, i) C(n-i, j-i) for j >= i, 0 above,
**
** and its inverse [1 t ... t^n] = [B_0^n(t) ... B_n^n(t)] M^-1,
**   M^-1[i][j] = C(i, j) / C(n, j) for i >= j, 0 above.
** Both are lower triangular.  0 <= n <= CF_BERNSTEIN_MATRIX_MAX_DEGREE.
*/
CF_API cf_status_t cf_bernstein_to_power_matrix(int n, double *M,
                                                cf_diag_t *diag);
CF_API cf_status_t cf_power_to_bernstein_matrix(int n, double *Minv,
                                                cf_diag_t *diag);

/* Coefficient conversions with those matrices (in and out may not alias):
** power a[0..n] (sum a_j t^j) -> Bernstein b[0..n] and back. */
CF_API cf_status_t cf_bernstein_from_power(int n, const double *a, double *b,
                                           cf_diag_t *diag);
CF_API cf_status_t cf_bernstein_to_power(int n, const double *b, double *a,
                                         cf_diag_t *diag);

/* A real function of one variable for the approximation below. */
typedef double (*cf_real_func_t)(double t, void *ud);

/*
** Bernstein's approximation (seed 000) f_n(t) = sum_i f(i/n) B_i^n(t), which
** converges uniformly to a continuous f.  coef[0..n] receives f(i/n)
** (n >= 1); a non-finite f(i/n) is an error naming i.  Evaluate f_n with
** cf_bernstein_eval.
*/
CF_API cf_status_t cf_bernstein_approx(cf_real_func_t f, void *ud, int n,
                                       double *coef, cf_diag_t *diag);

/* The graph of f_n as a planar Bézier curve of degree n: control points
** (i/n, f(i/n)) (linear precision makes its x coordinate equal to t), so
** the curve is t -> (t, f_n(t)). */
CF_API cf_status_t cf_bernstein_approx_curve(cf_real_func_t f, void *ud, int n,
                                             cf_bezier_t **out,
                                             cf_diag_t *diag);

#ifdef __cplusplus
}
#endif

#endif
