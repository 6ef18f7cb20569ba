/*
** The schemas of every named table of the figure language (lkeys.h):
** what each function takes by name.  A key added here is known to the
** check, listed to the tests (which misspell every key and every name
** and expect the suggestion), and documented by docs/language.md.
*/
#include <stddef.h>

#include "lkeys.h"

/* ---- enumerated names --------------------------------------------------- */

static const char *const places[] = {
    "center", "n", "ne", "e", "se", "s", "sw", "w", "nw", "auto",
    "above", "below", "left", "right", NULL,
};
static const char *const markers[] = {
    "none", "dot", "circle", "square", "diamond", "triangle", "cross",
    "plus", "star", "tick", NULL,
};
static const char *const dashes[] = {
    "solid", "dashed", "dotted", "dashdot", NULL,
};
/* the places of a legend or an inset: a corner, a side, or auto */
static const char *const box_places[] = {
    "auto", "n", "ne", "e", "se", "s", "sw", "w", "nw", "above", "below",
    "left", "right", NULL,
};
static const char *const themes[] = { "default", "mono", NULL };
static const char *const pages[] = { "ink", "fixed", NULL };
static const char *const kinds[] = { "clamped", "closed", "uniform", NULL };
static const char *const ends[] = { "plain", "tripled", "closed", NULL };
static const char *const interp_methods[] = {
    "natural", "clamped", "not-a-knot", "periodic", "catmull-rom", "global",
    NULL,
};
static const char *const params[] = {
    "uniform", "chord", "centripetal", "default", NULL,
};
static const char *const offset_methods[] = {
    "levien", "tiller-hanson", NULL,
};
static const char *const reduce_methods[] = { "l2", "uniform", NULL };
static const char *const hidden_modes[] = {
    "remove", "dashed", "show", NULL,
};
static const char *const shade_modes[] = { "smooth", "flat", NULL };

/* ---- key lists ---------------------------------------------------------- */

#define END { NULL, NULL, CF__KEYS_NONE, NULL }
#define KEY(name) { name, NULL, CF__KEYS_NONE, NULL }
#define NAMES(name, values) { name, values, CF__KEYS_NONE, NULL }
#define TABLE(name, schema) { name, NULL, schema, NULL }
#define PLACES(name) { name, places, CF__KEYS_NONE, \
                       "a table of places or a function returning one" }

/* the style of lines, areas and markers */
static const cf__lua_key_t line_style[] = {
    KEY("color"), KEY("fill"), KEY("width"),
    { "dash", dashes, CF__KEYS_NONE, "{on, off, ...} in bp" },
    KEY("opacity"), NAMES("marker", markers), KEY("marker_size"),
    KEY("marker_color"), KEY("arrow_size"), KEY("legend"), END,
};
/* the style of text */
static const cf__lua_key_t text_style[] = {
    KEY("color"), KEY("opacity"), KEY("font_size"), NAMES("place", places),
    NAMES("anchor", places), KEY("offset"), KEY("halo"), END,
};
/* every style key: refused, with a hint, where no style is taken */
static const cf__lua_key_t any_style[] = {
    KEY("color"), KEY("fill"), KEY("width"), KEY("dash"), KEY("opacity"),
    KEY("marker"), KEY("marker_size"), KEY("marker_color"),
    KEY("arrow_size"), KEY("font_size"), KEY("halo"), KEY("place"),
    KEY("anchor"), KEY("offset"), KEY("legend"), END,
};
/* the labels of the points a method draws (labels.c of the binding) */
static const cf__lua_key_t point_labels[] = {
    KEY("labels"), KEY("label_start"), PLACES("label_place"),
    TABLE("label_style", CF__KEYS_LABEL_STYLE), END,
};
/* the one label of an arrow */
static const cf__lua_key_t arrow_label[] = {
    KEY("label"), PLACES("label_place"),
    TABLE("label_style", CF__KEYS_LABEL_STYLE), END,
};

