/*
** Tensor-product Bézier, B-spline and NURBS surfaces in R^N.
**
** A surface is curves of curves.  Its control points form a grid
** P[i][j], i = 0..nu-1 along u, j = 0..nv-1 along v; arrays passed in and
** returned hold them row after row (row i is P[i][0] .. P[i][nv-1]), each
** point `dim` doubles (x y z x y z ...).  Indices in messages count from 0
** ("point P[3][2] has coordinate 1 = nan"); the figure language counts
** from 1, as Lua does.
**
**   Bézier surface of degrees (m, n):   S(u, v) = sum B_i^m(u) B_j^n(v) P_ij
**   B-spline surface of degrees (p, q)  with knot vectors U (along u, nu + p
**   + 1 knots) and V (along v, nv + q + 1 knots):
**                                       S(u, v) = sum N_i^p(u) N_j^q(v) P_ij
**
** Storage.  Like the curves (bezier.h, bspline.h): a polynomial surface
** stores Cartesian points, `dim` doubles each; a rational one stores them
** homogeneously, (w x_1 ... w x_N, w), dim + 1 doubles each; every
** construction runs on these, and division by w happens only when a point
** is returned.  A row of the grid is then a curve's control polygon, and
** the whole grid, read row by row, is a curve in u whose "points" are rows
** of nv homogeneous points: every operation in u (split, knot insertion,
** degree elevation, decomposition) is the curve operation on that curve,
** and every operation in v the same on the transposed grid.
**
** Objects are immutable and owned as in core.h: every operation returns a
** new surface, released with its destroy function (destroy(NULL) is
** harmless).  The evaluators eval and eval_grid never allocate; the others
** (derivatives, nets, normals, curvature) use a work buffer and may return
** CF_STATUS_NO_MEMORY.
**
** Parameters.  The domain is [0, 1] x [0, 1] for a Bézier surface and
** [u_p, u_{m-p}] x [v_q, v_{l-q}] for a B-spline surface.  Each of u, v
** follows the rule of the curves (core.h, "Parameters"): within
** 8 DBL_EPSILON max(|a|, |b|) of an end it is that end, further out is
** CF_STATUS_DOMAIN (the message names u or v), NaN and infinities
** CF_STATUS_NOT_FINITE.  Constructions (split, insert_knot, segment) take
** their parameters exactly.
**
** The constructions (extrusion, ruled, Coons, revolution, sphere, ...,
** interpolation) are in curvefig/surface-make.h.
*/
#ifndef CURVEFIG_SURFACE_H
#define CURVEFIG_SURFACE_H

#include "curvefig/bezier.h"
#include "curvefig/bspline.h"
#include "curvefig/core.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A parameter direction: CF_DIR_U is the first parameter (along i),
** CF_DIR_V the second (along j). */
typedef enum cf_dir {
    CF_DIR_U = 0,
    CF_DIR_V = 1
} cf_dir_t;

typedef struct cf_bezier_surface cf_bezier_surface_t;
typedef struct cf_bspline_surface cf_bspline_surface_t;

/* ==== Tensor-product Bézier surfaces ==================================== */

/*
** A surface of degrees (m, n) >= 0 in R^dim (dim >= 1) from the
** (m + 1) x (n + 1) grid of Cartesian points (row after row).
** weights == NULL makes a polynomial surface; otherwise (m + 1)(n + 1)
** finite positive weights, in the same order, make a rational one.  Each of
** m, n is at most CF_BEZIER_MAX_DEGREE.  A non-finite coordinate or a bad
** weight is named by row and column ("point P[2][1] has coordinate 3 = nan",
** "weight W[0][2] is -1; weights must be finite and positive"); diag->index
** is then the flat index i (n + 1) + j.
*/
CF_API cf_status_t cf_bezier_surface_create(size_t dim, int m, int n,
                                            const double *points,
                                            const double *weights,
                                            cf_bezier_surface_t **out,
                                            cf_diag_t *diag);

