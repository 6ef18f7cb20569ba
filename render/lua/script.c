/*
** The sandboxed Lua state that runs a figure script, set up: limited
** libraries (no file access, text chunks only, no finalisers, math.random
** seeded by the run), print to a chosen stream, the memory and instruction
** budgets installed (kept by script-budget.c), the tool's settings.
** Running a chunk and its results: script-run.c.
*/
#include <stdlib.h>
#include <string.h>

#include <lualib.h>

#include "lcount.h"
#include "lpairs.h"
#include "lfigure.h"
#include "lschema.h"
#include "ltheme.h"
#include "params.h"
#include "script-private.h"

/* Part of the budget kept in reserve until the rest is exhausted, so that
** the error can still be raised and the state closed within the budget:
** 1/16 of it, at most 1 MiB. */
#define RESERVE ((size_t)1 << 20)

static cf_status_t
fail(cf_diag_t *diag, cf_status_t status, const char *fmt, const char *arg)
{
    if (diag != NULL && diag->status == CF_STATUS_OK) {
        diag->status = status;
        diag->index = -1;
        snprintf(diag->msg, sizeof diag->msg, fmt, arg ? arg : "");
    }
    return status;
}

/* ---- the sandbox's base functions ------------------------------------- */

/* load of text chunks only. */
static int
safe_load(lua_State *L)
{
    const char *mode = luaL_optstring(L, 3, "t");
    size_t len;
    const char *chunk = lua_tolstring(L, 1, &len);
    if (strchr(mode, 'b') != NULL ||
        (chunk != NULL && len > 0 && chunk[0] == LUA_SIGNATURE[0]))
        return luaL_error(L, "load: binary (bytecode) chunks are not "
                          "allowed in figure scripts");
    lua_settop(L, 4);
    lua_pushliteral(L, "t");
    lua_replace(L, 3);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, 4, LUA_MULTRET);
    return lua_gettop(L);
}

/* setmetatable without finalisers: Lua runs a __gc metamethod with the
** hooks off, so a loop in it would escape the instruction limit (and an
** object is marked for finalisation by any __gc field present when its
** metatable is set, even a placeholder replaced later). */
static int
safe_setmetatable(lua_State *L)
{
    int t = lua_type(L, 2);
    luaL_checktype(L, 1, LUA_TTABLE);
    luaL_argexpected(L, t == LUA_TNIL || t == LUA_TTABLE, 2, "nil or table");
    if (t == LUA_TTABLE) {
        lua_pushliteral(L, "__gc");
        if (lua_rawget(L, 2) != LUA_TNIL)
            return luaL_error(L, "setmetatable: __gc is not allowed in "
                              "figure scripts (a finaliser would run "
                              "outside the instruction limit)");
        lua_pop(L, 1);
    }
    if (luaL_getmetafield(L, 1, "__metatable") != LUA_TNIL)
        return luaL_error(L, "cannot change a protected metatable");
    lua_settop(L, 2);
    lua_setmetatable(L, 1);
    return 1;
}

static void
wrap_global(lua_State *L, const char *name, lua_CFunction f)
{
    lua_getglobal(L, name);
    lua_pushcclosure(L, f, 1);
    lua_setglobal(L, name);
}

static void
remove_field(lua_State *L, const char *table, const char *name)
{
    if (table != NULL) {
        lua_getglobal(L, table);
        lua_pushnil(L);
        lua_setfield(L, -2, name);
        lua_pop(L, 1);
    } else {
        lua_pushnil(L);
        lua_setglobal(L, name);
    }
}

#define SEED_KEY "curvefig.seed"

/* math.randomseed: without an argument, the run's seed (registry) rather
** than the clock's; with one, Lua's (upvalue 1). */
static int
seeded_randomseed(lua_State *L)
{
    if (lua_gettop(L) == 0)
        lua_getfield(L, LUA_REGISTRYINDEX, SEED_KEY);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
    return lua_gettop(L);
}

/* Seed math.random with seed (and keep it for math.randomseed()). */
static void
seed_random(lua_State *L, lua_Integer seed)
{
    lua_pushinteger(L, seed);
    lua_setfield(L, LUA_REGISTRYINDEX, SEED_KEY);
    lua_getglobal(L, LUA_MATHLIBNAME);
    lua_getfield(L, -1, "randomseed");
    lua_pushinteger(L, seed);
    lua_call(L, 1, 0);
    lua_pop(L, 1);
}

