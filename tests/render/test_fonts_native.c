/* The native fonts (render/backends/font-native.c: HarfBuzz in the faces
** pango would choose) against pango itself (render/backends/font-pango.c):
** every run the labels of figures/ and examples/ shape (fonts-corpus.txt,
** the requests of a render of each), the characters and pairs a course
** page's glyph data shapes, torture texts and whole labels give the same
** shaping (baseline, logical and ink rectangles, unknown glyphs) and the
** same glyphs (spans, their text, faces, glyph ids, offsets, advances and
** clusters); drawn into a PDF, the two give the same bytes.  A run the
** native fonts hand to pango must be one their rule names. */
#include <locale.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cairo-ft.h>
#include <cairo-pdf.h>
#include <cairo-ps.h>
#include <cmocka.h>

#include "curvefig/label.h"
#include "font-faces.h"
#include "font-glyphs.h"
#include "font-itemize.h"
#include "font-native.h"
#include "font-pango.h"
#include "label-impl.h"
#include "label-private.h"
#include "testutil.h"

static const char *corpus_path;

#define SERIF "Latin Modern Roman,CMU Serif,Noto Serif CJK SC"
#define SUB "LM Roman 7," SERIF
#define MATH "Latin Modern Math," SERIF
#define SANS "Latin Modern Sans,CMU Sans Serif,Noto Sans CJK SC"

typedef struct pair {
    void *pctx, *nctx;
    void *prun, *nrun;
    int native, handed;   /* runs shaped natively, handed to pango */
} pair_t;

static void
open_pair(pair_t *p)
{
    memset(p, 0, sizeof *p);
    p->pctx = cf__pango_fonts.open(cf__pango_fonts.self);
    p->nctx = cf__native_fonts.open(cf__native_fonts.self);
    assert_non_null(p->pctx);
    assert_non_null(p->nctx);
}

static void
close_pair(pair_t *p)
{
    cf__pango_fonts.release(p->prun);
    cf__native_fonts.release(p->nrun);
    cf__pango_fonts.close(p->pctx);
    cf__native_fonts.close(p->nctx);
}

/* The bytes of a PDF of g drawn from (3.3, 17.7) (a stable date). */
static void
pdf_write(void *u, const unsigned char *data, unsigned n);

typedef struct bytes {
    unsigned char *data;
    size_t n;
} bytes_t;

static cairo_status_t
pdf_sink(void *u, const unsigned char *data, unsigned n)
{
    pdf_write(u, data, n);
    return CAIRO_STATUS_SUCCESS;
}

static void
pdf_write(void *u, const unsigned char *data, unsigned n)
{
    bytes_t *b = u;
    b->data = realloc(b->data, b->n + n);
    assert_non_null(b->data);
    memcpy(b->data + b->n, data, n);
    b->n += n;
}

static bytes_t
drawn(const cf__fonts_t *fonts, void *run, bool path)
{
    bytes_t b = { NULL, 0 };
    cairo_surface_t *s =
        cairo_pdf_surface_create_for_stream(pdf_sink, &b, 200, 100);
    cairo_t *cr = cairo_create(s);
    cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_CREATE_DATE,
                                   "2020-01-01T00:00:00Z");
    cairo_move_to(cr, 3.3, 17.7);
    if (fonts == &cf__pango_fonts)
        fonts->draw(run, cr, path);
    else
        cf__font_glyphs_draw(cr, fonts->glyphs(run), path);
    if (path)
        cairo_fill(cr);
    cairo_destroy(cr);
    cairo_surface_finish(s);
    cairo_surface_destroy(s);
    return b;
}

