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
** allocator (cf_malloc); a configuration is used by one thread at a time,
** apart from its fonts' coverage (cf__fm_font_has).
*/
#ifndef CURVEFIG_RENDER_FONT_MATCH_H
#define CURVEFIG_RENDER_FONT_MATCH_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "fontlangs.h"
#include "fontmeta.h"

/* Where the charsets of a configuration's fonts read from the fonts'
** metadata cache are (render/backends/font-cache.h): the cache file
** mapped, kept as long as the configuration. */
typedef struct cf__fm_mapped {
    void *map;
    size_t len;
    char *cache;       /* the cache file (the C library's heap), removed
                          when a charset in it is found damaged (NULL:
                          none) */
} cf__fm_mapped_t;

/* A font of the configuration.  Its charset is meta.ranges, or, for a
** font read from the cache, a view of the cache's bytes (meta.nranges
** pairs of little-endian u32, meta.ranges NULL) checked (ascending,
** apart, in Unicode) the first time the font's coverage is asked for
** (cf__fm_font_has, the sort's trimming, cf__fm_font_range); a view
** found damaged is replaced by the charset read again from the font's
** file (none when that fails), and the cache file is removed so that the
** next run writes it anew; so is a view of a font whose file changed in
** place (unverified, below).  The languages are the cache's: the
** matching needs no charset. */
typedef struct cf__fm_font {
    char *file;
    cf__fmeta_t meta;
    cf__flangset_t langs;
    const unsigned char *view;   /* NULL: meta.ranges */
    cf__fm_mapped_t *mapped;     /* the view's cache */
    int state;                   /* the view: 0 not checked, 1 good, 2
                                    damaged (reread) */
    uint32_t *reread;            /* the file's charset (the C library's
                                    heap), nreread pairs */
    size_t nreread;
    /* unverified: a font taken from the cache without a look at its
    ** file (its directory's time the cache's: font-cache.h), whose
    ** file's size and time (the cache's, below) are compared with the
    ** file's at its first use, with the view's check: a file changed in
    ** place is then a damaged view */
    bool unverified;
    uint64_t size;
    int64_t sec;
    uint32_t nsec;
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

/* The configuration keeps m (cf_malloc'd; the mapping unmapped and m
** freed with it). */
void cf__fm_config_keep(cf__fm_config_t *c, cf__fm_mapped_t *m);

/* Release m (unmapped, freed; harmless on NULL). */
void cf__fm_mapped_free(cf__fm_mapped_t *m);

/* Whether the font's charset holds c (checked at its first use: see
** cf__fm_font_t).  Safe from several threads at once. */
bool cf__fm_font_has(const cf__fm_font_t *f, uint32_t c);

/* The font's first use checks done (its view, and its file's size and
** time when unverified: see cf__fm_font_t), once: for a font about to
** be drawn, whose coverage may not have been asked for.  Safe from
** several threads at once. */
void cf__fm_font_verify(const cf__fm_font_t *f);

/* The number of ranges of the font's charset, and its range i in *a,
** *b (false past the last). */
size_t cf__fm_font_nranges(const cf__fm_font_t *f);
bool cf__fm_font_range(const cf__fm_font_t *f, size_t i, uint32_t *a,
                       uint32_t *b);

/* Whether p[0..8n) is a charset as the cache holds it: n pairs of
** little-endian u32 first and last, ascending, apart (maximal ranges),
** at most U+10FFFF. */
bool cf__fm_ranges_valid(const unsigned char *p, size_t n);

/* The little-endian u32 at p. */
static inline uint32_t
cf__fm_le32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16
           | (uint32_t)p[3] << 24;
}

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
