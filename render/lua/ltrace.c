/*
** The message handler of figure scripts (ltrace.h).
*/
#include <limits.h>
#include <string.h>

#include "ltrace.h"

/* The traceback shows at most TRACE_HEAD script frames from the top of the
** stack and TRACE_TAIL from its bottom, "..." between them, and runs of
** one frame repeated (recursion) as one line with a count. */
#define TRACE_HEAD 10
#define TRACE_TAIL 11

/* The deepest valid stack level.  lua_getstack(L, n) walks n frames, so
** probing every level of a deep recursion (a stack overflow is ~200 000
** frames) would take quadratic time: double, then bisect, O(n log n). */
int
cf__lua_deepest_level(lua_State *L)
{
    lua_Debug ar;
    int ok = 1, bad = 2;
    while (lua_getstack(L, bad, &ar)) {
        ok = bad;
        if (bad > INT_MAX / 2)
            return bad;
        bad *= 2;
    }
    while (bad - ok > 1) {
        int mid = ok + (bad - ok) / 2;
        if (lua_getstack(L, mid, &ar))
            ok = mid;
        else
            bad = mid;
    }
    return ok;
}

typedef struct trace {
    luaL_Buffer *b;
    const char *msg;
    int first;           /* the first script frame is still to come */
    char last[LUA_IDSIZE + 16]; /* the pending "file:line", or "" */
    long repeats;        /* how many times it occurred in a row */
} trace;

static void
trace_flush(lua_State *L, trace *t)
{
    if (t->last[0] == '\0')
        return;
    if (t->repeats > 1)
        lua_pushfstring(L, "\n    from %s (%I times)", t->last,
                        (lua_Integer)t->repeats);
    else
        lua_pushfstring(L, "\n    from %s", t->last);
    luaL_addvalue(t->b);
    t->last[0] = '\0';
    t->repeats = 0;
}

/* Add the script frames among the levels from `from` to `to`, at most max
** of them; returns the first level not looked at. */
static int
trace_levels(lua_State *L, trace *t, int from, int to, int max)
{
    lua_Debug ar;
    char here[sizeof t->last];
    int n = 0, level;
    for (level = from; level <= to && n < max; level++) {
        if (!lua_getstack(L, level, &ar) || !lua_getinfo(L, "Sl", &ar))
            break;
        if (ar.currentline <= 0 || ar.source[0] != '@')
            continue;
        n++;
        if (t->first) {
            /* the frame that raised the error is already in msg */
            t->first = 0;
            if (strstr(t->msg, ar.short_src) == t->msg)
                continue;
        }
        snprintf(here, sizeof here, "%s:%d", ar.short_src, ar.currentline);
        if (strcmp(here, t->last) != 0) {
            trace_flush(L, t);
            memcpy(t->last, here, sizeof here);
        }
        t->repeats++;
    }
    return level;
}

/* A message without the script's position (raised by a C function, or by
** the sandbox's own wrappers: "(sandbox):N: ") gets the position of the
** first script frame. */
static const char *
place_message(lua_State *L, const char *msg)
{
    lua_Debug ar;
    for (int level = 1; level < 64 && lua_getstack(L, level, &ar); level++) {
        size_t n;
        if (!lua_getinfo(L, "Sl", &ar) || ar.source[0] != '@' ||
            ar.currentline <= 0)
            continue;
        n = strlen(ar.short_src);
        if (strncmp(msg, ar.short_src, n) == 0 && msg[n] == ':')
            return msg;
        if (strncmp(msg, "(sandbox):", 10) == 0 &&
            strstr(msg + 10, ": ") != NULL)
            msg = strstr(msg + 10, ": ") + 2;
        return lua_pushfstring(L, "%s:%d: %s", ar.short_src, ar.currentline,
                               msg);
    }
    return msg;
}

/* The message at idx with each NUL written \0 (a C string would end
** there); pushed when it had one. */
static const char *
whole_message(lua_State *L, int idx)
{
    size_t len;
    const char *msg = lua_tolstring(L, idx, &len);
    luaL_Buffer b;
    if (msg == NULL || strlen(msg) == len)
        return msg;
    luaL_buffinit(L, &b);
    for (size_t i = 0; i < len; i++) {
        if (msg[i] == '\0')
            luaL_addstring(&b, "\\0");
        else
            luaL_addchar(&b, msg[i]);
    }
    luaL_pushresult(&b);
    return lua_tostring(L, -1);
}

/* Message handler: the message, then the script's frames below it. */
int
cf__lua_traceback(lua_State *L)
{
    luaL_Buffer b;
    trace t;
    int deepest;
    t.msg = whole_message(L, 1);
    if (t.msg == NULL) {
        if (luaL_callmeta(L, 1, "__tostring") &&
            lua_type(L, -1) == LUA_TSTRING)
            t.msg = lua_tostring(L, -1);
        else
            t.msg = lua_pushfstring(L, "(error object is a %s value)",
                                    luaL_typename(L, 1));
    }
    t.msg = place_message(L, t.msg);
    t.b = &b;
    t.first = 1;
    t.last[0] = '\0';
    t.repeats = 0;
    luaL_buffinit(L, &b);
    luaL_addstring(&b, t.msg);
    deepest = cf__lua_deepest_level(L);
    if (deepest <= 2 * (TRACE_HEAD + TRACE_TAIL)) {
        trace_levels(L, &t, 1, deepest, INT_MAX);
    } else {
        /* the head, "...", then the script frames among the last levels
        ** (C frames such as metamethod calls are not shown) */
        int tail = deepest - 2 * TRACE_TAIL + 1;
        int next = trace_levels(L, &t, 1, tail - 1, TRACE_HEAD);
        trace_flush(L, &t);
        if (next < tail) {
            lua_pushfstring(L, "\n    ... (%d levels not shown)",
                            tail - next);
            luaL_addvalue(&b);
        }
        t.first = 0;
        trace_levels(L, &t, next > tail ? next : tail, deepest, INT_MAX);
    }
    trace_flush(L, &t);
    luaL_pushresult(&b);
    return 1;
}

