/*
** The Unicode properties the native fonts' itemisation asks of a
** character (render/backends/font-itemize.c), for the characters of the
** shaper's fast path, without HarfBuzz: general category and script as
** HarfBuzz 6.0's hb_unicode_general_category and hb_unicode_script give
** them, from a table of runs generated from HarfBuzz (uprops-table.h, by
** tests/unit/test_uprops.c --generate, which checks every code point of
** it against the HarfBuzz it is built with).  It covers Latin, Greek and
** Cyrillic (U+0000-U+052F, U+1E00-U+1FFF), punctuation, symbols and
** mathematical operators (U+2000-U+2BFF), CJK punctuation, kana and
** Bopomofo (U+3000-U+312F, U+31A0-U+31FF), CJK ideographs (U+3400-U+4DBF,
** U+4E00-U+9FFF), full- and halfwidth forms (U+FF00-U+FFEF) and the
** mathematical alphanumerics (U+1D400-U+1D7FF); outside, the caller asks
** HarfBuzz.
*/
#ifndef CURVEFIG_RENDER_UPROPS_H
#define CURVEFIG_RENDER_UPROPS_H

#include <stdbool.h>
#include <stdint.h>

/* HarfBuzz's general category numbers (hb_unicode_general_category_t). */
#define CF__GC_CONTROL 0
#define CF__GC_SPACING_MARK 10
#define CF__GC_ENCLOSING_MARK 11
#define CF__GC_NON_SPACING_MARK 12
#define CF__GC_SPACE_SEPARATOR 29

/* c's general category (*gc, HarfBuzz's number) and script (*script, its
** ISO 15924 tag as hb_script_t is); false when c is outside the table. */
bool cf__uprops(uint32_t c, unsigned *gc, uint32_t *script);

/* Whether the shaper may be given c (render/fontfile/shape.h): in the
** table, not a mark (M*), not U+2044 FRACTION SLASH. */
bool cf__uprops_simple(uint32_t c);

#endif
