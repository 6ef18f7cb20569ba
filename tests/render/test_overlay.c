/* Overlay steps: beamer's specifications parsed and checked, the GROUP
** operations carrying them (the dump), a PDF page per step of one size,
** step k's raster equal to a figure of only the elements shown on step
** k, numbered PNGs, the animated SVG (its frames the steps' SVGs, its
** static picture the last step, read back with librsvg). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cmocka.h>
#include <cairo.h>
#include <librsvg/rsvg.h>

#include "testutil.h"
#include "curvefig/figure.h"
#include "overlay-spec.h"

/* ---- specifications ----------------------------------------------------- */

static void
test_spec_parse(void **state)
{
    static const struct { const char *s; unsigned last; } good[] = {
        { "1", 1 }, { "2-", 2 }, { "1-3", 3 }, { "-4", 4 }, { "2,4-", 4 },
        { "3,1", 3 }, { "1-2,5", 5 }, { "999", 999 },
    };
    static const struct { const char *s, *why; } bad[] = {
        { "", "empty" }, { "0", "step 0" }, { "0-2", "step 0" },
        { "3-1", "runs backwards" }, { "2-x", "unexpected \"x\"" },
        { "a", "not a step number" }, { "1,,2", "an empty range" },
        { "-", "needs a step" }, { "+-", "incremental" },
        { "1000", "up to 999" }, { " 2", "not a step number" },
        { "2,", "an empty range" },
    };
    char why[120];
    unsigned last;
    (void)state;
    for (size_t i = 0; i < sizeof good / sizeof good[0]; i++) {
        last = 0;
        assert_int_equal(cf__overlay_parse(good[i].s, &last, why,
                                           sizeof why), 0);
        assert_int_equal(last, good[i].last);
    }
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        why[0] = '\0';
        assert_int_equal(cf__overlay_parse(bad[i].s, &last, why,
                                           sizeof why), -1);
        if (strstr(why, bad[i].why) == NULL)
            fail_msg("\"%s\": \"%s\" lacks \"%s\"", bad[i].s, why,
                     bad[i].why);
    }
}

static void
test_spec_visible(void **state)
{
    /* steps 1..6 of each, as beamer shows them */
    static const struct { const char *s, *on; } cases[] = {
        { "2-", "011111" }, { "3", "001000" }, { "1-2", "110000" },
        { "2,4-", "010111" }, { "-3", "111000" }, { "1,3,5", "101010" },
        { NULL, "111111" },
    };
    (void)state;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        for (unsigned k = 1; k <= 6; k++)
            assert_int_equal(cf__overlay_visible(cases[i].s, k),
                             cases[i].on[k - 1] == '1');
}

/* ---- figures ------------------------------------------------------------ */

/* Element j of the test figure: a polygon, a curve, a point, a label and
** an arrow, each inside the window, with these steps (NULL: always). */
static const char *const specs[5] = { NULL, "2-", "3", "1-2", "2,4-" };

/* The figure with the elements whose bit is in mask; overlays when
** with_steps (else none). */
static cf_figure_t *
make_figure(unsigned mask, bool with_steps)
{
    double poly[] = { 1, 1, 3, 8, 7, 8, 9, 2 };
    double cp[] = { 1, 1, 3, 8, 7, 8, 9, 2 };
    double pt[] = { 5, 6.5 };
    cf_figure_t *fig = NULL;
    cf_bezier_t *c = NULL;
    cf_style_t s;
    assert_int_equal(cf_figure_create(60, 50, CF_UNIT_MM, &fig, NULL), 0);
    assert_int_equal(cf_figure_set_window(fig, 0, 10, 0, 10), 0);
    assert_int_equal(cf_bezier_create(2, 3, cp, NULL, &c, NULL), 0);
    for (unsigned j = 0; j < 5; j++) {
        if (!(mask & (1u << j)))
            continue;
        assert_int_equal(cf_figure_set_overlay(fig, with_steps ? specs[j]
                                                               : NULL), 0);
        cf_style_init(&s);
        switch (j) {
        case 0:
            assert_int_equal(cf_figure_add_polygon(fig, poly, 4, NULL), 0);
            break;
        case 1:
            assert_int_equal(cf_figure_add_bezier(fig, c, NULL), 0);
            break;
        case 2:
            s.set = CF_STYLE_MARKER | CF_STYLE_MARKER_SIZE;
            s.marker = CF_MARKER_STAR;
            s.marker_size = 9;
            assert_int_equal(cf_figure_add_points(fig, pt, 1, &s), 0);
            break;
        case 3:
            s.set = CF_STYLE_PLACE;
            s.place = CF_PLACE_N;
            assert_int_equal(cf_figure_add_label(fig, 5, 3, "b_0^3(t)", &s),
                             0);
            break;
        default:
            assert_int_equal(cf_figure_add_arrow(fig, 2, 5, 2, 0, NULL), 0);
            break;
        }
    }
    cf_bezier_destroy(c);
    return fig;
}

