/*
** The triangles of regions in space (render/figure/region-tri.c and
** region-hull.c), against independent slow methods:
**
**   ears       simple polygons (star-shaped, spirals, combs, points of a
**              grid, many in a line): m - 2 triangles, each turning
**              counter-clockwise, their areas adding up to the polygon's,
**              and at points of a lattice away from every edge, one
**              triangle over each point inside and none outside; a convex
**              quadrilateral as before (its first corner cut off);
**   winding    polygons of random points, crossing themselves: at points
**              away from every edge, the winding numbers of the triangles
**              (each with its sign) add up to the polygon's;
**   crossing   the same through the figure's entry, for polygons in a
**              plane in space (a bow tie, a pentagram, random ones);
**   hull       random points (in a cube, on a sphere, near a plane) and
**              points on a grid or repeated (faces in one plane): the same
**              faces as adding the points one at a time against every face
**              where no four points lie in one plane; everywhere a closed
**              surface (every edge once each way, V - E + F = 2), every
**              point at most the tolerance beyond any face, and the same
**              volume;
**   big        200,000 points on a sphere and a polygon of 200,000 points
**              (the cost is measured by bench/bench_regions.c, not here):
**              the hull's every point inside, the polygon's triangles
**              adding up to its area.
*/
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/figure.h"
#include "figure/region.h"

/* A small generator of its own, the same numbers on every machine. */
static uint64_t rng = 0x9e3779b97f4a7c15u;

static double
uniform(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) * 0x1p-53;
}

