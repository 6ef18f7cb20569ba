/*
** The drawing of the cairo stand-in (cairo-lite.h): paths flattened to
** polygons (curves to 0.1 device pixel), filled by the nonzero rule with
** 4 sub-scanlines a pixel and exact horizontal coverage; strokes as the
** union of one quadrilateral a segment, joins (round: a polygonal disc;
** miter up to cairo's limit 10, else bevel) and caps, all wound alike so
** that the nonzero rule unites them; dashes split the flattened line.  A8
** images composite OVER and CLEAR within the clip; recording surfaces
** gather ink boxes as cairo's analysis surface does (rounded out; strokes
** grown by cairo's style expansion).
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cairo-lite.h"

/* ---- flattening --------------------------------------------------------- */

static int
pts_add(pts_t *a, double x, double y)
{
    if (a->n == a->cap) {
        int cap = a->cap ? 2 * a->cap : 64;
        pt_t *p = realloc(a->p, (size_t)cap * sizeof *p);
        if (p == NULL)
            return -1;
        a->p = p;
        a->cap = cap;
    }
    a->p[a->n].x = x;
    a->p[a->n].y = y;
    a->n++;
    return 0;
}

/* Each subpath of the path: its flattened points and whether it was
** closed, handed to f. */
typedef int (*subpath_fn)(void *ctx, const pt_t *p, int n, int closed);

static int
flatten(const cairo_t *cr, subpath_fn f, void *ctx)
{
    pts_t a = { NULL, 0, 0 };
    int i, bad = 0, closed = 0;
    for (i = 0; i < cr->n && !bad; i += cr->path[i].header.length) {
        const cairo_path_data_t *d = &cr->path[i];
        switch (d->header.type) {
        case CAIRO_PATH_MOVE_TO:
            if (a.n >= 2 || closed)
                bad = f(ctx, a.p, a.n, closed);
            a.n = 0;
            closed = 0;
            bad = bad || pts_add(&a, d[1].point.x, d[1].point.y);
            break;
        case CAIRO_PATH_LINE_TO:
            bad = pts_add(&a, d[1].point.x, d[1].point.y);
            break;
        case CAIRO_PATH_CURVE_TO: {
            pt_t p0 = a.n > 0 ? a.p[a.n - 1] : (pt_t){ d[1].point.x,
                                                       d[1].point.y };
            double x1 = d[1].point.x, y1 = d[1].point.y;
            double x2 = d[2].point.x, y2 = d[2].point.y;
            double x3 = d[3].point.x, y3 = d[3].point.y;
            double ddx = fmax(fabs(p0.x - 2 * x1 + x2), fabs(x1 - 2 * x2 + x3));
            double ddy = fmax(fabs(p0.y - 2 * y1 + y2), fabs(y1 - 2 * y2 + y3));
            double dd = hypot(ddx, ddy);
            int k, n = (int)ceil(sqrt(0.75 * dd / TOL));
            if (!(n >= 1))
                n = 1;
            if (n > 256)
                n = 256;
            for (k = 1; k <= n && !bad; k++) {
                double t = (double)k / n, s = 1 - t;
                double b0 = s * s * s, b1 = 3 * s * s * t, b2 = 3 * s * t * t,
                       b3 = t * t * t;
                bad = pts_add(&a, b0 * p0.x + b1 * x1 + b2 * x2 + b3 * x3,
                              b0 * p0.y + b1 * y1 + b2 * y2 + b3 * y3);
            }
            break;
        }
        case CAIRO_PATH_CLOSE_PATH:
            closed = 1;
            break;
        }
    }
    if (!bad && (a.n >= 2 || closed))
        bad = f(ctx, a.p, a.n, closed);
    free(a.p);
    return bad;
}

/* ---- polygons and the rasteriser ---------------------------------------- */

