/*
** The display list: what a laid-out figure draws, as device-independent
** operations in page units (bp, y down, origin at the top left of the
** page).  The layout writes it (render/layout/layout.c and the element kinds);
** backends read it (render/backends/backend.h).  Nothing here knows cairo.
**
** Operations, in drawing order:
**   GROUP / END      one element of the figure (its kind name and index);
**                    a backend keeps the drawing state local to it
**   CLIP / UNCLIP    what follows, up to UNCLIP or the group's END, is
**                    clipped to a rectangle (or only scoped, without one)
**   PATH             segments (move, line, cubic, rectangle, arc, close)
**                    and a paint: fill, stroke, or fill then stroke
**   MARKER           a marker symbol at a point (draw_markers)
**   TEXT             a laid-out label (its shaped runs) with its TeX-like
**                    source, anchor, placement and origin, so that a
**                    backend draws the glyphs or hands the source to TeX
**   MESH             smooth shading: opaque triangles with a colour at
**                    each corner, painted in order (a later one over an
**                    earlier one), as a mesh gradient where the format
**                    has them, else as flat pieces (render/dlist/mesh.c)
*/
#ifndef CURVEFIG_RENDER_DLIST_H
#define CURVEFIG_RENDER_DLIST_H

#include <stdbool.h>
#include <stddef.h>

#include "curvefig/figure.h"

typedef enum cf__seg {
    CF__SEG_MOVE,      /* x y */
    CF__SEG_LINE,      /* x y */
    CF__SEG_CURVE,     /* x1 y1 x2 y2 x3 y3 */
    CF__SEG_RECT,      /* x y w h: a closed subpath */
    CF__SEG_ARC,       /* cx cy r a0 a1: counter-clockwise on the page's
                          y-down axes, as cairo_arc */
    CF__SEG_CLOSE
} cf__seg_t;

typedef enum cf__cap { CF__CAP_BUTT, CF__CAP_ROUND } cf__cap_t;
typedef enum cf__join { CF__JOIN_MITER, CF__JOIN_ROUND } cf__join_t;

/* How a line is stroked. */
typedef struct cf__stroke {
    cf_color_t color;
    double opacity;          /* multiplies color.a */
    double width;
    cf__cap_t cap;
    cf__join_t join;
    size_t dash_count;       /* 0: solid */
    double dash[CF_STYLE_DASH_MAX];
} cf__stroke_t;

/* The paint of a path: fill (with fill colour), stroke, or both (fill
** first). */
typedef struct cf__paint {
    bool fill, stroke;
    cf_color_t fill_color;
    double fill_opacity;
    cf__stroke_t line;
} cf__paint_t;

typedef struct cf__path {
    const unsigned char *segs;   /* cf__seg_t each */
    const double *coords;        /* the segments' numbers, in order */
    size_t nsegs;
} cf__path_t;

/* A marker symbol (the style fields it uses, resolved). */
typedef struct cf__marker_op {
    cf_marker_t marker;
    double x, y;
    bool has_dir;
    double dir[2];           /* page direction of the curve (ticks) */
    double size;             /* marker_size */
    double width;            /* the element's line width (ticks) */
    cf_color_t color;        /* marker_color */
    cf_color_t fill;         /* inside of an open circle */
    double opacity;
} cf__marker_op_t;

/* A label.  The glyphs are `label` drawn with its baseline origin at
** (ox, oy); the same text for TeX is `source`, placed at `place` of the
** anchor (px, py) with gap `offset`. */
typedef struct cf__text_op {
    const cf_label_t *label;
    const char *source;
    double px, py;
    cf_place_t place;
    double offset;
    double font_size;
    double ox, oy;
    double ink[4];           /* ink box relative to the origin */
    cf_color_t color;
    double opacity;
    double halo;             /* > 0: a border of halo_color (the page's
                                background) first; on a transparent page
                                a knockout (render/backends/backend.h) */
    cf_color_t halo_color;
} cf__text_op_t;

/* A triangle of a mesh: its page corners, the colour at each (a mesh
** gradient interpolates them linearly), and the flat colours of the four
** pieces that stand for it where a format has no mesh gradients: the
** triangle cut at its edges' midpoints, the pieces at corners 0, 1, 2,
** then the middle one.  The maker chooses both (shading is not linear
** in the colours). */
typedef struct cf__mesh_tri {
    double p[6];
    cf_color_t corner[3];
    cf_color_t piece[4];
} cf__mesh_tri_t;

