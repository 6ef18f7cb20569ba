/*
** The native fonts of labels (render/labels/font.h): HarfBuzz shapes, in
** the faces pango would choose (render/backends/font-faces.c), the way
** pango 1.50 lays out a one-line text, so that every number is pango's:
**   - the text in script runs as pango's script iterator cuts it (common
**     and inherited characters joining their neighbours, paired brackets
**     taking the script of their opening);
**   - each character's font: the first font of the description's set
**     that has it; spaces (and other separators) take the font of the
**     text around them, a run of spaces before a change of font going
**     with the font that comes earlier in the set;
**   - each item (one script, one font) shaped by hb_shape with the whole
**     text as context, left to right, script and language set, clusters
**     monotone by character, pango's unknown-glyph marks;
**   - logical and ink extents: each glyph's advance from HarfBuzz, its
**     ink from cairo's scaled font in units rounded as pango rounds, the
**     font's logical height from HarfBuzz's ascender and descender, the
**     line's and the layout's rectangles combined as pango combines them.
** What this does not do is handed to pango (render/backends/
** font-pango.c, which loads it then): a run with a character of another
** script than Latin, Greek, Cyrillic, Han, Hiragana, Katakana, Hangul and
** Bopomofo (right-to-left and complex scripts among them), a control or
** format character, an emoji or a variation selector, a character no font
** of the set has (pango draws a box), a face with variations or
** configured features, an empty text; and every run when pango's default
** language (from the C library's LC_CTYPE) is not C or POSIX, where pango
** would tag items with languages this does not derive
** (cf__native_fonts_handles).
*/
#include <locale.h>
#include <math.h>
#include <pthread.h>
#include <stddef.h>
#include <string.h>

#include <hb.h>
#include <hb-ot.h>

#include "curvefig/core.h"
#include "font-config.h"
#include "font-faces.h"
#include "font-glyphs.h"
#include "font-native.h"
#include "font-pango.h"
#include "grow.h"
#include "label-impl.h"

#define PAREN_DEPTH 128

typedef struct native_fonts {
    void *pango;          /* pango's context, opened for the first run
                             handed to it */
    cairo_t *cr;          /* for outlines */
    hb_buffer_t *buf;
} native_fonts_t;

typedef struct item {
    size_t offset, length;
    cf__nface_t *font;    /* NULL: spaces, filled later */
    int position;         /* the font's place in the set */
    hb_script_t script;
} item_t;

typedef struct native_run {
    void *pango;          /* pango's run, when pango shaped it */
    bool native;          /* which one the last shape used */
    bool oom;             /* the last shape ran out of memory */
    cf__font_glyphs_buf_t glyphs;
    item_t *items;
    size_t nitems, cap_items;
} native_run_t;

/* pango's default language, canonical ("c" when the program never set
** the locale), read once as pango reads it (pango_language_get_default):
** one per process, as pango's is. */
static char the_language[32];
static pthread_once_t language_once = PTHREAD_ONCE_INIT;

