/*
** Internals shared by knots.c, bspline.c and bspline-ops.c.
*/
#ifndef CURVEFIG_BSPLINE_PRIVATE_H
#define CURVEFIG_BSPLINE_PRIVATE_H

#include <stdatomic.h>
#include <stdint.h>

#include "core-private.h"
#include "domain-private.h"
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

/* Largest count of control points and dimension (the span grid stores
** 32-bit spans). */
#define CF__BSPLINE_MAX_COUNT ((size_t)1 << 30)

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
static inline size_t
cf__bspline_span(const cf_bspline_t *c, double u)
{
    return cf_knots_find_span(c->p, c->U, c->nknots, u);
}

/* Check u is finite and inside the domain (constructions: knot insertion,
** split, segment). */
cf_status_t cf__bspline_check_param(const cf_bspline_t *c, double u,
                                    cf_diag_t *diag);

/* An evaluator's parameter *u by the domain rule on the curve's domain
** (domain-private.h; clamped to an end it misses by rounding). */
CF__INLINE cf_status_t
cf__bspline_param(const cf_bspline_t *c, double *u)
{
    return cf__param_clamp(c->a, c->b, u);
}

/* ---- the span search and the basis, inlined into the evaluators ---- */

/* The grid cell of u (the same expression at build and query time). */
CF__INLINE size_t
cf__bspline_cell(const cf_bspline_t *c, double u)
{
    long G = (long)c->ngrid;
    /* a signed conversion (cvttsd2si) and clamps, no branches */
    long g = (long)((u - c->a) * c->ginv);
    g = g < 0 ? 0 : g;
    g = g < G - 1 ? g : G - 1;
    return (size_t)g;
}

/* Branch-free span search through the grid (the conventions of
** cf_knots_find_span for u in the domain). */
/* With one break point per cell at most: the span below the cell's break
** point, plus one when u has reached it; two independent loads, exact
** (see build_accel). */
CF__INLINE size_t
cf__bspline_split_span(const cf_bspline_t *c, double u)
{
    size_t g = cf__bspline_cell(c, u);
    return c->grid[g] + (size_t)(u >= c->gsplit[g]);
}

CF__INLINE size_t
cf__bspline_grid_span(const cf_bspline_t *c, double u)
{
    const double *U = c->U;
    size_t last = c->last_span, k, s;
    long G = (long)c->ngrid, g;
    if (c->splitok)
        return cf__bspline_split_span(c, u);
    /* a signed conversion (cvttsd2si) and clamps, no branches */
    g = (long)((u - c->a) * c->ginv);
    g = g < 0 ? 0 : g;
    g = g < G - 1 ? g : G - 1;
    k = c->grid[g];
    for (s = ((size_t)1 << c->gsteps) >> 1; s != 0; s >>= 1) {
        size_t t = k + s, m;
        t = t < last ? t : last;
        /* all ones when U[t] <= u: a select without a branch */
        m = (size_t)0 - (size_t)(U[t] <= u);
        k = (t & m) | (k & ~m);
    }
    return k;
}

/* The nonzero basis functions on span k with the precomputed reciprocals
** (the triangular scheme, A2.2). */
CF__INLINE void
cf__bspline_basis_rk(const double *U, const double *rk, size_t nk, size_t k,
                     int p, double u, double *N)
{
    double left[CF_BSPLINE_MAX_DEGREE + 1], right[CF_BSPLINE_MAX_DEGREE + 1];
    N[0] = 1.0;
    for (int j = 1; j <= p; j++) {
        const double *r = rk + (size_t)(j - 1) * nk + (k + 1 - (size_t)j);
        double saved = 0.0;
        left[j] = u - U[k + 1 - (size_t)j];
        right[j] = U[k + (size_t)j] - u;
        for (int q = 0; q < j; q++) {
            double t = N[q] * r[q];
            N[q] = saved + right[q + 1] * t;
            saved = left[j - q] * t;
        }
        N[j] = saved;
    }
}

/* Span of u: keep k (sorted runs), step to the next span, or search. */
CF__INLINE size_t
cf__bspline_next_span(const cf_bspline_t *c, size_t k, double u, bool ready)
{
    const double *U = c->U;
    if ((u >= U[k]) & (u < U[k + 1]))
        return k;
    return ready ? cf__bspline_grid_span(c, u) : cf__bspline_span(c, u);
}

/* The planar polynomial cubic batch path: points (deriv 0) or first
** derivatives (deriv 1) at n parameters in the domain. */
cf_status_t cf__bspline_eval_cubic2(const cf_bspline_t *c, const double *u,
                                    size_t n, double *out, int deriv);

