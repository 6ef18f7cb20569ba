/*
** The labels of the points a drawing method marks (llabels.h).
*/
#include <string.h>

#include "curvefig/figure3d.h"
#include "lcommon.h"
#include "llabels.h"
#include "lstyle.h"

/* fmt with every plain %d that follows _ or ^ and receives a number of
** several characters wrapped in braces (u_%d of 10: u_{%d}); pushed. */
static const char *
group_format(lua_State *L, const char *fmt, const lua_Integer *args,
             int nargs)
{
    luaL_Buffer b;
    int a = 0;
    luaL_buffinit(L, &b);
    for (const char *p = fmt; *p != '\0'; p++) {
        if (*p != '%') {
            luaL_addchar(&b, *p);
        } else if (p[1] == '%') {
            luaL_addlstring(&b, p++, 2);
        } else if (p[1] == 'd' && p > fmt && (p[-1] == '_' || p[-1] == '^')
                   && a < nargs && (args[a] >= 10 || args[a] < 0)) {
            luaL_addstring(&b, "{%d}");
            p++;
            a++;
        } else {
            /* another conversion: copied through its letter */
            luaL_addchar(&b, *p++);
            while (*p != '\0' && strchr("-+ #0123456789.", *p) != NULL)
                luaL_addchar(&b, *p++);
            if (*p == '\0')
                break;
            luaL_addchar(&b, *p);
            a++;
        }
    }
    luaL_pushresult(&b);
    return lua_tostring(L, -1);
}

/* string.format(fmt, args...) with the digits grouped; pushes the text. */
static const char *
format_label(lua_State *L, const char *fmt, const lua_Integer *args,
             int nargs)
{
    lua_getfield(L, LUA_REGISTRYINDEX, "curvefig.format");
    group_format(L, fmt, args, nargs);
    for (int k = 0; k < nargs; k++)
        lua_pushinteger(L, args[k]);
    lua_call(L, nargs + 1, 1);
    return lua_tostring(L, -1);
}

const char *
cf__lua_item_label(lua_State *L, int idx, size_t k, const lua_Integer *args,
                   int nargs, const char *fn)
{
    int t = lua_type(L, idx);
    if (t == LUA_TSTRING) {
        if (nargs == 0) {
            lua_pushvalue(L, idx);
            return cf__lua_check_text(L, -1, fn, "labels");
        }
        format_label(L, cf__lua_check_text(L, idx, fn, "labels"), args,
                     nargs);
        return cf__lua_check_text(L, -1, fn, "labels");
    }
    if (t == LUA_TTABLE) {
        lua_geti(L, idx, (lua_Integer)k + 1);
    } else if (t == LUA_TFUNCTION) {
        lua_pushvalue(L, idx);
        for (int i = 0; i < nargs; i++)
            lua_pushinteger(L, args[i]);
        lua_call(L, nargs, 1);
    } else if (t == LUA_TNIL || t == LUA_TBOOLEAN) {
        lua_pushnil(L);
    } else {
        luaL_error(L, "%s: labels must be a format string, a table of "
                   "strings or a function", fn);
    }
    if (lua_type(L, -1) == LUA_TSTRING || lua_type(L, -1) == LUA_TNUMBER)
        return cf__lua_check_text(L, -1, fn, "labels");
    if (!lua_isnil(L, -1) && !lua_isboolean(L, -1))
        luaL_error(L, "%s: labels entry %d is a %s, not a string", fn,
                   (int)k + 1, luaL_typename(L, -1));
    return NULL;
}

