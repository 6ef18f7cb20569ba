/*
** The fonts labels are set in: a run of text in one font shaped into
** glyphs and measured, and the outlines of those glyphs.  The labels know
** nothing else of fonts: they are given a table of these functions (a
** figure's, render/figure/model.h, from its creation), chosen at the top
** by render/output/create.c.  Three implementations:
**   native (render/backends/font-native.c): the native renderer's,
**     HarfBuzz's shaping in the faces pango 1.50 would choose, with the
**     same numbers as pango; the runs it does not shape go to
**   pango (render/backends/font-pango.c), with cairo's font backend for
**     unhinted metrics (both draw and outline through cairo's scaled
**     fonts, render/backends/font-glyphs.c);
**   the glyph table (render/labels/font-table.c): plain C over the glyph
**     data a course page embeds (render/output/label-glyphs.c writes it
**     from the native shaping): the browser module sets labels with it.
** All answer in pango units (1/1024 bp), so a text shaped at export is
** the same numbers in the page as in the tool.
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

/* The glyphs of a shaped run, whatever shaped it: what the native
** backends draw (render/backends/label-cairo.c), outline and export
** (render/output/label-glyphs.c).  A run is spans of glyphs, each in one
** face and for one stretch of the run's text, in drawing order (left to
** right).  In CF__FONT_SCALE units, y down: a span starts `x` from the
** run's left end; a glyph's origin is `x` from its span's start and `y`
** below the run's baseline (`baseline` below the run's top). */
#define CF__FONT_GLYPH_EMPTY 0x0FFFFFFFu   /* no glyph: draw nothing */

typedef struct cf__font_face {
    void *scaled;          /* its cairo_scaled_font_t (natively) */
    const char *key;       /* the same string for the same face at any
                              size, another for another face */
    void *outlines;        /* NULL, or a cache of its glyphs' outlines
                              for a face that lives as long as the
                              process (render/backends/font-glyphs.h) */
    void *show_options;    /* NULL, or the cairo_font_options_t its
                              glyphs are shown with, not its scaled
                              font's (render/backends/font-faces.c) */
    const char *file;      /* NULL, or its font file (fontconfig's
                              FC_FILE), which a PDF embeds */
    unsigned index;        /* the face's index in that file (FC_INDEX) */
    const char *psname;    /* NULL, or its PostScript name
                              (FC_POSTSCRIPT_NAME): a collection's faces
                              have their own, their CFF one shared */
    bool emboldened;       /* bold made by cairo (FC_EMBOLDEN): a PDF
                              draws its outlines, the file has it not */
    bool has_matrix;       /* matrix holds its font matrix */
    double matrix[4];      /* its scaled font's font matrix (xx yx xy yy,
                              cairo's, y down), known without the scaled
                              font: the PDF writer's, and the outlines'
                              read from the file */
    void *own;             /* NULL, or its outlines read from its file,
                              made at need (render/backends/
                              font-outlines.h) */
    void *(*make_scaled)(const struct cf__font_face *face);
                           /* NULL, or makes `scaled` at need (the native
                              faces: only drawing through cairo and the
                              glyphs the file cannot give need it) */
} cf__font_face_t;

typedef struct cf__font_glyph {
    unsigned id;           /* in its face, or CF__FONT_GLYPH_EMPTY */
    int x, y;
    int width;             /* its advance */
    unsigned cluster;      /* the byte of the span's text it begins at */
} cf__font_glyph_t;

typedef struct cf__font_span {
    const cf__font_face_t *face;
    size_t glyph, nglyphs;     /* its glyphs: glyphs[glyph ...] */
    size_t byte, nbytes;       /* its text: the run's text[byte ...] */
    int x;
    int shift;                 /* how far pango's layout raises it: runs
                                  of another script than the first one's
                                  sit on its baseline (ideographic, hanging
                                  or roman, from the fonts' tables); the
                                  drawing, the outlines and the page's
                                  glyph data all move it */
    bool backward;             /* right to left: glyphs in visual order,
                                  clusters from the last glyph */
} cf__font_span_t;

typedef struct cf__font_glyphs {
    const char *family;        /* the request (cf__font_req_t) */
    bool italic, bold;
    const char *text;          /* the run's text (UTF-8) */
    size_t len;
    cf__font_shape_t shape;    /* what shape answered */
    int baseline;
    const cf__font_span_t *spans;
    size_t nspans;
    const cf__font_glyph_t *glyphs;
    size_t nglyphs;
    double size;               /* bp, as asked for */
} cf__font_glyphs_t;

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
    /* The glyphs of a shaped run (valid until it is shaped again or
    ** released); NULL for fonts that have no faces to draw with (the
    ** glyph table: its labels are drawn as their outlines). */
    const cf__font_glyphs_t *(*glyphs)(void *run);
    /* Draw a run with unknown glyphs (which only pango draws, as boxes)
    ** from cairo_t cr's current point as cf__font_glyphs_draw would
    ** (render/backends/font-glyphs.h); NULL: such runs are outlined. */
    void (*draw)(void *run, void *cr, bool path);
    void *self;
} cf__fonts_t;

#endif
