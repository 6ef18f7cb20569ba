/*
** What the facts of a figure show beyond its curves (describe-private.h):
** the constructions recognised from the points drawn (de Casteljau at t,
** de Boor at u) and the relations between its curves (a subdivision, a
** degree elevation, a knot insertion), each checked against the core's
** own operation, never guessed from how the script was written.
*/
#include <math.h>
#include <string.h>

#include "describe-private.h"

/* Whether page-plane point p is one of the points drawn or labelled. */
static bool
drawn(const cf__describe_t *d, const double *p, size_t *label)
{
    for (size_t i = 0; i < d->fig->facts.count; i++) {
        const cf__fact_t *x = &d->fig->facts.items[i];
        if (x->kind != CF__FACT_MARKS && x->kind != CF__FACT_LABEL)
            continue;
        for (size_t k = 0; k < x->n; k++)
            if (fabs(x->xy[2 * k] - p[0]) <= d->eps
                && fabs(x->xy[2 * k + 1] - p[1]) <= d->eps) {
                if (label != NULL && x->kind == CF__FACT_LABEL)
                    *label = i;
                return true;
            }
    }
    return false;
}

bool
cf__describe_drawn(const cf__describe_t *d, const double *p)
{
    return drawn(d, p, NULL);
}

/* The label whose anchor is page-plane point p, or NULL. */
const char *
cf__describe_name_at(const cf__describe_t *d, const double *p)
{
    for (size_t i = 0; i < d->fig->facts.count; i++) {
        const cf__fact_t *x = &d->fig->facts.items[i];
        if (x->kind == CF__FACT_LABEL && fabs(x->xy[0] - p[0]) <= d->eps
            && fabs(x->xy[1] - p[1]) <= d->eps)
            return x->text;
    }
    return NULL;
}

