/* Label halos (render/backends/backend.h): on a painted page a halo is a
** border in the background colour; on a transparent page it is a knockout, the
** ink under the label's box grown by the halo left out so that the slide's own
** colour shows, and nothing white is painted.  Measured on the pixels of PNGs
** of one fixed page drawn three ways (a thick line with the label, the line
** alone, the label alone), and on the SVG and PGF text; with overlay steps, a
** label knocks out only on the steps it is shown. */
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

#include "curvefig/figure.h"
#include "curvefig/output.h"
#include "pngtest.h"
#include "script.h"

#define DPI 144.0
#define HALO 3.0        /* bp */

/* A fixed page; a 6 bp line across it at y = 0; `label` at (2, 0). */
static const char *const FIGURE =
    "local f = figure{ name = 'k', width = '6cm', height = '2cm',\n"
    "                  page = 'fixed', window = {0, 4, -1, 1} }\n"
    "if LINE then f:line({0, 0}, {4, 0}, { width = 6 }) end\n"
    "if LABEL then f:label({2, 0}, 'M_{10}', { place = 'center', halo = 3%s })\n"
    "end\n";

typedef struct image {
    cairo_surface_t *s;
    int w, h, stride;
    const unsigned char *px;
} image_t;

/* The figure of FIGURE with the line and/or the label (its extra style
** keys `extra`), rendered in format with the background mode and step. */
static unsigned char *
render(bool line, bool label, const char *extra, cf_format_t format,
       cf_background_t bg, unsigned step, size_t *size)
{
    char code[1024];
    cf_script_t *sc = NULL;
    cf_write_options_t o;
    unsigned char *out = NULL;
    cf_figure_t *fig;
    snprintf(code, sizeof code, "LINE = %s LABEL = %s\n",
             line ? "true" : "false", label ? "true" : "false");
    snprintf(code + strlen(code), sizeof code - strlen(code), FIGURE, extra);
    assert_int_equal(cf_script_create(NULL, NULL, &sc, NULL), 0);
    if (cf_script_run_string(sc, code, "knockout.lua") != CF_STATUS_OK)
        fail_msg("%s", cf_script_error(sc));
    fig = cf_script_figure(sc, 0);
    assert_int_equal(cf_figure_set_background(fig, bg), 0);
    cf_write_options_init(&o);
    o.dpi = DPI;
    o.step = step;
    assert_int_equal(cf_figure_render(fig, format, &o, &out, size, NULL), 0);
    cf_script_destroy(sc);
    return out;
}

static image_t
png(bool line, bool label, const char *extra, cf_background_t bg,
    unsigned step)
{
    size_t size = 0;
    unsigned char *data = render(line, label, extra, CF_FORMAT_PNG, bg, step,
                                 &size);
    image_t im;
    im.s = tu_png_decode(data, size);
    assert_int_equal(cairo_surface_status(im.s), CAIRO_STATUS_SUCCESS);
    cf_free(data);
    cairo_surface_flush(im.s);
    im.w = cairo_image_surface_get_width(im.s);
    im.h = cairo_image_surface_get_height(im.s);
    im.stride = cairo_image_surface_get_stride(im.s);
    im.px = cairo_image_surface_get_data(im.s);
    return im;
}

static uint32_t
at(const image_t *im, int x, int y)
{
    return *(const uint32_t *)(const void *)(im->px + y * im->stride + 4 * x);
}

static unsigned
alpha(const image_t *im, int x, int y)
{
    return at(im, x, y) >> 24;
}

/* The transparent page: the line is cut exactly around the label's box
** grown by the halo (two pixels of anti-aliasing either way), drawn
** everywhere else as without the label; the label is drawn whole and
** nothing is painted where neither is. */
static void
test_transparent_knocks_out(void **state)
{
    image_t both = png(true, true, "", CF_BACKGROUND_NONE, 0);
    image_t line = png(true, false, "", CF_BACKGROUND_NONE, 0);
    image_t lab = png(false, true, "", CF_BACKGROUND_NONE, 0);
    int g[4], cut = 0, x, y;
    double h = HALO * DPI / 72;
    (void)state;
    assert_int_equal(both.w, line.w);
    assert_int_equal(both.h, lab.h);
    tu_alpha_box(lab.s, g);
    assert_true(g[2] > g[0] && g[3] > g[1]);
    for (y = 0; y < both.h; y++)
        for (x = 0; x < both.w; x++) {
            /* distance outside the glyphs' box, pixels */
            double dx = fmax(fmax(g[0] - x, x + 1 - g[2]), 0),
                   dy = fmax(fmax(g[1] - y, y + 1 - g[3]), 0);
            /* a pixel of anti-aliasing at the glyphs' edge and one at the
            ** knockout's: two pixels of slack on either side */
            bool inside = dx <= h - 2 && dy <= h - 2;
            bool outside = dx >= h + 2 || dy >= h + 2;
            if (outside && at(&both, x, y) != at(&line, x, y))
                fail_msg("pixel (%d, %d) %08x, %08x without the label", x,
                         y, at(&both, x, y), at(&line, x, y));
            if (inside && at(&both, x, y) != at(&lab, x, y))
                fail_msg("pixel (%d, %d) in the knockout %08x, %08x of the "
                         "label alone", x, y, at(&both, x, y),
                         at(&lab, x, y));
            cut += inside && alpha(&line, x, y) == 255
                   && alpha(&lab, x, y) == 0;
        }
    /* the 6 bp line crosses the box: a band of it is cut */
    assert_true(cut > (int)(2 * h * 6 * DPI / 72) / 2);
    cairo_surface_destroy(both.s);
    cairo_surface_destroy(line.s);
    cairo_surface_destroy(lab.s);
}

