/*
** The figure language: every opener of its functions, in order (the
** sandbox of script.c opens it before the name guards; the fuzz target's
** dictionary, tests/fuzz/gen-script-dict.c, lists the names it defines).
*/
#include "lanimate.h"
#include "lbspline.h"
#include "lcommon.h"
#include "lfigure.h"
#include "lparams.h"
#include "lsurface.h"
#include "ltheme.h"

void
cf__lua_open_language(lua_State *L)
{
    cf__lua_open_bezier(L);
    cf__lua_open_bspline(L);
    cf__lua_open_knots(L);
    cf__lua_open_bernstein(L);
    cf__lua_open_offset(L);
    cf__lua_open_reduce(L);
    cf__lua_open_interp(L);
    cf__lua_open_conic(L);
    cf__lua_open_surface(L);
    cf__lua_open_surface_make(L);
    cf__lua_open_surface_triangle(L);
    cf__lua_open_figure(L);
    cf__lua_open_params(L);
    cf__lua_open_animate(L);
    cf__lua_open_theme(L);
}
