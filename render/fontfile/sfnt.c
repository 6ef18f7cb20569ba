/*
** The sfnt container (render/fontfile/sfnt.h): the face of a file or of a
** collection ('ttcf'), its table directory, and the metrics a PDF font
** descriptor needs, read from head, hhea, maxp, OS/2, post, hmtx and
** name.  Every table is checked to lie inside the file, and to be as long
** as the fields read from it, before it is read.
*/
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "sfnt.h"

void
cf__ff_init(cf__ff_t *f, const unsigned char *data, size_t len,
            const char *name, char *why, size_t why_cap)
{
    if (why != NULL && why_cap > 0)
        why[0] = '\0';
    f->data = data;
    f->len = data != NULL ? len : 0;
    f->name = name != NULL ? name : "font";
    f->why = why;
    f->why_cap = why_cap;
}

int
cf__ff_fail(cf__ff_t *f, const char *fmt, ...)
{
    va_list ap;
    int k;
    if (f->why == NULL || f->why_cap == 0)
        return 1;
    k = snprintf(f->why, f->why_cap, "%s: ", f->name);
    if (k < 0 || (size_t)k >= f->why_cap)
        return 1;
    va_start(ap, fmt);
    vsnprintf(f->why + k, f->why_cap - (size_t)k, fmt, ap);
    va_end(ap);
    return 1;
}

static int
known_version(uint32_t v)
{
    return v == 0x00010000u || v == CF__FF_TAG('t', 'r', 'u', 'e') ||
           v == CF__FF_TAG('O', 'T', 'T', 'O');
}

int
cf__ff_face_open(cf__ff_t *f, unsigned index, cf__ff_face_t *face)
{
    size_t at = 0;
    uint32_t tag;
    if (f->len < 12)
        return cf__ff_fail(f, "%zu bytes, too short for a font", f->len);
    tag = cf__ff_u32(f->data);
    if (tag == CF__FF_TAG('t', 't', 'c', 'f')) {
        uint32_t nfonts = cf__ff_u32(f->data + 8);
        if (index >= nfonts)
            return cf__ff_fail(f, "face %u asked of a collection of %u",
                               index, (unsigned)nfonts);
        if (!cf__ff_fits(12, 4 * (size_t)index + 4, f->len))
            return cf__ff_fail(f, "the collection's offset of face %u "
                               "lies past the file's end", index);
        at = cf__ff_u32(f->data + 12 + 4 * (size_t)index);
        if (!cf__ff_fits(at, 12, f->len))
            return cf__ff_fail(f, "face %u at %zu lies past the file's end",
                               index, at);
        tag = cf__ff_u32(f->data + at);
    } else if (index != 0) {
        return cf__ff_fail(f, "face %u asked of a file of one font", index);
    }
    if (!known_version(tag)) {
        if (tag == CF__FF_TAG('w', 'O', 'F', 'F') ||
            tag == CF__FF_TAG('w', 'O', 'F', '2'))
            return cf__ff_fail(f, "a WOFF font, not read (unpack it)");
        return cf__ff_fail(f, "not a TrueType or OpenType font (tag "
                           "0x%08x at %zu)", (unsigned)tag, at);
    }
    face->version = tag;
    face->num_tables = cf__ff_u16(f->data + at + 4);
    if (!cf__ff_fits(at + 12, 16 * (size_t)face->num_tables, f->len))
        return cf__ff_fail(f, "the table directory at %zu (%u tables) runs "
                           "past the file's end", at, face->num_tables);
    face->dir = f->data + at + 12;
    return 0;
}

static void
tag_text(uint32_t tag, char s[5])
{
    int i;
    for (i = 0; i < 4; i++) {
        unsigned c = (tag >> (24 - 8 * i)) & 0xff;
        s[i] = (char)(c >= 0x20 && c < 0x7f ? c : '?');
    }
    s[4] = '\0';
}

