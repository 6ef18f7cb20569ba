/* Legends, zoom insets and panels, read back from the display list's dump
** (cf_figure_dump) and the rendered PNG: legend samples carry their
** elements' paint, an automatic legend covers no element's ink, panels
** sharing x put a data x at one page x, an inset's paths are the affine
** image of the main drawing's, and bad input is refused by name. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cairo.h>
#include <cmocka.h>

#include "curvefig/figure.h"
#include "pngtest.h"

/* ---- the dump, line by line --------------------------------------------- */

typedef struct lines {
    char *text;       /* the whole dump */
    char *buf;        /* its copy, cut into lines */
    char **line;
    size_t n;
} lines_t;

static void
dump_lines(cf_figure_t *fig, lines_t *out)
{
    size_t size, cap = 64;
    char *p;
    assert_int_equal(cf_figure_dump(fig, NULL, &out->text, &size, NULL), 0);
    out->buf = malloc(size + 1);
    memcpy(out->buf, out->text, size + 1);
    out->line = malloc(cap * sizeof *out->line);
    out->n = 0;
    for (p = strtok(out->buf, "\n"); p != NULL; p = strtok(NULL, "\n")) {
        if (out->n == cap)
            out->line = realloc(out->line, (cap *= 2) * sizeof *out->line);
        out->line[out->n++] = p;
    }
}

static void
lines_free(lines_t *l)
{
    cf_free(l->text);
    free(l->buf);
    free(l->line);
}

/* The index of the first line from `from` starting with prefix. */
static size_t
find(const lines_t *l, size_t from, const char *prefix)
{
    size_t i;
    for (i = from; i < l->n; i++)
        if (strncmp(l->line[i], prefix, strlen(prefix)) == 0)
            return i;
    fail_msg("no line \"%s\" after line %zu", prefix, from);
    return 0;
}

/* The paint of a path line: what comes before " :". */
static void
paint_of(const char *line, char *out, size_t size)
{
    const char *colon = strstr(line, " :");
    size_t n = colon != NULL ? (size_t)(colon - line) : strlen(line);
    assert_true(n < size);
    memcpy(out, line, n);
    out[n] = '\0';
}

/* The numbers of a path line after " :", letters skipped. */
static size_t
path_numbers(const char *line, double *v, size_t max)
{
    const char *p = strstr(line, " :");
    size_t n = 0;
    char *end;
    assert_non_null(p);
    p += 2;
    while (*p != '\0' && n < max) {
        while (*p == ' ' || (*p >= 'A' && *p <= 'Z'))
            p++;
        if (*p == '\0')
            break;
        v[n++] = strtod(p, &end);
        p = end;
    }
    return n;
}

/* The first segment letter of a path line. */
static char
first_seg(const char *line)
{
    const char *p = strstr(line, " :");
    return p != NULL ? p[3] : '\0';
}

/* ---- PNG pixels -------------------------------------------------------- */

/* Nothing drawn at pixel (x, y): transparent or opaque white. */
static bool
pixel_blank(cairo_surface_t *img, int x, int y)
{
    const unsigned char *d = cairo_image_surface_get_data(img);
    int stride = cairo_image_surface_get_stride(img);
    uint32_t v;
    cairo_format_t f = cairo_image_surface_get_format(img);
    if (f == CAIRO_FORMAT_RGB24)
        return (*(const uint32_t *)(d + (size_t)y * (size_t)stride
                                    + 4 * (size_t)x) & 0xffffffu)
            == 0xffffffu;
    v = *(const uint32_t *)(d + (size_t)y * (size_t)stride + 4 * (size_t)x);
    return (v >> 24) == 0 || v == 0xffffffffu;
}

/* ---- figures ------------------------------------------------------------ */

static cf_bezier_t *
cubic(double x0, double y0, double x1, double y1, double x2, double y2,
      double x3, double y3)
{
    double c[8] = { x0, y0, x1, y1, x2, y2, x3, y3 };
    cf_bezier_t *b = NULL;
    assert_int_equal(cf_bezier_create(2, 3, c, NULL, &b, NULL), 0);
    return b;
}

