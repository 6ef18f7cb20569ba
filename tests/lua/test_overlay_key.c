/* visible = "2-" on every drawing method: each schema whose last key
** list is the overlay key (lkeys.c) is called through its example with
** the option, and every group of the figure's display list carries the
** specification; a call after it without the option carries none. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/figure.h"
#include "lkeys.h"
#include "script.h"

/* The dump of the one figure of code. */
static char *
dump_of(const char *code)
{
    cf_script_t *sc = NULL;
    char *text = NULL;
    size_t size;
    assert_int_equal(cf_script_create(NULL, NULL, &sc, NULL), 0);
    if (cf_script_run_string(sc, code, "overlay") != CF_STATUS_OK)
        fail_msg("%s\n%s", code, cf_script_error(sc));
    assert_int_equal(cf_script_figure_count(sc), 1);
    assert_int_equal(cf_figure_dump(cf_script_figure(sc, 0), NULL, &text,
                                    &size, NULL), 0);
    cf_script_destroy(sc);
    return text;
}

/* A valid call of every drawing method, O its options. */
static const struct { const char *fn, *call; } calls[] = {
    { "curve", "f:curve(c, O)" },
    { "polygon", "f:polygon(P, O)" },
    { "points", "f:points(P, O)" },
    { "hull", "f:hull(P, O)" },
    { "fill", "f:fill(P, O)" },
    { "polyline", "f:polyline(P, O)" },
    { "line", "f:line({0, 0}, {1, 1}, O)" },
    { "label", "f:label({0, 0}, 'A', O)" },
    { "arrow", "f:arrow({0, 0}, {1, 1}, O)" },
    { "arrow_to", "f:arrow_to({0, 0}, {1, 1}, O)" },
    { "tangent", "f:tangent(c, 0.5, O)" },
    { "knots", "f:knots(s, O)" },
    { "decasteljau", "f:decasteljau(c, 0.5, O)" },
    { "deboor", "f:deboor(s, 1, O)" },
    { "plot", "O.x = {0, 3}; O.y = {0, 2}; f:plot(O)" },
    { "func", "f:func(math.sin, 0, 1, O)" },
    { "graph", "f:graph(bezier{ {0}, {1}, {0} }, O)" },
    { "basis", "f:basis(s, 0, 2, O)" },
    { "bernstein", "f:bernstein(3, 1, O)" },
    { "surface", "f:view(-60, 30); f:surface(bezier_surface{ points = "
      "{ { {0, 0, 0}, {0, 1, 0} }, { {1, 0, 0}, {1, 1, 1} } } }, O)" },
    { "decasteljau_surface", "f:view(-60, 30); f:decasteljau_surface("
      "bezier_surface{ points = { { {0, 0, 0}, {0, 1, 0} }, { {1, 0, 0}, "
      "{1, 1, 1} } } }, 0.5, 0.5, O)" },
};

static const char *
call_of(const char *fn)
{
    for (size_t i = 0; i < sizeof calls / sizeof calls[0]; i++)
        if (strcmp(calls[i].fn, fn) == 0)
            return calls[i].call;
    return NULL;
}

static void
test_every_drawing_method(void **state)
{
    size_t methods = 0;
    (void)state;
    for (int i = 1; i < CF__KEYS_COUNT_; i++) {
        const cf__lua_schema_t *s = cf__lua_schema_at((cf__lua_keys_t)i);
        const char *call;
        char code[1200], *text, *line, *last = NULL;
        size_t groups = 0, with = 0;
        if (s->keys[CF__LUA_KEY_LISTS - 1] == NULL)
            continue;
        call = call_of(s->fn);
        if (call == NULL)
            fail_msg("%s takes visible: add a call of it here", s->fn);
        methods++;
        snprintf(code, sizeof code, "%slocal O = { visible = '2-' }\n%s\n"
                 "f:line({0, 0}, {1, 1})\n", cf__lua_schema_prelude, call);
        text = dump_of(code);
        for (line = text; line != NULL && *line != '\0';) {
            char *nl = strchr(line, '\n');
            if (strncmp(line, "group ", 6) == 0) {
                const char *ov = strstr(line, " overlay 2-\n");
                groups++;
                last = line;
                if (ov != NULL && ov < nl)
                    with++;
            }
            line = nl != NULL ? nl + 1 : NULL;
        }
        /* every group but the closing line's carries it */
        if (!(groups >= 2 && with == groups - 1))
            fail_msg("%s: %zu of %zu groups carry the overlay\n%s", s->fn,
                     with, groups, text);
        assert_true(strstr(last, "overlay") == NULL
                    || strstr(last, "overlay") > strchr(last, '\n'));
        cf_free(text);
    }
    assert_int_equal(methods, sizeof calls / sizeof calls[0]);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_drawing_method),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
