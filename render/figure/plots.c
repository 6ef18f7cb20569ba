/*
** Function plots: graphs of piecewise polynomials (Bézier pieces in R^1
** over breakpoints), B-spline basis functions, and sampled functions
** fitted with cubic Hermite segments.  Each is a curve element of role
** CF_ROLE_GRAPH (render/figure/el-curve.c).
*/
#include <math.h>
#include <string.h>

#include "curvefig/bspline.h"
#include "model.h"

/* The graph of a dim-1 polynomial Bézier over [x0, x1] as a planar Bézier
** whose x control values are equally spaced (x is then linear in t). */
static cf_status_t
graph_bezier(cf_figure_t *fig, const cf_bezier_t *c, double x0, double x1,
             cf_bezier_t **out)
{
    int deg = cf_bezier_degree(c), n, i;
    const double *y = cf_bezier_hpoints(c);
    double *q;
    cf_status_t st;
    if (cf_bezier_dim(c) != 1 || cf_bezier_is_rational(c))
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "a graph piece must be a polynomial Bézier in R^1 "
                           "(this one is in R^%zu%s)", cf_bezier_dim(c),
                           cf_bezier_is_rational(c) ? ", rational" : "");
    /* a constant (degree 0) becomes a degree-1 segment over the whole
    ** interval: two control points */
    n = deg > 0 ? deg : 1;
    q = cf_alloc_array(2 * ((size_t)n + 1), sizeof *q);
    if (q == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for a graph");
    for (i = 0; i <= n; i++) {
        q[2 * i] = deg > 0 ? x0 + (x1 - x0) * i / deg : i == 0 ? x0 : x1;
        q[2 * i + 1] = y[deg > 0 ? i : 0];
    }
    st = cf_bezier_create(2, n, q, NULL, out, &fig->err);
    cf_free(q);
    return st;
}

cf_status_t
cf_figure_add_graph(cf_figure_t *fig, const cf_bezier_t *const *pieces,
                    const double *breaks, size_t count,
                    const cf_style_t *style)
{
    cf__element_t *e;
    size_t i;
    cf_status_t st = CF_STATUS_OK;
    CF__FIG_CHECK(fig);
    if (pieces == NULL || breaks == NULL || count == 0)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "pieces or breaks NULL, or no piece");
    if (cf__fig_check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    if (cf_check_finite_points(breaks, count + 1, 1, 1, "graph break",
                               &fig->err) != CF_STATUS_OK)
        return fig->err.status;
    for (i = 0; i < count; i++) {
        if (breaks[i + 1] < breaks[i])
            return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, (long)i + 1,
                               "graph break %zu (%g) is smaller than break "
                               "%zu (%g)", i + 1, breaks[i + 1], i,
                               breaks[i]);
        if (pieces[i] == NULL)
            return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, (long)i,
                               "graph piece %zu is NULL", i);
    }
    e = cf__curve_new(fig, CF_ROLE_GRAPH, style);
    if (e == NULL)
        return fig->err.status;
    for (i = 0; i < count && st == CF_STATUS_OK; i++) {
        cf_bezier_t *g = NULL;
        if (!(breaks[i + 1] > breaks[i]))
            continue;
        st = graph_bezier(fig, pieces[i], breaks[i], breaks[i + 1], &g);
        if (st == CF_STATUS_OK)
            st = cf__curve_add(fig, e, g, NULL);
    }
    if (cf__element_commit(fig, e, st) != CF_STATUS_OK)
        return fig->err.status;
    return cf__fact_graph(fig);
}

