/*
** The PDF writer's pages: a display list as the content stream of a PDF
** page (render/backends/backend.h; the document around the pages is
** render/backends/pdf-doc.c).  The page is flipped once (1 0 0 -1 0 H
** cm), so that the stream speaks the display list's y-down bp.  Paths
** as m l c re h (arcs as cubic pieces, render/dlist/dlist.h), filled
** (nonzero) and stroked as the cairo backend does, with PDF's default
** miter limit 10 (cairo's); a path with a translucent fill and a stroke
** is painted twice (f then S: B would knock the fill out under the
** stroke).  Colours as rg / RG, opacities through ExtGStates (/aN sets
** /ca, /AN /CA; one pair per distinct value).  What the stream has set
** is remembered (and restored with each Q), so that a run of paths of
** one style sets it once.  Clips are q re W n ... Q; a knockout clips
** the page minus each box; a mesh is a free-form Gouraud shading (type
** 4: each triangle's colour linear, as cairo's patches) painted with sh.
** A path far off the page is cut as the cairo backend cuts it
** (render/backends/far-clip.h), to the visible box.  A label is text:
** each glyph shown (Tj) with a Tm of its font's matrix at its origin, in
** the fonts of render/backends/pdf-fonts.h; its fraction rules filled;
** a label that cannot be text (see backend.h) is the outlines of its
** glyphs, filled.  A halo is the outlines stroked under the label (2
** halo wide, round joins), as the cairo backend draws it.  Numbers have
** at most 3 decimals (1/1000 bp), colours and opacities 4; a number not
** finite or beyond 1e9 bp is a fault, as in the SVG writer (the scopes
** and faults are theirs: cf__scopes_t).  The whole page is the marked
** content of the document's Figure (MCID 0 on every page).
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "backend.h"
#include "buffer.h"
#include "decimals.h"
#include "far-clip.h"
#include "grow.h"
#include "pdf-fonts.h"

static void
put(cf__pdfw_t *w, const char *s)
{
    cf__buf_append(&w->content, s, strlen(s));
}

static void
fault(cf__pdfw_t *w, cf__svgw_fault_kind_t k, double v)
{
    cf__scopes_fault(&w->sc, k, v);
}

/* v and a space. */
static void
num(cf__pdfw_t *w, double v)
{
    if (cf__svg_put_num(&w->content, v) != 0) {
        if (isfinite(v) && fabs(v) <= 1e9)
            w->sc.bad = true;                  /* out of memory */
        else
            fault(w, CF__SVGW_FAULT_NUMBER, v);
        return;
    }
    put(w, " ");
}

/* A colour channel or opacity (0..1, 4 decimals) and a space. */
static void
unit(cf__pdfw_t *w, double v)
{
    char t[48];
    size_t n = cf__decimals(t, v > 0 ? v < 1 ? v : 1 : 0, 4);
    t[n++] = ' ';
    cf__buf_append(&w->content, t, n);
}

static void
point(cf__pdfw_t *w, double x, double y, const char *op)
{
    num(w, x);
    num(w, y);
    put(w, op);
}

/* ---- paths -------------------------------------------------------------- */

typedef struct path_ctx {
    cf__pdfw_t *w;
    bool have_cp;
} path_ctx_t;

static void
arc_to(void *ctx, const double *p, int n)
{
    path_ctx_t *pc = ctx;
    if (n == 1) {
        point(pc->w, p[0], p[1], pc->have_cp ? "l\n" : "m\n");
        pc->have_cp = true;
        return;
    }
    num(pc->w, p[0]);
    num(pc->w, p[1]);
    num(pc->w, p[2]);
    num(pc->w, p[3]);
    point(pc->w, p[4], p[5], "c\n");
}

