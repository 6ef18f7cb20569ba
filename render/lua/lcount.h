/*
** The sandbox's counted library functions (lcount.c) and the part of the
** script's budget they charge (script-budget.c).
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

/* Charge steps to the instructions of the script whose state L is (its
** budget, lcommon.h); past its limit raise the limit's error.  Returns 0
** when within it. */
int cf__lua_charge(lua_State *L, unsigned long long steps);
/* cf_nearest_name (the suggestion of an error message) with its work
** charged first: a script that catches the error of a misspelt name in a
** loop pays for the comparisons with every candidate. */
const char *cf__lua_nearest_name(lua_State *L, const char *key,
                                 const char *const *names, size_t n);
/* Charge what a caught error cost Lua: a walk over the call stack. */
void cf__lua_charge_unwind(lua_State *L);

#endif
