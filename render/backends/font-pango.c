/*
** The fonts of labels natively (render/labels/font.h): pango on cairo's
** font backend, here among the backends because it includes cairo's and
** pango's headers (the labels see only the table of functions, which
** render/output/create.c hands to the figures and labels it makes).  A
** run is a PangoLayout; its outlines are pango's glyph paths through
** cairo (a path, never drawn).  Metrics and outlines are unhinted, so
** glyph positions are the same in every output format and at every
** resolution.
*/
#include <pango/pangocairo.h>
#include <stdio.h>
#include <stdlib.h>

#include "curvefig/core.h"
#include "font-pango.h"

/* the key of a run's size as it was asked for (a double) */
#define SIZE_KEY "curvefig-size"

typedef struct pango_fonts {
    PangoContext *pc;
    cairo_t *cr;              /* for outlines, made at need */
} pango_fonts_t;

static void *
open_fonts(void *self)
{
    PangoFontMap *fm = pango_cairo_font_map_get_default();
    pango_fonts_t *f;
    cairo_font_options_t *fo;
    (void)self;
    if (fm == NULL)
        return NULL;
    f = cf_calloc(1, sizeof *f);
    if (f == NULL)
        return NULL;
    f->pc = pango_font_map_create_context(fm);
    if (f->pc == NULL) {
        cf_free(f);
        return NULL;
    }
    fo = cairo_font_options_create();
    cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
    cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
    cairo_font_options_set_antialias(fo, CAIRO_ANTIALIAS_GRAY);
    pango_cairo_context_set_font_options(f->pc, fo);
    cairo_font_options_destroy(fo);
    pango_cairo_context_set_resolution(f->pc, 72.0);
    pango_context_set_round_glyph_positions(f->pc, FALSE);
    return f;
}

static void
close_fonts(void *ctx)
{
    pango_fonts_t *f = ctx;
    if (f == NULL)
        return;
    if (f->cr != NULL)
        cairo_destroy(f->cr);
    g_object_unref(f->pc);
    cf_free(f);
}

PangoContext *
cf__pango_fonts_context(void *ctx)
{
    return ((pango_fonts_t *)ctx)->pc;
}

static int
shape(void *ctx, const cf__font_req_t *req, void **run,
      cf__font_shape_t *out)
{
    pango_fonts_t *f = ctx;
    PangoLayout *l = *run;
    PangoFontDescription *fd;
    PangoRectangle ink, logical;
    if (l == NULL) {
        l = pango_layout_new(f->pc);
        if (l == NULL)
            return -1;
        *run = l;
    }
    fd = pango_font_description_new();
    pango_font_description_set_family(fd, req->family);
    pango_font_description_set_style(fd, req->italic ? PANGO_STYLE_ITALIC
                                                     : PANGO_STYLE_NORMAL);
    pango_font_description_set_weight(fd, req->bold ? PANGO_WEIGHT_BOLD
                                                    : PANGO_WEIGHT_NORMAL);
    pango_font_description_set_absolute_size(fd, req->size * PANGO_SCALE);
    {
        double *size = malloc(sizeof *size);
        if (size == NULL) {
            pango_font_description_free(fd);
            return -1;
        }
        *size = req->size;
        g_object_set_data_full(G_OBJECT(l), SIZE_KEY, size, free);
    }
    pango_layout_set_font_description(l, fd);
    pango_font_description_free(fd);
    pango_layout_set_text(l, req->text, (int)req->len);
    pango_layout_get_extents(l, &ink, &logical);
    out->baseline = pango_layout_get_baseline(l);
    out->logical[0] = logical.x;
    out->logical[1] = logical.y;
    out->logical[2] = logical.width;
    out->logical[3] = logical.height;
    out->ink[0] = ink.x;
    out->ink[1] = ink.y;
    out->ink[2] = ink.width;
    out->ink[3] = ink.height;
    out->unknown = pango_layout_get_unknown_glyphs_count(l);
    return 0;
}

static void
release(void *run)
{
    if (run != NULL)
        g_object_unref(run);
}

/* v as the glyph data writes and the page reads it */
static double
as_written(double v)
{
    char buf[32];
    snprintf(buf, sizeof buf, "%.5g", v);
    return strtod(buf, NULL);
}

