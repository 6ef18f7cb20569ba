/* The SVG writer (render/backends/backend-svgw.c), which the course pages use
** where there is no cairo, against cairo's SVG: every shipped figure
** written both ways, both rasterised by librsvg at the pixel suite's
** 144 dpi and compared by its comparator (render/tool/imgcmp.h) with the
** pixel suite's threshold (0.1) and anti-aliasing allowance (one pixel),
** and no bad pixel at all, labels included: cairo writes glyphs as
** <symbol>s of its outlines, the writer as paths of pango's outlines
** through cairo, the same curves rounded to 1/1000 bp, which moves an
** edge by far less than the allowance (the pixel suite's own allowance
** for labels, CF__IMGCMP_TEXT_FRACTION, is for cairo's hinted text
** against librsvg, which does not arise here).
** Then the writer's own properties: a well-formed document whose clips
** and groups balance, and refusal of a non-finite coordinate. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <librsvg/rsvg.h>

#include "backend.h"
#include "curvefig/output.h"
#include "imgcmp.h"
#include "output-private.h"
#include "script.h"
#include "shipped.h"
#include "testutil.h"

/* An SVG document rasterised at dpi on white (the page's size, its last
** partial pixel rounded up); NULL when librsvg refuses it. */
static cairo_surface_t *
rasterise(const unsigned char *svg, size_t size, double dpi)
{
    GError *err = NULL;
    RsvgHandle *h = rsvg_handle_new_from_data(svg, size, &err);
    gdouble w, hh;
    cairo_surface_t *s;
    cairo_t *cr;
    RsvgRectangle vp;
    if (h == NULL) {
        print_error("librsvg: %s\n", err->message);
        g_error_free(err);
        return NULL;
    }
    rsvg_handle_set_dpi(h, dpi);
    if (!rsvg_handle_get_intrinsic_size_in_pixels(h, &w, &hh)) {
        g_object_unref(h);
        return NULL;
    }
    s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, (int)ceil(w - 1e-9),
                                   (int)ceil(hh - 1e-9));
    cr = cairo_create(s);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    vp.x = vp.y = 0;
    vp.width = w;
    vp.height = hh;
    if (!rsvg_handle_render_document(h, cr, &vp, &err)) {
        print_error("librsvg: %s\n", err->message);
        g_error_free(err);
        cairo_destroy(cr);
        cairo_surface_destroy(s);
        g_object_unref(h);
        return NULL;
    }
    cairo_destroy(cr);
    g_object_unref(h);
    cairo_surface_flush(s);
    return s;
}

static cf__imgcmp_image
image_of(cairo_surface_t *s)
{
    cf__imgcmp_image im;
    im.width = cairo_image_surface_get_width(s);
    im.height = cairo_image_surface_get_height(s);
    im.stride = cairo_image_surface_get_stride(s);
    im.data = cairo_image_surface_get_data(s);
    return im;
}

/* The figure through the SVG writer into out (empty). */
static cf_status_t
write_svgw(cf_figure_t *fig, unsigned step, cf__buf_t *out, cf_diag_t *d)
{
    cf__glyph_outliner_t g;
    cf__svgw_t w;
    cf_status_t st;
    memset(&g, 0, sizeof g);
    memset(&w, 0, sizeof w);
    w.out = out;
    w.outline = cf__glyph_outline;
    w.outline_ctx = &g;
    st = cf__figure_play(fig, step, &cf__svgw_backend, &w, d);
    cf__glyph_outliner_fini(&g);
    return st;
}

typedef struct tally {
    size_t figures, with_text;
    long aa, pixels;
    double worst_fraction;
    char worst[160];
} tally_t;

static void
compare_figure(const char *script, const char *name, cf_figure_t *fig,
               tally_t *t)
{
    unsigned char *cairo_svg = NULL;
    size_t cairo_size = 0;
    cf__buf_t mine;
    cf_diag_t d;
    cairo_surface_t *a, *b;
    cf__imgcmp_image ia, ib;
    cf__imgcmp_options o;
    cf__imgcmp_result r;
    long pixels;
    bool text;
    cf_write_options_t wo;
    memset(&mine, 0, sizeof mine);
    /* a figure with overlay steps: its last step, one page */
    cf_write_options_init(&wo);
    wo.step = cf_figure_steps(fig) > 1 ? cf_figure_steps(fig) : 0;
    if (cf_figure_render(fig, CF_FORMAT_SVG, &wo, &cairo_svg, &cairo_size,
                         &d) != CF_STATUS_OK)
        fail_msg("%s: %s: cairo: %s", script, name, d.msg);
    if (write_svgw(fig, wo.step, &mine, &d) != CF_STATUS_OK)
        fail_msg("%s: %s: SVG writer: %s", script, name, d.msg);
    text = memmem(cairo_svg, cairo_size, "<symbol", 7) != NULL;
    a = rasterise(mine.data, mine.size, CF__IMGCMP_DPI);
    b = rasterise(cairo_svg, cairo_size, CF__IMGCMP_DPI);
    if (a == NULL || b == NULL)
        fail_msg("%s: %s: librsvg refused %s", script, name,
                 a == NULL ? "the writer's SVG" : "cairo's SVG");
    ia = image_of(a);
    ib = image_of(b);
    pixels = (long)ia.width * ia.height;
    o.threshold = CF__IMGCMP_THRESHOLD;
    o.aa_radius = CF__IMGCMP_AA_RADIUS;
    o.max_bad_pixels = 0;
    if (cf__imgcmp_compare(&ia, &ib, &o, &r, NULL) != 0)
        fail_msg("%s: %s: sizes differ: %dx%d (writer), %dx%d (cairo)",
                 script, name, ia.width, ia.height, ib.width, ib.height);
    if (!r.match) {
        /* both documents beside the test, to look at */
        char file[256];
        FILE *f;
        snprintf(file, sizeof file, "svgw-%s.svg", name);
        if ((f = fopen(file, "wb")) != NULL) {
            fwrite(mine.data, 1, mine.size, f);
            fclose(f);
        }
        snprintf(file, sizeof file, "cairo-%s.svg", name);
        if ((f = fopen(file, "wb")) != NULL) {
            fwrite(cairo_svg, 1, cairo_size, f);
            fclose(f);
        }
        fail_msg("%s: %s: %ld of %ld pixels differ (at most %ld), first at "
                 "(%d, %d); largest difference %.3f", script, name,
                 r.bad_pixels, pixels, o.max_bad_pixels, r.bad_x[0],
                 r.bad_y[0], r.max_delta);
    }
    t->figures++;
    t->with_text += text;
    t->pixels += pixels;
    t->aa += r.aa_pixels;
    if ((double)r.aa_pixels / (double)pixels > t->worst_fraction) {
        t->worst_fraction = (double)r.aa_pixels / (double)pixels;
        snprintf(t->worst, sizeof t->worst, "%s (%ld of %ld)", name,
                 r.aa_pixels, pixels);
    }
    cairo_surface_destroy(a);
    cairo_surface_destroy(b);
    cf_free(cairo_svg);
    cf__buf_free(&mine);
}

