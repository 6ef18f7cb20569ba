/*
** The sandboxed Lua state that runs a figure script: limited libraries, a
** memory budget shared by Lua and the curve library, an instruction budget,
** print to a chosen stream, and messages with the script's file and line.
*/
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include <lualib.h>

#include "lbspline.h"
#include "lcommon.h"
#include "lsurface.h"
#include "lfigure.h"
#include "lanimate.h"
#include "lparams.h"
#include "ltheme.h"
#include "lschema.h"
#include "lcount.h"
#include "ltrace.h"
#include "script.h"

/* Part of the budget kept in reserve until the rest is exhausted, so that
** the error can still be raised and the state closed within the budget:
** 1/16 of it, at most 1 MiB. */
#define RESERVE ((size_t)1 << 20)
#define HOOK_EVERY 10000
/* Memory a script allocates also counts against its instruction budget,
** one instruction per ALLOC_BYTES bytes: work done inside one instruction
** (s = s .. "x" copies all of s) is otherwise free, and a loop growing a
** string one byte at a time copies n^2/2 bytes in n iterations within a
** small memory budget -- 10 s for 2 million instructions, minutes under
** the default limit.  A figure script allocates a
** few MiB in all: well under 1 % of its budget. */
#define ALLOC_BYTES 16

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

static void count_hook(lua_State *L, lua_Debug *ar);

static void *
budget_alloc(void *ud, void *ptr, size_t osize, size_t nsize)
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
            lua_sethook(s->L, count_hook, LUA_MASKCOUNT, 1);
        }
    }
    return p;
}

/* A memory budget in the unit it was given in: "256 MiB", "512 KiB",
** "1000 bytes". */
static const char *
format_size(char buf[40], size_t bytes)
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
                        s->where, format_size(size, s->max_memory));
    else
        lua_pushfstring(L, "%sscript exceeded the instruction limit of %I "
                        "instructions", s->where,
                        (lua_Integer)s->budget.max_instructions);
    return lua_error(L);
}

static void
count_hook(lua_State *L, lua_Debug *ar)
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
        lua_sethook(L, count_hook, LUA_MASKCOUNT, 1);
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
static int
safe_call(lua_State *L)
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
static int
safe_xpcall(lua_State *L)
{
    if (lua_type(L, 2) == LUA_TFUNCTION) {
        lua_pushvalue(L, 2);
        lua_pushcclosure(L, run_handler, 1);
        lua_replace(L, 2);
    }
    return safe_call(L);
}

/* ---- charging work done in C -------------------------------------------- */

/* The budget's check (lcommon.h): past the instruction limit, or once any
** limit is hit, raise the limit's error with the hook armed at every
** instruction. */
static int
check_limits(lua_State *L)
{
    cf_script_t *s = script_of(L);
    if (s->budget.instructions > s->budget.max_instructions &&
        s->limit_hit == LIMIT_NONE)
        s->limit_hit = LIMIT_INSTRUCTIONS;
    if (s->limit_hit == LIMIT_NONE)
        return 0;
    note_position(s);
    lua_sethook(L, count_hook, LUA_MASKCOUNT, 1);
    return limit_error(L, s);
}

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

/* ---- the library allocator shares the budget ---------------------------- */

static void *
library_alloc(void *ud, void *ptr, size_t osize, size_t nsize)
{
    return budget_alloc(ud, ptr, osize, nsize);
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
    wrap_global(L, "pcall", safe_call);
    wrap_global(L, "xpcall", safe_xpcall);
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
                format_size(size, s->max_memory));
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
    s->budget.check = check_limits;
    s->budget.max_instructions = limits && limits->max_instructions
                                     ? limits->max_instructions
                                     : CF_SCRIPT_DEFAULT_INSTRUCTIONS;
    s->L = lua_newstate(budget_alloc, s);
    if (s->L == NULL) {
        cf_status_t st = s->limit_hit ? too_small(s, diag)
                                      : fail(diag, CF_STATUS_NO_MEMORY,
                                             "out of memory%s", NULL);
        cf__params_destroy(s->params);
        free(s);
        return st;
    }
    s->alloc.realloc = library_alloc;
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
    lua_sethook(s->L, count_hook, LUA_MASKCOUNT, HOOK_EVERY);
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

