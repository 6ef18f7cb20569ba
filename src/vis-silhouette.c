/* Silhouettes: the contour of a surface for a view, traced on each patch
** and fitted by cubic pieces with a measured error
** (curvefig/visibility.h). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "vis-private.h"

/* Cells of the sign grid along each side of a patch. */
#define GRID 16
/* Fitting: the measured error each piece must reach, as a fraction of the
** tolerance, and the checks per piece. */
#define AIM 0.25
#define CHECKS 16

typedef struct ctx {
    const cf_scene_t *sc;
    const cf__vpatch_t *p;
    cf_silhouette_t *out;
    size_t cap;
    size_t chains_cap;
    long budget;        /* fits left for the scene (a bound on the work) */
} ctx_t;

/* Fits per call at most: beyond, pieces are kept as they are (converged
** false). */
#define BUDGET 400000L

/* g(s, t) = (S_s x S_t) . v with v = d (orthographic) or E - S, and its
** gradient; false where the patch cannot be evaluated. */
CF__NO_COVERAGE static bool
contour(const ctx_t *c, double s, double t, double *g, double *gs,
        double *gt)
{
    double D[18], v[3], n[3], a[3], b[3];
    const cf_view_t *vw = &c->sc->view;
    /* the second derivatives only for the gradient (the first ones come
    ** out the same either way) */
    if (!cf__vpatch_eval(c->p, c->p->h, s, t, gs != NULL ? 2 : 1, D))
        return false;
    for (int k = 0; k < 3; k++)
        v[k] = vw->projection == CF_PROJECTION_PERSPECTIVE ? vw->eye[k] - D[k]
                                                            : vw->dir[k];
#define CROSS(o, x, y)                                                       \
    (o)[0] = (x)[1] * (y)[2] - (x)[2] * (y)[1];                              \
    (o)[1] = (x)[2] * (y)[0] - (x)[0] * (y)[2];                              \
    (o)[2] = (x)[0] * (y)[1] - (x)[1] * (y)[0]
#define DOT(x, y) ((x)[0] * (y)[0] + (x)[1] * (y)[1] + (x)[2] * (y)[2])
    CROSS(n, D + 3, D + 6);
    *g = DOT(n, v);
    if (gs != NULL) {
        /* (S_ss x S_t + S_s x S_st) . v; the term of v' is 0 */
        CROSS(a, D + 9, D + 6);
        CROSS(b, D + 3, D + 12);
        *gs = DOT(a, v) + DOT(b, v);
        CROSS(a, D + 12, D + 6);
        CROSS(b, D + 3, D + 15);
        *gt = DOT(a, v) + DOT(b, v);
    }
    return isfinite(*g);
}

/* Newton along the gradient from (s, t) onto g = 0. */
static bool
project(const ctx_t *c, double *st)
{
    for (int it = 0; it < 30; it++) {
        double g, gs, gt;
        if (!contour(c, st[0], st[1], &g, &gs, &gt))
            return false;
        double n2 = gs * gs + gt * gt;
        if (!(n2 > 0.0))
            return false;
        double ds = -g * gs / n2, dt = -g * gt / n2;
        st[0] += ds;
        st[1] += dt;
        if (fabs(ds) + fabs(dt) <= 1e-15)
            return true;
    }
    double g;
    return contour(c, st[0], st[1], &g, NULL, NULL) &&
           fabs(g) <= 1e-12 * (fabs(g) + 1.0);
}

/* The root of g on the segment a-b (signs differ), by bisection. */
static void
edge_root(const ctx_t *c, const double *a, const double *b, double ga,
          double *out)
{
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < 52; it++) {
        double m = 0.5 * (lo + hi), g;
        double x[2] = {a[0] + m * (b[0] - a[0]), a[1] + m * (b[1] - a[1])};
        if (!contour(c, x[0], x[1], &g, NULL, NULL))
            break;
        if ((g >= 0.0) == (ga >= 0.0))
            lo = m;
        else
            hi = m;
    }
    double m = 0.5 * (lo + hi);
    out[0] = a[0] + m * (b[0] - a[0]);
    out[1] = a[1] + m * (b[1] - a[1]);
}

