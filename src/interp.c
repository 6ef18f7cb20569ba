/*
** Interpolation front end: input checks and dispatch (cf_interpolate); the
** chapter-4 cubics of Ferguson and Coons.  Options, names and data
** parameters are in interp-params.c, the spline constructions in
** interp-spline.c.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "bezier-private.h"
#include "interp-private.h"
#include "numtext-private.h"

static cf_status_t
check_tangent(const double *t, size_t dim, const char *name, cf_diag_t *diag)
{
    if (t == NULL)
        return CF_STATUS_OK;
    for (size_t k = 0; k < dim; k++) {
        if (!isfinite(t[k]))
            return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                             "%s has coordinate %zu = %s; coordinates must "
                             "be finite", name, k + 1, CF__NUM(t[k]));
    }
    return CF_STATUS_OK;
}

/* ---- the front end ------------------------------------------------------ */

static bool
same_point(const double *a, const double *b, size_t dim)
{
    for (size_t k = 0; k < dim; k++)
        if (a[k] != b[k])
            return false;
    return true;
}

/* Fewest points each method accepts (GLOBAL: checked with its degree). */
static size_t
min_points(cf_interp_method_t m, bool closed)
{
    switch (m) {
    case CF_INTERP_NOT_A_KNOT:
        return 4;
    case CF_INTERP_PERIODIC:
        return 3;
    case CF_INTERP_CATMULL_ROM:
        return closed ? 3 : 2;
    default:
        return 2;
    }
}

static const char *
method_title(cf_interp_method_t m, bool closed)
{
    switch (m) {
    case CF_INTERP_NATURAL:
        return "natural cubic spline";
    case CF_INTERP_CLAMPED:
        return "clamped cubic spline";
    case CF_INTERP_NOT_A_KNOT:
        return "not-a-knot cubic spline";
    case CF_INTERP_PERIODIC:
        return "periodic cubic spline";
    case CF_INTERP_CATMULL_ROM:
        return closed ? "closed Catmull-Rom spline" : "Catmull-Rom spline";
    default:
        return "global interpolation";
    }
}

static cf_status_t
check_options(size_t dim, const cf_interp_options_t *o, cf_diag_t *diag)
{
    const char *title;
    if ((unsigned)o->method > CF_INTERP_GLOBAL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "unknown interpolation method %d", (int)o->method);
    if ((unsigned)o->param > CF_PARAM_POWER)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "unknown parametrisation %d", (int)o->param);
    title = method_title(o->method, o->closed);
    if (o->method == CF_INTERP_GLOBAL) {
        if (o->degree < 1 || o->degree > CF_BSPLINE_MAX_DEGREE)
            return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                             "global interpolation degree %d is outside "
                             "1..%d", o->degree, CF_BSPLINE_MAX_DEGREE);
        if (o->closed)
            return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                             "global interpolation cannot be closed; use "
                             "method periodic for a closed cubic spline");
        if (o->degree == 1 &&
            (o->start_tangent != NULL || o->end_tangent != NULL))
            return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                             "global interpolation of degree 1 (a polyline) "
                             "takes no end tangents");
    } else {
        if (o->degree != 0 && o->degree != 3)
            return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                             "%s has degree 3, got degree %d; use method "
                             "global for other degrees", title, o->degree);
        if (o->closed && o->method != CF_INTERP_CATMULL_ROM &&
            o->method != CF_INTERP_PERIODIC)
            return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                             "%s cannot be closed; use method periodic for "
                             "a closed cubic spline", title);
    }
    if (o->method == CF_INTERP_CLAMPED &&
        (o->start_tangent == NULL || o->end_tangent == NULL))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "clamped cubic spline needs start_tangent and "
                         "end_tangent");
    if (o->method != CF_INTERP_CLAMPED && o->method != CF_INTERP_GLOBAL &&
        (o->start_tangent != NULL || o->end_tangent != NULL))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "%s takes no end tangents; use method clamped or "
                         "global", title);
    if (check_tangent(o->start_tangent, dim, "start_tangent", diag) !=
            CF_STATUS_OK ||
        check_tangent(o->end_tangent, dim, "end_tangent", diag) !=
            CF_STATUS_OK)
        return CF_STATUS_NOT_FINITE;
    return CF_STATUS_OK;
}

