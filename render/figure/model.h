/*
** The figure model, private to the renderer: the figure object, the
** element record every kind starts with, and the class (a table of
** functions) that gives each kind its bounds and its drawing.
**
** The figure layer (render/figure/): figure.c, text.c, style.c and the
** element kinds declare their shared functions here; the layout's are in
** render/layout/layout-private.h.  The layers: docs/library.md,
** "How the renderer is built".
*/
#ifndef CURVEFIG_RENDER_MODEL_H
#define CURVEFIG_RENDER_MODEL_H

#include <stdbool.h>

#include "curvefig/figure.h"
#include "curvefig/figure3d.h"
#include "curvefig/geometry.h"
#include "curvefig/visibility.h"
#include "dlist.h"
#include "facts.h"

/* ---- layout (filled in by layout.c, read by the element kinds) -------- */

/* The page layout of one rendering. */
typedef struct cf__layout {
    double xmin, xmax, ymin, ymax;   /* data window */
    double sx, sy;                   /* bp per data unit */
    double ox, oy;                   /* page position of (xmin, ymin) */
    double tol;                      /* fitting tolerance, data units */
    bool clip;                       /* explicit window: lines clipped to
                                        it, points outside it left out */
    double px, py;                   /* page position of the figure's top
                                        left (a panel's cell, a crop) */
} cf__layout_t;

static inline void
cf__map(const cf__layout_t *l, double x, double y, double *px, double *py)
{
    *px = l->ox + l->sx * (x - l->xmin);
    *py = l->oy - l->sy * (y - l->ymin);
}

/* Whether a point is drawn: always, unless the window was set explicitly
** and the point lies outside it (beyond rounding: 1e-9 of its size). */
static inline bool
cf__in_window(const cf__layout_t *l, double x, double y)
{
    double ex = 1e-9 * (l->xmax - l->xmin), ey = 1e-9 * (l->ymax - l->ymin);
    return !l->clip
        || (x >= l->xmin - ex && x <= l->xmax + ex && y >= l->ymin - ey
            && y <= l->ymax + ey);
}

/* A CLIP to an explicit window widened by pad bp on every side (a line
** lying on the window's edge stays whole); without one, a CLIP that only
** scopes what follows. */
static inline void
cf__clip_to_window(const cf__layout_t *l, double pad, cf__dl_t *dl)
{
    double x0, y0, x1, y1, r[4];
    if (!l->clip) {
        cf__dl_clip(dl, NULL);
        return;
    }
    cf__map(l, l->xmin, l->ymax, &x0, &y0);
    cf__map(l, l->xmax, l->ymin, &x1, &y1);
    r[0] = x0 - pad;
    r[1] = y0 - pad;
    r[2] = x1 - x0 + 2 * pad;
    r[3] = y1 - y0 + 2 * pad;
    cf__dl_clip(dl, r);
}

/* ---- elements ----------------------------------------------------------- */

typedef struct cf__bounds {
    double x0, x1, y0, y1;
    bool any;
    bool nomem;     /* an element's box could not be computed (out of
                       memory): the layout's error, not a smaller box */
} cf__bounds_t;

static inline void
cf__bounds_add(cf__bounds_t *b, double x, double y)
{
    if (!b->any) {
        b->x0 = b->x1 = x;
        b->y0 = b->y1 = y;
        b->any = true;
        return;
    }
    b->x0 = b->x0 < x ? b->x0 : x;
    b->x1 = b->x1 > x ? b->x1 : x;
    b->y0 = b->y0 < y ? b->y0 : y;
    b->y1 = b->y1 > y ? b->y1 : y;
}

/* A label of an element: its source and its current layout. */
typedef struct cf__text {
    char *src;
    cf_label_t *lab;
} cf__text_t;

typedef struct cf__element cf__element_t;

/* The place and the distance from its anchor (bp) of a label placed
** automatically, for the current layout. */
typedef struct cf__auto_place {
    cf_place_t place;
    double offset;
} cf__auto_place_t;

/* Flags of a kind. */
enum {
    CF__KIND_SHADING = 1u << 0,   /* automatic labels may sit on it: left
                                     out of the placement raster */
    CF__KIND_AXES = 1u << 1       /* a figure with axes keeps no aspect
                                     ratio unless asked */
};