static void
read_language(void)
{
    const char *lc = setlocale(LC_CTYPE, NULL);
    size_t n = 0;
    if (lc == NULL)
        lc = "C";
    for (; *lc != '\0' && n + 1 < sizeof the_language; lc++) {
        char ch = *lc;
        if (ch >= 'A' && ch <= 'Z')
            ch = (char)(ch - 'A' + 'a');
        else if (ch == '_')
            ch = '-';
        else if (!((ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9')
                   || ch == '-'))
            break;
        the_language[n++] = ch;
    }
    the_language[n] = '\0';
}

static const char *
default_language(void)
{
    pthread_once(&language_once, read_language);
    return the_language;
}

static bool
script_ok(hb_script_t s)
{
    switch (s) {
    case HB_SCRIPT_COMMON:
    case HB_SCRIPT_INHERITED:
    case HB_SCRIPT_LATIN:
    case HB_SCRIPT_GREEK:
    case HB_SCRIPT_CYRILLIC:
    case HB_SCRIPT_HAN:
    case HB_SCRIPT_HIRAGANA:
    case HB_SCRIPT_KATAKANA:
    case HB_SCRIPT_HANGUL:
    case HB_SCRIPT_BOPOMOFO:
        return true;
    default:
        return false;
    }
}

/* Characters pango's emoji iterator may take for emoji (blocks of
** pictographs, keycaps, tags, modifiers), and variation selectors. */
static bool
emoji_like(unsigned c)
{
    return (c >= 0x2300 && c <= 0x23ff) || c == 0x25fd || c == 0x25fe
           || (c >= 0x2600 && c <= 0x27bf) || (c >= 0x2b00 && c <= 0x2bff)
           || c == 0x20e3 || (c >= 0xfe00 && c <= 0xfe0f)
           || (c >= 0x1f000 && c <= 0x1faff)
           || (c >= 0xe0000 && c <= 0xe01ef);
}

static unsigned
next_char(const char *s, size_t len, size_t *k)
{
    unsigned cp;
    size_t n = cf__utf8_decode(s, len, *k, &cp);
    *k += n > 0 ? n : 1;
    return n > 0 ? cp : 0xfffd;
}

bool
cf__native_fonts_handles(const char *text, size_t len)
{
    hb_unicode_funcs_t *u = hb_unicode_funcs_get_default();
    const char *lang = default_language();
    size_t k = 0;
    if (len == 0 || (strcmp(lang, "c") != 0 && strcmp(lang, "posix") != 0))
        return false;
    while (k < len) {
        size_t at = k;
        unsigned c = next_char(text, len, &k);
        hb_unicode_general_category_t gc =
            hb_unicode_general_category(u, c);
        if (cf__utf8_decode(text, len, at, &c) == 0
            || !script_ok(hb_unicode_script(u, c)) || emoji_like(c)
            || gc == HB_UNICODE_GENERAL_CATEGORY_CONTROL
            || gc == HB_UNICODE_GENERAL_CATEGORY_FORMAT
            || gc == HB_UNICODE_GENERAL_CATEGORY_SURROGATE
            || gc == HB_UNICODE_GENERAL_CATEGORY_PRIVATE_USE
            || gc == HB_UNICODE_GENERAL_CATEGORY_UNASSIGNED
            || gc == HB_UNICODE_GENERAL_CATEGORY_LINE_SEPARATOR
            || gc == HB_UNICODE_GENERAL_CATEGORY_PARAGRAPH_SEPARATOR)
            return false;
    }
    return true;
}

/* ---- pango's script runs ------------------------------------------------ */

static const unsigned paired[] = {
    0x0028, 0x0029, 0x003c, 0x003e, 0x005b, 0x005d, 0x007b, 0x007d,
    0x00ab, 0x00bb, 0x0f3a, 0x0f3b, 0x0f3c, 0x0f3d, 0x169b, 0x169c,
    0x2018, 0x2019, 0x201c, 0x201d, 0x2039, 0x203a, 0x2045, 0x2046,
    0x207d, 0x207e, 0x208d, 0x208e, 0x27e6, 0x27e7, 0x27e8, 0x27e9,
    0x27ea, 0x27eb, 0x27ec, 0x27ed, 0x27ee, 0x27ef, 0x2983, 0x2984,
    0x2985, 0x2986, 0x2987, 0x2988, 0x2989, 0x298a, 0x298b, 0x298c,
    0x298d, 0x298e, 0x298f, 0x2990, 0x2991, 0x2992, 0x2993, 0x2994,
    0x2995, 0x2996, 0x2997, 0x2998, 0x29fc, 0x29fd, 0x2e02, 0x2e03,
    0x2e04, 0x2e05, 0x2e09, 0x2e0a, 0x2e0c, 0x2e0d, 0x2e1c, 0x2e1d,
    0x2e20, 0x2e21, 0x2e22, 0x2e23, 0x2e24, 0x2e25, 0x2e26, 0x2e27,
    0x2e28, 0x2e29, 0x3008, 0x3009, 0x300a, 0x300b, 0x300c, 0x300d,
    0x300e, 0x300f, 0x3010, 0x3011, 0x3014, 0x3015, 0x3016, 0x3017,
    0x3018, 0x3019, 0x301a, 0x301b, 0xfe59, 0xfe5a, 0xfe5b, 0xfe5c,
    0xfe5d, 0xfe5e, 0xff08, 0xff09, 0xff3b, 0xff3d, 0xff5b, 0xff5d,
    0xff5f, 0xff60, 0xff62, 0xff63
};

static int
pair_index(unsigned c)
{
    int lo = 0, hi = (int)(sizeof paired / sizeof paired[0]) - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        if (c < paired[mid])
            hi = mid - 1;
        else if (c > paired[mid])
            lo = mid + 1;
        else
            return mid;
    }
    return -1;
}

