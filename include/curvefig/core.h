/*
** curvefig core: status codes, error details and the allocator hook.
**
** Every fallible function of curvefig returns a cf_status_t (CF_STATUS_OK = 0)
** and takes, as its last argument, an optional cf_diag_t * that receives a
** message naming what was wrong and where ("knot 4 (0.30) is smaller than
** knot 3 (0.50)").  Passing NULL is always allowed.  Nothing in the core
** prints, aborts, uses errno or longjmp.
**
** Ownership and failure, for every header of curvefig:
**   - An object (cf_bezier_t, cf_bspline_t, cf_figure_t, ...) comes from a
**     create function or an operation and is released with its destroy
**     function; destroy(NULL) is harmless.  Curves are immutable: every
**     operation returns a new object and leaves its inputs as they were.
**   - A function that returns an object through `**out` sets *out to NULL
**     when it fails (never a half-built object).  So the variable passed
**     as out loses whatever it held: cf_bspline_insert_knot(c, u, 1, &c,
**     ...) overwrites c, with the result or with NULL.  Write results into
**     a new variable.
**   - Lists (cf_bezier_list_t, cf_cubics_list_t) own their items: their
**     destroy function destroys every item and the list.  Copy an item
**     (cf_bezier_copy) to keep it.
**   - The arrays inside public structs (cf_cubics_t.pts, .t; a list's
**     items, t0, t1) belong to the struct: read them, never free, resize or
**     keep them past the struct's destroy.
**   - Plain arrays a function hands out (said per function) are released
**     with cf_free.
**   - Input arrays are copied: the caller may change or free them as soon
**     as the call returns.
**
** Argument order.  Every evaluator (a function that computes values of a
** curve, a basis or an offset at parameters) takes, in this order: the
** object (a curve, or what defines it: degree, knots, coefficients); the
** parameter, or the parameter array and its count; the other numbers
** (derivative order k, distance d); the outputs; the diag, if any:
**   cf_bezier_eval_derivs(c, t, k, out)
**   cf_bezier_eval_deriv_many(c, t, n, k, out)
**   cf_offset_point_many(c, t, n, d, out)
** (tests/unit/test_api_order.c checks every public header against it).
**
** Parameters.  A parameter that misses an end of its domain [a, b] by at
** most 8 DBL_EPSILON max(|a|, |b|) is that end: the evaluators clamp it.
** One further out is CF_STATUS_DOMAIN; NaN and infinities are
** CF_STATUS_NOT_FINITE.
**
** The API is what these headers declare with CF_API (export.h):
** libcurvefig-core is built with hidden visibility and exports exactly
** those functions; the internals (cf__ names) are not part of it.
*/
#ifndef CURVEFIG_CORE_H
#define CURVEFIG_CORE_H

#include <stdbool.h>
#include <stddef.h>

#include "curvefig/export.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum cf_status {
    CF_STATUS_OK = 0,
    CF_STATUS_NO_MEMORY,      /* an allocation failed */
    CF_STATUS_INVALID_ARG,    /* NULL pointer, zero count, bad option */
    CF_STATUS_DIM_MISMATCH,   /* dimensions of two operands differ */
    CF_STATUS_BAD_DEGREE,     /* negative, too large, or inconsistent */
    CF_STATUS_BAD_KNOTS,      /* knot vector violates a rule */
    CF_STATUS_BAD_WEIGHT,     /* weight not finite or not positive */
    CF_STATUS_NOT_FINITE,     /* NaN or infinite coordinate or parameter */
    CF_STATUS_DOMAIN,         /* parameter outside the curve's domain */
    CF_STATUS_DEGENERATE,     /* zero tangent, coincident points, ... */
    CF_STATUS_NO_CONVERGENCE, /* iteration did not reach its tolerance */
    CF_STATUS_TOO_FEW_POINTS, /* fewer points than the operation needs */
    CF_STATUS_IO,             /* a file could not be written */
    CF_STATUS_SCRIPT,         /* a figure script failed */
    CF_STATUS_LAST_
} cf_status_t;

