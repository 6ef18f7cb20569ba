/*
** The seen and hidden parts of a filled region in space (region.h): each
** of its triangles is cut into a grid of cells small in the image, every
** grid point is asked of the scene (cf_scene_point_visible), a cell whose
** corners agree is taken whole (a run of them along a row as one
** polygon) and a cell whose corners differ is cut along the straight line
** between the points where its edges change, each found by bisection.
** The image of a triangle in space is a triangle under a perspective view
** as well, and so is the image of each cell: the polygons are exact but
** for the cut cells.
*/
#include <math.h>
#include <string.h>

#include "grow.h"
#include "region.h"

void
cf__polys_fini(cf__polys_t *p)
{
    cf_free(p->xy);
    cf_free(p->len);
    memset(p, 0, sizeof *p);
}

typedef struct ctx {
    cf_figure_t *fig;
    const cf_scene_t *sc;
    double split;
    bool positive;
    cf__polys_t *out[2];     /* hidden, seen */
    const double *win;       /* xmin xmax ymin ymax widened, or NULL */
    size_t queries;
    cf_status_t st;
} ctx_t;

/* Whether the space point p is seen. */
static bool
seen_at(ctx_t *c, const double *p)
{
    bool seen = true;
    if (c->win != NULL) {
        /* far outside the window (more than a cell): in no cell that
        ** shows, not asked */
        double q[2];
        cf__fig_project1(c->fig, p, 3, q);
        if (q[0] < c->win[0] || q[0] > c->win[1] || q[1] < c->win[2]
            || q[1] > c->win[3])
            return true;
    }
    c->queries++;
    if (c->sc != NULL && c->st == CF_STATUS_OK)
        c->st = cf_scene_point_visible(c->sc, p, NULL, &seen, NULL,
                                       &c->fig->err);
    return seen;
}

/* Append the polygon of m space points (their images), counter-clockwise
** in the image when c->positive. */
static void
emit(ctx_t *c, bool seen, const double *pts, size_t m)
{
    cf__polys_t *o = c->out[seen ? 1 : 0];
    double *xy, area = 0;
    size_t *len;
    if (c->st != CF_STATUS_OK || m < 3)
        return;
    xy = cf__grow_array(o->xy, &o->xycap, o->nxy + m, 2 * sizeof *xy, 64);
    len = xy != NULL ? cf__grow_array(o->len, &o->lcap, o->n + 1,
                                      sizeof *len, 16)
                     : NULL;
    if (xy != NULL)
        o->xy = xy;
    if (len == NULL) {
        c->st = cf__fig_nomem(c->fig, "a region in space");
        return;
    }
    o->len = len;
    xy += 2 * o->nxy;
    for (size_t i = 0; i < m; i++)
        cf__fig_project1(c->fig, pts + 3 * i, 3, xy + 2 * i);
    for (size_t i = 0; i < m; i++) {
        const double *a = xy + 2 * i, *b = xy + 2 * ((i + 1) % m);
        area += a[0] * b[1] - a[1] * b[0];
    }
    if (c->positive && area < 0)
        for (size_t i = 0; i < m / 2; i++)
            for (int k = 0; k < 2; k++) {
                double t = xy[2 * i + k];
                xy[2 * i + k] = xy[2 * (m - 1 - i) + k];
                xy[2 * (m - 1 - i) + k] = t;
            }
    o->nxy += m;
    o->len[o->n++] = m;
}

static double
image_len(const cf_figure_t *fig, const double *a, const double *b)
{
    double pa[2], pb[2];
    cf__fig_project1(fig, a, 3, pa);
    cf__fig_project1(fig, b, 3, pb);
    return hypot(pa[0] - pb[0], pa[1] - pb[1]);
}

static void
lerp3(const double *a, const double *b, double t, double *o)
{
    for (int k = 0; k < 3; k++)
        o[k] = a[k] + t * (b[k] - a[k]);
}

/* The point of edge a b (a seen as sa, b not) where it changes, to
** c->split in the image; bisected from the lesser end (by coordinates),
** so that the two cells that share the edge cut it at one point. */
static void
change_on(ctx_t *c, const double *a, const double *b, bool sa, double *o)
{
    double t0 = 0, t1 = 1, m[3], len;
    if (a[0] > b[0] || (a[0] == b[0] && (a[1] > b[1]
                                         || (a[1] == b[1] && a[2] > b[2])))) {
        const double *t = a;
        a = b;
        b = t;
        sa = !sa;
    }
    len = image_len(c->fig, a, b);
    while ((t1 - t0) * len > c->split && c->st == CF_STATUS_OK) {
        double t = 0.5 * (t0 + t1);
        lerp3(a, b, t, m);
        if (seen_at(c, m) == sa)
            t0 = t;
        else
            t1 = t;
    }
    lerp3(a, b, 0.5 * (t0 + t1), o);
}

