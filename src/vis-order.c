/* Painting order of facets below quadratic cost (vis-private.h).
**
** Only facets whose images overlap need an order between them.  The
** facets' image boxes go into a uniform grid; each pair of facets sharing
** a cell, whose boxes overlap, is compared once (in the cell holding the
** low corner of the boxes' intersection): the intersection of their
** images (one triangle clipped by the other) and, at its corners, the
** depth of each facet's plane in view space (where lines of sight are
** lines of constant image, so depth is affine on a facet's image).  The
** nearer facet is painted after the other; a pair that crosses (nearer
** at one corner, farther at another) gets both constraints.  Facets that
** must be painted in a cycle (crossing facets, cyclic overlaps) then form
** the strongly connected components of the constraint graph (Tarjan):
** each such component is ordered by the BSP tree of vis-bsp.c, which
** splits its facets, and the components are painted in topological order
** of the graph.  A facet of a component meets every constraint of the
** facet it was split from, so the order is right for every overlapping
** pair.  With facets of similar size the grid holds a few facets a cell
** and the cost is about linear; the grid's entries are bounded, so the
** memory is linear in the number of facets whatever their sizes.
*/
#include <math.h>
#include <string.h>

#include "vis-private.h"

typedef struct edge { size_t from, to; } edge_t;

typedef struct order {
    double *q;             /* view-space corners, 9 a facet */
    double *box;           /* image boxes x0 y0 x1 y1 */
    double eps, area_eps;
    size_t *seen;          /* seen[j] == L: small facet j met large L */
    edge_t *edges;
    size_t nedges, ecap;
} order_t;

static double
cross2(const double *o, const double *a, const double *b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

/* Depth at image point x of the plane of facet corners q (view space). */
static double
depth_at(const double *q, double area, const double *x)
{
    double a[2] = {q[0], q[1]}, b[2] = {q[3], q[4]}, c[2] = {q[6], q[7]};
    double wb = cross2(a, x, c) / area, wc = cross2(a, b, x) / area;
    return q[2] + wb * (q[5] - q[2]) + wc * (q[8] - q[2]);
}

/* Polygon p (n points) clipped to the side of line a-b where s * cross
** is positive; the new count. */
static int
clip_edge(const double (*p)[2], int n, const double *a, const double *b,
          double s, double (*out)[2])
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        const double *u = p[i], *v = p[(i + 1) % n];
        double du = s * cross2(a, b, u), dv = s * cross2(a, b, v);
        if (du >= 0)
            memcpy(out[m++], u, sizeof out[0]);
        if ((du > 0 && dv < 0) || (du < 0 && dv > 0)) {
            double t = du / (du - dv);
            out[m][0] = u[0] + t * (v[0] - u[0]);
            out[m][1] = u[1] + t * (v[1] - u[1]);
            m++;
        }
    }
    return m;
}

static cf_status_t
add_edge(order_t *o, size_t from, size_t to)
{
    edge_t *e = cf__grow(o->edges, &o->ecap, o->nedges + 1, sizeof *e, 256);
    if (e == NULL)
        return CF_STATUS_NO_MEMORY;
    o->edges = e;
    e[o->nedges].from = from;
    e[o->nedges].to = to;
    o->nedges++;
    return CF_STATUS_OK;
}

/* The constraints between facets i and j whose boxes overlap. */
static cf_status_t
compare(order_t *o, size_t i, size_t j)
{
    const double *qi = o->q + 9 * i, *qj = o->q + 9 * j;
    double ai[2] = {qi[0], qi[1]}, bi[2] = {qi[3], qi[4]},
           ci[2] = {qi[6], qi[7]};
    double aj[2] = {qj[0], qj[1]}, bj[2] = {qj[3], qj[4]},
           cj[2] = {qj[6], qj[7]};
    double areai = cross2(ai, bi, ci), areaj = cross2(aj, bj, cj);
    double poly[2][12][2];
    int n = 3;
    if (fabs(areai) <= o->area_eps || fabs(areaj) <= o->area_eps)
        return CF_STATUS_OK;   /* seen edge-on: hides nothing */
    memcpy(poly[0][0], ai, sizeof ai);
    memcpy(poly[0][1], bi, sizeof bi);
    memcpy(poly[0][2], ci, sizeof ci);
    double s = areaj > 0 ? 1.0 : -1.0;
    const double *cj3[3] = {aj, bj, cj};
    int cur = 0;
    for (int k = 0; k < 3 && n > 0; k++) {
        n = clip_edge((const double (*)[2])poly[cur], n, cj3[k],
                      cj3[(k + 1) % 3], s, poly[1 - cur]);
        cur = 1 - cur;
    }
    if (n < 3)
        return CF_STATUS_OK;
    double area = 0, lo = HUGE_VAL, hi = -HUGE_VAL;
    for (int k = 0; k < n; k++)
        area += cross2(poly[cur][0], poly[cur][k], poly[cur][(k + 1) % n]);
    if (fabs(area) <= o->area_eps)
        return CF_STATUS_OK;   /* the images only touch */
    for (int k = 0; k < n; k++) {
        double d = depth_at(qi, areai, poly[cur][k]) -
                   depth_at(qj, areaj, poly[cur][k]);
        lo = fmin(lo, d);
        hi = fmax(hi, d);
    }
    cf_status_t st = CF_STATUS_OK;
    if (hi > o->eps)           /* i nearer somewhere: j first */
        st = add_edge(o, j, i);
    if (lo < -o->eps && st == CF_STATUS_OK)
        st = add_edge(o, i, j);
    return st;
}

