/*
** A shaped run's glyphs (render/labels/font.h: cf__font_glyphs_t) with
** cairo (render/backends/font-glyphs.c), whichever fonts shaped it: drawn
** as pango's cairo renderer draws a layout, outlined, and built by the
** fonts that shape.
*/
#ifndef CURVEFIG_RENDER_FONT_GLYPHS_H
#define CURVEFIG_RENDER_FONT_GLYPHS_H

#include <cairo.h>
#include <stdbool.h>

#include "font.h"

/* A glyph no face has (the character's code in the low bits, as pango
** marks it): it has no outline, and only pango draws it (a box). */
#define CF__FONT_GLYPH_UNKNOWN 0x10000000u

/* Draw the run's glyphs (path: append their outlines to cr's path) from
** cr's current point, which is the run's top left at its baseline's
** height minus the baseline, as pango_cairo_show_layout and
** pango_cairo_layout_path draw a one-line layout: the same cairo calls
** with the same numbers (each span its own save/restore, scaled font and
** cairo_show_text_glyphs with its clusters where the surface keeps text),
** the current point restored after.  Unknown glyphs are left out. */
void cf__font_glyphs_draw(cairo_t *cr, const cf__font_glyphs_t *g,
                          bool path);

/* The face's cairo scaled font, made at need (cf__font_face_t.
** make_scaled); NULL when cairo failed. */
cairo_scaled_font_t *cf__font_face_scaled(const cf__font_face_t *face);

/* Whether any glyph of the run is unknown (CF__FONT_GLYPH_UNKNOWN). */
bool cf__font_glyphs_unknown(const cf__font_glyphs_t *g);

/* v as a course page's glyph data writes it and the page reads it back:
** strtod of printf's "%.5g" (5 significant digits), the same double,
** found by arithmetic where that is exact (1e-3 <= |v| < 1e4, away from
** a tie of the rounding) and by the two calls elsewhere. */
double cf__font_five_digits(double v);

/* The outline of glyph id of scaled font sf per bp of size (from the
** glyph's origin, y down), each coordinate as a course page's glyph data
** holds it (cairo's glyph path at the font's size over that size, to 5
** significant digits): op 'M', 'L', 'C' or 'Z' with its 1, 1, 3 or 0
** points handed to f.  The native outlines and the page's are made of
** these same numbers, so that a label's ink is the same double in the tool
** and in the page.  cr: any context (its path is replaced); 0, or -1 when
** cairo failed. */
int cf__font_glyph_outline(cairo_t *cr, cairo_scaled_font_t *sf,
                           unsigned long id,
                           void (*f)(void *u, char op, const double *v),
                           void *u);

/* A cache of a face's glyph outlines per bp (cf__font_glyph_outline's
** numbers, computed once a glyph), for cf__font_face_t.outlines; NULL when
** out of memory.  It lives as long as the face, in the C library's heap,
** and may be used from several threads. */
void *cf__font_outline_cache_new(void);

/* The outlines of the run's glyphs appended to out, its top left at
** (x, y) (bp, y down), in the arithmetic of the page's glyph table
** (render/labels/font-table.c); *cr: a context made at need (the
** caller destroys it). */
void cf__font_glyphs_outline(cairo_t **cr, const cf__font_glyphs_t *g,
                             double x, double y, cf__pathb_t *out);

/* A run's glyphs being built: spans and glyphs appended, the text and
** the arrays owned here (zero at first; cf__font_glyphs_fini). */
typedef struct cf__font_glyphs_buf {
    cf__font_glyphs_t g;
    cf__font_span_t *spans;
    cf__font_glyph_t *glyphs;
    char *text, *family;
    size_t cap_spans, cap_glyphs, cap_text, cap_family;
    bool failed;
} cf__font_glyphs_buf_t;

/* Empty b for the run req asks for, shaped as sh. */
void cf__font_glyphs_reset(cf__font_glyphs_buf_t *b,
                           const cf__font_req_t *req,
                           const cf__font_shape_t *sh);
/* A new span of face over the run's text[byte ...][0..nbytes), x from
** the run's left end; its glyphs follow (cf__font_glyphs_add). */
void cf__font_glyphs_span(cf__font_glyphs_buf_t *b,
                          const cf__font_face_t *face, size_t byte,
                          size_t nbytes, int x);
void cf__font_glyphs_add(cf__font_glyphs_buf_t *b,
                         const cf__font_glyph_t *glyph);
void cf__font_glyphs_fini(cf__font_glyphs_buf_t *b);

#endif