cf_status_t
cf_interpolate(size_t dim, const double *points, size_t count,
               const cf_interp_options_t *opt, cf_bspline_t **out,
               cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_interp_options_t local;
    const cf_interp_options_t *o = &local;
    bool closed;
    size_t need, nd = 0;
    double *u;
    cf_status_t st;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "out must not be NULL");
    *out = NULL;
    if (opt != NULL)
        local = *opt;
    else
        cf_interp_options_init(&local);
    if (local.degree == 0)
        local.degree = 3;
    if (dim < 1)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "dimension must be at least 1, got 0");
    if (points == NULL && count > 0)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "points must not be NULL");
    st = check_options(dim, o, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (count > 0) {
        st = cf__check_finite_points(points, count, dim, dim, "point", diag);
        if (st != CF_STATUS_OK)
            return st;
    }
    closed = o->method == CF_INTERP_PERIODIC ||
             (o->method == CF_INTERP_CATMULL_ROM && o->closed);
    /* a closed curve given with its closing point: drop the repeat */
    if (closed && count >= 2 &&
        same_point(points, points + (count - 1) * dim, dim))
        count--;
    if (o->method == CF_INTERP_GLOBAL) {
        nd = (o->start_tangent != NULL) + (o->end_tangent != NULL);
        if (count < 2)
            return cf__error(diag, CF_STATUS_TOO_FEW_POINTS, (long)count,
                             "global interpolation needs at least 2 "
                             "points, got %zu", count);
        if (count + nd < (size_t)o->degree + 1) {
            if (nd == 0)
                return cf__error(diag, CF_STATUS_TOO_FEW_POINTS,
                                 (long)count, "global interpolation of "
                                 "degree %d needs at least %d points, got "
                                 "%zu", o->degree, o->degree + 1, count);
            return cf__error(diag, CF_STATUS_TOO_FEW_POINTS, (long)count,
                             "global interpolation of degree %d needs at "
                             "least %d points and end derivatives "
                             "together, got %zu + %zu", o->degree,
                             o->degree + 1, count, nd);
        }
    } else {
        need = min_points(o->method, closed);
        if (count < need)
            return cf__error(diag, CF_STATUS_TOO_FEW_POINTS, (long)count,
                             "%s needs at least %zu %spoints, got %zu",
                             method_title(o->method, closed), need,
                             closed ? "distinct " : "", count);
    }
    u = cf__alloc_array(count + 1, sizeof *u);
    if (u == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "no memory for %zu parameters", count + 1);
    st = cf__interp_prepare_params(dim, points, count, o, closed, true, u,
                                   diag);
    if (st == CF_STATUS_OK) {
        switch (o->method) {
        case CF_INTERP_NATURAL:
        case CF_INTERP_CLAMPED:
            st = cf__interp_cubic_ends(dim, points, count, u,
                                       o->start_tangent, o->end_tangent,
                                       out, diag);
            break;
        case CF_INTERP_NOT_A_KNOT:
            st = cf__interp_not_a_knot(dim, points, count, u, out, diag);
            break;
        case CF_INTERP_PERIODIC:
            st = cf__interp_periodic(dim, points, count, u, out, diag);
            break;
        case CF_INTERP_CATMULL_ROM:
            st = cf__interp_catmull_rom(dim, points, count, u, closed, out,
                                        diag);
            break;
        case CF_INTERP_GLOBAL:
            st = cf__interp_global(dim, points, count, u, o->degree,
                                   o->start_tangent, o->end_tangent, out,
                                   diag);
            break;
        }
    }
    cf__free(u);
    return st;
}