/* The elements shown on step k as a mask. */
static unsigned
mask_at(unsigned k)
{
    unsigned m = 0;
    for (unsigned j = 0; j < 5; j++)
        if (cf__overlay_visible(specs[j], k))
            m |= 1u << j;
    return m;
}

static unsigned char *
render(cf_figure_t *fig, cf_format_t f, unsigned step, size_t *n)
{
    cf_write_options_t o;
    unsigned char *data = NULL;
    cf_diag_t d;
    cf_write_options_init(&o);
    o.step = step;
    o.dpi = 100;
    cf_diag_clear(&d);
    if (cf_figure_render(fig, f, &o, &data, n, &d) != CF_STATUS_OK)
        fail_msg("render: %s", d.msg);
    return data;
}

static void
test_steps_counted(void **state)
{
    cf_figure_t *fig = make_figure(31, true), *plain = make_figure(31, false);
    (void)state;
    assert_int_equal(cf_figure_steps(fig), 4);
    assert_int_equal(cf_figure_steps(plain), 1);
    assert_int_equal(cf_figure_element_count(fig), 5);
    for (unsigned k = 1; k <= 4; k++)
        for (size_t j = 0; j < 5; j++)
            assert_int_equal(cf_figure_visible_at(fig, j, k),
                             (mask_at(k) >> j) & 1);
    assert_false(cf_figure_visible_at(fig, 0, 5));
    assert_false(cf_figure_visible_at(fig, 5, 1));
    cf_figure_destroy(fig);
    cf_figure_destroy(plain);
}

static void
test_bad_spec_and_step(void **state)
{
    cf_figure_t *fig = make_figure(31, true);
    cf_write_options_t o;
    unsigned char *data = NULL;
    size_t n;
    cf_diag_t d;
    (void)state;
    cf_write_options_init(&o);
    o.step = 5;
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_PNG, &o, &data, &n, &d),
                     CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(d.msg, "step 5: the figure has 4 steps"));
    assert_null(data);
    assert_int_equal(cf_figure_set_overlay(fig, "2-1"),
                     CF_STATUS_INVALID_ARG);
    cf_diag_clear(&d);
    cf_figure_status(fig, &d);
    assert_non_null(strstr(d.msg, "visible = \"2-1\": the range 2-1 runs "
                                  "backwards"));
    cf_figure_destroy(fig);
}

static void
test_dump_shows_overlay(void **state)
{
    cf_figure_t *fig = make_figure(31, true);
    char *text = NULL, *line;
    size_t n, groups = 0;
    (void)state;
    assert_int_equal(cf_figure_dump(fig, NULL, &text, &n, NULL), 0);
    for (line = text; line != NULL && *line != '\0';) {
        char *nl = strchr(line, '\n');
        if (strncmp(line, "group ", 6) == 0) {
            char want[64];
            const char *ov = strstr(line, " overlay ");
            if (specs[groups] == NULL) {
                assert_true(ov == NULL || ov > nl);
            } else {
                snprintf(want, sizeof want, " overlay %s\n", specs[groups]);
                assert_non_null(ov);
                assert_memory_equal(ov, want, strlen(want));
            }
            groups++;
        }
        line = nl != NULL ? nl + 1 : NULL;
    }
    assert_int_equal(groups, 5);
    cf_free(text);
    cf_figure_destroy(fig);
}

static const unsigned char *
find(const unsigned char *p, const unsigned char *end, const char *needle)
{
    size_t m = strlen(needle);
    for (; p + m <= end; p++)
        if (memcmp(p, needle, m) == 0)
            return p;
    return NULL;
}

/* Occurrences of needle in [p, p + n) not followed by letter s. */
static size_t
count_pages(const unsigned char *p, size_t n)
{
    static const char needle[] = "/Type /Page";
    size_t m = sizeof needle - 1, c = 0;
    for (size_t i = 0; i + m < n; i++)
        if (memcmp(p + i, needle, m) == 0 && p[i + m] != 's')
            c++;
    return c;
}