static bool
real_script(hb_script_t s)
{
    return s != HB_SCRIPT_COMMON && s != HB_SCRIPT_INHERITED
           && s != HB_SCRIPT_UNKNOWN;
}

typedef struct script_iter {
    const char *text;
    size_t len, start, end;
    hb_script_t script;
    struct { int pair; hb_script_t script; } stack[PAREN_DEPTH];
    int sp;
} script_iter_t;

/* The next script run: [start, end) and its script; false at the end. */
static bool
script_next(script_iter_t *it, hb_unicode_funcs_t *u)
{
    int start_sp = it->sp;
    if (it->end == it->len)
        return false;
    it->script = HB_SCRIPT_COMMON;
    it->start = it->end;
    while (it->end < it->len) {
        size_t k = it->end;
        unsigned c = next_char(it->text, it->len, &k);
        hb_script_t sc = hb_unicode_script(u, c);
        int pi = sc != HB_SCRIPT_COMMON ? -1 : pair_index(c);
        if (pi >= 0) {
            if ((pi & 1) == 0) {
                if (++it->sp >= PAREN_DEPTH)
                    it->sp = 0;
                it->stack[it->sp].pair = pi;
                it->stack[it->sp].script = it->script;
            } else if (it->sp >= 0) {
                while (it->sp >= 0 && it->stack[it->sp].pair != (pi & ~1))
                    it->sp--;
                if (it->sp < start_sp)
                    start_sp = it->sp;
                if (it->sp >= 0)
                    sc = it->stack[it->sp].script;
            }
        }
        if (!real_script(it->script) || !real_script(sc)
            || it->script == sc) {
            if (!real_script(it->script) && real_script(sc)) {
                it->script = sc;
                while (start_sp < it->sp)
                    it->stack[++start_sp].script = it->script;
            }
            if (pi >= 0 && (pi & 1) != 0 && it->sp >= 0) {
                it->sp--;
                if (it->sp < start_sp)
                    start_sp = it->sp;
            }
        } else {
            break;
        }
        it->end = k;
    }
    return true;
}

/* ---- items ---------------------------------------------------------------- */

/* pango's characters that choose no font (spaces, separators). */
static bool
as_space(hb_unicode_funcs_t *u, unsigned c)
{
    hb_unicode_general_category_t gc = hb_unicode_general_category(u, c);
    return gc == HB_UNICODE_GENERAL_CATEGORY_CONTROL
           || (gc == HB_UNICODE_GENERAL_CATEGORY_FORMAT
               && !((c >= 0x600 && c <= 0x6ff) || c == 0x70f || c == 0x8e2))
           || gc == HB_UNICODE_GENERAL_CATEGORY_SURROGATE
           || gc == HB_UNICODE_GENERAL_CATEGORY_LINE_SEPARATOR
           || gc == HB_UNICODE_GENERAL_CATEGORY_PARAGRAPH_SEPARATOR
           || (gc == HB_UNICODE_GENERAL_CATEGORY_SPACE_SEPARATOR
               && c != 0x1680)
           || (c >= 0xfe00 && c <= 0xfe0f) || (c >= 0xe0100 && c <= 0xe01ef);
}

static item_t *
new_item(native_run_t *r)
{
    item_t *t = cf__grow_array(r->items, &r->cap_items, r->nitems + 1,
                               sizeof *t, 8);
    if (t == NULL)
        return NULL;
    r->items = t;
    memset(&t[r->nitems], 0, sizeof *t);
    return &t[r->nitems++];
}

