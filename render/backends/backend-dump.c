/*
** The dump backend: a display list as text, one operation a line, numbers
** with 12 significant digits.  The same list gives the same text on every
** run and machine (no addresses, no clock), so tests compare dumps.
**
**   page W H background R G B A
**   group INDEX KIND [overlay SPEC] ... end
**   clip X Y W H | clip none ... unclip
**   knockout N X Y W H ... (N boxes) ... unclip
**   path fill R G B A OPACITY | stroke R G B A OPACITY WIDTH CAP JOIN
**        dash N D1 .. : M x y L x y C x1 y1 x2 y2 x3 y3 R x y w h
**        A cx cy r a0 a1 Z
**   marker KIND X Y size S width W color R G B A fill R G B A OPACITY
**        [dir DX DY]
**   text "SOURCE" anchor X Y place P offset O size S origin X Y
**        color R G B A OPACITY [halo H R G B A] runs N
*/
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "backend.h"
#include "grow.h"

static void
put(cf__dump_t *d, const char *fmt, ...)
{
    va_list ap;
    int n;
    if (d->failed)
        return;
    for (;;) {
        size_t room = d->cap - d->len;
        va_start(ap, fmt);
        n = vsnprintf(d->text != NULL ? d->text + d->len : NULL,
                      d->text != NULL ? room : 0, fmt, ap);
        va_end(ap);
        if (n < 0) {
            d->failed = true;
            return;
        }
        if (d->text != NULL && (size_t)n < room) {
            d->len += (size_t)n;
            return;
        }
        {
            char *t = cf__grow_array(d->text, &d->cap,
                                     d->len + (size_t)n + 1, 1, 4096);
            if (t == NULL) {
                d->failed = true;
                return;
            }
            d->text = t;
        }
    }
}

static void
put_color(cf__dump_t *d, const cf_color_t *c)
{
    put(d, " %.12g %.12g %.12g %.12g", c->r, c->g, c->b, c->a);
}

static void
begin_page(void *ctx, const cf__page_t *pg)
{
    put(ctx, "page %.12g %.12g background", pg->width, pg->height);
    put_color(ctx, &pg->background);
    put(ctx, "\n");
}

static void
begin_group(void *ctx, const char *name, size_t index, const char *overlay)
{
    if (overlay != NULL)
        put(ctx, "group %zu %s overlay %s\n", index, name, overlay);
    else
        put(ctx, "group %zu %s\n", index, name);
}

static void
end_group(void *ctx)
{
    put(ctx, "end\n");
}

static void
clip(void *ctx, bool has_rect, const double r[4])
{
    if (has_rect)
        put(ctx, "clip %.12g %.12g %.12g %.12g\n", r[0], r[1], r[2], r[3]);
    else
        put(ctx, "clip none\n");
}

static void
unclip(void *ctx)
{
    put(ctx, "unclip\n");
}

static void
draw_path(void *ctx, const cf__path_t *p, const cf__paint_t *paint)
{
    static const char letter[] = "MLCRAZ";
    static const int count[] = { 2, 2, 6, 4, 5, 0 };
    const double *v = p->coords;
    size_t i;
    int k;
    put(ctx, "path");
    if (paint->fill) {
        put(ctx, " fill");
        put_color(ctx, &paint->fill_color);
        put(ctx, " %.12g", paint->fill_opacity);
    }
    if (paint->stroke) {
        const cf__stroke_t *s = &paint->line;
        put(ctx, " stroke");
        put_color(ctx, &s->color);
        put(ctx, " %.12g %.12g %s %s dash %zu", s->opacity, s->width,
            s->cap == CF__CAP_ROUND ? "round" : "butt",
            s->join == CF__JOIN_ROUND ? "round" : "miter", s->dash_count);
        for (i = 0; i < s->dash_count; i++)
            put(ctx, " %.12g", s->dash[i]);
    }
    put(ctx, " :");
    for (i = 0; i < p->nsegs; i++) {
        int seg = p->segs[i];
        put(ctx, " %c", letter[seg]);
        for (k = 0; k < count[seg]; k++)
            put(ctx, " %.12g", *v++);
    }
    put(ctx, "\n");
}

static const char *
marker_name(cf_marker_t m)
{
    static const char *const names[] = {
        "none", "dot", "circle", "square", "diamond", "triangle", "cross",
        "plus", "star", "tick"
    };
    return (unsigned)m < sizeof names / sizeof names[0] ? names[m] : "?";
}

static void
draw_marker(void *ctx, const cf__marker_op_t *m)
{
    put(ctx, "marker %s %.12g %.12g size %.12g width %.12g color",
        marker_name(m->marker), m->x, m->y, m->size, m->width);
    put_color(ctx, &m->color);
    put(ctx, " fill");
    put_color(ctx, &m->fill);
    put(ctx, " %.12g", m->opacity);
    if (m->has_dir)
        put(ctx, " dir %.12g %.12g", m->dir[0], m->dir[1]);
    put(ctx, "\n");
}

static void
draw_text(void *ctx, const cf__text_op_t *t)
{
    const char *s;
    put(ctx, "text \"");
    for (s = t->source; *s != '\0'; s++) {
        if (*s == '"' || *s == '\\')
            put(ctx, "\\%c", *s);
        else if (*s == '\n')
            put(ctx, "\\n");
        else
            put(ctx, "%c", *s);
    }
    put(ctx, "\" anchor %.12g %.12g place %d offset %.12g size %.12g "
        "origin %.12g %.12g color", t->px, t->py, (int)t->place, t->offset,
        t->font_size, t->ox, t->oy);
    put_color(ctx, &t->color);
    put(ctx, " %.12g", t->opacity);
    if (t->halo > 0) {
        put(ctx, " halo %.12g", t->halo);
        put_color(ctx, &t->halo_color);
    }
    put(ctx, " runs %zu\n", cf_label_box_count(t->label));
}

static int
end_page(void *ctx)
{
    return ((cf__dump_t *)ctx)->failed ? -1 : 0;
}

static void
knockout(void *ctx, const double (*b)[4], size_t n)
{
    put(ctx, "knockout %zu", n);
    for (size_t i = 0; i < n; i++)
        put(ctx, " %.12g %.12g %.12g %.12g", b[i][0], b[i][1], b[i][2],
            b[i][3]);
    put(ctx, "\n");
}

const cf__backend_t cf__dump_backend = {
    "dump", begin_page, begin_group, end_group, clip, unclip, draw_path,
    draw_marker, draw_text, end_page, knockout, NULL
};
