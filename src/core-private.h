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

/*
** A hot function in one copy per x86-64 level (x86-64-v4, v3 and the
** baseline), the one for this processor chosen at its first call: write it
** as CF__INLINE ret name_body(params), then CF__CLONED(ret, name, (params),
** (args), return) (the last argument empty when ret is void), which
** defines the static function name.  The level is cf__cpu_level's, from
** the CPU features the C library found at start (glibc's
** <sys/platform/x86.h>), with no CPUID instruction: on a virtual machine
** each one traps into the hypervisor, and GCC's target_clones ran libgcc's
** detection (some ten of them) at every start, 50 us of the 1.4 ms of a
** minimal render (glibc.cpu.hwcaps in GLIBC_TUNABLES lowers the level:
** the core tests run the lower copies so).  With another compiler or C
** library, under a sanitizer (as before) and on other processors, name is
** the body alone.
*/
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__) && \
    !defined(CF__SANITIZED) && defined(__has_include)
#if __has_include(<sys/platform/x86.h>)
#define CF__LEVELS 1
#endif
#endif
/* The x86-64 level of this processor (1 to 4; 1 without CF__LEVELS). */
int cf__cpu_level(void);
#ifdef CF__LEVELS
#include <stdatomic.h>
#define CF__CLONED(ret, name, params, args, ret_kw)                         \
    __attribute__((target("arch=x86-64-v4"))) static ret name##_v4 params   \
    {                                                                       \
        ret_kw name##_body args;                                            \
    }                                                                       \
    __attribute__((target("arch=x86-64-v3"))) static ret name##_v3 params   \
    {                                                                       \
        ret_kw name##_body args;                                            \
    }                                                                       \
    static ret name##_v1 params                                             \
    {                                                                       \
        ret_kw name##_body args;                                            \
    }                                                                       \
    static ret name params                                                  \
    {                                                                       \
        typedef ret(*level_fn) params;                                      \
        static _Atomic(level_fn) chosen;                                    \
        level_fn f = atomic_load_explicit(&chosen, memory_order_relaxed);   \
        if (f == NULL) {                                                    \
            int level = cf__cpu_level();                                    \
            f = level >= 4 ? name##_v4 : level == 3 ? name##_v3 : name##_v1; \
            atomic_store_explicit(&chosen, f, memory_order_relaxed);        \
        }                                                                   \
        ret_kw f args;                                                      \
    }
#else
#define CF__CLONED(ret, name, params, args, ret_kw)                         \
    static ret name params                                                  \
    {                                                                       \
        ret_kw name##_body args;                                            \
    }
#endif

#if defined(__GNUC__)
#define CF__PRINTF(f, a) __attribute__((format(printf, f, a)))
#define CF__UNLIKELY(x) __builtin_expect(!!(x), 0)
/* a small kernel inlined into its loop even at -O2 */
#define CF__INLINE static inline __attribute__((always_inline))
/* A function whose small hot loop must not straddle a 64-byte line: such
** a loop took some 15 % longer a step on the processor measured (AMD Zen
** 4), and where it fell moved with any code added before it in the
** library (W5ins, W5bez, W1d 1-2.5 %, docs/performance.md, "Benchmarks").
** The function starts on a 64-byte boundary, so that where its loop lies
** depends on its own code alone. */
#define CF__LOOP_ALIGNED __attribute__((aligned(64)))
#else
#define CF__PRINTF(f, a)
#define CF__UNLIKELY(x) (x)
#define CF__INLINE static inline
#define CF__LOOP_ALIGNED
#endif

/* fmin and fmax as glibc's x86-64 code computes them, inlined: the other
** argument where one is a NaN, and of two equal arguments (+0 and -0
** among them) the second.  GCC calls libm for fmin and fmax unless NaNs
** are ruled out (-ffinite-math-only), which a hot loop pays for (the
** scene's measures in src/scene-tree.c: 9 % of a heavy view); the
** WebAssembly module's C library (musl) orders signed zeros otherwise,
** these give the same bits in both. */
CF__INLINE double
cf__fmin(double a, double b)
{
    return a < b || b != b ? a : b;
}

CF__INLINE double
cf__fmax(double a, double b)
{
    return a > b || b != b ? a : b;
}

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
