/*
** A face's languages (render/fontfile/fontlangs.h) against fontconfig:
**   test_fontlangs             the orthographies of langs-table.h are
**                              fontconfig's (names, order, characters,
**                              pages); every face of the tool's font
**                              directories gets the FC_LANG of
**                              FcFreeTypeQuery; requested languages
**                              compare with each face's set as
**                              FcLangSetHasLang compares them;
**   test_fontlangs --generate  write render/fontfile/langs-table.h's
**                              text (from the installed fontconfig).
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

#include <cmocka.h>
#include <fontconfig/fontconfig.h>
#include <fontconfig/fcfreetype.h>

#include "fontlangs.h"
#include "fontmeta.h"
#include "sfnt.h"
#include "testutil.h"
#include "tool-fonts.h"

typedef struct lang_set {
    const char *name;
    unsigned pages;
    unsigned first;
    unsigned count;
} lang_set_t;

#include "langs-table.h"

/* The charset's ranges (first, last pairs) into r (cap pairs); their
** number, and its pages. */
static size_t
ranges_of(const FcCharSet *cs, uint32_t *r, size_t cap, unsigned *pages)
{
    FcChar32 map[FC_CHARSET_MAP_SIZE], next, base, c;
    size_t n = 0;
    int k;
    *pages = 0;
    for (base = FcCharSetFirstPage(cs, map, &next); base != FC_CHARSET_DONE;
         base = FcCharSetNextPage(cs, map, &next)) {
        (*pages)++;
        for (k = 0; k < FC_CHARSET_MAP_SIZE; k++)
            for (c = 0; c < 32; c++) {
                uint32_t u = base + 32 * (uint32_t)k + c;
                if (!(map[k] >> c & 1))
                    continue;
                if (n > 0 && r[2 * n - 1] + 1 == u) {
                    r[2 * n - 1] = u;
                } else if (n < cap) {
                    r[2 * n] = r[2 * n + 1] = u;
                    n++;
                }
            }
    }
    return n;
}

static size_t
fc_langs(char **names, size_t max)
{
    FcStrSet *set = FcGetLangs();
    FcStrList *l = FcStrListCreate(set);
    FcChar8 *s;
    size_t n = 0;
    while ((s = FcStrListNext(l)) != NULL && n < max)
        names[n++] = strdup((const char *)s);
    FcStrListDone(l);
    FcStrSetDestroy(set);
    return n;
}

/* The first language before i with language i's characters (i: none). */
static size_t
same_as_earlier(char **names, size_t i)
{
    size_t k;
    for (k = 0; k < i; k++)
        if (FcCharSetEqual(FcLangGetCharSet((FcChar8 *)names[k]),
                           FcLangGetCharSet((FcChar8 *)names[i])))
            break;
    return k;
}

static int
generate(void)
{
    static uint32_t r[2 * 65536];
    static size_t firsts[512];
    char *names[512];
    size_t n = fc_langs(names, 512), i, k, first = 0, col = 0;
    unsigned pages;
    printf("/* Generated from fontconfig %d.%d.%d's orthographies (FcGetLangs,"
           "\n** FcLangGetCharSet) by tests/unit/test_fontlangs.c --generate;"
           " checked\n** by the same test. */\n",
           FC_MAJOR, FC_MINOR, FC_REVISION);
    printf("static const uint32_t lang_ranges[] = {\n");
    for (i = 0; i < n; i++) {
        size_t m = ranges_of(FcLangGetCharSet((FcChar8 *)names[i]), r,
                             65536, &pages);
        if (same_as_earlier(names, i) < i)
            m = 0;   /* written once, for the first of them */
        for (k = 0; k < m; k++) {
            printf("%s0x%x, 0x%x,", col == 0 ? "    " : " ",
                   (unsigned)r[2 * k], (unsigned)r[2 * k + 1]);
            if (++col == 4) {
                printf("\n");
                col = 0;
            }
        }
    }
    printf("%s};\n", col ? "\n" : "");
    printf("static const lang_set_t lang_sets[] = {\n");
    for (i = 0; i < n; i++) {
        size_t m = ranges_of(FcLangGetCharSet((FcChar8 *)names[i]), r,
                             65536, &pages);
        /* a language whose characters are an earlier one's shares them */
        size_t k2 = same_as_earlier(names, i);
        printf("    { \"%s\", %u, %zu, %zu },\n", names[i], pages,
               k2 < i ? firsts[k2] : first, m);
        firsts[i] = k2 < i ? firsts[k2] : first;
        if (k2 == i)
            first += m;
    }
    for (i = 0; i < n; i++)
        free(names[i]);
    printf("};\n");
    return 0;
}

