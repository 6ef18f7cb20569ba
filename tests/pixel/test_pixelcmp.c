/*
** The comparator must pass what is the same picture and fail what is not:
** checked on synthetic images drawn with cairo.
*/
#include <cairo.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "imgcmp.h"

typedef void (*draw_fn)(cairo_t *cr, double param);

static cairo_surface_t *
draw(draw_fn f, double param)
{
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 80, 60);
    cairo_t *cr = cairo_create(s);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    f(cr, param);
    cairo_destroy(cr);
    cairo_surface_flush(s);
    return s;
}

static cf__imgcmp_image
view(cairo_surface_t *s)
{
    cf__imgcmp_image im = { cairo_image_surface_get_width(s),
                    cairo_image_surface_get_height(s),
                    cairo_image_surface_get_stride(s),
                    cairo_image_surface_get_data(s) };
    return im;
}

/* a thin grey polygon with a filled marker at (x, 30) */
static void
polygon_marker(cairo_t *cr, double x)
{
    cairo_set_source_rgb(cr, 0.55, 0.55, 0.55);
    cairo_set_line_width(cr, 1.0);
    cairo_move_to(cr, 5, 50);
    cairo_line_to(cr, x, 30);
    cairo_line_to(cr, 75, 50);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_arc(cr, x, 30, 3.0, 0, 6.283185307179586);
    cairo_fill(cr);
}

static void
curve_colour(cairo_t *cr, double red)
{
    cairo_set_source_rgb(cr, red, 0.1, 0.1);
    cairo_set_line_width(cr, 2.0);
    cairo_move_to(cr, 5, 55);
    cairo_curve_to(cr, 20, 0, 60, 0, 75, 55);
    cairo_stroke(cr);
}

/* a horizontal hairline on a pixel row, or spread over two half rows */
static void
hairline(cairo_t *cr, double y)
{
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    cairo_set_line_width(cr, 1.0);
    cairo_move_to(cr, 5, y);
    cairo_line_to(cr, 75, y);
    cairo_stroke(cr);
}

static int
compare(cairo_surface_t *a, cairo_surface_t *b, cf__imgcmp_result *r)
{
    cf__imgcmp_image ia = view(a), ib = view(b);
    cf__imgcmp_options opt = { 0.1, 1, 0 };
    unsigned char diff[80 * 60 * 4];
    assert_int_equal(cf__imgcmp_compare(&ia, &ib, &opt, r, diff), 0);
    return r->match;
}

static void
test_delta_scale(void **state)
{
    (void)state;
    /* black against white: Y differs by 255, I and Q by 0, so the
    ** distance is sqrt(0.5053 * 255^2 / 35215) = 0.9660 */
    assert_true(fabs(cf__imgcmp_pixel_delta(0xff000000u, 0xffffffffu) - 0.9660) < 1e-3);
    assert_true(cf__imgcmp_pixel_delta(0xff123456u, 0xff123456u) == 0.0);
    /* transparent is white (composited on white) */
    assert_true(cf__imgcmp_pixel_delta(0x00000000u, 0xffffffffu) == 0.0);
    /* one grey level is far below the 0.1 threshold */
    assert_true(cf__imgcmp_pixel_delta(0xff808080u, 0xff818181u) < 0.01);
}

static void
test_identical_takes_fast_path(void **state)
{
    cf__imgcmp_result r;
    cairo_surface_t *a = draw(polygon_marker, 40), *b = draw(polygon_marker, 40);
    (void)state;
    assert_true(compare(a, b, &r));
    assert_true(r.identical);
    assert_int_equal(r.bad_pixels, 0);
    cairo_surface_destroy(a);
    cairo_surface_destroy(b);
}

static void
test_subpixel_shift_is_antialiasing(void **state)
{
    cf__imgcmp_result r;
    cairo_surface_t *a = draw(polygon_marker, 40), *b = draw(polygon_marker, 40.35);
    (void)state;
    assert_true(compare(a, b, &r));
    assert_false(r.identical);
    assert_true(r.aa_pixels > 0);
    cairo_surface_destroy(a);
    cairo_surface_destroy(b);
}

static void
test_half_pixel_line_placement_is_same_ink(void **state)
{
    cf__imgcmp_result r;
    cairo_surface_t *a = draw(hairline, 30.5), *b = draw(hairline, 30.0);
    (void)state;
    assert_true(compare(a, b, &r));
    assert_false(r.identical);
    cairo_surface_destroy(a);
    cairo_surface_destroy(b);
    /* but a line two pixels away is a different picture */
    a = draw(hairline, 30.5);
    b = draw(hairline, 32.5);
    assert_false(compare(a, b, &r));
    cairo_surface_destroy(a);
    cairo_surface_destroy(b);
}