/* A cell whose corners differ: each kind's polygon walks the corners of
** its kind and the change points between them, in the cell's turn. */
static void
cut_cell(ctx_t *c, const double *v, const bool *s)
{
    double ch[3][3], poly[5 * 3];
    for (int i = 0; i < 3; i++)
        if (s[i] != s[(i + 1) % 3])
            change_on(c, v + 3 * i, v + 3 * ((i + 1) % 3), s[i], ch[i]);
    for (int kind = 0; kind < 2; kind++) {
        size_t m = 0;
        for (int i = 0; i < 3; i++) {
            if (s[i] == (kind == 1))
                memcpy(poly + 3 * m++, v + 3 * i, 3 * sizeof *poly);
            if (s[i] != s[(i + 1) % 3])
                memcpy(poly + 3 * m++, ch[i], 3 * sizeof *poly);
        }
        emit(c, kind == 1, poly, m);
    }
}

/* Grid point (i, j) of triangle t cut k times: t0 + i/k (t1 - t0) + j/k
** (t2 - t0). */
static void
grid_point(const double *t, size_t k, size_t i, size_t j, double *o)
{
    double a = (double)i / (double)k, b = (double)j / (double)k;
    for (int q = 0; q < 3; q++)
        o[q] = t[q] + a * (t[3 + q] - t[q]) + b * (t[6 + q] - t[q]);
}

/* Row j of the grid (between grid lines j and j + 1): its cells in order
** are up (i, j) (i + 1, j) (i, j + 1) and down (i + 1, j) (i + 1, j + 1)
** (i, j + 1), alternating; a run of whole cells of one kind is the
** polygon of its bottom and top ends. */
static void
row(ctx_t *c, const double *t, size_t k, size_t j, const bool *seen,
    const size_t *at)
{
    size_t ncell = 2 * (k - j) - 1, run0 = 0;
    int kind = -1;
#define S(i, jj) seen[at[jj] + (i)]
    for (size_t q = 0; q <= ncell; q++) {
        int here = -1;
        size_t i = q / 2;
        bool up = q % 2 == 0, cs[3] = { false, false, false };
        double v[9];
        if (q < ncell) {
            if (up) {
                cs[0] = S(i, j), cs[1] = S(i + 1, j), cs[2] = S(i, j + 1);
            } else {
                cs[0] = S(i + 1, j), cs[1] = S(i + 1, j + 1);
                cs[2] = S(i, j + 1);
            }
            here = cs[0] == cs[1] && cs[1] == cs[2] ? cs[0] : 2;
        }
        if (here != kind && kind >= 0 && kind < 2) {
            /* close the run of cells run0 .. q - 1 */
            size_t i0 = run0 / 2, i1 = (q - 1) / 2;
            double poly[12];
            grid_point(t, k, run0 % 2 == 0 ? i0 : i0 + 1, j, poly);
            grid_point(t, k, i1 + 1, j, poly + 3);
            grid_point(t, k, (q - 1) % 2 == 0 ? i1 : i1 + 1, j + 1,
                       poly + 6);
            grid_point(t, k, i0, j + 1, poly + 9);
            if (memcmp(poly, poly + 3, 3 * sizeof *poly) == 0)
                memmove(poly + 3, poly + 6, 6 * sizeof *poly);
            emit(c, kind == 1, poly,
                 memcmp(poly + 6, poly + 9, 3 * sizeof *poly) == 0 ? 3 : 4);
        }
        if (here == 2) {
            if (up) {
                grid_point(t, k, i, j, v);
                grid_point(t, k, i + 1, j, v + 3);
                grid_point(t, k, i, j + 1, v + 6);
            } else {
                grid_point(t, k, i + 1, j, v);
                grid_point(t, k, i + 1, j + 1, v + 3);
                grid_point(t, k, i, j + 1, v + 6);
            }
            cut_cell(c, v, cs);
        }
        if (here != kind)
            run0 = q;
        kind = here;
    }
#undef S
}

