/*
** Internals shared by knots.c, bspline.c and bspline-ops.c.
*/
#ifndef CURVEFIG_BSPLINE_PRIVATE_H
#define CURVEFIG_BSPLINE_PRIVATE_H

#include <stdatomic.h>
#include <stdint.h>

#include "core-private.h"
#include "curvefig/bspline.h"

/*
** The curve, in one block: header, knots U[nknots], points P[count * hdim],
** reciprocals rk[p * nknots] and the span grid grid[ngrid].
**   rk[(j - 1) * nknots + a] = 1 / (U[a + j] - U[a]) (0 when they are
**   equal), j = 1..p, a + j < nknots: every denominator of the triangular
**   scheme and of the derivative recursion.
**   Cells: g = clamp((long)((u - a) * ginv), 0, ngrid - 1), monotone in u.
**   splitok (every cell holds at most one interior break point, all of
**   multiplicity 1): grid[g] is the span just below the cell's break point
**   gsplit[g] (+inf if none) and the span is grid[g] + (u >= gsplit[g]),
**   exact.  Otherwise grid[g] is the span of a + (g - 1/2) h (a span with
**   U[k] <= u for every u of cells g - 1 .. g), and a branch-free bisection
**   of gsteps steps from there finds the span.
** The accelerators (rk, grid, ginv, gsteps) are filled lazily by the first
** batch evaluation (their memory is part of the block, so nothing is
** allocated then): accel goes 0 -> 1 (one thread builds) -> 2 (ready,
** published with release order); a thread that finds 1 evaluates without
** them.  Constructions that never evaluate in batches never pay for them.
*/
struct cf_bspline {
    size_t dim;        /* Cartesian N */
    size_t hdim;       /* stored doubles per point: N + rational */
    int p;
    bool rational;
    size_t count;      /* n + 1 */
    size_t nknots;     /* n + p + 2 */
    size_t first_span; /* first non-empty span of the domain */
    size_t last_span;  /* last non-empty span of the domain */
    double a, b;       /* domain */
    double *U;
    double *P;
    double *rk;
    uint32_t *grid;
    double *gsplit;    /* ngrid: the break point in cell g, +inf if none */
    bool splitok;      /* the exact one-break-point cells are in use */
    size_t ngrid;
    double ginv;       /* ngrid / (b - a) */
    int gsteps;
    atomic_int accel;  /* 0 none, 1 being built, 2 ready */
};

/* Allocate a curve with room for the given sizes; U and P are to be filled
** by the caller, then cf__bspline_finish computes the domain and spans.
** Returns NULL when out of memory (or the sizes overflow). */
cf_bspline_t *cf__bspline_alloc(size_t dim, bool rational, int p,
                                size_t count);
void cf__bspline_finish(cf_bspline_t *c);

/* Make sure the accelerators are there; false when another thread is
** building them right now (then evaluate without them). */
bool cf__bspline_accel(const cf_bspline_t *c);

/* Unchecked span search on a curve (the conventions of
** cf_knots_find_span). */
size_t cf__bspline_span(const cf_bspline_t *c, double u);

/* Check u is finite and inside the domain. */
cf_status_t cf__bspline_check_param(const cf_bspline_t *c, double u,
                                    cf_diag_t *diag);

/*
** The d-th derivatives (d >= 0) of the nonzero basis functions on span k
** (U[k] <= u < U[k+1] or the last span at the end): v[j] =
** N_{k-p+j}^{p (d)}(u), j = 0..p.  rk may be NULL (then it divides).
*/
void cf__basis_deriv(int p, const double *U, size_t nknots, const double *rk,
                     size_t k, double u, int d, double *v);

/* Unchecked: the multiplicity of u in U (a sorted vector). */
/* Knots U[0..n-1] finite and non-decreasing; the one check and wording
** ("knot 4 (0.30) is smaller than knot 3 (0.50)", `what` naming the
** array: "knot", "new knot"), with as many digits as tell the two apart.
** NOT_FINITE or BAD_KNOTS with the index. */
cf_status_t cf__check_knot_order(const double *U, size_t n, const char *what,
                                 cf_diag_t *diag);

int cf__knots_mult(const double *U, size_t nknots, double u);

#endif
