/*
** Internals of the 3D visibility modules (view.c, scene*.c, vis-*.c):
** patches of a scene, their evaluation and subdivision, the box tree.
**
** View space.  Every patch is kept twice, as a net of 4-homogeneous points:
** in space (w x, w y, w z, w) and in view space (X, Y, Z, W) = M (w p, w),
** where x = X / W, y = Y / W is the image and zeta = Z / W a depth that
** grows towards the viewer: d . p for an orthographic view, D z / (D - z)
** (z = d . (p - T)) for a perspective one, which makes the perspective map
** projective, so lines of sight are the lines of constant image in view
** space and a patch in view space is again a rational Bézier patch.
*/
#ifndef CURVEFIG_VIS_PRIVATE_H
#define CURVEFIG_VIS_PRIVATE_H

#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "core-private.h"
#include "curvefig/visibility.h"

/* Arithmetic kernels with no branch of their own worth a fuzzer's
** attention (patch evaluation, halving, the box tree's build): left out of
** clang's coverage
** instrumentation, whose comparison tracing of their loop counters took
** half of fuzz_visibility's time. */
#if defined(__clang__)
#define CF__NO_COVERAGE __attribute__((no_sanitize("coverage")))
#else
#define CF__NO_COVERAGE
#endif

/* Largest degrees a scene accepts (per direction of a tensor patch, and of
** a triangular patch): the evaluators work on the stack. */
#define CF__VIS_MAX_DEG 32
#define CF__VIS_TRI_MAX_DEG 24

/*
** hypot(x, y) against r, with hypot's answer: decided by x^2 + y^2
** against r^2 where these are normal numbers more than 1e-12 apart
** relatively (their rounding, a few units in the last place, cannot turn
** the answer there), by hypot elsewhere.  The hot loops' norms:
** cf__hypot_le is hypot(x, y) <= r, cf__hypot_gt is hypot(x, y) > r (the
** two differ where hypot is a NaN).  cf__hypot_sign: -1 where hypot is
** below r, 1 where above, 0 where the squares cannot tell.
*/
CF__INLINE int
cf__hypot_sign(double x, double y, double r)
{
    double q = x * x + y * y, r2 = r * r;
    if (q > 1e-280 && q < 1e280 && r2 > 1e-280 && r2 < 1e280) {
        if (q < r2 * (1.0 - 1e-12))
            return -1;
        if (q > r2 * (1.0 + 1e-12))
            return 1;
    }
    return 0;
}

CF__INLINE bool
cf__hypot_le(double x, double y, double r)
{
    int c = cf__hypot_sign(x, y, r);
    return c != 0 ? c < 0 : hypot(x, y) <= r;
}

CF__INLINE bool
cf__hypot_gt(double x, double y, double r)
{
    int c = cf__hypot_sign(x, y, r);
    return c != 0 ? c > 0 : hypot(x, y) > r;
}

/* The length of (x, y) for measures that steer the subdivision (a net's
** polygon and its chords): sqrt of the sum of squares, within an ulp of
** hypot, where neither square can overflow or underflow, hypot elsewhere
** (glibc's hypot was a tenth of a heavy view's instructions). */
CF__INLINE double
cf__norm2(double x, double y)
{
    double q = x * x + y * y;
    if (q > 1e-280 && q < 1e280)
        return sqrt(q);
    return hypot(x, y);
}

/* The part [a, b] (0 <= a < b, b > 0) of a curve of degree d in place,
** its points 4-homogeneous and `stride` doubles apart: de Casteljau at b
** keeping [0, b], then at a / b keeping the end (a curve piece's net,
** vis-curve.c; a leaf's, vis-clear.c). */
CF__INLINE void
cf__hcurve_part(double *x, int d, size_t stride, double a, double b)
{
    for (int r = 1; r <= d; r++)
        for (int i = d; i >= r; i--)
            for (int e = 0; e < 4; e++)
                x[(size_t)i * stride + e] =
                    (1 - b) * x[(size_t)(i - 1) * stride + e] +
                    b * x[(size_t)i * stride + e];
    double c = a / b;
    for (int r = 1; r <= d; r++)
        for (int i = 0; i <= d - r; i++)
            for (int e = 0; e < 4; e++)
                x[(size_t)i * stride + e] =
                    (1 - c) * x[(size_t)i * stride + e] +
                    c * x[(size_t)(i + 1) * stride + e];
}

/* The 4 x 4 matrix M of a view (row-major). */
void cf__view_matrix(const cf_view_t *view, double M[16]);

/* One Bézier patch of a scene. */
typedef struct cf__vpatch {
    size_t surface;     /* number of its surface */
    bool tri;           /* triangular patch of degree n (m == n) */
    int m, n;           /* degrees in s and t */
    double u0, u1;      /* the patch is [u0, u1] x [v0, v1] of its */
    double v0, v1;      /* surface (tensor; triangles: 0 1 0 1) */
    double *h;          /* space net, 4 doubles a point */
    double *g;          /* view-space net */
} cf__vpatch_t;

