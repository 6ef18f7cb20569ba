/* Figure elements as they reach the SVG: exact cubics, fitted curves within
** the tolerance (measured against independent evaluations), graphs,
** B-splines, nets, projection, window fitting, sticky errors. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cairo.h>
#include <cmocka.h>

#include "curvefig/bspline.h"
#include "curvefig/figure.h"
#include "testutil.h"
#include "pngtest.h"

/* cairo rounds path coordinates to 1/256 pt; a point on a cubic is a
** convex combination of its control points, so rounding moves it by at
** most sqrt(2)/256 = 0.0056 pt. */
#define ROUNDING 0.0056

/* ---- SVG path parsing --------------------------------------------------- */

typedef struct seg {
    double p[8];   /* start, c1, c2, end (page pt) */
    bool line;
} seg_t;

typedef struct paths {
    seg_t seg[4096];
    size_t nseg;
    size_t nmove;          /* subpaths */
    char cmds[8192];       /* the command letters in order */
    size_t ncmd;
} paths_t;

static char *
render_svg(cf_figure_t *fig)
{
    unsigned char *data;
    size_t size;
    char *s;
    cf_diag_t d;
    cf_diag_clear(&d);
    if (cf_figure_render(fig, CF_FORMAT_SVG, NULL, &data, &size, &d)
        != CF_STATUS_OK)
        fail_msg("render: %s", d.msg);
    s = malloc(size + 1);
    memcpy(s, data, size);
    s[size] = '\0';
    cf_free(data);
    return s;
}

/* Parse the d attributes of every stroked path (style "fill:none") of the
** drawing (after </defs>, which holds the glyphs). */
static void
stroked_paths(const char *svg, paths_t *out)
{
    const char *p = strstr(svg, "</defs>");
    memset(out, 0, sizeof *out);
    if (p == NULL)
        p = svg;
    while ((p = strstr(p, "<path ")) != NULL) {
        const char *end = strchr(p, '>'), *d;
        double cur[2] = { 0, 0 };
        char *q;
        p += 6;
        if (end == NULL)
            break;
        d = strstr(p, " d=\"");
        if (d == NULL || d > end)
            continue;
        {
            const char *st = strstr(p, "style=\"");
            if (st == NULL || st > end || strstr(st, "fill:none") == NULL
                || strstr(st, "fill:none") > end)
                continue;
        }
        assert_null(strstr(p, "transform") != NULL
                            && strstr(p, "transform") < end
                        ? "transform" : NULL);
        d += 4;
        while (*d != '"') {
            char c;
            while (*d == ' ')
                d++;
            c = *d;
            if (c == '"')
                break;
            d++;
            out->cmds[out->ncmd++] = c;
            if (c == 'M') {
                cur[0] = strtod(d, &q);
                cur[1] = strtod(q, &q);
                d = q;
                out->nmove++;
            } else if (c == 'C' || c == 'L') {
                seg_t *s = &out->seg[out->nseg++];
                int k, n = c == 'C' ? 3 : 1;
                s->p[0] = cur[0];
                s->p[1] = cur[1];
                for (k = 0; k < n; k++) {
                    s->p[2 + 2 * k] = strtod(d, &q);
                    s->p[3 + 2 * k] = strtod(q, &q);
                    d = q;
                }
                if (c == 'L') {
                    /* as a cubic: thirds */
                    double x1 = s->p[2], y1 = s->p[3];
                    s->p[6] = x1;
                    s->p[7] = y1;
                    s->p[2] = cur[0] + (x1 - cur[0]) / 3;
                    s->p[3] = cur[1] + (y1 - cur[1]) / 3;
                    s->p[4] = cur[0] + 2 * (x1 - cur[0]) / 3;
                    s->p[5] = cur[1] + 2 * (y1 - cur[1]) / 3;
                    s->line = true;
                }
                cur[0] = s->p[6];
                cur[1] = s->p[7];
            } else if (c != 'Z') {
                fail_msg("unexpected path command %c", c);
            }
        }
        p = end;
    }
    out->cmds[out->ncmd] = '\0';
}

static void
cubic_at(const double *c, double s, double *x, double *y)
{
    double u = 1 - s;
    *x = u * u * u * c[0] + 3 * u * u * s * c[2] + 3 * u * s * s * c[4]
        + s * s * s * c[6];
    *y = u * u * u * c[1] + 3 * u * u * s * c[3] + 3 * u * s * s * c[5]
        + s * s * s * c[7];
}

/* Distance from q to the polyline pts[n] (2D). */
static double
dist_polyline(const double *pts, size_t n, double qx, double qy)
{
    double best = INFINITY;
    size_t i;
    for (i = 0; i + 1 < n; i++) {
        double ax = pts[2 * i], ay = pts[2 * i + 1];
        double bx = pts[2 * i + 2] - ax, by = pts[2 * i + 3] - ay;
        double l2 = bx * bx + by * by, t = 0, dx, dy;
        if (l2 > 0)
            t = fmin(1, fmax(0, ((qx - ax) * bx + (qy - ay) * by) / l2));
        dx = qx - ax - t * bx;
        dy = qy - ay - t * by;
        best = fmin(best, hypot(dx, dy));
    }
    return best;
}

/* Independent evaluation of a (rational) Bézier by the Bernstein sum. */
static void
bernstein_eval(const double *P, const double *w, int n, double t,
               double *out)
{
    double sx = 0, sy = 0, sw = 0, b;
    int i, k;
    for (i = 0; i <= n; i++) {
        b = 1;
        for (k = 1; k <= i; k++)
            b = b * (n - i + k) / k;    /* C(n, i) */
        b *= pow(t, i) * pow(1 - t, n - i);
        b *= w != NULL ? w[i] : 1.0;
        sx += b * P[2 * i];
        sy += b * P[2 * i + 1];
        sw += b;
    }
    out[0] = sx / sw;
    out[1] = sy / sw;
}

static cf_figure_t *
new_fig(void)
{
    cf_figure_t *fig = NULL;
    assert_int_equal(cf_figure_create(120, 90, CF_UNIT_MM, &fig, NULL),
                     CF_STATUS_OK);
    return fig;
}

/* The data -> page map of a rendered figure: scale from the figure, the
** offset from a known data point (x0, y0) appearing at page (px0, py0). */
typedef struct map {
    double sx, sy, px0, py0, x0, y0;
} map_t;

