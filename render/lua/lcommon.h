/*
** Helpers shared by the Lua binding files (render/lua/l*.c): reading
** points and numbers from Lua tables into scratch buffers that Lua owns
** (so nothing leaks when a luaL_check* longjmps), pushing results back,
** boxes for library objects, and turning a status into a Lua error.
*/
#ifndef CURVEFIG_RENDER_LUA_LCOMMON_H
#define CURVEFIG_RENDER_LUA_LCOMMON_H

#include <stdbool.h>
#include <stdio.h>

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
** the least number of points accepted.  A list takes no names: an entry
** other than 1..n of the list, or of one of its points, is refused ("the
** point list has an entry named 'closed'"); so in the other readers
** of lists and points below. */
double *cf__lua_check_points(lua_State *L, int idx, const char *fn,
                             const char *what, size_t min, size_t *count,
                             size_t *dim);
/* The same for the list part of a table whose names its function has
** checked (bezier{ P0, P1, weights = {...} }). */
double *cf__lua_check_point_list(lua_State *L, int idx, const char *fn,
                                 const char *what, size_t min,
                                 size_t *count, size_t *dim);
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
/* A string (or a number, as text) argument; def when nil or none (def
** NULL: required).  "bspline: kind must be a string, got table". */
const char *cf__lua_opt_text(lua_State *L, int idx, const char *fn,
                             const char *what, const char *def);
/* A text that reaches an output (a caption, a title, a name, a label, a
** legend entry, a slider's label ...): a string or a number, valid UTF-8
** without NUL or control characters other than tab and newline; refused
** otherwise with the key and the byte, counted from 0 as in labels
** ("figure: caption has the control character U+0001 at byte 3").
** cf__lua_opt_text checks the same. */
const char *cf__lua_check_text(lua_State *L, int idx, const char *fn,
                               const char *what);
/* The length of the UTF-8 sequence at text (n bytes left), 0 when it is
** not valid UTF-8 (overlong forms, surrogates, past U+10FFFF). */
size_t cf__utf8_sequence(const char *text, size_t n);

/* true or false (nil or none: def); another value is refused, not read as
** Lua's truth ("closed = 'no'" is no longer true). */
bool cf__lua_opt_bool_arg(lua_State *L, int idx, const char *fn,
                          const char *what, bool def);

void cf__lua_push_point(lua_State *L, const double *p, size_t dim);
void cf__lua_push_points(lua_State *L, const double *p, size_t count,
                         size_t dim);
void cf__lua_push_numbers(lua_State *L, const double *v, size_t count);

/* Field of the table at idx, pushed (nil when absent). */
int cf__lua_field(lua_State *L, int idx, const char *key);

/* Raise "fn: message" for a failed status, with the script's position. */
int cf__lua_fail(lua_State *L, const char *fn, cf_status_t status,
                 const cf_diag_t *diag);

/* nresults when status is OK; otherwise the error of cf__lua_fail. */
int cf__lua_done(lua_State *L, const char *fn, cf_status_t status,
                 const cf_diag_t *diag, int nresults);

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
void cf__lua_open_knots(lua_State *L);
void cf__lua_open_offset(lua_State *L);
void cf__lua_open_reduce(lua_State *L);
void cf__lua_open_interp(lua_State *L);
void cf__lua_open_conic(lua_State *L);
/* All of the figure language's functions, every opener in order, before
** the name guards (language.c). */
void cf__lua_open_language(lua_State *L);

/* The one grow helper of the binding's growing C buffers: makes room for
** need elements of elem bytes in *ptr (capacity *cap elements), doubling
** from 64, never past max elements.  The memory comes from the library's
** current allocator -- the script's budget while a script runs -- and is
** freed with cf_free.  On failure (need > max, overflow, memory) returns
** false and leaves *ptr and *cap as they were: the caller still owns the
** old block, and frees it once. */
bool cf__lua_grow(void **ptr, size_t *cap, size_t need, size_t elem,
                  size_t max);

/* The allocator's user data of every state the script module makes
** (script.c) begins with this: the bindings tell the memory limit from
** another failure by it, without calling up into the script module. */
typedef struct cf__lua_budget {
    bool memory_exceeded; /* the script's memory limit was reached */
    /* the instructions run (work done in C charged too) and the limit */
    unsigned long long instructions, max_instructions;
    size_t printed;       /* bytes print has written */
    FILE *out;            /* where print writes */
    /* raises the limit's error when a limit is exceeded (script-budget.c);
    ** returns 0 otherwise */
    int (*check)(lua_State *L);
} cf__lua_budget_t;

/* True when the state's memory limit was reached (a NO_MEMORY status is
** then reported as "out of memory" for the limit's message). */
bool cf__lua_memory_exceeded(lua_State *L);

#endif
