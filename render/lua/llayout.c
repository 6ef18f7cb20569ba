/*
** Layouts in the figure language: the legend = "..." key of every drawing
** method, f:legend{...}, f:inset{...} and f:panels{...}, whose panels are
** figure values of their own that take every method.
*/
#include <string.h>

#include "curvefig/figure.h"
#include "lcommon.h"
#include "llayout.h"
#include "lschema.h"
#include "lstyle.h"

#define check(L, fn, call) cf__lua_fig_check((L), (fn), fig, (call), NULL)

/* ---- legend = "..." ----------------------------------------------------- */

/* A drawing method (upvalue 1, named by upvalue 2) run in this call's
** frame, its arguments and messages as without the wrapper; then the
** first element it added gets the legend entry of the first table
** argument with a legend key (kept in the registry meanwhile). */
static int
with_legend(lua_State *L)
{
    cf_figure_t *fig = cf__lua_check_figure(L);
    const char *fn = lua_tostring(L, lua_upvalueindex(2));
    lua_CFunction method = lua_tocfunction(L, lua_upvalueindex(1));
    size_t before = cf_figure_element_count(fig);
    int top = lua_gettop(L), i, legend = LUA_TNIL, ref = LUA_NOREF, n;
    for (i = 2; i <= top && legend == LUA_TNIL; i++)
        if (lua_type(L, i) == LUA_TTABLE) {
            lua_pushliteral(L, "legend");
            legend = lua_rawget(L, i);
            if (legend == LUA_TSTRING) {
                cf__lua_check_text(L, -1, fn, "legend");
                ref = luaL_ref(L, LUA_REGISTRYINDEX);
            }
            else if (legend == LUA_TNIL)
                lua_pop(L, 1);
        }
    if (legend != LUA_TNIL && legend != LUA_TSTRING)
        return luaL_error(L, "%s: legend must be a string, got %s", fn,
                          lua_typename(L, legend));
    n = method(L);
    if (ref == LUA_NOREF)
        return n;
    lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
    luaL_unref(L, LUA_REGISTRYINDEX, ref);
    if (cf__lua_labels_on(L) && cf_figure_element_count(fig) > before)
        check(L, fn,
              cf_figure_add_legend_at(fig, before, lua_tostring(L, -1)));
    lua_pop(L, 1);
    return n;
}

void
cf__lua_set_legend_methods(lua_State *L, const luaL_Reg *methods)
{
    for (; methods->name != NULL; methods++) {
        lua_pushcfunction(L, methods->func);
        lua_pushstring(L, methods->name);
        lua_pushcclosure(L, with_legend, 2);
        lua_setfield(L, -2, methods->name);
    }
}

/* place (a name) and frame of the table at idx */
static void
read_legend(lua_State *L, cf_figure_t *fig, int idx, const char *fn,
            const char *place_key, const char *frame_key)
{
    cf_place_t place = CF_PLACE_AUTO;
    bool frame;
    cf_diag_t diag;
    cf_diag_clear(&diag);
    if (cf__lua_field(L, idx, place_key) != LUA_TNIL
        && cf_place_from_name(cf__lua_opt_text(L, -1, fn, place_key, NULL),
                              &place, &diag) != CF_STATUS_OK)
        cf__lua_error(L, "%s: %s: %s", fn, place_key, diag.msg);
    lua_pop(L, 1);
    frame = cf__lua_opt_bool(L, idx, frame_key, fn, true);
    check(L, fn, cf_figure_set_legend_place(fig, place, frame));
}

void
cf__lua_read_figure_legend(lua_State *L, cf_figure_t *fig)
{
    read_legend(L, fig, 1, "figure", "legend_place", "legend_frame");
}

/* f:legend{ place = "se", frame = false } */
static int
m_legend(lua_State *L)
{
    cf_figure_t *fig = cf__lua_check_figure(L);
    lua_settop(L, 2);
    luaL_checktype(L, 2, LUA_TTABLE);
    cf__lua_check_table(L, 2, CF__KEYS_LEGEND);
    read_legend(L, fig, 2, "legend", "place", "frame");
    lua_settop(L, 1);
    return 1;
}

/* ---- insets ------------------------------------------------------------- */

/* at = "ne" or {x, y, w, h} (lengths) of the options at idx into in. */
static void
read_at(lua_State *L, int idx, cf_inset_t *in)
{
    int t = cf__lua_field(L, idx, "at");
    cf_diag_t diag;
    cf_diag_clear(&diag);
    if (t == LUA_TTABLE) {
        if (luaL_len(L, -1) != 4)
            luaL_error(L, "inset: at is a place (\"ne\") or {x, y, w, h} in "
                       "page units from the top left");
        for (int k = 0; k < 4; k++) {
            lua_rawgeti(L, -1, k + 1);
            in->rect[k] = cf__lua_read_length(L, -1, "inset", "at", 0);
            lua_pop(L, 1);
        }
        in->has_rect = true;
    } else if (t != LUA_TNIL) {
        static const char *const places[] = {
            "auto", "n", "ne", "e", "se", "s", "sw", "w", "nw", "above",
            "below", "left", "right",
        };
        const char *v = cf__lua_opt_text(L, -1, "inset", "at", NULL), *near;
        in->beside = strcmp(v, "above") == 0 || strcmp(v, "below") == 0
                     || strcmp(v, "left") == 0 || strcmp(v, "right") == 0;
        if (cf_place_from_name(v, &in->place, &diag) != CF_STATUS_OK) {
            near = cf_nearest_name(v, places,
                                   sizeof places / sizeof places[0]);
            if (near != NULL)
                cf__lua_error(L, "inset: at \"%s\" is unknown (did you mean "
                              "\"%s\"?)", v, near);
            cf__lua_error(L, "inset: at: %s", diag.msg);
        }
    }
    lua_pop(L, 1);
}

