/*
** curvefig figures: lecture illustrations drawn with cairo and pango and
** written as SVG, PDF, PS, EPS and PNG (library curvefig-render).
**
** A figure has a physical size, a data window (fitted to what is drawn by
** default, or explicit) and a list of elements drawn in the order they are
** added.  Elements keep their data; everything is laid out when the figure
** is written, so the window, theme and tolerance may be changed at any time
** before cf_figure_write.
**
** Coordinates.  Element coordinates are data coordinates, x to the right
** and y UP, interleaved 2D points (x0 y0 x1 y1 ...).  Points of dimension
** dim >= 3 can be projected with cf_figure_project (the projection set by
** cf_figure_set_projection; default: keep the first two coordinates).  All
** lengths in styles and options (widths, marker sizes, font sizes, offsets,
** tolerances) are in bp, the PostScript/PDF point of 1/72 in; use
** cf_length_to_bp to convert (CF_UNIT_TEXPT: 10 TeX pt = 9.9626 bp).
**
** Curves reach the file as path commands: polynomial pieces of degree <= 3
** as exact cubic segments (one SVG `C` each), everything else (higher
** degree, rational, projected rational) as cubic segments fitted within the
** figure's tolerance (default 0.01 bp, measured on the page).  Never a dense
** polyline.
**
** Errors are sticky, like cairo: every function returns a cf_status_t, and
** the first error is also kept in the figure; once a figure is in error,
** later calls do nothing and return that status.  cf_figure_status gives
** the status and its message.  Writing a file that fails for a reason
** outside the figure (unwritable directory) returns CF_STATUS_IO but does
** not put the figure in error.
**
** Labels use a small TeX-like syntax (see curvefig/label.h).
*/
#ifndef CURVEFIG_FIGURE_H
#define CURVEFIG_FIGURE_H

#include "curvefig/core.h"
#include "curvefig/bezier.h"
#include "curvefig/export.h"
#include "curvefig/label.h"
#include "curvefig/output.h"
#include "curvefig/layout.h"
#include "curvefig/overlay.h"
#include "curvefig/style.h"