size_t cf__vpatch_count(const cf__vpatch_t *p);

/*
** Cartesian point and derivatives of a 4-homogeneous net of the patch's
** shape at local (s, t) ([0, 1]^2, or barycentric u = s, v = t, w = 1 - s
** - t): out[0..2] the point, out[3..5] d/ds, out[6..8] d/dt and with k == 2
** out[9..11] d2/ds2, out[12..14] d2/dsdt, out[15..17] d2/dt2 (for a
** triangle d/ds is along (1, 0, -1), d/dt along (0, 1, -1)); with k == 0
** only out[0..2].  false where the weight is not positive.
*/
bool cf__vpatch_eval(const cf__vpatch_t *p, const double *net, double s,
                     double t, int k, double *out);

/* Halves of a tensor net of degrees (m, n) (4-homogeneous), in s (dir 0)
** or t (dir 1) at 1/2: lo and hi each (m + 1)(n + 1) 4 doubles. */
void cf__vnet_split(const double *net, int m, int n, int dir, double *lo,
                    double *hi);
/* Halves of a triangular net of degree n at the middle of its edge from
** corner a to corner b (0: b_n00, 1: b_0n0, 2: b_00n): one keeps corner a,
** the other b; each lists its corners' order in perm (new corner i is old
** corner perm[i], or 3 for the edge's middle). */
void cf__vtri_split(const double *net, int n, int a, int b, double *lo,
                    int perm_lo[3], double *hi, int perm_hi[3]);

/* Measures of a net of the patch's shape (4-homogeneous; c receives its
** Cartesian points, 3 doubles each): box, image (first two coordinates)
** and full diameters, weight ratio, distance from the bilinear (linear)
** map of its corners, a quarter of the corners' twist (tensor), whether
** its cells turn both ways in the image, extents along s and t. */
typedef struct cf__vmeasure {
    double lo[3], hi[3];
    double diam, img;
    double wratio, dev, twist;
    bool fold;
    int orient;     /* +1 or -1: every cell turns that way in the image;
                       0: it folds or is flat */
    double ext[2];
} cf__vmeasure_t;

void cf__vnet_measure(const cf__vpatch_t *p, const double *net, double *c,
                      cf__vmeasure_t *ms);

/* A piece of a patch in the box tree: its parameter region (tensor:
** r = s0 s1 t0 t1; triangle: three corners (u v) of the patch), the box of
** its view-space net, whether its image may fold, and which way its cells
** turn (the measure's orient). */
typedef struct cf__vleaf {
    uint32_t patch;
    bool fold;
    int8_t orient;
    double r[6];
    double lo[3], hi[3];
    /* two unit normals of its sides in the image (tensor: of its s and t
    ** edges; triangle: of two edges) and the range of its control points
    ** along each, widened by a bound of how far outside them Newton's
    ** point may land and still count as in the piece: no point whose
    ** image lies outside a range can be found on the piece
    ** (cf__leaf_may_hold) */
    float hn[2][2];         /* floats: the ranges are rounded outwards */
    float hlo[2], hhi[2];
} cf__vleaf_t;

/* Whether the image point x[2] may be the image of a point of leaf l as
** Newton finds it (cf__vpatch_locate within 1e-9 scale, in the leaf's
** region within its slack): the leaf's box and its two side ranges, the
** latter widened by 1e-8 scale (scale: the scene's size).  Every piece
** lies in the hull of its control points (positive weights), so a point
** outside is on no piece. */
CF__INLINE bool
cf__leaf_may_hold(const cf__vleaf_t *l, const double *x, double scale)
{
    double e = 1e-8 * scale;
    for (int k = 0; k < 2; k++) {
        double d = (double)l->hn[k][0] * x[0] + (double)l->hn[k][1] * x[1];
        if (d < (double)l->hlo[k] - e || d > (double)l->hhi[k] + e)
            return false;
    }
    return true;
}

/*
** Whether leaf l holds no point that Newton (cf__vpatch_locate, its point
** within 1e-9 of the scene's size of the image q[2], in the leaf's region
** within its slack) could find and, with depth, none whose depth exceeds
** zmin either: then no run of Newton on the leaf finds a point that
** counts, and cf__scene_hidden leaves out a folding leaf's starts when
** its first one has not converged within a few steps (with depth, only
** where what Newton found would not matter either: the leaf's points are
** not all in front).  Proved by halving the leaf's view-space net (its region
** widened by the slack) until every piece's hull misses q, or lies behind
** zmin, widened for the rounding; false when that takes more than a few
** dozen pieces, for a triangle and for degrees above 3.
*/
bool cf__leaf_clear(const cf_scene_t *sc, const cf__vleaf_t *l,
                    const double *q, double zmin, bool depth);

