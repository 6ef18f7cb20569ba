/*
** The SVG writer: a display list as an SVG document, the one writer of
** SVG (files and the live view through render/output/formats.c, overlay
** animations through render/output/svg-steps.c, the course pages in the
** browser module).  Paths as <path> elements with their own fill, stroke,
** caps, joins, dashes and opacities, inside one group that sets what
** most of them share (no fill, round caps and joins, cairo's miter limit
** 10); each element of the figure a <g class="KIND" data-index="N">;
** each clip a <clipPath>; markers come as paths (render/dlist/marker.c).
** A label natively: a <use> of each glyph's outline, each outline once
** in <defs> (render/output/svg-glyphs.c); in the page, where there is no
** pango: the outlines of its glyphs as one path (the outline function).
** A halo: the same outlines stroked under them.  Numbers with at most 3
** decimals (1/1000 bp); colours exact (#rrggbb or percentages).
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "backend.h"
#include "buffer.h"
#include "decimals.h"
#include "grow.h"

#define PI 3.14159265358979323846

static void
put(cf__svgw_t *w, const char *s)
{
    cf__buf_append(w->dst, s, strlen(s));
}

int
cf__svg_put_num(struct cf__buf *b, double v)
{
    char t[48];
    size_t n;
    if (!isfinite(v) || fabs(v) > 1e9)
        return -1;
    n = cf__decimals(t, v, 3);
    return cf__buf_append(b, t, n);
}

static void
fault(cf__svgw_t *w, cf__svgw_fault_kind_t k, double v)
{
    cf__scopes_fault(&w->sc, k, v);
}

static void
put_num(cf__svgw_t *w, double v)
{
    if (cf__svg_put_num(w->dst, v) == 0)
        return;
    if (isfinite(v) && fabs(v) <= 1e9)
        w->sc.bad = true;                  /* out of memory */
    else
        fault(w, CF__SVGW_FAULT_NUMBER, v);
}

static void
put_xy(cf__svgw_t *w, double x, double y)
{
    put_num(w, x);
    put(w, " ");
    put_num(w, y);
}

/* One channel as a percentage, at most 3 decimals, no trailing zeros. */
static void
put_percent(cf__svgw_t *w, double c)
{
    put_num(w, 100 * (c > 0 ? c < 1 ? c : 1 : 0));
    put(w, "%");
}