/* A span's face on stderr, when two differ. */
static void
describe_span(const char *who, const cf__font_span_t *s)
{
    cairo_scaled_font_t *sf = cf__font_face_scaled(s->face);
    cairo_font_extents_t e;
    cairo_matrix_t m;
    FT_Face face = cairo_ft_scaled_font_lock_face(sf);
    cairo_scaled_font_extents(sf, &e);
    cairo_scaled_font_get_font_matrix(sf, &m);
    fprintf(stderr, "%s span: %s: %s %s, matrix %g %g %g %g, ascent %g\n",
            who, s->face->key, face != NULL ? face->family_name : "?",
            face != NULL ? face->style_name : "?", m.xx, m.yx, m.xy, m.yy,
            e.ascent);
    cairo_ft_scaled_font_unlock_face(sf);
}

static void
same_glyphs(const cf__font_glyphs_t *a, const cf__font_glyphs_t *b,
            const char *what)
{
    size_t i;
    if (a->nspans != b->nspans || a->nglyphs != b->nglyphs
        || a->baseline != b->baseline) {
        for (i = 0; i < a->nspans; i++)
            describe_span("pango", &a->spans[i]);
        for (i = 0; i < b->nspans; i++)
            describe_span("native", &b->spans[i]);
        fail_msg("%s: %zu/%zu spans, %zu/%zu glyphs, baseline %d/%d", what,
                 a->nspans, b->nspans, a->nglyphs, b->nglyphs, a->baseline,
                 b->baseline);
    }
    for (i = 0; i < a->nspans; i++) {
        const cf__font_span_t *s = &a->spans[i], *t = &b->spans[i];
        cairo_font_face_t *fa =
            cairo_scaled_font_get_font_face(cf__font_face_scaled(s->face));
        cairo_font_face_t *fb =
            cairo_scaled_font_get_font_face(cf__font_face_scaled(t->face));
        cairo_matrix_t ma, mb;
        cairo_scaled_font_get_font_matrix(cf__font_face_scaled(s->face), &ma);
        cairo_scaled_font_get_font_matrix(cf__font_face_scaled(t->face), &mb);
        if (s->byte != t->byte || s->nbytes != t->nbytes || s->x != t->x
            || s->glyph != t->glyph || s->nglyphs != t->nglyphs
            || s->backward != t->backward || fa != fb
            || memcmp(&ma, &mb, sizeof ma) != 0)
            fail_msg("%s: span %zu differs (bytes %zu+%zu / %zu+%zu, x %d/%d,"
                     " face %s)", what, i, s->byte, s->nbytes, t->byte,
                     t->nbytes, s->x, t->x, fa == fb ? "same" : "other");
    }
    for (i = 0; i < a->nglyphs; i++) {
        const cf__font_glyph_t *g = &a->glyphs[i], *h = &b->glyphs[i];
        if (g->id != h->id || g->x != h->x || g->y != h->y
            || g->width != h->width || g->cluster != h->cluster)
            fail_msg("%s: glyph %zu: %u %d %d %d %u / %u %d %d %d %u", what, i,
                     g->id, g->x, g->y, g->width, g->cluster, h->id, h->x,
                     h->y, h->width, h->cluster);
    }
}