/* Three styled elements with legend entries. */
static cf_figure_t *
legend_figure(void)
{
    static const double poly[] = { 0, 0, 1, 3, 4, 3.5, 6, 0.5 };
    static const double pt[] = { 3, 1 };
    cf_figure_t *fig = NULL;
    cf_bezier_t *c = cubic(0, 0, 1, 3, 4, 3.5, 6, 0.5);
    cf_style_t red, star;
    assert_int_equal(cf_figure_create(8, 5.5, CF_UNIT_CM, &fig, NULL), 0);
    cf_style_init(&red);
    red.set = CF_STYLE_COLOR | CF_STYLE_DASH | CF_STYLE_WIDTH;
    red.color.r = 0.8;
    red.color.a = 1;
    red.width = 2.25;
    red.dash[0] = 4;
    red.dash[1] = 1.5;
    red.dash_count = 2;
    cf_style_init(&star);
    star.set = CF_STYLE_MARKER | CF_STYLE_MARKER_SIZE;
    star.marker = CF_MARKER_STAR;
    star.marker_size = 7;
    assert_int_equal(cf_figure_add_polygon(fig, poly, 4, NULL), 0);
    assert_int_equal(cf_figure_add_legend(fig, "polygon $P_i$"), 0);
    assert_int_equal(cf_figure_add_bezier(fig, c, &red), 0);
    assert_int_equal(cf_figure_add_legend(fig, "c(t)"), 0);
    assert_int_equal(cf_figure_add_points(fig, pt, 1, &star), 0);
    assert_int_equal(cf_figure_add_legend(fig, "c(1/2)"), 0);
    cf_bezier_destroy(c);
    return fig;
}

/* The lines of element group `index` [*g0, *g1) (top level). */
static void
group_range(const lines_t *l, const char *head, size_t *g0, size_t *g1)
{
    *g0 = find(l, 0, head);
    *g1 = find(l, *g0, "end");
}

/* Each entry's sample has the paint of its element's first path and its
** first marker, as the dump shows them. */
static void
test_legend_samples_match_styles(void **state)
{
    static const char *const heads[] = { "group 0 polygon", "group 1 curve",
                                         "group 2 points" };
    cf_figure_t *fig = legend_figure();
    lines_t l;
    size_t lg, i, k, path_in_legend = 0, marker_in_legend = 0;
    (void)state;
    dump_lines(fig, &l);
    lg = find(&l, 0, "group 3 legend");
    /* the frame first, then per entry: sample path, marker, text */
    assert_true(strncmp(l.line[lg + 1], "path fill", 9) == 0);
    for (k = 0; k < 3; k++) {
        size_t g0, g1;
        char want[512], got[512];
        const char *elpath = NULL, *elmark = NULL;
        group_range(&l, heads[k], &g0, &g1);
        for (i = g0; i < g1; i++) {
            if (elpath == NULL && strncmp(l.line[i], "path", 4) == 0)
                elpath = l.line[i];
            if (elmark == NULL && strncmp(l.line[i], "marker", 6) == 0)
                elmark = l.line[i];
        }
        /* the k-th text of the legend; its sample lines precede it */
        {
            size_t t = lg, seen = 0, j;
            const char *lpath = NULL, *lmark = NULL;
            for (j = lg + 2; j < l.n && seen <= k; j++) {
                if (strncmp(l.line[j], "text", 4) == 0) {
                    seen++;
                    t = j;
                    continue;
                }
                if (seen == k && strncmp(l.line[j], "path", 4) == 0)
                    lpath = l.line[j];
                if (seen == k && strncmp(l.line[j], "marker", 6) == 0)
                    lmark = l.line[j];
            }
            assert_true(t > lg);
            if (elpath != NULL) {
                assert_non_null(lpath);
                paint_of(elpath, want, sizeof want);
                paint_of(lpath, got, sizeof got);
                assert_string_equal(got, want);
                path_in_legend++;
            }
            if (elmark != NULL) {
                char *a, *b;
                assert_non_null(lmark);
                /* same symbol, size, width, colours: all after x y */
                a = strstr(elmark, " size ");
                b = strstr(lmark, " size ");
                assert_non_null(a);
                assert_non_null(b);
                assert_string_equal(b, a);
                {
                    char na[32], nb[32];
                    assert_int_equal(sscanf(elmark, "marker %31s", na), 1);
                    assert_int_equal(sscanf(lmark, "marker %31s", nb), 1);
                    assert_string_equal(nb, na);
                }
                marker_in_legend++;
            }
        }
    }
    assert_int_equal(path_in_legend, 2);   /* polygon, curve */
    assert_int_equal(marker_in_legend, 2); /* polygon's dots, the star */
    assert_non_null(strstr(l.text, "text \"polygon $P_i$\""));
    lines_free(&l);
    cf_figure_destroy(fig);
}

