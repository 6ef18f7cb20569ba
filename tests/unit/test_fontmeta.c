/*
** A face's metadata read from the file (render/fontfile/fontmeta.h)
** against fontconfig's own scan of it (FcFreeTypeQuery), the oracle: for
** every face of every font in the tool's font directories (render/tool/
** fonts.c; each skipped when not installed) the families and their
** languages in order, the PostScript name, slant, weight, width,
** decorative, optical size, font version, font format, the code pages
** fontconfig reads its exclusive languages from, and the charset,
** character by character.  A face this refuses must be one the tool's
** configuration cannot use anyway (none of the directories has one).
**
** Damaged copies of each font (truncated at many lengths, bytes flipped
** at seeded random offsets) give 0 or 1, never a crash (the ASan build
** runs this); allocation failure gives -1 and leaks nothing
** (tu_fail_loop).
*/
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <dirent.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cmocka.h>
#include <fontconfig/fontconfig.h>
#include <fontconfig/fcfreetype.h>

#include "fontmeta.h"
#include "sfnt.h"
#include "testutil.h"
#include "tool-fonts.h"


static int
by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The font files of the directories, sorted in each; their number. */
static size_t
font_files(char **out, size_t max)
{
    size_t n = 0, d;
    for (d = 0; d < TOOL_FONT_DIRS; d++) {
        DIR *dir = opendir(tool_font_dirs[d].dir);
        struct dirent *e;
        size_t first = n;
        if (dir == NULL)
            continue;
        while ((e = readdir(dir)) != NULL && n < max) {
            size_t len = strlen(e->d_name);
            if (len < 5 || (strcmp(e->d_name + len - 4, ".otf") != 0
                            && strcmp(e->d_name + len - 4, ".ttf") != 0
                            && strcmp(e->d_name + len - 4, ".ttc") != 0))
                continue;
            out[n] = malloc(strlen(tool_font_dirs[d].dir) + len + 2);
            sprintf(out[n], "%s/%s", tool_font_dirs[d].dir, e->d_name);
            n++;
        }
        closedir(dir);
        qsort(out + first, n - first, sizeof *out, by_name);
    }
    return n;
}

static void
same_charset(const char *what, const cf__fmeta_t *m, FcCharSet *cs)
{
    FcChar32 map[FC_CHARSET_MAP_SIZE], next, base, c;
    size_t count = 0, i;
    int k;
    for (i = 0; i < m->nranges; i++)
        count += m->ranges[2 * i + 1] - m->ranges[2 * i] + 1;
    if (count != FcCharSetCount(cs))
        fail_msg("%s: %zu characters, fontconfig %u", what, count,
                 FcCharSetCount(cs));
    for (base = FcCharSetFirstPage(cs, map, &next); base != FC_CHARSET_DONE;
         base = FcCharSetNextPage(cs, map, &next))
        for (k = 0; k < FC_CHARSET_MAP_SIZE; k++)
            for (c = 0; c < 32; c++)
                if ((map[k] >> c & 1) && !cf__fmeta_has(m, base + 32 * k + c))
                    fail_msg("%s: U+%04X missing", what,
                             (unsigned)(base + 32 * k + c));
}

static void
check_face(const char *file, const unsigned char *data, size_t len,
           unsigned id, FcPattern *p, size_t *faces)
{
    cf__fmeta_t m;
    char why[256], what[512];
    FcChar8 *s;
    FcCharSet *cs;
    FcRange *range;
    double d, lo, hi;
    int i, r, v;
    FcBool b;
    snprintf(what, sizeof what, "%s:%u", file, id);
    r = cf__fmeta_read(data, len, id, &m, why, sizeof why);
    if (r != 0)
        fail_msg("%s refused: %s", what, why);
    for (i = 0; FcPatternGetString(p, FC_FAMILY, i, &s) == FcResultMatch;
         i++) {
        FcChar8 *lang;
        if ((unsigned)i >= m.nfamily || strcmp((char *)s, m.family[i]) != 0)
            fail_msg("%s: family %d '%s', read '%s'", what, i, (char *)s,
                     (unsigned)i < m.nfamily ? m.family[i] : "(none)");
        if (FcPatternGetString(p, FC_FAMILYLANG, i, &lang) != FcResultMatch)
            lang = (FcChar8 *)"";
        if (strcmp((char *)lang, m.familylang[i]) != 0)
            fail_msg("%s: family %d's language '%s', read '%s'", what, i,
                     (char *)lang, m.familylang[i]);
    }
    assert_int_equal(i, m.nfamily);
    assert_int_equal(FcPatternGetString(p, FC_POSTSCRIPT_NAME, 0, &s),
                     FcResultMatch);
    if (strcmp((char *)s, m.psname) != 0)
        fail_msg("%s: PostScript name '%s', read '%s'", what, (char *)s,
                 m.psname);
    FcPatternGetInteger(p, FC_SLANT, 0, &v);
    if (v != m.slant)
        fail_msg("%s: slant %d, read %d", what, v, m.slant);
    FcPatternGetDouble(p, FC_WEIGHT, 0, &d);
    if (d != m.weight)
        fail_msg("%s: weight %g, read %g", what, d, m.weight);
    FcPatternGetDouble(p, FC_WIDTH, 0, &d);
    if (d != m.width)
        fail_msg("%s: width %g, read %g", what, d, m.width);
    FcPatternGetBool(p, FC_DECORATIVE, 0, &b);
    if ((b == FcTrue) != m.decorative)
        fail_msg("%s: decorative %d, read %d", what, b, m.decorative);
    FcPatternGetInteger(p, FC_FONTVERSION, 0, &v);
    assert_int_equal(v, m.fontversion);
    FcPatternGetString(p, FC_FONTFORMAT, 0, &s);
    assert_string_equal((char *)s, m.cff ? "CFF" : "TrueType");
    FcPatternGetInteger(p, FC_INDEX, 0, &v);
    assert_int_equal(v, m.index);
    if (FcPatternGetRange(p, FC_SIZE, 0, &range) == FcResultMatch) {
        assert_true(m.has_size);
        FcRangeGetDouble(range, &lo, &hi);
        assert_true(lo == m.size_lo && hi == m.size_hi);
    } else if (FcPatternGetDouble(p, FC_SIZE, 0, &d) == FcResultMatch) {
        assert_true(m.has_size && d == m.size_lo && d == m.size_hi);
    } else {
        assert_false(m.has_size);
    }
    FcPatternGetBool(p, FC_VARIABLE, 0, &b);
    assert_int_equal(b, FcFalse);
    assert_int_equal(FcPatternGetCharSet(p, FC_CHARSET, 0, &cs),
                     FcResultMatch);
    same_charset(what, &m, cs);
    cf__fmeta_fini(&m);
    (*faces)++;
}

