/*
** curvefig figures in three dimensions: a view and surfaces drawn as
** exact lines (library curvefig-render).
**
** The view is a cf_view_t of curvefig/view.h (azimuth, elevation,
** an orthographic or a perspective projection; its conventions are
** there).  A parallel projection of a polynomial Bézier or B-spline curve
** is one of the same degree; a perspective one is the rational curve of
** the same degree whose homogeneous control points are the images of the
** curve's: both are drawn exactly as the figure draws any plane curve
** (cubic segments within the figure's tolerance, never a polyline).
** Points, polygons, labels, arrows and curves given in R^3 are projected
** by the view; curves, polylines, polygons, points, labels, arrows and
** filled regions added with the functions below are also split or hidden
** by the figure's surfaces.
**
** A point at or behind the eye cannot be drawn: the element that holds it
** fails with CF_STATUS_DOMAIN, naming the point and a distance that would
** show it.
*/
#ifndef CURVEFIG_FIGURE3D_H
#define CURVEFIG_FIGURE3D_H

#include "curvefig/figure.h"
#include "curvefig/surface-triangle.h"
#include "curvefig/surface.h"
#include "curvefig/view.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Set the view of a figure of points in R^3 (made with
** cf_view_orthographic or cf_view_perspective): it replaces any
** projection set with cf_figure_set_projection (and that one replaces the
** view). */
CF_API cf_status_t cf_figure_set_view(cf_figure_t *fig, const cf_view_t *view);

/* The figure's view; false (and *out untouched) when it has none. */
CF_API bool cf_figure_get_view(const cf_figure_t *fig, cf_view_t *out);

/* The 3 x 4 matrix (row-major) of the view's projection in homogeneous
** coordinates: (X, Y, W) = M (x, y, z, 1), the image (X / W, Y / W), with
** W = 1 for an orthographic view and W = (D - z) / D for a perspective
** one (so that a curve's weights stay near its own). */
CF_API void cf_view_matrix(const cf_view_t *view, double m[12]);

/* ---- surfaces ----------------------------------------------------------- */

/* What happens to the part of a line that lies behind a surface. */
typedef enum cf_hidden {
    CF_HIDDEN_SHOW = 0,     /* drawn as if nothing hid it */
    CF_HIDDEN_DASHED,       /* drawn dashed and thinner */
    CF_HIDDEN_REMOVE        /* left out */
} cf_hidden_t;

/* Shading of a surface: its facets (cf_scene_facets_tol, within 2.5 bp
** of the surface on the page) painted back to front under every line of
** the figure, each in the front or back colour (the side facing the
** viewer is the normal side Su x Sv: front) lit by a distant light:
** colour * (0.35 + 0.65 |n . L|), n the facet's plane's normal (flat), or
** (smooth) each facet cut in four at its edges' midpoints and each piece
** lit by the surface's normals interpolated at its centroid; L the light
** direction (default: from the upper left, in front of the viewer:
** d + 0.6 ey - 0.4 ex normalised).  Each piece is also stroked with a
** hairline of its own colour so no seam shows (not when opacity < 1).
** PDF mesh gradients are not written. */
typedef enum cf_shade {
    CF_SHADE_NONE = 0,
    CF_SHADE_FLAT,
    CF_SHADE_SMOOTH
} cf_shade_t;

typedef struct cf_surface_shading {
    cf_shade_t shade;
    cf_color_t front, back;
    double opacity;             /* 0..1 */
    bool has_light;
    double light[3];            /* towards the light, any length > 0 */
} cf_surface_shading_t;

/* The lines of a surface that one call draws, all in one style. */
typedef struct cf_surface_lines {
    bool boundary;           /* the four boundary curves */
    bool silhouette;         /* the contour where the normal is
                                perpendicular to the line of sight */
    size_t nu, nv;           /* evenly spaced interior iso-lines: nu of
                                u = const, nv of v = const */
    const double *u_values;  /* or these parameters (inside the domain) */
    size_t u_count;
    const double *v_values;
    size_t v_count;
    bool knot_lines;         /* the iso-lines at the interior knots */
    bool net;                /* the control net (rows and columns) */
    bool occludes;           /* the surface hides what lies behind it (set
                                it on one call per surface) */
    cf_hidden_t hidden;
    cf_style_t iso_style;    /* iso- and knot lines: over the theme's curve
                                style at half its width */
    cf_style_t net_style;    /* the net: over the theme's polygon style */
    cf_surface_shading_t shading;   /* shade NONE: not shaded (needs
                                       occludes) */
} cf_surface_lines_t;

/* Boundary and silhouette, hidden lines removed, occluding, no style
** overrides. */
CF_API void cf_surface_lines_init(cf_surface_lines_t *lines);

/* Draw lines of a surface in R^3 (copied) in a figure with a view.  Every
** line is an exact curve (iso-curve, boundary, silhouette) projected
** exactly, split where it passes behind an occluding surface of the figure
** (cf_scene_curve_visibility, to 20 times the figure's fitting tolerance on
** the page); the visible pieces take the style (iso- and knot lines
** iso_style, the net net_style), the hidden ones are drawn as
** lines->hidden says (dashed: the same colour, 0.7 of the width, dashes of
** 4 and 3 widths).  Net vertices are marked with the net style's marker,
** faded (dashed) or left out (remove) when hidden.  Errors name what is
** wrong: a surface not in R^3, a figure without a view, an iso-line
** parameter outside the domain ("isolines: u = 1.5 is outside the domain
** [0, 1]"), a degenerate patch (its points on one line); when drawn, a
** surface that lies wholly outside an explicit window.  Role
** CF_ROLE_CURVE. */
CF_API cf_status_t cf_figure_add_surface(cf_figure_t *fig,
                                         const struct cf_bspline_surface *s,
                                         const cf_surface_lines_t *lines,
                                         const cf_style_t *style);

