/* The curvefig tool against hostile scripts (the sandbox: no os, io,
** require, bytecode; limits of time, memory, tables, strings, patterns),
** errors with file and line, and every exit status (the shared helpers in
** test_tool.h). */
#include "test_tool.h"

/* ---- the sandbox -------------------------------------------------------- */

static void
hostile(void **state, const char *script, const char *message)
{
    result *r = *state;
    const char *args[] = { "render", src(script), "--max-memory", "32",
                           "--max-instructions", "2e7", NULL };
    run_tool(r, args);
    assert_int_equal(r->status, 1);
    assert_contains(r->err, message);
    /* the script's file and line */
    assert_contains(r->err, script);
    assert_int_equal(count_files(r->dir), 0);
}

static void
test_hostile_os(void **state)
{
    hostile(state, "hostile/os_execute.lua",
            "os_execute.lua:2: 'os' is not available to figure scripts");
}

static void
test_hostile_io(void **state)
{
    hostile(state, "hostile/io_open.lua",
            "io_open.lua:2: 'io' is not available to figure scripts");
}

static void
test_hostile_require(void **state)
{
    hostile(state, "hostile/require.lua",
            "require.lua:2: 'require' is not available to figure scripts");
}

static void
test_hostile_bytecode(void **state)
{
    hostile(state, "hostile/bytecode.lua",
            "bytecode.lua:3: load: binary (bytecode) chunks are not allowed");
}

static void
test_hostile_endless_loop(void **state)
{
    hostile(state, "hostile/endless.lua",
            "endless.lua:4: script exceeded the instruction limit of "
            "20000000 instructions");
}

static void
test_hostile_huge_table(void **state)
{
    hostile(state, "hostile/huge_table.lua",
            "huge_table.lua:5: script exceeded the memory limit of 32 MiB");
}

static void
test_hostile_huge_string(void **state)
{
    hostile(state, "hostile/huge_string.lua",
            "huge_string.lua:3: script exceeded the memory limit of 32 MiB");
}

/* A pattern search that would backtrack for hours inside one C call: its
** steps are counted before it runs, against the instruction limit (finding
** F9; before, only the tool's watchdog ended it). */
static void
test_hostile_pattern(void **state)
{
    hostile(state, "hostile/pattern.lua",
            "pattern.lua:4: script exceeded the instruction limit of "
            "20000000 instructions");
}

/* The tool's wall-clock watchdog: an endless loop under an instruction
** limit too large to reach within the --timeout. */
/* A point whose place on the page overflows: a clear error naming the
** element (the rasteriser of the label placement crashed on it). */
static void
test_hostile_far_point(void **state)
{
    hostile(state, "hostile/far_point.lua",
            "far_point.lua:4: figure 'far': polyline 1 (line 5) lies too far "
            "outside the drawing's 60.0 x 40.0 mm page to be drawn (its place "
            "on the page overflows to inf); move it nearer");
}

/* A label 1e300 bp from its point: the error naming it and its line
** (the label placement's ink sums read outside their raster). */
static void
test_hostile_far_label(void **state)
{
    hostile(state, "hostile/far_label.lua",
            "far_label.lua:5: figure 'far': label 2 \"P\" (line 7) lies "
            "2.494e+299 mm outside the drawing's 60.0 x 40.0 mm page");
}

/* Dash patterns too fine, or along a line too long, to measure dash by
** dash: drawn in bounded time (each ran for ever), PDF and PNG written. */
static void
test_hostile_fine_dash(void **state)
{
    result *r = *state;
    const char *args[] = { "render", src("hostile/fine_dash.lua"), "-f",
                           "pdf,png", "--timeout", "60", NULL };
    run_tool(r, args);
    assert_int_equal(r->status, 0);
    assert_int_equal(count_files(r->dir), 2);
}

static void
test_timeout(void **state)
{
    result *r = *state;
    const char *args[] = { "run", src("hostile/endless.lua"), "--timeout",
                           "1", "--max-instructions", "1e15", NULL };
    run_tool(r, args);
    assert_int_equal(r->status, 1);
    assert_contains(r->err, "endless.lua: the script exceeded the time "
                            "limit of 1 s (--timeout)");
    assert_string_equal(r->out, "");
    assert_int_equal(count_files(r->dir), 0);
}

/* `live --once` under the limits of render: a run that spins (the
** handler of xpcall loops, which escapes the instruction hook on the
** parent commit) ends with the time-limit error, in the JSON and on
** stderr, within the limit and a margin. */
static void
test_live_once_timeout(void **state)
{
    result *r = *state;
    const char *args[] = { "live", "xp.lua", "--once", "--timeout", "2",
                           "--max-instructions", "1e15", NULL };
    struct timespec t0, t1;
    double took;
    put_file(r, "xp.lua", "xpcall(error, function() while true do end end)\n",
             NULL, 0);
    clock_gettime(CLOCK_MONOTONIC, &t0);
    run_tool(r, args);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    took = (double)(t1.tv_sec - t0.tv_sec)
           + (double)(t1.tv_nsec - t0.tv_nsec) * 1e-9;
    assert_int_equal(r->status, 1);
    assert_contains(r->err, "xp.lua: the script exceeded the time limit of "
                            "2 s (--timeout)");
    assert_contains(r->out, "\"error\": {\"message\": \"xp.lua: the script "
                            "exceeded the time limit of 2 s");
    if (took > 6)
        fail_msg("live --once took %.1f s with --timeout 2", took);
}

