/*
** The budgets of a figure script (script.h): the Lua state's allocator,
** shared with the curve library, that holds the memory budget and charges
** allocations to the instruction budget; the count hook; the limits'
** messages; pcall and xpcall that cannot catch a limit; and rendering
** inside the memory budget.
*/
#include <stdio.h>
#include <stdlib.h>

#include "lcount.h"
#include "script-private.h"

/* Memory a script allocates also counts against its instruction budget,
** one instruction per ALLOC_BYTES bytes: work done inside one instruction
** (s = s .. "x" copies all of s) is otherwise free, and a loop growing a
** string one byte at a time copies n^2/2 bytes in n iterations within a
** small memory budget -- 10 s for 2 million instructions, minutes under
** the default limit.  A figure script allocates a
** few MiB in all: well under 1 % of its budget. */
#define ALLOC_BYTES 16

/* ---- the budgets -------------------------------------------------------- */

/* Remember the script's current file and line in s->where.  Only reads
** the call stack (lua_getstack and lua_getinfo "Sl" allocate nothing), so
** it may run inside the allocator. */
static void
note_position(cf_script_t *s)
{
    lua_Debug ar;
    if (s->L == NULL || !s->running)
        return;
    for (int level = 0; lua_getstack(s->L, level, &ar); level++) {
        if (!lua_getinfo(s->L, "Sl", &ar))
            break;
        if (ar.source[0] == '@' && ar.currentline > 0) {
            snprintf(s->where, sizeof s->where, "%s:%d: ", ar.short_src,
                     ar.currentline);
            return;
        }
    }
}

void *
cf__script_budget_alloc(void *ud, void *ptr, size_t osize, size_t nsize)
{
    cf_script_t *s = ud;
    size_t old = ptr != NULL ? osize : 0;
    size_t cap = s->max_memory - (s->limit_hit ? 0 : s->reserve);
    void *p;
    if (nsize == 0) {
        free(ptr);
        /* a block made before the budget was installed is not counted */
        s->used = old <= s->used ? s->used - old : 0;
        return NULL;
    }
    if (nsize > old && (nsize - old > cap || s->used > cap - (nsize - old))) {
        s->refused++;
        if (s->limit_hit == LIMIT_NONE) {
            s->limit_hit = LIMIT_MEMORY;
            s->budget.memory_exceeded = true;
            note_position(s);
        }
        return NULL;
    }
    p = realloc(ptr, nsize);
    if (p == NULL)
        return NULL;
    s->used = (old <= s->used ? s->used - old : 0) + nsize;
    if (nsize > old) {
        s->budget.instructions += (nsize - old) / ALLOC_BYTES;
        /* over the limit: the hook raises it at the next instruction, not
        ** up to HOOK_EVERY instructions (and as many allocations) later */
        if (s->budget.instructions > s->budget.max_instructions &&
            s->limit_hit == LIMIT_NONE && s->running) {
            s->limit_hit = LIMIT_INSTRUCTIONS;
            note_position(s);
            lua_sethook(s->L, cf__script_count_hook, LUA_MASKCOUNT, 1);
        }
    }
    return p;
}

/* A memory budget in the unit it was given in: "256 MiB", "512 KiB",
** "1000 bytes". */
const char *
cf__script_format_size(char buf[40], size_t bytes)
{
    if (bytes >= ((size_t)1 << 20) && bytes % ((size_t)1 << 20) == 0)
        snprintf(buf, 40, "%zu MiB", bytes >> 20);
    else if (bytes >= 1024 && bytes % 1024 == 0)
        snprintf(buf, 40, "%zu KiB", bytes >> 10);
    else
        snprintf(buf, 40, "%zu bytes", bytes);
    return buf;
}

/* The message of an exhausted budget, at the position last seen by the
** hook (an allocation failure cannot ask Lua where it happened). */
static int
limit_error(lua_State *L, cf_script_t *s)
{
    char size[40];
    if (s->limit_hit == LIMIT_MEMORY)
        lua_pushfstring(L, "%sscript exceeded the memory limit of %s",
                        s->where, cf__script_format_size(size, s->max_memory));
    else
        lua_pushfstring(L, "%sscript exceeded the instruction limit of %I "
                        "instructions", s->where,
                        (lua_Integer)s->budget.max_instructions);
    return lua_error(L);
}