/* Whether the boxes of i and j overlap (with an inside); the overlap's
** low corner into lo. */
static bool
boxes_meet(const order_t *o, size_t i, size_t j, double *lo)
{
    const double *bi = o->box + 4 * i, *bj = o->box + 4 * j;
    lo[0] = fmax(bi[0], bj[0]);
    lo[1] = fmax(bi[1], bj[1]);
    return lo[0] < fmin(bi[2], bj[2]) && lo[1] < fmin(bi[3], bj[3]);
}

typedef struct grid {
    double lo[2], cell;
    size_t nx, ny;
    size_t *start, *items;    /* cell c: items[start[c] .. start[c + 1]) */
} grid_t;

static size_t
cell_of(const grid_t *g, double v, int axis)
{
    double t = (v - g->lo[axis]) / g->cell;
    size_t k = t > 0 ? (size_t)t : 0, n = axis == 0 ? g->nx : g->ny;
    return k < n ? k : n - 1;
}

/* Every overlapping pair of the facets set[0..n), each compared once.
** Boxes more than SMALL_CELLS cells wide or high (of a grid whose cells
** are about the mean box) are large: the small ones go into the grid and
** are paired within it; each large one meets the small ones in the cells
** under it; the large ones among themselves the same way, recursively
** (they are at most a third of the set).  So the grid has at most
** (SMALL_CELLS + 1)^2 entries a facet whatever the boxes' sizes. */
#define SMALL_CELLS 4
#define BRUTE_MAX 32

