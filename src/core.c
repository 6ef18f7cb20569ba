/*
** Status strings, error details, the allocator hook and shared checks.
*/
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core-private.h"
#include "numtext-private.h"

static const char *const status_strings[CF_STATUS_LAST_] = {
    [CF_STATUS_OK] = "success",
    [CF_STATUS_NO_MEMORY] = "out of memory",
    [CF_STATUS_INVALID_ARG] = "invalid argument",
    [CF_STATUS_DIM_MISMATCH] = "dimensions do not match",
    [CF_STATUS_BAD_DEGREE] = "invalid degree",
    [CF_STATUS_BAD_KNOTS] = "invalid knot vector",
    [CF_STATUS_BAD_WEIGHT] = "invalid weight",
    [CF_STATUS_NOT_FINITE] = "value is not finite",
    [CF_STATUS_DOMAIN] = "parameter outside the domain",
    [CF_STATUS_DEGENERATE] = "degenerate geometry",
    [CF_STATUS_NO_CONVERGENCE] = "no convergence",
    [CF_STATUS_TOO_FEW_POINTS] = "too few points",
    [CF_STATUS_IO] = "input/output error",
    [CF_STATUS_SCRIPT] = "figure script error",
};

const char *
cf_status_to_string(cf_status_t status)
{
    if ((unsigned)status >= CF_STATUS_LAST_)
        return "unknown status";
    return status_strings[status];
}

void
cf_diag_clear(cf_diag_t *diag)
{
    if (diag == NULL)
        return;
    diag->status = CF_STATUS_OK;
    diag->index = -1;
    diag->msg[0] = '\0';
}

cf_status_t
cf_diag_set(cf_diag_t *diag, cf_status_t status, long index,
            const char *fmt, ...)
{
    if (diag != NULL && diag->status == CF_STATUS_OK) {
        va_list ap;
        diag->status = status;
        diag->index = index;
        va_start(ap, fmt);
        vsnprintf(diag->msg, sizeof diag->msg, fmt, ap);
        va_end(ap);
        cf__spell_nan(diag->msg);
    }
    return status;
}

/* ---- allocator ---------------------------------------------------------- */

static void *
default_realloc(void *ud, void *ptr, size_t old_size, size_t new_size)
{
    (void)ud;
    (void)old_size;
    if (new_size == 0) {
        free(ptr);
        return NULL;
    }
    return realloc(ptr, new_size);
}

/* The process default (cf_set_allocator) and the calling thread's current
** one (cf_use_allocator; realloc NULL: none, the default applies). */
static cf_allocator_t default_allocator = { default_realloc, NULL };
#if defined(__GNUC__)
/* initial-exec: one load, no call per allocation (the library is linked,
** not opened at run time) */
__attribute__((tls_model("initial-exec")))
#endif
static _Thread_local cf_allocator_t thread_allocator = { NULL, NULL };

static const cf_allocator_t *
current(void)
{
    return thread_allocator.realloc != NULL ? &thread_allocator
                                            : &default_allocator;
}

void
cf_set_allocator(const cf_allocator_t *a)
{
    if (a == NULL || a->realloc == NULL) {
        default_allocator.realloc = default_realloc;
        default_allocator.ud = NULL;
    } else {
        default_allocator = *a;
    }
}

void
cf_get_allocator(cf_allocator_t *a)
{
    if (a != NULL)
        *a = *current();
}

void
cf_use_allocator(const cf_allocator_t *a, cf_allocator_t *previous)
{
    if (previous != NULL)
        *previous = thread_allocator;
    if (a == NULL || a->realloc == NULL) {
        thread_allocator.realloc = NULL;
        thread_allocator.ud = NULL;
    } else {
        thread_allocator = *a;
    }
}

/* A header in front of every block remembers its size, so that the hook
** receives the old size as lua_Alloc does, and the allocator that made it,
** so that the block is resized and freed by that one whichever is current
** then.  A multiple of max_align_t keeps the alignment. */
typedef union {
    struct {
        size_t size;
        cf_allocator_t by;
    } b;
    max_align_t align_;
} block_header;

void *
cf__malloc(size_t size)
{
    const cf_allocator_t *a = current();
    block_header *h;
    if (size > SIZE_MAX - sizeof *h)
        return NULL;
    h = a->realloc(a->ud, NULL, 0, sizeof *h + size);
    if (h == NULL)
        return NULL;
    h->b.size = size;
    h->b.by = *a;
    return h + 1;
}

void *
cf__alloc_array(size_t n, size_t size)
{
    if (size != 0 && n > SIZE_MAX / size)
        return NULL;
    return cf__malloc(n * size);
}