int
cf__pango_glyph_outline(cairo_t *cr, PangoFont *font, PangoGlyph id,
                        void (*f)(void *u, char op, const double *v), void *u)
{
    cairo_scaled_font_t *sf =
        pango_cairo_font_get_scaled_font(PANGO_CAIRO_FONT(font));
    cairo_matrix_t fm;
    cairo_glyph_t g;
    cairo_path_t *path;
    double s;
    int i, rc = 0;
    if (sf == NULL)
        return -1;
    /* the font's own scaled font: a scaled font of the same face made at
    ** another size moved the glyph paths of this one by 1/128 bp */
    cairo_scaled_font_get_font_matrix(sf, &fm);
    s = fm.yy != 0 ? fm.yy : 1;
    g.index = id;
    g.x = g.y = 0;
    cairo_set_scaled_font(cr, sf);
    cairo_new_path(cr);
    cairo_glyph_path(cr, &g, 1);
    path = cairo_copy_path(cr);
    cairo_new_path(cr);
    if (path->status != CAIRO_STATUS_SUCCESS)
        rc = -1;
    for (i = 0; rc == 0 && i < path->num_data;
         i += path->data[i].header.length) {
        static const char op[] = { 'M', 'L', 'C', 'Z' };
        const cairo_path_data_t *d = &path->data[i];
        double v[6];
        int k;
        for (k = 1; k < d->header.length && k <= 3; k++) {
            v[2 * k - 2] = as_written(d[k].point.x / s);
            v[2 * k - 1] = as_written(d[k].point.y / s);
        }
        f(u, op[d->header.type], v);
    }
    cairo_path_destroy(path);
    return rc;
}

typedef struct place {
    cf__pathb_t *out;
    double ox, oy, size;  /* the glyph's origin, the run's size */
} place_t;

/* A point of a glyph's outline placed as render/labels/font-table.c
** places it (the same operations, so the same doubles). */
static void
placed(void *u, char op, const double *v)
{
    const place_t *p = u;
    int n = op == 'C' ? 3 : op == 'Z' ? 0 : 1, j;
    double xy[6];
    for (j = 0; j < n; j++) {
        xy[2 * j] = p->ox + v[2 * j] * p->size;
        xy[2 * j + 1] = p->oy + v[2 * j + 1] * p->size;
    }
    cf__pathb_add(p->out, op == 'M' ? CF__SEG_MOVE : op == 'L' ? CF__SEG_LINE
                          : op == 'C' ? CF__SEG_CURVE : CF__SEG_CLOSE, xy);
}

/* The outlines of a run's glyphs, its top left at (x, y): each glyph's
** outline per bp (cf__pango_glyph_outline) at its place in the layout,
** in the same arithmetic as the page's glyph table. */
static void
outline(void *ctx, void *run, double x, double y, cf__pathb_t *out)
{
    pango_fonts_t *f = ctx;
    PangoLayoutIter *it;
    const double *size = g_object_get_data(G_OBJECT(run), SIZE_KEY);
    place_t p;
    if (f->cr == NULL) {
        cairo_surface_t *s = cairo_recording_surface_create(
            CAIRO_CONTENT_ALPHA, NULL);
        f->cr = cairo_create(s);
        cairo_surface_destroy(s);
    }
    if (size == NULL) {
        out->failed = true;
        return;
    }
    p.out = out;
    p.size = *size;
    it = pango_layout_get_iter(run);
    do {
        PangoLayoutRun *r = pango_layout_iter_get_run_readonly(it);
        PangoRectangle logical;
        int i, gx, base;
        if (r == NULL)
            continue;
        pango_layout_iter_get_run_extents(it, NULL, &logical);
        base = pango_layout_iter_get_baseline(it);
        gx = logical.x;
        for (i = 0; i < r->glyphs->num_glyphs; i++) {
            const PangoGlyphInfo *g = &r->glyphs->glyphs[i];
            if (!(g->glyph & PANGO_GLYPH_UNKNOWN_FLAG)
                && g->glyph != PANGO_GLYPH_EMPTY) {
                p.ox = x + (double)(gx + g->geometry.x_offset)
                           / CF__FONT_SCALE;
                p.oy = y + (double)(base + g->geometry.y_offset)
                           / CF__FONT_SCALE;
                if (cf__pango_glyph_outline(f->cr, r->item->analysis.font,
                                            g->glyph, placed, &p) != 0)
                    out->failed = true;
            }
            gx += g->geometry.width;
        }
    } while (pango_layout_iter_next_run(it));
    pango_layout_iter_free(it);
}

const cf__fonts_t cf__pango_fonts = {
    open_fonts, close_fonts, shape, release, outline, NULL
};
