/*
** What a font file says about its faces, as fontconfig reads it
** (render/fontfile/fontmeta.c): the metadata fontconfig's matching uses,
** read from the file's own tables (name, OS/2, head, cmap, fvar), without
** FreeType or fontconfig, for a face matcher that needs neither.
**
** Each value is the one fontconfig 2.14's scan (fcfreetype.c) puts in a
** font's pattern:
**   family      the name table's WWS family (21), typographic family (16)
**               and family (1) names, Microsoft platform first, then
**               Unicode, Macintosh, ISO; in each platform encodings in
**               order and English first; each name trimmed of spaces and
**               kept once (blanks and case ignored); familylang the
**               language of each ("en", "ja", "zh-cn" ...);
**   slant       a style name containing "italic" or "kursiv" (italic) or
**               "oblique" (oblique), else the font's italic flag (OS/2
**               fsSelection bits 0 and 9, head's macStyle without OS/2);
**   weight      OS/2 usWeightClass on fontconfig's scale
**               (FcWeightFromOpenTypeDouble), else a weight word of a style
**               name, else medium (bold when the font's bold flag is set);
**   width       OS/2 usWidthClass 1..9, else a width word of a style name,
**               else normal;
**   decorative  a style name containing a decorative word ("caps" ...);
**   size        OS/2 version 5's optical point sizes (twips / 20);
**   fontversion head's fontRevision; fontformat "CFF" or "TrueType";
**   postscriptname  name id 6 (Windows English, else Macintosh Roman);
**   charset     the characters the font's Unicode cmap maps to a glyph
**               (format 12 for Windows UCS-4 when present, else format 4),
**               a control character (up to U+001F) only when its glyph has
**               contours;
**   codepages   OS/2 ulCodePageRange (version >= 1): fontconfig's
**               exclusive languages (ja, zh-cn, ko, zh-tw).
** A face fontconfig would read other than this (a name in an encoding
** other than UTF-16 or ASCII, a language this does not list, a cmap
** format other than 4 and 12, a variable font, a CFF font that maps a
** control character) is refused with the reason: a matcher using these
** records then leaves the configuration to fontconfig.
*/
#ifndef CURVEFIG_RENDER_FONTMETA_H
#define CURVEFIG_RENDER_FONTMETA_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define CF__FMETA_NAMES 8          /* family names kept, at most */
#define CF__FMETA_NAME_LEN 96      /* bytes of a name with its NUL */

/* fontconfig's constants (fontconfig.h) */
#define CF__FMETA_SLANT_ROMAN 0
#define CF__FMETA_SLANT_ITALIC 100
#define CF__FMETA_SLANT_OBLIQUE 110

typedef struct cf__fmeta {
    unsigned index;                 /* the face in its file */
    unsigned nfamily;
    char family[CF__FMETA_NAMES][CF__FMETA_NAME_LEN];
    char familylang[CF__FMETA_NAMES][8];   /* "" : none ("und" then) */
    char psname[CF__FMETA_NAME_LEN];
    int slant;
    double weight, width;
    bool decorative;
    bool has_size;
    double size_lo, size_hi;        /* equal: one size */
    int32_t fontversion;
    bool cff;                       /* fontformat "CFF", else "TrueType" */
    bool has_codepages;
    uint32_t codepages[2];
    uint32_t *ranges;               /* charset: first, last, first, last
                                       ... ascending (cf_free'd by
                                       cf__fmeta_fini) */
    size_t nranges;                 /* pairs */
} cf__fmeta_t;

/* The number of faces of the font data[0..len) (a collection's count, 1
** for a single font); 0 when it is no font this reads. */
unsigned cf__fmeta_count(const unsigned char *data, size_t len);

/* Read face `index` of the font data[0..len) into out.  0: out filled;
** 1: refused (why, why_cap bytes, says why; out empty); -1: out of
** memory (out empty). */
int cf__fmeta_read(const unsigned char *data, size_t len, unsigned index,
                   cf__fmeta_t *out, char *why, size_t why_cap);

/* Whether the face's charset holds c. */
bool cf__fmeta_has(const cf__fmeta_t *m, uint32_t c);

/* Whether ranges[0..2n) (first, last pairs, ascending, maximal) hold
** [a, b] whole. */
bool cf__fmeta_ranges_hold(const uint32_t *ranges, size_t n, uint32_t a,
                           uint32_t b);

/* fontconfig's comparisons of names, ASCII case: FcStrCmpIgnoreCase(a, b)
** == 0, and FcStrCmpIgnoreBlanksAndCase(a, b[0..bn)) == 0. */
bool cf__fmeta_same_ci(const char *a, const char *b);
bool cf__fmeta_same_name(const char *a, const char *b, size_t bn);

/* Release out's charset (harmless on an empty or released one). */
void cf__fmeta_fini(cf__fmeta_t *m);

#endif
