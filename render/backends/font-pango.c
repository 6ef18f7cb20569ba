/*
** The fonts of labels natively (render/labels/font.h): pango on cairo's
** font backend, here among the backends because it includes cairo's and
** pango's headers (the labels see only the table of functions, which
** render/output/create.c hands to the figures and labels it makes).  A
** run is a PangoLayout, described once shaped as its glyphs (font.h:
** cf__font_glyphs_t), which is all the backends see of it; its outlines
** are the glyphs' paths through cairo (a path, never drawn).  Metrics and
** outlines are unhinted, so glyph positions are the same in every output
** format and at every resolution.  The native fonts (font-native.c) hand
** the runs they do not shape themselves to these.
*/
#include <pango/pangocairo.h>
#include <string.h>

#include "curvefig/core.h"
#include "font-glyphs.h"
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

/* A run: pango's layout and its glyphs described. */
typedef struct pango_run {
    PangoLayout *layout;
    cf__font_glyphs_buf_t glyphs;
    cf__font_face_t *faces;   /* one a span */
    char **keys;
    size_t nfaces, cap_faces;
} pango_run_t;

static void
clear_faces(pango_run_t *r)
{
    size_t i;
    for (i = 0; i < r->nfaces; i++)
        g_free(r->keys[i]);
    r->nfaces = 0;
}

/* The face of font: its scaled font and its description without size. */
static bool
add_face(pango_run_t *r, PangoFont *font)
{
    PangoFontDescription *d;
    if (r->nfaces == r->cap_faces) {
        size_t cap = r->cap_faces ? 2 * r->cap_faces : 4;
        cf__font_face_t *f = cf_alloc_array(cap, sizeof *f);
        char **k = cf_alloc_array(cap, sizeof *k);
        if (f == NULL || k == NULL) {
            cf_free(f);
            cf_free(k);
            return false;
        }
        if (r->nfaces > 0) {
            memcpy(f, r->faces, r->nfaces * sizeof *f);
            memcpy(k, r->keys, r->nfaces * sizeof *k);
        }
        cf_free(r->faces);
        cf_free(r->keys);
        r->faces = f;
        r->keys = k;
        r->cap_faces = cap;
    }
    d = pango_font_describe(font);
    pango_font_description_unset_fields(d, PANGO_FONT_MASK_SIZE);
    r->keys[r->nfaces] = pango_font_description_to_string(d);
    pango_font_description_free(d);
    r->faces[r->nfaces].scaled =
        pango_cairo_font_get_scaled_font(PANGO_CAIRO_FONT(font));
    r->faces[r->nfaces].key = r->keys[r->nfaces];
    r->faces[r->nfaces].outlines = NULL;   /* pango's fonts come and go */
    r->faces[r->nfaces].show_options = NULL;
    r->faces[r->nfaces].file = NULL;      /* a PDF draws its outlines */
    r->faces[r->nfaces].index = 0;
    r->faces[r->nfaces].psname = NULL;
    r->faces[r->nfaces].emboldened = false;
    r->faces[r->nfaces].has_matrix = false;
    r->faces[r->nfaces].own = NULL;        /* drawn and outlined by cairo */
    r->faces[r->nfaces].make_scaled = NULL;
    r->nfaces++;
    return true;
}

