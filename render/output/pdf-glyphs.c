/*
** The glyphs of the PDF files (render/backends/backend-pdfw.c, natively):
** each label's glyphs (render/backends/label-glyph-runs.c) with their
** faces' font files, font matrices (the ones cairo's scaled fonts have,
** known without making them) and the text
** of their clusters, for the PDF writer to show as text.  A face without
** a file (pango's) or emboldened by cairo makes the label its outlines.
*/
#include <cairo.h>

#include "label-glyph-runs.h"
#include "output-private.h"

typedef struct label_ctx {
    cf__buf_t *glyphs, *rules;
} label_ctx_t;

static int
on_glyph(void *ctx, const cf__label_glyph_t *g)
{
    label_ctx_t *lc = ctx;
    cf__pdfw_glyph_t p;
    cairo_matrix_t m;
    if (g->face == NULL || g->face->file == NULL || g->face->emboldened
        || g->index > 0xffff)
        return 1;
    if (g->face->has_matrix) {
        m.xx = g->face->matrix[0];
        m.yx = g->face->matrix[1];
        m.xy = g->face->matrix[2];
        m.yy = g->face->matrix[3];
    } else {
        cairo_scaled_font_get_font_matrix(g->font, &m);
    }
    p.file = g->face->file;
    p.index = g->face->index;
    p.psname = g->face->psname;
    p.m[0] = m.xx;
    p.m[1] = m.yx;
    p.m[2] = m.xy;
    p.m[3] = m.yy;
    p.gid = (unsigned)g->index;
    p.x = g->x;
    p.y = g->y;
    p.text = g->text;
    p.len = g->len;
    return cf__buf_append(lc->glyphs, &p, sizeof p);
}

static int
on_rule(void *ctx, const double r[4])
{
    return cf__buf_append(((label_ctx_t *)ctx)->rules, r, 4 * sizeof *r);
}

int
cf__pdf_glyphs(void *ctx, const cf__text_op_t *t, cf__buf_t *glyphs,
               cf__buf_t *rules)
{
    static const cf__label_glyph_fns_t fns = { on_glyph, on_rule };
    label_ctx_t lc;
    (void)ctx;
    lc.glyphs = glyphs;
    lc.rules = rules;
    return cf__label_glyphs(t->label, t->ox, t->oy, &fns, &lc);
}
