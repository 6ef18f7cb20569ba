/*
** The colours of a figure that a colour vision deficiency or a greyscale
** print makes hard to tell apart (cf_figure_colour_check, docs/
** accessibility.md): the figure drawn through a backend that keeps each
** element's paints (lines, fills, markers; not its labels, not the
** legend's samples), then every two paints that only their colour tells
** apart -- lines of the same dash pattern and widths within a factor of
** 1.5, markers of the same shape and sizes within 1.5, any two fills --
** (a shaded surface's facets, shades of its colours, stand for its front
** and back colours; its outline, iso-lines and net are lines as any) whose
** colours lie at least min_de apart (CIEDE2000) for normal vision
** and closer than that for a simulated one (colour-vision.h).
*/
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "colour-check.h"
#include "output-private.h"
#include "surface-lines.h"

typedef enum paint_what { PAINT_LINE, PAINT_FILL, PAINT_MARKER } paint_what_t;

typedef struct paint {
    const char *element;     /* kind name of the group */
    size_t index;            /* the element's index in the figure */
    paint_what_t what;
    cf_color_t color;        /* over a white page, opaque */
    double width;            /* line width, marker size */
    int shape;               /* marker */
    size_t dash_count;
    double dash[CF_STYLE_DASH_MAX];
} paint_t;

#define GROUP_DEPTH 16

typedef struct rec {
    paint_t *p;
    size_t n, cap;
    const char *group[GROUP_DEPTH];
    size_t index[GROUP_DEPTH];
    int depth;
    bool failed;
} rec_t;

static cf_color_t
over_white(cf_color_t c, double opacity)
{
    double a = c.a * opacity;
    cf_color_t o;
    o.r = a * c.r + (1 - a);
    o.g = a * c.g + (1 - a);
    o.b = a * c.b + (1 - a);
    o.a = 1;
    return o;
}

static bool
same_paint(const paint_t *a, const paint_t *b)
{
    return a->index == b->index && a->what == b->what
        && a->color.r == b->color.r && a->color.g == b->color.g
        && a->color.b == b->color.b && a->width == b->width
        && a->shape == b->shape && a->dash_count == b->dash_count
        && memcmp(a->dash, b->dash, a->dash_count * sizeof a->dash[0]) == 0
        && strcmp(a->element, b->element) == 0;
}

/* Paint p into the list unless it is there already. */
static void
push(rec_t *r, const paint_t *p)
{
    for (size_t k = 0; k < r->n; k++)
        if (same_paint(&r->p[k], p))
            return;
    if (r->n == r->cap) {
        size_t cap = r->cap ? 2 * r->cap : 32;
        paint_t *q = cf_realloc_array(r->p, cap, sizeof *q);
        if (q == NULL) {
            r->failed = true;
            return;
        }
        r->p = q;
        r->cap = cap;
    }
    r->p[r->n++] = *p;
}

/* Whether the innermost group is a surface. */
static bool
in_surface(const rec_t *r)
{
    return r->depth >= 1
        && strcmp(r->group[r->depth <= GROUP_DEPTH ? r->depth - 1
                                                      : GROUP_DEPTH - 1],
                  "surface") == 0;
}

static void
add(rec_t *r, paint_t *p, double alpha)
{
    size_t i;
    /* inside no element (the page), in the legend (samples of the
    ** elements' own paints), or invisible: nothing to compare */
    if (r->depth < 1 || !(alpha > 0.02))
        return;
    for (i = 0; i < (size_t)r->depth && i < GROUP_DEPTH; i++)
        if (strcmp(r->group[i], "legend") == 0)
            return;
    i = (size_t)(r->depth < GROUP_DEPTH ? r->depth : GROUP_DEPTH) - 1;
    p->element = r->group[i];
    p->index = r->index[i];
    push(r, p);
}

static void
begin_page(void *ctx, const cf__page_t *page)
{
    (void)ctx;
    (void)page;
}

static void
begin_group(void *ctx, const char *name, size_t index, const char *overlay)
{
    rec_t *r = ctx;
    (void)overlay;
    if (r->depth < GROUP_DEPTH) {
        r->group[r->depth] = name;
        r->index[r->depth] = index;
    }
    r->depth++;
}

static void
end_group(void *ctx)
{
    rec_t *r = ctx;
    if (r->depth > 0)
        r->depth--;
}

static void
clip(void *ctx, bool has_rect, const double rect[4])
{
    (void)ctx;
    (void)has_rect;
    (void)rect;
}

static void
unclip(void *ctx)
{
    (void)ctx;
}