#ifdef __cplusplus
extern "C" {
#endif

struct cf_bspline;   /* include/curvefig/bspline.h */

/* ---- figure ------------------------------------------------------------- */

/* A figure of width x height (> 0, finite) in the given unit.  *out is
** NULL on failure. */
CF_API cf_status_t cf_figure_create(double width, double height,
                                    cf_unit_t unit, cf_figure_t **out,
                                    cf_diag_t *diag);
CF_API void cf_figure_destroy(cf_figure_t *fig);

/* The figure's first error (CF_STATUS_OK if none); fills diag (if not
** NULL) with its message.  NULL fig: INVALID_ARG. */
CF_API cf_status_t cf_figure_status(const cf_figure_t *fig, cf_diag_t *diag);

/* The number of elements added so far (0 for NULL): element i of the
** legend and overlay functions counts from 0 in the order added. */
CF_API size_t cf_figure_element_count(const cf_figure_t *fig);

/* The line of the script that adds the elements added next (0: unknown,
** the default): the figure's errors and warnings about an element name it
** ("label 3 (line 12) lies ...").  The Lua binding sets it at every call
** of a figure's method. */
CF_API void cf_figure_set_line(cf_figure_t *fig, int line);

/* What the last layout of the figure (a render, a dump, an ink box)
** noted without failing: every label that lies on drawn ink (on a stroke,
** a marker or another label; shadings do not count), placed by hand or
** automatically, as `label "TEXT" (place P) lies on KIND N` (N counts the
** elements from 1; with the script lines when known: `label "TEXT" (line
** L, place P) lies on KIND N (line M)`), one line each.  "" when none (or
** fig is NULL); valid until the next layout or cf_figure_destroy. */
CF_API const char *cf_figure_warnings(const cf_figure_t *fig);

/* Page size in bp (before any tight cropping). */
CF_API void cf_figure_get_size(const cf_figure_t *fig, double *width_bp,
                               double *height_bp);

/* Title and description: SVG <title>/<desc>, PDF Title/Subject metadata.
** UTF-8, copied.  NULL clears. */
CF_API cf_status_t cf_figure_set_title(cf_figure_t *fig, const char *title);
CF_API cf_status_t cf_figure_set_caption(cf_figure_t *fig,
                                         const char *caption);

/* Copy a theme into the figure (default: cf_theme_get("default")).
** Applies to all elements, including ones already added. */
CF_API cf_status_t cf_figure_set_theme(cf_figure_t *fig,
                                       const cf_theme_t *theme);
/* The figure's current theme (to modify and set back). */
CF_API void cf_figure_get_theme(const cf_figure_t *fig, cf_theme_t *out);

/* Explicit data window (xmin < xmax, ymin < ymax).  With keep_aspect
** (cf_figure_set_fit) the window is enlarged symmetrically so that one data
** unit has the same length on both axes; otherwise it fills the page
** inside the margin.  Curves, polylines, polygons, hulls, fills and nets
** are clipped to the window widened by their line width (a line on the
** window's edge stays whole); points, knot marks, polygon and net
** vertices and labels anchored outside the window are left out; arrows
** and axes are drawn whole.  Only what remains is given room (a close-up
** of a larger drawing keeps its scale). */
CF_API cf_status_t cf_figure_set_window(cf_figure_t *fig, double xmin,
                                        double xmax, double ymin, double ymax);
/* Go back to a window fitted to what is drawn (the default): the tight
** box of curves (not of their control points, unless those are drawn too),
** polygon vertices, points, arrow ends, label anchors, axes ranges. */
CF_API cf_status_t cf_figure_set_window_auto(cf_figure_t *fig);
/* Fitting: the window is scaled so that everything drawn, including what
** sticks out of it (labels, markers, arrow heads, line widths), lies at
** least margin_bp (>= 0, default 4) inside the page edges.  keep_aspect:
** equal scales on both axes.  Until this is called the aspect ratio is
** kept, except in figures with axes (function plots). */
CF_API cf_status_t cf_figure_set_fit(cf_figure_t *fig, double margin_bp,
                                     bool keep_aspect);
/* The margin (bp) and whether the aspect ratio is kept (automatic: false
** with axes); either output may be NULL.  INVALID_ARG for a NULL fig. */
CF_API cf_status_t cf_figure_get_fit(const cf_figure_t *fig,
                                     double *margin_bp, bool *keep_aspect);
/* What the written page is.  CF_PAGE_FIXED (the default): width x
** height, the drawing at least the margin inside it.  CF_PAGE_INK: the ink
** box of everything drawn (every overlay step together) plus the margin
** on every side, the box TikZ, MetaPost and Asymptote give; the drawing is
** scaled so that this page is at most width x height and reaches one of
** them (both when the aspect ratio is free): width and height then size
** the final box, not a page around it. */
typedef enum cf_page_mode {
    CF_PAGE_FIXED = 0,
    CF_PAGE_INK
} cf_page_mode_t;
CF_API cf_status_t cf_figure_set_page_mode(cf_figure_t *fig,
                                           cf_page_mode_t mode);
/* Where the page is painted with the theme's background colour (the
** colour also of label halos and legend boxes).  CF_BACKGROUND_AUTO (the
** default): in PNG only, which goes to viewers and web pages that show a
** transparent image on grey or black; PDF, SVG, PS, EPS and PGF, which go
** into documents and slides, are transparent, so that a coloured slide
** shows around the ink.  CF_BACKGROUND_ALWAYS: in every format;
** CF_BACKGROUND_NONE: in none (a PNG with an alpha channel). */
typedef enum cf_background {
    CF_BACKGROUND_AUTO = 0,
    CF_BACKGROUND_ALWAYS,
    CF_BACKGROUND_NONE
} cf_background_t;
CF_API cf_status_t cf_figure_set_background(cf_figure_t *fig,
                                            cf_background_t mode);
/* The window and the data -> page map the figure would use now:
** window[4] = xmin xmax ymin ymax; page x = sx * (x - xmin) + ox, page
** y (down) = oy - sy * (y - ymin).  Any output may be NULL. */
CF_API cf_status_t cf_figure_get_window(cf_figure_t *fig, double window[4],
                                        double *sx, double *sy);

/* What is drawn must lie on the page: writing or rendering a figure (not
** cropped with the tight option) whose ink sticks out of its fixed page is
** CF_STATUS_INVALID_ARG, naming the element and by how much (mm and pt),
** and a figure that draws nothing at all is too.  With clip true, ink
** outside the page is cut off instead (default false). */
CF_API cf_status_t cf_figure_set_clip(cf_figure_t *fig, bool clip);

/* Tolerance (bp on the page, > 0, default 0.01) for curves that are fitted
** by cubic segments. */
CF_API cf_status_t cf_figure_set_tolerance(cf_figure_t *fig, double tol_bp);

/* A draft (default false): a quicker drawing for an interactive page while
** the pointer drags (docs/interactive.md, "Drafts").  The caller loosens
** the tolerance; a draft adds that the surfaces' hidden lines, silhouettes
** and scene made for one layout pass serve the later passes within
** CF_FIGURE_DRAFT_SLACK times their tolerance.  Printed figures never are. */
#define CF_FIGURE_DRAFT_SLACK 1.25
CF_API cf_status_t cf_figure_set_draft(cf_figure_t *fig, bool draft);

/* The largest dimension a projection takes. */
#define CF_FIGURE_MAX_DIM 64

/* Projection for points in R^dim, 2 <= dim <= CF_FIGURE_MAX_DIM: matrix m
** is 2 x dim,
** row-major (page x = m[0..dim-1] . p, y = m[dim..2dim-1] . p).  Used by
** cf_figure_project and for curves of dim >= 3.  Default for any dim:
** (x, y) = first two coordinates. */
CF_API cf_status_t cf_figure_set_projection(cf_figure_t *fig, size_t dim,
                                            const double *m);
/* out[2 * n] = projection of n points of dimension dim (stride dim);
** dim == 2 copies.  out may equal in only when dim == 2. */
CF_API cf_status_t cf_figure_project(cf_figure_t *fig, const double *in,
                                     size_t n, size_t dim, double *out);

/* ---- elements (drawn in the order added) -------------------------------- */

/* A Bézier curve (polynomial or rational) of dim 2, or dim >= 3 through
** the projection.  The curve is copied.  dim 1: INVALID_ARG (use
** cf_figure_add_graph).  Role CF_ROLE_CURVE. */
CF_API cf_status_t cf_figure_add_bezier(cf_figure_t *fig, const cf_bezier_t *c,
                                        const cf_style_t *style);

/* Only the arc on [a, b] of the parameter domain [0, 1] (0 <= a < b <= 1),
** e.g. to highlight a part of a curve drawn before. */
CF_API cf_status_t cf_figure_add_bezier_range(cf_figure_t *fig,
                                              const cf_bezier_t *c, double a,
                                              double b,
                                              const cf_style_t *style);

/* The curves of a list (cf_bspline_to_beziers, Ferguson and Coons chains,
** ...) drawn as one path: consecutive items that meet continue the same
** subpath, so joins are joins, not two line caps.  Items of dim >= 3 are
** projected; every item is copied. */
CF_API cf_status_t cf_figure_add_bezier_list(cf_figure_t *fig,
                                             const cf_bezier_list_t *list,
                                             const cf_style_t *style);

/* A chain of cubic segments (cf_bezier_to_cubics, offsets) of dim 2, drawn
** as one path (a jump between segments starts a new subpath). Copied. */
CF_API cf_status_t cf_figure_add_cubics(cf_figure_t *fig,
                                        const cf_cubics_t *cubics,
                                        const cf_style_t *style);

/* A B-spline or NURBS curve (include/curvefig/bspline.h), drawn through its
** Bézier pieces.  a < b restricts it to the parameter range [a, b] (inside
** the domain); a == b (e.g. both 0) draws the whole domain. */
CF_API cf_status_t cf_figure_add_bspline(cf_figure_t *fig,
                                         const struct cf_bspline *s, double a,
                                         double b, const cf_style_t *style);

/* Knot marks: C(u_i) for every distinct knot u_i in the curve's domain,
** drawn as the style's marker (CF_MARKER_TICK: a bar across the curve).
** Role CF_ROLE_KNOTS. */
CF_API cf_status_t cf_figure_add_bspline_knots(cf_figure_t *fig,
                                               const struct cf_bspline *s,
                                               const cf_style_t *style);

/* The distinct knots of s inside its domain, in order (the ones
** cf_figure_add_bspline_knots marks): value u[k], the index first[k] of
** its first copy in the knot vector, its multiplicity mult[k] (copies in
** the whole vector) and the curve point C(u[k]) projected into the plane
** (cf_figure_project) at pts[2k], pts[2k + 1].  Any array may be NULL;
** each needs room for cf_bspline_nknots(s) entries (pts: twice that).
** *count receives the number of distinct knots. */
CF_API cf_status_t cf_figure_bspline_knots(cf_figure_t *fig,
                                           const struct cf_bspline *s,
                                           double *u, size_t *first,
                                           size_t *mult, double *pts,
                                           size_t *count);

/* A tangent arrow: from c(t) to c(t) + scale * c'(t), projected into the
** plane (scale <= 0: 1 / degree, the end legs of a Bézier; 1 for degree
** 0).  tip (may be NULL) receives the arrow's end in the plane, for a
** label.  t outside the domain is CF_STATUS_DOMAIN naming the domain.
** Role CF_ROLE_ARROW. */
CF_API cf_status_t cf_figure_add_bezier_tangent(cf_figure_t *fig,
                                                const cf_bezier_t *c,
                                                double t, double scale,
                                                const cf_style_t *style,
                                                double tip[2]);
CF_API cf_status_t cf_figure_add_bspline_tangent(cf_figure_t *fig,
                                                 const struct cf_bspline *s,
                                                 double t, double scale,
                                                 const cf_style_t *style,
                                                 double tip[2]);

/* Marks at given points; tangents (2 * n doubles, any length, may be NULL)
** orient CF_MARKER_TICK bars across the curve.  Role CF_ROLE_KNOTS. */
CF_API cf_status_t cf_figure_add_knot_marks(cf_figure_t *fig,
                                            const double *pts,
                                            const double *tangents, size_t n,
                                            const cf_style_t *style);

/* A control polygon: n >= 1 points joined by thin lines, a marker at each
** vertex.  Role CF_ROLE_POLYGON. */
CF_API cf_status_t cf_figure_add_polygon(cf_figure_t *fig, const double *pts,
                                         size_t n, const cf_style_t *style);

/* Lines through n >= 2 points (closed: back to the first), no markers
** unless the style sets one.  Role CF_ROLE_POLYLINE. */
CF_API cf_status_t cf_figure_add_polyline(cf_figure_t *fig, const double *pts,
                                          size_t n, bool closed,
                                          const cf_style_t *style);

/* The convex hull of n >= 1 points, filled translucent and outlined.
** Role CF_ROLE_HULL. */
CF_API cf_status_t cf_figure_add_hull(cf_figure_t *fig, const double *pts,
                                      size_t n, const cf_style_t *style);

/* A filled polygon with these n >= 3 vertices as given.  Role CF_ROLE_FILL. */
CF_API cf_status_t cf_figure_add_fill(cf_figure_t *fig, const double *pts,
                                      size_t n, const cf_style_t *style);

/* Point markers.  Role CF_ROLE_POINTS. */
CF_API cf_status_t cf_figure_add_points(cf_figure_t *fig, const double *pts,
                                        size_t n, const cf_style_t *style);

/* An arrow from (x, y) to (x + dx, y + dy) with a head at the end.
** Role CF_ROLE_ARROW. */
CF_API cf_status_t cf_figure_add_arrow(cf_figure_t *fig, double x, double y,
                                       double dx, double dy,
                                       const cf_style_t *style);

/* A label (syntax below) placed at style.place of (x, y), style.offset bp
** away.  Role CF_ROLE_LABEL.  Text is parsed when added (syntax errors are
** reported here, with the byte position).  A figure places at most
** CF_FIGURE_MAX_LABELS labels (each among all the others: the work grows
** faster than their square); more make its rendering fail, saying so. */
#define CF_FIGURE_MAX_LABELS 250
CF_API cf_status_t cf_figure_add_label(cf_figure_t *fig, double x, double y,
                                       const char *text,
                                       const cf_style_t *style);

/* A de Casteljau triangle or de Boor net: level j has counts[j] points,
** stored one level after another in pts (2D).  Each level is drawn as a
** polyline with markers in its own colour: colors[j] if colors != NULL,
** else the theme palette (level 0 in the polygon colour).  The layout of
** cf_bezier_decasteljau (counts n+1, n, ..., 1) fits directly.
** Role CF_ROLE_NET. */
CF_API cf_status_t cf_figure_add_net(cf_figure_t *fig, const double *pts,
                                     const size_t *counts, size_t levels,
                                     const cf_color_t *colors,
                                     const cf_style_t *style);

/* ---- function plots ----------------------------------------------------- */

/* Axes of a function plot.  Initialise with cf_axes_init and fill in. */
typedef struct cf_axes {
    double xmin, xmax, ymin, ymax;   /* ranges (xmin < xmax, ymin < ymax) */
    /* Ticks: explicit positions (xticks, xtick_count > 0) or every
    ** xtick_step from a multiple of it (step > 0), or automatic 1-2-5 steps
    ** (step == 0), or none (step < 0).  Tick labels: xtick_labels[i] (label
    ** syntax) when given, else the number ("%g", minus sign U+2212). */
    const double *xticks;
    size_t xtick_count;
    const char *const *xtick_labels;
    double xtick_step;
    const double *yticks;
    size_t ytick_count;
    const char *const *ytick_labels;
    double ytick_step;
    const char *xlabel;              /* label syntax, at the x axis end */
    const char *ylabel;              /* at the y axis end */
    /* Knots marked on the x axis (a marker on the axis and, if knot_labels
    ** != NULL, a label such as "u_3" below it; a repeated value is marked
    ** once with its labels stacked). */
    const double *knots;
    size_t knot_count;
    const char *const *knot_labels;
    bool arrows;                     /* arrow heads at the axis ends */
    bool grid;                       /* light grid lines at the ticks */
    bool box;                        /* a frame instead of two axes */
} cf_axes_t;

/* Axis lines through 0 (or at the range edge if 0 is outside), step 0,
** arrows true, everything else 0/NULL. */
CF_API void cf_axes_init(cf_axes_t *axes);

/* Axes; their ranges are part of the fitted window.  Strings are copied.
** Role CF_ROLE_AXES. */
CF_API cf_status_t cf_figure_add_axes(cf_figure_t *fig, const cf_axes_t *axes,
                                      const cf_style_t *style);

/* The graph of a piecewise polynomial function, exact: piece i is a
** dim-1 polynomial Bézier (Bernstein coefficients = its control values)
** on [0, 1], drawn over x in [breaks[i], breaks[i + 1]] (breaks
** non-decreasing; empty pieces skipped; jumps start a new subpath).
** Degree <= 3 pieces become one exact cubic segment each; higher degrees
** are fitted within the tolerance.  count >= 1.  Role CF_ROLE_GRAPH.
** B-spline basis functions: the Bézier pieces of a 1D spline with control
** values e_i; Bernstein B_i^n: one piece with coefficients e_i. */
CF_API cf_status_t cf_figure_add_graph(cf_figure_t *fig,
                                       const cf_bezier_t *const *pieces,
                                       const double *breaks, size_t count,
                                       const cf_style_t *style);

/* The same from a list with t0/t1 ranges (cf_bspline to_beziers of a 1D
** spline): piece i over [t0[i], t1[i]]. */
CF_API cf_status_t cf_figure_add_graph_list(cf_figure_t *fig,
                                            const cf_bezier_list_t *list,
                                            const cf_style_t *style);

/* The graph of the B-spline basis function N_i^p over the knots
** u_0 .. u_{nknots-1} (non-decreasing, finite, u_0 < u_{nknots-1}; any
** length >= i + p + 2), drawn over the whole range [u_0, u_{nknots-1}]:
** zero outside [u_i, u_{i+p+1}], exact (its polynomial pieces become graph
** pieces as in cf_figure_add_graph).  0 <= p <= CF_BSPLINE_MAX_DEGREE.
** Errors name the knot: "basis: knot 4 (0.3) is smaller than knot 3
** (0.5)".  Role CF_ROLE_GRAPH. */
CF_API cf_status_t cf_figure_add_basis(cf_figure_t *fig, const double *knots,
                                       size_t nknots, int i, int p,
                                       const cf_style_t *style);

/* The graph of y = f(x) on [a, b] (a < b) for any function: sampled now
** (f is not kept), fitted by cubic Hermite segments with derivatives from
** differences, subdividing until the midpoint error is below 2e-5 of the
** graph's range (at most 4096 segments).  f returns 0, or non-zero to stop
** (INVALID_ARG).  Non-finite values: NOT_FINITE.  Role CF_ROLE_GRAPH. */
typedef int (*cf_function_t)(void *closure, double x, double *y);
CF_API cf_status_t cf_figure_add_function(cf_figure_t *fig, cf_function_t f,
                                          void *closure, double a, double b,
                                          const cf_style_t *style);

#ifdef __cplusplus
}
#endif

#endif