static const cf__lua_key_t figure_keys[] = {
    KEY("name"), KEY("caption"), KEY("title"), KEY("alt"),
    KEY("description"), KEY("lang"), KEY("width"), KEY("height"),
    NAMES("page", pages), KEY("window"), KEY("margin"), KEY("aspect"),
    NAMES("theme", themes), KEY("background"), KEY("font"),
    KEY("font_size"),
    KEY("tolerance"), KEY("projection"), KEY("view"), KEY("distance"),
    KEY("target"), KEY("clip"),
    NAMES("legend_place", box_places), KEY("legend_frame"), END,
};
static const char *const palettes[] = { "default", "okabe-ito", "greyscale",
                                        NULL };
static const cf__lua_key_t theme_keys[] = {
    KEY("family"), KEY("size"), NAMES("palette", palettes), KEY("redundant"),
    END,
};
static const cf__lua_key_t legend_keys[] = {
    NAMES("place", box_places), KEY("frame"), END,
};
static const cf__lua_key_t inset_keys[] = {
    KEY("region"),
    /* a place or a box of lengths ({"1cm", ...}): read_at checks it */
    KEY("at"),
    KEY("scale"), KEY("size"), END,
};
static const cf__lua_key_t panels_keys[] = {
    KEY("rows"), KEY("cols"), KEY("gap"), KEY("share_x"), KEY("share_y"),
    KEY("titles"), END,
};
static const cf__lua_key_t bezier_keys[] = {
    KEY("points"), KEY("weights"), END,
};
static const cf__lua_key_t bspline_keys[] = {
    KEY("degree"), KEY("points"), KEY("weights"), KEY("knots"),
    NAMES("kind", kinds), END,
};
static const cf__lua_key_t coons_keys[] = {
    KEY("points"), NAMES("ends", ends), END,
};
static const cf__lua_key_t arc_keys[] = {
    KEY("center"), KEY("x"), KEY("y"), KEY("r"), KEY("from"), KEY("to"),
    END,
};
/* interpolate and approximate (approximate has no method) */
static const cf__lua_key_t fit_keys[] = {
    KEY("points"), NAMES("param", params), KEY("degree"), KEY("exponent"),
    KEY("closed"), KEY("params"), KEY("start_tangent"), KEY("end_tangent"),
    END,
};
static const cf__lua_key_t interpolate_keys[] = {
    NAMES("method", interp_methods), END,
};
static const cf__lua_key_t approximate_keys[] = {
    KEY("count"), KEY("fix_ends"), END,
};
static const cf__lua_key_t bezier_surface_keys[] = {
    KEY("points"), KEY("weights"), END,
};
static const cf__lua_key_t bspline_surface_keys[] = {
    KEY("degree"), KEY("knots"), KEY("points"), KEY("weights"), END,
};
static const cf__lua_key_t revolve_keys[] = {
    KEY("axis"), KEY("center"), KEY("from"), KEY("to"), END,
};
/* nurbs_sphere, nurbs_cylinder, nurbs_cone, nurbs_torus */
static const cf__lua_key_t quadric_keys[] = {
    KEY("center"), KEY("r"), KEY("h"), END,
};
static const cf__lua_key_t no_keys[] = { END };
static const cf__lua_key_t triangle_keys[] = {
    KEY("degree"), KEY("points"), KEY("weights"), END,
};
static const cf__lua_key_t torus_keys[] = {
    KEY("center"), KEY("R"), KEY("r"), END,
};
static const cf__lua_key_t interp_surface_keys[] = {
    KEY("points"), NAMES("method", interp_methods), NAMES("param", params),
    KEY("degree"), KEY("exponent"), KEY("count"), KEY("fix_ends"), END,
};
static const cf__lua_key_t offset_keys[] = {
    KEY("tolerance"), KEY("trim"), NAMES("method", offset_methods), END,
};
static const cf__lua_key_t reduce_keys[] = {
    KEY("by"), KEY("continuity"), NAMES("method", reduce_methods), END,
};
static const cf__lua_key_t reduce_bspline_keys[] = {
    KEY("by"), KEY("tolerance"), NAMES("method", reduce_methods), END,
};
static const cf__lua_key_t range_keys[] = {
    KEY("range"), NAMES("hidden", hidden_modes), END,
};
/* points, polygons, polylines and labels in R^3 (lspace.c) */
static const cf__lua_key_t hidden_keys[] = {
    NAMES("hidden", hidden_modes), END,
};
static const cf__lua_key_t closed_keys[] = {
    KEY("closed"), NAMES("hidden", hidden_modes), END,
};
static const cf__lua_key_t scale_keys[] = { KEY("scale"), END };
static const cf__lua_key_t net_keys[] = {
    KEY("colors"), KEY("labels"), KEY("label_start"),
    PLACES("label_place"),
    TABLE("label_style", CF__KEYS_LABEL_STYLE),
    TABLE("point", CF__KEYS_POINT_STYLE), KEY("levels"), END,
};
static const cf__lua_key_t plot_keys[] = {
    KEY("x"), KEY("y"), KEY("xticks"), KEY("yticks"), KEY("xtick_labels"),
    KEY("ytick_labels"), KEY("xlabel"), KEY("ylabel"), KEY("knots"),
    KEY("knot_labels"), KEY("arrows"), KEY("grid"), KEY("box"),
    KEY("font_size"), END,
};

