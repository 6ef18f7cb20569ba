/*
** The text of a run of the native fonts (render/backends/font-native.c)
** in pango's items: which texts these fonts take at all
** (cf__native_fonts_handles: the rest is pango's), then the text cut as
** pango 1.50 cuts a one-line text:
**   - in script runs as pango's script iterator cuts it (common and
**     inherited characters joining their neighbours, paired brackets
**     taking the script of their opening);
**   - each character's font: the first font of the description's set
**     that has it; spaces (and other separators) take the font of the
**     text around them, a run of spaces before a change of font going
**     with the font that comes earlier in the set.
** A character that no font of the set has leaves the run to pango.
** Characters' general category and script come from the shaper's table
** (render/fontfile/uprops.h) when it has them, from HarfBuzz otherwise
** (so that simple text does not load it).
*/
#include <locale.h>
#include <pthread.h>
#include <string.h>

#include "font-itemize.h"
#include "grow.h"
#include "label-impl.h"
#include "uprops.h"

#define PAREN_DEPTH 128

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

const char *
cf__native_language(void)
{
    pthread_once(&language_once, read_language);
    return the_language;
}

/* HarfBuzz's general category and script of c */
static hb_unicode_general_category_t
category_of(unsigned c)
{
    unsigned gc;
    uint32_t script;
    if (cf__uprops(c, &gc, &script))
        return (hb_unicode_general_category_t)gc;
    return hb_unicode_general_category(hb_unicode_funcs_get_default(), c);
}

static hb_script_t
script_of(unsigned c)
{
    unsigned gc;
    uint32_t script;
    if (cf__uprops(c, &gc, &script))
        return (hb_script_t)script;
    return hb_unicode_script(hb_unicode_funcs_get_default(), c);
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
    const char *lang = cf__native_language();
    size_t k = 0;
    if (len == 0 || (strcmp(lang, "c") != 0 && strcmp(lang, "posix") != 0))
        return false;
    while (k < len) {
        size_t at = k;
        unsigned c = next_char(text, len, &k);
        hb_unicode_general_category_t gc = category_of(c);
        if (cf__utf8_decode(text, len, at, &c) == 0
            || !script_ok(script_of(c)) || emoji_like(c)
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
script_next(script_iter_t *it)
{
    int start_sp = it->sp;
    if (it->end == it->len)
        return false;
    it->script = HB_SCRIPT_COMMON;
    it->start = it->end;
    while (it->end < it->len) {
        size_t k = it->end;
        unsigned c = next_char(it->text, it->len, &k);
        hb_script_t sc = script_of(c);
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
as_space(unsigned c)
{
    hb_unicode_general_category_t gc = category_of(c);
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
        if (cf__nface_has_char(f, c)) {
            *pos = i;
            return f;
        }
    return NULL;
}

/* The items of text: false when a character has no font (pango's then)
** or out of memory. */
bool
cf__native_itemize(native_run_t *r, cf__nfontset_t *set, const char *text,
                   size_t len)
{
    script_iter_t it;
    memset(&it, 0, sizeof it);
    it.text = text;
    it.len = len;
    it.sp = -1;
    r->nitems = 0;
    while (script_next(&it)) {
        item_t *cur = NULL;
        size_t k = it.start, first_space = (size_t)-1, run_first = r->nitems;
        int cur_pos = 0xffff;
        while (k < it.end) {
            size_t at = k;
            unsigned c = next_char(text, len, &k);
            cf__nface_t *font = NULL;
            int pos = 0xffff;
            size_t fs = first_space;
            bool space = as_space(c);
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

