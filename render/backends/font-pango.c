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

#include "curvefig/core.h"
#include "font-pango.h"

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

static void
outline(void *ctx, void *run, double x, double y, cf__pathb_t *out)
{
    static const cf__seg_t seg[] = {
        CF__SEG_MOVE, CF__SEG_LINE, CF__SEG_CURVE, CF__SEG_CLOSE
    };
    pango_fonts_t *f = ctx;
    cairo_path_t *path;
    int i;
    if (f->cr == NULL) {
        cairo_surface_t *s = cairo_recording_surface_create(
            CAIRO_CONTENT_ALPHA, NULL);
        f->cr = cairo_create(s);
        cairo_surface_destroy(s);
    }
    cairo_new_path(f->cr);
    cairo_move_to(f->cr, x, y);
    pango_cairo_layout_path(f->cr, run);
    path = cairo_copy_path(f->cr);
    if (path->status != CAIRO_STATUS_SUCCESS)
        out->failed = true;
    for (i = 0; path->status == CAIRO_STATUS_SUCCESS && i < path->num_data;
         i += path->data[i].header.length) {
        const cairo_path_data_t *d = &path->data[i];
        double xy[6];
        int k;
        for (k = 1; k < d->header.length && k <= 3; k++) {
            xy[2 * k - 2] = d[k].point.x;
            xy[2 * k - 1] = d[k].point.y;
        }
        cf__pathb_add(out, seg[d->header.type], xy);
    }
    cairo_path_destroy(path);
}

const cf__fonts_t cf__pango_fonts = {
    open_fonts, close_fonts, shape, release, outline, NULL
};
