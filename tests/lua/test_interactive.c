/*
** Interactive figures in-process: slider{} and points{} take their
** defaults with no values and the host's values clamped, snapped and
** constrained otherwise, rounded to the decimals of the step or grid; bad declarations fail naming file, line and key;
** the values' JSON is read strictly; cf_interactive_run's handles lie
** where the figure's own drawing puts the points (the display list, read
** apart from the map); its Lua text reads back as the same values; a
** page's "@view:NAME" turns a 3D figure.
*/
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/figure.h"
#include "interactive.h"
#include "params.h"
#include "script.h"

static FILE *sink;

/* Run code with the values' JSON; returns what it printed (malloc'd). */
static char *
printed(const char *code, const char *values)
{
    FILE *out = tmpfile();
    cf_script_t *s = NULL;
    cf_diag_t diag;
    char *text;
    long n;
    char err[200];
    assert_non_null(out);
    cf_diag_clear(&diag);
    assert_int_equal(cf_script_create(NULL, out, &s, &diag), CF_STATUS_OK);
    if (values != NULL)
        assert_int_equal(cf__params_give_json(cf_script_params(s), values,
                                              strlen(values), err,
                                              sizeof err), 0);
    if (cf_script_run_string(s, code, "inter.lua") != CF_STATUS_OK)
        fail_msg("%s", cf_script_error(s));
    cf_script_destroy(s);
    fflush(out);
    n = ftell(out);
    text = calloc((size_t)n + 1, 1);
    assert_non_null(text);
    rewind(out);
    assert_int_equal(fread(text, 1, (size_t)n, out), (size_t)n);
    fclose(out);
    return text;
}

static const char decls[] =
    "local t = slider{ name = 't', min = 0, max = 1, default = 0.25, "
    "step = 0.1 }\n"
    "local g = points{ name = 'G', default = { {0, 0}, {1, 1} }, "
    "constrain = { grid = 0.5 } }\n"
    "local l = points{ name = 'L', default = { {0, 0} }, "
    "constrain = { line = { {0, 0}, {1, 1} } } }\n"
    "local c = slider{ name = 'c', min = -1, max = 1 }\n"
    "print(string.format('%.12g %.12g %.12g %.12g %.12g %.12g %.12g', t, "
    "g[1][1], g[1][2], g[2][1], l[1][1], l[1][2], c))\n";

static void
test_defaults(void **state)
{
    char *out = printed(decls, NULL);
    (void)state;
    /* c has no default: its min */
    assert_string_equal(out, "0.25 0 0 1 0 0 -1\n");
    free(out);
}

static void
test_given_values(void **state)
{
    char *out;
    (void)state;
    /* t snapped to the step, G to the grid, L onto the line y = x */
    out = printed(decls, "{ \"t\": 0.33, \"G\": [[0.3, 0.74], [1.2, 2]], "
                         "\"L\": [[2, 0]], \"c\": 0.5 }");
    assert_string_equal(out, "0.3 0.5 0.5 1 1 1 0.5\n");
    free(out);
    /* clamped to the range; a list of another length keeps the defaults;
    ** a value for no parameter is ignored */
    out = printed(decls, "{\"t\": 7, \"G\": [[5, 5]], \"c\": -9, \"x\": 1}");
    assert_string_equal(out, "1 0 0 1 0 0 -1\n");
    free(out);
}