static void
to_page(const map_t *m, double x, double y, double *px, double *py)
{
    *px = m->px0 + m->sx * (x - m->x0);
    *py = m->py0 - m->sy * (y - m->y0);
}

/* The map of a rendered figure whose first path starts at data (x0, y0). */
static map_t
map_from(cf_figure_t *fig, const paths_t *ps, double x0, double y0)
{
    map_t m;
    assert_int_equal(cf_figure_get_window(fig, NULL, &m.sx, &m.sy),
                     CF_STATUS_OK);
    m.px0 = ps->seg[0].p[0];
    m.py0 = ps->seg[0].p[1];
    m.x0 = x0;
    m.y0 = y0;
    return m;
}

/* Max distance (page pt) from the drawn path to the exact curve given as a
** dense polyline in data coordinates. */
static double
path_error(const paths_t *ps, const map_t *m, const double *exact, size_t n)
{
    double *pg = malloc(2 * n * sizeof *pg), worst = 0;
    size_t i, k;
    for (i = 0; i < n; i++)
        to_page(m, exact[2 * i], exact[2 * i + 1], &pg[2 * i],
                &pg[2 * i + 1]);
    for (i = 0; i < ps->nseg; i++) {
        for (k = 0; k <= 32; k++) {
            double x, y;
            cubic_at(ps->seg[i].p, k / 32.0, &x, &y);
            worst = fmax(worst, dist_polyline(pg, n, x, y));
        }
    }
    free(pg);
    return worst;
}

/* ---- tests -------------------------------------------------------------- */

static void
test_cubic_is_one_C(void **state)
{
    double P[] = { 0, 0, 1, 2, 3, 2, 4, 0 };
    cf_bezier_t *c;
    cf_figure_t *fig = new_fig();
    paths_t *ps = malloc(sizeof *ps);
    map_t m;
    char *svg;
    int k;
    (void)state;
    assert_int_equal(cf_bezier_create(2, 3, P, NULL, &c, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_figure_add_bezier(fig, c, NULL), CF_STATUS_OK);
    svg = render_svg(fig);
    stroked_paths(svg, ps);
    /* one subpath, one cubic segment */
    assert_string_equal(ps->cmds, "MC");
    /* its control points are the curve's, mapped (the map is affine,
    ** so the segment is the curve itself) */
    m = map_from(fig, ps, 0, 0);
    tu_assert_close(m.sx, m.sy, 1e-12, 0);   /* aspect ratio kept */
    for (k = 1; k < 4; k++) {
        double px, py;
        to_page(&m, P[2 * k], P[2 * k + 1], &px, &py);
        assert_true(fabs(px - ps->seg[0].p[2 * k]) <= 1.0 / 256);
        assert_true(fabs(py - ps->seg[0].p[2 * k + 1]) <= 1.0 / 256);
    }
    free(svg);
    free(ps);
    cf_bezier_destroy(c);
    cf_figure_destroy(fig);
}

static void
check_fitted(const double *P, const double *w, int n, size_t max_segments)
{
    cf_bezier_t *c;
    cf_figure_t *fig = new_fig();
    paths_t *ps = malloc(sizeof *ps);
    size_t N = 20001, i;
    double *exact = malloc(2 * N * sizeof *exact), err, end[2];
    map_t m;
    char *svg;

    assert_int_equal(cf_bezier_create(2, n, P, w, &c, NULL), CF_STATUS_OK);
    assert_int_equal(cf_figure_add_bezier(fig, c, NULL), CF_STATUS_OK);
    svg = render_svg(fig);
    stroked_paths(svg, ps);
    assert_int_equal(ps->nmove, 1);
    assert_true(ps->nseg >= 1 && ps->nseg <= max_segments);
    for (i = 0; i < ps->ncmd; i++)
        assert_true(ps->cmds[i] == 'M' || ps->cmds[i] == 'C');
    m = map_from(fig, ps, P[0], P[1]);
    for (i = 0; i < N; i++)
        bernstein_eval(P, w, n, (double)i / (N - 1), exact + 2 * i);
    /* the path is within the default tolerance 0.01 pt of the curve
    ** (plus cairo's rounding; the dense polyline of 20000 chords adds
    ** < 1e-4 pt at these curvatures) */
    err = path_error(ps, &m, exact, N);
    assert_true(err <= 0.01 + ROUNDING + 1e-4);
    /* and it covers the whole curve: it ends at c(1) */
    to_page(&m, exact[2 * N - 2], exact[2 * N - 1], &end[0], &end[1]);
    assert_true(hypot(end[0] - ps->seg[ps->nseg - 1].p[6],
                      end[1] - ps->seg[ps->nseg - 1].p[7])
                <= 2.0 / 256);
    free(exact);
    free(svg);
    free(ps);
    cf_bezier_destroy(c);
    cf_figure_destroy(fig);
}

static void
test_degree5_fitted(void **state)
{
    double P[] = { 0, 0, 1, 4, 2, -3, 3, 5, 4, -2, 5, 1 };
    (void)state;
    /* "few": cf_bezier_to_cubics gives 22 at this scale (about 300 pt
    ** across; tolerance 3e-5 of the size) */
    check_fitted(P, NULL, 5, 24);
}

static void
test_rational_arc_fitted(void **state)
{
    /* a quarter circle of radius 1 about the origin: w = 1, sqrt(2)/2, 1 */
    double P[] = { 1, 0, 1, 1, 0, 1 }, w[] = { 1, sqrt(0.5), 1 };
    cf_bezier_t *c;
    cf_figure_t *fig = new_fig();
    paths_t *ps = malloc(sizeof *ps);
    double sx, sy, cx, cy, r, worst = 0;
    size_t i, k;
    char *svg;
    (void)state;
    check_fitted(P, w, 2, 8);
    /* independently of any evaluator: every drawn point lies on the
    ** circle */
    assert_int_equal(cf_bezier_create(2, 2, P, w, &c, NULL), CF_STATUS_OK);
    assert_int_equal(cf_figure_add_bezier(fig, c, NULL), CF_STATUS_OK);
    svg = render_svg(fig);
    stroked_paths(svg, ps);
    assert_int_equal(cf_figure_get_window(fig, NULL, &sx, &sy),
                     CF_STATUS_OK);
    r = sx;
    cx = ps->seg[0].p[0] - r;   /* the path starts at (1, 0) */
    cy = ps->seg[0].p[1];
    for (i = 0; i < ps->nseg; i++)
        for (k = 0; k <= 64; k++) {
            double x, y;
            cubic_at(ps->seg[i].p, k / 64.0, &x, &y);
            worst = fmax(worst, fabs(hypot(x - cx, y - cy) - r));
        }
    /* tolerance + rounding of the segment and of the start point used as
    ** the reference */
    assert_true(worst <= 0.01 + 2 * ROUNDING);
    free(svg);
    free(ps);
    cf_bezier_destroy(c);
    cf_figure_destroy(fig);
}

static void
test_tolerance_option(void **state)
{
    double P[] = { 0, 0, 1, 4, 2, -3, 3, 5, 4, -2, 5, 1 };
    cf_bezier_t *c;
    size_t coarse, fine;
    paths_t *ps = malloc(sizeof *ps);
    int pass;
    (void)state;
    assert_int_equal(cf_bezier_create(2, 5, P, NULL, &c, NULL),
                     CF_STATUS_OK);
    for (pass = 0; pass < 2; pass++) {
        cf_figure_t *fig = new_fig();
        char *svg;
        assert_int_equal(cf_figure_set_tolerance(fig, pass ? 1e-4 : 1.0),
                         CF_STATUS_OK);
        assert_int_equal(cf_figure_add_bezier(fig, c, NULL), CF_STATUS_OK);
        svg = render_svg(fig);
        stroked_paths(svg, ps);
        if (pass)
            fine = ps->nseg;
        else
            coarse = ps->nseg;
        free(svg);
        cf_figure_destroy(fig);
    }
    /* a tighter tolerance needs more segments */
    assert_true(fine > coarse);
    free(ps);
    cf_bezier_destroy(c);
}

/* N_i^p by the Cox-de Boor recursion (0/0 = 0) on half-open spans: the
** independent value for test_basis_graph (whose knots are all simple, so
** N_i^p is continuous and the right end of the range needs no care). */
static double
cox_de_boor(const double *u, int i, int p, double x)
{
    double a = 0, b = 0;
    if (p == 0)
        return u[i] <= x && x < u[i + 1] ? 1 : 0;
    if (u[i + p] > u[i])
        a = (x - u[i]) / (u[i + p] - u[i]) * cox_de_boor(u, i, p - 1, x);
    if (u[i + p + 1] > u[i + 1])
        b = (u[i + p + 1] - x) / (u[i + p + 1] - u[i + 1])
            * cox_de_boor(u, i + 1, p - 1, x);
    return a + b;
}

static void
test_basis_graph(void **state)
{
    /* N_1^2 and N_2^3 over uneven knots, drawn over the whole range
    ** [0, 15]: the path must follow Cox-de Boor's values (zero outside
    ** the support) within the 1/256 pt rounding plus the sag of the
    ** 6001-point reference polyline (below 1e-4 pt here) */
    static const double U[] = { 0, 1, 3, 6, 10, 11, 15 };
    static const int cases[][2] = { { 1, 2 }, { 2, 3 }, { 0, 1 } };
    size_t n = 6001;
    double *exact = malloc(2 * n * sizeof *exact);
    paths_t *ps = malloc(sizeof *ps);
    (void)state;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        cf_figure_t *fig = new_fig();
        const seg_t *last;
        double px, py;
        map_t m;
        char *svg;
        assert_int_equal(cf_figure_add_basis(fig, U, 7, cases[c][0],
                                             cases[c][1], NULL),
                         CF_STATUS_OK);
        for (size_t k = 0; k < n; k++) {
            double x = 15.0 * (double)k / (double)(n - 1);
            exact[2 * k] = x;
            exact[2 * k + 1] = cox_de_boor(U, cases[c][0], cases[c][1], x);
        }
        svg = render_svg(fig);
        stroked_paths(svg, ps);
        assert_true(ps->nseg >= 1);
        assert_int_equal(ps->nmove, 1);   /* continuous for p >= 1 */
        m = map_from(fig, ps, 0.0, 0.0);  /* N(0) = 0: starts at (0, 0) */
        assert_true(path_error(ps, &m, exact, n) <= 2 * ROUNDING);
        /* and ends at (15, 0): the whole knot range is drawn */
        last = &ps->seg[ps->nseg - 1];
        to_page(&m, 15.0, 0.0, &px, &py);
        assert_true(fabs(last->p[6] - px) <= ROUNDING
                    && fabs(last->p[7] - py) <= ROUNDING);
        free(svg);
        cf_figure_destroy(fig);
    }
    free(exact);
    free(ps);
}

