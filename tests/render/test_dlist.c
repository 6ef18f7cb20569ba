/* The display list and its backends: one figure with every element kind is
** laid out into a display list; the dump, cairo and PGF backends are
** handed that same list, and what each gives is compared with the public
** functions' output, so the model and the layout are shown not to depend
** on the backend asked for. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "backend.h"
#include "curvefig/access.h"
#include "curvefig/bspline.h"
#include "curvefig/figure.h"
#include "grow.h"
#include "layout-private.h"
#include "output-private.h"

static int
square(void *closure, double x, double *y)
{
    (void)closure;
    *y = x * x;
    return 0;
}

/* A figure with every kind of element (and an automatic label place). */
static cf_figure_t *
every_kind(void)
{
    static const double ctrl[] = { 0, 0, 1, 2, 3, 2, 4, 0 };
    static const double quintic[] = { 0, 0, 1, 1, 2, -1, 3, 1, 4, 0, 5, 1 };
    static const double knots[] = { 0, 0, 0, 0, 0.5, 1, 1, 1, 1 };
    static const double spline[] = { 0, 1, 1, 3, 2, 0, 3, 3, 4, 1 };
    static const double net[] = { 0, 0, 1, 2, 3, 2, 0.5, 1, 2, 2, 1.25, 1.5 };
    static const size_t counts[] = { 3, 2, 1 };
    static const double tri[] = { 0, 0, 4, 0, 2, 3 };
    static const double tangents[] = { 1, 0, 0, 1 };
    static const double axknots[] = { 0, 0.5, 0.5, 1 };
    static const char *const knot_labels[] = { "u_0", "u_1", "u_2", "u_3" };
    cf_figure_t *fig = NULL;
    cf_bezier_t *c = NULL, *q = NULL, *g = NULL;
    cf_bspline_t *s = NULL;
    cf_style_t st, auto_place, dashed;
    cf_axes_t ax;
    double y01[] = { 0.2, 0.8 }, breaks[] = { 0, 4 };
    const cf_bezier_t *pieces[1];

    assert_int_equal(cf_figure_create(8, 6, CF_UNIT_CM, &fig, NULL), 0);
    assert_int_equal(cf_bezier_create(2, 3, ctrl, NULL, &c, NULL), 0);
    assert_int_equal(cf_bezier_create(2, 5, quintic, NULL, &q, NULL), 0);
    assert_int_equal(cf_bezier_create(1, 1, y01, NULL, &g, NULL), 0);
    assert_int_equal(cf_bspline_create(2, 3, knots, 9, spline, 5, NULL, &s,
                                       NULL), 0);
    cf_style_init(&st);
    cf_style_init(&auto_place);
    auto_place.set = CF_STYLE_PLACE | CF_STYLE_HALO;
    auto_place.place = CF_PLACE_AUTO;
    auto_place.halo = 1.5;
    cf_style_init(&dashed);
    dashed.set = CF_STYLE_DASH;
    dashed.dash[0] = 3;
    dashed.dash[1] = 2;
    dashed.dash_count = 2;
    cf_axes_init(&ax);
    ax.xmin = -0.5;
    ax.xmax = 5;
    ax.ymin = -1;
    ax.ymax = 3.5;
    ax.grid = true;
    ax.knots = axknots;
    ax.knot_count = 4;
    ax.knot_labels = knot_labels;
    ax.xlabel = "t";
    ax.ylabel = "N_i^3(t)";
    pieces[0] = g;
    assert_int_equal(cf_figure_add_axes(fig, &ax, NULL), 0);
    assert_int_equal(cf_figure_add_fill(fig, tri, 3, NULL), 0);
    assert_int_equal(cf_figure_add_hull(fig, ctrl, 4, NULL), 0);
    assert_int_equal(cf_figure_add_polygon(fig, ctrl, 4, NULL), 0);
    assert_int_equal(cf_figure_add_bezier(fig, c, NULL), 0);
    assert_int_equal(cf_figure_add_bezier(fig, q, &dashed), 0);
    assert_int_equal(cf_figure_add_bspline(fig, s, 0, 0, NULL), 0);
    assert_int_equal(cf_figure_add_bspline_knots(fig, s, NULL), 0);
    assert_int_equal(cf_figure_add_knot_marks(fig, ctrl, tangents, 2, NULL),
                     0);
    assert_int_equal(cf_figure_add_polyline(fig, tri, 3, true, &dashed), 0);
    assert_int_equal(cf_figure_add_points(fig, tri, 3, NULL), 0);
    assert_int_equal(cf_figure_add_net(fig, net, counts, 3, NULL, NULL), 0);
    assert_int_equal(cf_figure_add_arrow(fig, 0, 0, 1, 1, NULL), 0);
    assert_int_equal(cf_figure_add_graph(fig, pieces, breaks, 1, NULL), 0);
    assert_int_equal(cf_figure_add_basis(fig, knots, 9, 2, 3, NULL), 0);
    assert_int_equal(cf_figure_add_function(fig, square, NULL, 0, 1.5, NULL),
                     0);
    assert_int_equal(cf_figure_add_label(fig, 3, 2, "P_3", &auto_place), 0);
    assert_int_equal(cf_figure_add_label(fig, 1, 2, "\\hat{P}_1", &st), 0);
    cf_bezier_destroy(c);
    cf_bezier_destroy(q);
    cf_bezier_destroy(g);
    cf_bspline_destroy(s);
    return fig;
}