/* A rational surface from homogeneous points (w x, w), dim + 1 doubles
** each. */
CF_API cf_status_t cf_bezier_surface_create_homogeneous(
    size_t dim, int m, int n, const double *hpoints,
    cf_bezier_surface_t **out, cf_diag_t *diag);

/* The bilinear patch of four corners P00, P01, P10, P11 (4 * dim doubles,
** in that order): S(u, v) = (1-u)(1-v) P00 + (1-u) v P01 + u (1-v) P10
** + u v P11, a Bézier surface of degrees (1, 1). */
CF_API cf_status_t cf_bezier_surface_bilinear(size_t dim,
                                              const double *corners,
                                              cf_bezier_surface_t **out,
                                              cf_diag_t *diag);

CF_API cf_status_t cf_bezier_surface_copy(const cf_bezier_surface_t *s,
                                          cf_bezier_surface_t **out,
                                          cf_diag_t *diag);
CF_API void cf_bezier_surface_destroy(cf_bezier_surface_t *s);

/* Queries (never fail on a valid surface; 0 / NULL / false on NULL). */
CF_API size_t cf_bezier_surface_dim(const cf_bezier_surface_t *s);
CF_API int cf_bezier_surface_degree_u(const cf_bezier_surface_t *s);
CF_API int cf_bezier_surface_degree_v(const cf_bezier_surface_t *s);
CF_API bool cf_bezier_surface_is_rational(const cf_bezier_surface_t *s);
/* The stored grid: (m + 1)(n + 1) (dim + rational) doubles. */
CF_API const double *cf_bezier_surface_hpoints(const cf_bezier_surface_t *s);
/* Cartesian points into out[(m + 1)(n + 1) dim]; weights into
** out[(m + 1)(n + 1)] (all 1 for a polynomial surface). */
CF_API void cf_bezier_surface_get_points(const cf_bezier_surface_t *s,
                                         double *out);
CF_API void cf_bezier_surface_get_weights(const cf_bezier_surface_t *s,
                                          double *out);

/* out[dim] = S(u, v) (the Bernstein bases of u and v, then one weighted
** sum of the grid; agrees with the de Casteljau scheme to rounding). */
CF_API cf_status_t cf_bezier_surface_eval(const cf_bezier_surface_t *s,
                                          double u, double v, double *out);

/*
** Partial derivatives up to total order k >= 0:
** out[((a (k + 1)) + b) dim ...] = d^(a+b) S / du^a dv^b (u, v) for
** a + b <= k; the entries with a + b > k are set to 0.  out needs
** (k + 1)^2 dim doubles.  Exact for rational surfaces (the quotient rule
** on the homogeneous derivatives, The NURBS Book A4.4).
*/
CF_API cf_status_t cf_bezier_surface_eval_derivs(
    const cf_bezier_surface_t *s, double u, double v, int k, double *out);

/*
** The de Casteljau scheme at (u, v) as data, Cartesian: first, for each
** column j = 0..n, the triangle in u of P[0][j] .. P[m][j] (levels 0..m,
** level l with m + 1 - l points, as cf_bezier_decasteljau), the columns one
** after the other; then the triangle in v of the n + 1 points those
** columns reach (the control polygon of the iso-curve at u), whose last
** level is S(u, v).  Column j starts at point j (m + 1)(m + 2) / 2, the v
** triangle at point (n + 1)(m + 1)(m + 2) / 2.  out needs
** cf_bezier_surface_decasteljau_size(s) doubles.
*/
CF_API size_t cf_bezier_surface_decasteljau_size(
    const cf_bezier_surface_t *s);
CF_API cf_status_t cf_bezier_surface_decasteljau(
    const cf_bezier_surface_t *s, double u, double v, double *out);

/* Unit normal Su x Sv / |Su x Sv| (dim == 3, INVALID_ARG otherwise;
** DEGENERATE where Su x Sv = 0). */
CF_API cf_status_t cf_bezier_surface_normal(const cf_bezier_surface_t *s,
                                            double u, double v, double *out);

