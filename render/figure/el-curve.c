/*
** Curves: Bézier pieces in the plane (projected when given in R^3 or
** higher) or fixed cubic segments, turned into cubic segments when the
** figure is laid out, because the fitting tolerance is given on the page
** and the scale is known only then.  Bézier curves, lists, cubic chains,
** B-splines and their knot marks.
*/
#include <math.h>
#include <string.h>

#include "curvefig/bspline.h"
#include "grow.h"
#include "model.h"

/* One piece of a curve: a planar Bézier converted at layout time, or a
** fixed cubic segment (8 doubles). */
typedef struct piece {
    cf_bezier_t *bez;
    double cubic[8];
    cf_cubics_t *cache;      /* conversion of bez */
    double cache_tol;
} piece_t;

typedef struct curve_el {
    cf__element_t base;
    piece_t *pieces;
    size_t npieces, cap;
} curve_el_t;

static void
curve_fini(cf__element_t *el)
{
    curve_el_t *e = (curve_el_t *)el;
    size_t i;
    for (i = 0; i < e->npieces; i++) {
        cf_bezier_destroy(e->pieces[i].bez);
        cf_cubics_destroy(e->pieces[i].cache);
    }
    cf_free(e->pieces);
}

static void
curve_bounds(const cf__element_t *el, cf__bounds_t *b)
{
    const curve_el_t *e = (const curve_el_t *)el;
    size_t i, k;
    for (i = 0; i < e->npieces; i++) {
        const piece_t *pc = &e->pieces[i];
        if (pc->bez != NULL) {
            /* the tight box of the curve, not of its control points */
            double lo[2], hi[2];
            if (cf_bezier_bbox(pc->bez, lo, hi) == CF_STATUS_OK) {
                cf__bounds_add(b, lo[0], lo[1]);
                cf__bounds_add(b, hi[0], hi[1]);
            } else {
                b->nomem = true;
            }
        } else {
            for (k = 0; k < 4; k++)
                cf__bounds_add(b, pc->cubic[2 * k], pc->cubic[2 * k + 1]);
        }
    }
}

/* Append a cubic (data coordinates) to the path, starting a subpath when
** it does not continue the previous one; last[0..1] is the previous end
** on the page (unrounded: cairo's current point is rounded to 1/256), NAN
** at the start, last[2..3] the start of the subpath it ends. */
static void
path_cubic(cf__dl_t *dl, const cf__layout_t *l, const double *c,
           double last[4])
{
    double p[8];
    size_t k;
    for (k = 0; k < 4; k++)
        cf__map(l, c[2 * k], c[2 * k + 1], &p[2 * k], &p[2 * k + 1]);
    if (isnan(last[0]) || fabs(last[0] - p[0]) > 1e-6
        || fabs(last[1] - p[1]) > 1e-6) {
        cf__dl_move(dl, p[0], p[1]);
        last[2] = p[0];
        last[3] = p[1];
    }
    cf__dl_curve(dl, p[2], p[3], p[4], p[5], p[6], p[7]);
    last[0] = p[6];
    last[1] = p[7];
}

/* The cubic segments of a Bézier piece within tolerance tol. */
static cf_status_t
piece_cubics(cf_figure_t *fig, piece_t *pc, double tol)
{
    cf_cubics_t *c = NULL;
    cf_status_t st;
    /* a fit within a smaller tolerance serves a larger one: the layout's
    ** ink pass fits at the first, larger scale, and the page (smaller once
    ** labels took their room) reuses it */
    if (pc->cache != NULL && pc->cache_tol <= tol)
        return CF_STATUS_OK;
    /* polynomial curves of degree >= 4: Hermite pieces within the
    ** a-priori bound, no fitting; rational ones: Hermite pieces halved on
    ** their measured error */
    st = cf_bezier_to_cubics_bounded(pc->bez, tol, &c, &fig->err);
    if (st != CF_STATUS_OK)
        return cf__fig_fail(fig, st, "curve to cubics");
    cf_cubics_destroy(pc->cache);
    pc->cache = c;
    pc->cache_tol = tol;
    return CF_STATUS_OK;
}

