/* Label syntax and layout: scripts, stacking, fonts, scripts of the world,
** syntax errors. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>
#include <pango/pangocairo.h>

#include "buffer.h"
#include "curvefig/figure.h"
#include "font-table.h"
#include "label-cairo.h"
#include "testutil.h"

#define SIZE 10.0

static cf_label_t *
layout(const char *text)
{
    cf_label_t *lab = NULL;
    cf_diag_t d;
    cf_diag_clear(&d);
    if (cf_label_create(text, NULL, SIZE, &lab, &d) != CF_STATUS_OK)
        fail_msg("label \"%s\": %s", text, d.msg);
    return lab;
}

/* s with its ASCII letters in the math italic alphabet (U+1D434 A,
** U+1D44E a, U+210E h), as mathematics sets them; static storage. */
static const char *
mi(const char *s)
{
    static char out[256];
    size_t n = 0;
    for (; *s != '\0' && n + 5 < sizeof out; s++) {
        unsigned c = (unsigned char)*s, cp = 0;
        if (c >= 'A' && c <= 'Z')
            cp = 0x1d434 + (c - 'A');
        else if (c == 'h')
            cp = 0x210e;
        else if (c >= 'a' && c <= 'z')
            cp = 0x1d44e + (c - 'a');
        if (cp == 0) {
            out[n++] = (char)c;
        } else if (cp < 0x10000) {
            out[n++] = (char)(0xe0 | (cp >> 12));
            out[n++] = (char)(0x80 | ((cp >> 6) & 0x3f));
            out[n++] = (char)(0x80 | (cp & 0x3f));
        } else {
            out[n++] = (char)(0xf0 | (cp >> 18));
            out[n++] = (char)(0x80 | ((cp >> 12) & 0x3f));
            out[n++] = (char)(0x80 | ((cp >> 6) & 0x3f));
            out[n++] = (char)(0x80 | (cp & 0x3f));
        }
    }
    out[n] = '\0';
    return out;
}

/* The first box whose run text equals s, or s set in the math italic. */
static const cf_label_box_t *
box_of(const cf_label_t *lab, const char *s)
{
    size_t i;
    for (i = 0; i < cf_label_box_count(lab); i++)
        if (strcmp(cf_label_run_text(lab, i), s) == 0)
            return cf_label_get_box(lab, i);
    for (i = 0; i < cf_label_box_count(lab); i++)
        if (strcmp(cf_label_run_text(lab, i), mi(s)) == 0)
            return cf_label_get_box(lab, i);
    fail_msg("no run \"%s\"", s);
    return NULL;
}

/* The last subscript and superscript runs (both must exist). */
static void
scripts_of(const cf_label_t *lab, const cf_label_box_t **sub,
           const cf_label_box_t **sup)
{
    size_t i;
    *sub = *sup = NULL;
    for (i = 0; i < cf_label_box_count(lab); i++) {
        const cf_label_box_t *b = cf_label_get_box(lab, i);
        if (b->kind == CF_LABEL_SUB)
            *sub = b;
        if (b->kind == CF_LABEL_SUP)
            *sup = b;
    }
    assert_non_null(*sub);
    assert_non_null(*sup);
}

static void
test_subscript_lower_and_smaller(void **state)
{
    cf_label_t *lab = layout("P_0");
    const cf_label_box_t *p, *z;
    (void)state;
    /* Given "P_0", Then P is at the base line, 0 is a smaller run below
    ** it, starting where P ends. */
    assert_int_equal(cf_label_box_count(lab), 2);
    p = box_of(lab, "P");
    z = box_of(lab, "0");
    assert_int_equal(p->kind, CF_LABEL_BASE);
    assert_int_equal(z->kind, CF_LABEL_SUB);
    assert_true(p->italic);     /* math letters italic */
    assert_false(z->italic);    /* digits upright */
    assert_true(z->y < p->y);   /* lower */
    assert_true(z->size < p->size);
    /* TeX scriptsize 7 pt for 10 pt text; exact ratio */
    tu_assert_close(z->size, 0.7 * SIZE, 1e-12, 0);
    tu_assert_close(z->x, p->x + p->width, 1e-9, 1);
    /* TeX sub1 = 0.15 em for a subscript alone */
    tu_assert_close(-z->y, 0.15 * SIZE, 1e-9, 1);
    cf_label_destroy(lab);
    /* the script is set in Latin Modern's 7 pt design, like cmr7: its
    ** digits are 0.569 em wide, those of the 10 pt design 0.5 em */
    lab = layout("0P_0");
    z = cf_label_get_box(lab, 2);
    assert_string_equal(cf_label_run_text(lab, 2), "0");
    assert_int_equal(z->level, 1);
    assert_true(z->width / z->size > 0.55);
    z = cf_label_get_box(lab, 0);
    assert_string_equal(cf_label_run_text(lab, 0), "0");
    assert_int_equal(z->level, 0);
    tu_assert_close(z->width / z->size, 0.5, 1e-3, 0);
    cf_label_destroy(lab);
}

static void
test_superscript_and_sub_stack(void **state)
{
    const char *texts[] = { "B_i^n(t)", "B^n_i(t)", "N_{i}^{p}(u)" };
    size_t k;
    (void)state;
    for (k = 0; k < 3; k++) {
        cf_label_t *lab = layout(texts[k]);
        const cf_label_box_t *b = cf_label_get_box(lab, 0), *sub, *sup,
                             *paren = box_of(lab, "(");
        scripts_of(lab, &sub, &sup);
        /* stacked: the subscript starts right after the base letter,
        ** the superscript at the same x moved right by the slanted B's
        ** italic correction (cmmi10: B 0.05 em, N 0.11 em); one above,
        ** one below the base line */
        tu_assert_close(sub->x, b->x + b->width, 1e-9, 1);
        assert_true(sup->x >= sub->x);
        assert_true(sup->x - sub->x < 0.15 * SIZE);
        assert_true(sup->y > 0);
        assert_true(sub->y < 0);
        assert_int_equal(sub->level, 1);
        assert_int_equal(sup->level, 1);
        /* the sub- and superscript boxes do not overlap vertically */
        assert_true(sub->y + sub->ascent * 0.75 < sup->y);
        /* the parenthesis follows the wider script */
        assert_true(paren->x >= fmax(sub->x + sub->width,
                                     sup->x + sup->width) - 1e-9);
        assert_int_equal(paren->kind, CF_LABEL_BASE);
        cf_label_destroy(lab);
    }
}

