/*
** The Unicode table of the shaper's fast path (render/fontfile/uprops.h)
** against HarfBuzz: every code point it covers has HarfBuzz's general
** category and script, every other one is outside it; the general
** category numbers it names are HarfBuzz's.
**   test_uprops             check
**   test_uprops --generate  write render/fontfile/uprops-table.h's text
**                           (from the HarfBuzz linked) to stdout
*/
#include <stdio.h>
#include <string.h>

#include <hb.h>

#include "uprops.h"

static const uint32_t ranges[][2] = {
    { 0x0000, 0x052F }, { 0x1E00, 0x1FFF }, { 0x2000, 0x2BFF },
    { 0x3000, 0x30FF }, { 0x3100, 0x312F }, { 0x31A0, 0x31FF },
    { 0x3400, 0x4DBF }, { 0x4E00, 0x9FFF }, { 0xFF00, 0xFFEF },
    { 0x1D400, 0x1D7FF }
};
#define NRANGES (sizeof ranges / sizeof ranges[0])

static int
generate(void)
{
    hb_unicode_funcs_t *u = hb_unicode_funcs_get_default();
    uint32_t scripts[256], prev_end = 0;
    unsigned ns = 0, r;
    printf("/* Generated from HarfBuzz %s's hb_unicode_general_category "
           "and\n** hb_unicode_script by tests/unit/test_uprops.c "
           "--generate; checked by\n** the same test over every code point "
           "it covers. */\n", hb_version_string());
    printf("static const uprops_run_t uprops_runs[] = {\n");
    for (r = 0; r < NRANGES; r++) {
        int last_gc = -1;
        uint32_t last_s = 0, c;
        if (r > 0 && prev_end + 1 != ranges[r][0])
            printf("    { 0x%05X, 0xFF, 0 },\n", (unsigned)prev_end + 1);
        for (c = ranges[r][0]; c <= ranges[r][1]; c++) {
            int gc = (int)hb_unicode_general_category(u, c);
            uint32_t s = (uint32_t)hb_unicode_script(u, c);
            unsigned si;
            for (si = 0; si < ns && scripts[si] != s; si++)
                ;
            if (si == ns) {
                if (ns == 256)
                    return 1;
                scripts[ns++] = s;
            }
            if (gc != last_gc || s != last_s) {
                printf("    { 0x%05X, %d, %u },\n", (unsigned)c, gc, si);
                last_gc = gc;
                last_s = s;
            }
        }
        prev_end = ranges[r][1];
    }
    printf("    { 0x%05X, 0xFF, 0 }\n};\n", (unsigned)prev_end + 1);
    printf("static const uint32_t uprops_scripts[] = {\n");
    for (r = 0; r < ns; r++)
        printf("    0x%08Xu,   /* %c%c%c%c */\n", (unsigned)scripts[r],
               (char)(scripts[r] >> 24), (char)(scripts[r] >> 16),
               (char)(scripts[r] >> 8), (char)scripts[r]);
    printf("};\n");
    return 0;
}

int
main(int argc, char **argv)
{
    hb_unicode_funcs_t *u = hb_unicode_funcs_get_default();
    uint32_t c, script;
    unsigned gc, r;
    long covered = 0, wrong = 0;
    if (argc > 1 && strcmp(argv[1], "--generate") == 0)
        return generate();
    if (CF__GC_CONTROL != HB_UNICODE_GENERAL_CATEGORY_CONTROL
        || CF__GC_SPACING_MARK != HB_UNICODE_GENERAL_CATEGORY_SPACING_MARK
        || CF__GC_ENCLOSING_MARK
               != HB_UNICODE_GENERAL_CATEGORY_ENCLOSING_MARK
        || CF__GC_NON_SPACING_MARK
               != HB_UNICODE_GENERAL_CATEGORY_NON_SPACING_MARK
        || CF__GC_SPACE_SEPARATOR
               != HB_UNICODE_GENERAL_CATEGORY_SPACE_SEPARATOR) {
        printf("FAIL: general category numbers are not HarfBuzz's\n");
        return 1;
    }
    for (c = 0; c <= 0x10FFFF; c++) {
        bool in = false, has = cf__uprops(c, &gc, &script);
        for (r = 0; r < NRANGES; r++)
            in = in || (c >= ranges[r][0] && c <= ranges[r][1]);
        if (has != in) {
            printf("FAIL: U+%04X %s the table\n", (unsigned)c,
                   has ? "in" : "not in");
            wrong++;
            continue;
        }
        if (!in)
            continue;
        covered++;
        if (gc != (unsigned)hb_unicode_general_category(u, c)
            || script != (uint32_t)hb_unicode_script(u, c)) {
            printf("FAIL: U+%04X: %u %08X, HarfBuzz %u %08X\n", (unsigned)c,
                   gc, (unsigned)script,
                   (unsigned)hb_unicode_general_category(u, c),
                   (unsigned)hb_unicode_script(u, c));
            wrong++;
        }
    }
    printf("%ld code points covered, as HarfBuzz %s has them; %ld wrong\n",
           covered, hb_version_string(), wrong);
    return wrong != 0;
}
