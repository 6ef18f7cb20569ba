/*
** Helpers shared by the Lua binding files.
*/
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdint.h>
#include <string.h>

#include "lcommon.h"
#include "../../src/numtext-private.h"

/* More points or numbers than this in one table is certainly a mistake
** (and keeps n * dim * sizeof(double) far from overflow). */
#define MAX_ITEMS ((size_t)1 << 26)

/* What check_len refuses besides entries 1..n */
enum { LIST, ONE_POINT, NAMES_CHECKED };

int
cf__lua_error(lua_State *L, const char *fmt, ...)
{
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    cf__spell_nan(msg);
    return luaL_error(L, "%s", msg);
}

double *
cf__lua_buffer(lua_State *L, size_t n)
{
    if (n > MAX_ITEMS * 4)
        cf__lua_error(L, "too many values (%zu)", n);
    return lua_newuserdatauv(L, (n ? n : 1) * sizeof(double), 0);
}

bool
cf__lua_grow(void **ptr, size_t *cap, size_t need, size_t elem, size_t max)
{
    size_t n = *cap ? *cap : 64;
    void *p;
    if (need <= *cap)
        return true;
    if (need > max || elem == 0)
        return false;
    while (n < need)
        n = n > max / 2 ? max : 2 * n;
    if (n > max)
        n = max;
    p = cf_realloc_array(*ptr, n, elem);
    if (p == NULL)
        return false;
    *ptr = p;
    *cap = n;
    return true;
}

/* A list takes no names: an entry of the table at idx whose key is not
** one of 1..n is refused (one = true: the table is one point).  Of several
** names the first in byte order is named, the same at every run (the
** order of lua_next follows Lua's hash seed, new in every state). */
static void
refuse_names(lua_State *L, int idx, lua_Integer n, const char *fn,
             const char *what, bool one)
{
    const char *name = NULL;
    size_t name_len = 0;
    bool other = false;
    lua_pushnil(L);
    while (lua_next(L, idx) != 0) {
        lua_Integer k;
        lua_pop(L, 1);
        k = lua_isinteger(L, -1) ? lua_tointeger(L, -1) : 0;
        if (k >= 1 && k <= n)
            continue;
        if (lua_type(L, -1) == LUA_TSTRING) {
            size_t len;
            /* the key stays in the table: its text stays put */
            const char *s = lua_tolstring(L, -1, &len);
            int c = name == NULL ? -1
                    : memcmp(s, name, len < name_len ? len : name_len);
            if (name == NULL || c < 0 || (c == 0 && len < name_len)) {
                name = s;
                name_len = len;
            }
        } else {
            other = true;
        }
    }
    if (name != NULL)
        luaL_error(L, "%s: %s%s%s has an entry named '%s'; %s", fn,
                   one ? "" : "the ", what, one ? "" : " list", name,
                   one ? "a point is {x, y, ...}"
                       : "a list takes no names (options go in the "
                         "table after it)");
    if (other)
        luaL_error(L, "%s: %s%s%s has an entry outside 1..%d", fn,
                   one ? "" : "the ", what, one ? "" : " list", (int)n);
}

static size_t
check_len(lua_State *L, int idx, const char *fn, const char *what, int names)
{
    lua_Integer n;
    if (lua_isnil(L, idx)
        && (names == ONE_POINT || strstr(what, "point") != NULL))
        luaL_error(L, "%s: %s is nil; Lua lists start at 1: P[1] is P_0, "
                   "P[0] is nil", fn, what);
    if (!lua_istable(L, idx))
        luaL_error(L, "%s: %s must be a table, got %s", fn, what,
                   luaL_typename(L, idx));
    n = luaL_len(L, idx);
    if (n < 0 || (lua_Unsigned)n > MAX_ITEMS)
        cf__lua_error(L, "%s: %s has %lld entries; too many", fn, what,
                      (long long)n);
    if (names != NAMES_CHECKED)
        refuse_names(L, idx, n, fn, what, names == ONE_POINT);
    return (size_t)n;
}

/* Entry i (counted from 1, as Lua's) of a list of what, for a message:
** control points, knots and weights by their mathematical index
** ("point P_0", "knot u_3", "weight w_1", as the language's conventions
** count them), other entries as Lua counts them. */
static const char *
entry_name(char *buf, size_t cap, const char *what, size_t i)
{
    static const char *const math[][2] = {
        { "point", "P" }, { "knot", "u" }, { "weight", "w" },
    };
    for (size_t k = 0; k < sizeof math / sizeof math[0]; k++)
        if (strcmp(what, math[k][0]) == 0) {
            snprintf(buf, cap, "%s %s_%zu", what, math[k][1], i - 1);
            return buf;
        }
    snprintf(buf, cap, "%s %zu", what, i);
    return buf;
}