void *
cf__calloc(size_t n, size_t size)
{
    void *p = cf__alloc_array(n, size);
    if (p != NULL)
        memset(p, 0, n * size);
    return p;
}

void *
cf__realloc_array(void *ptr, size_t n, size_t size)
{
    block_header *h, *nh;
    cf_allocator_t by;
    size_t bytes;
    if (ptr == NULL)
        return cf__alloc_array(n, size);
    if (size != 0 && n > SIZE_MAX / size)
        return NULL;
    bytes = n * size;
    if (bytes > SIZE_MAX - sizeof *h)
        return NULL;
    h = (block_header *)ptr - 1;
    by = h->b.by;
    nh = by.realloc(by.ud, h, sizeof *h + h->b.size, sizeof *h + bytes);
    if (nh == NULL)
        return NULL;
    nh->b.size = bytes;
    return nh + 1;
}

void *
cf__grow(void *arr, size_t *cap, size_t need, size_t size, size_t first)
{
    size_t n = *cap > 0 ? *cap : (first > 0 ? first : 1);
    void *p;
    if (need <= *cap && arr != NULL)
        return arr;
    while (n < need)
        n = n > SIZE_MAX / 2 ? need : 2 * n;
    p = cf__realloc_array(arr, n, size);
    if (p != NULL)
        *cap = n;
    return p;
}

void
cf__free(void *ptr)
{
    block_header *h;
    cf_allocator_t by;
    if (ptr == NULL)
        return;
    h = (block_header *)ptr - 1;
    by = h->b.by;
    by.realloc(by.ud, h, sizeof *h + h->b.size, 0);
}

void
cf_free(void *ptr)
{
    cf__free(ptr);
}

void *
cf_malloc(size_t size)
{
    return cf__malloc(size);
}

void *
cf_calloc(size_t n, size_t size)
{
    return cf__calloc(n, size);
}

void *
cf_alloc_array(size_t n, size_t size)
{
    return cf__alloc_array(n, size);
}

void *
cf_realloc_array(void *ptr, size_t n, size_t size)
{
    return cf__realloc_array(ptr, n, size);
}

/* ---- shared checks ------------------------------------------------------ */

cf_status_t
cf__check_finite_points(const double *pts, size_t count, size_t dim,
                        size_t stride, const char *what, cf_diag_t *diag)
{
    for (size_t i = 0; i < count; i++) {
        for (size_t k = 0; k < dim; k++) {
            double v = pts[i * stride + k];
            if (!isfinite(v))
                return cf__error(diag, CF_STATUS_NOT_FINITE, (long)i,
                                 "%s %s%zu has coordinate %zu = %s; "
                                 "coordinates must be finite", what,
                                 strcmp(what, "point") == 0 ? "P_" : "", i,
                                 k + 1, CF__NUM(v));
        }
    }
    return CF_STATUS_OK;
}

cf_status_t
cf__check_weights(const double *w, size_t count, cf_diag_t *diag)
{
    for (size_t i = 0; i < count; i++) {
        if (!isfinite(w[i]) || !(w[i] > 0.0))
            return cf__error(diag, CF_STATUS_BAD_WEIGHT, (long)i,
                             "weight w_%zu is %s; weights must be finite "
                             "and positive", i, CF__NUM(w[i]));
    }
    return CF_STATUS_OK;
}

double
cf__binomial(int n, int k)
{
    double r = 1.0;
    if (k < 0 || k > n)
        return 0.0;
    if (k > n - k)
        k = n - k;
    for (int i = 1; i <= k; i++)
        r = r * (double)(n - k + i) / (double)i;
    return nearbyint(r);
}

int
cf__cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

cf_status_t
cf__check_affine(const double *A, const double *b, size_t dim,
                 cf_diag_t *diag)
{
    cf_status_t st;
    if (A == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "the matrix is NULL");
    st = cf__check_finite_points(A, dim, dim, dim, "matrix row", diag);
    if (st == CF_STATUS_OK && b != NULL)
        st = cf__check_finite_points(b, 1, dim, dim, "translation", diag);
    return st;
}

void
cf__affine_points(const double *A, const double *b, size_t dim,
                  bool rational, const double *src, size_t count,
                  size_t stride, double *dst)
{
    for (size_t i = 0; i < count; i++) {
        const double *p = src + i * stride;
        double *q = dst + i * stride;
        double w = rational ? p[dim] : 1.0;
        for (size_t k = 0; k < dim; k++) {
            double s = 0.0;
            for (size_t j = 0; j < dim; j++)
                s += A[k * dim + j] * p[j];
            q[k] = s + (b != NULL ? b[k] * w : 0.0);
        }
        if (rational)
            q[dim] = w;
    }
}
