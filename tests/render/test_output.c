/* Output: five formats, byte-identical renders, page = ink box, SVG
** metadata read back with librsvg, atomic writes, bad arguments.  The PNG
** writer and the tool's fonts are in test_output_png.c, the shared helpers
** in test_output.h. */
#include "test_output.h"

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
    assert_true(blob_has(&pdf, "/CreationDate (D:20000101000000Z)"));
    cf_free(pdf.data);
    /* SOURCE_DATE_EPOCH = 1700000000 is 2023-11-14 22:13:20 UTC */
    setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
    assert_int_equal(cf_figure_set_description(fig, "auto"), CF_STATUS_OK);
    pdf = render(fig, CF_FORMAT_PDF, NULL);
    assert_true(blob_has(&pdf, "/CreationDate (D:20231114221320Z)"));
    assert_true(blob_has(&pdf, "/ModDate (D:20231114221320Z)"));
    unsetenv("SOURCE_DATE_EPOCH");
    /* the alt text and the description go into the PDF metadata */
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
    /* the alt text (here the caption) in <title>, escaped, the figure
    ** labelled by it (docs/accessibility.md) */
    assert_true(blob_has(&svg, "\">Levels &amp; the point C(t)</title>"));
    assert_true(blob_has(&svg, " role=\"img\" aria-labelledby=\"cf-t"));
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
    };
    return cmocka_run_group_tests(tests, make_tmpdir, remove_tmpdir);
}