static void
test_hostile_metatable(void **state)
{
    hostile(state, "hostile/metatable.lua", "metatable is locked");
}

/* A bytecode file given as the script itself. */
static void
test_bytecode_script_refused(void **state)
{
    result *r = *state;
    char path[300];
    FILE *f;
    const char *args[] = { "run", path, NULL };
    snprintf(path, sizeof path, "/tmp/curvefig-bc-%d.lua", (int)getpid());
    f = fopen(path, "wb");
    assert_non_null(f);
    fputs("\033LuaT\0\031\223\r\n", f);
    fclose(f);
    run_tool(r, args);
    remove(path);
    assert_int_equal(r->status, 1);
    assert_contains(r->err, "binary (bytecode) chunks are not allowed");
}

/* ---- errors with file and line ------------------------------------------ */

static void
test_syntax_error_position(void **state)
{
    result *r = *state;
    const char *args[] = { "run", src("broken_syntax.lua"), NULL };
    run_tool(r, args);
    assert_int_equal(r->status, 1);
    assert_contains(r->err, "broken_syntax.lua:4: unexpected symbol near '='");
}

static void
test_runtime_error_position(void **state)
{
    result *r = *state;
    const char *args[] = { "render", src("broken_runtime.lua"), NULL };
    run_tool(r, args);
    assert_int_equal(r->status, 1);
    assert_contains(r->err, "broken_runtime.lua:5: bspline: 10 knots given, "
                            "degree 2 with 8 points needs 11");
    assert_contains(r->err, "from ");
    assert_contains(r->err, "broken_runtime.lua:8");
    assert_contains(r->err, "broken_runtime.lua:11");
    assert_int_equal(count_files(r->dir), 0);
}

/* ---- exit statuses ------------------------------------------------------ */

static void
expect_status(void **state, int status, const char *message,
              const char *const *args)
{
    result *r = *state;
    run_tool(r, args);
    if (r->status != status)
        fail_msg("status %d, expected %d; stderr:\n%s", r->status, status,
                 r->err);
    if (message != NULL)
        assert_contains(status == 0 ? r->out : r->err, message);
    reset(r);
}

static void
test_exit_statuses(void **state)
{
    const char *none[] = { NULL };
    const char *help[] = { "--help", NULL };
    const char *lang[] = { "help", "language", NULL };
    const char *version[] = { "--version", NULL };
    const char *unknown[] = { "paint", NULL };
    const char *badopt[] = { "render", src("multi.lua"), "--colour", NULL };
    const char *badfmt[] = { "render", src("multi.lua"), "-f", "svg,jpg",
                             NULL };
    const char *baddpi[] = { "render", src("multi.lua"), "--dpi", "0",
                             NULL };
    const char *noval[] = { "render", src("multi.lua"), "-o", NULL };
    const char *noscript[] = { "run", NULL };
    const char *twoscripts[] = { "run", src("multi.lua"), src("multi.lua"),
                                 NULL };
    const char *missing[] = { "run", "no-such-script.lua", NULL };
    const char *badonly[] = { "render", src("multi.lua"), "--only", "nope",
                              NULL };
    const char *failing[] = { "run", src("broken_syntax.lua"), NULL };
    const char *unwritable[] = { "render", src("multi.lua"), "-o",
                                 "/proc/curvefig-cannot-write", NULL };
    const char *ok[] = { "run", src("core_bezier.lua"), NULL };
    expect_status(state, 2, "no command given", none);
    expect_status(state, 0, "usage: curvefig", help);
    expect_status(state, 0, "f:decasteljau(c, t", lang);
    expect_status(state, 0, "curvefig ", version);
    expect_status(state, 2, "unknown command 'paint'", unknown);
    expect_status(state, 2, "unknown option '--colour'", badopt);
    expect_status(state, 2, "bad format list 'svg,jpg'", badfmt);
    expect_status(state, 2, "--dpi '0'", baddpi);
    expect_status(state, 2, "option '-o' needs a value", noval);
    expect_status(state, 2, "run: no script given", noscript);
    expect_status(state, 2, "give exactly one script", twoscripts);
    expect_status(state, 2, "cannot read the script no-such-script.lua",
                  missing);
    expect_status(state, 2, "defines no figure named 'nope'", badonly);
    expect_status(state, 1, "broken_syntax.lua:4:", failing);
    expect_status(state, 1, "cannot create the directory", unwritable);
    expect_status(state, 0, "core_bezier: ok", ok);
}

int
main(int argc, char **argv)
{
    const struct CMUnitTest tests[] = {
        T(test_hostile_os),
        T(test_hostile_io),
        T(test_hostile_require),
        T(test_hostile_bytecode),
        T(test_hostile_endless_loop),
        T(test_hostile_huge_table),
        T(test_hostile_huge_string),
        T(test_hostile_pattern),
        T(test_hostile_far_point),
        T(test_hostile_far_label),
        T(test_hostile_fine_dash),
        T(test_timeout),
        T(test_live_once_timeout),
        T(test_hostile_metatable),
        T(test_bytecode_script_refused),
        T(test_syntax_error_position),
        T(test_runtime_error_position),
        T(test_exit_statuses),
    };
    if (tool_args(argc, argv) != 0)
        return 2;
    return cmocka_run_group_tests(tests, NULL, NULL);
}