static double
orient(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* ---- ear clipping -------------------------------------------------------- */

/* Simple polygons, counter-clockwise, of m vertices into q. */
enum { STAR, STAR_GRID, SPIRAL, COMB, KINDS };

static size_t
simple_polygon(int kind, size_t m, double *q)
{
    const double tau = 6.283185307179586;
    switch (kind) {
    case STAR:       /* random radii at increasing angles */
        for (size_t i = 0; i < m; i++) {
            double t = tau * ((double)i + 0.8 * uniform()) / (double)m;
            double r = 0.2 + uniform();
            q[2 * i] = r * cos(t);
            q[2 * i + 1] = r * sin(t);
        }
        return m;
    case STAR_GRID: { /* points of a grid sorted by their angle about a
                         point inside: many in a line */
        size_t k = 0;
        for (size_t i = 0; i < m; i++) {
            double x = round(16 * uniform()) - 8, y = round(16 * uniform()) - 8;
            bool again = false;
            for (size_t j = 0; j < k && !again; j++)
                again = (q[2 * j] == x && q[2 * j + 1] == y)
                    || atan2(q[2 * j + 1] - 0.05, q[2 * j] - 0.1)
                           == atan2(y - 0.05, x - 0.1);
            if (!again) {
                q[2 * k] = x;
                q[2 * k++ + 1] = y;
            }
        }
        for (size_t i = 1; i < k; i++)    /* insertion sort by angle */
            for (size_t j = i; j > 0
                 && atan2(q[2 * j - 1] - 0.05, q[2 * j - 2] - 0.1)
                        > atan2(q[2 * j + 1] - 0.05, q[2 * j] - 0.1);
                 j--)
                for (int c = 0; c < 2; c++) {
                    double t = q[2 * j + c];
                    q[2 * j + c] = q[2 * j - 2 + c];
                    q[2 * j - 2 + c] = t;
                }
        return k;
    }
    case SPIRAL: {   /* out along one arm, back along a thicker one */
        size_t h = m / 2;
        double turns = 1 + 3 * uniform();
        for (size_t i = 0; i < h; i++) {
            double t = turns * tau * (double)i / (double)(h - 1);
            double r = 1 + t, w = 0.4 + 0.3 * uniform();
            q[2 * i] = r * cos(t);
            q[2 * i + 1] = r * sin(t);
            q[2 * (m - 1 - i)] = (r + w * tau) * cos(t);
            q[2 * (m - 1 - i) + 1] = (r + w * tau) * sin(t);
        }
        /* the arms' order turns clockwise in places: reverse if needed */
        return m - (m % 2);
    }
    default: {       /* a comb: teeth of random heights on a bar */
        size_t t = m / 4, k = 0;
        for (size_t i = 0; i < t; i++) {
            double h = 1 + 5 * uniform();
            q[2 * k] = (double)(t - i);
            q[2 * k++ + 1] = 1;
            q[2 * k] = (double)(t - i);
            q[2 * k++ + 1] = 1 + h;
            q[2 * k] = (double)(t - i) - 0.5;
            q[2 * k++ + 1] = 1 + h;
            q[2 * k] = (double)(t - i) - 0.5;
            q[2 * k++ + 1] = 1;
        }
        q[2 * k] = 0;
        q[2 * k++ + 1] = 0;
        q[2 * k] = (double)t + 1;
        q[2 * k++ + 1] = 0;
        /* that runs clockwise (teeth right to left on top): reversed by
        ** the caller's check */
        return k;
    }
    }
}

/* Whether segments a b and c d meet (closed). */
static bool
meet(const double *a, const double *b, const double *c, const double *d)
{
    double o1 = orient(a, b, c), o2 = orient(a, b, d);
    double o3 = orient(c, d, a), o4 = orient(c, d, b);
    if (o1 == 0 && o2 == 0)   /* in one line: do their boxes overlap */
        return fmax(fmin(a[0], b[0]), fmin(c[0], d[0]))
                   <= fmin(fmax(a[0], b[0]), fmax(c[0], d[0]))
            && fmax(fmin(a[1], b[1]), fmin(c[1], d[1]))
                   <= fmin(fmax(a[1], b[1]), fmax(c[1], d[1]));
    return (o1 <= 0 || o2 <= 0) && (o1 >= 0 || o2 >= 0)
        && (o3 <= 0 || o4 <= 0) && (o3 >= 0 || o4 >= 0);
}

/* Whether polygon idx of q is simple: edges meet only where consecutive
** ones share their vertex (every pair asked). */
static bool
is_simple(const double *q, const size_t *idx, size_t k)
{
    for (size_t i = 0; i < k; i++)
        for (size_t j = i + 1; j < k; j++) {
            const double *a = q + 2 * idx[i], *b = q + 2 * idx[(i + 1) % k];
            const double *c = q + 2 * idx[j], *d = q + 2 * idx[(j + 1) % k];
            if (j == i + 1 || (i == 0 && j == k - 1)) {
                /* neighbours: only their shared vertex, unless they fold
                ** back along each other */
                const double *o = j == i + 1 ? a : b, *e = j == i + 1 ? d : c;
                const double *s = j == i + 1 ? b : a;
                if (orient(o, s, e) == 0
                    && (e[0] - s[0]) * (o[0] - s[0])
                               + (e[1] - s[1]) * (o[1] - s[1]) > 0)
                    return false;
                continue;
            }
            if (meet(a, b, c, d))
                return false;
        }
    return true;
}

static double
signed_area(const double *q, size_t m)
{
    double s = 0;
    for (size_t i = 0; i < m; i++) {
        size_t j = (i + 1) % m;
        s += q[2 * i] * q[2 * j + 1] - q[2 * j] * q[2 * i + 1];
    }
    return s / 2;
}

static void
reverse(double *q, size_t m)
{
    for (size_t i = 0; i < m / 2; i++)
        for (int k = 0; k < 2; k++) {
            double t = q[2 * i + k];
            q[2 * i + k] = q[2 * (m - 1 - i) + k];
            q[2 * (m - 1 - i) + k] = t;
        }
}

/* Repeated consecutive points dropped (the caller of the ear clipping
** does so). */
static size_t
distinct(const double *q, size_t m, size_t *idx)
{
    size_t k = 0;
    for (size_t i = 0; i < m; i++)
        if (k == 0 || q[2 * i] != q[2 * idx[k - 1]]
            || q[2 * i + 1] != q[2 * idx[k - 1] + 1])
            idx[k++] = i;
    while (k > 1 && q[2 * idx[0]] == q[2 * idx[k - 1]]
           && q[2 * idx[0] + 1] == q[2 * idx[k - 1] + 1])
        k--;
    return k;
}

/* ---- winding numbers, tiling --------------------------------------------- */

static int
winding(const double *q, const size_t *v, size_t m, const double *x)
{
    int w = 0;
    for (size_t i = 0; i < m; i++) {
        const double *a = q + 2 * v[i], *b = q + 2 * v[(i + 1) % m];
        if (a[1] <= x[1]) {
            if (b[1] > x[1] && orient(a, b, x) > 0)
                w++;
        } else if (b[1] <= x[1] && orient(a, b, x) < 0) {
            w--;
        }
    }
    return w;
}

/* The distance from x to segment a b. */
static double
seg_dist(const double *a, const double *b, const double *x)
{
    double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((x[0] - a[0]) * dx + (x[1] - a[1]) * dy) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(x[0] - a[0] - t * dx, x[1] - a[1] - t * dy);
}

/* The distance from x to the nearest edge of triangles tri of q. */
static double
near_triangles(const double *q, const size_t *tri, size_t nt,
               const double *x)
{
    double near = INFINITY;
    for (size_t t = 0; t < nt; t++)
        for (int e = 0; e < 3; e++)
            near = fmin(near, seg_dist(q + 2 * tri[3 * t + e],
                                       q + 2 * tri[3 * t + (e + 1) % 3], x));
    return near;
}

/* Triangles tri (nt of them) tile the simple polygon idx of q: k - 2 of
** them, each turning left, their areas adding up to the polygon's, and at points of a lattice
** away from every edge, each inside the polygon is in one triangle and
** each outside in none. */
static void
assert_triangulates(const double *q, const size_t *idx, size_t k,
                    const size_t *tri, size_t nt)
{
    double area = 0, parea = 0, lo[2] = { INFINITY, INFINITY };
    double hi[2] = { -INFINITY, -INFINITY };
    assert_int_equal(nt, k - 2);
    for (size_t t = 0; t < nt; t++) {
        double o = orient(q + 2 * tri[3 * t], q + 2 * tri[3 * t + 1],
                          q + 2 * tri[3 * t + 2]);
        assert_true(o > 0);
        area += o;
    }
    for (size_t i = 0; i < k; i++) {
        const double *a = q + 2 * idx[i], *b = q + 2 * idx[(i + 1) % k];
        parea += a[0] * b[1] - b[0] * a[1];
        for (int c = 0; c < 2; c++) {
            lo[c] = fmin(lo[c], a[c]);
            hi[c] = fmax(hi[c], a[c]);
        }
    }
    /* exact for the grid's small integers; the comb's heights are random
    ** doubles, and two sums of up to 400 products each round to within
    ** 400 ulps of their size */
    assert_true(fabs(area - parea) <= 1e-13 * (double)k * fabs(parea));
    for (int i = 0; i < 24; i++)
        for (int j = 0; j < 24; j++) {
            double x[2] = { lo[0] + (hi[0] - lo[0]) * (i + 0.31) / 24,
                            lo[1] + (hi[1] - lo[1]) * (j + 0.43) / 24 };
            int sum = 0;
            if (near_triangles(q, tri, nt, x) < 1e-9)
                continue;
            for (size_t t = 0; t < nt; t++)
                sum += winding(q, tri + 3 * t, 3, x);
            assert_int_equal(sum, winding(q, idx, k, x));
            assert_true(sum == 0 || sum == 1);
        }
}

static void
test_ears(void **state)
{
    size_t sizes[] = { 3, 4, 5, 8, 13, 40, 101, 400 };
    double *q = malloc(2 * 2000 * sizeof *q);
    size_t *idx = malloc(2000 * sizeof *idx), *tri = malloc(6000 * sizeof *tri);
    size_t polygons = 0, nt;
    const size_t quad[6] = { 3, 0, 1, 1, 2, 3 };
    (void)state;
    assert_non_null(q);
    assert_non_null(idx);
    assert_non_null(tri);
    for (int kind = 0; kind < KINDS; kind++)
        for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
            for (int rep = 0; rep < 25; rep++) {
                size_t m = simple_polygon(kind, sizes[s] < 8 && kind >= SPIRAL
                                                    ? 8 : sizes[s], q), k;
                if (signed_area(q, m) < 0)
                    reverse(q, m);
                k = distinct(q, m, idx);
                if (k < 3 || !is_simple(q, idx, k))
                    continue;   /* a generator's polygon may cross */
                assert_true(cf__ear_clip(q, idx, k, tri, &nt));
                assert_triangulates(q, idx, k, tri, nt);
                polygons++;
            }
    assert_true(polygons > 700);
    /* a convex quadrilateral: its first corner, then the rest */
    for (size_t i = 0; i < 4; i++) {
        q[2 * i] = i == 1 || i == 2 ? 1 + 0.1 * (double)i : 0;
        q[2 * i + 1] = i >= 2 ? 1 : 0.2 * (double)i;
        idx[i] = i;
    }
    assert_true(cf__ear_clip(q, idx, 4, tri, &nt));
    assert_int_equal(nt, 2);
    assert_memory_equal(tri, quad, sizeof quad);
    free(q);
    free(idx);
    free(tri);
}

static void
test_winding(void **state)
{
    double q[2 * 64];
    size_t idx[64], tri[3 * 64], nt, checked = 0;
    (void)state;
    for (int rep = 0; rep < 400; rep++) {
        size_t m = 4 + (size_t)(uniform() * 40), k;
        for (size_t i = 0; i < m; i++) {
            q[2 * i] = uniform();
            q[2 * i + 1] = uniform();
        }
        if (signed_area(q, m) < 0)
            reverse(q, m);
        k = distinct(q, m, idx);
        assert_true(cf__ear_clip(q, idx, k, tri, &nt));
        assert_true(nt <= k - 2);
        for (int s = 0; s < 200; s++) {
            double x[2] = { uniform(), uniform() }, near = INFINITY;
            int sum = 0;
            for (size_t i = 0; i < k; i++)
                near = fmin(near, seg_dist(q + 2 * idx[i],
                                           q + 2 * idx[(i + 1) % k], x));
            near = fmin(near, near_triangles(q, tri, nt, x));
            if (near < 1e-9)
                continue;   /* on an edge: the winding number is not one */
            for (size_t t = 0; t < nt; t++)
                sum += winding(q, tri + 3 * t, 3, x);
            if (sum != winding(q, idx, k, x))
                fail_msg("polygon %d (%zu points): at (%.17g, %.17g) the "
                         "triangles wind %d times, the polygon %d", rep, k,
                         x[0], x[1], sum, winding(q, idx, k, x));
            checked++;
        }
    }
    assert_true(checked > 70000);
}

/* Polygons in a plane in space that cross themselves (a bow tie, a
** pentagram, random ones), through the figure's own entry: their
** triangles, each counted with its sign seen from above the plane, wind
** as often as the polygon about every lattice point away from the edges.
** (Before the fast ear clipping, a bow tie came out as one triangle
** reaching outside it, and the pentagram's five points with a corner
** filled outside them.) */
static void
test_crossing_in_space(void **state)
{
    cf_figure_t *fig = NULL;
    double p[3 * 40], q[2 * 40];
    size_t idx[40];
    (void)state;
    assert_int_equal(cf_figure_create(60, 40, CF_UNIT_MM, &fig, NULL), 0);
    for (int rep = 0; rep < 60; rep++) {
        size_t n;
        cf__tris_t tris;
        bool planar;
        if (rep == 0) {        /* a bow tie */
            const double bow[8] = { 0, 0, 2, 2, 2, 0, 0, 2 };
            n = 4;
            memcpy(q, bow, sizeof bow);
        } else if (rep == 1) { /* a pentagram */
            n = 5;
            for (size_t k = 0; k < 5; k++) {
                double t = 1.5707963267948966 + 4 * 3.141592653589793
                    * (double)k / 5;
                q[2 * k] = cos(t);
                q[2 * k + 1] = sin(t);
            }
        } else {
            n = 4 + (size_t)(uniform() * 30);
            for (size_t k = 0; k < n; k++) {
                q[2 * k] = uniform();
                q[2 * k + 1] = uniform();
            }
        }
        for (size_t k = 0; k < n; k++) {   /* in the plane z = .3x + .2y */
            p[3 * k] = q[2 * k];
            p[3 * k + 1] = q[2 * k + 1];
            p[3 * k + 2] = 0.3 * q[2 * k] + 0.2 * q[2 * k + 1];
            idx[k] = k;
        }
        memset(&tris, 0, sizeof tris);
        assert_int_equal(cf__region_polygon(fig, p, n, "fill", &tris,
                                            &planar), 0);
        if (!planar) fail_msg("rep %d not planar", rep);
        for (int i = 0; i < 30; i++)
            for (int j = 0; j < 30; j++) {
                double lo = rep == 1 ? -1 : 0, hi = rep == 0 ? 2 : 1;
                double x[2] = { lo + (hi - lo) * (i + 0.31) / 30,
                                lo + (hi - lo) * (j + 0.43) / 30 };
                double near = INFINITY, tq[6];
                size_t tv[3] = { 0, 1, 2 };
                int sum = 0;
                for (size_t k = 0; k < n; k++)
                    near = fmin(near, seg_dist(q + 2 * k,
                                               q + 2 * ((k + 1) % n), x));
                for (size_t t = 0; t < tris.n; t++) {
                    for (int e = 0; e < 3; e++) {
                        tq[2 * e] = tris.p[9 * t + 3 * e];
                        tq[2 * e + 1] = tris.p[9 * t + 3 * e + 1];
                    }
                    for (int e = 0; e < 3; e++)
                        near = fmin(near, seg_dist(tq + 2 * e,
                                                   tq + 2 * ((e + 1) % 3), x));
                    sum += winding(tq, tv, 3, x);
                }
                if (near < 1e-9)
                    continue;
                if (sum != winding(q, idx, n, x))
                    fail_msg("polygon %d (%zu points): at (%g, %g) the "
                             "triangles wind %d times, the polygon %d", rep,
                             n, x[0], x[1], sum, winding(q, idx, n, x));
            }
        cf__tris_fini(&tris);
    }
    cf_figure_destroy(fig);
}

/* ---- hulls -------------------------------------------------------------- */

typedef struct hulled {
    size_t *f, nf;
} hulled_t;

/* Lexicographic order of n indices: triples (faces) and pairs (edges). */
static int
cmp_n(const size_t *x, const size_t *y, int n)
{
    for (int k = 0; k < n; k++)
        if (x[k] != y[k])
            return x[k] < y[k] ? -1 : 1;
    return 0;
}

static int
cmp_face(const void *a, const void *b)
{
    return cmp_n(a, b, 3);
}

static int
cmp_pair(const void *a, const void *b)
{
    return cmp_n(a, b, 2);
}

/* Each face turned to start at its smallest index, the faces sorted. */
static void
canonical(hulled_t *h)
{
    for (size_t i = 0; i < h->nf; i++) {
        size_t *v = h->f + 3 * i;
        while (v[0] > v[1] || v[0] > v[2]) {
            size_t t = v[0];
            v[0] = v[1];
            v[1] = v[2];
            v[2] = t;
        }
    }
    qsort(h->f, h->nf, 3 * sizeof *h->f, cmp_face);
}

static double
volume(const double *p, const hulled_t *h)
{
    double v = 0;
    for (size_t i = 0; i < h->nf; i++) {
        const double *a = p + 3 * h->f[3 * i], *b = p + 3 * h->f[3 * i + 1],
                     *c = p + 3 * h->f[3 * i + 2];
        v += a[0] * (b[1] * c[2] - b[2] * c[1])
            - a[1] * (b[0] * c[2] - b[2] * c[0])
            + a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    return v / 6;
}

/* A closed surface: every directed edge once, its reverse once, and
** V - E + F = 2. */
static void
assert_closed(const hulled_t *h, size_t n, const char *what)
{
    size_t *e = malloc(6 * h->nf * sizeof *e), ne = 0, nv = 0;
    unsigned char *used = calloc(n, 1);
    assert_non_null(e);
    assert_non_null(used);
    for (size_t i = 0; i < h->nf; i++)
        for (int k = 0; k < 3; k++) {
            e[2 * ne] = h->f[3 * i + k];
            e[2 * ne + 1] = h->f[3 * i + (k + 1) % 3];
            ne++;
            used[h->f[3 * i + k]] = 1;
        }
    qsort(e, ne, 2 * sizeof *e, cmp_pair);
    for (size_t i = 1; i < ne; i++)
        if (e[2 * i] == e[2 * i - 2] && e[2 * i + 1] == e[2 * i - 1])
            fail_msg("%s: edge %zu %zu twice", what, e[2 * i], e[2 * i + 1]);
    for (size_t i = 0; i < ne; i++) {
        size_t lo = 0, hi = ne, key[2] = { e[2 * i + 1], e[2 * i] };
        while (lo < hi) {
            size_t mid = (lo + hi) / 2;
            if (cmp_pair(e + 2 * mid, key) < 0)
                lo = mid + 1;
            else
                hi = mid;
        }
        if (lo >= ne || e[2 * lo] != key[0] || e[2 * lo + 1] != key[1])
            fail_msg("%s: edge %zu %zu has no twin", what, e[2 * i],
                     e[2 * i + 1]);
    }
    for (size_t i = 0; i < n; i++)
        nv += used[i];
    assert_int_equal((long)nv - (long)(ne / 2) + (long)h->nf, 2);
    free(e);
    free(used);
}

/* Every point at most eps beyond each face's plane. */
static void
assert_inside(const double *p, size_t n, const hulled_t *h, double eps,
              const char *what)
{
    for (size_t i = 0; i < h->nf; i++) {
        const double *a = p + 3 * h->f[3 * i], *b = p + 3 * h->f[3 * i + 1],
                     *c = p + 3 * h->f[3 * i + 2];
        double ab[3], ac[3], nrm[3], l;
        for (int k = 0; k < 3; k++) {
            ab[k] = b[k] - a[k];
            ac[k] = c[k] - a[k];
        }
        nrm[0] = ab[1] * ac[2] - ab[2] * ac[1];
        nrm[1] = ab[2] * ac[0] - ab[0] * ac[2];
        nrm[2] = ab[0] * ac[1] - ab[1] * ac[0];
        l = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
        for (size_t j = 0; j < n; j++) {
            double d = (nrm[0] * (p[3 * j] - a[0])
                        + nrm[1] * (p[3 * j + 1] - a[1])
                        + nrm[2] * (p[3 * j + 2] - a[2])) / l;
            /* the tolerance, plus the rounding of the distance */
            if (d > eps * (1 + 1e-6) + 1e-14)
                fail_msg("%s: point %zu lies %g beyond face %zu (%zu %zu "
                         "%zu)", what, j, d, i, h->f[3 * i],
                         h->f[3 * i + 1], h->f[3 * i + 2]);
        }
    }
}

/* The first tetrahedron as the figure chooses it: the first point, the
** farthest from it, the farthest from their line, the farthest from
** their plane. */
static bool
start(const double *p, size_t n, size_t t4[4], double *size)
{
    double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3], best, nn[3];
    double ab[3], ac[3];
    for (int k = 0; k < 3; k++)
        hi[k] = -INFINITY;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], p[3 * i + k]);
            hi[k] = fmax(hi[k], p[3 * i + k]);
        }
    *size = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0])
                 + (hi[1] - lo[1]) * (hi[1] - lo[1])
                 + (hi[2] - lo[2]) * (hi[2] - lo[2]));
    t4[0] = 0;
    best = -1;
    for (size_t i = 0; i < n; i++) {
        double d = hypot(hypot(p[3 * i] - p[0], p[3 * i + 1] - p[1]),
                         p[3 * i + 2] - p[2]);
        if (d > best) {
            best = d;
            t4[1] = i;
        }
    }
    for (int k = 0; k < 3; k++)
        ab[k] = p[3 * t4[1] + k] - p[k];
    best = -1;
    for (size_t i = 0; i < n; i++) {
        double d[3], c[3];
        for (int k = 0; k < 3; k++)
            d[k] = p[3 * i + k] - p[k];
        c[0] = ab[1] * d[2] - ab[2] * d[1];
        c[1] = ab[2] * d[0] - ab[0] * d[2];
        c[2] = ab[0] * d[1] - ab[1] * d[0];
        if (hypot(hypot(c[0], c[1]), c[2]) > best) {
            best = hypot(hypot(c[0], c[1]), c[2]);
            t4[2] = i;
        }
    }
    for (int k = 0; k < 3; k++)
        ac[k] = p[3 * t4[2] + k] - p[k];
    nn[0] = ab[1] * ac[2] - ab[2] * ac[1];
    nn[1] = ab[2] * ac[0] - ab[0] * ac[2];
    nn[2] = ab[0] * ac[1] - ab[1] * ac[0];
    best = 0;
    for (size_t i = 0; i < n; i++) {
        double d = fabs(nn[0] * (p[3 * i] - p[0]) + nn[1] * (p[3 * i + 1] - p[1])
                        + nn[2] * (p[3 * i + 2] - p[2]));
        if (d > best) {
            best = d;
            t4[3] = i;
        }
    }
    return best > 0;
}

