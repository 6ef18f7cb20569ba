/*
** The view of a 3D figure (include/curvefig/figure3d.h): azimuth and
** elevation, a parallel or a central projection, and the homogeneous
** images of points that make a projected curve exact (the same degree,
** rational under a perspective).
*/
#include <math.h>
#include <string.h>

#include "model.h"

void
cf_view_matrix(const cf_view_t *view, double m[12])
{
    const double *ex = view->ex, *ey = view->ey, *d = view->dir;
    const double *t = view->target;
    double D = view->distance, xt = 0, yt = 0, dt = 0;
    if (view->projection != CF_PROJECTION_PERSPECTIVE || !(D > 0)) {
        for (int k = 0; k < 3; k++) {
            m[k] = ex[k];
            m[4 + k] = ey[k];
            m[8 + k] = 0.0;
        }
        m[3] = m[7] = 0.0;
        m[11] = 1.0;
        return;
    }
    for (int k = 0; k < 3; k++) {
        xt += ex[k] * t[k];
        yt += ey[k] * t[k];
        dt += d[k] * t[k];
    }
    /* W = (D - z) / D with z = d . (P - T); X = W (ex . T) + ex . (P - T)
    ** = ex . P - (ex . T) (d . P) / D + (ex . T)(d . T) / D, Y alike */
    for (int k = 0; k < 3; k++) {
        m[k] = ex[k] - xt * d[k] / D;
        m[4 + k] = ey[k] - yt * d[k] / D;
        m[8 + k] = -d[k] / D;
    }
    m[3] = xt * dt / D;
    m[7] = yt * dt / D;
    m[11] = 1.0 + dt / D;
}

cf_status_t
cf_figure_set_view(cf_figure_t *fig, const cf_view_t *view)
{
    double rows[6];
    cf_status_t st;
    CF__FIG_CHECK(fig);
    if (view == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "view: NULL");
    if (view->projection == CF_PROJECTION_PERSPECTIVE
        && !(isfinite(view->distance) && view->distance > 0))
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "view: distance = %g must be positive and "
                           "finite", view->distance);
    /* the orthographic rows serve the linear uses of the projection (and
    ** a figure drawn before the view is known) */
    memcpy(rows, view->ex, 3 * sizeof *rows);
    memcpy(rows + 3, view->ey, 3 * sizeof *rows);
    st = cf_figure_set_projection(fig, 3, rows);
    if (st != CF_STATUS_OK)
        return st;
    fig->view = *view;
    cf_view_matrix(view, fig->view_m);
    fig->has_view = true;
    return CF_STATUS_OK;
}

bool
cf_figure_get_view(const cf_figure_t *fig, cf_view_t *out)
{
    if (fig == NULL || !fig->has_view)
        return false;
    if (out != NULL)
        *out = fig->view;
    return true;
}

bool
cf__fig_is_central(const cf_figure_t *fig, size_t dim)
{
    return fig->has_view && dim == 3
        && fig->view.projection == CF_PROJECTION_PERSPECTIVE;
}

bool
cf__fig_project_h(const cf_figure_t *fig, const double *hp, size_t dim,
                  bool rational, double out[3])
{
    double w = rational ? hp[dim] : 1.0;
    if (cf__fig_is_central(fig, dim)) {
        const double *m = fig->view_m;
        for (int r = 0; r < 3; r++)
            out[r] = m[4 * r] * hp[0] + m[4 * r + 1] * hp[1]
                + m[4 * r + 2] * hp[2] + m[4 * r + 3] * w;
        /* the eye itself or behind it (W = (D - z) / D w); a point
        ** within 1e-9 D of the eye's plane is not drawable either */
        return out[2] > 1e-9 * w;
    }
    cf__fig_project1(fig, hp, dim, out);
    out[2] = w;
    return true;
}

cf_status_t
cf__fig_behind_eye(cf_figure_t *fig, const double *p, const char *what)
{
    double s = 0;
    for (int k = 0; k < 3; k++)
        s += fig->view.dir[k] * (p[k] - fig->view.target[k]);
    return cf_diag_set(&fig->err, CF_STATUS_DOMAIN, -1,
                       "%s (%g, %g, %g) lies at or behind the eye of the "
                       "view (distance = %g); a distance above %g shows it",
                       what, p[0], p[1], p[2], fig->view.distance,
                       s > 0 ? 1.5 * s : fig->view.distance);
}
