/*
** The names the figure language knows, and the one check of every table a
** script passes by name.
**
** Each function that takes a table of named entries has a schema
** (render/lua/lkeys.c): its keys, for an enumerated value the names it may
** take, for a nested table (label_style, point, ...) the schema of that
** table.  cf__lua_check_table refuses, before the function reads anything:
**
**   an unknown key        bspline: unknown field 'knot' (did you mean
**                         'knots'?)
**   an unknown name       interpolate: method "natral" is unknown (did you
**                         mean "natural"?)
**   an entry without a    curve: option 1 has no name; options are named,
**   name                  e.g. { color = "red" }
**
** (the script's file and line are put in front of every message), and the
** same for every nested table.  The missing-name handlers installed by
** cf__lua_guard_names (methods of the classes, functions of the
** libraries, the sandbox's globals) use the same nearest-name search:
** "figure has no method 'decastlejau' (did you mean 'decasteljau'?)".
*/
#ifndef CURVEFIG_RENDER_LUA_LSCHEMA_H
#define CURVEFIG_RENDER_LUA_LSCHEMA_H

#include <stdbool.h>
#include <stddef.h>

#include <lauxlib.h>
#include <lua.h>

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

typedef struct cf__lua_schema {
    const char *fn;               /* the function, as messages name it */
    const char *noun;             /* "field" (constructors), "option" */
    const cf__lua_key_t *keys[3]; /* key lists, each ended by { NULL } */
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

/* Check the table at idx against schema k (nil or none: nothing to
** check); raises the error described above. */
void cf__lua_check_table(lua_State *L, int idx, cf__lua_keys_t k);

/* Damerau-Levenshtein distance (adjacent transpositions count one),
** capped at 100. */
int cf__lua_distance(const char *a, const char *b);
/* The name of names[0..n-1] nearest to s, if near enough to suggest (at
** most one edit per three letters, at least one), else NULL. */
const char *cf__lua_nearest(const char *s, const char *const *names,
                            size_t n);

/* Install the missing-name handlers: on the method tables of the classes,
** on the library tables (math, string, table, utf8, knots, conic) and on
** the global table (a missing global is an error, the nearest global or
** local of the calling function suggested). */
void cf__lua_guard_names(lua_State *L);

/* The check of self (argument 1) of a method of class tname
** ("curvefig.figure"), shown as shown ("figure"): when it is not one,
** "curve: call a method with ':' (f:curve(...)), not '.'" if the method
** was called as a field (f.curve(c)), luaL_checkudata's message
** otherwise. */
void *cf__lua_check_self(lua_State *L, const char *tname, const char *shown);

#endif