/* Space point, image point and their derivatives along uv direction T at
** (s, t). */
static bool
frame(const ctx_t *c, const double *st, const double *T, double *P,
      double *dP, double *I, double *dI)
{
    double D[18], G[18];
    if (!cf__vpatch_eval(c->p, c->p->h, st[0], st[1], 1, D) ||
        !cf__vpatch_eval(c->p, c->p->g, st[0], st[1], 1, G))
        return false;
    for (int k = 0; k < 3; k++) {
        P[k] = D[k];
        dP[k] = D[3 + k] * T[0] + D[6 + k] * T[1];
    }
    for (int k = 0; k < 2; k++) {
        I[k] = G[k];
        dI[k] = G[3 + k] * T[0] + G[6 + k] * T[1];
    }
    return true;
}

/* The contour's unit tangent in (s, t) at st, turned along dir. */
static bool
tangent(const ctx_t *c, const double *st, const double *dir, double *T)
{
    double g, gs, gt;
    if (!contour(c, st[0], st[1], &g, &gs, &gt))
        return false;
    double n = hypot(gs, gt);
    if (!(n > 0.0))
        return false;
    T[0] = -gt / n;
    T[1] = gs / n;
    if (T[0] * dir[0] + T[1] * dir[1] < 0.0) {
        T[0] = -T[0];
        T[1] = -T[1];
    }
    return true;
}

static void
bez(const double *cp, int dim, double l, double *out)
{
    double a = 1.0 - l;
    double b0 = a * a * a, b1 = 3 * a * a * l, b2 = 3 * a * l * l,
           b3 = l * l * l;
    for (int k = 0; k < dim; k++)
        out[k] = b0 * cp[k] + b1 * cp[dim + k] + b2 * cp[2 * dim + k] +
                 b3 * cp[3 * dim + k];
}

/*
** The cubic piece from contour point A to B (parameters): Hermite in
** (s, t) with the contour's tangents scaled by the chord, and in space and
** the image with the tangents mapped.  Its errors measured at CHECKS
** points.  false if it cannot be built.
*/
static bool
fit(const ctx_t *c, const double *A, const double *B,
    cf_silhouette_piece_t *pc)
{
    double ch[2] = {B[0] - A[0], B[1] - A[1]}, L = hypot(ch[0], ch[1]);
    double TA[2], TB[2], P0[3], P1[3], d0[3], d1[3], I0[2], I1[2], e0[2],
        e1[2];
    if (!(L > 0.0) || !tangent(c, A, ch, TA) || !tangent(c, B, ch, TB))
        return false;
    TA[0] *= L;
    TA[1] *= L;
    TB[0] *= L;
    TB[1] *= L;
    if (!frame(c, A, TA, P0, d0, I0, e0) || !frame(c, B, TB, P1, d1, I1, e1))
        return false;
    const cf__vpatch_t *p = c->p;
    double su = p->tri ? 1.0 : p->u1 - p->u0, sv = p->tri ? 1.0 : p->v1 - p->v0;
    double ou = p->tri ? 0.0 : p->u0, ov = p->tri ? 0.0 : p->v0;
    double uvl[8] = {A[0], A[1], A[0] + TA[0] / 3, A[1] + TA[1] / 3,
                     B[0] - TB[0] / 3, B[1] - TB[1] / 3, B[0], B[1]};
    for (int k = 0; k < 3; k++) {
        pc->space[k] = P0[k];
        pc->space[3 + k] = P0[k] + d0[k] / 3;
        pc->space[6 + k] = P1[k] - d1[k] / 3;
        pc->space[9 + k] = P1[k];
    }
    for (int k = 0; k < 2; k++) {
        pc->image[k] = I0[k];
        pc->image[2 + k] = I0[k] + e0[k] / 3;
        pc->image[4 + k] = I1[k] - e1[k] / 3;
        pc->image[6 + k] = I1[k];
    }
    for (int i = 0; i < 4; i++) {
        pc->uv[2 * i] = ou + su * uvl[2 * i];
        pc->uv[2 * i + 1] = ov + sv * uvl[2 * i + 1];
    }
    pc->surface = p->surface;
    pc->error_space = pc->error_image = 0.0;
    for (int i = 1; i <= CHECKS; i++) {
        double l = (double)i / (CHECKS + 1), st[2], x[3], im[2], D[18], G[18];
        bez(uvl, 2, l, st);
        if (!project(c, st) ||
            !cf__vpatch_eval(p, p->h, st[0], st[1], 0, D) ||
            !cf__vpatch_eval(p, p->g, st[0], st[1], 0, G))
            return false;
        bez(pc->space, 3, l, x);
        bez(pc->image, 2, l, im);
        pc->error_space = fmax(pc->error_space,
                               sqrt((x[0] - D[0]) * (x[0] - D[0]) +
                                    (x[1] - D[1]) * (x[1] - D[1]) +
                                    (x[2] - D[2]) * (x[2] - D[2])));
        pc->error_image =
            fmax(pc->error_image, hypot(im[0] - G[0], im[1] - G[1]));
    }
    return true;
}

