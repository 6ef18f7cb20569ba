/*
** The cairo backend: a display list drawn onto a cairo context, whatever
** its surface (SVG, PDF, PS, PNG in render/output/output.c; the recording
** surface of the ink box; the raster of automatic label placement).
** Every stroke sets width, cap, join and dash, so an operation draws the
** same whatever came before it.  A path reaching beyond cairo's range
** (2^23 device units in its fixed point) is cut first
** (render/backends/far-clip.h): the same inside the page.
*/
#include <math.h>

#include <cairo.h>

#include "backend.h"
#include "far-clip.h"
#include "label-cairo.h"

static void
set_source(cairo_t *cr, const cf_color_t *c, double opacity)
{
    cairo_set_source_rgba(cr, c->r, c->g, c->b, c->a * opacity);
}

static void
set_stroke(cairo_t *cr, const cf__stroke_t *s)
{
    cairo_set_line_width(cr, s->width);
    cairo_set_line_join(cr, s->join == CF__JOIN_ROUND ? CAIRO_LINE_JOIN_ROUND
                                                      : CAIRO_LINE_JOIN_MITER);
    cairo_set_line_cap(cr, s->cap == CF__CAP_ROUND ? CAIRO_LINE_CAP_ROUND
                                                   : CAIRO_LINE_CAP_BUTT);
    if (s->dash_count > 0)
        cairo_set_dash(cr, s->dash, (int)s->dash_count, 0.0);
    else
        cairo_set_dash(cr, NULL, 0, 0.0);
}

static void
begin_page(void *ctx, const cf__page_t *pg)
{
    cairo_t *cr = ctx;
    const cf_color_t *bg = &pg->background;
    if (!(bg->a > 0))
        return;
    cairo_save(cr);
    cairo_set_source_rgba(cr, bg->r, bg->g, bg->b, bg->a);
    if (pg->raster) {
        cairo_paint(cr);
    } else {
        cairo_rectangle(cr, 0, 0, pg->width, pg->height);
        cairo_fill(cr);
    }
    cairo_restore(cr);
}

static void
begin_group(void *ctx, const char *name, size_t index, const char *overlay)
{
    (void)name;
    (void)index;
    (void)overlay;
    cairo_save(ctx);
}

static void
restore(void *ctx)
{
    cairo_restore(ctx);
}

static void
clip(void *ctx, bool has_rect, const double r[4])
{
    cairo_t *cr = ctx;
    cairo_save(cr);
    if (!has_rect)
        return;
    cairo_new_path(cr);
    cairo_rectangle(cr, r[0], r[1], r[2], r[3]);
    cairo_clip(cr);
}

static void
append_path(cairo_t *cr, const cf__path_t *p)
{
    const double *v = p->coords;
    size_t i;
    cairo_new_path(cr);
    for (i = 0; i < p->nsegs; i++) {
        switch ((cf__seg_t)p->segs[i]) {
        case CF__SEG_MOVE:
            cairo_move_to(cr, v[0], v[1]);
            v += 2;
            break;
        case CF__SEG_LINE:
            cairo_line_to(cr, v[0], v[1]);
            v += 2;
            break;
        case CF__SEG_CURVE:
            cairo_curve_to(cr, v[0], v[1], v[2], v[3], v[4], v[5]);
            v += 6;
            break;
        case CF__SEG_RECT:
            cairo_rectangle(cr, v[0], v[1], v[2], v[3]);
            v += 4;
            break;
        case CF__SEG_ARC:
            cairo_arc(cr, v[0], v[1], v[2], v[3], v[4]);
            v += 5;
            break;
        case CF__SEG_CLOSE:
            cairo_close_path(cr);
            break;
        }
    }
}

/* The path of cr filled and stroked as paint says. */
static void
paint_path(cairo_t *cr, const cf__paint_t *paint)
{
    if (paint->fill) {
        set_source(cr, &paint->fill_color, paint->fill_opacity);
        if (!paint->stroke) {
            cairo_fill(cr);
            return;
        }
        cairo_fill_preserve(cr);
    }
    set_stroke(cr, &paint->line);
    set_source(cr, &paint->line.color, paint->line.opacity);
    cairo_stroke(cr);
}