typedef enum cf__op_kind {
    CF__OP_GROUP,
    CF__OP_END,
    CF__OP_CLIP,
    CF__OP_UNCLIP,
    CF__OP_PATH,
    CF__OP_MARKER,
    CF__OP_TEXT,
    CF__OP_MESH
} cf__op_kind_t;

typedef struct cf__op {
    cf__op_kind_t kind;
    union {
        struct {
            const char *name;
            size_t index;
            const char *overlay;   /* beamer overlay specification ("2-"),
                                      NULL: visible on every step */
            int line;              /* the script's line of the element, 0:
                                      unknown (errors name it) */
        } group;
        struct { bool has_rect; double rect[4]; } clip;   /* x y w h */
        struct { size_t seg0, nsegs, coord0; cf__paint_t paint; } path;
        cf__marker_op_t marker;
        cf__text_op_t text;
        struct { size_t tri0, ntri; } mesh;   /* dl->tris */
    } u;
} cf__op_t;

typedef struct cf__dl {
    cf__op_t *ops;
    size_t count, cap;
    unsigned char *segs;
    size_t nsegs, segcap;
    double *coords;
    size_t ncoords, coordcap;
    cf__mesh_tri_t *tris;             /* of the MESH operations */
    size_t ntris, tricap;
    size_t path_seg0, path_coord0;   /* the path being built */
    bool failed;                      /* an allocation failed */
} cf__dl_t;

void cf__dl_init(cf__dl_t *dl);
void cf__dl_free(cf__dl_t *dl);
/* Drop every operation (keeps the memory). */
void cf__dl_reset(cf__dl_t *dl);

/* Whether every page number of the operations from op0, the path
** coordinates from coord0 and the mesh triangles from tri0 on is finite;
** when not, *bad is the first that is not. */
bool cf__dl_finite_from(const cf__dl_t *dl, size_t op0, size_t coord0,
                        size_t tri0, double *bad);

void cf__dl_group(cf__dl_t *dl, const char *name, size_t index);
void cf__dl_end(cf__dl_t *dl);
/* rect NULL: a scope without a clip. */
void cf__dl_clip(cf__dl_t *dl, const double *rect);
void cf__dl_unclip(cf__dl_t *dl);

/* A path: segments appended after cf__dl_path_begin, then painted (or
** dropped) by cf__dl_path_paint. */
void cf__dl_path_begin(cf__dl_t *dl);
void cf__dl_move(cf__dl_t *dl, double x, double y);
void cf__dl_line(cf__dl_t *dl, double x, double y);
void cf__dl_curve(cf__dl_t *dl, double x1, double y1, double x2, double y2,
                  double x3, double y3);
void cf__dl_rect(cf__dl_t *dl, double x, double y, double w, double h);
void cf__dl_arc(cf__dl_t *dl, double cx, double cy, double r, double a0,
                double a1);
void cf__dl_close(cf__dl_t *dl);
/* paint NULL: the segments are dropped (nothing drawn). */
void cf__dl_path_paint(cf__dl_t *dl, const cf__paint_t *paint);

void cf__dl_marker(cf__dl_t *dl, const cf__marker_op_t *m);

/* The outline of a marker symbol (render/dlist/marker.c), the same for every
** backend: its path and how it is painted — filled in the marker colour,
** filled with `fill` then stroked in the marker colour, or only stroked;
** strokes of width line_width. */
typedef enum cf__marker_paint {
    CF__MARKER_FILL,
    CF__MARKER_FILL_STROKE,
    CF__MARKER_STROKE
} cf__marker_paint_t;

typedef struct cf__marker_shape {
    unsigned char segs[16];
    double coords[48];
    size_t ncoords;
    cf__path_t path;          /* points into segs and coords */
    cf__marker_paint_t paint;
    double line_width;
} cf__marker_shape_t;

/* false: nothing to draw (CF_MARKER_NONE or unknown). */
bool cf__marker_shape(const cf__marker_op_t *m, cf__marker_shape_t *out);
/* The marker as a drawing backend receives it: its shape (out) and the
** paint of that path, every stroke property explicit (butt caps, miter
** joins, no dash; the circle's path closed, so it has no caps), the fill
** and stroke colours and opacity of the marker.  false: nothing to draw. */
bool cf__marker_paint(const cf__marker_op_t *m, cf__marker_shape_t *out,
                      cf__paint_t *paint);
void cf__dl_text(cf__dl_t *dl, const cf__text_op_t *t);

