/*
** The SVG writer: a display list as an SVG document without cairo, for
** the WebAssembly module of the course pages (docs/interactive.md), where
** there is no cairo.  It draws what the cairo backend draws (the same
** paths, paints, markers of render/marker.c, clips and groups), as SVG
** elements: paths with their own fill, stroke, caps, joins, dashes and
** opacities; each clip a <clipPath>; a label as the outlines of its
** glyphs, which the caller's outline function gives (natively from pango,
** render/glyph-outline.c; in the page from the glyph data embedded at
** export time), a halo stroked under them.  Caps and joins carry over
** from a stroke to a later marker of the same group as in cairo's state.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "backend.h"
#include "render-private.h"

#define PI 3.14159265358979323846

static void
put(cf__svgw_t *w, const char *s)
{
    cf__buf_append(w->out, s, strlen(s));
}

int
cf__svg_put_num(struct cf__buf *b, double v)
{
    char t[40];
    int n;
    if (!isfinite(v) || fabs(v) > 1e9)
        return -1;
    n = snprintf(t, sizeof t, "%.3f", v);
    while (n > 0 && t[n - 1] == '0')
        t[--n] = '\0';
    if (n > 0 && t[n - 1] == '.')
        t[--n] = '\0';
    if (strcmp(t, "-0") == 0)
        strcpy(t, "0");
    return cf__buf_append(b, t, strlen(t));
}

static void
put_num(cf__svgw_t *w, double v)
{
    if (cf__svg_put_num(w->out, v) != 0)
        w->bad = true;
}

static void
put_xy(cf__svgw_t *w, double x, double y)
{
    put_num(w, x);
    put(w, " ");
    put_num(w, y);
}

static void
put_color(cf__svgw_t *w, const char *attr, const cf_color_t *c,
          double alpha)
{
    char b[96];
    snprintf(b, sizeof b, " %s=\"rgb(%.3f%%,%.3f%%,%.3f%%)\"", attr,
             100 * c->r, 100 * c->g, 100 * c->b);
    put(w, b);
    if (alpha < 1) {
        snprintf(b, sizeof b, " %s-opacity=\"%.4g\"", attr,
                 alpha > 0 ? alpha : 0);
        put(w, b);
    }
}

/* cairo_arc: counter-clockwise on the y-down page (increasing angle, SVG's
** sweep 1) from a0 to a1 raised by whole turns to a1 >= a0; a line from
** the current point to its start.  Pieces of at most half a turn. */
static void
arc(cf__svgw_t *w, const double *v, bool *have_cp)
{
    double x = v[0], y = v[1], r = v[2], a0 = v[3], a1 = v[4];
    int n, i;
    if (!(a1 >= a0) && isfinite(a1) && isfinite(a0) && a0 - a1 < 1e6)
        while (a1 < a0)
            a1 += 2 * PI;
    if (!(a1 >= a0 && a1 - a0 < 1e6 && isfinite(r)))
        return;
    put(w, *have_cp ? "L" : "M");
    put_xy(w, x + r * cos(a0), y + r * sin(a0));
    *have_cp = true;
    if (!(r > 0))
        return;
    n = (int)ceil((a1 - a0) / PI - 1e-9);
    for (i = 1; i <= n; i++) {
        double b = i == n ? a1 : a0 + i * PI;
        put(w, "A");
        put_num(w, r);
        put(w, " ");
        put_num(w, r);
        put(w, " 0 0 1 ");
        put_xy(w, x + r * cos(b), y + r * sin(b));
    }
}

/* The path data of p: the d attribute's value. */
static void
put_path(cf__svgw_t *w, const cf__path_t *p)
{
    const double *v = p->coords;
    bool have_cp = false;
    size_t i;
    for (i = 0; i < p->nsegs; i++) {
        switch ((cf__seg_t)p->segs[i]) {
        case CF__SEG_MOVE:
        case CF__SEG_LINE:
            put(w, p->segs[i] == CF__SEG_MOVE || !have_cp ? "M" : "L");
            put_xy(w, v[0], v[1]);
            have_cp = true;
            v += 2;
            break;
        case CF__SEG_CURVE:
            if (!have_cp) {
                put(w, "M");
                put_xy(w, v[0], v[1]);
            }
            put(w, "C");
            put_xy(w, v[0], v[1]);
            put(w, " ");
            put_xy(w, v[2], v[3]);
            put(w, " ");
            put_xy(w, v[4], v[5]);
            have_cp = true;
            v += 6;
            break;
        case CF__SEG_RECT:
            put(w, "M");
            put_xy(w, v[0], v[1]);
            put(w, "h");
            put_num(w, v[2]);
            put(w, "v");
            put_num(w, v[3]);
            put(w, "h");
            put_num(w, -v[2]);
            put(w, "Z");
            have_cp = true;
            v += 4;
            break;
        case CF__SEG_ARC:
            arc(w, v, &have_cp);
            v += 5;
            break;
        case CF__SEG_CLOSE:
            if (have_cp)
                put(w, "Z");
            break;
        }
    }
}

