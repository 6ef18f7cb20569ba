/*
** Helpers shared by the unit tests: a seeded PRNG and relative comparisons.
** Include after <stdarg.h>, <stddef.h>, <setjmp.h> and <cmocka.h>.
*/
#ifndef CURVEFIG_TESTUTIL_H
#define CURVEFIG_TESTUTIL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "curvefig/core.h"

/* splitmix64, the generator of docs/benchmarks.md. */
typedef struct tu_rng {
    uint64_t state;
} tu_rng;

void tu_rng_seed(tu_rng *r, uint64_t seed);
uint64_t tu_rng_next(tu_rng *r);
double tu_rng_u01(tu_rng *r);                 /* [0, 1) */
double tu_rng_range(tu_rng *r, double lo, double hi);

/* |a - b| <= rel * scale, where scale = max(|a|, |b|, floor). */
bool tu_close(double a, double b, double rel, double floor);

/* cmocka assertion with a message naming both values. */
void tu_assert_close_(double a, double b, double rel, double floor,
                      const char *expr, const char *file, int line);
#define tu_assert_close(a, b, rel, floor) \
    tu_assert_close_((a), (b), (rel), (floor), #a " ~ " #b, __FILE__, __LINE__)

/* Maximum norm of a - b over n doubles. */
double tu_max_diff(const double *a, const double *b, size_t n);

/*
** Failing allocator for out-of-memory tests: after tu_fail_alloc_after(k),
** the k-th allocation from now (1-based) and every later one fail, until
** tu_fail_alloc_reset().  tu_alloc_live() counts live blocks (for leaks).
*/
void tu_fail_alloc_after(long k);
void tu_fail_alloc_reset(void);
long tu_alloc_live(void);
/* Only the k-th allocation fails, the later ones succeed; whether it has
** failed yet. */
void tu_fail_alloc_once(long k);
bool tu_alloc_failed_once(void);

/*
** Run op with the k-th allocation failing for k = 1, 2, ... until it
** succeeds, first with every later allocation failing too, then with the
** k-th alone failing and the later ones granted; returns the number of
** failure points (k - 1, the same both ways) and prints it.  Every failing
** run must return CF_STATUS_NO_MEMORY and leave no block live; takes_diag:
** op passes its diag to the library, whose status and message must then
** say so.  An operation that met its one failure must not succeed (a
** failure passed over is a result computed without what it needed).
*/
typedef cf_status_t (*tu_alloc_op)(cf_diag_t *diag);
long tu_fail_loop(const char *name, tu_alloc_op op, bool takes_diag);

/* The names of the figure scripts (*.lua) in dir, sorted, strdup'd into
** names (at most max); their number. */
size_t tu_figure_scripts(const char *dir, char **names, size_t max);

/* The text of a public header (include/curvefig/<name> under the source
** tree root) into buf, NUL-terminated; fails the test when unreadable. */
void tu_read_header(const char *root, const char *name, char *buf,
                    size_t size);

/* 1 in how many cases of a large grid of comparisons a test runs: the
** environment's CF_TEST_SAMPLE (a whole number from 1 to 1000), else 1.
** The sanitizer build sets it for the tests that compare every glyph or
** every request with an oracle (tests/render/meson.build), which it runs
** 5 to 10 times slower: the release build runs the whole grid. */
unsigned tu_sample(void);

/* The bytes of the file at path, malloc'd (*len set; a NUL after them),
** NULL when it cannot be read whole (the caller frees it); and n bytes
** written to path (failing the test when they cannot be). */
unsigned char *tu_read_file(const char *path, size_t *len);
void tu_write_file(const char *path, const void *data, size_t n);
/* Whether the n bytes at p (a file's, a rendering's: no C string, no NUL
** after them) hold the string s. */
bool tu_bytes_hold(const unsigned char *p, size_t n, const char *s);

#endif
