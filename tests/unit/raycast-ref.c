/* The tests' independent ray caster (raycast-ref.h). */
#include "raycast-ref.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "curvefig/bezier.h"

typedef long double ld;

typedef struct rc_patch {
    bool tri;
    int m, n;         /* degrees (triangle: n) */
    ld *h;            /* homogeneous (w x, w y, w z, w) */
    ld lo[3], hi[3];  /* box of the Cartesian control points */
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
    rc->n++;
    return true;
}

static bool
add_bez(rc_scene_t *rc, const cf_bezier_surface_t *s)
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

bool
rc_add_triangle(rc_scene_t *rc, const cf_bezier_triangle_t *t)
{
    int n = cf_bezier_triangle_degree(t);
    size_t cnt = count(true, n, n);
    double *pts = malloc(cnt * 4 * sizeof(double));
    bool ok;
    if (pts == NULL || cf_bezier_triangle_dim(t) != 3) {
        free(pts);
        return false;
    }
    cf_bezier_triangle_get_points(t, pts);
    cf_bezier_triangle_get_weights(t, pts + 3 * cnt);
    ok = add(rc, true, n, n, pts, pts + 3 * cnt);
    free(pts);
    return ok;
}

/* S(u, v) by de Casteljau, long double. */
static void
eval(const rc_patch_t *p, ld u, ld v, ld *out)
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
static bool
crosses(const rc_patch_t *p, const double *o, const ld *e, ld smax, ld pad)
{
    ld t0 = 0.0L, t1 = smax;
    for (int c = 0; c < 3; c++) {
        ld lo = p->lo[c] - pad, hi = p->hi[c] + pad;
        if (fabsl(e[c]) < 1e-30L) {
            if (o[c] < lo || o[c] > hi)
                return false;
            continue;
        }
        ld a = (lo - o[c]) / e[c], b = (hi - o[c]) / e[c];
        if (a > b) {
            ld x = a;
            a = b;
            b = x;
        }
        t0 = fmaxl(t0, a);
        t1 = fminl(t1, b);
    }
    return t0 <= t1;
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
newton(const rc_patch_t *p, const double *o, const ld *e, ld u, ld v,
       ld *su, ld *sv, ld *ss)
{
    ld S[3], s = 0.0L, ee = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
    eval(p, u, v, S);
    for (int c = 0; c < 3; c++)
        s += (S[c] - o[c]) * e[c];
    s /= ee;
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
        if (!(u > -1 && u < 2 && v > -1 && v < 2))
            return false;
    }
    return false;
}

static size_t
hits(const rc_scene_t *rc, const double *p, double margin, ld *nearest)
{
    ld e[3], smax, en;
    size_t found = 0;
    sight(rc, p, e, &smax);
    en = sqrtl(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    *nearest = HUGE_VALL;
    for (size_t k = 0; k < rc->n; k++) {
        const rc_patch_t *pt = &rc->p[k];
        const int G = 7;
        if (!crosses(pt, p, e, smax, (ld)margin))
            continue;
        for (int a = 0; a < G; a++)
            for (int b = 0; b < G; b++) {
                ld u = (a + 0.5L) / G, v = (b + 0.5L) / G, su, sv, ss;
                if (pt->tri && u + v > 1)
                    continue;
                if (!newton(pt, p, e, u, v, &su, &sv, &ss))
                    continue;
                ld dist = ss * en;
                if (dist > margin && ss < smax) {
                    found++;
                    if (dist < *nearest)
                        *nearest = dist;
                }
            }
    }
    return found;
}

bool
rc_hidden(const rc_scene_t *rc, const double *p, double margin, double *dist)
{
    ld near;
    bool h = hits(rc, p, margin, &near) > 0;
    if (dist != NULL)
        *dist = h ? (double)near : 0.0;
    return h;
}

size_t
rc_hits(const rc_scene_t *rc, const double *p, double margin)
{
    ld near;
    return hits(rc, p, margin, &near);
}