/* Shape req both ways: the same shaping, the same glyphs (when the
** native fonts shaped it), the same PDF bytes for a few.  Returns
** whether the native fonts shaped it themselves. */
static bool
compare(pair_t *p, const cf__font_req_t *req, bool draw)
{
    cf__font_shape_t a, b;
    char what[512];
    bool native;
    snprintf(what, sizeof what, "\"%.*s\" in %s%s%s at %g", (int)req->len,
             req->text, req->family, req->italic ? " italic" : "",
             req->bold ? " bold" : "", req->size);
    assert_int_equal(cf__pango_fonts.shape(p->pctx, req, &p->prun, &a), 0);
    assert_int_equal(cf__native_fonts.shape(p->nctx, req, &p->nrun, &b), 0);
    native = !cf__native_fonts_used_pango(p->nrun);
    if (native) {
        p->native++;
        assert_true(cf__native_fonts_handles(req->text, req->len));
        same_glyphs(cf__pango_fonts.glyphs(p->prun),
                    cf__native_fonts.glyphs(p->nrun), what);
    } else {
        p->handed++;
    }
    if (memcmp(&a, &b, sizeof a) != 0)
        fail_msg("%s: shaping differs: baseline %d/%d logical %d %d %d %d /"
                 " %d %d %d %d ink %d %d %d %d / %d %d %d %d unknown %d/%d",
                 what, a.baseline, b.baseline, a.logical[0], a.logical[1],
                 a.logical[2], a.logical[3], b.logical[0], b.logical[1],
                 b.logical[2], b.logical[3], a.ink[0], a.ink[1], a.ink[2],
                 a.ink[3], b.ink[0], b.ink[1], b.ink[2], b.ink[3], a.unknown,
                 b.unknown);
    if (draw && native) {
        int k;
        for (k = 0; k < 2; k++) {
            bytes_t x = drawn(&cf__pango_fonts, p->prun, k == 1);
            bytes_t y = drawn(&cf__native_fonts, p->nrun, k == 1);
            if (x.n != y.n || memcmp(x.data, y.data, x.n) != 0)
                fail_msg("%s: the PDF of its %s differs (%zu / %zu bytes)",
                         what, k ? "path" : "glyphs", x.n, y.n);
            free(x.data);
            free(y.data);
        }
    }
    return native;
}

static bool
compare_text(pair_t *p, const char *family, bool italic, bool bold,
             double size, const char *text, bool draw)
{
    cf__font_req_t req;
    req.family = family;
    req.italic = italic;
    req.bold = bold;
    req.size = size;
    req.text = text;
    req.len = strlen(text);
    return compare(p, &req, draw);
}

/* Every run of the labels of figures/ and examples/. */
static void
test_corpus(void **state)
{
    FILE *f = fopen(corpus_path, "r");
    char line[2048];
    pair_t p;
    int n = 0;
    (void)state;
    assert_non_null(f);
    open_pair(&p);
    while (fgets(line, sizeof line, f) != NULL) {
        char *field[5], *s = line;
        cf__font_req_t req;
        int k;
        line[strcspn(line, "\n")] = '\0';
        for (k = 0; k < 5; k++) {
            field[k] = s;
            s = k < 4 ? strchr(s, '\t') : NULL;
            if (k < 4) {
                assert_non_null(s);
                *s++ = '\0';
            }
        }
        req.family = field[0];
        req.italic = atoi(field[1]) != 0;
        req.bold = atoi(field[2]) != 0;
        req.size = strtod(field[3], NULL);
        req.text = field[4];
        req.len = strlen(field[4]);
        compare(&p, &req, n % 16 == 0);
        n++;
    }
    fclose(f);
    /* every run of the course is the native fonts' */
    assert_true(n > 500);
    assert_int_equal(p.native, n);
    close_pair(&p);
}

/* The characters and pairs a course page's glyph data shapes
** (render/output/label-glyphs.c), at its 100 bp, in the theme's fonts. */
static void
test_characters_and_pairs(void **state)
{
    static const char *const families[] = { SERIF, SUB, MATH, SANS };
    pair_t p;
    size_t f;
    (void)state;
    open_pair(&p);
    for (f = 0; f < sizeof families / sizeof families[0]; f++) {
        unsigned a, b;
        char s[16];
        for (a = 0x20; a < 0x7f; a++) {
            s[0] = (char)a;
            s[1] = '\0';
            compare_text(&p, families[f], f == 3, false, 100, s, false);
        }
        for (a = 0x391; a <= 0x3c9; a++) {
            size_t n;
            if (a == 0x3a2)
                continue;   /* unassigned: pango's */
            n = cf__utf8_encode(a, s);
            s[n] = '\0';
            compare_text(&p, families[f], false, f == 1, 100, s, false);
        }
        for (a = 'A'; a <= 'z'; a++)
            for (b = 'A'; b <= 'z'; b += 3) {
                s[0] = (char)a;
                s[1] = (char)b;
                s[2] = '\0';
                compare_text(&p, families[f], false, false, 100, s, false);
            }
    }
    assert_int_equal(p.handed, 0);
    close_pair(&p);
}

