/*
** The view of a 3D figure (include/curvefig/figure3d.h): azimuth and
** elevation, a parallel or a central projection, as the homogeneous matrix
** whose images of control points make a projected curve exact (the same
** degree, rational under a perspective; figure.c projects with it).
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
