/* Labels as TeX source (the PGF backend's), square roots, unknown commands
** and their suggestions, the math italic alphabet, TeX's spacing, relations
** and overlines, every listed command (the shared helpers in test_label.h). */
#include "test_label.h"

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

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sqrt),
        cmocka_unit_test(test_unknown_command_suggests),
        cmocka_unit_test(test_label_tex),
        cmocka_unit_test(test_math_italic_alphabet),
        cmocka_unit_test(test_math_spacing),
        cmocka_unit_test(test_relations_and_overline),
        cmocka_unit_test(test_every_listed_command_parses),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
