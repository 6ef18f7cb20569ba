/*
** Internals shared between the files of the core (prefix cf__).
*/
#ifndef CURVEFIG_CORE_PRIVATE_H
#define CURVEFIG_CORE_PRIVATE_H

#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>

#include "curvefig/core.h"

#define CF__PI 3.14159265358979323846

/* A sanitizer runtime is linked in (GCC's and clang's spellings). */
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define CF__SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define CF__SANITIZED 1
#endif
#endif

/* One clone of a hot function per x86-64 level, picked at load time (an
** ifunc; GCC).  Not in sanitizer builds: the resolvers run before the
** sanitizer runtime is initialised and crash the program before main. */
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__) && \
    !defined(CF__SANITIZED)
#define CF__CLONES                                                          \
    __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3",         \
                                 "default")))
#else
#define CF__CLONES
#endif

#if defined(__GNUC__)
#define CF__PRINTF(f, a) __attribute__((format(printf, f, a)))
#define CF__UNLIKELY(x) __builtin_expect(!!(x), 0)
/* a small kernel inlined into its loop even at -O2 */
#define CF__INLINE static inline __attribute__((always_inline))
#else
#define CF__PRINTF(f, a)
#define CF__UNLIKELY(x) (x)
#define CF__INLINE static inline
#endif

/*
** Every error is created by cf_diag_set (core.h; one place for a
** breakpoint): it fills diag (if not NULL and still OK) with status, index
** and the formatted message, and returns status.
*/
#define cf__error cf_diag_set

/* Allocation through the hook.  cf__alloc_array checks n * size for
** overflow; both return NULL on failure.  Memory from them is released with
** cf__free (which needs no size: sizes are kept in a small header). */
void *cf__malloc(size_t size);
void *cf__calloc(size_t n, size_t size);
void *cf__alloc_array(size_t n, size_t size);
void *cf__realloc_array(void *ptr, size_t n, size_t size);
void cf__free(void *ptr);
/* The one grow-by-doubling of the core's arrays: room for `need` elements
** of `size` bytes in arr, whose capacity is *cap elements.  arr itself
** when it has room; else the capacity doubles (from `first`) until it
** holds need, arr is reallocated and *cap set.  NULL when out of memory or
** the bytes would overflow size_t (arr and *cap untouched, arr still
** valid). */
void *cf__grow(void *arr, size_t *cap, size_t need, size_t size,
               size_t first);

/* Checks that report with a message.  `what` names the array ("point"),
** values are dim-interleaved with the given stride. */
cf_status_t cf__check_finite_points(const double *pts, size_t count,
                                    size_t dim, size_t stride,
                                    const char *what, cf_diag_t *diag);
cf_status_t cf__check_weights(const double *w, size_t count,
                              cf_diag_t *diag);

/* The affine map x -> A x + b of R^dim (A row-major dim x dim, b NULL for
** none): A and b finite (INVALID_ARG, NOT_FINITE naming "matrix row" or
** "translation"), then applied to count points at `stride` doubles each,
** homogeneous (w x, w) when rational (b scaled by w, w kept).  dst may be
** src. */
cf_status_t cf__check_affine(const double *A, const double *b, size_t dim,
                             cf_diag_t *diag);
void cf__affine_points(const double *A, const double *b, size_t dim,
                       bool rational, const double *src, size_t count,
                       size_t stride, double *dst);

/* qsort comparison of doubles, ascending. */
int cf__cmp_double(const void *x, const void *y);

/* n choose k as a double (exact for the ranges curvefig uses). */
double cf__binomial(int n, int k);

#endif