static cf_status_t
compare_set(order_t *o, const size_t *set, size_t n)
{
    cf_status_t st = CF_STATUS_OK;
    double lo[2];
    if (n <= BRUTE_MAX) {
        for (size_t a = 0; a < n && st == CF_STATUS_OK; a++)
            for (size_t b = a + 1; b < n && st == CF_STATUS_OK; b++)
                if (boxes_meet(o, set[a], set[b], lo))
                    st = compare(o, set[a], set[b]);
        return st;
    }
    grid_t g;
    double hi[2] = {-HUGE_VAL, -HUGE_VAL}, mean = 0.0;
    g.lo[0] = g.lo[1] = HUGE_VAL;
    for (size_t k = 0; k < n; k++) {
        const double *b = o->box + 4 * set[k];
        g.lo[0] = fmin(g.lo[0], b[0]);
        g.lo[1] = fmin(g.lo[1], b[1]);
        hi[0] = fmax(hi[0], b[2]);
        hi[1] = fmax(hi[1], b[3]);
        mean += fmax(b[2] - b[0], b[3] - b[1]) / (double)n;
    }
    double w = hi[0] - g.lo[0], h = hi[1] - g.lo[1];
    /* cells about the mean box, at most about 4 n of them */
    g.cell = fmax(mean, sqrt(w * h / (4.0 * (double)n)));
    g.cell = fmax(g.cell, 1e-9 * fmax(w, h));
    if (!(g.cell > 0))
        g.cell = 1.0;
    g.nx = (size_t)(w / g.cell) + 1;
    g.ny = (size_t)(h / g.cell) + 1;
    size_t ncell = g.nx * g.ny;
    size_t *large = cf__alloc_array(n, sizeof *large), nlarge = 0;
    g.start = cf__calloc(ncell + 1, sizeof *g.start);
    g.items = NULL;
    if (large == NULL || g.start == NULL) {
        cf__free(large);
        cf__free(g.start);
        return CF_STATUS_NO_MEMORY;
    }
    /* counts of the small ones, then each cell's items after its start */
    for (int pass = 0; pass < 2; pass++) {
        for (size_t k = 0; k < n; k++) {
            const double *b = o->box + 4 * set[k];
            size_t x0 = cell_of(&g, b[0], 0), x1 = cell_of(&g, b[2], 0),
                   y0 = cell_of(&g, b[1], 1), y1 = cell_of(&g, b[3], 1);
            if (x1 - x0 > SMALL_CELLS || y1 - y0 > SMALL_CELLS) {
                if (pass == 0)
                    large[nlarge++] = set[k];
                continue;
            }
            for (size_t y = y0; y <= y1; y++)
                for (size_t x = x0; x <= x1; x++) {
                    if (pass == 0)
                        g.start[y * g.nx + x + 1]++;
                    else
                        g.items[g.start[y * g.nx + x]++] = set[k];
                }
        }
        if (pass > 0)
            break;
        for (size_t c = 0; c < ncell; c++)
            g.start[c + 1] += g.start[c];
        g.items = cf__alloc_array(g.start[ncell] + 1, sizeof *g.items);
        if (g.items == NULL) {
            cf__free(large);
            cf__free(g.start);
            return CF_STATUS_NO_MEMORY;
        }
    }
    /* g.start[c] is now the end of cell c; undo that shift */
    for (size_t c = ncell; c > 0; c--)
        g.start[c] = g.start[c - 1];
    g.start[0] = 0;
    /* small with small, once: in the cell of the overlap's low corner */
    for (size_t c = 0; c < ncell && st == CF_STATUS_OK; c++) {
        size_t cx = c % g.nx, cy = c / g.nx;
        for (size_t a = g.start[c]; a < g.start[c + 1] && st == CF_STATUS_OK;
             a++)
            for (size_t b = a + 1; b < g.start[c + 1] && st == CF_STATUS_OK;
                 b++) {
                size_t i = g.items[a], j = g.items[b];
                if (boxes_meet(o, i, j, lo) && cell_of(&g, lo[0], 0) == cx
                    && cell_of(&g, lo[1], 1) == cy)
                    st = compare(o, i, j);
            }
    }
    /* large with small: in the cells the large one's image meets (row by
    ** row: the triangle clipped to the row's slab), each small one once */
    for (size_t k = 0; k < nlarge && st == CF_STATUS_OK; k++) {
        size_t L = large[k];
        const double *q = o->q + 9 * L, *b = o->box + 4 * L;
        size_t y0 = cell_of(&g, b[1], 1), y1 = cell_of(&g, b[3], 1);
        for (size_t y = y0; y <= y1 && st == CF_STATUS_OK; y++) {
            double poly[2][8][2], ya = g.lo[1] + (double)y * g.cell,
                   yb = ya + g.cell;
            double a0[2] = {0.0, ya}, a1[2] = {1.0, ya}, b0[2] = {0.0, yb},
                   b1[2] = {1.0, yb};
            double xa = HUGE_VAL, xb = -HUGE_VAL;
            int m = 3, cur = 0;
            for (int c = 0; c < 3; c++) {
                poly[0][c][0] = q[3 * c];
                poly[0][c][1] = q[3 * c + 1];
            }
            /* y >= ya, then y <= yb; the first row and the last reach
            ** to the box (cell_of clamps) */
            if (y > y0) {
                m = clip_edge((const double (*)[2])poly[cur], m, a0, a1, 1.0,
                              poly[1 - cur]);
                cur = 1 - cur;
            }
            if (y < y1 && m > 0) {
                m = clip_edge((const double (*)[2])poly[cur], m, b0, b1, -1.0,
                              poly[1 - cur]);
                cur = 1 - cur;
            }
            if (m == 0)
                continue;
            for (int c = 0; c < m; c++) {
                xa = fmin(xa, poly[cur][c][0]);
                xb = fmax(xb, poly[cur][c][0]);
            }
            size_t x0 = cell_of(&g, xa, 0), x1 = cell_of(&g, xb, 0);
            for (size_t x = x0; x <= x1 && st == CF_STATUS_OK; x++) {
                size_t c = y * g.nx + x;
                for (size_t a = g.start[c];
                     a < g.start[c + 1] && st == CF_STATUS_OK; a++) {
                    size_t j = g.items[a];
                    if (o->seen[j] == L || !boxes_meet(o, L, j, lo))
                        continue;
                    o->seen[j] = L;
                    st = compare(o, L, j);
                }
            }
        }
    }
    cf__free(g.start);
    cf__free(g.items);
    /* large with large */
    if (st == CF_STATUS_OK && nlarge > 0)
        st = compare_set(o, large, nlarge);
    cf__free(large);
    return st;
}

