/*
** The counted library functions of the sandbox (lcount.h): each charges
** the work it does in C to the script's instruction budget.
*/
#define _GNU_SOURCE   /* memmem: a search linear in the subject */
#include <limits.h>
#include <string.h>

#include <lauxlib.h>
#include <lualib.h>

#include "curvefig/core.h"
#include "lcount.h"
#include "lcommon.h"
#include "lpattern.h"
#include "ltrace.h"
#include "script.h"

/* Iterations between two charges of the table loops */
#define CHARGE_EVERY 4096

enum { FIND, MATCH, GMATCH, GSUB };

static cf__lua_budget_t *
budget_of(lua_State *L)
{
    void *ud;
    lua_getallocf(L, &ud);
    return ud;
}

int
cf__lua_charge(lua_State *L, unsigned long long steps)
{
    cf__lua_budget_t *b = budget_of(L);
    b->instructions = steps > ULLONG_MAX - b->instructions
                          ? ULLONG_MAX : b->instructions + steps;
    return b->check(L);
}

/* A caught error costs Lua a walk over the whole call stack (it shrinks
** the stack after unwinding), which no instruction pays for: a script
** that catches errors in a loop 100,000 calls deep does quadratic work.
** Charge two instructions per level (a level of that walk takes about as
** long as two instructions). */
void
cf__lua_charge_unwind(lua_State *L)
{
    cf__lua_charge(L, 2 * ((unsigned long long)cf__lua_deepest_level(L) + 1));
}

/* Names longer than this are compared as "far" at once (src/names.c). */
#define NAME_CMP_MAX 100
/* Cells of the name comparison's table charged as one instruction (about
** as long: 4 us for 150 globals compared with a 5-letter name, some 6000
** cells, against 5-7 ns an instruction here). */
#define CELLS_A_STEP 8

const char *
cf__lua_nearest_name(lua_State *L, const char *key,
                     const char *const *names, size_t n)
{
    unsigned long long cells = 0;
    size_t k = strlen(key), i;
    for (i = 0; k <= NAME_CMP_MAX && i < n; i++) {
        size_t m = strlen(names[i]);
        if (m <= NAME_CMP_MAX)
            cells += (unsigned long long)(k + 1) * (m + 1);
    }
    cf__lua_charge(L, n + cells / CELLS_A_STEP);
    return cf_nearest_name(key, names, n);
}

/* Instructions left before the limit. */
static unsigned long long
budget_left(lua_State *L)
{
    cf__lua_budget_t *b = budget_of(L);
    return b->instructions < b->max_instructions
               ? b->max_instructions - b->instructions : 0;
}

static int
has_specials(const char *p, size_t lp)
{
    for (size_t i = 0; i < lp; i++)
        if (strchr("^$*+?.([%-", p[i]) != NULL && p[i] != '\0')
            return 1;
    return 0;
}

/* Where a search starts (Lua's rule for init): the byte offset, or
** ls + 1 when it starts past the end. */
static size_t
start_of(lua_Integer i, size_t ls)
{
    if (i > 0)
        return (lua_Unsigned)i - 1 > ls ? ls + 1 : (size_t)i - 1;
    if (i == 0 || (lua_Unsigned)-(i + 1) >= ls)
        return 0;
    return ls - (size_t)-(i + 1) - 1;
}

/* A plain find (plain = true, or a pattern without special characters),
** done here in linear time: Lua's own compares the whole pattern at every
** place its first byte occurs, which is quadratic.  Pushes true and the
** results when it answered, nothing when Lua should. */
static int
plain_find(lua_State *L, const char *str, size_t ls, const char *pat,
           size_t lp)
{
    size_t init = 0;
    const char *hit;
    if (!lua_isnoneornil(L, 4)) {
        int ok;
        lua_Integer i = lua_tointegerx(L, 4, &ok);
        if (!ok)
            return 0;
        init = start_of(i, ls);
    }
    cf__lua_charge(L, (ls - (init < ls ? init : ls) + lp) / 16);
    lua_pushboolean(L, 1);
    if (init > ls) {
        lua_pushnil(L);
        return 2;
    }
    hit = lp == 0 ? str + init : memmem(str + init, ls - init, pat, lp);
    if (hit == NULL) {
        lua_pushnil(L);
        return 2;
    }
    lua_pushinteger(L, (lua_Integer)(hit - str) + 1);
    lua_pushinteger(L, (lua_Integer)(hit - str + lp));
    return 3;
}

