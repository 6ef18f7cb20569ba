/*
** A face's metadata as fontconfig reads it (render/fontfile/fontmeta.h):
** the name table's families and styles, OS/2's classes and code pages,
** head's revision, the Unicode cmap as a list of ranges.  Every table is
** found and bounded by sfnt.c and every field read is checked to lie in
** its table.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "curvefig/core.h"
#include "fontmeta.h"
#include "grow.h"
#include "sfnt.h"

#define NSTYLES 16

/* One name record: fontconfig reads them sorted by platform, name id,
** encoding, English first, language, position. */
typedef struct rec {
    unsigned platform, nameid, encoding, language, idx;
} rec_t;

static bool
is_english(unsigned platform, unsigned language)
{
    return (platform == 1 && language == 0)
           || (platform == 3 && language == 0x409);
}

static int
by_record(const void *pa, const void *pb)
{
    const rec_t *a = pa, *b = pb;
    if (a->platform != b->platform)
        return (int)a->platform - (int)b->platform;
    if (a->nameid != b->nameid)
        return (int)a->nameid - (int)b->nameid;
    if (a->encoding != b->encoding)
        return (int)a->encoding - (int)b->encoding;
    if (a->language != b->language)
        return is_english(a->platform, a->language)   ? -1
               : is_english(b->platform, b->language) ? 1
               : (int)a->language - (int)b->language;
    return (int)a->idx - (int)b->idx;
}

/* The language fontconfig gives a name (its table, for the ids this
** knows); NULL: one this does not know (the face is refused). */
static const char *
name_language(unsigned platform, unsigned language)
{
    static const struct {
        unsigned platform, language;
        const char *lang;
    } langs[] = {
        { 1, 0, "en" },       { 3, 0x409, "en" },   { 3, 0x411, "ja" },
        { 3, 0x412, "ko" },   { 3, 0x804, "zh-cn" }, { 3, 0x404, "zh-tw" },
        { 3, 0xc04, "zh-hk" },
    };
    size_t i;
    for (i = 0; i < sizeof langs / sizeof langs[0]; i++)
        if (langs[i].platform == platform && langs[i].language == language)
            return langs[i].lang;
    return NULL;
}

/* UTF-8 of code point c into s (room for 4 bytes); its length. */
static size_t
put_utf8(char *s, unsigned c)
{
    if (c < 0x80) {
        s[0] = (char)c;
        return 1;
    }
    if (c < 0x800) {
        s[0] = (char)(0xc0 | c >> 6);
        s[1] = (char)(0x80 | (c & 0x3f));
        return 2;
    }
    if (c < 0x10000) {
        s[0] = (char)(0xe0 | c >> 12);
        s[1] = (char)(0x80 | ((c >> 6) & 0x3f));
        s[2] = (char)(0x80 | (c & 0x3f));
        return 3;
    }
    s[0] = (char)(0xf0 | c >> 18);
    s[1] = (char)(0x80 | ((c >> 12) & 0x3f));
    s[2] = (char)(0x80 | ((c >> 6) & 0x3f));
    s[3] = (char)(0x80 | (c & 0x3f));
    return 4;
}