cf_status_t
cf_figure_add_graph_list(cf_figure_t *fig, const cf_bezier_list_t *list,
                         const cf_style_t *style)
{
    double *breaks;
    size_t i;
    cf_status_t st;
    cf__element_t *e;
    CF__FIG_CHECK(fig);
    if (list == NULL || list->count == 0 || list->items == NULL
        || list->t0 == NULL || list->t1 == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "graph list: NULL, empty, or without t0/t1 ranges");
    if (cf__fig_check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    breaks = cf_alloc_array(2 * list->count, sizeof *breaks);
    if (breaks == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for a graph");
    for (i = 0; i < list->count; i++) {
        breaks[2 * i] = list->t0[i];
        breaks[2 * i + 1] = list->t1[i];
    }
    st = cf_check_finite_points(breaks, 2 * list->count, 1, 1,
                                "graph range", &fig->err);
    for (i = 0; i < list->count && st == CF_STATUS_OK; i++) {
        if (list->items[i] == NULL || breaks[2 * i + 1] < breaks[2 * i])
            st = cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, (long)i,
                             "graph list item %zu is NULL or has t1 < t0", i);
    }
    if (st != CF_STATUS_OK) {
        cf_free(breaks);
        return st;
    }
    e = cf__curve_new(fig, CF_ROLE_GRAPH, style);
    if (e == NULL) {
        cf_free(breaks);
        return fig->err.status;
    }
    for (i = 0; i < list->count && st == CF_STATUS_OK; i++) {
        cf_bezier_t *g = NULL;
        if (!(breaks[2 * i + 1] > breaks[2 * i]))
            continue;
        st = graph_bezier(fig, list->items[i], breaks[2 * i],
                          breaks[2 * i + 1], &g);
        if (st == CF_STATUS_OK)
            st = cf__curve_add(fig, e, g, NULL);
    }
    cf_free(breaks);
    if (cf__element_commit(fig, e, st) != CF_STATUS_OK)
        return fig->err.status;
    return cf__fact_graph(fig);
}

/* The graph of N_i^p over the whole knot vector [u_0, u_{m-1}]: the Bézier
** pieces of the core's spline of that one basis function, exact. */
cf_status_t
cf_figure_add_basis(cf_figure_t *fig, const double *knots, size_t nknots,
                    int i, int p, const cf_style_t *style)
{
    cf_bspline_t *spl = NULL;
    cf_bezier_list_t *list = NULL;
    cf_status_t st;
    CF__FIG_CHECK(fig);
    if (cf__fig_check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    st = cf_basis_one_spline(i, p, knots, nknots, &spl, &fig->err);
    if (st == CF_STATUS_OK)
        st = cf_bspline_to_beziers(spl, &list, &fig->err);
    cf_bspline_destroy(spl);
    if (st == CF_STATUS_OK)
        st = cf_figure_add_graph_list(fig, list, style);
    cf_bezier_list_destroy(list);
    return st == CF_STATUS_OK ? cf__fact_basis(fig, knots, nknots, p) : st;
}

/* Sampling state of cf_figure_add_function. */
typedef struct sampler {
    cf_function_t f;
    void *closure;
    double a, b, h;
    int stopped;
    bool bad;
} sampler_t;

static bool
sample(sampler_t *s, double x, double *y)
{
    if (s->stopped || s->bad)
        return false;
    if (s->f(s->closure, x, y) != 0) {
        s->stopped = 1;
        return false;
    }
    if (!isfinite(*y)) {
        s->bad = true;
        return false;
    }
    return true;
}

/* Value and derivative (central difference, one-sided at the ends). */
static bool
sample_d(sampler_t *s, double x, double *y, double *d)
{
    double xl = fmax(s->a, x - s->h), xr = fmin(s->b, x + s->h), yl, yr;
    if (!sample(s, x, y) || !sample(s, xl, &yl) || !sample(s, xr, &yr))
        return false;
    *d = (yr - yl) / (xr - xl);
    return true;
}

#define FN_MAX_SEGMENTS 4096

cf_status_t
cf_figure_add_function(cf_figure_t *fig, cf_function_t f, void *closure,
                       double a, double b, const cf_style_t *style)
{
    enum { START = 16, STACK = 64 };
    cf__element_t *e;
    sampler_t s;
    double ylo = INFINITY, yhi = -INFINITY, tol, y;
    double stack[STACK][4];   /* x, y, d of the right end; and level */
    double x0, y0, d0;
    size_t i, nseg = 0;
    cf_status_t st = CF_STATUS_OK;

    CF__FIG_CHECK(fig);
    if (f == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "function is NULL");
    if (cf__fig_check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    if (!(isfinite(a) && isfinite(b)))
        return cf_diag_set(&fig->err, CF_STATUS_NOT_FINITE, -1,
                           "function range [%g, %g] is not finite", a, b);
    if (!(a < b))
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "function range [%g, %g] is empty", a, b);
    s.f = f;
    s.closure = closure;
    s.a = a;
    s.b = b;
    s.h = 1e-6 * (b - a);
    s.stopped = 0;
    s.bad = false;
    /* the graph's range sets the tolerance */
    for (i = 0; i <= 64; i++) {
        if (!sample(&s, a + (b - a) * (double)i / 64, &y))
            break;
        ylo = fmin(ylo, y);
        yhi = fmax(yhi, y);
    }
    tol = 2e-5 * fmax(yhi - ylo, 1e-3 * (b - a));
    e = cf__curve_new(fig, CF_ROLE_GRAPH, style);
    if (e == NULL)
        return fig->err.status;
    if (s.stopped || s.bad || !sample_d(&s, a, &y0, &d0))
        goto done;
    x0 = a;
    {
        int top = 0;
        /* right ends still to reach, nearest last */
        for (i = START; i >= 1; i--) {
            stack[top][0] = a + (b - a) * (double)i / START;
            stack[top][3] = 0;
            stack[top][1] = NAN;
            top++;
        }
        while (top > 0 && st == CF_STATUS_OK) {
            double x1 = stack[top - 1][0], y1, d1, hx, worst = 0;
            double c[8];
            int lvl = (int)stack[top - 1][3], k;
            if (isnan(stack[top - 1][1])) {
                if (!sample_d(&s, x1, &y1, &d1))
                    goto done;
                stack[top - 1][1] = y1;
                stack[top - 1][2] = d1;
            }
            y1 = stack[top - 1][1];
            d1 = stack[top - 1][2];
            hx = x1 - x0;
            c[0] = x0;
            c[1] = y0;
            c[2] = x0 + hx / 3;
            c[3] = y0 + d0 * hx / 3;
            c[4] = x1 - hx / 3;
            c[5] = y1 - d1 * hx / 3;
            c[6] = x1;
            c[7] = y1;
            for (k = 1; k <= 3; k++) {
                double t = k / 4.0, u = 1 - t, yc, yf;
                yc = u * u * u * c[1] + 3 * u * u * t * c[3]
                    + 3 * u * t * t * c[5] + t * t * t * c[7];
                if (!sample(&s, x0 + t * hx, &yf))
                    goto done;
                worst = fmax(worst, fabs(yc - yf));
            }
            if (worst > tol && lvl < 24 && top < STACK
                && nseg + (size_t)top < FN_MAX_SEGMENTS) {
                stack[top][0] = x0 + hx / 2;
                stack[top][1] = NAN;
                stack[top][3] = lvl + 1;
                stack[top - 1][3] = lvl + 1;
                top++;
                continue;
            }
            st = cf__curve_add(fig, e, NULL, c);
            nseg++;
            x0 = x1;
            y0 = y1;
            d0 = d1;
            top--;
        }
    }
done:
    if (st == CF_STATUS_OK && s.stopped)
        st = cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                         "the plotted function reported an error");
    if (st == CF_STATUS_OK && s.bad)
        st = cf_diag_set(&fig->err, CF_STATUS_NOT_FINITE, -1,
                         "the plotted function is not finite on [%g, %g]", a,
                         b);
    if (cf__element_commit(fig, e, st) != CF_STATUS_OK)
        return fig->err.status;
    return cf__fact_graph(fig);
}

/* ---- point elements ----------------------------------------------------- */
