/* The colours of every shipped figure (the scripts of figures/ and of its
** directories: interactive, surfaces, examples, sliders at their default
** values) stay apart
** under protanopia, deuteranopia and tritanopia: cf_figure_colour_check at
** a CIEDE2000 of 10 (docs/accessibility.md) finds no two paints that only
** colour tells apart and that such a vision brings closer.  The clashes
** of colours that a script sets itself and that are not fixed yet are
** listed below by figure and colours, each one still expected (a fixed
** one must leave the list); greyscale clashes are counted and printed,
** not failed (most scripts' own colours; `curvefig check` names them). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/figure.h"
#include "shipped.h"

/* figure, vision, the two colours (either order): clashes of a script's
** own colours, to be fixed in the script */
static const char *const known[][4] = {
    { "decasteljau", "deuteranopia", "#f28e1c", "#e8b800" },
    { "decasteljau", "protanopia", "#f28e1c", "#2ca02c" },
    { "decasteljau", "protanopia", "#f28e1c", "#e8b800" },
    { "markova-3.9", "protanopia", "#d62728", "#1b7837" },
    { "orazem-decasteljau", "deuteranopia", "#f28e1c", "#e8b800" },
    { "orazem-decasteljau", "protanopia", "#f28e1c", "#2ca02c" },
    { "orazem-decasteljau", "protanopia", "#f28e1c", "#e8b800" },
    { "overlay-decasteljau", "deuteranopia", "#f28e1c", "#e8b800" },
    { "overlay-decasteljau", "protanopia", "#f28e1c", "#e8b800" },
};
#define NKNOWN (sizeof known / sizeof known[0])

typedef struct tally {
    size_t unexpected, greyscale;
    bool seen[NKNOWN];
} tally_t;

/* The text of "key": "VALUE" after p into out. */
static const char *
value(const char *p, const char *key, char *out, size_t n)
{
    char pat[32];
    const char *s, *e;
    snprintf(pat, sizeof pat, "\"%s\": \"", key);
    s = strstr(p, pat);
    if (s == NULL)
        return NULL;
    s += strlen(pat);
    e = strchr(s, '"');
    snprintf(out, n, "%.*s", (int)(e - s), s);
    return e;
}

static int
check_figure(void *ctx, const char *script, const char *name,
             cf_figure_t *fig)
{
    tally_t *t = ctx;
    char *json, vision[32], a[16], b[16];
    size_t size;
    int faults = 0;
    const char *p;
    assert_int_equal(cf_figure_colour_check(fig, 10.0, &json, &size, NULL),
                     0);
    for (p = json; (p = value(p, "vision", vision, sizeof vision)) != NULL;) {
        bool expected = false;
        p = value(p, "color", a, sizeof a);
        p = value(p, "color", b, sizeof b);
        assert_non_null(p);
        if (strcmp(vision, "greyscale") == 0) {
            t->greyscale++;
            continue;
        }
        for (size_t k = 0; k < NKNOWN; k++)
            if (strcmp(known[k][0], name) == 0
                && strcmp(known[k][1], vision) == 0
                && ((strcmp(known[k][2], a) == 0
                     && strcmp(known[k][3], b) == 0)
                    || (strcmp(known[k][2], b) == 0
                        && strcmp(known[k][3], a) == 0))) {
                t->seen[k] = expected = true;
            }
        if (!expected) {
            print_message("%s: figure '%s': %s and %s under %s\n", script,
                          name, a, b, vision);
            t->unexpected++;
            faults++;
        }
    }
    cf_free(json);
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
    print_message("%zu figures; %zu colour clashes under a deficiency "
                  "beyond the %zu known; %zu in greyscale\n", figures,
                  t.unexpected, NKNOWN, t.greyscale);
    assert_true(figures >= 60);
    assert_int_equal(t.unexpected, 0);
    for (size_t k = 0; k < NKNOWN; k++) {
        if (!t.seen[k])
            print_message("fixed: %s %s %s %s: leave it out of the list\n",
                          known[k][0], known[k][1], known[k][2], known[k][3]);
        assert_true(t.seen[k]);
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shipped),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