/* The name's text in UTF-8, trimmed of spaces, into dst (cap bytes):
** 0; 2: an encoding fontconfig skips (the name is not read); 1: one it
** reads and this does not, or too long (why written). */
static int
name_text(cf__ff_t *f, const rec_t *r, const unsigned char *s, size_t len,
          char *dst, size_t cap)
{
    size_t i, k = 0;
    bool wide;
    if (r->platform == 0 || (r->platform == 3 && (r->encoding == 0
        || r->encoding == 1 || r->encoding == 10))
        || (r->platform == 2 && r->encoding == 1))
        wide = true;
    else if ((r->platform == 1 && r->encoding == 0)
             || (r->platform == 2 && r->encoding == 0))
        wide = false;
    else if (r->platform == 1 || r->platform == 3 || r->platform == 2)
        return cf__ff_fail(f, "a name in encoding %u of platform %u",
                           r->encoding, r->platform);
    else
        return 2;
    for (i = 0; i < len;) {
        unsigned c;
        if (wide) {
            if (i + 2 > len)
                break;
            c = cf__ff_u16(s + i);
            i += 2;
            if (c >= 0xd800 && c < 0xdc00 && i + 2 <= len) {
                unsigned lo = cf__ff_u16(s + i);
                if (lo >= 0xdc00 && lo < 0xe000) {
                    c = 0x10000 + ((c - 0xd800) << 10) + (lo - 0xdc00);
                    i += 2;
                }
            }
        } else {
            c = s[i++];
            if (c >= 0x80)
                return cf__ff_fail(f, "a Macintosh name not in ASCII");
        }
        if (c == 0 || (c >= 0xd800 && c < 0xe000))
            return cf__ff_fail(f, "a name holds U+%04X", c);
        if (k + 5 > cap)
            return cf__ff_fail(f, "a name longer than %zu bytes", cap - 5);
        k += put_utf8(dst + k, c);
    }
    dst[k] = '\0';
    for (i = 0; dst[i] == ' '; i++)
        ;
    memmove(dst, dst + i, k - i + 1);
    k -= i;
    while (k > 0 && dst[k - 1] == ' ')
        dst[--k] = '\0';
    return 0;
}

static char
lower(char c)
{
    return c >= 'A' && c <= 'Z' ? (char)(c - 'A' + 'a') : c;
}

bool
cf__fmeta_same_name(const char *a, const char *b, size_t bn)
{
    const char *be = b + bn;
    while (true) {
        char x, y;
        while (*a == ' ')
            a++;
        while (b < be && *b == ' ')
            b++;
        x = lower(*a);
        y = b < be ? lower(*b) : '\0';
        if (x != y)
            return false;
        if (x == '\0')
            return true;
        a++;
        b++;
    }
}

bool
cf__fmeta_same_ci(const char *a, const char *b)
{
    for (; lower(*a) == lower(*b); a++, b++)
        if (*a == '\0')
            return true;
    return false;
}

/* s, lowercase, its blanks removed, into d (cap bytes). */
static void
squeeze(const char *s, char *d, size_t cap)
{
    size_t k = 0;
    for (; *s != '\0' && k + 1 < cap; s++) {
        char c = *s;
        if (c == ' ')
            continue;
        d[k++] = lower(c);
    }
    d[k] = '\0';
}

static bool
is_punct(unsigned char c)
{
    return c < '0' || (c > '9' && c < 'A') || (c > 'Z' && c < 'a')
           || (c > 'z' && c <= 0x7f);
}

/* fontconfig's FcStrContainsWord: word (lowercase) in s as a word. */
static bool
has_word(const char *s, const char *word)
{
    size_t n = strlen(s), m = strlen(word), i, j;
    bool start = true;
    for (i = 0; i + m <= n; i++) {
        if (start) {
            for (j = 0; j < m; j++)
                if (lower(s[i + j]) != word[j])
                    break;
            if (j == m && (i + m == n || is_punct((unsigned char)s[i + m])))
                return true;
        }
        start = is_punct((unsigned char)s[i]);
    }
    return false;
}

typedef struct word {
    const char *name;
    double value;
} word_t;

/* fontconfig's FcStringContainsConst: the first word's value, or -1. */
static double
contains(const char *style, const word_t *w, size_t n)
{
    char sq[CF__FMETA_NAME_LEN];
    size_t i;
    squeeze(style, sq, sizeof sq);
    for (i = 0; i < n; i++) {
        if (w[i].name[0] == '<') {
            if (has_word(style, w[i].name + 1))
                return w[i].value;
        } else if (strstr(sq, w[i].name) != NULL) {
            return w[i].value;
        }
    }
    return -1;
}

