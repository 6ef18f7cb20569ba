/*
** The visible = "2-" option of every drawing method: read when the
** method's options are checked (lschema.c), before it draws, and set as
** the figure's overlay for the elements the method adds
** (curvefig/overlay.h).  A method called without it sets none.
*/
#include <lauxlib.h>

#include "curvefig/figure.h"
#include "lcommon.h"
#include "lschema.h"
#include "lstyle.h"

/* idx is absolute (lschema.c). */
void
cf__lua_read_overlay(lua_State *L, int idx, const char *fn)
{
    cf_figure_t *fig;
    const char *spec = NULL;
    cf_diag_t diag;
    int t = LUA_TNIL;
    if (luaL_testudata(L, 1, CF__LUA_FIGURE) == NULL)
        return;   /* the method's own check of self reports it */
    fig = cf__lua_check_figure(L);
    if (lua_istable(L, idx)) {
        lua_pushliteral(L, "visible");
        t = lua_rawget(L, idx);
        if (t == LUA_TSTRING || (t == LUA_TNUMBER && lua_isinteger(L, -1)))
            spec = lua_tostring(L, -1);
        else if (t != LUA_TNIL)
            luaL_error(L, "%s: visible is an overlay specification, a "
                       "string of steps such as \"2-\" or \"1,3\", not a %s",
                       fn, luaL_typename(L, -1));
    }
    cf_diag_clear(&diag);
    cf__lua_fig_check(L, fn, fig, cf_figure_set_overlay(fig, spec), &diag);
    if (lua_istable(L, idx))
        lua_pop(L, 1);
}
