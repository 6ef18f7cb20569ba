/* Output: the PNG writer (render/output/png.c) against cairo's own, opaque
** and translucent pages, a figure's PNG, its errors; and the tool's font
** configuration (the shared helpers in test_output.h). */
#include "test_output.h"

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

/* argv[1], when given, is the built curvefig for the tool's tests. */
int
main(int argc, char **argv)
{
    tool_path = argc > 1 ? argv[1] : NULL;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_png_same_pixels_as_cairo),
        cmocka_unit_test(test_png_opaque_is_rgb),
        cmocka_unit_test(test_png_figure),
        cmocka_unit_test(test_png_errors),
        cmocka_unit_test(test_tool_fonts_same_as_system),
        cmocka_unit_test(test_tool_fonts_fallback_and_choice),
    };
    return cmocka_run_group_tests(tests, make_tmpdir, remove_tmpdir);
}
