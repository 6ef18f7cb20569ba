/*
** The lines of a surface in space, shared by the surface element
** (el-surface.c) and the makers of a triangular patch's lines
** (surface-tri.c): Bézier pieces in R^3 with the (u, v) line they follow
** on the surface, in families drawn each in its own style.
*/
#ifndef CURVEFIG_RENDER_SURFACE_LINES_H
#define CURVEFIG_RENDER_SURFACE_LINES_H

#include "curvefig/surface-triangle.h"
#include "curvefig/surface.h"
#include "model.h"

enum { CF__LINE_OUTLINE, CF__LINE_ISO, CF__LINE_NET, CF__LINE_FAMILIES };
/* The probe's families of the elements in space (el-space.c): segments of
** polylines and polygons, and points (a segment of length 0). */
enum { CF__LINE_SPACE = 8, CF__LINE_SPACE_POINT = 9 };

typedef struct cf__line3 {
    int family;
    cf_bezier_t *bez;        /* in R^3 */
    cf_bezier_t *uv;         /* (u, v) on the surface, NULL: not on it */
} cf__line3_t;

typedef struct cf__lines3 {
    cf__line3_t *items;
    size_t n, cap;
} cf__lines3_t;

/* Append a line, taking bez and uv over (freed on failure too). */
cf_status_t cf__lines3_add(cf_figure_t *fig, cf__lines3_t *l, int family,
                           cf_bezier_t *bez, cf_bezier_t *uv);
void cf__lines3_fini(cf__lines3_t *l);

/* A surface whose n control points p (Cartesian, R^3) lie on one line or
** in one point has no normal: DEGENERATE, saying so. */
cf_status_t cf__check_degenerate(cf_figure_t *fig, const double *p, size_t n);

/* The lines of a B-spline surface that o asks for (surface-lines-grid.c):
** boundary (outline), iso- and knot lines, the net of its control points
** cpts (Cartesian). */
cf_status_t cf__bspline_lines(cf_figure_t *fig, const cf_bspline_surface_t *s,
                              const double *cpts, const cf_surface_lines_t *o,
                              cf__lines3_t *out);

/* A copy of a triangular patch (from its points and weights). */
cf_status_t cf__triangle_copy(cf_figure_t *fig, const cf_bezier_triangle_t *t,
                              cf_bezier_triangle_t **out);

/* The lines of a triangular patch in R^3 that o asks for: the three
** edges (boundary), iso-lines u = const, v = const and w = const (nu of
** u and of w, nv of v, evenly spaced, or the given values of u and v),
** the net's edges.  Iso-lines are exact: the restriction of the patch to
** a line of its domain is a Bézier curve of the same degree whose control
** points are the patch's blossom at the line's ends. */
cf_status_t cf__triangle_lines(cf_figure_t *fig,
                               const cf_bezier_triangle_t *t,
                               const cf_surface_lines_t *o,
                               cf__lines3_t *out);

/* Paint the facets of scene sc within tol (surface-shade.c) in painting
** order, a facet of surface k with by_id[k] (k < nids; NULL or shade
** NONE: not painted), lit as curvefig/figure3d.h says. */
cf_status_t cf__shade_facets(cf_figure_t *fig, const cf_scene_t *sc,
                             double tol,
                             const cf_surface_shading_t *const *by_id,
                             size_t nids, const cf__layout_t *l,
                             cf__dl_t *dl);

/* For tests: every piece of every line the surface elements of fig split
** by the scene when laid out with tolerance tol (data units): fn(closure,
** element index, family, line in R^3, its (u, v) line on the surface (or
** NULL) with its distance from it (offset: a silhouette's error in space),
** t0, t1, visible) (hidden pieces too when hidden = "remove"; nothing of
** lines drawn whole, hidden = "show").  And every surface element:
** surf(closure, element index, B-spline surface or triangle (one NULL),
** occludes). */
typedef void (*cf__surface_piece_fn)(void *closure, size_t el, int family,
                                     const cf_bezier_t *bez,
                                     const cf_bezier_t *uv, double offset,
                                     double t0, double t1, bool visible);
typedef void (*cf__surface_fn)(void *closure, size_t el,
                               const cf_bspline_surface_t *s,
                               const cf_bezier_triangle_t *t,
                               bool occludes);
