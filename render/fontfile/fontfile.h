/*
** Font files read and subset for the PDF writer (render/fontfile/): an
** OpenType font with CFF outlines (.otf, or a face of an OpenType
** collection, .ttc/.otc) or a TrueType font (.ttf, glyf outlines), cut
** down to the glyphs a document uses, as the program a PDF embeds.  This
** layer reads files and writes bytes only (it uses render/base and libm,
** nothing else: no FreeType, no cairo); the file is mapped, not read
** whole (a Noto CJK collection is 20 MB, a figure uses a few of its
** glyphs), and every offset and length in it is checked against the file
** before it is used: a damaged or hostile font is refused (1), never read
** out of bounds.
**
** The subset keeps the font's glyph ids, so that a PDF content stream
** shows the same code for a glyph whatever else the page uses
** (Identity-H, two bytes a glyph):
**   CFF       a CID-keyed CFF (FontFile3, /Subtype /CIDFontType0C) whose
**             CIDs are the font's glyph ids: a name-keyed font is
**             converted (ROS Adobe Identity 0, one Font DICT in FDArray);
**             a CID-keyed one keeps its Font DICTs that the glyphs use;
**             only the subroutines the kept glyphs call are kept (the
**             others emptied, so that numbering holds);
**   TRUETYPE  a TrueType font (FontFile2) with the same number of glyphs,
**             the glyphs not kept empty (a loca entry of length 0), the
**             components of kept composite glyphs kept; its tables: head,
**             hhea, hmtx, loca, glyf, maxp and, when the font has them,
**             cvt, fpgm, prep (CIDFontType2, /CIDToGIDMap /Identity).
** Glyph 0 (.notdef) is always kept.
*/
#ifndef CURVEFIG_RENDER_FONTFILE_H
#define CURVEFIG_RENDER_FONTFILE_H

#include <stdbool.h>
#include <stddef.h>

#include "buffer.h"

typedef enum cf__fontfile_kind {
    CF__FONTFILE_CFF,
    CF__FONTFILE_TRUETYPE
} cf__fontfile_kind_t;

/* PDF FontDescriptor /Flags bits (ISO 32000-1, table 123) */
#define CF__FONTFILE_FIXED_PITCH (1u << 0)
#define CF__FONTFILE_SERIF       (1u << 1)
#define CF__FONTFILE_SYMBOLIC    (1u << 2)
#define CF__FONTFILE_NONSYMBOLIC (1u << 5)
#define CF__FONTFILE_ITALIC      (1u << 6)

typedef struct cf__fontfile_subset {
    cf__fontfile_kind_t kind;
    cf__buf_t program;        /* the bytes to embed (uncompressed) */
    char ps_name[64];         /* the PostScript name (CFF Name INDEX, else
                                 name table id 6), only the characters a
                                 PDF name may hold unescaped, no subset
                                 tag; "Font" when the file has none */
    unsigned units_per_em;    /* head */
    int bbox[4];              /* x0 y0 x1 y1, font units (head) */
    int ascent, descent;      /* font units: OS/2 typo ascender and
                                 descender, hhea's when there is no OS/2 */
    int cap_height;           /* OS/2 sCapHeight (version >= 2), else
                                 ascent */
    double italic_angle;      /* degrees (post) */
    unsigned flags;           /* CF__FONTFILE_* bits: SYMBOLIC always
                                 (the glyphs are shown by id, not by the
                                 standard Latin character set); ITALIC
                                 (post's angle, head's or OS/2's bit),
                                 FIXED_PITCH (post, PANOSE), SERIF (OS/2
                                 family class or PANOSE) when the font
                                 says so */
    unsigned stem_v;          /* an estimate (PDF requires /StemV): the
                                 CFF Private DICT's StdVW, else from the
                                 OS/2 weight class (400 gives 96) */
    unsigned *advances;       /* advances[i]: the advance width of gids[i]
                                 in font units (hmtx); cf_free'd by fini */
} cf__fontfile_subset_t;

/* The subset of face `index` of the font file at path that holds glyphs
** gids[0..n-1] (any order, repeats allowed; each < the font's number of
** glyphs).  0: out is filled; 1: the file cannot be subset (not found, not
** a font this reads, outlines it does not subset (CFF2, bitmaps only), a
** glyph id out of range, damaged): why (why_cap bytes, NUL-terminated)
** says what and where, out is empty; -1: out of memory (cf_alloc), out
** is empty. */
int cf__fontfile_subset(const char *path, unsigned index,
                        const unsigned *gids, size_t n,
                        cf__fontfile_subset_t *out, char *why,
                        size_t why_cap);

/* Release out's memory (harmless on an empty or released one). */
void cf__fontfile_subset_fini(cf__fontfile_subset_t *out);

#endif
