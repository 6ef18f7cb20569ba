/*
** An independent ray caster for the tests of visibility (the library's is
** src/vis-ray.c): long double, Newton's method on the three equations
** S(u, v) = p + s e (the point, the line of sight towards the eye) from a
** grid of starting points on every patch whose box the line crosses.  It
** shares nothing with the library but the public accessors of surfaces
** and the view's axes, so a test of figures can use it too: sample a
** drawn line densely and ask, for each sample, whether a surface lies
** between it and the eye.
*/
#ifndef CURVEFIG_TESTS_RAYCAST_REF_H
#define CURVEFIG_TESTS_RAYCAST_REF_H

#include <stdbool.h>
#include <stddef.h>

#include "curvefig/surface-triangle.h"
#include "curvefig/surface.h"
#include "curvefig/visibility.h"

typedef struct rc_scene rc_scene_t;

/* A scene for the view (copied).  NULL when out of memory. */
rc_scene_t *rc_create(const cf_view_t *view);
void rc_destroy(rc_scene_t *rc);

/* Surfaces (their control points are copied; B-spline surfaces as their
** Bézier patches).  false when out of memory or not in R^3. */
bool rc_add_bezier(rc_scene_t *rc, const cf_bezier_surface_t *s);
bool rc_add_bspline(rc_scene_t *rc, const cf_bspline_surface_t *s);
bool rc_add_triangle(rc_scene_t *rc, const cf_bezier_triangle_t *t);

/* Whether a surface point lies on the line of sight from p towards the
** eye farther than `margin` (in space) from p.  *dist (may be NULL)
** receives the distance of the nearest such point from p (0 when none);
** without it the search stops at the first point found. */
bool rc_hidden(const rc_scene_t *rc, const double *p, double margin,
               double *dist);

/* The number of surface points found on that line of sight beyond
** margin (for the tests' own checks). */
size_t rc_hits(const rc_scene_t *rc, const double *p, double margin);

#endif