/* The table is fontconfig's. */
static void
test_table(void **state)
{
    static uint32_t r[2 * 65536];
    char *names[512];
    size_t n = fc_langs(names, 512), i;
    (void)state;
    assert_int_equal(n, cf__flangs_count());
    for (i = 0; i < n; i++) {
        const FcCharSet *cs = FcLangGetCharSet((FcChar8 *)names[i]);
        cf__fmeta_t m;
        cf__flangset_t ls;
        unsigned pages;
        assert_string_equal(names[i], cf__flangs_name(i));
        assert_string_equal(names[i], lang_sets[i].name);
        m.nranges = ranges_of(cs, r, 65536, &pages);
        assert_int_equal(pages, lang_sets[i].pages);
        assert_int_equal(m.nranges, lang_sets[i].count);
        assert_memory_equal(r, lang_ranges + 2 * lang_sets[i].first,
                            2 * m.nranges * sizeof *r);
        /* a face whose charset is exactly the language's has it */
        memset(&m, 0, sizeof m);
        m.nranges = ranges_of(cs, r, 65536, &pages);
        m.ranges = r;
        cf__flangs_of(&m, &ls);
        assert_true(ls.bits[i / 32] >> (i % 32) & 1);
        free(names[i]);
    }
}


static const char *const asked[] = {
    "en", "en-us", "en-gb", "ru", "ru-ru", "uk", "bg", "sr", "zh-cn", "zh-tw",
    "zh-hk", "zh-sg", "zh", "ja", "ja-jp", "ko", "sl", "sl-si", "cs", "sk",
    "de", "de-at", "fr", "pl", "el", "he", "ar", "hi", "vi", "tr", "c",
    "posix", "", "und", "und-zsye", "und-zmth", "pt-br", "x", "q", "zz",
    "zu", "aa", "mn-mn", "mn-cn", "ku-tr", "pap-an", "sr-latn", "kk",
};

/* Every face's set is fontconfig's, and compares as fontconfig's. */
static void
test_faces(void **state)
{
    size_t d, faces = 0;
    (void)state;
    for (d = 0; d < TOOL_FONT_DIRS; d++) {
        DIR *dir = opendir(tool_font_dirs[d].dir);
        struct dirent *e;
        if (dir == NULL)
            continue;
        while ((e = readdir(dir)) != NULL) {
            char path[1024];
            void *map;
            size_t len, i;
            int err, count = 0;
            unsigned id, nfaces;
            if (e->d_name[0] == '.')
                continue;
            snprintf(path, sizeof path, "%s/%s", tool_font_dirs[d].dir, e->d_name);
            assert_null(cf__ff_map_file(path, &map, &len, &err));
            nfaces = cf__fmeta_count(map, len);
            for (id = 0; id < nfaces; id++) {
                FcPattern *p = FcFreeTypeQuery((FcChar8 *)path, id, NULL,
                                               &count);
                FcLangSet *fls;
                cf__fmeta_t m;
                cf__flangset_t ls;
                assert_int_equal(cf__fmeta_read(map, len, id, &m, NULL, 0),
                                 0);
                assert_int_equal(FcPatternGetLangSet(p, FC_LANG, 0, &fls),
                                 FcResultMatch);
                cf__flangs_of(&m, &ls);
                for (i = 0; i < cf__flangs_count(); i++) {
                    bool fc = FcLangSetHasLang(
                                  fls, (FcChar8 *)cf__flangs_name(i))
                              == FcLangEqual;
                    bool own = ls.bits[i / 32] >> (i % 32) & 1;
                    if (fc != own)
                        fail_msg("%s:%u: %s %s", path, id,
                                 cf__flangs_name(i),
                                 fc ? "missing" : "not fontconfig's");
                }
                for (i = 0; i < sizeof asked / sizeof asked[0]; i++) {
                    int fc = (int)FcLangSetHasLang(fls,
                                                   (FcChar8 *)asked[i]);
                    int own = cf__flangs_has(&ls, asked[i]);
                    if (fc != own)
                        fail_msg("%s:%u: '%s' compares %d, fontconfig %d",
                                 path, id, asked[i], own, fc);
                }
                cf__fmeta_fini(&m);
                FcPatternDestroy(p);
                faces++;
            }
            munmap(map, len);
        }
        closedir(dir);
    }
    if (faces == 0)
        skip();
    printf("%zu faces: fontconfig's languages\n", faces);
}

int
main(int argc, char **argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_table),
        cmocka_unit_test(test_faces),
    };
    if (argc > 1 && strcmp(argv[1], "--generate") == 0)
        return generate();
    return cmocka_run_group_tests(tests, NULL, NULL);
}
