/* Where a zoom inset goes, read back from the display list's dump
** (cf_figure_dump): an automatic inset's connectors keep off the points
** drawn where the first choice's connectors ran; a label on an inset's
** frame is reported in the figure's warnings, and one placed
** automatically keeps off the frames and connectors; an inset placed
** "above" goes above the drawing, not into it. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/figure.h"

/* The square around the window [0, 10]^2 drawn, so that the drawing's
** ink box is the window's, with room everywhere inside. */
static cf_figure_t *
square_figure(void)
{
    static const double sq[] = { 0, 0, 10, 0, 10, 10, 0, 10 };
    cf_figure_t *fig = NULL;
    assert_int_equal(cf_figure_create(10, 10, CF_UNIT_CM, &fig, NULL), 0);
    assert_int_equal(cf_figure_set_page_mode(fig, CF_PAGE_FIXED), 0);
    assert_int_equal(cf_figure_set_window(fig, 0, 10, 0, 10), 0);
    assert_int_equal(cf_figure_add_polyline(fig, sq, 4, true, NULL), 0);
    return fig;
}

static void
add_inset(cf_figure_t *fig, cf_place_t place, bool beside)
{
    cf_inset_t in;
    cf_inset_init(&in);
    in.region[0] = 3;
    in.region[1] = 3;
    in.region[2] = 4;
    in.region[3] = 4;
    in.scale = 2.5;
    in.place = place;
    in.beside = beside;
    assert_int_equal(cf_figure_add_inset(fig, &in), 0);
}

/* What the dump says of the first inset and the square. */
typedef struct seen {
    double seg[4][4];   /* connectors p q (page bp), cut at the inset */
    int nseg;
    double frame[4];    /* the region's frame x0 y0 x1 y1 */
    double box[4];      /* the inset's box */
    double sq[4];       /* the square's page box */
    double mark[8][3];  /* markers: x y size */
    int nmark;
} seen_t;

/* The numbers of a path line after " :" into v (letters into lt). */
static int
path_items(const char *line, char *lt, double *v, int max)
{
    const char *p = strstr(line, " :");
    int n = 0;
    char *end;
    assert_non_null(p);
    p += 2;
    while (*p != '\0' && n < max) {
        while (*p == ' ')
            p++;
        if (*p >= 'A' && *p <= 'Z') {
            lt[n] = *p++;
            continue;
        }
        if (*p == '\0')
            break;
        v[n] = strtod(p, &end);
        if (n > 0 && lt[n] == '\0')
            lt[n] = '.';
        n++;
        p = end;
    }
    return n;
}

/* Where segment p q enters box b, as a fraction of its length; 1 when it
** does not. */
static double
enters(const double b[4], const double *p, const double *q)
{
    double t0 = 0, t1 = 1;
    int k;
    for (k = 0; k < 2; k++) {
        double d = q[k] - p[k];
        if (fabs(d) < 1e-12) {
            if (p[k] < b[k] || p[k] > b[k + 2])
                return 1;
        } else {
            double ta = (b[k] - p[k]) / d, tb = (b[k + 2] - p[k]) / d;
            t0 = fmax(t0, fmin(ta, tb));
            t1 = fmin(t1, fmax(ta, tb));
        }
    }
    return t0 < t1 ? t0 : 1;
}

static void
read_dump(cf_figure_t *fig, seen_t *s)
{
    char *text, *line, *save = NULL;
    size_t size;
    int state = 0;   /* 0 before the inset, 1 in it, 2 after its clip */
    memset(s, 0, sizeof *s);
    assert_int_equal(cf_figure_dump(fig, NULL, &text, &size, NULL), 0);
    for (line = strtok_r(text, "\n", &save); line != NULL;
         line = strtok_r(NULL, "\n", &save)) {
        char lt[64];
        double v[64];
        int n, i;
        if (strncmp(line, "group 0 inset", 13) == 0)
            state = 1;
        else if (state == 1 && strncmp(line, "clip", 4) == 0)
            state = 2;
        if (state == 0 && strncmp(line, "marker ", 7) == 0) {
            double *m = s->mark[s->nmark++];
            assert_int_equal(sscanf(strchr(line + 7, ' '), "%lf %lf size %lf",
                                    &m[0], &m[1], &m[2]), 3);
        }
        if (strncmp(line, "path", 4) != 0 || state == 2)
            continue;
        memset(lt, 0, sizeof lt);
        n = path_items(line, lt, v, 64);
        if (state == 0 && s->sq[2] == 0 && n >= 8) {
            s->sq[0] = fmin(v[0], v[4]);
            s->sq[1] = fmin(v[1], v[5]);
            s->sq[2] = fmax(v[0], v[4]);
            s->sq[3] = fmax(v[1], v[5]);
        }
        if (state != 1)
            continue;
        for (i = 0; i < n; i++) {
            if (lt[i] == 'R') {
                double *b = strstr(line, "fill") != NULL ? s->box : s->frame;
                b[0] = v[i];
                b[1] = v[i + 1];
                b[2] = v[i] + v[i + 2];
                b[3] = v[i + 1] + v[i + 3];
                i += 3;
            } else if (lt[i] == 'M' && i + 3 < n && lt[i + 2] == 'L') {
                memcpy(s->seg[s->nseg++], &v[i], 4 * sizeof *v);
                i += 3;
            }
        }
    }
    cf_free(text);
    assert_int_equal(s->nseg, 2);
    assert_true(s->box[2] > s->box[0]);
    for (int k = 0; k < 2; k++) {
        double *g = s->seg[k], t = enters(s->box, g, g + 2);
        g[2] = g[0] + t * (g[2] - g[0]);
        g[3] = g[1] + t * (g[3] - g[1]);
    }
}

