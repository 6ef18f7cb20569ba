/*
** The measuring seam (render/backends/measure.h) over the display list, drawn by
** the rasterizer of render/backends/raster.c: a backend whose paths, markers and
** labels (their outlines, cf__label_outline) become polygons, painted
** into a coverage raster or reduced to their box.  Clips are rectangles,
** kept on a stack of the groups and clip scopes.
**
** Ink boxes are cairo's (the output's): fills and labels by the exact
** extremes of their paths, strokes by the box of their polygon (round
** caps and joins without dashes: the path's box grown by half the width,
** the same), paints of no alpha leave none; all drawn at 64 units a bp
** and rounded out to whole units, as cairo's recording surface does.
*/
#include <math.h>
#include <string.h>

#include "backend.h"
#include "label-private.h"
#include "measure.h"
#include "raster.h"

#define RASTER_TOL 0.1       /* flattening tolerance, raster pixels */
#define INK_SCALE 64.0       /* units a bp of ink boxes */
#define INK_TOL 0.1          /* flattening tolerance, ink units */
#define CLIP_DEPTH 64        /* clips kept; deeper scopes keep their
                                parent's */

typedef struct measure {
    cf__raster_t *r;          /* NULL: an ink box */
    cf__xform_t m;
    cf__poly_t pl;
    double clip[CLIP_DEPTH + 1][4];   /* device x0 y0 x1 y1 */
    int depth;
    double ink[4];            /* device units; ink[2] < ink[0]: none */
    bool failed;
} measure_t;

static void
push(measure_t *g, const double *rect)
{
    double *c;
    g->depth++;
    if (g->depth > CLIP_DEPTH)
        return;
    c = g->clip[g->depth];
    memcpy(c, g->clip[g->depth - 1], sizeof g->clip[0]);
    if (rect != NULL) {
        const cf__xform_t *m = &g->m;
        c[0] = fmax(c[0], rect[0] * m->scale + m->dx);
        c[1] = fmax(c[1], rect[1] * m->scale + m->dy);
        c[2] = fmin(c[2], (rect[0] + rect[2]) * m->scale + m->dx);
        c[3] = fmin(c[3], (rect[1] + rect[3]) * m->scale + m->dy);
    }
}

static const double *
clip_now(const measure_t *g)
{
    return g->clip[g->depth < CLIP_DEPTH ? g->depth : CLIP_DEPTH];
}

static void
begin_page(void *ctx, const cf__page_t *pg)
{
    (void)ctx;
    (void)pg;
}

static void
begin_group(void *ctx, const char *name, size_t index, const char *overlay)
{
    (void)name;
    (void)index;
    (void)overlay;
    push(ctx, NULL);
}

static void
pop(void *ctx)
{
    measure_t *g = ctx;
    if (g->depth > 0)
        g->depth--;
}

static void
clip(void *ctx, bool has_rect, const double r[4])
{
    push(ctx, has_rect ? r : NULL);
}

/* The box b (device) within the clip into the ink. */
static void
add_ink(measure_t *g, const double b[4])
{
    const double *c = clip_now(g);
    double x0 = fmax(b[0], c[0]), y0 = fmax(b[1], c[1]);
    double x1 = fmin(b[2], c[2]), y1 = fmin(b[3], c[3]);
    if (!(x1 > x0 && y1 > y0))
        return;
    if (g->ink[2] < g->ink[0]) {
        g->ink[0] = x0;
        g->ink[1] = y0;
        g->ink[2] = x1;
        g->ink[3] = y1;
        return;
    }
    g->ink[0] = fmin(g->ink[0], x0);
    g->ink[1] = fmin(g->ink[1], y0);
    g->ink[2] = fmax(g->ink[2], x1);
    g->ink[3] = fmax(g->ink[3], y1);
}

