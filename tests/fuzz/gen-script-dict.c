/*
** The script fuzzer's dictionary (libFuzzer's -dict format), generated from
** the figure language itself so that it names every function, method and
** key the day it is added:
**
**   - every global function the binding adds to Lua's as "name(" and
**     "name{", every function of a library table it adds as "lib.name("
**     (read from the global table after the binding has opened, before
**     its name guards lock the tables);
**   - every method of figures, Bézier curves and B-splines as ":name(";
**   - every key of every schema (render/lua/lkeys.c) as "key = ", and
**     every name of an enumerated value as "\"name\"";
**   - Lua syntax and the boundary values that the language must refuse or
**     survive (0, -1, NaN, Inf, huge and tiny numbers, empty tables).
**
** Each entry once; the names sorted (Lua's table order is not stable),
** then the syntax in its own order.  Fails when a list is empty or a
** schema's function is not among the functions found (the walk and the
** binding disagree).
**
** usage: gen-script-dict OUTPUT
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>

#include "lcommon.h"
#include "lkeys.h"

#define MAX_ENTRIES 4096

static char *entries[MAX_ENTRIES];
static size_t nentries;

static void
add(const char *a, const char *b, const char *c)
{
    size_t n = strlen(a) + strlen(b) + strlen(c) + 1;
    char *e = malloc(n);
    if (e == NULL || nentries == MAX_ENTRIES) {
        fprintf(stderr, "gen-script-dict: too many entries\n");
        exit(1);
    }
    snprintf(e, n, "%s%s%s", a, b, c);
    for (size_t i = 0; i < nentries; i++)
        if (strcmp(entries[i], e) == 0) {
            free(e);
            return;
        }
    entries[nentries++] = e;
}

/* The string keys of the table at the top of the stack whose values have
** type `type`, each added as prefix key suffix; returns how many. */
static size_t
add_keys(lua_State *L, int type, const char *prefix, const char *suffix)
{
    size_t n = 0;
    lua_pushnil(L);
    while (lua_next(L, -2) != 0) {
        if (lua_type(L, -2) == LUA_TSTRING && lua_type(L, -1) == type) {
            const char *k = lua_tostring(L, -2);
            if (k[0] != '_') {
                add(prefix, k, suffix);
                n++;
            }
        }
        lua_pop(L, 1);
    }
    return n;
}

static size_t
methods(lua_State *L, const char *tname)
{
    size_t n = 0;
    luaL_getmetatable(L, tname);
    if (lua_getfield(L, -1, "__index") == LUA_TTABLE)
        n = add_keys(L, LUA_TFUNCTION, ":", "(");
    lua_pop(L, 2);
    return n;
}