/* Highest derivative order of cf_bspline_eval_deriv_many for a NURBS
** (the quotient rule keeps all lower orders of one coordinate on the
** stack). */
#define CF__BSPLINE_MAX_RATIONAL_DERIV 128

/* The k-th derivatives (k >= 0; k <= CF__BSPLINE_MAX_RATIONAL_DERIV when
** rational) at u[0..n-1] into out[n * dim], one parameter at a time by the
** basis derivatives (rk: the reciprocals, or NULL).  DOMAIN / NOT_FINITE
** for a parameter outside the domain. */
cf_status_t cf__bspline_derivs_general(const cf_bspline_t *c, int k,
                                       const double *rk, const double *u,
                                       size_t n, double *out);

/*
** The d-th derivatives (d >= 0) of the nonzero basis functions on span k
** (U[k] <= u < U[k+1] or the last span at the end): v[j] =
** N_{k-p+j}^{p (d)}(u), j = 0..p.  rk may be NULL (then it divides).
*/
void cf__basis_deriv(int p, const double *U, size_t nknots, const double *rk,
                     size_t k, double u, int d, double *v);

/* Knots U[0..n-1] finite and non-decreasing; the one check and wording
** ("knot 4 (0.30) is smaller than knot 3 (0.50)", `what` naming the
** array: "knot", "new knot"), with as many digits as tell the two apart.
** NOT_FINITE or BAD_KNOTS with the index. */
cf_status_t cf__check_knot_order(const double *U, size_t n, const char *what,
                                 cf_diag_t *diag);

/* Unchecked: the multiplicity of u in U (a sorted vector). */
int cf__knots_mult(const double *U, size_t nknots, double u);

/* ---- shared by the constructions (bspline-ops.c, bspline-knot-ops.c) - */

/* NO_MEMORY with the one message of the constructions. */
cf_status_t cf__bspline_no_memory(cf_diag_t *diag);
/* *out = NULL; INVALID_ARG when c or out is NULL. */
cf_status_t cf__bspline_check_in(const cf_bspline_t *c, cf_bspline_t **out,
                                 cf_diag_t *diag);

/* dst = (1 - a) x + a y over hdim doubles. */
CF__INLINE void
cf__bspline_lerp(double *dst, const double *x, const double *y, double a,
                 size_t hd)
{
    for (size_t d = 0; d < hd; d++)
        dst[d] = (1.0 - a) * x[d] + a * y[d];
}

#if defined(__GNUC__)
/* Pairs of doubles (GCC's and clang's vector extension) for the planar
** kernels of refinement and decomposition: a point (x, y) per register.
** CF__LOAD2 / CF__STORE2 reach a pair anywhere in an array of doubles. */
#define CF__HAVE_PAIRS 1
typedef double cf__v2 __attribute__((vector_size(16)));
typedef long long cf__m2 __attribute__((vector_size(16)));
typedef double cf__u2 __attribute__((vector_size(16), aligned(8),
                                     may_alias));
#define CF__LOAD2(p) ((cf__v2)*(const cf__u2 *)(const void *)(p))
#define CF__STORE2(p, v) (*(cf__u2 *)(void *)(p) = (v))

/* (1 - t) x + t y, as cf__bspline_lerp rounds it. */
CF__INLINE cf__v2
cf__lerp2(cf__v2 x, cf__v2 y, double t)
{
    cf__v2 tv = { t, t }, one = { 1.0, 1.0 };
    return (one - tv) * x + tv * y;
}
#endif

/* dst = src over hdim doubles (a loop: hdim is small, a libc call per
** point costs more than the copy). */
CF__INLINE void
cf__bspline_copy_pt(double *dst, const double *src, size_t hd)
{
    for (size_t d = 0; d < hd; d++)
        dst[d] = src[d];
}

/* Largest index k with U[k] <= u (u >= U[0]). */
CF__INLINE size_t
cf__knots_last_le(const double *U, size_t nk, double u)
{
    size_t lo = 0, hi = nk;   /* U[lo] <= u; answer < hi */
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (U[mid] <= u)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

/* Insert u (a <= u <= b) r times, k the largest index with U[k] <= u and
** s the multiplicity of u (s + r <= p + 1), unchecked; NULL when out of
** memory. */
cf_bspline_t *cf__bspline_insert_raw(const cf_bspline_t *c, double u,
                                     size_t k, int s, int r);

/* The Bézier pieces of a cubic (any knot vector; bspline-cubic-pieces.c):
** piece s (s-th non-empty span of the domain) at Q + s * stride, four
** points of hdim doubles; breaks (may be NULL) the nseg + 1 parameters. */
void cf__bspline_cubic_pieces(const cf_bspline_t *c, double *Q,
                              size_t stride, double *breaks);

#endif
