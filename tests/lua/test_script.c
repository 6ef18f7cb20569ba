/*
** The script runner in-process (render/lua/script.h): its API, the limits,
** two scripts with their own allocators, and a seeded mutation fuzz of a
** figure script (every mutant must end with OK or a script error, never a
** crash; run under ASan/UBSan in CI).
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
#include "lcommon.h"
#include "script.h"
#include "testutil.h"

static FILE *sink;

static cf_script_t *
new_script(size_t mib, unsigned long long instructions)
{
    cf_script_limits_t lim = { mib << 20, instructions };
    cf_script_t *s = NULL;
    cf_diag_t diag;
    cf_diag_clear(&diag);
    assert_int_equal(cf_script_create(&lim, sink, &s, &diag), CF_STATUS_OK);
    assert_non_null(s);
    return s;
}

static void
test_api_and_figures(void **state)
{
    cf_script_t *s;
    (void)state;
    cf_script_destroy(NULL);
    assert_int_equal(cf_script_create(NULL, NULL, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_script_figure_count(NULL), 0);
    assert_string_equal(cf_script_error(NULL), "");
    s = new_script(64, 10000000);
    assert_int_equal(cf_script_run_string(NULL, "x = 1", "a"),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_script_run_string(s,
        "local f = figure{ name = 'a', caption = 'first' }\n"
        "f:curve(bezier{ {0, 0}, {1, 1}, {2, 0} })\n"
        "figure{ name = 'b' }\n", "two.lua"), CF_STATUS_OK);
    assert_int_equal(cf_script_figure_count(s), 2);
    assert_string_equal(cf_script_figure_name(s, 0), "a");
    assert_string_equal(cf_script_figure_caption(s, 0), "first");
    assert_string_equal(cf_script_figure_name(s, 1), "b");
    assert_string_equal(cf_script_figure_caption(s, 1), "");
    assert_non_null(cf_script_figure(s, 0));
    assert_int_equal(cf_figure_status(cf_script_figure(s, 0), NULL),
                     CF_STATUS_OK);
    assert_null(cf_script_figure(s, 2));
    /* a second chunk in the same state sees the first one's figures */
    assert_int_equal(cf_script_run_string(s, "figure{ name = 'a' }",
                                          "dup.lua"), CF_STATUS_SCRIPT);
    assert_non_null(strstr(cf_script_error(s), "dup.lua:1: figure: a figure "
                                               "named \"a\" is already"));
    cf_script_destroy(s);
}

static void
test_error_messages(void **state)
{
    cf_script_t *s;
    (void)state;
    s = new_script(64, 10000000);
    assert_int_equal(cf_script_run_string(s, "\n\nlocal c = bezier{}\n",
                                          "e.lua"), CF_STATUS_SCRIPT);
    assert_string_equal(cf_script_error(s), "e.lua:3: bezier: 0 points "
                                            "given, at least 1 needed");
    assert_int_equal(cf_script_run_string(s, "#!/usr/bin/env curvefig\n"
                                             "error('here')", "sh.lua"),
                     CF_STATUS_SCRIPT);
    assert_string_equal(cf_script_error(s), "sh.lua:2: here");
    assert_int_equal(cf_script_run_string(s, "local s = bspline{ degree = 2,"
                                             " knots = {0, 1}, points = "
                                             "{{0, 0}, {1, 1}, {2, 0}} }",
                                          "k.lua"), CF_STATUS_SCRIPT);
    assert_non_null(strstr(cf_script_error(s), "k.lua:1: bspline: 2 knots "
                                               "given, degree 2 with 3 "
                                               "points needs 6"));
    assert_int_equal(cf_script_run_file(s, "/nonexistent/x.lua"),
                     CF_STATUS_IO);
    assert_string_equal(cf_script_error(s), "cannot open /nonexistent/x.lua");
    cf_script_destroy(s);
}

