/*
** The fonts of the PDF writer's document (render/backends/pdf-fonts.c):
** each face of a font file the labels' text uses, once, as a Type0 font
** (Identity-H: two-byte codes that are the font's glyph ids) over a
** CIDFontType0 (a CID-keyed CFF, FontFile3 /CIDFontType0C) or a
** CIDFontType2 (TrueType, FontFile2, /CIDToGIDMap /Identity) that
** render/fontfile/fontfile.h cuts down to the glyphs used, with a subset
** tag of six capital letters made from the glyph set, /W from its
** advances, a FontDescriptor from its metrics and a ToUnicode CMap from
** the text of each glyph's cluster, so that the text can be extracted.
*/
#ifndef CURVEFIG_RENDER_PDF_FONTS_H
#define CURVEFIG_RENDER_PDF_FONTS_H

#include "backend.h"

/* The font of g's face, g's glyph and text noted: its number (/FN), or
** -1 out of memory, -2 when the face was refused (draw the label's
** outlines). */
int cf__pdfw_font_use(cf__pdfw_t *w, const cf__pdfw_glyph_t *g);

/* Subset every font used: 0; 1 when one was refused (marked so); -1 out
** of memory.  Then the number of objects they take (5 a font used). */
int cf__pdfw_fonts_subset(cf__pdfw_t *w);
size_t cf__pdfw_fonts_objects(const cf__pdfw_t *w);

/* The /Font entries of the resources, the fonts' objects numbered from
** first on: 0, or -1 out of memory.  begin_obj notes object n's offset
** and writes its "n 0 obj\n"; stream writes a stream object (dict: its
** entries but /Length and /Filter; program: a font's program, which the
** document compresses only when it is large). */
typedef struct cf__pdfw_objs {
    cf__buf_t *out;
    int (*begin_obj)(void *ctx, size_t n);
    int (*stream)(void *ctx, size_t n, const char *dict,
                  const cf__buf_t *data, bool program);
    void *ctx;
} cf__pdfw_objs_t;
int cf__pdfw_fonts_resources(const cf__pdfw_t *w, size_t first,
                             cf__buf_t *out);
int cf__pdfw_fonts_write(const cf__pdfw_t *w, size_t first,
                         const cf__pdfw_objs_t *o);

/* Release the fonts (clear: only what a restart drops, their glyphs and
** subsets, the refusals kept). */
void cf__pdfw_fonts_free(cf__pdfw_t *w, bool clear);

#endif
