/*
** The PGF backend: a display list as a pgfpicture for TeX (\input in a
** document that loads pgf or tikz).  Coordinates are big points with y
** up from the bottom left of the page; paths are PGF's move, line, curve
** and rectangle operations (arcs as the cubic pieces of at most a
** quarter turn); each drawing operation sits in its own pgfscope with
** its width, caps, joins, dash, colours and opacity, as the cairo
** backend sets them per operation; elements and clips are pgfscopes,
** an element with a beamer overlay specification also \visible<...>.
** Labels are TeX source (render/labels/label-tex.c) put with \pgftext at the
** anchor on the side of the label's place, so that TeX sets them in the
** document's font and size; a label pdflatex cannot set (Cyrillic, CJK)
** is drawn as the outlines of curvefig's own glyphs.  The box is the
** page: the bounding box is reset to it at the end.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <cairo.h>

#include "backend.h"
#include "buffer.h"
#include "decimals.h"
#include "label-cairo.h"

#define PI 3.14159265358979323846
#define PGF_MAX_BP CF__PGF_MAX_BP

static void
put(cf__pgf_t *g, const char *s)
{
    cf__buf_append(g->out, s, strlen(s));
}

/* A number of bp with at most 4 decimals, no trailing zeros. */
static void
put_num(cf__pgf_t *g, double v)
{
    char b[48];
    if (!(fabs(v) <= PGF_MAX_BP)) {
        if (!g->range_error)
            g->bad_value = v;
        g->range_error = true;
        v = 0;
    }
    cf__buf_append(g->out, b, cf__decimals(b, v, 4));
}

static void
put_dim(cf__pgf_t *g, double v)
{
    put_num(g, v);
    put(g, "bp");
}

/* {\pgfqpoint{x}{y}} of a page point (y down) */
static void
put_point(cf__pgf_t *g, double x, double y)
{
    put(g, "{\\pgfqpoint{");
    put_dim(g, x);
    put(g, "}{");
    put_dim(g, g->height - y);
    put(g, "}}");
}

/* \pgfpathrectangle of the page rectangle x y w h (y down). */
static void
put_rect(cf__pgf_t *g, double x, double y, double w, double h)
{
    put(g, "\\pgfpathrectangle");
    put_point(g, x, y);
    put(g, "{\\pgfqpoint{");
    put_dim(g, w);
    put(g, "}{");
    put_dim(g, -h);
    put(g, "}}");
}

static void
put_color(cf__pgf_t *g, const char *name, const cf_color_t *c)
{
    const double rgb[3] = { c->r, c->g, c->b };
    int k;
    put(g, "\\definecolor{");
    put(g, name);
    put(g, "}{rgb}{");
    for (k = 0; k < 3; k++) {
        put_num(g, rgb[k]);
        put(g, k < 2 ? "," : "}");
    }
}

/* \pgfsetstrokeopacity or fill opacity when below 1. */
static void
put_opacity(cf__pgf_t *g, const char *which, double a)
{
    if (!(a < 1))
        return;
    put(g, which);
    put(g, "{");
    put_num(g, fmax(0, a));
    put(g, "}");
}

static void set_fill(cf__pgf_t *g, const cf_color_t *c, double opacity);

/* Text as comment lines "% ..." of about 72 bytes, broken at spaces
** (docs/accessibility.md: the description in a PGF file). */
static void
put_comment_lines(cf__pgf_t *g, const char *text)
{
    const char *s = text;
    while (s != NULL && *s != '\0') {
        size_t n = strlen(s), cut = n;
        if (n > 72) {
            for (cut = 72; cut > 0 && s[cut] != ' '; cut--)
                ;
            if (cut == 0)
                for (cut = 72; cut < n && s[cut] != ' '; cut++)
                    ;
        }
        put(g, "% ");
        for (size_t i = 0; i < cut; i++)
            cf__buf_append(g->out, s[i] == '\n' || s[i] == '\r' ? " "
                                                               : s + i, 1);
        put(g, "\n");
        s += cut;
        while (*s == ' ')
            s++;
    }
}

