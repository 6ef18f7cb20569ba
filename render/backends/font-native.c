/*
** The native fonts of labels (render/labels/font.h): HarfBuzz shapes, in
** the faces pango would choose (render/backends/font-faces.c), the way
** pango 1.50 lays out a one-line text, so that every number is pango's:
**   - the text in items, one script and one font each, as pango's
**     script iterator and font choice cut it (font-itemize.c);
**   - each item shaped by hb_shape with the whole text as context, left
**     to right, script and language set, clusters monotone by character,
**     pango's unknown-glyph marks (here);
**   - the items' baseline shifts and the logical and ink extents as
**     pango combines them (font-extents.c).
** What this does not do is handed to pango (render/backends/
** font-pango.c, which loads it then): a run with a character of another
** script than Latin, Greek, Cyrillic, Han, Hiragana, Katakana, Hangul and
** Bopomofo (right-to-left and complex scripts among them), a control or
** format character, an emoji or a variation selector, a character no font
** of the set has (pango draws a box), a face with variations or
** configured features, an empty text; and every run when pango's default
** language (from the C library's LC_CTYPE) is not C or POSIX, where pango
** would tag items with languages this does not derive
** (cf__native_fonts_handles, font-itemize.c).  An item whose characters
** are all simple (render/fontfile/uprops.h: in the shaper's Unicode table,
** not marks, not U+2044), in a script the renderer's shaper knows and a
** face it reads, is shaped by that shaper (render/fontfile/shape.h), which
** gives exactly hb_shape's glyphs for the runs it accepts; the others,
** and the runs it hands back, by HarfBuzz, loaded then (so a figure whose
** items are all simple never loads HarfBuzz, GLib, graphite2 or PCRE2).
** This file is the glue: the fonts' table of render/labels/font.h, a run
** shaped natively or handed on, its glyphs drawn and outlined either
** way.
*/
#include <string.h>

#include <hb.h>

#include "curvefig/core.h"
#include "font-config.h"
#include "font-extents.h"
#include "font-itemize.h"
#include "font-native.h"
#include "font-pango.h"
#include "label-impl.h"
#include "uprops.h"

typedef struct native_fonts {
    void *pango;          /* pango's context, opened for the first run
                             handed to it */
    cairo_t *cr;          /* for outlines */
    hb_buffer_t *buf;     /* made for the first item HarfBuzz shapes */
} native_fonts_t;

/* ---- shaping -------------------------------------------------------------- */

static hb_bool_t
nominal_glyph(hb_font_t *font, void *data, hb_codepoint_t c,
              hb_codepoint_t *glyph, void *user)
{
    (void)data;
    (void)user;
    if (hb_font_get_nominal_glyph(hb_font_get_parent(font), c, glyph))
        return 1;
    if (hb_unicode_general_category(hb_unicode_funcs_get_default(), c)
        == HB_UNICODE_GENERAL_CATEGORY_SPACE_SEPARATOR) {
        if (c == 0x20) {
            *glyph = CF__FONT_GLYPH_UNKNOWN | 0x20;
            return 1;
        }
        return 0;
    }
    *glyph = CF__FONT_GLYPH_UNKNOWN | c;
    return 0;
}

/* pango's font functions over a face's: unknown characters marked. */
static hb_font_funcs_t *
pango_funcs(void)
{
    static hb_font_funcs_t *funcs;   /* immutable, made under the lock */
    if (funcs == NULL) {
        funcs = hb_font_funcs_create();
        hb_font_funcs_set_nominal_glyph_func(funcs, nominal_glyph, NULL,
                                             NULL);
        hb_font_funcs_make_immutable(funcs);
    }
    return funcs;
}

/* A glyph as hb_shape gives it, added to the run's span. */
static void
add_glyph(native_run_t *r, const item_t *t, unsigned id, unsigned cluster,
          int x_advance, int x_offset, int y_offset, int *x)
{
    cf__font_glyph_t g;
    g.id = id;
    g.width = x_advance;
    g.x = x_offset;
    g.y = -y_offset;
    if (g.width < 0) {
        g.width = -g.width;
        g.x += g.width;
    }
    g.cluster = cluster - (unsigned)t->offset;
    cf__font_glyphs_add(&r->glyphs, &g);
    *x += g.width;
}