/* Distance from (x, y) to the box b (x0 y0 x1 y1); 0 inside. */
static double
box_distance(const double b[4], double x, double y)
{
    double dx = fmax(fmax(b[0] - x, 0), x - b[2]);
    double dy = fmax(fmax(b[1] - y, 0), y - b[3]);
    return hypot(dx, dy);
}

/* No stroke or marker drawn at lines [0, to) of the dump comes into box
** (x0 y0 x1 y1): every line and cubic, sampled finely, keeps half its
** width away, every marker its radius.  The number of samples. */
static size_t
assert_no_ink_in(const lines_t *l, size_t to, const double box[4])
{
    double v[4096];
    size_t i, checked = 0;
    for (i = 0; i < to; i++) {
        const char *ln = l->line[i];
        const char *w;
        double half, x = 0, y = 0;
        size_t n, j = 0;
        const char *p;
        if (strncmp(ln, "path", 4) != 0)
            continue;
        w = strstr(ln, " stroke ");
        assert_non_null(w);
        {
            double r, g, b, a, op;
            assert_int_equal(sscanf(w, " stroke %lf %lf %lf %lf %lf %lf", &r,
                                    &g, &b, &a, &op, &half), 6);
            half *= 0.5;
        }
        n = path_numbers(ln, v, sizeof v / sizeof v[0]);
        /* walk the segments by their letters */
        for (p = strstr(ln, " :") + 2; *p != '\0'; p++) {
            int k;
            if (*p == 'M' || *p == 'L') {
                double x1 = v[j], y1 = v[j + 1];
                if (*p == 'L')
                    for (k = 0; k <= 64; k++) {
                        double t = k / 64.0;
                        assert_true(box_distance(box, x + t * (x1 - x),
                                                 y + t * (y1 - y)) > half);
                        checked++;
                    }
                x = x1;
                y = y1;
                j += 2;
            } else if (*p == 'C') {
                for (k = 0; k <= 256; k++) {
                    double t = k / 256.0, s = 1 - t;
                    double bx = s * s * s * x + 3 * s * s * t * v[j]
                        + 3 * s * t * t * v[j + 2] + t * t * t * v[j + 4];
                    double by = s * s * s * y + 3 * s * s * t * v[j + 1]
                        + 3 * s * t * t * v[j + 3] + t * t * t * v[j + 5];
                    assert_true(box_distance(box, bx, by) > half);
                    checked++;
                }
                x = v[j + 4];
                y = v[j + 5];
                j += 6;
            }
        }
        assert_int_equal(j, n);
    }
    /* markers: their whole disc outside the box */
    for (i = 0; i < to; i++) {
        double mx, my, ms;
        char name[32];
        if (sscanf(l->line[i], "marker %31s %lf %lf size %lf", name, &mx, &my,
                   &ms) == 4)
            assert_true(box_distance(box, mx, my) > 0.5 * ms);
    }
    return checked;
}