/* Right edge of the ink of one glyph (bp from its origin) and its advance,
** found independently of the label code: the glyph is rasterized 40
** times enlarged (1 pixel = 0.025 bp) and the rightmost column with ink
** is searched. */
static void
glyph_ink_right(const char *family, const char *glyph, double *ink_right,
                double *advance)
{
    enum { SCALE = 40, W = 1200, H = 900 };
    const double ox = 5, oy = 5;   /* glyph origin, bp */
    cairo_surface_t *img = cairo_image_surface_create(CAIRO_FORMAT_A8, W, H);
    cairo_t *cr = cairo_create(img);
    PangoLayout *pl = pango_cairo_create_layout(cr);
    PangoFontDescription *fd = pango_font_description_new();
    PangoRectangle logical;
    const unsigned char *data;
    int stride, x, y, right = -1;
    cairo_font_options_t *fo = cairo_font_options_create();

    /* unhinted, unrounded metrics, as the labels are laid out */
    cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
    cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
    pango_cairo_context_set_font_options(pango_layout_get_context(pl), fo);
    cairo_font_options_destroy(fo);
    pango_context_set_round_glyph_positions(pango_layout_get_context(pl),
                                            FALSE);
    pango_layout_context_changed(pl);
    pango_font_description_set_family(fd, family);
    /* the math font's italic alphabet is upright-styled: its glyphs lean */
    pango_font_description_set_style(fd, strcmp(family, "Latin Modern Math")
                                     == 0 ? PANGO_STYLE_NORMAL
                                          : PANGO_STYLE_ITALIC);
    pango_font_description_set_absolute_size(fd, SIZE * PANGO_SCALE);
    pango_layout_set_font_description(pl, fd);
    pango_layout_set_text(pl, glyph, -1);
    cairo_scale(cr, SCALE, SCALE);
    cairo_move_to(cr, ox, oy);
    pango_cairo_show_layout(cr, pl);
    pango_layout_get_extents(pl, NULL, &logical);
    *advance = (double)logical.width / PANGO_SCALE;
    cairo_surface_flush(img);
    data = cairo_image_surface_get_data(img);
    stride = cairo_image_surface_get_stride(img);
    for (y = 0; y < H; y++)
        for (x = W - 1; x > right; x--)
            if (data[y * stride + x] != 0)
                right = x;
    assert_true(right > 0 && right < W - 1);   /* ink, not cut off */
    *ink_right = (right + 1.0) / SCALE - ox;
    pango_font_description_free(fd);
    g_object_unref(pl);
    cairo_destroy(cr);
    cairo_surface_destroy(img);
}

static void
test_italic_correction(void **state)
{
    /* Latin Modern's slanted capitals reach right of their advance (TeX:
    ** the italic correction, cmmi10 N 0.109 em, V 0.222 em, f 0.108 em).
    ** TeX rule 17 sets the superscript after the correction, so that it
    ** clears the letter's upper right corner, and the subscript at the
    ** advance, tucked under it. */
    const char *letters[] = { "N", "P", "V", "C", "f", "T" };
    size_t k;
    (void)state;
    for (k = 0; k < sizeof letters / sizeof letters[0]; k++) {
        char text[16];
        double ink_right, advance;
        cf_label_t *lab;
        const cf_label_box_t *nuc, *sub, *sup;
        snprintf(text, sizeof text, "%s_0^4", letters[k]);
        lab = layout(text);
        glyph_ink_right("Latin Modern Math", mi(letters[k]), &ink_right,
                        &advance);
        nuc = box_of(lab, letters[k]);
        scripts_of(lab, &sub, &sup);
        /* the nucleus is the math font's italic letter, as measured */
        tu_assert_close(nuc->width, advance, 1e-9, 1);
        /* the test's premise: these letters overhang (by more than
        ** 0.03 em; 1 pixel is 0.0025 em) */
        assert_true(ink_right - advance > 0.03 * SIZE);
        /* superscript: its origin (and so its ink: digits have a
        ** positive left bearing) right of the nucleus' ink, within one
        ** pixel of the raster plus the antialiasing fringe; and not
        ** pushed further than the overhang */
        assert_true(sup->x >= nuc->x + ink_right - 2.0 / 40);
        assert_true(sup->x <= nuc->x + ink_right + 2.0 / 40);
        /* subscript: at the advance width */
        tu_assert_close(sub->x, nuc->x + nuc->width, 1e-9, 1);
        cf_label_destroy(lab);
        /* the same without a subscript, and after another atom */
        snprintf(text, sizeof text, "2%s^4", letters[k]);
        lab = layout(text);
        nuc = box_of(lab, letters[k]);
        sup = box_of(lab, "4");
        assert_true(sup->x >= nuc->x + ink_right - 2.0 / 40);
        assert_true(sup->x <= nuc->x + ink_right + 2.0 / 40);
        cf_label_destroy(lab);
    }
    {
        /* TeX's kern after a math italic letter: an upright delimiter or
        ** a digit after a slanted letter starts right of the letter's
        ** ink, f(t) and V] do not touch */
        const char *texts[] = { "f(t)", "V(t)", "f]", "P2" };
        const char *next[] = { "(", "(", "]", "2" };
        for (k = 0; k < 4; k++) {
            char letter[2] = { texts[k][0], '\0' };
            double ink_right, advance;
            cf_label_t *lab = layout(texts[k]);
            const cf_label_box_t *nuc = box_of(lab, letter);
            const cf_label_box_t *d = box_of(lab, next[k]);
            glyph_ink_right("Latin Modern Math", mi(letter), &ink_right,
                            &advance);
            assert_true(ink_right - advance > 0.03 * SIZE);
            assert_true(d->x >= nuc->x + ink_right - 2.0 / 40);
            assert_true(d->x <= nuc->x + ink_right + 2.0 / 40);
            cf_label_destroy(lab);
        }
    }
    {
        /* an upright nucleus (a digit, an upright capital Greek letter)
        ** has no correction: both scripts start at its advance */
        const char *upright[] = { "2_0^4", "\\Gamma_0^4" };
        for (k = 0; k < 2; k++) {
            cf_label_t *lab = layout(upright[k]);
            const cf_label_box_t *nuc = cf_label_get_box(lab, 0);
            const cf_label_box_t *a = cf_label_get_box(lab, 1);
            const cf_label_box_t *b = cf_label_get_box(lab, 2);
            assert_int_equal(cf_label_box_count(lab), 3);
            tu_assert_close(a->x, nuc->x + nuc->width, 1e-9, 1);
            tu_assert_close(b->x, nuc->x + nuc->width, 1e-9, 1);
            cf_label_destroy(lab);
        }
    }
}

