/*
** Helpers shared by the Lua binding files (render/lua/l*.c): reading
** points and numbers from Lua tables into scratch buffers that Lua owns
** (so nothing leaks when a luaL_check* longjmps), pushing results back,
** boxes for library objects, and turning a status into a Lua error.
*/
#ifndef CURVEFIG_RENDER_LUA_LCOMMON_H
#define CURVEFIG_RENDER_LUA_LCOMMON_H

#include <lauxlib.h>
#include <lua.h>

#include "curvefig/core.h"

/* Registry keys of the metatables. */
#define CF__LUA_BEZIER "curvefig.bezier"
#define CF__LUA_BSPLINE "curvefig.bspline"
#define CF__LUA_FIGURE "curvefig.figure"
#define CF__LUA_PLOT "curvefig.plot"
#define CF__LUA_HOLDER "curvefig.holder"
/* Registry flag: true when labels are left out (render --no-labels). */
#define CF__LUA_NO_LABELS "curvefig.nolabels"

/* Limits of the figure language, relied on by the bindings' stack
** buffers: coordinates per point, and the highest derivative order. */
#define CF__LUA_MAX_DIM 64
#define CF__LUA_MAX_DERIV 64

/* luaL_error with the C library's printf (%zu, %g), message <= 511 bytes;
** the script's file and line are put in front. */
int cf__lua_error(lua_State *L, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Scratch memory owned by Lua (a userdata pushed on the stack). */
double *cf__lua_buffer(lua_State *L, size_t n);

/* The array of points at idx: { {x, y, ...}, ... }, all of one dimension.
** Pushes a scratch buffer holding them interleaved; *count and *dim
** receive their number and dimension.  fn names the calling function in
** messages ("bezier: point 3 has 3 coordinates, point 1 has 2"). min is
** the least number of points accepted. */
double *cf__lua_check_points(lua_State *L, int idx, const char *fn,
                             const char *what, size_t min, size_t *count,
                             size_t *dim);
/* One point {x, y, ...} of dimension dim (0: any, then *dim is set). */
double *cf__lua_check_point(lua_State *L, int idx, const char *fn,
                            const char *what, size_t *dim);
/* An array of numbers { a, b, ... }. */
double *cf__lua_check_numbers(lua_State *L, int idx, const char *fn,
                              const char *what, size_t *count);
/* A finite number argument. */
double cf__lua_check_finite(lua_State *L, int idx, const char *fn,
                            const char *what);
/* An integer argument in [lo, hi] (opt: default when absent). */
int cf__lua_check_int(lua_State *L, int idx, const char *fn,
                      const char *what, int lo, int hi);
int cf__lua_opt_int(lua_State *L, int idx, const char *fn, const char *what,
                    int lo, int hi, int def);

void cf__lua_push_point(lua_State *L, const double *p, size_t dim);
void cf__lua_push_points(lua_State *L, const double *p, size_t count,
                         size_t dim);
void cf__lua_push_numbers(lua_State *L, const double *v, size_t count);

/* Field of the table at idx, pushed (nil when absent). */
int cf__lua_field(lua_State *L, int idx, const char *key);

/* Raise "fn: message" for a failed status, with the script's position. */
int cf__lua_fail(lua_State *L, const char *fn, cf_status_t status,
                 const cf_diag_t *diag);

/* A holder: a userdata that frees a library object in __gc unless it was
** released.  Push one, store the object in *slot, and call
** cf__lua_holder_release when it has been taken apart. */
typedef void (*cf__lua_free_fn)(void *);
void **cf__lua_holder(lua_State *L, cf__lua_free_fn fn);
void cf__lua_holder_release(lua_State *L, int idx);

/* Define a metatable: __index = methods, __gc and __close = gc,
** __tostring, __name; __metatable locked so scripts cannot reach __gc. */
void cf__lua_new_class(lua_State *L, const char *name, const luaL_Reg *methods,
                       lua_CFunction gc, lua_CFunction tostring);

/* The openers (each sets its globals in the state). */
void cf__lua_open_bezier(lua_State *L);
void cf__lua_open_bernstein(lua_State *L);
void cf__lua_open_offset(lua_State *L);
void cf__lua_open_interp(lua_State *L);
void cf__lua_open_conic(lua_State *L);

/* The budget hook the script module installs; the bindings map a
** NO_MEMORY status to the memory-limit message through it. */
int cf__lua_memory_exceeded(lua_State *L);

#endif