int
cf__ff_table_find(cf__ff_t *f, const cf__ff_face_t *face, uint32_t tag,
                  size_t min, cf__ff_table_t *t)
{
    unsigned i;
    char s[5];
    t->data = NULL;
    t->len = 0;
    for (i = 0; i < face->num_tables; i++) {
        const unsigned char *r = face->dir + 16 * (size_t)i;
        size_t off, len;
        if (cf__ff_u32(r) != tag)
            continue;
        off = cf__ff_u32(r + 8);
        len = cf__ff_u32(r + 12);
        tag_text(tag, s);
        if (!cf__ff_fits(off, len, f->len))
            return cf__ff_fail(f, "table '%s' at %zu (%zu bytes) runs past "
                               "the file's end", s, off, len);
        if (len < min)
            return cf__ff_fail(f, "table '%s' at %zu has %zu bytes, fewer "
                               "than %zu", s, off, len, min);
        t->data = f->data + off;
        t->len = len;
        return 0;
    }
    return 0;
}

static int
pdf_name_char(unsigned c)
{
    return c > 0x20 && c < 0x7f && strchr("()<>[]{}/%#", (int)c) == NULL;
}

void
cf__ff_ps_name(char *dst, const unsigned char *src, size_t len, int wide)
{
    size_t i, k = 0, step = wide ? 2 : 1;
    for (i = 0; i + step <= len && k < 63; i += step) {
        unsigned c = wide ? cf__ff_u16(src + i) : src[i];
        if (pdf_name_char(c))
            dst[k++] = (char)c;
    }
    dst[k] = '\0';
    if (k == 0)
        memcpy(dst, "Font", 5);
}

/* name id 6 (Macintosh Roman bytes, else Windows UTF-16BE). */
static int
name_id6(cf__ff_t *f, const cf__ff_face_t *face, char *dst)
{
    cf__ff_table_t t;
    size_t count, strings, i, best = (size_t)-1;
    int wide = 0;
    if (cf__ff_table_find(f, face, CF__FF_TAG('n', 'a', 'm', 'e'), 6, &t))
        return 1;
    cf__ff_ps_name(dst, NULL, 0, 0);
    if (t.data == NULL)
        return 0;
    count = cf__ff_u16(t.data + 2);
    strings = cf__ff_u16(t.data + 4);
    if (!cf__ff_fits(6, 12 * count, t.len))
        return cf__ff_fail(f, "the name table at %zu: %zu records run past "
                           "its end", cf__ff_at(f, t.data), count);
    for (i = 0; i < count; i++) {
        const unsigned char *r = t.data + 6 + 12 * i;
        unsigned platform = cf__ff_u16(r);
        if (cf__ff_u16(r + 6) != 6)
            continue;
        if (platform == 1 && cf__ff_u16(r + 2) == 0) {
            best = i;
            wide = 0;
            break;
        }
        if (platform == 3 && best == (size_t)-1) {
            best = i;
            wide = 1;
        }
    }
    if (best != (size_t)-1) {
        const unsigned char *r = t.data + 6 + 12 * best;
        size_t len = cf__ff_u16(r + 8), off = strings + cf__ff_u16(r + 10);
        if (!cf__ff_fits(off, len, t.len))
            return cf__ff_fail(f, "the name table at %zu: the PostScript "
                               "name runs past its end",
                               cf__ff_at(f, t.data));
        cf__ff_ps_name(dst, t.data + off, len, wide);
    }
    return 0;
}

