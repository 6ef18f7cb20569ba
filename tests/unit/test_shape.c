/*
** The renderer's shaper (render/fontfile/shape.h) against HarfBuzz, set up
** as the native fonts set it up (render/backends/font-native.c: a sub-font
** with pango's nominal-glyph function, left to right, language "c",
** cluster level monotone characters, the whole text as context):
**   - every run of the shipped figures' labels as the native fonts
**     itemised them (shape-items.tsv: face file and index, scale, slant,
**     script, the item in its text), and
**   - thousands of random strings over the characters of the fast path
**     (Latin with ligature candidates and kerning pairs, Greek, Cyrillic,
**     digits and punctuation, CJK) in every face the renderer uses, at
**     several sizes, with and without a synthetic slant.
** For each run the shaper accepts, glyph ids, clusters, advances and
** offsets must be HarfBuzz's; hb_font_get_h_extents must equal
** cf__otface_h_extents.  The counts of runs accepted and handed on are
** printed.  A character is offered to the shaper only when the native
** fonts' rule would (general category not M*, C*, Zl, Zp; no U+2044;
** script Latin, Greek, Cyrillic, Han, Hiragana, Katakana, Bopomofo or
** Common).
*/
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <hb-ot.h>
#include <hb.h>

#include <cmocka.h>

#include "curvefig/core.h"
#include "shape.h"
#include "testutil.h"

static long accepted, handed, mismatches, extents_checked;
static long by_script[8][4];   /* accepted, not simple text, refused, of
                                  which with every character in the face */
static int cur_alpha = 7;

static hb_bool_t
nominal_glyph(hb_font_t *font, void *data, hb_codepoint_t c,
              hb_codepoint_t *glyph, void *user)
{
    (void)data;
    (void)user;
    if (hb_font_get_nominal_glyph(hb_font_get_parent(font), c, glyph))
        return 1;
    *glyph = 0x10000000u | c;
    return 0;
}

static hb_font_funcs_t *
pango_funcs(void)
{
    static hb_font_funcs_t *funcs;
    if (funcs == NULL) {
        funcs = hb_font_funcs_create();
        hb_font_funcs_set_nominal_glyph_func(funcs, nominal_glyph, NULL,
                                             NULL);
        hb_font_funcs_make_immutable(funcs);
    }
    return funcs;
}

/* The characters the native fonts would give the fast path. */
static bool
simple_text(const char *text, size_t off, size_t len)
{
    hb_unicode_funcs_t *u = hb_unicode_funcs_get_default();
    hb_buffer_t *b = hb_buffer_create();
    unsigned n, i;
    bool ok = true;
    hb_glyph_info_t *info;
    hb_buffer_add_utf8(b, text + off, (int)len, 0, (int)len);
    info = hb_buffer_get_glyph_infos(b, &n);
    for (i = 0; i < n && ok; i++) {
        hb_codepoint_t c = info[i].codepoint;
        hb_unicode_general_category_t gc = hb_unicode_general_category(u, c);
        hb_script_t s = hb_unicode_script(u, c);
        ok = c != 0x2044 && c != 0xFFFD
             && gc != HB_UNICODE_GENERAL_CATEGORY_CONTROL
             && gc != HB_UNICODE_GENERAL_CATEGORY_FORMAT
             && gc != HB_UNICODE_GENERAL_CATEGORY_UNASSIGNED
             && gc != HB_UNICODE_GENERAL_CATEGORY_PRIVATE_USE
             && gc != HB_UNICODE_GENERAL_CATEGORY_SURROGATE
             && gc != HB_UNICODE_GENERAL_CATEGORY_LINE_SEPARATOR
             && gc != HB_UNICODE_GENERAL_CATEGORY_PARAGRAPH_SEPARATOR
             && gc != HB_UNICODE_GENERAL_CATEGORY_SPACING_MARK
             && gc != HB_UNICODE_GENERAL_CATEGORY_ENCLOSING_MARK
             && gc != HB_UNICODE_GENERAL_CATEGORY_NON_SPACING_MARK
             && (s == HB_SCRIPT_LATIN || s == HB_SCRIPT_GREEK
                 || s == HB_SCRIPT_CYRILLIC || s == HB_SCRIPT_HAN
                 || s == HB_SCRIPT_HIRAGANA || s == HB_SCRIPT_KATAKANA
                 || s == HB_SCRIPT_BOPOMOFO || s == HB_SCRIPT_COMMON);
    }
    hb_buffer_destroy(b);
    return ok;
}