static const word_t weights[] = {
    { "thin", 0 },        { "extralight", 40 }, { "ultralight", 40 },
    { "demilight", 55 },  { "semilight", 55 },  { "light", 50 },
    { "book", 75 },       { "regular", 80 },    { "normal", 80 },
    { "medium", 100 },    { "demibold", 180 },  { "demi", 180 },
    { "semibold", 180 },  { "extrabold", 205 }, { "superbold", 205 },
    { "ultrabold", 205 }, { "bold", 200 },      { "ultrablack", 215 },
    { "superblack", 215 }, { "extrablack", 215 }, { "<ultra", 205 },
    { "black", 210 },     { "heavy", 210 },
};
static const word_t widths[] = {
    { "ultracondensed", 50 }, { "extracondensed", 63 },
    { "semicondensed", 87 },  { "condensed", 75 },   { "normal", 100 },
    { "semiexpanded", 113 },  { "extraexpanded", 150 },
    { "ultraexpanded", 200 }, { "expanded", 125 },   { "extended", 125 },
};
static const word_t slants[] = {
    { "italic", CF__FMETA_SLANT_ITALIC },
    { "kursiv", CF__FMETA_SLANT_ITALIC },
    { "oblique", CF__FMETA_SLANT_OBLIQUE },
};
static const word_t decoratives[] = {
    { "shadow", 1 }, { "caps", 1 }, { "antiqua", 1 }, { "romansc", 1 },
    { "embosed", 1 }, { "dunhill", 1 },
};
#define NWORDS(a) (sizeof(a) / sizeof(a)[0])

/* fontconfig's FcWeightFromOpenTypeDouble. */
static double
weight_from_ot(double w)
{
    static const int ot[] = { 0, 100, 200, 300, 350, 380, 400,
                              500, 600, 700, 800, 900, 1000 };
    static const int fc[] = { 0, 0, 40, 50, 55, 75, 80,
                              100, 180, 200, 205, 210, 215 };
    int i;
    if (w < 0)
        return -1;
    if (w > 1000)
        w = 1000;
    for (i = 1; w > ot[i]; i++)
        ;
    if (w == ot[i])
        return fc[i];
    return fc[i - 1] + (w - ot[i - 1]) * (fc[i] - fc[i - 1])
                           / (ot[i] - ot[i - 1]);
}

typedef struct names {
    char style[NSTYLES][CF__FMETA_NAME_LEN];
    unsigned nstyle;
} names_t;

/* Add a name to a list of n (cap entries) unless there (blanks and case
** ignored); 1 when the list is full. */
static int
add_name(cf__ff_t *f, char (*list)[CF__FMETA_NAME_LEN], char (*langs)[8],
         unsigned *n, unsigned cap, const char *text, const char *lang)
{
    unsigned i;
    for (i = 0; i < *n; i++)
        if (cf__fmeta_same_name(list[i], text, strlen(text)))
            return 0;
    if (*n == cap)
        return cf__ff_fail(f, "more than %u names of a kind", cap);
    strcpy(list[*n], text);
    if (langs != NULL)
        strcpy(langs[*n], lang);
    (*n)++;
    return 0;
}