typedef struct torture {
    const char *text;
    bool native;    /* the native fonts shape it (else: pango, by rule) */
} torture_t;

static const torture_t torture[] = {
    { "ffi fl office", true },
    { "AV To Wa Ty", true },
    { "Bézierova křivka", true },
    { "Рациональная кривая Безье", true },
    { "Ελληνικά ω θ φ", true },
    { "曲线", true },
    { "曲线 P0", true },
    { "曲线 P", true },
    { "贝塞尔曲线", true },
    { "曲线 P0 (a) [b]", true },
    { "ひらがな カタカナ 한글", true },
    { "x (кривая) «q» ‘s’ “t”", true },
    { "∑ √ ∞ − ′ ↦ → ∈ ≤ ⋅ ∘ ⟨a⟩", true },
    { "a\xcc\x83 e\xcc\x81 n\xcc\x8c", true },       /* combining marks */
    { "  a  b\xc2\xa0" "c\xe2\x80\x89" "d  ", true }, /* spaces */
    { "1/2 + 3 = 0.5", true },
    { "\xf0\x9f\x98\x80 emoji", false },
    { "\xe2\x9c\x94\xef\xb8\x8f", false },            /* VS16 */
    { "\xd7\xa9\xd7\x9c\xd7\x95\xd7\x9d", false },    /* Hebrew, RTL */
    { "abc \xd9\x85\xd8\xb1\xd8\xad\xd8\xa8\xd8\xa7", false }, /* Arabic */
    { "a\xe2\x80\x8d" "b", false },                   /* ZWJ */
    { "\xe0\xa4\xb9\xe0\xa4\xbf\xe0\xa4\xa8", false }, /* Devanagari */
    { "tab\there", false },
    { "", false },
};

static void
test_torture(void **state)
{
    static const struct {
        const char *family;
        bool italic, bold;
        double size;
    } fonts[] = {
        { SERIF, false, false, 10 }, { SERIF, true, false, 9.96 },
        { SERIF, false, true, 12 }, { SERIF, true, true, 7 },
        { SUB, false, false, 7 }, { MATH, false, false, 10 },
        { SANS, false, false, 8 }, { SANS, true, true, 11.5 },
    };
    pair_t p;
    size_t i, k;
    (void)state;
    open_pair(&p);
    for (k = 0; k < sizeof fonts / sizeof fonts[0]; k++)
        for (i = 0; i < sizeof torture / sizeof torture[0]; i++) {
            bool native = compare_text(&p, fonts[k].family, fonts[k].italic,
                                       fonts[k].bold, fonts[k].size,
                                       torture[i].text, true);
            if (!torture[i].native && native)
                fail_msg("\"%s\" should have gone to pango",
                         torture[i].text);
            if (torture[i].native && !native)
                fail_msg("\"%s\" went to pango", torture[i].text);
        }
    close_pair(&p);
}

/* A character of an allowed script that no font of the set has goes to
** pango (which draws its box), by the rule's last clause. */
static void
test_no_font(void **state)
{
    pair_t p;
    (void)state;
    open_pair(&p);
    /* U+A7C0, a Latin letter of Unicode 14 */
    assert_false(compare_text(&p, "Latin Modern Roman", false, false, 10,
                              "x\xea\x9f\x80y", true));
    close_pair(&p);
}