static void
test_basis_errors(void **state)
{
    static const double up[] = { 0, 1, 3, 2, 10 }, flat[] = { 2, 2, 2, 2 };
    static const double nan_knots[] = { 0, 1, NAN, 3, 4 };
    static const struct {
        const double *u;
        size_t m;
        int i, p;
        cf_status_t st;
        const char *msg;
    } cases[] = {
        { up, 5, 0, 2, CF_STATUS_BAD_KNOTS,
          "knot u_3 (2.00) is smaller than knot u_2 (3.00)" },
        { up, 5, 2, 2, CF_STATUS_INVALID_ARG,
          "N_2^2 needs knots u_2..u_5, 5 given" },
        { up, 5, 0, -1, CF_STATUS_BAD_DEGREE, "degree -1" },
        { flat, 4, 0, 2, CF_STATUS_BAD_KNOTS, "span no interval" },
        { nan_knots, 5, 0, 2, CF_STATUS_NOT_FINITE, "knot u_2 is NaN" },
    };
    (void)state;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        cf_figure_t *fig = new_fig();
        cf_diag_t d;
        cf_diag_clear(&d);
        assert_int_equal(cf_figure_add_basis(fig, cases[c].u, cases[c].m,
                                             cases[c].i, cases[c].p, NULL),
                         cases[c].st);
        assert_int_equal(cf_figure_status(fig, &d), cases[c].st);
        if (strstr(d.msg, cases[c].msg) == NULL)
            fail_msg("case %zu: \"%s\" lacks \"%s\"", c, d.msg,
                     cases[c].msg);
        cf_figure_destroy(fig);
    }
}