void
cf__script_count_hook(lua_State *L, lua_Debug *ar)
{
    void *ud;
    cf_script_t *s;
    lua_getallocf(L, &ud);
    s = ud;
    if (lua_getinfo(L, "Sl", ar) && ar->source[0] == '@' &&
        ar->currentline > 0)
        snprintf(s->where, sizeof s->where, "%s:%d: ", ar->short_src,
                 ar->currentline);
    s->budget.instructions += HOOK_EVERY;
    if (s->budget.instructions > s->budget.max_instructions &&
        s->limit_hit == LIMIT_NONE)
        s->limit_hit = LIMIT_INSTRUCTIONS;
    if (s->limit_hit != LIMIT_NONE) {
        /* armed for good: every later instruction raises it again */
        lua_sethook(L, cf__script_count_hook, LUA_MASKCOUNT, 1);
        limit_error(L, s);
    }
}

static cf_script_t *
script_of(lua_State *L)
{
    void *ud;
    lua_getallocf(L, &ud);
    return ud;
}

/* ---- replaced base functions -------------------------------------------- */

/* pcall and xpcall that do not catch a limit: once a budget is exhausted
** the script ends, whatever it does. */
int
cf__script_safe_call(lua_State *L)
{
    cf_script_t *s = script_of(L);
    int n = lua_gettop(L);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, n, LUA_MULTRET);
    if (s->limit_hit != LIMIT_NONE)
        return limit_error(L, s);
    if (!lua_toboolean(L, 1))
        cf__lua_charge_unwind(L);
    return lua_gettop(L);
}

/* The script's message handler, wrapped: once a limit is hit the error
** passes through unchanged and the handler is not run.  Lua runs a
** handler for an error raised inside the count hook with the hooks off,
** where a loop in it would never be stopped. */
static int
run_handler(lua_State *L)
{
    cf_script_t *s = script_of(L);
    if (s->limit_hit != LIMIT_NONE) {
        lua_settop(L, 1);
        return 1;
    }
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
    if (s->limit_hit != LIMIT_NONE)
        return limit_error(L, s);
    return lua_gettop(L);
}

/* xpcall(f, msgh, ...) with msgh wrapped by run_handler. */
int
cf__script_safe_xpcall(lua_State *L)
{
    if (lua_type(L, 2) == LUA_TFUNCTION) {
        lua_pushvalue(L, 2);
        lua_pushcclosure(L, run_handler, 1);
        lua_replace(L, 2);
    }
    return cf__script_safe_call(L);
}

/* ---- charging work done in C -------------------------------------------- */

/* The budget's check (lcommon.h): past the instruction limit, or once any
** limit is hit, raise the limit's error with the hook armed at every
** instruction. */
int
cf__script_check_limits(lua_State *L)
{
    cf_script_t *s = script_of(L);
    if (s->budget.instructions > s->budget.max_instructions &&
        s->limit_hit == LIMIT_NONE)
        s->limit_hit = LIMIT_INSTRUCTIONS;
    if (s->limit_hit == LIMIT_NONE)
        return 0;
    note_position(s);
    lua_sethook(L, cf__script_count_hook, LUA_MASKCOUNT, 1);
    return limit_error(L, s);
}
/* ---- the library allocator shares the budget ---------------------------- */

void *
cf__script_library_alloc(void *ud, void *ptr, size_t osize, size_t nsize)
{
    return cf__script_budget_alloc(ud, ptr, osize, nsize);
}

/* ---- rendering inside the budget ---------------------------------------- */

void
cf_script_budget_begin(const cf_script_t *s, cf_script_scope_t *scope)
{
    scope->refused = s->refused;
    cf_use_allocator(&s->alloc, &scope->prev);
}

bool
cf_script_budget_end(const cf_script_t *s, cf_script_scope_t *scope,
                     char *msg, size_t size)
{
    char limit[40];
    cf_use_allocator(&scope->prev, NULL);
    if (s->refused == scope->refused)
        return false;
    if (msg != NULL && size > 0)
        snprintf(msg, size, "rendering exceeded the memory limit of %s (the "
                 "script and the rendering of its figures share it: "
                 "--max-memory)",
                 cf__script_format_size(limit, s->max_memory));
    return true;
}
