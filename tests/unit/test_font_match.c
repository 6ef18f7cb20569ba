/*
** The face matcher without fontconfig (render/backends/font-match.h)
** against fontconfig under the tool's configuration (render/tool/
** fonts.c, linked in), the oracle: for every request of a grid (the
** family lists the labels ask for, with the optical sizes in front, Latin
** Modern Math in front, single families of the configuration and others,
** generic names, names with other case and blanks; italic and bold;
** sizes; languages) the list pango's order gives (font-faces.c:
** FcFontSetMatch's prepared best, then FcFontSetSort's trimmed list from
** its second font on, each FcFontRenderPrepare'd) and, face by face, the
** properties the renderer reads: file, index, first family, slant,
** weight, width, embolden, matrix, PostScript name, point and pixel
** size, dpi; and the charset is the font's.
**
** fontconfig takes its default languages from the environment once per
** process: the test runs itself again under several LANG, LC_ALL and
** FC_LANG settings (--child K).  The first, the environment unset, runs
** the whole grid; each other one fifth of it, a different fifth for each
** K (every request compared under two or three of the twelve), which
** keeps the suite's test at 4 of the grid's 13 times (the whole of it,
** 219,024 requests, gave 0 differences when the matcher was written).
** Then allocation failure: tu_fail_loop over a match and a sort (the
** configuration's reading: test_font_cache.c).
*/
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cmocka.h>
#include <fontconfig/fontconfig.h>

#include "font-cache.h"
#include "font-faces.h"
#include "font-match.h"
#include "testutil.h"
#include "tool-fonts.h"

const char *cf__tool_fonts_init(void);

static const cf__fm_source_t *const sources = tool_font_dirs;
static const char *const *const accept = tool_font_families;

static FcFontSet *
config_fonts(void)
{
    static FcFontSet *fonts;
    int s, i;
    if (fonts != NULL)
        return fonts;
    fonts = FcFontSetCreate();
    for (s = 0; s < 2; s++) {
        FcFontSet *set = FcConfigGetFonts(NULL, (FcSetName)s);
        FcChar8 *format;
        if (set == NULL)
            continue;
        for (i = 0; i < set->nfont; i++)
            if (FcPatternGetString(set->fonts[i], FC_FONTFORMAT, 0, &format)
                    == FcResultMatch
                && (strcmp((char *)format, "TrueType") == 0
                    || strcmp((char *)format, "CFF") == 0)) {
                FcPatternReference(set->fonts[i]);
                FcFontSetAdd(fonts, set->fonts[i]);
            }
    }
    return fonts;
}

static long differences;