static void
put_path(cf__pdfw_t *w, const cf__path_t *p)
{
    const double *v = p->coords;
    path_ctx_t pc = { w, false };
    size_t i;
    for (i = 0; i < p->nsegs; i++) {
        switch ((cf__seg_t)p->segs[i]) {
        case CF__SEG_MOVE:
        case CF__SEG_LINE:
            point(w, v[0], v[1], p->segs[i] == CF__SEG_MOVE || !pc.have_cp
                                     ? "m\n" : "l\n");
            pc.have_cp = true;
            v += 2;
            break;
        case CF__SEG_CURVE:
            if (!pc.have_cp)
                point(w, v[0], v[1], "m\n");
            arc_to(&pc, v, 3);
            pc.have_cp = true;
            v += 6;
            break;
        case CF__SEG_RECT:
            num(w, v[0]);
            num(w, v[1]);
            num(w, v[2]);
            num(w, v[3]);
            put(w, "re\n");
            pc.have_cp = true;
            v += 4;
            break;
        case CF__SEG_ARC:
            cf__arc_cubics(v, arc_to, &pc);
            v += 5;
            break;
        case CF__SEG_CLOSE:
            if (pc.have_cp)
                put(w, "h\n");
            break;
        }
    }
}

/* ---- the graphics state ------------------------------------------------- */

/* The number of opacity a (< 1) among the document's; -1 out of memory. */
static int
alpha_index(cf__pdfw_t *w, double a)
{
    char t[48], u[48];
    size_t i;
    double *g;
    cf__decimals(t, a, 4);
    for (i = 0; i < w->nalphas; i++) {
        cf__decimals(u, w->alphas[i], 4);
        if (strcmp(t, u) == 0)
            return (int)i;
    }
    g = cf__grow_array(w->alphas, &w->alphas_cap, w->nalphas + 1, sizeof *g,
                       8);
    if (g == NULL || w->nalphas >= 100000) {
        w->sc.bad = true;
        return -1;
    }
    w->alphas = g;
    g[w->nalphas] = a;
    return (int)w->nalphas++;
}

/* Opacity a for filling (stroke false: /ca) or stroking (/CA); what is
** set is remembered as its number, -1 when opaque. */
static void
set_alpha(cf__pdfw_t *w, double a, bool stroke)
{
    int *cur = stroke ? &w->gs.CA : &w->gs.ca;
    int want = -1, k;
    char b[32];
    if (a < 0.99995 && (want = alpha_index(w, a > 0 ? a : 0)) < 0)
        return;
    if (want == *cur)
        return;
    k = want >= 0 ? want : alpha_index(w, 1);
    if (k < 0)
        return;
    snprintf(b, sizeof b, "/%c%d gs\n", stroke ? 'A' : 'a', k);
    put(w, b);
    *cur = want;
    w->translucent = w->translucent || want >= 0;
}

static void
set_color(cf__pdfw_t *w, const cf_color_t *c, bool stroke)
{
    double *cur = stroke ? w->gs.stroke : w->gs.fill;
    const double v[3] = { c->r, c->g, c->b };
    if (memcmp(cur, v, sizeof v) == 0)
        return;
    memcpy(cur, v, sizeof v);
    unit(w, v[0]);
    unit(w, v[1]);
    unit(w, v[2]);
    put(w, stroke ? "RG\n" : "rg\n");
}

static void
set_stroke(cf__pdfw_t *w, const cf__stroke_t *s)
{
    int cap = s->cap == CF__CAP_ROUND ? 1 : 0;
    int join = s->join == CF__JOIN_ROUND ? 1 : 0;
    char b[32];
    if (s->width != w->gs.width) {
        num(w, s->width);
        put(w, "w\n");
        w->gs.width = s->width;
    }
    if (cap != w->gs.cap) {
        snprintf(b, sizeof b, "%d J\n", cap);
        put(w, b);
        w->gs.cap = cap;
    }
    if (join != w->gs.join) {
        snprintf(b, sizeof b, "%d j\n", join);
        put(w, b);
        w->gs.join = join;
    }
    if (s->dash_count > 0) {
        put(w, "[");
        for (size_t i = 0; i < s->dash_count; i++)
            num(w, s->dash[i]);
        put(w, "] 0 d\n");
        w->gs.dashed = true;
    } else if (w->gs.dashed) {
        put(w, "[] 0 d\n");
        w->gs.dashed = false;
    }
    set_color(w, &s->color, true);
    set_alpha(w, s->color.a * s->opacity, true);
}

static void
init_gs(cf__pdfw_gs_t *gs)
{
    /* PDF's initial state: black, opaque, width 1, butt caps, miter
    ** joins, solid */
    memset(gs, 0, sizeof *gs);
    gs->ca = gs->CA = -1;
    gs->width = 1;
}