static void
test_two_pixel_move_fails(void **state)
{
    /* 1 pt at the 144 dpi of the pixel tests is 2 pixels */
    cf__imgcmp_result r;
    cairo_surface_t *a = draw(polygon_marker, 40), *b = draw(polygon_marker, 42);
    (void)state;
    assert_false(compare(a, b, &r));
    assert_true(r.bad_pixels > 0);
    cairo_surface_destroy(a);
    cairo_surface_destroy(b);
}

static void
test_colour_change_fails(void **state)
{
    cf__imgcmp_result r;
    cairo_surface_t *a = draw(curve_colour, 0.1), *b = draw(curve_colour, 0.9);
    (void)state;
    assert_false(compare(a, b, &r));
    assert_true(r.bad_pixels > 20);
    cairo_surface_destroy(a);
    cairo_surface_destroy(b);
}

/* The diff image: the expected image faded (dark ink becomes light grey),
** red where the images differ, yellow where only anti-aliasing does. */
static void
count_diff(const unsigned char *diff, int *red, int *yellow, int *faded_ink)
{
    *red = *yellow = *faded_ink = 0;
    for (int i = 0; i < 80 * 60; i++) {
        uint32_t v;
        memcpy(&v, diff + 4 * i, sizeof v);
        if (v == 0xffff0000u)
            (*red)++;
        else if (v == 0xffffd700u)
            (*yellow)++;
        else if (v != 0xffffffffu)
            (*faded_ink)++;
        /* a faded pixel is grey and light: 255 - 0.1 (255 - luma) */
        if (v != 0xffff0000u && v != 0xffffd700u)
            assert_true((v & 0xff) >= 229 && ((v >> 8) & 0xff) == (v & 0xff) &&
                        ((v >> 16) & 0xff) == (v & 0xff));
    }
}

static void
test_diff_image(void **state)
{
    cf__imgcmp_result r;
    cf__imgcmp_options opt = { 0.1, 1, 0 };
    static unsigned char diff[80 * 60 * 4];
    int red, yellow, ink;
    cairo_surface_t *a = draw(polygon_marker, 40), *b = draw(polygon_marker, 40);
    cf__imgcmp_image ia = view(a), ib = view(b);
    (void)state;
    /* identical: the faded copy alone */
    assert_int_equal(cf__imgcmp_compare(&ia, &ib, &opt, &r, diff), 0);
    count_diff(diff, &red, &yellow, &ink);
    assert_int_equal(red, 0);
    assert_int_equal(yellow, 0);
    assert_true(ink > 50);
    cairo_surface_destroy(b);
    /* a sub-pixel shift: yellow only */
    b = draw(polygon_marker, 40.35);
    ib = view(b);
    assert_int_equal(cf__imgcmp_compare(&ia, &ib, &opt, &r, diff), 0);
    count_diff(diff, &red, &yellow, &ink);
    assert_int_equal(red, 0);
    assert_int_equal(yellow, r.aa_pixels);
    assert_true(yellow > 0);
    cairo_surface_destroy(b);
    /* a two-pixel move: as many red pixels as bad ones */
    b = draw(polygon_marker, 42);
    ib = view(b);
    assert_int_equal(cf__imgcmp_compare(&ia, &ib, &opt, &r, diff), 0);
    count_diff(diff, &red, &yellow, &ink);
    assert_int_equal(red, r.bad_pixels);
    assert_true(red > 0);
    cairo_surface_destroy(a);
    cairo_surface_destroy(b);
}

static void
test_size_mismatch(void **state)
{
    cf__imgcmp_result r;
    cf__imgcmp_options opt = { 0.1, 1, 0 };
    cairo_surface_t *a = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 10, 10);
    cairo_surface_t *b = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 10, 11);
    cf__imgcmp_image ia = view(a), ib = view(b);
    (void)state;
    assert_int_equal(cf__imgcmp_compare(&ia, &ib, &opt, &r, NULL), -1);
    cairo_surface_destroy(a);
    cairo_surface_destroy(b);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_delta_scale),
        cmocka_unit_test(test_identical_takes_fast_path),
        cmocka_unit_test(test_subpixel_shift_is_antialiasing),
        cmocka_unit_test(test_half_pixel_line_placement_is_same_ink),
        cmocka_unit_test(test_two_pixel_move_fails),
        cmocka_unit_test(test_colour_change_fails),
        cmocka_unit_test(test_diff_image),
        cmocka_unit_test(test_size_mismatch),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
