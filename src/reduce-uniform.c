/*
** Near-best uniform degree reduction with end constraints.
**
** The same space as the least-squares reduction (reduce-l2.c): Q = g + sum
** x_j phi_j, g fixed by the end derivatives, and now the largest distance
** max_t |P(t) - Q(t)| is to be made small.  For a scalar polynomial the
** best uniform approximation is characterised by equioscillation and found
** by Remez's exchange; the error of a curve is a vector, which has no
** alternation theorem, so the minimax solution is approached here by
** Lawson's iteration, which works for vector (and complex) errors alike:
**
**   on S Chebyshev nodes t_s, weights omega_s (sum 1), solve the weighted
**   least-squares problem min sum_s omega_s |y_s - sum_j x_j phi_j(t_s)|^2
**   (y = P - g), then omega_s <- omega_s e_s / sum(omega e), e_s the
**   distance at t_s.
**
** The first step, equal weights on Chebyshev nodes, is Gauss-Chebyshev
** quadrature of the least-squares problem with the Chebyshev weight
** 1 / sqrt(t (1 - t)) (exact for S > n): for k0 = k1 = -1 it is the
** truncated Chebyshev series (Chebyshev economisation, what Eck's method
** does under end constraints), already close to the best.  The
** reweighting then moves the solution to the minimax one on the grid, and
** each step gives a lower bound of the grid's minimax error,
** sqrt(sum_s omega_s e_s^2), so the iteration stops when the best maximum
** found is within 1e-4 of that bound (or after 400 steps).  The nodes are
** 16 (n + 1) (at least 64), so that the maximum between them exceeds the
** maximum on them by a fraction of about (pi / 32)^2 / 2 = 0.5 %.
** The iteration works on the correction of the least-squares solution of
** reduce-l2.c (which is its first candidate: the result is never worse
** on the grid), and its least-squares problems are solved by Householder
** QR.
*/
#include <float.h>
#include <math.h>
#include <string.h>

#include "bpoly-private.h"
#include "core-private.h"
#include "reduce-private.h"

#define LAWSON_STEPS 400
#define LAWSON_GAP 1e-4

/* min |A x - B| with M = [A | B] (rows x (cols + nb), destroyed) into
** X (cols x nb); false when A is (numerically) rank deficient. */
static bool
lsq(double *M, size_t rows, size_t cols, size_t nb, double *v, double *X)
{
    size_t w = cols + nb;
    double big = 0.0;
    for (size_t k = 0; k < cols; k++) {
        double nrm = 0.0, alpha, vv = 0.0;
        for (size_t i = k; i < rows; i++)
            nrm += M[i * w + k] * M[i * w + k];
        nrm = sqrt(nrm);
        big = fmax(big, nrm);
        if (!(nrm > 1e-13 * big))
            return false;
        alpha = M[k * w + k] > 0.0 ? -nrm : nrm;
        for (size_t i = k; i < rows; i++)
            v[i] = M[i * w + k];
        v[k] -= alpha;
        for (size_t i = k; i < rows; i++)
            vv += v[i] * v[i];
        /* the reflection I - 2 v v^T / v^T v on the later columns and B */
        for (size_t j = k + 1; j < w; j++) {
            double s = 0.0;
            for (size_t i = k; i < rows; i++)
                s += v[i] * M[i * w + j];
            s = 2.0 * s / vv;
            for (size_t i = k; i < rows; i++)
                M[i * w + j] -= s * v[i];
        }
        M[k * w + k] = alpha;
    }
    for (size_t j = 0; j < nb; j++)
        for (size_t k = cols; k-- > 0;) {
            double s = M[k * w + cols + j];
            for (size_t l = k + 1; l < cols; l++)
                s -= M[k * w + l] * X[l * nb + j];
            X[k * nb + j] = s / M[k * w + k];
        }
    return true;
}