/* ---- scopes ------------------------------------------------------------- */

/* A scope (opened: q), the visible box and the state kept for its Q. */
static void
push(cf__pdfw_t *w, bool group, bool opened, const char *name,
     size_t index)
{
    int d = w->sc.depth;
    if (!cf__scopes_push(&w->sc, group, opened, name, index))
        return;
    memcpy(w->saved[d].clip, w->clip, sizeof w->clip);
    w->saved[d].gs = w->gs;
    if (opened)
        put(w, "q\n");
}

static void
pop(void *ctx)
{
    cf__pdfw_t *w = ctx;
    int d = --w->sc.depth;
    memcpy(w->clip, w->saved[d].clip, sizeof w->clip);
    if (w->sc.stack[d].opened) {
        put(w, "Q\n");
        w->gs = w->saved[d].gs;
    }
}

static void
begin_page(void *ctx, const cf__page_t *pg)
{
    cf__pdfw_t *w = ctx;
    memset(&w->content, 0, sizeof w->content);
    w->translucent = false;
    w->width = pg->width;
    w->height = pg->height;
    w->lang = pg->lang;
    w->sc.depth = 0;
    w->clip[0] = 0;
    w->clip[1] = 0;
    w->clip[2] = pg->width;
    w->clip[3] = pg->height;
    init_gs(&w->gs);
    put(w, "/Figure << /MCID 0 >> BDC\n1 0 0 -1 0 ");
    num(w, pg->height);
    put(w, "cm\n");
    push(w, true, false, NULL, 0);
    if (pg->background.a > 0) {
        set_color(w, &pg->background, false);
        set_alpha(w, pg->background.a, false);
        put(w, "0 0 ");
        num(w, pg->width);
        num(w, pg->height);
        put(w, "re\nf\n");
    }
}

static void
begin_group(void *ctx, const char *name, size_t index, const char *overlay)
{
    (void)overlay;
    push(ctx, true, true, name, index);
}

/* Close the scopes opened since the innermost group, then it. */
static void
end_group(void *ctx)
{
    cf__scopes_end_group(&((cf__pdfw_t *)ctx)->sc, 1, pop, ctx);
}

static void
clip(void *ctx, bool has_rect, const double r[4])
{
    cf__pdfw_t *w = ctx;
    push(w, false, has_rect, NULL, 0);
    if (!has_rect)
        return;
    num(w, r[0]);
    num(w, r[1]);
    num(w, r[2]);
    num(w, r[3]);
    put(w, "re\nW n\n");
    w->clip[0] = fmax(w->clip[0], fmin(r[0], r[0] + r[2]));
    w->clip[1] = fmax(w->clip[1], fmin(r[1], r[1] + r[3]));
    w->clip[2] = fmin(w->clip[2], fmax(r[0], r[0] + r[2]));
    w->clip[3] = fmin(w->clip[3], fmax(r[1], r[1] + r[3]));
}

static void
unclip(void *ctx)
{
    cf__pdfw_t *w = ctx;
    if (w->sc.depth > 1 && !w->sc.stack[w->sc.depth - 1].group)
        pop(w);
}

/* far outside any page (bp), within every viewer's numbers */
#define KNOCKOUT_FAR 1e5

/* Each box clips its inside away: a rectangle far around the page and
** the box the other way round, so that the box winds 0 (nonzero rule);
** successive clips intersect. */
static void
knockout(void *ctx, const double (*b)[4], size_t n)
{
    cf__pdfw_t *w = ctx;
    push(w, false, true, NULL, 0);
    for (size_t i = 0; i < n; i++) {
        double x0 = b[i][0], y0 = b[i][1], x1 = x0 + b[i][2],
               y1 = y0 + b[i][3];
        put(w, "-100000 -100000 200000 200000 re\n");
        point(w, x0, y0, "m\n");
        point(w, x0, y1, "l\n");
        point(w, x1, y1, "l\n");
        point(w, x1, y0, "l\nh\nW n\n");
    }
}

/* ---- painting ----------------------------------------------------------- */

