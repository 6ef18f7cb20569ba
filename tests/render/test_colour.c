/* Colour vision (render/figure/colour-vision.c) and the figure's colour
** check (cf_figure_colour_check): CIEDE2000 against the test data Sharma,
** Wu and Dalal publish with their formula; CIELAB of sRGB red and white;
** the simulations against Machado et al.'s table and their own
** properties -- greys stay put, and a dichromat's matrix loses one
** direction of colour, so that two colours apart along it look alike --;
** the palettes apart under every vision; palette names checked with the
** nearest one named; the check naming a red/green pair of lines under
** deuteranopia and letting it be once the lines differ in dash, and its
** structured report (the clashes, their distances and paints); a net's
** levels told apart by dash and marker with the theme's redundant. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/figure.h"
#include "figure/colour-vision.h"
#include "output/colour-check.h"

static void
near(double got, double want, double tol)
{
    if (!(fabs(got - want) <= tol)) {
        fprintf(stderr, "got %.6f, want %.6f (tol %g)\n", got, want, tol);
        fail();
    }
}

/* Sharma, Wu, Dalal, "The CIEDE2000 color-difference formula:
** implementation notes, supplementary test data, and mathematical
** observations", Color Res. Appl. 30 (2005), Table 1: pairs 1, 7, 17, 25,
** 34 with their distances (4 decimals published). */
static void
test_ciede2000_sharma(void **state)
{
    static const double pairs[][7] = {
        { 50, 2.6772, -79.7751, 50, 0, -82.7485, 2.0425 },
        { 50, 0, 0, 50, -1, 2, 2.3669 },
        { 50, 2.5, 0, 73, 25, -18, 27.1492 },
        { 60.2574, -34.0099, 36.2677, 60.4626, -34.1751, 39.4387, 1.2644 },
        { 22.7233, 20.0904, -46.6940, 23.0331, 14.9730, -42.5619, 2.0373 },
    };
    (void)state;
    for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; i++) {
        near(cf__ciede2000(pairs[i], pairs[i] + 3), pairs[i][6], 5e-5);
        /* symmetric */
        near(cf__ciede2000(pairs[i] + 3, pairs[i]), pairs[i][6], 5e-5);
    }
}

/* sRGB red is L* 53.24, a* 80.09, b* 67.20 (D65); white L* 100, a* b* 0 */
static void
test_lab(void **state)
{
    double red[3] = { 1, 0, 0 }, white[3] = { 1, 1, 1 }, lab[3];
    (void)state;
    cf__lab_from_linear(red, lab);
    near(lab[0], 53.24, 0.01);
    near(lab[1], 80.09, 0.01);
    near(lab[2], 67.20, 0.01);
    cf__lab_from_linear(white, lab);
    near(lab[0], 100, 1e-3);
    near(lab[1], 0, 1e-3);
    near(lab[2], 0, 1e-3);
}

/* Machado et al. 2009, Table 1, severity 1.0: a primary's simulation is
** its column of the matrix (clipped to [0, 1]). */
static void
test_machado_columns(void **state)
{
    static const double table[3][3][3] = {
        { { 0.152286, 1.052583, -0.204868 },
          { 0.114503, 0.786281, 0.099216 },
          { -0.003882, -0.048116, 1.051998 } },
        { { 0.367322, 0.860646, -0.227968 },
          { 0.280085, 0.672501, 0.047413 },
          { -0.011820, 0.042940, 0.968881 } },
        { { 1.255528, -0.076749, -0.178779 },
          { -0.078411, 0.930809, 0.147602 },
          { 0.004733, 0.691367, 0.303900 } },
    };
    (void)state;
    for (int v = 0; v < 3; v++)
        for (int j = 0; j < 3; j++) {
            double rgb[3] = { 0, 0, 0 }, out[3];
            rgb[j] = 1;   /* sRGB 1 is linear 1 */
            cf__vision_simulate((cf__vision_t)(CF__VISION_PROTAN + v), rgb,
                                out);
            for (int i = 0; i < 3; i++) {
                double want = table[v][i][j];
                near(out[i], want < 0 ? 0 : want > 1 ? 1 : want, 1e-12);
            }
        }
}