static void
begin_page(void *ctx, const cf__page_t *pg)
{
    cf__pgf_t *g = ctx;
    const char *s;
    g->height = pg->height;
    g->width = pg->width;
    g->base = pg->label_size > 0 ? pg->label_size : CF__PGF_BASE_SIZE;
    g->depth = 0;
    g->overlays = 0;
    put(g, "% curvefig picture, ");
    put_num(g, pg->width);
    put(g, " x ");
    put_num(g, pg->height);
    put(g, " bp: a pgfpicture; \\usepackage{pgf} (or tikz)\n");
    if (g->title != NULL) {
        put(g, "% ");
        for (s = g->title; *s != '\0'; s++)
            cf__buf_append(g->out, *s == '\n' || *s == '\r' ? " " : s, 1);
        put(g, "\n");
    }
    put_comment_lines(g, g->desc);
    put(g, "\\begin{pgfpicture}\n"
           "\\providecommand\\text[1]{\\mbox{#1}}\n"
           "\\providecommand\\boldsymbol[1]{\\mbox{\\boldmath$#1$}}\n"
           "\\providecommand\\binom[2]{{#1\\choose#2}}\n");
    if (pg->background.a > 0) {
        put(g, "\\begin{pgfscope}");
        set_fill(g, &pg->background, 1);
        put_rect(g, 0, 0, pg->width, pg->height);
        put(g, "\\pgfusepath{fill}\\end{pgfscope}\n");
    }
}

static void
begin_group(void *ctx, const char *name, size_t index, const char *overlay)
{
    cf__pgf_t *g = ctx;
    char line[80];
    bool ov = overlay != NULL && overlay[0] != '\0';
    if (ov) {
        /* outside beamer every step is shown */
        put(g, "\\ifdefined\\visible\\else\\def\\visible<#1>#2{#2}\\fi"
               "\\visible<");
        put(g, overlay);
        put(g, ">{");
    }
    if (g->depth < 64)
        g->overlays = (g->overlays & ~(1ull << g->depth))
            | ((unsigned long long)ov << g->depth);
    g->depth++;
    snprintf(line, sizeof line, "\\begin{pgfscope}%% %zu %s\n", index, name);
    put(g, line);
}

static void
end_group(void *ctx)
{
    cf__pgf_t *g = ctx;
    put(g, "\\end{pgfscope}");
    if (g->depth > 0) {
        g->depth--;
        if (g->depth < 64 && (g->overlays >> g->depth & 1))
            put(g, "}");
    }
    put(g, "\n");
}

static void
clip(void *ctx, bool has_rect, const double r[4])
{
    cf__pgf_t *g = ctx;
    put(g, "\\begin{pgfscope}");
    if (has_rect) {
        put_rect(g, r[0], r[1], r[2], r[3]);
        put(g, "\\pgfusepath{clip}");
    }
    put(g, "\n");
}

static void
unclip(void *ctx)
{
    put(ctx, "\\end{pgfscope}\n");
}

static void
seg_point(cf__pgf_t *g, const char *op, double x, double y)
{
    put(g, op);
    put_point(g, x, y);
    put(g, "\n");
}

static void
curve(cf__pgf_t *g, double x1, double y1, double x2, double y2, double x3,
      double y3)
{
    put(g, "\\pgfpathcurveto");
    put_point(g, x1, y1);
    put_point(g, x2, y2);
    put_point(g, x3, y3);
    put(g, "\n");
}

typedef struct arc_ctx {
    cf__pgf_t *g;
    bool have_cp;
} arc_ctx_t;

static void
arc_to(void *ctx, const double *p, int n)
{
    arc_ctx_t *a = ctx;
    if (n == 1)
        seg_point(a->g, a->have_cp ? "\\pgfpathlineto" : "\\pgfpathmoveto",
                  p[0], p[1]);
    else
        curve(a->g, p[0], p[1], p[2], p[3], p[4], p[5]);
}

