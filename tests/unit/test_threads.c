/*
** Threads (docs/library.md, "Threads"): one curve evaluated in batches from
** several threads at once (the first batch call fills the evaluation
** accelerator while the others evaluate without it or with it), and a
** per-thread allocator in each thread; the curves of one
** cf_bspline_to_beziers list (one shared block) destroyed from several
** threads at once, the block freed once.  Meant to run under
** ThreadSanitizer too (-Db_sanitize=thread), which reports any data race.
*/
#include <math.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/curvefig.h"
#include "testutil.h"

#define THREADS 4
#define NPAR 4000

static const double P[] = { 0, 0, 1, 3, 2, -1, 4, 2, 5, 0, 7, 1, 8, 3, 9, 0 };
static const double U[] = { 0, 0, 0, 0, 0.2, 0.35, 0.5, 0.8, 1, 1, 1, 1 };

static double params[NPAR], ref[2 * NPAR];
static atomic_int go;

/* A counting allocator, one per thread. */
typedef struct counter {
    long live, total;
} counter_t;

static void *
count_realloc(void *ud, void *ptr, size_t old_size, size_t new_size)
{
    counter_t *c = ud;
    (void)old_size;
    if (new_size == 0) {
        if (ptr != NULL)
            c->live--;
        free(ptr);
        return NULL;
    }
    if (ptr == NULL) {
        c->live++;
        c->total++;
    }
    return realloc(ptr, new_size);
}

typedef struct job {
    const cf_bspline_t *shared;
    int ok;
    long total;
} job_t;

static void *
worker(void *arg)
{
    job_t *job = arg;
    double *out = malloc(2 * NPAR * sizeof *out);
    counter_t cnt = { 0, 0 };
    cf_allocator_t mine = { count_realloc, &cnt }, prev;
    job->ok = out != NULL;
    while (!atomic_load(&go))
        ;
    for (int rep = 0; rep < 3 && job->ok; rep++) {
        cf_bspline_t *own = NULL;
        if (cf_bspline_eval_many(job->shared, params, NPAR, out) != 0)
            job->ok = 0;
        for (size_t i = 0; i < 2 * NPAR && job->ok; i++)
            if (!tu_close(out[i], ref[i], 1e-13, 10.0))
                job->ok = 0;
        /* curves of this thread through its own allocator */
        cf_use_allocator(&mine, &prev);
        if (cf_bspline_create(2, 3, U, 12, P, 8, NULL, &own, NULL) != 0 ||
            cf_bspline_eval_deriv_many(own, params, NPAR, 1, out) != 0)
            job->ok = 0;
        cf_bspline_destroy(own);
        cf_use_allocator(&prev, NULL);
        if (cnt.live != 0)
            job->ok = 0;
    }
    job->total = cnt.total;
    free(out);
    return NULL;
}

static void
test_shared_curve(void **state)
{
    cf_bspline_t *c = NULL;
    pthread_t th[THREADS];
    job_t jobs[THREADS];
    (void)state;
    assert_int_equal(cf_bspline_create(2, 3, U, 12, P, 8, NULL, &c, NULL), 0);
    for (size_t i = 0; i < NPAR; i++) {
        params[i] = (double)((i * 7919) % NPAR) / (NPAR - 1);
        assert_int_equal(cf_bspline_eval(c, params[i], ref + 2 * i), 0);
    }
    atomic_store(&go, 0);
    for (int t = 0; t < THREADS; t++) {
        jobs[t].shared = c;
        jobs[t].ok = 0;
        assert_int_equal(pthread_create(&th[t], NULL, worker, &jobs[t]), 0);
    }
    atomic_store(&go, 1);
    for (int t = 0; t < THREADS; t++)
        assert_int_equal(pthread_join(th[t], NULL), 0);
    for (int t = 0; t < THREADS; t++) {
        assert_true(jobs[t].ok);
        assert_true(jobs[t].total >= 3);   /* its curves used its allocator */
    }
    cf_bspline_destroy(c);
}

/* Blocks counted across threads (the block of a list is freed by the
** thread that drops its last curve, through the allocator that made it). */
static atomic_long blocks_live;

static void *
shared_count_realloc(void *ud, void *ptr, size_t old_size, size_t new_size)
{
    (void)ud;
    (void)old_size;
    if (new_size == 0) {
        if (ptr != NULL)
            atomic_fetch_sub(&blocks_live, 1);
        free(ptr);
        return NULL;
    }
    if (ptr == NULL)
        atomic_fetch_add(&blocks_live, 1);
    return realloc(ptr, new_size);
}

typedef struct share {
    cf_bezier_t **items;
    size_t n, first;
    int ok;
} share_t;

static void *
dropper(void *arg)
{
    share_t *s = arg;
    while (!atomic_load(&go))
        ;
    for (size_t i = s->first; i < s->n; i += THREADS) {
        double x[2];
        if (cf_bezier_eval(s->items[i], 0.5, x) != 0 || !isfinite(x[0]))
            s->ok = 0;
        cf_bezier_destroy(s->items[i]);
    }
    return NULL;
}

static void
test_pieces_across_threads(void **state)
{
    enum { NPTS = 400 };
    double Uk[NPTS + 4], Pk[2 * NPTS];
    cf_allocator_t counting = { shared_count_realloc, NULL }, prev;
    cf_bspline_t *c = NULL;
    cf_bezier_list_t *list = NULL;
    cf_bezier_t **items;
    pthread_t th[THREADS];
    share_t sh[THREADS];
    size_t n;
    (void)state;
    for (int i = 0; i < 4; i++) {
        Uk[i] = 0.0;
        Uk[NPTS + i] = 1.0;
    }
    for (int i = 4; i < NPTS; i++)
        Uk[i] = (i - 3) / (double)(NPTS - 3);
    for (int i = 0; i < 2 * NPTS; i++)
        Pk[i] = sin(0.37 * i);
    cf_use_allocator(&counting, &prev);
    assert_int_equal(cf_bspline_create(2, 3, Uk, NPTS + 4, Pk, NPTS, NULL, &c,
                                       NULL), 0);
    assert_int_equal(cf_bspline_to_beziers(c, &list, NULL), 0);
    cf_use_allocator(&prev, NULL);
    /* the threads own the curves now; the list goes without them */
    items = list->items;
    n = list->count;
    list->items = NULL;
    list->count = 0;
    cf_bezier_list_destroy(list);
    atomic_store(&go, 0);
    for (int t = 0; t < THREADS; t++) {
        sh[t].items = items;
        sh[t].n = n;
        sh[t].first = (size_t)t;
        sh[t].ok = 1;
        assert_int_equal(pthread_create(&th[t], NULL, dropper, &sh[t]), 0);
    }
    atomic_store(&go, 1);
    for (int t = 0; t < THREADS; t++)
        assert_int_equal(pthread_join(th[t], NULL), 0);
    for (int t = 0; t < THREADS; t++)
        assert_true(sh[t].ok);
    cf_free(items);
    cf_bspline_destroy(c);
    /* the curves' block was freed, once */
    assert_int_equal(atomic_load(&blocks_live), 0);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shared_curve),
        cmocka_unit_test(test_pieces_across_threads),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
