/* Figures: bad input and sticky errors, huge extents, knot lists and
** tangents, out of memory (the shared helpers in test_figure.h). */
#include "test_figure.h"

/* ---- errors ------------------------------------------------------------- */

#define EXPECT(call, status)                                               \
    do {                                                                   \
        cf_figure_t *fig = new_fig();                                      \
        cf_diag_t dg_;                                                     \
        cf_diag_clear(&dg_);                                               \
        assert_int_equal((call), (status));                                \
        assert_int_equal(cf_figure_status(fig, &dg_), (status));           \
        assert_true(strlen(dg_.msg) > 0);                                  \
        cf_figure_destroy(fig);                                            \
    } while (0)

static void
test_bad_input(void **state)
{
    double pts[] = { 0, 0, 1, 1, 2, 0 }, nanpts[] = { 0, 0, NAN, 1 };
    double one[] = { 0, 1 };
    cf_bezier_t *line, *c1;
    cf_style_t bad;
    cf_axes_t ax;
    cf_figure_t *f2 = NULL;
    const cf_bezier_t *pieces[1];
    size_t counts[] = { 2, 0 };
    (void)state;
    assert_int_equal(cf_bezier_create(2, 1, pts, NULL, &line, NULL), 0);
    assert_int_equal(cf_bezier_create(1, 1, one, NULL, &c1, NULL), 0);
    cf_style_init(&bad);
    bad.set = CF_STYLE_WIDTH;
    bad.width = -1;

    /* creation */
    assert_int_equal(cf_figure_create(0, 10, CF_UNIT_MM, &f2, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_null(f2);
    assert_int_equal(cf_figure_create(-5, 10, CF_UNIT_MM, &f2, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_figure_create(NAN, 10, CF_UNIT_MM, &f2, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_figure_create(10, INFINITY, CF_UNIT_MM, &f2, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_figure_create(10, 10, (cf_unit_t)42, &f2, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_figure_create(10, 10, CF_UNIT_MM, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_null(f2);

    /* elements */
    EXPECT(cf_figure_add_points(fig, nanpts, 2, NULL), CF_STATUS_NOT_FINITE);
    EXPECT(cf_figure_add_points(fig, NULL, 2, NULL), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_polygon(fig, pts, 0, NULL),
           CF_STATUS_TOO_FEW_POINTS);
    EXPECT(cf_figure_add_polyline(fig, pts, 1, false, NULL),
           CF_STATUS_TOO_FEW_POINTS);
    EXPECT(cf_figure_add_fill(fig, pts, 2, NULL), CF_STATUS_TOO_FEW_POINTS);
    EXPECT(cf_figure_add_hull(fig, nanpts, 2, NULL), CF_STATUS_NOT_FINITE);
    EXPECT(cf_figure_add_polygon(fig, pts, 3, &bad), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_bezier(fig, NULL, NULL), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_bezier(fig, c1, NULL), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_bezier_range(fig, line, 0.5, 0.2, NULL),
           CF_STATUS_DOMAIN);
    EXPECT(cf_figure_add_bezier_range(fig, line, NAN, 0.2, NULL),
           CF_STATUS_NOT_FINITE);
    EXPECT(cf_figure_add_cubics(fig, NULL, NULL), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_arrow(fig, 0, 0, NAN, 1, NULL),
           CF_STATUS_NOT_FINITE);
    EXPECT(cf_figure_add_label(fig, 0, 0, "P_", NULL),
           CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_label(fig, INFINITY, 0, "P", NULL),
           CF_STATUS_NOT_FINITE);
    EXPECT(cf_figure_add_label(fig, 0, 0, NULL, NULL),
           CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_net(fig, pts, counts, 2, NULL, NULL),
           CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_net(fig, pts, NULL, 1, NULL, NULL),
           CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_knot_marks(fig, pts, nanpts, 2, NULL),
           CF_STATUS_NOT_FINITE);
    pieces[0] = c1;
    EXPECT(cf_figure_add_graph(fig, pieces, NULL, 1, NULL),
           CF_STATUS_INVALID_ARG);
    {
        double rev[] = { 1, 0 };
        EXPECT(cf_figure_add_graph(fig, pieces, rev, 1, NULL),
               CF_STATUS_INVALID_ARG);
    }
    EXPECT(cf_figure_add_graph_list(fig, NULL, NULL), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_function(fig, NULL, NULL, 0, 1, NULL),
           CF_STATUS_INVALID_ARG);
    cf_axes_init(&ax);
    ax.xmin = 2;
    ax.xmax = 1;
    EXPECT(cf_figure_add_axes(fig, &ax, NULL), CF_STATUS_INVALID_ARG);
    cf_axes_init(&ax);
    ax.ymax = NAN;
    EXPECT(cf_figure_add_axes(fig, &ax, NULL), CF_STATUS_NOT_FINITE);
    cf_axes_init(&ax);
    ax.xtick_step = 1e-9;
    EXPECT(cf_figure_add_axes(fig, &ax, NULL), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_set_window(fig, 1, 1, 0, 1), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_set_window(fig, 0, 1, NAN, 1), CF_STATUS_NOT_FINITE);
    EXPECT(cf_figure_set_fit(fig, -1, true), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_set_tolerance(fig, 0), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_set_projection(fig, 1, pts), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_set_theme(fig, NULL), CF_STATUS_INVALID_ARG);
    {
        cf_theme_t t;
        assert_int_equal(cf_theme_get("default", &t, NULL), 0);
        t.palette_size = 0;
        EXPECT(cf_figure_set_theme(fig, &t), CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_theme_get("mono", &t, NULL), 0);
        t.role[CF_ROLE_CURVE].color.r = 2;
        EXPECT(cf_figure_set_theme(fig, &t), CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_theme_get("neon", &t, NULL),
                         CF_STATUS_INVALID_ARG);
    }
    /* NULL figure */
    assert_int_equal(cf_figure_add_points(NULL, pts, 1, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_figure_status(NULL, NULL), CF_STATUS_INVALID_ARG);
    cf_figure_destroy(NULL);

    /* names */
    {
        cf_marker_t mk;
        cf_place_t pl;
        cf_unit_t un;
        cf_color_t col;
        assert_int_equal(cf_marker_from_name("star", &mk, NULL), 0);
        assert_int_equal(mk, CF_MARKER_STAR);
        assert_int_equal(cf_marker_from_name("blob", &mk, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_place_from_name("below", &pl, NULL), 0);
        assert_int_equal(pl, CF_PLACE_S);
        assert_int_equal(cf_place_from_name("up", &pl, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_unit_from_name("texpt", &un, NULL), 0);
        assert_int_equal(un, CF_UNIT_TEXPT);
        assert_int_equal(cf_unit_from_name("px", &un, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_color_parse("#ff800080", &col, NULL), 0);
        tu_assert_close(col.g, 128.0 / 255, 1e-15, 0);
        tu_assert_close(col.a, 128.0 / 255, 1e-15, 0);
        assert_int_equal(cf_color_parse("#ff80", &col, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_color_parse("#gg0000", &col, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_color_parse("chartreuse", &col, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_color_parse("none", &col, NULL), 0);
        assert_true(col.a == 0);
    }
    cf_bezier_destroy(line);
    cf_bezier_destroy(c1);
}

/* Coordinates near DBL_MAX: the extent overflows; the write fails with a
** message saying so, not with a tolerance the user never set (finding
** F4). */
static void
test_huge_extent_refused(void **state)
{
    const double pts[] = { -1.7e308, 0.0, 1.7e308, 1.0 };
    cf_figure_t *fig = NULL;
    unsigned char *data = NULL;
    size_t size = 0;
    cf_diag_t d;
    (void)state;
    assert_int_equal(cf_figure_create(8, 6, CF_UNIT_CM, &fig, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_figure_add_polyline(fig, pts, 2, false, NULL),
                     CF_STATUS_OK);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, NULL, &data,
                                      &size, &d), CF_STATUS_NOT_FINITE);
    assert_null(data);
    assert_non_null(strstr(d.msg, "the drawing spans"));
    assert_non_null(strstr(d.msg, "too large"));
    cf_figure_destroy(fig);

    assert_int_equal(cf_figure_create(8, 6, CF_UNIT_CM, &fig, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_figure_set_window(fig, -1e308, 1e308, -1e308,
                                          1e308), CF_STATUS_OK);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, NULL, &data,
                                      &size, &d), CF_STATUS_NOT_FINITE);
    assert_non_null(strstr(d.msg, "the window spans"));
    cf_figure_destroy(fig);
}

static void
test_sticky_error(void **state)
{
    double pts[] = { 0, 0, 1, 1 }, nanpts[] = { 0, NAN };
    cf_figure_t *fig = new_fig();
    cf_diag_t d;
    unsigned char *data = NULL;
    size_t size = 1;
    (void)state;
    assert_int_equal(cf_figure_add_polygon(fig, pts, 2, NULL), 0);
    assert_int_equal(cf_figure_add_points(fig, nanpts, 1, NULL),
                     CF_STATUS_NOT_FINITE);
    /* the first error is kept; later calls do nothing and return it */
    assert_int_equal(cf_figure_add_label(fig, 0, 0, "P_", NULL),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_figure_add_polygon(fig, pts, 2, NULL),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_figure_set_tolerance(fig, 1), CF_STATUS_NOT_FINITE);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_status(fig, &d), CF_STATUS_NOT_FINITE);
    assert_int_equal(d.status, CF_STATUS_NOT_FINITE);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, NULL, &data, &size,
                                      &d), CF_STATUS_NOT_FINITE);
    assert_null(data);
    assert_int_equal(size, 0);
    assert_true(strlen(d.msg) > 0);
    cf_figure_destroy(fig);
}

/* A constant (degree-0) graph piece is drawn as a horizontal segment over
** its whole interval (f:bernstein(0, 0) in the figure language: B_0^0 = 1
** on [0, 1]).  The piece is widened to degree 1 inside the renderer. */
static void
test_graph_constant_piece(void **state)
{
    double y0 = 0.75, breaks[] = { -1, 2 };
    cf_bezier_t *c = NULL;
    const cf_bezier_t *pieces[1];
    cf_figure_t *fig = NULL;
    char *text = NULL;
    const char *p;
    size_t size;
    double w[4], x0, ya, x1, yb, c1[4];
    (void)state;
    assert_int_equal(cf_bezier_create(1, 0, &y0, NULL, &c, NULL), 0);
    assert_int_equal(cf_figure_create(60, 40, CF_UNIT_MM, &fig, NULL), 0);
    pieces[0] = c;
    assert_int_equal(cf_figure_add_graph(fig, pieces, breaks, 1, NULL), 0);
    assert_int_equal(cf_figure_get_window(fig, w, NULL, NULL), 0);
    assert_float_equal(w[0], -1, 1e-12);
    assert_float_equal(w[1], 2, 1e-12);
    assert_int_equal(cf_figure_dump(fig, NULL, &text, &size, NULL), 0);
    p = strstr(text, " : M ");
    assert_non_null(p);
    assert_int_equal(sscanf(p, " : M %lf %lf C %lf %lf %lf %lf %lf %lf", &x0,
                            &ya, &c1[0], &c1[1], &c1[2], &c1[3], &x1, &yb),
                     8);
    /* one horizontal cubic from the left end to the right end */
    assert_float_equal(ya, yb, 1e-9);
    assert_float_equal(c1[1], ya, 1e-9);
    assert_float_equal(c1[3], ya, 1e-9);
    assert_true(x1 - x0 > 100);
    cf_free(text);
    cf_figure_destroy(fig);
    cf_bezier_destroy(c);
}

/* The distinct knots of a B-spline with their first index and
** multiplicity, at the curve's points; tangent arrows end at c(t) +
** c'(t) / degree (for a cubic Bézier at t = 0: P1; at t = 1: 2 P3 - P2). */
static void
test_knot_list_and_tangents(void **state)
{
    static const double U[] = { 0, 0, 0, 0, 0.5, 0.5, 1, 1, 1, 1 };
    static const double P[] = { 0, 0, 1, 2, 2, 3, 3, 1, 4, 2, 5, 0 };
    static const double B[] = { 0, 0, 1, 2, 3, 2, 4, 0 };
    cf_bspline_t *s = NULL;
    cf_bezier_t *c = NULL;
    cf_figure_t *fig = NULL;
    double u[10], pts[20], tip[2], want[2];
    size_t first[10], mult[10], n = 0, k;
    cf_diag_t d;
    (void)state;
    assert_int_equal(cf_bspline_create(2, 3, U, 10, P, 6, NULL, &s, NULL),
                     0);
    assert_int_equal(cf_bezier_create(2, 3, B, NULL, &c, NULL), 0);
    assert_int_equal(cf_figure_create(60, 40, CF_UNIT_MM, &fig, NULL), 0);
    assert_int_equal(cf_figure_bspline_knots(fig, s, u, first, mult, pts,
                                             &n), 0);
    assert_int_equal(n, 3);
    assert_float_equal(u[0], 0, 0);
    assert_float_equal(u[1], 0.5, 0);
    assert_float_equal(u[2], 1, 0);
    assert_int_equal(first[0], 0);
    assert_int_equal(first[1], 4);
    assert_int_equal(first[2], 6);
    assert_int_equal(mult[0], 4);
    assert_int_equal(mult[1], 2);
    assert_int_equal(mult[2], 4);
    for (k = 0; k < n; k++) {
        double p[2];
        assert_int_equal(cf_bspline_eval(s, u[k], p), 0);
        assert_float_equal(pts[2 * k], p[0], 1e-12);
        assert_float_equal(pts[2 * k + 1], p[1], 1e-12);
    }
    /* clamped ends: the first and last control points */
    assert_float_equal(pts[0], 0, 1e-12);
    assert_float_equal(pts[4], 5, 1e-12);
    assert_int_equal(cf_figure_add_bezier_tangent(fig, c, 0, 0, NULL, tip),
                     0);
    assert_float_equal(tip[0], 1, 1e-12);
    assert_float_equal(tip[1], 2, 1e-12);
    assert_int_equal(cf_figure_add_bezier_tangent(fig, c, 1, 0, NULL, tip),
                     0);
    assert_float_equal(tip[0], 5, 1e-12);
    assert_float_equal(tip[1], -2, 1e-12);
    /* scale 1 at the B-spline's start: P0 + C'(0), where
    ** C'(0) = 3 (P1 - P0) / (u_4 - u_1) = 3 (P1 - P0) / 0.5 */
    assert_int_equal(cf_figure_add_bspline_tangent(fig, s, 0, 1, NULL, tip),
                     0);
    want[0] = 0 + 3 * (1 - 0) / 0.5;
    want[1] = 0 + 3 * (2 - 0) / 0.5;
    assert_float_equal(tip[0], want[0], 1e-9);
    assert_float_equal(tip[1], want[1], 1e-9);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_add_bezier_tangent(fig, c, 1.5, 0, NULL,
                                                  NULL), CF_STATUS_DOMAIN);
    assert_int_equal(cf_figure_status(fig, &d), CF_STATUS_DOMAIN);
    assert_non_null(strstr(d.msg, "outside the domain [0, 1]"));
    cf_figure_destroy(fig);
    assert_int_equal(cf_figure_create(60, 40, CF_UNIT_MM, &fig, NULL), 0);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_add_bspline_tangent(fig, s, 2, 0, NULL, NULL),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_figure_status(fig, &d), CF_STATUS_DOMAIN);
    assert_non_null(strstr(d.msg, "t = 2 is outside the domain [0, 1]"));
    cf_figure_destroy(fig);
    cf_bspline_destroy(s);
    cf_bezier_destroy(c);
}

static void
test_out_of_memory(void **state)
{
    double P[] = { 0, 5, 1, -1, 3, 0, 4, 3, 6, 10 };
    long k;
    cf_style_t autoplace;
    (void)state;
    cf_style_init(&autoplace);
    autoplace.set = CF_STYLE_PLACE;
    autoplace.place = CF_PLACE_AUTO;
    /* fail each allocation in turn while building and rendering a
    ** figure (an explicit window, a label placed automatically): a
    ** status every time, no leak, eventually success */
    for (k = 1; k < 2000; k++) {
        cf_figure_t *fig = NULL;
        cf_bezier_t *c = NULL;
        cf_status_t st;
        unsigned char *data = NULL;
        size_t size;
        cf_axes_t ax;
        tu_fail_alloc_after(k);
        st = cf_figure_create(60, 40, CF_UNIT_MM, &fig, NULL);
        if (st == CF_STATUS_OK)
            st = cf_bezier_create(2, 4, P, NULL, &c, NULL);
        if (st == CF_STATUS_OK) {
            cf_figure_add_polygon(fig, P, 5, NULL);
            cf_figure_add_bezier(fig, c, NULL);
            cf_figure_add_label(fig, 0, 5, "P_0", NULL);
            cf_figure_add_label(fig, 1, -1, "P_1", &autoplace);
            cf_figure_set_window(fig, -1, 7, -2, 11);
            cf_axes_init(&ax);
            cf_figure_add_axes(fig, &ax, NULL);
            st = cf_figure_render(fig, CF_FORMAT_SVG, NULL, &data, &size,
                                  NULL);
        }
        cf_free(data);
        cf_bezier_destroy(c);
        cf_figure_destroy(fig);
        assert_int_equal(tu_alloc_live(), 0);
        tu_fail_alloc_reset();
        if (st == CF_STATUS_OK)
            return;
        assert_int_equal(st, CF_STATUS_NO_MEMORY);
    }
    fail_msg("never succeeded");
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bad_input),
        cmocka_unit_test(test_huge_extent_refused),
        cmocka_unit_test(test_sticky_error),
        cmocka_unit_test(test_graph_constant_piece),
        cmocka_unit_test(test_knot_list_and_tangents),
        cmocka_unit_test(test_out_of_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