/* Whether the image of triangle t lies outside the window. */
static bool
outside(const ctx_t *c, const double *t)
{
    double q[6];
    bool out[4] = { true, true, true, true };
    if (c->win == NULL)
        return false;
    for (int v = 0; v < 3; v++) {
        cf__fig_project1(c->fig, t + 3 * v, 3, q + 2 * v);
        out[0] = out[0] && q[2 * v] < c->win[0];
        out[1] = out[1] && q[2 * v] > c->win[1];
        out[2] = out[2] && q[2 * v + 1] < c->win[2];
        out[3] = out[3] && q[2 * v + 1] > c->win[3];
    }
    return out[0] || out[1] || out[2] || out[3];
}

/* A grid has at most KMAX cells along an edge: a larger triangle is cut
** in four at its edges' midpoints first (those outside the window are
** then not asked at all). */
enum { KMAX = 1024 };

/* One triangle of the region. */
static void
triangle(ctx_t *c, const double *t, double cell)
{
    double e = fmax(image_len(c->fig, t, t + 3),
                    fmax(image_len(c->fig, t + 3, t + 6),
                         image_len(c->fig, t + 6, t)));
    double wmin = INFINITY, wmax = 0;
    size_t k, npts;
    bool *seen;
    size_t *at;
    if (c->sc == NULL || outside(c, t)) {
        emit(c, true, t, 3);
        return;
    }
    /* under a perspective the grid's cells are larger on the page where
    ** the triangle is nearer the eye: by W's ratio at its corners */
    for (int q = 0; q < 3; q++) {
        double h[3];
        if (cf__fig_project_h(c->fig, t + 3 * q, 3, false, h)) {
            wmin = fmin(wmin, h[2]);
            wmax = fmax(wmax, h[2]);
        }
    }
    if (wmax > 0 && wmin > 0)
        e *= wmax / wmin;
    if (e > KMAX * cell) {
        double m[9], sub[9];
        static const int corner[4][3] = {
            { -1, 0, 2 }, { 0, -2, 1 }, { 2, 1, -3 }, { 0, 1, 2 }
        };
        /* m: the midpoints of edges 0 1, 1 2, 2 0; the four triangles
        ** keep t's turn (corner c of t is -1 - c) */
        lerp3(t, t + 3, 0.5, m);
        lerp3(t + 3, t + 6, 0.5, m + 3);
        lerp3(t + 6, t, 0.5, m + 6);
        for (int q = 0; q < 4 && c->st == CF_STATUS_OK; q++) {
            for (int v = 0; v < 3; v++) {
                int w = corner[q][v];
                memcpy(sub + 3 * v, w < 0 ? t + 3 * (-1 - w) : m + 3 * w,
                       3 * sizeof *sub);
            }
            triangle(c, sub, cell);
        }
        return;
    }
    k = (size_t)ceil(e / cell);
    k = k < 1 ? 1 : k;
    npts = (k + 1) * (k + 2) / 2;
    seen = cf_alloc_array(npts, sizeof *seen);
    at = cf_alloc_array(k + 1, sizeof *at);
    if (seen == NULL || at == NULL) {
        c->st = cf__fig_nomem(c->fig, "a region in space");
        cf_free(seen);
        cf_free(at);
        return;
    }
    /* row j of the grid holds k + 1 - j points, from at[j] */
    for (size_t j = 0, n = 0; j <= k; j++) {
        at[j] = n;
        for (size_t i = 0; i + j <= k; i++, n++) {
            double p[3];
            grid_point(t, k, i, j, p);
            seen[n] = seen_at(c, p);
        }
    }
    for (size_t j = 0; j < k && c->st == CF_STATUS_OK; j++)
        row(c, t, k, j, seen, at);
    cf_free(seen);
    cf_free(at);
}

cf_status_t
cf__region_parts(cf_figure_t *fig, const cf_scene_t *sc,
                 const cf__tris_t *tris, const cf__region_grid_t *g,
                 cf__polys_t *seen, cf__polys_t *hidden, size_t *queries)
{
    ctx_t c;
    double win[4];
    memset(&c, 0, sizeof c);
    c.fig = fig;
    c.sc = sc;
    c.split = g->split;
    c.positive = g->positive;
    c.out[0] = hidden;
    c.out[1] = seen;
    if (g->window != NULL) {
        for (int k = 0; k < 4; k++)
            win[k] = g->window[k] + (k % 2 == 0 ? -2 : 2) * g->cell;
        c.win = win;
    }
    for (size_t i = 0; i < tris->n && c.st == CF_STATUS_OK; i++)
        triangle(&c, tris->p + 9 * i, g->cell);
    if (queries != NULL)
        *queries = c.queries;
    return c.st;
}