/* Messages of the figure methods: a tick step that is not positive is
** refused (the library reads step < 0 as "no ticks" and 0 as automatic),
** and f:func reports the figure's own message (from an initialised
** diag, never stack garbage). */
/* Source nested too deeply: the parser's "C stack overflow" carries no
** position of its own; the message gets the chunk's name and the line
** the parser had reached, in the same form as the parser's
** other messages (a long name shortened the same way). */
static void
test_parser_nesting(void **state)
{
    char code[1200], name[100], expect[200];
    cf_script_t *s;
    size_t n = 0;
    (void)state;
    s = new_script(16, 1000000);
    n += (size_t)snprintf(code, sizeof code, "#!/usr/bin/env curvefig\n"
                          "local a = 1\nlocal x = ");
    for (int i = 0; i < 500; i++)
        code[n++] = '{';
    code[n++] = '\n';
    code[n] = '\0';
    assert_int_equal(cf_script_run_string(s, code, "nest.lua"),
                     CF_STATUS_SCRIPT);
    assert_string_equal(cf_script_error(s), "nest.lua:3: C stack overflow "
                                            "(the script nests too deeply)");
    /* a name longer than Lua's LUA_IDSIZE - 1 = 59 characters: "..." and
    ** its end, as in a syntax error under the same name */
    memset(name, 'n', 80);
    memcpy(name + 76, ".lua", 5);
    assert_int_equal(cf_script_run_string(s, "local = 1", name),
                     CF_STATUS_SCRIPT);
    snprintf(expect, sizeof expect, "...%s:1: ", name + 80 - 56);
    assert_non_null(strstr(cf_script_error(s), expect));
    assert_true(strstr(cf_script_error(s), expect) == cf_script_error(s));
    assert_int_equal(cf_script_run_string(s, code + 24, name),
                     CF_STATUS_SCRIPT);
    snprintf(expect, sizeof expect, "...%s:2: C stack overflow (the script "
             "nests too deeply)", name + 80 - 56);
    assert_string_equal(cf_script_error(s), expect);
    /* the other syntax errors are unchanged */
    assert_int_equal(cf_script_run_string(s, "\nlocal = 1", "syn.lua"),
                     CF_STATUS_SCRIPT);
    assert_string_equal(cf_script_error(s), "syn.lua:2: <name> expected "
                                            "near '='");
    cf_script_destroy(s);
}

static void
test_figure_messages(void **state)
{
    static const struct {
        const char *code, *message;
    } cases[] = {
        { "local f = figure{ name = 'z' }\n"
          "f:plot{ x = {0, 1}, y = {0, 1}, xticks = -0.1 }",
          "t.lua:2: plot: xticks step -0.1 must be positive (or false for "
          "none)" },
        { "local f = figure{ name = 'z' }\n"
          "f:plot{ x = {0, 1}, y = {0, 1}, yticks = 0 }",
          "t.lua:2: plot: yticks step 0 must be positive (or false for "
          "none)" },
        { "local f = figure{ name = 'z' }\n"
          "f:func(function(x) return 0/0 end, 0, 1)",
          "t.lua:2: func: the plotted function is not finite on [0, 1]" },
        { "local f = figure{ name = 'z' }\n"
          "f:func(function(x) return x end, 1, 0)",
          "t.lua:2: func: function range [1, 0] is empty" },
    };
    (void)state;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        cf_script_t *s = new_script(16, 10000000);
        assert_int_equal(cf_script_run_string(s, cases[i].code, "t.lua"),
                         CF_STATUS_SCRIPT);
        assert_string_equal(cf_script_error(s), cases[i].message);
        cf_script_destroy(s);
    }
    /* false, a positive step and a list are still accepted */
    {
        cf_script_t *s = new_script(16, 10000000);
        assert_int_equal(cf_script_run_string(s,
            "local f = figure{ name = 'z' }\n"
            "f:plot{ x = {0, 1}, y = {0, 1}, xticks = false, yticks = 0.5 }\n"
            "local g = figure{ name = 'y' }\n"
            "g:plot{ x = {0, 1}, y = {0, 1}, xticks = {0, 1} }", "t.lua"),
            CF_STATUS_OK);
        cf_script_destroy(s);
    }
}