/* Item t shaped by the renderer's shaper: 1 done, 0 not handled (then
** HarfBuzz shapes it), -1 out of memory. */
static int
own_item(native_run_t *r, const item_t *t, const char *text, int *x)
{
    uint32_t tag = cf__ot_script_tag((uint32_t)t->script);
    size_t k = t->offset, end = t->offset + t->length, i;
    int rc;
    if (t->font->own == NULL || tag == 0)
        return 0;
    while (k < end) {
        unsigned c;
        size_t n = cf__utf8_decode(text, end, k, &c);
        if (n == 0 || !cf__uprops_simple(c))
            return 0;
        k += n;
    }
    rc = cf__ot_shape(t->font->own, tag, &t->font->own_scale, text,
                      t->offset, t->length, &r->ot);
    if (rc != 0)
        return rc < 0 ? -1 : 0;
    cf__font_glyphs_span(&r->glyphs, &t->font->face, t->offset, t->length,
                         *x);
    for (i = 0; i < r->ot.n; i++) {
        const cf__otglyph_t *g = &r->ot.g[i];
        add_glyph(r, t, g->id, g->cluster, g->x_advance, g->x_offset,
                  g->y_offset, x);
    }
    return r->glyphs.failed ? -1 : 1;
}

/* Shape item t of text into b (a span at x); its width added to *x;
** false when a glyph is unknown or the face is not ours, or out of
** memory (r->oom). */
static bool
shape_item(native_fonts_t *nf, native_run_t *r, const item_t *t,
           const char *text, size_t len, int *x)
{
    hb_font_t *sub, *font;
    unsigned n, i;
    hb_glyph_info_t *info;
    hb_glyph_position_t *pos;
    int own;
    if (t->font->unsupported || !cf__nface_scalable(t->font))
        return false;
    if ((own = own_item(r, t, text, x)) != 0) {
        r->oom = own < 0;
        return own > 0;
    }
    if ((font = cf__nface_hb(t->font)) == NULL)
        return false;
    if (nf->buf == NULL) {
        nf->buf = hb_buffer_create();
        if (!hb_buffer_allocation_successful(nf->buf)) {
            hb_buffer_destroy(nf->buf);
            nf->buf = NULL;
            r->oom = true;
            return false;
        }
    }
    hb_buffer_clear_contents(nf->buf);
    hb_buffer_set_direction(nf->buf, HB_DIRECTION_LTR);
    hb_buffer_set_script(nf->buf, t->script);
    hb_buffer_set_language(nf->buf, hb_language_from_string("c", -1));
    hb_buffer_set_cluster_level(nf->buf,
                                HB_BUFFER_CLUSTER_LEVEL_MONOTONE_CHARACTERS);
    hb_buffer_set_flags(nf->buf, HB_BUFFER_FLAG_BOT | HB_BUFFER_FLAG_EOT);
    hb_buffer_set_invisible_glyph(nf->buf, CF__FONT_GLYPH_EMPTY);
    hb_buffer_add_utf8(nf->buf, text, (int)t->offset, (unsigned)t->offset,
                       0);
    hb_buffer_add_utf8(nf->buf, text, (int)(t->offset + t->length),
                       (unsigned)t->offset, (int)t->length);
    hb_buffer_add_utf8(nf->buf, text, (int)len,
                       (unsigned)(t->offset + t->length), 0);
    sub = hb_font_create_sub_font(font);
    hb_font_set_funcs(sub, pango_funcs(), NULL, NULL);
    hb_shape(sub, nf->buf, NULL, 0);
    hb_font_destroy(sub);
    info = hb_buffer_get_glyph_infos(nf->buf, &n);
    pos = hb_buffer_get_glyph_positions(nf->buf, NULL);
    if (n == 0)
        return false;
    cf__font_glyphs_span(&r->glyphs, &t->font->face, t->offset, t->length,
                         *x);
    for (i = 0; i < n; i++) {
        unsigned id = info[i].codepoint;
        if (id != CF__FONT_GLYPH_EMPTY && (id & CF__FONT_GLYPH_UNKNOWN))
            return false;
        add_glyph(r, t, id, info[i].cluster, pos[i].x_advance,
                  pos[i].x_offset, pos[i].y_offset, x);
    }
    return !r->glyphs.failed;
}

