/* Label syntax and layout: scripts, stacking, fonts, scripts of the world,
** syntax errors.  Labels as TeX source and the commands of mathematics are
** in test_label_tex.c, the shared helpers in test_label.h. */
#include "test_label.h"
#include "font-table.h"

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
        /* the layers below the output are given the fonts: none is an
        ** error, not a crash */
        lab = (cf_label_t *)&lab;
        assert_int_equal(cf__label_create(NULL, "x", NULL, SIZE, &lab, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_null(lab);
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
        cmocka_unit_test(test_world_scripts_have_glyphs),
        cmocka_unit_test(test_syntax_errors),
        cmocka_unit_test(test_tex_points),
        cmocka_unit_test(test_out_of_memory),
        cmocka_unit_test(test_font_table),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
