/*
** The glyphs of a label one by one (render/backends/label-cairo.h): each
** glyph's font, index and origin on the page, where pango's cairo
** renderer puts it when it draws the label (cf__label_draw,
** cf__label_path): per line, its logical left edge and baseline; per run
** of the line, the widths of the runs before it; per glyph, the widths of
** the glyphs before it plus its own offset, all in pango units added to
** the run's origin in page units.  A label's runs carry no attributes
** (no rise, no shapes), so nothing else moves a glyph.  The SVG writer
** draws each glyph's outline once and uses it at these origins.  Native
** only: a run's shaping is pango's layout (render/backends/font-pango.c).
*/
#include <pango/pangocairo.h>

#include "label-glyph-runs.h"
#include "label-impl.h"

/* Whether every glyph of the layout is a glyph of its font (pango draws a
** missing one as a box of its hexadecimal code, which has no outline). */
static bool
all_known(PangoLayout *layout)
{
    PangoLayoutIter *it = pango_layout_get_iter(layout);
    bool ok = true;
    do {
        PangoLayoutRun *run = pango_layout_iter_get_run_readonly(it);
        int i;
        if (run == NULL)
            continue;
        for (i = 0; ok && i < run->glyphs->num_glyphs; i++) {
            PangoGlyph g = run->glyphs->glyphs[i].glyph;
            ok = g == PANGO_GLYPH_EMPTY || !(g & PANGO_GLYPH_UNKNOWN_FLAG);
        }
    } while (ok && pango_layout_iter_next_run(it));
    pango_layout_iter_free(it);
    return ok;
}

static int
layout_glyphs(PangoLayout *layout, double ox, double oy,
              const cf__label_glyph_fns_t *fns, void *ctx)
{
    PangoLayoutIter *it = pango_layout_get_iter(layout);
    int r = 0;
    do {
        PangoLayoutRun *run = pango_layout_iter_get_run_readonly(it);
        PangoRectangle logical;
        cairo_scaled_font_t *font;
        double bx, by;
        int i, xpos = 0;
        if (run == NULL)
            continue;
        font = pango_cairo_font_get_scaled_font(
            (PangoCairoFont *)run->item->analysis.font);
        if (font == NULL)
            continue;
        pango_layout_iter_get_run_extents(it, NULL, &logical);
        bx = ox + (double)logical.x / PANGO_SCALE;
        by = oy + (double)pango_layout_iter_get_baseline(it) / PANGO_SCALE;
        for (i = 0; r == 0 && i < run->glyphs->num_glyphs; i++) {
            const PangoGlyphInfo *gi = &run->glyphs->glyphs[i];
            if (gi->glyph != PANGO_GLYPH_EMPTY)
                r = fns->glyph(
                    ctx, font, gi->glyph,
                    bx + (double)(xpos + gi->geometry.x_offset) / PANGO_SCALE,
                    gi->geometry.y_offset != 0
                        ? by + (double)gi->geometry.y_offset / PANGO_SCALE
                        : by);
            xpos += gi->geometry.width;
        }
    } while (r == 0 && pango_layout_iter_next_run(it));
    pango_layout_iter_free(it);
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
            && (run->shaped == NULL || !all_known(run->shaped)))
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
        r = layout_glyphs(run->shaped, x + run->x,
                          y - run->y - run->baseline, fns, ctx);
    }
    return r;
}
