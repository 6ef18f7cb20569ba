/*
** The cairo subset of render/wasm/shim/cairo.h for the WebAssembly
** module: paths kept in device space, flattened to polygons (curves to
** 0.1 device pixel), filled by the nonzero rule with 4 sub-scanlines a
** pixel and exact horizontal coverage; strokes as the union of one
** quadrilateral a segment, joins (round: a polygonal disc; miter up to
** cairo's limit 10, else bevel) and caps, all wound alike so that the
** nonzero rule unites them; dashes split the flattened line.  A8 images
** composite OVER and CLEAR within a rectangular clip; recording surfaces
** only gather ink extents.  What it draws is close to cairo's pixels,
** not equal: the rasters decide where automatic labels go, and a label
** on a threshold may choose another place in the page than natively.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cairo.h"

#define PI 3.14159265358979323846
#define SUB 4                 /* sub-scanlines a pixel */
#define TOL 0.1               /* flattening tolerance, device pixels */
#define DEPTH 32

enum { IMAGE, RECORDING };

struct _cairo_surface {
    int kind;
    int w, h, stride;
    unsigned char *data;
    double ink[4];
    int has_ink;
    cairo_status_t status;
};

typedef struct { double xx, yx, xy, yy, x0, y0; } mat_t;

typedef struct gstate {
    mat_t m;
    double alpha;
    cairo_surface_t *src;
    double src_x, src_y;
    cairo_operator_t op;
    double width;
    cairo_line_cap_t cap;
    cairo_line_join_t join;
    double dash[16];
    int ndash;
    int has_clip;
    double clip[4];           /* device x0 y0 x1 y1 */
} gstate_t;

typedef struct { double x, y; } pt_t;

/* growable arrays of points and of edges */
typedef struct { pt_t *p; int n, cap; } pts_t;
typedef struct { double x0, y0, x1, y1; int dir; } edge_t;
typedef struct { edge_t *e; int n, cap; double box[4]; int failed; } poly_t;

struct _cairo {
    cairo_surface_t *target;
    gstate_t st[DEPTH];
    int depth;
    cairo_path_data_t *path;
    int n, cap;
    int has_cp;
    double cpx, cpy, spx, spy;   /* device: current point, subpath start */
    cairo_status_t status;
};

struct _cairo_font_options { int unused; };

int cairo_version(void) { return 0; }

/* ---- surfaces ----------------------------------------------------------- */

cairo_surface_t *
cairo_image_surface_create(cairo_format_t format, int width, int height)
{
    cairo_surface_t *s = calloc(1, sizeof *s);
    (void)format;
    if (s == NULL)
        return NULL;
    s->kind = IMAGE;
    if (width < 0 || height < 0 || width > 32767 || height > 32767) {
        s->status = CAIRO_STATUS_INVALID_SIZE;
        return s;
    }
    s->w = width;
    s->h = height;
    s->stride = (width + 3) & ~3;
    s->data = calloc((size_t)s->stride * (size_t)height + 1, 1);
    if (s->data == NULL)
        s->status = CAIRO_STATUS_NO_MEMORY;
    return s;
}

cairo_surface_t *
cairo_recording_surface_create(cairo_content_t content, const void *extents)
{
    cairo_surface_t *s = calloc(1, sizeof *s);
    (void)content;
    (void)extents;
    if (s != NULL)
        s->kind = RECORDING;
    return s;
}

unsigned char *
cairo_image_surface_get_data(cairo_surface_t *s)
{
    return s != NULL ? s->data : NULL;
}

int cairo_image_surface_get_width(cairo_surface_t *s) { return s ? s->w : 0; }
int cairo_image_surface_get_height(cairo_surface_t *s) { return s ? s->h : 0; }
int cairo_image_surface_get_stride(cairo_surface_t *s)
{
    return s ? s->stride : 0;
}
void cairo_surface_flush(cairo_surface_t *s) { (void)s; }

cairo_status_t
cairo_surface_status(cairo_surface_t *s)
{
    return s != NULL ? s->status : CAIRO_STATUS_NO_MEMORY;
}

void
cairo_surface_destroy(cairo_surface_t *s)
{
    if (s == NULL)
        return;
    free(s->data);
    free(s);
}

