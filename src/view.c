/* Views: the projection of points and, exactly, of curves
** (curvefig/view.h). */
#include <math.h>
#include <string.h>

#include "numtext-private.h"
#include "vis-private.h"

static double
dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static cf_status_t
view_axes(cf_view_t *view, double azimuth, double elevation,
          cf_diag_t *diag)
{
    double a, e;
    if (!isfinite(azimuth))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "view: azimuth %s is not finite", CF__NUM(azimuth));
    if (!isfinite(elevation))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "view: elevation %s is not finite",
                         CF__NUM(elevation));
    memset(view, 0, sizeof *view);
    view->azimuth = azimuth;
    view->elevation = elevation;
    a = azimuth * CF__PI / 180.0;
    e = elevation * CF__PI / 180.0;
    view->ex[0] = -sin(a);
    view->ex[1] = cos(a);
    view->ex[2] = 0.0;
    view->ey[0] = -cos(a) * sin(e);
    view->ey[1] = -sin(a) * sin(e);
    view->ey[2] = cos(e);
    view->dir[0] = cos(e) * cos(a);
    view->dir[1] = cos(e) * sin(a);
    view->dir[2] = sin(e);
    return CF_STATUS_OK;
}

cf_status_t
cf_view_orthographic(cf_view_t *view, double azimuth, double elevation,
                     cf_diag_t *diag)
{
    cf_diag_clear(diag);
    if (view == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "view is NULL");
    return view_axes(view, azimuth, elevation, diag);
}

cf_status_t
cf_view_perspective(cf_view_t *view, double azimuth, double elevation,
                    double distance, const double *target, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st;
    double T[3] = {0.0, 0.0, 0.0};
    if (view == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "view is NULL");
    if (!isfinite(distance))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "view: distance %s is not finite", CF__NUM(distance));
    if (!(distance > 0.0))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "view: distance %s must be positive",
                         CF__NUM(distance));
    if (target != NULL) {
        for (int i = 0; i < 3; i++) {
            if (!isfinite(target[i]))
                return cf__error(diag, CF_STATUS_NOT_FINITE, i,
                                 "view: target coordinate %d = %s is not "
                                 "finite", i, CF__NUM(target[i]));
            T[i] = target[i];
        }
    }
    st = view_axes(view, azimuth, elevation, diag);
    if (st != CF_STATUS_OK)
        return st;
    view->projection = CF_PROJECTION_PERSPECTIVE;
    view->distance = distance;
    for (int i = 0; i < 3; i++) {
        view->target[i] = T[i];
        view->eye[i] = T[i] + distance * view->dir[i];
    }
    return CF_STATUS_OK;
}

/*
** Orthographic: rows ex, ey, d, (0 0 0 1).  Perspective, with W = w (D - z)
** / D and z = d . (p - T): X = (ex . T) W + ex . (w p) - w ex . T (the same
** for Y), Z = w z, so Z / W = D z / (D - z).
*/
void
cf__view_matrix(const cf_view_t *v, double M[16])
{
    memset(M, 0, 16 * sizeof(double));
    if (v->projection != CF_PROJECTION_PERSPECTIVE) {
        for (int i = 0; i < 3; i++) {
            M[i] = v->ex[i];
            M[4 + i] = v->ey[i];
            M[8 + i] = v->dir[i];
        }
        M[15] = 1.0;
        return;
    }
    double D = v->distance, dT = dot3(v->dir, v->target);
    const double *ax[2] = {v->ex, v->ey};
    /* W row: (-d / D, (D + d . T) / D) */
    for (int i = 0; i < 3; i++)
        M[12 + i] = -v->dir[i] / D;
    M[15] = (D + dT) / D;
    for (int r = 0; r < 2; r++) {
        double aT = dot3(ax[r], v->target);
        for (int i = 0; i < 3; i++)
            M[4 * r + i] = ax[r][i] + aT * M[12 + i];
        M[4 * r + 3] = aT * M[15] - aT;
    }
    for (int i = 0; i < 3; i++)
        M[8 + i] = v->dir[i];
    M[11] = -dT;
}

/* Homogeneous (X Y Z W) of the homogeneous point h (w p, w). */
static void
apply_h(const double M[16], const double *h, double *g)
{
    for (int r = 0; r < 4; r++)
        g[r] = M[4 * r] * h[0] + M[4 * r + 1] * h[1] + M[4 * r + 2] * h[2] +
               M[4 * r + 3] * h[3];
}

bool
cf__view_apply(const double M[16], const double *p, double *q)
{
    double h[4] = {p[0], p[1], p[2], 1.0}, g[4];
    apply_h(M, h, g);
    if (!(g[3] > 0.0))
        return false;
    q[0] = g[0] / g[3];
    q[1] = g[1] / g[3];
    q[2] = g[2] / g[3];
    return true;
}

cf_status_t
cf_view_project(const cf_view_t *view, const double *p, double *out,
                double *depth)
{
    double M[16], q[3];
    if (view == NULL || p == NULL || out == NULL)
        return CF_STATUS_INVALID_ARG;
    if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]))
        return CF_STATUS_NOT_FINITE;
    cf__view_matrix(view, M);
    if (!cf__view_apply(M, p, q))
        return CF_STATUS_DOMAIN;
    out[0] = q[0];
    out[1] = q[1];
    if (depth != NULL) {
        if (view->projection == CF_PROJECTION_PERSPECTIVE) {
            double r[3] = {p[0] - view->target[0], p[1] - view->target[1],
                           p[2] - view->target[2]};
            *depth = dot3(view->dir, r);
        } else {
            *depth = q[2];
        }
    }
    return CF_STATUS_OK;
}