static char *
dump(cf_figure_t *fig)
{
    char *text = NULL;
    size_t size = 0;
    cf_diag_t d;
    cf_diag_clear(&d);
    if (cf_figure_dump(fig, NULL, &text, &size, &d) != CF_STATUS_OK)
        fail_msg("dump: %s", d.msg);
    assert_int_equal(strlen(text), size);
    return text;
}

/* The display list the output functions build: layout, then the list. */
static void
build(cf_figure_t *fig, cf__dl_t *dl, cf__page_t *page)
{
    cf__layout_t lay;
    cf__dl_init(dl);
    assert_int_equal(cf__figure_layout(fig, &lay), 0);
    assert_int_equal(cf__figure_build(fig, &lay, dl), 0);
    memset(page, 0, sizeof *page);
    cf_figure_get_size(fig, &page->width, &page->height);
    page->background = fig->theme.background;
}

static size_t
count_lines(const char *text, const char *prefix)
{
    size_t n = 0, k = strlen(prefix);
    const char *p = text;
    while (p != NULL && *p != '\0') {
        if (strncmp(p, prefix, k) == 0)
            n++;
        p = strchr(p, '\n');
        if (p != NULL)
            p++;
    }
    return n;
}

/* The place number in the dump of the label with this source. */
static int
label_place(const char *text, const char *src)
{
    char key[64];
    const char *q;
    int place = -1;
    snprintf(key, sizeof key, "text \"%s\"", src);
    q = strstr(text, key);
    assert_non_null(q);
    q = strstr(q, " place ");
    assert_non_null(q);
    assert_int_equal(sscanf(q, " place %d", &place), 1);
    return place;
}

/* The dump names every element kind once per element, carries the
** labels' TeX-like sources and their placement, and paths with cubic
** segments, dashes and fills. */
static void
test_dump_content(void **state)
{
    static const char *const kinds[] = {
        "axes", "fill", "hull", "polygon", "curve", "knot marks",
        "polyline", "points", "net", "arrow", "label"
    };
    cf_figure_t *fig = every_kind();
    char *text = dump(fig), line[64];
    const char *p;
    size_t i;
    (void)state;
    assert_int_equal(count_lines(text, "page "), 1);
    assert_int_equal(count_lines(text, "group "), 18);
    assert_int_equal(count_lines(text, "end\n"), 18);
    for (i = 0; i < sizeof kinds / sizeof kinds[0]; i++) {
        snprintf(line, sizeof line, " %s\n", kinds[i]);
        assert_non_null(strstr(text, line));
    }
    /* six curves: Bézier, quintic, B-spline, graph, basis, function */
    for (i = 0, p = text; (p = strstr(p, " curve\n")) != NULL; p++)
        i++;
    assert_int_equal(i, 6);
    assert_non_null(strstr(text, "text \"P_3\" anchor "));
    assert_non_null(strstr(text, "text \"\\\\hat{P}_1\" anchor "));
    assert_non_null(strstr(text, "text \"N_i^3(t)\" anchor "));
    assert_non_null(strstr(text, " halo 1.5 "));
    assert_non_null(strstr(text, " dash 2 3 2 :"));
    assert_non_null(strstr(text, "path fill "));
    assert_non_null(strstr(text, " C "));
    assert_non_null(strstr(text, "marker tick "));
    /* the automatic label got a place: not CF_PLACE_AUTO; so did the
    ** label given none (automatic by default) */
    assert_int_not_equal(label_place(text, "P_3"), (int)CF_PLACE_AUTO);
    assert_int_not_equal(label_place(text, "\\\\hat{P}_1"), (int)CF_PLACE_AUTO);
    assert_int_not_equal(label_place(text, "\\\\hat{P}_1"), (int)CF_PLACE_CENTER);
    cf_free(text);
    cf_figure_destroy(fig);
}