/* cairo_arc: a line from the current point to its start, then its cubic
** pieces of at most a quarter turn (render/dlist/dlist.h). */
static void
arc(cf__pgf_t *g, const double *v, bool have_cp)
{
    arc_ctx_t a = { g, have_cp };
    cf__arc_cubics(v, arc_to, &a);
}

static void
append_path(cf__pgf_t *g, const cf__path_t *p)
{
    const double *v = p->coords;
    double cx = 0, cy = 0, sx = 0, sy = 0;
    bool have_cp = false;
    size_t i;
    for (i = 0; i < p->nsegs; i++) {
        switch ((cf__seg_t)p->segs[i]) {
        case CF__SEG_MOVE:
        case CF__SEG_LINE:
            seg_point(g, p->segs[i] == CF__SEG_MOVE || !have_cp
                          ? "\\pgfpathmoveto" : "\\pgfpathlineto",
                      v[0], v[1]);
            if (p->segs[i] == CF__SEG_MOVE || !have_cp) {
                sx = v[0];
                sy = v[1];
            }
            cx = v[0];
            cy = v[1];
            have_cp = true;
            v += 2;
            break;
        case CF__SEG_CURVE:
            if (!have_cp)
                seg_point(g, "\\pgfpathmoveto", sx = v[0], sy = v[1]);
            curve(g, v[0], v[1], v[2], v[3], v[4], v[5]);
            cx = v[4];
            cy = v[5];
            have_cp = true;
            v += 6;
            break;
        case CF__SEG_RECT:
            put_rect(g, v[0], v[1], v[2], v[3]);
            put(g, "\n");
            cx = sx = v[0];
            cy = sy = v[1];
            have_cp = true;
            v += 4;
            break;
        case CF__SEG_ARC:
            arc(g, v, have_cp);
            if (!have_cp) {
                sx = v[0] + v[2] * cos(v[3]);
                sy = v[1] + v[2] * sin(v[3]);
            }
            have_cp = true;
            v += 5;
            break;
        case CF__SEG_CLOSE:
            if (have_cp) {
                put(g, "\\pgfpathclose\n");
                cx = sx;
                cy = sy;
            }
            break;
        }
    }
    (void)cx;
    (void)cy;
}

static void
set_stroke(cf__pgf_t *g, const cf__stroke_t *s)
{
    size_t i;
    put(g, "\\pgfsetlinewidth{");
    put_dim(g, s->width);
    put(g, s->cap == CF__CAP_ROUND ? "}\\pgfsetroundcap" : "}\\pgfsetbuttcap");
    put(g, s->join == CF__JOIN_ROUND ? "\\pgfsetroundjoin"
                                     : "\\pgfsetmiterjoin");
    if (s->dash_count > 0) {
        put(g, "\\pgfsetdash{");
        for (i = 0; i < s->dash_count; i++) {
            put(g, "{");
            put_dim(g, s->dash[i]);
            put(g, "}");
        }
        put(g, "}{0bp}");
    }
    put_color(g, "cfstroke", &s->color);
    put(g, "\\pgfsetstrokecolor{cfstroke}");
    put_opacity(g, "\\pgfsetstrokeopacity", s->color.a * s->opacity);
}

static void
set_fill(cf__pgf_t *g, const cf_color_t *c, double opacity)
{
    put_color(g, "cffill", c);
    put(g, "\\pgfsetfillcolor{cffill}");
    put_opacity(g, "\\pgfsetfillopacity", c->a * opacity);
}

static void
draw_path(void *ctx, const cf__path_t *path, const cf__paint_t *paint)
{
    cf__pgf_t *g = ctx;
    put(g, "\\begin{pgfscope}");
    if (paint->fill)
        set_fill(g, &paint->fill_color, paint->fill_opacity);
    if (paint->stroke)
        set_stroke(g, &paint->line);
    put(g, "\n");
    append_path(g, path);
    put(g, paint->fill && paint->stroke ? "\\pgfusepath{fill,stroke}"
           : paint->fill ? "\\pgfusepath{fill}" : "\\pgfusepath{stroke}");
    put(g, "\\end{pgfscope}\n");
}


