/*
** The glyphs of a label one by one (render/backends/label-cairo.h): each
** glyph's font, index and origin on the page, where the label's drawing
** puts it (cf__label_draw, cf__label_path: render/backends/font-glyphs.c):
** the run's baseline; per span, the widths of the spans before it; per
** glyph, the widths of the glyphs before it plus its own offset, all in
** pango units added to the run's origin in page units.  The SVG writer
** draws each glyph's outline once and uses it at these origins.  Native
** only: a run's glyphs have cairo's scaled fonts (render/labels/font.h),
** the native faces' made only when asked for (cf__font_face_scaled): a
** glyph's font is NULL until then.
*/
#include "font-glyphs.h"
#include "label-glyph-runs.h"
#include "label-impl.h"

/* The bytes of glyph k's cluster in span s (from its cluster to the
** next larger cluster of the span's glyphs), 0 when a glyph before it
** in the span's logical order begins the same cluster. */
static size_t
cluster_len(const cf__font_glyphs_t *g, const cf__font_span_t *s, size_t k)
{
    unsigned c = g->glyphs[s->glyph + k].cluster;
    size_t end = s->nbytes, i;
    for (i = 0; i < s->nglyphs; i++) {
        unsigned ci = g->glyphs[s->glyph + i].cluster;
        if (ci == c && (s->backward ? i > k : i < k))
            return 0;
        if (ci > c && ci < end)
            end = ci;
    }
    return c < end ? end - c : 0;
}

static int
run_glyphs(const cf__font_glyphs_t *g, double ox, double oy,
           const cf__label_glyph_fns_t *fns, void *ctx)
{
    double by = oy + (double)g->baseline / CF__FONT_SCALE;
    size_t i, k;
    int r = 0;
    for (i = 0; r == 0 && i < g->nspans; i++) {
        const cf__font_span_t *s = &g->spans[i];
        double bx = ox + (double)s->x / CF__FONT_SCALE;
        int xpos = 0;
        if (s->face->scaled == NULL && s->face->make_scaled == NULL)
            continue;
        for (k = 0; r == 0 && k < s->nglyphs; k++) {
            const cf__font_glyph_t *gi = &g->glyphs[s->glyph + k];
            if (gi->id != CF__FONT_GLYPH_EMPTY) {
                cf__label_glyph_t lg;
                /* made at need by its user (cf__font_face_scaled) */
                lg.font = s->face->make_scaled != NULL ? NULL
                                                       : s->face->scaled;
                lg.face = s->face;
                lg.index = gi->id;
                lg.x = bx + (double)(xpos + gi->x) / CF__FONT_SCALE;
                lg.y = gi->y != 0 ? by + (double)gi->y / CF__FONT_SCALE
                                  : by;
                lg.len = cluster_len(g, s, k);
                lg.text = g->text + s->byte
                          + (lg.len > 0 ? gi->cluster : 0);
                r = fns->glyph(ctx, &lg);
            }
            xpos += gi->width;
        }
    }
    return r;
}

int
cf__label_glyphs(const cf_label_t *label, double x, double y,
                 const cf__label_glyph_fns_t *fns, void *ctx)
{
    size_t i;
    int r = 0;
    if (label == NULL)
        return 0;
    for (i = 0; i < label->count; i++) {
        const run_t *run = &label->runs[i];
        if (run->ink[3] > run->ink[1] && !(run->rule_h > 0)
            && (run->shaped == NULL || label->fonts->glyphs == NULL
                || cf__font_glyphs_unknown(
                    label->fonts->glyphs(run->shaped))))
            return 1;
    }
    for (i = 0; r == 0 && i < label->count; i++) {
        const run_t *run = &label->runs[i];
        if (!(run->ink[3] > run->ink[1]))
            continue;
        if (run->rule_h > 0) {
            double rect[4];
            rect[0] = x + run->x;
            rect[1] = y - run->y - run->rule_h;
            rect[2] = run->width;
            rect[3] = run->rule_h;
            r = fns->rule(ctx, rect);
            continue;
        }
        r = run_glyphs(label->fonts->glyphs(run->shaped), x + run->x,
                       y - run->y - run->baseline, fns, ctx);
    }
    return r;
}