/* No stroke of any element passes through the automatic legend's box:
** every cubic and line of the elements' paths, sampled finely, keeps half
** its line width away; and the rendered page is blank in a ring just
** inside the frame (nothing crosses into it). */
static void
test_legend_auto_avoids_ink(void **state)
{
    cf_figure_t *fig = legend_figure();
    lines_t l;
    size_t lg;
    double box[4], v[8];
    unsigned char *png;
    size_t png_size, checked;
    (void)state;
    dump_lines(fig, &l);
    lg = find(&l, 0, "group 3 legend");
    assert_int_equal(path_numbers(l.line[lg + 1], v, 8), 4);
    box[0] = v[0];
    box[1] = v[1];
    box[2] = v[0] + v[2];
    box[3] = v[1] + v[3];
    checked = assert_no_ink_in(&l, lg, box);
    assert_true(checked > 400);
    /* the PNG without the frame: in the ring between the box's edge and
    ** its content nothing is drawn.  The frame is part of the ink the
    ** drawing makes room for: without it the legend may sit a little
    ** elsewhere, so the box moves with its first sample (the line after
    ** the frame's, or the group's first) */
    assert_true(path_numbers(l.line[lg + 2], v, 8) >= 2);
    {
        lines_t l2;
        double w[8];
        size_t lg2;
        assert_int_equal(cf_figure_set_legend_place(fig, CF_PLACE_AUTO,
                                                    false), 0);
        dump_lines(fig, &l2);
        lg2 = find(&l2, 0, "group 3 legend");
        assert_true(path_numbers(l2.line[lg2 + 1], w, 8) >= 2);
        box[0] += w[0] - v[0];
        box[2] += w[0] - v[0];
        box[1] += w[1] - v[1];
        box[3] += w[1] - v[1];
        lines_free(&l2);
    }
    {
        cf_write_options_t o;
        cairo_surface_t *img;
        double k;
        int x, y, blank = 0;
        cf_write_options_init(&o);
        k = o.dpi / 72.0;
        assert_int_equal(cf_figure_render(fig, CF_FORMAT_PNG, &o, &png,
                                          &png_size, NULL), 0);
        img = tu_png_decode(png, png_size);
        assert_int_equal(cairo_surface_status(img), CAIRO_STATUS_SUCCESS);
        for (y = (int)ceil(box[1] * k); y < (int)floor(box[3] * k); y++)
            for (x = (int)ceil(box[0] * k); x < (int)floor(box[2] * k); x++) {
                /* the pixel's far edges, a pixel off the content */
                double x0 = x / k, x1 = (x + 1) / k;
                double y0 = y / k, y1 = (y + 1) / k;
                bool ring = x1 < box[0] + 2 || x0 > box[2] - 2
                    || y1 < box[1] + 2 || y0 > box[3] - 2;
                if (!ring)
                    continue;
                if (!pixel_blank(img, x, y))
                    fail_msg("ink at pixel %d %d (%g %g bp) in the legend "
                             "box %g %g %g %g", x, y, x0, y0, box[0], box[1],
                             box[2], box[3]);
                blank++;
            }
        assert_true(blank > 100);
        cairo_surface_destroy(img);
        cf_free(png);
    }
    lines_free(&l);
    cf_figure_destroy(fig);
}

/* ---- panels ------------------------------------------------------------- */

/* The page x of the markers of a points element drawn in each panel at
** data x = xs[j], read from the dump in drawing order. */
static void
marker_xys(const lines_t *l, double *xs, double *ys, size_t n)
{
    size_t i, k = 0;
    for (i = 0; i < l->n && k < n; i++) {
        double x, y;
        char name[32];
        if (sscanf(l->line[i], "marker %31s %lf %lf", name, &x, &y) == 3) {
            xs[k] = x;
            ys[k++] = y;
        }
    }
    assert_int_equal(k, n);
}