/* The current path painted as paint says. */
static void
paint_path(cf__pdfw_t *w, const cf__paint_t *paint, const cf__path_t *p)
{
    double fa = paint->fill_color.a * paint->fill_opacity;
    double sa = paint->line.color.a * paint->line.opacity;
    if (paint->fill) {
        set_color(w, &paint->fill_color, false);
        set_alpha(w, fa, false);
    }
    if (!paint->stroke) {
        put(w, "f\n");
        return;
    }
    if (paint->fill && (fa < 0.99995 || sa < 0.99995)) {
        put(w, "f\n");
        put_path(w, p);
        set_stroke(w, &paint->line);
        put(w, "S\n");
        return;
    }
    set_stroke(w, &paint->line);
    put(w, paint->fill ? "B\n" : "S\n");
}

static void
sink_move(void *w, double x, double y)
{
    point(w, x, y, "m\n");
}

static void
sink_line(void *w, double x, double y)
{
    point(w, x, y, "l\n");
}

static void
sink_curve(void *w, double x1, double y1, double x2, double y2, double x3,
           double y3)
{
    const double c[6] = { x1, y1, x2, y2, x3, y3 };
    path_ctx_t pc = { w, true };
    arc_to(&pc, c, 3);
}

/* cf__far_sink_t's arc: cairo_arc, a line from the current point (the
** sink always has one but at a subpath's start, where the cutter
** moves first) */
static void
sink_arc(void *w, double cx, double cy, double r, double a0, double a1)
{
    const double v[5] = { cx, cy, r, a0, a1 };
    path_ctx_t pc = { w, true };
    cf__arc_cubics(v, arc_to, &pc);
}

static void
sink_close(void *w)
{
    put(w, "h\n");
}

static const cf__far_ctm_t identity = { 1, 0, 0, 1, 0, 0 };

/* A path beyond the safe region: its fill and its stroke cut apart to the
** visible box, as the cairo backend does. */
static void
draw_far(cf__pdfw_t *w, const cf__path_t *path, const cf__paint_t *paint)
{
    cf__far_sink_t sink = { sink_move, sink_line, sink_curve, sink_arc,
                            sink_close, w };
    cf__far_frame_t fr;
    cf__paint_t one = *paint;
    if (!cf__far_frame(&identity, w->clip, &fr)) {
        put_path(w, path);
        paint_path(w, paint, path);
        return;
    }
    if (paint->fill) {
        cf__far_fill(path, &fr, &sink);
        one.stroke = false;
        paint_path(w, &one, path);
    }
    if (!paint->stroke)
        return;
    if (!cf__far_stroke(path, &fr, &paint->line, &sink))
        put_path(w, path);
    one = *paint;
    one.fill = false;
    paint_path(w, &one, path);
}

static void
draw_path(void *ctx, const cf__path_t *path, const cf__paint_t *paint)
{
    cf__pdfw_t *w = ctx;
    if (!paint->fill && !paint->stroke)
        return;
    if (!cf__far_safe(path, &identity)) {
        draw_far(w, path, paint);
        return;
    }
    put_path(w, path);
    paint_path(w, paint, path);
}

/* ---- meshes ------------------------------------------------------------- */