static cf_status_t
curve_draw(cf_figure_t *fig, cf__element_t *el, const cf__layout_t *l,
           const cf_style_t *s, cf__dl_t *dl)
{
    curve_el_t *e = (curve_el_t *)el;
    size_t i, k;
    double last[4] = { NAN, NAN, NAN, NAN };
    cf__paint_t paint;
    cf__clip_to_window(l, s->width > 0 ? s->width : 0, dl);
    cf__dl_path_begin(dl);
    for (i = 0; i < e->npieces; i++) {
        piece_t *pc = &e->pieces[i];
        if (pc->bez == NULL) {
            path_cubic(dl, l, pc->cubic, last);
        } else {
            if (piece_cubics(fig, pc, l->tol) != CF_STATUS_OK) {
                cf__dl_unclip(dl);
                return fig->err.status;
            }
            for (k = 0; k < pc->cache->count; k++)
                path_cubic(dl, l, pc->cache->pts + 8 * k, last);
        }
    }
    /* closed where the last subpath ends at its own start (a close ends
    ** the last subpath: closing one that began elsewhere -- a loop drawn
    ** in two runs, the second ending at the first's start -- would draw
    ** the chord of the second) */
    if (!isnan(last[0]) && fabs(last[0] - last[2]) < 1e-6
        && fabs(last[1] - last[3]) < 1e-6)
        cf__dl_close(dl);
    memset(&paint, 0, sizeof paint);
    paint.stroke = true;
    cf__stroke_from_style(s, &paint.line);
    cf__dl_path_paint(dl, &paint);
    cf__dl_unclip(dl);
    return CF_STATUS_OK;
}

static const cf__kind_t curve_kind = {
    "curve", 0, curve_fini, curve_bounds, curve_draw, NULL, NULL, NULL
};

cf__element_t *
cf__curve_new(cf_figure_t *fig, cf_role_t role, const cf_style_t *style)
{
    return cf__element_new(fig, &curve_kind, sizeof(curve_el_t), role,
                           style);
}

cf_status_t
cf__curve_add(cf_figure_t *fig, cf__element_t *el, cf_bezier_t *bez,
              const double *cubic)
{
    curve_el_t *e = (curve_el_t *)el;
    piece_t *np = cf__grow_array(e->pieces, &e->cap, e->npieces + 1,
                                 sizeof *np, 16);
    if (np == NULL) {
        cf_bezier_destroy(bez);
        return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for curve pieces");
    }
    e->pieces = np;
    memset(&e->pieces[e->npieces], 0, sizeof e->pieces[0]);
    e->pieces[e->npieces].bez = bez;
    if (cubic != NULL)
        memcpy(e->pieces[e->npieces].cubic, cubic, 8 * sizeof(double));
    e->npieces++;
    return CF_STATUS_OK;
}


/* A planar copy of c (projected when dim >= 3): the projection maps the
** homogeneous control points (w x, w) to (w P x, w), or under a
** perspective to the images (X, Y, W), so the copy is exact. */
cf_status_t
cf__fig_planar_bezier(cf_figure_t *fig, const cf_bezier_t *c,
                      cf_bezier_t **out)
{
    size_t dim = cf_bezier_dim(c), hd, i, np;
    int deg = cf_bezier_degree(c);
    bool rat = cf_bezier_is_rational(c), hom;
    const double *hp = cf_bezier_hpoints(c);
    double *q;
    cf_status_t st = CF_STATUS_OK;

    if (dim == 2)
        return cf_bezier_copy(c, out, &fig->err);
    if (dim < 2)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "a curve in R^%zu cannot be drawn as a plane "
                           "curve (use a graph for functions)", dim);
    hd = dim + (rat ? 1 : 0);
    hom = rat || cf__fig_is_central(fig, dim);
    np = (size_t)deg + 1;
    q = cf_alloc_array(np * 3, sizeof *q);
    if (q == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                           "out of memory projecting a curve");
    for (i = 0; i < np && st == CF_STATUS_OK; i++) {
        double h[3];
        if (!cf__fig_project_h(fig, hp + i * hd, dim, rat, h)) {
            double p[3] = { 0, 0, 0 };
            for (size_t k = 0; k < 3 && k < dim; k++)
                p[k] = hp[i * hd + k] / (rat ? hp[i * hd + dim] : 1.0);
            st = cf__fig_behind_eye(fig, p, "a curve's control point");
            break;
        }
        memcpy(q + i * (hom ? 3 : 2), h, (hom ? 3 : 2) * sizeof *h);
    }
    if (st == CF_STATUS_OK && hom)
        st = cf_bezier_create_homogeneous(2, deg, q, out, &fig->err);
    else if (st == CF_STATUS_OK)
        st = cf_bezier_create(2, deg, q, NULL, out, &fig->err);
    cf_free(q);
    return st;
}

static cf_status_t
check_curve(cf_figure_t *fig, const void *c, const cf_style_t *style,
            const char *what)
{
    if (c == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "%s is NULL", what);
    return cf__fig_check_style(fig, style);
}

