/* The tests' independent ray caster (raycast-ref.h). */
#include "raycast-ref.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "curvefig/bezier.h"

typedef long double ld;

/* min and max without libm's calls (the subdivision's inner loop) */
static inline ld
lmin(ld a, ld b)
{
    return a < b ? a : b;
}

static inline ld
lmax(ld a, ld b)
{
    return a > b ? a : b;
}

/* Samples of each piece for the starting points of Newton. */
#define GRID 6
/* Tensor pieces (and triangles) up to this degree are subdivided. */
#define SUB_DEG 8

typedef struct rc_patch {
    bool tri;
    int m, n;         /* degrees (triangle: n) */
    ld *h;            /* homogeneous (w x, w y, w z, w) */
    ld lo[3], hi[3];  /* box of the Cartesian control points */
    ld grid[GRID][GRID][3];  /* S at (i + 1/2, j + 1/2) / GRID */
} rc_patch_t;

struct rc_scene {
    cf_view_t view;
    rc_patch_t *p;
    size_t n, cap;
};

rc_scene_t *
rc_create(const cf_view_t *view)
{
    rc_scene_t *rc = calloc(1, sizeof *rc);
    if (rc != NULL)
        rc->view = *view;
    return rc;
}

void
rc_destroy(rc_scene_t *rc)
{
    if (rc == NULL)
        return;
    for (size_t i = 0; i < rc->n; i++)
        free(rc->p[i].h);
    free(rc->p);
    free(rc);
}

static void eval(const struct rc_patch *p, ld u, ld v, ld *out);

static size_t
count(bool tri, int m, int n)
{
    return tri ? (size_t)(n + 1) * (size_t)(n + 2) / 2
               : (size_t)(m + 1) * (size_t)(n + 1);
}

/* A patch from Cartesian points and weights (double). */
static bool
add(rc_scene_t *rc, bool tri, int m, int n, const double *pts,
    const double *w)
{
    size_t cnt = count(tri, m, n);
    rc_patch_t *p;
    if (m > 32 || n > 32 || (tri && n > 24))
        return false;
    if (rc->n == rc->cap) {
        size_t cap = rc->cap ? 2 * rc->cap : 16;
        rc_patch_t *np = realloc(rc->p, cap * sizeof *np);
        if (np == NULL)
            return false;
        rc->p = np;
        rc->cap = cap;
    }
    p = &rc->p[rc->n];
    p->tri = tri;
    p->m = m;
    p->n = n;
    p->h = malloc(cnt * 4 * sizeof(ld));
    if (p->h == NULL)
        return false;
    for (int c = 0; c < 3; c++) {
        p->lo[c] = HUGE_VALL;
        p->hi[c] = -HUGE_VALL;
    }
    for (size_t i = 0; i < cnt; i++) {
        for (int c = 0; c < 3; c++) {
            p->h[4 * i + c] = (ld)pts[3 * i + c] * (ld)w[i];
            p->lo[c] = fminl(p->lo[c], pts[3 * i + c]);
            p->hi[c] = fmaxl(p->hi[c], pts[3 * i + c]);
        }
        p->h[4 * i + 3] = w[i];
    }
    for (int i = 0; i < GRID; i++)
        for (int j = 0; j < GRID; j++) {
            ld u = (i + 0.5L) / GRID, v = (j + 0.5L) / GRID;
            if (tri && u + v > 1) {
                u = u / (u + v + 0.01L);
                v = v / (u + v + 0.01L);
            }
            eval(p, u, v, p->grid[i][j]);
        }
    rc->n++;
    return true;
}

static bool
add_piece(rc_scene_t *rc, const cf_bezier_surface_t *s)
{
    int m = cf_bezier_surface_degree_u(s), n = cf_bezier_surface_degree_v(s);
    size_t cnt = count(false, m, n);
    double *pts = malloc(cnt * 4 * sizeof(double));
    bool ok;
    if (pts == NULL || cf_bezier_surface_dim(s) != 3) {
        free(pts);
        return false;
    }
    cf_bezier_surface_get_points(s, pts);
    cf_bezier_surface_get_weights(s, pts + 3 * cnt);
    ok = add(rc, false, m, n, pts, pts + 3 * cnt);
    free(pts);
    return ok;
}