/* The first font of the set with character c (its place in *pos); NULL
** when none has it. */
static cf__nface_t *
font_for(cf__nfontset_t *set, unsigned c, int *pos)
{
    cf__nface_t *f;
    int i;
    for (i = 0; (f = cf__nfontset_font(set, i)) != NULL; i++)
        if (f->charset != NULL && FcCharSetHasChar(f->charset, c)) {
            *pos = i;
            return f;
        }
    return NULL;
}

/* The items of text: false when a character has no font (pango's then)
** or out of memory. */
static bool
itemize(native_run_t *r, cf__nfontset_t *set, const char *text, size_t len)
{
    hb_unicode_funcs_t *u = hb_unicode_funcs_get_default();
    script_iter_t it;
    memset(&it, 0, sizeof it);
    it.text = text;
    it.len = len;
    it.sp = -1;
    r->nitems = 0;
    while (script_next(&it, u)) {
        item_t *cur = NULL;
        size_t k = it.start, first_space = (size_t)-1, run_first = r->nitems;
        int cur_pos = 0xffff;
        while (k < it.end) {
            size_t at = k;
            unsigned c = next_char(text, len, &k);
            cf__nface_t *font = NULL;
            int pos = 0xffff;
            size_t fs = first_space;
            bool space = as_space(u, c);
            if (space) {
                if (first_space == (size_t)-1)
                    first_space = at;
            } else {
                first_space = (size_t)-1;
                font = font_for(set, c, &pos);
                if (font == NULL)
                    return false;
            }
            if (cur != NULL) {
                if (cur->font == NULL && font != NULL) {
                    size_t j = r->nitems;
                    while (j > run_first && r->items[j - 1].font == NULL)
                        r->items[--j].font = font;
                    cur_pos = pos;
                } else if (cur->font != NULL && font == NULL) {
                    font = cur->font;
                    pos = cur_pos;
                }
                if (cur->font == font)
                    continue;
                if (fs != (size_t)-1 && cur->offset < fs && pos < cur_pos)
                    at = fs;   /* the spaces go with the new font */
                cur->length = at - cur->offset;
            }
            cur = new_item(r);
            if (cur == NULL) {
                r->oom = true;
                return false;
            }
            cur->offset = at;
            cur->font = font;
            cur->script = it.script;
            cur_pos = pos;
        }
        if (cur != NULL) {
            cur->length = it.end - cur->offset;
            if (cur->font == NULL) {
                int pos;
                cf__nface_t *font = font_for(set, ' ', &pos);
                size_t j = r->nitems;
                if (font == NULL)
                    return false;
                while (j > run_first && r->items[j - 1].font == NULL)
                    r->items[--j].font = font;
            }
        }
    }
    return true;
}

/* ---- shaping -------------------------------------------------------------- */

static hb_bool_t
nominal_glyph(hb_font_t *font, void *data, hb_codepoint_t c,
              hb_codepoint_t *glyph, void *user)
{
    (void)data;
    (void)user;
    if (hb_font_get_nominal_glyph(hb_font_get_parent(font), c, glyph))
        return 1;
    if (hb_unicode_general_category(hb_unicode_funcs_get_default(), c)
        == HB_UNICODE_GENERAL_CATEGORY_SPACE_SEPARATOR) {
        if (c == 0x20) {
            *glyph = CF__FONT_GLYPH_UNKNOWN | 0x20;
            return 1;
        }
        return 0;
    }
    *glyph = CF__FONT_GLYPH_UNKNOWN | c;
    return 0;
}

/* pango's font functions over a face's: unknown characters marked. */
static hb_font_funcs_t *
pango_funcs(void)
{
    static hb_font_funcs_t *funcs;   /* immutable, made under the lock */
    if (funcs == NULL) {
        funcs = hb_font_funcs_create();
        hb_font_funcs_set_nominal_glyph_func(funcs, nominal_glyph, NULL,
                                             NULL);
        hb_font_funcs_make_immutable(funcs);
    }
    return funcs;
}