typedef struct face face_t;
static bool all_mapped(const face_t *f, const char *s, size_t len);

struct face {
    const char *file;
    unsigned index;
    hb_face_t *hb;
    cf__otface_t *own;
};

/* Whether the face's cmap has every character of s[0..len). */
static bool
all_mapped(const face_t *f, const char *s, size_t len)
{
    hb_buffer_t *b = hb_buffer_create();
    unsigned n, i;
    bool ok = true;
    hb_glyph_info_t *info;
    hb_buffer_add_utf8(b, s, (int)len, 0, (int)len);
    info = hb_buffer_get_glyph_infos(b, &n);
    for (i = 0; i < n && ok; i++)
        ok = cf__otface_glyph(f->own, info[i].codepoint) != 0;
    hb_buffer_destroy(b);
    return ok;
}

static face_t faces[64];
static size_t nfaces;

static face_t *
face_of(const char *file, unsigned index)
{
    size_t i;
    hb_blob_t *blob;
    for (i = 0; i < nfaces; i++)
        if (faces[i].index == index && strcmp(faces[i].file, file) == 0)
            return &faces[i];
    if (nfaces == sizeof faces / sizeof faces[0])
        abort();
    faces[nfaces].file = strdup(file);
    faces[nfaces].index = index;
    blob = hb_blob_create_from_file(file);
    faces[nfaces].hb = hb_face_create(blob, index);
    hb_blob_destroy(blob);
    if (cf__otface_open(file, index, &faces[nfaces].own) != 0)
        abort();
    return &faces[nfaces++];
}

static cf__otrun_t run;

/* One run shaped both ways; false on a difference (printed). */
static bool
compare(face_t *f, int xs, int ys, float slant, hb_script_t script,
        const char *text, size_t off, size_t len)
{
    hb_font_t *font, *sub;
    hb_buffer_t *b;
    cf__otscale_t sc;
    unsigned n, i;
    hb_glyph_info_t *info;
    hb_glyph_position_t *pos;
    int r, asc, desc, gap;
    hb_font_extents_t ext;
    bool same = true;
    uint32_t tag = cf__ot_script_tag((uint32_t)script);
    if (!simple_text(text, off, len) || tag == 0) {
        by_script[cur_alpha][1]++;
        handed++;
        return true;
    }
    sc.x_scale = xs;
    sc.y_scale = ys;
    sc.slant = slant;
    r = cf__ot_shape(f->own, tag, &sc, text, off, len, &run);
    if (r < 0)
        abort();
    font = hb_font_create(f->hb);
    hb_font_set_scale(font, xs, ys);
    hb_font_set_ptem(font, (float)ys / 1024.f);
    hb_font_set_synthetic_slant(font, slant);
    if (cf__otface_h_extents(f->own, ys, &asc, &desc, &gap)) {
        hb_font_get_h_extents(font, &ext);
        extents_checked++;
        if (ext.ascender != asc || ext.descender != desc
            || ext.line_gap != gap) {
            printf("extents differ: %s %u at %d: hb %d %d %d, own %d %d %d\n",
                   f->file, f->index, ys, ext.ascender, ext.descender,
                   ext.line_gap, asc, desc, gap);
            same = false;
        }
    }
    if (r == 1) {
        by_script[cur_alpha][2]++;
        by_script[cur_alpha][3] += all_mapped(f, text + off, len);
        handed++;
        hb_font_destroy(font);
        return same;
    }
    accepted++;
    by_script[cur_alpha][0]++;
    b = hb_buffer_create();
    hb_buffer_set_direction(b, HB_DIRECTION_LTR);
    hb_buffer_set_script(b, script);
    hb_buffer_set_language(b, hb_language_from_string("c", -1));
    hb_buffer_set_cluster_level(b, HB_BUFFER_CLUSTER_LEVEL_MONOTONE_CHARACTERS);
    hb_buffer_set_flags(b, HB_BUFFER_FLAG_BOT | HB_BUFFER_FLAG_EOT);
    hb_buffer_set_invisible_glyph(b, 0x0FFFFFFFu);
    hb_buffer_add_utf8(b, text, (int)off, (unsigned)off, 0);
    hb_buffer_add_utf8(b, text, (int)(off + len), (unsigned)off, (int)len);
    hb_buffer_add_utf8(b, text, (int)strlen(text), (unsigned)(off + len), 0);
    sub = hb_font_create_sub_font(font);
    hb_font_set_funcs(sub, pango_funcs(), NULL, NULL);
    hb_shape(sub, b, NULL, 0);
    info = hb_buffer_get_glyph_infos(b, &n);
    pos = hb_buffer_get_glyph_positions(b, NULL);
    if (n != run.n)
        same = false;
    for (i = 0; same && i < n; i++)
        same = info[i].codepoint == run.g[i].id
               && info[i].cluster == run.g[i].cluster
               && pos[i].x_advance == run.g[i].x_advance
               && pos[i].x_offset == run.g[i].x_offset
               && pos[i].y_offset == run.g[i].y_offset
               && pos[i].y_advance == 0;
    if (!same) {
        printf("differ: %s %u scale %d slant %g script %c%c%c%c \"%.*s\"\n",
               f->file, f->index, xs, (double)slant, (char)(tag >> 24),
               (char)(tag >> 16), (char)(tag >> 8), (char)tag, (int)len,
               text + off);
        for (i = 0; i < n; i++)
            printf("  hb  %u cl %u adv %d off %d,%d\n", info[i].codepoint,
                   info[i].cluster, pos[i].x_advance, pos[i].x_offset,
                   pos[i].y_offset);
        for (i = 0; i < run.n; i++)
            printf("  own %u cl %u adv %d off %d,%d\n", run.g[i].id,
                   run.g[i].cluster, run.g[i].x_advance, run.g[i].x_offset,
                   run.g[i].y_offset);
        mismatches++;
    }
    hb_font_destroy(sub);
    hb_font_destroy(font);
    hb_buffer_destroy(b);
    return same;
}