typedef struct cf__vnode {
    double lo[3], hi[3];
    uint32_t first, count;  /* leaves (count > 0) or children first, first+1 */
} cf__vnode_t;

struct cf_scene {
    cf_view_t view;
    double M[16];
    double tol;
    size_t nsurf;
    size_t *surf_first;     /* first patch of each surface, nsurf + 1 */
    bool *surf_tri;
    size_t nsurf_cap;
    cf__vpatch_t *patches;
    size_t npatch, npatch_cap;
    cf__vleaf_t *leaves;
    size_t nleaf, nleaf_cap;
    cf__vnode_t *nodes;
    size_t nnode;
    double lo[3], hi[3];    /* box of every control point, space */
    double size;            /* its diagonal */
    bool newton_all;        /* tests: no leaf left out by cf__leaf_clear */
};

/* Pieces of patch ip into the scene's leaves (scene-tree.c). */
cf_status_t cf__scene_leaves(cf_scene_t *sc, size_t ip);
/* The box tree over all leaves, rebuilt. */
cf_status_t cf__scene_tree(cf_scene_t *sc);

/* Newton for the point of patch ip whose image is img[2], from local
** (s, t); true with the local parameters and the view-space point in
** st[2], q[3] when it converges. */
bool cf__vpatch_locate(const cf_scene_t *sc, size_t ip, const double *img,
                       double s, double t, double *st, double *q);

/* Where the point p (view space q) lies, for self-occlusion: surface and
** (u, v) on it, or has == false. */
typedef struct cf__vself {
    bool has;
    size_t surface;
    double uv[2];
    double offset;
} cf__vself_t;

/* Whether view-space point q is hidden; *occ gets the surface. */
bool cf__scene_hidden(const cf_scene_t *sc, const double *q,
                      const cf__vself_t *self, size_t *occ);

/* Whether no leaf's view-space box meets the view-space box lo[3], hi[3]
** in the image with any depth more than the depth margin in front of
** lo[2]: nothing there can hide a point of the box. */
bool cf__scene_box_clear(const cf_scene_t *sc, const double *lo,
                         const double *hi);

/*
** As cf__scene_box_clear, for the part of a curve that lies on surface
** `surface` with its (u, v) in the box uv[4] = u0 u1 v0 v1: the pieces of
** that surface whose parameters meet the box (the pieces that hold the
** part's points and their neighbours across the box) are not counted
** when they hide nothing of it.  strict: each of them must not fold and
** all must turn the same way in the image (so that surface is one-to-one
** onto its image around the part: no contour crosses it); every other
** piece whose depth reaches the box's must lie behind it.  !strict (a
** curve only near its surface, a silhouette): those pieces are not
** counted at all; the sheet's own fold is left to the samples.  surface
** SIZE_MAX (uv NULL): cf__scene_box_clear.
*/
bool cf__scene_box_clear_on(const cf_scene_t *sc, const double *lo,
                            const double *hi, size_t surface,
                            const double *uv, bool strict);

/* The patch of surface `surface` holding its parameters (u, v), and local
** parameters on it (s, t); false if none. */
bool cf__scene_find(const cf_scene_t *sc, size_t surface, double u, double v,
                    size_t *ip, double *s, double *t);

/* A growing array of facets. */
typedef struct cf__facet_buf {
    cf_facet_t *items;
    size_t n, cap;
} cf__facet_buf_t;

/* The painting order of the facets of fb by a BSP tree (vis-bsp.c):
** facets crossing a plane (beyond eps) are split, the pieces appended to
** fb; *order (cf__free) lists the facets to draw, back first. */
cf_status_t cf__bsp_order(cf__facet_buf_t *fb, const cf_view_t *view,
                          double eps, size_t **order, size_t *norder,
                          size_t *splits);

/* The painting order of the facets of fb below quadratic cost
** (vis-order.c): only facets whose images overlap are compared (a grid of
** their image boxes), by the depths of their planes over the overlap (M:
** the view's matrix); facets that must be painted in a cycle (crossing
** or cyclic overlaps) are ordered among themselves by cf__bsp_order,
** their pieces appended to fb.  *order (cf__free) lists the facets to
** draw, back first. */
cf_status_t cf__facet_order(cf__facet_buf_t *fb, const cf_view_t *view,
                            const double M[16], double eps, size_t **order,
                            size_t *norder, size_t *splits);

/* The view-space point q[3] of the exact contour of surface `surface`
** nearest its parameters uv[2] (Newton on the contour's equation; uv
** itself if that fails or goes far); false if uv is on no patch. */
bool cf__contour_point(const cf_scene_t *sc, size_t surface,
                       const double *uv, double *q);

/* Image (x, y) and depth zeta of a view-space Cartesian point from a
** space point; false at or behind the eye. */
bool cf__view_apply(const double M[16], const double *p, double *q);

#endif
