/*
** The parameters of interactive figures in the figure language
** (lparams.c): slider{...} and points{...}, reading and declaring in the
** store of params.h.
*/
#ifndef CURVEFIG_RENDER_LUA_LPARAMS_H
#define CURVEFIG_RENDER_LUA_LPARAMS_H

#include <lua.h>

#include "params.h"

/* The store the state's slider{} and points{} declare in (owned by the
** caller, alive while the state runs). */
void cf__lua_set_params(lua_State *L, cf__params_t *params);
/* The state's store (NULL when it has none). */
cf__params_t *cf__lua_params(lua_State *L);
/* Set the globals slider and points. */
void cf__lua_open_params(lua_State *L);

#endif
