/*
** The PDF writer's own paths (render/backends/backend-pdfw.c, pdf-doc.c,
** pdf-fonts.c), its backend functions called directly:
**   - a face the subsetter refuses (here a font file that is not there)
**     makes the document answer 1, and after cf__pdfw_restart the same
**     page is its label's outlines, with no font; a face that is there
**     (Latin Modern Math, when fontconfig has it) is embedded;
**   - opacities: one ExtGState pair per distinct value, the page a
**     transparency group only when it is translucent;
**   - faults: a number beyond 1e9 bp names its element, groups nested
**     too deep, both as the SVG writer words them;
**   - the document of a page is the same bytes twice;
**   - strings: a literal string's escapes, and text strings as UTF-16BE
**     hex against the code points written out by hand (surrogate pairs,
**     bytes that start no UTF-8 sequence, text longer than the writer's
**     chunk).
*/
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "backend.h"
#include "pdf-strings.h"

static bool
has(const cf__buf_t *b, const char *s)
{
    size_t n = strlen(s);
    for (size_t i = 0; i + n <= b->size; i++)
        if (memcmp(b->data + i, s, n) == 0)
            return true;
    return false;
}

/* a label's outlines: a square */
static int
outline(void *ctx, const cf__text_op_t *t, cf__buf_t *d)
{
    static const char sq[] = "M10 10L20 10L20 20L10 20Z";
    (void)ctx;
    (void)t;
    return cf__buf_append(d, sq, sizeof sq - 1);
}

/* a label's glyphs: glyph 5 of the font file named by ctx, and a rule */
static int
glyphs(void *ctx, const cf__text_op_t *t, cf__buf_t *g, cf__buf_t *rules)
{
    cf__pdfw_glyph_t gl;
    const double rule[4] = { 10, 30, 8, 0.5 };
    (void)t;
    memset(&gl, 0, sizeof gl);
    gl.file = ctx;
    gl.m[0] = 10;
    gl.m[3] = 10;
    gl.gid = 5;
    gl.x = 12;
    gl.y = 20;
    gl.text = "x";
    gl.len = 1;
    return cf__buf_append(g, &gl, sizeof gl)
           || cf__buf_append(rules, rule, sizeof rule);
}

static void
page_of_label(cf__pdfw_t *w)
{
    cf__page_t pg;
    cf__text_op_t t;
    memset(&pg, 0, sizeof pg);
    pg.width = 100;
    pg.height = 50;
    memset(&t, 0, sizeof t);
    t.color = (cf_color_t){ 0, 0, 0, 1 };
    t.opacity = 1;
    cf__pdfw_backend.begin_page(w, &pg);
    cf__pdfw_backend.draw_text(w, &t);
    assert_int_equal(cf__pdfw_backend.end_page(w), 0);
}

static void
test_refused_face(void **state)
{
    cf__pdfw_t w;
    cf__buf_t out;
    (void)state;
    memset(&w, 0, sizeof w);
    memset(&out, 0, sizeof out);
    w.outline = outline;
    w.glyphs = glyphs;
    w.outline_ctx = (void *)"/nonexistent/font.otf";
    page_of_label(&w);
    assert_int_equal(cf__pdfw_document(&w, "t", NULL, "2000-01-01T00:00:00Z",
                                       &out), 1);
    assert_int_equal(out.size, 0);
    cf__pdfw_restart(&w);
    page_of_label(&w);
    assert_int_equal(cf__pdfw_document(&w, "t", NULL, "2000-01-01T00:00:00Z",
                                       &out), 0);
    assert_false(has(&out, "/FontFile"));
    assert_false(has(&out, "/F0 "));
    cf__buf_free(&out);
    cf__pdfw_fini(&w);
}

static void
test_embedded_face(void **state)
{
    char file[512];
    FILE *p = popen("fc-match -f '%{file}' 'Latin Modern Math'", "r");
    size_t n = p != NULL ? fread(file, 1, sizeof file - 1, p) : 0;
    cf__pdfw_t w;
    cf__buf_t out;
    (void)state;
    if (p != NULL)
        pclose(p);
    file[n] = '\0';
    if (strstr(file, "latinmodern-math") == NULL)
        skip();
    memset(&w, 0, sizeof w);
    memset(&out, 0, sizeof out);
    w.outline = outline;
    w.glyphs = glyphs;
    w.outline_ctx = file;
    page_of_label(&w);
    assert_int_equal(cf__pdfw_document(&w, "t", NULL, "2000-01-01T00:00:00Z",
                                       &out), 0);
    assert_true(has(&out, "/FontFile3"));
    assert_true(has(&out, "/Subtype /Type0"));
    assert_true(has(&out, "/Encoding /Identity-H"));
    assert_true(has(&out, "/ToUnicode"));
    assert_true(has(&out, "/W [ 5 [ "));
    assert_true(has(&out, "/Font << /F0 "));
    cf__buf_free(&out);
    cf__pdfw_fini(&w);
}

