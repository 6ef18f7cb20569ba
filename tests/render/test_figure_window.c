/* Figures: the window and its fit, clipping, automatic label places, the
** hull, label halos (the shared helpers in test_figure.h). */
#include "test_figure.h"

static void
test_window_fit(void **state)
{
    double pts[] = { 0, 0, 10, 1 }, win[4], sx, sy, W, H;
    cf_figure_t *fig = new_fig();
    cf_axes_t ax;
    (void)state;
    cf_figure_get_size(fig, &W, &H);
    tu_assert_close(W, 120 * 72 / 25.4, 1e-14, 0);
    assert_int_equal(cf_figure_add_polyline(fig, pts, 2, false, NULL), 0);
    assert_int_equal(cf_figure_get_window(fig, win, &sx, &sy), 0);
    /* fitted to the points, aspect kept, inside the page */
    tu_assert_close(win[0], 0, 0, 1e-12);
    tu_assert_close(win[1], 10, 1e-12, 0);
    tu_assert_close(sx, sy, 1e-12, 0);
    assert_true(sx * 10 <= W && sx * 10 > 0.8 * W);
    cf_figure_destroy(fig);

    /* the window holds the curve, not its control points: the parabola
    ** through (0,0), (2,0) with middle control point (1,10) peaks at 5 */
    fig = new_fig();
    {
        double Q[] = { 0, 0, 1, 10, 2, 0 };
        cf_bezier_t *c;
        assert_int_equal(cf_bezier_create(2, 2, Q, NULL, &c, NULL), 0);
        assert_int_equal(cf_figure_add_bezier(fig, c, NULL), 0);
        assert_int_equal(cf_figure_get_window(fig, win, &sx, &sy), 0);
        tu_assert_close(win[3], 5, 1e-12, 0);
        tu_assert_close(win[2], 0, 0, 1e-12);
        cf_bezier_destroy(c);
    }
    cf_figure_destroy(fig);

    /* with axes the aspect ratio is free by default: [0,10] x [0,1] fills
    ** the page */
    fig = new_fig();
    cf_axes_init(&ax);
    ax.xmax = 10;
    ax.ymax = 1;
    assert_int_equal(cf_figure_add_axes(fig, &ax, NULL), 0);
    assert_int_equal(cf_figure_get_window(fig, win, &sx, &sy), 0);
    assert_true(sy > 5 * sx);
    assert_true(sx * 10 > 0.6 * W && sy * 1 > 0.6 * H);
    /* ... unless asked */
    assert_int_equal(cf_figure_set_fit(fig, 4, true), 0);
    assert_int_equal(cf_figure_get_window(fig, win, &sx, &sy), 0);
    tu_assert_close(sx, sy, 1e-12, 0);
    /* an explicit window */
    assert_int_equal(cf_figure_set_window(fig, -1, 2, -3, 4), 0);
    assert_int_equal(cf_figure_get_window(fig, win, NULL, NULL), 0);
    assert_true(win[0] == -1 && win[1] == 2 && win[2] == -3 && win[3] == 4);
    cf_figure_destroy(fig);
}

/* Lengths of the runs of dark pixels (grey level < 128) down the
** middle column of the figure rendered at dpi; returns the run count. */
static size_t
dark_runs_mid_column(cf_figure_t *fig, double dpi, int *runs, size_t cap)
{
    cf_write_options_t o;
    unsigned char *data;
    size_t size;
    cairo_surface_t *img;
    const unsigned char *px;
    int w, h, stride, y, len = 0;
    size_t n = 0;
    cf_write_options_init(&o);
    o.dpi = dpi;
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_PNG, &o, &data,
                                      &size, NULL), CF_STATUS_OK);
    img = tu_png_decode(data, size);
    assert_int_equal(cairo_surface_status(img), CAIRO_STATUS_SUCCESS);
    w = cairo_image_surface_get_width(img);
    h = cairo_image_surface_get_height(img);
    stride = cairo_image_surface_get_stride(img);
    px = cairo_image_surface_get_data(img);
    for (y = 0; y <= h; y++) {
        /* ARGB32 on an opaque white page: the green byte is the grey */
        bool dark = y < h && px[y * stride + 4 * (w / 2) + 1] < 128;
        if (dark) {
            len++;
        } else if (len > 0) {
            if (n < cap)
                runs[n] = len;
            n++;
            len = 0;
        }
    }
    cairo_surface_destroy(img);
    cf_free(data);
    return n;
}