static void
test_limits(void **state)
{
    cf_script_t *s;
    (void)state;
    s = new_script(8, 1000000);
    assert_int_equal(cf_script_run_string(s, "while true do end", "l.lua"),
                     CF_STATUS_SCRIPT);
    assert_string_equal(cf_script_error(s), "l.lua:1: script exceeded the "
                                            "instruction limit of 1000000 "
                                            "instructions");
    cf_script_destroy(s);
    s = new_script(8, 1000000000);
    /* memory through the curve library counts too: degree elevation of a
    ** line in R^64 to degree 1001 allocates 1002 * 64 doubles (0.5 MB) per
    ** curve, and they are kept alive */
    assert_int_equal(cf_script_run_string(s,
        "local P = {}\n"
        "for i = 1, 2 do\n"
        "  local p = {} for k = 1, 64 do p[k] = k end P[i] = p end\n"
        "local keep = {}\n"
        "for i = 1, 1e6 do keep[i] = bezier(P):elevate(1000) end\n",
        "m.lua"), CF_STATUS_SCRIPT);
    assert_non_null(strstr(cf_script_error(s), "m.lua:5: "));
    assert_non_null(strstr(cf_script_error(s), "memory limit of 8 MiB"));
    cf_script_destroy(s);
}

/* The binding's one grow helper (c:flatten's buffer was freed twice when
** its size cap was tested after realloc): it doubles from 64 up to max,
** keeps the contents, and on any failure (past max, or the allocator
** refusing) leaves the block and the capacity as they were, for the
** caller to free once.  The failing allocator counts the live blocks. */
static void
test_grow(void **state)
{
    void *p = NULL;
    double *v;
    size_t cap = 0;
    (void)state;
    tu_fail_alloc_after(1000);
    assert_true(cf__lua_grow(&p, &cap, 10, sizeof(double), 100));
    assert_int_equal(cap, 64);
    v = p;
    for (int i = 0; i < 64; i++)
        v[i] = i + 0.5;
    assert_true(cf__lua_grow(&p, &cap, 65, sizeof(double), 100));
    assert_int_equal(cap, 100);
    v = p;
    for (int i = 0; i < 64; i++)
        assert_true(v[i] == i + 0.5);
    assert_false(cf__lua_grow(&p, &cap, 101, sizeof(double), 100));
    assert_ptr_equal(p, v);
    assert_int_equal(cap, 100);
    assert_true(cf__lua_grow(&p, &cap, 100, sizeof(double), 100));
    assert_ptr_equal(p, v);
    /* n * size overflows: refused, nothing allocated */
    assert_false(cf__lua_grow(&p, &cap, 200, SIZE_MAX / 4, SIZE_MAX));
    assert_ptr_equal(p, v);
    assert_int_equal(tu_alloc_live(), 1);
    cf_free(p);
    assert_int_equal(tu_alloc_live(), 0);
    /* the allocator refuses the growth: the old block stays whole */
    p = NULL;
    cap = 0;
    tu_fail_alloc_after(2);
    assert_true(cf__lua_grow(&p, &cap, 64, sizeof(double), 1000));
    v = p;
    v[63] = 7;
    assert_false(cf__lua_grow(&p, &cap, 65, sizeof(double), 1000));
    assert_ptr_equal(p, v);
    assert_int_equal(cap, 64);
    assert_true(v[63] == 7);
    cf_free(p);
    assert_int_equal(tu_alloc_live(), 0);
    tu_fail_alloc_reset();
}

/* Lua runs finalisers with the hooks off: setmetatable refuses a __gc
** field (even a placeholder, which marks the object for finalisation), so
** no script code can run outside the instruction limit (an endless loop
** in __gc would hang the process).  Other metamethods,
** __close included, stay under the limit. */
static void
test_no_finalisers(void **state)
{
    cf_script_t *s;
    (void)state;
    s = new_script(16, 1000000);
    assert_int_equal(cf_script_run_string(s,
        "\nsetmetatable({}, { __gc = function() while true do end end })\n"
        "collectgarbage()\n", "gc.lua"), CF_STATUS_SCRIPT);
    assert_string_equal(cf_script_error(s), "gc.lua:2: setmetatable: __gc is "
                        "not allowed in figure scripts (a finaliser would "
                        "run outside the instruction limit)");
    assert_int_equal(cf_script_run_string(s,
        "local mt = { __gc = false }\n"
        "local t = setmetatable({}, mt)\n"
        "mt.__gc = function() while true do end end\n", "gc2.lua"),
        CF_STATUS_SCRIPT);
    assert_non_null(strstr(cf_script_error(s), "gc2.lua:2: setmetatable: "
                                               "__gc is not allowed"));
    /* setmetatable itself still works: its result, __index, protection */
    assert_int_equal(cf_script_run_string(s,
        "local t = setmetatable({}, { __index = function(_, k) return k end,"
        " __metatable = 'no' })\n"
        "assert(t.abc == 'abc' and getmetatable(t) == 'no')\n"
        "assert(not pcall(setmetatable, t, {}))\n"
        "assert(setmetatable(t, nil) == nil)\n", "ok.lua"),
        CF_STATUS_SCRIPT);
    assert_non_null(strstr(cf_script_error(s), "ok.lua:4: cannot change a "
                                               "protected metatable"));
    cf_script_destroy(s);
    s = new_script(16, 1000000);
    assert_int_equal(cf_script_run_string(s,
        "local x <close> = setmetatable({}, { __close = function()\n"
        "  while true do end end })\n"
        "error('boom')\n", "close.lua"), CF_STATUS_SCRIPT);
    assert_string_equal(cf_script_error(s), "close.lua:2: script exceeded "
                        "the instruction limit of 1000000 instructions");
    cf_script_destroy(s);
}