/* Shape req natively into r; false when pango must (the rule above), or
** when out of memory (r->oom). */
static bool
shape_native(native_fonts_t *nf, native_run_t *r, const cf__font_req_t *req,
             cf__font_shape_t *out)
{
    const char *lang = cf__native_language();
    cf__nfontset_t *set;
    cf__font_shape_t none;
    size_t i;
    int x = 0;
    bool ok;
    r->oom = false;
    if (!cf__native_fonts_handles(req->text, req->len))
        return false;
    memset(&none, 0, sizeof none);
    cf__nfaces_lock();
    set = cf__nfontset_get(req->family, req->italic, req->bold,
                           (int)(req->size * CF__FONT_SCALE), lang);
    ok = set != NULL && cf__native_itemize(r, set, req->text, req->len);
    cf__font_glyphs_reset(&r->glyphs, req, &none);
    for (i = 0; ok && i < r->nitems; i++)
        ok = shape_item(nf, r, &r->items[i], req->text, req->len, &x);
    if (ok) {
        cf__native_baseline_shifts(r);
        cf__native_extents(r, out);
        r->glyphs.g.shape = *out;
        r->glyphs.g.baseline = out->baseline;
    }
    cf__nfaces_unlock();
    if (r->glyphs.failed)
        r->oom = true;
    return ok && !r->glyphs.failed && !r->oom;
}

static void *
open_fonts(void *self)
{
    native_fonts_t *f = cf_calloc(1, sizeof *f);
    (void)self;
    if (f == NULL)
        return NULL;
    cf__fonts_configure();
    return f;
}

static void
close_fonts(void *ctx)
{
    native_fonts_t *f = ctx;
    if (f == NULL)
        return;
    if (f->pango != NULL)
        cf__pango_fonts.close(f->pango);
    if (f->cr != NULL)
        cairo_destroy(f->cr);
    if (f->buf != NULL)
        hb_buffer_destroy(f->buf);
    cf_free(f);
}

static int
shape(void *ctx, const cf__font_req_t *req, void **run,
      cf__font_shape_t *out)
{
    native_fonts_t *f = ctx;
    native_run_t *r = *run;
    if (r == NULL) {
        r = cf_calloc(1, sizeof *r);
        if (r == NULL)
            return -1;
        *run = r;
    }
    r->native = shape_native(f, r, req, out);
    if (r->native)
        return 0;
    if (r->oom)
        return -1;   /* out of memory, not a run for pango */
    if (f->pango == NULL) {
        f->pango = cf__pango_fonts.open(cf__pango_fonts.self);
        if (f->pango == NULL)
            return -1;
    }
    return cf__pango_fonts.shape(f->pango, req, &r->pango, out);
}

static void
release(void *run)
{
    native_run_t *r = run;
    if (r == NULL)
        return;
    if (r->pango != NULL)
        cf__pango_fonts.release(r->pango);
    cf__font_glyphs_fini(&r->glyphs);
    cf__otrun_fini(&r->ot);
    cf_free(r->items);
    cf_free(r);
}

static const cf__font_glyphs_t *
glyphs(void *run)
{
    native_run_t *r = run;
    return r->native ? &r->glyphs.g : cf__pango_fonts.glyphs(r->pango);
}

static void
draw(void *run, void *cr, bool path)
{
    native_run_t *r = run;
    if (r->native)
        cf__font_glyphs_draw(cr, &r->glyphs.g, path);
    else
        cf__pango_fonts.draw(r->pango, cr, path);
}

static void
outline(void *ctx, void *run, double x, double y, cf__pathb_t *out)
{
    cf__font_glyphs_outline(&((native_fonts_t *)ctx)->cr, glyphs(run), x, y,
                            out);
}

bool
cf__native_fonts_used_pango(void *run)
{
    return !((native_run_t *)run)->native;
}

const cf__fonts_t cf__native_fonts = {
    open_fonts, close_fonts, shape, release, outline, glyphs, draw, NULL
};
