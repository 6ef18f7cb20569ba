/* Labels laid out in linear time: a run that grows a character at a time
** is shaped again only at its tail, and the label's runs, their widths
** and the places of what follows them are those of the whole run shaped
** at once. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>
#include <pango/pangocairo.h>

#include "curvefig/label.h"
#include "label-private.h"
#include "testutil.h"

#define SIZE 10.0

/* The label of prefix, then unit to n bytes in all (whole units), then
** suffix (static storage), laid out at SIZE. */
static cf_label_t *
label_of(const char *prefix, const char *unit, size_t n, const char *suffix,
         const char **text)
{
    static char s[CF_LABEL_MAX_BYTES + 1];
    size_t len = (size_t)snprintf(s, sizeof s, "%s", prefix);
    size_t u = strlen(unit), tail = strlen(suffix);
    cf_label_t *lab = NULL;
    cf_diag_t d;
    while (len + u + tail <= n && len + u + tail < sizeof s) {
        memcpy(s + len, unit, u);
        len += u;
    }
    memcpy(s + len, suffix, tail + 1);
    *text = s;
    cf_diag_clear(&d);
    assert_int_equal(cf_label_create(s, NULL, SIZE, &lab, &d), CF_STATUS_OK);
    return lab;
}

/* The bytes shaped grow linearly with the label: at most 200 a byte of
** label (the tail of 16 to 32 bytes and its move every 16 bytes, then
** the whole run once), where shaping the run again at each character
** costs n^2 / 2 (500,000 bytes for 1000). */
static void
test_shaping_is_linear(void **state)
{
    static const char *const units[][3] = {
        { "", "a", "" }, { "", "ab ", "" }, { "$", "x", "$" },
        { "$", "xy", "^2$" }, { "", "AVAWAY office To ", "" },
        { "", "\xc3\xa9t\xc3\xa9 ", "" },
    };
    (void)state;
    for (size_t u = 0; u < sizeof units / sizeof units[0]; u++) {
        for (size_t n = 100; n <= CF_LABEL_MAX_BYTES; n *= 3) {
            const char *s;
            cf_label_t *lab = label_of(units[u][0], units[u][1], n,
                                       units[u][2], &s);
            size_t shaped = cf__label_shaped_bytes(lab), len = strlen(s);
            if (shaped > 200 * len + 1000)
                fail_msg("label of %zu bytes (\"%.40s...\") shaped %zu "
                         "bytes: more than 200 a byte", len, s, shaped);
            cf_label_destroy(lab);
        }
    }
}

/* A long run followed by a script: the script starts where the whole run,
** shaped at once, ends (its width as pango gives it for the run's text)
** plus the same italic correction as after a short run: the places that
** the tail measurement gives equal those of shaping the run whole. */
static void
test_places_after_long_runs(void **state)
{
    static const char *const units[] = { "x", "AV", "fi", "Wa" };
    (void)state;
    for (size_t u = 0; u < sizeof units / sizeof units[0]; u++) {
        const char *text;
        cf_label_t *a = label_of("$", units[u], 8, "^2$", &text);
        cf_label_t *b = label_of("$", units[u], 600, "^2$", &text);
        size_t na = cf_label_box_count(a), nb = cf_label_box_count(b);
        cf_label_box_t ra, sa, rb, sb;
        assert_int_equal(na, 2);
        assert_int_equal(nb, 2);
        ra = *cf_label_get_box(a, 0);
        sa = *cf_label_get_box(a, 1);
        rb = *cf_label_get_box(b, 0);
        sb = *cf_label_get_box(b, 1);
        /* the gap between the run's end and the script is the same (the
        ** italic correction of the same last letter), to pango's unit */
        assert_true(fabs((sb.x - (rb.x + rb.width)) - (sa.x - (ra.x + ra.width)))
                    < 1.0 / PANGO_SCALE);
        cf_label_destroy(a);
        cf_label_destroy(b);
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shaping_is_linear),
        cmocka_unit_test(test_places_after_long_runs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