static int
count_lines(const char *s)
{
    int n = 1;
    for (; *s != '\0'; s++)
        n += *s == '\n';
    return n;
}

/* A stack overflow (~500 000 frames) is reported at once with a short
** traceback: the top frames, "...", the bottom ones, and a frame repeated
** in a row as one line with its count (a traceback that probed every
** level would be quadratic in the depth and run for minutes). */
static void
test_deep_recursion(void **state)
{
    cf_script_t *s;
    const char *e;
    (void)state;
    s = new_script(256, 1000000000);
    assert_int_equal(cf_script_run_string(s,
        "local function f(n) return 1 + f(n + 1) end\n"
        "f(0)\n", "d.lua"), CF_STATUS_SCRIPT);
    e = cf_script_error(s);
    assert_non_null(strstr(e, "d.lua:1: stack overflow\n"
                              "    from d.lua:1 (9 times)\n"
                              "    ... ("));
    assert_non_null(strstr(e, " levels not shown)\n"
                              "    from d.lua:1 (21 times)\n"
                              "    from d.lua:2"));
    assert_int_equal(count_lines(e), 5);
    cf_script_destroy(s);
    /* two functions calling each other: nothing to collapse, at most 10
    ** frames above the "..." line and 22 levels below it */
    s = new_script(256, 1000000000);
    assert_int_equal(cf_script_run_string(s,
        "local g\n"
        "local function f(n) return 1 + g(n) end\n"
        "g = function(n) return 1 + f(n + 1) end\n"
        "f(0)\n", "m.lua"), CF_STATUS_SCRIPT);
    e = cf_script_error(s);
    assert_non_null(strstr(e, "stack overflow"));
    assert_non_null(strstr(e, "levels not shown"));
    assert_non_null(strstr(e, "    from m.lua:4"));
    assert_true(count_lines(e) <= 1 + 10 + 1 + 22);
    cf_script_destroy(s);
    /* a shallow error keeps every frame */
    s = new_script(16, 1000000);
    assert_int_equal(cf_script_run_string(s,
        "local function f(n) if n == 0 then error('deep') end\n"
        "  return 1 + f(n - 1) end\n"
        "local function g() return 1 + f(3) end\n"
        "g()\n", "s.lua"), CF_STATUS_SCRIPT);
    assert_string_equal(cf_script_error(s),
                        "s.lua:1: deep\n"
                        "    from s.lua:2 (3 times)\n"
                        "    from s.lua:3\n"
                        "    from s.lua:4");
    cf_script_destroy(s);
}