cf_status_t
cf__reduce_uniform(const cf__reduce_job_t *j, double *Q)
{
    int n = j->n, m = j->m, d = m - j->k0 - j->k1 - 2;
    size_t h = j->h, mp = (size_t)(m + 1), u = (size_t)(d + 1);
    size_t S = (size_t)(16 * (n + 1)) < 64 ? 64 : (size_t)(16 * (n + 1));
    double *phi, *F, *Y, *A, *X, *Xbest, *om, *e, *v, *g;
    double best, floor = 0.0;

    /* start from the least-squares solution: the iteration then solves
    ** for a correction of it, and an exactly reducible curve (a residual
    ** of rounding size) comes back as exactly as the L2 solution does */
    if (cf__reduce_l2(j, Q) != CF_STATUS_OK)
        return CF_STATUS_NO_MEMORY;
    if (d < 0)
        return CF_STATUS_OK;
    phi = cf__alloc_array(u * mp + S * u + S * (u + h) + S * h +
                              2 * u * h + 3 * S + h,
                          sizeof *phi);
    if (phi == NULL)
        return CF_STATUS_NO_MEMORY;
    F = phi + u * mp;        /* F[s * u + j] = phi_j(t_s) */
    A = F + S * u;           /* [sqrt(om) F | sqrt(om) Y] */
    Y = A + S * (u + h);     /* Y[s * h + c] = (P - Q)(t_s) */
    X = Y + S * h;
    Xbest = X + u * h;
    om = Xbest + u * h;
    e = om + S;
    v = e + S;
    g = v + S;
    if (cf__reduce_phi(m, j->k0, j->k1, phi) != CF_STATUS_OK) {
        cf__free(phi);
        return CF_STATUS_NO_MEMORY;
    }
    for (size_t s = 0; s < S; s++) {
        double t = 0.5 * (1.0 - cos(CF__PI * (2.0 * (double)s + 1.0) /
                                    (2.0 * (double)S)));
        for (size_t jj = 0; jj < u; jj++)
            F[s * u + jj] = cf__bp_eval(phi + jj * mp, m, t);
        cf__bp_curve_derivs(j->P, NULL, h, h, n, t, 0, Y + s * h);
        for (size_t c = 0; c < h; c++)
            floor = fmax(floor, 64.0 * DBL_EPSILON * fabs(Y[s * h + c]));
        cf__bp_curve_derivs(Q, NULL, h, h, m, t, 0, g);
        for (size_t c = 0; c < h; c++)
            Y[s * h + c] -= g[c];
        om[s] = 1.0 / (double)S;
    }
    /* the start, x = 0 (the L2 solution), is the first candidate; a step
    ** must improve on the best by more than rounding (floor: 64 eps times
    ** the curve's size), or it would fit rounding noise with coefficients
    ** far above it */
    memset(Xbest, 0, u * h * sizeof *Xbest);
    best = 0.0;
    for (size_t s = 0; s < S; s++) {
        double d2 = 0.0;
        for (size_t c = 0; c < h; c++)
            d2 += Y[s * h + c] * Y[s * h + c];
        best = fmax(best, sqrt(d2));
    }
    /* an error of rounding size: the L2 solution is the answer */
    for (int step = 0; step < LAWSON_STEPS && best > floor; step++) {
        double E = 0.0, lower = 0.0, sum = 0.0;
        for (size_t s = 0; s < S; s++) {
            double r = sqrt(om[s]);
            for (size_t jj = 0; jj < u; jj++)
                A[s * (u + h) + jj] = r * F[s * u + jj];
            for (size_t c = 0; c < h; c++)
                A[s * (u + h) + u + c] = r * Y[s * h + c];
        }
        if (!lsq(A, S, u, h, v, X))
            break;
        for (size_t s = 0; s < S; s++) {
            double d2 = 0.0;
            for (size_t c = 0; c < h; c++) {
                double r = Y[s * h + c];
                for (size_t jj = 0; jj < u; jj++)
                    r -= X[jj * h + c] * F[s * u + jj];
                d2 += r * r;
            }
            e[s] = sqrt(d2);
            E = fmax(E, e[s]);
            lower += om[s] * d2;
        }
        if (E < best - floor) {
            best = E;
            memcpy(Xbest, X, u * h * sizeof *X);
        }
        if (best <= (1.0 + LAWSON_GAP) * sqrt(lower) || !(E > 0.0))
            break;
        for (size_t s = 0; s < S; s++)
            sum += (om[s] *= e[s]);
        for (size_t s = 0; s < S; s++)
            om[s] /= sum;
    }
    for (size_t jj = 0; jj < u; jj++)
        for (size_t q = 0; q < mp; q++)
            for (size_t c = 0; c < h; c++)
                Q[q * h + c] += Xbest[jj * h + c] * phi[jj * mp + q];
    cf__free(phi);
    return CF_STATUS_OK;
}
