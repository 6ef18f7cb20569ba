/*
** Internals of degree reduction (prefix cf__reduce_), shared by the files
** reduce-*.c.  Curves are arrays of homogeneous control points: point i of
** a curve of degree n is P[i * h .. i * h + h - 1], h = dim + rational,
** the weight last when rational.
**
**   reduce-l2.c       the end conditions and the constrained least-squares
**                     solution through Jacobi polynomials
**   reduce-uniform.c  the near-best uniform solution (Chebyshev weight,
**                     Lawson's iteration)
**   reduce-error.c    the certified bound, the measured maximum, the L2
**                     distance
**   reduce-bezier.c   the Bézier API and the one dispatcher the B-spline
**                     file calls
**   reduce-bspline.c  the B-spline API
*/
#ifndef CURVEFIG_REDUCE_PRIVATE_H
#define CURVEFIG_REDUCE_PRIVATE_H

#include <stdbool.h>
#include <stddef.h>

#include "curvefig/reduce.h"

/* The largest degree reduced: the Jacobi coefficients grow like binomials
** of twice the degree, and their alternating sums lose digits beyond. */
#define CF__REDUCE_MAX_DEGREE 40

/* One reduction problem: P of degree n to Q of degree m with C^k0 at
** t = 0 and C^k1 at t = 1 (k0, k1 >= -1, k0 + k1 + 2 <= m + 1). */
typedef struct cf__reduce_job {
    const double *P;
    int n, m, k0, k1;
    size_t h;
} cf__reduce_job_t;

/* Q[0..k0] and Q[m-k1..m]: the points of degree m whose derivatives of
** order <= k at the end equal those of P (the other points untouched). */
void cf__reduce_ends(const cf__reduce_job_t *j, double *Q);

/* The free points' space, span{B_i^m : k0 < i < m - k1}, has the basis
** phi_j = t^(k0+1) (1-t)^(k1+1) J_j(2t - 1), j = 0 .. m - k0 - k1 - 2,
** J_j the Jacobi polynomial P_j^(2k1+2, 2k0+2), orthogonal in L2[0, 1]:
** phi[j * (m + 1) + i] receives its Bernstein coefficients of degree m.
** NO_MEMORY only. */
cf_status_t cf__reduce_phi(int m, int k0, int k1, double *phi);

/* The integral over [0, 1] of B_p^a B_q^b (in long double). */
long double cf__reduce_gram(int a, int p, int b, int q);

/* The least-squares solution: Q (m + 1 points) keeps the ends and is the
** L2-nearest to P among such curves.  NO_MEMORY only. */
cf_status_t cf__reduce_l2(const cf__reduce_job_t *j, double *Q);

/* The near-best uniform solution into Q.  NO_MEMORY only. */
cf_status_t cf__reduce_uniform(const cf__reduce_job_t *j, double *Q);

/* The solution by method into Q, with the errors of the pair in *rep
** (max_error, bound, l2_error; may be NULL).  dim: the Cartesian
** dimension (h - 1 when rational).  DEGENERATE (index: the point) when a
** weight of Q is not positive or a coordinate not finite. */
cf_status_t cf__reduce_solve(const cf__reduce_job_t *j, size_t dim,
                             bool rational, cf_reduce_method_t method,
                             double *Q, cf_reduce_report_t *rep,
                             cf_diag_t *diag);

/* The checks of by (1 .. degree - least) and the method; what names the
** curve ("curve", "B-spline") in the messages. */
cf_status_t cf__reduce_check_degree(const char *what, int degree, int by,
                                    int least, cf_reduce_method_t method,
                                    cf_diag_t *diag);

/* Certified bounds of max |P(t) - Q(t)| (Cartesian, rational quotient
** when rational; the weights must be positive): *polygon (may be NULL)
** from the control points of the difference, *bound refined by halving
** it (reduce-error.c), unless the polygon bound is already <= enough
** (then *bound is the polygon bound).  NO_MEMORY only. */
cf_status_t cf__reduce_bound(const double *P, int n, const double *Q, int m,
                             size_t dim, bool rational, double enough,
                             double *bound, double *polygon);

/* max |P(t) - Q(t)| measured at 64 (n + 1) + 1 parameters, each local
** maximum refined by golden-section search. */
double cf__reduce_measure(const double *P, int n, const double *Q, int m,
                          size_t dim, bool rational);

/* sqrt of the integral of |P - Q|^2 (homogeneous coordinates).
** NO_MEMORY only. */
cf_status_t cf__reduce_l2_distance(const double *P, int n, const double *Q,
                                   int m, size_t h, double *out);

#endif