/* Budgets in bytes: the messages name the budget in the unit
** it was given in, a budget too small for the sandbox itself is refused
** by cf_script_create, and the reserve used to report the limit lies
** inside the budget, so Lua's own count never goes past it. */
static void
test_small_budgets(void **state)
{
    static const char code[] =
        "local t = {}\n"
        "for i = 1, 1e7 do\n"
        "  t[i] = { i }\n"
        "  if collectgarbage('count') * 1024 > 524288 then print('over') end\n"
        "end\n";
    static const size_t tiny[] = { 1000, 8 << 10 };
    static const char *const tiny_msg[] = {
        "the memory limit of 1000 bytes is too small for the sandbox itself",
        "the memory limit of 8 KiB is too small for the sandbox itself",
    };
    cf_script_limits_t lim = { 512 << 10, 100000000 };
    cf_script_t *s = NULL;
    cf_diag_t diag;
    char out[64];
    FILE *f;
    (void)state;
    for (size_t i = 0; i < 2; i++) {
        lim.max_memory = tiny[i];
        cf_diag_clear(&diag);
        assert_int_equal(cf_script_create(&lim, sink, &s, &diag),
                         CF_STATUS_NO_MEMORY);
        assert_null(s);
        assert_string_equal(diag.msg, tiny_msg[i]);
    }
    f = tmpfile();
    assert_non_null(f);
    lim.max_memory = 512 << 10;
    cf_diag_clear(&diag);
    assert_int_equal(cf_script_create(&lim, f, &s, &diag), CF_STATUS_OK);
    assert_int_equal(cf_script_run_string(s, code, "b.lua"),
                     CF_STATUS_SCRIPT);
    /* in the loop (line 2 or 3: where the allocation that passes the
    ** budget falls depends on the sandbox's own size) */
    assert_true(strstr(cf_script_error(s), "b.lua:2: script exceeded the "
                                           "memory limit of 512 KiB") ||
                strstr(cf_script_error(s), "b.lua:3: script exceeded the "
                                           "memory limit of 512 KiB"));
    cf_script_destroy(s);
    /* nothing printed: the count never passed the budget */
    rewind(f);
    assert_null(fgets(out, sizeof out, f));
    fclose(f);
}

/* The pattern functions run inside one C call, out of the hook's sight:
** their search is counted first against the instruction limit (finding
** F9: an embedding program had no bound on it).  The results are still
** Lua's; the values below are worked out from the manual's rules. */
static void
test_pattern_budget(void **state)
{
    cf_script_t *s;
    (void)state;
    s = new_script(16, 10000000);
    assert_int_equal(cf_script_run_string(s,
        "local s = string.rep('a', 200000)\n"
        "print(s:find('.-.-.-.-.-.-b'))\n", "p.lua"), CF_STATUS_SCRIPT);
    assert_string_equal(cf_script_error(s), "p.lua:2: script exceeded the "
                        "instruction limit of 10000000 instructions");
    cf_script_destroy(s);
    s = new_script(16, 10000000);
    assert_int_equal(cf_script_run_string(s,
        "local t = 'key1 = 10, key2 = 20, (a(b)c) x'\n"
        "local a, b, k, v = t:find('(%w+) = (%d+)')\n"
        "assert(a == 1 and b == 9 and k == 'key1' and v == '10')\n"
        "assert(t:match('key2 = (%d+)') == '20')\n"
        "assert(t:find('=', 1, true) == 6 and t:find('=', -10) == nil)\n"
        "assert(t:find('k', -21) == 12 and t:find('^k') == 1)\n"
        "assert(select(2, t:find('%b()')) == 29 and #t == 31)\n"
        "assert(t:find('%f[%a]%a+', 2) == 12)\n"
        "assert(select(3, ('hi hi'):find('(h%w+) %1')) == 'hi')\n"
        "assert(t:match('()x$') == 31)\n"
        "local n = 0\n"
        "for k, v in t:gmatch('(%w+) = (%d+)') do n = n + tonumber(v) end\n"
        "assert(n == 30)\n"
        "local u, c = t:gsub('%d+', function(d) return d * 2 end)\n"
        "assert(u == 'key2 = 20, key4 = 40, (a(b)c) x' and c == 4)\n"
        "assert(('a.b'):gsub('%.', '%%') == 'a%b')\n"
        "-- a long subject with a pattern that does not backtrack\n"
        "local words = string.rep('word ', 20000)\n"
        "local w = 0\n"
        "for _ in words:gmatch('%S+') do w = w + 1 end\n"
        "assert(w == 20000 and select(2, words:gsub('o', 'o')) == 20000)\n",
        "ok.lua"), CF_STATUS_OK);
    /* Lua's own messages keep the script's line */
    assert_int_equal(cf_script_run_string(s, "\nlocal x = ('a'):find('[a')",
                                          "m.lua"), CF_STATUS_SCRIPT);
    assert_string_equal(cf_script_error(s), "m.lua:2: malformed pattern "
                                            "(missing ']')");
    assert_int_equal(cf_script_run_string(s, "string.gsub(nil, 'a', 'b')",
                                          "n.lua"), CF_STATUS_SCRIPT);
    assert_string_equal(cf_script_error(s), "n.lua:1: bad argument #1 to "
                        "'gsub' (string expected, got nil)");
    cf_script_destroy(s);
}