/* Shape item t of text into b (a span at x); its width added to *x;
** false when a glyph is unknown or the face is not ours. */
static bool
shape_item(native_fonts_t *nf, native_run_t *r, const item_t *t,
           const char *text, size_t len, int *x)
{
    hb_font_t *sub;
    unsigned n, i;
    hb_glyph_info_t *info;
    hb_glyph_position_t *pos;
    if (t->font->unsupported || cf__nface_scaled(t->font) == NULL)
        return false;
    hb_buffer_clear_contents(nf->buf);
    hb_buffer_set_direction(nf->buf, HB_DIRECTION_LTR);
    hb_buffer_set_script(nf->buf, t->script);
    hb_buffer_set_language(nf->buf, hb_language_from_string("c", -1));
    hb_buffer_set_cluster_level(nf->buf,
                                HB_BUFFER_CLUSTER_LEVEL_MONOTONE_CHARACTERS);
    hb_buffer_set_flags(nf->buf, HB_BUFFER_FLAG_BOT | HB_BUFFER_FLAG_EOT);
    hb_buffer_set_invisible_glyph(nf->buf, CF__FONT_GLYPH_EMPTY);
    hb_buffer_add_utf8(nf->buf, text, (int)t->offset, (unsigned)t->offset,
                       0);
    hb_buffer_add_utf8(nf->buf, text, (int)(t->offset + t->length),
                       (unsigned)t->offset, (int)t->length);
    hb_buffer_add_utf8(nf->buf, text, (int)len,
                       (unsigned)(t->offset + t->length), 0);
    sub = hb_font_create_sub_font(t->font->hb);
    hb_font_set_funcs(sub, pango_funcs(), NULL, NULL);
    hb_shape(sub, nf->buf, NULL, 0);
    hb_font_destroy(sub);
    info = hb_buffer_get_glyph_infos(nf->buf, &n);
    pos = hb_buffer_get_glyph_positions(nf->buf, NULL);
    if (n == 0)
        return false;
    cf__font_glyphs_span(&r->glyphs, &t->font->face, t->offset, t->length,
                         *x);
    for (i = 0; i < n; i++) {
        cf__font_glyph_t g;
        g.id = info[i].codepoint;
        if (g.id != CF__FONT_GLYPH_EMPTY && (g.id & CF__FONT_GLYPH_UNKNOWN))
            return false;
        g.width = pos[i].x_advance;
        g.x = pos[i].x_offset;
        g.y = -pos[i].y_offset;
        if (g.width < 0) {
            g.width = -g.width;
            g.x += g.width;
        }
        g.cluster = info[i].cluster - (unsigned)t->offset;
        cf__font_glyphs_add(&r->glyphs, &g);
        *x += g.width;
    }
    return !r->glyphs.failed;
}

/* pango's baseline shifts: the first item's script names the baseline
** (roman, hanging, ideographic), each item's font says where that
** baseline is for its script; an item sits lifted by the difference. */
static void
baseline_shifts(native_run_t *r)
{
    hb_ot_layout_baseline_tag_t tag = 0;
    hb_position_t baseline = 0;
    size_t i;
    for (i = 0; i < r->nitems && i < r->glyphs.g.nspans; i++) {
        const item_t *t = &r->items[i];
        hb_tag_t stags[HB_OT_MAX_TAGS_PER_SCRIPT];
        hb_tag_t ltags[HB_OT_MAX_TAGS_PER_LANGUAGE];
        unsigned ns = HB_OT_MAX_TAGS_PER_SCRIPT;
        unsigned nl = HB_OT_MAX_TAGS_PER_LANGUAGE;
        hb_position_t own;
        hb_ot_tags_from_script_and_language(
            t->script, hb_language_from_string("c", -1), &ns, stags, &nl,
            ltags);
        if (tag == 0)
            tag = hb_ot_layout_get_horizontal_baseline_tag_for_script(
                t->script);
        hb_ot_layout_get_baseline_with_fallback(
            t->font->hb, tag, HB_DIRECTION_LTR, stags[ns - 1],
            nl > 0 ? ltags[nl - 1] : HB_TAG_NONE, &own);
        if (i == 0)
            baseline = own;
        r->glyphs.spans[i].shift = baseline - own;
    }
}

/* a double in pango units, rounded as pango rounds */
static int
units(double v)
{
    return (int)floor(v * CF__FONT_SCALE + 0.5);
}

/* min and max as pango combines rectangles */
static int
imin(int a, int b)
{
    return a < b ? a : b;
}

