/*
** Views: the projection of R^3 onto the plane of a figure, for points and,
** exactly, for Bézier and B-spline curves.  A view (cf_view_t) is what a
** scene (curvefig/visibility.h) and a figure in three dimensions
** (curvefig/figure3d.h) are seen through.
**
** The convention is that of figure{view = {azimuth, elevation}} (degrees):
** with a = azimuth, e = elevation,
**
**   ex = (-sin a, cos a, 0)                     screen x
**   ey = (-cos a sin e, -sin a sin e, cos e)    screen y (up)
**   d  = ex x ey = (cos e cos a, cos e sin a, sin e)   towards the viewer
**
** Orthographic: the image of P is (ex . P, ey . P), exactly the figure's
** projection matrix; its depth is d . P (larger is nearer the viewer).
** Perspective with a target T and a distance D > 0: the eye is at
** E = T + D d, and with z = d . (P - T) (the depth; z < D in front of the
** eye)
**
**   image(P) = (ex . T, ey . T) + D / (D - z) (ex . (P - T), ey . (P - T)),
**
** so the plane through T facing the viewer is drawn as the orthographic
** view draws it, and nearer things larger.  A point with z >= D (at or
** behind the eye) has no image: CF_STATUS_DOMAIN.
**
** The projection is linear on homogeneous coordinates, so the image of a
** Bézier or B-spline curve is exactly a curve of the same degree and knots:
** polynomial under an orthographic view (rational if the curve is), and
** rational under a perspective one, with weights w (D - z_i) / D, positive
** when the whole control polygon is in front of the eye.
*/
#ifndef CURVEFIG_VIEW_H
#define CURVEFIG_VIEW_H

#include "curvefig/bezier.h"
#include "curvefig/bspline.h"
#include "curvefig/core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum cf_projection {
    CF_PROJECTION_ORTHOGRAPHIC = 0,
    CF_PROJECTION_PERSPECTIVE = 1
} cf_projection_t;

/* A view: fill it with cf_view_orthographic or cf_view_perspective (the
** other fields are derived; read them, do not set them). */
typedef struct cf_view {
    cf_projection_t projection;
    double azimuth, elevation;  /* degrees, as given */
    double distance;            /* D (perspective), 0 for orthographic */
    double target[3];           /* T (perspective), 0 for orthographic */
    double ex[3], ey[3];        /* screen axes (above) */
    double dir[3];              /* d: unit vector towards the viewer */
    double eye[3];              /* E = T + D d (perspective), else 0 */
} cf_view_t;

/* An orthographic view from azimuth and elevation in degrees (finite:
** NOT_FINITE otherwise, naming which). */
CF_API cf_status_t cf_view_orthographic(cf_view_t *view, double azimuth,
                                        double elevation, cf_diag_t *diag);

/* A perspective view: the eye at distance > 0 from target[3] in the
** direction of (azimuth, elevation).  target NULL is the origin. */
CF_API cf_status_t cf_view_perspective(cf_view_t *view, double azimuth,
                                       double elevation, double distance,
                                       const double *target,
                                       cf_diag_t *diag);

/* The image of p[3]: out[2] (the image) and *depth (z above; may be
** NULL).  DOMAIN if p is at or behind the eye, NOT_FINITE for NaN. */
CF_API cf_status_t cf_view_project(const cf_view_t *view, const double *p,
                                   double *out, double *depth);

/* The unit vector from p[3] towards the viewer (d for an orthographic
** view, (E - p) / |E - p| for a perspective one) into out[3]: the
** direction n . out > 0 of a normal n facing the viewer. */
CF_API cf_status_t cf_view_towards_eye(const cf_view_t *view,
                                       const double *p, double *out);

/* The exact image of a curve in R^3 as a curve in R^2 of the same degree
** (and knots): polynomial for an orthographic view and a polynomial
** curve, rational otherwise.  DIM_MISMATCH if the curve is not in R^3,
** DOMAIN (naming the control point) if a control point is at or behind
** the eye.  *out is new (NULL on failure). */
CF_API cf_status_t cf_view_project_bezier(const cf_view_t *view,
                                          const cf_bezier_t *c,
                                          cf_bezier_t **out,
                                          cf_diag_t *diag);
CF_API cf_status_t cf_view_project_bspline(const cf_view_t *view,
                                           const cf_bspline_t *c,
                                           cf_bspline_t **out,
                                           cf_diag_t *diag);

#ifdef __cplusplus
}
#endif

#endif