/* The layout's glyphs as font.h describes them: a span a pango run, at
** the sum of the widths of the runs before it, as pango's renderer
** places them. */
static bool
describe(pango_run_t *r, const cf__font_req_t *req,
         const cf__font_shape_t *sh)
{
    PangoLayoutIter *it;
    size_t k = 0;
    int x = 0, baseline;
    clear_faces(r);
    cf__font_glyphs_reset(&r->glyphs, req, sh);
    it = pango_layout_get_iter(r->layout);
    baseline = pango_layout_iter_get_baseline(it);
    r->glyphs.g.baseline = baseline;
    do {
        PangoLayoutRun *run = pango_layout_iter_get_run_readonly(it);
        if (run != NULL && add_face(r, run->item->analysis.font)) {
            int i;
            cf__font_glyphs_span(&r->glyphs, NULL,
                                 (size_t)run->item->offset,
                                 (size_t)run->item->length, x);
            if (!r->glyphs.failed) {
                cf__font_span_t *s = &r->glyphs.spans[r->glyphs.g.nspans - 1];
                s->backward = (run->item->analysis.level & 1) != 0;
                s->shift = run->y_offset;
            }
            for (i = 0; i < run->glyphs->num_glyphs; i++) {
                const PangoGlyphInfo *gi = &run->glyphs->glyphs[i];
                cf__font_glyph_t g;
                g.id = gi->glyph;
                g.x = gi->geometry.x_offset;
                g.y = gi->geometry.y_offset;
                g.width = gi->geometry.width;
                g.cluster = (unsigned)run->glyphs->log_clusters[i];
                cf__font_glyphs_add(&r->glyphs, &g);
                x += gi->geometry.width;
            }
        } else if (run != NULL) {
            r->glyphs.failed = true;
        }
    } while (pango_layout_iter_next_run(it));
    pango_layout_iter_free(it);
    /* the faces, now that their array no longer moves */
    for (k = 0; k < r->glyphs.g.nspans && !r->glyphs.failed; k++)
        r->glyphs.spans[k].face = &r->faces[k];
    return !r->glyphs.failed;
}

static int
shape(void *ctx, const cf__font_req_t *req, void **handle,
      cf__font_shape_t *out)
{
    pango_fonts_t *f = ctx;
    pango_run_t *r = *handle;
    PangoFontDescription *fd;
    PangoRectangle ink, logical;
    if (r == NULL) {
        r = cf_calloc(1, sizeof *r);
        if (r == NULL)
            return -1;
        r->layout = pango_layout_new(f->pc);
        if (r->layout == NULL) {
            cf_free(r);
            return -1;
        }
        *handle = r;
    }
    fd = pango_font_description_new();
    pango_font_description_set_family(fd, req->family);
    pango_font_description_set_style(fd, req->italic ? PANGO_STYLE_ITALIC
                                                     : PANGO_STYLE_NORMAL);
    pango_font_description_set_weight(fd, req->bold ? PANGO_WEIGHT_BOLD
                                                    : PANGO_WEIGHT_NORMAL);
    pango_font_description_set_absolute_size(fd, req->size * PANGO_SCALE);
    pango_layout_set_font_description(r->layout, fd);
    pango_font_description_free(fd);
    pango_layout_set_text(r->layout, req->text, (int)req->len);
    pango_layout_get_extents(r->layout, &ink, &logical);
    out->baseline = pango_layout_get_baseline(r->layout);
    out->logical[0] = logical.x;
    out->logical[1] = logical.y;
    out->logical[2] = logical.width;
    out->logical[3] = logical.height;
    out->ink[0] = ink.x;
    out->ink[1] = ink.y;
    out->ink[2] = ink.width;
    out->ink[3] = ink.height;
    out->unknown = pango_layout_get_unknown_glyphs_count(r->layout);
    return describe(r, req, out) ? 0 : -1;
}

static void
release(void *run)
{
    pango_run_t *r = run;
    if (r == NULL)
        return;
    clear_faces(r);
    cf_free(r->faces);
    cf_free(r->keys);
    cf__font_glyphs_fini(&r->glyphs);
    g_object_unref(r->layout);
    cf_free(r);
}

static const cf__font_glyphs_t *
glyphs(void *run)
{
    return &((pango_run_t *)run)->glyphs.g;
}

/* A run with unknown glyphs: pango draws them as boxes. */
static void
draw(void *run, void *cr, bool path)
{
    if (path)
        pango_cairo_layout_path(cr, ((pango_run_t *)run)->layout);
    else
        pango_cairo_show_layout(cr, ((pango_run_t *)run)->layout);
}

static void
outline(void *ctx, void *run, double x, double y, cf__pathb_t *out)
{
    cf__font_glyphs_outline(&((pango_fonts_t *)ctx)->cr, glyphs(run), x, y,
                            out);
}

const cf__fonts_t cf__pango_fonts = {
    open_fonts, close_fonts, shape, release, outline, glyphs, draw, NULL
};