int
cf__ff_metrics(cf__ff_t *f, const cf__ff_face_t *face, const unsigned *gids,
               size_t n, cf__fontfile_subset_t *out, unsigned *num_glyphs)
{
    cf__ff_table_t head, hhea, maxp, os2, post, hmtx;
    unsigned nhm, weight = 400;
    size_t i;
    if (cf__ff_table_find(f, face, CF__FF_TAG('h', 'e', 'a', 'd'), 54,
                          &head) ||
        cf__ff_table_find(f, face, CF__FF_TAG('h', 'h', 'e', 'a'), 36,
                          &hhea) ||
        cf__ff_table_find(f, face, CF__FF_TAG('m', 'a', 'x', 'p'), 6,
                          &maxp) ||
        cf__ff_table_find(f, face, CF__FF_TAG('O', 'S', '/', '2'), 78,
                          &os2) ||
        cf__ff_table_find(f, face, CF__FF_TAG('p', 'o', 's', 't'), 16,
                          &post) ||
        cf__ff_table_find(f, face, CF__FF_TAG('h', 'm', 't', 'x'), 0,
                          &hmtx))
        return 1;
    if (head.data == NULL || hhea.data == NULL || maxp.data == NULL ||
        hmtx.data == NULL)
        return cf__ff_fail(f, "no '%s' table",
                           head.data == NULL ? "head" :
                           hhea.data == NULL ? "hhea" :
                           maxp.data == NULL ? "maxp" : "hmtx");
    *num_glyphs = cf__ff_u16(maxp.data + 4);
    out->units_per_em = cf__ff_u16(head.data + 18);
    if (out->units_per_em < 16 || out->units_per_em > 16384)
        return cf__ff_fail(f, "head at %zu: %u units per em (16 to 16384)",
                           cf__ff_at(f, head.data), out->units_per_em);
    for (i = 0; i < 4; i++)
        out->bbox[i] = cf__ff_s16(head.data + 36 + 2 * i);
    out->ascent = cf__ff_s16(hhea.data + 4);
    out->descent = cf__ff_s16(hhea.data + 6);
    out->cap_height = out->ascent;
    out->flags = CF__FONTFILE_SYMBOLIC;
    if (cf__ff_u16(head.data + 44) & 2)
        out->flags |= CF__FONTFILE_ITALIC;
    if (os2.data != NULL) {
        unsigned family = cf__ff_u16(os2.data + 30) >> 8;
        weight = cf__ff_u16(os2.data + 4);
        out->ascent = cf__ff_s16(os2.data + 68);
        out->descent = cf__ff_s16(os2.data + 70);
        out->cap_height = out->ascent;
        if (cf__ff_u16(os2.data) >= 2 && os2.len >= 90)
            out->cap_height = cf__ff_s16(os2.data + 88);
        if (cf__ff_u16(os2.data + 62) & 1)
            out->flags |= CF__FONTFILE_ITALIC;
        /* IBM family classes 1 to 7 are serif faces; else the PANOSE
           serif style of a Latin text face (2 to 10; 11 to 13 sans) */
        if ((family >= 1 && family <= 7) ||
            (os2.data[32] == 2 && os2.data[33] >= 2 && os2.data[33] <= 10))
            out->flags |= CF__FONTFILE_SERIF;
        if (os2.data[32] == 2 && os2.data[35] == 9)
            out->flags |= CF__FONTFILE_FIXED_PITCH;
    }
    if (post.data != NULL) {
        int32_t a = (int32_t)cf__ff_u32(post.data + 4);
        out->italic_angle = a / 65536.0;
        if (a != 0)
            out->flags |= CF__FONTFILE_ITALIC;
        if (cf__ff_u32(post.data + 12) != 0)
            out->flags |= CF__FONTFILE_FIXED_PITCH;
    }
    /* the usual estimate from the weight class (400 gives 96) */
    out->stem_v = weight >= 50 && weight <= 1000 ?
                  10 + 220 * (weight - 50) / 900 + 1 : 96;
    nhm = cf__ff_u16(hhea.data + 34);
    if (nhm == 0 || !cf__ff_fits(0, 4 * (size_t)nhm, hmtx.len))
        return cf__ff_fail(f, "hmtx at %zu: %zu bytes hold fewer than the "
                           "%u metrics hhea counts",
                           cf__ff_at(f, hmtx.data), hmtx.len, nhm);
    for (i = 0; i < n; i++) {
        unsigned g = gids[i] < nhm ? gids[i] : nhm - 1;
        out->advances[i] = cf__ff_u16(hmtx.data + 4 * (size_t)g);
    }
    return name_id6(f, face, out->ps_name);
}

int
cf__ff_loca_range(const cf__ff_table_t *loca, int long_loca, unsigned gid,
                  size_t glyf_len, size_t *a, size_t *b)
{
    if (long_loca) {
        *a = cf__ff_u32(loca->data + 4 * (size_t)gid);
        *b = cf__ff_u32(loca->data + 4 * (size_t)gid + 4);
    } else {
        *a = 2 * (size_t)cf__ff_u16(loca->data + 2 * (size_t)gid);
        *b = 2 * (size_t)cf__ff_u16(loca->data + 2 * (size_t)gid + 2);
    }
    return *a > *b || *b > glyf_len;
}