static void
draw_path(void *ctx, const cf__path_t *path, const cf__paint_t *paint)
{
    rec_t *r = ctx;
    paint_t p;
    (void)path;
    /* a shaded surface's facets (and the hairlines of their own colour
    ** that close the seams): shades of its front and back colours, which
    ** the check takes from the element itself (surface_colours) */
    if (paint->fill && in_surface(r))
        return;
    if (paint->fill) {
        memset(&p, 0, sizeof p);
        p.what = PAINT_FILL;
        p.color = over_white(paint->fill_color, paint->fill_opacity);
        add(r, &p, paint->fill_color.a * paint->fill_opacity);
    }
    if (paint->stroke && paint->line.width > 0) {
        memset(&p, 0, sizeof p);
        p.what = PAINT_LINE;
        p.color = over_white(paint->line.color, paint->line.opacity);
        p.width = paint->line.width;
        p.dash_count = paint->line.dash_count;
        memcpy(p.dash, paint->line.dash, sizeof p.dash);
        add(r, &p, paint->line.color.a * paint->line.opacity);
    }
}

static void
draw_marker(void *ctx, const cf__marker_op_t *m)
{
    rec_t *r = ctx;
    paint_t p;
    if (m->marker == CF_MARKER_NONE || !(m->size > 0))
        return;
    memset(&p, 0, sizeof p);
    p.what = PAINT_MARKER;
    p.color = over_white(m->color, m->opacity);
    p.width = m->size;
    p.shape = (int)m->marker;
    add(r, &p, m->color.a * m->opacity);
}

static void
draw_text(void *ctx, const cf__text_op_t *t)
{
    (void)ctx;
    (void)t;
}

static int
end_page(void *ctx)
{
    return ((rec_t *)ctx)->failed ? -1 : 0;
}

/* A smooth-shaded surface's mesh: like its flat facets above, its colours
** are the element's front and back (surface_colours). */
static void
draw_mesh(void *ctx, const cf__mesh_tri_t *t, size_t n)
{
    (void)ctx;
    (void)t;
    (void)n;
}

static const cf__backend_t colour_backend = {
    "colour check", begin_page, begin_group, end_group, clip, unclip,
    draw_path, draw_marker, draw_text, end_page, NULL, draw_mesh
};

/* The front and back colours of the figure's shaded surfaces, as fills. */
static void
surface_colours(cf_figure_t *fig, rec_t *r)
{
    for (size_t i = 0; i < cf_figure_element_count(fig); i++) {
        cf_surface_shading_t sh;
        paint_t p;
        if (!cf__surface_shading(fig, i, &sh))
            continue;
        for (int side = 0; side < 2; side++) {
            memset(&p, 0, sizeof p);
            p.element = side ? "surface back" : "surface front";
            p.index = i;
            p.what = PAINT_FILL;
            p.color = over_white(side ? sh.back : sh.front, sh.opacity);
            if (sh.opacity * (side ? sh.back : sh.front).a > 0.02)
                push(r, &p);
        }
    }
}

/* Whether only colour tells paints a and b apart. */
static bool
colour_alone(const paint_t *a, const paint_t *b)
{
    double lo, hi;
    if (a->what != b->what)
        return false;
    if (a->what == PAINT_FILL)
        return true;
    lo = a->width < b->width ? a->width : b->width;
    hi = a->width < b->width ? b->width : a->width;
    if (hi > 1.5 * lo)
        return false;
    if (a->what == PAINT_MARKER)
        return a->shape == b->shape;
    return a->dash_count == b->dash_count
        && memcmp(a->dash, b->dash, a->dash_count * sizeof a->dash[0]) == 0;
}

static unsigned
hex(cf_color_t c)
{
    return (unsigned)lround(c.r * 255) << 16 | (unsigned)lround(c.g * 255) << 8
        | (unsigned)lround(c.b * 255);
}

static const char *const what_names[] = { "line", "fill", "marker" };

/* Whether the clash c (of other elements) is in r already: the same
** vision, kind of paint and pair of colours. */
static bool
reported(const cf__colour_report_t *r, const cf__colour_clash_t *c)
{
    for (size_t k = 0; k < r->count; k++) {
        const cf__colour_clash_t *d = &r->clashes[k];
        if (d->vision == c->vision && d->paint == c->paint
            && ((d->a.rgb == c->a.rgb && d->b.rgb == c->b.rgb)
                || (d->a.rgb == c->b.rgb && d->b.rgb == c->a.rgb)))
            return true;
    }
    return false;
}

static cf__colour_paint_t
clash_paint(const paint_t *p)
{
    cf__colour_paint_t c;
    c.element = p->element;
    c.number = p->index + 1;
    c.rgb = hex(p->color);
    return c;
}

