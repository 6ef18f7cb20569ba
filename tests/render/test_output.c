/* Output: five formats, byte-identical renders, page = ink box, SVG
** metadata read back with librsvg, atomic writes, bad arguments. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <dirent.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmocka.h>
#include <cairo.h>
#include <librsvg/rsvg.h>

#include "curvefig/figure.h"
#include "png-private.h"
#include "testutil.h"
#include "pngtest.h"
#include "spawn.h"

/* A figure with every kind of element and labels in four scripts. */
static cf_figure_t *
build_figure(bool transparent)
{
    double P[] = { 0, 5, 1, -1, 3, 0, 4, 3, 6, 10 }, tri[30];
    size_t counts[] = { 5, 4, 3, 2, 1 };
    cf_figure_t *fig = NULL;
    cf_bezier_t *c;
    cf_style_t s;
    cf_axes_t ax;
    cf_theme_t th;

    assert_int_equal(cf_figure_create(90, 70, CF_UNIT_MM, &fig, NULL), 0);
    if (transparent) {
        cf_figure_get_theme(fig, &th);
        th.background.a = 0;
        assert_int_equal(cf_figure_set_theme(fig, &th), 0);
    }
    assert_int_equal(cf_bezier_create(2, 4, P, NULL, &c, NULL), 0);
    assert_int_equal(cf_bezier_decasteljau(c, 0.75, tri), 0);
    assert_int_equal(cf_figure_add_hull(fig, P, 5, NULL), 0);
    assert_int_equal(cf_figure_add_net(fig, tri, counts, 5, NULL, NULL), 0);
    assert_int_equal(cf_figure_add_bezier(fig, c, NULL), 0);
    cf_style_init(&s);
    s.set = CF_STYLE_MARKER | CF_STYLE_MARKER_SIZE;
    s.marker = CF_MARKER_STAR;
    s.marker_size = 8;
    assert_int_equal(cf_figure_add_points(fig, tri + 28, 1, &s), 0);
    assert_int_equal(cf_figure_add_label(fig, 0, 5, "P_0", NULL), 0);
    assert_int_equal(cf_figure_add_label(fig, 6, 10, "B_i^n(t)", NULL), 0);
    assert_int_equal(cf_figure_add_label(fig, 3, 0, "\\omega_{k-1}", NULL),
                     0);
    assert_int_equal(cf_figure_add_label(fig, 1, -1,
                                         "k\xc5\x99ivka \xd0\x9a\xd1\x80"
                                         "\xd0\xb8\xd0\xb2\xd0\xb0\xd1\x8f"
                                         " \xe6\x9b\xb2\xe7\xba\xbf", NULL),
                     0);
    assert_int_equal(cf_figure_add_arrow(fig, 4, 3, 1, 2, NULL), 0);
    cf_axes_init(&ax);
    ax.xmin = -1;
    ax.xmax = 7;
    ax.ymin = -2;
    ax.ymax = 11;
    ax.xlabel = "x";
    ax.ylabel = "y";
    assert_int_equal(cf_figure_add_axes(fig, &ax, NULL), 0);
    assert_int_equal(cf_figure_set_title(fig, "de Casteljau <t = 3/4>"), 0);
    assert_int_equal(cf_figure_set_caption(fig, "Levels & the point C(t)"),
                     0);
    cf_bezier_destroy(c);
    return fig;
}

typedef struct blob {
    unsigned char *data;
    size_t size;
} blob_t;

static blob_t
render(cf_figure_t *fig, cf_format_t f, const cf_write_options_t *o)
{
    blob_t b;
    cf_diag_t d;
    cf_diag_clear(&d);
    if (cf_figure_render(fig, f, o, &b.data, &b.size, &d) != CF_STATUS_OK)
        fail_msg("render %s: %s", cf_format_extension(f), d.msg);
    return b;
}

static bool
blob_has(const blob_t *b, const char *s)
{
    size_t n = strlen(s), i;
    for (i = 0; i + n <= b->size; i++)
        if (memcmp(b->data + i, s, n) == 0)
            return true;
    return false;
}

/* The text after `key` in a blob, as a C string (up to a newline). */
static bool
blob_line(const blob_t *b, const char *key, char *out, size_t cap)
{
    size_t n = strlen(key), i, k;
    for (i = 0; i + n <= b->size; i++) {
        if (memcmp(b->data + i, key, n) == 0) {
            for (k = 0; k + 1 < cap && i + n + k < b->size
                 && b->data[i + n + k] != '\n'; k++)
                out[k] = (char)b->data[i + n + k];
            out[k] = '\0';
            return true;
        }
    }
    return false;
}

static void
test_byte_identical(void **state)
{
    cf_figure_t *a = build_figure(false), *b = build_figure(false);
    cf_write_options_t o;
    int f, tight;
    (void)state;
    cf_write_options_init(&o);
    for (tight = 0; tight < 2; tight++) {
        o.tight = tight;
        for (f = 0; f < CF_FORMAT_LAST_; f++) {
            blob_t x = render(a, (cf_format_t)f, &o);
            blob_t y = render(a, (cf_format_t)f, &o);
            blob_t z = render(b, (cf_format_t)f, &o);
            /* same figure twice, and an identical second figure (cairo's
            ** per-process surface ids must not leak into the SVG) */
            assert_int_equal(x.size, y.size);
            assert_int_equal(x.size, z.size);
            assert_memory_equal(x.data, y.data, x.size);
            assert_memory_equal(x.data, z.data, x.size);
            assert_true(x.size > 100);
            cf_free(x.data);
            cf_free(y.data);
            cf_free(z.data);
        }
    }
    cf_figure_destroy(a);
    cf_figure_destroy(b);
}

/* cf_figure_render_mapped: the bytes of cf_figure_render and the map of
** cf_figure_page_map, from one layout, on the page as given and cropped
** to the ink (where the map moves by the crop). */
static void
test_render_mapped(void **state)
{
    cf_figure_t *fig = build_figure(false);
    cf_write_options_t o;
    int tight;
    (void)state;
    cf_write_options_init(&o);
    for (tight = 0; tight < 2; tight++) {
        double map[6], want[6];
        unsigned char *data = NULL;
        size_t size = 0;
        blob_t ref;
        o.tight = tight;
        ref = render(fig, CF_FORMAT_SVG, &o);
        assert_int_equal(cf_figure_page_map(fig, &o, want, NULL), 0);
        assert_int_equal(cf_figure_render_mapped(fig, CF_FORMAT_SVG, &o,
                                                 &data, &size, map, NULL),
                         0);
        assert_int_equal(size, ref.size);
        assert_memory_equal(data, ref.data, size);
        assert_memory_equal(map, want, sizeof map);
        /* a real map: the data box of 90 x 70 mm, y up */
        assert_true(map[0] > 1 && map[3] < -1 && map[1] == 0 && map[2] == 0);
        cf_free(data);
        cf_free(ref.data);
        /* no map asked for: cf_figure_render */
        assert_int_equal(cf_figure_render_mapped(fig, CF_FORMAT_SVG, &o,
                                                 &data, &size, NULL, NULL),
                         0);
        assert_true(size > 100);
        cf_free(data);
    }
    cf_figure_destroy(fig);
}