/* One face against fontconfig's prepared pattern; false (and a message)
** when they differ. */
static bool
same_face(const char *what, int k, FcPattern *p, const cf__fm_face_t *f)
{
    FcChar8 *s;
    FcMatrix m, *mv;
    FcBool b = FcFalse;
    FcCharSet *cs;
    double d;
    int v, i;
    char diff[256] = "";
    FcPatternGetString(p, FC_FILE, 0, &s);
    if (strcmp((char *)s, f->font->file) != 0)
        snprintf(diff, sizeof diff, "file %s, matcher %s", (char *)s,
                 f->font->file);
    else if (FcPatternGetInteger(p, FC_INDEX, 0, &v), v != (int)f->font->meta.index)
        snprintf(diff, sizeof diff, "index %d, matcher %u", v,
                 f->font->meta.index);
    else if (FcPatternGetString(p, FC_FAMILY, 0, &s),
             strcmp((char *)s, f->family) != 0)
        snprintf(diff, sizeof diff, "family %s, matcher %s", (char *)s,
                 f->family);
    else if (FcPatternGetInteger(p, FC_SLANT, 0, &v), v != f->slant)
        snprintf(diff, sizeof diff, "slant %d, matcher %d", v, f->slant);
    else if (FcPatternGetDouble(p, FC_WEIGHT, 0, &d), d != f->weight)
        snprintf(diff, sizeof diff, "weight %g, matcher %g", d, f->weight);
    else if (FcPatternGetDouble(p, FC_WIDTH, 0, &d), d != f->width)
        snprintf(diff, sizeof diff, "width %g, matcher %g", d, f->width);
    else if (FcPatternGetBool(p, FC_EMBOLDEN, 0, &b), (b == FcTrue) != f->embolden)
        snprintf(diff, sizeof diff, "embolden %d, matcher %d", b, f->embolden);
    else if (FcPatternGetString(p, FC_POSTSCRIPT_NAME, 0, &s),
             strcmp((char *)s, f->font->meta.psname) != 0)
        snprintf(diff, sizeof diff, "psname %s, matcher %s", (char *)s,
                 f->font->meta.psname);
    else if (FcPatternGetDouble(p, FC_SIZE, 0, &d), d != f->size)
        snprintf(diff, sizeof diff, "size %.17g, matcher %.17g", d, f->size);
    else if (FcPatternGetDouble(p, FC_PIXEL_SIZE, 0, &d), d != f->pixel_size)
        snprintf(diff, sizeof diff, "pixel size %g, matcher %g", d,
                 f->pixel_size);
    else if (FcPatternGetDouble(p, FC_DPI, 0, &d), d != f->dpi)
        snprintf(diff, sizeof diff, "dpi %g, matcher %g", d, f->dpi);
    else if (FcPatternGetString(p, FC_FONT_FEATURES, 0, &s) == FcResultMatch
             || FcPatternGetString(p, FC_FONT_VARIATIONS, 0, &s)
                    == FcResultMatch)
        snprintf(diff, sizeof diff, "features or variations");
    if (diff[0] == '\0') {
        FcMatrixInit(&m);
        for (i = 0; FcPatternGetMatrix(p, FC_MATRIX, i, &mv) == FcResultMatch;
             i++)
            FcMatrixMultiply(&m, &m, mv);
        if (m.xx != 1 || m.yx != 0 || m.yy != 1
            || m.xy != (f->sheared ? 0.2 : 0))
            snprintf(diff, sizeof diff, "matrix [%g %g; %g %g], matcher %s",
                     m.xx, m.xy, m.yx, m.yy,
                     f->sheared ? "sheared" : "identity");
        else if (FcPatternGetCharSet(p, FC_CHARSET, 0, &cs) != FcResultMatch
                 || !cf__fm_font_has(f->font, 'A')
                        != !FcCharSetHasChar(cs, 'A'))
            snprintf(diff, sizeof diff, "charset");
    }
    if (diff[0] != '\0') {
        if (differences < 20)
            print_message("%s, font %d: %s\n", what, k, diff);
        differences++;
        return false;
    }
    return true;
}

static const char *const families[] = {
    "Latin Modern Roman,CMU Serif,Noto Serif CJK SC",
    "Latin Modern Sans,CMU Sans Serif,Noto Sans CJK SC",
    "Latin Modern Math,Latin Modern Roman,CMU Serif,Noto Serif CJK SC",
    "Latin Modern Math,Latin Modern Sans,CMU Sans Serif,Noto Sans CJK SC",
    "LM Roman 5,Latin Modern Roman,CMU Serif,Noto Serif CJK SC",
    "LM Roman 6,Latin Modern Roman,CMU Serif,Noto Serif CJK SC",
    "LM Roman 7,Latin Modern Roman,CMU Serif,Noto Serif CJK SC",
    "LM Roman 8,Latin Modern Roman,CMU Serif,Noto Serif CJK SC",
    "LM Roman 9,Latin Modern Roman,CMU Serif,Noto Serif CJK SC",
    "LM Roman 10,Latin Modern Roman,CMU Serif,Noto Serif CJK SC",
    "LM Roman 12,Latin Modern Roman,CMU Serif,Noto Serif CJK SC",
    "LM Roman 17,Latin Modern Roman,CMU Serif,Noto Serif CJK SC",
    "LM Sans 8,Latin Modern Sans,CMU Sans Serif,Noto Sans CJK SC",
    "LM Sans 10,Latin Modern Sans,CMU Sans Serif,Noto Sans CJK SC",
    "LM Sans 17,Latin Modern Sans,CMU Sans Serif,Noto Sans CJK SC",
    "Latin Modern Roman", "CMU Serif", "Noto Serif CJK SC",
    "Latin Modern Math", "Latin Modern Sans", "CMU Sans Serif",
    "Noto Sans CJK SC", "LM Roman 7", "LM Roman Caps 10", "LM Mono 10",
    "CMU Typewriter Text", "Noto Sans CJK JP", "DejaVu Sans", "serif",
    "sans-serif", "monospace", "", "latin modern roman", "LatinModern Roman",
    " CMU  Serif ", "Noto Serif CJK SC,Latin Modern Roman",
    "CMU Serif,Latin Modern Roman", "Unknown,Nothing,CMU Sans Serif",
    "Latin Modern Roman,Latin Modern Roman",
};
static const char *const langs[] = {
    "en", "en-us", "ru", "zh-cn", "zh-tw", "sl", "cs", "ja", "ko", "de",
    "el", "uk", "c", "und", "ar", "hi", "pt-br", "x",
};
static const int sizes[] = { 5120, 7168, 10240, 12288, 17408, 10000 };

