/*
** curvefig figure styles: units, colours, markers, label places, the
** style of an element and the themes that give every role its style
** (library curvefig-render; included by curvefig/figure.h).
*/
#ifndef CURVEFIG_STYLE_H
#define CURVEFIG_STYLE_H

#include <stdbool.h>
#include <stddef.h>

#include "curvefig/core.h"
#include "curvefig/export.h"

#ifdef __cplusplus
extern "C" {
#endif

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
CF_API double cf_length_to_bp(double value, cf_unit_t unit);

/* "bp", "pt", "texpt", "mm", "cm", "in" -> unit; INVALID_ARG otherwise. */
CF_API cf_status_t cf_unit_from_name(const char *name, cf_unit_t *out,
                                     cf_diag_t *diag);

/* ---- colours and styles ------------------------------------------------- */

typedef struct cf_color {
    double r, g, b, a;   /* 0..1 each; a = 0 is transparent (nothing drawn) */
} cf_color_t;

/* "#rrggbb", "#rrggbbaa", "none", or a name: black white grey gray red
** green blue orange yellow purple brown cyan magenta darkblue darkred
** darkgreen lightgrey.  INVALID_ARG otherwise. */
CF_API cf_status_t cf_color_parse(const char *text, cf_color_t *out,
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
CF_API cf_status_t cf_marker_from_name(const char *name, cf_marker_t *out,
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
CF_API cf_status_t cf_place_from_name(const char *name, cf_place_t *out,
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
CF_API void cf_style_init(cf_style_t *style);

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
    bool redundant;                       /* a second channel besides
                                             colour: the levels of a net
                                             dashed each its own way */
} cf_theme_t;

/* Built-in themes: "default" (colour, legible in print, on a projector
** and in greyscale) and "mono" (black and greys only).  INVALID_ARG for
** another name. */
CF_API cf_status_t cf_theme_get(const char *name, cf_theme_t *out,
                                cf_diag_t *diag);

/* The palette of a theme by name (docs/accessibility.md): "default",
** "okabe-ito" (Okabe and Ito's eight colours for colour-blind readers) or
** "greyscale" (for greyscale print); an unknown name is an error naming
** the nearest one. */
CF_API cf_status_t cf_theme_set_palette(cf_theme_t *theme, const char *name,
                                        cf_diag_t *diag);

/* With theme->redundant, level `level` (1, 2, ...) of a construction
** whose levels differ in colour (a net's, a surface scheme's) dashed and
** marked its own way too: the dash pattern where style sets none
** (CF_STYLE_DASH), the marker shape where it sets none (CF_STYLE_MARKER)
** and the theme's polygons have markers; level 0 (the control polygon) and
** a theme without redundant leave style as it is. */
CF_API void cf_theme_level_style(const cf_theme_t *theme, size_t level,
                                 cf_style_t *style);

/* The font of every label of a theme, set once: family "serif" (Latin
** Modern Roman, mathematics in Latin Modern Math as TeX sets it), "sans"
** (Latin Modern Sans, mathematics with its letters in Latin Modern Sans
** Oblique as beamer sets it) or a Pango family list; NULL keeps the
** family.  size_bp (> 0, <= 1000; 0 keeps the size) is the size of
** labels; every other role's size (tick labels) is scaled with it. */
CF_API cf_status_t cf_theme_set_fonts(cf_theme_t *theme, const char *family,
                                      double size_bp, cf_diag_t *diag);

#ifdef __cplusplus
}
#endif

#endif
