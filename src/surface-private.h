/*
** Internals of the surface modules (surface-*.c): the object layouts and
** the helpers they share.
*/
#ifndef CURVEFIG_SURFACE_PRIVATE_H
#define CURVEFIG_SURFACE_PRIVATE_H

#include <stdbool.h>
#include <stddef.h>

#include "core-private.h"
#include "domain-private.h"
#include "curvefig/surface.h"

/* One allocation: header, then the grid of (m + 1)(n + 1) hdim doubles,
** row i (along u) after row. */
struct cf_bezier_surface {
    size_t dim, hdim;  /* Cartesian N; stored doubles per point */
    int m, n;          /* degrees in u and v */
    bool rational;
    double pts[];
};

/* One allocation: header, U[nU], V[nV], the grid P[nu * nv * hdim]. */
struct cf_bspline_surface {
    size_t dim, hdim;
    int p, q;
    bool rational;
    size_t nu, nv, nU, nV;
    double ua, ub, va, vb;   /* the domain */
    double *U, *V, *P;
};

/* Surfaces with uninitialised contents, or NULL (out of memory, sizes
** overflow).  cf__bsurf_finish sets the domain from U and V. */
cf_bezier_surface_t *cf__bsurf_bezier_new(size_t dim, int m, int n,
                                          bool rational);
cf_bspline_surface_t *cf__bsurf_new(size_t dim, bool rational, int p, int q,
                                    size_t nu, size_t nv);
void cf__bsurf_finish(cf_bspline_surface_t *s);

/* The grid of nu x nv points (dim doubles each, row after row) and
** optional weights into hpts (hdim = dim + (weights != NULL)), checking
** them with messages naming P[i][j] / W[i][j]. */
cf_status_t cf__surf_fill(size_t dim, const double *points,
                          const double *weights, size_t nu, size_t nv,
                          double *hpts, cf_diag_t *diag);
/* The same check of a homogeneous grid (finite, weights > 0). */
cf_status_t cf__surf_check_h(size_t dim, const double *hpts, size_t nu,
                             size_t nv, cf_diag_t *diag);

/* dst[j][i] = src[i][j] for a nu x nv grid of blocks of h doubles. */
void cf__surf_transpose(const double *src, size_t nu, size_t nv, size_t h,
                        double *dst);

/* Cartesian points / weights of a stored grid of cnt points. */
void cf__surf_points(const double *hpts, size_t cnt, size_t dim,
                     bool rational, double *out);
void cf__surf_weights(const double *hpts, size_t cnt, size_t dim,
                      bool rational, double *out);

/* A parameter of direction dir ("u", "v") by the domain rule, with the
** message naming it. */
cf_status_t cf__surf_param(double a, double b, double *x, cf_dir_t dir,
                           cf_diag_t *diag);

/* The Cartesian derivatives S_{u^a v^b}, a + b <= k, from the homogeneous
** ones A (layout (a (k + 1) + b) hdim, the weight derivative last) by the
** quotient rule (A4.4); out in the same layout with dim doubles per entry,
** entries a + b > k zeroed.  Polynomial (hdim == dim): a copy. */
void cf__surf_rational_derivs(const double *A, size_t dim, size_t hdim,
                              int k, double *out);

/* The point sum_i sum_j Nu[i] Nv[j] P[i][j] of the active sub-grid P
** (pu rows of qv points, h doubles each, rows `stride` doubles apart),
** Cartesian (divided by the weight sum when h > dim) into out[dim]; no
** allocation. */
void cf__surf_tensor_point(const double *P, size_t stride, size_t h,
                           size_t dim, const double *Nu, size_t pu,
                           const double *Nv, size_t qv, double *out);
/* The homogeneous derivatives A_{ab} (a + b < K, layout (a K + b) h) of
** that sub-grid from the basis derivative tables Nu[a pu + i],
** Nv[b qv + j]; R is scratch of qv h doubles. */
void cf__surf_tensor_derivs(const double *P, size_t stride, size_t h,
                            const double *Nu, size_t pu, const double *Nv,
                            size_t qv, size_t K, double *R, double *A);

/* Normal and curvatures from the derivatives up to order 2 in the layout
** above (k = 2, dim = 3). */
cf_status_t cf__surf_normal(const double *D, double *out);
cf_status_t cf__surf_curvature(const double *D, double *gauss,
                               double *mean);

#endif
