/*
** Glyph outlines read from the font files themselves (render/fontfile/
** outline.c, outline-cff.c, outline-glyf.c, outline-points.c): the points
** FreeType 2.12
** gives for a glyph loaded unhinted (FT_LOAD_NO_HINTING) at a character
** size, the same integers, so that the renderer's vector outputs and its
** layout take a glyph's outline and ink extents from here instead of
** cairo-ft and FreeType (render/backends/font-outlines.c) and come out
** the same bytes.  This layer reads bytes only: no FreeType, no cairo.
**
** What is reproduced, in FreeType's integer arithmetic (FT_MulFix rounds
** half away from zero, FT_DivFix likewise, both on 16.16 numbers):
**   the size   FT_Set_Char_Size(w, h) in 26.6 at 72 dpi: the scales
**              x_scale = FT_DivFix(w, upem), y_scale = FT_DivFix(h, upem)
**              (16.16, font units to 26.6 pixels; TrueType's integer-ppem
**              rounding is for hinted loads only);
**   CFF        the Type 2 charstring (Adobe Technical Note #5177) run as
**              FreeType's Adobe engine (psaux) runs it unhinted: operands
**              16.16, the path at "unity" scale 1/64 (a point is
**              FT_MulFix(v, 0x400) in 16.16, shifted right by 10 into the
**              outline: whole font units, fractions floored), lines of
**              zero length dropped, a contour's last point dropped when
**              it is on its first; then each point FT_MulFix'd by the
**              scales.  Every operator: the hints counted and skipped
**              (hintmask and cntrmask bytes), the four flexes as two
**              curves, callsubr/callgsubr with the bias (107, 1131,
**              32768), the arithmetic a glyph may compute with (abs, add,
**              sub, mul, div, neg, drop, exch, dup).  CID-keyed fonts
**              read their Font DICT's local Subrs through FDSelect
**              (formats 0 and 3).  Not handled (1, the caller keeps
**              FreeType): seac (endchar with 4 operands), a Font Matrix
**              other than the default, CFF2, the logic, storage and
**              stack operators (and, or, not, eq, ifelse, put, get,
**              index, roll), random, sqrt;
**   TrueType   glyf with loca (short or long), simple glyphs' flags and
**              deltas, composite glyphs (their components' points moved
**              by the offsets, ARGS_ARE_XY_VALUES, or matched points;
**              WE_HAVE_A_SCALE, AN_XY_SCALE, A_2X2 as 2.14 transforms of
**              the scaled points, as FreeType applies them), 8 levels of
**              components at most; then moved by -(xMin - lsb) scaled, as
**              FreeType puts the origin at the phantom point.  Not
**              handled: SCALED_COMPONENT_OFFSET with a scale,
**              USE_MY_METRICS whose component's origin is not the
**              glyph's;
**   the shape  FreeType's transform (FT_Set_Transform: a 16.16 matrix
**              cairo sets for a slanted or non-square font) applied to
**              every point (FT_Outline_Transform), after the metrics are
**              taken.
** The metrics are the control box of the outline before the transform
** (FT_Outline_Get_CBox: the glyph's horiBearingX, horiBearingY, width
** and height).
**
** The work is bounded: a CFF glyph may interpret at most
** CF__CFF_STEPS_PER_GLYPH * 16 charstring bytes (subroutines included)
** and hold CF__OL_MAX_POINTS points; a TrueType glyph as many points and
** 8 levels of components.  Every offset is checked against its table: a
** damaged glyph is refused (1), never read out of bounds.
*/
#ifndef CURVEFIG_RENDER_OUTLINE_H
#define CURVEFIG_RENDER_OUTLINE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define CF__OL_MAX_POINTS 32768

/* Point tags, as FreeType's FT_CURVE_TAG_*: on the curve, a quadratic
** control point, a cubic one. */
#define CF__OL_ON    1
#define CF__OL_CONIC 0
#define CF__OL_CUBIC 2

/* An outline in 26.6 (y up, as FreeType's): n points, contour k the
** points up to ends[k] (inclusive).  Grown with the library's allocator
** (cf_alloc), or with the C library's when libc is set (the renderer's
** caches of process-long faces, outside the library's count of live
** blocks); cf__outline_fini releases it. */
typedef struct cf__outline {
    bool libc;
    int64_t *x, *y;
    unsigned char *tags;
    size_t n, cap;
    size_t *ends;
    size_t ncontours, cap_contours;
    int64_t cbox[4];      /* xMin yMin xMax yMax before the shape */
} cf__outline_t;

void cf__outline_fini(cf__outline_t *o);

/* A face's outlines: the font file mapped, one face of it, its CFF or
** glyf tables found. */
typedef struct cf__olface cf__olface_t;

/* Face `index` of the font file at path: 0 and *out; 1 when the file
** cannot give outlines (unreadable, damaged, CFF2, a Font Matrix this does
** not read: the caller keeps FreeType); -1 out of memory.  The face lives
** in the C library's heap (malloc), for faces that live as long as the
** process, and keeps the file mapped until cf__olface_close. */
int cf__olface_open(const char *path, unsigned index, cf__olface_t **out);
/* The same over bytes in memory, in the library's allocator (not copied:
** they outlive the face). */
int cf__olface_open_mem(const unsigned char *data, size_t len,
                        unsigned index, cf__olface_t **out);
void cf__olface_close(cf__olface_t *face);

unsigned cf__olface_units_per_em(const cf__olface_t *face);
unsigned cf__olface_num_glyphs(const cf__olface_t *face);

/* A size: FreeType's scales from a character size (26.6, FT_Set_Char_Size
** at 72 dpi), and its transform (16.16: xx xy yx yy; FT_Set_Transform). */
typedef struct cf__olsize {
    int64_t x_scale, y_scale;
    int64_t m[4];
    bool transform;       /* m is not the identity */
} cf__olsize_t;

void cf__olface_size(const cf__olface_t *face, int64_t char_w,
                     int64_t char_h, const int64_t m[4], cf__olsize_t *sz);

/* Glyph gid's outline at size sz into o (emptied first): 0; 1 not
** handled or damaged (o's contents undefined); -1 out of memory. */
int cf__olface_glyph(const cf__olface_t *face, unsigned gid,
                     const cf__olsize_t *sz, cf__outline_t *o);

#endif
