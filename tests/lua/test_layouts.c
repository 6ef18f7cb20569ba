/*
** Layouts in the figure language: legend = "..." on the drawing methods,
** f:legend, f:inset and f:panels, whose panels are figure values taking
** every method, read back from the figure's display-list dump.
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

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_legend_entries),
        cmocka_unit_test(test_panels),
        cmocka_unit_test(test_panel_keeps_parent),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