static void
test_no_clock_in_files(void **state)
{
    cf_figure_t *fig = build_figure(false);
    blob_t pdf, ps, eps;
    (void)state;
    unsetenv("SOURCE_DATE_EPOCH");
    pdf = render(fig, CF_FORMAT_PDF, NULL);
    ps = render(fig, CF_FORMAT_PS, NULL);
    eps = render(fig, CF_FORMAT_EPS, NULL);
    assert_false(blob_has(&ps, "%%CreationDate"));
    assert_false(blob_has(&eps, "%%CreationDate"));
    assert_true(blob_has(&pdf, "/CreationDate (20000101000000Z)"));
    cf_free(pdf.data);
    /* SOURCE_DATE_EPOCH = 1700000000 is 2023-11-14 22:13:20 UTC */
    setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
    pdf = render(fig, CF_FORMAT_PDF, NULL);
    assert_true(blob_has(&pdf, "/CreationDate (20231114221320Z)"));
    unsetenv("SOURCE_DATE_EPOCH");
    /* title and caption go into the PDF metadata */
    assert_true(blob_has(&pdf, "/Title"));
    assert_true(blob_has(&pdf, "/Subject"));
    cf_free(pdf.data);
    cf_free(ps.data);
    cf_free(eps.data);
    cf_figure_destroy(fig);
}

static void
test_svg_parses_with_librsvg(void **state)
{
    cf_figure_t *fig = build_figure(false);
    blob_t svg = render(fig, CF_FORMAT_SVG, NULL);
    GError *err = NULL;
    RsvgHandle *h;
    gboolean hw, hh, hv;
    RsvgLength w, hgt;
    RsvgRectangle vb;
    double W, H;
    (void)state;
    h = rsvg_handle_new_from_data(svg.data, svg.size, &err);
    assert_null(err);
    assert_non_null(h);
    rsvg_handle_get_intrinsic_dimensions(h, &hw, &w, &hh, &hgt, &hv, &vb);
    cf_figure_get_size(fig, &W, &H);
    /* the size is in pt and equals the page */
    assert_true(hw && hh);
    assert_int_equal(w.unit, RSVG_UNIT_PT);
    assert_true(fabs(w.length - W) <= 1 && fabs(hgt.length - H) <= 1);
    /* it draws */
    {
        cairo_surface_t *img = cairo_image_surface_create(
            CAIRO_FORMAT_ARGB32, 200, 160);
        cairo_t *cr = cairo_create(img);
        RsvgRectangle vp = { 0, 0, 200, 160 };
        int x, y, ink = 0, stride;
        const unsigned char *px;
        assert_true(rsvg_handle_render_document(h, cr, &vp, &err));
        cairo_destroy(cr);
        cairo_surface_flush(img);
        px = cairo_image_surface_get_data(img);
        stride = cairo_image_surface_get_stride(img);
        for (y = 0; y < 160; y++)
            for (x = 0; x < 200; x++) {
                const unsigned char *p = px + y * stride + 4 * x;
                if (p[3] > 0 && p[0] < 128)
                    ink++;
            }
        assert_true(ink > 200);
        cairo_surface_destroy(img);
    }
    g_object_unref(h);
    /* <title> and <desc>, escaped */
    assert_true(blob_has(&svg, "<title>de Casteljau &lt;t = 3/4&gt;</title>"));
    assert_true(blob_has(&svg, "<desc>Levels &amp; the point C(t)</desc>"));
    assert_true(blob_has(&svg, "width=\""));
    cf_free(svg.data);
    cf_figure_destroy(fig);
}

/* Pixel box of everything not fully transparent: x0 y0 x1 y1 (pixels,
** x1/y1 exclusive). */
static void
pixel_box(const blob_t *png, int box[4], int *w, int *h)
{
    cairo_surface_t *img = tu_png_decode(png->data, png->size);
    assert_int_equal(cairo_surface_status(img), CAIRO_STATUS_SUCCESS);
    *w = cairo_image_surface_get_width(img);
    *h = cairo_image_surface_get_height(img);
    tu_alpha_box(img, box);
    cairo_surface_destroy(img);
}

static void
test_page_is_ink_box(void **state)
{
    cf_figure_t *fig = build_figure(true);
    cf_write_options_t o;
    double ink[4], pw, ph, W, H;
    blob_t png, eps, pdf, svg;
    int box[4], w, h;
    char line[128];
    double x0, y0, x1, y1;
    (void)state;
    /* Independent measure of the ink: cairo's own rasterization at 4 px
    ** per pt of the untrimmed page, transparent background. */
    cf_write_options_init(&o);
    o.dpi = 288;
    png = render(fig, CF_FORMAT_PNG, &o);
    pixel_box(&png, box, &w, &h);
    assert_int_equal(cf_figure_ink_box(fig, &o, ink, &pw, &ph, NULL), 0);
    cf_figure_get_size(fig, &W, &H);
    tu_assert_close(pw, W, 1e-12, 0);
    tu_assert_close(ph, H, 1e-12, 0);
    /* the reported ink box agrees with the pixels within 1 pt */
    assert_true(fabs(ink[0] - box[0] / 4.0) <= 1);
    assert_true(fabs(ink[1] - box[1] / 4.0) <= 1);
    assert_true(fabs(ink[2] - box[2] / 4.0) <= 1);
    assert_true(fabs(ink[3] - box[3] / 4.0) <= 1);
    /* everything lies on the page */
    assert_true(ink[0] >= 0 && ink[1] >= 0 && ink[2] <= W && ink[3] <= H);
    cf_free(png.data);

    /* tight: EPS bounding box, PDF page, SVG viewBox = ink box size, the
    ** size of the tight PNG's ink (the drawing moved by the crop may
    ** place an automatic label a little differently from the untrimmed
    ** page, so its own pixels) */
    o.tight = true;
    assert_int_equal(cf_figure_ink_box(fig, &o, NULL, &pw, &ph, NULL), 0);
    png = render(fig, CF_FORMAT_PNG, &o);
    pixel_box(&png, box, &w, &h);
    cf_free(png.data);
    assert_true(fabs(pw - (box[2] - box[0]) / 4.0) <= 1);
    assert_true(fabs(ph - (box[3] - box[1]) / 4.0) <= 1);
    eps = render(fig, CF_FORMAT_EPS, &o);
    assert_true(blob_line(&eps, "%%BoundingBox: ", line, sizeof line));
    assert_int_equal(sscanf(line, "%lf %lf %lf %lf", &x0, &y0, &x1, &y1), 4);
    assert_true(fabs((x1 - x0) - pw) <= 1 && fabs((y1 - y0) - ph) <= 1);
    pdf = render(fig, CF_FORMAT_PDF, &o);
    assert_true(blob_line(&pdf, "/MediaBox [ ", line, sizeof line));
    assert_int_equal(sscanf(line, "%lf %lf %lf %lf", &x0, &y0, &x1, &y1), 4);
    assert_true(fabs((x1 - x0) - pw) <= 1 && fabs((y1 - y0) - ph) <= 1);
    svg = render(fig, CF_FORMAT_SVG, &o);
    assert_true(blob_line(&svg, "viewBox=\"", line, sizeof line));
    assert_int_equal(sscanf(line, "%lf %lf %lf %lf", &x0, &y0, &x1, &y1), 4);
    assert_true(fabs(x1 - pw) <= 1 && fabs(y1 - ph) <= 1);
    /* the tight PNG has ink at all four edges */
    o.dpi = 144;
    png = render(fig, CF_FORMAT_PNG, &o);
    pixel_box(&png, box, &w, &h);
    assert_true(box[0] <= 2 && box[1] <= 2);
    assert_true(box[2] >= w - 2 && box[3] >= h - 2);
    cf_free(png.data);
    cf_free(eps.data);
    cf_free(pdf.data);
    cf_free(svg.data);
    cf_figure_destroy(fig);
}