cf_status_t
cf_figure_add_bezier_range(cf_figure_t *fig, const cf_bezier_t *c, double a,
                           double b, const cf_style_t *style)
{
    cf__element_t *e;
    cf_bezier_t *plane = NULL, *seg = NULL;
    cf_status_t st;
    CF__FIG_CHECK(fig);
    if (check_curve(fig, c, style, "Bézier curve") != CF_STATUS_OK)
        return fig->err.status;
    if (!(isfinite(a) && isfinite(b)))
        return cf_diag_set(&fig->err, CF_STATUS_NOT_FINITE, -1,
                           "curve range [%g, %g] is not finite", a, b);
    if (!(0 <= a && a < b && b <= 1))
        return cf_diag_set(&fig->err, CF_STATUS_DOMAIN, -1,
                           "curve range [%g, %g] must satisfy 0 <= a < b <= 1",
                           a, b);
    st = cf__fig_planar_bezier(fig, c, &plane);
    if (st != CF_STATUS_OK)
        return cf__fig_fail(fig, st, "Bézier curve");
    if (a > 0 || b < 1) {
        st = cf_bezier_segment(plane, a, b, &seg, &fig->err);
        cf_bezier_destroy(plane);
        if (st != CF_STATUS_OK)
            return cf__fig_fail(fig, st, "Bézier curve range");
        plane = seg;
    }
    e = cf__curve_new(fig, CF_ROLE_CURVE, style);
    if (e == NULL) {
        cf_bezier_destroy(plane);
        return fig->err.status;
    }
    st = cf__element_commit(fig, e, cf__curve_add(fig, e, plane, NULL));
    return st == CF_STATUS_OK ? cf__fact_bezier(fig, c) : st;
}

cf_status_t
cf_figure_add_bezier(cf_figure_t *fig, const cf_bezier_t *c,
                     const cf_style_t *style)
{
    return cf_figure_add_bezier_range(fig, c, 0.0, 1.0, style);
}

cf_status_t
cf_figure_add_bezier_list(cf_figure_t *fig, const cf_bezier_list_t *list,
                          const cf_style_t *style)
{
    cf__element_t *e;
    size_t i;
    cf_status_t st = CF_STATUS_OK;
    CF__FIG_CHECK(fig);
    if (check_curve(fig, list, style, "Bézier list") != CF_STATUS_OK)
        return fig->err.status;
    if (list->count > 0 && list->items == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "Bézier list of %zu items has no items",
                           list->count);
    for (i = 0; i < list->count; i++)
        if (list->items[i] == NULL)
            return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, (long)i,
                               "Bézier list item %zu is NULL", i);
    e = cf__curve_new(fig, CF_ROLE_CURVE, style);
    if (e == NULL)
        return fig->err.status;
    for (i = 0; i < list->count && st == CF_STATUS_OK; i++) {
        cf_bezier_t *plane = NULL;
        st = cf__fig_planar_bezier(fig, list->items[i], &plane);
        if (st == CF_STATUS_OK)
            st = cf__curve_add(fig, e, plane, NULL);
    }
    return cf__element_commit(fig, e, st);
}

cf_status_t
cf_figure_add_cubics(cf_figure_t *fig, const cf_cubics_t *cubics,
                     const cf_style_t *style)
{
    cf__element_t *e;
    size_t i, j, dim;
    cf_status_t st = CF_STATUS_OK;
    CF__FIG_CHECK(fig);
    if (check_curve(fig, cubics, style, "cubic chain") != CF_STATUS_OK)
        return fig->err.status;
    dim = cubics->dim;
    if (dim < 2 || (cubics->count > 0 && cubics->pts == NULL))
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "cubic chain: dimension %zu (need >= 2) or no "
                           "points", dim);
    if (cf_check_finite_points(cubics->pts, 4 * cubics->count, dim, dim,
                               "cubic control point", &fig->err)
        != CF_STATUS_OK)
        return fig->err.status;
    e = cf__curve_new(fig, CF_ROLE_CURVE, style);
    if (e == NULL)
        return fig->err.status;
    for (i = 0; i < cubics->count && st == CF_STATUS_OK; i++) {
        double q[8];
        for (j = 0; j < 4; j++)
            cf__fig_project1(fig, cubics->pts + (4 * i + j) * dim, dim,
                             q + 2 * j);
        st = cf__curve_add(fig, e, NULL, q);
    }
    return cf__element_commit(fig, e, st);
}

