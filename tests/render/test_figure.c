/* Figure elements as they reach the SVG: exact cubics, fitted curves within
** the tolerance (measured against independent evaluations), graphs,
** B-splines, nets, projection.  The window, labels and halos are in
** test_figure_window.c, errors and out of memory in test_figure_errors.c,
** the shared helpers in test_figure.h. */
#include "test_figure.h"

/* The SVG writer rounds path coordinates to 1/1000 bp (render/backends/
** backend-svgw.c): each by at most COORD_ROUND (and the decimal reading
** back by 1e-12); a point on a cubic is a convex combination of its
** control points, so rounding moves it by at most sqrt(2) COORD_ROUND. */
#define COORD_ROUND (0.0005 + 1e-12)

#define ROUNDING (1.4143 * COORD_ROUND)

/* a point mapped from data coordinates against a drawn one: the map's
** origin (map_from) is a drawn point, so rounded too */
#define MAPPED_ROUND (2 * COORD_ROUND)

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
        assert_true(fabs(px - ps->seg[0].p[2 * k]) <= MAPPED_ROUND);
        assert_true(fabs(py - ps->seg[0].p[2 * k + 1]) <= MAPPED_ROUND);
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
    ** (plus the writer's rounding; the dense polyline of 20000 chords adds
    ** < 1e-4 pt at these curvatures) */
    err = path_error(ps, &m, exact, N);
    assert_true(err <= 0.01 + ROUNDING + 1e-4);
    /* and it covers the whole curve: it ends at c(1) */
    to_page(&m, exact[2 * N - 2], exact[2 * N - 1], &end[0], &end[1]);
    assert_true(hypot(end[0] - ps->seg[ps->nseg - 1].p[6],
                      end[1] - ps->seg[ps->nseg - 1].p[7])
                <= 2 * COORD_ROUND);
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
    ** the support) within the 1/1000 bp rounding plus the sag of the
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
    assert_true(fabs(px - ps->seg[0].p[2]) <= MAPPED_ROUND
                && fabs(py - ps->seg[0].p[3]) <= MAPPED_ROUND);
    to_page(&m, 2.0 / 3, 2.0 / 3, &px, &py);
    assert_true(fabs(px - ps->seg[0].p[4]) <= MAPPED_ROUND
                && fabs(py - ps->seg[0].p[5]) <= MAPPED_ROUND);
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
                    <= 2 * COORD_ROUND);
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
    while ((p = strstr(p, "<path ")) != NULL) {
        const char *end = strchr(p, '>'), *st;
        size_t n;
        assert_non_null(end);
        st = in_tag(p, end, " stroke=\"");
        p = end;
        if (st == NULL || in_tag(st, end, " fill=\"") != NULL)
            continue;
        n = strcspn(st + 9, "\"");
        assert_true(n < 64 && ncol < 8);
        memcpy(colours[ncol], st + 9, n);
        colours[ncol][n] = '\0';
        ncol++;
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
                              py - ps->seg[0].p[2 * i + 1]) <= 2 * COORD_ROUND);
        }
        free(svg);
        free(ps);
        cf_figure_destroy(fig);
        cf_bezier_destroy(c);
    }
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
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