/* Grey levels of a label rendered alone at 300 dpi (tight). */
static blob_t
label_png(const char *text)
{
    cf_figure_t *fig = NULL;
    cf_write_options_t o;
    blob_t b;
    assert_int_equal(cf_figure_create(40, 20, CF_UNIT_MM, &fig, NULL), 0);
    assert_int_equal(cf_figure_add_label(fig, 0, 0, text, NULL), 0);
    cf_write_options_init(&o);
    o.dpi = 300;
    o.tight = true;
    b = render(fig, CF_FORMAT_PNG, &o);
    cf_figure_destroy(fig);
    return b;
}

static void
test_cjk_and_cyrillic_ink(void **state)
{
    /* 曲线 and Кривые drawn with real glyphs: ink, and not the picture
    ** of the missing-glyph box that a noncharacter (U+10FFFD) gets */
    const char *texts[] = {
        "\xe6\x9b\xb2\xe7\xba\xbf",
        "\xd0\x9a\xd1\x80\xd0\xb8\xd0\xb2\xd1\x8b\xd0\xb5",
    };
    blob_t none = label_png("\xf4\x8f\xbf\xbd\xf4\x8f\xbf\xbd");
    int k, nb[4], nw, nh;
    (void)state;
    pixel_box(&none, nb, &nw, &nh);
    for (k = 0; k < 2; k++) {
        blob_t b = label_png(texts[k]);
        int box[4], w, h;
        pixel_box(&b, box, &w, &h);
        /* a label of two or six glyphs at 10 pt: several pt wide */
        assert_true(box[2] - box[0] > 40 && box[3] - box[1] > 20);
        assert_false(b.size == none.size
                     && memcmp(b.data, none.data, b.size) == 0);
        cf_free(b.data);
    }
    cf_free(none.data);
}

static char tmpdir[64];

static int
make_tmpdir(void **state)
{
    (void)state;
    snprintf(tmpdir, sizeof tmpdir, "/tmp/cf-render-XXXXXX");
    return mkdtemp(tmpdir) == NULL ? -1 : 0;
}

/* Number of entries of tmpdir starting with prefix. */
static int
count_entries(const char *prefix)
{
    DIR *d = opendir(tmpdir);
    struct dirent *e;
    int n = 0;
    while ((e = readdir(d)) != NULL)
        if (strncmp(e->d_name, prefix, strlen(prefix)) == 0)
            n++;
    closedir(d);
    return n;
}

static blob_t
read_file(const char *path)
{
    blob_t b = { NULL, 0 };
    FILE *f = fopen(path, "rb");
    long n;
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    b.data = malloc((size_t)n + 1);
    b.size = fread(b.data, 1, (size_t)n, f);
    fclose(f);
    return b;
}

static void
test_write_all_and_magic(void **state)
{
    cf_figure_t *fig = build_figure(false);
    char base[128], path[160];
    const char *magic[] = { "<?xml", "%PDF-", "%!PS-Adobe-3.0\n",
                            "%!PS-Adobe-3.0 EPSF-3.0", "\x89PNG",
                            "% curvefig picture" };
    int f;
    cf_write_options_t tight;
    (void)state;
    snprintf(base, sizeof base, "%s/fig", tmpdir);
    /* write_all lays the page out once for all formats: each file is
    ** still what render gives for that format alone, also cropped */
    cf_write_options_init(&tight);
    tight.tight = true;
    tight.padding = 3;
    tight.dpi = 96;
    for (int pass = 0; pass < 2; pass++) {
        const cf_write_options_t *o = pass == 0 ? NULL : &tight;
        assert_int_equal(cf_figure_write_all(fig, base, 0x3f, o, NULL), 0);
        for (f = 0; f < CF_FORMAT_LAST_; f++) {
            blob_t b, m;
            snprintf(path, sizeof path, "%s.%s", base,
                     cf_format_extension((cf_format_t)f));
            b = read_file(path);
            assert_true(b.size > strlen(magic[f]));
            assert_memory_equal(b.data, magic[f], strlen(magic[f]));
            m = render(fig, (cf_format_t)f, o);
            assert_int_equal(m.size, b.size);
            assert_memory_equal(m.data, b.data, b.size);
            cf_free(m.data);
            free(b.data);
        }
    }
    assert_int_equal(count_entries(".cf-tmp-"), 0);
    cf_figure_destroy(fig);
}

