/*
** Allocation failure across the library: for representative operations of
** every module, the k-th allocation from the start of the operation fails
** (tests/testutil.h, tu_fail_loop), for k = 1, 2, ... until the
** operation succeeds.  Every failing run must return CF_STATUS_NO_MEMORY
** (with the diag saying so, when the function takes one), leave no output
** object behind and leak nothing (tu_alloc_live() == 0; ASan and valgrind
** check the frees too).  The operations free what they create, so a
** successful run also ends with no live block.
**
** With the renderer (CF_TEST_RENDER): figures, labels, rendering to memory
** and the script runner too; cairo's and pango's own allocations do not
** go through the hook, only curvefig's.
*/
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/curvefig.h"
#include "testutil.h"
#ifdef CF_TEST_RENDER
#include "curvefig/access.h"
#include "curvefig/figure.h"
#include "script.h"
#endif

/* Shared inputs, made once with the default allocator. */
static cf_bezier_t *bez, *rbez;
static cf_bspline_t *bsp, *nurbs, *open_bsp;
static long total_points;   /* failure points exercised, all operations */

static const double P5[] = { 0, 0, 1, 2, 2, -1, 3, 2, 4, 0 };
static const double W5[] = { 1, 2, 0.5, 1.5, 1 };

typedef cf_status_t (*op_fn)(cf_diag_t *diag);

/* tu_fail_loop, counted into total_points. */
static long
fail_loop(const char *name, op_fn op, bool takes_diag)
{
    long points = tu_fail_loop(name, op, takes_diag);
    total_points += points;
    return points;
}

/* ---- core curves -------------------------------------------------------- */

static cf_status_t
op_bezier_create(cf_diag_t *diag)
{
    cf_bezier_t *c = NULL;
    cf_status_t st = cf_bezier_create(2, 4, P5, W5, &c, diag);
    assert_true((st == CF_STATUS_OK) == (c != NULL));
    cf_bezier_destroy(c);
    return st;
}

static cf_status_t
op_bezier_ops(cf_diag_t *diag)
{
    cf_bezier_t *l = NULL, *r = NULL, *e = NULL, *d = NULL, *red = NULL;
    cf_status_t st = cf_bezier_split(rbez, 0.3, &l, &r, diag);
    if (st == CF_STATUS_OK)
        st = cf_bezier_elevate(l, 2, &e, diag);
    if (st == CF_STATUS_OK)
        st = cf_bezier_derivative(r, 1, &d, diag);
    if (st == CF_STATUS_OK)
        st = cf_bezier_reduce(bez, NULL, &red, NULL, diag);
    if (st != CF_STATUS_OK)
        assert_true(red == NULL);
    cf_bezier_destroy(l);
    cf_bezier_destroy(r);
    cf_bezier_destroy(e);
    cf_bezier_destroy(d);
    cf_bezier_destroy(red);
    return st;
}

static cf_status_t
op_bezier_cubics(cf_diag_t *diag)
{
    cf_cubics_t *cu = NULL;
    cf_status_t st = cf_bezier_to_cubics(rbez, 1e-6, &cu, diag);
    assert_true((st == CF_STATUS_OK) == (cu != NULL));
    cf_cubics_destroy(cu);
    return st;
}

static cf_status_t
op_bezier_geometry(cf_diag_t *diag)
{
    double lo[2], hi[2], len, t, dist;
    cf_status_t st;
    (void)diag;
    st = cf_bezier_bbox(rbez, lo, hi);
    if (st == CF_STATUS_OK)
        st = cf_bezier_length(bez, 1e-9, &len);
    if (st == CF_STATUS_OK)
        st = cf_bezier_closest(bez, (const double[]){ 1.5, 3.0 }, &t, &dist);
    return st;
}

