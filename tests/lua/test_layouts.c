/*
** Layouts in the figure language: legend = "..." on the drawing methods,
** f:legend, f:inset and f:panels, whose panels are figure values taking
** every method, read back from the figure's display-list dump; a label
** outside the window; the panels' warnings.
*/
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/figure.h"
#include "script.h"

static cf_script_t *
run(const char *src)
{
    cf_script_limits_t lim = { 64u << 20, 100000000 };
    cf_script_t *s = NULL;
    assert_int_equal(cf_script_create(&lim, NULL, &s, NULL), CF_STATUS_OK);
    if (cf_script_run_string(s, src, "layouts.lua") != CF_STATUS_OK)
        fail_msg("%s", cf_script_error(s));
    return s;
}

static char *
dump(cf_script_t *s, size_t i)
{
    char *text;
    size_t size;
    cf_diag_t d;
    cf_diag_clear(&d);
    if (cf_figure_dump(cf_script_figure(s, i), NULL, &text, &size, &d)
        != CF_STATUS_OK)
        fail_msg("%s", d.msg);
    return text;
}

static size_t
count(const char *text, const char *what)
{
    size_t n = 0, len = strlen(what), i;
    for (i = 0; text[i] != '\0'; i++)
        n += strncmp(text + i, what, len) == 0;
    return n;
}

/* Entries from several kinds of method (an offset too), in order. */
static void
test_legend_entries(void **state)
{
    cf_script_t *s;
    char *t;
    (void)state;
    s = run("local f = figure{ name = 'l', legend_place = 'nw' }\n"
            "local c = bezier{ {0, 0}, {1, 2}, {2, 0} }\n"
            "f:polygon(c, { legend = 'P' })\n"
            "f:curve(c, { color = 'red', legend = 'c(t)' })\n"
            "f:points({ {1, 1} }, { marker = 'star', legend = 'Q' })\n"
            "f:curve(c:offset(0.1), { legend = 'offset' })\n"
            "assert(f:curve(c) == f)\n");
    t = dump(s, 0);
    assert_int_equal(count(t, " legend\n"), 1);
    assert_non_null(strstr(t, "text \"P\""));
    assert_true(strstr(t, "text \"P\"") < strstr(t, "text \"c(t)\""));
    assert_true(strstr(t, "text \"c(t)\"") < strstr(t, "text \"Q\""));
    assert_true(strstr(t, "text \"Q\"") < strstr(t, "text \"offset\""));
    assert_non_null(strstr(t, "marker star"));
    cf_free(t);
    cf_script_destroy(s);
}

/* Two panels sharing x: one figure is listed, its dump has both panels
** with their titles and elements; a panel's name tells its parent. */
static void
test_panels(void **state)
{
    cf_script_t *s;
    char *t;
    (void)state;
    s = run("local f = figure{ name = 'p', height = '9cm' }\n"
            "local a, b = f:panels{ rows = 2, cols = 1, share_x = true,\n"
            "                       titles = { 'curve', 'basis' } }\n"
            "assert(a:name() == 'p(a)' and b:name() == 'p(b)')\n"
            "a:curve(bezier{ {0, 0}, {1, 2}, {2, 0} }, { legend = 'c' })\n"
            "b:plot{ x = { 0, 2 }, y = { 0, 1 } }\n"
            "b:bernstein(2, 1)\n"
            "b:inset{ region = { 0.5, 0.2, 1, 0.5 },\n"
            "         at = { '10bp', '10bp', '40bp', '30bp' } }\n"
            "a, b = nil, nil\n"
            "collectgarbage()\n");
    assert_int_equal(cf_script_figure_count(s), 1);
    t = dump(s, 0);
    assert_int_equal(count(t, " panel\n"), 2);
    assert_non_null(strstr(t, "text \"curve\""));
    assert_non_null(strstr(t, "text \"basis\""));
    assert_int_equal(count(t, " legend\n"), 1);
    assert_int_equal(count(t, " inset\n"), 1);
    cf_free(t);
    cf_script_destroy(s);
}

/* A panel outlives its parent's variable: the parent stays alive. */
static void
test_panel_keeps_parent(void **state)
{
    cf_script_t *s;
    char *t;
    (void)state;
    s = run("local a\n"
            "do\n"
            "  local f = figure{ name = 'k' }\n"
            "  a = f:panels{ rows = 1, cols = 2 }\n"
            "end\n"
            "collectgarbage()\n"
            "a:curve(bezier{ {0, 0}, {1, 1} })\n");
    t = dump(s, 0);
    assert_non_null(strstr(t, "group 0 curve"));
    cf_free(t);
    cf_script_destroy(s);
}