static void
sink_move(void *cr, double x, double y)
{
    cairo_move_to(cr, x, y);
}

static void
sink_line(void *cr, double x, double y)
{
    cairo_line_to(cr, x, y);
}

static void
sink_curve(void *cr, double x1, double y1, double x2, double y2, double x3,
           double y3)
{
    cairo_curve_to(cr, x1, y1, x2, y2, x3, y3);
}

static void
sink_arc(void *cr, double cx, double cy, double r, double a0, double a1)
{
    cairo_arc(cr, cx, cy, r, a0, a1);
}

static void
sink_close(void *cr)
{
    cairo_close_path(cr);
}

static cf__far_ctm_t
ctm(cairo_t *cr)
{
    cairo_matrix_t m;
    cairo_get_matrix(cr, &m);
    return (cf__far_ctm_t){ m.xx, m.yx, m.xy, m.yy, m.x0, m.y0 };
}

/* A path beyond cairo's range: its fill and its stroke cut apart
** (render/backends/far-clip.h) to what the clip shows; drawn whole when
** there is no bounded clip (a recording surface) or the stroke is too wide
** to cut. */
static void
draw_far(cairo_t *cr, const cf__path_t *path, const cf__paint_t *paint,
         const cf__far_ctm_t *m)
{
    cf__far_sink_t sink = { sink_move, sink_line, sink_curve, sink_arc,
                            sink_close, cr };
    cf__far_frame_t fr;
    double ext[4];
    cairo_clip_extents(cr, &ext[0], &ext[1], &ext[2], &ext[3]);
    if (!cf__far_frame(m, ext, &fr)) {
        append_path(cr, path);
        paint_path(cr, paint);
        return;
    }
    fr.raster = cairo_surface_get_type(cairo_get_target(cr))
             == CAIRO_SURFACE_TYPE_IMAGE;
    if (paint->fill) {
        cairo_new_path(cr);
        cf__far_fill(path, &fr, &sink);
        set_source(cr, &paint->fill_color, paint->fill_opacity);
        cairo_fill(cr);
    }
    if (!paint->stroke)
        return;
    cairo_new_path(cr);
    if (!cf__far_stroke(path, &fr, &paint->line, &sink))
        append_path(cr, path);
    set_stroke(cr, &paint->line);
    set_source(cr, &paint->line.color, paint->line.opacity);
    cairo_stroke(cr);
}

static void
draw_path(void *ctx, const cf__path_t *path, const cf__paint_t *paint)
{
    cairo_t *cr = ctx;
    cf__far_ctm_t m = ctm(cr);
    if (!cf__far_safe(path, &m)) {
        draw_far(cr, path, paint, &m);
        return;
    }
    append_path(cr, path);
    paint_path(cr, paint);
}

