/* The box of every shipped figure (the scripts in figures/, page = "ink"
** by default) is its ink box plus the 1 bp margin, and it is sized by
** width and height: measured on the PNG's pixels, the ink reaches the
** page within the margin on all four sides, and the page reaches the
** script's width or height (a figure with panels: at most them).  And the
** C API alike: a figure of page mode CF_PAGE_INK with a free aspect ratio
** is exactly width x height; the page is painted in PNG only. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <cairo.h>

#include "model.h"
#include "pngtest.h"
#include "shipped.h"
#include "script.h"
#include "testutil.h"

#define DPI 144.0
#define MARGIN 1.0      /* bp: the default margin of page = "ink" */
#define SLACK 0.05      /* bp: the layout's fit (0.01) and rounding */

/* The box of the pixels with ink (alpha > 0: white halos of labels are
** ink too) of a transparent PNG in memory (x0 y0 x1 y1, pixels), and
** its size. */
static void
ink_pixels(const unsigned char *png, size_t size, int box[4], int *w, int *h)
{
    cairo_surface_t *img = tu_png_decode(png, size);
    assert_int_equal(cairo_surface_status(img), CAIRO_STATUS_SUCCESS);
    *w = cairo_image_surface_get_width(img);
    *h = cairo_image_surface_get_height(img);
    tu_alpha_box(img, box);
    cairo_surface_destroy(img);
}

/* Faults of one figure, printed; their number. */
static int
check_figure(cf_figure_t *fig, const char *name)
{
    cf_write_options_t o;
    unsigned char *png = NULL;
    size_t size = 0;
    double ink[4], pw, ph, W, H, px = DPI / 72;
    int box[4], w, h, bad = 0, k;
    cf_write_options_init(&o);
    o.dpi = DPI;
    assert_int_equal(cf_figure_ink_box(fig, &o, ink, &pw, &ph, NULL), 0);
    cf_figure_get_size(fig, &W, &H);
    if (pw > W + SLACK || ph > H + SLACK
        || (fig->panels == NULL && fabs(pw - W) > SLACK
            && fabs(ph - H) > SLACK)) {
        print_message("%s: box %.3f x %.3f bp for width x height %.3f x "
                      "%.3f\n", name, pw, ph, W, H);
        bad++;
    }
    assert_int_equal(cf_figure_set_background(fig, CF_BACKGROUND_NONE), 0);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_PNG, &o, &png, &size,
                                      NULL), 0);
    ink_pixels(png, size, box, &w, &h);
    /* (a PNG of a figure with steps shows the last one in the box of
    ** them all) the margin of white on each side: 1 bp, give or take the
    ** anti-aliasing pixel and the rounding of the page to pixels */
    {
        double white[4] = { box[0] / px, box[1] / px, (w - box[2]) / px,
                            (h - box[3]) / px };
        for (k = 0; k < 4 && cf_figure_steps(fig) <= 1; k++)
            if (white[k] > MARGIN + 2 / px + SLACK) {
                print_message("%s: %.2f bp of white on side %d (margin "
                              "%g bp)\n", name, white[k], k, MARGIN);
                bad++;
                break;
            }
    }
    cf_free(png);
    return bad;
}

static int
check_shipped(void *ctx, const char *script, const char *name,
              cf_figure_t *fig)
{
    (void)ctx;
    (void)script;
    return check_figure(fig, name);
}

static void
test_shipped_figures_fit(void **state)
{
    size_t failed, figures;
    (void)state;
    figures = tu_each_shipped_figure(CF_SOURCE_ROOT, check_shipped, NULL,
                                     &failed);
    print_message("%zu figures, %zu not fitted to their ink\n", figures,
                  failed);
    assert_true(figures >= 60);
    assert_int_equal(failed, 0);
}

/* The C API: CF_PAGE_INK with a free aspect ratio fills width x height
** exactly; CF_PAGE_FIXED keeps the page; the background is painted in PNG
** only unless CF_BACKGROUND_ALWAYS (the SVG paints it as a white
** rectangle). */
static void
test_api_page_and_background(void **state)
{
    static const double P[] = { 0, 0, 1, 2, 3, 2, 4, 0 };
    cf_figure_t *fig = NULL;
    cf_bezier_t *c = NULL;
    double pw, ph;
    unsigned char *svg = NULL;
    size_t size = 0;
    const char *white = "fill=\"#ffffff\"";
    (void)state;
    assert_int_equal(cf_bezier_create(2, 3, P, NULL, &c, NULL), 0);
    assert_int_equal(cf_figure_create(200, 120, CF_UNIT_BP, &fig, NULL), 0);
    assert_int_equal(cf_figure_add_bezier(fig, c, NULL), 0);
    assert_int_equal(cf_figure_set_fit(fig, 1, false), 0);
    assert_int_equal(cf_figure_ink_box(fig, NULL, NULL, &pw, &ph, NULL), 0);
    assert_true(pw == 200 && ph == 120);   /* fixed: the page */
    assert_int_equal(cf_figure_set_page_mode(fig, CF_PAGE_INK), 0);
    assert_int_equal(cf_figure_ink_box(fig, NULL, NULL, &pw, &ph, NULL), 0);
    assert_true(fabs(pw - 200) < SLACK && fabs(ph - 120) < SLACK);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, NULL, &svg, &size,
                                      NULL), 0);
    assert_false(tu_bytes_hold(svg, size, white));
    cf_free(svg);
    assert_int_equal(cf_figure_set_background(fig, CF_BACKGROUND_ALWAYS), 0);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, NULL, &svg, &size,
                                      NULL), 0);
    assert_true(tu_bytes_hold(svg, size, white));
    cf_free(svg);
    cf_figure_destroy(fig);
    cf_bezier_destroy(c);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_api_page_and_background),
        cmocka_unit_test(test_shipped_figures_fit),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