/* A patch as SPLIT x SPLIT pieces (cf_bezier_surface_segment): their
** boxes are tighter, so fewer are crossed by a line of sight. */
#define SPLIT 2
static bool
add_bez(rc_scene_t *rc, const cf_bezier_surface_t *s)
{
    bool ok = true;
    for (int i = 0; i < SPLIT && ok; i++)
        for (int j = 0; j < SPLIT && ok; j++) {
            cf_bezier_surface_t *seg = NULL;
            ok = cf_bezier_surface_segment(s, (double)i / SPLIT,
                                           (double)(i + 1) / SPLIT,
                                           (double)j / SPLIT,
                                           (double)(j + 1) / SPLIT, &seg,
                                           NULL) == CF_STATUS_OK &&
                 add_piece(rc, seg);
            cf_bezier_surface_destroy(seg);
        }
    return ok;
}

bool
rc_add_bezier(rc_scene_t *rc, const cf_bezier_surface_t *s)
{
    return add_bez(rc, s);
}

bool
rc_add_bspline(rc_scene_t *rc, const cf_bspline_surface_t *s)
{
    cf_bezier_surface_list_t *list = NULL;
    bool ok = true;
    if (cf_bspline_surface_to_beziers(s, &list, NULL) != CF_STATUS_OK)
        return false;
    for (size_t i = 0; i < list->nu * list->nv && ok; i++)
        ok = add_bez(rc, list->items[i]);
    cf_bezier_surface_list_destroy(list);
    return ok;
}

/*
** A triangle of degree n as a tensor patch of degrees (n, n) that folds
** its edge s = 1 into the corner b_n00: u = s, v = (1 - s) t, w = (1 - s)
** (1 - t).  Then u^i v^j w^k = s^i (1 - s)^(n - i) t^j (1 - t)^(n - i - j)
** and the trinomial coefficient is C(n, i) C(n - i, j), so
**     T = sum_i B^n_i(s) sum_j b_(i, j, n - i - j) B^(n - i)_j(t):
** row i of the net is the curve in t of degree n - i whose points are
** b_(i, j, n - i - j), elevated to degree n; homogeneous, so a rational
** patch stays exact.  h: the triangle's homogeneous points in its order
** (b_ijk at r (r + 1) / 2 + (r - j), r = n - i); net: (n + 1)^2 points.
*/
static void
triangle_as_tensor(const ld *h, int n, ld *net)
{
    for (int i = 0; i <= n; i++) {
        ld *row = net + 4 * (size_t)i * (size_t)(n + 1);
        int r = n - i;
        for (int j = 0; j <= r; j++)
            memcpy(row + 4 * j, h + 4 * (r * (r + 1) / 2 + (r - j)),
                   4 * sizeof *row);
        for (int d = r; d < n; d++)       /* degree d -> d + 1 */
            for (int j = d + 1; j >= 0; j--)
                for (int c = 0; c < 4; c++) {
                    ld a = j > 0 ? row[4 * (j - 1) + c] : 0.0L,
                       b = j <= d ? row[4 * j + c] : 0.0L;
                    row[4 * j + c] = ((ld)j * a + (ld)(d + 1 - j) * b)
                                     / (ld)(d + 1);
                }
    }
}