static bool
good(const ctx_t *c, const cf_silhouette_piece_t *pc)
{
    double aim = AIM * c->sc->tol;
    return pc->error_image <= aim && pc->error_space <= aim;
}

static cf_status_t
emit(ctx_t *c, const cf_silhouette_piece_t *pc)
{
    cf_silhouette_t *o = c->out;
    double z = 1e-9 * c->sc->size, span = 0.0;
    for (int i = 1; i < 4; i++)
        for (int k = 0; k < 3; k++)
            span = fmax(span, fabs(pc->space[3 * i + k] - pc->space[k]));
    if (span <= z)   /* a degenerate edge (a pole): one point in space */
        return CF_STATUS_OK;
    cf_silhouette_piece_t *it = cf__grow(o->items, &c->cap, o->n + 1,
                                         sizeof *it, 16);
    if (it == NULL)
        return CF_STATUS_NO_MEMORY;
    o->items = it;
    it[o->n] = *pc;
    it[o->n].chain = o->nchains;
    o->max_error = fmax(o->max_error, pc->error_image);
    o->n++;
    return CF_STATUS_OK;
}

/* Whether contour points A and B (local parameters) are within the aim
** of each other in space and in the image. */
static bool
near_ends(const ctx_t *c, const double *A, const double *B)
{
    double a[18], b[18], ga[18], gb[18], aim = AIM * c->sc->tol;
    if (!cf__vpatch_eval(c->p, c->p->h, A[0], A[1], 0, a) ||
        !cf__vpatch_eval(c->p, c->p->h, B[0], B[1], 0, b) ||
        !cf__vpatch_eval(c->p, c->p->g, A[0], A[1], 0, ga) ||
        !cf__vpatch_eval(c->p, c->p->g, B[0], B[1], 0, gb))
        return false;
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2])) <= aim &&
           hypot(ga[0] - gb[0], ga[1] - gb[1]) <= aim;
}

/* Pieces from contour point A to B, halving (at the contour point nearest
** the middle) where the error is too large. */
static cf_status_t
span_fit(ctx_t *c, const double *A, const double *B, int depth)
{
    cf_silhouette_piece_t pc;
    memset(&pc, 0, sizeof pc);
    bool ok = fit(c, A, B, &pc);
    /* a piece that cannot be fitted (no tangent at its ends) and whose
    ** ends are within the aim of each other in space and in the image is
    ** not halved further: its halves fail alike, down to the budget */
    bool tiny = hypot(B[0] - A[0], B[1] - A[1]) <= 1e-9 ||
                (!ok && near_ends(c, A, B));
    if (--c->budget <= 0)
        depth = 30;
    if (ok && (good(c, &pc) || depth >= 30 || tiny)) {
        if (!good(c, &pc))
            c->out->converged = false;
        return emit(c, &pc);
    }
    double M[2] = {0.5 * (A[0] + B[0]), 0.5 * (A[1] + B[1])};
    double len = hypot(B[0] - A[0], B[1] - A[1]);
    /* the contour point nearest the middle must split the piece (Newton
    ** may leave for another branch, off the patch: no progress, down to
    ** the budget) */
    if (depth >= 30 || tiny || !project(c, M) ||
        !(hypot(M[0] - A[0], M[1] - A[1]) < 0.9 * len &&
          hypot(M[0] - B[0], M[1] - B[1]) < 0.9 * len)) {
        c->out->converged = false;
        return ok ? emit(c, &pc) : CF_STATUS_OK;
    }
    cf_status_t st = span_fit(c, A, M, depth + 1);
    return st != CF_STATUS_OK ? st : span_fit(c, M, B, depth + 1);
}