static void
test_pdf_page_per_step(void **state)
{
    cf_figure_t *fig = make_figure(31, true), *plain = make_figure(31, false);
    unsigned char *pdf, *one;
    size_t n, n1;
    (void)state;
    pdf = render(fig, CF_FORMAT_PDF, 0, &n);
    assert_int_equal(count_pages(pdf, n), 4);
    one = render(plain, CF_FORMAT_PDF, 0, &n1);
    assert_int_equal(count_pages(one, n1), 1);
    cf_free(one);
    one = render(fig, CF_FORMAT_PDF, 2, &n1);
    assert_int_equal(count_pages(one, n1), 1);
    cf_free(one);
    /* every page the same box: cairo writes each page's MediaBox */
    {
        const unsigned char *p = pdf, *end = pdf + n, *first = NULL;
        size_t boxes = 0;
        while ((p = find(p, end, "/MediaBox")) != NULL) {
            const unsigned char *e = memchr(p, ']', (size_t)(end - p));
            assert_non_null(e);
            if (first == NULL)
                first = p;
            else
                assert_memory_equal(first, p, (size_t)(e - p));
            boxes++;
            p = e;
        }
        assert_true(boxes >= 4);
    }
    cf_free(pdf);
    cf_figure_destroy(fig);
    cf_figure_destroy(plain);
}

/* The PNG of a at step ka is byte for byte that of b at step kb. */
static void
assert_same_png(cf_figure_t *a, unsigned ka, cf_figure_t *b, unsigned kb)
{
    size_t na, nb;
    unsigned char *pa = render(a, CF_FORMAT_PNG, ka, &na);
    unsigned char *pb = render(b, CF_FORMAT_PNG, kb, &nb);
    assert_int_equal(na, nb);
    assert_memory_equal(pa, pb, na);
    cf_free(pa);
    cf_free(pb);
}

/* Step k drawn alone is byte for byte the figure made of the elements
** shown on step k and no overlays. */
static void
test_step_raster_is_its_elements(void **state)
{
    cf_figure_t *fig = make_figure(31, true);
    (void)state;
    for (unsigned k = 1; k <= 4; k++) {
        cf_figure_t *only = make_figure(mask_at(k), false);
        assert_same_png(fig, k, only, 0);
        cf_figure_destroy(only);
    }
    /* without a step, one picture stands for the sequence: the last step */
    assert_same_png(fig, 0, fig, 4);
    cf_figure_destroy(fig);
}

static void
test_numbered_pngs(void **state)
{
    char dir[] = "/tmp/cf-overlay-XXXXXX", path[256], base[128];
    cf_figure_t *fig = make_figure(31, true);
    cf_write_options_t o;
    unsigned char *last = NULL, *all;
    size_t nlast = 0, nall;
    (void)state;
    assert_non_null(mkdtemp(dir));
    snprintf(base, sizeof base, "%s/fig", dir);
    cf_write_options_init(&o);
    o.dpi = 100;
    assert_int_equal(cf_figure_write_all(fig, base,
                                         CF_FORMAT_BIT(CF_FORMAT_PNG)
                                             | CF_FORMAT_BIT(CF_FORMAT_SVG),
                                         &o, NULL), 0);
    for (unsigned k = 1; k <= 5; k++) {
        size_t n, m;
        unsigned char *d, *want;
        snprintf(path, sizeof path, "%s-%u.png", base, k);
        d = tu_read_file(path, &n);
        if (k == 5) {
            assert_null(d);   /* four steps, four files */
            break;
        }
        assert_non_null(d);
        want = render(fig, CF_FORMAT_PNG, k, &m);
        assert_int_equal(n, m);
        assert_memory_equal(d, want, n);
        cf_free(want);
        unlink(path);
        free(last);
        last = d;
        nlast = n;
        /* step files of the other formats only when asked */
        snprintf(path, sizeof path, "%s-%u.svg", base, k);
        assert_int_not_equal(access(path, F_OK), 0);
    }
    snprintf(path, sizeof path, "%s.png", base);
    all = tu_read_file(path, &nall);
    assert_non_null(all);
    assert_int_equal(nall, nlast);
    assert_memory_equal(all, last, nall);
    unlink(path);
    snprintf(path, sizeof path, "%s.svg", base);
    unlink(path);
    free(all);
    free(last);
    /* step_files: NAME-K.svg too */
    o.step_files = true;
    assert_int_equal(cf_figure_write_all(fig, base,
                                         CF_FORMAT_BIT(CF_FORMAT_SVG), &o,
                                         NULL), 0);
    for (unsigned k = 1; k <= 4; k++) {
        snprintf(path, sizeof path, "%s-%u.svg", base, k);
        assert_int_equal(access(path, F_OK), 0);
        unlink(path);
    }
    snprintf(path, sizeof path, "%s.svg", base);
    unlink(path);
    assert_int_equal(rmdir(dir), 0);
    cf_figure_destroy(fig);
}