/*
** Up to degree SUB_DEG a triangle is added as that tensor patch, which
** the subdivision finds robustly where the line of sight grazes it (near
** a fold Newton's starts miss the hits); above, as a triangle (Newton).
*/
bool
rc_add_triangle(rc_scene_t *rc, const cf_bezier_triangle_t *t)
{
    int n = cf_bezier_triangle_degree(t);
    size_t cnt = count(true, n, n), tcnt = count(false, n, n);
    double *pts = malloc((cnt + tcnt) * 4 * sizeof(double));
    ld *h = malloc((cnt + tcnt) * 4 * sizeof(ld));
    bool ok;
    if (pts == NULL || h == NULL || cf_bezier_triangle_dim(t) != 3) {
        free(pts);
        free(h);
        return false;
    }
    cf_bezier_triangle_get_points(t, pts);
    cf_bezier_triangle_get_weights(t, pts + 3 * cnt);
    if (n > SUB_DEG) {
        ok = add(rc, true, n, n, pts, pts + 3 * cnt);
    } else {
        ld *net = h + 4 * cnt;
        for (size_t i = 0; i < cnt; i++) {
            for (int c = 0; c < 3; c++)
                h[4 * i + c] = (ld)pts[3 * i + c] * (ld)pts[3 * cnt + i];
            h[4 * i + 3] = pts[3 * cnt + i];
        }
        triangle_as_tensor(h, n, net);
        /* back to points and weights, as add takes them (rounded to
        ** doubles: 1e-16 of the coordinates, far below what is asked) */
        for (size_t i = 0; i < tcnt; i++) {
            for (int c = 0; c < 3; c++)
                pts[3 * i + c] = (double)(net[4 * i + c] / net[4 * i + 3]);
            pts[3 * tcnt + i] = (double)net[4 * i + 3];
        }
        ok = add(rc, false, n, n, pts, pts + 3 * tcnt);
    }
    free(pts);
    free(h);
    return ok;
}

/* S(u, v) by de Casteljau, long double. */
static void
eval(const struct rc_patch *p, ld u, ld v, ld *out)
{
    ld buf[4 * 1089], col[4 * 33];
    if (p->tri) {
        int n = p->n;
        ld w = 1.0L - u - v;
        memcpy(buf, p->h, count(true, n, n) * 4 * sizeof(ld));
        /* level d -> d - 1, b_ijk at r (r + 1) / 2 + (r - j), r = d - i */
        for (int d = n; d > 0; d--)
            for (int i = d - 1; i >= 0; i--)
                for (int j = d - 1 - i; j >= 0; j--) {
                    int r0 = d - 1 - i, r1 = d - i;
                    ld *o = buf + 4 * (r0 * (r0 + 1) / 2 + (r0 - j));
                    const ld *a = buf + 4 * (r0 * (r0 + 1) / 2 + (r0 - j));
                    const ld *b = buf + 4 * (r1 * (r1 + 1) / 2 + (r1 - j - 1));
                    const ld *c = buf + 4 * (r1 * (r1 + 1) / 2 + (r1 - j));
                    for (int e = 0; e < 4; e++)
                        o[e] = u * a[e] + v * b[e] + w * c[e];
                }
        for (int e = 0; e < 3; e++)
            out[e] = buf[e] / buf[3];
        return;
    }
    for (int i = 0; i <= p->m; i++) {
        memcpy(buf, p->h + (size_t)i * (p->n + 1) * 4,
               (size_t)(p->n + 1) * 4 * sizeof(ld));
        for (int l = p->n; l > 0; l--)
            for (int j = 0; j < l; j++)
                for (int e = 0; e < 4; e++)
                    buf[4 * j + e] = (1 - v) * buf[4 * j + e] +
                                     v * buf[4 * j + 4 + e];
        memcpy(col + 4 * i, buf, 4 * sizeof(ld));
    }
    for (int l = p->m; l > 0; l--)
        for (int i = 0; i < l; i++)
            for (int e = 0; e < 4; e++)
                col[4 * i + e] = (1 - u) * col[4 * i + e] + u * col[4 * i + 4 + e];
    for (int e = 0; e < 3; e++)
        out[e] = col[e] / col[3];
}

/* The line of sight from p: p + s e, s in (0, smax). */
static void
sight(const rc_scene_t *rc, const double *p, ld *e, ld *smax)
{
    if (rc->view.projection == CF_PROJECTION_PERSPECTIVE) {
        for (int c = 0; c < 3; c++)
            e[c] = (ld)rc->view.eye[c] - p[c];
        *smax = 1.0L;
    } else {
        for (int c = 0; c < 3; c++)
            e[c] = rc->view.dir[c];
        *smax = HUGE_VALL;
    }
}

