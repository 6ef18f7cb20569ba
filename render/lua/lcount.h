/*
** The sandbox's counted library functions (lcount.c) and the part of the
** script's budget they charge (script.c).
**
** Some functions of Lua's libraries loop inside one C call, where the
** instruction hook cannot see them: string.rep("", 1e13),
** table.move({}, 1, 1e12, 1, {}), table.insert with a __len of 1e15, a
** plain string.find of "aaa...ab" in "aaa...a", print of gigabytes, a
** backtracking pattern.  The sandbox replaces each by a version that
** charges its work to the instruction budget before or while it runs
** (one instruction per iteration of such a loop, per step of a pattern
** search, per 16 bytes printed), so the limit stops them too.
*/
#ifndef CURVEFIG_RENDER_LUA_LCOUNT_H
#define CURVEFIG_RENDER_LUA_LCOUNT_H

#include <stddef.h>
#include <stdio.h>

#include <lua.h>

/* Install the counted functions in the state's string and table
** libraries and as print (script.c's sandbox opener). */
void cf__lua_open_counted(lua_State *L);

/* ---- script.c: the budget of the script whose state L is -------------- */

/* Add steps to the instructions the script has run; past its limit raise
** the limit's error (the hook then raises it again at every instruction).
** Returns 0 when within it. */
int cf__script_charge(lua_State *L, unsigned long long steps);
/* Instructions left before the limit. */
unsigned long long cf__script_left(lua_State *L);
/* Charge what a caught error cost Lua: a walk over the call stack. */
void cf__script_charge_unwind(lua_State *L);
/* print is about to write bytes: charge them and return how many of them
** fit in the script's output limit (CF_SCRIPT_MAX_PRINT). */
size_t cf__script_print_room(lua_State *L, size_t bytes);
/* Where print writes. */
FILE *cf__script_out(lua_State *L);

#endif