enum { CUBE, SPHERE, FLAT, GRID, REPEATED, CLOUDS };

static size_t
cloud(int kind, size_t n, double *p)
{
    for (size_t i = 0; i < n; i++) {
        double *x = p + 3 * i;
        switch (kind) {
        case CUBE:
            for (int k = 0; k < 3; k++)
                x[k] = 2 * uniform() - 1;
            break;
        case SPHERE: {
            double z = 2 * uniform() - 1, t = 6.283185307179586 * uniform();
            x[0] = sqrt(1 - z * z) * cos(t);
            x[1] = sqrt(1 - z * z) * sin(t);
            x[2] = z;
            break;
        }
        case FLAT:   /* a slab 1e-3 thick */
            x[0] = 2 * uniform() - 1;
            x[1] = 2 * uniform() - 1;
            x[2] = 1e-3 * uniform();
            break;
        case GRID:   /* 5 x 5 x 5 lattice points, many in each face */
            for (int k = 0; k < 3; k++)
                x[k] = floor(5 * uniform());
            break;
        default:     /* eight points, each many times */
            for (int k = 0; k < 3; k++)
                x[k] = uniform() < 0.5 ? 0 : 1;
            if (i % 3 == 0)
                x[0] += 0.5;
            break;
        }
    }
    return n;
}