/* The items of the shipped figures (shape-items.tsv, fields: ITEM, file,
** index, x and y scale, slant, script, offset, length, text). */
static void
replay_items(const char *path)
{
    FILE *in = fopen(path, "r");
    char line[4096];
    long before = accepted, hbefore = handed;
    if (in == NULL) {
        printf("cannot read %s\n", path);
        exit(1);
    }
    while (fgets(line, sizeof line, in) != NULL) {
        char *field[10], *p = line;
        int k;
        size_t n = strlen(line);
        if (n > 0 && line[n - 1] == '\n')
            line[n - 1] = '\0';
        for (k = 0; k < 10; k++) {
            field[k] = p;
            p = k < 9 ? strchr(p, '\t') : NULL;
            if (k < 9 && p == NULL)
                break;
            if (p != NULL)
                *p++ = '\0';
        }
        if (k < 9 || fopen(field[1], "r") == NULL)
            continue;
        compare(face_of(field[1], (unsigned)atoi(field[2])), atoi(field[3]),
                atoi(field[4]), strtof(field[5], NULL),
                (hb_script_t)strtoul(field[6], NULL, 10), field[9],
                strtoul(field[7], NULL, 10), strtoul(field[8], NULL, 10));
    }
    fclose(in);
    printf("shipped figures' items: %ld accepted, %ld handed on\n",
           accepted - before, handed - hbefore);
}

/* ---- random strings ----------------------------------------------------- */

static tu_rng rng = { 0x2545F4914F6CDD1Dull };

static unsigned
rnd(unsigned n)
{
    return (unsigned)(tu_rng_next(&rng) % n);
}

