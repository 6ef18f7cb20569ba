/*
** Least-squares degree reduction with end constraints, in closed form.
**
** P of degree n is to be replaced by Q of degree m < n with the derivatives
** of orders 0 .. k0 at t = 0 and 0 .. k1 at t = 1 kept.  Those derivatives
** fix Q_0 .. Q_k0 and Q_{m-k1} .. Q_m (cf__reduce_ends); call g the curve
** of degree m with these points and zeros elsewhere.  The remaining part
** Q - g lies in
**
**   V = span{B_i^m : k0 < i < m - k1} = w(t) * Pi_d,
**   w(t) = t^(k0+1) (1 - t)^(k1+1),  d = m - k0 - k1 - 2,
**
** and minimising the integral of |P - g - (Q - g)|^2 makes Q - g the
** orthogonal projection of f = P - g onto V.  With the Jacobi polynomials
** J_j = P_j^(alpha, beta)(2t - 1), alpha = 2 k1 + 2, beta = 2 k0 + 2,
** orthogonal for the weight w^2 = t^beta (1 - t)^alpha, the functions
** phi_j = w J_j (j = 0 .. d) are an orthogonal basis of V, so
**
**   Q = g + sum_j  <f, phi_j> / <phi_j, phi_j>  phi_j
**
** (Lutterkort, Peters and Reif, "Polynomial degree reduction in the
** L2-norm equals best Euclidean approximation of Bézier coefficients",
** CAGD 16 (1999); Woźny and Lewanowicz, "Multi-degree reduction of Bézier
** curves with constraints, using dual Bernstein basis polynomials",
** CAGD 26 (2009), where the same projection is written with the dual
** basis of V).  Every inner product is exact in Bernstein form:
**
**   int_0^1 B_p^a B_q^b dt = C(a,p) C(b,q) / ((a + b + 1) C(a+b, p+q)),
**
** and J_j has the Bernstein coefficients
**
**   J_j = sum_i (-1)^(j-i) C(j+alpha, i) C(j+beta, j-i) t^i (1-t)^(j-i),
**
** so that w J_j = sum_i (-1)^(j-i) C(j+alpha, i) C(j+beta, j-i)
** / C(j+a+b, i+a) B_{i+a}^{j+a+b} (a = k0 + 1, b = k1 + 1), elevated to
** degree m.
*/
#include <math.h>
#include <string.h>

#include "bpoly-private.h"
#include "core-private.h"
#include "reduce-private.h"

static long double
lbinom(int n, int k)
{
    long double r = 1.0L;
    if (k < 0 || k > n)
        return 0.0L;
    if (k > n - k)
        k = n - k;
    for (int i = 1; i <= k; i++)
        r = r * (long double)(n - k + i) / (long double)i;
    return r;
}

long double
cf__reduce_gram(int a, int p, int b, int q)
{
    return lbinom(a, p) * lbinom(b, q) /
           ((long double)(a + b + 1) * lbinom(a + b, p + q));
}

/* Q[first + i * dir] for i = 0 .. k from P[pfirst + i * dir]: the forward
** differences of P at the end, scaled by n! (m-j)! / ((n-j)! m!) (equal
** j-th derivatives), summed back into points. */
static void
one_end(const cf__reduce_job_t *j, int k, const double *P0, double *Q0,
        long dir)
{
    size_t h = j->h;
    for (int i = 0; i <= k; i++)
        for (size_t c = 0; c < h; c++) {
            double q = 0.0, rho = 1.0;
            for (int l = 0; l <= i; l++) {
                double d = 0.0;
                /* l-th difference at the end */
                for (int s = 0; s <= l; s++)
                    d += ((l - s) % 2 ? -1.0 : 1.0) * cf__binomial(l, s) *
                         P0[(long)s * dir * (long)h + (long)c];
                if (l > 0)
                    rho *= (double)(j->n - l + 1) / (double)(j->m - l + 1);
                q += cf__binomial(i, l) * rho * d;
            }
            Q0[(long)i * dir * (long)h + (long)c] = q;
        }
}

void
cf__reduce_ends(const cf__reduce_job_t *j, double *Q)
{
    size_t h = j->h;
    one_end(j, j->k0, j->P, Q, 1);
    one_end(j, j->k1, j->P + (size_t)j->n * h, Q + (size_t)j->m * h, -1);
}

/* The basis in long double (the alternating sums of binomials lose about
** log2(2^j) bits; long double's 11 more bits keep the reduction of an
** elevated curve exact to 1e-14): phi[j * (m + 1) + i]. */
static void
phi_long(int m, int k0, int k1, long double *phi)
{
    int a = k0 + 1, b = k1 + 1, d = m - k0 - k1 - 2;
    int alpha = 2 * k1 + 2, beta = 2 * k0 + 2;
    for (int j = 0; j <= d; j++) {
        long double *row = phi + (size_t)j * (size_t)(m + 1);
        int e = j + a + b;
        for (int i = 0; i <= m; i++)
            row[i] = 0.0L;
        for (int i = 0; i <= j; i++)
            row[i + a] = ((j - i) % 2 ? -1.0L : 1.0L) *
                         lbinom(j + alpha, i) * lbinom(j + beta, j - i) /
                         lbinom(e, i + a);
        /* elevate e -> m: R_i = i/(r+1) R_{i-1} + (1 - i/(r+1)) R_i */
        for (int r = e; r < m; r++)
            for (int i = r + 1; i >= 0; i--) {
                long double lam = (long double)i / (long double)(r + 1);
                row[i] = (i > 0 ? lam * row[i - 1] : 0.0L) +
                         (i <= r ? (1.0L - lam) * row[i] : 0.0L);
            }
    }
}

