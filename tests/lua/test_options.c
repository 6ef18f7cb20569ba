/*
** The figure language's options mean what their names say, in-process
** (render/lua/script.h): a list of points with weights is rational; every
** labelling method honours label_place and label_style alike; knot-label
** callbacks receive the multiplicity; a generated subscript of several
** digits is grouped.  Figures are compared as rendered SVG, and two
** spellings of one figure must give the same bytes.
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

static FILE *sink;

/* Run code, which must succeed; returns the SVG of its first figure
** (cf_free it). */
static char *
svg_of(const char *code)
{
    cf_script_t *s = NULL;
    cf_diag_t diag;
    unsigned char *out = NULL;
    size_t len = 0;
    char *text;
    cf_diag_clear(&diag);
    assert_int_equal(cf_script_create(NULL, sink, &s, &diag), CF_STATUS_OK);
    if (cf_script_run_string(s, code, "opt.lua") != CF_STATUS_OK)
        fail_msg("%s", cf_script_error(s));
    assert_true(cf_script_figure_count(s) >= 1);
    assert_int_equal(cf_figure_render(cf_script_figure(s, 0), CF_FORMAT_SVG,
                                      NULL, &out, &len, &diag),
                     CF_STATUS_OK);
    text = malloc(len + 1);
    assert_non_null(text);
    memcpy(text, out, len);
    text[len] = '\0';
    cf_free(out);
    cf_script_destroy(s);
    return text;
}

/* The SVG of prelude .. body (body a format of one %s: the options). */
static char *
svg_with(const char *prelude, const char *body, const char *options)
{
    char code[4096];
    char line[1024];
    snprintf(line, sizeof line, body, options);
    snprintf(code, sizeof code, "%s\n%s\n", prelude, line);
    return svg_of(code);
}

static void
assert_same(const char *prelude, const char *body, const char *a,
            const char *b)
{
    char *x = svg_with(prelude, body, a), *y = svg_with(prelude, body, b);
    if (strcmp(x, y) != 0)
        fail_msg("%s and %s draw different figures", a, b);
    free(x);
    free(y);
}

static void
assert_differ(const char *prelude, const char *body, const char *a,
              const char *b)
{
    char *x = svg_with(prelude, body, a), *y = svg_with(prelude, body, b);
    if (strcmp(x, y) == 0)
        fail_msg("%s and %s draw the same figure", a, b);
    free(x);
    free(y);
}

static void
run_ok(const char *code)
{
    cf_script_t *s = NULL;
    cf_diag_t diag;
    cf_diag_clear(&diag);
    assert_int_equal(cf_script_create(NULL, sink, &s, &diag), CF_STATUS_OK);
    if (cf_script_run_string(s, code, "opt.lua") != CF_STATUS_OK)
        fail_msg("%s", cf_script_error(s));
    cf_script_destroy(s);
}

/* bezier{ P0, P1, P2, weights = {...} } is the rational curve of
** bezier{ points = {...}, weights = {...} }: at t = 1/2 the weighted
** Bernstein values are 1/4, 1, 1/4 (sum 3/2), so the point is
** x = (0 + 1 + 2/4) / (3/2) = 1, y = 2 / (3/2) = 4/3, not the
** polynomial's (1, 1). */
static void
test_list_with_weights(void **state)
{
    (void)state;
    run_ok("local a = bezier{ {0, 0}, {1, 2}, {2, 0}, weights = {1, 2, 1} }\n"
           "local b = bezier{ points = { {0, 0}, {1, 2}, {2, 0} },\n"
           "                  weights = {1, 2, 1} }\n"
           "assert(a:is_rational() and b:is_rational())\n"
           "local p, q = a:eval(0.5), b:eval(0.5)\n"
           "assert(math.abs(p[1] - 1) < 1e-15, p[1])\n"
           "assert(math.abs(p[2] - 4 / 3) < 1e-15, p[2])\n"
           "assert(p[1] == q[1] and p[2] == q[2])\n");
}

static const char knots_prelude[] =
    "local f = figure{ name = 'k' }\n"
    "local s = bspline{ degree = 3, points = { {0, 0}, {1, 2}, {2, 0},\n"
    "  {3, 2}, {4, 0}, {5, 2} } }";

/* label_place on f:knots is honoured (as on polygon and points): it draws
** what label_style's place draws, and another place draws otherwise. */
static void
test_knots_label_place(void **state)
{
    const char *body = "f:knots(s, { labels = 'u_%%d', %s })";
    (void)state;
    assert_same(knots_prelude, body, "label_place = 's'",
                "label_style = { place = 's' }");
    assert_differ(knots_prelude, body, "label_place = 's'",
                  "label_place = 'n'");
    /* a table of places, one per distinct knot, and a function */
    assert_same(knots_prelude, body,
                "label_place = { 's', 'n', 's', 'n' }",
                "label_place = function(i, m, x, y) "
                "return (i == 0 or i == 5) and 's' or 'n' end");
}