static cf_status_t
compare_pairs(order_t *o, size_t n)
{
    size_t *all = cf__alloc_array(n, sizeof *all);
    if (all == NULL)
        return CF_STATUS_NO_MEMORY;
    for (size_t i = 0; i < n; i++)
        all[i] = i;
    cf_status_t st = compare_set(o, all, n);
    cf__free(all);
    return st;
}

/* Tarjan's strongly connected components of the graph (CSR: the
** successors of v are adj[first[v] .. first[v + 1])), iteratively; the
** members of each component into members, in the order the components
** are found (a component after every one it reaches), with comp_end[k]
** the end of component k; the number of components. */
static size_t
tarjan(size_t n, const size_t *first, const size_t *adj, size_t *members,
       size_t *comp_end, size_t *work)
{
    const size_t NONE = (size_t)-1;
    size_t *index = work, *low = work + n, *stack = work + 2 * n,
           *call = work + 3 * n, *pos = work + 4 * n;
    bool *on = (bool *)(work + 5 * n);
    size_t counter = 0, top = 0, ncall = 0, ncomp = 0, nmem = 0;
    for (size_t v = 0; v < n; v++) {
        index[v] = NONE;
        on[v] = false;
    }
    for (size_t root = 0; root < n; root++) {
        if (index[root] != NONE)
            continue;
        call[ncall++] = root;
        pos[root] = first[root];
        index[root] = low[root] = counter++;
        stack[top++] = root;
        on[root] = true;
        while (ncall > 0) {
            size_t v = call[ncall - 1];
            if (pos[v] < first[v + 1]) {
                size_t w = adj[pos[v]++];
                if (index[w] == NONE) {
                    index[w] = low[w] = counter++;
                    stack[top++] = w;
                    on[w] = true;
                    pos[w] = first[w];
                    call[ncall++] = w;
                } else if (on[w] && index[w] < low[v]) {
                    low[v] = index[w];
                }
                continue;
            }
            ncall--;
            if (ncall > 0) {
                size_t u = call[ncall - 1];
                if (low[v] < low[u])
                    low[u] = low[v];
            }
            if (low[v] == index[v]) {
                size_t w;
                do {
                    w = stack[--top];
                    on[w] = false;
                    members[nmem++] = w;
                } while (w != v);
                comp_end[ncomp++] = nmem;
            }
        }
    }
    return ncomp;
}

/* Append the facets of a component of several (members m[0..k)) to fb in
** the BSP tree's order (its pieces where it splits them), their indices
** to *ord (capacity *cap, grown as needed; *no used). */
static cf_status_t
order_component(cf__facet_buf_t *fb, const cf_view_t *view, double eps,
                const size_t *m, size_t k, size_t **ord, size_t *cap,
                size_t *no, size_t *splits)
{
    cf__facet_buf_t tb = {NULL, 0, 0};
    size_t *sub = NULL, nsub = 0, sp = 0;
    tb.items = cf__alloc_array(k, sizeof *tb.items);
    if (tb.items == NULL)
        return CF_STATUS_NO_MEMORY;
    tb.cap = k;
    for (size_t i = 0; i < k; i++)
        tb.items[tb.n++] = fb->items[m[i]];
    cf_status_t st = cf__bsp_order(&tb, view, eps, &sub, &nsub, &sp);
    for (size_t i = 0; i < nsub && st == CF_STATUS_OK; i++) {
        cf_facet_t *g = cf__grow(fb->items, &fb->cap, fb->n + 1, sizeof *g,
                                 64);
        size_t *h = cf__grow(*ord, cap, *no + 1, sizeof *h, 64);
        if (g != NULL)
            fb->items = g;
        if (h != NULL)
            *ord = h;
        if (g == NULL || h == NULL) {
            st = CF_STATUS_NO_MEMORY;
            break;
        }
        g[fb->n] = tb.items[sub[i]];
        (*ord)[(*no)++] = fb->n++;
    }
    *splits += sp;
    cf__free(sub);
    cf__free(tb.items);
    return st;
}