/* The error of laying out figure i of a script. */
static void
dump_fails(cf_script_t *s, size_t i, const char *what)
{
    char *text = NULL;
    size_t size;
    cf_diag_t d;
    cf_diag_clear(&d);
    if (cf_figure_dump(cf_script_figure(s, i), NULL, &text, &size, &d)
        == CF_STATUS_OK) {
        cf_free(text);
        fail_msg("figure %zu laid out, expected \"%s\"", i, what);
    }
    if (strstr(d.msg, what) == NULL)
        fail_msg("\"%s\" not in \"%s\"", what, d.msg);
}

/* A label outside the window: drawn beside the window when the page
** holds it, refused by its text and place when too far. */
static void
test_label_outside_window(void **state)
{
    cf_script_t *s;
    char *t;
    (void)state;
    s = run("for k, x in ipairs({ 11, 100 }) do\n"
            "  local f = figure{ name = 'w' .. k, width = '6cm',\n"
            "                    height = '4cm', window = { 0, 10, 0, 10 } }\n"
            "  f:polyline({ {0, 0}, {10, 10} })\n"
            "  f:label({ x, 5 }, 'Q_1', { place = 'e' })\n"
            "end\n");
    t = dump(s, 0);
    assert_non_null(strstr(t, "text \"Q_1\""));
    cf_free(t);
    /* the error names the label's line in the script */
    dump_fails(s, 1, "label 2 \"Q_1\" (line 5) at (100, 5) is outside the "
                     "window [0, 10] x [0, 10]");
    cf_script_destroy(s);
}

/* Automatic tick labels that would stand on each other (0.2 ... 1 on a
** y axis 14 bp long) are labelled every nice multiple of the step that
** leaves them apart, every mark kept; on a roomy axis, and with a step
** given, every tick is labelled. */
static void
test_tick_labels_thinned(void **state)
{
    cf_script_t *s;
    char *t;
    static const char *const tenths[] = { "text \"0.2\"", "text \"0.4\"",
                                          "text \"0.6\"", "text \"0.8\"" };
    size_t k, marks_short, marks_tall;
    (void)state;
    s = run("local g = figure{ name = 'short', width = '6cm',\n"
            "                  height = '1.5cm' }\n"
            "g:plot{ x = {0, 10}, y = {0, 1} }\n"
            "local h = figure{ name = 'tall', width = '6cm',\n"
            "                  height = '8cm' }\n"
            "h:plot{ x = {0, 10}, y = {0, 1} }\n"
            "local k = figure{ name = 'given', width = '6cm',\n"
            "                  height = '1.5cm' }\n"
            "k:plot{ x = {0, 10}, y = {0, 1}, yticks = 0.2 }\n");
    t = dump(s, 0);
    for (k = 0; k < 4; k++)
        assert_int_equal(count(t, tenths[k]), 0);
    assert_int_equal(count(t, "text \"1\""), 1);
    /* the x axis has room: 0, 2, ..., 10 */
    assert_int_equal(count(t, "text \"4\""), 1);
    assert_int_equal(count(t, "text \"10\""), 1);
    marks_short = count(t, "move");
    cf_free(t);
    t = dump(s, 1);
    for (k = 0; k < 4; k++)
        assert_int_equal(count(t, tenths[k]), 1);
    marks_tall = count(t, "move");
    cf_free(t);
    /* the same marks, labelled or not */
    assert_int_equal(marks_short, marks_tall);
    t = dump(s, 2);
    for (k = 0; k < 4; k++)
        assert_int_equal(count(t, tenths[k]), 1);
    cf_free(t);
    cf_script_destroy(s);
}