/* guard(kind, s, p, init, plain) before find, match, gmatch, gsub: counts
** the steps the search will take against what is left of the budget (it
** runs inside one C call, where the hook cannot stop it) and charges
** them; a plain find it answers itself (true, results).  Arguments Lua
** would refuse are left for Lua to refuse. */
static int
pattern_guard(lua_State *L)
{
    int kind = (int)lua_tointeger(L, 1);
    size_t ls, lp, init = 0;
    const char *str, *pat;
    long long steps, left;
    unsigned long long room;
    int st;
    if (lua_type(L, 2) != LUA_TSTRING || lua_type(L, 3) != LUA_TSTRING)
        return 0;
    str = lua_tolstring(L, 2, &ls);
    pat = lua_tolstring(L, 3, &lp);
    if (kind == FIND && (lua_toboolean(L, 5) || !has_specials(pat, lp)))
        return plain_find(L, str, ls, pat, lp);
    if (kind != GSUB && !lua_isnoneornil(L, 4)) {
        int ok;
        lua_Integer i = lua_tointegerx(L, 4, &ok);
        if (!ok || start_of(i, ls) > ls)
            return 0;       /* Lua refuses it, or there is no search */
        init = start_of(i, ls);
    }
    room = budget_left(L);
    left = room > LLONG_MAX ? LLONG_MAX : (long long)room;
    st = cf__pattern_cost(str, ls, pat, lp, init, kind >= GMATCH, left,
                          &steps);
    if (st == CF__PATTERN_OVER)
        return cf__lua_charge(L, ULLONG_MAX);
    cf__lua_charge(L, (unsigned long long)steps);
    return 0;
}

/* count(kind, ...) before string.rep (0) and table.move (1): both loop
** over a count fixed by their arguments, charged in advance (the bytes
** string.rep copies are charged by the allocation of its result). */
static int
count_guard(lua_State *L)
{
    int kind = (int)lua_tointeger(L, 1), ok, ok2;
    lua_Integer a = lua_tointegerx(L, 3, &ok), b = lua_tointegerx(L, 4, &ok2);
    if (kind == 0 && ok && a > 0 && lua_isstring(L, 2)) {
        size_t l = 0, lsep = 0;
        lua_Unsigned n = (lua_Unsigned)a, piece;
        lua_tolstring(L, 2, &l);
        if (lua_isstring(L, 4))
            lua_tolstring(L, 4, &lsep);
        piece = (lua_Unsigned)(l + lsep);
        /* a result over 2 GiB Lua refuses before its loop */
        if (piece == 0 || piece <= (lua_Unsigned)INT_MAX / n)
            cf__lua_charge(L, n);
    } else if (kind == 1 && ok && ok2 && b >= a) {
        cf__lua_charge(L, (lua_Unsigned)b - (lua_Unsigned)a + 1u);
    }
    return 0;
}

/* t[dst] = t[dst + step] for count entries from dst on, dst moving by
** step: the shifting loop of table.insert and table.remove, charged as it
** goes (the table at 1; metamethods run hooked). */
static void
shift(lua_State *L, lua_Integer dst, lua_Integer count, int step)
{
    for (lua_Integer k = 0; k < count; k++, dst += step) {
        if (k % CHARGE_EVERY == 0)
            cf__lua_charge(L, CHARGE_EVERY);
        lua_geti(L, 1, dst + step);
        lua_seti(L, 1, dst);
    }
}

/* table.insert(t, [pos,] v): Lua's reads the length (a __len may say
** 10^15) and shifts every entry above pos in one C loop. */
static int
counted_insert(lua_State *L)
{
    lua_Integer e, pos;
    luaL_checkany(L, 1);
    e = luaL_len(L, 1);
    if (e == LUA_MAXINTEGER)
        return luaL_error(L, "table.insert: the table's length is the "
                          "largest integer");
    e++;
    switch (lua_gettop(L)) {
    case 2:
        pos = e;
        break;
    case 3:
        pos = luaL_checkinteger(L, 2);
        luaL_argcheck(L, (lua_Unsigned)pos - 1u < (lua_Unsigned)e, 2,
                      "position out of bounds");
        shift(L, e, e - pos, -1);
        break;
    default:
        return luaL_error(L, "wrong number of arguments to 'insert'");
    }
    lua_seti(L, 1, pos);
    return 0;
}

