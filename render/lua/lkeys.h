/*
** The schemas of the named tables of the figure language: which keys each
** function takes, the names of its enumerated values, the schemas of its
** nested tables (the lists are in lkeys.c; the check that uses them is
** lschema.h's).
*/
#ifndef CURVEFIG_RENDER_LUA_LKEYS_H
#define CURVEFIG_RENDER_LUA_LKEYS_H

#include <stdbool.h>

/* The tables the language takes, one schema each (index into the list of
** cf__lua_schema_at). */
typedef enum cf__lua_keys {
    CF__KEYS_NONE = 0,
    CF__KEYS_FIGURE,
    CF__KEYS_BEZIER,
    CF__KEYS_BSPLINE,
    CF__KEYS_COONS,
    CF__KEYS_NURBS_ARC,
    CF__KEYS_INTERPOLATE,
    CF__KEYS_APPROXIMATE,
    CF__KEYS_COONS_CHAIN,
    CF__KEYS_OFFSET,
    CF__KEYS_CURVE,
    CF__KEYS_POLYGON,
    CF__KEYS_POINTS,
    CF__KEYS_HULL,
    CF__KEYS_FILL,
    CF__KEYS_POLYLINE,
    CF__KEYS_LINE,
    CF__KEYS_LABEL,
    CF__KEYS_ARROW,
    CF__KEYS_ARROW_TO,
    CF__KEYS_TANGENT,
    CF__KEYS_KNOTS,
    CF__KEYS_DECASTELJAU,
    CF__KEYS_DEBOOR,
    CF__KEYS_PLOT,
    CF__KEYS_FUNC,
    CF__KEYS_GRAPH,
    CF__KEYS_BASIS,
    CF__KEYS_BERNSTEIN,
    CF__KEYS_LABEL_STYLE,   /* nested: label_style = { ... } */
    CF__KEYS_POINT_STYLE,   /* nested: point = { ... } of the nets */
    CF__KEYS_LEGEND,
    CF__KEYS_INSET,
    CF__KEYS_PANELS,
    CF__KEYS_SLIDER,
    CF__KEYS_PARAM_POINTS,  /* points{...}, a draggable point list */
    CF__KEYS_CONSTRAIN,     /* nested: constrain = { ... } of points{} */
    CF__KEYS_THEME,
    CF__KEYS_BEZIER_SURFACE,
    CF__KEYS_BSPLINE_SURFACE,
    CF__KEYS_REVOLVE,
    CF__KEYS_NURBS_SPHERE,
    CF__KEYS_NURBS_TORUS,
    CF__KEYS_NURBS_CYLINDER,
    CF__KEYS_NURBS_CONE,
    CF__KEYS_RULED,
    CF__KEYS_COONS_PATCH,
    CF__KEYS_BEZIER_TRIANGLE,
    CF__KEYS_INTERP_SURFACE,
    CF__KEYS_REDUCE,          /* c:reduce{...} of a Bézier curve */
    CF__KEYS_REDUCE_BSPLINE,  /* s:reduce{...} of a B-spline */
    CF__KEYS_SURFACE,         /* f:surface(s, {...}) */
    CF__KEYS_DECASTELJAU_SURFACE, /* and f:triangle_scheme */
    CF__KEYS_COUNT_
} cf__lua_keys_t;

typedef struct cf__lua_key {
    const char *name;
    const char *const *values;  /* the names of an enumerated value (a
                                   string, or a list of strings), or NULL */
    cf__lua_keys_t table;       /* a nested table's schema, or NONE */
    const char *also;           /* what else the value may be, for the
                                   message ("{on, off, ...} in bp"), or NULL */
} cf__lua_key_t;

#define CF__LUA_KEY_LISTS 4

typedef struct cf__lua_schema {
    const char *fn;               /* the function, as messages name it */
    const char *noun;             /* "field" (constructors), "option" */
    /* key lists, each ended by { NULL }; the last the overlay key
    ** (visible) of a method that draws, else NULL */
    const cf__lua_key_t *keys[CF__LUA_KEY_LISTS];
    bool positional;              /* entries 1..n (a list) are taken too */
    /* keys that belong to another function: refused with this hint */
    const cf__lua_key_t *elsewhere;
    const char *hint;
    /* a call passing the table in place of the first "%s", after the
    ** prelude cf__lua_schema_prelude (the tests build calls from it) */
    const char *example;
} cf__lua_schema_t;

/* Schema i, 1 <= i < CF__KEYS_COUNT_. */
const cf__lua_schema_t *cf__lua_schema_at(cf__lua_keys_t i);
/* Lua code defining f (a figure), c (a Bézier), s (a B-spline) and P (a
** list of points), for the examples. */
extern const char cf__lua_schema_prelude[];

#endif