/* Snapped values are the decimals the step and the grid are written
** with: three steps of 0.1 are 0.3 (not 0.30000000000000004), seven of
** 0.1 on a grid 0.7; a log slider is declared so in the JSON. */
static void
test_values_rounded(void **state)
{
    const char *code =
        "local t = slider{ name = 't', min = 0, max = 1, step = 0.1 }\n"
        "local w = slider{ name = 'w', min = 1, max = 100, step = 0.01,\n"
        "                  scale = 'log' }\n"
        "local G = points{ name = 'G', default = { {0, 0} },\n"
        "                  constrain = { grid = 0.1 } }\n"
        "print(t == 0.3, G[1][1] == 0.7, G[1][2] == 0.3, w == 3.16)\n";
    const char *values = "{\"t\": 0.31, \"w\": 3.1622776601683795, "
                         "\"G\": [[0.69, 0.33]]}";
    char *out = printed(code, values), *json = NULL;
    size_t len = 0;
    (void)state;
    assert_string_equal(out, "true\ttrue\ttrue\ttrue\n");
    free(out);
    assert_int_equal(cf_interactive_run(code, "inter.lua", values,
                                        strlen(values), NULL, sink, &json,
                                        &len),
                     CF_STATUS_OK);
    assert_non_null(strstr(json, "\"name\": \"w\", \"label\": \"w\", "
                                 "\"min\": 1, \"max\": 100, \"step\": 0.01, "
                                 "\"scale\": \"log\""));
    assert_non_null(strstr(json, "t = 0.3,"));
    free(json);
}

/* Steps and grids finer than 1e-6, and lines through points near the
** largest double: a step of 1e-7 made every value 0 (its decimals were
** taken for 0), a step or grid of 1e-320 made every value and point 0
** (v / step overflowed), a line from -1e308 to 1e308 made every dragged
** point 0 (its direction's square overflowed).  The values checked
** independently: multiples of the step to its decimals, the projection
** onto y = x by hand. */
static void
test_fine_steps_and_far_lines(void **state)
{
    const char *code =
        "local a = slider{ name = 'a', min = 0, max = 1e-5, step = 1e-7 }\n"
        "local b = slider{ name = 'b', min = 0, max = 1, step = 1e-6 }\n"
        "local c = slider{ name = 'c', min = 0, max = 1, step = 1e-320 }\n"
        "local G = points{ name = 'G', default = { {0, 0} },\n"
        "                  constrain = { grid = 1e-7 } }\n"
        "local H = points{ name = 'H', default = { {0, 0} },\n"
        "                  constrain = { grid = 1e-320 } }\n"
        "local L = points{ name = 'L', default = { {0, 0} },\n"
        "  constrain = { line = { {-1e308, -1e308}, {1e308, 1e308} } } }\n"
        "print(a == 3e-6, b == 0.123457, c == 0.3, G[1][1] == 2.5e-6,\n"
        "      G[1][2] == -1e-7, H[1][1] == 0.3, H[1][2] == 0.7,\n"
        "      L[1][1] == 0.5, L[1][2] == 0.5)\n";
    const char *values = "{\"a\": 3.04e-6, \"b\": 0.1234567, \"c\": 0.3, "
                         "\"G\": [[2.53e-6, -1.2e-7]], \"H\": [[0.3, 0.7]], "
                         "\"L\": [[0.3, 0.7]]}";
    char *out = printed(code, values);
    (void)state;
    assert_string_equal(out, "true\ttrue\ttrue\ttrue\ttrue\ttrue\ttrue\t"
                             "true\ttrue\n");
    free(out);
}

/* code must fail with every fragment of want (NULL-ended) */
static void
fails_with(const char *code, const char *const *want)
{
    cf_script_t *s = NULL;
    cf_diag_t diag;
    const char *err;
    cf_diag_clear(&diag);
    assert_int_equal(cf_script_create(NULL, sink, &s, &diag), CF_STATUS_OK);
    assert_int_equal(cf_script_run_string(s, code, "inter.lua"),
                     CF_STATUS_SCRIPT);
    err = cf_script_error(s);
    for (; *want != NULL; want++)
        if (strstr(err, *want) == NULL)
            fail_msg("script:\n%s\nwanted '%s' in:\n%s", code, *want, err);
    cf_script_destroy(s);
}