static void
poly_edge(poly_t *pl, double x0, double y0, double x1, double y1)
{
    edge_t *e;
    if (!(isfinite(x0) && isfinite(y0) && isfinite(x1) && isfinite(y1))) {
        pl->failed = 1;
        return;
    }
    if (pl->n == 0 && pl->box[2] < pl->box[0]) {
        pl->box[0] = pl->box[2] = x0;
        pl->box[1] = pl->box[3] = y0;
    }
    pl->box[0] = fmin(pl->box[0], fmin(x0, x1));
    pl->box[1] = fmin(pl->box[1], fmin(y0, y1));
    pl->box[2] = fmax(pl->box[2], fmax(x0, x1));
    pl->box[3] = fmax(pl->box[3], fmax(y0, y1));
    if (y0 == y1)
        return;
    if (pl->n == pl->cap) {
        int cap = pl->cap ? 2 * pl->cap : 256;
        edge_t *p = realloc(pl->e, (size_t)cap * sizeof *p);
        if (p == NULL) {
            pl->failed = 1;
            return;
        }
        pl->e = p;
        pl->cap = cap;
    }
    e = &pl->e[pl->n++];
    e->dir = y1 > y0 ? 1 : -1;
    e->x0 = y1 > y0 ? x0 : x1;
    e->y0 = y1 > y0 ? y0 : y1;
    e->x1 = y1 > y0 ? x1 : x0;
    e->y1 = y1 > y0 ? y1 : y0;
}

/* A closed polygon, wound positively (a stroke's pieces unite). */
static void
poly_add(poly_t *pl, const pt_t *p, int n, int orient)
{
    int i;
    double area = 0;
    for (i = 0; i < n; i++) {
        const pt_t *a = &p[i], *b = &p[(i + 1) % n];
        area += a->x * b->y - b->x * a->y;
    }
    if (!orient || area >= 0) {
        for (i = 0; i < n; i++)
            poly_edge(pl, p[i].x, p[i].y, p[(i + 1) % n].x, p[(i + 1) % n].y);
    } else {
        for (i = n; i > 0; i--)
            poly_edge(pl, p[i % n].x, p[i % n].y, p[i - 1].x, p[i - 1].y);
    }
}

static void
disc(poly_t *pl, double x, double y, double r)
{
    pt_t p[64];
    int i, n = (int)ceil(PI / acos(fmax(0.0, 1 - TOL / fmax(r, TOL))));
    if (n < 8)
        n = 8;
    if (n > 64)
        n = 64;
    for (i = 0; i < n; i++) {
        p[i].x = x + r * cos(2 * PI * i / n);
        p[i].y = y + r * sin(2 * PI * i / n);
    }
    poly_add(pl, p, n, 1);
}

static int
cmp_edge(const void *a, const void *b)
{
    double d = ((const edge_t *)a)->y0 - ((const edge_t *)b)->y0;
    return d < 0 ? -1 : d > 0;
}

typedef struct { double x; int dir; } cross_t;

static int
cmp_cross(const void *a, const void *b)
{
    double d = ((const cross_t *)a)->x - ((const cross_t *)b)->x;
    return d < 0 ? -1 : d > 0;
}

static void
add_span(float *row, int x0, int x1, double a, double b, double w)
{
    int i, ia, ib;
    if (a < x0)
        a = x0;
    if (b > x1)
        b = x1;
    if (!(b > a))
        return;
    ia = (int)floor(a);
    ib = (int)floor(b);
    if (ia == ib) {
        row[ia - x0] += (float)((b - a) * w);
        return;
    }
    row[ia - x0] += (float)((ia + 1 - a) * w);
    for (i = ia + 1; i < ib; i++)
        row[i - x0] += (float)w;
    if (ib < x1)
        row[ib - x0] += (float)((b - ib) * w);
}

/* The nonzero coverage of pl over the device box b (whole pixels),
** composited onto an A8 image with the state's operator and alpha. */
static void
raster(cairo_t *cr, poly_t *pl, const int b[4])
{
    cairo_surface_t *s = cr->target;
    const gstate_t *g = gs(cr);
    int w = b[2] - b[0], y, k, next = 0, nact = 0, i;
    int *act = malloc((size_t)(pl->n + 1) * sizeof *act);
    cross_t *cx = malloc((size_t)(pl->n + 1) * sizeof *cx);
    float *row = malloc((size_t)(w + 1) * sizeof *row);
    if (act == NULL || cx == NULL || row == NULL) {
        cr->status = CAIRO_STATUS_NO_MEMORY;
        goto done;
    }
    qsort(pl->e, (size_t)pl->n, sizeof *pl->e, cmp_edge);
    for (y = b[1]; y < b[3]; y++) {
        unsigned char *d = s->data + (size_t)y * (size_t)s->stride;
        memset(row, 0, (size_t)(w + 1) * sizeof *row);
        for (k = 0; k < SUB; k++) {
            double sy = y + (k + 0.5) / SUB;
            int nc = 0, wind = 0, j;
            double start = 0;
            while (next < pl->n && pl->e[next].y0 <= sy)
                act[nact++] = next++;
            for (i = 0; i < nact;) {
                const edge_t *e = &pl->e[act[i]];
                if (e->y1 <= sy) {
                    act[i] = act[--nact];
                    continue;
                }
                if (e->y0 <= sy) {
                    cx[nc].x = e->x0 + (sy - e->y0) * (e->x1 - e->x0)
                                       / (e->y1 - e->y0);
                    cx[nc].dir = e->dir;
                    nc++;
                }
                i++;
            }
            qsort(cx, (size_t)nc, sizeof *cx, cmp_cross);
            for (j = 0; j < nc; j++) {
                int was = wind;
                wind += cx[j].dir;
                if (was == 0 && wind != 0)
                    start = cx[j].x;
                else if (was != 0 && wind == 0)
                    add_span(row, b[0], b[2], start, cx[j].x, 1.0 / SUB);
            }
        }
        for (i = 0; i < w; i++) {
            double c = row[i] > 1 ? 1 : row[i], v = d[b[0] + i] / 255.0;
            if (!(c > 0))
                continue;
            v = g->op == CAIRO_OPERATOR_CLEAR ? v * (1 - c)
                                              : g->alpha * c + v * (1 - g->alpha * c);
            d[b[0] + i] = (unsigned char)lround(v * 255);
        }
    }
done:
    free(act);
    free(cx);
    free(row);
}