/* One chain of contour points pts[0..n-1]: greedy pieces over as many
** points as fit, then halving. */
static cf_status_t
chain_fit(ctx_t *c, const double *pts, size_t n, bool closed)
{
    cf_status_t st = CF_STATUS_OK;
    size_t before = c->out->n;
    size_t i = 0;
    while (i + 1 < n && st == CF_STATUS_OK) {
        size_t j = i + 1;
        cf_silhouette_piece_t pc;
        while (j + 1 < n && --c->budget > 0 &&
               fit(c, pts + 2 * i, pts + 2 * (j + 1), &pc) && good(c, &pc))
            j++;
        st = span_fit(c, pts + 2 * i, pts + 2 * j, 0);
        i = j;
    }
    if (st != CF_STATUS_OK || c->out->n == before)
        return st;
    bool *cl = cf__grow(c->out->closed, &c->chains_cap, c->out->nchains + 1,
                        sizeof *cl, 8);
    if (cl == NULL)
        return CF_STATUS_NO_MEMORY;
    c->out->closed = cl;
    cl[c->out->nchains++] = closed;
    return CF_STATUS_OK;
}

/* ---- tracing on the grid ------------------------------------------------ */

#define NV ((GRID + 1) * (GRID + 1))
#define NE (3 * NV)

typedef struct grid {
    double g[NV];
    bool ok[NV];
    double pt[NE][2];
    int adj[NE][2];
    bool cross[NE], seen[NE];
} grid_t;

static int
vid(int i, int j)
{
    return i * (GRID + 1) + j;
}

/* Edge of type k at (i, j): 0 to (i+1, j), 1 to (i, j+1), 2 from (i+1, j)
** to (i, j+1). */
static int
eid(int i, int j, int k)
{
    return 3 * vid(i, j) + k;
}

static void
edge_ends(int e, double *a, double *b, int *va, int *vb)
{
    int v = e / 3, k = e % 3, i = v / (GRID + 1), j = v % (GRID + 1);
    int ia = k == 2 ? i + 1 : i, ja = j;
    int ib = k == 0 ? i + 1 : i, jb = k == 0 ? j : j + 1;
    a[0] = (double)ia / GRID;
    a[1] = (double)ja / GRID;
    b[0] = (double)ib / GRID;
    b[1] = (double)jb / GRID;
    *va = vid(ia, ja);
    *vb = vid(ib, jb);
}

static void
link(grid_t *G, int a, int b)
{
    for (int k = 0; k < 2; k++)
        if (G->adj[a][k] < 0) {
            G->adj[a][k] = b;
            break;
        }
    for (int k = 0; k < 2; k++)
        if (G->adj[b][k] < 0) {
            G->adj[b][k] = a;
            break;
        }
}

/* A triangle of the grid given by its three edges. */
static void
triangle(grid_t *G, int e0, int e1, int e2)
{
    int es[3] = {e0, e1, e2}, c[3], n = 0;
    for (int k = 0; k < 3; k++)
        if (G->cross[es[k]])
            c[n++] = es[k];
    if (n == 2)
        link(G, c[0], c[1]);
}

