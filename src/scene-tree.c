/* The pieces of a scene's patches and the box tree over them
** (vis-private.h). */
#include <math.h>
#include <string.h>

#include "vis-private.h"

/* Pieces: a subdivision level at most this deep, and at most MAX_LEAVES
** per patch (then the rest are kept as they are: Newton still decides). */
#define MAX_LEVEL 26
#define MAX_LEAVES 65536

typedef struct piece {
    double r[6];
    int level;
} piece_t;

CF__NO_COVERAGE static double
dist3(const double *a, const double *b)
{
    double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
    return sqrt(x * x + y * y + z * z);
}

CF__NO_COVERAGE static double
cross2(const double *o, const double *a, const double *b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

static size_t
tidx(int n, int i, int j)
{
    size_t r = (size_t)(n - i);
    return r * (r + 1) / 2 + (r - (size_t)j);
}

CF__NO_COVERAGE void
cf__vnet_measure(const cf__vpatch_t *p, const double *net, double *c,
                 cf__vmeasure_t *ms)
{
    size_t cnt = cf__vpatch_count(p);
    double wmin = HUGE_VAL, wmax = 0.0, pos = 0.0, neg = 0.0;
    for (int k = 0; k < 3; k++) {
        ms->lo[k] = HUGE_VAL;
        ms->hi[k] = -HUGE_VAL;
    }
    for (size_t i = 0; i < cnt; i++) {
        const double *g = net + 4 * i;
        for (int k = 0; k < 3; k++) {
            c[3 * i + k] = g[k] / g[3];
            ms->lo[k] = cf__fmin(ms->lo[k], c[3 * i + k]);
            ms->hi[k] = cf__fmax(ms->hi[k], c[3 * i + k]);
        }
        wmin = cf__fmin(wmin, g[3]);
        wmax = cf__fmax(wmax, g[3]);
    }
    ms->diam = dist3(ms->lo, ms->hi);
    ms->img = hypot(ms->hi[0] - ms->lo[0], ms->hi[1] - ms->lo[1]);
    ms->wratio = wmax / wmin;
    ms->dev = 0.0;
    int m = p->m, n = p->n;
    if (!p->tri) {
        const double *c00 = c, *c01 = c + 3 * (size_t)n,
                     *c10 = c + 3 * (size_t)m * ((size_t)n + 1),
                     *c11 = c10 + 3 * (size_t)n;
        ms->ext[0] = ms->ext[1] = 0.0;
        ms->twist = 0.25 * sqrt((c00[0] - c10[0] - c01[0] + c11[0]) *
                                    (c00[0] - c10[0] - c01[0] + c11[0]) +
                                (c00[1] - c10[1] - c01[1] + c11[1]) *
                                    (c00[1] - c10[1] - c01[1] + c11[1]) +
                                (c00[2] - c10[2] - c01[2] + c11[2]) *
                                    (c00[2] - c10[2] - c01[2] + c11[2]));
        for (int i = 0; i <= m; i++)
            for (int j = 0; j <= n; j++) {
                double a = (double)i / m, b = (double)j / n, q[3];
                const double *x = c + 3 * ((size_t)i * (n + 1) + j);
                for (int k = 0; k < 3; k++)
                    q[k] = (1 - a) * (1 - b) * c00[k] + (1 - a) * b * c01[k] +
                           a * (1 - b) * c10[k] + a * b * c11[k];
                ms->dev = cf__fmax(ms->dev, dist3(x, q));
                if (i < m && j < n) {
                    const double *x10 = x + 3 * ((size_t)n + 1), *x01 = x + 3,
                                 *x11 = x10 + 3;
                    double k1 = cross2(x, x10, x01), k2 = cross2(x11, x01, x10);
                    pos = cf__fmax(pos, cf__fmax(k1, k2));
                    neg = cf__fmin(neg, cf__fmin(k1, k2));
                }
            }
        /* extents along s and t: the largest distance in the image
        ** between the ends of a column (a row), or, where the columns
        ** (rows) are much longer than that (loops: a patch whose rows
        ** close up was never halved across them), the longest control
        ** polygon */
        for (int dir = 0; dir < 2; dir++) {
            int a = dir == 0 ? n : m, b = dir == 0 ? m : n;
            double poly = 0.0;
            for (int j = 0; j <= a; j++) {
                size_t e0 = dir == 0 ? (size_t)j : (size_t)j * (n + 1),
                       e1 = dir == 0 ? (size_t)m * (n + 1) + j : e0 + n;
                double len = 0.0;
                ms->ext[dir] = cf__fmax(ms->ext[dir],
                                    cf__norm2(c[3 * e1] - c[3 * e0],
                                          c[3 * e1 + 1] - c[3 * e0 + 1]));
                for (int i = 0; i < b; i++) {
                    size_t k0 = dir == 0 ? (size_t)i * (n + 1) + j
                                         : (size_t)j * (n + 1) + i,
                           k1 = dir == 0 ? k0 + (size_t)n + 1 : k0 + 1;
                    const double *x0 = c + 3 * k0, *x1 = c + 3 * k1;
                    len += cf__norm2(x1[0] - x0[0], x1[1] - x0[1]) +
                           1e-3 * dist3(x0, x1);
                }
                poly = cf__fmax(poly, len);
            }
            if (poly > 4.0 * ms->ext[dir])
                ms->ext[dir] = poly;
        }
    } else {
        ms->twist = 0.0;
        ms->ext[0] = ms->ext[1] = 0.0;
        const double *A = c + 3 * tidx(n, n, 0), *B = c + 3 * tidx(n, 0, n),
                     *C = c + 3 * tidx(n, 0, 0);
        for (int i = n; i >= 0; i--)
            for (int j = n - i; j >= 0; j--) {
                int k = n - i - j;
                double q[3];
                const double *x = c + 3 * tidx(n, i, j);
                for (int e = 0; e < 3; e++)
                    q[e] = ((double)i * A[e] + (double)j * B[e] +
                            (double)k * C[e]) / n;
                ms->dev = cf__fmax(ms->dev, dist3(x, q));
                if (i + j < n) {
                    /* the upward cell (i+1, j, k-1), (i, j+1, k-1), (i, j, k) */
                    double o = cross2(c + 3 * tidx(n, i + 1, j),
                                      c + 3 * tidx(n, i, j + 1), x);
                    pos = cf__fmax(pos, o);
                    neg = cf__fmin(neg, o);
                }
            }
    }
    double eps = 1e-9 * ms->img * ms->img;
    ms->fold = pos > eps && neg < -eps;
    ms->orient = ms->fold ? 0 : pos > eps ? 1 : neg < -eps ? -1 : 0;
}

/*
** The side normals and ranges of a leaf (cf__vleaf_t) from its Cartesian
** view-space control points c.  A point Newton accepts on the leaf is in
** its region up to 1e-9 (patch parameters; a triangle's leaf: 1e-9 of its
** barycentric coordinates, parameter distance below 4e-9), so its image is
** within 4e-9 dmax of the leaf's (dmax: a bound of the patch's first
** derivatives in the image), and it is found within 1e-9 of the scene's
** size (cf__leaf_may_hold adds that); the ranges are widened by 1e-8 dmax
** and by 1e-12 of the coordinates for the rounding of the products.
*/
CF__NO_COVERAGE static void
leaf_sides(const cf__vpatch_t *p, const double *c, double dmax,
           cf__vleaf_t *l)
{
    size_t cnt = cf__vpatch_count(p);
    double side[2][2], big = 0.0;
    int m = p->m, n = p->n;
    if (!p->tri) {
        const double *c00 = c, *c01 = c + 3 * (size_t)n,
                     *c10 = c + 3 * (size_t)m * ((size_t)n + 1),
                     *c11 = c10 + 3 * (size_t)n;
        for (int k = 0; k < 2; k++) {
            side[0][k] = (c10[k] + c11[k]) - (c00[k] + c01[k]);
            side[1][k] = (c01[k] + c11[k]) - (c00[k] + c10[k]);
        }
    } else {
        const double *A = c + 3 * tidx(n, n, 0), *B = c + 3 * tidx(n, 0, n),
                     *C = c + 3 * tidx(n, 0, 0);
        for (int k = 0; k < 2; k++) {
            side[0][k] = A[k] - C[k];
            side[1][k] = B[k] - C[k];
        }
    }
    double hn[2][2], lo[2], hi[2];
    for (int d = 0; d < 2; d++) {
        double len = hypot(side[d][0], side[d][1]);
        if (len > 0.0 && isfinite(len)) {
            l->hn[d][0] = (float)(-side[d][1] / len);
            l->hn[d][1] = (float)(side[d][0] / len);
        } else {
            l->hn[d][0] = d == 0 ? 1.0f : 0.0f;
            l->hn[d][1] = d == 0 ? 0.0f : 1.0f;
        }
        /* the ranges along the stored directions as they are */
        hn[d][0] = l->hn[d][0];
        hn[d][1] = l->hn[d][1];
        lo[d] = HUGE_VAL;
        hi[d] = -HUGE_VAL;
    }
    for (size_t i = 0; i < cnt; i++) {
        const double *x = c + 3 * i;
        big = cf__fmax(big, cf__fmax(fabs(x[0]), fabs(x[1])));
        for (int d = 0; d < 2; d++) {
            double v = hn[d][0] * x[0] + hn[d][1] * x[1];
            lo[d] = cf__fmin(lo[d], v);
            hi[d] = cf__fmax(hi[d], v);
        }
    }
    double e = 1e-8 * dmax + 1e-12 * big;
    for (int d = 0; d < 2; d++) {
        /* a NaN bound (a point at infinity): the side test passes; the
        ** floats rounded outwards */
        double a = isfinite(e) && isfinite(lo[d]) ? lo[d] - e : -HUGE_VAL,
               b = isfinite(e) && isfinite(hi[d]) ? hi[d] + e : HUGE_VAL;
        float fa = (float)a, fb = (float)b;
        if ((double)fa > a)
            fa = nextafterf(fa, -HUGE_VALF);
        if ((double)fb < b)
            fb = nextafterf(fb, HUGE_VALF);
        l->hlo[d] = fa;
        l->hhi[d] = fb;
    }
}

static cf_status_t
push_leaf(cf_scene_t *sc, size_t ip, const piece_t *pc,
          const cf__vmeasure_t *ms, const double *c, double dmax)
{
    cf__vleaf_t *l = cf__grow(sc->leaves, &sc->nleaf_cap, sc->nleaf + 1,
                              sizeof *l, 256);
    if (l == NULL)
        return CF_STATUS_NO_MEMORY;
    sc->leaves = l;
    l = &sc->leaves[sc->nleaf++];
    l->patch = (uint32_t)ip;
    l->fold = ms->fold;
    l->orient = (int8_t)ms->orient;
    memcpy(l->r, pc->r, sizeof l->r);
    memcpy(l->lo, ms->lo, sizeof l->lo);
    memcpy(l->hi, ms->hi, sizeof l->hi);
    leaf_sides(&sc->patches[ip], c, dmax, l);
    return CF_STATUS_OK;
}

/* Parameters of the corners of two triangle halves from the parent's. */
static void
tri_regions(const double *r, const int *perm, double *out)
{
    for (int c = 0; c < 3; c++) {
        int o = perm[c];
        if (o == 3) {
            /* the middle of the edge split: the two corners not kept
            ** are at perm positions where the other half has them */
            continue;
        }
        out[2 * c] = r[2 * o];
        out[2 * c + 1] = r[2 * o + 1];
    }
}

/* Room for n pieces (and their nets, sz doubles each) on the stack. */
static bool
reserve(piece_t **stack, double **nets, size_t *cap, size_t n, size_t sz)
{
    if (n <= *cap)
        return true;
    size_t want = n < 64 ? 64 : 2 * n;
    piece_t *ps = cf__realloc_array(*stack, want, sizeof *ps);
    if (ps == NULL)
        return false;
    *stack = ps;
    double *ns = cf__realloc_array(*nets, want, sz * sizeof(double));
    if (ns == NULL)
        return false;
    *nets = ns;
    *cap = want;
    return true;
}

/* The pieces of patch ip, depth first: each piece's net lives at its place
** on the stack (nets, cnt * 4 doubles a piece), so halving allocates
** nothing but the stack's growth. */
cf_status_t
cf__scene_leaves(cf_scene_t *sc, size_t ip)
{
    const cf__vpatch_t *p = &sc->patches[ip];
    size_t cnt = cf__vpatch_count(p), sz = cnt * 4, nstack = 0, cap = 0;
    size_t first = sc->nleaf;
    piece_t *stack = NULL;
    double *nets = NULL;
    double *cart = cf__alloc_array(cnt, 3 * sizeof(double));
    double *half = cf__alloc_array(cnt, 8 * sizeof(double));
    cf_status_t st = CF_STATUS_OK;
    piece_t root;
    if (cart == NULL || half == NULL ||
        !reserve(&stack, &nets, &cap, 1, sz)) {
        cf__free(cart);
        cf__free(half);
        cf__free(stack);
        cf__free(nets);
        return CF_STATUS_NO_MEMORY;
    }
    memcpy(nets, p->g, sz * sizeof(double));
    root.level = 0;
    if (p->tri) {
        /* corners b_n00, b_0n0, b_00n at (u, v) = (1, 0), (0, 1), (0, 0) */
        double r[6] = {1, 0, 0, 1, 0, 0};
        memcpy(root.r, r, sizeof r);
    } else {
        double r[6] = {0, 1, 0, 1, 0, 0};
        memcpy(root.r, r, sizeof r);
    }
    stack[nstack++] = root;
    /* a bound of the patch's first derivatives in the image: 2 d r^2
    ** times the image diameter of its net (d its largest degree, r its
    ** weights' ratio in view space; a rational curve's derivative is at
    ** most its degree times 2 r^2 times the spread of its control
    ** points) */
    cf__vmeasure_t ms0;
    cf__vnet_measure(p, p->g, cart, &ms0);
    double dmax = 2.0 * (p->m > p->n ? p->m : p->n) * ms0.wratio *
                  ms0.wratio * ms0.img;
    while (nstack > 0) {
        piece_t pc = stack[--nstack];
        double *net = nets + nstack * sz;
        cf__vmeasure_t ms;
        cf__vnet_measure(p, net, cart, &ms);
        bool leaf = pc.level >= MAX_LEVEL ||
                    sc->nleaf - first >= MAX_LEAVES ||
                    ms.diam <= sc->tol / 8 ||
                    (!ms.fold && ms.dev <= 0.15 * ms.diam &&
                     ms.wratio <= 1.2) ||
                    (ms.fold && (ms.img <= sc->tol || ms.dev <= sc->tol / 4));
        if (leaf) {
            if ((st = push_leaf(sc, ip, &pc, &ms, cart, dmax)) !=
                CF_STATUS_OK)
                break;
            continue;
        }
        if (!reserve(&stack, &nets, &cap, nstack + 2, sz)) {
            st = CF_STATUS_NO_MEMORY;
            break;
        }
        net = nets + nstack * sz;
        piece_t a = pc, b = pc;
        double *lo = half, *hi = half + sz;
        a.level = b.level = pc.level + 1;
        if (!p->tri) {
            int dir = ms.ext[0] >= ms.ext[1] ? 0 : 1;
            double mid = 0.5 * (pc.r[2 * dir] + pc.r[2 * dir + 1]);
            cf__vnet_split(net, p->m, p->n, dir, lo, hi);
            a.r[2 * dir + 1] = mid;
            b.r[2 * dir] = mid;
        } else {
            /* the longest edge in the image, by its control polygon (not
            ** its corners: an edge whose ends meet, a loop, is long) */
            int n = p->n, ea = 0, eb = 1;
            double best = -1.0;
            for (int e = 0; e < 3; e++) {
                double d = 0.0;
                for (int i = 0; i < n; i++) {
                    /* edge 0: b_(n-i) i 0; 1: b_0 (n-i) i; 2: b_i 0 (n-i) */
                    const double *x0 = cart + 3 * (e == 0 ? tidx(n, n - i, i)
                                                  : e == 1 ? tidx(n, 0, n - i)
                                                           : tidx(n, i, 0)),
                                 *x1 = cart + 3 * (e == 0 ? tidx(n, n - i - 1,
                                                                i + 1)
                                                  : e == 1 ? tidx(n, 0,
                                                                  n - i - 1)
                                                           : tidx(n, i + 1, 0));
                    d += cf__norm2(x0[0] - x1[0], x0[1] - x1[1]) +
                         1e-3 * dist3(x0, x1);
                }
                if (d > best) {
                    best = d;
                    ea = e;
                    eb = (e + 1) % 3;
                }
            }
            int pa[3], pb[3];
            double mid[2] = {0.5 * (pc.r[2 * ea] + pc.r[2 * eb]),
                             0.5 * (pc.r[2 * ea + 1] + pc.r[2 * eb + 1])};
            cf__vtri_split(net, n, ea, eb, lo, pa, hi, pb);
            tri_regions(pc.r, pa, a.r);
            tri_regions(pc.r, pb, b.r);
            a.r[0] = mid[0];
            a.r[1] = mid[1];
            b.r[2] = mid[0];
            b.r[3] = mid[1];
        }
        /* a where the piece was, b above it (popped next) */
        memcpy(net, lo, sz * sizeof(double));
        memcpy(net + sz, hi, sz * sizeof(double));
        stack[nstack++] = a;
        stack[nstack++] = b;
    }
    cf__free(stack);
    cf__free(nets);
    cf__free(half);
    cf__free(cart);
    return st;
}

/* ---- the tree ----------------------------------------------------------- */

/* Twice the centre of leaf l along axis ax. */
CF__NO_COVERAGE static double
key(const cf__vleaf_t *l, int ax)
{
    return l->lo[ax] + l->hi[ax];
}

/* Reorder L[0..n-1] so that L[k] has the key it would have sorted, with
** no larger key before it and no smaller after (quickselect, middle
** pivot). */
CF__NO_COVERAGE static void
select_kth(cf__vleaf_t *L, size_t n, size_t k, int ax)
{
    size_t lo = 0, hi = n - 1;
    while (lo < hi) {
        double piv = key(&L[lo + (hi - lo) / 2], ax);
        size_t i = lo, j = hi;
        while (i <= j) {
            while (key(&L[i], ax) < piv)
                i++;
            while (key(&L[j], ax) > piv)
                j--;
            if (i <= j) {
                cf__vleaf_t t = L[i];
                L[i] = L[j];
                L[j] = t;
                i++;
                if (j == 0)
                    break;
                j--;
            }
        }
        if (k <= j)
            hi = j;
        else if (k >= i)
            lo = i;
        else
            return;
    }
}

CF__NO_COVERAGE static void
build(cf_scene_t *sc, size_t node, size_t first, size_t count)
{
    cf__vnode_t *nd = &sc->nodes[node];
    double clo[2] = {HUGE_VAL, HUGE_VAL}, chi[2] = {-HUGE_VAL, -HUGE_VAL};
    for (int k = 0; k < 3; k++) {
        nd->lo[k] = HUGE_VAL;
        nd->hi[k] = -HUGE_VAL;
    }
    for (size_t i = first; i < first + count; i++) {
        const cf__vleaf_t *l = &sc->leaves[i];
        for (int k = 0; k < 3; k++) {
            nd->lo[k] = cf__fmin(nd->lo[k], l->lo[k]);
            nd->hi[k] = cf__fmax(nd->hi[k], l->hi[k]);
        }
        for (int k = 0; k < 2; k++) {
            clo[k] = cf__fmin(clo[k], l->lo[k] + l->hi[k]);
            chi[k] = cf__fmax(chi[k], l->lo[k] + l->hi[k]);
        }
    }
    if (count <= 4) {
        nd->first = (uint32_t)first;
        nd->count = (uint32_t)count;
        return;
    }
    size_t half = count / 2, kid = sc->nnode;
    select_kth(sc->leaves + first, count, half,
               chi[0] - clo[0] >= chi[1] - clo[1] ? 0 : 1);
    sc->nnode += 2;
    nd->first = (uint32_t)kid;
    nd->count = 0;
    build(sc, kid, first, half);
    build(sc, kid + 1, first + half, count - half);
}

cf_status_t
cf__scene_tree(cf_scene_t *sc)
{
    cf__vnode_t *nodes;
    sc->nnode = 0;
    if (sc->nleaf == 0)
        return CF_STATUS_OK;
    nodes = cf__realloc_array(sc->nodes, 2 * sc->nleaf + 1, sizeof *nodes);
    if (nodes == NULL)
        return CF_STATUS_NO_MEMORY;
    sc->nodes = nodes;
    sc->nnode = 1;
    build(sc, 0, 0, sc->nleaf);
    return CF_STATUS_OK;
}