static void
test_explicit_window_clips(void **state)
{
    double longline[] = { -5, 0.25, 5, 0.25 }, inside[] = { 0, 0.25, 1,
                                                            0.25 };
    double mid[] = { 0.5, 0.25 }, far[] = { 3, 0.25, 0.5, 3 };
    double sx_long, sx_inside, box[4], W, H, win[4];
    cf_figure_t *fig;
    cf_style_t st;
    (void)state;
    /* A close-up: window [0, 1] x [0, 0.5] on 80 x 40 mm.  A line
    ** running far out of the window, a point inside, points outside.
    ** The window keeps its size as if only the part of the line inside
    ** it were drawn: lines are clipped to the window (widened by the
    ** line width), points outside are left out, and only what remains
    ** is given room.  (A label outside is drawn, or refused when too far
    ** for the page: tests/lua/test_layouts.c.) */
    assert_int_equal(cf_figure_create(80, 40, CF_UNIT_MM, &fig, NULL), 0);
    assert_int_equal(cf_figure_set_window(fig, 0, 1, 0, 0.5), 0);
    assert_int_equal(cf_figure_add_polyline(fig, longline, 2, false, NULL),
                     0);
    assert_int_equal(cf_figure_add_points(fig, mid, 1, NULL), 0);
    assert_int_equal(cf_figure_add_points(fig, far, 2, NULL), 0);
    assert_int_equal(cf_figure_add_polygon(fig, far, 2, NULL), 0);
    assert_int_equal(cf_figure_get_window(fig, win, &sx_long, NULL), 0);
    assert_int_equal(cf_figure_ink_box(fig, NULL, box, &W, &H, NULL), 0);
    assert_true(win[0] == 0 && win[1] == 1 && win[2] == 0 && win[3] == 0.5);
    /* all ink on the page, and no wider than the window plus the clip's
    ** widening (one line width, 0.8 bp by default, each side) plus the
    ** rounding of cairo's ink extents (whole bp, outwards) */
    assert_true(box[0] >= 0 && box[1] >= 0 && box[2] <= W && box[3] <= H);
    assert_true(box[2] - box[0] <= sx_long * 1 + 2 * 0.8 + 2);
    cf_figure_destroy(fig);

    assert_int_equal(cf_figure_create(80, 40, CF_UNIT_MM, &fig, NULL), 0);
    assert_int_equal(cf_figure_set_window(fig, 0, 1, 0, 0.5), 0);
    assert_int_equal(cf_figure_add_polyline(fig, inside, 2, false, NULL),
                     0);
    assert_int_equal(cf_figure_add_points(fig, mid, 1, NULL), 0);
    assert_int_equal(cf_figure_get_window(fig, NULL, &sx_inside, NULL), 0);
    cf_figure_destroy(fig);
    /* the two differ only by how far the ends stick out (round caps of
    ** half a width vs the clip's full width: 0.8 bp over ~200 bp); the
    ** unclipped line used to shrink the window by 40 % */
    tu_assert_close(sx_long, sx_inside, 0.01, 0);

    /* Lines lying on the window's edges stay whole: two 2 bp lines along
    ** the bottom and top edges, rendered at 4 pixels per bp, are 8
    ** pixels thick (half a line clipped away would leave 4). */
    assert_int_equal(cf_figure_create(80, 40, CF_UNIT_MM, &fig, NULL), 0);
    assert_int_equal(cf_figure_set_window(fig, 0, 1, 0, 0.5), 0);
    cf_style_init(&st);
    st.set = CF_STYLE_WIDTH | CF_STYLE_COLOR;
    st.width = 2;
    st.color.a = 1;   /* black */
    {
        double bottom[] = { 0, 0, 1, 0 };
        cf_bezier_t *top;
        double tp[] = { 0, 0.5, 0.5, 0.5, 1, 0.5 };
        int runs[8];
        size_t n, k;
        assert_int_equal(cf_bezier_create(2, 2, tp, NULL, &top, NULL), 0);
        assert_int_equal(cf_figure_add_polyline(fig, bottom, 2, false, &st),
                         0);
        assert_int_equal(cf_figure_add_bezier(fig, top, &st), 0);
        cf_bezier_destroy(top);
        n = dark_runs_mid_column(fig, 4 * 72, runs, 8);
        assert_int_equal(n, 2);
        for (k = 0; k < n; k++)
            assert_in_range(runs[k], 7, 9);   /* 8 px, +-1 for the
                                                 antialiased edges */
    }
    cf_figure_destroy(fig);
}