/* Gaussian curvature K = (LN - M^2) / (EG - F^2) and mean curvature
** H = (EN - 2FM + GL) / (2 (EG - F^2)) with the second fundamental form
** taken along the normal above (so H changes sign with the orientation);
** dim == 3.  Either output may be NULL. */
CF_API cf_status_t cf_bezier_surface_curvature(const cf_bezier_surface_t *s,
                                               double u, double v,
                                               double *gauss, double *mean);

/* The iso-parametric curve as an exact Bézier curve: dir == CF_DIR_U fixes
** u = value and gives the curve in v (degree n), CF_DIR_V fixes v and gives
** the curve in u (degree m); rational when the surface is.  value follows
** the evaluators' rule. */
CF_API cf_status_t cf_bezier_surface_iso(const cf_bezier_surface_t *s,
                                         cf_dir_t dir, double value,
                                         cf_bezier_t **out, cf_diag_t *diag);

/* Split at value in (0, 1) of the direction: lo is the part before value,
** hi the part after, both reparametrised to [0, 1].  Either may be NULL. */
CF_API cf_status_t cf_bezier_surface_split(const cf_bezier_surface_t *s,
                                           cf_dir_t dir, double value,
                                           cf_bezier_surface_t **lo,
                                           cf_bezier_surface_t **hi,
                                           cf_diag_t *diag);

/* The sub-patch on [u0, u1] x [v0, v1] (0 <= u0 < u1 <= 1, likewise v),
** reparametrised to [0, 1]^2. */
CF_API cf_status_t cf_bezier_surface_segment(const cf_bezier_surface_t *s,
                                             double u0, double u1, double v0,
                                             double v1,
                                             cf_bezier_surface_t **out,
                                             cf_diag_t *diag);

/* Degree elevation by ru >= 0 in u and rv >= 0 in v: the same surface with
** degrees (m + ru, n + rv). */
CF_API cf_status_t cf_bezier_surface_elevate(const cf_bezier_surface_t *s,
                                             int ru, int rv,
                                             cf_bezier_surface_t **out,
                                             cf_diag_t *diag);

/* The box of the Cartesian control points, lo[dim], hi[dim]: it contains
** the surface (convex hull property; the weights are positive). */
CF_API void cf_bezier_surface_bbox(const cf_bezier_surface_t *s, double *lo,
                                   double *hi);

/* A grid of patches (result of cf_bspline_surface_to_beziers): item
** i nv + j covers [u0[i], u1[i]] x [v0[j], v1[j]] of the source. */
typedef struct cf_bezier_surface_list {
    size_t nu, nv;                 /* patches along u and along v */
    cf_bezier_surface_t **items;   /* nu * nv, row after row */
    double *u0, *u1;               /* nu each */
    double *v0, *v1;               /* nv each */
} cf_bezier_surface_list_t;

CF_API void cf_bezier_surface_list_destroy(cf_bezier_surface_list_t *list);

/* ==== B-spline and NURBS surfaces ======================================= */

/*
** A surface of degrees p, q (0..CF_BSPLINE_MAX_DEGREE) with the nu x nv
** grid of Cartesian points, knot vectors U (nU = nu + p + 1 knots) and V
** (nV = nv + q + 1).  Each knot vector is checked like a curve's
** (cf_knots_validate; the message says which: "knots U: knot 4 (0.30) is
** smaller than knot 3 (0.50)", "knots V: 9 knots given, degree 2 with 5
** points needs 8"), so clamped, open and periodic vectors are all
** accepted.  weights == NULL: polynomial; otherwise nu nv finite positive
** weights make a NURBS surface.  Messages name points and weights by row
** and column, as for Bézier surfaces.
*/
CF_API cf_status_t cf_bspline_surface_create(
    size_t dim, int p, int q, const double *U, size_t nU, const double *V,
    size_t nV, const double *points, size_t nu, size_t nv,
    const double *weights, cf_bspline_surface_t **out, cf_diag_t *diag);