/* Two scripts alive at once, each with its own budget: the curves a script
** makes count against its own limit only (10 elevated curves are 5 MB, so
** two runs exceed 8 MiB in one script but not one run in each of two),
** the thread's allocator outside a run is untouched, and scripts may be
** destroyed in any order. */
static void
test_two_scripts(void **state)
{
    static const char grow[] =
        "local P = {}\n"
        "for i = 1, 2 do\n"
        "  local p = {} for k = 1, 64 do p[k] = k end P[i] = p end\n"
        "keep = rawget(_ENV, \"keep\") or {}\n"
        "for i = 1, 10 do keep[#keep + 1] = bezier(P):elevate(1000) end\n";
    cf_allocator_t before, during;
    cf_script_t *a, *b, *c;
    (void)state;
    cf_get_allocator(&before);
    a = new_script(8, 1000000000);
    b = new_script(8, 1000000000);
    cf_get_allocator(&during);
    assert_true(during.realloc == before.realloc && during.ud == before.ud);
    assert_int_equal(cf_script_run_string(a, grow, "a.lua"), CF_STATUS_OK);
    assert_int_equal(cf_script_run_string(b, grow, "b.lua"), CF_STATUS_OK);
    assert_int_equal(cf_script_run_string(a, grow, "a.lua"), CF_STATUS_SCRIPT);
    assert_non_null(strstr(cf_script_error(a), "memory limit of 8 MiB"));
    c = new_script(32, 1000000000);
    /* the first one goes first: b and c are not disturbed */
    cf_script_destroy(a);
    assert_int_equal(cf_script_run_string(c, grow, "c.lua"), CF_STATUS_OK);
    assert_int_equal(cf_script_run_string(c, grow, "c.lua"), CF_STATUS_OK);
    assert_int_equal(cf_script_run_string(b, "x = #keep", "b.lua"),
                     CF_STATUS_OK);
    cf_script_destroy(b);
    assert_int_equal(cf_script_run_string(c, grow, "c.lua"), CF_STATUS_OK);
    cf_script_destroy(c);
    cf_get_allocator(&during);
    assert_true(during.realloc == before.realloc && during.ud == before.ud);
}

static const char fuzz_seed[] =
    "local c = bezier{ {0, 0}, {1, 2}, {3, 2}, {4, 0} }\n"
    "local s = bspline{ degree = 2, knots = {0, 0, 0, 0.5, 1, 1, 1},\n"
    "                   points = {{0, 0}, {1, 1}, {2, 0}, {3, 1}} }\n"
    "local f = figure{ name = 'z', width = '5cm', height = '4cm' }\n"
    "f:polygon(c, { labels = 'P_%d' }):curve(c):curve(s)\n"
    "f:decasteljau(c, 0.5, { point = true }):deboor(s, 0.25)\n"
    "f:knots(s):hull(c):tangent(c, 0.3):arrow({0, 0}, {1, 1})\n"
    "local l, r = c:split(0.4)\n"
    "print(l:eval(0.5)[1], s:insert_knot(0.75):count(), #s:to_beziers())\n"
    "f:plot{ x = {0, 1}, y = {0, 1}, knots = {0, 0.5, 1} }\n"
    "f:basis(s, 1):bernstein(3, 1):func(function(x) return x end, 0, 1)\n";