/* The globals the binding added to Lua's (the table at index `lua` holds
** Lua's own): each function as "name(" and "name{", each function of a
** new library table as "lib.name(". */
static size_t
globals(lua_State *L, int lua)
{
    size_t n = 0;
    lua_pushglobaltable(L);
    lua_pushnil(L);
    while (lua_next(L, -2) != 0) {
        const char *k = lua_type(L, -2) == LUA_TSTRING
                            ? lua_tostring(L, -2) : NULL;
        int seen = k != NULL && lua_getfield(L, lua, k) != LUA_TNIL;
        lua_pop(L, 1);
        if (k == NULL || seen) {
            lua_pop(L, 1);
            continue;
        }
        if (lua_type(L, -1) == LUA_TFUNCTION) {
            add(k, "(", "");
            add(k, "{", "");
            n++;
        } else if (lua_type(L, -1) == LUA_TTABLE) {
            char prefix[64];
            snprintf(prefix, sizeof prefix, "%s.", k);
            n += add_keys(L, LUA_TFUNCTION, prefix, "(");
        }
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    return n;
}

static int
has(const char *a, const char *b, const char *c)
{
    char e[128];
    snprintf(e, sizeof e, "%s%s%s", a, b, c);
    for (size_t i = 0; i < nentries; i++)
        if (strcmp(entries[i], e) == 0)
            return 1;
    return 0;
}

/* Every schema's function is one the walk found (a method, a global, or a
** nested table's key): the schemas and the registered functions agree. */
static int
schemas_found(void)
{
    int bad = 0;
    for (int i = 1; i < CF__KEYS_COUNT_; i++) {
        const char *fn = cf__lua_schema_at((cf__lua_keys_t)i)->fn;
        if (!has(":", fn, "(") && !has("", fn, "(") && !has(fn, " = ", "")) {
            fprintf(stderr, "gen-script-dict: schema '%s' names no method, "
                    "global or key\n", fn);
            bad = 1;
        }
    }
    return bad;
}

static int
cmp(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static size_t
schema_keys(void)
{
    size_t n = 0;
    for (int i = 1; i < CF__KEYS_COUNT_; i++) {
        const cf__lua_schema_t *s = cf__lua_schema_at((cf__lua_keys_t)i);
        for (int l = 0; l < CF__LUA_KEY_LISTS; l++)
            for (const cf__lua_key_t *k = s->keys[l]; k && k->name; k++) {
                add(k->name, " = ", "");
                n++;
                for (const char *const *v = k->values; v && *v; v++)
                    add("\"", *v, "\"");
            }
    }
    return n;
}

/* Lua's libraries, then a copy of the global table (left on the stack),
** then the binding. */
static int
open_language(lua_State *L)
{
    luaL_openlibs(L);
    lua_newtable(L);
    lua_pushglobaltable(L);
    lua_pushnil(L);
    while (lua_next(L, -2) != 0) {
        lua_pushvalue(L, -2);
        lua_insert(L, -2);
        lua_settable(L, -5);
    }
    lua_pop(L, 1);
    cf__lua_open_language(L);
    return 1;
}

/* one dictionary line: the entry quoted, bytes outside printable ASCII
** and the quote and backslash as \xNN */
static void
put(FILE *f, const char *e)
{
    fputc('"', f);
    for (const unsigned char *p = (const unsigned char *)e; *p; p++) {
        if (*p < 0x20 || *p >= 0x7f || *p == '"' || *p == '\\')
            fprintf(f, "\\x%02X", *p);
        else
            fputc(*p, f);
    }
    fputs("\"\n", f);
}

int
main(int argc, char **argv)
{
    static const char *const syntax[] = {
        "local ", "function", "end", "for i = 1, ", " do ", "if ", " then ",
        "else", "while ", "repeat", "until ", "return", "nil", "true",
        "false", "..", "#", "{", "}", "\"", "pcall(", "setmetatable(",
        "load(", "string.rep(",
        /* the values that boundaries are made of */
        "0", "-1", "1", "2", "3", "(0)", "(0, 0)", "0, 0", "(0, 1)", "-0.0",
        "0/0", "1/0", "-1/0", "1e300", "-1e300", "1e-320", "math.huge",
        "2^31", "{}", "{ {0, 0} }", "{0, 0}", "{0, 0, 0}",
        /* extreme tolerances and sizes: c:flatten(1e-300) freed a buffer
        ** twice; huge counts reach the C loops of the libraries */
        "1e-300", "(1e-300)", "1e-12", "1e-9", "1e12", "1e13", "1e15",
        "2^53", "2^63", "math.maxinteger", "math.mininteger", "1 << 40",
        "1000000", "(1e300)", "(-1e-300)", "xpcall(", "error(", "print(",
        "table.move(", "table.insert(", "table.remove(", "table.concat(",
        "string.find(", ", 1, true)", "__len", "__index", "__close",
        "<close>", "\\0", "\\255", "\\1", "utf8.char(",
    };
    lua_State *L;
    size_t nm, ng, nk;
    FILE *f;

    if (argc != 2) {
        fprintf(stderr, "usage: gen-script-dict OUTPUT\n");
        return 2;
    }
    L = luaL_newstate();
    if (L == NULL) {
        fprintf(stderr, "gen-script-dict: no Lua state\n");
        return 1;
    }
    lua_pushcfunction(L, open_language);
    if (lua_pcall(L, 0, 1, 0) != LUA_OK) {
        fprintf(stderr, "gen-script-dict: %s\n", lua_tostring(L, -1));
        return 1;
    }
    nm = methods(L, CF__LUA_FIGURE) + methods(L, CF__LUA_BEZIER)
         + methods(L, CF__LUA_BSPLINE);
    ng = globals(L, lua_gettop(L));
    nk = schema_keys();
    qsort(entries, nentries, sizeof entries[0], cmp);
    for (size_t i = 0; i < sizeof syntax / sizeof syntax[0]; i++)
        add(syntax[i], "", "");
    lua_close(L);
    if (schemas_found() != 0)
        return 1;
    if (nm == 0 || ng == 0 || nk == 0) {
        fprintf(stderr, "gen-script-dict: %zu methods, %zu globals, %zu keys: "
                "the walk found nothing\n", nm, ng, nk);
        return 1;
    }
    f = fopen(argv[1], "w");
    if (f == NULL) {
        perror(argv[1]);
        return 1;
    }
    fprintf(f, "# generated by tests/fuzz/gen-script-dict.c: %zu methods, "
            "%zu global functions, %zu keys\n", nm, ng, nk);
    for (size_t i = 0; i < nentries; i++) {
        put(f, entries[i]);
        free(entries[i]);
    }
    return fclose(f) == 0 ? 0 : 1;
}