/* The ink box of all text in an SVG: the glyph outlines (cairo puts them
** in <symbol>s, used at the glyph origins) read from the file, each the
** box of its path's points (which holds the outline). */
static void
text_page_box(const char *svg, double box[4])
{
    const char *p = strstr(svg, "</defs>");
    int uses = 0;
    assert_non_null(p);
    box[0] = box[1] = INFINITY;
    box[2] = box[3] = -INFINITY;
    while ((p = strstr(p, "<use xlink:href=\"#")) != NULL) {
        char id[64], key[80];
        const char *q = p + 18, *sym, *d;
        double x, y;
        size_t n = strcspn(q, "\"");
        assert_true(n < sizeof id);
        memcpy(id, q, n);
        id[n] = '\0';
        x = strtod(strstr(q, " x=\"") + 4, NULL);
        y = strtod(strstr(q, " y=\"") + 4, NULL);
        snprintf(key, sizeof key, "id=\"%s\"", id);
        sym = strstr(svg, key);
        assert_non_null(sym);
        d = strstr(sym, " d=\"");
        assert_non_null(d);
        d += 4;
        while (*d != '"') {
            char *e1, *e2;
            double gx, gy;
            if ((*d >= 'A' && *d <= 'Z') || *d == ' ') {
                d++;
                continue;
            }
            gx = strtod(d, &e1);
            gy = strtod(e1, &e2);
            assert_true(e1 != d && e2 != e1);
            box[0] = fmin(box[0], x + gx);
            box[2] = fmax(box[2], x + gx);
            box[1] = fmin(box[1], y + gy);
            box[3] = fmax(box[3], y + gy);
            d = e2;
        }
        uses++;
        p = q;
    }
    assert_true(uses > 0);
}

/* How many of 64 samples per drawn path segment fall inside box. */
static int
samples_inside(const paths_t *ps, const double box[4])
{
    size_t i;
    int k, n = 0;
    for (i = 0; i < ps->nseg; i++)
        for (k = 0; k <= 64; k++) {
            double x, y;
            cubic_at(ps->seg[i].p, k / 64.0, &x, &y);
            if (x > box[0] && x < box[2] && y > box[1] && y < box[3])
                n++;
        }
    return n;
}

/* A figure of a polyline through pts (n points) and the label "P_1" at
** vertex v, placed `place`; returns its SVG. */
static char *
labelled_polyline(const double *pts, size_t n, size_t v, cf_place_t place)
{
    cf_figure_t *fig = new_fig();
    cf_style_t st;
    char *svg;
    cf_style_init(&st);
    st.set = CF_STYLE_PLACE;
    st.place = place;
    assert_int_equal(cf_figure_add_polyline(fig, pts, n, false, NULL), 0);
    assert_int_equal(cf_figure_add_label(fig, pts[2 * v], pts[2 * v + 1],
                                         "P_1", &st), 0);
    svg = render_svg(fig);
    /* deterministic: the same choice on every rendering */
    {
        char *again = render_svg(fig);
        assert_string_equal(svg, again);
        free(again);
    }
    cf_figure_destroy(fig);
    return svg;
}

static void
test_auto_label_place(void **state)
{
    /* a V with its vertex at the bottom, a line just under the vertex
    ** (at 1/10 of the V's height: some 13 bp on this page), and a
    ** Lambda: the label of the vertex must not cross any of the lines */
    double vee[] = { 0, 1, 1, 0, 2, 1 };
    double vee_floor[] = { 0, 1, 1, 0, 2, 1, 2, -0.1, 0, -0.1 };
    double lambda[] = { 0, 0, 1, 1, 2, 0 };
    struct {
        const double *pts;
        size_t n;
    } cases[] = { { vee, 3 }, { vee_floor, 5 }, { lambda, 3 } };
    size_t k;
    cf_place_t pl;
    (void)state;
    assert_int_equal(cf_place_from_name("auto", &pl, NULL), 0);
    assert_int_equal(pl, CF_PLACE_AUTO);
    for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char *svg = labelled_polyline(cases[k].pts, cases[k].n, 1,
                                      CF_PLACE_AUTO);
        paths_t *ps = malloc(sizeof *ps);
        double box[4];
        stroked_paths(svg, ps);
        assert_true(ps->nseg >= 2);
        text_page_box(svg, box);
        assert_int_equal(samples_inside(ps, box), 0);
        free(svg);
        /* the check sees a collision: the default place (ne) of the V's
        ** vertex puts the label on the right leg */
        if (k == 0) {
            svg = labelled_polyline(cases[k].pts, cases[k].n, 1,
                                    CF_PLACE_NE);
            stroked_paths(svg, ps);
            text_page_box(svg, box);
            assert_true(samples_inside(ps, box) > 0);
            free(svg);
        }
        free(ps);
    }
}