/* The list the dump backend is handed is the one the cairo backend
** consumes: the SVG and the PNG drawn from this very list equal the public
** renderer's files, its dump equals cf_figure_dump's, and using one backend
** changes nothing the other sees. */
static void
test_backend_independence(void **state)
{
    static const cf_format_t formats[] = { CF_FORMAT_SVG, CF_FORMAT_PNG,
                                           CF_FORMAT_PDF, CF_FORMAT_PGF };
    cf_figure_t *fig = every_kind();
    cf__dl_t dl;
    cf__page_t page;
    cf__dump_t d;
    char *before = dump(fig), *after;
    size_t f;
    (void)state;
    build(fig, &dl, &page);
    memset(&d, 0, sizeof d);
    assert_int_equal(cf__dl_play_page(&dl, &page, &cf__dump_backend, &d), 0);
    assert_string_equal(d.text, before);
    for (f = 0; f < sizeof formats / sizeof formats[0]; f++) {
        unsigned char *data = NULL;
        char *alt = NULL, *desc = NULL;
        size_t size = 0;
        cf__buf_t mine;
        memset(&mine, 0, sizeof mine);
        assert_int_equal(cf_figure_render(fig, formats[f], NULL, &data,
                                          &size, NULL), 0);
        cf__page_t pg = page;
        /* the page is painted in PNG only (CF_BACKGROUND_AUTO) */
        if (formats[f] != CF_FORMAT_PNG)
            pg.background.a = 0;
        /* with the text every file carries (docs/accessibility.md) */
        assert_int_equal(cf_figure_alt_text(fig, &alt), CF_STATUS_OK);
        assert_int_equal(cf_figure_description(fig, &desc), CF_STATUS_OK);
        assert_int_equal(cf__format_render(formats[f], &dl, &pg, 150,
                                           alt, desc, &mine, NULL), 0);
        cf_free(alt);
        cf_free(desc);
        assert_int_equal(mine.size, size);
        assert_memory_equal(mine.data, data, size);
        cf__buf_free(&mine);
        cf_free(data);
    }
    after = dump(fig);
    assert_string_equal(after, before);
    cf_free(d.text);
    cf_free(before);
    cf_free(after);
    cf__dl_free(&dl);
    cf_figure_destroy(fig);
}

static size_t
count_str(const char *text, const char *s)
{
    size_t n = 0;
    const char *p = text;
    while ((p = strstr(p, s)) != NULL) {
        n++;
        p += strlen(s);
    }
    return n;
}