/* Whole labels laid out with each, their boxes the same doubles. */
static void
test_labels(void **state)
{
    static const char *const texts[] = {
        "$P_{11}$", "$\\mathbf{x}(t) = \\sum_{i=0}^n B_i^n(t)\\,P_i$",
        "$\\mathbf{Bold}$ and $\\mathit{italic}$ $\\boldsymbol{x\\alpha}$",
        "$\\mathrm{ffi} \\mathbb{R} \\mathcal{A}$ \\text{a  b}",
        "$\\frac{1}{2}\\omega^2$", "Bézierova křivka $b_{030}$",
        "\\text{曲线} $C^1$", "$\\alpha \\mapsto \\langle u, v \\rangle$",
    };
    size_t i, k;
    (void)state;
    for (i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        cf_label_t *a = NULL, *b = NULL;
        cf_diag_t d;
        cf_diag_clear(&d);
        if (cf__label_create(&cf__pango_fonts, texts[i], NULL, 10, &a, &d)
                != CF_STATUS_OK
            || cf__label_create(&cf__native_fonts, texts[i], NULL, 10, &b,
                                &d) != CF_STATUS_OK)
            fail_msg("%s: %s", texts[i], d.msg);
        assert_int_equal(cf_label_box_count(a), cf_label_box_count(b));
        for (k = 0; k < cf_label_box_count(a); k++) {
            const cf_label_box_t *x = cf_label_get_box(a, k);
            const cf_label_box_t *y = cf_label_get_box(b, k);
            assert_true(x->x == y->x && x->y == y->y
                        && x->width == y->width && x->ascent == y->ascent
                        && x->descent == y->descent && x->size == y->size
                        && x->level == y->level && x->kind == y->kind
                        && x->italic == y->italic && x->start == y->start
                        && x->end == y->end);
        }
        {
            double ia[4], ib[4];
            cf__label_ink(a, ia);
            cf__label_ink(b, ib);
            assert_memory_equal(ia, ib, sizeof ia);
        }
        cf_label_destroy(a);
        cf_label_destroy(b);
    }
}

/* The box of a path's points (x0 y0 x1 y1). */
static void
points_box(const double *xy, size_t n, double box[4])
{
    size_t i;
    box[0] = box[1] = 1e300;
    box[2] = box[3] = -1e300;
    for (i = 0; i + 1 < n; i += 2) {
        box[0] = xy[i] < box[0] ? xy[i] : box[0];
        box[1] = xy[i + 1] < box[1] ? xy[i + 1] : box[1];
        box[2] = xy[i] > box[2] ? xy[i] : box[2];
        box[3] = xy[i + 1] > box[3] ? xy[i + 1] : box[3];
    }
}

/* The outlines (SVG, the page's glyph data, halos) lie where the drawing
** puts the glyphs: the box of cf__font_glyphs_outline's points against
** the box of the path cairo draws (cf__font_glyphs_draw), both from the
** run's top left at (3.5, 17.75) (a point cairo's current point keeps
** exactly).  A run of a second script is raised by pango's baseline shift
** ("曲线 P0": 474 units, 0.46 bp at 10 bp); the outlines' coordinates are
** written to 5 digits per bp of size, under 1e-3 bp here, so 0.01 bp. */
static void
test_outlines_where_drawn(void **state)
{
    pair_t p;
    size_t i, k;
    (void)state;
    open_pair(&p);
    for (k = 0; k < 2; k++)
        for (i = 0; i < sizeof torture / sizeof torture[0]; i++) {
            cf__font_req_t req;
            const cf__font_glyphs_t *g;
            cf__font_shape_t sh;
            cf__pathb_t out;
            cairo_t *ocr = NULL, *cr;
            cairo_surface_t *s;
            cairo_path_t *path;
            double a[4], b[4], *xy;
            size_t n = 0;
            int j;
            if (!torture[i].native)
                continue;
            req.family = k == 0 ? SERIF : SANS;
            req.italic = req.bold = false;
            req.size = 10;
            req.text = torture[i].text;
            req.len = strlen(req.text);
            assert_int_equal(
                cf__native_fonts.shape(p.nctx, &req, &p.nrun, &sh), 0);
            g = cf__native_fonts.glyphs(p.nrun);
            memset(&out, 0, sizeof out);
            cf__font_glyphs_outline(&ocr, g, 3.5, 17.75, &out);
            assert_false(out.failed);
            if (out.ncoords == 0) {
                cf__pathb_free(&out);
                if (ocr != NULL)
                    cairo_destroy(ocr);
                continue;
            }
            points_box(out.coords, out.ncoords, a);
            s = cairo_recording_surface_create(CAIRO_CONTENT_ALPHA, NULL);
            cr = cairo_create(s);
            cairo_move_to(cr, 3.5, 17.75);
            cf__font_glyphs_draw(cr, g, true);
            path = cairo_copy_path(cr);
            xy = malloc((size_t)path->num_data * 2 * sizeof *xy);
            assert_non_null(xy);
            /* the glyphs' points: not the current point's own moves,
            ** before them and after (a move no segment follows) */
            for (j = 0; j < path->num_data; j += path->data[j].header.length) {
                int m, next = j + path->data[j].header.length;
                if (path->data[j].header.type == CAIRO_PATH_MOVE_TO
                    && (next >= path->num_data
                        || path->data[next].header.type
                               == CAIRO_PATH_MOVE_TO))
                    continue;
                for (m = 1; m < path->data[j].header.length; m++) {
                    xy[n++] = path->data[j + m].point.x;
                    xy[n++] = path->data[j + m].point.y;
                }
            }
            points_box(xy, n, b);
            for (j = 0; j < 4; j++)
                if (!(fabs(a[j] - b[j]) < 0.01))
                    fail_msg("\"%s\": outline box %g %g %g %g, drawn %g %g"
                             " %g %g", req.text, a[0], a[1], a[2], a[3],
                             b[0], b[1], b[2], b[3]);
            free(xy);
            cairo_path_destroy(path);
            cairo_destroy(cr);
            cairo_surface_destroy(s);
            cairo_destroy(ocr);
            cf__pathb_free(&out);
        }
    close_pair(&p);
}