/* ---- labels ------------------------------------------------------------- */

/* The \pgftext anchor of each place: the side of the text box that
** touches the anchor point; x and y signs of the gap (page y down). */
static const struct {
    const char *anchor;
    int sx, sy;
} places[CF_PLACE_LAST_] = {
    [CF_PLACE_CENTER] = { "", 0, 0 },
    [CF_PLACE_N] = { "bottom,", 0, -1 },
    [CF_PLACE_NE] = { "left,bottom,", 1, -1 },
    [CF_PLACE_E] = { "left,", 1, 0 },
    [CF_PLACE_SE] = { "left,top,", 1, 1 },
    [CF_PLACE_S] = { "top,", 0, 1 },
    [CF_PLACE_SW] = { "right,top,", -1, 1 },
    [CF_PLACE_W] = { "right,", -1, 0 },
    [CF_PLACE_NW] = { "right,bottom,", -1, -1 },
    [CF_PLACE_AUTO] = { "", 0, 0 },
};

static void
pgftext(cf__pgf_t *g, const cf__text_op_t *t, const char *tex, double dx,
        double dy)
{
    unsigned p = (unsigned)t->place < CF_PLACE_LAST_ ? (unsigned)t->place
                                                     : CF_PLACE_CENTER;
    double d = places[p].sx != 0 && places[p].sy != 0 ? t->offset * 0.7071
                                                      : t->offset;
    put(g, "\\pgftext[");
    put(g, places[p].anchor);
    put(g, "at=");
    put_point(g, t->px + places[p].sx * d + dx, t->py + places[p].sy * d + dy);
    put(g, "]{");
    /* the size relative to the document's: the theme's labels at its
    ** size */
    if (fabs(t->font_size / g->base - 1) > 0.005) {
        put(g, "\\scalebox{");
        put_num(g, t->font_size / g->base);
        put(g, "}{");
        put(g, tex);
        put(g, "}");
    } else {
        put(g, tex);
    }
    put(g, "}\n");
}

/* A label TeX can set: the halo as copies around it in the halo colour
** (16 on a ring of the halo's width, 8 on one of half of it, so that
** strokes between them are covered), then the text. */
static void
tex_text(cf__pgf_t *g, const cf__text_op_t *t, const char *tex)
{
    int k;
    if (t->halo > 0 && t->halo_color.a > 0) {
        put(g, "\\begin{pgfscope}");
        put_color(g, "cftext", &t->halo_color);
        put(g, "\\color{cftext}");
        put_opacity(g, "\\pgfsetfillopacity", t->halo_color.a);
        put(g, "\n");
        for (k = 0; k < 24; k++) {
            /* 16 on a ring at the halo's width, 8 at half of it */
            bool outer = k < 16;
            double r = outer ? t->halo : 0.5 * t->halo;
            double a = outer ? PI * k / 8 : PI * (k - 16) / 4;
            pgftext(g, t, tex, r * cos(a), r * sin(a));
        }
        put(g, "\\end{pgfscope}\n");
    }
    put(g, "\\begin{pgfscope}");
    put_color(g, "cftext", &t->color);
    put(g, "\\color{cftext}");
    put_opacity(g, "\\pgfsetfillopacity", t->color.a * t->opacity);
    put(g, "\n");
    pgftext(g, t, tex, 0, 0);
    put(g, "\\end{pgfscope}\n");
}