/* A translucent element makes cairo's PostScript writer embed a fallback
** image; with PS and EPS both asked for, the EPS is derived from the PS
** (output.c): it must be byte for byte cairo's own EPS, which
** cf_figure_render(EPS) gives. */
static void
test_write_all_eps_from_ps(void **state)
{
    static const double square[] = { 0, 0, 4, 0, 4, 3, 0, 3 };
    static const double line[] = { -1, -1, 5, 4 };
    cf_figure_t *fig = NULL;
    cf_style_t s;
    char base[128], path[160];
    blob_t ps, eps, ref;
    (void)state;
    assert_int_equal(cf_figure_create(60, 40, CF_UNIT_MM, &fig, NULL), 0);
    cf_style_init(&s);
    s.set = CF_STYLE_OPACITY;
    s.opacity = 0.3;
    assert_int_equal(cf_figure_add_fill(fig, square, 4, &s), 0);
    assert_int_equal(cf_figure_add_polyline(fig, line, 2, false, NULL), 0);
    assert_int_equal(cf_figure_add_label(fig, 2, 1.5, "$P_0$ \xd0\x9a", NULL),
                     0);
    snprintf(base, sizeof base, "%s/eps", tmpdir);
    assert_int_equal(cf_figure_write_all(fig, base,
                                         CF_FORMAT_BIT(CF_FORMAT_PS)
                                         | CF_FORMAT_BIT(CF_FORMAT_EPS),
                                         NULL, NULL), 0);
    snprintf(path, sizeof path, "%s.ps", base);
    ps = read_file(path);
    snprintf(path, sizeof path, "%s.eps", base);
    eps = read_file(path);
    /* a fallback image is there (translucency in PostScript) */
    assert_true(blob_has(&ps, "cairo_image"));
    ref = render(fig, CF_FORMAT_EPS, NULL);
    assert_int_equal(eps.size, ref.size);
    assert_memory_equal(eps.data, ref.data, ref.size);
    assert_true(blob_has(&eps, "%!PS-Adobe-3.0 EPSF-3.0\n"));
    assert_false(blob_has(&eps, "cairo_set_page_size"));
    cf_free(ref.data);
    free(ps.data);
    free(eps.data);
    cf_figure_destroy(fig);
}

static void
test_failed_write_keeps_old_file(void **state)
{
    cf_figure_t *good = build_figure(false), *bad = build_figure(false);
    double nanpt[] = { NAN, 0 };
    char path[128], sub[128];
    blob_t before, after;
    cf_diag_t d;
    (void)state;
    snprintf(path, sizeof path, "%s/keep.svg", tmpdir);
    assert_int_equal(cf_figure_write(good, path, CF_FORMAT_SVG, NULL, NULL),
                     0);
    before = read_file(path);
    /* a figure in error writes nothing */
    assert_int_equal(cf_figure_add_points(bad, nanpt, 1, NULL),
                     CF_STATUS_NOT_FINITE);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_write(bad, path, CF_FORMAT_SVG, NULL, &d),
                     CF_STATUS_NOT_FINITE);
    assert_true(strlen(d.msg) > 0);
    after = read_file(path);
    assert_int_equal(before.size, after.size);
    assert_memory_equal(before.data, after.data, before.size);
    free(after.data);
    /* a render option out of range: nothing written either */
    {
        cf_write_options_t o;
        cf_write_options_init(&o);
        o.dpi = 0;
        assert_int_equal(cf_figure_write(good, path, CF_FORMAT_PNG, &o,
                                         NULL), CF_STATUS_INVALID_ARG);
        after = read_file(path);
        assert_memory_equal(before.data, after.data, before.size);
        free(after.data);
    }
    /* rename onto a non-empty directory fails: the directory stays and
    ** no temporary file is left behind */
    snprintf(sub, sizeof sub, "%s/dir.svg", tmpdir);
    assert_int_equal(mkdir(sub, 0755), 0);
    snprintf(path, sizeof path, "%s/dir.svg/inside", tmpdir);
    fclose(fopen(path, "w"));
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_write(good, sub, CF_FORMAT_SVG, NULL, &d),
                     CF_STATUS_IO);
    assert_non_null(strstr(d.msg, "dir.svg"));
    assert_int_equal(count_entries(".cf-tmp-"), 0);
    assert_int_equal(access(path, F_OK), 0);
    free(before.data);
    cf_figure_destroy(good);
    cf_figure_destroy(bad);
}

/* A coordinate beyond TeX's largest dimension (16383.99998 pt) — a line
** from far away, clipped to the window — is an error for PGF that names
** it; the old file stays, no temporary file is left.  The same figure
** still renders as SVG. */
static void
test_pgf_too_large(void **state)
{
    static const double line[] = { -1e5, 0, 10, 10 };
    cf_figure_t *fig = NULL, *good = build_figure(false);
    char path[128];
    blob_t before, after;
    cf_diag_t d;
    unsigned char *data = NULL;
    size_t size = 0;
    (void)state;
    snprintf(path, sizeof path, "%s/big.pgf", tmpdir);
    assert_int_equal(cf_figure_write(good, path, CF_FORMAT_PGF, NULL, NULL),
                     0);
    before = read_file(path);
    assert_int_equal(cf_figure_create(100, 100, CF_UNIT_MM, &fig, NULL), 0);
    assert_int_equal(cf_figure_set_window(fig, 0, 10, 0, 10), 0);
    assert_int_equal(cf_figure_set_clip(fig, true), 0);
    assert_int_equal(cf_figure_add_polyline(fig, line, 2, false, NULL), 0);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_write(fig, path, CF_FORMAT_PGF, NULL, &d),
                     CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(d.msg, "pgf: coordinate -"));
    assert_non_null(strstr(d.msg, "beyond what TeX can hold"));
    after = read_file(path);
    assert_int_equal(before.size, after.size);
    assert_memory_equal(before.data, after.data, before.size);
    assert_int_equal(count_entries(".cf-tmp-"), 0);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, NULL, &data, &size,
                                      NULL), 0);
    cf_free(data);
    free(before.data);
    free(after.data);
    cf_figure_destroy(fig);
    cf_figure_destroy(good);
}