/* ---- Ferguson cubics ---------------------------------------------------- */

static cf_status_t
check_vec(const double *v, size_t dim, const char *name, cf_diag_t *diag)
{
    if (v == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "%s must not be NULL", name);
    return check_tangent(v, dim, name, diag);
}

/* Bézier points of the Hermite cubic: P0, P0 + T0/3, P1 - T1/3, P1
** (from C'(0) = 3 (B1 - B0), C'(1) = 3 (B3 - B2)). */
static void
hermite_to_bezier(size_t dim, const double *p0, const double *p1,
                  const double *t0, const double *t1, double *b)
{
    for (size_t k = 0; k < dim; k++) {
        b[k] = p0[k];
        b[dim + k] = p0[k] + t0[k] / 3.0;
        b[2 * dim + k] = p1[k] - t1[k] / 3.0;
        b[3 * dim + k] = p1[k];
    }
}

cf_status_t
cf_ferguson_cubic(size_t dim, const double *p0, const double *p1,
                  const double *t0, const double *t1, cf_bezier_t **out,
                  cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bezier_t *c;
    cf_status_t st;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "out must not be NULL");
    *out = NULL;
    if (dim < 1)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "dimension must be at least 1, got 0");
    if ((st = check_vec(p0, dim, "P0", diag)) != CF_STATUS_OK ||
        (st = check_vec(p1, dim, "P1", diag)) != CF_STATUS_OK ||
        (st = check_vec(t0, dim, "tangent T0", diag)) != CF_STATUS_OK ||
        (st = check_vec(t1, dim, "tangent T1", diag)) != CF_STATUS_OK)
        return st;
    c = cf__bezier_new(dim, 3, false);
    if (c == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "no memory for a Ferguson cubic in R^%zu", dim);
    hermite_to_bezier(dim, p0, p1, t0, t1, c->pts);
    *out = c;
    return CF_STATUS_OK;
}

cf_status_t
cf_ferguson_chain(size_t dim, const double *points, const double *tangents,
                  size_t count, cf_bezier_list_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bezier_list_t *list;
    cf_status_t st;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "out must not be NULL");
    *out = NULL;
    if (dim < 1 || points == NULL || tangents == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "needs dim >= 1, points and "
                         "tangents");
    if (count < 2)
        return cf__error(diag, CF_STATUS_TOO_FEW_POINTS, (long)count,
                         "Ferguson chain needs at least 2 points, got %zu",
                         count);
    if ((st = cf__check_finite_points(points, count, dim, dim, "point",
                                      diag)) != CF_STATUS_OK ||
        (st = cf__check_finite_points(tangents, count, dim, dim, "tangent",
                                      diag)) != CF_STATUS_OK)
        return st;
    list = cf__bezier_list_new(count - 1, true);
    if (list == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "no memory for a chain of %zu cubics", count - 1);
    for (size_t i = 0; i + 1 < count; i++) {
        cf_bezier_t *c = cf__bezier_new(dim, 3, false);
        if (c == NULL) {
            cf_bezier_list_destroy(list);
            return cf__error(diag, CF_STATUS_NO_MEMORY, (long)i,
                             "no memory for a chain of %zu cubics",
                             count - 1);
        }
        hermite_to_bezier(dim, points + i * dim, points + (i + 1) * dim,
                          tangents + i * dim, tangents + (i + 1) * dim,
                          c->pts);
        list->items[i] = c;
        list->t0[i] = (double)i;
        list->t1[i] = (double)(i + 1);
    }
    *out = list;
    return CF_STATUS_OK;
}

/* ---- Coons cubics ------------------------------------------------------- */

