/*
** The one check of every named table (lschema.h) and the missing-name
** handlers.
*/
#include <string.h>

#include "lcommon.h"
#include "lpairs.h"
#include "lcount.h"
#include "lschema.h"

#define MAX_NAMES 256 /* candidates gathered for one suggestion */

/* ---- the table check ---------------------------------------------------- */

static size_t
key_names(const cf__lua_schema_t *s, const char **out, size_t cap)
{
    size_t n = 0;
    for (int l = 0; l < CF__LUA_KEY_LISTS; l++)
        for (const cf__lua_key_t *k = s->keys[l]; k != NULL && k->name;
             k++)
            if (n < cap)
                out[n++] = k->name;
    return n;
}

static const cf__lua_key_t *
find_key(const cf__lua_key_t *const *lists, int nlists, const char *name)
{
    for (int l = 0; l < nlists; l++)
        for (const cf__lua_key_t *k = lists[l]; k != NULL && k->name; k++)
            if (strcmp(k->name, name) == 0)
                return k;
    return NULL;
}

/* "a, b or c" of the names, into b (for messages without a suggestion) */
static void
add_list(luaL_Buffer *b, const char *const *names, size_t n,
         const char *quote)
{
    for (size_t i = 0; i < n; i++) {
        if (i > 0)
            luaL_addstring(b, i + 1 == n ? " or " : ", ");
        luaL_addstring(b, quote);
        luaL_addstring(b, names[i]);
        luaL_addstring(b, quote);
    }
}

static void
unknown_key(lua_State *L, const cf__lua_schema_t *s, const char *where,
            const char *key)
{
    const char *names[MAX_NAMES];
    size_t n = key_names(s, names, MAX_NAMES);
    const char *near;
    luaL_Buffer b;
    if (s->elsewhere != NULL && find_key(&s->elsewhere, 1, key) != NULL)
        luaL_error(L, "%s: '%s' is not %s %s: %s", where, key,
                   s->noun[0] == 'o' ? "an" : "a", s->noun, s->hint);
    near = cf__lua_nearest_name(L, key, names, n);
    if (near != NULL)
        luaL_error(L, "%s: unknown %s '%s' (did you mean '%s'?)", where,
                   s->noun, key, near);
    luaL_buffinit(L, &b);
    lua_pushfstring(L, "%s: unknown %s '%s'; the %ss are ", where, s->noun,
                    key, s->noun);
    luaL_addvalue(&b);
    add_list(&b, names, n, "");
    luaL_pushresult(&b);
    lua_error(L);
}

static void
check_name(lua_State *L, const char *where, const cf__lua_key_t *k, int idx)
{
    const char *key = k->name, *const *values = k->values;
    size_t n = 0;
    const char *v = lua_tostring(L, idx), *near;
    luaL_Buffer b;
    for (; values[n] != NULL; n++)
        if (strcmp(values[n], v) == 0)
            return;
    near = cf__lua_nearest_name(L, v, values, n);
    if (near != NULL)
        luaL_error(L, "%s: %s \"%s\" is unknown (did you mean \"%s\"?)",
                   where, key, v, near);
    luaL_buffinit(L, &b);
    lua_pushfstring(L, "%s: %s \"%s\" is unknown; the names are ", where,
                    key, v);
    luaL_addvalue(&b);
    add_list(&b, values, n, "\"");
    if (k->also != NULL) {
        luaL_addstring(&b, ", or ");
        luaL_addstring(&b, k->also);
    }
    luaL_pushresult(&b);
    lua_error(L);
}