static void
test_write_errors(void **state)
{
    cf_figure_t *fig = build_figure(false);
    cf_write_options_t o;
    char path[160];
    cf_format_t f;
    cf_diag_t d;
    unsigned char *data;
    size_t size;
    (void)state;
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_write(fig, "/nonexistent-cf-dir/a.svg",
                                     CF_FORMAT_SVG, NULL, &d),
                     CF_STATUS_IO);
    assert_non_null(strstr(d.msg, "nonexistent-cf-dir"));
    /* the parent is a regular file */
    snprintf(path, sizeof path, "%s/plain", tmpdir);
    fclose(fopen(path, "w"));
    snprintf(path, sizeof path, "%s/plain/a.svg", tmpdir);
    assert_int_equal(cf_figure_write(fig, path, CF_FORMAT_SVG, NULL, NULL),
                     CF_STATUS_IO);
    assert_int_equal(cf_figure_write(fig, "", CF_FORMAT_SVG, NULL, NULL),
                     CF_STATUS_IO);
    assert_int_equal(cf_figure_write(fig, NULL, CF_FORMAT_SVG, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    snprintf(path, sizeof path, "%s/a.svg", tmpdir);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_write(fig, path, (cf_format_t)17, NULL, &d),
                     CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(d.msg, "format"));
    assert_int_equal(cf_figure_write(NULL, path, CF_FORMAT_SVG, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_format_from_name("jpg", &f, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_format_from_name("eps", &f, NULL), 0);
    assert_int_equal(f, CF_FORMAT_EPS);
    assert_string_equal(cf_format_extension((cf_format_t)-1), "");
    cf_write_options_init(&o);
    o.dpi = NAN;
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_PNG, &o, &data, &size,
                                      NULL), CF_STATUS_INVALID_ARG);
    o.dpi = 2400;
    o.padding = -1;
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_PNG, &o, &data, &size,
                                      NULL), CF_STATUS_INVALID_ARG);
    o.padding = 0;
    /* 90 mm at 2400 dpi is 8504 px: allowed; a huge page is refused */
    {
        cf_figure_t *big = NULL;
        assert_int_equal(cf_figure_create(190, 190, CF_UNIT_IN, &big, NULL),
                         0);
        assert_int_equal(cf_figure_render(big, CF_FORMAT_PNG, &o, &data,
                                          &size, NULL),
                         CF_STATUS_INVALID_ARG);
        cf_figure_destroy(big);
    }
    assert_int_equal(cf_figure_write_all(fig, path, 0, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_figure_write_all(fig, path, 1u << 9, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_figure_write_all(fig, NULL, 1, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, NULL, NULL, &size,
                                      NULL), CF_STATUS_INVALID_ARG);
    /* none of this put the figure in error */
    assert_int_equal(cf_figure_status(fig, NULL), CF_STATUS_OK);
    cf_figure_destroy(fig);
}

/* ---- the PNG writer (render/output/png.c)
** ------------------------------------ */

static cairo_status_t
mem_write(void *closure, const unsigned char *data, unsigned int length)
{
    cf__buf_t *b = closure;
    return cf__buf_append(b, data, length) == 0 ? CAIRO_STATUS_SUCCESS
                                                : CAIRO_STATUS_NO_MEMORY;
}

/* cairo's reader (libpng, CRCs checked) on PNG bytes. */
static cairo_surface_t *
png_decode(const cf__buf_t *b)
{
    cairo_surface_t *s = tu_png_decode(b->data, b->size);
    assert_int_equal(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
    return s;
}

/* Same size, format and pixels (the bytes of each row). */
static void
assert_same_pixels(cairo_surface_t *a, cairo_surface_t *b)
{
    int w = cairo_image_surface_get_width(a);
    int h = cairo_image_surface_get_height(a), y;
    assert_int_equal(w, cairo_image_surface_get_width(b));
    assert_int_equal(h, cairo_image_surface_get_height(b));
    assert_int_equal(cairo_image_surface_get_format(a),
                     cairo_image_surface_get_format(b));
    for (y = 0; y < h; y++) {
        size_t ra = (size_t)y * (size_t)cairo_image_surface_get_stride(a);
        size_t rb = (size_t)y * (size_t)cairo_image_surface_get_stride(b);
        assert_memory_equal(cairo_image_surface_get_data(a) + ra,
                            cairo_image_surface_get_data(b) + rb,
                            4 * (size_t)w);
    }
}

/* Random premultiplied pixels: channels <= alpha; alpha 0, 255 and the
** values between all occur.  `opaque_share` of the pixels are opaque. */
static cairo_surface_t *
random_image(tu_rng *r, int w, int h, double opaque_share)
{
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w,
                                                    h);
    unsigned char *d = cairo_image_surface_get_data(s);
    int stride = cairo_image_surface_get_stride(s), x, y;
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            uint32_t a, p;
            double u = tu_rng_u01(r);
            a = u < opaque_share ? 255
              : u < opaque_share + 0.05 ? 0
                                        : (uint32_t)(tu_rng_next(r) % 256);
            p = a << 24;
            for (int c = 0; c < 3; c++)
                p |= (uint32_t)(tu_rng_next(r) % (a + 1)) << (8 * c);
            memcpy(d + (size_t)y * stride + 4 * (size_t)x, &p, 4);
        }
    }
    cairo_surface_mark_dirty(s);
    return s;
}

static bool
all_alpha_255(cairo_surface_t *s)
{
    int w = cairo_image_surface_get_width(s);
    int h = cairo_image_surface_get_height(s), x, y;
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            uint32_t p;
            memcpy(&p, cairo_image_surface_get_data(s)
                           + (size_t)y * cairo_image_surface_get_stride(s)
                           + 4 * (size_t)x, 4);
            if (p >> 24 != 0xff)
                return false;
        }
    }
    return true;
}

/* CRC-32 of the PNG specification (ISO 3309, reflected polynomial
** 0xedb88320), bit by bit: independent of zlib's table-driven one. */
static uint32_t
crc32_bitwise(const unsigned char *p, size_t n)
{
    uint32_t c = 0xffffffffu;
    size_t i;
    for (i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++)
            c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return c ^ 0xffffffffu;
}

static uint32_t
get_u32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8
         | p[3];
}

typedef struct png_facts {
    int colour_type;
    uint32_t ppm;      /* pHYs pixels per metre, 0 when absent */
    int idat_count;
    size_t idat_max;
} png_facts_t;

/* Walk the chunks: signature, IHDR first, IDATs contiguous, IEND last,
** every CRC right. */
static png_facts_t
png_walk(const cf__buf_t *b)
{
    static const unsigned char sig[8] = { 0x89, 'P', 'N', 'G', '\r', '\n',
                                          0x1a, '\n' };
    png_facts_t info = { -1, 0, 0, 0 };
    size_t pos = 8;
    bool ended = false, idat_done = false;
    int n = 0;
    assert_true(b->size > 8);
    assert_memory_equal(b->data, sig, 8);
    while (pos < b->size) {
        uint32_t len;
        const unsigned char *type;
        assert_false(ended);
        assert_true(b->size - pos >= 12);
        len = get_u32(b->data + pos);
        assert_true(b->size - pos - 12 >= len);
        type = b->data + pos + 4;
        assert_int_equal(crc32_bitwise(type, 4 + (size_t)len),
                         get_u32(type + 4 + len));
        if (n == 0) {
            assert_memory_equal(type, "IHDR", 4);
            assert_int_equal(len, 13);
            assert_int_equal(type[4 + 8], 8);
            info.colour_type = type[4 + 9];
        } else if (memcmp(type, "IDAT", 4) == 0) {
            assert_false(idat_done);
            info.idat_count++;
            if (len > info.idat_max)
                info.idat_max = len;
        } else {
            if (info.idat_count > 0)
                idat_done = true;
            if (memcmp(type, "pHYs", 4) == 0) {
                assert_int_equal(len, 9);
                assert_int_equal(get_u32(type + 4), get_u32(type + 8));
                assert_int_equal(type[12], 1);
                info.ppm = get_u32(type + 4);
            } else {
                assert_memory_equal(type, "IEND", 4);
                assert_int_equal(len, 0);
                ended = true;
            }
        }
        pos += 12 + (size_t)len;
        n++;
    }
    assert_true(ended);
    assert_true(info.idat_count > 0);
    return info;
}

