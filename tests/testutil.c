#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <dirent.h>

#include <cmocka.h>

#include "curvefig/core.h"
#include "testutil.h"

void
tu_rng_seed(tu_rng *r, uint64_t seed)
{
    r->state = seed;
}

uint64_t
tu_rng_next(tu_rng *r)
{
    uint64_t z;
    r->state += 0x9E3779B97F4A7C15u;
    z = r->state;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

double
tu_rng_u01(tu_rng *r)
{
    return (double)(tu_rng_next(r) >> 11) * 0x1p-53;
}

double
tu_rng_range(tu_rng *r, double lo, double hi)
{
    return lo + (hi - lo) * tu_rng_u01(r);
}

bool
tu_close(double a, double b, double rel, double floor)
{
    double scale = fmax(fmax(fabs(a), fabs(b)), floor);
    if (isnan(a) || isnan(b))
        return false;
    return fabs(a - b) <= rel * scale;
}

void
tu_assert_close_(double a, double b, double rel, double floor,
                 const char *expr, const char *file, int line)
{
    if (!tu_close(a, b, rel, floor)) {
        print_error("%s: %.17g vs %.17g (diff %.3g, allowed %.3g relative "
                    "to max(|a|,|b|,%g))\n",
                    expr, a, b, fabs(a - b), rel, floor);
        _fail(file, line);
    }
}

double
tu_max_diff(const double *a, const double *b, size_t n)
{
    double m = 0.0;
    for (size_t i = 0; i < n; i++) {
        double d = fabs(a[i] - b[i]);
        if (isnan(d))
            return INFINITY;
        if (d > m)
            m = d;
    }
    return m;
}

static long fail_after = -1;
static long live_blocks = 0;
static bool fail_once;      /* only the fail_after-th fails, not the rest */
static bool failed_once;    /* ... and it has */

static void *
failing_realloc(void *ud, void *ptr, size_t old_size, size_t new_size)
{
    (void)ud;
    (void)old_size;
    if (new_size == 0) {
        if (ptr != NULL)
            live_blocks--;
        free(ptr);
        return NULL;
    }
    if (fail_after > 0) {
        fail_after--;
        if (fail_after == 0) {
            if (fail_once) {
                fail_after = -1;
                failed_once = true;
            }
            return NULL;
        }
    } else if (fail_after == 0) {
        return NULL;
    }
    void *p = realloc(ptr, new_size);
    if (p != NULL && ptr == NULL)
        live_blocks++;
    return p;
}

void
tu_fail_alloc_after(long k)
{
    cf_allocator_t a = { failing_realloc, NULL };
    fail_after = k;
    fail_once = failed_once = false;
    live_blocks = 0;
    cf_set_allocator(&a);
}

void
tu_fail_alloc_once(long k)
{
    tu_fail_alloc_after(k);
    fail_once = true;
}

bool
tu_alloc_failed_once(void)
{
    return failed_once;
}

void
tu_fail_alloc_reset(void)
{
    fail_after = -1;
    fail_once = false;
    cf_set_allocator(NULL);
}

long
tu_alloc_live(void)
{
    return live_blocks;
}

/* One allocation failing (once) or every one from the k-th (!once). */
static long
fail_loop(const char *name, tu_alloc_op op, bool takes_diag, bool once)
{
    long k;
    clock_t t0 = clock();
    for (k = 1; k < 200000; k++) {
        cf_diag_t diag;
        cf_status_t st;
        long live;
        bool hit;
        cf_diag_clear(&diag);
        if (once)
            tu_fail_alloc_once(k);
        else
            tu_fail_alloc_after(k);
        st = op(&diag);
        live = tu_alloc_live();
        hit = tu_alloc_failed_once();
        tu_fail_alloc_reset();
        if (live != 0)
            fail_msg("%s: %ld blocks leaked with allocation %ld failing "
                     "(status %s)", name, live, k, cf_status_to_string(st));
        if (once && st == CF_STATUS_OK && hit)
            fail_msg("%s: allocation %ld alone failed, and the operation "
                     "succeeded all the same", name, k);
        if (st == CF_STATUS_OK)
            break;
        if (st != CF_STATUS_NO_MEMORY)
            fail_msg("%s: allocation %ld failing gave %s (%s), not "
                     "NO_MEMORY", name, k, cf_status_to_string(st),
                     diag.msg);
        if (takes_diag && (diag.status != CF_STATUS_NO_MEMORY ||
                           diag.msg[0] == '\0'))
            fail_msg("%s: allocation %ld failing: the diag says %d \"%s\"",
                     name, k, (int)diag.status, diag.msg);
    }
    assert_true(k < 200000);
    print_message("%-28s %4ld allocation failure points%s (%.1f s)\n", name,
                  k - 1, once ? ", each alone" : "",
                  (double)(clock() - t0) / CLOCKS_PER_SEC);
    return k - 1;
}

long
tu_fail_loop(const char *name, tu_alloc_op op, bool takes_diag)
{
    long points = fail_loop(name, op, takes_diag, false);
    /* and each allocation failing alone: none passed over */
    assert_int_equal(fail_loop(name, op, takes_diag, true), points);
    return points;
}

static int
by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

size_t
tu_figure_scripts(const char *dir, char **names, size_t max)
{
    DIR *d = opendir(dir);
    struct dirent *de;
    size_t n = 0;
    assert_non_null(d);
    while ((de = readdir(d)) != NULL && n < max) {
        size_t k = strlen(de->d_name);
        if (k > 4 && strcmp(de->d_name + k - 4, ".lua") == 0) {
            names[n] = malloc(k + 1);
            assert_non_null(names[n]);
            memcpy(names[n++], de->d_name, k + 1);
        }
    }
    closedir(d);
    qsort(names, n, sizeof *names, by_name);
    return n;
}

unsigned char *
tu_read_file(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    unsigned char *b;
    long n;
    *len = 0;
    if (f == NULL)
        return NULL;
    if (fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0
        || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        return NULL;
    }
    b = malloc((size_t)n + 1);
    if (b == NULL || fread(b, 1, (size_t)n, f) != (size_t)n) {
        free(b);
        fclose(f);
        return NULL;
    }
    fclose(f);
    b[n] = 0;
    *len = (size_t)n;
    return b;
}

void
tu_read_header(const char *root, const char *name, char *buf, size_t size)
{
    char path[512];
    size_t n;
    FILE *f;
    snprintf(path, sizeof path, "%s/include/curvefig/%s", root, name);
    f = fopen(path, "r");
    if (f == NULL)
        fail_msg("cannot read %s", path);
    n = fread(buf, 1, size - 1, f);
    buf[n] = '\0';
    fclose(f);
}

bool
tu_bytes_hold(const unsigned char *p, size_t n, const char *s)
{
    size_t k = strlen(s), i;
    for (i = 0; i + k <= n; i++)
        if (memcmp(p + i, s, k) == 0)
            return true;
    return false;
}

void
tu_write_file(const char *path, const void *data, size_t n)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(data, 1, n, f), n);
    assert_int_equal(fclose(f), 0);
}

unsigned
tu_sample(void)
{
    const char *v = getenv("CF_TEST_SAMPLE");
    char *end;
    long k;
    if (v == NULL || *v == '\0')
        return 1;
    k = strtol(v, &end, 10);
    return *end == '\0' && k >= 1 && k <= 1000 ? (unsigned)k : 1;
}