/* Greys look the same to every vision: the rows sum to 1. */
static void
test_greys_stay(void **state)
{
    (void)state;
    for (int v = CF__VISION_NORMAL; v < CF__VISION_LAST_; v++)
        for (double g = 0; g <= 1.0; g += 0.125) {
            double rgb[3] = { g, g, g }, out[3];
            cf__vision_simulate((cf__vision_t)v, rgb, out);
            for (int i = 0; i < 3; i++)
                near(out[i], cf__srgb_to_linear(g), 2e-6);
        }
}

/* A protanope's and a deuteranope's matrices are singular (rank 2; the
** tritanope's of Machado et al. is not): two colours apart along the null
** direction n (linear RGB) look alike to that vision, though they lie far
** apart for normal vision.  n is the cross product of two rows, read off
** the simulation itself. */
static void
test_confusion_line(void **state)
{
    (void)state;
    for (int v = CF__VISION_PROTAN; v <= CF__VISION_DEUTAN; v++) {
        double row[3][3], n[3], base[3] = { 0.35, 0.35, 0.35 }, a[3], b[3];
        double sa[3], sb[3], k = 1e9, len;
        cf_color_t ca, cb;
        /* the matrix read off the simulation of mid-grey plus a little of
        ** each primary (inside [0, 1]: no clipping) */
        for (int j = 0; j < 3; j++) {
            double lin0[3], lin1[3], rgb[3];
            double g = 0.5, lg = cf__srgb_to_linear(g);
            double d = 0.05;
            rgb[0] = rgb[1] = rgb[2] = g;
            cf__vision_simulate((cf__vision_t)v, rgb, lin0);
            /* sRGB value whose linear is lg + d */
            rgb[j] = 1.055 * pow(lg + d, 1 / 2.4) - 0.055;
            cf__vision_simulate((cf__vision_t)v, rgb, lin1);
            for (int i = 0; i < 3; i++)
                row[i][j] = (lin1[i] - lin0[i]) / d;
        }
        n[0] = row[0][1] * row[1][2] - row[0][2] * row[1][1];
        n[1] = row[0][2] * row[1][0] - row[0][0] * row[1][2];
        n[2] = row[0][0] * row[1][1] - row[0][1] * row[1][0];
        len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int i = 0; i < 3; i++) {
            n[i] /= len;
            if (fabs(n[i]) > 1e-9) {
                double lim = (0.3 / fabs(n[i]));   /* stay in [0.05, 0.65] */
                k = lim < k ? lim : k;
            }
        }
        /* the third row lies in the span of the first two */
        near(row[2][0] * n[0] + row[2][1] * n[1] + row[2][2] * n[2], 0,
             2e-3);
        for (int i = 0; i < 3; i++) {
            a[i] = base[i] + k * n[i];
            b[i] = base[i] - k * n[i];
            /* to sRGB */
            sa[i] = a[i] <= 0.0031308 ? 12.92 * a[i]
                                      : 1.055 * pow(a[i], 1 / 2.4) - 0.055;
            sb[i] = b[i] <= 0.0031308 ? 12.92 * b[i]
                                      : 1.055 * pow(b[i], 1 / 2.4) - 0.055;
        }
        ca = (cf_color_t){ sa[0], sa[1], sa[2], 1 };
        cb = (cf_color_t){ sb[0], sb[1], sb[2], 1 };
        assert_true(cf__colour_distance(CF__VISION_NORMAL, ca, cb) > 20);
        assert_true(cf__colour_distance((cf__vision_t)v, ca, cb) < 1.5);
    }
}