cf_status_t
cf__reduce_phi(int m, int k0, int k1, double *phi)
{
    int d = m - k0 - k1 - 2;
    size_t count = (size_t)(d + 1) * (size_t)(m + 1);
    long double *tmp = cf__alloc_array(count, sizeof *tmp);
    if (tmp == NULL)
        return CF_STATUS_NO_MEMORY;
    phi_long(m, k0, k1, tmp);
    for (size_t i = 0; i < count; i++)
        phi[i] = (double)tmp[i];
    cf__free(tmp);
    return CF_STATUS_OK;
}

/* f = P - A elevated to degree n (A: m + 1 points):
** A'_i = sum_l C(m,l) C(n-m,i-l) / C(n,i) A_l */
static void
residual(const cf__reduce_job_t *j, const long double *A, long double *f)
{
    int n = j->n, m = j->m;
    size_t h = j->h;
    for (int i = 0; i <= n; i++)
        for (size_t c = 0; c < h; c++) {
            long double q = 0.0L;
            for (int l = 0; l <= m; l++)
                if (i - l >= 0 && i - l <= n - m)
                    q += lbinom(m, l) * lbinom(n - m, i - l) /
                         lbinom(n, i) * A[(size_t)l * h + c];
            f[(size_t)i * h + c] = (long double)j->P[(size_t)i * h + c] - q;
        }
}

/* acc += sum_j <f, phi_j> / <phi_j, phi_j> phi_j; G[p * (m + 1) + q] =
** int B_p^n B_q^m, nn[j] = <phi_j, phi_j> */
static void
project(const cf__reduce_job_t *j, int d, const long double *f,
        const long double *phi, const long double *G, const long double *nn,
        long double *acc)
{
    int n = j->n, m = j->m;
    size_t h = j->h, mp = (size_t)(m + 1);
    for (int jj = 0; jj <= d; jj++) {
        const long double *ph = phi + (size_t)jj * mp;
        for (size_t c = 0; c < h; c++) {
            long double s = 0.0L;
            for (int p = 0; p <= n; p++) {
                long double row = 0.0L;
                for (int q = 0; q <= m; q++)
                    row += G[(size_t)p * mp + (size_t)q] * ph[q];
                s += f[(size_t)p * h + c] * row;
            }
            s /= nn[jj];
            for (int q = 0; q <= m; q++)
                acc[(size_t)q * h + c] += s * ph[q];
        }
    }
}

/* The projection is done twice: once of P - g, then of what is left of
** P after the first result, added to it (one step of iterative
** refinement).  The second step makes the result as accurate as its
** residual, so that an elevated curve comes back to 1e-14 also where long
** double is no wider than double (valgrind, other platforms): the first
** step's error is a multiple of the rounding of the alternating sums,
** the second's a multiple of that times the first's error. */
cf_status_t
cf__reduce_l2(const cf__reduce_job_t *j, double *Q)
{
    int n = j->n, m = j->m, d = m - j->k0 - j->k1 - 2;
    size_t h = j->h, np = (size_t)(n + 1), mp = (size_t)(m + 1);
    long double *f, *phi, *G, *acc, *nn;

    memset(Q, 0, mp * h * sizeof *Q);
    cf__reduce_ends(j, Q);
    if (d < 0)
        return CF_STATUS_OK;
    f = cf__alloc_array(np * h + (size_t)(d + 1) * mp + np * mp + mp * h +
                            (size_t)(d + 1),
                        sizeof *f);
    if (f == NULL)
        return CF_STATUS_NO_MEMORY;
    phi = f + np * h;
    G = phi + (size_t)(d + 1) * mp;
    acc = G + np * mp;
    nn = acc + mp * h;
    for (int p = 0; p <= n; p++)
        for (int q = 0; q <= m; q++)
            G[(size_t)p * mp + (size_t)q] = cf__reduce_gram(n, p, m, q);
    phi_long(m, j->k0, j->k1, phi);
    for (int jj = 0; jj <= d; jj++) {
        const long double *ph = phi + (size_t)jj * mp;
        nn[jj] = 0.0L;
        for (int p = 0; p <= m; p++)
            for (int q = 0; q <= m; q++)
                nn[jj] += ph[p] * ph[q] * cf__reduce_gram(m, p, m, q);
    }
    for (size_t i = 0; i < mp * h; i++)
        acc[i] = (long double)Q[i];
    for (int step = 0; step < 2; step++) {
        residual(j, acc, f);
        project(j, d, f, phi, G, nn, acc);
    }
    for (size_t i = 0; i < mp * h; i++)
        Q[i] = (double)acc[i];
    cf__free(f);
    return CF_STATUS_OK;
}