/* The line crosses the box of the patch (slab test, margin pad). */
/* The part [*s0, *s1] of the line o + s e within [s0, s1] in the box
** lo..hi (slab test); false when empty. */
static bool
slab(const ld *lo, const ld *hi, const double *o, const ld *e, ld *s0,
     ld *s1)
{
    ld t0 = *s0, t1 = *s1;
    for (int c = 0; c < 3; c++) {
        if (fabsl(e[c]) < 1e-30L) {
            if (o[c] < lo[c] || o[c] > hi[c])
                return false;
            continue;
        }
        ld a = (lo[c] - o[c]) / e[c], b = (hi[c] - o[c]) / e[c];
        t0 = lmax(t0, lmin(a, b));
        t1 = lmin(t1, lmax(a, b));
    }
    *s0 = t0;
    *s1 = t1;
    return t0 <= t1;
}

/* The line crosses the box of the patch (pad around it) for s in
** [*s0, *s1] within [0, smax]. */
static bool
crosses(const rc_patch_t *p, const double *o, const ld *e, ld smax, ld pad,
        ld *s0, ld *s1)
{
    ld lo[3], hi[3];
    for (int c = 0; c < 3; c++) {
        lo[c] = p->lo[c] - pad;
        hi[c] = p->hi[c] + pad;
    }
    *s0 = 0.0L;
    *s1 = smax;
    return slab(lo, hi, o, e, s0, s1);
}

static bool
inside(const rc_patch_t *p, ld u, ld v)
{
    const ld e = 1e-9L;
    if (p->tri)
        return u >= -e && v >= -e && u + v <= 1 + e;
    return u >= -e && u <= 1 + e && v >= -e && v <= 1 + e;
}

/* Newton on F(u, v, s) = S(u, v) - o - s e from (u, v); the derivatives
** by central differences.  true with the solution. */
static bool
newton(const rc_patch_t *p, const double *o, const ld *e, ld u, ld v, ld s,
       ld *su, ld *sv, ld *ss)
{
    ld S[3];
    for (int it = 0; it < 40; it++) {
        ld F[3], A[3], B[3], J[3][3], h = 1e-7L;
        eval(p, u, v, S);
        for (int c = 0; c < 3; c++)
            F[c] = S[c] - o[c] - s * e[c];
        ld fn = fabsl(F[0]) + fabsl(F[1]) + fabsl(F[2]);
        if (fn < 1e-15L) {
            *su = u;
            *sv = v;
            *ss = s;
            return inside(p, u, v);
        }
        eval(p, u + h, v, A);
        eval(p, u - h, v, B);
        for (int c = 0; c < 3; c++)
            J[c][0] = (A[c] - B[c]) / (2 * h);
        eval(p, u, v + h, A);
        eval(p, u, v - h, B);
        for (int c = 0; c < 3; c++) {
            J[c][1] = (A[c] - B[c]) / (2 * h);
            J[c][2] = -e[c];
        }
        /* Cramer */
        ld det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
                 J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                 J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
        if (fabsl(det) < 1e-24L)
            return false;
        ld d[3];
        for (int k = 0; k < 3; k++) {
            ld M[3][3];
            memcpy(M, J, sizeof M);
            for (int c = 0; c < 3; c++)
                M[c][k] = -F[c];
            d[k] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
                    M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                    M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) /
                   det;
        }
        ld len = sqrtl(d[0] * d[0] + d[1] * d[1]);
        if (len > 0.25L) {
            for (int k = 0; k < 3; k++)
                d[k] *= 0.25L / len;
        }
        u += d[0];
        v += d[1];
        s += d[2];
        if (!(u > -0.5L && u < 1.5L && v > -0.5L && v < 1.5L))
            return false;
    }
    return false;
}

/* Subdivision of tensor pieces (degrees up to SUB_DEG): halve the net
** until its box, crossed by the line of sight beyond the margin, is
** smaller than SUB_MIN of the piece. */
#define SUB_MIN 1e-6L

