/*
** Small dense and banded linear solvers used by interpolation and
** least-squares approximation (prefix cf__).
**
** Right-hand sides are blocks of `nrhs` columns stored row by row: row i
** of the right-hand side (and of the solution) is rhs[i * nrhs ...
** i * nrhs + nrhs - 1].  With nrhs = dim this is exactly the interleaved
** point layout of curvefig, so one call solves for every coordinate.
**
** Every solver reports a zero (or, relative to the matrix, negligible)
** pivot as CF_STATUS_DEGENERATE and a failed allocation as
** CF_STATUS_NO_MEMORY; the message names the row.  Inputs marked "in/out"
** are overwritten.
*/
#ifndef CURVEFIG_LINSOLVE_PRIVATE_H
#define CURVEFIG_LINSOLVE_PRIVATE_H

#include <stddef.h>

#include "curvefig/core.h"

/*
** Cyclic tridiagonal system (periodic splines):
**     sub[i] x[i-1] + mid[i] x[i] + sup[i] x[i+1] = rhs[i],  i = 0 .. n-1
** where row 0 has sub[0] in column n-1 and row n-1 has sup[n-1] in column
** 0.  rhs (in/out) receives the solution.  Solved by the Sherman-Morrison
** formula around two solves of the tridiagonal part by the Thomas
** algorithm (no pivoting; stable for diagonally dominant or symmetric
** positive definite matrices, which is what the spline systems are).
** n >= 3.
*/
cf_status_t cf__solve_cyclic_tridiagonal(size_t n, const double *sub,
                                         const double *mid,
                                         const double *sup, double *rhs,
                                         size_t nrhs, cf_diag_t *diag);

/*
** Banded matrix with kl sub- and ku super-diagonals, LU-factorised with
** partial pivoting (row interchanges within the band, like LAPACK's
** dgbtrf).  Row i stores columns i - kl .. i + ku + kl (the extra kl
** columns receive the fill-in of the interchanges).
*/
typedef struct cf__band {
    size_t n, kl, ku, width;  /* width = 2 kl + ku + 1 */
    double *a;                /* n * width */
    double *lower;            /* n * kl multipliers of L */
    size_t *pivot;            /* row interchanged with row k at step k */
    int factored;
} cf__band_t;

/* Allocate an n x n band of zeros. */
cf_status_t cf__band_init(cf__band_t *b, size_t n, size_t kl, size_t ku,
                          cf_diag_t *diag);
void cf__band_fini(cf__band_t *b);
/* Set entry (i, j); |j - i| must lie in the band (asserted: misuse). */
void cf__band_set(cf__band_t *b, size_t i, size_t j, double v);
/* LU factorisation in place. */
cf_status_t cf__band_factor(cf__band_t *b, cf_diag_t *diag);
/* Solve with the factorisation; rhs (in/out) is n x nrhs. */
void cf__band_solve(const cf__band_t *b, double *rhs, size_t nrhs);

/*
** Banded least squares by Givens rotations, one row at a time (for
** B-spline fitting: every row has at most w consecutive nonzeros).  The
** triangular factor R (upper bandwidth w - 1) and Q^T b are accumulated
** in O(n w) memory; each row costs O(w (w + nrhs)).  Rows must be added
** with non-decreasing first columns (asserted), so R never gets entries
** beyond the band.
*/
typedef struct cf__lsq_band {
    size_t n, w, nrhs;
    double *R;      /* n * w: R[i * w + d] is entry (i, i + d) */
    double *qb;     /* n * nrhs: the top n rows of Q^T b */
    double *row;    /* w + nrhs scratch */
    size_t last_first;
    double scale;   /* largest |entry| added, for the rank test */
} cf__lsq_band_t;

cf_status_t cf__lsq_band_init(cf__lsq_band_t *b, size_t n, size_t w,
                              size_t nrhs, cf_diag_t *diag);
void cf__lsq_band_fini(cf__lsq_band_t *b);
/* Add the row with values v[0..w-1] in columns first .. first + w - 1
** (columns >= n must hold 0) and right-hand side rhs[nrhs]. */
void cf__lsq_band_add(cf__lsq_band_t *b, size_t first, const double *v,
                      const double *rhs);
/* x[n * nrhs] by back substitution; DEGENERATE when a diagonal entry of R
** is negligible (the columns are dependent, naming the column; x is then
** partly written). */
cf_status_t cf__lsq_band_solve(const cf__lsq_band_t *b, double *x,
                               cf_diag_t *diag);

#endif