void
cairo_recording_surface_ink_extents(cairo_surface_t *s, double *x0,
                                    double *y0, double *width,
                                    double *height)
{
    int any = s != NULL && s->has_ink;
    *x0 = any ? s->ink[0] : 0;
    *y0 = any ? s->ink[1] : 0;
    *width = any ? s->ink[2] - s->ink[0] : 0;
    *height = any ? s->ink[3] - s->ink[1] : 0;
}

/* ---- contexts and state ------------------------------------------------- */

static gstate_t *
gs(cairo_t *cr)
{
    return &cr->st[cr->depth];
}

static void
to_device(const mat_t *m, double x, double y, double *dx, double *dy)
{
    *dx = m->xx * x + m->xy * y + m->x0;
    *dy = m->yx * x + m->yy * y + m->y0;
}

static void
to_user(const mat_t *m, double x, double y, double *ux, double *uy)
{
    double det = m->xx * m->yy - m->xy * m->yx;
    x -= m->x0;
    y -= m->y0;
    if (det == 0) {
        *ux = *uy = 0;
        return;
    }
    *ux = (m->yy * x - m->xy * y) / det;
    *uy = (-m->yx * x + m->xx * y) / det;
}

cairo_t *
cairo_create(cairo_surface_t *target)
{
    cairo_t *cr = calloc(1, sizeof *cr);
    if (cr == NULL)
        return NULL;
    cr->target = target;
    cr->st[0].m.xx = cr->st[0].m.yy = 1;
    cr->st[0].alpha = 1;
    cr->st[0].op = CAIRO_OPERATOR_OVER;
    cr->st[0].width = 2;
    cr->st[0].join = CAIRO_LINE_JOIN_MITER;
    if (target == NULL || target->status != CAIRO_STATUS_SUCCESS)
        cr->status = CAIRO_STATUS_NO_MEMORY;
    return cr;
}

void
cairo_destroy(cairo_t *cr)
{
    if (cr == NULL)
        return;
    free(cr->path);
    free(cr);
}

cairo_status_t
cairo_status(cairo_t *cr)
{
    return cr != NULL ? cr->status : CAIRO_STATUS_NO_MEMORY;
}

void
cairo_save(cairo_t *cr)
{
    if (cr->depth + 1 >= DEPTH) {
        cr->status = CAIRO_STATUS_NO_MEMORY;
        return;
    }
    cr->st[cr->depth + 1] = cr->st[cr->depth];
    cr->depth++;
}

void
cairo_restore(cairo_t *cr)
{
    if (cr->depth == 0) {
        cr->status = CAIRO_STATUS_INVALID_RESTORE;
        return;
    }
    cr->depth--;
}

void
cairo_scale(cairo_t *cr, double sx, double sy)
{
    mat_t *m = &gs(cr)->m;
    m->xx *= sx;
    m->yx *= sx;
    m->xy *= sy;
    m->yy *= sy;
}

void
cairo_identity_matrix(cairo_t *cr)
{
    mat_t *m = &gs(cr)->m;
    memset(m, 0, sizeof *m);
    m->xx = m->yy = 1;
}

void
cairo_set_source_rgba(cairo_t *cr, double r, double g, double b, double a)
{
    (void)r;
    (void)g;
    (void)b;
    gs(cr)->alpha = a < 0 ? 0 : a > 1 ? 1 : a;
    gs(cr)->src = NULL;
}

void
cairo_set_source_surface(cairo_t *cr, cairo_surface_t *s, double x, double y)
{
    gs(cr)->src = s;
    gs(cr)->src_x = x;
    gs(cr)->src_y = y;
}

void cairo_set_operator(cairo_t *cr, cairo_operator_t op) { gs(cr)->op = op; }
void cairo_set_line_width(cairo_t *cr, double w) { gs(cr)->width = w; }
void cairo_set_line_cap(cairo_t *cr, cairo_line_cap_t c) { gs(cr)->cap = c; }
void cairo_set_line_join(cairo_t *cr, cairo_line_join_t j)
{
    gs(cr)->join = j;
}

void
cairo_set_dash(cairo_t *cr, const double *dashes, int n, double offset)
{
    int i;
    double sum = 0;
    (void)offset;
    gs(cr)->ndash = 0;
    if (dashes == NULL || n <= 0 || n > 16)
        return;
    for (i = 0; i < n; i++) {
        gs(cr)->dash[i] = dashes[i];
        sum += dashes[i];
    }
    if (sum > 0)
        gs(cr)->ndash = n;
}