/* table.remove(t [, pos]), likewise. */
static int
counted_remove(lua_State *L)
{
    lua_Integer size, pos;
    luaL_checkany(L, 1);
    size = luaL_len(L, 1);
    pos = luaL_optinteger(L, 2, size);
    if (pos != size)
        luaL_argcheck(L, (lua_Unsigned)pos - 1u <= (lua_Unsigned)size, 2,
                      "position out of bounds");
    lua_geti(L, 1, pos);
    if (pos < size) {
        shift(L, pos, size - pos, 1);
        pos = size;
    }
    lua_pushnil(L);
    lua_seti(L, 1, pos);
    return 1;
}

/* Write len bytes of what print prints, within the output limit. */
static void
print_part(lua_State *L, FILE *out, const char *str, size_t len)
{
    cf__lua_budget_t *b = budget_of(L);
    size_t room = b->printed < CF_SCRIPT_MAX_PRINT
                      ? CF_SCRIPT_MAX_PRINT - b->printed : 0;
    cf__lua_charge(L, len / 16);
    if (room > len)
        room = len;
    b->printed += room;
    fwrite(str, 1, room, out);
    if (room < len) {
        fputc('\n', out);
        luaL_error(L, "print: the script's output reached its limit of "
                   "%d MiB", (int)(CF_SCRIPT_MAX_PRINT >> 20));
    }
}

/* print to the script's stream, its bytes charged and capped. */
static int
counted_print(lua_State *L)
{
    FILE *out = budget_of(L)->out;
    int n = lua_gettop(L);
    for (int i = 1; i <= n; i++) {
        size_t len;
        const char *str = luaL_tolstring(L, i, &len);
        if (i > 1)
            print_part(L, out, "\t", 1);
        print_part(L, out, str, len);
        lua_pop(L, 1);
    }
    print_part(L, out, "\n", 1);
    return 0;
}

/* The wrappers: Lua closures ending in a tail call, so that Lua's own
** messages still name the script's line. */
static const char wrappers[] =
    "local guard, count, find, match, gmatch, gsub, rep, move = ...\n"
    "string.find = function(...)\n"
    "  local done, a, b = guard(0, ...)\n"
    "  if done then if a then return a, b end return nil end\n"
    "  return find(...)\n"
    "end\n"
    "string.match = function(...) guard(1, ...) return match(...) end\n"
    "string.gmatch = function(...) guard(2, ...) return gmatch(...) end\n"
    "string.gsub = function(...) guard(3, ...) return gsub(...) end\n"
    "string.rep = function(...) count(0, ...) return rep(...) end\n"
    "table.move = function(...) count(1, ...) return move(...) end\n";

/* Lua names a library function in its messages by looking it up in the
** loaded modules: they keep the original tables' contents, so that
** "bad argument #1 to 'string.rep'" survives the wrappers. */
static void
keep_names(lua_State *L, const char *lib)
{
    luaL_getsubtable(L, LUA_REGISTRYINDEX, LUA_LOADED_TABLE);
    lua_newtable(L);
    lua_getglobal(L, lib);
    lua_pushnil(L);
    while (lua_next(L, -2)) {
        lua_pushvalue(L, -2);
        lua_insert(L, -2);
        lua_settable(L, -5);
    }
    lua_pop(L, 1);
    lua_setfield(L, -2, lib);
    lua_pop(L, 1);
}

void
cf__lua_open_counted(lua_State *L)
{
    static const char *const strs[] = { "find", "match", "gmatch", "gsub",
                                        "rep" };
    keep_names(L, LUA_STRLIBNAME);
    keep_names(L, LUA_TABLIBNAME);
    if (luaL_loadbufferx(L, wrappers, sizeof wrappers - 1, "=(sandbox)",
                         "t") != LUA_OK)
        lua_error(L);
    lua_pushcfunction(L, pattern_guard);
    lua_pushcfunction(L, count_guard);
    lua_getglobal(L, LUA_STRLIBNAME);
    for (int i = 0; i < 5; i++)
        lua_getfield(L, -1 - i, strs[i]);
    lua_remove(L, -6);
    lua_getglobal(L, LUA_TABLIBNAME);
    lua_getfield(L, -1, "move");
    lua_remove(L, -2);
    lua_call(L, 8, 0);
    lua_getglobal(L, LUA_TABLIBNAME);
    lua_pushcfunction(L, counted_insert);
    lua_setfield(L, -2, "insert");
    lua_pushcfunction(L, counted_remove);
    lua_setfield(L, -2, "remove");
    lua_pop(L, 1);
    lua_pushcfunction(L, counted_print);
    lua_setglobal(L, "print");
}