static void
test_hull(void **state)
{
    size_t sizes[] = { 4, 5, 8, 20, 100, 600 };
    double *p = malloc(3 * 600 * sizeof *p);
    size_t compared = 0;
    (void)state;
    assert_non_null(p);
    for (int kind = 0; kind < CLOUDS; kind++)
        for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
            for (int rep = 0; rep < 12; rep++) {
                size_t n = cloud(kind, sizes[s], p), t4[4];
                double size, eps;
                hulled_t fast, slow;
                char what[64];
                if (!start(p, n, t4, &size)
                    || t4[0] == t4[1] || t4[1] == t4[2] || t4[3] == t4[0])
                    continue;
                eps = 1e-9 * size;
                snprintf(what, sizeof what, "cloud %d, %zu points, rep %d",
                         kind, n, rep);
                assert_true(cf__hull3(p, n, t4, eps, false, &fast.f,
                                      &fast.nf));
                assert_true(cf__hull3(p, n, t4, eps, true, &slow.f,
                                      &slow.nf));
                assert_closed(&fast, n, what);
                assert_inside(p, n, &fast, eps, what);
                /* the same solid: the volumes agree to their rounding */
                assert_true(fabs(volume(p, &fast) - volume(p, &slow))
                            <= 1e-12 * size * size * size);
                if (kind == CUBE || kind == SPHERE || kind == FLAT) {
                    canonical(&fast);
                    canonical(&slow);
                    if (fast.nf != slow.nf
                        || memcmp(fast.f, slow.f,
                                  3 * fast.nf * sizeof *fast.f) != 0)
                        fail_msg("%s: %zu faces, one at a time %zu", what,
                                 fast.nf, slow.nf);
                    compared++;
                }
                cf_free(fast.f);
                cf_free(slow.f);
            }
    assert_true(compared > 150);
    free(p);
}

