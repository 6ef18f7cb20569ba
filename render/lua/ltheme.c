/*
** The fonts of a whole set of figures: theme{ family = "sans", size = 11 }
** (and their colours: theme{ palette = "okabe-ito", redundant = true })
** (TeX points) in a script sets them for every figure made after it; the
** tool's --font, --font-size and --theme set them for every script it
** renders, over the scripts' theme{} calls; figure{ font = ..., font_size
** = ... } sets one figure's.  Each figure{} applies them to its theme.
*/
#include <string.h>

#include "curvefig/figure.h"
#include "lcommon.h"
#include "lschema.h"
#include "lstyle.h"
#include "ltheme.h"

/* registry fields: the script's theme{} and the tool's choice */
#define SCRIPT_FAMILY "curvefig.font_family"
#define SCRIPT_SIZE "curvefig.font_size"
#define TOOL_FAMILY "curvefig.tool_font_family"
#define TOOL_SIZE "curvefig.tool_font_size"
#define SCRIPT_PALETTE "curvefig.palette"
#define SCRIPT_REDUNDANT "curvefig.redundant"

/* The family and size (bp, 0: none) in registry fields fam and size. */
static void
registry_fonts(lua_State *L, const char *fam, const char *size,
               const char **family, double *bp)
{
    lua_getfield(L, LUA_REGISTRYINDEX, fam);
    if (lua_isstring(L, -1))
        *family = lua_tostring(L, -1);   /* kept alive by the registry */
    lua_pop(L, 1);
    lua_getfield(L, LUA_REGISTRYINDEX, size);
    if (lua_isnumber(L, -1))
        *bp = lua_tonumber(L, -1);
    lua_pop(L, 1);
}

/* Check family and size (bp) as cf_theme_set_fonts would; an error
** naming fn otherwise. */
static void
check_fonts(lua_State *L, const char *fn, const char *family, double bp)
{
    cf_theme_t th;
    cf_diag_t diag;
    cf_theme_get("default", &th, NULL);
    if (cf_theme_set_fonts(&th, family, bp, &diag) != CF_STATUS_OK)
        luaL_error(L, "%s: %s", fn, diag.msg);
}

/* family at idx (nil: NULL) and size at idx + 1 (nil: 0), checked */
static void
read_fonts(lua_State *L, int idx, const char *fn, const char *fkey,
           const char *skey, const char **family, double *bp)
{
    *family = lua_isnil(L, idx) ? NULL
                                : cf__lua_opt_text(L, idx, fn, fkey, NULL);
    /* a bare number is in TeX points, as in \documentclass[11pt] */
    if (lua_isnil(L, idx + 1))
        *bp = 0;
    else if (lua_type(L, idx + 1) == LUA_TNUMBER)
        *bp = cf__lua_check_finite(L, idx + 1, fn, skey) * 72.0 / 72.27;
    else
        *bp = cf__lua_read_length(L, idx + 1, fn, skey, 0);
    if (!lua_isnil(L, idx + 1) && !(*bp > 0))
        luaL_error(L, "%s: %s must be positive", fn, skey);
    check_fonts(L, fn, *family, *bp);
}

/* palette = NAME and redundant = BOOL of theme{} at idx, kept for the
** figures made after it (the schema checked the name). */
static void
read_colours(lua_State *L, int idx)
{
    if (cf__lua_field(L, idx, "palette") != LUA_TNIL) {
        (void)cf__lua_opt_text(L, -1, "theme", "palette", NULL);
        lua_setfield(L, LUA_REGISTRYINDEX, SCRIPT_PALETTE);
    } else {
        lua_pop(L, 1);
    }
    if (cf__lua_field(L, idx, "redundant") != LUA_TNIL) {
        lua_pushboolean(L, cf__lua_opt_bool_arg(L, -1, "theme", "redundant",
                                                false));
        lua_setfield(L, LUA_REGISTRYINDEX, SCRIPT_REDUNDANT);
    }
    lua_pop(L, 1);
}

/* The palette and redundancy of theme{} applied to th. */
static void
apply_colours(lua_State *L, cf_theme_t *th)
{
    cf_diag_t diag;
    cf_diag_clear(&diag);
    if (lua_getfield(L, LUA_REGISTRYINDEX, SCRIPT_PALETTE) == LUA_TSTRING
        && cf_theme_set_palette(th, lua_tostring(L, -1), &diag)
               != CF_STATUS_OK)
        luaL_error(L, "theme: %s", diag.msg);
    lua_pop(L, 1);
    if (lua_getfield(L, LUA_REGISTRYINDEX, SCRIPT_REDUNDANT) == LUA_TBOOLEAN)
        th->redundant = lua_toboolean(L, -1);
    lua_pop(L, 1);
}

/* theme{ family = "serif" | "sans" | "Family,...", size = "11pt",
** palette = "okabe-ito", redundant = true } */
static int
l_theme(lua_State *L)
{
    const char *family;
    double bp;
    lua_settop(L, 1);
    luaL_checktype(L, 1, LUA_TTABLE);
    cf__lua_check_table(L, 1, CF__KEYS_THEME);
    read_colours(L, 1);
    cf__lua_field(L, 1, "family");
    cf__lua_field(L, 1, "size");
    read_fonts(L, 2, "theme", "family", "size", &family, &bp);
    if (family != NULL) {
        lua_pushvalue(L, 2);
        lua_setfield(L, LUA_REGISTRYINDEX, SCRIPT_FAMILY);
    }
    if (bp > 0) {
        lua_pushnumber(L, bp);
        lua_setfield(L, LUA_REGISTRYINDEX, SCRIPT_SIZE);
    }
    return 0;
}

void
cf__lua_open_theme(lua_State *L)
{
    lua_pushcfunction(L, l_theme);
    lua_setglobal(L, "theme");
}

void
cf__lua_set_tool_fonts(lua_State *L, const char *family, double size_bp)
{
    if (family != NULL)
        lua_pushstring(L, family);
    else
        lua_pushnil(L);
    lua_setfield(L, LUA_REGISTRYINDEX, TOOL_FAMILY);
    if (size_bp > 0)
        lua_pushnumber(L, size_bp);
    else
        lua_pushnil(L);
    lua_setfield(L, LUA_REGISTRYINDEX, TOOL_SIZE);
}

void
cf__lua_apply_fonts(lua_State *L, int opts, cf_figure_t *fig)
{
    const char *family = NULL, *own;
    double bp = 0, own_bp;
    cf_theme_t th;
    cf_diag_t diag;
    int top = lua_gettop(L);
    registry_fonts(L, SCRIPT_FAMILY, SCRIPT_SIZE, &family, &bp);
    registry_fonts(L, TOOL_FAMILY, TOOL_SIZE, &family, &bp);
    cf__lua_field(L, opts, "font");
    cf__lua_field(L, opts, "font_size");
    read_fonts(L, top + 1, "figure", "font", "font_size", &own, &own_bp);
    if (own != NULL)
        family = own;
    if (own_bp > 0)
        bp = own_bp;
    cf_figure_get_theme(fig, &th);
    cf_diag_clear(&diag);
    if (cf_theme_set_fonts(&th, family, bp, &diag) != CF_STATUS_OK)
        luaL_error(L, "figure: %s", diag.msg);
    apply_colours(L, &th);
    if (cf_figure_set_theme(fig, &th) != CF_STATUS_OK) {
        cf_figure_status(fig, &diag);
        luaL_error(L, "figure: %s", diag.msg);
    }
    lua_settop(L, top);
}
