/*
** The cairo subset of render/wasm/shim/cairo.h for the WebAssembly
** module: surfaces, the drawing state, paths (kept in device space) and
** rectangular clips; cairo-fill.c draws.  What it draws is close to
** cairo's pixels, not equal: the rasters decide where automatic labels
** go, and a label on a threshold may take another place in the page than
** in the tool (the shipped examples take the same).
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cairo-lite.h"

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