static int
compare_shipped(void *ctx, const char *script, const char *name,
                cf_figure_t *fig)
{
    compare_figure(script, name, fig, ctx);
    return 0;
}

static void
test_every_figure_as_cairo_draws_it(void **state)
{
    tally_t t;
    (void)state;
    memset(&t, 0, sizeof t);
    tu_each_shipped_figure(CF_SOURCE_ROOT, compare_shipped, &t, NULL);
    print_message("%zu figures (%zu with labels, %ld pixels) alike: %ld "
                  "pixels apart by anti-aliasing only, most in %s\n",
                  t.figures, t.with_text, t.pixels, t.aa,
                  t.worst[0] ? t.worst : "none");
    assert_true(t.figures >= 60);
    assert_true(t.with_text >= 30);
}

/* Groups and clips balance; a non-finite coordinate fails the page. */
static int
no_outline(void *ctx, const cf__text_op_t *t, cf__buf_t *d)
{
    (void)ctx;
    (void)t;
    (void)d;
    return 0;
}

static size_t
count(const char *s, const char *what)
{
    size_t n = 0;
    for (s = strstr(s, what); s != NULL; s = strstr(s + 1, what))
        n++;
    return n;
}

static void
test_structure_and_bad_numbers(void **state)
{
    cf__dl_t dl;
    cf__page_t pg;
    cf__paint_t paint;
    cf__buf_t out;
    cf__svgw_t w;
    double rect[4] = { 1, 2, 30, 40 };
    (void)state;
    memset(&pg, 0, sizeof pg);
    pg.width = 100;
    pg.height = 50;
    memset(&paint, 0, sizeof paint);
    paint.stroke = true;
    paint.line.width = 1.5;
    paint.line.opacity = 1;
    paint.line.color.a = 1;
    cf__dl_init(&dl);
    cf__dl_group(&dl, "curve", 0);
    cf__dl_clip(&dl, rect);
    cf__dl_path_begin(&dl);
    cf__dl_move(&dl, 0, 0);
    cf__dl_arc(&dl, 50, 25, 10, 0, 7);   /* more than a turn */
    cf__dl_path_paint(&dl, &paint);
    cf__dl_unclip(&dl);
    cf__dl_group(&dl, "points", 1);
    cf__dl_clip(&dl, NULL);              /* scope only, closed by END */
    cf__dl_end(&dl);
    cf__dl_end(&dl);
    memset(&out, 0, sizeof out);
    memset(&w, 0, sizeof w);
    w.out = &out;
    w.outline = no_outline;
    assert_int_equal(cf__dl_play_page(&dl, &pg, &cf__svgw_backend, &w), 0);
    assert_int_equal(cf__buf_append(&out, "", 1), 0);
    assert_int_equal(count((char *)out.data, "<g"),
                     count((char *)out.data, "</g>"));
    assert_int_equal(count((char *)out.data, "<clipPath"), 1);
    /* 7 rad from 0: three pieces of at most half a turn */
    assert_int_equal(count((char *)out.data, "A10 10 0 0 1 "), 3);
    assert_non_null(strstr((char *)out.data, "width=\"100pt\""));
    assert_non_null(strstr((char *)out.data, "</svg>\n"));
    cf__buf_free(&out);

    cf__dl_reset(&dl);
    cf__dl_path_begin(&dl);
    cf__dl_move(&dl, 0, 0);
    cf__dl_line(&dl, NAN, 1);
    cf__dl_path_paint(&dl, &paint);
    memset(&w, 0, sizeof w);
    w.out = &out;
    w.outline = no_outline;
    assert_int_not_equal(cf__dl_play_page(&dl, &pg, &cf__svgw_backend, &w),
                         0);
    cf__buf_free(&out);
    cf__dl_free(&dl);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_structure_and_bad_numbers),
        cmocka_unit_test(test_every_figure_as_cairo_draws_it),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