static const char *const latin[] = {
    "a", "b", "c", "d", "e", "f", "g", "h", "i", "j", "k", "l", "m", "n",
    "o", "p", "q", "r", "s", "t", "u", "v", "w", "x", "y", "z", "A", "B",
    "C", "D", "F", "L", "P", "T", "V", "W", "Y", "ff", "fi", "fl", "ffi",
    "ffl", "AV", "To", "Ty", "Wa", "LT", "P_", "é", "à", "ü", "ß", "ø", "æ",
    "œ", "ñ", "ç", "Å", "ĳ", "ﬁ", "ı", "ȷ", "ŀ", "Ł", "ğ"
};
static const char *const common[] = {
    "0", "1", "2", "3", "7", "9", " ", " ", ".", ",", ";", ":", "!", "?",
    "'", "\"", "(", ")", "[", "]", "{", "}", "-", "–", "—", "+", "=", "<",
    ">", "/", "*", "&", "%", "$", "#", "@", "^", "_", "|", "~", "…", "‘",
    "’", "“", "”", "×", "÷", "±", "∞", "≤", "≥", "→", "·", "°", "′", "−",
    "𝑥", "𝑃", "𝛼", "∑", "∫", "‖", "⟨", "⟩", "，", "。", "、", "：",
    "「", "」", "（", "）", "ー", "､", " ", "--", "---", "``", "''", "!`",
    "?`", "<<", ">>", ",,"
};
static const char *const greek[] = {
    "α", "β", "γ", "δ", "ε", "ζ", "η", "θ", "ι", "κ", "λ", "μ", "ν", "ξ",
    "ο", "π", "ρ", "σ", "ς", "τ", "υ", "φ", "χ", "ψ", "ω", "Α", "Γ", "Δ",
    "Θ", "Λ", "Ξ", "Π", "Σ", "Φ", "Ψ", "Ω", "ά", "έ", "ή", "ί", "ό", "ύ",
    "ώ", "ϑ", "ϕ", "ϵ"
};
static const char *const cyrillic[] = {
    "а", "б", "в", "г", "д", "е", "ж", "з", "и", "й", "к", "л", "м", "н",
    "о", "п", "р", "с", "т", "у", "ф", "х", "ц", "ч", "ш", "щ", "ъ", "ы",
    "ь", "э", "ю", "я", "ё", "А", "Б", "Г", "Д", "Ж", "Т", "У", "Ф", "Я",
    "Ё", "Є", "Ї", "Ў"
};
static const char *const han[] = {
    "的", "一", "是", "不", "了", "人", "我", "在", "有", "他", "这", "中",
    "大", "来", "上", "国", "个", "到", "说", "们", "为", "子", "和", "你",
    "点", "线", "曲", "面", "图", "数", "学", "角", "形", "圆", "边", "长",
    "骨", "直", "写", "次", "今", "关", "门", "户", "令", "化", "与", "海",
    "述", "遍", "浩", "净", "户", "冷", "真", "这"
};
static const char *const kana[] = {
    "あ", "い", "う", "え", "お", "か", "き", "く", "け", "こ", "が", "ぱ",
    "ゃ", "っ", "ア", "イ", "ウ", "カ", "キ", "ガ", "パ", "ャ", "ッ", "ヴ",
    "ヶ", "ヽ", "ゝ"
};
static const char *const bopomofo[] = { "ㄅ", "ㄆ", "ㄇ", "ㄈ", "ㄉ", "ㄚ" };

typedef struct alphabet {
    hb_script_t script;
    const char *const *chars;
    size_t n;
} alphabet_t;

#define ALPHA(s, a) { s, a, sizeof a / sizeof a[0] }
static const alphabet_t alphabets[] = {
    ALPHA(HB_SCRIPT_LATIN, latin), ALPHA(HB_SCRIPT_COMMON, common),
    ALPHA(HB_SCRIPT_GREEK, greek), ALPHA(HB_SCRIPT_CYRILLIC, cyrillic),
    ALPHA(HB_SCRIPT_HAN, han), ALPHA(HB_SCRIPT_HIRAGANA, kana),
    ALPHA(HB_SCRIPT_BOPOMOFO, bopomofo)
};