/* The painted page (PNG's default): the halo is white over the line, at
** most the halo's width from the glyphs; the line is kept beyond. */
static void
test_painted_halo_is_background(void **state)
{
    image_t both = png(true, true, "", CF_BACKGROUND_AUTO, 0);
    image_t line = png(true, false, "", CF_BACKGROUND_NONE, 0);
    image_t lab = png(false, true, "", CF_BACKGROUND_NONE, 0);
    int white = 0, x, y;
    (void)state;
    for (y = 0; y < both.h; y++)
        for (x = 0; x < both.w; x++)
            if (alpha(&line, x, y) == 255 && alpha(&lab, x, y) == 0
                && at(&both, x, y) == 0xffffffffu)
                white++;
    assert_true(white > 100);
    cairo_surface_destroy(both.s);
    cairo_surface_destroy(line.s);
    cairo_surface_destroy(lab.s);
}

static bool
has(const unsigned char *data, size_t size, const char *s)
{
    size_t n = strlen(s);
    for (size_t i = 0; i + n <= size; i++)
        if (memcmp(data + i, s, n) == 0)
            return true;
    return false;
}

static size_t
count(const unsigned char *data, size_t size, const char *s)
{
    size_t n = strlen(s), k = 0;
    for (size_t i = 0; i + n <= size; i++)
        k += memcmp(data + i, s, n) == 0;
    return k;
}

/* SVG and PGF of the transparent page: a clip, no white halo. */
static void
test_vector_formats(void **state)
{
    size_t size = 0;
    unsigned char *svg = render(true, true, "", CF_FORMAT_SVG,
                                CF_BACKGROUND_AUTO, 0, &size);
    unsigned char *pgf;
    (void)state;
    assert_true(has(svg, size, "clip-path"));
    assert_false(has(svg, size, "rgb(100%,100%,100%)"));
    cf_free(svg);
    pgf = render(true, true, "", CF_FORMAT_PGF, CF_BACKGROUND_AUTO, 0, &size);
    assert_int_equal(count(pgf, size, "\\pgfseteorule"), 1);
    assert_int_equal(count(pgf, size, "\\pgftext"), 1);   /* no halo copies */
    cf_free(pgf);
    /* painted: the 24 copies of the halo and the text, no knockout */
    pgf = render(true, true, "", CF_FORMAT_PGF, CF_BACKGROUND_ALWAYS, 0,
                 &size);
    assert_int_equal(count(pgf, size, "\\pgfseteorule"), 0);
    assert_int_equal(count(pgf, size, "\\pgftext"), 25);
    cf_free(pgf);
}

/* A label shown from step 2: on step 1 the line is whole; on step 2 it is
** cut; in PGF (every step on one picture) it is not cut and no halo is
** drawn. */
static void
test_overlay_steps(void **state)
{
    const char *vis = ", visible = '2-'";
    image_t s1 = png(true, true, vis, CF_BACKGROUND_NONE, 1);
    image_t s2 = png(true, true, vis, CF_BACKGROUND_NONE, 2);
    image_t line = png(true, false, "", CF_BACKGROUND_NONE, 0);
    size_t size = 0, diff1 = 0, diff2 = 0;
    unsigned char *pgf;
    (void)state;
    for (int y = 0; y < line.h; y++)
        for (int x = 0; x < line.w; x++) {
            diff1 += at(&s1, x, y) != at(&line, x, y);
            diff2 += alpha(&line, x, y) == 255 && alpha(&s2, x, y) == 0;
        }
    assert_int_equal(diff1, 0);
    assert_true(diff2 > 100);
    cairo_surface_destroy(s1.s);
    cairo_surface_destroy(s2.s);
    cairo_surface_destroy(line.s);
    pgf = render(true, true, vis, CF_FORMAT_PGF, CF_BACKGROUND_AUTO, 0,
                 &size);
    assert_int_equal(count(pgf, size, "\\pgfseteorule"), 0);
    assert_int_equal(count(pgf, size, "\\pgftext"), 1);
    cf_free(pgf);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_transparent_knocks_out),
        cmocka_unit_test(test_painted_halo_is_background),
        cmocka_unit_test(test_vector_formats),
        cmocka_unit_test(test_overlay_steps),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