/* The device box of pl within the clip and the surface, whole pixels;
** 0 when empty. */
static int
clip_box(cairo_t *cr, const double box[4], int out[4])
{
    const gstate_t *g = gs(cr);
    double b[4] = { box[0], box[1], box[2], box[3] };
    if (g->has_clip) {
        b[0] = fmax(b[0], g->clip[0]);
        b[1] = fmax(b[1], g->clip[1]);
        b[2] = fmin(b[2], g->clip[2]);
        b[3] = fmin(b[3], g->clip[3]);
    }
    if (!(b[2] > b[0] && b[3] > b[1]))
        return 0;
    if (cr->target->kind == RECORDING) {
        cairo_surface_t *s = cr->target;
        /* whole units, rounded out, as cairo's extents */
        b[0] = floor(b[0]);
        b[1] = floor(b[1]);
        b[2] = ceil(b[2]);
        b[3] = ceil(b[3]);
        if (!s->has_ink)
            memcpy(s->ink, b, sizeof b);
        s->ink[0] = fmin(s->ink[0], b[0]);
        s->ink[1] = fmin(s->ink[1], b[1]);
        s->ink[2] = fmax(s->ink[2], b[2]);
        s->ink[3] = fmax(s->ink[3], b[3]);
        s->has_ink = 1;
        return 0;
    }
    out[0] = (int)fmax(0, floor(b[0]));
    out[1] = (int)fmax(0, floor(b[1]));
    out[2] = (int)fmin(cr->target->w, ceil(b[2]));
    out[3] = (int)fmin(cr->target->h, ceil(b[3]));
    return out[2] > out[0] && out[3] > out[1];
}

static void
draw_poly(cairo_t *cr, poly_t *pl)
{
    int b[4];
    if (pl->failed) {
        cr->status = CAIRO_STATUS_NO_MEMORY;
        return;
    }
    if (pl->box[2] >= pl->box[0] && clip_box(cr, pl->box, b))
        raster(cr, pl, b);
}

static int
fill_subpath(void *ctx, const pt_t *p, int n, int closed)
{
    poly_t *pl = ctx;
    (void)closed;
    if (n >= 2)
        poly_add(pl, p, n, 0);
    return pl->failed;
}

static void
poly_init(poly_t *pl)
{
    memset(pl, 0, sizeof *pl);
    pl->box[0] = 1;
    pl->box[2] = 0;   /* empty */
}

void
cairo_fill_preserve(cairo_t *cr)
{
    poly_t pl;
    poly_init(&pl);
    if (flatten(cr, fill_subpath, &pl) != 0)
        pl.failed = 1;
    draw_poly(cr, &pl);
    free(pl.e);
}

void
cairo_fill(cairo_t *cr)
{
    cairo_fill_preserve(cr);
    path_clear(cr);
}

/* ---- strokes ------------------------------------------------------------ */

typedef struct stroker {
    poly_t pl;
    double hw;
    cairo_line_cap_t cap;
    cairo_line_join_t join;
    const double *dash;
    int ndash;
    double scale;
} stroker_t;