/* bp from point (x, y) to segment g. */
static double
to_segment(const double *g, double x, double y)
{
    double dx = g[2] - g[0], dy = g[3] - g[1], l2 = dx * dx + dy * dy, t;
    t = l2 > 0 ? fmax(0, fmin(1, ((x - g[0]) * dx + (y - g[1]) * dy) / l2))
               : 0;
    return hypot(x - g[0] - t * dx, y - g[1] - t * dy);
}

/* Page bp to data units of the square figure. */
static void
to_data(const seen_t *s, double px, double py, double *x, double *y)
{
    *x = 10 * (px - s->sq[0]) / (s->sq[2] - s->sq[0]);
    *y = 10 * (s->sq[3] - py) / (s->sq[3] - s->sq[1]);
}

/* Two points put where an automatic inset's connectors ran: the inset's
** connectors then keep off both markers (there is room to spare). */
static void
test_connectors_avoid_points(void **state)
{
    cf_figure_t *fig = square_figure();
    double pts[4];
    seen_t a, b;
    int i, k;
    (void)state;
    add_inset(fig, CF_PLACE_AUTO, false);
    read_dump(fig, &a);
    cf_figure_destroy(fig);
    for (k = 0; k < 2; k++)
        to_data(&a, 0.5 * (a.seg[k][0] + a.seg[k][2]),
                0.5 * (a.seg[k][1] + a.seg[k][3]), &pts[2 * k],
                &pts[2 * k + 1]);
    fig = square_figure();
    assert_int_equal(cf_figure_add_points(fig, pts, 2, NULL), 0);
    add_inset(fig, CF_PLACE_AUTO, false);
    read_dump(fig, &b);
    assert_int_equal(b.nmark, 2);
    for (i = 0; i < b.nmark; i++)
        for (k = 0; k < 2; k++) {
            double d = to_segment(b.seg[k], b.mark[i][0], b.mark[i][1]);
            if (d < 0.5 * b.mark[i][2] + 1.5)
                fail_msg("connector %d passes %.2f bp from marker %d", k, d,
                         i);
        }
    cf_figure_destroy(fig);
}

/* A label put by hand on the region's frame is reported; a label placed
** automatically at the frame's corner keeps off the frame. */
static void
test_labels_see_insets(void **state)
{
    cf_figure_t *fig = square_figure();
    cf_style_t at;
    const char *w;
    seen_t s;
    (void)state;
    cf_style_init(&at);
    at.place = CF_PLACE_CENTER;
    at.set |= CF_STYLE_PLACE;
    add_inset(fig, CF_PLACE_AUTO, false);
    assert_int_equal(cf_figure_add_label(fig, 3.5, 4, "WWW", &at), 0);
    read_dump(fig, &s);
    w = cf_figure_warnings(fig);
    if (strstr(w, "WWW") == NULL)
        fail_msg("no warning for a label on an inset's frame: \"%s\"", w);
    cf_figure_destroy(fig);

    fig = square_figure();
    add_inset(fig, CF_PLACE_AUTO, false);
    assert_int_equal(cf_figure_add_label(fig, 3, 4, "WWW", NULL), 0);
    read_dump(fig, &s);
    w = cf_figure_warnings(fig);
    if (w[0] != '\0')
        fail_msg("an automatic label lies on ink: \"%s\"", w);
    cf_figure_destroy(fig);
}

/* "above" (N beside the drawing): the inset's box lies above the
** drawing's ink, "n" inside it. */
static void
test_above_is_outside(void **state)
{
    cf_figure_t *fig = square_figure();
    seen_t s;
    (void)state;
    add_inset(fig, CF_PLACE_N, true);
    read_dump(fig, &s);
    if (!(s.box[3] < s.sq[1]))
        fail_msg("inset box %g..%g, the drawing's top %g", s.box[1], s.box[3],
                 s.sq[1]);
    cf_figure_destroy(fig);
    fig = square_figure();
    add_inset(fig, CF_PLACE_N, false);
    read_dump(fig, &s);
    assert_true(s.box[1] > s.sq[1]);
    cf_figure_destroy(fig);
    /* beside is for the sides only */
    {
        cf_inset_t in;
        assert_int_equal(cf_figure_create(10, 10, CF_UNIT_CM, &fig, NULL), 0);
        cf_inset_init(&in);
        in.region[2] = in.region[3] = 1;
        in.place = CF_PLACE_NE;
        in.beside = true;
        assert_int_equal(cf_figure_add_inset(fig, &in),
                         CF_STATUS_INVALID_ARG);
        cf_figure_destroy(fig);
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_connectors_avoid_points),
        cmocka_unit_test(test_labels_see_insets),
        cmocka_unit_test(test_above_is_outside),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
