/*
** The glyphs of the SVG files (render/backends/backend-svgw.c, natively):
** each label as its glyphs (render/backends/label-glyph-runs.c), each glyph
** an outline drawn once in the document's <defs> and used at every place
** it appears (as cairo's SVG surface, the writer before it, did).  A glyph is its cairo
** scaled font (one per font face, size and options, held here by a
** reference so that the pointer names it while the table lives), or the
** native face whose glyphs are read from its file (font-outlines.h), and
** its index in the font; its outline is cairo's path of it at the origin,
** the same numbers either way.
*/
#include <string.h>

#include <cairo.h>

#include "font-glyphs.h"
#include "font-outlines.h"
#include "grow.h"
#include "label-glyph-runs.h"
#include "output-private.h"

struct cf__svg_glyph {
    cairo_scaled_font_t *font;        /* held; NULL for a face read from
                                         its file */
    const cf__font_face_t *face;      /* that face (a native one, which
                                         lives as long as the process) */
    unsigned long index;
};

/* The number of a glyph (1 and up), added at need; 0 out of memory or
** when its font cannot be made. */
static unsigned
glyph_id(cf__svg_glyphs_t *sg, const cf__label_glyph_t *lg)
{
    struct cf__svg_glyph *g;
    cairo_scaled_font_t *font = lg->font;
    const cf__font_face_t *face = NULL;
    size_t i;
    if (cf__own_face(lg->face)) {
        face = lg->face;
        font = NULL;
    } else if (font == NULL) {
        font = cf__font_face_scaled(lg->face);
        if (font == NULL)
            return 0;
    }
    for (i = sg->n; i-- > 0;)
        if (sg->g[i].font == font && sg->g[i].face == face
            && sg->g[i].index == lg->index)
            return (unsigned)i + 1;
    g = cf__grow_array(sg->g, &sg->cap, sg->n + 1, sizeof *g, 64);
    if (g == NULL || sg->n + 1 > 0xffffffu)
        return 0;
    sg->g = g;
    g[sg->n].font = font != NULL ? cairo_scaled_font_reference(font) : NULL;
    g[sg->n].face = face;
    g[sg->n].index = lg->index;
    return (unsigned)++sg->n;
}

typedef struct label_ctx {
    cf__svg_glyphs_t *sg;
    cf__buf_t *uses, *rules;
} label_ctx_t;

static int
on_glyph(void *ctx, const cf__label_glyph_t *g)
{
    label_ctx_t *lc = ctx;
    cf__svgw_use_t u;
    u.id = glyph_id(lc->sg, g);
    u.x = g->x;
    u.y = g->y;
    if (u.id == 0)
        return -1;
    return cf__buf_append(lc->uses, &u, sizeof u);
}

static int
on_rule(void *ctx, const double r[4])
{
    label_ctx_t *lc = ctx;
    const char *const op[] = { "M", " ", "h", "v" };
    double v[4];
    int k, bad = 0;
    v[0] = r[0];
    v[1] = r[1];
    v[2] = r[2];
    v[3] = r[3];
    for (k = 0; k < 4 && !bad; k++)
        bad = cf__buf_append(lc->rules, op[k], 1) != 0
              || cf__svg_put_num(lc->rules, v[k]) != 0;
    if (!bad) {
        bad = cf__buf_append(lc->rules, "h", 1) != 0
              || cf__svg_put_num(lc->rules, -v[2]) != 0
              || cf__buf_append(lc->rules, "Z", 1) != 0;
    }
    return bad ? -1 : 0;
}

static int
uses(void *ctx, const cf__text_op_t *t, cf__buf_t *u, cf__buf_t *rules)
{
    static const cf__label_glyph_fns_t fns = { on_glyph, on_rule };
    label_ctx_t lc;
    lc.sg = ctx;
    lc.uses = u;
    lc.rules = rules;
    return cf__label_glyphs(t->label, t->ox, t->oy, &fns, &lc);
}

static int
outline(void *ctx, const cf__text_op_t *t, cf__buf_t *d)
{
    return cf__glyph_outline(&((cf__svg_glyphs_t *)ctx)->outliner, t, d);
}

static int
glyph_path(void *ctx, unsigned id, cf__buf_t *d)
{
    cf__svg_glyphs_t *sg = ctx;
    cairo_t *cr;
    cairo_glyph_t glyph;
    cairo_path_t *path;
    int r;
    if (id == 0 || id > sg->n)
        return -1;
    if (sg->outliner.cr == NULL) {
        cairo_surface_t *s = cairo_recording_surface_create(
            CAIRO_CONTENT_ALPHA, NULL);
        sg->outliner.cr = cairo_create(s);
        cairo_surface_destroy(s);
    }
    cr = sg->outliner.cr;
    glyph.index = sg->g[id - 1].index;
    glyph.x = 0;
    glyph.y = 0;
    cairo_new_path(cr);
    if (sg->g[id - 1].face != NULL) {
        if (cf__own_glyph_path(cr, sg->g[id - 1].face, glyph.index, 0, 0)
            != 0)
            return -1;
    } else {
        cairo_set_scaled_font(cr, sg->g[id - 1].font);
        cairo_glyph_path(cr, &glyph, 1);
    }
    path = cairo_copy_path(cr);
    r = cf__svg_path_data(path, d);
    cairo_path_destroy(path);
    cairo_new_path(cr);
    return r;
}

void
cf__svg_glyphs_attach(cf__svg_glyphs_t *sg, cf__svgw_t *w)
{
    w->outline = outline;
    w->uses = uses;
    w->glyph_path = glyph_path;
    w->outline_ctx = sg;
}

void
cf__svg_glyphs_fini(cf__svg_glyphs_t *sg)
{
    size_t i;
    for (i = 0; i < sg->n; i++)
        if (sg->g[i].font != NULL)
            cairo_scaled_font_destroy(sg->g[i].font);
    cf_free(sg->g);
    cf__glyph_outliner_fini(&sg->outliner);
    memset(sg, 0, sizeof *sg);
}