/* The PGF backend handed the list: a pgfscope per group and per clip, all
** closed; a \pgftext per label (none of the figure's needs outlines;
** eight more per halo); every cubic of the list a \pgfpathcurveto, every
** dash a \pgfsetdash; the page as the bounding box.  A group with an
** overlay specification is \visible<spec>{...}, and the dump shows it. */
static void
test_pgf_backend(void **state)
{
    cf_figure_t *fig = every_kind();
    cf__dl_t dl;
    cf__page_t page;
    cf__buf_t out;
    cf__pgf_t g;
    cf__dump_t d;
    char *text, *dumped, want[96];
    size_t groups, texts, halos, curves, dashes, clips;
    (void)state;
    build(fig, &dl, &page);
    memset(&d, 0, sizeof d);
    assert_int_equal(cf__dl_play_page(&dl, &page, &cf__dump_backend, &d), 0);
    dumped = d.text;
    groups = count_lines(dumped, "group ");
    texts = count_lines(dumped, "text ");
    halos = count_str(dumped, " halo ");
    curves = count_str(dumped, " C ");
    dashes = count_str(dumped, " dash ") - count_str(dumped, " dash 0 ");
    clips = count_lines(dumped, "clip ") - count_lines(dumped, "clip none");

    dl.ops[0].u.group.overlay = "2-";
    memset(&out, 0, sizeof out);
    memset(&g, 0, sizeof g);
    g.out = &out;
    assert_int_equal(cf__dl_play_page(&dl, &page, &cf__pgf_backend, &g), 0);
    cf__pgf_fini(&g);
    assert_int_equal(cf__buf_append(&out, "", 1), 0);
    text = (char *)out.data;
    assert_int_equal(count_str(text, "\\begin{pgfscope}% "), groups);
    assert_int_equal(count_str(text, "\\begin{pgfscope}"),
                     count_str(text, "\\end{pgfscope}"));
    assert_int_equal(count_str(text, "\\pgftext["), texts + 24 * halos);
    assert_true(count_str(text, "\\pgfpathcurveto") >= curves);
    assert_true(dashes > 0);
    assert_int_equal(count_str(text, "\\pgfsetdash{"), dashes);
    assert_int_equal(count_str(text, "\\pgfusepath{clip}"), clips);
    assert_int_equal(count_str(text, "\\begin{pgfpicture}"), 1);
    assert_non_null(strstr(text, "\\end{pgfpicture}%\n"));
    assert_non_null(strstr(text, "\\pgfusepath{use as bounding box}"));
    snprintf(want, sizeof want, "\\visible<2->{\\begin{pgfscope}%% 0 %s\n",
             dl.ops[0].u.group.name);
    assert_non_null(strstr(text, want));
    assert_int_equal(count_str(text, "\\fi\\visible<"), 1);
    cf_free(d.text);
    memset(&d, 0, sizeof d);
    assert_int_equal(cf__dl_play_page(&dl, &page, &cf__dump_backend, &d), 0);
    snprintf(want, sizeof want, "group 0 %s overlay 2-\n",
             dl.ops[0].u.group.name);
    assert_non_null(strstr(d.text, want));
    cf_free(d.text);
    cf__buf_free(&out);
    cf__dl_free(&dl);
    cf_figure_destroy(fig);
}