/* What a kind does; one static table per kind, beside its record. */
typedef struct cf__kind {
    const char *name;             /* "curve", "label" (messages, dumps) */
    unsigned flags;
    void (*fini)(cf__element_t *e);
    void (*bounds)(const cf__element_t *e, cf__bounds_t *b);
    /* Append the element's operations for layout l; s is its resolved
    ** style.  Errors go into fig. */
    cf_status_t (*draw)(cf_figure_t *fig, cf__element_t *e,
                        const cf__layout_t *l, const cf_style_t *s,
                        cf__dl_t *dl);
    /* Labels: the anchor (data), the text and where the place chosen
    ** for the current layout goes (used when placed CF_PLACE_AUTO).
    ** NULL for other kinds. */
    bool (*auto_label)(cf__element_t *e, double *x, double *y,
                       cf__text_t **text, cf__auto_place_t **chosen);
    /* Surfaces: whether the element hides what lies behind it, and its
    ** addition to the figure's scene of occluding surfaces (figure-
    ** scene.c, which knows no kind).  NULL for other kinds. */
    bool (*occludes)(const cf__element_t *e);
    cf_status_t (*occlude)(cf__element_t *e, struct cf_scene *sc,
                           cf_diag_t *err);
} cf__kind_t;

/* The start of every element record. */
struct cf__element {
    const cf__kind_t *kind;
    cf_role_t role;
    cf_style_t style;             /* overrides */
    char *overlay;                /* the steps it is shown on (a beamer
                                     overlay specification), NULL: all */
    int line;                     /* the script's line that added it (its
                                     warnings name it), 0: unknown */
};

/* Where a box goes beside the drawing (render/layout/room.c): undecided (a new
** layout), inside the drawing's ink box, or in a band at its right or
** below it (or, for an inset, at its left or above it). */
typedef enum cf__room_band {
    CF__ROOM_UNDECIDED,
    CF__ROOM_INSIDE,
    CF__ROOM_RIGHT,
    CF__ROOM_BELOW,
    CF__ROOM_LEFT,
    CF__ROOM_ABOVE
} cf__room_band_t;

/* A legend entry: element el and its text. */
typedef struct cf__legend_entry {
    size_t el;
    cf__text_t text;
} cf__legend_entry_t;