static void
test_hull(void **state)
{
    /* a square with an interior point and a repeated corner: the hull is
    ** the square */
    double pts[] = { 0, 0, 2, 0, 1, 1, 2, 2, 0, 2, 2, 2 };
    cf_figure_t *fig = new_fig();
    char *svg;
    const char *p, *d;
    int lines = 0;
    (void)state;
    assert_int_equal(cf_figure_add_hull(fig, pts, 6, NULL), 0);
    svg = render_svg(fig);
    p = strstr(svg, "</defs>");
    p = strstr(p != NULL ? p : svg, " fill-opacity=\"0.35\"");
    assert_non_null(p);
    while (p > svg && strncmp(p, "<path ", 6) != 0)
        p--;   /* the hull's path: d comes first */
    d = strstr(p, " d=\"");
    for (d += 4; *d != '"'; d++)
        if (*d == 'L')
            lines++;
    assert_int_equal(lines, 3);   /* M + 3 L + Z: four corners */
    free(svg);
    cf_figure_destroy(fig);
}

static void
test_label_halo(void **state)
{
    cf_figure_t *fig = new_fig();
    cf_style_t s;
    char *svg;
    const char *p;
    (void)state;
    cf_style_init(&s);
    s.set = CF_STYLE_HALO;
    s.halo = 1.5;
    assert_int_equal(cf_figure_add_label(fig, 0, 0, "C(t)", &s), 0);
    assert_int_equal(cf_figure_set_background(fig, CF_BACKGROUND_ALWAYS), 0);
    svg = render_svg(fig);
    /* on a painted page, the glyph outlines stroked 3 bp wide in the
    ** (white) background colour, under the glyphs (a transparent page's
    ** knockout: test_knockout.c) */
    p = strstr(svg, "</defs>");
    assert_non_null(p);
    p = strstr(p, " stroke=\"#ffffff\" stroke-width=\"3\"");
    assert_non_null(p);
    assert_non_null(strstr(p, "<use"));   /* the glyphs come after it */
    free(svg);
    cf_figure_destroy(fig);
    /* out of range */
    fig = new_fig();
    s.halo = -1;
    assert_int_equal(cf_figure_add_label(fig, 0, 0, "C", &s),
                     CF_STATUS_INVALID_ARG);
    cf_figure_destroy(fig);
}

/* An allocator whose fresh bytes are junk varying along the block (junk
** != 0) or zero (junk == 0). */
static void *
junk_alloc(void *ud, void *ptr, size_t old_size, size_t new_size)
{
    unsigned char *p;
    size_t i, junk = *(const size_t *)ud;
    if (new_size == 0) {
        free(ptr);
        return NULL;
    }
    p = realloc(ptr, new_size);
    if (p == NULL)
        return NULL;
    for (i = ptr == NULL ? 0 : old_size; i < new_size; i++)
        p[i] = (unsigned char)(junk != 0 ? (i * 131 + i / 907) * junk : 0);
    return p;
}

/* A figure with an explicit window, a line through it and automatic
** labels inside and outside it, as SVG made with the allocator giving
** junk (or zero) fresh memory. */
static char *
window_labels_svg(size_t junk)
{
    cf_allocator_t a = { junk_alloc, &junk }, before;
    double pts[] = { -0.2, 0.1, 1.3, 0.4 };
    cf_figure_t *fig = NULL;
    char *svg;
    cf_use_allocator(&a, &before);
    assert_int_equal(cf_figure_create(80, 40, CF_UNIT_MM, &fig, NULL), 0);
    assert_int_equal(cf_figure_set_window(fig, 0, 1, 0, 0.5), 0);
    assert_int_equal(cf_figure_add_polyline(fig, pts, 2, false, NULL), 0);
    assert_int_equal(cf_figure_add_label(fig, 0.5, 0.25, "A", NULL), 0);
    assert_int_equal(cf_figure_add_label(fig, 1.12, 0.38, "B_1", NULL), 0);
    assert_int_equal(cf_figure_add_label(fig, -0.1, 0.12, "C", NULL), 0);
    svg = render_svg(fig);
    cf_figure_destroy(fig);
    cf_use_allocator(&before, NULL);
    return svg;
}

/* The label placement's raster is emptied where it is read or painted,
** not whole (render/layout/place-raster.c): the places of labels
** outside an explicit window, whose candidates lie beyond the box the
** placement readies, read their own rows too.  Whatever fresh memory
** holds, the figure is the same (before that, a label outside the
** window weighed its places on what the allocator left there: found by
** memcheck on the script fuzzer's corpus). */
static void
test_labels_on_fresh_memory(void **state)
{
    char *zero = window_labels_svg(0), *junk;
    size_t k;
    (void)state;
    for (k = 1; k < 6; k++) {
        junk = window_labels_svg(k * 37);
        assert_string_equal(junk, zero);
        free(junk);
    }
    free(zero);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_window_fit),
        cmocka_unit_test(test_explicit_window_clips),
        cmocka_unit_test(test_auto_label_place),
        cmocka_unit_test(test_hull),
        cmocka_unit_test(test_label_halo),
        cmocka_unit_test(test_labels_on_fresh_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