/* A curve panel (aspect kept, window [0, 1] x [0, 0.6]) above a plot
** panel (axes, free aspect, [-0.1, 1.2] x [0, 1]), both with markers at
** x = 0.25 and 0.75. */
static cf_figure_t *
two_panels(unsigned flags, cf_figure_t **p)
{
    static const double top_pts[] = { 0.25, 0.3, 0.75, 0.5 };
    static const double bot_pts[] = { 0.25, 0.9, 0.75, 0.1 };
    cf_figure_t *fig = NULL;
    cf_bezier_t *c = cubic(0, 0, 0.3, 0.6, 0.7, 0.6, 1, 0);
    cf_axes_t ax;
    assert_int_equal(cf_figure_create(8, 9, CF_UNIT_CM, &fig, NULL), 0);
    assert_int_equal(cf_figure_add_panels(fig, 2, 1, 6, flags, p), 0);
    assert_int_equal(cf_figure_set_window(p[0], 0, 1, 0, 0.6), 0);
    assert_int_equal(cf_figure_add_bezier(p[0], c, NULL), 0);
    assert_int_equal(cf_figure_add_points(p[0], top_pts, 2, NULL), 0);
    cf_axes_init(&ax);
    ax.xmin = -0.1;
    ax.xmax = 1.2;
    ax.ymin = 0;
    ax.ymax = 1;
    assert_int_equal(cf_figure_add_axes(p[1], &ax, NULL), 0);
    assert_int_equal(cf_figure_add_points(p[1], bot_pts, 2, NULL), 0);
    cf_bezier_destroy(c);
    return fig;
}

/* With CF_PANELS_SHARE_X the same data x is the same page x in both
** panels, exactly; without it the two panels map x differently. */
static void
test_panels_share_x(void **state)
{
    cf_figure_t *p[2], *fig;
    lines_t l;
    double x[4], y[4];
    (void)state;
    fig = two_panels(CF_PANELS_SHARE_X, p);
    dump_lines(fig, &l);
    assert_non_null(strstr(l.text, "group 0 panel"));
    assert_non_null(strstr(l.text, "group 1 panel"));
    assert_non_null(strstr(l.text, "text \"(a)\""));
    assert_non_null(strstr(l.text, "text \"(b)\""));
    marker_xys(&l, x, y, 4);
    assert_true(x[0] == x[2]);
    assert_true(x[1] == x[3]);
    assert_true(x[1] - x[0] > 10);
    /* the top panel keeps its aspect: page dy / dx = data 0.2 / 0.5 */
    assert_true(fabs((y[0] - y[1]) / (x[1] - x[0]) - 0.4) < 1e-9);
    lines_free(&l);
    cf_figure_destroy(fig);

    fig = two_panels(0, p);
    dump_lines(fig, &l);
    marker_xys(&l, x, y, 4);
    assert_true(fabs(x[0] - x[2]) > 1 || fabs(x[1] - x[3]) > 1);
    lines_free(&l);
    cf_figure_destroy(fig);
}

/* CF_PANELS_SHARE_Y: panels side by side put a data y at one page y. */
static void
test_panels_share_y(void **state)
{
    static const double a[] = { 0, 0.2, 1, 0.7 };
    static const double b[] = { 5, 0.2, 9, 0.7, 7, 3 };
    cf_figure_t *fig = NULL, *p[2];
    lines_t l;
    double x[5], y[5];
    (void)state;
    assert_int_equal(cf_figure_create(10, 5, CF_UNIT_CM, &fig, NULL), 0);
    assert_int_equal(cf_figure_add_panels(fig, 1, 2, 4, CF_PANELS_SHARE_Y,
                                          p), 0);
    assert_int_equal(cf_figure_set_fit(p[0], 10, false), 0);
    assert_int_equal(cf_figure_set_fit(p[1], 10, false), 0);
    assert_int_equal(cf_figure_add_points(p[0], a, 2, NULL), 0);
    assert_int_equal(cf_figure_add_points(p[1], b, 3, NULL), 0);
    dump_lines(fig, &l);
    marker_xys(&l, x, y, 5);
    assert_true(y[0] == y[2]);
    assert_true(y[1] == y[3]);
    assert_true(x[2] > x[1]);   /* the second panel right of the first */
    lines_free(&l);
    cf_figure_destroy(fig);
}

