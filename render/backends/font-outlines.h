/*
** A native face's glyphs read from its font file (render/backends/
** font-outlines.c, over render/fontfile/outline.h) instead of cairo-ft and
** FreeType: the same path cairo_glyph_path appends and the same ink
** extents cairo_scaled_font_glyph_extents reports for the face's scaled
** font, so that the layout and the SVG, PDF and PGF writers load no
** FreeType and their bytes do not change.
**
** The numbers are cairo 1.16's over FreeType 2.12's: the face's scaled
** font's scale (its font matrix, identity CTM) split as cairo-ft splits
** it (_compute_transform: the x basis vector's length and |det| over it,
** each at least 1) into FT_Set_Char_Size's character size (x * 64 + .5,
** truncated) and FT_Set_Transform's shape (the normalised matrix in
** 16.16, truncated, its off-diagonal terms negated for y up); the glyph's
** outline y-inverted and decomposed as FT_Outline_Decompose walks it
** (implied on-curve points at the truncated midpoint of two conic ones),
** each point 26.6 << 2 into cairo's 24.8, a conic arc as the cubic
** x0 + 2/3 (c - x0), x3 + 2/3 (c - x3) truncated, a contour closed before
** the next move and at the end; the extents as cairo-ft takes unhinted
** metrics: the glyph loaded at the em size (character size upem), its
** control box / 64 times 1 / upem, the corners through the font matrix.
**
** A face is not handled (1: the caller takes cairo's scaled font) when
** it is emboldened (FT_Outline_Embolden is not reproduced), when its file
** gives no outlines (render/fontfile/outline.h's refusals) or a glyph is
** refused.
*/
#ifndef CURVEFIG_RENDER_FONT_OUTLINES_H
#define CURVEFIG_RENDER_FONT_OUTLINES_H

#include <stdbool.h>
#include <stdint.h>

#include <cairo.h>

#include "font.h"

/* Whether face's glyphs come from its file (the face set up at the first
** call). */
bool cf__own_face(const cf__font_face_t *face);

/* Glyph id's path appended to cr's path at the glyph origin (ox, oy) in
** cairo's 24.8 fixed point, as cairo_glyph_path appends it on a context
** with the identity matrix: 0, 1 not handled (nothing appended), -1 out
** of memory. */
int cf__own_glyph_path(cairo_t *cr, const cf__font_face_t *face,
                       unsigned long id, int32_t ox, int32_t oy);

/* cairo_scaled_font_glyph_extents of glyph id at the origin: 0, 1, -1. */
int cf__own_glyph_extents(const cf__font_face_t *face, unsigned long id,
                          cairo_text_extents_t *e);

/* cairo's _cairo_fixed_from_double (24.8, nearest, ties to even). */
int32_t cf__own_fixed(double v);

/* Whether cr's user space is its device space (the identity matrix), as
** cf__own_glyph_path needs. */
bool cf__own_identity(cairo_t *cr);

#endif