/* ---- running ------------------------------------------------------------ */

/* The message of a run, its n bytes kept whole: a NUL in it (error("a\0b"))
** is written \0 rather than ending the message there. */
static void
set_error_n(cf_script_t *s, const char *msg, size_t n)
{
    size_t nul = 0, k = 0;
    for (size_t i = 0; i < n; i++)
        nul += msg[i] == '\0';
    free(s->error);
    s->error = malloc(n + nul + 1);
    if (s->error == NULL)
        return;
    for (size_t i = 0; i < n; i++) {
        if (msg[i] == '\0') {
            s->error[k++] = '\\';
            s->error[k++] = '0';
        } else {
            s->error[k++] = msg[i];
        }
    }
    s->error[k] = '\0';
}

static void
set_error(cf_script_t *s, const char *msg)
{
    set_error_n(s, msg, strlen(msg));
}

static cf_status_t
finish(cf_script_t *s, int rc, const char *name)
{
    lua_State *L = s->L;
    if (rc == LUA_OK)
        return CF_STATUS_OK;
    if (s->limit_hit == LIMIT_MEMORY || rc == LUA_ERRMEM) {
        char buf[512], size[40];
        format_size(size, s->max_memory);
        if (s->where[0] != '\0')
            snprintf(buf, sizeof buf, "%sscript exceeded the memory limit "
                     "of %s", s->where, size);
        else
            snprintf(buf, sizeof buf, "%s: script exceeded the memory limit "
                     "of %s", name, size);
        set_error(s, buf);
    } else {
        size_t len;
        const char *msg = lua_tolstring(L, -1, &len);
        if (msg != NULL)
            set_error_n(s, msg, len);
        else
            set_error(s, "unknown error");
    }
    lua_settop(L, 0);
    return CF_STATUS_SCRIPT;
}

static cf_status_t
run_loaded(cf_script_t *s, int rc, const char *name)
{
    lua_State *L = s->L;
    cf_allocator_t prev;
    if (rc != LUA_OK)
        return finish(s, rc, name);
    lua_pushcfunction(L, cf__lua_traceback);
    lua_insert(L, -2);
    s->running = 1;
    cf_use_allocator(&s->alloc, &prev);
    rc = lua_pcall(L, 0, 0, -2);
    cf_use_allocator(&prev, NULL);
    s->running = 0;
    return finish(s, rc, name);
}

cf_status_t
cf_script_run_file(cf_script_t *s, const char *path)
{
    FILE *f;
    char *code;
    long len;
    cf_status_t st;
    if (s == NULL || path == NULL)
        return CF_STATUS_INVALID_ARG;
    f = fopen(path, "rb");
    if (f == NULL) {
        char buf[512];
        snprintf(buf, sizeof buf, "cannot open %s", path);
        set_error(s, buf);
        return CF_STATUS_IO;
    }
    if (fseek(f, 0, SEEK_END) != 0 || (len = ftell(f)) < 0 ||
        fseek(f, 0, SEEK_SET) != 0 ||
        (code = malloc((size_t)len + 1)) == NULL) {
        char buf[512];
        fclose(f);
        snprintf(buf, sizeof buf, "cannot read %s", path);
        set_error(s, buf);
        return CF_STATUS_IO;
    }
    if (fread(code, 1, (size_t)len, f) != (size_t)len) {
        char buf[512];
        fclose(f);
        free(code);
        snprintf(buf, sizeof buf, "cannot read %s", path);
        set_error(s, buf);
        return CF_STATUS_IO;
    }
    fclose(f);
    code[len] = '\0';
    st = cf_script_run_string(s, code, path);
    free(code);
    return st;
}

/* The chunk is handed to the parser one line at a time, so that the
** reader knows which line the parser has reached when it fails. */
typedef struct line_reader {
    const char *p;
    size_t left;
    int line;            /* lines handed out so far */
} line_reader;

static const char *
read_line(lua_State *L, void *ud, size_t *size)
{
    line_reader *rd = ud;
    const char *nl, *p = rd->p;
    (void)L;
    if (rd->left == 0) {
        *size = 0;
        return NULL;
    }
    nl = memchr(p, '\n', rd->left);
    *size = nl != NULL ? (size_t)(nl - p) + 1 : rd->left;
    rd->p += *size;
    rd->left -= *size;
    if (rd->line < INT_MAX)
        rd->line++;
    return p;
}