/* Our PNG and cairo's decode to the same pixels (cairo's reader
** premultiplies again, so equal decodings mean equal un-premultiplied
** bytes in the files); seeded random images, one of them incompressible
** enough to span several IDAT chunks. */
static void
test_png_same_pixels_as_cairo(void **state)
{
    static const int sizes[][2] = { { 1, 1 }, { 37, 23 }, { 64, 1 },
                                    { 1, 50 }, { 300, 220 } };
    static const double opaque[] = { 0.0, 0.9, 0.5, 0.99, 0.3 };
    tu_rng r;
    size_t i;
    (void)state;
    tu_rng_seed(&r, 20261122);
    for (i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        cairo_surface_t *img = random_image(&r, sizes[i][0], sizes[i][1],
                                            opaque[i]);
        cairo_surface_t *ours, *theirs;
        cf__buf_t mine, ref;
        png_facts_t info;
        memset(&mine, 0, sizeof mine);
        memset(&ref, 0, sizeof ref);
        assert_int_equal(cf__png_encode(img, 150, &mine, NULL),
                         CF_STATUS_OK);
        assert_int_equal(cairo_surface_write_to_png_stream(img, mem_write,
                                                           &ref),
                         CAIRO_STATUS_SUCCESS);
        info = png_walk(&mine);
        /* RGB exactly when every pixel is opaque, as cairo decides */
        assert_int_equal(info.colour_type,
                         all_alpha_255(img) ? 2 : 6);
        assert_true(info.idat_max <= 65536);
        /* 300 x 220 RGBA of noise: > 200 KB of deflate output */
        if (sizes[i][0] == 300)
            assert_true(info.idat_count >= 3);
        /* 150 dpi = 150 / 0.0254 = 5905.5 pixels per metre, rounded */
        assert_int_equal(info.ppm, 5906);
        ours = png_decode(&mine);
        theirs = png_decode(&ref);
        assert_same_pixels(ours, theirs);
        cairo_surface_destroy(ours);
        cairo_surface_destroy(theirs);
        cairo_surface_destroy(img);
        cf__buf_free(&mine);
        cf__buf_free(&ref);
    }
}

/* Opaque ARGB32 and RGB24 are written as RGB (colour type 2), like cairo;
** one transparent pixel makes it RGBA; no pHYs without a resolution. */
static void
test_png_opaque_is_rgb(void **state)
{
    tu_rng r;
    cairo_surface_t *img, *dec, *rgb24;
    cf__buf_t b;
    png_facts_t info;
    cairo_t *cr;
    int x, y;
    (void)state;
    tu_rng_seed(&r, 7);
    img = random_image(&r, 40, 30, 1.0);
    memset(&b, 0, sizeof b);
    assert_int_equal(cf__png_encode(img, 0, &b, NULL), CF_STATUS_OK);
    info = png_walk(&b);
    assert_int_equal(info.colour_type, 2);
    assert_int_equal(info.ppm, 0);
    /* cairo reads RGB as RGB24: the same colours with alpha 255 */
    dec = png_decode(&b);
    assert_int_equal(cairo_image_surface_get_format(dec),
                     CAIRO_FORMAT_RGB24);
    for (y = 0; y < 30; y++) {
        for (x = 0; x < 40; x++) {
            uint32_t p, q;
            memcpy(&p, cairo_image_surface_get_data(img)
                           + y * cairo_image_surface_get_stride(img) + 4 * x,
                   4);
            memcpy(&q, cairo_image_surface_get_data(dec)
                           + y * cairo_image_surface_get_stride(dec) + 4 * x,
                   4);
            assert_int_equal(p & 0xffffff, q & 0xffffff);
        }
    }
    cairo_surface_destroy(dec);
    cf__buf_free(&b);

    /* RGB24: the x byte is ignored whatever it holds */
    rgb24 = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 40, 30);
    cr = cairo_create(rgb24);
    cairo_set_source_surface(cr, img, 0, 0);
    cairo_paint(cr);
    cairo_destroy(cr);
    assert_int_equal(cf__png_encode(rgb24, 72, &b, NULL), CF_STATUS_OK);
    info = png_walk(&b);
    assert_int_equal(info.colour_type, 2);
    /* 72 / 0.0254 = 2834.6 */
    assert_int_equal(info.ppm, 2835);
    cf__buf_free(&b);
    cairo_surface_destroy(rgb24);

    /* one transparent pixel: RGBA */
    memset(cairo_image_surface_get_data(img)
               + 29 * cairo_image_surface_get_stride(img) + 4 * 39,
           0, 4);
    cairo_surface_mark_dirty(img);
    assert_int_equal(cf__png_encode(img, 150, &b, NULL), CF_STATUS_OK);
    assert_int_equal(png_walk(&b).colour_type, 6);
    cf__buf_free(&b);
    cairo_surface_destroy(img);
}

/* A rendered figure: PNG from cf_figure_render is well formed, carries
** the resolution and is the same bytes twice. */
static void
test_png_figure(void **state)
{
    cf_figure_t *fig = build_figure(true);
    cf_write_options_t o;
    blob_t a, b;
    cf__buf_t view;
    png_facts_t info;
    cairo_surface_t *dec;
    (void)state;
    cf_write_options_init(&o);
    o.dpi = 96;
    a = render(fig, CF_FORMAT_PNG, &o);
    b = render(fig, CF_FORMAT_PNG, &o);
    assert_int_equal(a.size, b.size);
    assert_memory_equal(a.data, b.data, a.size);
    memset(&view, 0, sizeof view);
    view.data = a.data;
    view.size = a.size;
    info = png_walk(&view);
    assert_int_equal(info.colour_type, 6);   /* transparent background */
    /* 96 / 0.0254 = 3779.5 */
    assert_int_equal(info.ppm, 3780);
    dec = png_decode(&view);
    /* 90 mm x 70 mm at 96 dpi: 340.2 x 264.6 -> 341 x 265 pixels */
    assert_int_equal(cairo_image_surface_get_width(dec), 341);
    assert_int_equal(cairo_image_surface_get_height(dec), 265);
    cairo_surface_destroy(dec);
    cf_free(a.data);
    cf_free(b.data);
    cf_figure_destroy(fig);
    /* an opaque background covers every pixel, also the last column and
    ** row that the page (340.2 x 264.6 px) only partly covers: RGB */
    fig = build_figure(false);
    a = render(fig, CF_FORMAT_PNG, &o);
    view.data = a.data;
    view.size = a.size;
    assert_int_equal(png_walk(&view).colour_type, 2);
    dec = png_decode(&view);
    assert_int_equal(cairo_image_surface_get_width(dec), 341);
    {
        /* the last pixel: white background (the axes end well inside) */
        uint32_t p;
        memcpy(&p, cairo_image_surface_get_data(dec)
                       + 264 * cairo_image_surface_get_stride(dec) + 4 * 340,
               4);
        assert_int_equal(p & 0xffffff, 0xffffff);
    }
    cairo_surface_destroy(dec);
    cf_free(a.data);
    cf_figure_destroy(fig);
}