/* A mesh as one mesh gradient (in PDF and PostScript a shading of type
** 7, tensor-product patches, which cairo writes; raster surfaces
** rasterise it): each triangle a patch of three straight sides, closed
** by cairo with its fourth corner on the first, which makes the colour
** linear on the triangle.  Later patches paint over earlier ones, as the
** list orders them. */
static void
draw_mesh(void *ctx, const cf__mesh_tri_t *t, size_t n)
{
    cairo_t *cr = ctx;
    cairo_pattern_t *m = cairo_pattern_create_mesh();
    double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
    for (size_t i = 0; i < n; i++) {
        for (unsigned k = 0; k < 6; k += 2) {
            x0 = fmin(x0, t[i].p[k]);
            x1 = fmax(x1, t[i].p[k]);
            y0 = fmin(y0, t[i].p[k + 1]);
            y1 = fmax(y1, t[i].p[k + 1]);
        }
        cairo_mesh_pattern_begin_patch(m);
        cairo_mesh_pattern_move_to(m, t[i].p[0], t[i].p[1]);
        cairo_mesh_pattern_line_to(m, t[i].p[2], t[i].p[3]);
        cairo_mesh_pattern_line_to(m, t[i].p[4], t[i].p[5]);
        for (unsigned k = 0; k < 4; k++) {
            const cf_color_t *c = &t[i].corner[k % 3];
            cairo_mesh_pattern_set_corner_color_rgb(m, k, c->r, c->g, c->b);
        }
        cairo_mesh_pattern_end_patch(m);
    }
    cairo_save(cr);
    /* bounded by the triangles' box: cairo 1.16's tagged PDF (a Figure
    ** around the page, render/output/formats.c) refuses an unbounded
    ** nesting"); the mesh paints nothing outside its patches anyway, and
    ** the box is 1 bp wider so that its edge never cuts a pixel the
    ** patches cover */
    if (n > 0) {
        cairo_rectangle(cr, x0 - 1, y0 - 1, x1 - x0 + 2, y1 - y0 + 2);
        cairo_clip(cr);
    }
    cairo_set_source(cr, m);
    cairo_paint(cr);
    cairo_restore(cr);
    cairo_pattern_destroy(m);
}

static void
draw_text(void *ctx, const cf__text_op_t *t)
{
    if (t->halo > 0)
        cf__label_draw_halo(t->label, ctx, t->ox, t->oy, &t->halo_color,
                            t->halo);
    cf__label_draw(t->label, ctx, t->ox, t->oy, &t->color, t->opacity);
}

static int
end_page(void *ctx)
{
    return cairo_status(ctx) != CAIRO_STATUS_SUCCESS;
}

/* far outside any page (bp), inside cairo's fixed-point range */
#define KNOCKOUT_FAR 1e5

/* Each box clips its inside away: a rectangle far around the page and
** the box the other way round, so that the box winds 0; successive clips
** intersect, so overlapping boxes are fine. */
static void
knockout(void *ctx, const double (*b)[4], size_t n)
{
    cairo_t *cr = ctx;
    cairo_save(cr);
    for (size_t i = 0; i < n; i++) {
        double x0 = b[i][0], y0 = b[i][1], x1 = x0 + b[i][2],
               y1 = y0 + b[i][3];
        cairo_new_path(cr);
        cairo_rectangle(cr, -KNOCKOUT_FAR, -KNOCKOUT_FAR, 2 * KNOCKOUT_FAR,
                        2 * KNOCKOUT_FAR);
        cairo_move_to(cr, x0, y0);
        cairo_line_to(cr, x0, y1);
        cairo_line_to(cr, x1, y1);
        cairo_line_to(cr, x1, y0);
        cairo_close_path(cr);
        cairo_clip(cr);
    }
}

const cf__backend_t cf__cairo_backend = {
    "cairo", begin_page, begin_group, restore, clip, restore, draw_path,
    NULL, draw_text, end_page, knockout, draw_mesh
};

/* device units per bp when measuring ink */
#define INK_SCALE 64.0

int
cf__cairo_ink(const cf__dl_t *dl, size_t from, size_t to, double ink[4])
{
    cairo_surface_t *rec;
    cairo_t *cr;
    double x, y, w, h;
    int bad;
    rec = cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, NULL);
    cr = cairo_create(rec);
    /* cairo rounds the extents out to whole device units: drawn at
    ** INK_SCALE device units per bp, the box is exact to 1/INK_SCALE bp */
    cairo_scale(cr, INK_SCALE, INK_SCALE);
    cf__dl_play(dl, from, to, &cf__cairo_backend, cr);
    cairo_destroy(cr);
    cairo_recording_surface_ink_extents(rec, &x, &y, &w, &h);
    bad = cairo_surface_status(rec) != CAIRO_STATUS_SUCCESS;
    cairo_surface_destroy(rec);
    ink[0] = x / INK_SCALE;
    ink[1] = y / INK_SCALE;
    ink[2] = (x + w) / INK_SCALE;
    ink[3] = (y + h) / INK_SCALE;
    return bad;
}