static void
random_runs(face_t *f, int strings)
{
    static const double sizes[] = { 5, 7, 8.5, 10, 10.95, 12, 17.28, 24 };
    size_t s, a;
    int k;
    for (s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        int scale = (int)(sizes[s] * 1024);
        float slant = s % 3 == 2 ? 0.2f : 0.f;
        for (a = 0; a < sizeof alphabets / sizeof alphabets[0]; a++)
            for (k = 0; k < strings; k++) {
                char text[256], pre[32], post[32];
                size_t len = 0, n = 1 + rnd(10), i;
                const alphabet_t *al = &alphabets[a];
                cur_alpha = (int)a;
                text[0] = '\0';
                strcpy(pre, rnd(3) == 0 ? "x " : "");
                strcpy(post, rnd(3) == 0 ? " y" : "");
                strcat(text, pre);
                for (i = 0; i < n; i++) {
                    const char *c = rnd(4) == 0 && a != 1 ?
                        common[rnd(sizeof common / sizeof common[0])] :
                        al->chars[rnd((unsigned)al->n)];
                    strcat(text, c);
                }
                len = strlen(text) - strlen(pre);
                strcat(text, post);
                compare(f, scale, scale, slant, al->script, text,
                        strlen(pre), len);
            }
    }
}

int
main(int argc, char **argv)
{
    static const char *const files[] = {
        "/usr/share/texmf/fonts/opentype/public/lm-math/latinmodern-math.otf",
        "/usr/share/fonts/truetype/cmu/cmunrm.ttf",
        "/usr/share/fonts/truetype/cmu/cmunti.ttf",
        "/usr/share/fonts/truetype/cmu/cmunss.ttf",
        "/usr/share/fonts/truetype/cmu/cmunsi.ttf",
        "/usr/share/texmf/fonts/opentype/public/lm/lmsans10-regular.otf",
        "/usr/share/texmf/fonts/opentype/public/lm/lmsans10-oblique.otf",
    };
    static const char *const lm[] = { "5", "6", "7", "8", "9", "10", "12",
                                      "17" };
    static const char *const styles[] = { "regular", "italic", "bold" };
    static const char *const cjk[] = {
        "/usr/share/fonts/opentype/noto/NotoSerifCJK-Regular.ttc",
        "/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc"
    };
    size_t i, j;
    int strings = argc > 2 ? atoi(argv[2]) : 60;
    long before;
    replay_items(argc > 1 ? argv[1] : "shape-items.tsv");
    before = accepted;
    for (i = 0; i < sizeof lm / sizeof lm[0]; i++)
        for (j = 0; j < 3; j++) {
            char path[200];
            FILE *t;
            snprintf(path, sizeof path,
                     "/usr/share/texmf/fonts/opentype/public/lm/"
                     "lmroman%s-%s.otf", lm[i], styles[j]);
            if ((t = fopen(path, "r")) == NULL)
                continue;
            fclose(t);
            random_runs(face_of(path, 0), strings);
        }
    for (i = 0; i < sizeof files / sizeof files[0]; i++)
        random_runs(face_of(files[i], 0), strings);
    for (i = 0; i < sizeof cjk / sizeof cjk[0]; i++) {
        hb_blob_t *blob = hb_blob_create_from_file(cjk[i]);
        unsigned n = hb_face_count(blob);
        hb_blob_destroy(blob);
        for (j = 0; j < n; j++)
            random_runs(face_of(cjk[i], (unsigned)j), strings / 4 + 1);
    }
    printf("random strings: %ld accepted\n", accepted - before);
    for (i = 0; i < sizeof alphabets / sizeof alphabets[0]; i++)
        printf("  script %c%c%c%c: %ld accepted, %ld not given (characters "
               "outside the fast path), %ld refused by the shaper (%ld of "
               "them with every character in the face)\n",
               (char)(alphabets[i].script >> 24),
               (char)(alphabets[i].script >> 16),
               (char)(alphabets[i].script >> 8), (char)alphabets[i].script,
               by_script[i][0], by_script[i][1], by_script[i][2],
               by_script[i][3]);
    for (i = 0; i < nfaces; i++)
        printf("face %s %u: %s\n", faces[i].file, faces[i].index,
               cf__otface_usable(faces[i].own) ? "usable" : "not usable");
    printf("all: %ld runs accepted, %ld handed on, %ld extents compared, "
           "%ld differences\n", accepted, handed, extents_checked,
           mismatches);
    for (i = 0; i < nfaces; i++)
        cf__otface_close(faces[i].own);
    cf__otrun_fini(&run);
    return mismatches == 0 && accepted > 0 ? 0 : 1;
}