static cairo_status_t
no_sink(void *u, const unsigned char *data, unsigned n)
{
    (void)u;
    (void)data;
    (void)n;
    return CAIRO_STATUS_SUCCESS;
}

/* The scaled font cairo shows a native span's glyphs with on surface s,
** set as cf__font_glyphs_draw sets it. */
static cairo_scaled_font_t *
shown_with(cairo_surface_t *s, const cf__font_span_t *span)
{
    cairo_t *cr = cairo_create(s);
    cairo_scaled_font_t *sf;
    cairo_set_scaled_font(cr, cf__font_face_scaled(span->face));
    assert_non_null(span->face->show_options);
    cairo_set_font_options(cr, span->face->show_options);
    sf = cairo_get_scaled_font(cr);
    cairo_destroy(cr);
    return sf;
}

/* A label shown on a PDF or PostScript surface uses the very scaled font
** its layout measured and outlined (cairo found it in its cache): its
** glyphs are not loaded again by FreeType for another scaled font of the
** same numbers (markova-2.17's PDF: 27 glyph loads, not 45).  On an image
** surface, whose glyph positions are rounded, it is another (the glyphs
** where they were drawn before: the same PNG bytes). */
static void
test_shown_with_layout_font(void **state)
{
    void *ctx = cf__native_fonts.open(cf__native_fonts.self), *run = NULL;
    cf__font_req_t req;
    cf__font_shape_t sh;
    const cf__font_glyphs_t *g;
    cairo_surface_t *pdf, *ps, *img;
    size_t i;
    (void)state;
    assert_non_null(ctx);
    req.family = MATH;
    req.italic = true;
    req.bold = false;
    req.size = 10;
    req.text = "P";
    req.len = 1;
    assert_int_equal(cf__native_fonts.shape(ctx, &req, &run, &sh), 0);
    assert_false(cf__native_fonts_used_pango(run));
    g = cf__native_fonts.glyphs(run);
    assert_true(g->nspans > 0);
    pdf = cairo_pdf_surface_create_for_stream(no_sink, NULL, 100, 100);
    ps = cairo_ps_surface_create_for_stream(no_sink, NULL, 100, 100);
    img = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 10, 10);
    for (i = 0; i < g->nspans; i++) {
        assert_ptr_equal(shown_with(pdf, &g->spans[i]),
                         cf__font_face_scaled(g->spans[i].face));
        assert_ptr_equal(shown_with(ps, &g->spans[i]),
                         cf__font_face_scaled(g->spans[i].face));
        assert_ptr_not_equal(shown_with(img, &g->spans[i]),
                             cf__font_face_scaled(g->spans[i].face));
    }
    cairo_surface_destroy(pdf);
    cairo_surface_destroy(ps);
    cairo_surface_destroy(img);
    cf__native_fonts.release(run);
    cf__native_fonts.close(ctx);
}