/* The pixels of clip b (i0 j0 i1 j1) a polygon with box pb (device)
** may paint, added to r's dirty box, and those rows made ready (the rows
** cf__poly_paint reads and writes); whether it reaches beyond b into
** r's cut. */
static void
grow_dirty(cf__raster_t *r, const int b[4], const double pb[4])
{
    double u[4];
    int d[4], *t = r->dirty;
    /* both sides bounded: a polygon wholly beyond the page (a label 1e17
    ** bp off) has its left edge beyond every int too */
    u[0] = floor(fmin(fmax(pb[0], -1e9), 1e9));
    u[1] = floor(fmin(fmax(pb[1], -1e9), 1e9));
    u[2] = ceil(fmin(fmax(pb[2], -1e9), 1e9));
    u[3] = ceil(fmin(fmax(pb[3], -1e9), 1e9));
    if (u[0] < b[0] || u[1] < b[1] || u[2] > b[2] || u[3] > b[3])
        r->cut = true;
    d[0] = (int)fmax(b[0], u[0]);
    d[1] = (int)fmax(b[1], u[1]);
    d[2] = (int)fmin(b[2], u[2]);
    d[3] = (int)fmin(b[3], u[3]);
    if (d[2] <= d[0] || d[3] <= d[1])
        return;
    cf__raster_ready(r, d[1], d[3]);
    if (t[2] <= t[0] || t[3] <= t[1]) {
        memcpy(t, d, sizeof d);
        return;
    }
    t[0] = d[0] < t[0] ? d[0] : t[0];
    t[1] = d[1] < t[1] ? d[1] : t[1];
    t[2] = d[2] > t[2] ? d[2] : t[2];
    t[3] = d[3] > t[3] ? d[3] : t[3];
}

/* The polygon g->pl painted with alpha, or its box into the ink. */
static void
put_poly(measure_t *g, double alpha)
{
    if (g->pl.failed) {
        g->failed = true;
    } else if (g->r == NULL) {
        if (g->pl.box[2] >= g->pl.box[0])
            add_ink(g, g->pl.box);
    } else {
        const double *c = clip_now(g);
        int b[4];
        b[0] = (int)fmax(0, fmin(g->r->w, floor(c[0] + 0.5)));
        b[1] = (int)fmax(0, fmin(g->r->h, floor(c[1] + 0.5)));
        b[2] = (int)fmax(0, fmin(g->r->w, floor(c[2] + 0.5)));
        b[3] = (int)fmax(0, fmin(g->r->h, floor(c[3] + 0.5)));
        if (b[2] > b[0] && b[3] > b[1] && g->pl.n > 0 && alpha > 0) {
            grow_dirty(g->r, b, g->pl.box);
            if (cf__poly_paint(&g->pl, g->r->px, g->r->stride, b, alpha,
                               false, g->r->rows) != 0)
                g->failed = true;
        }
    }
    cf__poly_reset(&g->pl);
}

static void
fill(measure_t *g, const cf__path_t *p, const cf__xform_t *m, double alpha)
{
    if (!(alpha > 0))
        return;
    if (g->r != NULL && g->r->solid)
        alpha = 1;
    if (g->r == NULL) {
        double b[4] = { 1, 0, 0, 0 };
        cf__path_box(p, m->scale, m->dx, m->dy, b);
        if (b[2] >= b[0])
            add_ink(g, b);
        return;
    }
    cf__poly_fill(&g->pl, p, m);
    put_poly(g, alpha);
}