/* The place of label k from the label_place value at idx into ls. */
static void
label_place(lua_State *L, int idx, size_t k, const lua_Integer *args,
            int nargs, const double *xy, const char *text, cf_style_t *ls,
            const char *fn)
{
    cf_diag_t diag;
    int t = lua_type(L, idx);
    if (t == LUA_TTABLE) {
        t = lua_geti(L, idx, (lua_Integer)k + 1);
    } else if (t == LUA_TFUNCTION) {
        lua_pushvalue(L, idx);
        for (int i = 0; i < nargs; i++)
            lua_pushinteger(L, args[i]);
        lua_pushnumber(L, xy[0]);
        lua_pushnumber(L, xy[1]);
        lua_call(L, nargs + 2, 1);
        t = lua_type(L, -1);
    } else {
        lua_pushvalue(L, idx);
    }
    if (t == LUA_TSTRING) {
        cf_diag_clear(&diag);
        if (cf_place_from_name(lua_tostring(L, -1), &ls->place, &diag))
            luaL_error(L, "%s: label_place: %s", fn, diag.msg);
        ls->set |= CF_STYLE_PLACE;
    } else if (t != LUA_TNIL) {
        luaL_error(L, "%s: label_place is a place (\"ne\"), a table of "
                   "places, one per label, or a function returning a place "
                   "(the label \"%s\" got a %s)", fn, text,
                   lua_typename(L, t));
    }
    lua_pop(L, 1);
}

/* Label k with the integers a (nargs of them) at xy, if it has a text;
** labels and places at top + 1, top + 2. */
/* Labels anchored at points in R^3 (NULL: in the plane) and what their
** hidden points do. */
typedef struct space_at {
    const double *p3;
    cf_hidden_t hidden;
} space_at_t;

static void
label_one(lua_State *L, cf_figure_t *fig, int top, size_t k,
          const lua_Integer *a, int nargs, const double *xy,
          const cf_style_t *base, const space_at_t *sp, const char *fn)
{
    const char *text = cf__lua_item_label(L, top + 1, k, a, nargs, fn);
    cf_style_t ls = *base;
    cf_diag_t diag;
    if (text == NULL)
        return;
    label_place(L, top + 2, k, a, nargs, xy, text, &ls, fn);
    cf_diag_clear(&diag);
    cf__lua_fig_check(L, fn, fig, sp->p3 != NULL
                      ? cf_figure_add_space_label(fig, sp->p3 + 3 * k, text,
                                                  sp->hidden, &ls)
                      : cf_figure_add_label(fig, xy[0], xy[1], text, &ls),
                      &diag);
}

static void
label_items(lua_State *L, cf_figure_t *fig, int opts, const char *labels_key,
            const double *pts, size_t n, const lua_Integer *args, int nargs,
            const space_at_t *sp, const char *fn)
{
    int top = lua_gettop(L), t;
    cf_style_t base;
    lua_Integer start, *a;
    if (!cf__lua_labels_on(L) || !lua_istable(L, opts))
        return;
    t = cf__lua_field(L, opts, labels_key);
    if (t == LUA_TNIL || (t == LUA_TBOOLEAN && !lua_toboolean(L, -1))) {
        lua_settop(L, top);
        return;
    }
    cf__lua_field(L, opts, "label_place");
    cf__lua_field(L, opts, "label_start");
    start = cf__lua_opt_int(L, -1, fn, "label_start", -(1 << 30), 1 << 30, 0);
    cf__lua_read_sub_style(L, opts, "label_style", fn, fig, &base);
    a = lua_newuserdatauv(L, (nargs > 0 ? (size_t)nargs : 1) * sizeof *a, 0);
    for (size_t k = 0; k < n; k++) {
        if (nargs > 0) {
            memcpy(a, args + k * (size_t)nargs, (size_t)nargs * sizeof *a);
            a[0] += start;
        }
        label_one(L, fig, top, k, a, nargs, pts + 2 * k, &base, sp, fn);
        lua_settop(L, top + 4);
    }
    lua_settop(L, top);
}

void
cf__lua_label_items(lua_State *L, cf_figure_t *fig, int opts,
                    const char *labels_key, const double *pts, size_t n,
                    const lua_Integer *args, int nargs, const char *fn)
{
    space_at_t plane = {NULL, CF_HIDDEN_SHOW};
    label_items(L, fig, opts, labels_key, pts, n, args, nargs, &plane, fn);
}

void
cf__lua_label_space_items(lua_State *L, cf_figure_t *fig, int opts,
                          const char *labels_key, const double *pts,
                          const double *p3, cf_hidden_t hidden, size_t n,
                          const lua_Integer *args, int nargs, const char *fn)
{
    space_at_t sp = {p3, hidden};
    label_items(L, fig, opts, labels_key, pts, n, args, nargs, &sp, fn);
}