/* A load error at the top of the stack, below it the chunk name "@name":
** the parser's "C stack overflow" (source nested too deeply) carries no
** position; give it the chunk's short name (as the other syntax errors
** have it) and the line the parser had reached. */
static void
place_load_error(lua_State *L, int line)
{
    const char *msg = lua_tostring(L, -1);
    const char *src = "?";
    lua_Debug ar;
    if (msg == NULL)
        return;
    /* the short name of the chunk, the way Lua prints it: from an empty
    ** chunk loaded under the same name */
    if (luaL_loadbufferx(L, "", 0, lua_tostring(L, -2), "t") == LUA_OK) {
        lua_pushvalue(L, -1);
        if (lua_getinfo(L, ">S", &ar))
            src = ar.short_src;
    }
    /* stack: ..., name, msg, chunk or error */
    if (strncmp(msg, src, strlen(src)) != 0 || msg[strlen(src)] != ':') {
        if (strcmp(msg, "C stack overflow") == 0)
            lua_pushfstring(L, "%s:%d: C stack overflow (the script nests "
                            "too deeply)", src, line);
        else
            lua_pushfstring(L, "%s:%d: %s", src, line, msg);
        lua_replace(L, -3);
    }
    lua_pop(L, 1);
}

cf_status_t
cf_script_run_string(cf_script_t *s, const char *code, const char *name)
{
    lua_State *L;
    int rc;
    line_reader rd;
    if (s == NULL || code == NULL || name == NULL)
        return CF_STATUS_INVALID_ARG;
    L = s->L;
    if (code[0] == LUA_SIGNATURE[0]) {
        char buf[512];
        snprintf(buf, sizeof buf, "%s: binary (bytecode) chunks are not "
                 "allowed; give the script's source", name);
        set_error(s, buf);
        return CF_STATUS_SCRIPT;
    }
    /* A first line starting with '#' (#!/usr/bin/env curvefig) is skipped
    ** like lua.c does; its newline is kept so line numbers stay right. */
    if (code[0] == '#') {
        const char *nl = strchr(code, '\n');
        code = nl != NULL ? nl : "";
    }
    rd.p = code;
    rd.left = strlen(code);
    rd.line = 0;
    lua_pushfstring(L, "@%s", name);
    rc = lua_load(L, read_line, &rd, lua_tostring(L, -1), "t");
    if (rc != LUA_OK && rc != LUA_ERRMEM && s->limit_hit == LIMIT_NONE)
        place_load_error(L, rd.line > 0 ? rd.line : 1);
    lua_remove(L, -2);
    return run_loaded(s, rc, name);
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

const char *
cf_script_error(const cf_script_t *s)
{
    if (s == NULL || s->error == NULL)
        return "";
    return s->error;
}

/* ---- the figures -------------------------------------------------------- */

size_t
cf_script_figure_count(const cf_script_t *s)
{
    return s != NULL ? cf__lua_figure_count(s->L) : 0;
}

cf_figure_t *
cf_script_figure(const cf_script_t *s, size_t i)
{
    return s != NULL ? cf__lua_figure_at(s->L, i) : NULL;
}

const char *
cf_script_figure_name(const cf_script_t *s, size_t i)
{
    return s != NULL ? cf__lua_figure_string(s->L, i, 1) : "";
}

const char *
cf_script_figure_caption(const cf_script_t *s, size_t i)
{
    return s != NULL ? cf__lua_figure_string(s->L, i, 2) : "";
}

const char *
cf_script_figure_where(const cf_script_t *s, size_t i)
{
    return s != NULL ? cf__lua_figure_string(s->L, i, 3) : "";
}

const cf__anim_spec_t *
cf_script_animation(const cf_script_t *s)
{
    return s != NULL && s->animated ? &s->anim : NULL;
}

cf__params_t *
cf_script_params(const cf_script_t *s)
{
    return s != NULL ? s->params : NULL;
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
                 "--max-memory)", format_size(limit, s->max_memory));
    return true;
}