/* The nets of de Casteljau and de Boor take the same label options. */
static void
test_net_label_place(void **state)
{
    const char *prelude = "local f = figure{ name = 'n' }\n"
                          "local c = bezier{ {0, 0}, {1, 2}, {2, 0} }";
    const char *body = "f:decasteljau(c, 0.5, { labels = 'P_{%%d,%%d}', "
                       "%s })";
    (void)state;
    assert_same(prelude, body, "label_place = 'w'",
                "label_style = { place = 'w' }");
    assert_differ(prelude, body, "label_place = 'w'", "label_place = 'e'");
    /* label_start shifts the first integer, as on polygons */
    assert_same(prelude, body, "label_start = 1",
                "labels = function(i, j) return 'P_{' .. (i + 1) .. ',' "
                ".. j .. '}' end");
}

/* An arrow's label takes label_style and label_place. */
static void
test_arrow_label_style(void **state)
{
    const char *prelude = "local f = figure{ name = 'a' }";
    const char *body = "f:arrow({0, 0}, {1, 1}, { label = 'v', %s })";
    (void)state;
    assert_differ(prelude, body, "label_style = { font_size = 20 }",
                  "label_style = {}");
    assert_same(prelude, body, "label_place = 'sw'",
                "label_style = { place = 'sw' }");
}

/* The knot-label callback gets (index of the first copy, multiplicity):
** clamped cubic with 6 points, knots 0 0 0 0 1/3 2/3 1 1 1 1. */
static void
test_knot_multiplicity(void **state)
{
    (void)state;
    run_ok("local f = figure{ name = 'm' }\n"
           "local s = bspline{ degree = 3, points = { {0, 0}, {1, 2},\n"
           "  {2, 0}, {3, 2}, {4, 0}, {5, 2} } }\n"
           "local got = {}\n"
           "f:knots(s, { labels = function(i, m)\n"
           "  got[#got + 1] = i .. ':' .. m return nil end })\n"
           "assert(table.concat(got, ' ') == '0:4 4:1 5:1 6:4',\n"
           "       table.concat(got, ' '))\n"
           "local axis = {}\n"
           "f:plot{ x = {0, 1}, y = {0, 1}, knots = {0, 0, 0.5, 1},\n"
           "  knot_labels = function(i, m) axis[#axis + 1] = i .. ':' .. m\n"
           "    return 'u' end }\n"
           "assert(table.concat(axis, ' ') == '0:2 1:2 2:1 3:1',\n"
           "       table.concat(axis, ' '))\n");
}

/* "u_%d" of 10 and 11 is u_{10}, u_{11}: the figure drawn with the format
** is the one drawn with braces written out, and not the one drawn with
** u_10 (TeX's u_1 followed by 0). */
static void
test_subscript_grouped(void **state)
{
    const char *prelude =
        "local f = figure{ name = 'g', width = '12cm' }\n"
        "local P = {}\n"
        "for i = 0, 11 do P[#P + 1] = { i, i % 2 } end";
    const char *body = "f:points(P, { %s })";
    (void)state;
    assert_same(prelude, body, "labels = 'u_%d'",
                "labels = function(i) return 'u_{' .. i .. '}' end");
    assert_differ(prelude, body, "labels = 'u_%d'",
                  "labels = function(i) return 'u_' .. i end");
    /* superscripts too; one digit is left as it is; %% stays a percent */
    assert_same(prelude, body, "labels = 'w^%d'",
                "labels = function(i) return i < 10 and 'w^' .. i or "
                "'w^{' .. i .. '}' end");
    assert_same(prelude, body, "labels = '%d%%'",
                "labels = function(i) return i .. '%' end");
}

/* clip = true cuts off what a fixed page cannot hold, where without it
** the figure is refused (the bad-input case page-ink-outside). */
static void
test_clip(void **state)
{
    char *svg;
    (void)state;
    svg = svg_of("local f = figure{ name = 'c', width = '1cm', height = "
                 "'1cm', margin = '1mm', window = {0, 1, 0, 1},\n"
                 "  clip = true }\n"
                 "f:label({0.9, 0.5}, 'P_0 = start')\n");
    assert_non_null(strstr(svg, "<svg"));
    free(svg);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_list_with_weights),
        cmocka_unit_test(test_knots_label_place),
        cmocka_unit_test(test_net_label_place),
        cmocka_unit_test(test_arrow_label_style),
        cmocka_unit_test(test_knot_multiplicity),
        cmocka_unit_test(test_subscript_grouped),
        cmocka_unit_test(test_clip),
    };
    int rc;
    sink = fopen("/dev/null", "w");
    if (sink == NULL)
        return 1;
    rc = cmocka_run_group_tests(tests, NULL, NULL);
    fclose(sink);
    return rc;
}