/* A colour: #rrggbb when its channels are whole 8-bit values (what a
** 0-255 or hexadecimal colour of a theme gives), else rgb() of
** percentages, so that either way the viewer gets the exact colour. */
static void
put_color(cf__svgw_t *w, const char *attr, const cf_color_t *c,
          double alpha)
{
    const double ch[3] = { c->r, c->g, c->b };
    char b[64];
    bool bytes = true;
    int i, v[3];
    for (i = 0; i < 3; i++) {
        double k = ch[i] * 255;
        v[i] = k >= 0 && k <= 255 ? (int)lround(k) : -1;
        bytes = bytes && v[i] >= 0 && fabs(k - v[i]) < 1e-6;
    }
    put(w, " ");
    put(w, attr);
    if (bytes) {
        snprintf(b, sizeof b, "=\"#%02x%02x%02x\"", v[0], v[1], v[2]);
        put(w, b);
    } else {
        put(w, "=\"rgb(");
        for (i = 0; i < 3; i++) {
            put_percent(w, ch[i]);
            put(w, i < 2 ? "," : ")\"");
        }
    }
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

/* A stroke's attributes; caps and joins where they differ from the
** page's round ones (begin_page). */
static void
put_stroke(cf__svgw_t *w, const cf__stroke_t *s)
{
    size_t i;
    put_color(w, "stroke", &s->color, s->color.a * s->opacity);
    put(w, " stroke-width=\"");
    put_num(w, s->width);
    put(w, "\"");
    if (s->cap != CF__CAP_ROUND)
        put(w, " stroke-linecap=\"butt\"");
    if (s->join != CF__JOIN_ROUND)
        put(w, " stroke-linejoin=\"miter\"");
    if (s->dash_count > 0) {
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

/* A scope: an element's group, or a clip (opened: it wrote a <g>). */
static void
push(cf__svgw_t *w, bool group, bool opened)
{
    cf__scopes_push(&w->sc, group, opened, NULL, 0);
}

static void
pop(void *ctx)
{
    cf__svgw_t *w = ctx;
    w->sc.depth--;
    if (w->sc.stack[w->sc.depth].opened)
        put(w, "</g>\n");
}

static void
put_escaped(cf__buf_t *b, const char *s)
{
    for (; *s != '\0'; s++) {
        const char *r = *s == '<' ? "&lt;" : *s == '>' ? "&gt;"
                      : *s == '&' ? "&amp;" : *s == '"' ? "&quot;" : NULL;
        if (r != NULL)
            cf__buf_append(b, r, strlen(r));
        else
            cf__buf_append(b, s, 1);
    }
}

/* The id of an SVG's title ("t") or description ("d"): FNV-1a of both
** texts, so that equal figures share it and others differ. */
static void
a11y_id(const char *title, const char *desc, char kind, char *id,
        size_t cap)
{
    unsigned long h = 2166136261ul;
    const char *parts[2] = { title, desc != NULL ? desc : "" };
    for (int k = 0; k < 2; k++) {
        for (const char *s = parts[k]; *s != '\0'; s++)
            h = ((h ^ (unsigned char)*s) * 16777619ul) & 0xfffffffful;
        h = ((h ^ 0xffu) * 16777619ul) & 0xfffffffful;
    }
    snprintf(id, cap, "cf-%c%08lx", kind, h);
}

static int
app(cf__buf_t *out, const char *s)
{
    return cf__buf_append(out, s, strlen(s));
}

int
cf__svgw_a11y_attrs(cf__buf_t *out, const char *title, const char *desc,
                    const char *lang)
{
    char t[24], d[24];
    int r;
    a11y_id(title, desc, 't', t, sizeof t);
    a11y_id(title, desc, 'd', d, sizeof d);
    r = app(out, " role=\"img\" aria-labelledby=\"");
    r |= app(out, t);
    if (desc != NULL && desc[0] != '\0') {
        r |= app(out, "\" aria-describedby=\"");
        r |= app(out, d);
    }
    r |= app(out, "\"");
    if (lang != NULL) {
        r |= app(out, " xml:lang=\"");
        put_escaped(out, lang);
        r |= app(out, "\"");
    }
    return r != 0 || out->failed ? -1 : 0;
}

int
cf__svgw_a11y_head(cf__buf_t *out, const char *title, const char *desc)
{
    char id[24];
    int r;
    a11y_id(title, desc, 't', id, sizeof id);
    r = app(out, "<title id=\"");
    r |= app(out, id);
    r |= app(out, "\">");
    put_escaped(out, title);
    r |= app(out, "</title>\n");
    if (desc != NULL && desc[0] != '\0') {
        a11y_id(title, desc, 'd', id, sizeof id);
        r |= app(out, "<desc id=\"");
        r |= app(out, id);
        r |= app(out, "\">");
        put_escaped(out, desc);
        r |= app(out, "</desc>\n");
    }
    return r != 0 || out->failed ? -1 : 0;
}

/* The document's head goes to out, the drawing to body; end_page puts
** the glyph outlines the drawing used between them. */
static void
begin_page(void *ctx, const cf__page_t *pg)
{
    cf__svgw_t *w = ctx;
    cf__buf_t *out = w->out;
    memset(&w->body, 0, sizeof w->body);
    w->dst = out;
    put(w, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<svg xmlns=\"http://www.w3.org/2000/svg\"");
    if (w->uses != NULL)
        put(w, " xmlns:xlink=\"http://www.w3.org/1999/xlink\"");
    put(w, " width=\"");
    put_num(w, pg->width);
    put(w, "pt\" height=\"");
    put_num(w, pg->height);
    put(w, "pt\" viewBox=\"0 0 ");
    put_xy(w, pg->width, pg->height);
    put(w, "\"");
    if (w->title != NULL)
        cf__svgw_a11y_attrs(out, w->title, w->caption, pg->lang);
    put(w, ">\n");
    if (w->title != NULL)
        cf__svgw_a11y_head(out, w->title, w->caption);
    w->dst = &w->body;
    w->sc.depth = 0;
    push(w, true, false);
    if (pg->background.a > 0) {
        put(w, "<rect width=\"100%\" height=\"100%\"");
        put_color(w, "fill", &pg->background, pg->background.a);
        put(w, "/>\n");
    }
    /* what most paths have: unfilled, round caps and joins; cairo's
    ** miter limit (SVG's default is 4) */
    put(w, "<g fill=\"none\" stroke-linecap=\"round\" "
           "stroke-linejoin=\"round\" stroke-miterlimit=\"10\">\n");
    push(w, false, true);
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
    cf__scopes_push(&w->sc, true, true, name, index);
}

/* Close the scopes opened since the innermost group, then it. */
static void
end_group(void *ctx)
{
    cf__scopes_end_group(&((cf__svgw_t *)ctx)->sc, 2, pop, ctx);
}

static void
clip(void *ctx, bool has_rect, const double r[4])
{
    cf__svgw_t *w = ctx;
    char b[48];
    if (!has_rect) {
        push(w, false, false);
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
    push(w, false, true);
}

static void
unclip(void *ctx)
{
    cf__svgw_t *w = ctx;
    if (w->sc.depth > 2 && !w->sc.stack[w->sc.depth - 1].group)
        pop(w);
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
    if (paint->stroke)
        put_stroke(w, &paint->line);
    put(w, "/>\n");
}

/* ---- labels ------------------------------------------------------------- */

/* Mark glyph id used; false when out of memory. */
static bool
use_glyph(cf__svgw_t *w, unsigned id)
{
    if (id >= w->nused) {
        size_t cap = w->nused;
        unsigned char *u = cf__grow_array(w->used, &cap, (size_t)id + 1, 1,
                                          64);
        if (u == NULL)
            return false;
        memset(u + w->nused, 0, cap - w->nused);
        w->used = u;
        w->nused = cap;
    }
    w->used[id] = 1;
    return true;
}

/* The label's glyphs as <use>s of their outlines and its fraction rules
** as a path, in a group that fills them in colour c, or strokes them
** (halo not NULL). */
static void
put_uses(cf__svgw_t *w, const cf__buf_t *uses, const cf__buf_t *rules,
         const cf_color_t *c, double alpha, const cf__stroke_t *halo)
{
    const cf__svgw_use_t *u = (const cf__svgw_use_t *)(void *)uses->data;
    size_t i, n = uses->size / sizeof *u;
    char id[32];
    put(w, "<g");
    if (halo != NULL)
        put_stroke(w, halo);
    else
        put_color(w, "fill", c, alpha);
    put(w, ">\n");
    for (i = 0; i < n; i++) {
        if (!use_glyph(w, u[i].id))
            w->sc.bad = true;
        snprintf(id, sizeof id, "<use xlink:href=\"#g%u\" x=\"", u[i].id);
        put(w, id);
        put_num(w, u[i].x);
        put(w, "\" y=\"");
        put_num(w, u[i].y);
        put(w, "\"/>\n");
    }
    if (rules->size > 0) {
        put(w, "<path d=\"");
        cf__buf_append(w->dst, rules->data, rules->size);
        put(w, "\"/>\n");
    }
    put(w, "</g>\n");
}

/* The stroke of a label's halo: its outlines stroked 2 halo wide (round
** joins, which a closed outline has only). */
static void
halo_stroke(const cf__text_op_t *t, cf__stroke_t *s)
{
    memset(s, 0, sizeof *s);
    s->color = t->halo_color;
    s->opacity = 1;
    s->width = 2 * t->halo;
    s->cap = CF__CAP_ROUND;
    s->join = CF__JOIN_ROUND;
}

/* The label as one path of its outlines (the page's way, and natively a
** label with a glyph missing from its font). */
static void
put_outline(cf__svgw_t *w, const cf__text_op_t *t)
{
    cf__buf_t d;
    memset(&d, 0, sizeof d);
    if (w->outline(w->outline_ctx, t, &d) != 0) {
        fault(w, CF__SVGW_FAULT_GLYPHS, 0);
        cf__buf_free(&d);
        return;
    }
    if (d.size > 0 && t->halo > 0 && t->halo_color.a > 0) {
        cf__stroke_t s;
        halo_stroke(t, &s);
        put(w, "<path d=\"");
        cf__buf_append(w->dst, d.data, d.size);
        put(w, "\"");
        put_stroke(w, &s);
        put(w, "/>\n");
    }
    if (d.size > 0) {
        put(w, "<path d=\"");
        cf__buf_append(w->dst, d.data, d.size);
        put(w, "\"");
        put_color(w, "fill", &t->color, t->color.a * t->opacity);
        put(w, "/>\n");
    }
    cf__buf_free(&d);
}

/* A label: the halo (its outlines stroked with round joins, which a
** closed outline has only), then the glyphs filled. */
static void
draw_text(void *ctx, const cf__text_op_t *t)
{
    cf__svgw_t *w = ctx;
    cf__buf_t uses, rules;
    int r;
    if (w->uses == NULL) {
        put_outline(w, t);
        return;
    }
    memset(&uses, 0, sizeof uses);
    memset(&rules, 0, sizeof rules);
    r = w->uses(w->outline_ctx, t, &uses, &rules);
    if (r == 1)
        put_outline(w, t);
    else if (r != 0)
        fault(w, CF__SVGW_FAULT_GLYPHS, 0);
    else if (uses.failed || rules.failed)
        w->sc.bad = true;
    else if (uses.size > 0 || rules.size > 0) {
        if (t->halo > 0 && t->halo_color.a > 0) {
            cf__stroke_t s;
            halo_stroke(t, &s);
            put_uses(w, &uses, &rules, NULL, 0, &s);
        }
        put_uses(w, &uses, &rules, &t->color, t->color.a * t->opacity,
                 NULL);
    }
    cf__buf_free(&uses);
    cf__buf_free(&rules);
}

/* The outlines of the glyphs used, each once. */
static void
put_defs(cf__svgw_t *w)
{
    size_t id;
    char b[64];
    bool any = false;
    for (id = 0; id < w->nused; id++) {
        if (!w->used[id])
            continue;
        if (!any)
            put(w, "<defs>\n");
        any = true;
        snprintf(b, sizeof b, "<symbol overflow=\"visible\" id=\"g%zu\">"
                              "<path d=\"", id);
        put(w, b);
        if (w->glyph_path(w->outline_ctx, (unsigned)id, w->dst) != 0)
            fault(w, CF__SVGW_FAULT_GLYPHS, 0);
        put(w, "\"/></symbol>\n");
    }
    if (any)
        put(w, "</defs>\n");
}

static int
end_page(void *ctx)
{
    cf__svgw_t *w = ctx;
    while (w->sc.depth > 0)
        pop(w);
    put(w, "</svg>\n");
    w->dst = w->out;
    put_defs(w);
    cf__buf_append(w->out, w->body.data, w->body.size);
    if (w->body.failed)
        w->sc.bad = true;
    cf__buf_free(&w->body);
    cf_free(w->used);
    w->used = NULL;
    w->nused = 0;
    return w->out->failed || w->sc.bad ? -1 : 0;
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
    push(w, false, true);
}

const cf__backend_t cf__svgw_backend = {
    "svg", begin_page, begin_group, end_group, clip, unclip, draw_path,
    NULL, draw_text, end_page, knockout, NULL
};

cf_status_t
cf__svgw_fault(const cf__svgw_t *w, const char *what, cf_diag_t *diag)
{
    return cf__scopes_diag(&w->sc, "SVG", what, diag);
}