/* Seeded mutations: replace, insert or delete a few bytes (digits, signs,
** brackets, quotes, letters) of the seed script. */
static void
test_fuzz_mutations(void **state)
{
    static const char alphabet[] = "0123456789-+.e{}()[],'\"=_%:#xyn \n";
    tu_rng rng;
    char buf[sizeof fuzz_seed + 64];
    int ok = 0, failed = 0;
    (void)state;
    tu_rng_seed(&rng, 20261122);
    for (int iter = 0; iter < 400; iter++) {
        size_t len = strlen(fuzz_seed);
        cf_script_t *s;
        cf_status_t st;
        int edits = 1 + (int)(tu_rng_next(&rng) % 4);
        memcpy(buf, fuzz_seed, len + 1);
        for (int e = 0; e < edits; e++) {
            size_t pos = (size_t)(tu_rng_next(&rng) % len);
            char ch = alphabet[tu_rng_next(&rng) % (sizeof alphabet - 1)];
            switch (tu_rng_next(&rng) % 3) {
            case 0:
                buf[pos] = ch;
                break;
            case 1:
                if (len + 1 < sizeof buf) {
                    memmove(buf + pos + 1, buf + pos, len - pos + 1);
                    buf[pos] = ch;
                    len++;
                }
                break;
            default:
                memmove(buf + pos, buf + pos + 1, len - pos);
                len--;
                break;
            }
        }
        s = new_script(32, 5000000);
        st = cf_script_run_string(s, buf, "fuzz.lua");
        if (st == CF_STATUS_OK) {
            ok++;
        } else {
            assert_int_equal(st, CF_STATUS_SCRIPT);
            assert_true(strlen(cf_script_error(s)) > 0);
            failed++;
        }
        cf_script_destroy(s);
    }
    /* both outcomes occur: the mutations are neither all harmless nor all
    ** fatal */
    assert_true(ok > 0 && failed > 0);
}

/* The theme's fonts: theme{} sets the family and size (TeX points) of
** every figure made after it, figure{ font_size } one figure's, and the
** tool's choice (cf_script_set_fonts) wins over theme{} but not over a
** figure's own; tick labels scale with the labels. */
static void
test_theme_fonts(void **state)
{
    static const char code[] =
        "theme{ family = 'sans', size = 11 }\n"
        "figure{ name = 'a' }\n"
        "figure{ name = 'b', font_size = 12, font = 'serif' }\n"
        "figure{ name = 'c', font_size = '9bp' }\n";
    const double pt = 72.0 / 72.27;
    cf_theme_t th;
    cf_script_t *s;
    (void)state;
    s = new_script(64, 0);
    assert_int_equal(cf_script_run_string(s, code, "fonts"), CF_STATUS_OK);
    cf_figure_get_theme(cf_script_figure(s, 0), &th);
    assert_true(strncmp(th.font_family, "Latin Modern Sans", 17) == 0);
    tu_assert_close(th.role[CF_ROLE_LABEL].font_size, 11 * pt, 1e-12, 0);
    tu_assert_close(th.role[CF_ROLE_AXES].font_size, 8 * 1.1 * pt, 1e-12, 0);
    cf_figure_get_theme(cf_script_figure(s, 1), &th);
    assert_true(strncmp(th.font_family, "Latin Modern Roman", 18) == 0);
    tu_assert_close(th.role[CF_ROLE_LABEL].font_size, 12 * pt, 1e-12, 0);
    cf_figure_get_theme(cf_script_figure(s, 2), &th);
    tu_assert_close(th.role[CF_ROLE_LABEL].font_size, 9, 1e-12, 0);
    cf_script_destroy(s);
    /* the tool's fonts over theme{}, a figure's own over the tool's */
    s = new_script(64, 0);
    cf_script_set_fonts(s, "serif", 10 * pt);
    assert_int_equal(cf_script_run_string(s, code, "fonts"), CF_STATUS_OK);
    cf_figure_get_theme(cf_script_figure(s, 0), &th);
    assert_true(strncmp(th.font_family, "Latin Modern Roman", 18) == 0);
    tu_assert_close(th.role[CF_ROLE_LABEL].font_size, 10 * pt, 1e-12, 0);
    cf_figure_get_theme(cf_script_figure(s, 1), &th);
    tu_assert_close(th.role[CF_ROLE_LABEL].font_size, 12 * pt, 1e-12, 0);
    cf_script_destroy(s);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_api_and_figures),
        cmocka_unit_test(test_theme_fonts),
        cmocka_unit_test(test_error_messages),
        cmocka_unit_test(test_parser_nesting),
        cmocka_unit_test(test_figure_messages),
        cmocka_unit_test(test_limits),
        cmocka_unit_test(test_grow),
        cmocka_unit_test(test_deep_recursion),
        cmocka_unit_test(test_no_finalisers),
        cmocka_unit_test(test_small_budgets),
        cmocka_unit_test(test_pattern_budget),
        cmocka_unit_test(test_two_scripts),
        cmocka_unit_test(test_fuzz_mutations),
    };
    int rc;
    sink = fopen("/dev/null", "w");
    if (sink == NULL)
        return 1;
    rc = cmocka_run_group_tests(tests, NULL, NULL);
    fclose(sink);
    return rc;
}
