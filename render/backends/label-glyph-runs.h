/*
** The glyphs of a label one by one (render/backends/label-glyph-runs.c),
** natively only (the fonts' glyph runs and cairo's scaled fonts; the browser
** module has neither): for the glyph uses of the SVG files
** (render/output/svg-glyphs.c).
*/
#ifndef CURVEFIG_RENDER_LABEL_GLYPH_RUNS_H
#define CURVEFIG_RENDER_LABEL_GLYPH_RUNS_H

#include "font.h"
#include "label-cairo.h"

/* The glyphs of the label one by one, baseline origin at (x, y), where
** cf__label_path puts them (render/backends/label-glyph-runs.c): glyph
** gets each glyph (its scaled font and face, index, origin on the page
** and the text of the cluster it begins), rule each fraction rule (x y w
** h), in drawing order.  1, and no call, when a glyph is missing from its
** font (pango draws a box for it, which has no outline of the font: take
** the label's path whole); else the first nonzero result of a call, or
** 0. */
typedef struct cf__label_glyph {
    cairo_scaled_font_t *font;    /* NULL: not made yet (face's
                                     cf__font_face_scaled makes it) */
    const cf__font_face_t *face;
    unsigned long index;
    double x, y;
    const char *text;     /* the characters (UTF-8) of the cluster it */
    size_t len;           /* begins; len 0: it begins none (a later glyph
                             of a cluster) */
} cf__label_glyph_t;

typedef struct cf__label_glyph_fns {
    int (*glyph)(void *ctx, const cf__label_glyph_t *g);
    int (*rule)(void *ctx, const double rect[4]);
} cf__label_glyph_fns_t;

int cf__label_glyphs(const cf_label_t *label, double x, double y,
                     const cf__label_glyph_fns_t *fns, void *ctx);

#endif