/* A static English description of a status ("invalid knot vector"). */
CF_API const char *cf_status_to_string(cf_status_t status);

/*
** Optional detail record.  Every function that takes one resets it on
** entry, so after the call it describes that call alone, whether or not
** the caller cleared it: on failure the same status as the return value,
** the offending index (or -1) and a NUL-terminated message; on success
** CF_STATUS_OK, index -1 and an empty message.  Inside one call the first
** error is kept (cf_diag_set writes into a diag that is still OK only).
*/
#define CF_DIAG_MSG_SIZE 192
typedef struct cf_diag {
    cf_status_t status;
    long index;                  /* offending index (point, knot, ...), or -1 */
    char msg[CF_DIAG_MSG_SIZE];  /* NUL-terminated English message */
} cf_diag_t;

/* Reset a diag to "no error". */
CF_API void cf_diag_clear(cf_diag_t *diag);

/* The name of names[0..n-1] nearest to s (Damerau-Levenshtein distance),
** if near enough to suggest in a message's "did you mean" (at most one
** edit per three letters, at least one); else a name that is a word of s
** (degree_elevate: elevate); else NULL. */
CF_API const char *cf_nearest_name(const char *s, const char *const *names,
                                   size_t n);

/*
** Allocator hook, shaped like lua_Alloc: realloc(ud, ptr, old_size,
** new_size); new_size == 0 frees and returns NULL.
**
** Every block remembers the allocator that made it: it is resized and
** freed by that one, whichever allocator is current when cf_free (or a
** destroy function) runs.  New blocks come from the current allocator of
** the calling thread:
**
**   - cf_use_allocator(a, &prev) makes a current for this thread only, and
**     stores the one it replaces in prev; cf_use_allocator(&prev, NULL)
**     puts that back.  Scopes nest, and callers who each keep their own
**     allocator (a sandboxed script, a test) coexist in one process.
**     a == NULL (or a->realloc == NULL) leaves the thread without one of
**     its own.
**   - A thread without one uses the process default: the C library, or
**     what cf_set_allocator installed (cf_set_allocator(NULL) restores the
**     C library).  Not thread-safe to change while other threads allocate
**     through the default.
**
** cf_get_allocator gives the calling thread's current allocator.  An
** allocator must stay usable as long as blocks made by it are alive.
*/
typedef struct cf_allocator {
    void *(*realloc)(void *ud, void *ptr, size_t old_size, size_t new_size);
    void *ud;
} cf_allocator_t;

CF_API void cf_set_allocator(const cf_allocator_t *allocator);
CF_API void cf_get_allocator(cf_allocator_t *allocator);
CF_API void cf_use_allocator(const cf_allocator_t *allocator,
                             cf_allocator_t *previous);

/* Memory the library hands out as plain arrays (documented per function)
** is released with cf_free. cf_free(NULL) is harmless. */
CF_API void cf_free(void *ptr);

/*
** Allocation through the hook, for code built on curvefig (the renderer,
** the figure language) whose memory should be accounted with the curves':
** cf_malloc(size); cf_calloc(n, size) zeroed; cf_alloc_array(n, size) and
** cf_realloc_array(ptr, n, size) check n * size for overflow.  Each returns
** NULL on failure (cf_realloc_array leaves ptr untouched then).  Memory from
** them is released with cf_free.
*/
CF_API void *cf_malloc(size_t size);
CF_API void *cf_calloc(size_t n, size_t size);
CF_API void *cf_alloc_array(size_t n, size_t size);
CF_API void *cf_realloc_array(void *ptr, size_t n, size_t size);

/*
** Fill a diag the way curvefig's own functions do, for code built on
** curvefig that reports through the same record: if diag is not NULL and
** still OK, its status, index and printf-formatted message are set.
** Returns status, so that `return cf_diag_set(diag, ...)` reads naturally.
*/
#if defined(__GNUC__)
__attribute__((format(printf, 4, 5)))
#endif
CF_API cf_status_t cf_diag_set(cf_diag_t *diag, cf_status_t status, long index,
                               const char *fmt, ...);

#ifdef __cplusplus
}
#endif

#endif