/* ---- meshes -------------------------------------------------------------- */

/* Append a triangle to the MESH operation that ends the list, or start
** one: consecutive triangles are one mesh, painted in order. */
void cf__dl_mesh_tri(cf__dl_t *dl, const cf__mesh_tri_t *t);

/* The triangles of a MESH operation. */
const cf__mesh_tri_t *cf__dl_op_mesh(const cf__dl_t *dl, const cf__op_t *op,
                                     size_t *n);

/* (render/dlist/mesh.c) A flat triangle of page corners q[6] in colour c: its path (segs and
** coords: room for 4 and 6) and paint: filled, and when opaque also
** stroked with a hairline (0.25 bp) of its own colour, which closes the
** seams anti-aliasing leaves between neighbours.  false: nothing to see
** (an area below 1e-4 bp^2, where writers would drop the fill and keep
** the stroke). */
bool cf__flat_triangle(const double *q, cf_color_t c, double opacity,
                       unsigned char *segs, double *coords, cf__path_t *path,
                       cf__paint_t *paint);

/* Piece k (0..3) of a mesh triangle as a flat triangle's corners q[6]
** (the stand-in where a format has no mesh gradients). */
void cf__mesh_piece(const cf__mesh_tri_t *t, int k, double *q);

/* Append every operation of src to dst, moved by (dx, dy) on the page
** (a panel's display list into its cell). */
void cf__dl_append_moved(cf__dl_t *dst, const cf__dl_t *src, double dx,
                         double dy);

/* The path of a PATH operation. */
void cf__dl_op_path(const cf__dl_t *dl, const cf__op_t *op, cf__path_t *out);

/* Paint helpers from a resolved style: the stroke of its line (width,
** colour, opacity, dash; round caps and joins, butt caps when dashed). */
void cf__stroke_from_style(const cf_style_t *s, cf__stroke_t *out);
/* A marker of the resolved style at a page point. */
void cf__marker_from_style(const cf_style_t *s, cf_marker_t marker,
                           double x, double y, const double *dir,
                           cf__marker_op_t *out);

/* ---- exact boxes (path-box.c) ------------------------------------------ */

/* The exact box (x0 y0 x1 y1) of what path p draws at device = page *
** scale + (dx, dy), curves and arcs by their extremes (a move drawn from
** by nothing adds nothing), grown into box (box[2] < box[0]: empty at
** first). */
void cf__path_box(const cf__path_t *p, double scale, double dx, double dy,
                  double box[4]);
/* A length no shorter than what path p draws, times scale (its curves by
** their control polygons, each subpath's close included); infinite when a
** number is not finite. */
double cf__path_length_bound(const cf__path_t *p, double scale);
/* fmin and fmax as C11 gives them (a NaN gives the other number; else
** the smaller, the second of two equal, as glibc's minsd: signed zeros
** come out the same), inline: cf__box_grow takes every point of every
** polygon the measures make, and a call to libm each time was a tenth of
** measuring a figure's ink. */
static inline double
cf__fmin(double a, double b)
{
    return a != a ? b : b != b ? a : a < b ? a : b;
}

static inline double
cf__fmax(double a, double b)
{
    return a != a ? b : b != b ? a : a > b ? a : b;
}

/* (x, y) grown into box (box[2] < box[0]: empty). */
static inline void
cf__box_grow(double box[4], double x, double y)
{
    if (box[2] < box[0]) {
        box[0] = box[2] = x;
        box[1] = box[3] = y;
        return;
    }
    box[0] = cf__fmin(box[0], x);
    box[1] = cf__fmin(box[1], y);
    box[2] = cf__fmax(box[2], x);
    box[3] = cf__fmax(box[3], y);
}
/* The angles of an arc v (cx cy r a0 a1) as cairo_arc takes them: a1
** raised by whole turns to at least a0; false when they are not finite
** or too far apart. */
bool cf__arc_range(const double *v, double *a0, double *a1);

/* ---- arcs as cubics (arc-cubic.c) -------------------------------------- */

/* The arc v (cx cy r a0 a1) as cairo_arc draws it (counter-clockwise on
** the y-down page, a1 raised by whole turns to a1 >= a0): to gets its
** start (n 1: one point), then its cubic pieces of at most a quarter
** turn (n 3: two control points and the end).  false (no call) when the
** angles are not finite or too far apart. */
bool cf__arc_cubics(const double *v, void (*to)(void *ctx, const double *p,
                                                int n), void *ctx);

#endif