static cf_status_t
trace_patch(ctx_t *c, grid_t *G, double *pts)
{
    bool tri = c->p->tri;
    for (int i = 0; i <= GRID; i++)
        for (int j = 0; j <= GRID; j++) {
            int v = vid(i, j);
            G->ok[v] = (!tri || i + j <= GRID) &&
                       contour(c, (double)i / GRID, (double)j / GRID, &G->g[v],
                               NULL, NULL);
        }
    for (int e = 0; e < NE; e++) {
        double a[2], b[2];
        int va, vb;
        G->adj[e][0] = G->adj[e][1] = -1;
        G->seen[e] = false;
        G->cross[e] = false;
        edge_ends(e, a, b, &va, &vb);
        if (va >= NV || vb >= NV || a[0] > 1.0 || a[1] > 1.0 || b[0] > 1.0 ||
            b[1] > 1.0 || !G->ok[va] || !G->ok[vb])
            continue;
        if ((G->g[va] >= 0.0) != (G->g[vb] >= 0.0)) {
            G->cross[e] = true;
            edge_root(c, a, b, G->g[va], G->pt[e]);
        }
    }
    for (int i = 0; i < GRID; i++)
        for (int j = 0; j < GRID; j++) {
            if (!tri || i + j < GRID)
                triangle(G, eid(i, j, 0), eid(i, j, 1), eid(i, j, 2));
            if (!tri || i + j < GRID - 1)
                triangle(G, eid(i + 1, j, 1), eid(i, j + 1, 0), eid(i, j, 2));
        }
    /* chains: from open ends first, then the loops */
    cf_status_t st = CF_STATUS_OK;
    for (int pass = 0; pass < 2 && st == CF_STATUS_OK; pass++)
        for (int e = 0; e < NE && st == CF_STATUS_OK; e++) {
            if (!G->cross[e] || G->seen[e] || G->adj[e][0] < 0 ||
                (pass == 0 && G->adj[e][1] >= 0))
                continue;
            size_t n = 0;
            int cur = e, prev = -1;
            bool closed = false;
            while (cur >= 0 && !G->seen[cur]) {
                G->seen[cur] = true;
                memcpy(pts + 2 * n++, G->pt[cur], 2 * sizeof(double));
                int nx = G->adj[cur][0] == prev ? G->adj[cur][1]
                                                : G->adj[cur][0];
                prev = cur;
                cur = nx;
            }
            if (cur == e && n > 2) {
                closed = true;
                memcpy(pts + 2 * n++, G->pt[e], 2 * sizeof(double));
            }
            st = chain_fit(c, pts, n, closed);
        }
    return st;
}

void
cf_silhouette_destroy(cf_silhouette_t *s)
{
    if (s == NULL)
        return;
    cf__free(s->items);
    cf__free(s->closed);
    cf__free(s);
}

cf_status_t
cf_scene_silhouette(const cf_scene_t *sc, size_t surface,
                    cf_silhouette_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st = CF_STATUS_OK;
    ctx_t c;
    grid_t *G;
    double *pts;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    if (sc == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "scene is NULL");
    if (surface != SIZE_MAX && surface >= sc->nsurf)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "surface %zu is not in the scene (it has %zu)",
                         surface, sc->nsurf);
    memset(&c, 0, sizeof c);
    c.sc = sc;
    c.budget = BUDGET;
    c.out = cf__calloc(1, sizeof *c.out);
    G = cf__malloc(sizeof *G);
    pts = cf__alloc_array(NE + 1, 2 * sizeof(double));
    if (c.out == NULL || G == NULL || pts == NULL) {
        cf_silhouette_destroy(c.out);
        cf__free(G);
        cf__free(pts);
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    }
    c.out->converged = true;
    for (size_t i = 0; i < sc->npatch && st == CF_STATUS_OK; i++) {
        if (surface != SIZE_MAX && sc->patches[i].surface != surface)
            continue;
        c.p = &sc->patches[i];
        st = trace_patch(&c, G, pts);
    }
    cf__free(G);
    cf__free(pts);
    if (st != CF_STATUS_OK) {
        cf_silhouette_destroy(c.out);
        return cf__error(diag, st, -1, "out of memory");
    }
    *out = c.out;
    return CF_STATUS_OK;
}

bool
cf__contour_point(const cf_scene_t *sc, size_t surface, const double *uv,
                  double *q)
{
    ctx_t c;
    size_t ip;
    double st[2], G[18];
    memset(&c, 0, sizeof c);
    c.sc = sc;
    if (!cf__scene_find(sc, surface, uv[0], uv[1], &ip, &st[0], &st[1]))
        return false;
    c.p = &sc->patches[ip];
    double keep[2] = {st[0], st[1]};
    if (!project(&c, st) || hypot(st[0] - keep[0], st[1] - keep[1]) > 0.1) {
        st[0] = keep[0];
        st[1] = keep[1];
    }
    if (!cf__vpatch_eval(c.p, c.p->g, st[0], st[1], 0, G))
        return false;
    memcpy(q, G, 3 * sizeof(double));
    return true;
}