static void
test_declaration_errors(void **state)
{
    static const struct {
        const char *code;
        const char *want[4];
    } cases[] = {
        { "x = 1\nslider{ name = 't', min = 1, max = 0 }",
          { "inter.lua:2:", "slider 't'", "min 1 is not below max 0" } },
        { "slider{ name = 't', min = 0, max = 1, default = 2 }",
          { "inter.lua:1:", "default 2 lies outside" } },
        { "slider{ name = 't', min = 0, max = 1, step = 0 }",
          { "inter.lua:1:", "step 0 must be positive" } },
        { "slider{ name = 't', min = 0, max = 1, step = -0.1 }",
          { "inter.lua:1:", "step -0.1 must be positive" } },
        { "slider{ name = 't', min = 0, max = 1, step = 2 }",
          { "inter.lua:1:", "step 2 exceeds the range" } },
        { "slider{ name = 't', min = 0, max = 1 }\n"
          "points{ name = 't', default = { {0, 0} } }",
          { "inter.lua:2:", "points 't'", "already declared (line 1)" } },
        { "slider{ name = 't', min = 0, max = 1, mx = 2 }",
          { "inter.lua:1:", "unknown field 'mx' (did you mean 'max'?)" } },
        { "slider{ name = 't', min = 0 }",
          { "inter.lua:1:", "slider: max" } },
        { "points{ name = 'P', default = { {0, 0}, {1} } }",
          { "inter.lua:1:", "points: default" } },
        { "points{ name = 'P', default = { {0, 0, 1} } }",
          { "inter.lua:1:", "must be {x, y}" } },
        { "points{ name = 'P', default = { {0, 0.3} }, "
          "constrain = { grid = 0.25 } }",
          { "inter.lua:1:", "default point 1 (0, 0.3) is not on its grid" } },
        { "points{ name = 'P', default = { {0, 0} }, "
          "constrain = { grid = 0 } }",
          { "inter.lua:1:", "grid 0 must be positive" } },
        { "points{ name = 'P', default = { {0, 0} }, "
          "constrain = { lin = 0 } }",
          { "inter.lua:1:", "constrain: unknown option 'lin' (did you mean "
            "'line'?)" } },
        { "points{ name = 'P', default = { {0, 0} }, "
          "constrain = { line = { {1, 1}, {1, 1} } } }",
          { "inter.lua:1:", "the line's two points coincide" } },
        { "slider{ name = '', min = 0, max = 1 }",
          { "inter.lua:1:", "name must not be empty" } },
    };
    (void)state;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        fails_with(cases[i].code, cases[i].want);
}

/* A log slider needs min > 0; a scale is linear or log. */
static void
test_scale_errors(void **state)
{
    static const char *const zero[] = {
        "inter.lua:1:", "slider 'w'", "scale = \"log\" needs min > 0", NULL
    };
    static const char *const name[] = {
        "inter.lua:1:", "scale \"lg\" is unknown", NULL
    };
    (void)state;
    fails_with("slider{ name = 'w', min = 0, max = 1, scale = 'log' }", zero);
    fails_with("slider{ name = 'w', min = 1, max = 2, scale = 'lg' }", name);
}

static void
test_bad_values_json(void **state)
{
    static const char *const bad[] = {
        "", "{", "[]", "{\"t\" 1}", "{\"t\": }", "{\"t\": 1,}",
        "{\"t\": [[1, 2], [3]]}", "{\"t\": 1e999}", "{\"t\": 1} x",
        "{\"t\": \"a\"}", "{\"t\\u0041\": 1}", "{t: 1}",
        "{\"t\": [[1, 2]}", "{\"t\": 1.2.3}",
    };
    const char *code = "slider{ name = 't', min = 0, max = 1 }\n";
    (void)state;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char *json = NULL;
        size_t len = 0;
        assert_int_equal(cf_interactive_run(code, "inter.lua", bad[i],
                                            strlen(bad[i]), NULL, sink,
                                            &json, &len),
                         CF_STATUS_INVALID_ARG);
        assert_non_null(json);
        if (strstr(json, "\"message\": \"values: ") == NULL)
            fail_msg("%s -> %s", bad[i], json);
        assert_null(strstr(json, "\"svg\""));
        free(json);
    }
}

