/* API misuse of the renderer's public functions (figures, styles,
** labels, layouts, insets, panels, output), as test_api_misuse.c does for
** the core: NULL pointers, empty and zero-sized inputs, out-of-range
** numbers and inconsistent arguments must give a status, never a crash.
** test_api_misuse.c's test_every_function_listed reads this file too. */
#include "test_api_misuse.h"

static int
plot_nan(void *closure, double x, double *y)
{
    (void)closure;
    (void)x;
    *y = NAN;
    return 0;
}

static void
test_figure(void **state)
{
    cf_unit_t unit;
    cf_color_t col;
    cf_marker_t mk;
    cf_place_t pl;
    cf_style_t st;
    cf_theme_t th;
    cf_figure_t *fig = NULL;
    cf_axes_t ax;
    cf_format_t fmt;
    cf_write_options_t wo;
    cf_label_t *lab = NULL;
    cf_bezier_t *c = NULL;
    cf_bspline_t *s = NULL;
    unsigned char *data = NULL;
    size_t size = 0;
    double win[4], sx, sy, box[4], box6[6], pw, ph, w, asc, desc;
    (void)state;
    assert_true(isfinite(cf_length_to_bp(1, (cf_unit_t)99)) ||
                isnan(cf_length_to_bp(1, (cf_unit_t)99)));
    BAD(cf_unit_from_name(NULL, &unit, NULL));
    BAD(cf_unit_from_name("furlong", &unit, NULL));
    BAD(cf_unit_from_name("cm", NULL, NULL));
    BAD(cf_color_parse(NULL, &col, NULL));
    BAD(cf_color_parse("#12345", &col, NULL));
    BAD(cf_color_parse("octarine", &col, NULL));
    BAD(cf_color_parse("red", NULL, NULL));
    BAD(cf_marker_from_name(NULL, &mk, NULL));
    BAD(cf_marker_from_name("heart", &mk, NULL));
    BAD(cf_place_from_name(NULL, &pl, NULL));
    BAD(cf_place_from_name("up", &pl, NULL));
    cf_style_init(NULL);
    cf_style_init(&st);
    BAD(cf_theme_get(NULL, &th, NULL));
    BAD(cf_theme_get("neon", &th, NULL));
    BAD(cf_theme_get("default", NULL, NULL));
    BAD(cf_figure_create(0, 6, CF_UNIT_CM, &fig, NULL));
    BAD(cf_figure_create(NAN, 6, CF_UNIT_CM, &fig, NULL));
    BAD(cf_figure_create(8, -6, CF_UNIT_CM, &fig, NULL));
    BAD(cf_figure_create(8, 6, (cf_unit_t)99, &fig, NULL));
    BAD(cf_figure_create(8, 6, CF_UNIT_CM, NULL, NULL));
    assert_null(fig);
    cf_figure_destroy(NULL);
    /* every figure function on NULL */
    BAD(cf_figure_status(NULL, NULL));
    assert_string_equal(cf_figure_warnings(NULL), "");
    cf_figure_set_line(NULL, 12);   /* nothing to set, no crash */
    cf_figure_get_size(NULL, &w, &w);
    BAD(cf_figure_set_title(NULL, "t"));
    BAD(cf_figure_set_caption(NULL, "c"));
    BAD(cf_figure_set_theme(NULL, &th));
    cf_figure_get_theme(NULL, &th);
    BAD(cf_figure_set_window(NULL, 0, 1, 0, 1));
    BAD(cf_figure_set_window_auto(NULL));
    BAD(cf_figure_set_fit(NULL, 10, true));
    BAD(cf_figure_get_window(NULL, win, &sx, &sy));
    BAD(cf_figure_set_tolerance(NULL, 0.1));
    BAD(cf_figure_set_draft(NULL, true));
    BAD(cf_figure_set_projection(NULL, 3, P4));
    BAD(cf_figure_project(NULL, P4, 1, 2, win));
    BAD(cf_figure_add_bezier(NULL, c, &st));
    BAD(cf_figure_add_bezier_range(NULL, c, 0, 1, &st));
    BAD(cf_figure_add_bezier_list(NULL, NULL, &st));
    BAD(cf_figure_add_cubics(NULL, NULL, &st));
    BAD(cf_figure_add_bspline(NULL, s, 0, 1, &st));
    BAD(cf_figure_add_bspline_knots(NULL, s, &st));
    BAD(cf_figure_add_knot_marks(NULL, P4, NULL, 2, &st));
    BAD(cf_figure_add_polygon(NULL, P4, 4, &st));
    BAD(cf_figure_add_polyline(NULL, P4, 4, false, &st));
    BAD(cf_figure_add_hull(NULL, P4, 4, &st));
    BAD(cf_figure_add_fill(NULL, P4, 4, &st));
    BAD(cf_figure_add_points(NULL, P4, 4, &st));
    BAD(cf_figure_add_arrow(NULL, 0, 0, 1, 1, &st));
    BAD(cf_figure_add_label(NULL, 0, 0, "P", &st));
    BAD(cf_figure_add_net(NULL, P4, (const size_t[]){ 2, 1 }, 2, NULL, &st));
    cf_axes_init(NULL);
    cf_axes_init(&ax);
    BAD(cf_figure_add_axes(NULL, &ax, &st));
    BAD(cf_figure_add_graph(NULL, NULL, NULL, 0, &st));
    BAD(cf_figure_add_graph_list(NULL, NULL, &st));
    BAD(cf_figure_add_basis(NULL, NULL, 0, 0, 0, &st));
    BAD(cf_figure_add_function(NULL, plot_nan, NULL, 0, 1, &st));
    BAD(cf_figure_write(NULL, "/nonexistent/x.svg", CF_FORMAT_SVG, NULL,
                        NULL));
    BAD(cf_figure_write_all(NULL, "/nonexistent/x", 1, NULL, NULL));
    BAD(cf_figure_render(NULL, CF_FORMAT_SVG, NULL, &data, &size, NULL));
    BAD(cf_figure_ink_box(NULL, NULL, box, &pw, &ph, NULL));
    BAD(cf_figure_page_map(NULL, NULL, box6, NULL));
    BAD(cf_figure_render_mapped(NULL, CF_FORMAT_SVG, NULL, &data, &size,
                                box6, NULL));
    {
        char *glyphs = NULL;
        BAD(cf_figures_glyph_data(NULL, 1, &glyphs, &size, NULL));
        assert_null(glyphs);
    }
    BAD(cf_format_from_name(NULL, &fmt, NULL));
    BAD(cf_format_from_name("bmp", &fmt, NULL));
    assert_string_equal(cf_format_extension((cf_format_t)99), "");
    cf_write_options_init(NULL);
    cf_write_options_init(&wo);
    /* a real figure given bad arguments: each call fails; errors are
    ** sticky (figure.h), so the first one stays the figure's status */
    assert_int_equal(cf_figure_create(8, 6, CF_UNIT_CM, &fig, NULL), 0);
    assert_int_equal(cf_bezier_create(2, 3, P4, NULL, &c, NULL), 0);
    assert_int_equal(cf_bspline_create_clamped(2, 2, P4, 4, NULL, &s, NULL),
                     0);
    {
        cf_diag_t d1, d2;
        cf_diag_clear(&d1);
        cf_diag_clear(&d2);
        BAD(cf_figure_set_window(fig, 1, 1, 0, 1));
        BAD(cf_figure_status(fig, &d1));
        BAD(cf_figure_set_window(fig, 0, NAN, 0, 1));
        BAD(cf_figure_status(fig, &d2));
        assert_string_equal(d1.msg, d2.msg);
    }
    BAD(cf_figure_set_fit(fig, -1, true));
    BAD(cf_figure_set_page_mode(fig, (cf_page_mode_t)7));
    BAD(cf_figure_set_background(fig, (cf_background_t)7));
    BAD(cf_figure_set_tolerance(fig, 0));
    BAD(cf_figure_set_theme(fig, NULL));
    BAD(cf_figure_set_projection(fig, 3, NULL));
    BAD(cf_figure_set_projection(fig, 0, P4));
    BAD(cf_figure_project(fig, NULL, 1, 2, win));
    BAD(cf_figure_project(fig, P4, 1, 2, NULL));
    BAD(cf_figure_add_bezier(fig, NULL, &st));
    BAD(cf_figure_add_bezier_range(fig, c, 0.7, 0.2, &st));
    BAD(cf_figure_add_bezier_range(fig, c, 0, 2, &st));
    BAD(cf_figure_add_bezier_list(fig, NULL, &st));
    BAD(cf_figure_add_cubics(fig, NULL, &st));
    BAD(cf_figure_add_bspline(fig, NULL, 0, 1, &st));
    BAD(cf_figure_add_bspline(fig, s, 0.5, 0.2, &st));
    BAD(cf_figure_add_bspline_knots(fig, NULL, &st));
    BAD(cf_figure_add_knot_marks(fig, NULL, NULL, 2, &st));
    BAD(cf_figure_add_polygon(fig, NULL, 4, &st));
    BAD(cf_figure_add_polygon(fig, NANS, 4, &st));
    BAD(cf_figure_add_polyline(fig, NULL, 4, true, &st));
    BAD(cf_figure_add_hull(fig, NULL, 4, &st));
    BAD(cf_figure_add_fill(fig, NANS, 4, &st));
    BAD(cf_figure_add_points(fig, NULL, 4, &st));
    BAD(cf_figure_add_arrow(fig, NAN, 0, 1, 1, &st));
    BAD(cf_figure_add_label(fig, 0, 0, NULL, &st));
    BAD(cf_figure_add_label(fig, 0, 0, "P_{0", &st));
    BAD(cf_figure_add_label(fig, NAN, 0, "P", &st));
    BAD(cf_figure_add_net(fig, NULL, (const size_t[]){ 2, 1 }, 2, NULL,
                          &st));
    BAD(cf_figure_add_net(fig, P4, NULL, 2, NULL, &st));
    BAD(cf_figure_add_axes(fig, NULL, &st));
    BAD(cf_figure_add_graph(fig, NULL, NULL, 1, &st));
    BAD(cf_figure_add_graph_list(fig, NULL, &st));
    BAD(cf_figure_add_basis(fig, NULL, 5, 0, 2, &st));
    BAD(cf_figure_add_function(fig, NULL, NULL, 0, 1, &st));
    BAD(cf_figure_add_function(fig, plot_nan, NULL, 1, 0, &st));
    BAD(cf_figure_get_window(fig, NULL, &sx, &sy));
    BAD(cf_figure_write(fig, NULL, CF_FORMAT_SVG, NULL, NULL));
    BAD(cf_figure_write(fig, "/nonexistent-dir/x.svg", CF_FORMAT_SVG, NULL,
                        NULL));
    BAD(cf_figure_write(fig, "x.svg", (cf_format_t)99, NULL, NULL));
    BAD(cf_figure_write_all(fig, NULL, 1, NULL, NULL));
    BAD(cf_write_file(NULL, "x", 1, NULL));
    BAD(cf_write_file("x.txt", NULL, 1, NULL));
    BAD(cf_write_file("", "x", 1, NULL));
    BAD(cf_write_file("dir/", "x", 1, NULL));
    BAD(cf_write_file("/nonexistent-dir/x.txt", "x", 1, NULL));
    BAD(cf_figure_render(fig, CF_FORMAT_SVG, NULL, NULL, &size, NULL));
    BAD(cf_figure_render(fig, (cf_format_t)99, NULL, &data, &size, NULL));
    wo.dpi = 0;
    BAD(cf_figure_render(fig, CF_FORMAT_PNG, &wo, &data, &size, NULL));
    assert_null(data);
    BAD(cf_figure_ink_box(fig, NULL, NULL, &pw, &ph, NULL));
    BAD(cf_figure_page_map(fig, NULL, NULL, NULL));
    BAD(cf_figure_render_mapped(fig, CF_FORMAT_SVG, NULL, &data, NULL, box6,
                                NULL));
    BAD(cf_figure_render_places(fig, CF_FORMAT_SVG, NULL, &data, &size,
                                box6, (char **)&data, NULL, NULL));
    BAD(cf_figures_glyph_data(&fig, 1, NULL, &size, NULL));
    BAD(cf_figure_dump(fig, NULL, NULL, &size, NULL));
    BAD(cf_figure_set_clip(NULL, true));
    BAD(cf_figure_set_page_mode(NULL, CF_PAGE_INK));
    BAD(cf_figure_get_fit(NULL, NULL, NULL));
    cf_label_each_command(NULL, NULL);   /* no visitor: nothing */
    BAD(cf_theme_set_fonts(NULL, "sans", 10, NULL));
    BAD(cf_theme_set_palette(NULL, "default", NULL));
    cf_theme_level_style(NULL, 1, NULL);   /* nothing to set: nothing */
    BAD(cf_figure_colour_check(fig, 10, NULL, &size, NULL));
    BAD(cf_figure_colour_check(NULL, 10, (char **)&data, &size, NULL));
    BAD(cf_figure_colour_check(fig, NAN, (char **)&data, &size, NULL));
    assert_null(data);
    BAD(cf_figure_set_background(NULL, CF_BACKGROUND_NONE));
    BAD(cf_figure_bspline_knots(fig, NULL, NULL, NULL, NULL, NULL, NULL));
    BAD(cf_figure_add_bezier_tangent(fig, NULL, 0, 0, NULL, NULL));
    BAD(cf_figure_add_bspline_tangent(NULL, s, 0, 0, NULL, NULL));
    BAD(cf_figure_dump(NULL, NULL, (char **)&data, &size, NULL));
    BAD(cf_figure_set_title(fig, NULL) == CF_STATUS_OK &&
        cf_figure_set_caption(fig, NULL) == CF_STATUS_OK
        ? CF_STATUS_OK : CF_STATUS_INVALID_ARG);
    cf_figure_get_size(fig, NULL, NULL);
    cf_figure_get_theme(fig, NULL);
    /* the figure in error refuses to render; a fresh one renders */
    cf_write_options_init(&wo);
    BAD(cf_figure_render(fig, CF_FORMAT_SVG, &wo, &data, &size, NULL));
    assert_null(data);
    cf_figure_destroy(fig);
    assert_int_equal(cf_figure_create(8, 6, CF_UNIT_CM, &fig, NULL), 0);
    assert_int_equal(cf_figure_add_bezier(fig, c, &st), 0);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, &wo, &data, &size,
                                      NULL), 0);
    assert_true(size > 0);
    cf_free(data);
    cf_figure_destroy(fig);
    cf_bezier_destroy(c);
    cf_bspline_destroy(s);
    /* labels */
    BAD(cf_label_create(NULL, NULL, 10, &lab, NULL));
    BAD(cf_label_create("P", NULL, 0, &lab, NULL));
    BAD(cf_label_create("P", NULL, NAN, &lab, NULL));
    BAD(cf_label_create("P", "", 10, &lab, NULL));
    BAD(cf_label_create("P", NULL, 10, NULL, NULL));
    BAD(cf_label_create("\\frac{1}", NULL, 10, &lab, NULL));
    assert_null(lab);
    cf_label_destroy(NULL);
    assert_int_equal(cf_label_box_count(NULL), 0);
    assert_null(cf_label_get_box(NULL, 0));
    assert_string_equal(cf_label_run_text(NULL, 0), "");
    cf_label_get_extents(NULL, &w, &asc, &desc);
    assert_int_equal(cf_label_unknown_glyphs(NULL), 0);
    /* legends, insets, panels and overlay steps */
    {
        cf_figure_t *g = NULL, *cells[2] = { NULL, NULL };
        cf_inset_t in;
        assert_int_equal(cf_figure_element_count(NULL), 0);
        BAD(cf_figure_add_legend(NULL, "a"));
        BAD(cf_figure_add_legend_at(NULL, 0, "a"));
        BAD(cf_figure_set_legend_place(NULL, CF_PLACE_NE, true));
        cf_inset_init(NULL);
        cf_inset_init(&in);
        BAD(cf_figure_add_inset(NULL, &in));
        BAD(cf_figure_add_panels(NULL, 2, 1, 0, 0, cells));
        BAD(cf_figure_set_panel_title(NULL, "(a)"));
        BAD(cf_figure_set_overlay(NULL, "2-"));
        assert_int_equal(cf_figure_steps(NULL), 0);
        assert_false(cf_figure_visible_at(NULL, 0, 1));
        IS(CF_STATUS_OK, cf_figure_create(8, 6, CF_UNIT_CM, &g, NULL));
        BAD(cf_figure_add_legend(g, "nothing drawn yet"));
        cf_figure_destroy(g);
        IS(CF_STATUS_OK, cf_figure_create(8, 6, CF_UNIT_CM, &g, NULL));
        BAD(cf_figure_add_legend_at(g, 5, "no element 5"));
        cf_figure_destroy(g);
        IS(CF_STATUS_OK, cf_figure_create(8, 6, CF_UNIT_CM, &g, NULL));
        BAD(cf_figure_add_panels(g, 0, 1, 0, 0, cells));
        cf_figure_destroy(g);
        IS(CF_STATUS_OK, cf_figure_create(8, 6, CF_UNIT_CM, &g, NULL));
        BAD(cf_figure_set_overlay(g, "3-1"));
        cf_figure_destroy(g);
        IS(CF_STATUS_OK, cf_figure_create(8, 6, CF_UNIT_CM, &g, NULL));
        BAD(cf_figure_add_inset(g, NULL));
        cf_figure_destroy(g);
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_figure),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