/* Coordinate k of the point at tbl: point i (counted from 1) of a list,
** or the one point when i is 0. */
static double
coord(lua_State *L, int tbl, lua_Integer k, const char *fn, const char *what,
      size_t i)
{
    int isnum;
    double v;
    char point[80];
    if (i > 0)
        entry_name(point, sizeof point, what, i);
    else
        snprintf(point, sizeof point, "%s", what);
    lua_geti(L, tbl, k);
    v = (double)lua_tonumberx(L, -1, &isnum);
    if (!isnum)
        cf__lua_error(L, "%s: %s coordinate %d is %s, not a number", fn,
                      point, (int)k, luaL_typename(L, -1));
    if (!isfinite(v))
        cf__lua_error(L, "%s: %s coordinate %d is %s; coordinates must be "
                      "finite", fn, point, (int)k, CF__NUM(v));
    lua_pop(L, 1);
    return v;
}

static double *
check_points(lua_State *L, int idx, const char *fn, const char *what,
             size_t min, size_t *count, size_t *dim, int names)
{
    size_t n, d = 0;
    double *buf;
    idx = lua_absindex(L, idx);
    n = check_len(L, idx, fn, what, names);
    if (n < min)
        cf__lua_error(L, "%s: %zu %s%s given, at least %zu needed", fn, n,
                      what, n == 1 ? "" : "s", min);
    for (size_t i = 0; i < n; i++) {
        size_t di;
        char name[80];
        lua_geti(L, idx, (lua_Integer)i + 1);
        entry_name(name, sizeof name, what, i + 1);
        if (lua_isnil(L, -1))
            cf__lua_error(L, "%s: %s (entry %zu) is nil; Lua lists start at "
                          "1: P[1] is P_0, P[0] is nil", fn, name, i + 1);
        if (!lua_istable(L, -1))
            cf__lua_error(L, "%s: %s must be a table {x, y, ...}, got %s",
                          fn, name, luaL_typename(L, -1));
        di = (size_t)luaL_len(L, -1);
        refuse_names(L, lua_gettop(L), (lua_Integer)di, fn, what, true);
        lua_pop(L, 1);
        if (di < 1)
            cf__lua_error(L, "%s: %s has no coordinates", fn, name);
        if (i == 0)
            d = di;
        else if (di != d)
        {
            char first[80];
            cf__lua_error(L, "%s: %s has %zu coordinates, %s has %zu", fn,
                          name, di, entry_name(first, sizeof first, what, 1),
                          d);
        }
    }
    if (n > 0 && d > CF__LUA_MAX_DIM)
        cf__lua_error(L, "%s: points with %zu coordinates; at most %d", fn, d,
                      CF__LUA_MAX_DIM);
    buf = cf__lua_buffer(L, n * d);
    for (size_t i = 0; i < n; i++) {
        lua_geti(L, idx, (lua_Integer)i + 1);
        for (size_t k = 0; k < d; k++)
            buf[i * d + k] = coord(L, lua_gettop(L), (lua_Integer)k + 1, fn,
                                   what, i + 1);
        lua_pop(L, 1);
    }
    *count = n;
    *dim = d;
    return buf;
}

double *
cf__lua_check_points(lua_State *L, int idx, const char *fn, const char *what,
                     size_t min, size_t *count, size_t *dim)
{
    return check_points(L, idx, fn, what, min, count, dim, LIST);
}

double *
cf__lua_check_point_list(lua_State *L, int idx, const char *fn,
                         const char *what, size_t min, size_t *count,
                         size_t *dim)
{
    return check_points(L, idx, fn, what, min, count, dim, NAMES_CHECKED);
}

double *
cf__lua_check_point(lua_State *L, int idx, const char *fn, const char *what,
                    size_t *dim)
{
    size_t d;
    double *buf;
    idx = lua_absindex(L, idx);
    d = check_len(L, idx, fn, what, ONE_POINT);
    if (d < 1)
        luaL_error(L, "%s: %s has no coordinates", fn, what);
    if (*dim != 0 && d != *dim)
        cf__lua_error(L, "%s: %s has %zu coordinates, expected %zu", fn,
                      what, d, *dim);
    buf = cf__lua_buffer(L, d);
    for (size_t k = 0; k < d; k++)
        buf[k] = coord(L, idx, (lua_Integer)k + 1, fn, what, 0);
    *dim = d;
    return buf;
}

