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
** Labels use a small TeX-like syntax (see "Labels" below).
*/
#ifndef CURVEFIG_FIGURE_H
#define CURVEFIG_FIGURE_H

#include "curvefig/core.h"
#include "curvefig/bezier.h"

#ifdef __cplusplus
extern "C" {
#endif

struct cf_bspline;   /* include/curvefig/bspline.h */

typedef struct cf_figure cf_figure_t;

/* ---- units -------------------------------------------------------------- */

typedef enum cf_unit {
    CF_UNIT_BP = 0,   /* PostScript/PDF point, 1/72 in (cairo's unit) */
    CF_UNIT_PT = 0,   /* "pt" means bp here, as in cairo and SVG */
    CF_UNIT_TEXPT,    /* TeX point, 1/72.27 in */
    CF_UNIT_MM,
    CF_UNIT_CM,
    CF_UNIT_IN,
    CF_UNIT_LAST_
} cf_unit_t;

/* value * (size of one unit in bp).  TeX points: 10 -> 9.9626. */
double cf_length_to_bp(double value, cf_unit_t unit);

/* "bp", "pt", "texpt", "mm", "cm", "in" -> unit; INVALID_ARG otherwise. */
cf_status_t cf_unit_from_name(const char *name, cf_unit_t *out,
                              cf_diag_t *diag);

/* ---- colours and styles ------------------------------------------------- */

typedef struct cf_color {
    double r, g, b, a;   /* 0..1 each; a = 0 is transparent (nothing drawn) */
} cf_color_t;

/* "#rrggbb", "#rrggbbaa", "none", or a name: black white grey gray red
** green blue orange yellow purple brown cyan magenta darkblue darkred
** darkgreen lightgrey.  INVALID_ARG otherwise. */
cf_status_t cf_color_parse(const char *text, cf_color_t *out,
                           cf_diag_t *diag);

typedef enum cf_marker {
    CF_MARKER_NONE = 0,
    CF_MARKER_DOT,        /* filled disc */
    CF_MARKER_CIRCLE,     /* ring (filled with the style's fill colour) */
    CF_MARKER_SQUARE,
    CF_MARKER_DIAMOND,
    CF_MARKER_TRIANGLE,
    CF_MARKER_CROSS,      /* x */
    CF_MARKER_PLUS,       /* + */
    CF_MARKER_STAR,       /* filled five-pointed star */
    CF_MARKER_TICK,       /* short bar across the curve (knot marks) */
    CF_MARKER_LAST_
} cf_marker_t;

/* "none" "dot" "circle" "square" "diamond" "triangle" "cross" "plus"
** "star" "tick". */
cf_status_t cf_marker_from_name(const char *name, cf_marker_t *out,
                                cf_diag_t *diag);

/* Where a label goes relative to its anchor point. */
typedef enum cf_place {
    CF_PLACE_CENTER = 0,  /* centred on the point */
    CF_PLACE_N,           /* above */
    CF_PLACE_NE,
    CF_PLACE_E,           /* to the right, vertically centred */
    CF_PLACE_SE,
    CF_PLACE_S,
    CF_PLACE_SW,
    CF_PLACE_W,
    CF_PLACE_NW,
    CF_PLACE_AUTO,        /* the one of the eight places above whose box
                             (plus 1 bp) covers the least of what is
                             drawn (lines, markers, other labels, the page
                             edge), ties and near-ties in the order ne, nw,
                             se, sw, n, s, e, w; chosen at drawing time */
    CF_PLACE_LAST_
} cf_place_t;

/* "center" "n" "ne" "e" "se" "s" "sw" "w" "nw" "auto" (also "above",
** "below", "left", "right"). */
cf_status_t cf_place_from_name(const char *name, cf_place_t *out,
                               cf_diag_t *diag);

#define CF_STYLE_DASH_MAX 8

/* Bits of cf_style_t.set: a field is used only if its bit is set;
** otherwise the theme's value for the element's role applies. */
enum {
    CF_STYLE_COLOR       = 1u << 0,
    CF_STYLE_FILL        = 1u << 1,
    CF_STYLE_WIDTH       = 1u << 2,
    CF_STYLE_DASH        = 1u << 3,
    CF_STYLE_OPACITY     = 1u << 4,
    CF_STYLE_MARKER      = 1u << 5,
    CF_STYLE_MARKER_SIZE = 1u << 6,
    CF_STYLE_FONT_SIZE   = 1u << 7,
    CF_STYLE_PLACE       = 1u << 8,
    CF_STYLE_OFFSET      = 1u << 9,
    CF_STYLE_ARROW_SIZE  = 1u << 10,
    CF_STYLE_MARKER_COLOR = 1u << 11,
    CF_STYLE_HALO        = 1u << 12,
    CF_STYLE_ALL_        = (1u << 13) - 1
};

/* Per-element overrides (and, fully set, the theme's style of a role).
** NULL wherever a `const cf_style_t *` is taken means "theme only". */
typedef struct cf_style {
    unsigned set;                   /* CF_STYLE_* bits of the given fields */
    cf_color_t color;               /* stroke and text colour */
    cf_color_t fill;                /* fill of hulls, fills, marker interiors */
    double width;                   /* line width, bp (> 0) */
    double dash[CF_STYLE_DASH_MAX]; /* on/off lengths, bp */
    size_t dash_count;              /* 0 = solid */
    double opacity;                 /* 0..1, multiplies every alpha */
    cf_marker_t marker;             /* vertex marker of polygons, points */
    double marker_size;             /* marker diameter, bp */
    cf_color_t marker_color;        /* marker outline / dot colour */
    double font_size;               /* label size, bp */
    cf_place_t place;               /* label side of the anchor point */
    double offset;                  /* gap between point and label, bp */
    double arrow_size;              /* arrow head length, bp (0: none) */
    double halo;                    /* labels: a border of this width (bp)
                                       in the background colour around
                                       the glyphs, so that a label over a
                                       line stays legible (0: none) */
} cf_style_t;

/* set = 0 (nothing overridden), other fields zero. */
void cf_style_init(cf_style_t *style);

/* ---- themes ------------------------------------------------------------- */

/* The theme holds one complete style per role; an element takes its
** role's style and applies its own overrides. */
typedef enum cf_role {
    CF_ROLE_CURVE = 0,  /* Bézier, B-spline and cubic curves: thick, dark */
    CF_ROLE_POLYGON,    /* control polygons: thin grey, filled dots */
    CF_ROLE_POLYLINE,   /* plain lines, no markers */
    CF_ROLE_POINTS,     /* point markers */
    CF_ROLE_HULL,       /* convex hulls: translucent fill, thin outline */
    CF_ROLE_FILL,       /* filled polygons as given */
    CF_ROLE_LABEL,      /* labels */
    CF_ROLE_ARROW,      /* vectors: tangents, normals, translations */
    CF_ROLE_KNOTS,      /* knot marks on curves */
    CF_ROLE_AXES,       /* axes, ticks, tick labels (font_size) */
    CF_ROLE_GRAPH,      /* function graphs on axes */
    CF_ROLE_NET,        /* de Casteljau / de Boor nets (colour per level
                           from the palette; width, marker, sizes here) */
    CF_ROLE_LAST_
} cf_role_t;

#define CF_PALETTE_MAX 12
#define CF_FONT_FAMILY_MAX 160

typedef struct cf_theme {
    cf_style_t role[CF_ROLE_LAST_];       /* all fields set */
    cf_color_t palette[CF_PALETTE_MAX];   /* net levels, several graphs */
    size_t palette_size;
    cf_color_t background;                /* painted under everything in
                                             every format; a = 0: none */
    /* Pango family list (comma-separated fallbacks, no style words):
    ** default "Latin Modern Roman,CMU Serif,Noto Serif CJK SC". */
    char font_family[CF_FONT_FAMILY_MAX];
    double tick_size;                     /* axis tick length, bp */
} cf_theme_t;

/* Built-in themes: "default" (colour, legible in print, on a projector
** and in greyscale) and "mono" (black and greys only).  INVALID_ARG for
** another name. */
cf_status_t cf_theme_get(const char *name, cf_theme_t *out, cf_diag_t *diag);

/* ---- figure ------------------------------------------------------------- */

/* A figure of width x height (> 0, finite) in the given unit.  *out is
** NULL on failure. */
cf_status_t cf_figure_create(double width, double height, cf_unit_t unit,
                             cf_figure_t **out, cf_diag_t *diag);
void cf_figure_destroy(cf_figure_t *fig);

/* The figure's first error (CF_STATUS_OK if none); fills diag (if not
** NULL) with its message.  NULL fig: INVALID_ARG. */
cf_status_t cf_figure_status(const cf_figure_t *fig, cf_diag_t *diag);

/* Page size in bp (before any tight cropping). */
void cf_figure_get_size(const cf_figure_t *fig, double *width_bp,
                        double *height_bp);

/* Title and description: SVG <title>/<desc>, PDF Title/Subject metadata.
** UTF-8, copied.  NULL clears. */
cf_status_t cf_figure_set_title(cf_figure_t *fig, const char *title);
cf_status_t cf_figure_set_caption(cf_figure_t *fig, const char *caption);

/* Copy a theme into the figure (default: cf_theme_get("default")).
** Applies to all elements, including ones already added. */
cf_status_t cf_figure_set_theme(cf_figure_t *fig, const cf_theme_t *theme);
/* The figure's current theme (to modify and set back). */
void cf_figure_get_theme(const cf_figure_t *fig, cf_theme_t *out);

/* Explicit data window (xmin < xmax, ymin < ymax).  With keep_aspect
** (cf_figure_set_fit) the window is enlarged symmetrically so that one data
** unit has the same length on both axes; otherwise it fills the page
** inside the margin.  Curves, polylines, polygons, hulls, fills and nets
** are clipped to the window widened by their line width (a line on the
** window's edge stays whole); points, knot marks, polygon and net
** vertices and labels anchored outside the window are left out; arrows
** and axes are drawn whole.  Only what remains is given room (a close-up
** of a larger drawing keeps its scale). */
cf_status_t cf_figure_set_window(cf_figure_t *fig, double xmin, double xmax,
                                 double ymin, double ymax);
/* Go back to a window fitted to what is drawn (the default): the tight
** box of curves (not of their control points, unless those are drawn too),
** polygon vertices, points, arrow ends, label anchors, axes ranges. */
cf_status_t cf_figure_set_window_auto(cf_figure_t *fig);
/* Fitting: the window is scaled so that everything drawn, including what
** sticks out of it (labels, markers, arrow heads, line widths), lies at
** least margin_bp (>= 0, default 4) inside the page edges.  keep_aspect:
** equal scales on both axes.  Until this is called the aspect ratio is
** kept, except in figures with axes (function plots). */
cf_status_t cf_figure_set_fit(cf_figure_t *fig, double margin_bp,
                              bool keep_aspect);
/* The window and the data -> page map the figure would use now:
** window[4] = xmin xmax ymin ymax; page x = sx * (x - xmin) + ox, page
** y (down) = oy - sy * (y - ymin).  Any output may be NULL. */
cf_status_t cf_figure_get_window(cf_figure_t *fig, double window[4],
                                 double *sx, double *sy);

/* Tolerance (bp on the page, > 0, default 0.01) for curves that are fitted
** by cubic segments. */
cf_status_t cf_figure_set_tolerance(cf_figure_t *fig, double tol_bp);

/* Projection for points in R^dim, dim >= 2: matrix m is 2 x dim,
** row-major (page x = m[0..dim-1] . p, y = m[dim..2dim-1] . p).  Used by
** cf_figure_project and for curves of dim >= 3.  Default for any dim:
** (x, y) = first two coordinates. */
cf_status_t cf_figure_set_projection(cf_figure_t *fig, size_t dim,
                                     const double *m);
/* out[2 * n] = projection of n points of dimension dim (stride dim);
** dim == 2 copies.  out may equal in only when dim == 2. */
cf_status_t cf_figure_project(cf_figure_t *fig, const double *in, size_t n,
                              size_t dim, double *out);

/* ---- elements (drawn in the order added) -------------------------------- */

/* A Bézier curve (polynomial or rational) of dim 2, or dim >= 3 through
** the projection.  The curve is copied.  dim 1: INVALID_ARG (use
** cf_figure_add_graph).  Role CF_ROLE_CURVE. */
cf_status_t cf_figure_add_bezier(cf_figure_t *fig, const cf_bezier_t *c,
                                 const cf_style_t *style);

/* Only the arc on [a, b] of the parameter domain [0, 1] (0 <= a < b <= 1),
** e.g. to highlight a part of a curve drawn before. */
cf_status_t cf_figure_add_bezier_range(cf_figure_t *fig,
                                       const cf_bezier_t *c, double a,
                                       double b, const cf_style_t *style);

/* The curves of a list (cf_bspline_to_beziers, Ferguson and Coons chains,
** ...) drawn as one path: consecutive items that meet continue the same
** subpath, so joins are joins, not two line caps.  Items of dim >= 3 are
** projected; every item is copied. */
cf_status_t cf_figure_add_bezier_list(cf_figure_t *fig,
                                      const cf_bezier_list_t *list,
                                      const cf_style_t *style);

/* A chain of cubic segments (cf_bezier_to_cubics, offsets) of dim 2, drawn
** as one path (a jump between segments starts a new subpath). Copied. */
cf_status_t cf_figure_add_cubics(cf_figure_t *fig, const cf_cubics_t *cubics,
                                 const cf_style_t *style);

/* A B-spline or NURBS curve (include/curvefig/bspline.h), drawn through its
** Bézier pieces.  a < b restricts it to the parameter range [a, b] (inside
** the domain); a == b (e.g. both 0) draws the whole domain. */
cf_status_t cf_figure_add_bspline(cf_figure_t *fig,
                                  const struct cf_bspline *s, double a,
                                  double b, const cf_style_t *style);

/* Knot marks: C(u_i) for every distinct knot u_i in the curve's domain,
** drawn as the style's marker (CF_MARKER_TICK: a bar across the curve).
** Role CF_ROLE_KNOTS. */
cf_status_t cf_figure_add_bspline_knots(cf_figure_t *fig,
                                        const struct cf_bspline *s,
                                        const cf_style_t *style);

/* Marks at given points; tangents (2 * n doubles, any length, may be NULL)
** orient CF_MARKER_TICK bars across the curve.  Role CF_ROLE_KNOTS. */
cf_status_t cf_figure_add_knot_marks(cf_figure_t *fig, const double *pts,
                                     const double *tangents, size_t n,
                                     const cf_style_t *style);

/* A control polygon: n >= 1 points joined by thin lines, a marker at each
** vertex.  Role CF_ROLE_POLYGON. */
cf_status_t cf_figure_add_polygon(cf_figure_t *fig, const double *pts,
                                  size_t n, const cf_style_t *style);

/* Lines through n >= 2 points (closed: back to the first), no markers
** unless the style sets one.  Role CF_ROLE_POLYLINE. */
cf_status_t cf_figure_add_polyline(cf_figure_t *fig, const double *pts,
                                   size_t n, bool closed,
                                   const cf_style_t *style);

/* The convex hull of n >= 1 points, filled translucent and outlined.
** Role CF_ROLE_HULL. */
cf_status_t cf_figure_add_hull(cf_figure_t *fig, const double *pts,
                               size_t n, const cf_style_t *style);

/* A filled polygon with these n >= 3 vertices as given.  Role CF_ROLE_FILL. */
cf_status_t cf_figure_add_fill(cf_figure_t *fig, const double *pts,
                               size_t n, const cf_style_t *style);

/* Point markers.  Role CF_ROLE_POINTS. */
cf_status_t cf_figure_add_points(cf_figure_t *fig, const double *pts,
                                 size_t n, const cf_style_t *style);

/* An arrow from (x, y) to (x + dx, y + dy) with a head at the end.
** Role CF_ROLE_ARROW. */
cf_status_t cf_figure_add_arrow(cf_figure_t *fig, double x, double y,
                                double dx, double dy,
                                const cf_style_t *style);

/* A label (syntax below) placed at style.place of (x, y), style.offset bp
** away.  Role CF_ROLE_LABEL.  Text is parsed when added (syntax errors are
** reported here, with the byte position). */
cf_status_t cf_figure_add_label(cf_figure_t *fig, double x, double y,
                                const char *text, const cf_style_t *style);

/* A de Casteljau triangle or de Boor net: level j has counts[j] points,
** stored one level after another in pts (2D).  Each level is drawn as a
** polyline with markers in its own colour: colors[j] if colors != NULL,
** else the theme palette (level 0 in the polygon colour).  The layout of
** cf_bezier_decasteljau (counts n+1, n, ..., 1) fits directly.
** Role CF_ROLE_NET. */
cf_status_t cf_figure_add_net(cf_figure_t *fig, const double *pts,
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
void cf_axes_init(cf_axes_t *axes);

/* Axes; their ranges are part of the fitted window.  Strings are copied.
** Role CF_ROLE_AXES. */
cf_status_t cf_figure_add_axes(cf_figure_t *fig, const cf_axes_t *axes,
                               const cf_style_t *style);

/* The graph of a piecewise polynomial function, exact: piece i is a
** dim-1 polynomial Bézier (Bernstein coefficients = its control values)
** on [0, 1], drawn over x in [breaks[i], breaks[i + 1]] (breaks
** non-decreasing; empty pieces skipped; jumps start a new subpath).
** Degree <= 3 pieces become one exact cubic segment each; higher degrees
** are fitted within the tolerance.  count >= 1.  Role CF_ROLE_GRAPH.
** B-spline basis functions: the Bézier pieces of a 1D spline with control
** values e_i; Bernstein B_i^n: one piece with coefficients e_i. */
cf_status_t cf_figure_add_graph(cf_figure_t *fig,
                                const cf_bezier_t *const *pieces,
                                const double *breaks, size_t count,
                                const cf_style_t *style);

/* The same from a list with t0/t1 ranges (cf_bspline to_beziers of a 1D
** spline): piece i over [t0[i], t1[i]]. */
cf_status_t cf_figure_add_graph_list(cf_figure_t *fig,
                                     const cf_bezier_list_t *list,
                                     const cf_style_t *style);

/* The graph of the B-spline basis function N_i^p over the knots
** u_0 .. u_{nknots-1} (non-decreasing, finite, u_0 < u_{nknots-1}; any
** length >= i + p + 2), drawn over the whole range [u_0, u_{nknots-1}]:
** zero outside [u_i, u_{i+p+1}], exact (its polynomial pieces become graph
** pieces as in cf_figure_add_graph).  0 <= p <= CF_BSPLINE_MAX_DEGREE.
** Errors name the knot: "basis: knot 4 (0.3) is smaller than knot 3
** (0.5)".  Role CF_ROLE_GRAPH. */
cf_status_t cf_figure_add_basis(cf_figure_t *fig, const double *knots,
                                size_t nknots, int i, int p,
                                const cf_style_t *style);

/* The graph of y = f(x) on [a, b] (a < b) for any function: sampled now
** (f is not kept), fitted by cubic Hermite segments with derivatives from
** differences, subdividing until the midpoint error is below 2e-5 of the
** graph's range (at most 4096 segments).  f returns 0, or non-zero to stop
** (INVALID_ARG).  Non-finite values: NOT_FINITE.  Role CF_ROLE_GRAPH. */
typedef int (*cf_function_t)(void *closure, double x, double *y);
cf_status_t cf_figure_add_function(cf_figure_t *fig, cf_function_t f,
                                   void *closure, double a, double b,
                                   const cf_style_t *style);

/* ---- output ------------------------------------------------------------- */

typedef enum cf_format {
    CF_FORMAT_SVG = 0,
    CF_FORMAT_PDF,
    CF_FORMAT_PS,
    CF_FORMAT_EPS,
    CF_FORMAT_PNG,
    CF_FORMAT_LAST_
} cf_format_t;

#define CF_FORMAT_BIT(f) (1u << (f))

/* "svg" "pdf" "ps" "eps" "png" -> format; INVALID_ARG otherwise. */
cf_status_t cf_format_from_name(const char *name, cf_format_t *out,
                                cf_diag_t *diag);
/* "svg", ... ("" for an invalid value). */
const char *cf_format_extension(cf_format_t format);

typedef struct cf_write_options {
    double dpi;       /* PNG resolution, default 150, range [1, 2400] */
    bool tight;       /* crop the page to the ink box (strokes and labels
                         included) plus padding; default false */
    double padding;   /* bp around the ink box when tight, default 0 */
} cf_write_options_t;

void cf_write_options_init(cf_write_options_t *options);

/* Write the figure to path in one format (options NULL: defaults).  The
** file is written to a temporary name in the same directory and renamed:
** on failure the old file is left as it was (or none is made).  Output is
** deterministic: PDF CreationDate from SOURCE_DATE_EPOCH or none, no PS
** %%CreationDate, SVG ids numbered per file, SVG units in pt, SVG
** <title>/<desc> from the title and caption. */
cf_status_t cf_figure_write(cf_figure_t *fig, const char *path,
                            cf_format_t format,
                            const cf_write_options_t *options,
                            cf_diag_t *diag);

/* Write basename.<ext> for every format whose CF_FORMAT_BIT is in
** formats; stops at the first failure. */
cf_status_t cf_figure_write_all(cf_figure_t *fig, const char *basename,
                                unsigned formats,
                                const cf_write_options_t *options,
                                cf_diag_t *diag);

/* Render to memory: *data (release with cf_free) and *size. */
cf_status_t cf_figure_render(cf_figure_t *fig, cf_format_t format,
                             const cf_write_options_t *options,
                             unsigned char **data, size_t *size,
                             cf_diag_t *diag);

/* The ink box of everything drawn, in page bp (x0 y0 x1 y1, y down) at the
** physical size, and the page size the options give (tight or not). */
cf_status_t cf_figure_ink_box(cf_figure_t *fig,
                              const cf_write_options_t *options,
                              double box[4], double *page_width,
                              double *page_height, cf_diag_t *diag);

/* ---- labels ------------------------------------------------------------- */

/*
** Label syntax.  A text without `$` is all math; with `$`, text outside
** $...$ is upright text and inside is math.
**   math: ASCII letters italic; digits, punctuation, ( ) [ ] upright;
**         `-` becomes the minus sign U+2212; + − = < > get thin spaces
**         around them at the base level; spaces are kept, except next
**         to such operators (TeX's spacing applies there).
**   x_i  x_{...}  subscript; x^n  x^{...}  superscript; both (any order)
**         stack at the same x: B_i^n, N_{i}^{p}; scripts nest (size 70 %,
**         then 50 %; Latin Modern's 7 pt and 5 pt designs are used for
**         them, as in TeX).  ' is a prime (U+2032).
**   \alpha ... \omega, \Gamma ... \Omega (also \varepsilon \vartheta
**         \varphi \varrho \varsigma): lowercase italic, uppercase upright.
**   \cdot \times \infty \partial \nabla \pm \leq \geq \neq \to \ldots
**         \dots \sum \prod \int, \, \; \quad spaces, \{ \} \_ \$ \\ escapes.
**   \mathrm{...} \text{...} upright; \mathbf{...} bold; \mathit{...}.
**   \frac{num}{den} (script size, centred, rule on the math axis);
**   \hat \bar \tilde \vec \dot \ddot over one character.
**   Any UTF-8 text (Czech, Russian, Slovene, Chinese): letters outside
**   ASCII are set upright; the family list supplies Cyrillic and CJK.
** Errors (unbalanced braces, unknown command, dangling _ or ^, invalid
** UTF-8) are INVALID_ARG with the byte position in diag->index.
*/

/* One run of glyphs of a laid-out label. */
typedef enum cf_label_kind {
    CF_LABEL_BASE = 0,  /* at the level's baseline */
    CF_LABEL_SUB,       /* a subscript run */
    CF_LABEL_SUP        /* a superscript run */
} cf_label_kind_t;

typedef struct cf_label_box {
    double x, y;             /* left end of the run's baseline, bp, relative
                                to the label origin; y UP */
    double width;            /* advance width, bp */
    double ascent, descent;  /* logical extents above/below the baseline
                                (descent positive) */
    double size;             /* font size, bp */
    int level;               /* 0 base, 1 script, 2 scriptscript */
    cf_label_kind_t kind;    /* innermost script kind of the run */
    bool italic;
    size_t start, end;       /* 0 and the byte length of the run's text
                                (cf_label_run_text; "" for a fraction
                                rule) */
} cf_label_box_t;

typedef struct cf_label cf_label_t;

/* Parse and lay out text at font size size_bp with the family list family
** (NULL: the default theme's). */
cf_status_t cf_label_create(const char *text, const char *family,
                            double size_bp, cf_label_t **out,
                            cf_diag_t *diag);
void cf_label_destroy(cf_label_t *label);

size_t cf_label_box_count(const cf_label_t *label);
/* Box i (NULL if out of range). */
const cf_label_box_t *cf_label_get_box(const cf_label_t *label, size_t i);
/* The UTF-8 text of run i ("" if out of range). */
const char *cf_label_run_text(const cf_label_t *label, size_t i);
/* Logical size of the whole label: width, ascent above and descent below
** the base line (bp). */
void cf_label_get_extents(const cf_label_t *label, double *width,
                          double *ascent, double *descent);
/* Number of characters no font of the family list (nor fontconfig's
** fallback) could show: 0 means no empty boxes. */
size_t cf_label_unknown_glyphs(const cf_label_t *label);

#ifdef __cplusplus
}
#endif

#endif