/* An enumerated value: a string, or a list whose strings are names. */
static void
check_values(lua_State *L, const char *where, const cf__lua_key_t *k,
             int idx)
{
    if (lua_type(L, idx) == LUA_TSTRING) {
        check_name(L, where, k, idx);
    } else if (lua_type(L, idx) == LUA_TNUMBER) {
        luaL_error(L, "%s: %s is a name, e.g. \"%s\", not a number", where,
                   k->name, k->values[0]);
    } else if (lua_istable(L, idx)) {
        lua_Integer n = (lua_Integer)lua_rawlen(L, idx);
        for (lua_Integer i = 1; i <= n; i++) {
            if (lua_rawgeti(L, idx, i) == LUA_TSTRING)
                check_name(L, where, k, lua_gettop(L));
            lua_pop(L, 1);
        }
    }
}

static void check_at(lua_State *L, int idx, cf__lua_keys_t id,
                     const char *where);

static void
check_entry(lua_State *L, const cf__lua_schema_t *s, const char *where,
            int tbl)
{
    /* key at -2, value at -1 */
    const char *key;
    const cf__lua_key_t *k;
    if (lua_type(L, -2) == LUA_TNUMBER) {
        lua_Integer i = lua_tointeger(L, -2);
        if (s->positional && lua_isinteger(L, -2) && i >= 1 &&
            (lua_Unsigned)i <= lua_rawlen(L, tbl))
            return;
        luaL_error(L, "%s: %s %s has no name; %ss are named, e.g. { %s = "
                   "... }", where, s->noun, lua_tostring(L, -2), s->noun,
                   s->keys[0][0].name);
    }
    if (lua_type(L, -2) != LUA_TSTRING)
        luaL_error(L, "%s: a %s name must be a string, got %s", where,
                   s->noun, luaL_typename(L, -2));
    key = lua_tostring(L, -2);
    k = find_key(s->keys, CF__LUA_KEY_LISTS, key);
    if (k == NULL)
        unknown_key(L, s, where, key);
    if (k->values != NULL)
        check_values(L, where, k, lua_gettop(L));
    if (k->table != CF__KEYS_NONE && lua_istable(L, -1)) {
        const char *sub = lua_pushfstring(L, "%s: %s", where, key);
        check_at(L, lua_gettop(L) - 1, k->table, sub);
        lua_pop(L, 1);
    }
}

static void
check_at(lua_State *L, int idx, cf__lua_keys_t id, const char *where)
{
    const cf__lua_schema_t *s = cf__lua_schema_at(id);
    idx = lua_absindex(L, idx);
    if (lua_isnoneornil(L, idx))
        return;
    if (!lua_istable(L, idx))
        luaL_error(L, "%s: the %ss must be a table, got %s", where, s->noun,
                   luaL_typename(L, idx));
    luaL_checkstack(L, 8, "nested tables");
    /* in one order (lpairs.h): of two bad entries, the same is named at
    ** every run */
    cf__lua_sorted_keys(L, idx);
    for (lua_Integer i = 1, n = (lua_Integer)lua_rawlen(L, -1); i <= n;
         i++) {
        lua_rawgeti(L, -1, i);
        lua_pushvalue(L, -1);
        lua_rawget(L, idx);
        check_entry(L, s, where, idx);
        lua_pop(L, 2);
    }
    lua_pop(L, 1);
}

void
cf__lua_check_table(lua_State *L, int idx, cf__lua_keys_t k)
{
    check_at(L, idx, k, cf__lua_schema_at(k)->fn);
}

/* ---- missing names ------------------------------------------------------ */

/* Gather the string keys of the table at idx into names (up to cap), in
** one order (lpairs.h: the same candidates, and of equally near ones the
** same suggestion, at every run); the sequence of keys stays pushed, as
** the names' anchor. */
static size_t
table_names(lua_State *L, int idx, const char **names, size_t n, size_t cap)
{
    cf__lua_sorted_keys(L, idx);
    for (lua_Integer i = 1, m = (lua_Integer)lua_rawlen(L, -1);
         i <= m && n < cap; i++) {
        if (lua_rawgeti(L, -1, i) == LUA_TSTRING)
            names[n++] = lua_tostring(L, -1);
        lua_pop(L, 1);
    }
    return n;
}