static void
be32(unsigned char *p, unsigned long v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

static unsigned long
quantize(double v, double lo, double hi, double max)
{
    double k = (v - lo) / (hi - lo) * max;
    return (unsigned long)(k > 0 ? k < max ? k + 0.5 : max : 0);
}

/* The vertices of a free-form shading (flag 8 bits, x y 32 bits each over
** box, the triangles' box grown to whole bp and 1 more, r g b 16 bits)
** into data; false when a number is bad (not finite or beyond 1e9: a
** fault). */
static bool
shading(cf__pdfw_t *w, const cf__mesh_tri_t *t, size_t n, cf__buf_t *data,
        double box[4])
{
    box[0] = box[1] = HUGE_VAL;
    box[2] = box[3] = -HUGE_VAL;
    for (size_t i = 0; i < n; i++)
        for (unsigned k = 0; k < 6; k += 2) {
            if (!(fabs(t[i].p[k]) <= 1e9 && fabs(t[i].p[k + 1]) <= 1e9)) {
                fault(w, CF__SVGW_FAULT_NUMBER,
                      fabs(t[i].p[k]) <= 1e9 ? t[i].p[k + 1] : t[i].p[k]);
                return false;
            }
            box[0] = fmin(box[0], t[i].p[k]);
            box[2] = fmax(box[2], t[i].p[k]);
            box[1] = fmin(box[1], t[i].p[k + 1]);
            box[3] = fmax(box[3], t[i].p[k + 1]);
        }
    box[0] = floor(box[0]) - 1;
    box[1] = floor(box[1]) - 1;
    box[2] = ceil(box[2]) + 1;
    box[3] = ceil(box[3]) + 1;
    for (size_t i = 0; i < n; i++)
        for (unsigned k = 0; k < 3; k++) {
            const cf_color_t *c = &t[i].corner[k];
            const double ch[3] = { c->r, c->g, c->b };
            unsigned char v[15];
            v[0] = 0;
            be32(v + 1, quantize(t[i].p[2 * k], box[0], box[2],
                                 4294967295.0));
            be32(v + 5, quantize(t[i].p[2 * k + 1], box[1], box[3],
                                 4294967295.0));
            for (unsigned j = 0; j < 3; j++) {
                unsigned long q = quantize(ch[j], 0, 1, 65535.0);
                v[9 + 2 * j] = (unsigned char)(q >> 8);
                v[10 + 2 * j] = (unsigned char)q;
            }
            cf__buf_append(data, v, sizeof v);
        }
    return true;
}

static void
draw_mesh(void *ctx, const cf__mesh_tri_t *t, size_t n)
{
    cf__pdfw_t *w = ctx;
    struct cf__pdfw_shading *s;
    char b[64];
    if (n == 0)
        return;
    s = cf__grow_array(w->shadings, &w->shadings_cap, w->nshadings + 1,
                       sizeof *s, 4);
    if (s == NULL) {
        w->sc.bad = true;
        return;
    }
    w->shadings = s;
    s += w->nshadings;
    memset(s, 0, sizeof *s);
    if (!shading(w, t, n, &s->data, s->box) || s->data.failed) {
        w->sc.bad = true;
        cf__buf_free(&s->data);
        return;
    }
    snprintf(b, sizeof b, "/Sh%zu sh\n", w->nshadings++);
    put(w, b);
}

/* ---- labels ------------------------------------------------------------- */

/* SVG path data of M L C Z (cf__svg_path_data's) as PDF path operators:
** the numbers as they are. */
static void
put_svg_path(cf__pdfw_t *w, const cf__buf_t *d)
{
    const char *p = (const char *)d->data, *end = p + d->size;
    const char *op = NULL;
    while (p < end) {
        const char *q = p;
        switch (*p) {
        case 'M': op = "m\n"; p++; continue;
        case 'L': op = "l\n"; p++; continue;
        case 'C': op = "c\n"; p++; continue;
        case 'Z': put(w, "h\n"); p++; continue;
        case ' ': p++; continue;
        default:
            break;
        }
        /* the numbers up to the next operator */
        while (q < end && *q != 'M' && *q != 'L' && *q != 'C' && *q != 'Z')
            q++;
        cf__buf_append(&w->content, p, (size_t)(q - p));
        put(w, " ");
        if (op != NULL)
            put(w, op);
        p = q;
    }
}

/* The label's outlines as one path: stroked as its halo (2 halo wide,
** round joins, which a closed outline has only), filled unless
** halo_only. */
static void
draw_outline(cf__pdfw_t *w, const cf__text_op_t *t, bool halo_only)
{
    cf__buf_t d;
    memset(&d, 0, sizeof d);
    if (w->outline(w->outline_ctx, t, &d) != 0 || d.failed) {
        fault(w, CF__SVGW_FAULT_GLYPHS, 0);
        cf__buf_free(&d);
        return;
    }
    if (d.size > 0 && t->halo > 0 && t->halo_color.a > 0) {
        cf__stroke_t s;
        memset(&s, 0, sizeof s);
        s.color = t->halo_color;
        s.opacity = 1;
        s.width = 2 * t->halo;
        s.cap = CF__CAP_ROUND;
        s.join = CF__JOIN_ROUND;
        put_svg_path(w, &d);
        set_stroke(w, &s);
        put(w, "S\n");
    }
    if (d.size > 0 && !halo_only) {
        put_svg_path(w, &d);
        set_color(w, &t->color, false);
        set_alpha(w, t->color.a * t->opacity, false);
        put(w, "f\n");
    }
    cf__buf_free(&d);
}

/* The label as text: each glyph shown at its origin with its font's
** matrix (glyph space y up, so its y column negated), Tf size 1; the
** fraction rules filled.  1 when a font is refused (nothing written). */
static int
draw_glyphs(cf__pdfw_t *w, const cf__text_op_t *t, const cf__buf_t *glyphs,
            const cf__buf_t *rules)
{
    const cf__pdfw_glyph_t *g = (const cf__pdfw_glyph_t *)(void *)
                                glyphs->data;
    const double *r = (const double *)(void *)rules->data;
    size_t i, n = glyphs->size / sizeof *g, nr = rules->size / (4 * sizeof *r);
    int cur = -1;
    char b[48];
    for (i = 0; i < n; i++) {
        int k = cf__pdfw_font_use(w, &g[i]);
        if (k == -2)
            return 1;
        if (k < 0) {
            w->sc.bad = true;
            return 0;
        }
    }
    if (t->halo > 0 && t->halo_color.a > 0)
        draw_outline(w, t, true);
    set_color(w, &t->color, false);
    set_alpha(w, t->color.a * t->opacity, false);
    if (n > 0)
        put(w, "BT\n");
    for (i = 0; i < n; i++) {
        int k = cf__pdfw_font_use(w, &g[i]);
        if (k != cur) {
            snprintf(b, sizeof b, "/F%d 1 Tf\n", k);
            put(w, b);
            cur = k;
        }
        num(w, g[i].m[0]);
        num(w, g[i].m[1]);
        num(w, -g[i].m[2]);
        num(w, -g[i].m[3]);
        num(w, g[i].x);
        num(w, g[i].y);
        snprintf(b, sizeof b, "Tm <%04X> Tj\n", g[i].gid & 0xffffu);
        put(w, b);
    }
    if (n > 0)
        put(w, "ET\n");
    for (i = 0; i < nr; i++) {
        num(w, r[4 * i]);
        num(w, r[4 * i + 1]);
        num(w, r[4 * i + 2]);
        num(w, r[4 * i + 3]);
        put(w, "re\n");
    }
    if (nr > 0)
        put(w, "f\n");
    return 0;
}

static void
draw_text(void *ctx, const cf__text_op_t *t)
{
    cf__pdfw_t *w = ctx;
    cf__buf_t glyphs, rules;
    int r = 1;
    if (w->glyphs != NULL) {
        memset(&glyphs, 0, sizeof glyphs);
        memset(&rules, 0, sizeof rules);
        r = w->glyphs(w->outline_ctx, t, &glyphs, &rules);
        if (r == 0 && (glyphs.failed || rules.failed))
            w->sc.bad = true;
        else if (r == 0)
            r = draw_glyphs(w, t, &glyphs, &rules);
        else if (r != 1)
            fault(w, CF__SVGW_FAULT_GLYPHS, 0);
        cf__buf_free(&glyphs);
        cf__buf_free(&rules);
    }
    if (r == 1)
        draw_outline(w, t, false);
}

/* ---- the page's end ----------------------------------------------------- */

static int
end_page(void *ctx)
{
    cf__pdfw_t *w = ctx;
    struct cf__pdfw_page *pg;
    while (w->sc.depth > 0)
        pop(w);
    put(w, "EMC\n");
    pg = cf__grow_array(w->pages, &w->pages_cap, w->npages + 1, sizeof *pg,
                        4);
    if (pg == NULL || w->content.failed)
        w->sc.bad = true;
    if (pg != NULL)
        w->pages = pg;
    if (!w->sc.bad) {
        w->pages[w->npages].content = w->content;
        w->pages[w->npages++].translucent = w->translucent;
        memset(&w->content, 0, sizeof w->content);
    }
    cf__buf_free(&w->content);
    return w->sc.bad ? -1 : 0;
}

const cf__backend_t cf__pdfw_backend = {
    "pdf", begin_page, begin_group, end_group, clip, unclip, draw_path,
    NULL, draw_text, end_page, knockout, draw_mesh
};

cf_status_t
cf__pdfw_fault(const cf__pdfw_t *w, cf_diag_t *diag)
{
    return cf__scopes_diag(&w->sc, "PDF", "pdf", diag);
}
