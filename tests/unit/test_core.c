/* Status strings, diagnostics and the allocator hook. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/core.h"
#include "curvefig/version.h"
#include "../../src/core-private.h"
#include "testutil.h"

static void
test_status_strings(void **state)
{
    (void)state;
    assert_string_equal(cf_status_to_string(CF_STATUS_OK), "success");
    for (int s = 0; s < CF_STATUS_LAST_; s++) {
        const char *str = cf_status_to_string((cf_status_t)s);
        assert_non_null(str);
        assert_true(strlen(str) > 0);
        assert_string_not_equal(str, "unknown status");
    }
    assert_string_equal(cf_status_to_string((cf_status_t)9999),
                        "unknown status");
    assert_string_equal(cf_status_to_string((cf_status_t)-1),
                        "unknown status");
}

static void
test_diag_keeps_first_error(void **state)
{
    cf_diag_t d;
    (void)state;
    cf_diag_clear(&d);
    assert_int_equal(d.status, CF_STATUS_OK);
    assert_int_equal(d.index, -1);
    assert_int_equal(cf__error(&d, CF_STATUS_BAD_KNOTS, 4,
                               "knot %d (%.2f) is smaller than knot %d (%.2f)",
                               4, 0.3, 3, 0.5),
                     CF_STATUS_BAD_KNOTS);
    assert_string_equal(d.msg, "knot 4 (0.30) is smaller than knot 3 (0.50)");
    assert_int_equal(d.index, 4);
    /* printf's "-nan" and "nan" read "NaN"; a word holding "nan" stays */
    cf_diag_clear(&d);
    cf__error(&d, CF_STATUS_NOT_FINITE, 0, "x is %g, y is %g (nanometre)",
              -(double)NAN, (double)NAN);
    assert_string_equal(d.msg, "x is NaN, y is NaN (nanometre)");
    cf_diag_clear(&d);
    cf__error(&d, CF_STATUS_BAD_KNOTS, 4, "knot %d (%.2f) is smaller than "
              "knot %d (%.2f)", 4, 0.3, 3, 0.5);
    /* a second error does not overwrite the first */
    cf__error(&d, CF_STATUS_DOMAIN, 7, "other");
    assert_int_equal(d.status, CF_STATUS_BAD_KNOTS);
    assert_int_equal(d.index, 4);
    /* NULL diag is allowed */
    assert_int_equal(cf__error(NULL, CF_STATUS_DOMAIN, 0, "x"),
                     CF_STATUS_DOMAIN);
    cf_diag_clear(NULL);
}