static void
test_opacity_and_bytes(void **state)
{
    cf__pdfw_t w;
    cf__buf_t a, b;
    cf__page_t pg;
    cf__paint_t paint;
    const unsigned char segs[] = { CF__SEG_RECT };
    const double coords[] = { 1, 2, 3, 4 };
    cf__path_t path = { segs, coords, 1 };
    (void)state;
    memset(&pg, 0, sizeof pg);
    pg.width = 100;
    pg.height = 50;
    memset(&paint, 0, sizeof paint);
    paint.fill = true;
    paint.fill_color = (cf_color_t){ 1, 0, 0, 1 };
    for (int k = 0; k < 2; k++) {
        memset(&w, 0, sizeof w);
        w.outline = outline;
        cf__pdfw_backend.begin_page(&w, &pg);
        paint.fill_opacity = 0.5;
        cf__pdfw_backend.draw_path(&w, &path, &paint);
        cf__pdfw_backend.draw_path(&w, &path, &paint);
        paint.fill_opacity = 0.25;
        cf__pdfw_backend.draw_path(&w, &path, &paint);
        paint.fill_opacity = 0.5;
        cf__pdfw_backend.draw_path(&w, &path, &paint);
        assert_int_equal(cf__pdfw_backend.end_page(&w), 0);
        /* an opaque second page */
        paint.fill_opacity = 1;
        cf__pdfw_backend.begin_page(&w, &pg);
        cf__pdfw_backend.draw_path(&w, &path, &paint);
        assert_int_equal(cf__pdfw_backend.end_page(&w), 0);
        assert_int_equal(w.nalphas, 2);
        memset(k == 0 ? &a : &b, 0, sizeof a);
        assert_int_equal(cf__pdfw_document(&w, NULL, NULL,
                                           "2000-01-01T00:00:00Z",
                                           k == 0 ? &a : &b), 0);
        cf__pdfw_fini(&w);
    }
    assert_true(has(&a, "/a0 << /ca 0.5 >> /A0 << /CA 0.5 >> "
                        "/a1 << /ca 0.25 >>"));
    assert_false(has(&a, "/a2"));
    /* the first page a group, the second not */
    {
        const char *g = "/Group << /Type /Group /S /Transparency";
        size_t n = strlen(g), count = 0;
        for (size_t i = 0; i + n <= a.size; i++)
            count += memcmp(a.data + i, g, n) == 0;
        assert_int_equal(count, 1);
    }
    assert_int_equal(a.size, b.size);
    assert_memory_equal(a.data, b.data, a.size);
    cf__buf_free(&a);
    cf__buf_free(&b);
}

static void
test_faults(void **state)
{
    cf__pdfw_t w;
    cf__page_t pg;
    cf__paint_t paint;
    cf_diag_t d;
    const unsigned char segs[] = { CF__SEG_MOVE, CF__SEG_LINE };
    const double coords[] = { 0, 0, 2e9, 1 };
    cf__path_t path = { segs, coords, 2 };
    (void)state;
    memset(&pg, 0, sizeof pg);
    pg.width = 100;
    pg.height = 50;
    memset(&paint, 0, sizeof paint);
    paint.stroke = true;
    paint.line.width = 1;
    paint.line.opacity = 1;
    paint.line.color.a = 1;
    memset(&w, 0, sizeof w);
    w.outline = outline;
    cf__pdfw_backend.begin_page(&w, &pg);
    cf__pdfw_backend.begin_group(&w, "arrow", 1, NULL);
    /* far beyond the page, but cut to it first: no fault */
    cf__pdfw_backend.draw_path(&w, &path, &paint);
    cf__pdfw_backend.end_group(&w);
    assert_int_equal(cf__pdfw_backend.end_page(&w), 0);
    cf__pdfw_fini(&w);
    /* a mesh corner beyond 1e9 is a fault of its element */
    memset(&w, 0, sizeof w);
    w.outline = outline;
    cf__pdfw_backend.begin_page(&w, &pg);
    cf__pdfw_backend.begin_group(&w, "surface", 2, NULL);
    {
        cf__mesh_tri_t t;
        memset(&t, 0, sizeof t);
        t.p[2] = 3e9;
        t.p[5] = 1;
        cf__pdfw_backend.draw_mesh(&w, &t, 1);
    }
    cf__pdfw_backend.end_group(&w);
    assert_int_not_equal(cf__pdfw_backend.end_page(&w), 0);
    cf_diag_clear(&d);
    assert_int_equal(cf__pdfw_fault(&w, &d), CF_STATUS_INVALID_ARG);
    assert_string_equal(d.msg, "pdf: a coordinate of surface 3 is 3e+09, "
                               "too far from the page; PDF holds numbers "
                               "within 1e9 bp");
    cf__pdfw_fini(&w);
    /* groups too deep */
    memset(&w, 0, sizeof w);
    w.outline = outline;
    cf__pdfw_backend.begin_page(&w, &pg);
    for (int i = 0; i < CF__PDFW_DEPTH + 2; i++)
        cf__pdfw_backend.begin_group(&w, "g", (size_t)i, NULL);
    assert_int_not_equal(cf__pdfw_backend.end_page(&w), 0);
    cf_diag_clear(&d);
    assert_int_equal(cf__pdfw_fault(&w, &d), CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(d.msg, "groups nested deeper than"));
    cf__pdfw_fini(&w);
}

