/*
** Conics as quadratic Bézier curves, exact (not approximations).
**
** Every function returns a list of planar quadratic curves joined end to
** end (release it with cf_bezier_list_destroy); list->t0[i], list->t1[i]
** give the range of the conic's own parameter (angle, u or s below) that
** piece i covers.  Circles, ellipses and hyperbolas are rational with
** weights (1, w, 1): P1 is the intersection of the end tangents and, for a
** piece spanning the parameter interval 2 delta,
**
**   circle / ellipse arc:  w = cos(delta)   (pieces of at most 90 degrees,
**                                            so w >= cos 45 degrees)
**   hyperbola arc:         w = cosh(delta)  (pieces of |s1 - s0| <= 2)
**
** Parabola arcs are polynomial quadratics (w = 1) in one piece, so that
** they reach SVG/PDF as exact cubics.
**
** All inputs must be finite; lengths positive.  Errors name the argument.
*/
#ifndef CURVEFIG_CONIC_H
#define CURVEFIG_CONIC_H

#include "curvefig/bezier.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Arc of the circle with center (cx, cy) and radius r > 0 from angle a0 to
** angle a1 (radians, counter-clockwise when a1 > a0, clockwise when
** a1 < a0; any nonzero span, more than a turn allowed), split into
** ceil(|a1 - a0| / (pi/2)) equal pieces. */
CF_API cf_status_t cf_conic_arc(double cx, double cy, double r, double a0,
                                double a1, cf_bezier_list_t **out,
                                cf_diag_t *diag);

/* The full circle, counter-clockwise from angle 0, as four quarter arcs
** with exact quadrant points (closed: the last end equals the first
** start). */
CF_API cf_status_t cf_conic_circle(double cx, double cy, double r,
                                   cf_bezier_list_t **out, cf_diag_t *diag);

/* Arc of the ellipse C + R(rotation) (a cos t, b sin t), a, b > 0, for t
** from t0 to t1 (the eccentric anomaly; split like cf_conic_arc).  The
** pieces are the affine image of the unit circle's arc pieces (weights
** unchanged), hence exact. */
CF_API cf_status_t cf_conic_ellipse(double cx, double cy, double a, double b,
                                    double rotation, double t0, double t1,
                                    cf_bezier_list_t **out, cf_diag_t *diag);

/* Arc of the parabola with vertex (vx, vy), focal length f > 0 (vertex to
** focus) and axis direction `axis` (radians; the focus is at
** V + f (cos axis, sin axis)): the points
**   V + u (sin axis, -cos axis) + u^2 / (4 f) (cos axis, sin axis)
** for u from u0 to u1 (u0 < u1); u is the coordinate along the tangent at
** the vertex (for axis = pi/2 the parabola y = vy + (x - vx)^2 / (4 f)).
** One polynomial quadratic: P1 = the intersection of the end tangents. */
CF_API cf_status_t cf_conic_parabola(double vx, double vy, double f,
                                     double axis, double u0, double u1,
                                     cf_bezier_list_t **out, cf_diag_t *diag);

/* Arc of one branch of the hyperbola C + R(rotation) (a cosh s, b sinh s),
** a, b > 0 (semi-axes; the branch through C + R(rotation) (a, 0)), for s
** from s0 to s1 (s0 < s1), in pieces of |s1 - s0| <= 2. */
CF_API cf_status_t cf_conic_hyperbola(double cx, double cy, double a, double b,
                                      double rotation, double s0, double s1,
                                      cf_bezier_list_t **out, cf_diag_t *diag);

#ifdef __cplusplus
}
#endif

#endif