/* ---- large ------------------------------------------------------------- */

static void
test_big(void **state)
{
    size_t n = 200000, t4[4], *f, nf, *idx, *tri, nt;
    double *p = malloc(3 * n * sizeof *p), size, area = 0, *q;
    hulled_t h;
    (void)state;
    assert_non_null(p);
    cloud(SPHERE, n, p);
    assert_true(start(p, n, t4, &size));
    assert_true(cf__hull3(p, n, t4, 1e-9 * size, false, &f, &nf));
    h.f = f;
    h.nf = nf;
    assert_true(nf > 1000);
    assert_closed(&h, n, "200,000 points on a sphere");
    /* inside: against every face would be 10^11 tests; the volume is
    ** that of the sphere less what the faces cut off (below 1 %) */
    assert_true(volume(p, &h) > 0.99 * 4.18879020478639 &&
                volume(p, &h) < 4.18879020478639);
    cf_free(f);
    /* a star of 200,000 points: the triangles' areas add up to the
    ** polygon's */
    q = p;
    n = simple_polygon(STAR, n, q);
    idx = malloc(n * sizeof *idx);
    tri = malloc(3 * n * sizeof *tri);
    assert_non_null(idx);
    assert_non_null(tri);
    n = distinct(q, n, idx);
    assert_true(cf__ear_clip(q, idx, n, tri, &nt));
    assert_int_equal(nt, n - 2);
    for (size_t t = 0; t < nt; t++) {
        double o = orient(q + 2 * tri[3 * t], q + 2 * tri[3 * t + 1],
                          q + 2 * tri[3 * t + 2]);
        assert_true(o > 0);
        area += o / 2;
    }
    assert_true(fabs(area - signed_area(q, n)) <= 1e-9 * area);
    free(idx);
    free(tri);
    free(p);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ears),
        cmocka_unit_test(test_winding),
        cmocka_unit_test(test_crossing_in_space),
        cmocka_unit_test(test_hull),
        cmocka_unit_test(test_big),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