/* A NURBS surface from homogeneous points (w x, w), dim + 1 doubles each. */
CF_API cf_status_t cf_bspline_surface_create_homogeneous(
    size_t dim, int p, int q, const double *U, size_t nU, const double *V,
    size_t nV, const double *hpoints, size_t nu, size_t nv,
    cf_bspline_surface_t **out, cf_diag_t *diag);

/* The same surface as a B-spline: knots {0^(m+1), 1^(m+1)} and
** {0^(n+1), 1^(n+1)} (BAD_DEGREE above CF_BSPLINE_MAX_DEGREE). */
CF_API cf_status_t cf_bspline_surface_from_bezier(
    const cf_bezier_surface_t *s, cf_bspline_surface_t **out,
    cf_diag_t *diag);

CF_API cf_status_t cf_bspline_surface_copy(const cf_bspline_surface_t *s,
                                           cf_bspline_surface_t **out,
                                           cf_diag_t *diag);
CF_API void cf_bspline_surface_destroy(cf_bspline_surface_t *s);

/* Queries (never fail on a valid surface; 0 / NULL / false on NULL). */
CF_API size_t cf_bspline_surface_dim(const cf_bspline_surface_t *s);
CF_API int cf_bspline_surface_degree_u(const cf_bspline_surface_t *s);
CF_API int cf_bspline_surface_degree_v(const cf_bspline_surface_t *s);
CF_API size_t cf_bspline_surface_count_u(const cf_bspline_surface_t *s);
CF_API size_t cf_bspline_surface_count_v(const cf_bspline_surface_t *s);
CF_API bool cf_bspline_surface_is_rational(const cf_bspline_surface_t *s);
/* The knot vector of a direction and its length (*n may be NULL). */
CF_API const double *cf_bspline_surface_knots(const cf_bspline_surface_t *s,
                                              cf_dir_t dir, size_t *n);
/* The stored grid: nu nv (dim + rational) doubles. */
CF_API const double *cf_bspline_surface_hpoints(
    const cf_bspline_surface_t *s);
CF_API void cf_bspline_surface_get_points(const cf_bspline_surface_t *s,
                                          double *out);
CF_API void cf_bspline_surface_get_weights(const cf_bspline_surface_t *s,
                                           double *out);
/* The domain [a, b] of a direction (either pointer may be NULL). */
CF_API void cf_bspline_surface_domain(const cf_bspline_surface_t *s,
                                      cf_dir_t dir, double *a, double *b);

/* out[dim] = S(u, v): the nonzero basis functions of u and of v (A2.2),
** then one weighted sum of the (p + 1)(q + 1) active points (A3.5, A4.3). */
CF_API cf_status_t cf_bspline_surface_eval(const cf_bspline_surface_t *s,
                                           double u, double v, double *out);

/*
** Evaluation on the grid of parameters u[0..nu-1] x v[0..nv-1], exploiting
** the tensor structure: the basis functions are computed once per u and
** once per v, and for each u the active rows are combined once.  Point
** (a, b) goes to pts[(a nv + b) dim]; su and sv (either or both may be
** NULL) receive the first partials dS/du and dS/dv in the same layout
** (exact for a NURBS).  Allocates a work buffer (NO_MEMORY); an invalid
** parameter is reported before anything is written.  The arrays u and v
** are given as one: uv holds the nu values of u followed by the nv values
** of v.
*/
CF_API cf_status_t cf_bspline_surface_eval_grid(
    const cf_bspline_surface_t *s, const double *uv, size_t nu, size_t nv,
    double *pts, double *su, double *sv);

/*
** Partial derivatives up to total order k >= 0, in the layout of
** cf_bezier_surface_eval_derivs (out[(a (k + 1) + b) dim] = S_{u^a v^b}).
** The NURBS Book A3.6 on the basis derivatives (A2.3), and for a NURBS
** surface the quotient rule A4.4.  At an interior knot the derivatives are
** those of the patch on the right (right limits), at the right end of a
** domain those of the last patch.
*/
CF_API cf_status_t cf_bspline_surface_eval_derivs(
    const cf_bspline_surface_t *s, double u, double v, int k, double *out);