/* The environment's number (envs below) of this process, a child. */
static size_t child;

/* Every request of the grid (or of its part for this child): the lists
** equal, face by face. */
static void
test_identity(void **state)
{
    cf__fm_config_t *c;
    char why[512];
    size_t fi, li, si, compared = 0, grid = 0;
    /* tu_sample: 1 but in the sanitizer build */
    size_t sample = (child > 0 ? 5 : 1) * tu_sample(), offset = child % sample;
    int style;
    (void)state;
    if (cf__fcache_config(sources, 4, accept, 7, NULL, &c, why, sizeof why) != 0) {
        print_message("the matcher declines: %s\n", why);
        skip();
    }
    assert_string_equal(cf__tool_fonts_init(),
                        "Latin Modern, CMU and Noto CJK (curvefig's "
                        "configuration)");
    assert_int_equal(config_fonts()->nfont, (int)cf__fm_config_count(c));
    for (fi = 0; fi < sizeof families / sizeof families[0]; fi++)
        for (style = 0; style < 4; style++)
            for (si = 0; si < sizeof sizes / sizeof sizes[0]; si++)
                for (li = 0; li < sizeof langs / sizeof langs[0]; li++) {
                    bool it = style & 1, bo = style >> 1;
                    if (grid++ % sample != offset)
                        continue;
                    FcFontSet *fonts = config_fonts();
                    FcPattern *p = cf__nfaces_pattern(families[fi], it, bo,
                                                sizes[si], langs[li]);
                    FcResult res;
                    FcPattern *m = FcFontSetMatch(NULL, &fonts, 1, p, &res);
                    FcFontSet *sorted = FcFontSetSort(NULL, &fonts, 1, p,
                                                      FcTrue, NULL, &res);
                    cf__fm_face_t first, *list;
                    size_t n, k;
                    char what[512];
                    snprintf(what, sizeof what, "'%s' %s%s %d %s",
                             families[fi], it ? "italic" : "roman",
                             bo ? " bold" : "", sizes[si], langs[li]);
                    assert_int_equal(cf__fm_match(c, families[fi], it, bo,
                                                  sizes[si], langs[li],
                                                  &first), 0);
                    assert_int_equal(cf__fm_sort(c, families[fi], it, bo,
                                                 sizes[si], langs[li], &list,
                                                 &n), 0);
                    if (same_face(what, 0, m, &first)) {
                        if ((int)n != sorted->nfont) {
                            if (differences < 20)
                                print_message("%s: %d sorted, matcher %zu\n",
                                              what, sorted->nfont, n);
                            differences++;
                        }
                        for (k = 1; k < n && (int)k < sorted->nfont; k++) {
                            FcPattern *q = FcFontRenderPrepare(
                                NULL, p, sorted->fonts[k]);
                            bool same = same_face(what, (int)k, q, &list[k]);
                            FcPatternDestroy(q);
                            if (!same)
                                break;
                        }
                    }
                    cf_free(list);
                    FcPatternDestroy(m);
                    FcFontSetDestroy(sorted);
                    FcPatternDestroy(p);
                    compared++;
                }
    cf__fm_config_free(c);
    print_message("%zu requests (LANG=%s LC_ALL=%s FC_LANG=%s): %ld "
                  "differences\n", compared,
                  getenv("LANG") ? getenv("LANG") : "",
                  getenv("LC_ALL") ? getenv("LC_ALL") : "",
                  getenv("FC_LANG") ? getenv("FC_LANG") : "", differences);
    assert_int_equal(differences, 0);
}