/* Curves in R^3 (copied) in a figure with a view, split by the figure's
** occluding surfaces as the surfaces' lines are, the hidden pieces drawn
** as hidden says; they hide nothing themselves.  Role CF_ROLE_CURVE. */
CF_API cf_status_t cf_figure_add_space_curves(cf_figure_t *fig,
                                              const cf_bezier_list_t *list,
                                              cf_hidden_t hidden,
                                              const cf_style_t *style);

/*
** Polylines, control polygons, points and labels in R^3 (copied) in a
** figure with a view, split by the figure's occluding surfaces: each
** segment is a straight line in space (a curve of degree 1) split where it
** passes behind a surface as the surfaces' lines are (to 20 times the
** fitting tolerance on the page), each vertex, point and label anchor is
** seen or hidden (cf_scene_point_visible).  Hidden pieces of lines are
** drawn as hidden says (dashed: the same colour, 0.7 of the width, dashes
** of 4 and 3 widths; remove: left out; show: as visible ones); hidden
** markers and labels are faded to 0.4 of their opacity (dashed), left out
** (remove) or drawn alike (show).  They hide nothing themselves.  Errors:
** a figure without a view, fewer points than needed, a point not finite
** or at or behind the eye (naming it).  Roles: CF_ROLE_POLYLINE,
** CF_ROLE_POLYGON, CF_ROLE_POINTS, CF_ROLE_LABEL.
*/
CF_API cf_status_t cf_figure_add_space_polyline(cf_figure_t *fig,
                                                const double *pts, size_t n,
                                                bool closed,
                                                cf_hidden_t hidden,
                                                const cf_style_t *style);
CF_API cf_status_t cf_figure_add_space_polygon(cf_figure_t *fig,
                                               const double *pts, size_t n,
                                               cf_hidden_t hidden,
                                               const cf_style_t *style);
CF_API cf_status_t cf_figure_add_space_points(cf_figure_t *fig,
                                              const double *pts, size_t n,
                                              cf_hidden_t hidden,
                                              const cf_style_t *style);
CF_API cf_status_t cf_figure_add_space_label(cf_figure_t *fig,
                                             const double *p,
                                             const char *text,
                                             cf_hidden_t hidden,
                                             const cf_style_t *style);
/* An arrow from p to q in R^3: its shaft a segment split as above, its
** head at the image of q drawn when q is seen and, when q is hidden, as a
** hidden marker is (faded, left out or drawn).  Role CF_ROLE_ARROW. */
CF_API cf_status_t cf_figure_add_space_arrow(cf_figure_t *fig,
                                             const double *p,
                                             const double *q,
                                             cf_hidden_t hidden,
                                             const cf_style_t *style);

/*
** Filled regions in R^3 (copied) in a figure with a view: a filled polygon
** (n >= 3 points; its plane's triangles, ear-clipped; a polygon not in one
** plane is triangulated in the plane of its Newell normal, a polygon that
** crosses itself is the fan of its first vertex under the nonzero rule)
** and a convex hull (n >= 1; the faces of the 3D hull that face the
** viewer, which cover the hull's image once; points in one plane: their
** hull in it; on one line: the segment, its outline only).  When drawn,
** the part of the region that the figure's occluding surfaces hide is
** found on a grid of cells at most 8 times the visibility tolerance long
** on the page (1.6 bp by default; each grid point asked with
** cf_scene_point_visible), a cell whose corners differ cut straight
** between the points where its edges change (bisected to half the
** tolerance): the seen part is filled in the style's fill at its opacity,
** the hidden part at 0.4 of it (dashed), left out (remove) or filled alike
** (show).  The outline (the polygon; a hull's outline in the image) is a
** polygon in space split as cf_figure_add_space_polygon's, stroked when
** the style's colour and width are.  A region hides nothing itself.  It
** is painted where it comes among the elements: added before a shaded
** surface, it lies under that surface's shading, and the figure warns
** (cf_figure_warnings, naming it and its line).
** Errors: a figure without a view, too few points, a point not finite or
** at or behind the eye, a filled polygon whose points lie on one line.
** Roles CF_ROLE_FILL and CF_ROLE_HULL.
*/
CF_API cf_status_t cf_figure_add_space_fill(cf_figure_t *fig,
                                            const double *pts, size_t n,
                                            cf_hidden_t hidden,
                                            const cf_style_t *style);
CF_API cf_status_t cf_figure_add_space_hull(cf_figure_t *fig,
                                            const double *pts, size_t n,
                                            cf_hidden_t hidden,
                                            const cf_style_t *style);

/* The line of the script that added element i (counted from 0), which
** the figure's warnings about it name (0: unknown, the default). */
CF_API void cf_figure_set_element_line(cf_figure_t *fig, size_t i, int line);

/* The same for a triangular Bézier patch in R^3: its three edges
** (boundary), iso-lines of u, v and w (nu of u and of w, nv of v evenly
** spaced; u_values and v_values), its net; knot_lines has no meaning. */
CF_API cf_status_t cf_figure_add_triangle_surface(
    cf_figure_t *fig, const cf_bezier_triangle_t *t,
    const cf_surface_lines_t *lines, const cf_style_t *style);

#ifdef __cplusplus
}
#endif

#endif