static void
put_stroke(cf__svgw_t *w, const cf__stroke_t *s, cf__cap_t cap,
           cf__join_t join, bool dashed)
{
    size_t i;
    put_color(w, "stroke", &s->color, s->color.a * s->opacity);
    put(w, " stroke-width=\"");
    put_num(w, s->width);
    put(w, "\" stroke-miterlimit=\"10\"");
    if (cap == CF__CAP_ROUND)
        put(w, " stroke-linecap=\"round\"");
    if (join == CF__JOIN_ROUND)
        put(w, " stroke-linejoin=\"round\"");
    if (dashed && s->dash_count > 0) {
        put(w, " stroke-dasharray=\"");
        for (i = 0; i < s->dash_count; i++) {
            if (i > 0)
                put(w, " ");
            put_num(w, s->dash[i]);
        }
        put(w, "\"");
    }
}

/* ---- the backend -------------------------------------------------------- */

static void
push(cf__svgw_t *w, bool group)
{
    if (w->depth >= CF__SVGW_DEPTH) {
        w->bad = true;
        return;
    }
    w->stack[w->depth].group = group;
    w->stack[w->depth].cap = w->depth > 0 ? w->stack[w->depth - 1].cap
                                          : CF__CAP_BUTT;
    w->stack[w->depth].join = w->depth > 0 ? w->stack[w->depth - 1].join
                                           : CF__JOIN_MITER;
    w->depth++;
}

static void
begin_page(void *ctx, const cf__page_t *pg)
{
    cf__svgw_t *w = ctx;
    put(w, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"");
    put_num(w, pg->width);
    put(w, "pt\" height=\"");
    put_num(w, pg->height);
    put(w, "pt\" viewBox=\"0 0 ");
    put_xy(w, pg->width, pg->height);
    put(w, "\">\n");
    w->depth = 0;
    push(w, true);
    if (pg->background.a > 0) {
        put(w, "<rect width=\"100%\" height=\"100%\"");
        put_color(w, "fill", &pg->background, pg->background.a);
        put(w, "/>\n");
    }
}

static void
begin_group(void *ctx, const char *name, size_t index, const char *overlay)
{
    cf__svgw_t *w = ctx;
    char b[64];
    (void)overlay;
    snprintf(b, sizeof b, "%zu", index);
    put(w, "<g class=\"");
    put(w, name);
    put(w, "\" data-index=\"");
    put(w, b);
    put(w, "\">\n");
    push(w, true);
}

/* Close the scopes opened since the innermost group, then it. */
static void
end_group(void *ctx)
{
    cf__svgw_t *w = ctx;
    while (w->depth > 1) {
        bool g = w->stack[--w->depth].group;
        put(w, "</g>\n");
        if (g)
            break;
    }
}

static void
clip(void *ctx, bool has_rect, const double r[4])
{
    cf__svgw_t *w = ctx;
    char b[48];
    if (!has_rect) {
        put(w, "<g>\n");
        push(w, false);
        return;
    }
    snprintf(b, sizeof b, "c%u", ++w->clips);
    put(w, "<clipPath id=\"");
    put(w, b);
    put(w, "\"><rect x=\"");
    put_num(w, r[0]);
    put(w, "\" y=\"");
    put_num(w, r[1]);
    put(w, "\" width=\"");
    put_num(w, r[2]);
    put(w, "\" height=\"");
    put_num(w, r[3]);
    put(w, "\"/></clipPath>\n<g clip-path=\"url(#");
    put(w, b);
    put(w, ")\">\n");
    push(w, false);
}

static void
unclip(void *ctx)
{
    cf__svgw_t *w = ctx;
    if (w->depth > 1 && !w->stack[w->depth - 1].group) {
        w->depth--;
        put(w, "</g>\n");
    }
}

