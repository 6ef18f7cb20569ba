/* The SVG writer (render/backends/backend-svgw.c), the one writer of SVG:
** files and the live view (labels as <use>s of glyph outlines defined
** once, render/output/svg-glyphs.c) and the course pages (labels as whole
** outline paths, where there is no pango).
**   - Every shipped figure written both ways, both rasterised by librsvg
**     at the pixel suite's 144 dpi and compared by its comparator
**     (render/tool/imgcmp.h) with its threshold (0.1) and anti-aliasing
**     allowance (one pixel), and no bad pixel at all, labels included.
**     (The pixel suite compares the files' SVG against cairo's PNG.)
**   - Every label of every shipped figure: its glyphs placed at the
**     origins render/backends/label-glyph-runs.c gives make exactly the
**     outline pango's own renderer draws (cf__label_path), point for
**     point to one step of cairo's path grid (1/256 bp), where a glyph
**     misplaced by the baseline, a run's width or an offset would be off
**     by far more.
**   - A glyph used four times is defined once.
**   - A well-formed document whose clips and groups balance, and refusal
**     of a non-finite coordinate. */
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
#include "font-glyphs.h"
#include "label-glyph-runs.h"
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

/* The figure through the SVG writer as a course page draws it (labels as
** outline paths) into out (empty). */
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
    unsigned char *file_svg = NULL;
    size_t file_size = 0;
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
    if (cf_figure_render(fig, CF_FORMAT_SVG, &wo, &file_svg, &file_size,
                         &d) != CF_STATUS_OK)
        fail_msg("%s: %s: file: %s", script, name, d.msg);
    if (write_svgw(fig, wo.step, &mine, &d) != CF_STATUS_OK)
        fail_msg("%s: %s: page: %s", script, name, d.msg);
    text = memmem(file_svg, file_size, "<use", 4) != NULL;
    a = rasterise(mine.data, mine.size, CF__IMGCMP_DPI);
    b = rasterise(file_svg, file_size, CF__IMGCMP_DPI);
    if (a == NULL || b == NULL)
        fail_msg("%s: %s: librsvg refused %s", script, name,
                 a == NULL ? "the page's SVG" : "the file's SVG");
    ia = image_of(a);
    ib = image_of(b);
    pixels = (long)ia.width * ia.height;
    o.threshold = CF__IMGCMP_THRESHOLD;
    o.aa_radius = CF__IMGCMP_AA_RADIUS;
    o.max_bad_pixels = 0;
    if (cf__imgcmp_compare(&ia, &ib, &o, &r, NULL) != 0)
        fail_msg("%s: %s: sizes differ: %dx%d (page), %dx%d (file)",
                 script, name, ia.width, ia.height, ib.width, ib.height);
    if (!r.match) {
        /* both documents beside the test, to look at */
        char file[256];
        FILE *f;
        snprintf(file, sizeof file, "page-%s.svg", name);
        if ((f = fopen(file, "wb")) != NULL) {
            fwrite(mine.data, 1, mine.size, f);
            fclose(f);
        }
        snprintf(file, sizeof file, "file-%s.svg", name);
        if ((f = fopen(file, "wb")) != NULL) {
            fwrite(file_svg, 1, file_size, f);
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
    cf_free(file_svg);
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
test_every_figure_alike_in_files_and_pages(void **state)
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

/* ---- glyphs where pango draws them ------------------------------------- */

/* cairo keeps path points on a grid of 1/256 device units (bp here): a
** point may land one step either side of its double */
#define GRID (1.0 / 256 + 1e-12)

typedef struct glyph_check {
    cairo_t *ref, *mine;       /* recording surfaces' contexts */
    size_t labels, glyphs, whole;
    double worst;
} glyph_check_t;

static int
glyph_at(void *ctx, const cf__label_glyph_t *lg)
{
    glyph_check_t *g = ctx;
    cairo_glyph_t gl;
    gl.index = lg->index;
    gl.x = lg->x;
    gl.y = lg->y;
    /* cairo's own path of the glyph: the native faces' scaled fonts are
    ** made here, as the writer reads their glyphs from the files */
    cairo_set_scaled_font(g->mine, lg->font != NULL
                                       ? lg->font
                                       : cf__font_face_scaled(lg->face));
    cairo_glyph_path(g->mine, &gl, 1);
    g->glyphs++;
    return 0;
}

static int
rule_at(void *ctx, const double r[4])
{
    glyph_check_t *g = ctx;
    cairo_rectangle(g->mine, r[0], r[1], r[2], r[3]);
    return 0;
}

/* The first element of path from i on that is not a move followed by
** another move or by the end (no ink: pango's renderer ends a label
** with a move back to its origin). */
static int
inked(const cairo_path_t *path, int i)
{
    while (i < path->num_data
           && path->data[i].header.type == CAIRO_PATH_MOVE_TO) {
        int n = i + path->data[i].header.length;
        if (n < path->num_data
            && path->data[n].header.type != CAIRO_PATH_MOVE_TO)
            break;
        i = n;
    }
    return i;
}

/* The label's outline both ways: the same segments, the same points. */
static void
check_text(void *ctx, const cf__text_op_t *t)
{
    static const cf__label_glyph_fns_t fns = { glyph_at, rule_at };
    glyph_check_t *g = ctx;
    cairo_path_t *a, *b;
    int i, j, r;
    cairo_new_path(g->ref);
    cairo_new_path(g->mine);
    cf__label_path(t->label, g->ref, t->ox, t->oy);
    r = cf__label_glyphs(t->label, t->ox, t->oy, &fns, g);
    assert_true(r == 0 || r == 1);
    g->labels++;
    if (r == 1) {   /* a glyph missing from its font: the path whole */
        g->whole++;
        return;
    }
    a = cairo_copy_path(g->ref);
    b = cairo_copy_path(g->mine);
    assert_int_equal(a->status, CAIRO_STATUS_SUCCESS);
    assert_int_equal(b->status, CAIRO_STATUS_SUCCESS);
    for (i = 0, j = 0;; i += a->data[i].header.length,
                        j += b->data[j].header.length) {
        const cairo_path_data_t *p, *q;
        i = inked(a, i);
        j = inked(b, j);
        if (i >= a->num_data || j >= b->num_data)
            break;
        p = &a->data[i];
        q = &b->data[j];
        if (p->header.type != q->header.type)
            fail_msg("label \"%s\": element %d of pango's path is not "
                     "element %d of its glyphs'", t->source, i, j);
        for (int k = 1; k < p->header.length; k++) {
            double e = fmax(fabs(p[k].point.x - q[k].point.x),
                            fabs(p[k].point.y - q[k].point.y));
            g->worst = fmax(g->worst, e);
            if (!(e <= GRID))
                fail_msg("label \"%s\": a point %g bp from pango's",
                         t->source, e);
        }
    }
    if (i < a->num_data || j < b->num_data)
        fail_msg("label \"%s\": the paths differ in length", t->source);
    cairo_path_destroy(a);
    cairo_path_destroy(b);
}

static void nop(void *ctx) { (void)ctx; }
static void nop_page(void *ctx, const cf__page_t *p) { (void)ctx; (void)p; }
static void
nop_group(void *ctx, const char *n, size_t i, const char *o)
{
    (void)ctx;
    (void)n;
    (void)i;
    (void)o;
}
static void
nop_clip(void *ctx, bool has, const double r[4])
{
    (void)ctx;
    (void)has;
    (void)r;
}
static void
nop_path(void *ctx, const cf__path_t *p, const cf__paint_t *paint)
{
    (void)ctx;
    (void)p;
    (void)paint;
}
static int nop_end(void *ctx) { (void)ctx; return 0; }

static const cf__backend_t glyph_checker = {
    "glyph-check", nop_page, nop_group, nop, nop_clip, nop, nop_path,
    NULL, check_text, nop_end, NULL, NULL
};

static int
check_shipped(void *ctx, const char *script, const char *name,
              cf_figure_t *fig)
{
    cf_diag_t d;
    (void)script;
    if (cf__figure_play(fig, 0, &glyph_checker, ctx, &d) != CF_STATUS_OK)
        fail_msg("%s: %s", name, d.msg);
    return 0;
}

static void
test_glyphs_where_pango_draws_them(void **state)
{
    glyph_check_t g;
    cairo_surface_t *s = cairo_recording_surface_create(CAIRO_CONTENT_ALPHA,
                                                        NULL);
    (void)state;
    memset(&g, 0, sizeof g);
    g.ref = cairo_create(s);
    g.mine = cairo_create(s);
    tu_each_shipped_figure(CF_SOURCE_ROOT, check_shipped, &g, NULL);
    print_message("%zu labels, %zu glyphs placed as pango draws them (worst "
                  "%.2g bp); %zu labels drawn whole\n", g.labels, g.glyphs,
                  g.worst, g.whole);
    assert_true(g.labels >= 300 && g.glyphs >= g.labels);
    cairo_destroy(g.ref);
    cairo_destroy(g.mine);
    cairo_surface_destroy(s);
}

/* Two labels "aa": one outline of a, used four times. */
static void
test_glyph_defined_once(void **state)
{
    cf_figure_t *fig;
    unsigned char *svg;
    size_t size;
    char *text;
    (void)state;
    assert_int_equal(cf_figure_create(100, 60, CF_UNIT_BP, &fig, NULL), 0);
    assert_int_equal(cf_figure_set_window(fig, 0, 1, 0, 1), 0);
    assert_int_equal(cf_figure_add_label(fig, 0.2, 0.5, "aa", NULL), 0);
    assert_int_equal(cf_figure_add_label(fig, 0.7, 0.5, "aa", NULL), 0);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, NULL, &svg, &size,
                                      NULL), 0);
    text = malloc(size + 1);
    memcpy(text, svg, size);
    text[size] = '\0';
    assert_int_equal(count(text, "<symbol"), 1);
    assert_int_equal(count(text, "<use xlink:href=\"#g1\""), 4);
    free(text);
    cf_free(svg);
    cf_figure_destroy(fig);
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
    /* the failure says which: a number, and in which element */
    {
        cf_diag_t d;
        cf_diag_clear(&d);
        assert_int_equal(cf__svgw_fault(&w, "svg", &d), CF_STATUS_INVALID_ARG);
        assert_string_equal(d.msg, "svg: a coordinate is NaN, not a finite "
                                   "number; SVG holds numbers within 1e9 bp");
        cf__dl_reset(&dl);
        cf__dl_group(&dl, "arrow", 1);
        cf__dl_path_begin(&dl);
        cf__dl_move(&dl, 0, 0);
        cf__dl_line(&dl, 2e9, 1);
        cf__dl_path_paint(&dl, &paint);
        cf__dl_end(&dl);
        memset(&w, 0, sizeof w);
        w.out = &out;
        w.outline = no_outline;
        assert_int_not_equal(cf__dl_play_page(&dl, &pg, &cf__svgw_backend,
                                              &w), 0);
        cf__buf_free(&out);
        cf_diag_clear(&d);
        assert_int_equal(cf__svgw_fault(&w, "frame 3 of the animated svg",
                                        &d), CF_STATUS_INVALID_ARG);
        assert_string_equal(d.msg, "frame 3 of the animated svg: a "
                                   "coordinate of arrow 2 is 2e+09, too far "
                                   "from the page; SVG holds numbers within "
                                   "1e9 bp");
        assert_int_equal(d.index, 1);
        /* out of memory: said so alone */
        memset(&w, 0, sizeof w);
        w.sc.bad = true;
        cf_diag_clear(&d);
        assert_int_equal(cf__svgw_fault(&w, "svg", &d), CF_STATUS_NO_MEMORY);
        assert_string_equal(d.msg, "out of memory writing svg");
    }
    cf__dl_free(&dl);
}

