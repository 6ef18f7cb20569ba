/*
** The names the figure language knows, and the one check of every table a
** script passes by name.
**
** Each function that takes a table of named entries has a schema
** (lkeys.h, the lists in lkeys.c): its keys, for an enumerated value the
** names it may take, for a nested table (label_style, point, ...) the
** schema of that table.  cf__lua_check_table refuses, before the function reads anything:
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
** libraries, the sandbox's globals) use the same nearest-name search (cf_nearest_name):
** "figure has no method 'decastlejau' (did you mean 'decasteljau'?)".
*/
#ifndef CURVEFIG_RENDER_LUA_LSCHEMA_H
#define CURVEFIG_RENDER_LUA_LSCHEMA_H

#include <stdbool.h>
#include <stddef.h>

#include <lauxlib.h>
#include <lua.h>

#include "lkeys.h"

/* Check the table at idx against schema k (nil or none: nothing to
** check); raises the error described above. */
void cf__lua_check_table(lua_State *L, int idx, cf__lua_keys_t k);


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