cf_status_t cf__figure_surface_pieces(cf_figure_t *fig, double tol,
                                      cf__surface_piece_fn fn,
                                      cf__surface_fn surf, void *closure);

/* The figure's scene of occluding surfaces for visibility at tolerance tol
** (data units), kept in the figure; *out NULL when no surface occludes
** (figure-scene.c). */
cf_status_t cf__figure_scene(cf_figure_t *fig, double tol, cf_scene_t **out);

/*
** The tolerance surfaces' products (hidden lines, silhouettes, the scene)
** are made at when tol is asked for.  An exact run's page cropped to its
** ink (layout.c) measures its ink roughly first (fig->refit_rough: ten
** times tol, as a draft), then at the next refit makes them at
** CF__REFIT_MAKE times its tolerance, or finer where the tolerance fell
** from the first refit's (fig->refit_drop, d): 1 - 0.4 d - 0.01 times it,
** at least 0.9 times.  The later refits and the drawing shown, whose
** tolerances go on falling by 0.05 to 0.44 times d in all (the crop
** converging; the shipped figures and 46 views of the 3D example), take
** them when made within their own (cf__tol_serves): one set made where
** the layout made two.  (Made at 0.97 times the second refit's tolerance,
** the 3D example's drawing fell below it after drops of 10 to 24 % and
** made its set again: a fifth of its exact runs' time in the page.)
** Otherwise tol itself.
*/
#define CF__REFIT_ROUGH 10.0
#define CF__REFIT_MAKE 0.97
#define CF__REFIT_FOLLOW 0.4
static inline double
cf__tol_make(const cf_figure_t *fig, double tol)
{
    double k = 1.0 - CF__REFIT_FOLLOW * fig->refit_drop - 0.01;
    if (fig->refit_rough)
        return CF__REFIT_ROUGH * tol;
    if (!fig->refitting || fig->draft)
        return tol;
    return (k < CF__REFIT_MAKE ? (k > 0.9 ? k : 0.9) : CF__REFIT_MAKE) * tol;
}

/* Whether what was made for tolerance `made` serves tolerance tol: made
** within it (within what cf__tol_make makes for it), or, in a draft
** (cf_figure_set_draft) and the ink refits, within
** CF_FIGURE_DRAFT_SLACK times it (the layout's later passes ask for a few
** percent less than its first). */
static inline bool
cf__tol_serves(const cf_figure_t *fig, double made, double tol)
{
    double want = fig->refit_rough ? CF__REFIT_ROUGH * tol : tol;
    return made > 0
        && made <= (fig->draft || fig->refitting
                    ? CF_FIGURE_DRAFT_SLACK * want : want);
}

/* Elements in space (el-space.c): whether p[3] is seen in the scene for
** layout tolerance tol (true without one); for the probe above, the
** pieces of element el (index `index`) when it is one (families
** CF__LINE_SPACE, CF__LINE_SPACE_POINT), else nothing. */
cf_status_t cf__space_point_visible(cf_figure_t *fig, const double *p,
                                    double tol, bool *seen);
/* The marker of a point at xy (data) in style s, seen or hidden: left out
** (remove), faded to 0.4 of its opacity (dashed) or drawn alike. */
void cf__space_marker(const cf__layout_t *l, const cf_style_t *s,
                      const double *xy, bool seen, cf_hidden_t hidden,
                      cf__dl_t *dl);
/* A polyline in space (closed: a polygon) owned by the caller, not in the
** figure (a region's outline, el-region.c): drawn with its kind's draw in
** a style given then, released with its kind's fini and cf_free; NULL
** with the error in fig. */
cf__element_t *cf__space_outline_new(cf_figure_t *fig, const double *pts,
                                     size_t n, bool closed,
                                     cf_hidden_t hidden, const char *what);
cf_status_t cf__space_pieces(cf_figure_t *fig, cf__element_t *el,
                             size_t index, double tol,
                             cf__surface_piece_fn fn, void *closure);
/* The front and back colours and opacity of element i of fig when it is a
** shaded surface (for the colour check, render/output/colour-check.c). */
bool cf__surface_shading(const cf_figure_t *fig, size_t i,
                         cf_surface_shading_t *out);

#endif