/* Labels TeX cannot set (Cyrillic) are written as curvefig's glyph
** outlines: all of them, wherever the label lies on the page.  The box of
** the outline points of each label equals the ink box pango gives the
** label (the text op's), to a small fraction of a bp (the outlines' Bézier
** control points lie on or just outside the glyphs' ink). */
static void
test_pgf_outlines_whole(void **state)
{
    static const double at[][2] = { { 0.5, 0.5 }, { 7, 1 }, { 4, 5.5 } };
    cf_figure_t *fig = NULL;
    cf_style_t st;
    cf__dl_t dl;
    cf__page_t page;
    cf__buf_t out;
    cf__pgf_t g;
    const char *p;
    size_t i, k = 0;
    (void)state;
    assert_int_equal(cf_figure_create(8, 6, CF_UNIT_CM, &fig, NULL), 0);
    assert_int_equal(cf_figure_set_window(fig, 0, 8, 0, 6), 0);
    cf_style_init(&st);
    st.set = CF_STYLE_PLACE;
    st.place = CF_PLACE_CENTER;
    for (i = 0; i < 3; i++)
        assert_int_equal(cf_figure_add_label(fig, at[i][0], at[i][1],
                                             "Кривая Безье", &st), 0);
    build(fig, &dl, &page);
    memset(&out, 0, sizeof out);
    memset(&g, 0, sizeof g);
    g.out = &out;
    assert_int_equal(cf__dl_play_page(&dl, &page, &cf__pgf_backend, &g), 0);
    cf__pgf_fini(&g);
    assert_int_equal(cf__buf_append(&out, "", 1), 0);
    p = (const char *)out.data;
    for (i = 0; i < dl.count; i++) {
        const cf__text_op_t *t = &dl.ops[i].u.text;
        double b[4] = { INFINITY, INFINITY, -INFINITY, -INFINITY }, x, y;
        const char *end;
        if (dl.ops[i].kind != CF__OP_TEXT)
            continue;
        /* this label's outlines: from its scope to the next fill */
        p = strstr(p, "\\pgfpathmoveto");
        assert_non_null(p);
        end = strstr(p, "\\pgfusepath{fill}");
        assert_non_null(end);
        for (; p != NULL && p < end; p = strstr(p + 1, "{\\pgfqpoint{")) {
            if (sscanf(p, "%*[^{]{\\pgfqpoint{%lfbp}{%lfbp}}", &x, &y) != 2
                && sscanf(p, "{\\pgfqpoint{%lfbp}{%lfbp}}", &x, &y) != 2)
                continue;
            y = page.height - y;
            b[0] = fmin(b[0], x);
            b[1] = fmin(b[1], y);
            b[2] = fmax(b[2], x);
            b[3] = fmax(b[3], y);
        }
        /* across: the first and last glyphs' ink; up and down: at
        ** least the ink, at most 3 bp more (control points of the
        ** outlines off the glyphs) */
        assert_true(fabs(b[0] - (t->ox + t->ink[0])) < 0.5);
        assert_true(fabs(b[2] - (t->ox + t->ink[2])) < 0.5);
        assert_true(b[1] <= t->oy + t->ink[1] + 0.3
                    && b[1] >= t->oy + t->ink[1] - 3);
        assert_true(b[3] >= t->oy + t->ink[3] - 0.3
                    && b[3] <= t->oy + t->ink[3] + 3);
        p = end;
        k++;
    }
    assert_int_equal(k, 3);
    cf__buf_free(&out);
    cf__dl_free(&dl);
    cf_figure_destroy(fig);
}

/* Nothing in a dump depends on the run: two figures built alike dump
** alike, and a changed element changes the dump. */
static void
test_dump_deterministic(void **state)
{
    cf_figure_t *a = every_kind(), *b = every_kind();
    char *ta = dump(a), *tb = dump(b), *tc;
    (void)state;
    assert_string_equal(ta, tb);
    assert_int_equal(cf_figure_add_arrow(b, 1, 1, 0, 1, NULL), 0);
    tc = dump(b);
    assert_string_not_equal(ta, tc);
    cf_free(ta);
    cf_free(tb);
    cf_free(tc);
    cf_figure_destroy(a);
    cf_figure_destroy(b);
}

/* Ink outside a fixed page is an error naming the element and how far it
** sticks out; clipping or a tight page accepts it.  A figure that draws
** nothing is an error. */
static void
test_page_checks(void **state)
{
    static const double line[] = { 0, 0, 10, 10 };
    cf_figure_t *fig = NULL;
    cf_write_options_t tight;
    unsigned char *data = NULL;
    size_t size = 0;
    cf_style_t big;
    cf_diag_t d;
    double ink[4], pw, ph;
    (void)state;
    assert_int_equal(cf_figure_create(40, 30, CF_UNIT_MM, &fig, NULL), 0);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, NULL, &data, &size,
                                      &d), CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(d.msg, "the figure draws nothing (0 elements"));
    assert_null(data);
    /* elements, all outside an explicit window: nothing drawn either */
    assert_int_equal(cf_figure_add_points(fig, line, 2, NULL), 0);
    assert_int_equal(cf_figure_set_window(fig, 20, 30, 20, 30), 0);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_PNG, NULL, &data, &size,
                                      &d), CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(d.msg, "draws nothing (1 elements"));
    /* a wide label at the window's right edge sticks out of the page */
    assert_int_equal(cf_figure_set_window(fig, 0, 10, 0, 10), 0);
    cf_style_init(&big);
    big.set = CF_STYLE_FONT_SIZE | CF_STYLE_PLACE;
    big.font_size = 14;
    big.place = CF_PLACE_E;
    assert_int_equal(cf_figure_add_label(fig, 10, 5, "P_0 = c(0) = start",
                                         &big), 0);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, NULL, &data, &size,
                                      &d), CF_STATUS_INVALID_ARG);
    assert_null(data);
    assert_non_null(strstr(d.msg, "label 2 \"P_0 = c(0) = start\" sticks "
                           "out of the 40.0 x 30.0 mm page by "));
    assert_non_null(strstr(d.msg, " on the right"));
    assert_int_equal(d.index, 1);
    /* how far: the ink box's right edge beyond the page, in mm */
    assert_int_equal(cf_figure_ink_box(fig, NULL, ink, &pw, &ph, NULL), 0);
    {
        char want[32];
        snprintf(want, sizeof want, "by %.1f mm", (ink[2] - pw) * 25.4 / 72);
        assert_non_null(strstr(d.msg, want));
    }
    /* the figure itself is not in error: a tight page or clipping draws */
    assert_int_equal(cf_figure_status(fig, NULL), CF_STATUS_OK);
    cf_write_options_init(&tight);
    tight.tight = true;
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, &tight, &data,
                                      &size, NULL), 0);
    cf_free(data);
    assert_int_equal(cf_figure_set_clip(fig, true), 0);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, NULL, &data, &size,
                                      NULL), 0);
    assert_true(size > 0);
    cf_free(data);
    cf_figure_destroy(fig);
}