static cf_status_t
bspline_pieces(cf_figure_t *fig, cf__element_t *e, const cf_bspline_t *s,
               double a, double b)
{
    cf_bezier_list_t *list = NULL;
    cf_status_t st;
    size_t i;
    double lo, hi;

    cf_bspline_domain(s, &lo, &hi);
    if (a == b) {
        a = lo;
        b = hi;
    }
    if (!(isfinite(a) && isfinite(b)))
        return cf_diag_set(&fig->err, CF_STATUS_NOT_FINITE, -1,
                           "B-spline range [%g, %g] is not finite", a, b);
    if (!(lo <= a && a < b && b <= hi))
        return cf_diag_set(&fig->err, CF_STATUS_DOMAIN, -1,
                           "B-spline range [%g, %g] must lie inside the "
                           "domain [%g, %g]", a, b, lo, hi);
    st = cf_bspline_to_beziers(s, &list, &fig->err);
    if (st != CF_STATUS_OK)
        return st;
    for (i = 0; i < list->count && st == CF_STATUS_OK; i++) {
        double t0 = list->t0[i], t1 = list->t1[i], ta, tb;
        cf_bezier_t *plane = NULL, *seg = NULL;
        if (t1 <= a || t0 >= b || !(t1 > t0))
            continue;
        ta = (fmax(a, t0) - t0) / (t1 - t0);
        tb = (fmin(b, t1) - t0) / (t1 - t0);
        st = cf__fig_planar_bezier(fig, list->items[i], &plane);
        if (st != CF_STATUS_OK)
            break;
        if (ta > 0 || tb < 1) {
            st = cf_bezier_segment(plane, fmax(ta, 0), fmin(tb, 1), &seg,
                                   &fig->err);
            cf_bezier_destroy(plane);
            plane = seg;
            if (st != CF_STATUS_OK)
                break;
        }
        st = cf__curve_add(fig, e, plane, NULL);
    }
    cf_bezier_list_destroy(list);
    return st;
}

cf_status_t
cf_figure_add_bspline(cf_figure_t *fig, const struct cf_bspline *s,
                      double a, double b, const cf_style_t *style)
{
    cf__element_t *e;
    CF__FIG_CHECK(fig);
    if (check_curve(fig, s, style, "B-spline curve") != CF_STATUS_OK)
        return fig->err.status;
    if (cf_bspline_dim(s) < 2)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "a B-spline in R^%zu cannot be drawn as a plane "
                           "curve (use a graph for functions)",
                           cf_bspline_dim(s));
    e = cf__curve_new(fig, CF_ROLE_CURVE, style);
    if (e == NULL)
        return fig->err.status;
    if (cf__element_commit(fig, e, bspline_pieces(fig, e, s, a, b))
        != CF_STATUS_OK)
        return fig->err.status;
    return cf__fact_bspline(fig, s);
}

cf_status_t
cf_figure_add_bspline_knots(cf_figure_t *fig, const struct cf_bspline *s,
                            const cf_style_t *style)
{
    const double *u;
    size_t m, i, n = 0, dim;
    double lo, hi, *buf = NULL, *pts = NULL;
    cf_status_t st = CF_STATUS_OK;
    CF__FIG_CHECK(fig);
    if (check_curve(fig, s, style, "B-spline curve") != CF_STATUS_OK)
        return fig->err.status;
    dim = cf_bspline_dim(s);
    if (dim < 2)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "knot marks need a curve in R^2 or more, not "
                           "R^%zu", dim);
    u = cf_bspline_knots(s);
    m = cf_bspline_nknots(s);
    cf_bspline_domain(s, &lo, &hi);
    buf = cf_alloc_array(2 * dim, sizeof *buf);
    pts = cf_alloc_array(4 * (m ? m : 1), sizeof *pts);
    if (buf == NULL || pts == NULL) {
        cf_free(buf);
        cf_free(pts);
        return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for knot marks");
    }
    /* layout of pts: n points, then (after compaction) n tangents */
    for (i = 0; i < m && st == CF_STATUS_OK; i++) {
        if (u[i] < lo || u[i] > hi || (i > 0 && u[i] == u[i - 1]))
            continue;
        st = cf_bspline_eval_derivs(s, u[i], 1, buf);
        if (st != CF_STATUS_OK) {
            cf__fig_fail(fig, st, "knot marks");
            break;
        }
        cf__fig_project1(fig, buf, dim, pts + 2 * n);
        cf__fig_project1(fig, buf + dim, dim, pts + 2 * m + 2 * n);
        n++;
    }
    if (st == CF_STATUS_OK) {
        memmove(pts + 2 * n, pts + 2 * m, 2 * n * sizeof *pts);
        st = cf_figure_add_knot_marks(fig, pts, pts + 2 * n, n, style);
    }
    cf_free(buf);
    cf_free(pts);
    return st;
}