/* The uniform cubic B-spline segment of Q0..Q3 in Bézier form: the basis
** 1/6 [(1-t)^3, 3t^3 - 6t^2 + 4, -3t^3 + 3t^2 + 3t + 1, t^3] converted to
** Bernstein: B0 = (Q0 + 4Q1 + Q2)/6, B1 = (2Q1 + Q2)/3, B2 = (Q1 + 2Q2)/3,
** B3 = (Q1 + 4Q2 + Q3)/6. */
static void
coons_to_bezier(size_t dim, const double *q0, const double *q1,
                const double *q2, const double *q3, double *b)
{
    for (size_t k = 0; k < dim; k++) {
        b[k] = (q0[k] + 4.0 * q1[k] + q2[k]) / 6.0;
        b[dim + k] = (2.0 * q1[k] + q2[k]) / 3.0;
        b[2 * dim + k] = (q1[k] + 2.0 * q2[k]) / 3.0;
        b[3 * dim + k] = (q1[k] + 4.0 * q2[k] + q3[k]) / 6.0;
    }
}

cf_status_t
cf_coons_cubic(size_t dim, const double *p4, cf_bezier_t **out,
               cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bezier_t *c;
    cf_status_t st;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "out must not be NULL");
    *out = NULL;
    if (dim < 1 || p4 == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "needs dim >= 1 and four points");
    st = cf__check_finite_points(p4, 4, dim, dim, "point", diag);
    if (st != CF_STATUS_OK)
        return st;
    c = cf__bezier_new(dim, 3, false);
    if (c == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "no memory for a Coons cubic in R^%zu", dim);
    coons_to_bezier(dim, p4, p4 + dim, p4 + 2 * dim, p4 + 3 * dim, c->pts);
    *out = c;
    return CF_STATUS_OK;
}

/* Index into the given points of entry j of the treated sequence. */
static size_t
coons_index(cf_coons_ends_t ends, size_t count, size_t j)
{
    switch (ends) {
    case CF_COONS_TRIPLED:
        return j < 2 ? 0 : j - 2 >= count ? count - 1 : j - 2;
    case CF_COONS_CLOSED:
        return j % count;
    default:
        return j;
    }
}

cf_status_t
cf_coons_chain(size_t dim, const double *points, size_t count,
               cf_coons_ends_t ends, cf_bezier_list_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    static const size_t need[] = { 4, 2, 3 };
    static const char *const names[] = { "plain", "tripled-end",
                                         "closed" };
    cf_bezier_list_t *list;
    size_t total, nseg;
    cf_status_t st;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "out must not be NULL");
    *out = NULL;
    if (dim < 1 || points == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "needs dim >= 1 and points");
    if ((unsigned)ends > CF_COONS_CLOSED)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "unknown end treatment %d", (int)ends);
    if (count < need[ends])
        return cf__error(diag, CF_STATUS_TOO_FEW_POINTS, (long)count,
                         "%s Coons B-spline needs at least %zu points, got "
                         "%zu", names[ends], need[ends], count);
    st = cf__check_finite_points(points, count, dim, dim, "point", diag);
    if (st != CF_STATUS_OK)
        return st;
    total = ends == CF_COONS_TRIPLED ? count + 4
            : ends == CF_COONS_CLOSED ? count + 3
                                      : count;
    nseg = total - 3;
    list = cf__bezier_list_new(nseg, true);
    if (list == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "no memory for a chain of %zu cubics", nseg);
    for (size_t s = 0; s < nseg; s++) {
        cf_bezier_t *c = cf__bezier_new(dim, 3, false);
        if (c == NULL) {
            cf_bezier_list_destroy(list);
            return cf__error(diag, CF_STATUS_NO_MEMORY, (long)s,
                             "no memory for a chain of %zu cubics", nseg);
        }
        coons_to_bezier(dim, points + coons_index(ends, count, s) * dim,
                        points + coons_index(ends, count, s + 1) * dim,
                        points + coons_index(ends, count, s + 2) * dim,
                        points + coons_index(ends, count, s + 3) * dim,
                        c->pts);
        list->items[s] = c;
        list->t0[s] = (double)s;
        list->t1[s] = (double)(s + 1);
    }
    *out = list;
    return CF_STATUS_OK;
}
