/*
** The renderer's own shaper (render/fontfile/): for the simple runs of
** labels it gives exactly what HarfBuzz 6.0's hb_shape gives the native
** fonts (render/backends/font-native.c: left to right, cluster level
** monotone characters, language "c", the default shaper's features), from
** the font's own tables, without HarfBuzz; for anything it does not do it
** answers "not handled" (1) and the caller shapes with HarfBuzz as before.
**
** A face (cf__otface_open) is a font file mapped, one face of it, its
** tables found and checked once: cmap (formats 4 and 12 of the subtable
** HarfBuzz would choose), hmtx/hhea, OS/2, GDEF glyph classes, GSUB and
** GPOS.  A face HarfBuzz would shape otherwise is not usable: variable
** (fvar), AAT tables (morx, mort, kerx, trak), no GPOS, a TrueType 'kern'
** table beside a GPOS (HarfBuzz would apply it for scripts without a GPOS
** kern feature), a GSUB/GPOS with feature variations or not version 1.
**
** A run (cf__ot_shape) is handled when:
**   - its text is valid UTF-8, every character is mapped by the cmap, and
**     no glyph the run ever holds is a mark (GDEF class 3), so that
**     normalisation, mark zeroing, mark attachment and fallback
**     positioning do nothing; the caller keeps to characters without
**     general category M*, default ignorables, spaces other than U+0020
**     and U+2044 (fraction masks) (cf__ot_char_simple);
**   - the chosen LangSys has no required feature;
**   - every lookup that could apply is one done here: GSUB single (1),
**     multiple (2, one glyph or more), ligature (4), extension (7); GPOS
**     single (1), pair (2, both formats; device tables ignored as
**     HarfBuzz does at ppem 0), extension (9).  Other lookup types
**     (alternate, contextual, chaining, reverse, cursive, mark) are
**     checked: a contextual or chaining rule that matches, or any other
**     subtable whose coverage holds the glyph at hand, makes the run not
**     handled;
**   - no lookup would skip a glyph (lookup flags ignoring bases or
**     ligatures while the run has such glyphs in the way);
**   - a synthetic slant meets no y offset.
** Numbers are HarfBuzz's: advances em_scale_x(hmtx) with
** x_mult = (x_scale << 16) / upem, values of GPOS the same, extents
** roundf(value * (y_scale / upem)).
**
** Every table offset is checked against the table: a damaged table makes
** the face unusable or the run not handled, never a read out of bounds.
*/
#ifndef CURVEFIG_RENDER_SHAPE_H
#define CURVEFIG_RENDER_SHAPE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef struct cf__otface cf__otface_t;

/* The OpenType script tags of the scripts handled (HarfBuzz's old tags
** of Latin, Greek, Cyrillic, Han, Hiragana and Katakana, Bopomofo and
** Common). */
#define CF__OT_TAG(a, b, c, d) \
    ((uint32_t)(a) << 24 | (uint32_t)(b) << 16 | (uint32_t)(c) << 8 | (d))

/* The OpenType tag HarfBuzz uses for a script given by its ISO 15924 tag
** (HarfBuzz's hb_script_t value: 'Latn' ...), for the scripts handled;
** 0 for the others (Hangul, which HarfBuzz shapes with its own shaper,
** Inherited, and every script not verified). */
uint32_t cf__ot_script_tag(uint32_t iso15924);

/* Face `index` of the font file at path: 0 and *out (usable or not, see
** cf__otface_usable), -1 out of memory; a file that cannot be read or
** is damaged gives a face that is not usable. */
int cf__otface_open(const char *path, unsigned index, cf__otface_t **out);
/* The same over bytes in memory (not copied: they outlive the face). */
int cf__otface_open_mem(const unsigned char *data, size_t len,
                        unsigned index, cf__otface_t **out);
void cf__otface_close(cf__otface_t *face);

/* The same in storage of the caller's (cf__otface_size() bytes, aligned
** as malloc aligns): a face that lives as long as the process, outside
** the library's allocator; it never fails (an unreadable file gives a
** face that is not usable); cf__otface_release unmaps the file. */
size_t cf__otface_size(void);
void cf__otface_open_at(cf__otface_t *face, const char *path,
                        unsigned index);
void cf__otface_release(cf__otface_t *face);

bool cf__otface_usable(const cf__otface_t *face);

/* Whether the face has a BASE table (a baseline other than HarfBuzz's
** synthesised roman one, 0). */
bool cf__otface_has_base(const cf__otface_t *face);

/* The glyph of character c (0: none, as cmap's glyph 0). */
unsigned cf__otface_glyph(const cf__otface_t *face, uint32_t c);

/* hb_font_get_h_extents of the face at y_scale: ascender, descender,
** line gap; false when HarfBuzz would have none (then not usable). */
bool cf__otface_h_extents(const cf__otface_t *face, int y_scale, int *asc,
                          int *desc, int *gap);

/* One glyph of a shaped run, as hb_glyph_info_t and hb_glyph_position_t
** give it. */
typedef struct cf__otglyph {
    unsigned id;
    unsigned cluster;     /* byte offset in the whole text */
    int x_advance, x_offset, y_offset;
} cf__otglyph_t;

typedef struct cf__otrun {
    cf__otglyph_t *g;
    unsigned char *props;     /* each glyph's class, as HarfBuzz's */
    size_t n, cap;
    cf__otglyph_t *tg;        /* scratch: a substitution's output */
    unsigned char *tprops;
    size_t tn, tcap;
} cf__otrun_t;

void cf__otrun_fini(cf__otrun_t *r);

/* The scaling of a font as the native fonts set it (hb_font_set_scale,
** hb_font_set_synthetic_slant). */
typedef struct cf__otscale {
    int x_scale, y_scale;
    float slant;
} cf__otscale_t;

/* Shape text[off, off + len) (clusters are offsets in text) in script
** `script` (an OpenType script tag, CF__OT_TAG) into r: 0 shaped, 1 not
** handled (r's contents undefined), -1 out of memory. */
int cf__ot_shape(const cf__otface_t *face, uint32_t script,
                 const cf__otscale_t *scale, const char *text, size_t off,
                 size_t len, cf__otrun_t *r);

#endif
