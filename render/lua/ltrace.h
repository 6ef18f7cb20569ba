/*
** The message handler of figure scripts (for script.c): the message with
** the script's file and line put in front when a C function raised it
** (place_message), then the script's frames that led there -- at most 10
** from the top of the stack and 11 from its bottom, "..." between them,
** and a run of one frame repeated (recursion) as one line with a count.
*/
#ifndef CURVEFIG_RENDER_LUA_LTRACE_H
#define CURVEFIG_RENDER_LUA_LTRACE_H

#include <lauxlib.h>
#include <lua.h>

/* lua_pcall's message handler: replaces the message with the full one. */
int cf__lua_traceback(lua_State *L);

/* The deepest valid stack level, in O(n log n) calls of lua_getstack. */
int cf__lua_deepest_level(lua_State *L);

#endif