/* f:surface (lsurface-draw.c): the lines, the net and its labels */
static const cf__lua_key_t surface_keys[] = {
    KEY("boundary"), KEY("silhouette"), KEY("isolines"), KEY("knot_lines"),
    NAMES("hidden", hidden_modes), TABLE("iso_style", CF__KEYS_POINT_STYLE),
    KEY("net"), KEY("occludes"), NAMES("shade", shade_modes), KEY("light"),
    KEY("back"), END,
};

/* f:decasteljau_surface and f:triangle_scheme (lsurface-scheme.c) */
static const cf__lua_key_t surface_scheme_keys[] = {
    KEY("colors"), TABLE("point", CF__KEYS_POINT_STYLE), END,
};

/* the parameters of interactive figures (lparams.c) */
static const cf__lua_key_t slider_keys[] = {
    KEY("name"), KEY("label"), KEY("min"), KEY("max"), KEY("default"),
    KEY("step"), KEY("scale"), END,
};
static const cf__lua_key_t param_points_keys[] = {
    KEY("name"), KEY("default"), TABLE("constrain", CF__KEYS_CONSTRAIN),
    KEY("figure"), END,
};
static const cf__lua_key_t constrain_keys[] = { KEY("grid"), KEY("line"), END };

/* the steps an element is shown on (read with the style, lstyle.c) */
static const cf__lua_key_t overlay_keys[] = { KEY("visible"), END };

/* ---- the schemas -------------------------------------------------------- */

#define STYLE_HINT "a curve has no style; give it to the drawing method, " \
    "f:curve(c, { color = \"red\" })"
#define FIGURE_HINT "a style belongs to what is drawn, f:curve(c, { color " \
    "= \"red\" }); theme = \"mono\" restyles the whole figure"

/* a method whose table comes last: the first %s of the example */
#define METHOD(fn, a, b, c, ex) \
    { fn, "option", { a, b, c, NULL }, false, NULL, NULL, ex }
/* a method that draws: its elements may carry overlay steps */
#define DRAW(fn, a, b, c, ex) \
    { fn, "option", { a, b, c, overlay_keys }, false, NULL, NULL, ex }
#define MAKER(fn, a, b, positional, ex) \
    { fn, "field", { a, b, NULL, NULL }, positional, any_style, STYLE_HINT, \
      ex }

