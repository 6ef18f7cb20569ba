/*
** figure{ alt = "...", description = "..." | "auto" | "", lang = "cs" }:
** the accessible text of a figure (curvefig/access.h); the description is
** "auto" unless given ("": none).
*/
#include <lauxlib.h>

#include "curvefig/access.h"
#include "lcommon.h"
#include "lfigure.h"

/* The string of key `what` of table 1, or NULL when absent. */
static const char *
opt_string(lua_State *L, const char *what)
{
    int t = cf__lua_field(L, 1, what);
    const char *s;
    if (t == LUA_TNIL) {
        lua_pop(L, 1);
        return NULL;
    }
    if (t != LUA_TSTRING)
        luaL_error(L, "figure: %s must be a string, got %s", what,
                   lua_typename(L, t));
    s = cf__lua_check_text(L, -1, "figure", what);
    lua_pop(L, 1);    /* the table keeps it alive */
    return s;
}

void
cf__lua_read_access(lua_State *L, cf_figure_t *fig)
{
    const char *alt = opt_string(L, "alt");
    const char *desc = opt_string(L, "description");
    const char *lang = opt_string(L, "lang");
    cf_diag_t diag;
    cf_diag_clear(&diag);
    if (alt != NULL && alt[0] == '\0')
        luaL_error(L, "figure: alt is empty: say in a sentence what the "
                   "figure shows, or leave alt out (the caption is used)");
    /* every figure of a script is described unless it says otherwise */
    if (cf_figure_set_alt(fig, alt) != CF_STATUS_OK
        || cf_figure_set_description(fig, desc != NULL ? desc : "auto")
               != CF_STATUS_OK
        || cf_figure_set_lang(fig, lang) != CF_STATUS_OK) {
        cf_figure_status(fig, &diag);
        luaL_error(L, "figure: %s", diag.msg);
    }
}