typedef struct ray {
    const double *o;
    const ld *e;
    ld s0, s1, stop;
    ld best;        /* nearest s found */
    bool first_only;
    long budget;    /* boxes left to look at */
} ray_t;

static bool
net_crosses(const ld *net, size_t cnt, const ray_t *r, ld *size)
{
    ld lo[3] = {HUGE_VALL, HUGE_VALL, HUGE_VALL};
    ld hi[3] = {-HUGE_VALL, -HUGE_VALL, -HUGE_VALL};
    ld t0 = r->s0, t1 = lmin(r->s1, r->best);
    for (size_t i = 0; i < cnt; i++)
        for (int c = 0; c < 3; c++) {
            ld x = net[4 * i + c] / net[4 * i + 3];
            lo[c] = lmin(lo[c], x);
            hi[c] = lmax(hi[c], x);
        }
    *size = 0.0L;
    for (int c = 0; c < 3; c++)
        *size = lmax(*size, hi[c] - lo[c]);
    return slab(lo, hi, r->o, r->e, &t0, &t1);
}

static void
subdivide(const ld *net, int m, int n, ray_t *r, int depth)
{
    size_t cnt = (size_t)(m + 1) * (size_t)(n + 1);
    ld size, lo[(SUB_DEG + 1) * (SUB_DEG + 1) * 4],
        hi[(SUB_DEG + 1) * (SUB_DEG + 1) * 4];
    if (r->budget-- <= 0 || (r->first_only && r->best < HUGE_VALL) ||
        !net_crosses(net, cnt, r, &size))
        return;
    if (size <= r->stop || depth >= 60) {
        /* a hit: its s is about the middle of the crossing */
        ld c[3] = {0, 0, 0}, s = 0.0L, ee = 0.0L;
        for (size_t i = 0; i < cnt; i++)
            for (int k = 0; k < 3; k++)
                c[k] += net[4 * i + k] / net[4 * i + 3] / (ld)cnt;
        for (int k = 0; k < 3; k++) {
            s += (c[k] - r->o[k]) * r->e[k];
            ee += r->e[k] * r->e[k];
        }
        s /= ee;
        if (s < r->best)
            r->best = lmax(s, r->s0);
        return;
    }
    /* halve in the direction of the longer extent of the net */
    ld eu = 0.0L, ev = 0.0L;
    for (int i = 0; i <= m; i++)
        for (int c = 0; c < 3; c++) {
            const ld *a = net + 4 * (size_t)i * (n + 1),
                     *b = net + 4 * ((size_t)i * (n + 1) + n);
            ev = lmax(ev, fabsl(a[c] / a[3] - b[c] / b[3]));
        }
    for (int j = 0; j <= n; j++)
        for (int c = 0; c < 3; c++) {
            const ld *a = net + 4 * j, *b = net + 4 * ((size_t)m * (n + 1) + j);
            eu = lmax(eu, fabsl(a[c] / a[3] - b[c] / b[3]));
        }
    bool in_u = eu >= ev;
    int d = in_u ? m : n;
    size_t lines = in_u ? (size_t)n + 1 : (size_t)m + 1;
    for (size_t l = 0; l < lines; l++) {
        ld tmp[(SUB_DEG + 1) * 4];
        for (int k = 0; k <= d; k++) {
            size_t idx = in_u ? (size_t)k * (n + 1) + l : l * (n + 1) + k;
            memcpy(tmp + 4 * k, net + 4 * idx, 4 * sizeof(ld));
        }
        for (int lev = 0; lev <= d; lev++) {
            size_t ia = in_u ? (size_t)lev * (n + 1) + l : l * (n + 1) + lev;
            size_t ib = in_u ? (size_t)(d - lev) * (n + 1) + l
                             : l * (n + 1) + (d - lev);
            memcpy(lo + 4 * ia, tmp, 4 * sizeof(ld));
            memcpy(hi + 4 * ib, tmp + 4 * (d - lev), 4 * sizeof(ld));
            for (int k = 0; k < d - lev; k++)
                for (int c = 0; c < 4; c++)
                    tmp[4 * k + c] = 0.5L * (tmp[4 * k + c] + tmp[4 * k + 4 + c]);
        }
    }
    subdivide(lo, m, n, r, depth + 1);
    subdivide(hi, m, n, r, depth + 1);
}

