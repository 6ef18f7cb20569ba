/*
** The faces of the tool's font configuration chosen without fontconfig
** (render/backends/font-match.c): the fonts fontconfig would hold under
** render/tool/fonts.c's configuration, read from the files (render/
** fontfile/fontmeta.h, fontlangs.h), and fontconfig 2.14's choice among
** them for a label's description, in pango's order, with the properties
** fontconfig's prepared pattern gives each.
**
** The configuration (cf__fm_config_t):
**   fonts       the faces of the font directories in fontconfig's order
**               (directories in order, files sorted, faces by index),
**               those whose family is one of the accepted families
**               (<selectfont>), TrueType or CFF;
**   languages   fontconfig's default languages (FC_LANG, LC_ALL,
**               LC_CTYPE, LANG, normalised as FcLangNormalize does;
**               "en" when none), which FcConfigSubstitute adds to a
**               request's language and FcDefaultSubstitute takes the
**               name language from.
** A request (family list, italic, bold, size in 1/1024 pt, language) is
** scored against each font as FcCompare scores: family (the first of the
** request's names the font has, blanks and case ignored), language
** (FcLangSetHasLang of each of the request's languages), slant, weight,
** width, decorative, font version; the best is the match, and the sort is
** the fonts ordered by score (the languages settled as FcFontSetSort
** settles them), each kept only when it adds characters to those before.
** A face is prepared as FcFontRenderPrepare and the configuration's font
** rules prepare it: a roman font under an italic request is sheared
** (matrix [1 0.2; 0 1]) and called oblique, a font of weight medium or
** less under a bold request is emboldened and called bold, an optical
** size of Latin Modern ("LM Roman 7") put first among its families.
**
** Where the tool's configuration is something this does not model (a
** face refused by the reader, a subdirectory, an optical size range),
** the configuration is declined and fontconfig remains the matcher.  Memory comes from the library's
** allocator (cf_malloc); a configuration is used by one thread at a time.
*/
#ifndef CURVEFIG_RENDER_FONT_MATCH_H
#define CURVEFIG_RENDER_FONT_MATCH_H

#include <stdbool.h>
#include <stddef.h>

#include "fontlangs.h"
#include "fontmeta.h"

/* A font of the configuration. */
typedef struct cf__fm_font {
    char *file;
    cf__fmeta_t meta;
    cf__flangset_t langs;
} cf__fm_font_t;

typedef struct cf__fm_config cf__fm_config_t;

/* A face as fontconfig's prepared pattern describes it. */
typedef struct cf__fm_face {
    const cf__fm_font_t *font;   /* file, index, charset, PostScript name */
    const char *family;          /* the first family */
    int slant;
    double weight, width;
    bool embolden;
    bool sheared;                /* matrix [1 0.2; 0 1] (xx xy; yx yy) */
    double size, pixel_size, dpi;
} cf__fm_face_t;

/* One font source: the font files of a directory (render/backends/
** font-cache.h reads them). */
typedef struct cf__fm_source {
    const char *dir;
    bool required;      /* false: skipped when missing */
} cf__fm_source_t;

/* The configuration of fonts already read (render/backends/font-cache.h
** reads them from the font directories) (fonts[0..n-1], in
** fontconfig's order, each the configuration's from then on: their
** files and charsets are freed with it, the array is not). */
int cf__fm_config_of(cf__fm_font_t *fonts, size_t n,
                     const char *const *accept, size_t naccept,
                     cf__fm_config_t **out, char *why, size_t why_cap);

void cf__fm_config_free(cf__fm_config_t *c);

/* Whether one of the face's families is one of accept[0..n-1] (case
** ignored, as <selectfont> compares). */
bool cf__fm_accepts(const cf__fmeta_t *m, const char *const *accept,
                    size_t n);

/* Its fonts (for tests). */
size_t cf__fm_config_count(const cf__fm_config_t *c);
const cf__fm_font_t *cf__fm_config_font(const cf__fm_config_t *c,
                                        size_t i);

/* The request's best font, prepared: 0; 1 when there is no font; -1 out
** of memory. */
int cf__fm_match(const cf__fm_config_t *c, const char *family, bool italic,
                 bool bold, int size, const char *lang, cf__fm_face_t *out);

/* The request's trimmed sort, prepared: 0 with *out (cf_free'd by the
** caller) of *n faces; -1 out of memory. */
int cf__fm_sort(const cf__fm_config_t *c, const char *family, bool italic,
                bool bold, int size, const char *lang, cf__fm_face_t **out,
                size_t *n);

#endif