/* A bad grid and a second split are refused by name. */
static void
test_panels_bad_input(void **state)
{
    cf_figure_t *fig = NULL, *p[64];
    cf_diag_t d;
    (void)state;
    assert_int_equal(cf_figure_create(8, 6, CF_UNIT_CM, &fig, NULL), 0);
    assert_int_equal(cf_figure_add_panels(fig, 0, 2, 0, 0, p),
                     CF_STATUS_INVALID_ARG);
    cf_diag_clear(&d);
    cf_figure_status(fig, &d);
    assert_non_null(strstr(d.msg, "rows and cols are 1 to 8"));
    cf_figure_destroy(fig);
    assert_int_equal(cf_figure_create(8, 6, CF_UNIT_CM, &fig, NULL), 0);
    assert_int_equal(cf_figure_add_panels(fig, 1, 2, 0, 0, p), 0);
    assert_int_equal(cf_figure_add_panels(p[0], 1, 2, 0, 0, p + 2),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_figure_set_panel_title(fig, "x"),
                     CF_STATUS_INVALID_ARG);
    cf_figure_destroy(fig);
}

/* ---- insets ------------------------------------------------------------- */

/* Every number of the curve's path in the inset is the image of the
** main path's under the map taking the region's frame onto the inset's:
** p' = I0 + k (p - R0), with k the ratio of the frames' widths and of
** their heights alike. */
static void
test_inset_is_affine_image(void **state)
{
    cf_figure_t *fig = NULL;
    cf_bezier_t *c = cubic(0, 0, 4, 3, 0, 3, 4, 0);
    cf_inset_t in;
    lines_t l;
    size_t g, main_path, inset_path, i, n, m;
    double r[4], f[4], a[64], b[64], kx, ky;
    (void)state;
    assert_int_equal(cf_figure_create(13, 6, CF_UNIT_CM, &fig, NULL), 0);
    assert_int_equal(cf_figure_add_bezier(fig, c, NULL), 0);
    cf_inset_init(&in);
    in.region[0] = 1.7;
    in.region[1] = 1.85;
    in.region[2] = 2.3;
    in.region[3] = 2.25;
    in.scale = 3;
    assert_int_equal(cf_figure_add_inset(fig, &in), 0);
    dump_lines(fig, &l);
    main_path = find(&l, find(&l, 0, "group 0 curve"), "path");
    g = find(&l, 0, "group 0 inset");
    /* region frame and connectors, inset background, clip, the curve */
    assert_int_equal(first_seg(l.line[g + 1]), 'R');
    assert_int_equal(path_numbers(l.line[g + 1], r, 4), 4);
    assert_int_equal(path_numbers(l.line[find(&l, g + 1, "path fill")], f,
                                  4), 4);
    inset_path = find(&l, find(&l, g, "group 0 curve"), "path");
    kx = f[2] / r[2];
    ky = f[3] / r[3];
    assert_true(fabs(kx - 3) < 1e-9);
    assert_true(fabs(ky - 3) < 1e-9);
    n = path_numbers(l.line[main_path], a, 64);
    m = path_numbers(l.line[inset_path], b, 64);
    assert_int_equal(n, m);
    assert_true(n >= 8);
    for (i = 0; i < n; i += 2) {
        assert_true(fabs(b[i] - (f[0] + kx * (a[i] - r[0]))) < 1e-7);
        assert_true(fabs(b[i + 1] - (f[1] + ky * (a[i + 1] - r[1]))) < 1e-7);
    }
    /* the inset lies on the page and away from the region */
    assert_true(f[0] >= 0 && f[1] >= 0);
    assert_true(f[0] > r[0] + r[2] || f[1] > r[1] + r[3]
                || f[0] + f[2] < r[0] || f[1] + f[3] < r[1]);
    lines_free(&l);
    cf_figure_destroy(fig);
    cf_bezier_destroy(c);
}