static void
test_group_subscript_and_minus(void **state)
{
    cf_label_t *lab = layout("P_{k-p+1,1}");
    size_t i;
    char joined[64] = "";
    double y = NAN;
    (void)state;
    /* every script run sits on one base line at level 1, and '-' became
    ** the minus sign U+2212 */
    for (i = 1; i < cf_label_box_count(lab); i++) {
        const cf_label_box_t *b = cf_label_get_box(lab, i);
        assert_int_equal(b->level, 1);
        assert_int_equal(b->kind, CF_LABEL_SUB);
        if (isnan(y))
            y = b->y;
        assert_true(b->y == y);
        strcat(joined, cf_label_run_text(lab, i));
    }
    assert_string_equal(joined, mi("k\xe2\x88\x92p+1,1"));
    cf_label_destroy(lab);
}

static void
test_nested_scripts_and_greek(void **state)
{
    cf_label_t *lab;
    const cf_label_box_t *a, *b;
    (void)state;
    lab = layout("x^{a_b}");
    a = box_of(lab, "a");
    b = box_of(lab, "b");
    assert_int_equal(a->level, 1);
    assert_int_equal(b->level, 2);
    tu_assert_close(b->size, 0.5 * SIZE, 1e-12, 0);
    assert_true(b->y < a->y);
    assert_true(a->y > 0);
    cf_label_destroy(lab);

    /* an accent centred over its letter (moved right by the slant), also
    ** when the accent's run is the one that outgrows the run array (7
    ** runs before the P, 8 allocated) */
    {
        const char *texts[] = { "\\hat{P}", "1+2+3+4\\hat{P}" };
        size_t k;
        for (k = 0; k < 2; k++) {
            const cf_label_box_t *acc;
            lab = layout(texts[k]);
            a = box_of(lab, "P");
            acc = box_of(lab, "\xcb\x86");   /* U+02C6 modifier circumflex */
            assert_int_equal(acc->kind, CF_LABEL_BASE);
            assert_true(acc->x + 0.5 * acc->width > a->x + 0.3 * a->width);
            assert_true(acc->x + 0.5 * acc->width < a->x + 1.0 * a->width);
            assert_true(acc->y > a->y);
            cf_label_destroy(lab);
        }
    }

    /* over a group of several characters: centred over the group's
    ** width (TeX's non-wide accent over a box), above its top */
    {
        const cf_label_box_t *p0, *q0, *acc;
        double x0, x1;
        lab = layout("\\vec{PQ}");
        p0 = box_of(lab, "PQ");
        acc = box_of(lab, "\xe2\x86\x92");   /* U+2192 the arrow */
        q0 = p0;
        x0 = p0->x;
        x1 = q0->x + q0->width;
        tu_assert_close(acc->x + 0.5 * acc->width, 0.5 * (x0 + x1),
                        0.1 * SIZE, 0);
        assert_true(acc->y > p0->y + 0.4 * SIZE);
        cf_label_destroy(lab);
    }

    lab = layout("\\omega_i\\Omega\\alpha");
    assert_true(box_of(lab, "\xf0\x9d\x9c\x94")->italic);  /* ω italic */
    assert_false(box_of(lab, "\xce\xa9")->italic);     /* Ω upright */
    assert_true(box_of(lab, "\xf0\x9d\x9b\xbc")->italic);  /* α */
    assert_int_equal(cf_label_unknown_glyphs(lab), 0);
    cf_label_destroy(lab);
}

static void
test_text_and_math_modes(void **state)
{
    cf_label_t *lab;
    double w1, w2, a, d;
    (void)state;
    /* with $: text outside upright, math inside italic */
    lab = layout("křivka $C(u)$");
    assert_false(box_of(lab, "k\xc5\x99ivka ")->italic);
    assert_true(box_of(lab, "C")->italic);
    assert_true(box_of(lab, "u")->italic);
    cf_label_get_extents(lab, &w1, &a, &d);
    assert_true(w1 > 0 && a > 0 && d > 0);
    cf_label_destroy(lab);
    /* binary operators get TeX's medium space: "a+b" is wider than the
    ** sum of its glyph advances by 2 * 4/18 em */
    lab = layout("a+b");
    cf_label_get_extents(lab, &w2, NULL, NULL);
    {
        double sum = 0;
        size_t i;
        for (i = 0; i < cf_label_box_count(lab); i++)
            sum += cf_label_get_box(lab, i)->width;
        tu_assert_close(w2 - sum, 2 * 4.0 / 18 * SIZE, 1e-9, 1);
    }
    cf_label_destroy(lab);
    /* a leading minus is unary: no space after it */
    lab = layout("-1");
    cf_label_get_extents(lab, &w2, NULL, NULL);
    tu_assert_close(w2, cf_label_get_box(lab, 0)->width
                        + cf_label_get_box(lab, 1)->width, 1e-9, 1);
    cf_label_destroy(lab);
}