/* The buffer's bytes as a C string (freed by the caller). */
static char *
as_string(cf__buf_t *b)
{
    char *s = malloc(b->size + 1);
    assert_non_null(s);
    memcpy(s, b->data, b->size);
    s[b->size] = '\0';
    cf__buf_free(b);
    return s;
}

static void
test_strings(void **state)
{
    cf__buf_t b = { 0 };
    char *s, want[1024];
    (void)state;
    assert_int_equal(cf__pdf_put_string(&b, "a(b)c\\d\n\x7f\xc3\xa9~ "), 0);
    s = as_string(&b);
    assert_string_equal(s, "(a\\(b\\)c\\\\d\\012\\177\\303\\251~ )");
    free(s);
    /* A, e-acute (2 bytes), the euro sign (3), U+1D44E math italic a (4:
    ** the pair D835 DC4E), a lone continuation byte and a truncated
    ** sequence (each U+FFFD) */
    assert_int_equal(cf__pdf_put_text(&b, "A\xc3\xa9\xe2\x82\xac"
                                          "\xf0\x9d\x91\x8e\x80",
                                      "\xe2\x82"), 0);
    s = as_string(&b);
    assert_string_equal(s, "<FEFF004100E920ACD835DC4EFFFD0020FFFDFFFD>");
    free(s);
    /* longer than the chunk the writer fills: 150 code points, each of
    ** them astral every third one */
    {
        char in[1024];
        size_t n = 0, w = 0;
        for (int i = 0; i < 150; i++) {
            if (i % 3 == 2) {
                unsigned c = 0x1F600u + (unsigned)i, v = c - 0x10000u;
                in[n++] = (char)(0xf0 | (c >> 18));
                in[n++] = (char)(0x80 | ((c >> 12) & 0x3f));
                in[n++] = (char)(0x80 | ((c >> 6) & 0x3f));
                in[n++] = (char)(0x80 | (c & 0x3f));
                w += (size_t)snprintf(want + w, sizeof want - w, "%04X%04X",
                                      0xd800u + (v >> 10),
                                      0xdc00u + (v & 0x3ffu));
            } else {
                in[n++] = (char)('a' + i % 26);
                w += (size_t)snprintf(want + w, sizeof want - w, "%04X",
                                      (unsigned)('a' + i % 26));
            }
        }
        assert_int_equal(cf__pdf_put_utf16(&b, in, n), 0);
        s = as_string(&b);
        assert_string_equal(s, want);
        free(s);
    }
}

/* The buffer's edge the fuzzer found (fuzz_fontfile, a TrueType subset
** appending an empty glyph first): nothing appended to an empty buffer
** is a success, not a failure, and no null pointer arithmetic (UBSan). */
static void
test_buffer_empty(void **state)
{
    cf__buf_t b = { 0 };
    (void)state;
    assert_int_equal(cf__buf_append(&b, "", 0), 0);
    assert_int_equal(b.failed, 0);
    assert_int_equal(b.size, 0);
    assert_non_null(cf__buf_extend(&b, 0));
    assert_int_equal(cf__buf_append(&b, "ab", 2), 0);
    assert_int_equal(cf__buf_append(&b, "", 0), 0);
    assert_int_equal(b.size, 2);
    assert_memory_equal(b.data, "ab", 2);
    cf__buf_free(&b);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_refused_face),
        cmocka_unit_test(test_embedded_face),
        cmocka_unit_test(test_opacity_and_bytes),
        cmocka_unit_test(test_faults),
        cmocka_unit_test(test_strings),
        cmocka_unit_test(test_buffer_empty),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