/*
** The de Boor scheme at (u, v) as data, Cartesian: for each of the q + 1
** active columns j = s_v - q .. s_v (s_v the span of v), the de Boor net in
** u of P[s_u - p][j] .. P[s_u][j] (levels 0..p, level l with p + 1 - l
** points, as cf_bspline_deboor), the columns one after the other; then the
** de Boor net in v of the q + 1 points those columns reach, whose last
** level is S(u, v).  Column c starts at point c (p + 1)(p + 2) / 2, the v
** net at point (q + 1)(p + 1)(p + 2) / 2.  span (may be NULL) receives
** s_u and s_v.  out needs cf_bspline_surface_deboor_size(s) doubles.
*/
CF_API size_t cf_bspline_surface_deboor_size(const cf_bspline_surface_t *s);
CF_API cf_status_t cf_bspline_surface_deboor(const cf_bspline_surface_t *s,
                                             double u, double v, double *out,
                                             size_t span[2]);

/* Unit normal and curvatures, as for Bézier surfaces (dim == 3). */
CF_API cf_status_t cf_bspline_surface_normal(const cf_bspline_surface_t *s,
                                             double u, double v, double *out);
CF_API cf_status_t cf_bspline_surface_curvature(
    const cf_bspline_surface_t *s, double u, double v, double *gauss,
    double *mean);

/* The iso-parametric curve as an exact B-spline (NURBS) curve: CF_DIR_U
** fixes u = value, giving the curve in v with knots V and degree q;
** CF_DIR_V fixes v, giving the curve in u with knots U, degree p. */
CF_API cf_status_t cf_bspline_surface_iso(const cf_bspline_surface_t *s,
                                          cf_dir_t dir, double value,
                                          cf_bspline_t **out,
                                          cf_diag_t *diag);

/* The distinct knots of a direction inside its domain, ends included
** (the parameters of the knot lines: the iso-curves there draw the
** patch boundaries): into out (room for the direction's number of knots),
** their number into *count. */
CF_API cf_status_t cf_bspline_surface_knot_lines(
    const cf_bspline_surface_t *s, cf_dir_t dir, double *out, size_t *count);

/* Insert value into the knot vector of the direction r >= 1 times (A5.3;
** rules and messages of cf_bspline_insert_knot). */
CF_API cf_status_t cf_bspline_surface_insert_knot(
    const cf_bspline_surface_t *s, cf_dir_t dir, double value, int r,
    cf_bspline_surface_t **out, cf_diag_t *diag);

/* Knot refinement in one direction (A5.5): insert the nx knots x[]
** (non-decreasing, inside the domain) at once. */
CF_API cf_status_t cf_bspline_surface_refine(const cf_bspline_surface_t *s,
                                             cf_dir_t dir, const double *x,
                                             size_t nx,
                                             cf_bspline_surface_t **out,
                                             cf_diag_t *diag);

/* Split at value strictly inside the domain of the direction, both parts
** keeping the parameters (as cf_bspline_split).  Either may be NULL. */
CF_API cf_status_t cf_bspline_surface_split(const cf_bspline_surface_t *s,
                                            cf_dir_t dir, double value,
                                            cf_bspline_surface_t **lo,
                                            cf_bspline_surface_t **hi,
                                            cf_diag_t *diag);

/* Degree elevation by ru >= 0 in u and rv >= 0 in v (A5.10 per direction,
** through cf_bspline_elevate: an open direction comes back clamped to its
** domain). */
CF_API cf_status_t cf_bspline_surface_elevate(const cf_bspline_surface_t *s,
                                              int ru, int rv,
                                              cf_bspline_surface_t **out,
                                              cf_diag_t *diag);

/* Decomposition into Bézier patches (A5.7): one patch per pair of
** non-empty spans, each reparametrised to [0, 1]^2, with its parameter
** ranges; free with cf_bezier_surface_list_destroy. */
CF_API cf_status_t cf_bspline_surface_to_beziers(
    const cf_bspline_surface_t *s, cf_bezier_surface_list_t **out,
    cf_diag_t *diag);

#ifdef __cplusplus
}
#endif

#endif