static void
test_png_errors(void **state)
{
    cairo_surface_t *a8 = cairo_image_surface_create(CAIRO_FORMAT_A8, 4, 4);
    cairo_surface_t *rec = cairo_recording_surface_create(
        CAIRO_CONTENT_COLOR_ALPHA, NULL);
    cairo_surface_t *img = cairo_image_surface_create(CAIRO_FORMAT_ARGB32,
                                                      16, 16);
    cairo_surface_t *bad = cairo_image_surface_create(CAIRO_FORMAT_ARGB32,
                                                      -1, 5);
    cf__buf_t b;
    cf_diag_t d;
    long k, live;
    (void)state;
    memset(&b, 0, sizeof b);
    cf_diag_clear(&d);
    assert_int_equal(cf__png_encode(NULL, 72, &b, &d),
                     CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(d.msg, "NULL"));
    assert_int_equal(cf__png_encode(img, 72, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    cf_diag_clear(&d);
    assert_int_equal(cf__png_encode(a8, 72, &b, &d), CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(d.msg, "format"));
    assert_int_equal(cf__png_encode(rec, 72, &b, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf__png_encode(bad, 72, &b, NULL),
                     CF_STATUS_INVALID_ARG);
    cf_diag_clear(&d);
    assert_int_equal(cf__png_encode(img, NAN, &b, &d),
                     CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(d.msg, "dpi"));
    assert_int_equal(cf__png_encode(img, INFINITY, &b, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(b.size, 0);
    /* every allocation failing in turn: NO_MEMORY, nothing leaked */
    for (k = 1;; k++) {
        cf_status_t st;
        tu_fail_alloc_after(k);
        live = tu_alloc_live();
        st = cf__png_encode(img, 72, &b, NULL);
        cf__buf_free(&b);
        assert_int_equal(tu_alloc_live(), live);
        tu_fail_alloc_reset();
        if (st == CF_STATUS_OK)
            break;
        assert_int_equal(st, CF_STATUS_NO_MEMORY);
        assert_true(k < 100);
    }
    assert_true(k > 3);
    cairo_surface_destroy(a8);
    cairo_surface_destroy(rec);
    cairo_surface_destroy(img);
    cairo_surface_destroy(bad);
}

/* ---- the tool's font configuration (render/tool/fonts.c) ---------------- */

static const char *tool_path;   /* argv[1]: the built curvefig, or NULL */

/* Run the tool with args (NULL-terminated, without argv[0]); with
** system_fonts, FONTCONFIG_FILE names the system configuration.  stdout
** goes to out (may be NULL).  The exit status. */
static int
run_tool(const char *const *args, bool system_fonts, char *out, size_t cap)
{
    static const char *const system_env[] = {
        "FONTCONFIG_FILE=/etc/fonts/fonts.conf", "FONTCONFIG_PATH", NULL
    };
    static const char *const own_env[] = {
        "FONTCONFIG_FILE", "FONTCONFIG_PATH", NULL
    };
    const char *argv[16];
    char sink[1];
    tu_spawn_t sp;
    int status;
    size_t n = 0;
    argv[n++] = tool_path;
    while (args[n - 1] != NULL && n < 15) {
        argv[n] = args[n - 1];
        n++;
    }
    argv[n] = NULL;
    memset(&sp, 0, sizeof sp);
    sp.argv = argv;
    sp.env = system_fonts ? system_env : own_env;
    sp.capture = out != NULL ? out : sink;
    sp.capture_cap = out != NULL ? cap : sizeof sink;
    status = tu_spawn(&sp);
    assert_true(status >= 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static void
write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    assert_int_equal(fputs(text, f) >= 0, 1);
    assert_int_equal(fclose(f), 0);
}

/* The tool's own configuration is in use here (Debian with fonts-lmodern,
** fonts-cmu and fonts-noto-cjk); NULL-safe skip otherwise. */
static bool
tool_uses_own_fonts(void)
{
    const char *v[] = { "--version", NULL };
    char out[512];
    if (tool_path == NULL)
        return false;
    assert_int_equal(run_tool(v, false, out, sizeof out), 0);
    return strstr(out, "curvefig's configuration") != NULL;
}

/* Every label of a figure drawn from Latin Modern (optical sizes 5 to 17,
** upright, italic, bold), CMU Serif (Cyrillic, Greek upright) and Noto
** Serif CJK (regular, bold, and sheared in an italic run): the five files
** are byte for byte those of the system's fontconfig configuration. */
static void
test_tool_fonts_same_as_system(void **state)
{
    static const char script[] =
        "local f = figure{ name = \"fonts\", width = \"12cm\","
        " height = \"9cm\" }\n"
        "f:polyline({ {0, 0}, {10, 0}, {10, 9}, {0, 9} })\n"
        "local labels = {\n"
        "  \"$P_0 + Q^2_{k-1} \\\\omega_i \\\\times \\\\pm \\\\mp$\",\n"
        "  \"$a \\\\leq b \\\\geq c \\\\neq d \\\\approx e \\\\equiv f"
        " \\\\to g$\",\n"
        "  \"$x \\\\in A \\\\subset B, \\\\infty, \\\\partial, \\\\nabla,"
        " \\\\ldots, \\\\cdots$\",\n"
        "  \"$\\\\sum \\\\prod \\\\int f', \\\\ell, 30\\\\deg,"
        " \\\\|v\\\\|$\",\n"
        "  \"$\\\\hat{x} \\\\bar{y} \\\\tilde{z} \\\\vec{v} \\\\dot{a}"
        " \\\\ddot{b} \\\\frac{1}{2}$\",\n"
        "  \"$\\\\mathbf{B}_i \\\\mathit{it} \\\\mathrm{rm} \\\\text{text}"
        " \\\\operatorname{sin}$\",\n"
        "  \"K\\xc5\\x99ivka \\xd0\\x9a\\xd1\\x80\\xd0\\xb8\\xd0\\xb2"
        "\\xd0\\xb0"
        "\\xd1\\x8f \\xe6\\x9b\\xb2\\xe7\\xba\\xbf \\xce\\xba\\xce\\xbb\",\n"
        "  \"$\\\\mathbf{\\xd0\\x9a\\xd1\\x80\\xd0\\xb8\\xd0\\xb2\\xd0\\xb0"
        "\\xd1\\x8f} \\\\mathit{\\xd0\\x9a\\xd1\\x80\\xd0\\xb8\\xd0\\xb2"
        "\\xd0\\xb0"
        "\\xd1\\x8f}$\",\n"
        "  \"$\\\\mathbf{\\xe6\\x9b\\xb2\\xe7\\xba\\xbf}"
        " \\\\mathit{\\xe6\\x9b\\xb2\\xe7\\xba\\xbf} \\xe6\\x9b\\xb2$\",\n"
        "}\n"
        "for i, s in ipairs(labels) do\n"
        "  f:label({ 0.2, 9.2 - i }, s, { place = \"e\" })\n"
        "end\n"
        "f:label({ 5, 0.3 }, \"$\\\\alpha\\\\beta x_1$\","
        " { place = \"n\", font_size = 5 })\n"
        "f:label({ 8, 0.3 }, \"Ab $x^{y^{z}}_{k}$\","
        " { place = \"n\", font_size = 20 })\n";
    static const char *const ext[] = { "svg", "pdf", "png", "ps", "eps" };
    char path[256], dir_own[96], dir_sys[96];
    blob_t pdf;
    (void)state;
    if (!tool_uses_own_fonts())
        skip();
    snprintf(path, sizeof path, "%s/fonts.lua", tmpdir);
    write_text(path, script);
    snprintf(dir_own, sizeof dir_own, "%s/own", tmpdir);
    snprintf(dir_sys, sizeof dir_sys, "%s/sys", tmpdir);
    {
        const char *a[] = { "render", path, "-o", dir_own, "-f", "all",
                            NULL };
        const char *b[] = { "render", path, "-o", dir_sys, "-f", "all",
                            NULL };
        assert_int_equal(run_tool(a, false, NULL, 0), 0);
        assert_int_equal(run_tool(b, true, NULL, 0), 0);
    }
    for (size_t i = 0; i < sizeof ext / sizeof ext[0]; i++) {
        blob_t x, y;
        snprintf(path, sizeof path, "%s/fonts.%s", dir_own, ext[i]);
        x = read_file(path);
        snprintf(path, sizeof path, "%s/fonts.%s", dir_sys, ext[i]);
        y = read_file(path);
        assert_int_equal(x.size, y.size);
        assert_memory_equal(x.data, y.data, x.size);
        free(x.data);
        free(y.data);
    }
    /* and the fonts are the intended ones: Latin Modern's optical sizes,
    ** its math font (the letters of mathematics), CMU, Noto CJK regular
    ** and bold */
    snprintf(path, sizeof path, "%s/fonts.pdf", dir_own);
    pdf = read_file(path);
    assert_true(blob_has(&pdf, "LMRoman10-Regular"));
    assert_true(blob_has(&pdf, "LMRoman10-Bold"));
    assert_true(blob_has(&pdf, "LatinModernMath-Regular"));
    assert_true(blob_has(&pdf, "LMRoman5-Regular"));
    assert_true(blob_has(&pdf, "LMRoman17-Regular"));
    assert_true(blob_has(&pdf, "CMUSerif-Roman"));
    assert_true(blob_has(&pdf, "NotoSerifCJKsc-Regular"));
    assert_true(blob_has(&pdf, "NotoSerifCJKsc-Bold"));
    free(pdf.data);
}

/* Math symbols none of the three families has (cdot, circ, mapsto,
** angle brackets) come from Latin Modern Math, never a missing glyph;
** with FONTCONFIG_FILE set the system's configuration is reported. */
static void
test_tool_fonts_fallback_and_choice(void **state)
{
    static const char script[] =
        "local f = figure{ name = \"sym\", width = \"4cm\","
        " height = \"2cm\" }\n"
        "f:polyline({ {0, 0}, {4, 2} })\n"
        "f:label({ 2, 1 }, \"$a \\\\cdot b \\\\circ c \\\\mapsto"
        " \\\\langle u \\\\rangle$\")\n";
    const char *v[] = { "--version", NULL };
    char path[256], dir[96], out[512];
    blob_t pdf;
    (void)state;
    if (!tool_uses_own_fonts())
        skip();
    snprintf(path, sizeof path, "%s/sym.lua", tmpdir);
    write_text(path, script);
    snprintf(dir, sizeof dir, "%s/sym", tmpdir);
    {
        const char *a[] = { "render", path, "-o", dir, "-f", "pdf", NULL };
        assert_int_equal(run_tool(a, false, NULL, 0), 0);
    }
    snprintf(path, sizeof path, "%s/sym.pdf", dir);
    pdf = read_file(path);
    assert_true(blob_has(&pdf, "LatinModernMath-Regular"));
    free(pdf.data);
    assert_int_equal(run_tool(v, true, out, sizeof out), 0);
    assert_non_null(strstr(out, "fonts: the system's fontconfig"));
}

static int
remove_tmpdir(void **state)
{
    char cmd[128];
    (void)state;
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    return system(cmd) == 0 ? 0 : -1;
}

/* argv[1], when given, is the built curvefig for the tool's tests. */
int
main(int argc, char **argv)
{
    tool_path = argc > 1 ? argv[1] : NULL;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_byte_identical),
        cmocka_unit_test(test_render_mapped),
        cmocka_unit_test(test_no_clock_in_files),
        cmocka_unit_test(test_svg_parses_with_librsvg),
        cmocka_unit_test(test_page_is_ink_box),
        cmocka_unit_test(test_cjk_and_cyrillic_ink),
        cmocka_unit_test(test_write_all_and_magic),
        cmocka_unit_test(test_write_all_eps_from_ps),
        cmocka_unit_test(test_failed_write_keeps_old_file),
        cmocka_unit_test(test_pgf_too_large),
        cmocka_unit_test(test_write_errors),
        cmocka_unit_test(test_png_same_pixels_as_cairo),
        cmocka_unit_test(test_png_opaque_is_rgb),
        cmocka_unit_test(test_png_figure),
        cmocka_unit_test(test_png_errors),
        cmocka_unit_test(test_tool_fonts_same_as_system),
        cmocka_unit_test(test_tool_fonts_fallback_and_choice),
    };
    return cmocka_run_group_tests(tests, make_tmpdir, remove_tmpdir);
}