/* printf's "%.5g" read back by strtod: the reference. */
static double
five_digits_by_text(double v)
{
    char buf[32];
    snprintf(buf, sizeof buf, "%.5g", v);
    return strtod(buf, NULL);
}

static void
same_five_digits(double v)
{
    double a = cf__font_five_digits(v), b = five_digits_by_text(v);
    if (memcmp(&a, &b, sizeof a) != 0)
        fail_msg("%.17g: %.17g by arithmetic, %.17g by text", v, a, b);
}

/* cf__font_five_digits is the same double as the text round trip it
** stands for: 4 million values of every magnitude from 1e-6 to 1e6 (a
** fixed generator), the ties of the fifth digit (1.03125 = 33/32 and
** the like: exact halves, where printf rounds to even), every boundary
** of the arithmetic's range and of a decade with its neighbours, and
** zero, signs, infinities. */
static void
test_five_digits(void **state)
{
    static const double fixed[] = {
        0.0, -0.0, 1.03125, 1.03135, 0.0103125, 10312.5, 1031.25, 103.125,
        10.3125, 0.103125, 0.00103125, 2.5, 99999.5, 9999.95, 999.995,
        99.9995, 9.99995, 0.999995, 0.0999995, 0.00999995, 0.000999995,
        0.1, 0.01, 0.001, 1, 10, 100, 1000, 10000, 1e-4, 1e5, 1e300,
        -1e-300, 5e-324, 1e-3 * (1 - 1e-16),
    };
    uint64_t x = 0x9E3779B97F4A7C15u;
    size_t i;
    int k;
    (void)state;
    for (i = 0; i < sizeof fixed / sizeof fixed[0]; i++)
        for (k = -2; k <= 2; k++) {
            double v = fixed[i];
            int j;
            for (j = 0; j < (k < 0 ? -k : k); j++)
                v = nextafter(v, k < 0 ? -INFINITY : INFINITY);
            same_five_digits(v);
            same_five_digits(-v);
        }
    same_five_digits(INFINITY);
    same_five_digits(-INFINITY);
    for (i = 0; i < 4000000; i++) {
        double u, v;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        u = (double)(x >> 11) / 9007199254740992.0;  /* [0, 1) */
        v = pow(10.0, -6.0 + 12.0 * u);
        same_five_digits((x & 1) ? -v : v);
    }
}

/* Allocation failure (tu_fail_loop) in the native fonts' shaping of runs
** the renderer's own shaper takes (ligatures, kerning, Greek, Cyrillic, a
** script change) and one it hands to HarfBuzz (a combining mark): each
** failure is a clean -1, nothing leaks. */
static cf_status_t
op_shape_native(cf_diag_t *diag)
{
    static const char *const texts[] = {
        "office AV To", "P_0", "\xce\xb1\xce\xb2\xce\xb3 x",
        "\xd0\x9f\xd1\x80\xd0\xb8 (1+2)", "e\xcc\x81t\xc3\xa9"
    };
    void *ctx = cf__native_fonts.open(cf__native_fonts.self), *run = NULL;
    cf_status_t st = CF_STATUS_OK;
    size_t i;
    (void)diag;
    if (ctx == NULL)
        return CF_STATUS_NO_MEMORY;
    for (i = 0; i < sizeof texts / sizeof texts[0] && st == CF_STATUS_OK;
         i++) {
        cf__font_req_t req = { "Latin Modern Roman", i == 2, false, 10,
                               texts[i], strlen(texts[i]) };
        cf__font_shape_t sh;
        if (cf__native_fonts.shape(ctx, &req, &run, &sh) != 0)
            st = CF_STATUS_NO_MEMORY;
    }
    cf__native_fonts.release(run);
    cf__native_fonts.close(ctx);
    return st;
}