double *
cf__lua_check_numbers(lua_State *L, int idx, const char *fn, const char *what,
                      size_t *count)
{
    size_t n;
    double *buf;
    idx = lua_absindex(L, idx);
    n = check_len(L, idx, fn, what, LIST);
    buf = cf__lua_buffer(L, n);
    for (size_t i = 0; i < n; i++) {
        int isnum;
        char name[80];
        lua_geti(L, idx, (lua_Integer)i + 1);
        buf[i] = (double)lua_tonumberx(L, -1, &isnum);
        if (!isnum)
            cf__lua_error(L, "%s: %s is %s, not a number", fn,
                          entry_name(name, sizeof name, what, i + 1),
                          luaL_typename(L, -1));
        if (!isfinite(buf[i]))
            cf__lua_error(L, "%s: %s is %s; it must be finite", fn,
                          entry_name(name, sizeof name, what, i + 1),
                          CF__NUM(buf[i]));
        lua_pop(L, 1);
    }
    *count = n;
    return buf;
}

double
cf__lua_check_finite(lua_State *L, int idx, const char *fn, const char *what)
{
    int isnum;
    double v = (double)lua_tonumberx(L, idx, &isnum);
    if (!isnum)
        luaL_error(L, "%s: %s must be a number, got %s", fn, what,
                   luaL_typename(L, idx));
    if (!isfinite(v))
        cf__lua_error(L, "%s: %s is %s; it must be finite", fn, what,
                      CF__NUM(v));
    return v;
}

int
cf__lua_check_int(lua_State *L, int idx, const char *fn, const char *what,
                  int lo, int hi)
{
    int isint;
    lua_Integer v;
    if (lua_type(L, idx) != LUA_TNUMBER)
        luaL_error(L, "%s: %s must be an integer, got %s", fn, what,
                   luaL_typename(L, idx));
    v = lua_tointegerx(L, idx, &isint);
    if (!isint)
        luaL_error(L, "%s: %s must be an integer, got %s", fn, what,
                   lua_tostring(L, idx));
    if (v < lo || v > hi)
        cf__lua_error(L, "%s: %s is %lld; it must be in [%d, %d]", fn, what,
                      (long long)v, lo, hi);
    return (int)v;
}

int
cf__lua_opt_int(lua_State *L, int idx, const char *fn, const char *what,
                int lo, int hi, int def)
{
    if (lua_isnoneornil(L, idx))
        return def;
    return cf__lua_check_int(L, idx, fn, what, lo, hi);
}

size_t
cf__utf8_sequence(const char *text, size_t n)
{
    const unsigned char *u = (const unsigned char *)text;
    unsigned char lo = 0x80, hi = 0xbf;
    size_t len;
    if (n == 0)
        return 0;
    if (u[0] < 0x80)
        return 1;
    if (u[0] >= 0xc2 && u[0] <= 0xdf) {
        len = 2;
    } else if (u[0] >= 0xe0 && u[0] <= 0xef) {
        len = 3;
        lo = u[0] == 0xe0 ? 0xa0 : lo;   /* no overlong form */
        hi = u[0] == 0xed ? 0x9f : hi;   /* no surrogate */
    } else if (u[0] >= 0xf0 && u[0] <= 0xf4) {
        len = 4;
        lo = u[0] == 0xf0 ? 0x90 : lo;
        hi = u[0] == 0xf4 ? 0x8f : hi;   /* nothing past U+10FFFF */
    } else {
        return 0;
    }
    if (n < len || u[1] < lo || u[1] > hi)
        return 0;
    for (size_t k = 2; k < len; k++)
        if (u[k] < 0x80 || u[k] > 0xbf)
            return 0;
    return len;
}

const char *
cf__lua_check_text(lua_State *L, int idx, const char *fn, const char *what)
{
    size_t len, n;
    const char *text;
    if (!lua_isstring(L, idx))
        luaL_error(L, "%s: %s must be a string, got %s", fn, what,
                   luaL_typename(L, idx));
    text = lua_tolstring(L, idx, &len);
    for (size_t i = 0; i < len; i += n) {
        unsigned char c = (unsigned char)text[i];
        n = cf__utf8_sequence(text + i, len - i);
        if (n == 0)
            cf__lua_error(L, "%s: %s has invalid UTF-8 at byte %zu (0x%02X)",
                          fn, what, i, c);
        if (c == 0)
            cf__lua_error(L, "%s: %s has a NUL byte at byte %zu", fn, what,
                          i);
        if (c < 0x20 && c != '\t' && c != '\n')
            cf__lua_error(L, "%s: %s has the control character U+%04X at "
                          "byte %zu", fn, what, c, i);
    }
    return text;
}

const char *
cf__lua_opt_text(lua_State *L, int idx, const char *fn, const char *what,
                 const char *def)
{
    if (lua_isnoneornil(L, idx) && def != NULL)
        return def;
    return cf__lua_check_text(L, idx, fn, what);
}