static int
imax(int a, int b)
{
    return a > b ? a : b;
}

/* The layout's extents from the spans' glyphs (pango's glyph string,
** line and layout extents, one line, left to right). */
static void
extents(native_run_t *r, cf__font_shape_t *out)
{
    const cf__font_glyphs_t *g = &r->glyphs.g;
    int line_ink[4] = { 0, 0, 0, 0 }, line_log[4] = { 0, 0, 0, 0 };
    int x_pos = 0, base;
    size_t i, k;
    for (i = 0; i < g->nspans; i++) {
        const cf__font_span_t *s = &g->spans[i];
        cf__nface_t *f = (cf__nface_t *)((char *)s->face
                                         - offsetof(cf__nface_t, face));
        int ink[4] = { 0, 0, 0, 0 }, log[4] = { 0, 0, 0, 0 }, gx = 0, np;
        for (k = 0; k < s->nglyphs; k++) {
            const cf__font_glyph_t *gl = &g->glyphs[s->glyph + k];
            int gi[4] = { 0, 0, 0, 0 };
            if (gl->id != CF__FONT_GLYPH_EMPTY) {
                cairo_glyph_t cg;
                cairo_text_extents_t e;
                cg.index = gl->id;
                cg.x = cg.y = 0;
                cairo_scaled_font_glyph_extents(f->scaled, &cg, 1, &e);
                gi[0] = units(e.x_bearing);
                gi[1] = units(e.y_bearing);
                gi[2] = units(e.width);
                gi[3] = units(e.height);
            }
            if (gi[2] != 0 && gi[3] != 0) {
                if (ink[2] == 0 || ink[3] == 0) {
                    ink[0] = gx + gi[0] + gl->x;
                    ink[2] = gi[2];
                    ink[1] = gi[1] + gl->y;
                    ink[3] = gi[3];
                } else {
                    int nx = imin(ink[0], gx + gi[0] + gl->x),
                        ny = imin(ink[1], gi[1] + gl->y);
                    ink[2] = imax(ink[0] + ink[2],
                                  gx + gi[0] + gi[2] + gl->x) - nx;
                    ink[0] = nx;
                    ink[3] = imax(ink[1] + ink[3], gi[1] + gi[3] + gl->y)
                             - ny;
                    ink[1] = ny;
                }
            }
            log[2] += gl->width;
            if (k == 0) {
                log[1] = f->ext_y;
                log[3] = f->ext_height;
            } else {
                int ny = imin(log[1], f->ext_y);
                log[3] = imax(log[1] + log[3], f->ext_y + f->ext_height) - ny;
                log[1] = ny;
            }
            gx += gl->width;
        }
        ink[1] -= s->shift;
        log[1] -= s->shift;
        /* the line's rectangles */
        if (line_ink[2] == 0 || line_ink[3] == 0) {
            memcpy(line_ink, ink, sizeof ink);
            line_ink[0] += x_pos;
        } else if (ink[2] != 0 && ink[3] != 0) {
            np = imin(line_ink[0], x_pos + ink[0]);
            line_ink[2] = imax(line_ink[0] + line_ink[2],
                               x_pos + ink[0] + ink[2]) - np;
            line_ink[0] = np;
            np = imin(line_ink[1], ink[1]);
            line_ink[3] = imax(line_ink[1] + line_ink[3], ink[1] + ink[3])
                          - np;
            line_ink[1] = np;
        }
        np = imin(line_log[0], x_pos + log[0]);
        line_log[2] = imax(line_log[0] + line_log[2],
                           x_pos + log[0] + log[2]) - np;
        line_log[0] = np;
        np = imin(line_log[1], log[1]);
        line_log[3] = imax(line_log[1] + line_log[3], log[1] + log[3]) - np;
        line_log[1] = np;
        x_pos += log[2];
    }
    base = -line_log[1];
    out->baseline = base;
    out->logical[0] = 0;
    out->logical[1] = 0;
    out->logical[2] = imax(0, line_log[2]);
    out->logical[3] = base + line_log[1] + line_log[3];
    out->ink[0] = line_ink[0];
    out->ink[1] = base + line_ink[1];
    out->ink[2] = line_ink[2];
    out->ink[3] = line_ink[3];
    out->unknown = 0;
}