/* A figure whose arrow comes from 1e8 window units away on a page that
** clips: its SVG (a coordinate of 1e10 bp) is refused naming the arrow;
** the PNG draws it (render/backends/far-clip.h). */
static void
test_far_arrow_named(void **state)
{
    cf_figure_t *fig = NULL;
    cf_diag_t d;
    unsigned char *data = NULL;
    size_t size = 0;
    (void)state;
    assert_int_equal(cf_figure_create(60, 40, CF_UNIT_MM, &fig, NULL), 0);
    assert_int_equal(cf_figure_set_window(fig, 0, 1, 0, 1), 0);
    assert_int_equal(cf_figure_set_page_mode(fig, CF_PAGE_FIXED), 0);
    assert_int_equal(cf_figure_set_clip(fig, true), 0);
    assert_int_equal(cf_figure_add_polyline(fig, (const double[]){ 0, 0, 1,
                                                                   1 },
                                            2, false, NULL), 0);
    assert_int_equal(cf_figure_add_arrow(fig, 1e8, 0.5, 0.5 - 1e8, 0,
                                         NULL), 0);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, NULL, &data, &size,
                                      &d), CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(d.msg, "svg: a coordinate of arrow 2 is "));
    assert_non_null(strstr(d.msg, "too far from the page"));
    assert_null(data);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_PNG, NULL, &data, &size,
                                      NULL), 0);
    cf_free(data);
    cf_figure_destroy(fig);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_structure_and_bad_numbers),
        cmocka_unit_test(test_far_arrow_named),
        cmocka_unit_test(test_glyph_defined_once),
        cmocka_unit_test(test_glyphs_where_pango_draws_them),
        cmocka_unit_test(test_every_figure_alike_in_files_and_pages),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