static cf_status_t
op_bspline_create(cf_diag_t *diag)
{
    cf_bspline_t *c = NULL, *d = NULL;
    cf_status_t st = cf_bspline_create_clamped(2, 3, P5, 5, W5, &c, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_create_closed(2, 2, P5, 5, NULL, &d, diag);
    cf_bspline_destroy(c);
    cf_bspline_destroy(d);
    return st;
}

static cf_status_t
op_bspline_knots(cf_diag_t *diag)
{
    const double x[] = { 0.2, 0.2, 0.7 };
    cf_bspline_t *a = NULL, *b = NULL, *l = NULL, *r = NULL, *m = NULL;
    int removed = 0;
    cf_status_t st = cf_bspline_insert_knot(nurbs, 0.4, 2, &a, NULL, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_refine(bsp, x, 3, &b, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_remove_knot(b, 0.2, 2, 1e-9, &m, &removed, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_split(open_bsp, 0.5 * (cf_bspline_knots(open_bsp)[3]
                                             + cf_bspline_knots(open_bsp)[4]),
                              &l, &r, diag);
    cf_bspline_destroy(a);
    cf_bspline_destroy(b);
    cf_bspline_destroy(l);
    cf_bspline_destroy(r);
    cf_bspline_destroy(m);
    return st;
}

static cf_status_t
op_bspline_convert(cf_diag_t *diag)
{
    cf_bezier_list_t *list = NULL;
    cf_bspline_t *e = NULL, *d = NULL, *s = NULL;
    double *h = NULL, *br = NULL;
    size_t n = 0;
    cf_status_t st = cf_bspline_to_beziers(nurbs, &list, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_bezier_points(open_bsp, &h, &br, &n, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_elevate(bsp, 1, &e, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_derivative(nurbs, 1, &d, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_segment(bsp, 0.1, 0.8, &s, diag);
    cf_bezier_list_destroy(list);
    cf_free(h);
    cf_free(br);
    cf_bspline_destroy(e);
    cf_bspline_destroy(d);
    cf_bspline_destroy(s);
    return st;
}

static cf_status_t
op_nurbs_conics(cf_diag_t *diag)
{
    cf_bspline_t *c = NULL;
    cf_bezier_list_t *l = NULL, *e = NULL;
    cf_status_t st = cf_nurbs_circle((const double[]){ 1, 2 }, 3, &c, diag);
    if (st == CF_STATUS_OK)
        st = cf_conic_circle(0, 0, 1, &l, diag);
    if (st == CF_STATUS_OK)
        st = cf_conic_ellipse(0, 0, 2, 1, 0.3, 0, 5, &e, diag);
    cf_bspline_destroy(c);
    cf_bezier_list_destroy(l);
    cf_bezier_list_destroy(e);
    return st;
}

static double
square(double t, void *ud)
{
    (void)ud;
    return t * t;
}

static cf_status_t
op_bernstein_hull(cf_diag_t *diag)
{
    cf_bezier_t *c = NULL;
    size_t idx[5], n;
    double M[16];
    cf_status_t st = cf_bernstein_approx_curve(square, NULL, 6, &c, diag);
    if (st == CF_STATUS_OK)
        st = cf_bernstein_to_power_matrix(3, M, diag);
    if (st == CF_STATUS_OK)
        st = cf_bezier_hull(bez, idx, &n, diag);
    if (st == CF_STATUS_OK)
        st = cf_convex_hull_2d(P5, 5, 2, idx, &n, diag);
    cf_bezier_destroy(c);
    return st;
}

static cf_status_t
op_interp(cf_diag_t *diag)
{
    static const cf_interp_method_t methods[] = {
        CF_INTERP_NATURAL, CF_INTERP_NOT_A_KNOT, CF_INTERP_PERIODIC,
        CF_INTERP_CATMULL_ROM, CF_INTERP_GLOBAL,
    };
    cf_status_t st = CF_STATUS_OK;
    for (size_t i = 0; i < 5 && st == CF_STATUS_OK; i++) {
        cf_interp_options_t opt;
        cf_bspline_t *c = NULL;
        cf_interp_options_init(&opt);
        opt.method = methods[i];
        opt.param = CF_PARAM_CHORD;
        st = cf_interpolate(2, P5, 5, &opt, &c, diag);
        cf_bspline_destroy(c);
    }
    return st;
}

static cf_status_t
op_approx_chains(cf_diag_t *diag)
{
    cf_bspline_t *c = NULL;
    cf_bezier_list_t *f = NULL, *k = NULL;
    double res;
    const double T5[] = { 1, 0, 1, 1, 0, 1, -1, 0, 1, 1 };
    cf_status_t st = cf_approximate_lsq(2, P5, 5, 4, NULL, true, &c, &res,
                                        diag);
    if (st == CF_STATUS_OK)
        st = cf_ferguson_chain(2, P5, T5, 5, &f, diag);
    if (st == CF_STATUS_OK)
        st = cf_coons_chain(2, P5, 5, CF_COONS_TRIPLED, &k, diag);
    cf_bspline_destroy(c);
    cf_bezier_list_destroy(f);
    cf_bezier_list_destroy(k);
    return st;
}

static cf_status_t
op_offset(cf_diag_t *diag)
{
    cf_offset_options_t opt;
    cf_cubics_t *raw = NULL;
    cf_cubics_list_t *trim = NULL;
    cf_offset_report_t rep;
    cf_status_t st;
    cf_offset_options_init(&opt);
    opt.trim = true;
    st = cf_bezier_offset(bez, 0.3, &opt, &raw, &trim, &rep, diag);
    cf_cubics_destroy(raw);
    cf_cubics_list_destroy(trim);
    return st;
}

#ifdef CF_TEST_RENDER
/* ---- renderer and script runner ---------------------------------------- */

static cf_status_t
op_label(cf_diag_t *diag)
{
    cf_label_t *lab = NULL;
    cf_status_t st = cf_label_create("B_i^n(t) = \\frac{1}{2} P_{k-p+1,1}",
                                     NULL, 10.0, &lab, diag);
    assert_true((st == CF_STATUS_OK) == (lab != NULL));
    cf_label_destroy(lab);
    return st;
}

/* A figure of curves, a polygon and labels rendered to format; labels in
** Latin, mathematics and Russian (PDF: text in three embedded fonts). */
static cf_status_t
figure_to(cf_format_t format, cf_diag_t *diag)
{
    cf_figure_t *fig = NULL;
    cf_style_t style;
    unsigned char *data = NULL;
    size_t size = 0;
    cf_status_t st = cf_figure_create(8, 6, CF_UNIT_CM, &fig, diag);
    if (st != CF_STATUS_OK)
        return st;
    cf_style_init(&style);
    st = cf_figure_add_bezier(fig, rbez, &style);
    if (st == CF_STATUS_OK)
        st = cf_figure_add_bspline(fig, nurbs, 0, 1, &style);
    if (st == CF_STATUS_OK)
        st = cf_figure_add_polygon(fig, P5, 5, &style);
    if (st == CF_STATUS_OK)
        st = cf_figure_add_label(fig, 1, 2, "P_0", &style);
    if (st == CF_STATUS_OK && format == CF_FORMAT_PDF)
        st = cf_figure_add_label(fig, 3, 1, "\\text{кривая} \\frac{1}{2}",
                                 &style);
    if (st == CF_STATUS_OK)
        st = cf_figure_render(fig, format, NULL, &data, &size, diag);
    else
        st = cf_figure_status(fig, diag);
    cf_free(data);
    cf_figure_destroy(fig);
    return st;
}

static cf_status_t
op_figure(cf_diag_t *diag)
{
    return figure_to(CF_FORMAT_SVG, diag);
}

/* the PDF writer: pages, fonts subset and embedded, the document */
static cf_status_t
op_figure_pdf(cf_diag_t *diag)
{
    return figure_to(CF_FORMAT_PDF, diag);
}

/*
** The script runner allocates through its own budget (Lua's allocator and
** the library's hook both count against max_memory, in bytes), not through
** the test hook, so it is driven the other way: the budget grows from
** 16 KiB in steps of 16 KiB until the script runs.  Every smaller budget
** must fail cleanly with the memory-limit message (no crash; ASan and
** valgrind check that nothing leaks).  Returns the number of budgets that
** failed.
*/
static long
script_budget_loop(void)
{
    static const char code[] =
        "local c = bspline{ degree = 2, points = {{0,0},{1,2},{2,0},{3,1}} }\n"
        "local f = figure{ name = 'a' }\n"
        "f:curve((c:insert_knot(0.5))):polygon(c, { labels = 'P_%d' })\n"
        "local keep = {}\n"
        "for i = 1, 3000 do keep[i] = bezier{ {0, 0}, {i, 1}, {2, i} } end\n"
        "for i = 1, 3000, 7 do f:curve(keep[i]:elevate(2)) end\n";
    FILE *sink = fopen("/dev/null", "w");
    size_t budget;
    long failures = 0;
    assert_non_null(sink);
    for (budget = 16 << 10; budget < (64u << 20); budget += 16 << 10) {
        cf_script_limits_t lim = { budget, 0 };
        cf_script_t *s = NULL;
        cf_diag_t diag;
        cf_status_t st;
        cf_diag_clear(&diag);
        st = cf_script_create(&lim, sink, &s, &diag);
        if (st != CF_STATUS_OK) {
            /* too small even for the sandbox's own tables */
            assert_int_equal(st, CF_STATUS_NO_MEMORY);
            assert_null(s);
            failures++;
            continue;
        }
        st = cf_script_run_string(s, code, "alloc.lua");
        if (st == CF_STATUS_OK) {
            assert_int_equal(cf_script_figure_count(s), 1);
            cf_script_destroy(s);
            break;
        }
        if (strstr(cf_script_error(s), "memory limit") == NULL)
            fail_msg("budget %zu: %s", budget, cf_script_error(s));
        cf_script_destroy(s);
        failures++;
    }
    assert_true(budget < (64u << 20));
    fclose(sink);
    print_message("%-28s %4ld memory budgets too small (16 KiB + 16 KiB "
                  "steps)\n", "script run", failures);
    total_points += failures;
    return failures;
}
#endif

static void
test_core_modules(void **state)
{
    (void)state;
    assert_true(fail_loop("bezier_create", op_bezier_create, true) >= 1);
    assert_true(fail_loop("bezier split/elevate/...", op_bezier_ops, true)
                >= 4);
    assert_true(fail_loop("bezier_to_cubics", op_bezier_cubics, true) >= 2);
    fail_loop("bezier bbox/length/closest", op_bezier_geometry, false);
    assert_true(fail_loop("bspline create", op_bspline_create, true) >= 2);
    assert_true(fail_loop("bspline insert/refine/...", op_bspline_knots,
                          true) >= 4);
    assert_true(fail_loop("bspline to_beziers/...", op_bspline_convert, true)
                >= 5);
    assert_true(fail_loop("nurbs circle, conics", op_nurbs_conics, true)
                >= 3);
    assert_true(fail_loop("bernstein, hulls", op_bernstein_hull, true) >= 1);
    assert_true(fail_loop("interpolate (5 methods)", op_interp, true) >= 5);
    assert_true(fail_loop("approximate, chains", op_approx_chains, true)
                >= 3);
    assert_true(fail_loop("offset (trimmed)", op_offset, true) >= 2);
}

#ifdef CF_TEST_RENDER
/* The automatic description of a figure whose curves are made from one
** another (a split, an elevation, knot insertion): the relations are
** found by making the curves again, which allocates. */
static cf_status_t
op_description(cf_diag_t *diag)
{
    cf_figure_t *fig = NULL;
    cf_bezier_t *left = NULL, *up = NULL;
    cf_bspline_t *more = NULL;
    cf_style_t style;
    char *text = NULL;
    cf_status_t st = cf_bezier_split(bez, 0.4, &left, NULL, diag);
    if (st == CF_STATUS_OK)
        st = cf_bezier_elevate(bez, 1, &up, diag);
    if (st == CF_STATUS_OK)
        st = cf_bspline_insert_knot(bsp, 0.5, 1, &more, NULL, diag);
    if (st == CF_STATUS_OK)
        st = cf_figure_create(8, 6, CF_UNIT_CM, &fig, diag);
    if (st == CF_STATUS_OK) {
        cf_style_init(&style);
        if (cf_figure_add_bezier(fig, bez, &style) != CF_STATUS_OK
            || cf_figure_add_bezier(fig, left, &style) != CF_STATUS_OK
            || cf_figure_add_bezier(fig, up, &style) != CF_STATUS_OK
            || cf_figure_add_bspline(fig, bsp, 0, 1, &style) != CF_STATUS_OK
            || cf_figure_add_bspline(fig, more, 0, 1, &style) != CF_STATUS_OK
            || cf_figure_set_description(fig, "auto") != CF_STATUS_OK)
            st = cf_figure_status(fig, diag);
    }
    if (st == CF_STATUS_OK && (st = cf_figure_description(fig, &text))
                              != CF_STATUS_OK)
        cf_figure_status(fig, diag);
    if (st == CF_STATUS_OK) {   /* the three relations named */
        assert_non_null(strstr(text, "curve 1 before t = 0.4"));
        assert_non_null(strstr(text, "degree raised from 4 to 5"));
        assert_non_null(strstr(text, "after knot insertion at u = 1/2"));
    }
    cf_free(text);
    cf_figure_destroy(fig);
    cf_bspline_destroy(more);
    cf_bezier_destroy(up);
    cf_bezier_destroy(left);
    return st;
}

static void
test_render_modules(void **state)
{
    (void)state;
    assert_true(fail_loop("label_create", op_label, true) >= 1);
    assert_true(fail_loop("figure + render svg", op_figure, true) >= 4);
    assert_true(fail_loop("figure + render pdf", op_figure_pdf, true)
                >= 20);
    assert_true(fail_loop("automatic description", op_description, true)
                >= 4);
    /* the script runner: every budget too small for the script */
    assert_true(script_budget_loop() >= 10);
}
#endif

static int
setup(void **state)
{
    const double U[] = { 0, 0, 0, 0.3, 0.55, 0.8, 1.0, 1.2 };
    (void)state;
    if (cf_bezier_create(2, 4, P5, NULL, &bez, NULL) != CF_STATUS_OK ||
        cf_bezier_create(2, 4, P5, W5, &rbez, NULL) != CF_STATUS_OK ||
        cf_bspline_create_clamped(2, 2, P5, 5, NULL, &bsp, NULL) != 0 ||
        cf_bspline_create_clamped(2, 3, P5, 5, W5, &nurbs, NULL) != 0 ||
        cf_bspline_create(2, 2, U, 8, P5, 5, NULL, &open_bsp, NULL) != 0)
        return -1;
    return 0;
}

static int
teardown(void **state)
{
    (void)state;
    cf_bezier_destroy(bez);
    cf_bezier_destroy(rbez);
    cf_bspline_destroy(bsp);
    cf_bspline_destroy(nurbs);
    cf_bspline_destroy(open_bsp);
    print_message("%ld allocation failure points in all\n", total_points);
    return 0;
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_core_modules),
#ifdef CF_TEST_RENDER
        cmocka_unit_test(test_render_modules),
#endif
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