static void
test_fraction(void **state)
{
    cf_label_t *lab = layout("\\frac{1}{n+1}");
    const cf_label_box_t *one = box_of(lab, "1"), *n = box_of(lab, "n");
    size_t i;
    double w, a, d;
    (void)state;
    /* numerator above the base line, denominator below, both at script
    ** size, centred on each other; the rule is a run without text */
    assert_true(one->y > 0);
    assert_true(n->y < 0);
    tu_assert_close(one->size, 0.7 * SIZE, 1e-12, 0);
    {
        const cf_label_box_t *last = NULL, *rule = NULL;
        for (i = 0; i < cf_label_box_count(lab); i++) {
            if (cf_label_run_text(lab, i)[0] == '\0')
                rule = cf_label_get_box(lab, i);
            else if (cf_label_get_box(lab, i)->y < 0)
                last = cf_label_get_box(lab, i);
        }
        assert_non_null(rule);
        /* the denominator n+1 spans the rule; the numerator is centred */
        tu_assert_close(n->x, rule->x, 1e-9, 1);
        tu_assert_close(last->x + last->width, rule->x + rule->width, 1e-9,
                        1);
        tu_assert_close(one->x + one->width / 2, rule->x + rule->width / 2,
                        1e-9, 1);
        /* the rule sits on the math axis (0.25 em), between the two */
        assert_true(rule->y > 0 && rule->y < one->y);
    }
    cf_label_get_extents(lab, &w, &a, &d);
    assert_true(a > 0.5 * SIZE && d > 0.2 * SIZE);
    cf_label_destroy(lab);
}

static void
test_world_scripts_have_glyphs(void **state)
{
    const char *texts[] = {
        "\xd0\x9a\xd1\x80\xd0\xb8\xd0\xb2\xd1\x8b\xd0\xb5",   /* Кривые */
        "\xe6\x9b\xb2\xe7\xba\xbf",                             /* 曲线 */
        "B\xc3\xa9zierova k\xc5\x99ivka",                       /* Czech */
        "odmik krivulje \xc4\x8d\xc5\xa1\xc5\xbe",              /* Slovene */
    };
    size_t k;
    cf_label_t *lab;
    (void)state;
    for (k = 0; k < 4; k++) {
        lab = layout(texts[k]);
        assert_int_equal(cf_label_unknown_glyphs(lab), 0);
        cf_label_destroy(lab);
    }
    /* the check can fail: a noncharacter has no glyph in any font */
    lab = layout("\xf4\x8f\xbf\xbd");   /* U+10FFFD */
    assert_true(cf_label_unknown_glyphs(lab) > 0);
    cf_label_destroy(lab);
}