static int
read_names(cf__ff_t *f, const cf__ff_face_t *face, cf__fmeta_t *m,
           names_t *nm)
{
    static const unsigned platforms[] = { 3, 0, 1, 2 };
    static const unsigned ids[] = { 21, 16, 1, 22, 17, 2 };
    cf__ff_table_t t;
    size_t count, strings, i, p, k;
    rec_t *recs;
    int r = 0;
    if (cf__ff_table_find(f, face, CF__FF_TAG('n', 'a', 'm', 'e'), 6, &t))
        return 1;
    if (t.data == NULL)
        return cf__ff_fail(f, "no name table");
    count = cf__ff_u16(t.data + 2);
    strings = cf__ff_u16(t.data + 4);
    if (!cf__ff_fits(6, 12 * count, t.len))
        return cf__ff_fail(f, "the name table's %zu records run past its "
                           "end", count);
    recs = cf_alloc_array(count + 1, sizeof *recs);
    if (recs == NULL)
        return -1;
    for (i = 0; i < count; i++) {
        const unsigned char *d = t.data + 6 + 12 * i;
        recs[i].platform = cf__ff_u16(d);
        recs[i].encoding = cf__ff_u16(d + 2);
        recs[i].language = cf__ff_u16(d + 4);
        recs[i].nameid = cf__ff_u16(d + 6);
        recs[i].idx = (unsigned)i;
    }
    qsort(recs, count, sizeof *recs, by_record);
    for (p = 0; p < NWORDS(platforms) && r == 0; p++)
        for (k = 0; k < NWORDS(ids) && r == 0; k++)
            for (i = 0; i < count && r == 0; i++) {
                const rec_t *c = &recs[i];
                const unsigned char *d = t.data + 6 + 12 * c->idx;
                size_t len = cf__ff_u16(d + 8);
                size_t off = strings + cf__ff_u16(d + 10);
                char text[CF__FMETA_NAME_LEN];
                const char *lang;
                int got;
                if (c->platform != platforms[p] || c->nameid != ids[k])
                    continue;
                if (!cf__ff_fits(off, len, t.len)) {
                    r = cf__ff_fail(f, "name %zu runs past the table's end",
                                    i);
                    break;
                }
                got = name_text(f, c, t.data + off, len, text, sizeof text);
                if (got == 2)
                    continue;
                if (got != 0) {
                    r = got;
                    break;
                }
                lang = name_language(c->platform, c->language);
                if (lang == NULL) {
                    r = cf__ff_fail(f, "a name in language 0x%x of platform "
                                    "%u", c->language, c->platform);
                    break;
                }
                if (k < 3)
                    r = add_name(f, m->family, m->familylang, &m->nfamily,
                                 CF__FMETA_NAMES, text, lang);
                else
                    r = add_name(f, nm->style, NULL, &nm->nstyle, NSTYLES,
                                 text, lang);
            }
    cf_free(recs);
    if (r == 0 && m->nfamily == 0)
        r = cf__ff_fail(f, "no family name");
    return r;
}

/* name id 6 as FreeType gives it (Windows English UTF-16, else Macintosh
** Roman), only its printable ASCII. */
static int
read_psname(cf__ff_t *f, const cf__ff_face_t *face, char *dst)
{
    cf__ff_table_t t;
    size_t count, strings, i, win = (size_t)-1, mac = (size_t)-1, best;
    size_t len, off, k = 0;
    bool wide;
    dst[0] = '\0';
    if (cf__ff_table_find(f, face, CF__FF_TAG('n', 'a', 'm', 'e'), 6, &t)
        || t.data == NULL)
        return 1;
    count = cf__ff_u16(t.data + 2);
    strings = cf__ff_u16(t.data + 4);
    for (i = 0; i < count; i++) {
        const unsigned char *d = t.data + 6 + 12 * i;
        if (cf__ff_u16(d + 6) != 6 || cf__ff_u16(d + 8) == 0)
            continue;
        if (cf__ff_u16(d) == 3 && cf__ff_u16(d + 2) == 1
            && cf__ff_u16(d + 4) == 0x409 && win == (size_t)-1)
            win = i;
        if (cf__ff_u16(d) == 1 && cf__ff_u16(d + 2) == 0
            && cf__ff_u16(d + 4) == 0 && mac == (size_t)-1)
            mac = i;
    }
    if (win == (size_t)-1 && mac == (size_t)-1)
        return cf__ff_fail(f, "no PostScript name");
    best = win != (size_t)-1 ? win : mac;
    wide = best == win;
    len = cf__ff_u16(t.data + 6 + 12 * best + 8);
    off = strings + cf__ff_u16(t.data + 6 + 12 * best + 10);
    if (!cf__ff_fits(off, len, t.len))
        return cf__ff_fail(f, "the PostScript name runs past its table");
    for (i = 0; i + (wide ? 2 : 1) <= len && k + 1 < CF__FMETA_NAME_LEN;
         i += wide ? 2 : 1) {
        unsigned c = wide ? cf__ff_u16(t.data + off + i) : t.data[off + i];
        if (c < 32 || c > 126)
            return cf__ff_fail(f, "a PostScript name outside printable "
                               "ASCII");
        dst[k++] = (char)c;
    }
    dst[k] = '\0';
    return 0;
}