bool
cf__lua_opt_bool_arg(lua_State *L, int idx, const char *fn, const char *what,
                     bool def)
{
    if (lua_isnoneornil(L, idx))
        return def;
    if (!lua_isboolean(L, idx))
        luaL_error(L, "%s: %s is true or false, got %s", fn, what,
                   luaL_typename(L, idx));
    return lua_toboolean(L, idx);
}

void
cf__lua_push_point(lua_State *L, const double *p, size_t dim)
{
    lua_createtable(L, (int)dim, 0);
    for (size_t k = 0; k < dim; k++) {
        lua_pushnumber(L, (lua_Number)p[k]);
        lua_rawseti(L, -2, (lua_Integer)k + 1);
    }
}

void
cf__lua_push_points(lua_State *L, const double *p, size_t count, size_t dim)
{
    lua_createtable(L, count > INT32_MAX ? 0 : (int)count, 0);
    for (size_t i = 0; i < count; i++) {
        cf__lua_push_point(L, p + i * dim, dim);
        lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
}

void
cf__lua_push_numbers(lua_State *L, const double *v, size_t count)
{
    lua_createtable(L, count > INT32_MAX ? 0 : (int)count, 0);
    for (size_t i = 0; i < count; i++) {
        lua_pushnumber(L, (lua_Number)v[i]);
        lua_rawseti(L, -2, (lua_Integer)i + 1);
    }
}

int
cf__lua_field(lua_State *L, int idx, const char *key)
{
    if (!lua_istable(L, idx)) {
        lua_pushnil(L);
        return LUA_TNIL;
    }
    return lua_getfield(L, idx, key);
}

bool
cf__lua_memory_exceeded(lua_State *L)
{
    void *ud = NULL;
    lua_getallocf(L, &ud);
    return ud != NULL && ((const cf__lua_budget_t *)ud)->memory_exceeded;
}

int
cf__lua_fail(lua_State *L, const char *fn, cf_status_t status,
             const cf_diag_t *diag)
{
    if (status == CF_STATUS_NO_MEMORY && cf__lua_memory_exceeded(L))
        return luaL_error(L, "%s: out of memory", fn);
    if (diag != NULL && diag->status != CF_STATUS_OK && diag->msg[0] != '\0')
        return luaL_error(L, "%s: %s", fn, diag->msg);
    return luaL_error(L, "%s: %s", fn, cf_status_to_string(status));
}

int
cf__lua_done(lua_State *L, const char *fn, cf_status_t status,
             const cf_diag_t *diag, int nresults)
{
    if (status != CF_STATUS_OK)
        return cf__lua_fail(L, fn, status, diag);
    return nresults;
}

/* ---- holders ------------------------------------------------------------ */

typedef struct holder {
    cf__lua_free_fn fn;
    void *ptr;
} holder;

static int
holder_gc(lua_State *L)
{
    holder *h = luaL_checkudata(L, 1, CF__LUA_HOLDER);
    if (h->ptr != NULL && h->fn != NULL)
        h->fn(h->ptr);
    h->ptr = NULL;
    return 0;
}

void **
cf__lua_holder(lua_State *L, cf__lua_free_fn fn)
{
    holder *h = lua_newuserdatauv(L, sizeof *h, 0);
    h->fn = fn;
    h->ptr = NULL;
    if (luaL_newmetatable(L, CF__LUA_HOLDER)) {
        lua_pushcfunction(L, holder_gc);
        lua_setfield(L, -2, "__gc");
        lua_pushliteral(L, "locked");
        lua_setfield(L, -2, "__metatable");
    }
    lua_setmetatable(L, -2);
    return &h->ptr;
}

void
cf__lua_holder_release(lua_State *L, int idx)
{
    holder *h = luaL_checkudata(L, idx, CF__LUA_HOLDER);
    if (h->ptr != NULL && h->fn != NULL)
        h->fn(h->ptr);
    h->ptr = NULL;
}

void
cf__lua_new_class(lua_State *L, const char *name, const luaL_Reg *methods,
                  lua_CFunction gc, lua_CFunction tostring)
{
    luaL_newmetatable(L, name);
    lua_newtable(L);
    luaL_setfuncs(L, methods, 0);
    lua_setfield(L, -2, "__index");
    lua_pushcfunction(L, gc);
    lua_setfield(L, -2, "__gc");
    lua_pushcfunction(L, gc);
    lua_setfield(L, -2, "__close");
    if (tostring != NULL) {
        lua_pushcfunction(L, tostring);
        lua_setfield(L, -2, "__tostring");
    }
    lua_pushliteral(L, "locked");
    lua_setfield(L, -2, "__metatable");
    lua_pop(L, 1);
}