/* The number after key in json. */
static double
number_after(const char *json, const char *key)
{
    const char *p = strstr(json, key);
    assert_non_null(p);
    return strtod(p + strlen(key), NULL);
}

static void
test_handles_where_drawn(void **state)
{
    const char *code =
        "local P = points{ name = 'P', default = { {1, 2}, {3, -1} } }\n"
        "local f = figure{ name = 'h', width = '6cm', height = '4cm', "
        "window = { -1, 4, -2, 3 } }\n"
        "f:points({ P[2] })\n";
    const char *values = "{\"P\": [[0.5, 0.5], [2.5, 1.75]]}";
    char *json = NULL, *dump = NULL, *m;
    size_t len = 0, dlen;
    double map[6], mx, my, sx, sy;
    cf_script_t *s = NULL;
    cf_diag_t diag;
    char err[200];
    (void)state;
    assert_int_equal(cf_interactive_run(code, "inter.lua", values,
                                        strlen(values), NULL, sink, &json,
                                        &len),
                     CF_STATUS_OK);
    assert_non_null(strstr(json, "\"error\": null"));
    m = strstr(json, "\"to_svg\": [");
    assert_non_null(m);
    m += strlen("\"to_svg\": [");
    for (int k = 0; k < 6; k++)
        map[k] = strtod(m, &m), m += strspn(m, ", ");
    /* handle 1 of P at the drawn marker of P[2] */
    m = strstr(json, "\"index\": 1");
    assert_non_null(m);
    sx = number_after(m, "\"sx\": ");
    sy = number_after(m, "\"sy\": ");
    assert_true(fabs(map[0] * 2.5 + map[2] * 1.75 + map[4] - sx) < 1e-9);
    assert_true(fabs(map[1] * 2.5 + map[3] * 1.75 + map[5] - sy) < 1e-9);
    /* the same run in a script of its own: the marker's place in the
    ** display list */
    cf_diag_clear(&diag);
    assert_int_equal(cf_script_create(NULL, sink, &s, &diag), CF_STATUS_OK);
    assert_int_equal(cf__params_give_json(cf_script_params(s), values,
                                          strlen(values), err, sizeof err),
                     0);
    assert_int_equal(cf_script_run_string(s, code, "inter.lua"),
                     CF_STATUS_OK);
    assert_int_equal(cf_figure_dump(cf_script_figure(s, 0), NULL, &dump,
                                    &dlen, &diag),
                     CF_STATUS_OK);
    m = strstr(dump, "marker ");
    assert_non_null(m);
    m = strchr(m + strlen("marker "), ' ');
    mx = strtod(m, &m);
    my = strtod(m, &m);
    if (fabs(mx - sx) > 1e-6 || fabs(my - sy) > 1e-6)
        fail_msg("handle at (%g, %g), marker drawn at (%g, %g)", sx, sy, mx,
                 my);
    cf_free(dump);
    cf_script_destroy(s);
    free(json);
}