static void
draw_path(void *ctx, const cf__path_t *path, const cf__paint_t *paint)
{
    cf__svgw_t *w = ctx;
    put(w, "<path d=\"");
    put_path(w, path);
    put(w, "\"");
    if (paint->fill)
        put_color(w, "fill", &paint->fill_color,
                  paint->fill_color.a * paint->fill_opacity);
    else
        put(w, " fill=\"none\"");
    if (paint->stroke) {
        w->stack[w->depth - 1].cap = paint->line.cap;
        w->stack[w->depth - 1].join = paint->line.join;
        put_stroke(w, &paint->line, paint->line.cap, paint->line.join, true);
    }
    put(w, "/>\n");
}

static void
draw_marker(void *ctx, const cf__marker_op_t *m)
{
    cf__svgw_t *w = ctx;
    cf__marker_shape_t sh;
    cf__stroke_t s;
    if (!cf__marker_shape(m, &sh))
        return;
    put(w, "<path d=\"");
    put_path(w, &sh.path);
    put(w, "\"");
    memset(&s, 0, sizeof s);
    s.color = m->color;
    s.opacity = m->opacity;
    s.width = sh.line_width;
    switch (sh.paint) {
    case CF__MARKER_FILL:
        put_color(w, "fill", &m->color, m->color.a * m->opacity);
        break;
    case CF__MARKER_FILL_STROKE:
        put_color(w, "fill", &m->fill, m->fill.a * m->opacity);
        put_stroke(w, &s, w->stack[w->depth - 1].cap,
                   w->stack[w->depth - 1].join, false);
        break;
    case CF__MARKER_STROKE:
        put(w, " fill=\"none\"");
        put_stroke(w, &s, CF__CAP_BUTT, w->stack[w->depth - 1].join, false);
        break;
    }
    put(w, "/>\n");
}

static void
draw_text(void *ctx, const cf__text_op_t *t)
{
    cf__svgw_t *w = ctx;
    cf__buf_t d;
    memset(&d, 0, sizeof d);
    if (w->outline(w->outline_ctx, t, &d) != 0) {
        w->bad = true;
        cf__buf_free(&d);
        return;
    }
    if (d.size == 0)
        return;
    if (t->halo > 0 && t->halo_color.a > 0) {
        cf__stroke_t s;
        memset(&s, 0, sizeof s);
        s.color = t->halo_color;
        s.opacity = 1;
        s.width = 2 * t->halo;
        put(w, "<path d=\"");
        cf__buf_append(w->out, d.data, d.size);
        put(w, "\" fill=\"none\"");
        put_stroke(w, &s, w->stack[w->depth - 1].cap, CF__JOIN_ROUND,
                   false);
        put(w, "/>\n");
    }
    put(w, "<path d=\"");
    cf__buf_append(w->out, d.data, d.size);
    put(w, "\"");
    put_color(w, "fill", &t->color, t->color.a * t->opacity);
    put(w, "/>\n");
    cf__buf_free(&d);
}

static int
end_page(void *ctx)
{
    cf__svgw_t *w = ctx;
    while (w->depth > 0) {
        w->depth--;
        if (w->depth > 0)
            put(w, "</g>\n");
    }
    put(w, "</svg>\n");
    return w->out->failed || w->bad ? -1 : 0;
}

/* Each box clips its inside away (even-odd with a rectangle far around
** the page); each clip path is clipped by the one before, so they
** intersect, and one scope holds them all. */
static void
knockout(void *ctx, const double (*b)[4], size_t n)
{
    cf__svgw_t *w = ctx;
    char id[48];
    for (size_t i = 0; i < n; i++) {
        put(w, "<clipPath id=\"");
        snprintf(id, sizeof id, "c%u", ++w->clips);
        put(w, id);
        if (i > 0) {
            snprintf(id, sizeof id, "c%u", w->clips - 1);
            put(w, "\" clip-path=\"url(#");
            put(w, id);
            put(w, ")");
        }
        put(w, "\"><path clip-rule=\"evenodd\" d=\"M-100000 -100000H100000"
               "V100000H-100000Z M");
        put_xy(w, b[i][0], b[i][1]);
        put(w, "h");
        put_num(w, b[i][2]);
        put(w, "v");
        put_num(w, b[i][3]);
        put(w, "h");
        put_num(w, -b[i][2]);
        put(w, "Z\"/></clipPath>\n");
    }
    snprintf(id, sizeof id, "c%u", w->clips);
    put(w, "<g clip-path=\"url(#");
    put(w, id);
    put(w, ")\">\n");
    push(w, false);
}

const cf__backend_t cf__svgw_backend = {
    "svg", begin_page, begin_group, end_group, clip, unclip, draw_path,
    draw_marker, draw_text, end_page, knockout
};