static int
open_sandbox(lua_State *L)
{
    static const luaL_Reg libs[] = {
        { LUA_GNAME, luaopen_base },
        { LUA_MATHLIBNAME, luaopen_math },
        { LUA_STRLIBNAME, luaopen_string },
        { LUA_TABLIBNAME, luaopen_table },
        { LUA_UTF8LIBNAME, luaopen_utf8 },
    };
    for (size_t i = 0; i < sizeof libs / sizeof libs[0]; i++) {
        luaL_requiref(L, libs[i].name, libs[i].func, 1);
        lua_pop(L, 1);
    }
    lua_getglobal(L, LUA_MATHLIBNAME);
    lua_getfield(L, -1, "randomseed");
    lua_pushcclosure(L, seeded_randomseed, 1);
    lua_setfield(L, -2, "randomseed");
    lua_pop(L, 1);
    seed_random(L, CF_SCRIPT_DEFAULT_SEED);
    remove_field(L, NULL, "dofile");
    remove_field(L, NULL, "loadfile");
    remove_field(L, NULL, "require");
    remove_field(L, LUA_STRLIBNAME, "dump");
    cf__lua_open_counted(L);
    cf__lua_open_pairs(L);
    wrap_global(L, "pcall", cf__script_safe_call);
    wrap_global(L, "xpcall", cf__script_safe_xpcall);
    wrap_global(L, "load", safe_load);
    lua_pushcfunction(L, safe_setmetatable);
    lua_setglobal(L, "setmetatable");
    cf__lua_open_language(L);
    cf__lua_guard_names(L);
    return 0;
}

static cf_status_t
too_small(const cf_script_t *s, cf_diag_t *diag)
{
    char size[40];
    return fail(diag, CF_STATUS_NO_MEMORY, "the memory limit of %s is too "
                "small for the sandbox itself",
                cf__script_format_size(size, s->max_memory));
}

cf_status_t
cf_script_create(const cf_script_limits_t *limits, FILE *out,
                 cf_script_t **script, cf_diag_t *diag)
{
    cf_script_t *s;
    cf_allocator_t prev;
    int rc;
    if (script == NULL)
        return fail(diag, CF_STATUS_INVALID_ARG, "script is NULL%s", NULL);
    *script = NULL;
    s = calloc(1, sizeof *s);
    if (s == NULL)
        return fail(diag, CF_STATUS_NO_MEMORY, "out of memory%s", NULL);
    s->budget.out = out != NULL ? out : stdout;
    s->params = cf__params_create();
    if (s->params == NULL) {
        free(s);
        return fail(diag, CF_STATUS_NO_MEMORY, "out of memory%s", NULL);
    }
    s->max_memory = limits && limits->max_memory ? limits->max_memory
                                                 : CF_SCRIPT_DEFAULT_MEMORY;
    s->reserve = s->max_memory / 16 < RESERVE ? s->max_memory / 16 : RESERVE;
    s->budget.check = cf__script_check_limits;
    s->budget.max_instructions = limits && limits->max_instructions
                                     ? limits->max_instructions
                                     : CF_SCRIPT_DEFAULT_INSTRUCTIONS;
    s->L = lua_newstate(cf__script_budget_alloc, s);
    if (s->L == NULL) {
        cf_status_t st = s->limit_hit ? too_small(s, diag)
                                      : fail(diag, CF_STATUS_NO_MEMORY,
                                             "out of memory%s", NULL);
        cf__params_destroy(s->params);
        free(s);
        return st;
    }
    s->alloc.realloc = cf__script_library_alloc;
    s->alloc.ud = s;
    lua_pushcfunction(s->L, open_sandbox);
    cf_use_allocator(&s->alloc, &prev);
    rc = lua_pcall(s->L, 0, 0, 0);
    cf_use_allocator(&prev, NULL);
    /* the budget must hold the sandbox without touching the reserve */
    if (rc != LUA_OK || s->limit_hit) {
        cf_status_t st = s->limit_hit
                             ? too_small(s, diag)
                             : fail(diag, CF_STATUS_NO_MEMORY,
                                    "cannot set up the sandbox: %s",
                                    lua_tostring(s->L, -1));
        cf_script_destroy(s);
        return st;
    }
    lua_sethook(s->L, cf__script_count_hook, LUA_MASKCOUNT, HOOK_EVERY);
    cf__lua_set_params(s->L, s->params);
    cf__lua_set_animation(s->L, &s->anim, &s->animated);
    *script = s;
    return CF_STATUS_OK;
}

void
cf_script_destroy(cf_script_t *s)
{
    if (s == NULL)
        return;
    lua_close(s->L);
    cf__params_destroy(s->params);
    free(s->error);
    free(s);
}

void
cf_script_set_labels(cf_script_t *s, bool enabled)
{
    if (s == NULL)
        return;
    lua_pushboolean(s->L, !enabled);
    lua_setfield(s->L, LUA_REGISTRYINDEX, CF__LUA_NO_LABELS);
}

void
cf_script_set_fonts(cf_script_t *s, const char *family, double size_bp)
{
    if (s != NULL)
        cf__lua_set_tool_fonts(s->L, family, size_bp);
}

void
cf_script_set_page(cf_script_t *s, double width_bp, double height_bp)
{
    if (s != NULL)
        cf__lua_set_tool_page(s->L, width_bp, height_bp);
}

void
cf_script_set_seed(cf_script_t *s, long long seed)
{
    if (s != NULL)
        seed_random(s->L, (lua_Integer)seed);
}