/* A panel's warnings are its figure's, each naming the panel. */
static void
test_panel_warnings(void **state)
{
    cf_script_t *s;
    char *t;
    (void)state;
    s = run("local f = figure{ name = 'pw', height = '9cm' }\n"
            "local a, b = f:panels{ rows = 2, cols = 1 }\n"
            "a:curve(bezier{ {0, 0}, {1, 2}, {2, 0} })\n"
            "a:label({ 1, 1 }, 'ON', { place = 'center' })\n"
            "b:plot{ x = { 0, 2 }, y = { 0, 1 } }\n"
            "b:bernstein(2, 1)\n"
            "b:label({ 2.03, 0 }, 'X', { place = 'center' })\n");
    t = dump(s, 0);
    cf_free(t);
    assert_non_null(strstr(cf_figure_warnings(cf_script_figure(s, 0)),
                           "panel (a): label \"ON\" (line 4, place center) "
                           "lies on curve 1 (line 3)\n"));
    assert_non_null(strstr(cf_figure_warnings(cf_script_figure(s, 0)),
                           "panel (b): label \"X\" (line 7, place center) "
                           "lies on axes 1 (line 5)\n"));
    cf_script_destroy(s);
}

/* A faded label (its opacity, or a 3D label's point hidden) on a line is
** as unreadable as any: warned as the same label at full opacity is (its
** glyphs painted at 40 % never reached the half-inked pixels the check
** counts, and it was never warned); clear of the line, nothing. */
static void
test_faded_label_warns(void **state)
{
    static const double y[] = { 1.5, 2.6 };
    int k;
    (void)state;
    for (k = 0; k < 2; k++) {
        char src[512], *t;
        const char *w;
        cf_script_t *s;
        snprintf(src, sizeof src,
                 "local f = figure{ name = 'fade', width = '6cm',\n"
                 "  height = '4cm', window = { 0, 4, 0, 3 } }\n"
                 "f:curve(bezier{ {0, 1.5}, {4, 1.5} }, { width = 3 })\n"
                 "f:label({ 2, %g }, 'ABC', { place = 'center',\n"
                 "                           opacity = 0.4 })\n", y[k]);
        s = run(src);
        t = dump(s, 0);
        cf_free(t);
        w = cf_figure_warnings(cf_script_figure(s, 0));
        if (k == 0)
            assert_non_null(strstr(w, "label \"ABC\" (line 4, place "
                                      "center) lies on curve 1 (line 3)\n"));
        else
            assert_null(strstr(w, "lies on"));
        cf_script_destroy(s);
    }
}

/* at = "above": the inset's box above the drawing's top point; "n":
** inside the drawing, level with it. */
static void
test_inset_above(void **state)
{
    static const char *const at[] = { "above", "n" };
    int k;
    (void)state;
    for (k = 0; k < 2; k++) {
        char src[512], *t = NULL;
        const char *p;
        double mx, my, size, b[4];
        size_t n;
        cf_script_t *s;
        snprintf(src, sizeof src,
                 "local f = figure{ name = 'a' }\n"
                 "f:curve(bezier{ {0, 0}, {1, 2}, {2, 0} })\n"
                 "f:points({ {1, 1} })\n"
                 "f:inset{ region = { 0.2, 0.2, 0.6, 0.5 }, at = '%s' }\n",
                 at[k]);
        s = run(src);
        assert_int_equal(cf_figure_dump(cf_script_figure(s, 0), NULL, &t, &n,
                                        NULL), 0);
        p = strstr(t, "marker ");
        assert_non_null(p);
        assert_int_equal(sscanf(strchr(p + 7, ' '), "%lf %lf size %lf", &mx,
                                &my, &size), 3);
        p = strstr(strstr(t, "group 0 inset"), "path fill");
        assert_non_null(p);
        assert_int_equal(sscanf(strstr(p, " : R ") + 5, "%lf %lf %lf %lf",
                                &b[0], &b[1], &b[2], &b[3]), 4);
        if (k == 0 && !(b[1] + b[3] < my - 0.5 * size))
            fail_msg("at = 'above': box bottom %g, the point's top %g",
                     b[1] + b[3], my - 0.5 * size);
        if (k == 1 && !(b[1] + b[3] > my))
            fail_msg("at = 'n': box bottom %g above the point %g", b[1] + b[3],
                     my);
        cf_free(t);
        cf_script_destroy(s);
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_legend_entries),
        cmocka_unit_test(test_panels),
        cmocka_unit_test(test_panel_keeps_parent),
        cmocka_unit_test(test_label_outside_window),
        cmocka_unit_test(test_tick_labels_thinned),
        cmocka_unit_test(test_panel_warnings),
        cmocka_unit_test(test_faded_label_warns),
        cmocka_unit_test(test_inset_above),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
