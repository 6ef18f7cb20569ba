/*
** Memory budgets swept across whole scripts of the surface half: for each
** script, the smallest budget with which it runs and renders (SVG, PDF) is
** found, and the script is run again with budgets from 16 KiB up to it in
** even steps.  The budget is the allocator of Lua, of the library and of
** the rendering, so each step runs out at another place: in the sandbox,
** in a binding between a C call and the userdata that would own its
** result, in a surface operation, the hidden lines, the layout or a
** writer.  Every run that fails must fail with the memory-limit message
** (nothing else: no wrong error from half-built state); ASan, LSan and
** valgrind check that none of them frees twice or leaks.  test_alloc*.c
** fail the k-th allocation of C operations; this is the same from a
** script, which is how a hostile one reaches it.
*/
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <cmocka.h>

#include "curvefig/figure.h"
#include "script.h"

static FILE *sink;

/* The formats each figure is rendered to (the command line may change
** them), and the steps of a sweep. */
static cf_format_t formats[CF_FORMAT_LAST_] = { CF_FORMAT_SVG,
                                               CF_FORMAT_PDF };
static size_t nformats = 2;

/* Runs path with the budget and renders its figures; OK, or the status
** with the message in msg. */
static cf_status_t
run(const char *path, size_t budget, char *msg, size_t size)
{
    cf_script_limits_t lim = { budget, 0 };
    cf_script_t *s = NULL;
    cf_diag_t diag;
    cf_status_t st;
    cf_diag_clear(&diag);
    msg[0] = '\0';
    st = cf_script_create(&lim, sink, &s, &diag);
    if (st != CF_STATUS_OK) {
        snprintf(msg, size, "%s", diag.msg);
        return st;
    }
    st = cf_script_run_file(s, path);
    if (st != CF_STATUS_OK)
        snprintf(msg, size, "%s", cf_script_error(s));
    for (size_t i = 0; st == CF_STATUS_OK && i < cf_script_figure_count(s);
         i++) {
        for (size_t k = 0; st == CF_STATUS_OK && k < nformats; k++) {
            cf_script_scope_t scope;
            unsigned char *data = NULL;
            size_t n = 0;
            cf_diag_clear(&diag);
            cf_script_budget_begin(s, &scope);
            st = cf_figure_render(cf_script_figure(s, i), formats[k], NULL,
                                  &data, &n, &diag);
            cf_free(data);
            if (cf_script_budget_end(s, &scope, msg, size)) {
                /* a refused allocation is the rendering's failure */
                if (st == CF_STATUS_OK)
                    fail_msg("%s, figure %zu, format %zu, budget %zu: an "
                             "allocation was refused, yet the rendering "
                             "succeeded", path, i, k, budget);
            }
            else if (st != CF_STATUS_OK)
                snprintf(msg, size, "%s", diag.msg);
        }
    }
    cf_script_destroy(s);
    return st;
}

/* A failing run's message names the memory limit. */
static bool
out_of_memory(const char *msg)
{
    return strstr(msg, "memory limit") != NULL;
}

/*
** path: a script; name: how to call it.  A script that fails with the
** default budget (256 MiB) for another reason than memory (a hostile
** script, a bad one) is swept too: each run must end with that same
** message or the memory-limit one; "runs" below is then "ends so".
*/
static void
sweep_file(const char *path, const char *name, int steps)
{
    char msg[1024], *expect = NULL;
    size_t lo = 16 << 10, hi = 1 << 20;
    long failed = 0;
    clock_t t0 = clock();
    if (run(path, (size_t)256 << 20, msg, sizeof msg) != CF_STATUS_OK) {
        if (out_of_memory(msg)) {
            print_message("%-44s runs out of 256 MiB: not swept\n", name);
            return;
        }
        expect = strdup(msg);
        assert_non_null(expect);
    }
    /* the end it has with every budget large enough: a budget that gets
    ** there, then the smallest (to 4 KiB) */
    while (run(path, hi, msg, sizeof msg) != CF_STATUS_OK
           && (expect == NULL || strcmp(msg, expect) != 0)) {
        if (!out_of_memory(msg))
            fail_msg("%s with %zu bytes: %s", name, hi, msg);
        assert_true(hi < ((size_t)1 << 30));
        lo = hi;
        hi *= 2;
    }
    while (hi - lo > (4 << 10)) {
        size_t mid = lo + (hi - lo) / 2;
        if (run(path, mid, msg, sizeof msg) == CF_STATUS_OK
            || (expect != NULL && strcmp(msg, expect) == 0))
            hi = mid;
        else
            lo = mid;
    }
    for (int k = 0; k < steps; k++) {
        size_t budget = (16 << 10) + (hi - (16 << 10)) * (size_t)k
                        / (size_t)steps;
        if (run(path, budget, msg, sizeof msg) == CF_STATUS_OK
            || (expect != NULL && strcmp(msg, expect) == 0))
            continue;
        if (!out_of_memory(msg))
            fail_msg("%s with a budget of %zu bytes: %s%s%s", name, budget,
                     msg, expect != NULL ? "; with more: " : "",
                     expect != NULL ? expect : "");
        failed++;
    }
    print_message("%-44s %s from %zu bytes; %ld of %d smaller budgets "
                  "ran out (%.1f s)\n", name, expect ? "ends so" : "runs",
                  hi, failed, steps, (double)(clock() - t0) / CLOCKS_PER_SEC);
    free(expect);
    assert_true(failed >= steps / 2);
}

