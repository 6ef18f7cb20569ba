/* The colours of every shipped figure (the scripts of figures/ and of its
** directories: interactive, surfaces, examples, sliders at their default
** values) stay apart
** under protanopia, deuteranopia and tritanopia: the colour check at
** a CIEDE2000 of 10 (docs/accessibility.md) finds no two paints that only
** colour tells apart and that such a vision brings closer: any clash
** fails (a script whose own colours clash sets its elements apart by a
** second channel, dash or marker, as the Oražem figures do with
** theme{ redundant = true }).  Greyscale clashes are counted and printed,
** not failed (most scripts' own colours; `curvefig check` names them). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "colour-check.h"
#include "curvefig/figure.h"
#include "script.h"
#include "shipped.h"

typedef struct tally {
    size_t clashes, greyscale;
} tally_t;

static int
check_figure(void *ctx, const char *script, const char *name,
             cf_figure_t *fig)
{
    tally_t *t = ctx;
    cf__colour_report_t r;
    int faults = 0;
    assert_int_equal(cf__colour_report(fig, 10.0, &r, NULL), 0);
    for (size_t k = 0; k < r.count; k++) {
        const cf__colour_clash_t *c = &r.clashes[k];
        if (c->vision == CF__VISION_GREY) {
            t->greyscale++;
            continue;
        }
        print_message("%s: figure '%s': #%06x and #%06x under %s\n", script,
                      name, c->a.rgb, c->b.rgb, cf__vision_name(c->vision));
        t->clashes++;
        faults++;
    }
    cf__colour_report_fini(&r);
    return faults;
}

static void
test_shipped(void **state)
{
    tally_t t;
    size_t figures, failed;
    (void)state;
    memset(&t, 0, sizeof t);
    figures = tu_each_shipped_figure_all(CF_SOURCE_ROOT, check_figure, &t,
                                         &failed);
    print_message("%zu figures; %zu colour clashes under a deficiency; "
                  "%zu in greyscale\n", figures, t.clashes, t.greyscale);
    assert_true(figures >= 100);
    assert_int_equal(t.clashes, 0);
    assert_int_equal(failed, 0);
}

/* A surface's de Casteljau scheme whose levels alternate red and green
** (#d62728, #2ca02c: 4.6 apart under deuteranopia): a clash; with the
** theme's redundant = true its levels differ in dash and marker
** (cf_theme_level_style), and none is left. */
static void
test_surface_scheme_redundant(void **state)
{
    (void)state;
    for (int redundant = 0; redundant < 2; redundant++) {
        char code[1024], *json;
        size_t size;
        cf_script_t *sc = NULL;
        snprintf(code, sizeof code,
                 "theme{ redundant = %s }\n"
                 "local s = bezier_surface{ points = {\n"
                 "  { {0, 0, 0}, {0, 1, 1}, {0, 2, 0} },\n"
                 "  { {1, 0, 1}, {1, 1, 2}, {1, 2, 1} },\n"
                 "  { {2, 0, 0}, {2, 1, 1}, {2, 2, 0} } } }\n"
                 "local f = figure{ name = 's', width = '6cm', "
                 "height = '5cm', view = { 30, 20 } }\n"
                 "f:decasteljau_surface(s, 0.4, 0.6, { colors = { "
                 "'#d62728', '#2ca02c', '#d62728', '#2ca02c' } })\n",
                 redundant ? "true" : "false");
        assert_int_equal(cf_script_create(NULL, NULL, &sc, NULL), 0);
        if (cf_script_run_string(sc, code, "scheme.lua") != CF_STATUS_OK)
            fail_msg("%s", cf_script_error(sc));
        assert_int_equal(cf_script_figure_count(sc), 1);
        assert_int_equal(cf_figure_colour_check(cf_script_figure(sc, 0),
                                                10.0, &json, &size, NULL),
                         0);
        if (redundant)
            assert_null(strstr(json, "\"vision\""));
        else
            assert_non_null(strstr(json, "{\"vision\": \"deuteranopia\""));
        cf_free(json);
        cf_script_destroy(sc);
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shipped),
        cmocka_unit_test(test_surface_scheme_redundant),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