static void
test_syntax_errors(void **state)
{
    struct {
        const char *text;
        long at;
    } bad[] = {
        { "P_", 1 },          { "P^", 1 },      { "P_{0", 2 },
        { "P}", 1 },          { "\\foo", 0 },   { "x_1_2", 3 },
        { "a $b", 2 },        { "\xff", 0 },    { "_1", 0 },
        { "\\hat{}", 0 },     { "\\", 0 },      { "x^^", 1 },
        { "\\hat{ }", 0 },
        { "\\frac{1}", 0 },   { "\\frac 1", 0 },
        { "\\sqrt", 0 },      { "\\sqrt[3{x}", 5 }, { "\\left( x", 0 },
        { "x \\right)", 2 },  { "\\left< x \\right>", 0 },
        { "\\mathbb{x}", 9 },
    };
    size_t k;
    (void)state;
    for (k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        cf_label_t *lab = (cf_label_t *)&k;
        cf_diag_t d;
        cf_diag_clear(&d);
        assert_int_equal(cf_label_create(bad[k].text, NULL, SIZE, &lab, &d),
                         CF_STATUS_INVALID_ARG);
        assert_null(lab);
        assert_int_equal(d.index, bad[k].at);
        assert_non_null(strstr(d.msg, "byte"));
    }
    {
        cf_label_t *lab;
        assert_int_equal(cf_label_create(NULL, NULL, SIZE, &lab, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_label_create("x", NULL, 0, &lab, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_label_create("x", NULL, NAN, &lab, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_label_create("x", "", SIZE, &lab, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_label_create("x", NULL, SIZE, NULL, NULL),
                         CF_STATUS_INVALID_ARG);
    }
    /* queries on NULL are harmless */
    assert_int_equal(cf_label_box_count(NULL), 0);
    assert_null(cf_label_get_box(NULL, 0));
    assert_string_equal(cf_label_run_text(NULL, 0), "");
    cf_label_destroy(NULL);
}

static void
test_tex_points(void **state)
{
    (void)state;
    /* 10 pt TeX = 10 * 72 / 72.27 bp = 9.9626 bp */
    tu_assert_close(cf_length_to_bp(10, CF_UNIT_TEXPT), 9.962640099626401,
                    1e-15, 0);
    tu_assert_close(cf_length_to_bp(25.4, CF_UNIT_MM), 72, 1e-15, 0);
    tu_assert_close(cf_length_to_bp(1, CF_UNIT_IN), 72, 1e-15, 0);
    tu_assert_close(cf_length_to_bp(2.54, CF_UNIT_CM), 72, 1e-15, 0);
    assert_true(isnan(cf_length_to_bp(1, (cf_unit_t)99)));
}

static void
test_out_of_memory(void **state)
{
    long k;
    (void)state;
    /* every allocation of the label code fails in turn: a status, never a
    ** crash or a leak */
    for (k = 1; k < 400; k++) {
        cf_label_t *lab = NULL;
        cf_status_t st;
        tu_fail_alloc_after(k);
        st = cf_label_create("B_i^n(t) = \\omega_{k-1}^2 \\hat{P}", NULL,
                             SIZE, &lab, NULL);
        if (st == CF_STATUS_OK) {
            cf_label_destroy(lab);
            assert_int_equal(tu_alloc_live(), 0);
            tu_fail_alloc_reset();
            return;
        }
        assert_int_equal(st, CF_STATUS_NO_MEMORY);
        assert_null(lab);
        assert_int_equal(tu_alloc_live(), 0);
        tu_fail_alloc_reset();
    }
    fail_msg("label layout never succeeded");
}

/* Labels as TeX source for the PGF output (render/labels/label-tex.c): every
** part of the syntax, written as TeX would be typed by hand; scripts
** pdflatex cannot set are refused. */
static void
test_label_tex(void **state)
{
    static const char *const cases[][2] = {
        { "P_0", "$P_{0}$" },
        { "B_i^n(t)", "$B_{i}^{n}(t)$" },
        { "N_{i,p}", "$N_{{i,p}}$" },
        { "\\omega_i \\geq 0", "$\\omega _{i} \\geq  0$" },
        { "α ≤ −x′", "$\\alpha  \\leq  -x'$" },
        { "x^2'", "$x^{2}{}'$" },
        { "\\frac{1}{2} \\hat P", "$\\frac{1}{2} \\hat{P}$" },
        { "\\vec{PQ} + \\bar{ x }", "$\\vec{PQ} + \\bar{x}$" },
        { "\\omicron\\deg", "$o{}^{\\circ}$" },
        { "\\operatorname{deg} č", "$\\mathrm{deg} \\text{č}$" },
        { "a # b", "$a \\# b$" },
        { "$the curve$ x_1 <y> ~", "$the curve$ x\\_1 \\textless{}y"
                                   "\\textgreater{} \\textasciitilde{}" },
        { "$x$ \\alpha \\mathbf{b} \\\\", "$x$ \\ensuremath{\\alpha} "
                                           "\\textbf{b} \\textbackslash{}" },
        { "√2 ⇒ ΑΒ", "$\\surd 2 \\Rightarrow  \\mathrm{A}\\mathrm{B}$" },
        { "\\sqrt{2}/2 \\sqrt[3] x", "$\\sqrt{2}/2 \\sqrt[3]x$" },
        { "\\binom{n}{k} \\frac14", "$\\binom{n}{k} \\frac14$" },
        { "\\left( a \\right\\}", "$\\left( a \\right\\}$" },
        { "$s$ \\sqrt{t}", "$s$ \\ensuremath{\\sqrt{t}}" },
        { "", "" },
    };
    static const char *const refused[] = {
        "Кривая", "$кривая$ b_0", "贝塞尔", "x ∈ ℝ", "\\mathbb{R}",
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        cf__buf_t b;
        memset(&b, 0, sizeof b);
        assert_int_equal(cf__label_tex(cases[i][0], &b), 0);
        assert_int_equal(cf__buf_append(&b, "", 1), 0);
        if (strcmp((const char *)b.data, cases[i][1]) != 0)
            fail_msg("label \"%s\": TeX \"%s\", expected \"%s\"",
                     cases[i][0], (const char *)b.data, cases[i][1]);
        cf__buf_free(&b);
    }
    for (i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        cf__buf_t b;
        memset(&b, 0, sizeof b);
        assert_int_equal(cf__label_tex(refused[i], &b), 1);
        cf__buf_free(&b);
    }
}

/* The ink of lab drawn at 8 px per bp, its origin at (20, 60) bp, in an
** A8 image of 800 x 800 px (the caller destroys it). */
static cairo_surface_t *
draw_big(const cf_label_t *lab)
{
    static const cf_color_t black = { 0, 0, 0, 1 };
    cairo_surface_t *img = cairo_image_surface_create(CAIRO_FORMAT_A8, 800,
                                                      800);
    cairo_t *cr = cairo_create(img);
    cairo_scale(cr, 8, 8);
    cf__label_draw(lab, cr, 20, 60, &black, 1);
    cairo_destroy(cr);
    cairo_surface_flush(img);
    return img;
}

static int
ink_at(cairo_surface_t *img, int x, int y)
{
    const unsigned char *d = cairo_image_surface_get_data(img);
    return d[y * cairo_image_surface_get_stride(img) + x] > 128;
}

/* Measured on the pixels of \sqrt{radicand}: the top row of ink is the
** bar, which spans every column of the radicand's ink (found as the
** columns right of the sign, which is the run before it is placed, left
** of x_sign_end); the bar lies above the radicand with white rows
** between; returns the sign's height in px (the ink rows of the columns
** left of the radicand). */
static int
sqrt_pixels(const char *text, int *bar_len)
{
    cf_label_t *lab = layout(text);
    cairo_surface_t *img = draw_big(lab);
    int x, y, top = -1, bottom = -1, rad_x0 = -1, rad_x1 = -1, bar_y;
    int sign_top = 800, sign_bottom = -1, sign_x1 = -1, gap_rows = 0, run_x0;
    /* the bar: the first row with ink; its run of ink */
    for (y = 0; y < 800 && top < 0; y++)
        for (x = 0; x < 800; x++)
            if (ink_at(img, x, y)) {
                top = y;
                break;
            }
    assert_true(top >= 0);
    bar_y = top + 1;
    for (x = 799; x >= 0 && rad_x1 < 0; x--)
        if (ink_at(img, x, bar_y))
            rad_x1 = x;
    for (x = rad_x1; x >= 0 && ink_at(img, x, bar_y); x--)
        ;
    run_x0 = x;
    /* the sign: the columns up to the end of its run's advance */
    for (x = 0; x < (int)cf_label_box_count(lab); x++)
        if (strcmp(cf_label_run_text(lab, (size_t)x), "\xe2\x88\x9a") == 0)
            sign_x1 = (int)((20 + cf_label_get_box(lab, (size_t)x)->x
                             + cf_label_get_box(lab, (size_t)x)->width) * 8);
    assert_true(sign_x1 > 0);
    *bar_len = rad_x1 - sign_x1;
    /* one run of ink from the sign's top stroke to the bar's end */
    assert_true(run_x0 < sign_x1);
    for (x = 0; x < sign_x1; x++)
        for (y = 0; y < 800; y++)
            if (ink_at(img, x, y)) {
                sign_top = y < sign_top ? y : sign_top;
                sign_bottom = y > sign_bottom ? y : sign_bottom;
            }
    /* the radicand: the runs after the sign's advance; white rows
    ** between the bar (from its last row) and its ink, in the column of
    ** its middle */
    {
        double x0 = INFINITY, x1 = -INFINITY;
        int mid, last = -1;
        for (x = 0; x < (int)cf_label_box_count(lab); x++) {
            const cf_label_box_t *b = cf_label_get_box(lab, (size_t)x);
            if ((20 + b->x) * 8 >= sign_x1 - 0.5
                && cf_label_run_text(lab, (size_t)x)[0] != '\0') {
                x0 = fmin(x0, b->x);
                x1 = fmax(x1, b->x + b->width);
            }
        }
        assert_true(x1 > x0);
        mid = (int)((20 + 0.5 * (x0 + x1)) * 8);
        while (bar_y < 799 && ink_at(img, rad_x1 - 1, bar_y + 1))
            bar_y++;
        for (y = bar_y + 1; y < 800 && !ink_at(img, mid, y); y++)
            gap_rows++;
        assert_true(gap_rows >= 2 && y < 800);
        /* the radicand's ink lies under the bar: its last column is not
        ** right of the bar's */
        rad_x0 = (int)((20 + x0) * 8);
        for (x = rad_x0; x < 800; x++)
            for (y = bar_y + 1; y < 800; y++)
                if (ink_at(img, x, y)) {
                    last = x;
                    bottom = y > bottom ? y : bottom;
                }
        assert_true(last <= rad_x1);
    }
    /* the sign reaches the radicand's ink bottom or below, like TeX's (a
    ** pixel of antialiasing) */
    assert_true(sign_bottom + 1 >= bottom);
    assert_true(sign_top <= top + 2);        /* joins the bar */
    cairo_surface_destroy(img);
    cf_label_destroy(lab);
    return sign_bottom - sign_top;
}

/* \sqrt as TeX sets it, measured on the pixels: a bar over the radicand
** joined to a radical sign that grows with the radicand. */
static void
test_sqrt(void **state)
{
    int bar_x, bar_y2, bar_frac, h_x, h_x2, h_frac;
    cf_label_t *lab;
    size_t i;
    (void)state;
    h_x = sqrt_pixels("\\sqrt{x}", &bar_x);
    h_x2 = sqrt_pixels("\\sqrt{x^2+y^2}", &bar_y2);
    h_frac = sqrt_pixels("\\sqrt{\\frac{1}{2}}", &bar_frac);
    /* the bar as long as the radicand is wide */
    assert_true(bar_y2 > 3 * bar_x);
    /* a taller radicand, a taller sign: a fraction needs 1.39 em (its
    ** 1.3 em, the gap and the rule) where x fits the base sign's 1 em;
    ** 8 px per bp of a 10 bp label */
    assert_true(h_frac >= 1.3 * h_x);
    assert_true(h_x2 >= h_x);
    /* \sqrt[3]{x}: the degree two levels down, left of the sign and above
    ** its middle */
    lab = layout("\\sqrt[3]{x}");
    {
        const cf_label_box_t *three = box_of(lab, "3"), *x = box_of(lab, "x");
        tu_assert_close(three->size, 0.5 * SIZE, 1e-12, 0);
        assert_true(three->x < x->x);
        assert_true(three->y > 0.2 * SIZE);
    }
    cf_label_destroy(lab);
    /* \frac14 is \frac{1}{4}; \binom and \left( \right) stack and size */
    lab = layout("\\frac14");
    assert_int_equal(cf_label_box_count(lab), 3);
    assert_true(box_of(lab, "1")->y > 0 && box_of(lab, "4")->y < 0);
    cf_label_destroy(lab);
    lab = layout("\\left( \\frac{a}{b} \\right)");
    {
        double w, a, d;
        cf_label_get_extents(lab, &w, &a, &d);
        for (i = 0; i < cf_label_box_count(lab); i++)
            if (strcmp(cf_label_run_text(lab, i), "(") == 0)
                /* rule 19 asks 1.802 times a/b's 0.595 em from the
                ** axis: 1.07 em, past the base '(' (0.98 em) */
                assert_true(cf_label_get_box(lab, i)->size > 1.05 * SIZE);
    }
    cf_label_destroy(lab);
    lab = layout("\\mathbb{R}^2 \\in \\binom{n}{k}");
    assert_string_equal(cf_label_run_text(lab, 0), "\xe2\x84\x9d");
    cf_label_destroy(lab);
}

/* An unknown command names the nearest known one and the list. */
static void
test_unknown_command_suggests(void **state)
{
    cf_label_t *lab = NULL;
    cf_diag_t d;
    (void)state;
    cf_diag_clear(&d);
    assert_int_not_equal(cf_label_create("\\sqrtt{2}", NULL, SIZE, &lab, &d),
                         CF_STATUS_OK);
    assert_non_null(strstr(d.msg, "did you mean \\sqrt?"));
    assert_non_null(strstr(d.msg, "curvefig help labels"));
    assert_int_not_equal(cf_label_create("\\left( x", NULL, SIZE, &lab, &d),
                         CF_STATUS_OK);
    assert_non_null(strstr(d.msg, "\\right"));
}

/* Letters of mathematics are TeX's math italic: the code points of Latin
** Modern Math's italic alphabet (P U+1D443, h U+210E, alpha U+1D6FC),
** \boldsymbol its bold italic, \mathcal its calligraphic capitals;
** digits stay upright text. */
static void
test_math_italic_alphabet(void **state)
{
    cf_label_t *lab;
    (void)state;
    lab = layout("P");
    assert_string_equal(cf_label_run_text(lab, 0), "\xf0\x9d\x91\x83");
    cf_label_destroy(lab);
    lab = layout("h");
    assert_string_equal(cf_label_run_text(lab, 0), "\xe2\x84\x8e");
    cf_label_destroy(lab);
    lab = layout("\\alpha");
    assert_string_equal(cf_label_run_text(lab, 0), "\xf0\x9d\x9b\xbc");
    cf_label_destroy(lab);
    lab = layout("\\boldsymbol{a}");
    assert_string_equal(cf_label_run_text(lab, 0), "\xf0\x9d\x92\x82");
    cf_label_destroy(lab);
    lab = layout("\\mathcal{A}\\mathcal{B}");
    assert_string_equal(cf_label_run_text(lab, 0),
                        "\xf0\x9d\x92\x9c\xe2\x84\xac");
    cf_label_destroy(lab);
    lab = layout("12");
    assert_string_equal(cf_label_run_text(lab, 0), "12");
    cf_label_destroy(lab);
    /* a sans family keeps its own italic: letters stay ASCII */
    {
        cf_label_t *l2 = NULL;
        assert_int_equal(cf_label_create("x", "Latin Modern Sans", SIZE, &l2,
                                         NULL), CF_STATUS_OK);
        assert_string_equal(cf_label_run_text(l2, 0), "x");
        assert_true(cf_label_get_box(l2, 0)->italic);
        cf_label_destroy(l2);
    }
}

/* The gap between the advance of box a and the start of box b. */
static double
gap(const cf_label_t *lab, size_t a, size_t b)
{
    const cf_label_box_t *ba = cf_label_get_box(lab, a);
    const cf_label_box_t *bb = cf_label_get_box(lab, b);
    return bb->x - (ba->x + ba->width);
}

/* TeX's spaces between atoms, in mu of the quad (18 mu = SIZE): 4 mu
** around a binary operator, 5 around a relation, 3 after a comma, none
** after a unary minus; spaces typed in mathematics are ignored; \, \: \;
** \quad are 3, 4, 5 and 18 mu; scripts get no medium or thick space. */
static void
test_math_spacing(void **state)
{
    const double mu = SIZE / 18;
    cf_label_t *lab, *l2;
    (void)state;
    lab = layout("1+2=3,4");
    assert_int_equal(cf_label_box_count(lab), 7);
    assert_true(fabs(gap(lab, 0, 1) - 4 * mu) < 1e-9);
    assert_true(fabs(gap(lab, 1, 2) - 4 * mu) < 1e-9);
    assert_true(fabs(gap(lab, 2, 3) - 5 * mu) < 1e-9);
    assert_true(fabs(gap(lab, 3, 4) - 5 * mu) < 1e-9);
    assert_true(fabs(gap(lab, 5, 6) - 3 * mu) < 1e-9);
    /* spaces are ignored: the same layout */
    l2 = layout("1 + 2  =  3, 4");
    assert_int_equal(cf_label_box_count(l2), 7);
    assert_true(fabs(cf_label_get_box(l2, 6)->x
                     - cf_label_get_box(lab, 6)->x) < 1e-9);
    cf_label_destroy(l2);
    cf_label_destroy(lab);
    /* a unary minus: no space after it, and (-1) neither */
    lab = layout("-1");
    assert_true(fabs(cf_label_get_box(lab, 0)->x) < 1e-9);
    assert_true(fabs(gap(lab, 0, 1)) < 1e-9);
    cf_label_destroy(lab);
    lab = layout("1\\,2\\:3\\;4\\quad5");
    assert_true(fabs(gap(lab, 0, 1) - 3 * mu) < 1e-9);
    assert_true(fabs(gap(lab, 1, 2) - 4 * mu) < 1e-9);
    assert_true(fabs(gap(lab, 2, 3) - 5 * mu) < 1e-9);
    assert_true(fabs(gap(lab, 3, 4) - 18 * mu) < 1e-9);
    cf_label_destroy(lab);
    /* in a script, + gets no medium space */
    lab = layout("x_{1+2}");
    assert_true(fabs(gap(lab, 1, 2)) < 1e-9);
    cf_label_destroy(lab);
}

/* \ge and \le are U+2265 and U+2264 from the math font (TeX's shapes,
** not the slanted U+2A7E); \overline puts a rule over its group. */
static void
test_relations_and_overline(void **state)
{
    cf_label_t *lab;
    const cf_label_box_t *rule = NULL, *a;
    size_t i;
    (void)state;
    lab = layout("a\\ge b\\le c");
    assert_string_equal(cf_label_run_text(lab, 1), "\xe2\x89\xa5");
    assert_string_equal(cf_label_run_text(lab, 3), "\xe2\x89\xa4");
    cf_label_destroy(lab);
    lab = layout("\\overline{AB}");
    for (i = 0; i < cf_label_box_count(lab); i++)
        if (cf_label_run_text(lab, i)[0] == '\0')
            rule = cf_label_get_box(lab, i);
    assert_non_null(rule);
    a = cf_label_get_box(lab, 0);
    assert_true(fabs(rule->x - a->x) < 1e-9);
    assert_true(rule->width >= a->width - 1e-9);
    assert_true(rule->y > 0.6 * SIZE);
    cf_label_destroy(lab);
    assert_int_not_equal(cf_label_create("\\mathcal{a}", NULL, SIZE, &lab,
                                         NULL), CF_STATUS_OK);
}

/* Every command of the list `curvefig help labels` prints parses. */
static void
visit_parse(const char *kind, const char *name, const char *what, void *ctx)
{
    char text[64];
    cf_label_t *lab = NULL;
    cf_diag_t d;
    size_t *n = ctx;
    (void)what;
    if (strcmp(kind, "structure") == 0)
        snprintf(text, sizeof text, strcmp(name, "left") == 0
                 ? "\\%s(A\\right)"
                 : strcmp(name, "frac") == 0 || strcmp(name, "binom") == 0
                 ? "\\%s{A}{B}" : "\\%s{A}", name);
    else if (strcmp(kind, "accent") == 0)
        snprintf(text, sizeof text, "\\%s{x}", name);
    else
        snprintf(text, sizeof text, "a\\%s b", name);
    cf_diag_clear(&d);
    if (cf_label_create(text, NULL, SIZE, &lab, &d) != CF_STATUS_OK)
        fail_msg("%s \"%s\": %s", kind, text, d.msg);
    cf_label_destroy(lab);
    (*n)++;
}

static void
test_every_listed_command_parses(void **state)
{
    size_t n = 0;
    (void)state;
    cf_label_each_command(visit_parse, &n);
    assert_true(n > 100);
}

/* The glyph table of a course page (render/labels/font-table.c): a text
** composed from its characters is placed as pango places glyphs, every
** advance and ink box rounded to units of 1/1024 bp on its own (worked
** out by hand below), a text shaped at export is those numbers, and a line
** that is not glyph data is named by its number. */
static void
test_font_table(void **state)
{
    static const char data[] =
        "curvefig-glyphs 1\n"
        "D 0 0 0 0.8 0.2 Fam\n"
        "G 0 5 0.1 -0.7 0.5 0 M 0.1 0 L 0.5 0 L 0.5 -0.7 Z\n"
        "C 0 65 0 5 0.6\n"
        "K 0 65 65 -0.05\n"
        "S 0 10240 8000 0 0 100 200 1 2 3 4 0 1 0 5 7 8000 1 A\n";
    cf__font_table_t *t = cf__font_table_create();
    cf__fonts_t f;
    cf__font_req_t req = { "Fam", false, false, 10, "AA", 2 };
    cf__font_shape_t sh;
    cf__pathb_t out;
    void *run = NULL;
    int bad = -1;
    (void)state;
    assert_non_null(t);
    assert_int_equal(cf__font_table_load(t, data, strlen(data), &bad), 0);
    f = cf__font_table_fonts(t);
    assert_int_equal(f.shape(f.open(f.self), &req, &run, &sh), 0);
    /* baseline 0.8 * 10 bp; the first A's advance 0.6 - 0.05 (the kern of
    ** the pair), the second's 0.6: 5.5 + 6 bp */
    assert_int_equal(sh.baseline, 8192);
    assert_int_equal(sh.logical[2], 5632 + 6144);
    assert_int_equal(sh.logical[3], 8192 + 2048);
    /* ink: from the first A's 0.1 * 10 bp to the second's 5.5 + 5 bp,
    ** from 7 bp above the baseline to it */
    assert_int_equal(sh.ink[0], 1024);
    assert_int_equal(sh.ink[2], 5632 + 5120 - 1024);
    assert_int_equal(sh.ink[1], 8192 - 7168);
    assert_int_equal(sh.ink[3], 7168);
    assert_int_equal(sh.unknown, 0);
    /* its outline: two glyphs of M L L Z, the second 5.5 bp on */
    memset(&out, 0, sizeof out);
    f.outline(f.self, run, 0, 0, &out);
    assert_int_equal(out.nsegs, 8);
    assert_true(out.segs[4] == CF__SEG_MOVE);
    assert_true(fabs(out.coords[6] - (5.5 + 1)) < 1e-12);
    assert_true(fabs(out.coords[7] - 8) < 1e-12);
    cf__pathb_free(&out);
    /* a character without data: unknown, no glyph */
    req.text = "AB";
    assert_int_equal(f.shape(f.self, &req, &run, &sh), 0);
    assert_int_equal(sh.unknown, 1);
    assert_int_equal(sh.logical[2], 6144);
    /* "A" at 10 bp was shaped at export: its numbers as written */
    req.text = "A";
    req.len = 1;
    assert_int_equal(f.shape(f.self, &req, &run, &sh), 0);
    assert_int_equal(sh.baseline, 8000);
    assert_int_equal(sh.logical[2], 100);
    assert_int_equal(sh.ink[3], 4);
    f.release(run);
    /* line 3 is not glyph data */
    {
        static const char bad_data[] = "curvefig-glyphs 1\nD 0 0 0 1 0 F\n"
                                       "X 1 2\n";
        assert_int_equal(cf__font_table_load(t, bad_data, strlen(bad_data),
                                             &bad), -1);
    }
    assert_int_equal(bad, 3);
    cf__font_table_destroy(t);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_subscript_lower_and_smaller),
        cmocka_unit_test(test_superscript_and_sub_stack),
        cmocka_unit_test(test_italic_correction),
        cmocka_unit_test(test_group_subscript_and_minus),
        cmocka_unit_test(test_nested_scripts_and_greek),
        cmocka_unit_test(test_text_and_math_modes),
        cmocka_unit_test(test_fraction),
        cmocka_unit_test(test_sqrt),
        cmocka_unit_test(test_unknown_command_suggests),
        cmocka_unit_test(test_world_scripts_have_glyphs),
        cmocka_unit_test(test_syntax_errors),
        cmocka_unit_test(test_tex_points),
        cmocka_unit_test(test_label_tex),
        cmocka_unit_test(test_math_italic_alphabet),
        cmocka_unit_test(test_math_spacing),
        cmocka_unit_test(test_relations_and_overline),
        cmocka_unit_test(test_every_listed_command_parses),
        cmocka_unit_test(test_out_of_memory),
        cmocka_unit_test(test_font_table),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