struct cf_figure {
    cf_diag_t err;           /* the first error (sticky) */
    const struct cf__fonts *fonts;  /* its labels' (render/labels/font.h),
                                       given at its creation */
    double width, height;    /* bp */
    char *title, *caption;
    char *alt, *description, *lang;   /* accessible text (describe.c):
                                         NULL unset; description "auto" */
    cf__facts_t facts;       /* what it shows, for the description */
    cf_theme_t theme;
    bool window_set;
    double win[4];
    double margin;
    cf_page_mode_t page_mode;
    cf_background_t background;
    int aspect;              /* -1 automatic, 0 free, 1 kept */
    double tol;
    bool draft;              /* cf_figure_set_draft */
    bool refitting;          /* drawn for one of the ink refits of a page
                                cropped to its ink (layout.c) */
    bool refit_rough;        /* the first of them in an exact run: surfaces
                                made as for a draft (cf__tol_make) */
    double refit_drop;       /* at the second: how far the layout's
                                tolerance fell from the first's, relative
                                (0: it did not; cf__tol_make) */
    int layout_passes;       /* the ink refits the last layout made (1:
                                none; render/layout/layout.c) */
    bool clip_page;          /* ink outside the page is cut, not an error */
    size_t proj_dim;
    double *proj;            /* 2 x proj_dim */
    bool has_view;           /* a 3D view (figure-view.c) */
    cf_view_t view;
    double view_m[12];       /* its homogeneous projection */
    struct cf_scene *scene;  /* the occluding surfaces, for a layout's
                                tolerance (render/figure/el-surface.c) */
    double scene_tol;
    size_t scene_els;        /* the element count it was built for */
    cf__element_t **els;
    size_t count, cap;
    char *warnings;          /* of the last layout, a line each; NULL: none */
    size_t warnings_len;
    char *all_warnings;      /* a figure split into panels: its own and
                                its panels' of the last build, each line
                                of a panel naming it (render/layout/
                                layout.c); NULL: none */
    /* the layout (less its page position) the labels were last placed for
    ** within one cf__figure_layout and its builds (render/layout/place.c) */
    bool placed, placed_draft;
    cf__layout_t placed_for;
    /* the memory of its rasters, kept for the next placement (a layout
    ** places the labels once per refit), and which rows of the page's
    ** raster are empty (render/layout/place-raster.c), for a raster of
    ** place_w x place_h */
    unsigned char *place_px, *place_ready;
    size_t place_px_size;   /* bytes */
    int place_w, place_h;
    /* the places the frames of an animation pass on (render/output/
    ** anim-frames.c; owned by it): the automatic labels in turn keep hint[i]
    ** while it stays about as clear as their best place, or take it
    ** (force) */
    const cf__auto_place_t *place_hint;
    size_t nplace_hint;
    bool place_hint_force;
    /* legend (render/layout/legend.c) */
    cf__legend_entry_t *legend;
    size_t nlegend;
    cf_place_t legend_place;      /* CENTER (never set): automatic */
    bool legend_noframe;
    cf__room_band_t legend_band;  /* of this layout */
    /* insets (render/layout/inset.c) */
    cf_inset_t *insets;
    size_t ninsets;
    cf__room_band_t *inset_band;  /* each one's, of this layout */
    void *inset_cache;            /* their places for the last map they
                                     were found for (inset-place.c) */
    /* panels (render/layout/panel.c): rows x cols figures, or a panel's
    ** parent */
    cf_figure_t **panels;
    int rows, cols;
    unsigned panel_flags;
    double panel_gap;
    cf_figure_t *parent;
    cf__text_t panel_title;
    unsigned steps;          /* largest step named by an overlay, 0: none */
    char *overlay;           /* given to the elements added next, or NULL */
    unsigned overlay_last;   /* the largest step it names */
    int line;                /* the script's line of the elements added
                                next, 0: unknown (cf_figure_set_line) */
};

/* ---- figure.c: the figure's helpers for the element kinds -------------- */

#define CF__FIG_CHECK(fig)                                                 \
    do {                                                                   \
        if ((fig) == NULL)                                                 \
            return CF_STATUS_INVALID_ARG;                                  \
        if ((fig)->err.status != CF_STATUS_OK)                             \
            return (fig)->err.status;                                      \
    } while (0)

/* cf_figure_create with the fonts its labels are set in (render/labels/
** font.h, which the layers below the output take as an argument): the
** public function is render/output/create.c's, which chooses them; a
** figure's panels take their figure's. */
cf_status_t cf__figure_create(const struct cf__fonts *fonts, double width,
                              double height, cf_unit_t unit,
                              cf_figure_t **out, cf_diag_t *diag);