/* The pair: the old default palette's orange and green (de
** Casteljau levels 2 and 3) under protanopia; the value of an independent
** Python implementation of the same formulas. */
static void
test_known_pair(void **state)
{
    cf_color_t orange = { 0xe8 / 255.0, 0x82 / 255.0, 0x1e / 255.0, 1 };
    cf_color_t green = { 0x2a / 255.0, 0x9d / 255.0, 0x3c / 255.0, 1 };
    (void)state;
    near(cf__colour_distance(CF__VISION_PROTAN, orange, green), 3.77, 0.01);
    near(cf__colour_distance(CF__VISION_NORMAL, orange, green), 49.66, 0.01);
}

/* The least distance of palette colours [0, n) (and extra, when not
** NULL) under vision v. */
static double
least(const cf_theme_t *th, size_t n, const cf_color_t *extra, int v)
{
    double m = 1e9;
    for (size_t i = 0; i < n; i++) {
        for (size_t j = i + 1; j < n; j++) {
            double d = cf__colour_distance((cf__vision_t)v, th->palette[i],
                                           th->palette[j]);
            m = d < m ? d : m;
        }
        if (extra != NULL) {
            double d = cf__colour_distance((cf__vision_t)v, th->palette[i],
                                           *extra);
            m = d < m ? d : m;
        }
    }
    return m;
}

/* default and okabe-ito: every two apart under each deficiency; greyscale: its greys
** and the polygon's (level 0 of a net) apart in greyscale. */
static void
test_palettes(void **state)
{
    cf_theme_t th;
    cf_diag_t diag;
    (void)state;
    assert_int_equal(cf_theme_get("default", &th, NULL), 0);
    /* the default: all apart, and apart from the polygon's grey, under
    ** each deficiency; the first three and that grey in greyscale too */
    assert_int_equal(th.palette_size, 8);
    for (int v = CF__VISION_NORMAL; v <= CF__VISION_TRITAN; v++)
        assert_true(least(&th, 8, &th.role[CF_ROLE_POLYGON].color, v)
                    >= CF__COLOUR_MIN_DE);
    for (int v = CF__VISION_NORMAL; v < CF__VISION_LAST_; v++)
        assert_true(least(&th, 3, &th.role[CF_ROLE_POLYGON].color, v)
                    >= CF__COLOUR_MIN_DE);
    assert_int_equal(cf_theme_set_palette(&th, "okabe-ito", NULL), 0);
    assert_int_equal(th.palette_size, 8);
    for (int v = CF__VISION_NORMAL; v <= CF__VISION_TRITAN; v++)
        assert_true(least(&th, 8, NULL, v) >= CF__COLOUR_MIN_DE);
    assert_int_equal(cf_theme_set_palette(&th, "greyscale", NULL), 0);
    assert_true(least(&th, th.palette_size,
                      &th.role[CF_ROLE_POLYGON].color, CF__VISION_GREY)
                >= CF__COLOUR_MIN_DE);
    assert_int_not_equal(cf_theme_set_palette(&th, "okabe_ito", &diag), 0);
    assert_non_null(strstr(diag.msg, "did you mean \"okabe-ito\""));
}

/* Two lines, red and green of one width and dash: a clash under
** deuteranopia, named; one of them dashed: none. */
/* A figure of a red line and a green one (dashed or not), their styles
** into red and green. */
static cf_figure_t *
red_green(bool dashed, cf_style_t *red, cf_style_t *green)
{
    static const double a[] = { 0, 0, 1, 1 }, b[] = { 0, 1, 1, 0 };
    cf_figure_t *fig;
    assert_int_equal(cf_figure_create(4, 3, CF_UNIT_CM, &fig, NULL), 0);
    cf_style_init(red);
    cf_style_init(green);
    red->set = green->set = CF_STYLE_COLOR;
    assert_int_equal(cf_color_parse("#d62728", &red->color, NULL), 0);
    assert_int_equal(cf_color_parse("#2ca02c", &green->color, NULL), 0);
    if (dashed) {
        green->set |= CF_STYLE_DASH;
        green->dash_count = 2;
        green->dash[0] = 3;
        green->dash[1] = 2;
    }
    assert_int_equal(cf_figure_add_polyline(fig, a, 2, false, red), 0);
    assert_int_equal(cf_figure_add_polyline(fig, b, 2, false, green), 0);
    return fig;
}

