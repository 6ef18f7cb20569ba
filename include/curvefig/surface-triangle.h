/*
** Triangular Bézier patches (barycentric, degree n) in R^N, polynomial and
** rational.
**
**   T(u, v, w) = sum_{i+j+k=n} n! / (i! j! k!) u^i v^j w^k b_ijk,
**   u, v, w >= 0, u + v + w = 1,
**
** with the corners T(1, 0, 0) = b_n00, T(0, 1, 0) = b_0n0, T(0, 0, 1) =
** b_00n.  A point of the domain is given by (u, v); w = 1 - u - v.
**
** Order of the (n + 1)(n + 2) / 2 control points ("lexicographic"): by i
** from n down to 0, and within each i by j from n - i down to 0:
**   b_n00, b_(n-1)10, b_(n-1)01, b_(n-2)20, b_(n-2)11, b_(n-2)02, ..., b_00n
** so b_ijk is point r (r + 1) / 2 + (r - j) with r = n - i.
**
** Storage and ownership as for the curves (bezier.h): homogeneous (w x, w)
** points for a rational patch, immutable objects.  Parameters: u, v and
** w = 1 - u - v each >= 0, where a miss of at most 8 DBL_EPSILON counts as
** 0 (DOMAIN beyond, NOT_FINITE for NaN and infinities).
*/
#ifndef CURVEFIG_SURFACE_TRIANGLE_H
#define CURVEFIG_SURFACE_TRIANGLE_H

#include "curvefig/bezier.h"
#include "curvefig/core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cf_bezier_triangle cf_bezier_triangle_t;

/* Largest degree of a triangular patch. */
#define CF_BEZIER_TRIANGLE_MAX_DEGREE 64

/* A patch of degree n (0..CF_BEZIER_TRIANGLE_MAX_DEGREE) in R^dim from
** (n + 1)(n + 2) / 2 Cartesian points in the order above; weights NULL
** (polynomial) or as many finite positive weights.  Messages name the
** point by its indices: "point b_211 has coordinate 2 = nan". */
CF_API cf_status_t cf_bezier_triangle_create(size_t dim, int n,
                                             const double *points,
                                             const double *weights,
                                             cf_bezier_triangle_t **out,
                                             cf_diag_t *diag);
CF_API void cf_bezier_triangle_destroy(cf_bezier_triangle_t *t);

CF_API size_t cf_bezier_triangle_dim(const cf_bezier_triangle_t *t);
CF_API int cf_bezier_triangle_degree(const cf_bezier_triangle_t *t);
CF_API bool cf_bezier_triangle_is_rational(const cf_bezier_triangle_t *t);
/* Number of control points, (n + 1)(n + 2) / 2. */
CF_API size_t cf_bezier_triangle_count(const cf_bezier_triangle_t *t);
/* Cartesian points into out[count dim]; weights into out[count]. */
CF_API void cf_bezier_triangle_get_points(const cf_bezier_triangle_t *t,
                                          double *out);
CF_API void cf_bezier_triangle_get_weights(const cf_bezier_triangle_t *t,
                                           double *out);

/* out[dim] = T(u, v, 1 - u - v) by the triangular de Casteljau scheme. */
CF_API cf_status_t cf_bezier_triangle_eval(const cf_bezier_triangle_t *t,
                                           double u, double v, double *out);

/* The whole scheme, Cartesian, level after level: level l (0..n) holds the
** (n - l + 1)(n - l + 2) / 2 points b^l_ijk, i + j + k = n - l, in the
** order above, b^l_ijk = u b^(l-1)_(i+1)jk + v b^(l-1)_i(j+1)k
** + w b^(l-1)_ij(k+1); level n is T(u, v, w).  out needs
** cf_bezier_triangle_decasteljau_size(t) doubles. */
CF_API size_t cf_bezier_triangle_decasteljau_size(
    const cf_bezier_triangle_t *t);
CF_API cf_status_t cf_bezier_triangle_decasteljau(
    const cf_bezier_triangle_t *t, double u, double v, double *out);

/* Directional derivatives along dir[3] = (du, dv, dw) (barycentric, its
** components summing to 0: INVALID_ARG otherwise, within 1e-12 of their
** size): out[(j) dim] = D_dir^j T(u, v), j = 0..k (exact for rational
** patches). */
CF_API cf_status_t cf_bezier_triangle_eval_derivs(
    const cf_bezier_triangle_t *t, const double *dir, double u, double v,
    int k, double *out);

/* Unit normal (dim 3): D_(-1,1,0) T x D_(-1,0,1) T normalised, pointing to
** the side from which b_n00, b_0n0, b_00n turn counter-clockwise. */
CF_API cf_status_t cf_bezier_triangle_normal(const cf_bezier_triangle_t *t,
                                             double u, double v,
                                             double *out);

/* Subdivision at the point p = (u, v, w) inside the domain: out[0] has the
** corners (p, b_0n0, b_00n), out[1] (b_n00, p, b_00n), out[2] (b_n00,
** b_0n0, p); each is the original patch on that sub-triangle (its control
** points are de Casteljau points: b^i_0jk, b^j_i0k, b^k_ij0). */
CF_API cf_status_t cf_bezier_triangle_subdivide(
    const cf_bezier_triangle_t *t, double u, double v,
    cf_bezier_triangle_t *out[3], cf_diag_t *diag);

/* Degree elevation by one: b'_ijk = (i b_(i-1)jk + j b_i(j-1)k
** + k b_ij(k-1)) / (n + 1). */
CF_API cf_status_t cf_bezier_triangle_elevate(const cf_bezier_triangle_t *t,
                                              cf_bezier_triangle_t **out,
                                              cf_diag_t *diag);

/* The boundary curves as Bézier curves of degree n: edge 0 (w = 0) from
** b_n00 to b_0n0, edge 1 (u = 0) from b_0n0 to b_00n, edge 2 (v = 0) from
** b_00n to b_n00. */
CF_API cf_status_t cf_bezier_triangle_boundary(const cf_bezier_triangle_t *t,
                                               int edge, cf_bezier_t **out,
                                               cf_diag_t *diag);

#ifdef __cplusplus
}
#endif

#endif