/* An SVG rasterised by librsvg at its own size (pt at 72 dpi). */
static cairo_surface_t *
rsvg_raster(const unsigned char *svg, size_t n)
{
    GError *err = NULL;
    RsvgHandle *h = rsvg_handle_new_from_data(svg, n, &err);
    double w, hgt;
    cairo_surface_t *s;
    cairo_t *cr;
    RsvgRectangle vp;
    if (h == NULL)
        fail_msg("librsvg: %s", err != NULL ? err->message : "?");
    assert_true(rsvg_handle_get_intrinsic_size_in_pixels(h, &w, &hgt));
    s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, (int)w + 1,
                                   (int)hgt + 1);
    cr = cairo_create(s);
    vp.x = vp.y = 0;
    vp.width = w;
    vp.height = hgt;
    assert_true(rsvg_handle_render_document(h, cr, &vp, NULL));
    cairo_destroy(cr);
    g_object_unref(h);
    cairo_surface_flush(s);
    return s;
}

static bool
same_pixels(cairo_surface_t *a, cairo_surface_t *b)
{
    int h = cairo_image_surface_get_height(a);
    int st = cairo_image_surface_get_stride(a);
    return h == cairo_image_surface_get_height(b)
        && st == cairo_image_surface_get_stride(b)
        && memcmp(cairo_image_surface_get_data(a),
                  cairo_image_surface_get_data(b), (size_t)(h * st)) == 0;
}

static void
test_animated_svg(void **state)
{
    cf_figure_t *fig = make_figure(31, true);
    size_t n, nk;
    unsigned char *svg = render(fig, CF_FORMAT_SVG, 0, &n), *one;
    char *text = malloc(n + 1);
    cairo_surface_t *ra, *rk;
    (void)state;
    memcpy(text, svg, n);
    text[n] = '\0';
    /* one frame per step, each with its SMIL visibility animation: on
    ** during its quarter of the loop only */
    for (unsigned k = 1; k <= 4; k++) {
        char id[32], values[64] = "";
        const char *g, *anim;
        snprintf(id, sizeof id, "<g id=\"step-%u\"", k);
        g = strstr(text, id);
        assert_non_null(g);
        anim = strstr(g, "<animate attributeName=\"visibility\"");
        assert_non_null(anim);
        for (unsigned j = 1; j <= 4; j++)
            strcat(values, j == k ? (j > 1 ? ";visible" : "visible")
                                  : (j > 1 ? ";hidden" : "hidden"));
        assert_non_null(strstr(anim, values));
        assert_non_null(strstr(anim, "keyTimes=\"0;0.25;0.5;0.75\""));
        assert_non_null(strstr(anim, "dur=\"6s\""));
        assert_non_null(strstr(g, k == 4 ? "visibility=\"visible\""
                                         : "visibility=\"hidden\""));
    }
    assert_null(strstr(text, "<g id=\"step-5\""));
    /* well-formed for librsvg, which plays no animation: the picture is
    ** the last step's */
    ra = rsvg_raster(svg, n);
    one = render(fig, CF_FORMAT_SVG, 4, &nk);
    rk = rsvg_raster(one, nk);
    assert_true(same_pixels(ra, rk));
    cairo_surface_destroy(rk);
    cf_free(one);
    one = render(fig, CF_FORMAT_SVG, 1, &nk);
    rk = rsvg_raster(one, nk);
    assert_false(same_pixels(ra, rk));
    cairo_surface_destroy(rk);
    cairo_surface_destroy(ra);
    cf_free(one);
    free(text);
    cf_free(svg);
    cf_figure_destroy(fig);
}

/* A figure without overlays: the same bytes with any step option 0. */
static void
test_plain_figure_unchanged(void **state)
{
    cf_figure_t *fig = make_figure(31, false);
    cf_write_options_t o;
    unsigned char *a = NULL, *b = NULL;
    size_t na, nb;
    (void)state;
    cf_write_options_init(&o);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, &o, &a, &na, NULL),
                     0);
    o.step = 1;   /* the one step of a figure without overlays */
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, &o, &b, &nb, NULL),
                     0);
    assert_int_equal(na, nb);
    assert_memory_equal(a, b, na);
    assert_false(tu_bytes_hold(a, na, "<animate"));
    cf_free(a);
    cf_free(b);
    cf_figure_destroy(fig);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_spec_parse),
        cmocka_unit_test(test_spec_visible),
        cmocka_unit_test(test_steps_counted),
        cmocka_unit_test(test_bad_spec_and_step),
        cmocka_unit_test(test_dump_shows_overlay),
        cmocka_unit_test(test_pdf_page_per_step),
        cmocka_unit_test(test_step_raster_is_its_elements),
        cmocka_unit_test(test_numbered_pngs),
        cmocka_unit_test(test_animated_svg),
        cmocka_unit_test(test_plain_figure_unchanged),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
