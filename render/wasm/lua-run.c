/*
** The Lua side of the WebAssembly module: a chunk run in a fresh state
** with the figure language's standard libraries (base, math, string,
** table, utf8; no io, os, package or debug), its results or its error as
** text.  Lua is compiled as C++ for this module, so that lua_error is a
** WebAssembly exception and the page needs no setjmp/longjmp glue
** (docs/interactive.md, "Design").
*/
#include <stdlib.h>
#include <string.h>

#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>

#define EXPORT(name) __attribute__((export_name(#name), used))

static char *result;

static void
keep(const char *s, size_t n)
{
    free(result);
    result = malloc(n + 1);
    if (result != NULL) {
        memcpy(result, s, n);
        result[n] = '\0';
    }
}

/* Run src; 0 and its results joined by tabs (as tostring), or 1 and the
** error message; the text is cf_wasm_lua_result() until the next run. */
EXPORT(cf_wasm_lua_run) int
cf_wasm_lua_run(const char *src)
{
    static const luaL_Reg libs[] = {
        { LUA_GNAME, luaopen_base },
        { LUA_MATHLIBNAME, luaopen_math },
        { LUA_STRLIBNAME, luaopen_string },
        { LUA_TABLIBNAME, luaopen_table },
        { LUA_UTF8LIBNAME, luaopen_utf8 },
    };
    lua_State *L = luaL_newstate();
    luaL_Buffer b;
    size_t i, n;
    int top, st;
    if (L == NULL) {
        keep("out of memory", 13);
        return 1;
    }
    for (i = 0; i < sizeof libs / sizeof libs[0]; i++) {
        luaL_requiref(L, libs[i].name, libs[i].func, 1);
        lua_pop(L, 1);
    }
    st = luaL_loadbuffer(L, src, strlen(src), "=script");
    if (st == LUA_OK)
        st = lua_pcall(L, 0, LUA_MULTRET, 0);
    if (st != LUA_OK) {
        const char *msg = lua_tolstring(L, -1, &n);
        if (msg == NULL)
            msg = "error object is not a string", n = strlen(msg);
        keep(msg, n);
        lua_close(L);
        return 1;
    }
    top = lua_gettop(L);
    luaL_buffinit(L, &b);
    for (st = 1; st <= top; st++) {
        if (st > 1)
            luaL_addchar(&b, '\t');
        luaL_tolstring(L, st, NULL);
        luaL_addvalue(&b);
    }
    luaL_pushresult(&b);
    {
        const char *s = lua_tolstring(L, -1, &n);
        keep(s, n);
    }
    lua_close(L);
    return 0;
}

EXPORT(cf_wasm_lua_result) const char *
cf_wasm_lua_result(void)
{
    return result != NULL ? result : "";
}