static void
test_script_error_in_json(void **state)
{
    const char *code = "local t = slider{ name = 't', min = 0, max = 1 }\n"
                       "figure{ name = 'a' }\n"
                       "error('broken at ' .. t)\n";
    char *json = NULL;
    size_t len = 0;
    (void)state;
    assert_int_equal(cf_interactive_run(code, "inter.lua", "{\"t\": 0.5}", 10,
                                        NULL, sink, &json, &len),
                     CF_STATUS_OK);
    assert_non_null(strstr(json, "\"message\": \"inter.lua:3: broken at "
                                 "0.5"));
    assert_non_null(strstr(json, "\"line\": 3}"));
    assert_non_null(strstr(json, "\"name\": \"t\""));
    assert_non_null(strstr(json, "\"figures\": []"));
    free(json);
    /* the message also outside the JSON; "" for a good run, the values'
    ** error for bad values */
    {
        char msg[200] = "x";
        assert_int_equal(cf_interactive_run_error(code, "inter.lua",
                                                  "{\"t\": 0.5}", 10, NULL,
                                                  sink, &json, &len, msg,
                                                  sizeof msg),
                         CF_STATUS_OK);
        assert_string_equal(msg, "inter.lua:3: broken at 0.5");
        free(json);
        assert_int_equal(cf_interactive_run_error(
                             "figure{ name = 'a' }:points{ {0, 0}, {1, 1} }\n",
                             "inter.lua", NULL, 0,
                             NULL, sink, &json, &len, msg, sizeof msg),
                         CF_STATUS_OK);
        assert_string_equal(msg, "");
        free(json);
        assert_int_equal(cf_interactive_run_error(code, "inter.lua", "{", 1,
                                                  NULL, sink, &json, &len,
                                                  msg, sizeof msg),
                         CF_STATUS_INVALID_ARG);
        assert_non_null(strstr(msg, "values"));
        free(json);
    }
    /* a points list dragged in a figure the script does not make */
    code = "points{ name = 'P', default = { {0, 0} }, figure = 'nope' }\n"
           "figure{ name = 'a' }\n";
    assert_int_equal(cf_interactive_run(code, "inter.lua", NULL, 0, NULL,
                                        sink, &json, &len),
                     CF_STATUS_OK);
    assert_non_null(strstr(json, "figure = 'nope' names no figure"));
    assert_non_null(strstr(json, "\"line\": 1}"));
    free(json);
}

/* A message with bytes that are not UTF-8 and a NUL: the JSON carries
** neither raw (a browser's JSON.parse would take the invalid bytes, and a
** NUL cut the message); here it is all ASCII, the NUL written \0 and each
** stray byte U+FFFD. */
static void
test_error_bytes_in_json(void **state)
{
    const char *code = "error('bad \\255\\254 and \\0 here')\n";
    char *json = NULL;
    size_t len = 0;
    (void)state;
    assert_int_equal(cf_interactive_run(code, "inter.lua", NULL, 0, NULL,
                                        sink, &json, &len),
                     CF_STATUS_OK);
    for (size_t i = 0; i < len; i++)
        assert_true((unsigned char)json[i] < 0x80);
    assert_non_null(strstr(json, "bad \\ufffd\\ufffd and \\\\0 here"));
    free(json);
}

/* The "lua" text, unescaped from its JSON string, run in a script of its
** own: it must give the values the run used. */
static void
test_lua_text_reads_back(void **state)
{
    const char *code = "slider{ name = 't', min = 0, max = 1, step = 0.001 }"
                       "\npoints{ name = 'P', default = { {0, 0}, {1, 1} } }"
                       "\nslider{ name = 'and', min = 0, max = 2 }\n";
    const char *values = "{\"t\": 0.123, \"P\": [[0.1, 1e-7], [3, -4.25]], "
                         "\"and\": 1.5}";
    char *json = NULL, code2[2048], *p, *q;
    size_t len = 0;
    cf_script_t *s = NULL;
    cf_diag_t diag;
    (void)state;
    assert_int_equal(cf_interactive_run(code, "inter.lua", values,
                                        strlen(values), NULL, sink, &json,
                                        &len),
                     CF_STATUS_OK);
    p = strstr(json, "\"lua\": \"");
    assert_non_null(p);
    p += strlen("\"lua\": \"");
    q = code2;
    for (; *p != '"'; p++) {
        if (*p == '\\') {
            p++;
            *q++ = *p == 'n' ? '\n' : *p;
        } else {
            *q++ = *p;
        }
    }
    strcpy(q, "assert(values.t == 0.123 and values.P[1][2] == 1e-7 and "
              "values.P[2][1] == 3 and values.P[2][2] == -4.25 and "
              "values['and'] == 1.5)\n");
    cf_diag_clear(&diag);
    assert_int_equal(cf_script_create(NULL, sink, &s, &diag), CF_STATUS_OK);
    if (cf_script_run_string(s, code2, "values.lua") != CF_STATUS_OK)
        fail_msg("%s\n%s", code2, cf_script_error(s));
    cf_script_destroy(s);
    free(json);
}