/* A label given a place on a stroke is kept and reported; the same label
** placed automatically moves off the stroke and is not. */
static void
test_label_on_ink(void **state)
{
    static const double line[] = { 0, 0, 4, 0 };
    cf_figure_t *fig;
    cf_style_t at;
    char *text;
    const char *w;
    int pass;
    (void)state;
    for (pass = 0; pass < 2; pass++) {
        assert_int_equal(cf_figure_create(40, 30, CF_UNIT_MM, &fig, NULL), 0);
        assert_int_equal(cf_figure_add_polyline(fig, line, 2, false, NULL), 0);
        cf_style_init(&at);
        if (pass == 0) {
            at.place = CF_PLACE_CENTER;
            at.set |= CF_STYLE_PLACE;
        }
        assert_int_equal(cf_figure_add_label(fig, 2, 0, "W_1", &at), 0);
        text = dump(fig);
        w = cf_figure_warnings(fig);
        if (pass == 0) {
            assert_non_null(strstr(w, "label \"W_1\" (place center) lies "
                                      "on polyline 1\n"));
            /* kept where it was put */
            assert_int_equal(label_place(text, "W_1"), (int)CF_PLACE_CENTER);
        } else {
            assert_string_equal(w, "");
            assert_int_not_equal(label_place(text, "W_1"),
                                 (int)CF_PLACE_CENTER);
        }
        cf_free(text);
        cf_figure_destroy(fig);
    }
}

/* The renderer's grow-by-doubling (render/base/grow.c), which the display
** list, the byte buffer and the element list use: the capacity doubles
** from `first` to hold what is needed, an array with room comes back as
** it is, and a count whose bytes overflow size_t gives NULL with the array
** and its capacity kept. */
static void
test_grow_array(void **state)
{
    size_t cap = 0, i;
    double *a = NULL;
    (void)state;
    a = cf__grow_array(a, &cap, 5, sizeof *a, 4);
    assert_non_null(a);
    assert_int_equal(cap, 8);               /* 4 doubled once */
    for (i = 0; i < 5; i++)
        a[i] = 0.5 * (double)i;
    assert_ptr_equal(cf__grow_array(a, &cap, 8, sizeof *a, 4), a);
    a = cf__grow_array(a, &cap, 33, sizeof *a, 4);
    assert_non_null(a);
    assert_int_equal(cap, 64);
    assert_null(cf__grow_array(a, &cap, SIZE_MAX / 4, sizeof *a, 4));
    assert_int_equal(cap, 64);
    for (i = 0; i < 5; i++)
        assert_true(a[i] == 0.5 * (double)i);
    cf_free(a);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_grow_array),
        cmocka_unit_test(test_dump_content),
        cmocka_unit_test(test_pgf_outlines_whole),
        cmocka_unit_test(test_backend_independence),
        cmocka_unit_test(test_dump_deterministic),
        cmocka_unit_test(test_pgf_backend),
        cmocka_unit_test(test_page_checks),
        cmocka_unit_test(test_label_on_ink),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