/* Names a Lua script may expect that the sandbox leaves out. */
static const char *const sandboxed[] = {
    "io", "os", "package", "debug", "coroutine", "require", "dofile",
    "loadfile", NULL,
};

/* __index of a guarded table: upvalue 1 the message's lead ("figure has no
** method"); the table is argument 1, the name argument 2. */
static int
missing(lua_State *L)
{
    const char *names[MAX_NAMES], *key, *near;
    const char *lead = lua_tostring(L, lua_upvalueindex(1));
    size_t n;
    lua_Debug ar;
    if (lua_type(L, 2) != LUA_TSTRING)
        return 0;
    key = lua_tostring(L, 2);
    for (size_t i = 0; lua_toboolean(L, lua_upvalueindex(2)) &&
                       sandboxed[i] != NULL; i++)
        if (strcmp(key, sandboxed[i]) == 0)
            return luaL_error(L, "'%s' is not available to figure scripts "
                              "(the sandbox has no io, os, package, debug, "
                              "coroutine, require, dofile or loadfile)", key);
    n = table_names(L, 1, names, 0, MAX_NAMES);
    /* a missing global: the locals of the calling function count too */
    if (lua_toboolean(L, lua_upvalueindex(2)) && lua_getstack(L, 1, &ar)) {
        const char *local;
        for (int i = 1; n < MAX_NAMES &&
                        (local = lua_getlocal(L, &ar, i)) != NULL; i++) {
            lua_pop(L, 1);
            if (local[0] != '(')
                names[n++] = local;
        }
    }
    near = cf__lua_nearest_name(L, key, names, n);
    if (near != NULL)
        return luaL_error(L, "%s '%s' (did you mean '%s'?)", lead, key, near);
    return luaL_error(L, "%s '%s'", lead, key);
}

static void
guard(lua_State *L, int idx, const char *lead, bool globals)
{
    idx = lua_absindex(L, idx);
    lua_createtable(L, 0, 2);
    lua_pushstring(L, lead);
    lua_pushboolean(L, globals);
    lua_pushcclosure(L, missing, 2);
    lua_setfield(L, -2, "__index");
    lua_pushliteral(L, "locked");
    lua_setfield(L, -2, "__metatable");
    lua_setmetatable(L, idx);
}

static void
guard_class(lua_State *L, const char *tname, const char *lead)
{
    luaL_getmetatable(L, tname);
    lua_getfield(L, -1, "__index");
    guard(L, -1, lead, false);
    lua_pop(L, 2);
}

void
cf__lua_guard_names(lua_State *L)
{
    static const char *const libs[] = { "math", "string", "table", "utf8",
                                        "knots", "conic" };
    guard_class(L, CF__LUA_FIGURE, "figure has no method");
    guard_class(L, CF__LUA_BEZIER, "bezier has no method");
    guard_class(L, CF__LUA_BSPLINE, "bspline has no method");
    for (size_t i = 0; i < sizeof libs / sizeof libs[0]; i++) {
        if (lua_getglobal(L, libs[i]) == LUA_TTABLE) {
            const char *lead = lua_pushfstring(L, "%s has no field", libs[i]);
            guard(L, -2, lead, false);
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    lua_pushglobaltable(L);
    guard(L, -1, "unknown name", true);
    lua_pop(L, 1);
}

void *
cf__lua_check_self(lua_State *L, const char *tname, const char *shown)
{
    void *p = luaL_testudata(L, 1, tname);
    lua_Debug ar;
    if (p != NULL)
        return p;
    if (lua_getstack(L, 0, &ar) && lua_getinfo(L, "n", &ar) &&
        ar.name != NULL && strcmp(ar.namewhat, "field") == 0)
        luaL_error(L, "%s: call a method with ':' (%c:%s(...)), not '.'",
                   ar.name, shown[0] == 'f' ? 'f' : 'c', ar.name);
    return luaL_checkudata(L, 1, tname);
}