/* ---- the charset ------------------------------------------------------ */

typedef struct chars {
    uint32_t *c;
    size_t n, cap;
} chars_t;

static int
add_char(chars_t *s, uint32_t c)
{
    uint32_t *t = cf__grow_array(s->c, &s->cap, s->n + 1, sizeof *t, 1024);
    if (t == NULL)
        return -1;
    s->c = t;
    s->c[s->n++] = c;
    return 0;
}

/* Whether glyph gid of a TrueType face has contours (loca and glyf). */
static int
glyf_has_contours(cf__ff_t *f, const cf__ff_face_t *face, unsigned gid,
                  bool *yes)
{
    cf__ff_table_t head, loca, glyf;
    size_t a, b;
    *yes = false;
    if (cf__ff_table_find(f, face, CF__FF_TAG('h', 'e', 'a', 'd'), 54, &head)
        || cf__ff_table_find(f, face, CF__FF_TAG('l', 'o', 'c', 'a'), 0,
                             &loca)
        || cf__ff_table_find(f, face, CF__FF_TAG('g', 'l', 'y', 'f'), 0,
                             &glyf))
        return 1;
    if (head.data == NULL || loca.data == NULL || glyf.data == NULL)
        return cf__ff_fail(f, "a TrueType face without head, loca or glyf");
    if (cf__ff_u16(head.data + 50) == 0) {
        if (!cf__ff_fits(2 * (size_t)gid, 4, loca.len))
            return cf__ff_fail(f, "loca too short");
        a = 2 * (size_t)cf__ff_u16(loca.data + 2 * gid);
        b = 2 * (size_t)cf__ff_u16(loca.data + 2 * gid + 2);
    } else {
        if (!cf__ff_fits(4 * (size_t)gid, 8, loca.len))
            return cf__ff_fail(f, "loca too short");
        a = cf__ff_u32(loca.data + 4 * gid);
        b = cf__ff_u32(loca.data + 4 * gid + 4);
    }
    if (b <= a)
        return 0;
    if (!cf__ff_fits(a, 2, glyf.len))
        return cf__ff_fail(f, "glyph %u past glyf's end", gid);
    *yes = cf__ff_s16(glyf.data + a) != 0;
    return 0;
}

/* A cmap read: the face, where its characters go. */
typedef struct scan {
    cf__ff_t *f;
    const cf__ff_face_t *face;
    bool cff;
    unsigned num_glyphs;
    chars_t chars;
} scan_t;

static int
add_mapped(scan_t *sc, uint32_t c, unsigned gid)
{
    cf__ff_t *f = sc->f;
    const cf__ff_face_t *face = sc->face;
    bool cff = sc->cff;
    unsigned num_glyphs = sc->num_glyphs;
    chars_t *s = &sc->chars;
    bool yes;
    if (gid == 0 || gid >= num_glyphs)
        return 0;
    if (c <= 0x1f) {
        int r;
        if (cff)
            return cf__ff_fail(f, "a CFF font maps control character "
                               "U+%04X", (unsigned)c);
        if ((r = glyf_has_contours(f, face, gid, &yes)) != 0)
            return r;
        if (!yes)
            return 0;
    }
    return add_char(s, c);
}

static int
cmap4(scan_t *sc, const unsigned char *t, size_t len)
{
    cf__ff_t *f = sc->f;
    size_t segs, i;
    int r;
    if (len < 14)
        return cf__ff_fail(f, "cmap format 4 too short");
    segs = cf__ff_u16(t + 6) / 2;
    if (!cf__ff_fits(14, 8 * segs + 2, len))
        return cf__ff_fail(f, "cmap format 4: %zu segments past its end",
                           segs);
    for (i = 0; i < segs; i++) {
        unsigned end = cf__ff_u16(t + 14 + 2 * i);
        unsigned start = cf__ff_u16(t + 16 + 2 * segs + 2 * i);
        unsigned delta = cf__ff_u16(t + 16 + 4 * segs + 2 * i);
        size_t ro_at = 16 + 6 * segs + 2 * i;
        unsigned ro = cf__ff_u16(t + ro_at), c;
        if (start > end)
            continue;
        for (c = start; c <= end; c++) {
            unsigned gid;
            if (ro == 0) {
                gid = (c + delta) & 0xffff;
            } else {
                size_t at = ro_at + ro + 2 * (size_t)(c - start);
                if (!cf__ff_fits(at, 2, len))
                    return cf__ff_fail(f, "cmap format 4: a glyph id past "
                                       "its end");
                gid = cf__ff_u16(t + at);
                if (gid != 0)
                    gid = (gid + delta) & 0xffff;
            }
            if ((r = add_mapped(sc, c, gid)) != 0)
                return r;
        }
    }
    return 0;
}