/* A script of the source tree. */
static void
sweep(const char *name, int steps)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", CF_SOURCE_ROOT, name);
    sweep_file(path, name, steps);
}

/* The scripts of the command line (see main). */
static char **given;
static int ngiven, given_steps = 200;

static void
test_given_scripts(void **state)
{
    (void)state;
    for (int i = 0; i < ngiven; i++)
        sweep_file(given[i], given[i], given_steps);
}

static void
test_surface_scripts(void **state)
{
    (void)state;
    sweep("figures/surfaces/triangle.lua", 100);
    sweep("figures/surfaces/rational.lua", 100);
    sweep("figures/surfaces/knot-insertion.lua", 100);
    sweep("tests/surfaces/scenes/rational-triangles.lua", 100);
    sweep("tests/surfaces/scenes/space-lines.lua", 100);
    sweep("tests/lua/budget_regions.lua", 100);
}

/* The curve half's figures with what the layout adds: a legend, insets,
** panels, labels placed round the ink. */
static void
test_layout_scripts(void **state)
{
    (void)state;
    sweep("figures/examples/legend.lua", 100);
    sweep("figures/examples/inset.lua", 100);
    sweep("figures/examples/panels.lua", 100);
    sweep("figures/markova-2.17.lua", 100);
}

static int
setup(void **state)
{
    (void)state;
    sink = fopen("/dev/null", "w");
    return sink == NULL ? -1 : 0;
}

static int
teardown(void **state)
{
    (void)state;
    fclose(sink);
    return 0;
}

/*
** test_budget_sweep [--steps N] [--formats svg,pdf,ps,eps,png,pgf]
**                   [SCRIPT ...]
** Without scripts, the ten of the tests above; with scripts, those.
*/
int
main(int argc, char **argv)
{
    static const char *const names[] = { "svg", "pdf", "ps", "eps", "png",
                                          "pgf" };
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_surface_scripts),
        cmocka_unit_test(test_layout_scripts),
    };
    const struct CMUnitTest mine[] = {
        cmocka_unit_test(test_given_scripts),
    };
    int i = 1;
    for (; i + 1 < argc && argv[i][0] == '-'; i += 2) {
        if (strcmp(argv[i], "--steps") == 0) {
            given_steps = atoi(argv[i + 1]);
        } else if (strcmp(argv[i], "--formats") == 0) {
            char *list = argv[i + 1], *f;
            nformats = 0;
            for (f = strtok(list, ","); f != NULL; f = strtok(NULL, ","))
                for (size_t k = 0; k < CF_FORMAT_LAST_; k++)
                    if (strcmp(f, names[k]) == 0
                        && nformats < CF_FORMAT_LAST_)
                        formats[nformats++] = (cf_format_t)k;
        } else {
            break;
        }
    }
    if (given_steps < 1 || nformats == 0) {
        fprintf(stderr, "usage: %s [--steps N] [--formats svg,pdf,ps,eps,"
                "png,pgf] [SCRIPT ...]\n", argv[0]);
        return 2;
    }
    given = argv + i;
    ngiven = argc - i;
    return ngiven > 0 ? cmocka_run_group_tests(mine, setup, teardown)
                      : cmocka_run_group_tests(tests, setup, teardown);
}