/* The parameter beta in (0, 1) of q on segment a b (page plane), or -1. */
static double
on_segment(const cf__describe_t *d, const double *a, const double *b,
           const double *q)
{
    double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy, t;
    if (l2 <= d->eps * d->eps)
        return -1;
    t = ((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / l2;
    if (t <= 1e-9 || t >= 1 - 1e-9)
        return -1;
    if (hypot(a[0] + t * dx - q[0], a[1] + t * dy - q[1]) > d->eps)
        return -1;
    return t;
}

/* The point of the homogeneous combination (1 - s) wa a + s wb b in the
** plane (weights 1 for polynomial curves). */
static void
lerp_w(const double *a, double wa, const double *b, double wb, double s,
       double *out)
{
    double w = (1 - s) * wa + s * wb;
    out[0] = ((1 - s) * wa * a[0] + s * wb * b[0]) / w;
    out[1] = ((1 - s) * wa * a[1] + s * wb * b[1]) / w;
}

/* The parameter s of the combination that lies at ratio beta of the
** segment: beta = s wb / ((1 - s) wa + s wb). */
static double
unweight(double beta, double wa, double wb)
{
    return beta * wa / (beta * wa + (1 - beta) * wb);
}

static void
add_param(cf__curve_info_t *c, double v, bool deboor)
{
    for (size_t k = 0; k < c->nparams; k++)
        if (fabs(c->params[k] - v) <= 1e-9)
            return;
    if (c->nparams < CF__DESCRIBE_MAX_PARAMS) {
        c->params[c->nparams] = v;
        c->deboor = deboor;
        c->nparams++;
    }
}

/* de Casteljau at t on Bézier c: a drawn point q on the first leg gives
** t; the curve point and the point of level 1 on the last leg must be
** drawn too (a subdivision's left half alone has no point on the last
** leg). */
static void
find_decasteljau(const cf__describe_t *d, cf__curve_info_t *c)
{
    size_t n = c->npts - 1;
    const double *Q = c->plane, *w = c->w;
    if (n < 1)
        return;
    for (size_t i = 0; i < d->fig->facts.count; i++) {
        const cf__fact_t *x = &d->fig->facts.items[i];
        if (x->kind != CF__FACT_MARKS && x->kind != CF__FACT_LABEL)
            continue;
        for (size_t k = 0; k < x->n; k++) {
            double beta = on_segment(d, Q, Q + 2, x->xy + 2 * k), t;
            double p[CF__DESCRIBE_MAX_DIM], pp[2], last[2];
            if (beta < 0)
                continue;
            t = unweight(beta, w[0], w[1]);
            if (cf_bezier_eval(c->bez, t, p) != CF_STATUS_OK)
                continue;
            cf__fig_project1(d->fig, p, c->dim, pp);
            lerp_w(Q + 2 * (n - 1), w[n - 1], Q + 2 * n, w[n], t, last);
            if (drawn(d, pp, NULL) && (n < 2 || drawn(d, last, NULL)))
                add_param(c, t, false);
        }
    }
}

/* de Boor at u on B-spline c: a drawn point q on leg i (P_{i-1} P_i)
** gives u = t_i + alpha (t_{i+p} - t_i); the curve point and, for p >= 2,
** the point of level 1 on another leg must be drawn too. */
static void
find_deboor(const cf__describe_t *d, cf__curve_info_t *c)
{
    const double *t = cf_bspline_knots(c->bs), *Q = c->plane, *w = c->w;
    size_t n = c->npts - 1, p = (size_t)c->degree;
    double a, b;
    cf_bspline_domain(c->bs, &a, &b);
    if (p < 1)
        return;
    for (size_t i = 0; i < d->fig->facts.count; i++) {
        const cf__fact_t *x = &d->fig->facts.items[i];
        if (x->kind != CF__FACT_MARKS && x->kind != CF__FACT_LABEL)
            continue;
        for (size_t k = 0; k < x->n; k++)
            for (size_t leg = 1; leg <= n; leg++) {
                double beta, alpha, u, pt[CF__DESCRIBE_MAX_DIM], pp[2];
                size_t others = 0;
                if (!(t[leg + p] > t[leg]))
                    continue;
                beta = on_segment(d, Q + 2 * (leg - 1), Q + 2 * leg,
                                  x->xy + 2 * k);
                if (beta < 0)
                    continue;
                alpha = unweight(beta, w[leg - 1], w[leg]);
                u = t[leg] + alpha * (t[leg + p] - t[leg]);
                if (!(u > a && u < b)
                    || cf_bspline_eval(c->bs, u, pt) != CF_STATUS_OK)
                    continue;
                cf__fig_project1(d->fig, pt, c->dim, pp);
                if (!drawn(d, pp, NULL))
                    continue;
                for (size_t j = 1; j <= n && p >= 2; j++) {
                    double al, q[2];
                    if (j == leg || !(t[j + p] > t[j]))
                        continue;
                    al = (u - t[j]) / (t[j + p] - t[j]);
                    if (al <= 1e-9 || al >= 1 - 1e-9)
                        continue;
                    lerp_w(Q + 2 * (j - 1), w[j - 1], Q + 2 * j, w[j], al, q);
                    others += drawn(d, q, NULL);
                }
                if (p < 2 || others > 0)
                    add_param(c, u, true);
            }
    }
}

/* Whether the Cartesian points of a and b agree within tol. */
static bool
same_points(const double *a, const double *b, size_t n, double tol)
{
    for (size_t i = 0; i < n; i++)
        if (fabs(a[i] - b[i]) > tol)
            return false;
    return true;
}

/* Whether Bézier curves (or B-splines) x and y have the same control
** points and weights; tol scales with their size. */
static bool
same_bezier(const cf_bezier_t *x, const cf__curve_info_t *y, double tol)
{
    double p[CF__DESCRIBE_MAX_PTS * CF__DESCRIBE_MAX_DIM];
    double wx[CF__DESCRIBE_MAX_PTS];
    size_t n = (size_t)cf_bezier_degree(x) + 1;
    if (n > CF__DESCRIBE_MAX_PTS || n != y->npts || cf_bezier_dim(x) != y->dim
        || cf_bezier_is_rational(x) != y->rational)
        return false;
    cf_bezier_get_points(x, p);
    cf_bezier_get_weights(x, wx);
    return same_points(p, y->pts, n * y->dim, tol)
        && same_points(wx, y->w, n, 1e-9);
}

static bool
same_bspline(const cf_bspline_t *x, const cf__curve_info_t *y, double tol)
{
    double p[CF__DESCRIBE_MAX_PTS * CF__DESCRIBE_MAX_DIM];
    double wx[CF__DESCRIBE_MAX_PTS];
    size_t n = cf_bspline_count(x);
    if (n > CF__DESCRIBE_MAX_PTS || n != y->npts || cf_bspline_dim(x) != y->dim
        || cf_bspline_is_rational(x) != y->rational
        || cf_bspline_nknots(x) != cf_bspline_nknots(y->bs)
        || !same_points(cf_bspline_knots(x), cf_bspline_knots(y->bs),
                        cf_bspline_nknots(x), 1e-12))
        return false;
    cf_bspline_get_points(x, p);
    cf_bspline_get_weights(x, wx);
    return same_points(p, y->pts, n * y->dim, tol)
        && same_points(wx, y->w, n, 1e-9);
}

/* A construction the finder could not try for want of memory: the
** description would leave out what it is; d->nomem makes it an error. */
static bool
ran_out(cf__describe_t *d, cf_status_t st)
{
    if (st == CF_STATUS_NO_MEMORY)
        d->nomem = true;
    return st != CF_STATUS_OK;
}

/* y a subdivision of x (Béziers of one degree): y starts where x starts
** and its second point on x's first leg gives t (or it ends where x ends
** and its last but one point on x's last leg gives t). */
static bool
find_split(cf__describe_t *d, const cf__curve_info_t *x,
           cf__curve_info_t *y)
{
    size_t n = x->npts - 1;
    const double *X = x->plane, *Y = y->plane;
    for (int side = 0; side < 2 && n >= 1; side++) {
        size_t e = side ? n : 0, f = side ? n - 1 : 1;
        double beta, t;
        cf_bezier_t *part = NULL;
        bool same;
        if (fabs(X[2 * e] - Y[2 * e]) > d->eps
            || fabs(X[2 * e + 1] - Y[2 * e + 1]) > d->eps)
            continue;
        beta = on_segment(d, X + 2 * e, X + 2 * f, Y + 2 * f);
        if (beta < 0)
            continue;
        t = unweight(beta, x->w[e], x->w[f]);
        if (side)
            t = 1 - t;
        if (ran_out(d, cf_bezier_split(x->bez, t, side ? NULL : &part,
                                       side ? &part : NULL, NULL)))
            continue;
        same = same_bezier(part, y, d->tol);
        cf_bezier_destroy(part);
        if (same) {
            y->rel = side ? CF__REL_RIGHT : CF__REL_LEFT;
            y->rel_param = t;
            return true;
        }
    }
    return false;
}

static bool
find_elevation(cf__describe_t *d, const cf__curve_info_t *x,
               cf__curve_info_t *y)
{
    cf_bezier_t *up = NULL;
    bool same;
    if (y->degree <= x->degree
        || ran_out(d, cf_bezier_elevate(x->bez, y->degree - x->degree,
                                        &up, NULL)))
        return false;
    same = same_bezier(up, y, d->tol);
    cf_bezier_destroy(up);
    if (same)
        y->rel = CF__REL_ELEVATED;
    return same;
}

/* y is x with knots inserted: x's knots a sub-multiset of y's, and x
** refined by the others is y. */
static bool
find_insertion(cf__describe_t *d, const cf__curve_info_t *x,
               cf__curve_info_t *y)
{
    const double *kx = cf_bspline_knots(x->bs), *ky = cf_bspline_knots(y->bs);
    size_t nx = cf_bspline_nknots(x->bs), ny = cf_bspline_nknots(y->bs);
    size_t i = 0, j = 0, m = 0;
    cf_bspline_t *r = NULL;
    bool same;
    if (y->degree != x->degree || ny <= nx
        || ny - nx > CF__DESCRIBE_MAX_PARAMS)
        return false;
    while (j < ny) {
        if (i < nx && fabs(kx[i] - ky[j]) <= 1e-12) {
            i++;
        } else {
            if (m == CF__DESCRIBE_MAX_PARAMS)
                return false;
            y->inserted[m++] = ky[j];
        }
        j++;
    }
    if (i != nx || m != ny - nx
        || ran_out(d, cf_bspline_refine(x->bs, y->inserted, m, &r, NULL)))
        return false;
    same = same_bspline(r, y, d->tol);
    cf_bspline_destroy(r);
    if (same) {
        y->rel = CF__REL_INSERTED;
        y->ninserted = m;
    }
    return same;
}

/* The distance from point q to plane curve x: the nearest of 256 samples,
** refined by golden-section search between its neighbours. */
static double
distance_to(const cf__curve_info_t *x, const double *q)
{
    enum { N = 256 };
    double a, b, best = INFINITY, tb = 0, p[2];
    if (x->bez != NULL) {
        a = 0;
        b = 1;
    } else {
        cf_bspline_domain(x->bs, &a, &b);
    }
    for (int i = 0; i <= N; i++) {
        double t = a + (b - a) * i / N, dd;
        if ((x->bez ? cf_bezier_eval(x->bez, t, p)
                    : cf_bspline_eval(x->bs, t, p)) != CF_STATUS_OK)
            continue;
        dd = hypot(p[0] - q[0], p[1] - q[1]);
        if (dd < best) {
            best = dd;
            tb = t;
        }
    }
    {
        double lo = fmax(a, tb - (b - a) / N), hi = fmin(b, tb + (b - a) / N);
        const double g = 0.6180339887498949;
        for (int k = 0; k < 60; k++) {
            double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo), p2[2];
            if ((x->bez ? cf_bezier_eval(x->bez, m1, p)
                        : cf_bspline_eval(x->bs, m1, p)) != CF_STATUS_OK
                || (x->bez ? cf_bezier_eval(x->bez, m2, p2)
                           : cf_bspline_eval(x->bs, m2, p2)) != CF_STATUS_OK)
                break;
            if (hypot(p[0] - q[0], p[1] - q[1])
                < hypot(p2[0] - q[0], p2[1] - q[1]))
                hi = m2;
            else
                lo = m1;
        }
        if ((x->bez ? cf_bezier_eval(x->bez, 0.5 * (lo + hi), p)
                    : cf_bspline_eval(x->bs, 0.5 * (lo + hi), p))
            == CF_STATUS_OK)
            best = fmin(best, hypot(p[0] - q[0], p[1] - q[1]));
    }
    return best;
}

/* y an offset of x: plane Bézier y's points at t = 0, 1/4, ... 1 all at
** one distance d > 0 from x, within 1/200 of d (an offset is drawn as an
** approximation within the figure's tolerance). */
static bool
find_offset(const cf__describe_t *d, const cf__curve_info_t *x,
            cf__curve_info_t *y)
{
    double dist[5], lo = INFINITY, hi = 0, p[2];
    if (x->dim != 2 || y->dim != 2 || y->bez == NULL)
        return false;
    for (int k = 0; k < 5; k++) {
        if (cf_bezier_eval(y->bez, k / 4.0, p) != CF_STATUS_OK)
            return false;
        dist[k] = distance_to(x, p);
        lo = fmin(lo, dist[k]);
        hi = fmax(hi, dist[k]);
    }
    if (!(lo > 1e3 * d->eps && hi - lo <= 5e-3 * hi))
        return false;
    /* measured on an approximation: 3 significant digits */
    y->rel = CF__REL_OFFSET;
    {
        double m = 0.5 * (lo + hi), k = pow(10, 2 - floor(log10(m)));
        y->rel_param = round(m * k) / k;
    }
    return true;
}

void
cf__describe_find(cf__describe_t *d)
{
    for (size_t i = 0; i < d->ncurves; i++) {
        cf__curve_info_t *c = &d->curves[i];
        /* constructions are drawn on curves of few control points, and
        ** looked for among a bounded number of points drawn */
        if (c->dim > CF__DESCRIBE_MAX_DIM || c->npts > CF__DESCRIBE_MAX_PTS
            || d->nmarks > CF__DESCRIBE_MAX_MARKS)
            continue;
        if (c->bez != NULL)
            find_decasteljau(d, c);
        else
            find_deboor(d, c);
    }
    /* a curve made from an earlier one (pairs: few curves only; offsets
    ** sample, fewer still) */
    for (size_t j = 1; j < d->ncurves && d->ncurves <= 200; j++)
        for (size_t i = 0; i < j && d->curves[j].rel == CF__REL_NONE; i++) {
            cf__curve_info_t *x = &d->curves[i], *y = &d->curves[j];
            bool found = false;
            if (x->dim != y->dim || x->rational != y->rational)
                continue;
            if (x->bez != NULL && y->bez != NULL)
                found = (x->degree == y->degree && find_split(d, x, y))
                    || find_elevation(d, x, y);
            else if (x->bs != NULL && y->bs != NULL)
                found = find_insertion(d, x, y);
            /* an offset's pieces: of the first curve that is no offset */
            if (!found && x->rel != CF__REL_OFFSET && d->ncurves <= 64)
                found = find_offset(d, x, y);
            if (found)
                y->rel_of = i;
        }
}