/* ---- paths -------------------------------------------------------------- */

static void
put_data(cairo_t *cr, cairo_path_data_type_t type, const double *xy,
         int npts)
{
    int i, need = 1 + npts;
    if (cr->n + need > cr->cap) {
        int cap = cr->cap ? 2 * cr->cap : 256;
        cairo_path_data_t *p;
        while (cap < cr->n + need)
            cap *= 2;
        p = realloc(cr->path, (size_t)cap * sizeof *p);
        if (p == NULL) {
            cr->status = CAIRO_STATUS_NO_MEMORY;
            return;
        }
        cr->path = p;
        cr->cap = cap;
    }
    cr->path[cr->n].header.type = type;
    cr->path[cr->n].header.length = need;
    for (i = 0; i < npts; i++) {
        cr->path[cr->n + 1 + i].point.x = xy[2 * i];
        cr->path[cr->n + 1 + i].point.y = xy[2 * i + 1];
    }
    cr->n += need;
}

void
cairo_new_path(cairo_t *cr)
{
    cr->n = 0;
    cr->has_cp = 0;
}

void
cairo_move_to(cairo_t *cr, double x, double y)
{
    double d[2];
    to_device(&gs(cr)->m, x, y, &d[0], &d[1]);
    put_data(cr, CAIRO_PATH_MOVE_TO, d, 1);
    cr->cpx = cr->spx = d[0];
    cr->cpy = cr->spy = d[1];
    cr->has_cp = 1;
}

void
cairo_line_to(cairo_t *cr, double x, double y)
{
    double d[2];
    if (!cr->has_cp) {
        cairo_move_to(cr, x, y);
        return;
    }
    to_device(&gs(cr)->m, x, y, &d[0], &d[1]);
    put_data(cr, CAIRO_PATH_LINE_TO, d, 1);
    cr->cpx = d[0];
    cr->cpy = d[1];
}

void
cairo_curve_to(cairo_t *cr, double x1, double y1, double x2, double y2,
               double x3, double y3)
{
    double d[6];
    const mat_t *m = &gs(cr)->m;
    if (!cr->has_cp)
        cairo_move_to(cr, x1, y1);
    to_device(m, x1, y1, &d[0], &d[1]);
    to_device(m, x2, y2, &d[2], &d[3]);
    to_device(m, x3, y3, &d[4], &d[5]);
    put_data(cr, CAIRO_PATH_CURVE_TO, d, 3);
    cr->cpx = d[4];
    cr->cpy = d[5];
}

void
cairo_close_path(cairo_t *cr)
{
    if (!cr->has_cp)
        return;
    put_data(cr, CAIRO_PATH_CLOSE_PATH, NULL, 0);
    /* as cairo: the current point is the subpath's start, with a move */
    {
        double d[2] = { cr->spx, cr->spy };
        put_data(cr, CAIRO_PATH_MOVE_TO, d, 1);
    }
    cr->cpx = cr->spx;
    cr->cpy = cr->spy;
}

void
cairo_rectangle(cairo_t *cr, double x, double y, double w, double h)
{
    cairo_move_to(cr, x, y);
    cairo_line_to(cr, x + w, y);
    cairo_line_to(cr, x + w, y + h);
    cairo_line_to(cr, x, y + h);
    cairo_close_path(cr);
}

void
cairo_arc(cairo_t *cr, double xc, double yc, double r, double a1, double a2)
{
    int n, i;
    double step;
    if (!(a2 >= a1) && isfinite(a1) && isfinite(a2) && a1 - a2 < 1e6)
        while (a2 < a1)
            a2 += 2 * PI;
    if (!(a2 >= a1 && a2 - a1 < 1e6 && isfinite(r)))
        return;
    if (cr->has_cp)
        cairo_line_to(cr, xc + r * cos(a1), yc + r * sin(a1));
    else
        cairo_move_to(cr, xc + r * cos(a1), yc + r * sin(a1));
    n = (int)ceil((a2 - a1) / (PI / 2) - 1e-9);
    if (n < 1)
        n = 1;
    step = (a2 - a1) / n;
    for (i = 0; i < n; i++) {
        double a = a1 + i * step, b = a + step;
        double k = 4.0 / 3.0 * tan(step / 4) * r;
        double x0 = xc + r * cos(a), y0 = yc + r * sin(a);
        double x3 = xc + r * cos(b), y3 = yc + r * sin(b);
        cairo_curve_to(cr, x0 - k * sin(a), y0 + k * cos(a),
                       x3 + k * sin(b), y3 - k * cos(b), x3, y3);
    }
}