static void
test_checks_name_the_culprit(void **state)
{
    const double pts[] = { 0, 1, 2, 3, 4, NAN };
    const double w[] = { 1, 2, -0.5 };
    cf_diag_t d;
    (void)state;
    cf_diag_clear(&d);
    assert_int_equal(cf__check_finite_points(pts, 3, 2, 2, "point", &d),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(d.index, 2);
    assert_non_null(strstr(d.msg, "point P_2"));
    cf_diag_clear(&d);
    assert_int_equal(cf__check_weights(w, 3, &d), CF_STATUS_BAD_WEIGHT);
    assert_string_equal(d.msg,
                        "weight w_2 is -0.5; weights must be finite and positive");
    assert_int_equal(cf__check_weights(w, 2, NULL), CF_STATUS_OK);
}

static void
test_binomial(void **state)
{
    (void)state;
    assert_true(cf__binomial(5, 2) == 10.0);
    assert_true(cf__binomial(40, 20) == 137846528820.0);
    assert_true(cf__binomial(3, -1) == 0.0);
    assert_true(cf__binomial(3, 4) == 0.0);
    /* Pascal's rule over a range */
    for (int n = 1; n <= 50; n++)
        for (int k = 1; k < n; k++)
            tu_assert_close(cf__binomial(n, k),
                            cf__binomial(n - 1, k - 1) + cf__binomial(n - 1, k),
                            4e-16, 1.0);
}

static void
test_allocator_hook(void **state)
{
    double *p;
    (void)state;
    tu_fail_alloc_after(2);
    p = cf__alloc_array(4, sizeof *p);
    assert_non_null(p);
    assert_null(cf__malloc(8));        /* the 2nd allocation fails */
    assert_null(cf__malloc(8));        /* and every later one */
    cf__free(p);
    assert_int_equal(tu_alloc_live(), 0);
    tu_fail_alloc_reset();

    /* overflow of n * size is caught before any allocation */
    assert_null(cf__alloc_array(SIZE_MAX / 2, 4));
    p = cf__calloc(3, sizeof *p);
    assert_non_null(p);
    assert_true(p[0] == 0.0 && p[2] == 0.0);
    p = cf__realloc_array(p, 1000, sizeof *p);
    assert_non_null(p);
    assert_true(p[1] == 0.0);
    cf_free(p);
    cf_free(NULL);

    cf_allocator_t a;
    cf_get_allocator(&a);
    assert_non_null(a.realloc);
}

/* The grow-by-doubling of the core's arrays: the capacity starts at
** `first` and doubles until it holds what is needed; an array with room
** is returned as it is; an element count whose bytes overflow size_t, or
** a failed allocation, gives NULL and leaves the array and its capacity
** as they were (their contents kept). */
static void
test_grow(void **state)
{
    size_t cap = 0, i;
    int *a = NULL, *b;
    (void)state;
    tu_fail_alloc_after(4);   /* the three growths succeed, the 4th fails */
    a = cf__grow(a, &cap, 1, sizeof *a, 8);
    assert_non_null(a);
    assert_int_equal(cap, 8);
    for (i = 0; i < 8; i++)
        a[i] = (int)i;
    assert_ptr_equal(cf__grow(a, &cap, 8, sizeof *a, 8), a);
    assert_int_equal(cap, 8);
    a = cf__grow(a, &cap, 9, sizeof *a, 8);
    assert_non_null(a);
    assert_int_equal(cap, 16);
    a = cf__grow(a, &cap, 100, sizeof *a, 8);
    assert_non_null(a);
    assert_int_equal(cap, 128);             /* 16 doubled 3 times */
    assert_null(cf__grow(a, &cap, SIZE_MAX / 2, sizeof *a, 8));
    assert_null(cf__grow(a, &cap, SIZE_MAX, 1, 8));
    assert_int_equal(cap, 128);
    b = cf__grow(a, &cap, 129, sizeof *a, 8);
    assert_null(b);
    assert_int_equal(cap, 128);
    for (i = 0; i < 8; i++)
        assert_int_equal(a[i], (int)i);
    cf__free(a);
    assert_int_equal(tu_alloc_live(), 0);
    tu_fail_alloc_reset();
}

/* Two counting allocators: blocks remember the one that made them. */
typedef struct counter {
    long live, calls;
} counter;

static void *
counting_realloc(void *ud, void *ptr, size_t old_size, size_t new_size)
{
    counter *c = ud;
    (void)old_size;
    c->calls++;
    if (new_size == 0) {
        if (ptr != NULL)
            c->live--;
        free(ptr);
        return NULL;
    }
    if (ptr == NULL)
        c->live++;
    return realloc(ptr, new_size);
}

static void
test_allocator_per_block(void **state)
{
    counter ca = { 0, 0 }, cb = { 0, 0 };
    cf_allocator_t A = { counting_realloc, &ca }, B = { counting_realloc, &cb };
    cf_allocator_t prev, prev2, cur;
    double *pa, *pb, *pd;
    (void)state;
    /* A current for this thread: new blocks come from A */
    cf_use_allocator(&A, &prev);
    assert_null(prev.realloc);
    cf_get_allocator(&cur);
    assert_true(cur.realloc == counting_realloc && cur.ud == &ca);
    pa = cf__alloc_array(16, sizeof *pa);
    assert_non_null(pa);
    assert_int_equal(ca.live, 1);
    /* a nested scope with B */
    cf_use_allocator(&B, &prev2);
    assert_true(prev2.ud == &ca);
    pb = cf__malloc(64);
    assert_int_equal(cb.live, 1);
    /* a block of A resized and freed while B is current goes back to A */
    pa = cf__realloc_array(pa, 4000, sizeof *pa);
    assert_non_null(pa);
    assert_int_equal(ca.live, 1);
    assert_int_equal(cb.live, 1);
    cf__free(pa);
    assert_int_equal(ca.live, 0);
    assert_int_equal(cb.live, 1);
    cf_use_allocator(&prev2, NULL);      /* back to A */
    cf_get_allocator(&cur);
    assert_true(cur.ud == &ca);
    /* B's block freed under A goes to B */
    cf_free(pb);
    assert_int_equal(cb.live, 0);
    assert_int_equal(ca.live, 0);
    cf_use_allocator(&prev, NULL);       /* no allocator of the thread's */
    /* the default again: a block made now is not A's or B's */
    {
        long calls_a = ca.calls, calls_b = cb.calls;
        pd = cf__calloc(8, sizeof *pd);
        assert_non_null(pd);
        /* freed while A is current: still the default's */
        cf_use_allocator(&A, &prev);
        cf__free(pd);
        cf_use_allocator(&prev, NULL);
        assert_int_equal(ca.calls, calls_a);
        assert_int_equal(cb.calls, calls_b);
    }
    /* cf_set_allocator sets the process default, which a thread-current
    ** allocator overrides */
    cf_set_allocator(&B);
    pb = cf__malloc(8);
    assert_int_equal(cb.live, 1);
    cf_use_allocator(&A, &prev);
    pa = cf__malloc(8);
    assert_int_equal(ca.live, 1);
    cf_use_allocator(&prev, NULL);
    cf_set_allocator(NULL);
    cf__free(pa);
    cf__free(pb);
    assert_int_equal(ca.live, 0);
    assert_int_equal(cb.live, 0);
}

/* The run-time version is the headers' version, and the macros agree
** with each other and with the string. */
static void
test_version(void **state)
{
    char expect[32];
    (void)state;
    snprintf(expect, sizeof expect, "%d.%d.%d", CF_VERSION_MAJOR,
             CF_VERSION_MINOR, CF_VERSION_PATCH);
    assert_string_equal(CF_VERSION_STRING, expect);
    assert_string_equal(cf_version_string(), CF_VERSION_STRING);
    assert_int_equal(cf_version(), CF_VERSION);
    assert_int_equal(CF_VERSION, CF_VERSION_MAJOR * 10000
                                     + CF_VERSION_MINOR * 100
                                     + CF_VERSION_PATCH);
    assert_true(CF_VERSION_ENCODE(0, 1, 0) < CF_VERSION_ENCODE(0, 1, 1));
    assert_true(CF_VERSION_ENCODE(0, 9, 9) < CF_VERSION_ENCODE(1, 0, 0));
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_status_strings),
        cmocka_unit_test(test_version),
        cmocka_unit_test(test_diag_keeps_first_error),
        cmocka_unit_test(test_checks_name_the_culprit),
        cmocka_unit_test(test_binomial),
        cmocka_unit_test(test_allocator_hook),
        cmocka_unit_test(test_grow),
        cmocka_unit_test(test_allocator_per_block),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