static void
test_graph_exact(void **state)
{
    /* B_1^2 on [0, 1] as one piece, and a hat function as two */
    double b12[] = { 0, 1, 0 }, up[] = { 0, 1 }, down[] = { 1, 0 };
    double br1[] = { 0, 1 }, br2[] = { 0, 1, 2 };
    cf_bezier_t *b, *u, *d;
    const cf_bezier_t *one[1], *two[2];
    paths_t *ps = malloc(sizeof *ps);
    cf_figure_t *fig = new_fig();
    char *svg;
    map_t m;
    double px, py;
    (void)state;
    assert_int_equal(cf_bezier_create(1, 2, b12, NULL, &b, NULL), 0);
    assert_int_equal(cf_bezier_create(1, 1, up, NULL, &u, NULL), 0);
    assert_int_equal(cf_bezier_create(1, 1, down, NULL, &d, NULL), 0);
    one[0] = b;
    assert_int_equal(cf_figure_add_graph(fig, one, br1, 1, NULL), 0);
    svg = render_svg(fig);
    stroked_paths(svg, ps);
    assert_string_equal(ps->cmds, "MC");
    /* the segment is the degree-elevated polynomial: control values
    ** (0, 2/3, 2/3, 0) at x = 0, 1/3, 2/3, 1 */
    m = map_from(fig, ps, 0, 0);
    to_page(&m, 1.0 / 3, 2.0 / 3, &px, &py);
    assert_true(fabs(px - ps->seg[0].p[2]) <= 1.0 / 256
                && fabs(py - ps->seg[0].p[3]) <= 1.0 / 256);
    to_page(&m, 2.0 / 3, 2.0 / 3, &px, &py);
    assert_true(fabs(px - ps->seg[0].p[4]) <= 1.0 / 256
                && fabs(py - ps->seg[0].p[5]) <= 1.0 / 256);
    free(svg);
    cf_figure_destroy(fig);

    fig = new_fig();
    two[0] = u;
    two[1] = d;
    assert_int_equal(cf_figure_add_graph(fig, two, br2, 2, NULL), 0);
    svg = render_svg(fig);
    stroked_paths(svg, ps);
    assert_string_equal(ps->cmds, "MCC");   /* continuous: one subpath */
    free(svg);
    cf_figure_destroy(fig);

    /* a jump starts a new subpath */
    fig = new_fig();
    two[0] = u;
    two[1] = u;
    assert_int_equal(cf_figure_add_graph(fig, two, br2, 2, NULL), 0);
    svg = render_svg(fig);
    stroked_paths(svg, ps);
    assert_string_equal(ps->cmds, "MCMC");
    free(svg);
    cf_figure_destroy(fig);

    /* dimension 2 and rational pieces are refused */
    fig = new_fig();
    {
        double pts[] = { 0, 0, 1, 1 }, w[] = { 1, 2 };
        cf_bezier_t *p2, *r1;
        cf_diag_t dg;
        cf_diag_clear(&dg);
        assert_int_equal(cf_bezier_create(2, 1, pts, NULL, &p2, NULL), 0);
        one[0] = p2;
        assert_int_equal(cf_figure_add_graph(fig, one, br1, 1, NULL),
                         CF_STATUS_INVALID_ARG);
        cf_figure_destroy(fig);
        fig = new_fig();
        assert_int_equal(cf_bezier_create(1, 1, up, w, &r1, NULL), 0);
        one[0] = r1;
        assert_int_equal(cf_figure_add_graph(fig, one, br1, 1, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_figure_status(fig, &dg), CF_STATUS_INVALID_ARG);
        assert_non_null(strstr(dg.msg, "rational"));
        cf_bezier_destroy(p2);
        cf_bezier_destroy(r1);
    }
    cf_figure_destroy(fig);
    cf_bezier_destroy(b);
    cf_bezier_destroy(u);
    cf_bezier_destroy(d);
    free(ps);
}

static int
fn_sin(void *closure, double x, double *y)
{
    (void)closure;
    *y = sin(x);
    return 0;
}

static int
fn_stop(void *closure, double x, double *y)
{
    (void)closure;
    *y = x;
    return x > 0.5;
}

static int
fn_nan(void *closure, double x, double *y)
{
    (void)closure;
    *y = x > 0.5 ? NAN : x;
    return 0;
}

static void
test_function_graph(void **state)
{
    cf_figure_t *fig = new_fig();
    paths_t *ps = malloc(sizeof *ps);
    double sx, sy, worst = 0;
    size_t i, k;
    char *svg;
    (void)state;
    assert_int_equal(cf_figure_add_function(fig, fn_sin, NULL, 0, 2 * 3.14159265358979323846,
                                            NULL), CF_STATUS_OK);
    svg = render_svg(fig);
    stroked_paths(svg, ps);
    assert_int_equal(ps->nmove, 1);
    assert_true(ps->nseg >= 4 && ps->nseg < 200);
    assert_int_equal(cf_figure_get_window(fig, NULL, &sx, &sy), 0);
    for (i = 0; i < ps->nseg; i++)
        for (k = 0; k <= 16; k++) {
            double px, py, x, y;
            cubic_at(ps->seg[i].p, k / 16.0, &px, &py);
            x = (px - ps->seg[0].p[0]) / sx;   /* starts at (0, 0) */
            y = -(py - ps->seg[0].p[1]) / sy;
            /* the graph of a function: x maps back inside [0, 2 pi] */
            assert_true(x >= -1e-3 && x <= 2 * 3.14159265358979323846 + 1e-3);
            worst = fmax(worst, fabs(y - sin(x)) * sy);
        }
    /* promised: 2e-5 of the range (2) in data units; plus rounding of the
    ** point and of the reference start, in x and y (x error times
    ** |sin'| <= 1 in data units) */
    assert_true(worst <= 2e-5 * 2 * sy + 4 * ROUNDING);
    free(svg);
    cf_figure_destroy(fig);

    fig = new_fig();
    assert_int_equal(cf_figure_add_function(fig, fn_stop, NULL, 0, 1, NULL),
                     CF_STATUS_INVALID_ARG);
    cf_figure_destroy(fig);
    fig = new_fig();
    assert_int_equal(cf_figure_add_function(fig, fn_nan, NULL, 0, 1, NULL),
                     CF_STATUS_NOT_FINITE);
    cf_figure_destroy(fig);
    fig = new_fig();
    assert_int_equal(cf_figure_add_function(fig, fn_sin, NULL, 1, 1, NULL),
                     CF_STATUS_INVALID_ARG);
    cf_figure_destroy(fig);
    free(ps);
}

static void
test_bspline_pieces(void **state)
{
    /* the thesis' sample curve: p = 2, 8 points, 6 non-empty spans */
    double P[] = { 3, 1, 3.75, 2, 5, 3, 4, 4, 3, 3, 2, 4, 1, 3, 2.25, 2 };
    double U[] = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83, 1, 1, 1 };
    cf_bspline_t *s;
    cf_figure_t *fig = new_fig();
    paths_t *ps = malloc(sizeof *ps);
    double q[2], px, py;
    map_t m;
    char *svg;
    size_t i;
    (void)state;
    assert_int_equal(cf_bspline_create(2, 2, U, 11, P, 8, NULL, &s, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_figure_add_bspline(fig, s, 0, 0, NULL), 0);
    svg = render_svg(fig);
    stroked_paths(svg, ps);
    /* quadratic pieces are exact cubics: one C per span */
    assert_string_equal(ps->cmds, "MCCCCCC");
    m = map_from(fig, ps, 3, 1);
    /* segment i ends at the knot point C(u_{i+3}) */
    for (i = 0; i < 6; i++) {
        assert_int_equal(cf_bspline_eval(s, U[i + 3], q), 0);
        to_page(&m, q[0], q[1], &px, &py);
        assert_true(hypot(px - ps->seg[i].p[6], py - ps->seg[i].p[7])
                    <= 2.0 / 256);
    }
    free(svg);
    cf_figure_destroy(fig);

    /* the same pieces as a list: one path, one C per piece */
    {
        cf_bezier_list_t *list;
        assert_int_equal(cf_bspline_to_beziers(s, &list, NULL), 0);
        fig = new_fig();
        assert_int_equal(cf_figure_add_bezier_list(fig, list, NULL), 0);
        svg = render_svg(fig);
        stroked_paths(svg, ps);
        assert_string_equal(ps->cmds, "MCCCCCC");
        {
            /* a NULL item is refused (the item is put back afterwards) */
            cf_figure_t *f2 = new_fig();
            cf_bezier_t *keep = list->items[2];
            list->items[2] = NULL;
            assert_int_equal(cf_figure_add_bezier_list(f2, list, NULL),
                             CF_STATUS_INVALID_ARG);
            list->items[2] = keep;
            cf_figure_destroy(f2);
        }
        cf_bezier_list_destroy(list);
        free(svg);
        cf_figure_destroy(fig);
    }

    /* a sub-range [0.3, 0.6] touches three spans */
    fig = new_fig();
    assert_int_equal(cf_figure_add_bspline(fig, s, 0.3, 0.6, NULL), 0);
    assert_int_equal(cf_figure_add_bspline(fig, s, 0.6, 0.3, NULL),
                     CF_STATUS_DOMAIN);
    cf_figure_destroy(fig);
    fig = new_fig();
    assert_int_equal(cf_figure_add_bspline(fig, s, 0.3, 0.6, NULL), 0);
    assert_int_equal(cf_figure_add_bspline_knots(fig, s, NULL), 0);
    svg = render_svg(fig);
    stroked_paths(svg, ps);
    assert_int_equal(ps->nmove, 1 + 7);   /* the arc + 7 knot ticks */
    assert_int_equal(ps->nseg, 3 + 7);
    free(svg);
    cf_figure_destroy(fig);
    cf_bspline_destroy(s);
    free(ps);
}

static void
test_net_colours_and_projection(void **state)
{
    double P[] = { 0, 5, 1, -1, 3, 0, 4, 3, 6, 10 }, tri[30];
    size_t counts[] = { 5, 4, 3, 2, 1 }, i, j, ncol = 0;
    char colours[8][64];
    cf_bezier_t *c;
    cf_figure_t *fig = new_fig();
    char *svg;
    const char *p;
    (void)state;
    assert_int_equal(cf_bezier_create(2, 4, P, NULL, &c, NULL), 0);
    assert_int_equal(cf_bezier_decasteljau(c, 0.75, tri), 0);
    assert_int_equal(cf_figure_add_net(fig, tri, counts, 5, NULL, NULL), 0);
    svg = render_svg(fig);
    /* four stroked levels (the last is a single point), each its own
    ** colour */
    p = strstr(svg, "</defs>");
    p = p != NULL ? p : svg;
    while ((p = strstr(p, "fill:none")) != NULL) {
        const char *st = strstr(p, "stroke:rgb(");
        size_t n = strcspn(st, ")");
        assert_true(n < 64 && ncol < 8);
        memcpy(colours[ncol], st, n);
        colours[ncol][n] = '\0';
        ncol++;
        p = st;
    }
    assert_int_equal(ncol, 4);
    for (i = 0; i < ncol; i++)
        for (j = i + 1; j < ncol; j++)
            assert_string_not_equal(colours[i], colours[j]);
    free(svg);
    cf_figure_destroy(fig);
    cf_bezier_destroy(c);

    /* a cubic in R^3 through a projection: still one exact C, with the
    ** projected control points */
    {
        double Q[] = { 0, 0, 0, 1, 0, 2, 2, 1, 2, 3, 1, 0 };
        double M[] = { 1, 0, 0.5, 0, 1, 0.3 }, proj[8];
        paths_t *ps = malloc(sizeof *ps);
        map_t m;
        fig = new_fig();
        assert_int_equal(cf_figure_set_projection(fig, 3, M), 0);
        assert_int_equal(cf_figure_project(fig, Q, 4, 3, proj), 0);
        tu_assert_close(proj[2], 1 + 0.5 * 2, 1e-15, 0);
        tu_assert_close(proj[3], 0 + 0.3 * 2, 1e-15, 0);
        assert_int_equal(cf_bezier_create(3, 3, Q, NULL, &c, NULL), 0);
        assert_int_equal(cf_figure_add_bezier(fig, c, NULL), 0);
        svg = render_svg(fig);
        stroked_paths(svg, ps);
        assert_string_equal(ps->cmds, "MC");
        m = map_from(fig, ps, 0, 0);
        for (i = 1; i < 4; i++) {
            double px, py;
            to_page(&m, proj[2 * i], proj[2 * i + 1], &px, &py);
            assert_true(hypot(px - ps->seg[0].p[2 * i],
                              py - ps->seg[0].p[2 * i + 1]) <= 2.0 / 256);
        }
        free(svg);
        free(ps);
        cf_figure_destroy(fig);
        cf_bezier_destroy(c);
    }
}

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
    p = strstr(p != NULL ? p : svg, "fill-opacity:0.35");
    assert_non_null(p);
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
    p = strstr(p, "stroke-width:3;");
    assert_non_null(p);
    assert_non_null(strstr(p, "stroke:rgb(100%,100%,100%)"));
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

/* ---- errors ------------------------------------------------------------- */

#define EXPECT(call, status)                                               \
    do {                                                                   \
        cf_figure_t *fig = new_fig();                                      \
        cf_diag_t dg_;                                                     \
        cf_diag_clear(&dg_);                                               \
        assert_int_equal((call), (status));                                \
        assert_int_equal(cf_figure_status(fig, &dg_), (status));           \
        assert_true(strlen(dg_.msg) > 0);                                  \
        cf_figure_destroy(fig);                                            \
    } while (0)

static void
test_bad_input(void **state)
{
    double pts[] = { 0, 0, 1, 1, 2, 0 }, nanpts[] = { 0, 0, NAN, 1 };
    double one[] = { 0, 1 };
    cf_bezier_t *line, *c1;
    cf_style_t bad;
    cf_axes_t ax;
    cf_figure_t *f2 = NULL;
    const cf_bezier_t *pieces[1];
    size_t counts[] = { 2, 0 };
    (void)state;
    assert_int_equal(cf_bezier_create(2, 1, pts, NULL, &line, NULL), 0);
    assert_int_equal(cf_bezier_create(1, 1, one, NULL, &c1, NULL), 0);
    cf_style_init(&bad);
    bad.set = CF_STYLE_WIDTH;
    bad.width = -1;

    /* creation */
    assert_int_equal(cf_figure_create(0, 10, CF_UNIT_MM, &f2, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_null(f2);
    assert_int_equal(cf_figure_create(-5, 10, CF_UNIT_MM, &f2, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_figure_create(NAN, 10, CF_UNIT_MM, &f2, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_figure_create(10, INFINITY, CF_UNIT_MM, &f2, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_figure_create(10, 10, (cf_unit_t)42, &f2, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_figure_create(10, 10, CF_UNIT_MM, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_null(f2);

    /* elements */
    EXPECT(cf_figure_add_points(fig, nanpts, 2, NULL), CF_STATUS_NOT_FINITE);
    EXPECT(cf_figure_add_points(fig, NULL, 2, NULL), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_polygon(fig, pts, 0, NULL),
           CF_STATUS_TOO_FEW_POINTS);
    EXPECT(cf_figure_add_polyline(fig, pts, 1, false, NULL),
           CF_STATUS_TOO_FEW_POINTS);
    EXPECT(cf_figure_add_fill(fig, pts, 2, NULL), CF_STATUS_TOO_FEW_POINTS);
    EXPECT(cf_figure_add_hull(fig, nanpts, 2, NULL), CF_STATUS_NOT_FINITE);
    EXPECT(cf_figure_add_polygon(fig, pts, 3, &bad), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_bezier(fig, NULL, NULL), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_bezier(fig, c1, NULL), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_bezier_range(fig, line, 0.5, 0.2, NULL),
           CF_STATUS_DOMAIN);
    EXPECT(cf_figure_add_bezier_range(fig, line, NAN, 0.2, NULL),
           CF_STATUS_NOT_FINITE);
    EXPECT(cf_figure_add_cubics(fig, NULL, NULL), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_arrow(fig, 0, 0, NAN, 1, NULL),
           CF_STATUS_NOT_FINITE);
    EXPECT(cf_figure_add_label(fig, 0, 0, "P_", NULL),
           CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_label(fig, INFINITY, 0, "P", NULL),
           CF_STATUS_NOT_FINITE);
    EXPECT(cf_figure_add_label(fig, 0, 0, NULL, NULL),
           CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_net(fig, pts, counts, 2, NULL, NULL),
           CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_net(fig, pts, NULL, 1, NULL, NULL),
           CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_knot_marks(fig, pts, nanpts, 2, NULL),
           CF_STATUS_NOT_FINITE);
    pieces[0] = c1;
    EXPECT(cf_figure_add_graph(fig, pieces, NULL, 1, NULL),
           CF_STATUS_INVALID_ARG);
    {
        double rev[] = { 1, 0 };
        EXPECT(cf_figure_add_graph(fig, pieces, rev, 1, NULL),
               CF_STATUS_INVALID_ARG);
    }
    EXPECT(cf_figure_add_graph_list(fig, NULL, NULL), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_add_function(fig, NULL, NULL, 0, 1, NULL),
           CF_STATUS_INVALID_ARG);
    cf_axes_init(&ax);
    ax.xmin = 2;
    ax.xmax = 1;
    EXPECT(cf_figure_add_axes(fig, &ax, NULL), CF_STATUS_INVALID_ARG);
    cf_axes_init(&ax);
    ax.ymax = NAN;
    EXPECT(cf_figure_add_axes(fig, &ax, NULL), CF_STATUS_NOT_FINITE);
    cf_axes_init(&ax);
    ax.xtick_step = 1e-9;
    EXPECT(cf_figure_add_axes(fig, &ax, NULL), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_set_window(fig, 1, 1, 0, 1), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_set_window(fig, 0, 1, NAN, 1), CF_STATUS_NOT_FINITE);
    EXPECT(cf_figure_set_fit(fig, -1, true), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_set_tolerance(fig, 0), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_set_projection(fig, 1, pts), CF_STATUS_INVALID_ARG);
    EXPECT(cf_figure_set_theme(fig, NULL), CF_STATUS_INVALID_ARG);
    {
        cf_theme_t t;
        assert_int_equal(cf_theme_get("default", &t, NULL), 0);
        t.palette_size = 0;
        EXPECT(cf_figure_set_theme(fig, &t), CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_theme_get("mono", &t, NULL), 0);
        t.role[CF_ROLE_CURVE].color.r = 2;
        EXPECT(cf_figure_set_theme(fig, &t), CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_theme_get("neon", &t, NULL),
                         CF_STATUS_INVALID_ARG);
    }
    /* NULL figure */
    assert_int_equal(cf_figure_add_points(NULL, pts, 1, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_figure_status(NULL, NULL), CF_STATUS_INVALID_ARG);
    cf_figure_destroy(NULL);

    /* names */
    {
        cf_marker_t mk;
        cf_place_t pl;
        cf_unit_t un;
        cf_color_t col;
        assert_int_equal(cf_marker_from_name("star", &mk, NULL), 0);
        assert_int_equal(mk, CF_MARKER_STAR);
        assert_int_equal(cf_marker_from_name("blob", &mk, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_place_from_name("below", &pl, NULL), 0);
        assert_int_equal(pl, CF_PLACE_S);
        assert_int_equal(cf_place_from_name("up", &pl, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_unit_from_name("texpt", &un, NULL), 0);
        assert_int_equal(un, CF_UNIT_TEXPT);
        assert_int_equal(cf_unit_from_name("px", &un, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_color_parse("#ff800080", &col, NULL), 0);
        tu_assert_close(col.g, 128.0 / 255, 1e-15, 0);
        tu_assert_close(col.a, 128.0 / 255, 1e-15, 0);
        assert_int_equal(cf_color_parse("#ff80", &col, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_color_parse("#gg0000", &col, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_color_parse("chartreuse", &col, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_color_parse("none", &col, NULL), 0);
        assert_true(col.a == 0);
    }
    cf_bezier_destroy(line);
    cf_bezier_destroy(c1);
}

/* Coordinates near DBL_MAX: the extent overflows; the write fails with a
** message saying so, not with a tolerance the user never set (finding
** F4). */
static void
test_huge_extent_refused(void **state)
{
    const double pts[] = { -1.7e308, 0.0, 1.7e308, 1.0 };
    cf_figure_t *fig = NULL;
    unsigned char *data = NULL;
    size_t size = 0;
    cf_diag_t d;
    (void)state;
    assert_int_equal(cf_figure_create(8, 6, CF_UNIT_CM, &fig, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_figure_add_polyline(fig, pts, 2, false, NULL),
                     CF_STATUS_OK);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, NULL, &data,
                                      &size, &d), CF_STATUS_NOT_FINITE);
    assert_null(data);
    assert_non_null(strstr(d.msg, "the drawing spans"));
    assert_non_null(strstr(d.msg, "too large"));
    cf_figure_destroy(fig);

    assert_int_equal(cf_figure_create(8, 6, CF_UNIT_CM, &fig, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_figure_set_window(fig, -1e308, 1e308, -1e308,
                                          1e308), CF_STATUS_OK);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, NULL, &data,
                                      &size, &d), CF_STATUS_NOT_FINITE);
    assert_non_null(strstr(d.msg, "the window spans"));
    cf_figure_destroy(fig);
}

static void
test_sticky_error(void **state)
{
    double pts[] = { 0, 0, 1, 1 }, nanpts[] = { 0, NAN };
    cf_figure_t *fig = new_fig();
    cf_diag_t d;
    unsigned char *data = NULL;
    size_t size = 1;
    (void)state;
    assert_int_equal(cf_figure_add_polygon(fig, pts, 2, NULL), 0);
    assert_int_equal(cf_figure_add_points(fig, nanpts, 1, NULL),
                     CF_STATUS_NOT_FINITE);
    /* the first error is kept; later calls do nothing and return it */
    assert_int_equal(cf_figure_add_label(fig, 0, 0, "P_", NULL),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_figure_add_polygon(fig, pts, 2, NULL),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_figure_set_tolerance(fig, 1), CF_STATUS_NOT_FINITE);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_status(fig, &d), CF_STATUS_NOT_FINITE);
    assert_int_equal(d.status, CF_STATUS_NOT_FINITE);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_render(fig, CF_FORMAT_SVG, NULL, &data, &size,
                                      &d), CF_STATUS_NOT_FINITE);
    assert_null(data);
    assert_int_equal(size, 0);
    assert_true(strlen(d.msg) > 0);
    cf_figure_destroy(fig);
}

/* A constant (degree-0) graph piece is drawn as a horizontal segment over
** its whole interval (f:bernstein(0, 0) in the figure language: B_0^0 = 1
** on [0, 1]).  The piece is widened to degree 1 inside the renderer. */
static void
test_graph_constant_piece(void **state)
{
    double y0 = 0.75, breaks[] = { -1, 2 };
    cf_bezier_t *c = NULL;
    const cf_bezier_t *pieces[1];
    cf_figure_t *fig = NULL;
    char *text = NULL;
    const char *p;
    size_t size;
    double w[4], x0, ya, x1, yb, c1[4];
    (void)state;
    assert_int_equal(cf_bezier_create(1, 0, &y0, NULL, &c, NULL), 0);
    assert_int_equal(cf_figure_create(60, 40, CF_UNIT_MM, &fig, NULL), 0);
    pieces[0] = c;
    assert_int_equal(cf_figure_add_graph(fig, pieces, breaks, 1, NULL), 0);
    assert_int_equal(cf_figure_get_window(fig, w, NULL, NULL), 0);
    assert_float_equal(w[0], -1, 1e-12);
    assert_float_equal(w[1], 2, 1e-12);
    assert_int_equal(cf_figure_dump(fig, NULL, &text, &size, NULL), 0);
    p = strstr(text, " : M ");
    assert_non_null(p);
    assert_int_equal(sscanf(p, " : M %lf %lf C %lf %lf %lf %lf %lf %lf", &x0,
                            &ya, &c1[0], &c1[1], &c1[2], &c1[3], &x1, &yb),
                     8);
    /* one horizontal cubic from the left end to the right end */
    assert_float_equal(ya, yb, 1e-9);
    assert_float_equal(c1[1], ya, 1e-9);
    assert_float_equal(c1[3], ya, 1e-9);
    assert_true(x1 - x0 > 100);
    cf_free(text);
    cf_figure_destroy(fig);
    cf_bezier_destroy(c);
}

/* The distinct knots of a B-spline with their first index and
** multiplicity, at the curve's points; tangent arrows end at c(t) +
** c'(t) / degree (for a cubic Bézier at t = 0: P1; at t = 1: 2 P3 - P2). */
static void
test_knot_list_and_tangents(void **state)
{
    static const double U[] = { 0, 0, 0, 0, 0.5, 0.5, 1, 1, 1, 1 };
    static const double P[] = { 0, 0, 1, 2, 2, 3, 3, 1, 4, 2, 5, 0 };
    static const double B[] = { 0, 0, 1, 2, 3, 2, 4, 0 };
    cf_bspline_t *s = NULL;
    cf_bezier_t *c = NULL;
    cf_figure_t *fig = NULL;
    double u[10], pts[20], tip[2], want[2];
    size_t first[10], mult[10], n = 0, k;
    cf_diag_t d;
    (void)state;
    assert_int_equal(cf_bspline_create(2, 3, U, 10, P, 6, NULL, &s, NULL),
                     0);
    assert_int_equal(cf_bezier_create(2, 3, B, NULL, &c, NULL), 0);
    assert_int_equal(cf_figure_create(60, 40, CF_UNIT_MM, &fig, NULL), 0);
    assert_int_equal(cf_figure_bspline_knots(fig, s, u, first, mult, pts,
                                             &n), 0);
    assert_int_equal(n, 3);
    assert_float_equal(u[0], 0, 0);
    assert_float_equal(u[1], 0.5, 0);
    assert_float_equal(u[2], 1, 0);
    assert_int_equal(first[0], 0);
    assert_int_equal(first[1], 4);
    assert_int_equal(first[2], 6);
    assert_int_equal(mult[0], 4);
    assert_int_equal(mult[1], 2);
    assert_int_equal(mult[2], 4);
    for (k = 0; k < n; k++) {
        double p[2];
        assert_int_equal(cf_bspline_eval(s, u[k], p), 0);
        assert_float_equal(pts[2 * k], p[0], 1e-12);
        assert_float_equal(pts[2 * k + 1], p[1], 1e-12);
    }
    /* clamped ends: the first and last control points */
    assert_float_equal(pts[0], 0, 1e-12);
    assert_float_equal(pts[4], 5, 1e-12);
    assert_int_equal(cf_figure_add_bezier_tangent(fig, c, 0, 0, NULL, tip),
                     0);
    assert_float_equal(tip[0], 1, 1e-12);
    assert_float_equal(tip[1], 2, 1e-12);
    assert_int_equal(cf_figure_add_bezier_tangent(fig, c, 1, 0, NULL, tip),
                     0);
    assert_float_equal(tip[0], 5, 1e-12);
    assert_float_equal(tip[1], -2, 1e-12);
    /* scale 1 at the B-spline's start: P0 + C'(0), where
    ** C'(0) = 3 (P1 - P0) / (u_4 - u_1) = 3 (P1 - P0) / 0.5 */
    assert_int_equal(cf_figure_add_bspline_tangent(fig, s, 0, 1, NULL, tip),
                     0);
    want[0] = 0 + 3 * (1 - 0) / 0.5;
    want[1] = 0 + 3 * (2 - 0) / 0.5;
    assert_float_equal(tip[0], want[0], 1e-9);
    assert_float_equal(tip[1], want[1], 1e-9);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_add_bezier_tangent(fig, c, 1.5, 0, NULL,
                                                  NULL), CF_STATUS_DOMAIN);
    assert_int_equal(cf_figure_status(fig, &d), CF_STATUS_DOMAIN);
    assert_non_null(strstr(d.msg, "outside the domain [0, 1]"));
    cf_figure_destroy(fig);
    assert_int_equal(cf_figure_create(60, 40, CF_UNIT_MM, &fig, NULL), 0);
    cf_diag_clear(&d);
    assert_int_equal(cf_figure_add_bspline_tangent(fig, s, 2, 0, NULL, NULL),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_figure_status(fig, &d), CF_STATUS_DOMAIN);
    assert_non_null(strstr(d.msg, "t = 2 is outside the domain [0, 1]"));
    cf_figure_destroy(fig);
    cf_bspline_destroy(s);
    cf_bezier_destroy(c);
}

static void
test_out_of_memory(void **state)
{
    double P[] = { 0, 5, 1, -1, 3, 0, 4, 3, 6, 10 };
    long k;
    cf_style_t autoplace;
    (void)state;
    cf_style_init(&autoplace);
    autoplace.set = CF_STYLE_PLACE;
    autoplace.place = CF_PLACE_AUTO;
    /* fail each allocation in turn while building and rendering a
    ** figure (an explicit window, a label placed automatically): a
    ** status every time, no leak, eventually success */
    for (k = 1; k < 2000; k++) {
        cf_figure_t *fig = NULL;
        cf_bezier_t *c = NULL;
        cf_status_t st;
        unsigned char *data = NULL;
        size_t size;
        cf_axes_t ax;
        tu_fail_alloc_after(k);
        st = cf_figure_create(60, 40, CF_UNIT_MM, &fig, NULL);
        if (st == CF_STATUS_OK)
            st = cf_bezier_create(2, 4, P, NULL, &c, NULL);
        if (st == CF_STATUS_OK) {
            cf_figure_add_polygon(fig, P, 5, NULL);
            cf_figure_add_bezier(fig, c, NULL);
            cf_figure_add_label(fig, 0, 5, "P_0", NULL);
            cf_figure_add_label(fig, 1, -1, "P_1", &autoplace);
            cf_figure_set_window(fig, -1, 7, -2, 11);
            cf_axes_init(&ax);
            cf_figure_add_axes(fig, &ax, NULL);
            st = cf_figure_render(fig, CF_FORMAT_SVG, NULL, &data, &size,
                                  NULL);
        }
        cf_free(data);
        cf_bezier_destroy(c);
        cf_figure_destroy(fig);
        assert_int_equal(tu_alloc_live(), 0);
        tu_fail_alloc_reset();
        if (st == CF_STATUS_OK)
            return;
        assert_int_equal(st, CF_STATUS_NO_MEMORY);
    }
    fail_msg("never succeeded");
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cubic_is_one_C),
        cmocka_unit_test(test_degree5_fitted),
        cmocka_unit_test(test_rational_arc_fitted),
        cmocka_unit_test(test_tolerance_option),
        cmocka_unit_test(test_graph_exact),
        cmocka_unit_test(test_basis_graph),
        cmocka_unit_test(test_basis_errors),
        cmocka_unit_test(test_function_graph),
        cmocka_unit_test(test_bspline_pieces),
        cmocka_unit_test(test_net_colours_and_projection),
        cmocka_unit_test(test_window_fit),
        cmocka_unit_test(test_explicit_window_clips),
        cmocka_unit_test(test_auto_label_place),
        cmocka_unit_test(test_hull),
        cmocka_unit_test(test_label_halo),
        cmocka_unit_test(test_bad_input),
        cmocka_unit_test(test_huge_extent_refused),
        cmocka_unit_test(test_sticky_error),
        cmocka_unit_test(test_graph_constant_piece),
        cmocka_unit_test(test_knot_list_and_tangents),
        cmocka_unit_test(test_out_of_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