/* An automatic inset on a page the drawing fills: the drawing makes
** room, and no element's stroke or marker comes into the inset's box. */
static void
test_inset_auto_finds_room(void **state)
{
    static const double poly[] = { 0, 0, 4, 3, 0, 3, 4, 0 };
    cf_figure_t *fig = NULL;
    cf_bezier_t *c = cubic(0, 0, 4, 3, 0, 3, 4, 0);
    cf_inset_t in;
    lines_t l;
    size_t g;
    double f[4];
    (void)state;
    assert_int_equal(cf_figure_create(8, 6, CF_UNIT_CM, &fig, NULL), 0);
    assert_int_equal(cf_figure_add_polygon(fig, poly, 4, NULL), 0);
    assert_int_equal(cf_figure_add_bezier(fig, c, NULL), 0);
    cf_inset_init(&in);
    in.region[0] = 1.7;
    in.region[1] = 2.0;
    in.region[2] = 2.3;
    in.region[3] = 2.5;
    in.scale = 3;
    assert_int_equal(cf_figure_add_inset(fig, &in), 0);
    dump_lines(fig, &l);
    g = find(&l, 0, "group 0 inset");
    assert_int_equal(path_numbers(l.line[find(&l, g + 1, "path fill")], f,
                                  4), 4);
    f[2] += f[0];
    f[3] += f[1];
    assert_true(assert_no_ink_in(&l, g, f) > 300);
    lines_free(&l);
    cf_figure_destroy(fig);
    cf_bezier_destroy(c);
}

/* A region outside the window, an empty one, an unknown place. */
static void
test_inset_bad_input(void **state)
{
    cf_figure_t *fig = NULL;
    cf_bezier_t *c = cubic(0, 0, 4, 3, 0, 3, 4, 0);
    cf_inset_t in;
    cf_diag_t d;
    unsigned char *data;
    size_t size;
    (void)state;
    assert_int_equal(cf_figure_create(8, 6, CF_UNIT_CM, &fig, NULL), 0);
    assert_int_equal(cf_figure_add_bezier(fig, c, NULL), 0);
    cf_inset_init(&in);
    in.region[0] = 1;
    in.region[1] = 1;
    in.region[2] = 1;
    in.region[3] = 2;
    assert_int_equal(cf_figure_add_inset(fig, &in), CF_STATUS_INVALID_ARG);
    cf_diag_clear(&d);
    cf_figure_status(fig, &d);
    assert_non_null(strstr(d.msg, "inset 1: region"));
    assert_non_null(strstr(d.msg, "empty"));
    cf_figure_destroy(fig);

    assert_int_equal(cf_figure_create(8, 6, CF_UNIT_CM, &fig, NULL), 0);
    assert_int_equal(cf_figure_add_bezier(fig, c, NULL), 0);
    in.region[2] = 9;
    in.place = CF_PLACE_CENTER;
    assert_int_equal(cf_figure_add_inset(fig, &in), CF_STATUS_INVALID_ARG);
    cf_figure_destroy(fig);

    assert_int_equal(cf_figure_create(8, 6, CF_UNIT_CM, &fig, NULL), 0);
    assert_int_equal(cf_figure_add_bezier(fig, c, NULL), 0);
    in.place = CF_PLACE_AUTO;
    assert_int_equal(cf_figure_add_inset(fig, &in), 0);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, NULL, &data,
                                      &size, &d), CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(d.msg, "inset 1: region {1, 1, 9, 2} is not "
                                  "inside the window"));
    cf_figure_destroy(fig);
    cf_bezier_destroy(c);
}