static void
stroke(measure_t *g, const cf__path_t *p, const cf__xform_t *m,
       const cf__pen_t *pen, double alpha)
{
    double coverage;
    if (!(alpha > 0 && pen->width > 0))
        return;
    if (g->r == NULL && pen->cap == CF__CAP_ROUND
        && pen->join == CF__JOIN_ROUND && pen->ndash == 0) {
        /* the path's every point grown by a disc */
        double b[4] = { 1, 0, 0, 0 }, e = 0.5 * pen->width * m->scale;
        cf__path_box(p, m->scale, m->dx, m->dy, b);
        if (b[2] >= b[0]) {
            b[0] -= e;
            b[1] -= e;
            b[2] += e;
            b[3] += e;
            add_ink(g, b);
        }
        return;
    }
    cf__poly_stroke(&g->pl, p, m, pen, &coverage);
    /* a pattern stroked solid (too fine, or along too long a path) weighs
    ** the line as cairo's approximation of it inks it */
    if (!(coverage > 0)) {
        cf__poly_reset(&g->pl);
        return;
    }
    put_poly(g, g->r != NULL && g->r->solid ? 1 : alpha * coverage);
}

static void
draw_path(void *ctx, const cf__path_t *path, const cf__paint_t *paint)
{
    measure_t *g = ctx;
    if (paint->fill)
        fill(g, path, &g->m, paint->fill_color.a * paint->fill_opacity);
    if (paint->stroke) {
        const cf__stroke_t *s = &paint->line;
        cf__pen_t pen = { s->width, s->cap, s->join, s->dash, s->dash_count };
        stroke(g, path, &g->m, &pen, s->color.a * s->opacity);
    }
}


static void
draw_text(void *ctx, const cf__text_op_t *t)
{
    measure_t *g = ctx;
    cf__xform_t m = g->m;
    cf__path_t outline;
    if (t->label == NULL)
        return;
    m.dx += t->ox * m.scale;
    m.dy += t->oy * m.scale;
    if (g->r == NULL) {
        /* the box of the outline, kept by the label (measured each
        ** layout pass, a label's outline was most of the boxes' work) */
        double lb[4], b[4], e = t->halo * m.scale;
        cf__label_outline_box(t->label, lb);
        if (!(lb[2] >= lb[0]))
            return;
        b[0] = lb[0] * m.scale + m.dx;
        b[1] = lb[1] * m.scale + m.dy;
        b[2] = lb[2] * m.scale + m.dx;
        b[3] = lb[3] * m.scale + m.dy;
        /* a label so far off the page that its size is lost in its
        ** place's rounding (an offset of 1e17 bp) is still ink there:
        ** else it would be left out of the page checks, and of the
        ** figure, silently */
        if (lb[2] > lb[0] && !(b[2] > b[0]))
            b[2] = nextafter(b[0], INFINITY);
        if (lb[3] > lb[1] && !(b[3] > b[1]))
            b[3] = nextafter(b[1], INFINITY);
        if (t->color.a * t->opacity > 0)
            add_ink(g, b);
        if (t->halo > 0 && t->halo_color.a > 0) {
            double h[4] = { b[0] - e, b[1] - e, b[2] + e, b[3] + e };
            add_ink(g, h);
        }
        return;
    }
    cf__label_outline(t->label, &outline);
    if (t->halo > 0) {
        cf__pen_t pen = { 2 * t->halo, CF__CAP_ROUND, CF__JOIN_ROUND, NULL,
                          0 };
        stroke(g, &outline, &m, &pen, t->halo_color.a);
    }
    fill(g, &outline, &m, t->color.a * t->opacity);
}

static int
end_page(void *ctx)
{
    return ((measure_t *)ctx)->failed ? -1 : 0;
}

static const cf__backend_t measure_backend = {
    "measure", begin_page, begin_group, pop, clip, pop, draw_path,
    NULL, draw_text, end_page, NULL, NULL
};

static void
measure_init(measure_t *g, cf__raster_t *r, double scale, double dx,
             double dy, double tol)
{
    memset(g, 0, sizeof *g);
    g->r = r;
    g->m.scale = scale;
    g->m.dx = dx;
    g->m.dy = dy;
    g->m.tol = tol;
    cf__poly_init(&g->pl);
    g->pl.box_only = r == NULL;
    g->clip[0][0] = g->clip[0][1] = -INFINITY;
    g->clip[0][2] = g->clip[0][3] = INFINITY;
    g->ink[0] = 1;
    g->ink[2] = 0;
}

