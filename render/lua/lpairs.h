/*
** The sandbox's pairs (lpairs.c): the keys of a table without __pairs in
** a fixed order -- numbers ascending, strings in byte order, false, true,
** then other keys in Lua's order -- so that a script drawing in a pairs
** loop draws the same figure at every run.
*/
#ifndef CURVEFIG_RENDER_LUA_LPAIRS_H
#define CURVEFIG_RENDER_LUA_LPAIRS_H

#include <lua.h>

/* Install it as the global pairs (script.c's sandbox opener). */
void cf__lua_open_pairs(lua_State *L);

/* Push a new sequence of the keys of the table at idx in that order (the
** work charged to the instruction budget): for the checks of the binding
** that name the first bad key, so that the message is the same at every
** run. */
void cf__lua_sorted_keys(lua_State *L, int idx);

#endif