/* "@view:NAME" replaces the view the script gives figure NAME (elevation
** clamped to [-90, 90]) before the script goes on: f:project sees it; the
** JSON reports each figure's view as used, null for a 2D figure; names
** of parameters cannot start with '@'. */
static void
test_view_override(void **state)
{
    const char *code =
        "local f = figure{ name = 'cube', view = { 30, 20 } }\n"
        "f:points({ {0, 0, 0}, {1, 1, 1} })\n"
        "local g = figure{ name = 'flat' }\n"
        "g:points({ {0, 0}, {1, 1} })\n"
        "local h = figure{ name = 'late' }\n"
        "h:view(10, 5)\n"
        "h:points({ {0, 0, 0}, {1, 1, 1} })\n"
        "local p = f:project({ {0, 0, 1} })[1]\n"
        "local q = h:project({ {1, 0, 0} })[1]\n"
        "print(string.format('%.6f %.6f', p[2], q[1]))\n";
    const char *values = "{\"@view:cube\": [[-40, 120]], "
                         "\"@view:late\": [[100, -10]]}";
    static const char *const reserved[] = { "slider '@view:cube'",
                                            "reserved", NULL };
    char *out, *json = NULL;
    size_t len = 0;
    (void)state;
    /* ey . (0, 0, 1) = cos e: cos 20 degrees, then cos 90; ex . (1, 0, 0)
    ** = -sin a */
    out = printed(code, NULL);
    assert_string_equal(out, "0.939693 -0.173648\n");
    free(out);
    out = printed(code, values);
    assert_string_equal(out, "0.000000 -0.984808\n");
    free(out);
    assert_int_equal(cf_interactive_run(code, "inter.lua", values,
                                        strlen(values), NULL, sink, &json,
                                        &len),
                     CF_STATUS_OK);
    assert_non_null(strstr(json, "\"name\": \"cube\""));
    assert_non_null(strstr(json, "\"view\": [-40, 90]"));
    assert_non_null(strstr(json, "\"view\": null"));
    assert_non_null(strstr(json, "\"view\": [100, -10]"));
    free(json);
    assert_int_equal(cf_interactive_run(code, "inter.lua", NULL, 0, NULL,
                                        sink, &json, &len),
                     CF_STATUS_OK);
    assert_non_null(strstr(json, "\"view\": [30, 20]"));
    assert_non_null(strstr(json, "\"view\": [10, 5]"));
    free(json);
    fails_with("slider{ name = '@view:cube', min = 0, max = 1 }\n",
               reserved);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_defaults),
        cmocka_unit_test(test_given_values),
        cmocka_unit_test(test_declaration_errors),
        cmocka_unit_test(test_bad_values_json),
        cmocka_unit_test(test_handles_where_drawn),
        cmocka_unit_test(test_script_error_in_json),
        cmocka_unit_test(test_error_bytes_in_json),
        cmocka_unit_test(test_lua_text_reads_back),
        cmocka_unit_test(test_values_rounded),
        cmocka_unit_test(test_fine_steps_and_far_lines),
        cmocka_unit_test(test_scale_errors),
        cmocka_unit_test(test_view_override),
    };
    int rc;
    sink = fopen("/dev/null", "w");
    rc = cmocka_run_group_tests(tests, NULL, NULL);
    fclose(sink);
    return rc;
}