cf_status_t
cf_view_towards_eye(const cf_view_t *view, const double *p, double *out)
{
    if (view == NULL || p == NULL || out == NULL)
        return CF_STATUS_INVALID_ARG;
    if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]))
        return CF_STATUS_NOT_FINITE;
    if (view->projection != CF_PROJECTION_PERSPECTIVE) {
        memcpy(out, view->dir, 3 * sizeof(double));
        return CF_STATUS_OK;
    }
    double r[3], n;
    for (int i = 0; i < 3; i++)
        r[i] = view->eye[i] - p[i];
    n = sqrt(dot3(r, r));
    if (!(n > 0.0) || dot3(r, view->dir) <= 0.0)
        return CF_STATUS_DOMAIN;
    for (int i = 0; i < 3; i++)
        out[i] = r[i] / n;
    return CF_STATUS_OK;
}

/*
** The image of count homogeneous (or Cartesian, rational == false) points
** in R^3 as homogeneous points in R^2 (x W, y W, W), or Cartesian when the
** view is orthographic and the curve polynomial.  *hom tells which.
*/
static cf_status_t
project_points(const cf_view_t *view, const double *src, size_t count,
               bool rational, double *dst, bool *hom, cf_diag_t *diag)
{
    double M[16];
    bool persp = view->projection == CF_PROJECTION_PERSPECTIVE;
    cf__view_matrix(view, M);
    *hom = rational || persp;
    for (size_t i = 0; i < count; i++) {
        double h[4], g[4];
        const double *s = src + i * (rational ? 4 : 3);
        h[0] = s[0];
        h[1] = s[1];
        h[2] = s[2];
        h[3] = rational ? s[3] : 1.0;
        apply_h(M, h, g);
        if (persp && !(g[3] > 1e-12 * h[3]))
            return cf__error(diag, CF_STATUS_DOMAIN, (long)i,
                             "control point %zu is at or behind the eye "
                             "(distance %s)", i, CF__NUM(view->distance));
        if (*hom) {
            dst[3 * i] = g[0];
            dst[3 * i + 1] = g[1];
            dst[3 * i + 2] = g[3];
        } else {
            dst[2 * i] = g[0];
            dst[2 * i + 1] = g[1];
        }
    }
    return CF_STATUS_OK;
}

static cf_status_t
check_view(const cf_view_t *view, cf_diag_t *diag)
{
    if (view == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "view is NULL");
    if (!isfinite(view->dir[0]) || !isfinite(view->dir[1]) ||
        !isfinite(view->dir[2]) || fabs(dot3(view->dir, view->dir) - 1.0) >
                                       1e-9)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "view was not made by cf_view_orthographic or "
                         "cf_view_perspective");
    return CF_STATUS_OK;
}

/* The points of a curve (c: whether it was given; its dimension, its n
** homogeneous points) projected into *buf (3 doubles each, freed by the
** caller on success) and whether they are homogeneous; the checks of both
** projections below, in their order. */
static cf_status_t
project_curve_points(const cf_view_t *view, bool c, size_t dim,
                     const double *hpoints, size_t n, bool rational,
                     double **buf, bool *hom, cf_diag_t *diag)
{
    cf_status_t st;
    *buf = NULL;
    if ((st = check_view(view, diag)) != CF_STATUS_OK)
        return st;
    if (!c)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "curve is NULL");
    if (dim != 3)
        return cf__error(diag, CF_STATUS_DIM_MISMATCH, -1,
                         "curve is in R^%zu; a view projects R^3", dim);
    *buf = cf__alloc_array(n, 3 * sizeof(double));
    if (*buf == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    st = project_points(view, hpoints, n, rational, *buf, hom, diag);
    if (st != CF_STATUS_OK) {
        cf__free(*buf);
        *buf = NULL;
    }
    return st;
}

cf_status_t
cf_view_project_bezier(const cf_view_t *view, const cf_bezier_t *c,
                       cf_bezier_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st;
    double *buf;
    bool hom;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    st = project_curve_points(
        view, c != NULL, c != NULL ? cf_bezier_dim(c) : 0,
        c != NULL ? cf_bezier_hpoints(c) : NULL,
        c != NULL ? (size_t)cf_bezier_degree(c) + 1 : 0,
        c != NULL && cf_bezier_is_rational(c), &buf, &hom, diag);
    if (st != CF_STATUS_OK)
        return st;
    st = hom ? cf_bezier_create_homogeneous(2, cf_bezier_degree(c), buf, out,
                                            diag)
             : cf_bezier_create(2, cf_bezier_degree(c), buf, NULL, out, diag);
    cf__free(buf);
    return st;
}

cf_status_t
cf_view_project_bspline(const cf_view_t *view, const cf_bspline_t *c,
                        cf_bspline_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st;
    double *buf;
    bool hom;
    size_t n;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    n = c != NULL ? cf_bspline_count(c) : 0;
    st = project_curve_points(
        view, c != NULL, c != NULL ? cf_bspline_dim(c) : 0,
        c != NULL ? cf_bspline_hpoints(c) : NULL, n,
        c != NULL && cf_bspline_is_rational(c), &buf, &hom, diag);
    if (st != CF_STATUS_OK)
        return st;
    st = hom ? cf_bspline_create_homogeneous(
                   2, cf_bspline_degree(c), cf_bspline_knots(c),
                   cf_bspline_nknots(c), buf, n, out, diag)
             : cf_bspline_create(2, cf_bspline_degree(c), cf_bspline_knots(c),
                                 cf_bspline_nknots(c), buf, n, NULL, out,
                                 diag);
    cf__free(buf);
    return st;
}