/* The outlines of curvefig's glyphs of a label, filled (a halo stroked
** first), for labels TeX cannot set. */
static void
outline_text(cf__pgf_t *g, const cf__text_op_t *t)
{
    cairo_path_t *path;
    int i, pass;
    if (g->glyphs == NULL) {
        /* unbounded: pango leaves out the glyphs outside a bounded
        ** surface's extents */
        cairo_surface_t *s = cairo_recording_surface_create(
            CAIRO_CONTENT_ALPHA, NULL);
        g->glyphs = cairo_create(s);
        cairo_surface_destroy(s);
    }
    cairo_new_path(g->glyphs);
    cf__label_path(t->label, g->glyphs, t->ox, t->oy);
    path = cairo_copy_path(g->glyphs);
    if (path->status != CAIRO_STATUS_SUCCESS) {
        g->out->failed = 1;
        cairo_path_destroy(path);
        return;
    }
    for (pass = t->halo > 0 && t->halo_color.a > 0 ? 0 : 1; pass < 2;
         pass++) {
        put(g, "\\begin{pgfscope}");
        if (pass == 0) {
            cf__stroke_t halo;
            memset(&halo, 0, sizeof halo);
            halo.color = t->halo_color;
            halo.opacity = 1;
            halo.width = 2 * t->halo;
            halo.join = CF__JOIN_ROUND;
            set_stroke(g, &halo);
        } else {
            set_fill(g, &t->color, t->opacity);
        }
        put(g, "\n");
        for (i = 0; i < path->num_data; i += path->data[i].header.length) {
            const cairo_path_data_t *d = &path->data[i];
            switch (d->header.type) {
            case CAIRO_PATH_MOVE_TO:
                seg_point(g, "\\pgfpathmoveto", d[1].point.x, d[1].point.y);
                break;
            case CAIRO_PATH_LINE_TO:
                seg_point(g, "\\pgfpathlineto", d[1].point.x, d[1].point.y);
                break;
            case CAIRO_PATH_CURVE_TO:
                curve(g, d[1].point.x, d[1].point.y, d[2].point.x,
                      d[2].point.y, d[3].point.x, d[3].point.y);
                break;
            case CAIRO_PATH_CLOSE_PATH:
                put(g, "\\pgfpathclose\n");
                break;
            }
        }
        put(g, pass == 0 ? "\\pgfusepath{stroke}" : "\\pgfusepath{fill}");
        put(g, "\\end{pgfscope}\n");
    }
    cairo_path_destroy(path);
}

static void
draw_text(void *ctx, const cf__text_op_t *t)
{
    cf__pgf_t *g = ctx;
    cf__buf_t tex;
    int r;
    memset(&tex, 0, sizeof tex);
    r = cf__label_tex(t->source, &tex);
    if (r == 0 && tex.size > 0 && cf__buf_append(&tex, "", 1) == 0)
        tex_text(g, t, (const char *)tex.data);
    else if (r == 1)
        outline_text(g, t);
    else if (r < 0)
        g->out->failed = 1;
    cf__buf_free(&tex);
}

static int
end_page(void *ctx)
{
    cf__pgf_t *g = ctx;
    put(g, "\\pgfresetboundingbox\n");
    put_rect(g, 0, 0, g->width, g->height);
    put(g, "\n\\pgfusepath{use as bounding box}\n\\end{pgfpicture}%\n");
    return g->out->failed || g->range_error ? -1 : 0;
}

/* Each box clips its inside away (the even-odd rule with a rectangle
** around the page); clips within one scope intersect. */
static void
knockout(void *ctx, const double (*b)[4], size_t n)
{
    cf__pgf_t *g = ctx;
    double m = g->width + g->height;
    put(g, "\\begin{pgfscope}\\pgfseteorule\n");
    for (size_t i = 0; i < n; i++) {
        put_rect(g, -m, -m, g->width + 2 * m, g->height + 2 * m);
        put_rect(g, b[i][0], b[i][1], b[i][2], b[i][3]);
        put(g, "\\pgfusepath{clip}\n");
    }
}

const cf__backend_t cf__pgf_backend = {
    "pgf", begin_page, begin_group, end_group, clip, unclip, draw_path,
    NULL, draw_text, end_page, knockout, NULL
};

void
cf__pgf_fini(cf__pgf_t *g)
{
    if (g->glyphs != NULL)
        cairo_destroy((cairo_t *)g->glyphs);
    g->glyphs = NULL;
}