/* Points on the line of sight beyond margin (all of them, or stop at the
** first when first_only). */
static size_t
hits(const rc_scene_t *rc, const double *p, double margin, ld *nearest,
     bool first_only)
{
    ld e[3], smax, en;
    size_t found = 0;
    sight(rc, p, e, &smax);
    en = sqrtl(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    *nearest = HUGE_VALL;
    for (size_t k = 0; k < rc->n; k++) {
        const rc_patch_t *pt = &rc->p[k];
        /* uniform along the crossing, and denser near its start (a line
        ** of sight that grazes the sheet of its own point) */
        static const ld at[] = {0.1L, 0.3L, 0.5L, 0.7L, 0.9L, 0.002L,
                                0.006L, 0.02L, 0.05L};
        const int K = (int)(sizeof at / sizeof *at);
        ld s0, s1;
        if (!crosses(pt, p, e, smax, (ld)margin, &s0, &s1))
            continue;
        s0 = fmaxl(s0, (ld)margin / en);
        if (s1 < s0)
            continue;
        if (!pt->tri && pt->m <= SUB_DEG && pt->n <= SUB_DEG) {
            ld size = 0.0L;
            for (int c = 0; c < 3; c++)
                size = fmaxl(size, pt->hi[c] - pt->lo[c]);
            ray_t r = {p, e, (ld)margin / en, smax, SUB_MIN * size,
                       HUGE_VALL, first_only, 200000};
            subdivide(pt->h, pt->m, pt->n, &r, 0);
            if (r.best < HUGE_VALL) {
                found++;
                if (r.best * en < *nearest)
                    *nearest = r.best * en;
                if (first_only)
                    return found;
            }
            continue;
        }
        /* starts along the crossing: the grid sample nearest the line's
        ** point, at K points of the line in the box */
        if (s1 > 1e6L)
            s1 = s0 + 1e6L;
        for (int a = 0; a < K; a++) {
            ld s = s0 + at[a] * (s1 - s0), x[3], best = HUGE_VALL;
            ld u = 0.5L, v = 0.5L, su, sv, ss;
            for (int c = 0; c < 3; c++)
                x[c] = p[c] + s * e[c];
            for (int i = 0; i < GRID; i++)
                for (int j = 0; j < GRID; j++) {
                    const ld *g = pt->grid[i][j];
                    ld d = (g[0] - x[0]) * (g[0] - x[0]) +
                           (g[1] - x[1]) * (g[1] - x[1]) +
                           (g[2] - x[2]) * (g[2] - x[2]);
                    if (d < best) {
                        best = d;
                        u = (i + 0.5L) / GRID;
                        v = (j + 0.5L) / GRID;
                    }
                }
            if (pt->tri && u + v > 1) {
                u = u / (u + v + 0.01L);
                v = v / (u + v + 0.01L);
            }
            if (!newton(pt, p, e, u, v, s, &su, &sv, &ss))
                continue;
            ld dist = ss * en;
            if (dist > margin && ss < smax) {
                found++;
                if (dist < *nearest)
                    *nearest = dist;
                if (first_only)
                    return found;
            }
        }
    }
    return found;
}

bool
rc_hidden(const rc_scene_t *rc, const double *p, double margin, double *dist)
{
    ld near;
    bool h = hits(rc, p, margin, &near, dist == NULL) > 0;
    if (dist != NULL)
        *dist = h ? (double)near : 0.0;
    return h;
}

size_t
rc_hits(const rc_scene_t *rc, const double *p, double margin)
{
    ld near;
    return hits(rc, p, margin, &near, false);
}

bool
rc_long_double(void)
{
    volatile long double one = 1.0L, e = 1e-18L;
    return one + e != one;
}
