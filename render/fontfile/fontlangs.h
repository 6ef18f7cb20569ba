/*
** The languages of a face as fontconfig computes them
** (render/fontfile/fontlangs.c): fontconfig's FC_LANG of a font is the
** set of its orthographies (246 languages, each a set of characters)
** whose characters the font's charset all has, except that a font whose
** OS/2 code pages name exactly one of the exclusive Han languages (ja,
** zh-cn, ko, zh-tw) gets another Han language only when that language's
** character set has as many 256-character pages as the named one's.  The
** orthographies are fontconfig's own (langs-table.h, generated from
** fontconfig by tests/unit/test_fontlangs.c --generate and checked by the
** same test).
*/
#ifndef CURVEFIG_RENDER_FONTLANGS_H
#define CURVEFIG_RENDER_FONTLANGS_H

#include <stddef.h>
#include <stdint.h>

#include "fontmeta.h"

/* A set of fontconfig's languages, bit i for language i. */
typedef struct cf__flangset {
    uint32_t bits[8];
} cf__flangset_t;

/* The number of fontconfig's languages, and language i's name (sorted). */
size_t cf__flangs_count(void);
const char *cf__flangs_name(size_t i);

/* fontconfig's FcLangCompare of two language tags: 0 the same, 1 the
** same language of another territory, 2 another language. */
int cf__flangs_compare(const char *a, const char *b);

/* The index of the language named lang (case ignored), or -1
** (fontconfig's FcLangSetIndex found or not). */
int cf__flangs_find(const char *lang);

/* The languages of the face m. */
void cf__flangs_of(const cf__fmeta_t *m, cf__flangset_t *out);

/* How well the set holds lang (fontconfig's FcLangSetHasLang): 0 the
** language itself, 1 the language of another territory ("en" for
** "en-us"), 2 neither. */
int cf__flangs_has(const cf__flangset_t *ls, const char *lang);

#endif
