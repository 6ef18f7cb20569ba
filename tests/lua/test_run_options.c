/*
** The options of a run, through the built `curvefig` (suite 'lua'):
** math.random is seeded (--seed, default 0), so that a script drawing
** random numbers renders byte for byte the same twice; --width and
** --height give every figure its page in any unit; a length without a
** unit is refused, on the command line and in figure{}; a misspelt
** format or option names the nearest one.
*/
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

static const char *tool;
static char dir[64];

/* A script that draws random numbers, math.randomseed() without an
** argument between them. */
static const char script[] =
    "local f = figure{ name = 'r', width = '8cm', height = '6cm' }\n"
    "local P = {}\n"
    "for i = 1, 6 do P[i] = { 4 * (i - 1) / 5, math.random() } end\n"
    "math.randomseed()\n"
    "P[#P + 1] = { 4.2, math.random(1, 1000) / 1000 }\n"
    "f:polyline(P)\n";

/* Run the tool on the script with extra options into out/; its exit
** status. */
static int
render(const char *out, const char *extra)
{
    char cmd[1024];
    int rc;
    snprintf(cmd, sizeof cmd, "'%s' render %s/r.lua -f svg -o %s/%s %s "
             ">/dev/null 2>%s/err.txt", tool, dir, dir, out, extra, dir);
    rc = system(cmd);
    return rc == -1 ? -1 : WEXITSTATUS(rc);
}

/* The bytes of dir/name (free them); NULL when unreadable. */
static char *
slurp(const char *name)
{
    char path[256];
    FILE *f;
    char *buf;
    long n;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    f = fopen(path, "rb");
    if (f == NULL)
        return NULL;
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = malloc((size_t)n + 1);
    assert_non_null(buf);
    assert_int_equal(fread(buf, 1, (size_t)n, f), (size_t)n);
    buf[n] = '\0';
    fclose(f);
    return buf;
}

/* The width and height of an SVG's page (its width="..pt"). */
static void
svg_size(const char *name, double *w, double *h)
{
    char *svg = slurp(name);
    const char *p;
    assert_non_null(svg);
    p = strstr(svg, " width=\"");
    assert_non_null(p);
    *w = strtod(p + 8, NULL);
    p = strstr(svg, " height=\"");
    assert_non_null(p);
    *h = strtod(p + 9, NULL);
    free(svg);
}

static void
test_random_is_seeded(void **state)
{
    char *a, *b, *c;
    (void)state;
    assert_int_equal(render("a", ""), 0);
    assert_int_equal(render("b", ""), 0);
    assert_int_equal(render("c", "--seed 7"), 0);
    a = slurp("a/r.svg");
    b = slurp("b/r.svg");
    c = slurp("c/r.svg");
    assert_non_null(a);
    assert_non_null(b);
    assert_non_null(c);
    /* two runs: the same bytes; another seed: another figure */
    assert_string_equal(a, b);
    assert_true(strcmp(a, c) != 0);
    free(a);
    free(b);
    free(c);
    assert_int_equal(render("d", "--seed 0"), 0);
    a = slurp("a/r.svg");
    b = slurp("d/r.svg");
    assert_string_equal(a, b);   /* the default seed is 0 */
    free(a);
    free(b);
    assert_int_equal(render("e", "--seed x1"), 2);
}

static void
test_page_from_the_command_line(void **state)
{
    double w, h, w0, h0;
    char *err;
    (void)state;
    /* the script's 8 cm x 6 cm: the drawing, 4.2 x 1, reaches the width */
    assert_int_equal(render("p0", ""), 0);
    svg_size("p0/r.svg", &w0, &h0);
    assert_true(fabs(w0 - 8 * 72 / 2.54) < 0.1);
    /* 0.9 \linewidth of an 11 pt article: 324 TeX points = 322.79 bp
    ** (the SVG gives the page to 1/1000 bp) */
    assert_int_equal(render("p1", "--width 324texpt"), 0);
    svg_size("p1/r.svg", &w, &h);
    assert_true(fabs(w - 324 * 72 / 72.27) < 0.05);
    assert_true(fabs(w / h - w0 / h0) < 0.02 * w0 / h0);
    /* the height alone: the script's proportions, 4 cm x 3 cm */
    assert_int_equal(render("p2", "--height 3cm"), 0);
    svg_size("p2/r.svg", &w, &h);
    assert_true(fabs(w - 4 * 72 / 2.54) < 0.1);
    /* a length without its unit is refused, naming the points */
    assert_int_equal(render("p3", "--width 8"), 2);
    err = slurp("err.txt");
    assert_non_null(strstr(err, "--width '8': give a length and a unit"));
    assert_non_null(strstr(err, "pt: the PostScript point"));
    assert_non_null(strstr(err, "texpt: TeX's point"));
    free(err);
}

/* A misspelt format or option: the message names the nearest one. */
static void
test_near_names(void **state)
{
    char *err;
    (void)state;
    assert_int_equal(render("q", "-f pdff"), 2);
    err = slurp("err.txt");
    assert_non_null(strstr(err, "bad format list 'pdff' (did you mean pdf?"));
    free(err);
    assert_int_equal(render("q", "--output-dir x"), 2);
    err = slurp("err.txt");
    assert_non_null(strstr(err, "unknown option '--output-dir' (did you mean "
                                "--output, -o?)"));
    free(err);
}

int
main(int argc, char **argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_is_seeded),
        cmocka_unit_test(test_page_from_the_command_line),
        cmocka_unit_test(test_near_names),
    };
    char path[128];
    FILE *f;
    int rc;
    if (argc != 2) {
        fprintf(stderr, "usage: test_run_options TOOL\n");
        return 2;
    }
    tool = argv[1];
    snprintf(dir, sizeof dir, "/tmp/curvefig-run-XXXXXX");
    if (mkdtemp(dir) == NULL)
        return 2;
    snprintf(path, sizeof path, "%s/r.lua", dir);
    f = fopen(path, "w");
    if (f == NULL || fputs(script, f) < 0 || fclose(f) != 0)
        return 2;
    rc = cmocka_run_group_tests(tests, NULL, NULL);
    snprintf(path, sizeof path, "rm -rf '%s'", dir);
    if (system(path) != 0)
        return 2;
    return rc;
}