/* Every face of every font against fontconfig's scan. */
static void
test_against_fontconfig(void **state)
{
    char *files[512];
    size_t n = font_files(files, 512), i, faces = 0;
    (void)state;
    if (n == 0)
        skip();
    for (i = 0; i < n; i++) {
        void *map;
        size_t len;
        int err;
        unsigned count, id;
        assert_null(cf__ff_map_file(files[i], &map, &len, &err));
        count = cf__fmeta_count(map, len);
        assert_true(count >= 1);
        for (id = 0; id < count; id++) {
            int fc_count = 0;
            FcPattern *p = FcFreeTypeQuery((const FcChar8 *)files[i], id,
                                           NULL, &fc_count);
            assert_non_null(p);
            assert_int_equal(fc_count, count);
            check_face(files[i], map, len, id, p, &faces);
            FcPatternDestroy(p);
        }
        munmap(map, len);
        free(files[i]);
    }
    printf("%zu faces of %zu files read as fontconfig reads them\n", faces,
           n);
}

/* Damaged copies: 0 or 1, never a crash or a read out of bounds. */
static void
test_damaged(void **state)
{
    char *files[512];
    size_t n = font_files(files, 512), i;
    tu_rng rng;
    (void)state;
    if (n == 0)
        skip();
    tu_rng_seed(&rng, 20261205);
    for (i = 0; i < n; i++) {
        void *map;
        size_t len, cut, k;
        int err;
        unsigned char *copy;
        assert_null(cf__ff_map_file(files[i], &map, &len, &err));
        copy = malloc(len);
        /* the small fonts whole; of a collection its first megabyte */
        for (k = 0; k < 24; k++) {
            size_t j;
            cf__fmeta_t m;
            char why[128];
            size_t use = len < (1u << 20) ? len : (1u << 20);
            memcpy(copy, map, use);
            cut = k < 12 ? (size_t)(tu_rng_u01(&rng) * (double)use) : use;
            for (j = 0; k >= 12 && j < 16; j++)
                copy[(size_t)(tu_rng_u01(&rng) * (double)use)] =
                    (unsigned char)tu_rng_next(&rng);
            if (cf__fmeta_read(copy, cut, 0, &m, why, sizeof why) == 0)
                cf__fmeta_fini(&m);
        }
        free(copy);
        munmap(map, len);
        free(files[i]);
    }
}

static const char *fail_file;

static cf_status_t
read_op(cf_diag_t *diag)
{
    void *map;
    size_t len;
    int err, r;
    cf__fmeta_t m;
    (void)diag;
    assert_null(cf__ff_map_file(fail_file, &map, &len, &err));
    r = cf__fmeta_read(map, len, 0, &m, NULL, 0);
    munmap(map, len);
    if (r < 0)
        return CF_STATUS_NO_MEMORY;
    assert_int_equal(r, 0);
    cf__fmeta_fini(&m);
    return CF_STATUS_OK;
}

static void
test_alloc_failure(void **state)
{
    (void)state;
    fail_file = "/usr/share/fonts/truetype/cmu/cmunrm.ttf";
    if (access(fail_file, R_OK) != 0)
        skip();
    tu_fail_loop("fontmeta read", read_op, false);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_against_fontconfig),
        cmocka_unit_test(test_damaged),
        cmocka_unit_test(test_alloc_failure),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