/* f:inset{ region = {x0, y0, x1, y1}, at = "ne", scale = 3 } */
static int
m_inset(lua_State *L)
{
    cf_figure_t *fig = cf__lua_check_figure(L);
    cf_inset_t in;
    size_t n;
    double *r;
    lua_settop(L, 2);
    luaL_checktype(L, 2, LUA_TTABLE);
    cf__lua_check_table(L, 2, CF__KEYS_INSET);
    cf_inset_init(&in);
    if (cf__lua_field(L, 2, "region") == LUA_TNIL)
        return luaL_error(L, "inset: region = {x0, y0, x1, y1} is required");
    r = cf__lua_check_numbers(L, -1, "inset", "region", &n);
    if (n != 4)
        return luaL_error(L, "inset: region is {x0, y0, x1, y1}, %d numbers "
                          "given", (int)n);
    memcpy(in.region, r, sizeof in.region);
    read_at(L, 2, &in);
    in.scale = cf__lua_opt_number(L, 2, "scale", "inset", 0, NULL);
    cf__lua_field(L, 2, "size");
    in.size = cf__lua_read_length(L, -1, "inset", "size", 0);
    check(L, "inset", cf_figure_add_inset(fig, &in));
    lua_settop(L, 1);
    return 1;
}

/* ---- panels ------------------------------------------------------------- */

/* A figure value for panel p of the figure at idx, named name(letter). */
static void
push_panel(lua_State *L, int parent, cf_figure_t *p, int k)
{
    cf__lua_fbox_t *b = lua_newuserdatauv(L, sizeof *b, 4);
    b->fig = p;
    b->borrowed = true;
    luaL_setmetatable(L, CF__LUA_FIGURE);
    lua_getiuservalue(L, parent, 1);
    lua_pushfstring(L, "%s(%c)", lua_tostring(L, -1), 'a' + k);
    lua_remove(L, -2);
    lua_setiuservalue(L, -2, 1);
    lua_getiuservalue(L, parent, 2);
    lua_setiuservalue(L, -2, 2);
    luaL_where(L, 1);
    lua_setiuservalue(L, -2, 3);
    lua_pushvalue(L, parent);   /* keeps the parent alive */
    lua_setiuservalue(L, -2, 4);
}

/* titles = false, or a list of titles (label syntax) */
static void
read_titles(lua_State *L, cf_figure_t **panels, int n)
{
    if (cf__lua_field(L, 2, "titles") != LUA_TTABLE) {
        lua_pop(L, 1);
        return;
    }
    if ((int)luaL_len(L, -1) > n)
        luaL_error(L, "panels: %d titles for %d panels", (int)luaL_len(L, -1),
                   n);
    for (int k = 0; k < (int)luaL_len(L, -1); k++) {
        lua_rawgeti(L, -1, k + 1);
        cf__lua_fig_check(L, "panels", panels[k],
                          cf_figure_set_panel_title(
                              panels[k], cf__lua_opt_text(L, -1, "panels",
                                                          "title", NULL)),
                          NULL);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
}

/* local a, b = f:panels{ rows = 2, cols = 1, share_x = true } */
static int
m_panels(lua_State *L)
{
    cf_figure_t *fig = cf__lua_check_figure(L);
    cf_figure_t *panels[64];
    unsigned flags = 0;
    int rows, cols, k;
    double gap;
    lua_settop(L, 2);
    luaL_checktype(L, 2, LUA_TTABLE);
    cf__lua_check_table(L, 2, CF__KEYS_PANELS);
    cf__lua_field(L, 2, "rows");
    rows = cf__lua_opt_int(L, -1, "panels", "rows", 1, 8, 1);
    cf__lua_field(L, 2, "cols");
    cols = cf__lua_opt_int(L, -1, "panels", "cols", 1, 8, 1);
    cf__lua_field(L, 2, "gap");
    gap = cf__lua_read_length(L, -1, "panels", "gap", 6);
    lua_settop(L, 2);
    if (cf__lua_opt_bool(L, 2, "share_x", "panels", false))
        flags |= CF_PANELS_SHARE_X;
    if (cf__lua_opt_bool(L, 2, "share_y", "panels", false))
        flags |= CF_PANELS_SHARE_Y;
    if ((cf__lua_field(L, 2, "titles") == LUA_TBOOLEAN
         && !lua_toboolean(L, -1)) || !cf__lua_labels_on(L))
        flags |= CF_PANELS_NO_TITLES;
    lua_settop(L, 2);
    check(L, "panels", cf_figure_add_panels(fig, rows, cols, gap, flags,
                                             panels));
    if (cf__lua_labels_on(L))
        read_titles(L, panels, rows * cols);
    luaL_checkstack(L, rows * cols, "panels");
    for (k = 0; k < rows * cols; k++)
        push_panel(L, 1, panels[k], k);
    return rows * cols;
}

const luaL_Reg cf__lua_layout_methods[] = {
    { "legend", m_legend },
    { "inset", m_inset },
    { "panels", m_panels },
    { NULL, NULL },
};