static int
cmap12(scan_t *sc, const unsigned char *t, size_t len)
{
    size_t n, i;
    int r;
    cf__ff_t *f = sc->f;
    if (len < 16)
        return cf__ff_fail(f, "cmap format 12 too short");
    n = cf__ff_u32(t + 12);
    if (!cf__ff_fits(16, 12 * n, len) || n > len / 12)
        return cf__ff_fail(f, "cmap format 12: %zu groups past its end", n);
    for (i = 0; i < n; i++) {
        uint32_t a = cf__ff_u32(t + 16 + 12 * i);
        uint32_t b = cf__ff_u32(t + 20 + 12 * i);
        uint32_t g = cf__ff_u32(t + 24 + 12 * i), c;
        if (a > b || b > 0x10ffff || g >= sc->num_glyphs)
            continue;
        for (c = a; c <= b; c++) {
            uint64_t gid = (uint64_t)g + (c - a);
            if (gid >= sc->num_glyphs)
                break;
            if ((r = add_mapped(sc, c, (unsigned)gid)) != 0)
                return r;
        }
    }
    return 0;
}

static int
by_char(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

static int
read_charset(cf__ff_t *f, const cf__ff_face_t *face, cf__fmeta_t *m)
{
    cf__ff_table_t cmap, maxp;
    size_t n, i, best = (size_t)-1, any = (size_t)-1, at, sub;
    unsigned num_glyphs, fmt;
    chars_t s = { NULL, 0, 0 };
    scan_t sc;
    int r;
    if (cf__ff_table_find(f, face, CF__FF_TAG('c', 'm', 'a', 'p'), 4, &cmap)
        || cf__ff_table_find(f, face, CF__FF_TAG('m', 'a', 'x', 'p'), 6,
                             &maxp))
        return 1;
    if (cmap.data == NULL || maxp.data == NULL)
        return cf__ff_fail(f, "no cmap or maxp");
    num_glyphs = cf__ff_u16(maxp.data + 4);
    sc.f = f;
    sc.face = face;
    sc.cff = m->cff;
    sc.num_glyphs = num_glyphs;
    sc.chars = s;
    n = cf__ff_u16(cmap.data + 2);
    if (!cf__ff_fits(4, 8 * n, cmap.len))
        return cf__ff_fail(f, "cmap: %zu encodings past its end", n);
    /* FreeType's Unicode charmap: the last UCS-4 one, else the last
    ** Unicode one (format 14, variation sequences, is none) */
    for (i = 0; i < n; i++) {
        unsigned p = cf__ff_u16(cmap.data + 4 + 8 * i);
        unsigned e = cf__ff_u16(cmap.data + 6 + 8 * i);
        if (p == 3 && e == 0)
            return cf__ff_fail(f, "a symbol cmap");
        if ((p == 3 && e == 10) || (p == 0 && (e == 4 || e == 6)))
            best = i;
        if ((p == 0 && e != 5) || (p == 3 && (e == 1 || e == 10)))
            any = i;
    }
    if (best == (size_t)-1)
        best = any;
    if (best == (size_t)-1)
        return cf__ff_fail(f, "no Unicode cmap");
    sub = cf__ff_u32(cmap.data + 8 + 8 * best);
    if (!cf__ff_fits(sub, 4, cmap.len))
        return cf__ff_fail(f, "a cmap subtable past its end");
    fmt = cf__ff_u16(cmap.data + sub);
    if (fmt == 4) {
        at = cf__ff_u16(cmap.data + sub + 2);
        if (!cf__ff_fits(sub, at, cmap.len))
            return cf__ff_fail(f, "cmap format 4 past its end");
        r = cmap4(&sc, cmap.data + sub, at);
    } else if (fmt == 12) {
        if (!cf__ff_fits(sub, 8, cmap.len))
            return cf__ff_fail(f, "cmap format 12 past its end");
        at = cf__ff_u32(cmap.data + sub + 4);
        if (!cf__ff_fits(sub, at, cmap.len))
            return cf__ff_fail(f, "cmap format 12 past its end");
        r = cmap12(&sc, cmap.data + sub, at);
    } else {
        return cf__ff_fail(f, "cmap format %u", fmt);
    }
    s = sc.chars;
    if (r != 0) {
        cf_free(s.c);
        return r;
    }
    /* the subtables give the characters in order, mostly: sorted only
    ** when they did not (a CJK collection's face has 65,000) */
    for (i = 1; i < s.n && s.c[i - 1] < s.c[i]; i++)
        ;
    if (i < s.n)
        qsort(s.c, s.n, sizeof *s.c, by_char);
    for (i = 0, n = 0; i < s.n; i++)
        if (i == 0 || s.c[i] > s.c[i - 1] + 1)
            n++;
    if (n == 0) {
        cf_free(s.c);
        return cf__ff_fail(f, "an empty cmap");
    }
    m->ranges = cf_alloc_array(2 * n, sizeof *m->ranges);
    if (m->ranges == NULL) {
        cf_free(s.c);
        return -1;
    }
    m->nranges = 0;
    for (i = 0; i < s.n; i++) {
        if (i > 0 && s.c[i] <= s.c[i - 1] + 1) {
            m->ranges[2 * m->nranges - 1] = s.c[i];
            continue;
        }
        m->ranges[2 * m->nranges] = m->ranges[2 * m->nranges + 1] = s.c[i];
        m->nranges++;
    }
    cf_free(s.c);
    return 0;
}

/* ---- the face ---------------------------------------------------------- */

static int
read_face(cf__ff_t *f, unsigned index, cf__fmeta_t *m)
{
    cf__ff_face_t face;
    cf__ff_table_t os2, head, fvar, cff, glyf;
    names_t nm;
    bool italic = false, bold = false;
    unsigned i;
    int r;
    if (cf__ff_face_open(f, index, &face)
        || cf__ff_table_find(f, &face, CF__FF_TAG('O', 'S', '/', '2'), 0,
                             &os2)
        || cf__ff_table_find(f, &face, CF__FF_TAG('h', 'e', 'a', 'd'), 54,
                             &head)
        || cf__ff_table_find(f, &face, CF__FF_TAG('f', 'v', 'a', 'r'), 0,
                             &fvar)
        || cf__ff_table_find(f, &face, CF__FF_TAG('C', 'F', 'F', ' '), 0,
                             &cff)
        || cf__ff_table_find(f, &face, CF__FF_TAG('g', 'l', 'y', 'f'), 0,
                             &glyf))
        return 1;
    if (fvar.data != NULL)
        return cf__ff_fail(f, "a variable font");
    if (head.data == NULL)
        return cf__ff_fail(f, "no head table");
    if (cff.data == NULL && glyf.data == NULL)
        return cf__ff_fail(f, "no CFF or glyf outlines");
    m->index = index;
    m->cff = cff.data != NULL;
    m->fontversion = (int32_t)cf__ff_u32(head.data + 4);
    memset(&nm, 0, sizeof nm);
    if ((r = read_names(f, &face, m, &nm)) != 0
        || (r = read_psname(f, &face, m->psname)) != 0)
        return r;
    m->slant = -1;
    m->weight = m->width = -1;
    if (os2.data != NULL && os2.len >= 64) {
        unsigned version = cf__ff_u16(os2.data);
        unsigned wc = cf__ff_u16(os2.data + 6);
        unsigned fs = cf__ff_u16(os2.data + 62);
        static const double w[] = { 50, 63, 75, 87, 100, 113, 125, 150,
                                    200 };
        m->weight = weight_from_ot(cf__ff_u16(os2.data + 4));
        if (wc >= 1 && wc <= 9)
            m->width = w[wc - 1];
        italic = (fs & 0x201) != 0;
        bold = (fs & 0x20) != 0;
        if (version >= 1 && os2.len >= 86) {
            m->has_codepages = true;
            m->codepages[0] = cf__ff_u32(os2.data + 78);
            m->codepages[1] = cf__ff_u32(os2.data + 82);
        }
        if (version >= 5 && os2.len >= 100) {
            m->has_size = true;
            m->size_lo = cf__ff_u16(os2.data + 96) / 20.0;
            m->size_hi = cf__ff_u16(os2.data + 98) / 20.0;
        }
    } else if (os2.data != NULL) {
        return cf__ff_fail(f, "OS/2 too short");
    } else {
        unsigned mac = cf__ff_u16(head.data + 44);
        italic = (mac & 2) != 0;
        bold = (mac & 1) != 0;
    }
    for (i = 0; i < nm.nstyle; i++) {
        if (m->weight == -1)
            m->weight = contains(nm.style[i], weights, NWORDS(weights));
        if (m->width == -1)
            m->width = contains(nm.style[i], widths, NWORDS(widths));
        if (m->slant == -1)
            m->slant = (int)contains(nm.style[i], slants, NWORDS(slants));
        if (!m->decorative)
            m->decorative = contains(nm.style[i], decoratives,
                                     NWORDS(decoratives)) > 0;
    }
    if (nm.nstyle == 0)
        return cf__ff_fail(f, "no style name");
    if (m->slant == -1)
        m->slant = italic ? CF__FMETA_SLANT_ITALIC : CF__FMETA_SLANT_ROMAN;
    if (m->weight == -1)
        m->weight = bold ? 200 : 100;
    if (m->width == -1)
        m->width = 100;
    return read_charset(f, &face, m);
}

unsigned
cf__fmeta_count(const unsigned char *data, size_t len)
{
    uint32_t tag;
    if (data == NULL || len < 12)
        return 0;
    tag = cf__ff_u32(data);
    if (tag == CF__FF_TAG('t', 't', 'c', 'f')) {
        uint32_t n = cf__ff_u32(data + 8);
        return n > 0 && n <= (len - 12) / 4 ? (unsigned)n : 0;
    }
    return tag == 0x00010000u || tag == CF__FF_TAG('t', 'r', 'u', 'e')
                   || tag == CF__FF_TAG('O', 'T', 'T', 'O')
               ? 1
               : 0;
}

int
cf__fmeta_read(const unsigned char *data, size_t len, unsigned index,
               cf__fmeta_t *out, char *why, size_t why_cap)
{
    cf__ff_t f;
    int r;
    memset(out, 0, sizeof *out);
    cf__ff_init(&f, data, len, NULL, why, why_cap);
    r = read_face(&f, index, out);
    if (r != 0) {
        cf__fmeta_fini(out);
        memset(out, 0, sizeof *out);
        if (r < 0 && why != NULL && why_cap > 0)
            cf__ff_fail(&f, "out of memory");
    }
    return r;
}

bool
cf__fmeta_ranges_hold(const uint32_t *ranges, size_t n, uint32_t a,
                      uint32_t b)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (a < ranges[2 * mid])
            hi = mid;
        else if (a > ranges[2 * mid + 1])
            lo = mid + 1;
        else
            return b <= ranges[2 * mid + 1];
    }
    return false;
}

bool
cf__fmeta_has(const cf__fmeta_t *m, uint32_t c)
{
    return cf__fmeta_ranges_hold(m->ranges, m->nranges, c, c);
}

void
cf__fmeta_fini(cf__fmeta_t *m)
{
    cf_free(m->ranges);
    m->ranges = NULL;
    m->nranges = 0;
}
