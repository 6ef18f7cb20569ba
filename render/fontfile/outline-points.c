/*
** An outline grown point by point (render/fontfile/outline-private.h):
** the points, their tags and the contours' ends, in the library's
** allocator, for the CFF and TrueType readers below outline.c.
*/
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "curvefig/core.h"
#include "outline-private.h"

/* realloc of n items of size bytes in o's allocator */
static void *
grow(const cf__outline_t *o, void *p, size_t n, size_t size)
{
    if (!o->libc)
        return cf_realloc_array(p, n, size);
    return n > SIZE_MAX / size ? NULL : realloc(p, n * size);
}

void
cf__outline_fini(cf__outline_t *o)
{
    bool libc = o->libc;
    void (*release)(void *) = libc ? free : cf_free;
    release(o->x);
    release(o->y);
    release(o->tags);
    release(o->ends);
    memset(o, 0, sizeof *o);
    o->libc = libc;
}

int
cf__ol_add(cf__outline_t *o, int64_t x, int64_t y, unsigned char tag)
{
    if (o->n == o->cap) {
        size_t cap = o->cap ? 2 * o->cap : 64;
        int64_t *nx, *ny;
        unsigned char *nt;
        if (o->n >= CF__OL_MAX_POINTS)
            return 1;
        nx = grow(o, o->x, cap, sizeof *nx);
        if (nx == NULL)
            return -1;
        o->x = nx;
        ny = grow(o, o->y, cap, sizeof *ny);
        if (ny == NULL)
            return -1;
        o->y = ny;
        nt = grow(o, o->tags, cap, 1);
        if (nt == NULL)
            return -1;
        o->tags = nt;
        o->cap = cap;
    }
    o->x[o->n] = x;
    o->y[o->n] = y;
    o->tags[o->n++] = tag;
    return 0;
}

int
cf__ol_end_contour(cf__outline_t *o)
{
    if (o->ncontours == o->cap_contours) {
        size_t cap = o->cap_contours ? 2 * o->cap_contours : 16;
        size_t *e = grow(o, o->ends, cap, sizeof *e);
        if (e == NULL)
            return -1;
        o->ends = e;
        o->cap_contours = cap;
    }
    o->ends[o->ncontours++] = o->n - 1;
    return 0;
}