/* Append a line to the figure's warnings (cf_figure_warnings) unless it
** is there already. */
void cf__figure_warn(cf_figure_t *fig, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* " (line N)" into buf for an element the script added at line N (the
** errors and warnings that name an element name its line), "" when N is
** unknown (0); returns buf. */
#define CF__LINE_NOTE_SIZE 24
const char *cf__line_note(int line, char buf[CF__LINE_NOTE_SIZE]);
/* Record st in the figure (a generic message if the callee left none). */
cf_status_t cf__fig_fail(cf_figure_t *fig, cf_status_t st, const char *what);
/* "out of memory for <what>" in the figure. */
cf_status_t cf__fig_nomem(cf_figure_t *fig, const char *what);
/* n >= min finite points (what names them in messages). */
cf_status_t cf__fig_check_points(cf_figure_t *fig, const double *pts,
                                 size_t n, size_t min, const char *what);
cf_status_t cf__fig_check_style(cf_figure_t *fig, const cf_style_t *style);
/* A zeroed record of `size` bytes of kind k, not yet in the figure. */
void *cf__element_new(cf_figure_t *fig, const cf__kind_t *k, size_t size,
                      cf_role_t role, const cf_style_t *style);
/* Append the record made by cf__element_new, or release it if st fails. */
cf_status_t cf__element_commit(cf_figure_t *fig, void *e, cf_status_t st);
/* Project one point of dimension dim (stride 1) into out[2] (NaN for a
** point at or behind the eye of a perspective view). */
void cf__fig_project1(const cf_figure_t *fig, const double *p, size_t dim,
                      double *out);
double *cf__copy_doubles(const double *src, size_t n);
/* Element i's operations for a layout: a GROUP ... END. */
cf_status_t cf__element_draw(cf_figure_t *fig, size_t i,
                             const cf__layout_t *lay, cf__dl_t *dl);
/* The label font size of a role with overrides s. */
double cf__role_font_size(const cf_figure_t *fig, cf_role_t role,
                          const cf_style_t *s);

/* ---- figure.c: projection through a 3D view (figure-view.c sets it) ---------- */

/* The image (X, Y, W) of homogeneous point hp = (w x, w) (rational) or
** Cartesian x (not rational) of dimension dim under the figure's
** projection; W = w (1) unless the view is a perspective one.  False when
** W <= 0 (at or behind the eye). */
bool cf__fig_project_h(const cf_figure_t *fig, const double *hp, size_t dim,
                       bool rational, double out[3]);
/* Whether the figure's projection is a central (perspective) one for
** points of dimension dim. */
bool cf__fig_is_central(const cf_figure_t *fig, size_t dim);
/* "the point (x, y, z) lies at or behind the eye ..." into fig. */
cf_status_t cf__fig_behind_eye(cf_figure_t *fig, const double *p,
                               const char *what);

/* ---- el-curve.c: plane curves -------------------------------------------- */

/* A planar copy of c (projected when dim >= 3). */
cf_status_t cf__fig_planar_bezier(cf_figure_t *fig, const cf_bezier_t *c,
                                  cf_bezier_t **out);

/* ---- text.c: labels of elements ----------------------------------------- */

cf_status_t cf__text_set(cf_figure_t *fig, cf__text_t *t, const char *src,
                         double size);
/* Lay the label out again if the theme's family or the size changed. */
cf_status_t cf__text_ensure(cf_figure_t *fig, cf__text_t *t, double size);
void cf__text_fini(cf__text_t *t);
/* Origin of a label placed at `place` of page point (px, py), gap off. */
void cf__label_origin(const cf_label_t *lab, cf_place_t place, double off,
                      double px, double py, double *ox, double *oy);
/* Append the text at `place` of page point (px, py) in style s (colour,
** opacity, font size, halo); nothing when t has no source. */
cf_status_t cf__text_draw(cf_figure_t *fig, cf__text_t *t, const cf_style_t *s,
                          double px, double py, cf_place_t place,
                          double off, cf__dl_t *dl);

/* ---- el-curve.c: curves made of pieces, for the plots ------------------- */


/* An empty curve element of role (CF_ROLE_CURVE or CF_ROLE_GRAPH). */
cf__element_t *cf__curve_new(cf_figure_t *fig, cf_role_t role,
                             const cf_style_t *style);
/* Append a planar Bézier (taken over, even on failure) or, with bez NULL,
** a fixed cubic segment (8 doubles). */
cf_status_t cf__curve_add(cf_figure_t *fig, cf__element_t *e,
                          cf_bezier_t *bez, const double *cubic);

/* ---- arrow-head.c: the head of an arrow -------------------------------- */

/* A slightly concave ("stealth") triangle with its tip at (tx, ty)
** pointing along the unit vector (ux, uy), length len, filled. */
void cf__arrow_head(cf__dl_t *dl, double tx, double ty, double ux, double uy,
                    double len, const cf_color_t *color, double opacity);

/* ---- style.c ------------------------------------------------------------ */

/* The style of the hidden pieces of a line in space: 0.7 of the width,
** dashes of 4 and 3 widths. */
cf_style_t cf__hidden_style(const cf_style_t *s);
/* The effective style of an element: the theme's role style with the
** element's set fields applied over it. */
void cf__style_resolve(const cf_theme_t *theme, cf_role_t role,
                       const cf_style_t *over, cf_style_t *out);
/* Check the fields an element sets (finite, in range); names `what`. */
cf_status_t cf__style_check(const cf_style_t *style, cf_diag_t *diag);

#endif
