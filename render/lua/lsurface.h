/*
** Surfaces as Lua values (lsurface.c), for the other binding files: one
** class "curvefig.surface" holding a Bézier or a B-spline (NURBS) surface.
*/
#ifndef CURVEFIG_RENDER_LUA_LSURFACE_H
#define CURVEFIG_RENDER_LUA_LSURFACE_H

#include <lauxlib.h>
#include <lua.h>

#include "curvefig/surface-triangle.h"
#include "curvefig/surface.h"

#define CF__LUA_SURFACE "curvefig.surface"

/* The userdata: one of the two is set (NULL both once closed). */
typedef struct cf__lua_surface {
    cf_bezier_surface_t *bz;
    cf_bspline_surface_t *bs;
} cf__lua_surface_t;

/* self (argument 1) of a method: an open surface. */
cf__lua_surface_t *cf__lua_check_surface(lua_State *L);

/* The class's __gc / __tostring and the constructors bezier_surface{}
** and bspline_surface{} (lsurface.c; the opener in lsurface-methods.c
** puts them in place). */
int cf__lua_surface_gc(lua_State *L);
int cf__lua_surface_tostring(lua_State *L);
int cf__lua_bezier_surface(lua_State *L);
int cf__lua_bspline_surface(lua_State *L);

/* A new empty surface value on the stack; store the result in *slot. */
cf_bezier_surface_t **cf__lua_new_bezier_surface(lua_State *L);
cf_bspline_surface_t **cf__lua_new_bspline_surface(lua_State *L);

/* The grid of points at idx ({ {P11, P12, ...}, {P21, ...}, ... }, every
** row as long, every point of one dimension, finite): a scratch buffer,
** row after row, with its sizes; messages name row and column from 1
** ("row 3 has 4 points, row 1 has 5", "point P[3][2] ..."). */
double *cf__lua_check_grid(lua_State *L, int idx, const char *fn,
                           size_t *nu, size_t *nv, size_t *dim);

/* The triangular patch at idx (bezier_triangle{...}), NULL if it is not
** one or was closed (lsurface-triangle.c). */
cf_bezier_triangle_t *cf__lua_to_triangle(lua_State *L, int idx);

void cf__lua_open_surface(lua_State *L);
void cf__lua_open_surface_make(lua_State *L);
void cf__lua_open_surface_triangle(lua_State *L);

#endif