cf_status_t
cf__facet_order(cf__facet_buf_t *fb, const cf_view_t *view,
                const double M[16], double eps, size_t **order,
                size_t *norder, size_t *splits)
{
    size_t n = fb->n;
    order_t o;
    cf_status_t st = CF_STATUS_OK;
    *order = NULL;
    *norder = 0;
    *splits = 0;
    if (n == 0)
        return CF_STATUS_OK;
    memset(&o, 0, sizeof o);
    o.eps = eps;
    o.q = cf__alloc_array(n, 9 * sizeof *o.q);
    o.box = cf__alloc_array(n, 4 * sizeof *o.box);
    o.seen = cf__alloc_array(n, sizeof *o.seen);
    if (o.q == NULL || o.box == NULL || o.seen == NULL) {
        cf__free(o.q);
        cf__free(o.box);
        cf__free(o.seen);
        return CF_STATUS_NO_MEMORY;
    }
    for (size_t i = 0; i < n; i++)
        o.seen[i] = (size_t)-1;
    double span = 0.0;
    for (size_t i = 0; i < n && st == CF_STATUS_OK; i++) {
        double *q = o.q + 9 * i, *b = o.box + 4 * i;
        for (int k = 0; k < 3; k++)
            if (!cf__view_apply(M, fb->items[i].p + 3 * k, q + 3 * k))
                st = CF_STATUS_DOMAIN;
        b[0] = fmin(q[0], fmin(q[3], q[6]));
        b[1] = fmin(q[1], fmin(q[4], q[7]));
        b[2] = fmax(q[0], fmax(q[3], q[6]));
        b[3] = fmax(q[1], fmax(q[4], q[7]));
        span = fmax(span, fmax(fabs(b[0]), fmax(fabs(b[1]),
                                                fmax(fabs(b[2]),
                                                     fabs(b[3])))));
    }
    if (st != CF_STATUS_OK) {
        /* a corner at the eye (the scene refuses control points there):
        ** the tree alone */
        cf__free(o.q);
        cf__free(o.box);
        cf__free(o.seen);
        return cf__bsp_order(fb, view, eps, order, norder, splits);
    }
    /* areas below this are rounding (cross products of coordinates of
    ** magnitude span) */
    o.area_eps = 1e-12 * span * span;
    st = compare_pairs(&o, n);
    cf__free(o.q);
    cf__free(o.box);
    cf__free(o.seen);
    /* the graph as CSR, its components, then the order */
    size_t *first = NULL, *adj = NULL, *members = NULL, *cend = NULL,
           *work = NULL, *ord = NULL;
    if (st == CF_STATUS_OK) {
        first = cf__calloc(n + 1, sizeof *first);
        adj = cf__alloc_array(o.nedges + 1, sizeof *adj);
        members = cf__alloc_array(n, sizeof *members);
        cend = cf__alloc_array(n, sizeof *cend);
        work = cf__alloc_array(n, 6 * sizeof *work);
        if (first == NULL || adj == NULL || members == NULL || cend == NULL
            || work == NULL)
            st = CF_STATUS_NO_MEMORY;
    }
    if (st == CF_STATUS_OK) {
        for (size_t e = 0; e < o.nedges; e++)
            first[o.edges[e].from + 1]++;
        for (size_t v = 0; v < n; v++)
            first[v + 1] += first[v];
        size_t *fill = work;
        memcpy(fill, first, n * sizeof *fill);
        for (size_t e = 0; e < o.nedges; e++)
            adj[fill[o.edges[e].from]++] = o.edges[e].to;
    }
    cf__free(o.edges);
    size_t no = 0, cap = n, sp = 0;
    if (st == CF_STATUS_OK) {
        size_t ncomp = tarjan(n, first, adj, members, cend, work);
        ord = cf__alloc_array(cap, sizeof *ord);
        if (ord == NULL)
            st = CF_STATUS_NO_MEMORY;
        /* a component is found after those it reaches: paint backwards */
        for (size_t c = ncomp; c-- > 0 && st == CF_STATUS_OK;) {
            size_t b = c == 0 ? 0 : cend[c - 1], k = cend[c] - b;
            if (k == 1) {
                size_t *g = cf__grow(ord, &cap, no + 1, sizeof *ord, 64);
                if (g == NULL) {
                    st = CF_STATUS_NO_MEMORY;
                    break;
                }
                ord = g;
                ord[no++] = members[b];
                continue;
            }
            st = order_component(fb, view, eps, members + b, k, &ord, &cap,
                                 &no, &sp);
        }
    }
    cf__free(first);
    cf__free(adj);
    cf__free(members);
    cf__free(cend);
    cf__free(work);
    if (st != CF_STATUS_OK) {
        cf__free(ord);
        return st;
    }
    *order = ord;
    *norder = no;
    *splits = sp;
    return CF_STATUS_OK;
}
