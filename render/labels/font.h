/*
** The fonts labels are set in: a run of text in one font shaped into
** glyphs and measured, and the outlines of those glyphs.  The labels know
** nothing else of fonts: they are given a table of these functions (a
** figure's, render/figure/model.h, from its creation), chosen at the top
** by render/output/create.c.  Two implementations:
**   pango (render/backends/font-pango.c): the native renderer's, with
**     cairo's font backend for unhinted metrics and for the outlines;
**   the glyph table (render/labels/font-table.c): plain C over the glyph
**     data a course page embeds (render/output/label-glyphs.c writes it
**     from pango's shaping): the browser module sets labels with it.
** Both answer in pango units, so a text shaped at export is the same
** numbers in the page as in the tool.
*/
#ifndef CURVEFIG_RENDER_FONT_H
#define CURVEFIG_RENDER_FONT_H

#include <stdbool.h>
#include <stddef.h>

#include "pathb.h"

#define CF__FONT_SCALE 1024   /* units a bp (PANGO_SCALE) */

/* A run of text in one font. */
typedef struct cf__font_req {
    const char *family;     /* a list, as pango takes it */
    bool italic, bold;
    double size;            /* bp */
    const char *text;
    size_t len;
} cf__font_req_t;

/* Its shaping, in CF__FONT_SCALE units from the run's top left (y
** down): the baseline, the logical and the ink rectangle (x y width
** height), and how many characters have no glyph. */
typedef struct cf__font_shape {
    int baseline;
    int logical[4];
    int ink[4];
    int unknown;
} cf__font_shape_t;

typedef struct cf__fonts {
    /* A context for one label (NULL: out of memory), and its end. */
    void *(*open)(void *self);
    void (*close)(void *ctx);
    /* Shape req into *run (NULL at first, then the run's own handle,
    ** which the implementation may reuse) and *out; 0, or -1 when it
    ** failed (out of memory). */
    int (*shape)(void *ctx, const cf__font_req_t *req, void **run,
                 cf__font_shape_t *out);
    void (*release)(void *run);
    /* The outlines of a run's glyphs appended to out, its top left at
    ** (x, y) (bp, y down). */
    void (*outline)(void *ctx, void *run, double x, double y,
                    cf__pathb_t *out);
    void *self;
} cf__fonts_t;

#endif