static void
test_out_of_memory(void **state)
{
    (void)state;
    assert_int_equal(op_shape_native(NULL), CF_STATUS_OK);   /* faces made */
    assert_true(tu_fail_loop("native fonts' shaping", op_shape_native,
                             false) > 0);
}

/* Every font set of the themes' family lists walked to its end and again:
** the same faces, in the same places, each readable; past the end NULL,
** however often asked (a set's list once grew its array before knowing a
** font was left, and when the list ended just where it was full, the
** block realloc had moved was lost and the list left on the freed one:
** AddressSanitizer reads the second walk). */
static void
test_sets_to_their_end(void **state)
{
    static const char *const families[] = {
        CF__DEFAULT_FAMILY, CF__SANS_FAMILY, "Latin Modern Math",
        "Latin Modern Roman", "Noto Serif CJK SC,Latin Modern Roman"
    };
    static const double sizes[] = { 5, 7, 9.96, 12, 17.28, 24.88 };
    enum { MAX_FONTS = 400 };
    static cf__nface_t *first[MAX_FONTS];
    size_t f, z, sets = 0, longest = 0;
    (void)state;
    cf__native_fonts.close(cf__native_fonts.open(cf__native_fonts.self));
    for (f = 0; f < sizeof families / sizeof families[0]; f++)
        for (z = 0; z < sizeof sizes / sizeof sizes[0]; z++)
            for (int style = 0; style < 4; style++) {
                int size = (int)(sizes[z] * CF__FONT_SCALE);
                cf__nfontset_t *set;
                int n = 0, i;
                cf__nfaces_lock();
                set = cf__nfontset_get(families[f], style & 1, style & 2,
                                       size, cf__native_language());
                assert_non_null(set);
                while (n < MAX_FONTS
                       && (first[n] = cf__nfontset_font(set, n)) != NULL)
                    n++;
                assert_true(n > 0 && n < MAX_FONTS);
                for (i = 0; i < 3; i++)
                    assert_null(cf__nfontset_font(set, n + i));
                for (i = 0; i < n; i++) {
                    cf__nface_t *again = cf__nfontset_font(set, i);
                    assert_ptr_equal(again, first[i]);
                    assert_true(strlen(again->key) > 0);
                }
                cf__nfaces_unlock();
                sets++;
                if ((size_t)n > longest)
                    longest = (size_t)n;
            }
    printf("%zu font sets walked to their end, the longest %zu fonts\n",
           sets, longest);
}

int
main(int argc, char **argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_corpus),
        cmocka_unit_test(test_characters_and_pairs),
        cmocka_unit_test(test_torture),
        cmocka_unit_test(test_no_font),
        cmocka_unit_test(test_labels),
        cmocka_unit_test(test_outlines_where_drawn),
        cmocka_unit_test(test_shown_with_layout_font),
        cmocka_unit_test(test_five_digits),
        cmocka_unit_test(test_out_of_memory),
        cmocka_unit_test(test_sets_to_their_end),
    };
    if (argc < 2) {
        fprintf(stderr, "usage: %s fonts-corpus.txt [LOCALE]\n", argv[0]);
        return 2;
    }
    corpus_path = argv[1];
    /* with a locale: both read pango's default language from it (C.UTF-8
    ** is pango's "c" too, so the runs stay the native fonts') */
    if (argc > 2 && setlocale(LC_CTYPE, argv[2]) == NULL) {
        fprintf(stderr, "no locale %s here\n", argv[2]);
        return 77;
    }
    return cmocka_run_group_tests(tests, NULL, NULL);
}