static cf__fm_config_t *fail_config;

static cf_status_t
sort_op(cf_diag_t *diag)
{
    cf__fm_face_t *list, first;
    size_t n;
    (void)diag;
    assert_int_equal(cf__fm_match(fail_config, families[2], true, true,
                                  7168, "ru", &first), 0);
    if (cf__fm_sort(fail_config, families[2], true, true, 7168, "ru", &list,
                    &n) < 0)
        return CF_STATUS_NO_MEMORY;
    cf_free(list);
    return CF_STATUS_OK;
}

static void
test_alloc_failure(void **state)
{
    (void)state;
    if (cf__fcache_config(sources, 4, accept, 7, NULL, &fail_config, NULL, 0)
        != 0)
        skip();
    tu_fail_loop("font-match sort", sort_op, false);
    cf__fm_config_free(fail_config);
}

/* The environments the children run in: LANG, LC_ALL, FC_LANG. */
static const char *const envs[][3] = {
    { NULL, NULL, NULL },           { "C", NULL, NULL },
    { "en_US.UTF-8", NULL, NULL },  { "ru_RU.UTF-8", NULL, NULL },
    { "ja_JP.UTF-8", NULL, NULL },  { "zh_CN.UTF-8", NULL, NULL },
    { "sl_SI.UTF-8", NULL, NULL },  { "cs_CZ.UTF-8", NULL, NULL },
    { "pt_BR.UTF-8", NULL, NULL },  { "sr_RS@latin", NULL, NULL },
    { "en_US.UTF-8", "de_DE.UTF-8", NULL },
    { "en_US.UTF-8", NULL, "ko:en" }, { "xx_YY", NULL, NULL },
};

int
main(int argc, char **argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_identity),
    };
    const struct CMUnitTest alloc_tests[] = {
        cmocka_unit_test(test_alloc_failure),
    };
    size_t e;
    int failed = 0;
    if (argc > 2 && strcmp(argv[1], "--child") == 0) {
        child = (size_t)strtoul(argv[2], NULL, 10);
        return cmocka_run_group_tests(tests, NULL, NULL);
    }
    for (e = 0; e < sizeof envs / sizeof envs[0]; e++) {
        pid_t pid = fork();
        int status;
        if (pid == 0) {
            unsetenv("LANG");
            unsetenv("LC_ALL");
            unsetenv("LC_CTYPE");
            unsetenv("FC_LANG");
            unsetenv("FONTCONFIG_FILE");
            unsetenv("FONTCONFIG_PATH");
            if (envs[e][0] != NULL)
                setenv("LANG", envs[e][0], 1);
            if (envs[e][1] != NULL)
                setenv("LC_ALL", envs[e][1], 1);
            if (envs[e][2] != NULL)
                setenv("FC_LANG", envs[e][2], 1);
            char k[24];
            snprintf(k, sizeof k, "%zu", e);
            /* the program by its path (under valgrind /proc/self/exe is
            ** valgrind's own tool, which refuses to run) */
            execl(strchr(argv[0], '/') != NULL ? argv[0] : "/proc/self/exe",
                  argv[0], "--child", k, (char *)NULL);
            _exit(127);
        }
        if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status)
            || WEXITSTATUS(status) != 0)
            failed++;
    }
    failed += cmocka_run_group_tests(alloc_tests, NULL, NULL);
    return failed != 0;
}
