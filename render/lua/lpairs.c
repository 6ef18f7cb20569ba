/*
** pairs in a fixed order (lpairs.h).
**
** Lua 5.4 hashes strings with a seed made from the time and the addresses
** of each new state, so `for k, v in pairs(t)` visits the same table in
** another order at every run.  A figure script that adds its elements or
** labels in a pairs loop would then draw them in another order each time
** (another stacking, other label places, other bytes), which no
** image-diff test can guard.  The sandbox's pairs therefore visits the
** keys of a table without __pairs in one order: numbers ascending, then
** strings in byte order, then false and true, then the other keys (tables,
** functions: no order of theirs is stable) in Lua's own order.  It takes a
** snapshot of the keys when the loop starts; a key whose value is set to
** nil during the loop is passed over, as next does; a key added during it
** is not visited (next's behaviour is undefined then).  `next` itself is
** Lua's, in hash order.  The work, n log n comparisons, is charged to the
** instruction budget.
*/
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <lauxlib.h>

#include "lcount.h"
#include "lpairs.h"

/* one key: its rank (0 number, 1 string, 2 boolean, 3 other), its value
** for the first three, and its place in Lua's order for the others */
typedef struct key {
    int rank;
    int isint;
    lua_Integer i;
    double d;
    const char *s;
    size_t len;
    size_t raw;
} pkey_t;

/* a < b for two numbers, exactly (an integer and a float of the same
** value are one key in Lua, so they never meet here) */
static int
num_cmp(const pkey_t *a, const pkey_t *b)
{
    if (a->isint && b->isint)
        return a->i < b->i ? -1 : a->i > b->i;
    if (!a->isint && !b->isint)
        return a->d < b->d ? -1 : a->d > b->d;
    if (a->isint) {
        /* the float beyond every integer, or compared as one */
        if (b->d >= 9223372036854775808.0)
            return -1;
        if (b->d < -9223372036854775808.0)
            return 1;
        if ((double)a->i != b->d)
            return (double)a->i < b->d ? -1 : 1;
        /* equal as doubles: b is integral, compare exactly */
        return a->i < (lua_Integer)b->d ? -1 : a->i > (lua_Integer)b->d;
    }
    return -num_cmp(b, a);
}

static int
key_cmp(const void *pa, const void *pb)
{
    const pkey_t *a = pa, *b = pb;
    int c;
    if (a->rank != b->rank)
        return a->rank < b->rank ? -1 : 1;
    switch (a->rank) {
    case 0:
        return num_cmp(a, b);
    case 1:
        c = memcmp(a->s, b->s, a->len < b->len ? a->len : b->len);
        return c != 0 ? c : (a->len < b->len ? -1 : a->len > b->len);
    case 2:
        return a->isint < b->isint ? -1 : a->isint > b->isint;
    default:
        return a->raw < b->raw ? -1 : a->raw > b->raw;
    }
}

/* The iterator: upvalues the table, the sorted keys (a sequence) and the
** place reached. */
static int
next_pair(lua_State *L)
{
    lua_Integer at = lua_tointeger(L, lua_upvalueindex(3));
    lua_Integer n = (lua_Integer)lua_rawlen(L, lua_upvalueindex(2));
    while (at < n) {
        at++;
        lua_rawgeti(L, lua_upvalueindex(2), at);      /* key */
        lua_pushvalue(L, -1);
        if (lua_rawget(L, lua_upvalueindex(1)) != LUA_TNIL) {
            lua_pushinteger(L, at);
            lua_replace(L, lua_upvalueindex(3));
            return 2;
        }
        lua_pop(L, 2);   /* removed during the loop */
    }
    lua_pushinteger(L, at);
    lua_replace(L, lua_upvalueindex(3));
    lua_pushnil(L);
    return 1;
}

void
cf__lua_sorted_keys(lua_State *L, int idx)
{
    pkey_t local[16], *k = local;
    size_t n = 0, cap = 16;
    int keys, block;
    idx = lua_absindex(L, idx);
    luaL_checkstack(L, 6, "sorted keys");
    lua_newtable(L);                   /* the keys in Lua's order */
    keys = lua_gettop(L);
    /* described in a block on the C stack, past 16 keys in one owned by a
    ** userdata, which the budget counts; each key stays in `keys`, so a
    ** string's text stays put */
    lua_pushnil(L);
    block = lua_gettop(L);
    lua_pushnil(L);
    while (lua_next(L, idx) != 0) {
        pkey_t *e;
        lua_pop(L, 1);
        if (n == cap) {
            pkey_t *bigger;
            if (cap > SIZE_MAX / 2 / sizeof *k)
                luaL_error(L, "too many keys to order");
            bigger = lua_newuserdatauv(L, 2 * cap * sizeof *k, 0);
            memcpy(bigger, k, n * sizeof *k);
            lua_replace(L, block);
            k = bigger;
            cap *= 2;
        }
        e = &k[n];
        memset(e, 0, sizeof *e);
        e->raw = n;
        switch (lua_type(L, -1)) {
        case LUA_TNUMBER:
            e->rank = 0;
            e->isint = lua_isinteger(L, -1);
            if (e->isint)
                e->i = lua_tointeger(L, -1);
            else
                e->d = lua_tonumber(L, -1);
            break;
        case LUA_TSTRING:
            e->rank = 1;
            e->s = lua_tolstring(L, -1, &e->len);
            break;
        case LUA_TBOOLEAN:
            e->rank = 2;
            e->isint = lua_toboolean(L, -1);
            break;
        default:
            e->rank = 3;
            break;
        }
        lua_pushvalue(L, -1);
        lua_rawseti(L, keys, (lua_Integer)++n);
    }
    /* n log n comparisons, about one instruction each */
    {
        unsigned long long steps = n, m = n;
        while (m > 1) {
            steps += n;
            m >>= 1;
        }
        cf__lua_charge(L, steps);
    }
    qsort(k, n, sizeof *k, key_cmp);
    /* the keys in order: each sorted entry names its place in `keys` */
    lua_createtable(L, (int)(n < INT32_MAX ? n : INT32_MAX), 0);
    for (size_t i = 0; i < n; i++) {
        lua_rawgeti(L, keys, (lua_Integer)k[i].raw + 1);
        lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
    lua_replace(L, keys);
    lua_settop(L, keys);
}

static int
sorted_pairs(lua_State *L)
{
    luaL_checkany(L, 1);
    if (luaL_getmetafield(L, 1, "__pairs") != LUA_TNIL) {
        lua_pushvalue(L, 1);
        lua_call(L, 1, 3);
        return 3;
    }
    luaL_checktype(L, 1, LUA_TTABLE);
    lua_settop(L, 1);
    cf__lua_sorted_keys(L, 1);                          /* 2 */
    lua_pushvalue(L, 1);
    lua_pushvalue(L, 2);
    lua_pushinteger(L, 0);
    lua_pushcclosure(L, next_pair, 3);
    lua_pushvalue(L, 1);
    lua_pushnil(L);
    return 3;
}

void
cf__lua_open_pairs(lua_State *L)
{
    lua_pushcfunction(L, sorted_pairs);
    lua_setglobal(L, "pairs");
}