/* A legend without an element, twice for one, at the centre. */
static void
test_legend_bad_input(void **state)
{
    cf_figure_t *fig = NULL;
    static const double pt[] = { 0, 0 };
    (void)state;
    assert_int_equal(cf_figure_create(8, 6, CF_UNIT_CM, &fig, NULL), 0);
    assert_int_equal(cf_figure_add_legend(fig, "x"), CF_STATUS_INVALID_ARG);
    cf_figure_destroy(fig);
    assert_int_equal(cf_figure_create(8, 6, CF_UNIT_CM, &fig, NULL), 0);
    assert_int_equal(cf_figure_add_points(fig, pt, 1, NULL), 0);
    assert_int_equal(cf_figure_add_legend(fig, "x"), 0);
    assert_int_equal(cf_figure_add_legend(fig, "y"), CF_STATUS_INVALID_ARG);
    cf_figure_destroy(fig);
    assert_int_equal(cf_figure_create(8, 6, CF_UNIT_CM, &fig, NULL), 0);
    assert_int_equal(cf_figure_set_legend_place(fig, CF_PLACE_CENTER, true),
                     CF_STATUS_INVALID_ARG);
    cf_figure_destroy(fig);
    assert_int_equal(cf_figure_create(8, 6, CF_UNIT_CM, &fig, NULL), 0);
    assert_int_equal(cf_figure_add_points(fig, pt, 1, NULL), 0);
    assert_int_equal(cf_figure_add_legend(fig, "x_{"), CF_STATUS_INVALID_ARG);
    cf_figure_destroy(fig);
}

/* The anchor and baseline origin of the first text line of a dump. */
static void
text_origin(const lines_t *l, double *ay, double *oy)
{
    const char *t = strstr(l->line[find(l, 0, "text \"W\"")], " anchor ");
    double ax, ox, off, size;
    int place;
    assert_non_null(t);
    assert_int_equal(sscanf(t, " anchor %lf %lf place %d offset %lf size %lf "
                            "origin %lf %lf", &ax, ay, &place, &off, &size,
                            &ox, oy), 7);
}

/* Label places are chosen once for a layout and its builds, never kept
** across a change: a label placed above its line goes below it once a
** second line is drawn where it was. */
static void
test_places_follow_changes(void **state)
{
    static const double line[] = { 0, 0, 4, 0 }, over[] = { 1.5, 0.25,
                                                            2.5, 0.25 };
    cf_figure_t *fig = NULL;
    cf_style_t wide;
    lines_t l;
    double ay, oy;
    (void)state;
    assert_int_equal(cf_figure_create(40, 30, CF_UNIT_MM, &fig, NULL), 0);
    /* a fixed page and window: the map stays the same after the change */
    assert_int_equal(cf_figure_set_page_mode(fig, CF_PAGE_FIXED), 0);
    assert_int_equal(cf_figure_set_window(fig, 0, 4, -1, 1), 0);
    assert_int_equal(cf_figure_add_polyline(fig, line, 2, false, NULL), 0);
    assert_int_equal(cf_figure_add_label(fig, 2, 0, "W", NULL), 0);
    dump_lines(fig, &l);
    text_origin(&l, &ay, &oy);
    assert_true(oy < ay);   /* above the line (page y grows downwards) */
    lines_free(&l);
    cf_style_init(&wide);
    wide.set = CF_STYLE_WIDTH;
    wide.width = 8;
    assert_int_equal(cf_figure_add_polyline(fig, over, 2, false, &wide), 0);
    dump_lines(fig, &l);
    text_origin(&l, &ay, &oy);
    assert_true(oy > ay);   /* below it now */
    lines_free(&l);
    cf_figure_destroy(fig);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_legend_samples_match_styles),
        cmocka_unit_test(test_legend_auto_avoids_ink),
        cmocka_unit_test(test_legend_bad_input),
        cmocka_unit_test(test_panels_share_x),
        cmocka_unit_test(test_panels_share_y),
        cmocka_unit_test(test_panels_bad_input),
        cmocka_unit_test(test_inset_is_affine_image),
        cmocka_unit_test(test_inset_auto_finds_room),
        cmocka_unit_test(test_inset_bad_input),
        cmocka_unit_test(test_places_follow_changes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