/* The clashes of paints i and j (only colour tells them apart) into r:
** false when memory ran out. */
static bool
compare(const rec_t *rec, size_t i, size_t j, cf__colour_report_t *r)
{
    const paint_t *p = &rec->p[i], *q = &rec->p[j];
    double normal = cf__colour_distance(CF__VISION_NORMAL, p->color,
                                        q->color);
    if (!(normal >= r->threshold))
        return true;   /* alike on purpose, or already too close */
    for (int v = CF__VISION_PROTAN; v < CF__VISION_LAST_; v++) {
        cf__colour_clash_t c;
        c.vision = (cf__vision_t)v;
        c.paint = what_names[p->what];
        c.de = cf__colour_distance(c.vision, p->color, q->color);
        c.normal_de = normal;
        c.a = clash_paint(p);
        c.b = clash_paint(q);
        if (c.de >= r->threshold || reported(r, &c))
            continue;
        if (r->count == r->cap) {
            size_t cap = 2 * r->cap + 8;
            cf__colour_clash_t *m = cf_realloc_array(r->clashes, cap,
                                                     sizeof *m);
            if (m == NULL)
                return false;
            r->clashes = m;
            r->cap = cap;
        }
        r->clashes[r->count++] = c;
    }
    return true;
}

cf_status_t
cf__colour_report(cf_figure_t *fig, double min_de, cf__colour_report_t *r,
                  cf_diag_t *diag)
{
    rec_t rec;
    cf_status_t st;
    cf_diag_clear(diag);
    memset(r, 0, sizeof *r);
    if (!(isfinite(min_de) && min_de > 0 && min_de <= 100))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "colour check: threshold %g must lie in (0, 100]",
                           min_de);
    r->threshold = min_de;
    memset(&rec, 0, sizeof rec);
    st = cf__figure_play(fig, 0, &colour_backend, &rec, diag);
    if (st == CF_STATUS_OK)
        surface_colours(fig, &rec);
    r->paints = rec.n;
    for (size_t i = 0; st == CF_STATUS_OK && i < rec.n; i++)
        for (size_t j = i + 1; st == CF_STATUS_OK && j < rec.n; j++)
            if (colour_alone(&rec.p[i], &rec.p[j]) && !compare(&rec, i, j, r))
                st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                                 "out of memory checking the colours");
    if (st == CF_STATUS_OK && rec.failed)
        st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory checking the colours");
    cf_free(rec.p);
    return st;
}

void
cf__colour_report_fini(cf__colour_report_t *r)
{
    cf_free(r->clashes);
    memset(r, 0, sizeof *r);
}

static void
put(cf__buf_t *b, const char *fmt, ...)
{
    char s[512];
    va_list ap;
    int n;
    va_start(ap, fmt);
    n = vsnprintf(s, sizeof s, fmt, ap);
    va_end(ap);
    if (n > 0)
        cf__buf_append(b, s, (size_t)n < sizeof s ? (size_t)n : sizeof s - 1);
}

static void
put_paint(cf__buf_t *b, const cf__colour_paint_t *p)
{
    put(b, "{\"element\": \"%s\", \"index\": %zu, \"color\": \"#%06x\"}",
        p->element, p->number, p->rgb);
}

cf_status_t
cf__colour_report_json(const cf__colour_report_t *r, char **json,
                       size_t *size, cf_diag_t *diag)
{
    cf__buf_t b;
    memset(&b, 0, sizeof b);
    *json = NULL;
    *size = 0;
    put(&b, "{\"threshold\": %g, \"paints\": %zu, \"clashes\": [",
        r->threshold, r->paints);
    for (size_t k = 0; k < r->count; k++) {
        const cf__colour_clash_t *c = &r->clashes[k];
        put(&b, "%s\n  {\"vision\": \"%s\", \"paint\": \"%s\", \"de\": %.2f, "
            "\"normal_de\": %.2f, \"a\": ", k > 0 ? "," : "",
            cf__vision_name(c->vision), c->paint, c->de, c->normal_de);
        put_paint(&b, &c->a);
        put(&b, ", \"b\": ");
        put_paint(&b, &c->b);
        put(&b, "}");
    }
    put(&b, "]}\n");
    cf__buf_append(&b, "", 1);
    if (b.failed) {
        cf__buf_free(&b);
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory checking the colours");
    }
    *json = (char *)b.data;
    *size = b.size - 1;
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_colour_check(cf_figure_t *fig, double min_de, char **json,
                       size_t *size, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf__colour_report_t r;
    cf_status_t st;
    if (fig == NULL || json == NULL || size == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "colour check: figure or output is NULL");
    *json = NULL;
    *size = 0;
    st = cf__colour_report(fig, min_de, &r, diag);
    if (st == CF_STATUS_OK)
        st = cf__colour_report_json(&r, json, size, diag);
    cf__colour_report_fini(&r);
    return st;
}