cf_status_t
cf_figure_bspline_knots(cf_figure_t *fig, const struct cf_bspline *s,
                        double *u, size_t *first, size_t *mult, double *pts,
                        size_t *count)
{
    const double *k;
    size_t m, dim, i, j, n = 0;
    double lo, hi, *buf;
    CF__FIG_CHECK(fig);
    if (s == NULL || count == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "B-spline knots: curve or count is NULL");
    *count = 0;
    k = cf_bspline_knots(s);
    m = cf_bspline_nknots(s);
    dim = cf_bspline_dim(s);
    cf_bspline_domain(s, &lo, &hi);
    buf = cf_alloc_array(dim, sizeof *buf);
    if (buf == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for B-spline knots");
    for (i = 0; i < m; i++) {
        size_t copies = 0;
        if (k[i] < lo || k[i] > hi || (i > 0 && k[i] == k[i - 1]))
            continue;
        if (cf_bspline_eval(s, k[i], buf) != CF_STATUS_OK)
            continue;
        for (j = 0; j < m; j++)
            copies += k[j] == k[i];
        if (u != NULL)
            u[n] = k[i];
        if (first != NULL)
            first[n] = i;
        if (mult != NULL)
            mult[n] = copies;
        if (pts != NULL)
            cf__fig_project1(fig, buf, dim, pts + 2 * n);
        n++;
    }
    cf_free(buf);
    *count = n;
    return CF_STATUS_OK;
}

/* The tangent arrow from d[0 .. dim) (the point) and d[dim .. 2 dim) (the
** derivative). */
static cf_status_t
tangent_arrow(cf_figure_t *fig, double *d, size_t dim, int deg, double scale,
              const cf_style_t *style, double tip[2])
{
    double pd[4];
    size_t k;
    if (!(scale > 0))
        scale = deg > 0 ? 1.0 / deg : 1.0;
    for (k = 0; k < dim; k++)
        d[dim + k] = d[k] + scale * d[dim + k];
    if (cf_figure_project(fig, d, 2, dim, pd) != CF_STATUS_OK)
        return fig->err.status;
    if (tip != NULL) {
        tip[0] = pd[2];
        tip[1] = pd[3];
    }
    return cf_figure_add_arrow(fig, pd[0], pd[1], pd[2] - pd[0],
                               pd[3] - pd[1], style);
}

static cf_status_t
tangent_domain(cf_figure_t *fig, double t, double lo, double hi)
{
    if (!isfinite(t))
        return cf_diag_set(&fig->err, CF_STATUS_NOT_FINITE, -1,
                           "t = %g is not finite", t);
    return cf_diag_set(&fig->err, CF_STATUS_DOMAIN, -1,
                       "t = %g is outside the domain [%g, %g]", t,
                       lo, hi);
}

cf_status_t
cf_figure_add_bezier_tangent(cf_figure_t *fig, const cf_bezier_t *c,
                             double t, double scale, const cf_style_t *style,
                             double tip[2])
{
    size_t dim;
    double *d;
    cf_status_t st;
    CF__FIG_CHECK(fig);
    if (check_curve(fig, c, style, "Bézier curve") != CF_STATUS_OK)
        return fig->err.status;
    dim = cf_bezier_dim(c);
    d = cf_alloc_array(2 * dim, sizeof *d);
    if (d == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for a tangent");
    if (cf_bezier_eval_derivs(c, t, 1, d) != CF_STATUS_OK)
        st = tangent_domain(fig, t, 0, 1);
    else
        st = tangent_arrow(fig, d, dim, cf_bezier_degree(c), scale, style,
                           tip);
    cf_free(d);
    return st;
}

cf_status_t
cf_figure_add_bspline_tangent(cf_figure_t *fig, const struct cf_bspline *s,
                              double t, double scale,
                              const cf_style_t *style, double tip[2])
{
    size_t dim;
    double *d, lo, hi;
    cf_status_t st;
    CF__FIG_CHECK(fig);
    if (check_curve(fig, s, style, "B-spline curve") != CF_STATUS_OK)
        return fig->err.status;
    dim = cf_bspline_dim(s);
    d = cf_alloc_array(2 * dim, sizeof *d);
    if (d == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for a tangent");
    if (cf_bspline_eval_derivs(s, t, 1, d) != CF_STATUS_OK) {
        cf_bspline_domain(s, &lo, &hi);
        st = tangent_domain(fig, t, lo, hi);
    } else {
        st = tangent_arrow(fig, d, dim, cf_bspline_degree(s), scale, style,
                           tip);
    }
    cf_free(d);
    return st;
}