cairo_bool_t cairo_has_current_point(cairo_t *cr) { return cr->has_cp; }

void
cairo_get_current_point(cairo_t *cr, double *x, double *y)
{
    if (!cr->has_cp) {
        *x = *y = 0;
        return;
    }
    to_user(&gs(cr)->m, cr->cpx, cr->cpy, x, y);
}

/* The path in user space, without the moves cairo_close_path adds
** unless something follows them. */
cairo_path_t *
cairo_copy_path(cairo_t *cr)
{
    cairo_path_t *p = calloc(1, sizeof *p);
    int i, j;
    if (p == NULL)
        return NULL;
    p->data = malloc((size_t)(cr->n + 1) * sizeof *p->data);
    if (p->data == NULL) {
        p->status = CAIRO_STATUS_NO_MEMORY;
        return p;
    }
    for (i = 0; i < cr->n; i += cr->path[i].header.length) {
        int len = cr->path[i].header.length;
        if (cr->path[i].header.type == CAIRO_PATH_MOVE_TO
            && (i + len >= cr->n
                || cr->path[i + len].header.type == CAIRO_PATH_MOVE_TO))
            continue;
        p->data[p->num_data] = cr->path[i];
        for (j = 1; j < len; j++)
            to_user(&gs(cr)->m, cr->path[i + j].point.x,
                    cr->path[i + j].point.y,
                    &p->data[p->num_data + j].point.x,
                    &p->data[p->num_data + j].point.y);
        p->num_data += len;
    }
    return p;
}

void
cairo_path_destroy(cairo_path_t *path)
{
    if (path == NULL)
        return;
    free(path->data);
    free(path);
}

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
    cairo_new_path(cr);
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
        cairo_new_path(cr);
        return;
    }
    if (s.hw > 0 && flatten(cr, stroke_subpath, &s) != 0)
        s.pl.failed = 1;
    if (s.hw > 0)
        draw_poly(cr, &s.pl);
    free(s.pl.e);
    cairo_new_path(cr);
}

/* ---- clips and paints --------------------------------------------------- */

void
cairo_clip(cairo_t *cr)
{
    gstate_t *g = gs(cr);
    double b[4] = { 1, 1, 0, 0 };
    int i, any = 0;
    for (i = 0; i < cr->n; i += cr->path[i].header.length) {
        int j;
        for (j = 1; j < cr->path[i].header.length; j++) {
            double x = cr->path[i + j].point.x, y = cr->path[i + j].point.y;
            if (!any) {
                b[0] = b[2] = x;
                b[1] = b[3] = y;
                any = 1;
            }
            b[0] = fmin(b[0], x);
            b[1] = fmin(b[1], y);
            b[2] = fmax(b[2], x);
            b[3] = fmax(b[3], y);
        }
    }
    if (!any)
        b[0] = b[1] = b[2] = b[3] = 0;
    if (g->has_clip) {
        b[0] = fmax(b[0], g->clip[0]);
        b[1] = fmax(b[1], g->clip[1]);
        b[2] = fmin(b[2], g->clip[2]);
        b[3] = fmin(b[3], g->clip[3]);
    }
    memcpy(g->clip, b, sizeof b);
    g->has_clip = 1;
    cairo_new_path(cr);
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

/* ---- font options ------------------------------------------------------- */

cairo_font_options_t *
cairo_font_options_create(void)
{
    return calloc(1, sizeof(cairo_font_options_t));
}

void cairo_font_options_destroy(cairo_font_options_t *o) { free(o); }
void cairo_font_options_set_hint_metrics(cairo_font_options_t *o,
                                         cairo_hint_metrics_t h)
{
    (void)o;
    (void)h;
}
void cairo_font_options_set_hint_style(cairo_font_options_t *o,
                                       cairo_hint_style_t h)
{
    (void)o;
    (void)h;
}
void cairo_font_options_set_antialias(cairo_font_options_t *o,
                                      cairo_antialias_t a)
{
    (void)o;
    (void)a;
}