static void
test_check(void **state)
{
    cf_figure_t *fig;
    cf_style_t red, green;
    char *json;
    size_t size;
    (void)state;
    for (int dashed = 0; dashed < 2; dashed++) {
        fig = red_green(dashed, &red, &green);
        assert_int_equal(cf_figure_colour_check(fig, CF__COLOUR_MIN_DE,
                                                &json, &size, NULL), 0);
        assert_int_equal(strlen(json), size);
        if (dashed) {
            assert_null(strstr(json, "\"vision\""));
        } else {
            assert_non_null(strstr(json, "{\"vision\": \"deuteranopia\", "
                                         "\"paint\": \"line\""));
            assert_non_null(strstr(json, "\"index\": 1, \"color\": "
                                         "\"#d62728\""));
            assert_non_null(strstr(json, "\"index\": 2, \"color\": "
                                         "\"#2ca02c\""));
        }
        cf_free(json);
        cf_figure_destroy(fig);
    }
}

/* The check as a structure (colour-check.h), which `curvefig check`
** prints: red and green lines of one dash clash under exactly the visions
** that bring them closer than the threshold, each with the distances
** computed anew, the elements (from 1) and their colours; the JSON of
** cf_figure_colour_check is the report's. */
static void
test_report(void **state)
{
    cf_style_t red, green;
    cf_figure_t *fig = red_green(false, &red, &green);
    cf__colour_report_t r;
    char *json, *mine;
    size_t size, mysize, clashes = 0;
    double normal;
    (void)state;
    assert_int_equal(cf__colour_report(fig, CF__COLOUR_MIN_DE, &r, NULL), 0);
    assert_true(r.threshold == CF__COLOUR_MIN_DE);
    assert_int_equal(r.paints, 2);
    normal = cf__colour_distance(CF__VISION_NORMAL, red.color, green.color);
    assert_true(normal >= CF__COLOUR_MIN_DE);
    for (int v = CF__VISION_PROTAN; v < CF__VISION_LAST_; v++) {
        double d = cf__colour_distance((cf__vision_t)v, red.color,
                                       green.color);
        const cf__colour_clash_t *c = NULL;
        for (size_t k = 0; k < r.count; k++)
            if (r.clashes[k].vision == (cf__vision_t)v)
                c = &r.clashes[k];
        if (d >= CF__COLOUR_MIN_DE) {
            assert_null(c);
            continue;
        }
        assert_non_null(c);
        clashes++;
        assert_string_equal(c->paint, "line");
        assert_true(c->de == d && c->normal_de == normal);
        assert_string_equal(c->a.element, "polyline");
        assert_string_equal(c->b.element, "polyline");
        assert_true(c->a.number == 1 && c->a.rgb == 0xd62728);
        assert_true(c->b.number == 2 && c->b.rgb == 0x2ca02c);
    }
    assert_int_equal(r.count, clashes);
    assert_true(clashes >= 1);   /* deuteranopia at least (test_check) */
    assert_int_equal(cf__colour_report_json(&r, &mine, &mysize, NULL), 0);
    assert_int_equal(cf_figure_colour_check(fig, CF__COLOUR_MIN_DE, &json,
                                            &size, NULL), 0);
    assert_int_equal(size, mysize);
    assert_string_equal(json, mine);
    cf_free(json);
    cf_free(mine);
    cf__colour_report_fini(&r);
    assert_int_equal(cf__colour_report(fig, 0.0, &r, NULL),
                     CF_STATUS_INVALID_ARG);
    cf__colour_report_fini(&r);
    cf_figure_destroy(fig);
}

