/*
** The one grow-by-doubling of the renderer's arrays (render/base/grow.c),
** through the library's allocator (cf_realloc_array).
*/
#ifndef CURVEFIG_RENDER_GROW_H
#define CURVEFIG_RENDER_GROW_H

#include <stddef.h>

/* Room for `need` elements of `size` bytes in arr, whose capacity is *cap
** elements: arr itself when it has room; else the capacity doubles (from
** `first`) until it holds need, arr is reallocated and *cap set.  NULL
** when out of memory or the bytes would overflow size_t (arr and *cap
** untouched, arr still valid). */
void *cf__grow_array(void *arr, size_t *cap, size_t need, size_t size,
                     size_t first);

#endif