static void
join(stroker_t *s, pt_t a, pt_t v, pt_t b)
{
    double ux = v.x - a.x, uy = v.y - a.y, wx = b.x - v.x, wy = b.y - v.y;
    double lu = hypot(ux, uy), lw = hypot(wx, wy), cross, side;
    pt_t q[4];
    if (!(lu > 0 && lw > 0))
        return;
    if (s->join == CAIRO_LINE_JOIN_ROUND) {
        disc(&s->pl, v.x, v.y, s->hw);
        return;
    }
    ux /= lu, uy /= lu, wx /= lw, wy /= lw;
    cross = ux * wy - uy * wx;
    if (fabs(cross) < 1e-12)
        return;
    side = cross > 0 ? -1 : 1;          /* the outer side's normal sign */
    q[0] = v;
    q[1].x = v.x - side * uy * s->hw;
    q[1].y = v.y + side * ux * s->hw;
    q[3].x = v.x - side * wy * s->hw;
    q[3].y = v.y + side * wx * s->hw;
    {
        double cosang = -(ux * wx + uy * wy);   /* between the segments */
        double ml = 1 / sin(0.5 * acos(fmax(-1, fmin(1, cosang))));
        if (s->join == CAIRO_LINE_JOIN_MITER && ml <= 10) {
            double mx = (q[1].x + q[3].x) / 2 - v.x,
                   my = (q[1].y + q[3].y) / 2 - v.y;
            double lm = hypot(mx, my);
            if (lm > 0) {
                q[2].x = v.x + mx / lm * ml * s->hw;
                q[2].y = v.y + my / lm * ml * s->hw;
                poly_add(&s->pl, q, 4, 1);
                return;
            }
        }
    }
    q[2] = q[3];
    poly_add(&s->pl, q, 3, 1);
}

/* One dash (or the whole line): segments, joins, caps. */
static void
piece(stroker_t *s, const pt_t *p, int n, int closed)
{
    int i, any = 0;
    for (i = 0; i + 1 < n; i++) {
        double dx = p[i + 1].x - p[i].x, dy = p[i + 1].y - p[i].y;
        double l = hypot(dx, dy), nx, ny;
        pt_t q[4];
        if (!(l > 0))
            continue;
        any = 1;
        nx = -dy / l * s->hw;
        ny = dx / l * s->hw;
        q[0].x = p[i].x + nx, q[0].y = p[i].y + ny;
        q[1].x = p[i + 1].x + nx, q[1].y = p[i + 1].y + ny;
        q[2].x = p[i + 1].x - nx, q[2].y = p[i + 1].y - ny;
        q[3].x = p[i].x - nx, q[3].y = p[i].y - ny;
        poly_add(&s->pl, q, 4, 1);
    }
    if (!any) {
        if (s->cap == CAIRO_LINE_CAP_ROUND && n >= 1)
            disc(&s->pl, p[0].x, p[0].y, s->hw);
        return;
    }
    for (i = 1; i + 1 < n; i++)
        join(s, p[i - 1], p[i], p[i + 1]);
    if (closed && n >= 3) {
        join(s, p[n - 2], p[n - 1], p[0]);
        join(s, p[n - 1], p[0], p[1]);
    } else if (s->cap == CAIRO_LINE_CAP_ROUND) {
        disc(&s->pl, p[0].x, p[0].y, s->hw);
        disc(&s->pl, p[n - 1].x, p[n - 1].y, s->hw);
    }
}

static int
stroke_subpath(void *ctx, const pt_t *p, int n, int closed)
{
    stroker_t *s = ctx;
    pts_t a = { NULL, 0, 0 }, full = { NULL, 0, 0 };
    int i, k = 0, on = 1, bad = 0;
    double left;
    if (n < 1)
        return 0;
    if (s->ndash == 0) {
        if (closed && n >= 2 && p[n - 1].x == p[0].x && p[n - 1].y == p[0].y)
            n--;
        piece(s, p, n, closed);
        return s->pl.failed;
    }
    /* dashes along the line, the closing segment included */
    for (i = 0; i < n && !bad; i++)
        bad = pts_add(&full, p[i].x, p[i].y);
    if (closed && !bad)
        bad = pts_add(&full, p[0].x, p[0].y);
    left = s->dash[0] * s->scale;
    bad = bad || pts_add(&a, full.p[0].x, full.p[0].y);
    for (i = 0; i + 1 < full.n && !bad; i++) {
        pt_t u = full.p[i], v = full.p[i + 1];
        double l = hypot(v.x - u.x, v.y - u.y), pos = 0;
        while (!bad && l - pos > left) {
            double t = (pos + left) / l;
            pt_t m = { u.x + t * (v.x - u.x), u.y + t * (v.y - u.y) };
            if (on) {
                bad = pts_add(&a, m.x, m.y);
                piece(s, a.p, a.n, 0);
            }
            a.n = 0;
            bad = bad || pts_add(&a, m.x, m.y);
            pos += left;
            on = !on;
            k = (k + 1) % s->ndash;
            left = s->dash[k] * s->scale;
        }
        left -= l - pos;
        if (on)
            bad = bad || pts_add(&a, v.x, v.y);
    }
    if (on && !bad && a.n > 0)
        piece(s, a.p, a.n, 0);
    free(a.p);
    free(full.p);
    return bad || s->pl.failed;
}