/* ---- the interface ------------------------------------------------------ */

int
cf__raster_open(cf__raster_t *r, int w, int h, double res, double ox,
                double oy)
{
    memset(r, 0, sizeof *r);
    if (w < 1)
        w = 1;
    if (h < 1)
        h = 1;
    r->px = cf_calloc((size_t)w * (size_t)h, 1);
    if (r->px == NULL)
        return -1;
    r->w = w;
    r->h = h;
    r->stride = w;
    r->res = res;
    r->ox = ox;
    r->oy = oy;
    return 0;
}

void
cf__raster_close(cf__raster_t *r)
{
    cf_free(r->px);
    memset(r, 0, sizeof *r);
}

void
cf__raster_clear(cf__raster_t *r, const int *b)
{
    int i0 = 0, j0 = 0, i1 = r->w, j1 = r->h, j;
    if (b != NULL) {
        i0 = b[0] > 0 ? b[0] : 0;
        j0 = b[1] > 0 ? b[1] : 0;
        i1 = b[2] < r->w ? b[2] : r->w;
        j1 = b[3] < r->h ? b[3] : r->h;
    }
    if (b == NULL)
        r->dirty[0] = r->dirty[1] = r->dirty[2] = r->dirty[3] = 0;
    if (i1 <= i0)
        return;
    /* (a row not ready holds anything: it is emptied when it is used) */
    for (j = j0; j < j1; j++)
        if (r->ready == NULL || r->ready[j])
            memset(r->px + (size_t)j * (size_t)r->stride + (size_t)i0, 0,
                   (size_t)(i1 - i0));
}

void
cf__raster_ready(cf__raster_t *r, int j0, int j1)
{
    int j;
    if (r->ready == NULL)
        return;
    for (j = j0 > 0 ? j0 : 0; j < j1 && j < r->h; j++)
        if (!r->ready[j] && (r->rows == NULL || r->rows[j] != 0)) {
            memset(r->px + (size_t)j * (size_t)r->stride, 0, (size_t)r->w);
            r->ready[j] = 1;
        }
}

int
cf__raster_paint(cf__raster_t *r, const cf__dl_t *dl, size_t from,
                 size_t to)
{
    const int all[4] = { 0, 0, r->w, r->h };
    return cf__raster_paint_in(r, dl, from, to, all);
}

int
cf__raster_paint_in(cf__raster_t *r, const cf__dl_t *dl, size_t from,
                    size_t to, const int b[4])
{
    measure_t g;
    measure_init(&g, r, r->res, -r->ox * r->res, -r->oy * r->res,
                 RASTER_TOL);
    /* whole pixels: put_poly's rounding leaves them as they are */
    g.clip[0][0] = b[0];
    g.clip[0][1] = b[1];
    g.clip[0][2] = b[2];
    g.clip[0][3] = b[3];
    cf__dl_play(dl, from, to, &measure_backend, &g);
    cf__poly_free(&g.pl);
    return g.failed ? -1 : 0;
}

int
cf__dl_ink(const cf__dl_t *dl, size_t from, size_t to, double ink[4])
{
    measure_t g;
    measure_init(&g, NULL, INK_SCALE, 0, 0, INK_TOL);
    cf__dl_play(dl, from, to, &measure_backend, &g);
    cf__poly_free(&g.pl);
    if (g.ink[2] < g.ink[0]) {
        ink[0] = ink[1] = ink[2] = ink[3] = 0;
    } else {
        ink[0] = floor(g.ink[0]) / INK_SCALE;
        ink[1] = floor(g.ink[1]) / INK_SCALE;
        ink[2] = ceil(g.ink[2]) / INK_SCALE;
        ink[3] = ceil(g.ink[3]) / INK_SCALE;
    }
    return g.failed ? -1 : 0;
}
