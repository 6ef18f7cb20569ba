/*
** Internals of the script sandbox (script.h), shared by its files:
** script.c sets the sandbox up, script-budget.c keeps its memory and
** instruction budgets, script-run.c loads and runs a chunk and holds what
** the run left (its message, its figures).
*/
#ifndef CURVEFIG_RENDER_LUA_SCRIPT_PRIVATE_H
#define CURVEFIG_RENDER_LUA_SCRIPT_PRIVATE_H

#include <stdbool.h>
#include <stddef.h>

#include "lanimate.h"
#include "lcommon.h"
#include "lparams.h"
#include "script.h"

/* The count hook runs every HOOK_EVERY instructions (once the budget is
** exhausted, at every one). */
#define HOOK_EVERY 10000

enum { LIMIT_NONE, LIMIT_MEMORY, LIMIT_INSTRUCTIONS };

struct cf_script {
    cf__lua_budget_t budget; /* first: the bindings read it (lcommon.h) */
    lua_State *L;
    size_t used, max_memory, reserve;
    int limit_hit;
    unsigned long refused;  /* allocations the budget refused */
    int running;       /* a script is running (the stack can be read) */
    char where[160];   /* "file:line:" last seen by the hook, or "" */
    cf_allocator_t alloc;   /* the budget, current while the script runs */
    char *error;
    cf__params_t *params;   /* the sliders and points it declares */
    cf__anim_spec_t anim;   /* its animate{} (render/lua/lanimate.c) */
    bool animated;          /* animate{} was called */
};

/* ---- the budgets (script-budget.c) ------------------------------------- */

/* The Lua state's allocator (ud is the script): refuses what would pass
** the memory budget, charges what it grants to the instruction budget. */
void *cf__script_budget_alloc(void *ud, void *ptr, size_t osize,
                              size_t nsize);
/* The same as the curve library's allocator while the script runs. */
void *cf__script_library_alloc(void *ud, void *ptr, size_t osize,
                               size_t nsize);
/* The instruction count hook: raises the limit's error once a budget is
** exhausted. */
void cf__script_count_hook(lua_State *L, lua_Debug *ar);
/* The budget's check for work done in C (cf__lua_budget_t.check). */
int cf__script_check_limits(lua_State *L);
/* pcall and xpcall that do not catch a limit (upvalue 1: Lua's own). */
int cf__script_safe_call(lua_State *L);
int cf__script_safe_xpcall(lua_State *L);
/* A memory budget in the unit it was given in: "256 MiB", "512 KiB",
** "1000 bytes". */
const char *cf__script_format_size(char buf[40], size_t bytes);

#endif
