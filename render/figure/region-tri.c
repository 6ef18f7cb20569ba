/*
** Triangles of a filled polygon in space (region.h): ear-clipped in its
** plane.  The hulls are in region-hull.c.
*/
#include <math.h>
#include <string.h>

#include "curvefig/geometry.h"
#include "grow.h"
#include "region-geom.h"
#include "region.h"

cf_status_t
cf__tris_add(cf__tris_t *t, const double *a, const double *b,
             const double *c)
{
    double *np = cf__grow_array(t->p, &t->cap, t->n + 1, 9 * sizeof *np, 16);
    if (np == NULL)
        return CF_STATUS_NO_MEMORY;
    t->p = np;
    memcpy(np + 9 * t->n, a, 3 * sizeof *np);
    memcpy(np + 9 * t->n + 3, b, 3 * sizeof *np);
    memcpy(np + 9 * t->n + 6, c, 3 * sizeof *np);
    t->n++;
    return CF_STATUS_OK;
}

void
cf__tris_fini(cf__tris_t *t)
{
    cf_free(t->p);
    memset(t, 0, sizeof *t);
}

/* ---- polygons ----------------------------------------------------------- */

static double
orient2(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* Whether q lies in the closed triangle a b c (counter-clockwise). */
static bool
in_tri2(const double *a, const double *b, const double *c, const double *q)
{
    return orient2(a, b, q) >= 0 && orient2(b, c, q) >= 0
        && orient2(c, a, q) >= 0;
}

/* ---- ear clipping ------------------------------------------------------ */

enum { ALIVE = 1, REFLEX = 2, EAR = 4 };

typedef struct ears {
    const double *q;
    const size_t *idx;
    size_t *prev, *next;          /* neighbours, by rank (place in idx) */
    unsigned char *state;
    size_t *queue, head, tail;    /* ranks that were ears, in turn */
    /* the vertices that do not turn counter-clockwise, in a grid */
    double x0, y0, sx, sy;
    size_t g, *cell, *item;       /* cell c's items: item[cell[c]..) */
} ears_t;

static const double *
at(const ears_t *e, size_t r)
{
    return e->q + 2 * e->idx[r];
}

static size_t
cell_of(double v, double v0, double s, size_t g)
{
    double c = (v - v0) * s;
    return c >= (double)g ? g - 1 : c > 0 ? (size_t)c : 0;
}

static bool
turns_left(const ears_t *e, size_t r)
{
    return orient2(at(e, e->prev[r]), at(e, r), at(e, e->next[r])) > 0;
}

/* fmin and fmax of finite numbers, without a call. */
static double
lesser(double a, double b)
{
    return a < b ? a : b;
}

static double
greater(double a, double b)
{
    return a > b ? a : b;
}

/* The x range of triangle v (closed) between heights lo and hi. */
static void
row_span(const double *const v[3], double lo, double hi, double *x0,
         double *x1)
{
    *x0 = INFINITY;
    *x1 = -INFINITY;
    for (int k = 0; k < 3; k++) {
        const double *a = v[k], *b = v[(k + 1) % 3];
        double ylo = greater(lesser(a[1], b[1]), lo);
        double yhi = lesser(greater(a[1], b[1]), hi);
        if (ylo > yhi)
            continue;        /* the edge misses the band */
        if (a[1] == b[1]) {
            *x0 = lesser(*x0, lesser(a[0], b[0]));
            *x1 = greater(*x1, greater(a[0], b[0]));
        } else {
            double s = (b[0] - a[0]) / (b[1] - a[1]);
            double xa = a[0] + (ylo - a[1]) * s, xb = a[0] + (yhi - a[1]) * s;
            *x0 = lesser(*x0, lesser(xa, xb));
            *x1 = greater(*x1, greater(xa, xb));
        }
    }
}

/* Whether vertex b is an ear: its triangle turns counter-clockwise and
** holds no other vertex that is left and does not.  The grid's cells are
** asked row by row, each row from a cell left of where the triangle
** crosses it to a cell right of it (a thin triangle across the polygon
** asks the cells along it, not its whole box). */
static bool
is_ear(const ears_t *e, size_t b)
{
    size_t a = e->prev[b], c = e->next[b];
    const double *pa = at(e, a), *pb = at(e, b), *pc = at(e, c);
    const double *const v[3] = { pa, pb, pc };
    double h = e->sy > 0 ? 1 / e->sy : 0;
    size_t iy0, iy1, bx0, bx1;
    bool rows;
    if (!(orient2(pa, pb, pc) > 0))
        return false;
    iy0 = cell_of(lesser(pa[1], lesser(pb[1], pc[1])), e->y0, e->sy, e->g);
    iy1 = cell_of(greater(pa[1], greater(pb[1], pc[1])), e->y0, e->sy, e->g);
    bx0 = cell_of(lesser(pa[0], lesser(pb[0], pc[0])), e->x0, e->sx, e->g);
    bx1 = cell_of(greater(pa[0], greater(pb[0], pc[0])), e->x0, e->sx, e->g);
    rows = (iy1 - iy0 + 1) * (bx1 - bx0 + 1) > 64 && h > 0;
    for (size_t iy = iy0; iy <= iy1; iy++) {
        double x0, x1;
        size_t ix0 = bx0, ix1 = bx1;
        if (rows) {     /* the row, widened for rounding */
            row_span(v, e->y0 + ((double)iy - 1e-6) * h,
                     e->y0 + ((double)iy + 1 + 1e-6) * h, &x0, &x1);
            if (x0 > x1)
                continue;
            ix0 = cell_of(x0, e->x0, e->sx, e->g);
            ix1 = cell_of(x1, e->x0, e->sx, e->g);
            ix0 = ix0 > bx0 ? ix0 - 1 : bx0;
            ix1 = ix1 < bx1 ? ix1 + 1 : bx1;
        }
        for (size_t ix = ix0; ix <= ix1; ix++) {
            size_t cl = iy * e->g + ix;
            for (size_t k = e->cell[cl]; k < e->cell[cl + 1]; k++) {
                size_t w = e->item[k];
                if ((e->state[w] & (ALIVE | REFLEX)) == (ALIVE | REFLEX)
                    && w != a && w != b && w != c
                    && in_tri2(pa, pb, pc, at(e, w)))
                    return false;
            }
        }
    }
    return true;
}

/* Vertex r's turn and ear again, after a neighbour was cut off. */
static void
update(ears_t *e, size_t r)
{
    if ((e->state[r] & REFLEX) && turns_left(e, r))
        e->state[r] &= (unsigned char)~REFLEX;
    e->state[r] &= (unsigned char)~EAR;
    if (is_ear(e, r)) {
        e->state[r] |= EAR;
        e->queue[e->tail++] = r;
    }
}

/* The grid of the vertices that turn right or go straight: about one a
** cell. */
static bool
grid_build(ears_t *e, size_t m)
{
    double lo[2] = { INFINITY, INFINITY }, hi[2] = { -INFINITY, -INFINITY };
    size_t nr = 0, g = 1, ncell;
    for (size_t r = 0; r < m; r++)
        if (e->state[r] & REFLEX) {
            nr++;
            for (int k = 0; k < 2; k++) {
                lo[k] = fmin(lo[k], at(e, r)[k]);
                hi[k] = fmax(hi[k], at(e, r)[k]);
            }
        }
    while (g < 1024 && g * g < nr)
        g++;
    ncell = g * g;
    e->g = g;
    e->x0 = nr > 0 ? lo[0] : 0;
    e->y0 = nr > 0 ? lo[1] : 0;
    e->sx = nr > 0 && hi[0] > lo[0] ? (double)g / (hi[0] - lo[0]) : 0;
    e->sy = nr > 0 && hi[1] > lo[1] ? (double)g / (hi[1] - lo[1]) : 0;
    e->cell = cf_calloc(ncell + 1, sizeof *e->cell);
    e->item = cf_alloc_array(nr + 1, sizeof *e->item);
    if (e->cell == NULL || e->item == NULL)
        return false;
    for (size_t r = 0; r < m; r++)
        if (e->state[r] & REFLEX)
            e->cell[cell_of(at(e, r)[1], e->y0, e->sy, g) * g
                    + cell_of(at(e, r)[0], e->x0, e->sx, g) + 1]++;
    for (size_t c = 0; c < ncell; c++)
        e->cell[c + 1] += e->cell[c];
    for (size_t r = 0; r < m; r++)
        if (e->state[r] & REFLEX)
            e->item[e->cell[cell_of(at(e, r)[1], e->y0, e->sy, g) * g
                            + cell_of(at(e, r)[0], e->x0, e->sx, g)]++] = r;
    for (size_t c = ncell; c > 0; c--)     /* back to the cells' starts */
        e->cell[c] = e->cell[c - 1];
    e->cell[0] = 0;
    return true;
}

static void
emit(const ears_t *e, size_t a, size_t b, size_t c, size_t *tri, size_t *nt)
{
    tri[3 * *nt] = e->idx[a];
    tri[3 * *nt + 1] = e->idx[b];
    tri[3 * *nt + 2] = e->idx[c];
    (*nt)++;
}

bool
cf__ear_clip(const double *q, const size_t *idx, size_t m, size_t *tri,
             size_t *nt)
{
    ears_t e;
    size_t left = m, first = 0;
    bool ok;
    memset(&e, 0, sizeof e);
    *nt = 0;
    if (m < 3)
        return true;
    e.q = q;
    e.idx = idx;
    e.prev = cf_alloc_array(m, sizeof *e.prev);
    e.next = cf_alloc_array(m, sizeof *e.next);
    e.state = cf_alloc_array(m, sizeof *e.state);
    e.queue = cf_alloc_array(3 * m, sizeof *e.queue);   /* m + 2 a cut */
    ok = e.prev != NULL && e.next != NULL && e.state != NULL
        && e.queue != NULL;
    for (size_t r = 0; ok && r < m; r++) {
        e.prev[r] = r == 0 ? m - 1 : r - 1;
        e.next[r] = r + 1 == m ? 0 : r + 1;
    }
    for (size_t r = 0; ok && r < m; r++)
        e.state[r] = turns_left(&e, r) ? ALIVE : ALIVE | REFLEX;
    ok = ok && grid_build(&e, m);
    for (size_t r = 0; ok && r < m; r++)
        if (is_ear(&e, r)) {
            e.state[r] |= EAR;
            e.queue[e.tail++] = r;
        }
    while (ok && left > 3 && e.head < e.tail) {
        size_t b = e.queue[e.head++], a, c;
        if ((e.state[b] & (ALIVE | EAR)) != (ALIVE | EAR))
            continue;
        a = e.prev[b];
        c = e.next[b];
        emit(&e, a, b, c, tri, nt);
        e.next[a] = c;
        e.prev[c] = a;
        e.state[b] = 0;
        left--;
        update(&e, a);
        update(&e, c);
    }
    /* what is left, three vertices or a polygon without ears: the fan of
    ** its first vertex, each triangle with its sign */
    while (ok && !(e.state[first] & ALIVE))
        first++;
    for (size_t r = ok ? e.next[first] : first; r != first
                                                && e.next[r] != first;
         r = e.next[r])
        if (orient2(at(&e, first), at(&e, r), at(&e, e.next[r])) != 0)
            emit(&e, first, r, e.next[r], tri, nt);
    cf_free(e.prev);
    cf_free(e.next);
    cf_free(e.state);
    cf_free(e.queue);
    cf_free(e.cell);
    cf_free(e.item);
    return ok;
}

cf_status_t
cf__region_polygon(cf_figure_t *fig, const double *p, size_t n,
                   const char *what, cf__tris_t *out, bool *planar)
{
    double nn[3] = { 0, 0, 0 }, u[3], v[3], size = cf__points_size(p, n), d1, d2;
    double *q = cf_alloc_array(2 * n, sizeof *q), area = 0, len;
    size_t *idx = cf_alloc_array(n, sizeof *idx);
    size_t *tri = cf_alloc_array(3 * n, sizeof *tri), nt = 0, m = 0;
    size_t i1 = cf__farthest(p, n, p, &d1), i2;
    cf_status_t st = CF_STATUS_OK;
    *planar = true;
    if (q == NULL || idx == NULL || tri == NULL) {
        st = cf__fig_nomem(fig, what);
        goto done;
    }
    i2 = cf__farthest_line(p, n, p, p + 3 * i1, &d2);
    if (!(d1 > 1e-9 * size) || !(d2 > 1e-9 * size)) {
        st = cf_diag_set(&fig->err, CF_STATUS_DEGENERATE, -1,
                         "its %zu points lie on one line: no region to "
                         "fill (a %s needs three points off one line)", n,
                         what);
        goto done;
    }
    /* Newell's normal: the plane of the polygon (of its largest triangle
    ** when the areas cancel) */
    for (size_t i = 0; i < n; i++) {
        const double *a = p + 3 * i, *b = p + 3 * ((i + 1) % n);
        nn[0] += (a[1] - b[1]) * (a[2] + b[2]);
        nn[1] += (a[2] - b[2]) * (a[0] + b[0]);
        nn[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    if (!(cf__norm3(nn) > 1e-9 * size * size)) {
        double ab[3], ac[3];
        cf__sub3(p + 3 * i1, p, ab);
        cf__sub3(p + 3 * i2, p, ac);
        cf__cross3(ab, ac, nn);
    }
    len = cf__norm3(nn);     /* once: nn changes as it is divided */
    for (int k = 0; k < 3; k++)
        nn[k] /= len;
    cf__sub3(p + 3 * i1, p, u);
    for (int k = 0; k < 3; k++)
        u[k] /= d1;
    cf__cross3(nn, u, v);
    for (size_t i = 0; i < n; i++) {
        double d[3];
        cf__sub3(p + 3 * i, p, d);
        q[2 * i] = cf__dot3(d, u);
        q[2 * i + 1] = cf__dot3(d, v);
        if (fabs(cf__dot3(d, nn)) > 1e-9 * size)
            *planar = false;
    }
    /* the vertices counter-clockwise, repeated ones once */
    for (size_t i = 0; i < n; i++)
        area += orient2(q, q + 2 * i, q + 2 * ((i + 1) % n));
    for (size_t k = 0; k < n; k++) {
        size_t i = area >= 0 ? k : n - 1 - k;
        if (m == 0 || hypot(q[2 * i] - q[2 * idx[m - 1]],
                            q[2 * i + 1] - q[2 * idx[m - 1] + 1])
                          > 1e-12 * size)
            idx[m++] = i;
    }
    if (m > 1 && hypot(q[2 * idx[0]] - q[2 * idx[m - 1]],
                       q[2 * idx[0] + 1] - q[2 * idx[m - 1] + 1])
                     <= 1e-12 * size)
        m--;
    if (!cf__ear_clip(q, idx, m, tri, &nt)) {
        st = cf__fig_nomem(fig, what);
        goto done;
    }
    for (size_t t = 0; t < nt && st == CF_STATUS_OK; t++)
        if (cf__tris_add(out, p + 3 * tri[3 * t], p + 3 * tri[3 * t + 1],
                         p + 3 * tri[3 * t + 2]) != CF_STATUS_OK)
            st = cf__fig_nomem(fig, what);
done:
    cf_free(q);
    cf_free(idx);
    cf_free(tri);
    return st;
}