static const cf__lua_schema_t schemas[CF__KEYS_COUNT_] = {
    [CF__KEYS_NONE] = { "", "option", { NULL, NULL, NULL, NULL }, false, NULL,
                        NULL, NULL },
    [CF__KEYS_FIGURE] = { "figure", "option", { figure_keys, NULL, NULL, NULL },
                          false, any_style, FIGURE_HINT, "figure(%s)" },
    [CF__KEYS_BEZIER] = MAKER("bezier", bezier_keys, NULL, true,
                              "bezier(%s)"),
    [CF__KEYS_BSPLINE] = MAKER("bspline", bspline_keys, NULL, false,
                               "bspline(%s)"),
    [CF__KEYS_COONS] = MAKER("coons", coons_keys, NULL, false, "coons(%s)"),
    [CF__KEYS_NURBS_ARC] = MAKER("nurbs_arc", arc_keys, NULL, false,
                                 "nurbs_arc(%s)"),
    [CF__KEYS_INTERPOLATE] = MAKER("interpolate", fit_keys, interpolate_keys,
                                   false, "interpolate(%s)"),
    [CF__KEYS_APPROXIMATE] = MAKER("approximate", fit_keys, approximate_keys,
                                   false, "approximate(%s)"),
    [CF__KEYS_COONS_CHAIN] = MAKER("coons_chain", coons_keys, NULL, false,
                                   "coons_chain(%s)"),
    [CF__KEYS_OFFSET] = METHOD("offset", offset_keys, NULL, NULL,
                               "c:offset(0.1, %s)"),
    [CF__KEYS_REDUCE] = METHOD("reduce", reduce_keys, NULL, NULL,
                               "c:reduce(%s)"),
    [CF__KEYS_REDUCE_BSPLINE] = METHOD("reduce", reduce_bspline_keys, NULL,
                                       NULL, "s:reduce(%s)"),
    [CF__KEYS_CURVE] = DRAW("curve", line_style, range_keys, NULL,
                              "f:curve(c, %s)"),
    [CF__KEYS_POLYGON] = DRAW("polygon", line_style, point_labels, hidden_keys,
                                "f:polygon(P, %s)"),
    [CF__KEYS_POINTS] = DRAW("points", line_style, point_labels, hidden_keys,
                               "f:points(P, %s)"),
    [CF__KEYS_HULL] = DRAW("hull", line_style, point_labels, hidden_keys,
                             "f:hull(P, %s)"),
    [CF__KEYS_FILL] = DRAW("fill", line_style, point_labels, hidden_keys,
                             "f:fill(P, %s)"),
    [CF__KEYS_POLYLINE] = DRAW("polyline", line_style, point_labels,
                                 closed_keys, "f:polyline(P, %s)"),
    [CF__KEYS_LINE] = DRAW("line", line_style, hidden_keys, NULL,
                             "f:line({0, 0}, {1, 1}, %s)"),
    [CF__KEYS_LABEL] = DRAW("label", text_style, hidden_keys, NULL,
                              "f:label({0, 0}, 'P', %s)"),
    [CF__KEYS_ARROW] = DRAW("arrow", line_style, arrow_label, hidden_keys,
                              "f:arrow({0, 0}, {1, 1}, %s)"),
    [CF__KEYS_ARROW_TO] = DRAW("arrow_to", line_style, arrow_label, hidden_keys,
                                 "f:arrow_to({0, 0}, {1, 1}, %s)"),
    [CF__KEYS_TANGENT] = DRAW("tangent", line_style, arrow_label,
                                scale_keys, "f:tangent(c, 0.5, %s)"),
    [CF__KEYS_KNOTS] = DRAW("knots", line_style, point_labels, NULL,
                              "f:knots(s, %s)"),
    [CF__KEYS_DECASTELJAU] = DRAW("decasteljau", line_style, net_keys,
                                    NULL, "f:decasteljau(c, 0.5, %s)"),
    [CF__KEYS_DEBOOR] = DRAW("deboor", line_style, net_keys, NULL,
                               "f:deboor(s, 0.5, %s)"),
    [CF__KEYS_SURFACE] = DRAW("surface", line_style, surface_keys,
                              point_labels, "f:surface(s, %s)"),
    [CF__KEYS_DECASTELJAU_SURFACE] = DRAW("decasteljau_surface", line_style,
                                          surface_scheme_keys, NULL,
                                          "f:decasteljau_surface(s, 0.5, "
                                          "0.5, %s)"),
    [CF__KEYS_PLOT] = DRAW("plot", line_style, plot_keys, NULL,
                             "f:plot(%s)"),
    [CF__KEYS_FUNC] = DRAW("func", line_style, NULL, NULL,
                             "f:func(math.sin, 0, 1, %s)"),
    [CF__KEYS_GRAPH] = DRAW("graph", line_style, NULL, NULL,
                              "f:graph(c, %s)"),
    [CF__KEYS_BASIS] = DRAW("basis", line_style, NULL, NULL,
                              "f:basis(s, 0, 2, %s)"),
    [CF__KEYS_BERNSTEIN] = DRAW("bernstein", line_style, NULL, NULL,
                                  "f:bernstein(3, 1, %s)"),
    [CF__KEYS_LABEL_STYLE] = METHOD("label_style", text_style, NULL, NULL,
                                    "f:points(P, { labels = 'P', "
                                    "label_style = %s })"),
    [CF__KEYS_POINT_STYLE] = METHOD("point", line_style, NULL, NULL,
                                    "f:decasteljau(c, 0.5, { point = %s })"),
    [CF__KEYS_LEGEND] = METHOD("legend", legend_keys, NULL, NULL,
                               "f:legend(%s)"),
    [CF__KEYS_INSET] = METHOD("inset", inset_keys, NULL, NULL,
                              "f:curve(c); f:inset(%s)"),
    [CF__KEYS_PANELS] = METHOD("panels", panels_keys, NULL, NULL,
                               "f:panels(%s)"),
    [CF__KEYS_SLIDER] = { "slider", "field", { slider_keys, NULL, NULL, NULL },
                          false, NULL, NULL, "slider(%s)" },
    [CF__KEYS_PARAM_POINTS] = { "points", "field",
                                { param_points_keys, NULL, NULL, NULL },
                                false, NULL, NULL, "points(%s)" },
    [CF__KEYS_CONSTRAIN] = METHOD("constrain", constrain_keys, NULL, NULL,
                                  "points{ name = 'Q', default = P, "
                                  "constrain = %s }"),
    [CF__KEYS_THEME] = { "theme", "option", { theme_keys, NULL, NULL, NULL },
                         false, NULL, NULL, "theme(%s)" },
    [CF__KEYS_BEZIER_SURFACE] = MAKER("bezier_surface", bezier_surface_keys,
                                      NULL, false, "bezier_surface(%s)"),
    [CF__KEYS_BSPLINE_SURFACE] = MAKER("bspline_surface",
                                       bspline_surface_keys, NULL, false,
                                       "bspline_surface(%s)"),
    [CF__KEYS_REVOLVE] = METHOD("revolve", revolve_keys, NULL, NULL,
                                "revolve(bspline{ degree = 1, points = "
                                "{ {1, 0, 0}, {1, 0, 1} } }, %s)"),
    [CF__KEYS_NURBS_SPHERE] = MAKER("nurbs_sphere", quadric_keys, NULL,
                                    false, "nurbs_sphere(%s)"),
    [CF__KEYS_NURBS_CYLINDER] = MAKER("nurbs_cylinder", quadric_keys, NULL,
                                      false, "nurbs_cylinder(%s)"),
    [CF__KEYS_NURBS_CONE] = MAKER("nurbs_cone", quadric_keys, NULL, false,
                                  "nurbs_cone(%s)"),
    [CF__KEYS_RULED] = MAKER("ruled", no_keys, NULL, true,
                             "ruled(%s)"),
    [CF__KEYS_BEZIER_TRIANGLE] = MAKER("bezier_triangle", triangle_keys,
                                       NULL, false, "bezier_triangle(%s)"),
    [CF__KEYS_COONS_PATCH] = MAKER("coons_patch", no_keys, NULL, true,
                                   "coons_patch(%s)"),
    [CF__KEYS_NURBS_TORUS] = MAKER("nurbs_torus", torus_keys, NULL, false,
                                   "nurbs_torus(%s)"),
    [CF__KEYS_INTERP_SURFACE] = MAKER("interpolate_surface",
                                      interp_surface_keys, NULL, false,
                                      "interpolate_surface(%s)"),
};

const char cf__lua_schema_prelude[] =
    "local f = figure{ name = 'schema' }\n"
    "local c = bezier{ {0, 0}, {1, 2}, {2, 0} }\n"
    "local s = bspline{ degree = 2, points = { {0, 0}, {1, 2}, {2, 0}, "
    "{3, 1} } }\n"
    "local P = { {0, 0}, {1, 2}, {2, 0} }\n";

const cf__lua_schema_t *
cf__lua_schema_at(cf__lua_keys_t i)
{
    return &schemas[(unsigned)i < CF__KEYS_COUNT_ ? i : CF__KEYS_NONE];
}