/* A recording surface's ink of a stroke, as cairo's analysis surface
** takes it (_cairo_path_fixed_approximate_stroke_extents): the path's
** box grown by half the line width, or by sqrt(2) times the miter limit
** times the width for miter joins on a path not only of horizontal and
** vertical lines. */
static int
rect_subpath(void *ctx, const pt_t *p, int n, int closed)
{
    int *rectilinear = ctx, i;
    (void)closed;
    for (i = 0; i + 1 < n; i++)
        if (p[i].x != p[i + 1].x && p[i].y != p[i + 1].y)
            *rectilinear = 0;
    return 0;
}

static void
stroke_ink(cairo_t *cr, double hw)
{
    const gstate_t *g = gs(cr);
    poly_t pl;
    int rectilinear = 1, i;
    double e = hw;
    poly_init(&pl);
    flatten(cr, fill_subpath, &pl);
    for (i = 0; i < cr->n; i += cr->path[i].header.length)
        if (cr->path[i].header.type == CAIRO_PATH_CURVE_TO)
            rectilinear = 0;
    flatten(cr, rect_subpath, &rectilinear);
    if (g->join == CAIRO_LINE_JOIN_MITER && !rectilinear)
        e = fmax(e, 2 * hw * sqrt(2.0) * 10);
    if (!pl.failed && pl.box[2] >= pl.box[0]) {
        double b[4] = { pl.box[0] - e, pl.box[1] - e, pl.box[2] + e,
                        pl.box[3] + e };
        int ib[4];
        clip_box(cr, b, ib);
    }
    free(pl.e);
}

void
cairo_stroke(cairo_t *cr)
{
    const gstate_t *g = gs(cr);
    stroker_t s;
    memset(&s, 0, sizeof s);
    poly_init(&s.pl);
    s.scale = sqrt(fabs(g->m.xx * g->m.yy - g->m.xy * g->m.yx));
    s.hw = 0.5 * g->width * s.scale;
    s.cap = g->cap;
    s.join = g->join;
    s.dash = g->dash;
    s.ndash = g->ndash;
    if (cr->target->kind == RECORDING) {
        if (s.hw > 0)
            stroke_ink(cr, s.hw);
        path_clear(cr);
        return;
    }
    if (s.hw > 0 && flatten(cr, stroke_subpath, &s) != 0)
        s.pl.failed = 1;
    if (s.hw > 0)
        draw_poly(cr, &s.pl);
    free(s.pl.e);
    path_clear(cr);
}

void
cairo_paint(cairo_t *cr)
{
    cairo_surface_t *t = cr->target;
    const gstate_t *g = gs(cr);
    double box[4] = { 0, 0, t->w, t->h };
    int b[4], x, y;
    if (t->kind == RECORDING) {
        if (g->has_clip)
            clip_box(cr, g->clip, b);
        return;
    }
    if (!clip_box(cr, box, b))
        return;
    for (y = b[1]; y < b[3]; y++)
        for (x = b[0]; x < b[2]; x++) {
            unsigned char *d = &t->data[(size_t)y * (size_t)t->stride + (size_t)x];
            double a = g->alpha;
            if (g->src != NULL) {
                int sx = x - (int)lround(g->src_x), sy = y - (int)lround(g->src_y);
                a = sx >= 0 && sy >= 0 && sx < g->src->w && sy < g->src->h
                        ? g->src->data[(size_t)sy * (size_t)g->src->stride
                                       + (size_t)sx] / 255.0
                        : 0;
            }
            *d = g->op == CAIRO_OPERATOR_CLEAR
                     ? 0
                     : (unsigned char)lround(255 * (a + *d / 255.0 * (1 - a)));
        }
}