/* Shape req natively into r; false when pango must (the rule above), or
** when out of memory (r->oom). */
static bool
shape_native(native_fonts_t *nf, native_run_t *r, const cf__font_req_t *req,
             cf__font_shape_t *out)
{
    const char *lang = default_language();
    cf__nfontset_t *set;
    cf__font_shape_t none;
    size_t i;
    int x = 0;
    bool ok;
    r->oom = false;
    if (!cf__native_fonts_handles(req->text, req->len))
        return false;
    memset(&none, 0, sizeof none);
    cf__nfaces_lock();
    set = cf__nfontset_get(req->family, req->italic, req->bold,
                           (int)(req->size * CF__FONT_SCALE), lang);
    ok = set != NULL && itemize(r, set, req->text, req->len);
    cf__font_glyphs_reset(&r->glyphs, req, &none);
    for (i = 0; ok && i < r->nitems; i++)
        ok = shape_item(nf, r, &r->items[i], req->text, req->len, &x);
    if (ok) {
        baseline_shifts(r);
        extents(r, out);
        r->glyphs.g.shape = *out;
        r->glyphs.g.baseline = out->baseline;
    }
    cf__nfaces_unlock();
    if (r->glyphs.failed)
        r->oom = true;
    return ok && !r->glyphs.failed;
}

static void *
open_fonts(void *self)
{
    native_fonts_t *f = cf_calloc(1, sizeof *f);
    (void)self;
    if (f == NULL)
        return NULL;
    cf__fonts_configure();
    f->buf = hb_buffer_create();
    if (!hb_buffer_allocation_successful(f->buf)) {
        hb_buffer_destroy(f->buf);
        cf_free(f);
        return NULL;
    }
    return f;
}

static void
close_fonts(void *ctx)
{
    native_fonts_t *f = ctx;
    if (f == NULL)
        return;
    if (f->pango != NULL)
        cf__pango_fonts.close(f->pango);
    if (f->cr != NULL)
        cairo_destroy(f->cr);
    hb_buffer_destroy(f->buf);
    cf_free(f);
}

static int
shape(void *ctx, const cf__font_req_t *req, void **run,
      cf__font_shape_t *out)
{
    native_fonts_t *f = ctx;
    native_run_t *r = *run;
    if (r == NULL) {
        r = cf_calloc(1, sizeof *r);
        if (r == NULL)
            return -1;
        *run = r;
    }
    r->native = shape_native(f, r, req, out);
    if (r->native)
        return 0;
    if (r->oom)
        return -1;   /* out of memory, not a run for pango */
    if (f->pango == NULL) {
        f->pango = cf__pango_fonts.open(cf__pango_fonts.self);
        if (f->pango == NULL)
            return -1;
    }
    return cf__pango_fonts.shape(f->pango, req, &r->pango, out);
}

static void
release(void *run)
{
    native_run_t *r = run;
    if (r == NULL)
        return;
    if (r->pango != NULL)
        cf__pango_fonts.release(r->pango);
    cf__font_glyphs_fini(&r->glyphs);
    cf_free(r->items);
    cf_free(r);
}

static const cf__font_glyphs_t *
glyphs(void *run)
{
    native_run_t *r = run;
    return r->native ? &r->glyphs.g : cf__pango_fonts.glyphs(r->pango);
}

static void
draw(void *run, void *cr, bool path)
{
    native_run_t *r = run;
    if (r->native)
        cf__font_glyphs_draw(cr, &r->glyphs.g, path);
    else
        cf__pango_fonts.draw(r->pango, cr, path);
}

static void
outline(void *ctx, void *run, double x, double y, cf__pathb_t *out)
{
    cf__font_glyphs_outline(&((native_fonts_t *)ctx)->cr, glyphs(run), x, y,
                            out);
}

bool
cf__native_fonts_used_pango(void *run)
{
    return !((native_run_t *)run)->native;
}

const cf__fonts_t cf__native_fonts = {
    open_fonts, close_fonts, shape, release, outline, glyphs, draw, NULL
};