/* A cubic's de Casteljau net in Okabe and Ito's palette, whose orange and
** sky blue (levels 1 and 2) greyscale makes alike: a clash; with the
** theme's redundant = true the levels differ in dash and marker, and
** none is left. */
static void
test_redundant(void **state)
{
    static const double pts[] = { 0, 0, 1, 2, 3, 2, 4, 0,     /* level 0 */
                                  0.5, 1, 2, 2, 3.5, 1,       /* 1 */
                                  1.25, 1.5, 2.75, 1.5,       /* 2 */
                                  2, 1.5 };                   /* 3 */
    static const size_t counts[] = { 4, 3, 2, 1 };
    (void)state;
    for (int redundant = 0; redundant < 2; redundant++) {
        cf_figure_t *fig;
        cf_theme_t th;
        char *json;
        size_t size;
        assert_int_equal(cf_figure_create(6, 4, CF_UNIT_CM, &fig, NULL), 0);
        cf_figure_get_theme(fig, &th);
        assert_int_equal(cf_theme_set_palette(&th, "okabe-ito", NULL), 0);
        th.redundant = redundant;
        assert_int_equal(cf_figure_set_theme(fig, &th), 0);
        assert_int_equal(cf_figure_add_net(fig, pts, counts, 4, NULL, NULL),
                         0);
        assert_int_equal(cf_figure_colour_check(fig, CF__COLOUR_MIN_DE,
                                                &json, &size, NULL), 0);
        if (redundant)
            assert_null(strstr(json, "\"vision\""));
        else
            assert_non_null(strstr(json, "{\"vision\": \"greyscale\""));
        cf_free(json);
        cf_figure_destroy(fig);
    }
}

/* cf_theme_level_style: levels 1..6 each a dash pattern of their own,
** levels 1..5 a marker shape of their own (none the polygon's dot); a
** style's own dash and marker kept; level 0 and a theme without
** redundant left alone. */
static void
test_level_style(void **state)
{
    cf_theme_t th;
    cf_style_t s[7], own;
    (void)state;
    assert_int_equal(cf_theme_get("default", &th, NULL), 0);
    th.redundant = true;
    for (size_t j = 0; j < 7; j++) {
        cf_style_init(&s[j]);
        cf_theme_level_style(&th, j, &s[j]);
    }
    assert_int_equal(s[0].set, 0);
    for (size_t j = 1; j < 7; j++) {
        assert_true(s[j].set & CF_STYLE_DASH);
        assert_true(s[j].dash_count >= 2);
        for (size_t k = 1; k < j; k++)
            assert_false(s[j].dash_count == s[k].dash_count
                         && memcmp(s[j].dash, s[k].dash,
                                   s[j].dash_count * sizeof s[j].dash[0])
                             == 0);
        if (j <= 5) {
            assert_true(s[j].set & CF_STYLE_MARKER);
            assert_int_not_equal(s[j].marker,
                                 th.role[CF_ROLE_POLYGON].marker);
            for (size_t k = 1; k < j; k++)
                assert_int_not_equal(s[j].marker, s[k].marker);
        }
    }
    cf_style_init(&own);
    own.set = CF_STYLE_DASH | CF_STYLE_MARKER;
    own.marker = CF_MARKER_CROSS;
    cf_theme_level_style(&th, 2, &own);
    assert_int_equal(own.dash_count, 0);
    assert_int_equal(own.marker, CF_MARKER_CROSS);
    th.redundant = false;
    cf_style_init(&own);
    cf_theme_level_style(&th, 2, &own);
    assert_int_equal(own.set, 0);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ciede2000_sharma),
        cmocka_unit_test(test_lab),
        cmocka_unit_test(test_machado_columns),
        cmocka_unit_test(test_greys_stay),
        cmocka_unit_test(test_confusion_line),
        cmocka_unit_test(test_known_pair),
        cmocka_unit_test(test_palettes),
        cmocka_unit_test(test_check),
        cmocka_unit_test(test_report),
        cmocka_unit_test(test_redundant),
        cmocka_unit_test(test_level_style),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
