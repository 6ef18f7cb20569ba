/*
** Growing arrays (render/base/grow.h).
*/
#include <stdint.h>

#include "curvefig/core.h"
#include "grow.h"

void *
cf__grow_array(void *arr, size_t *cap, size_t need, size_t size,
               size_t first)
{
    size_t n = *cap > 0 ? *cap : (first > 0 ? first : 1);
    void *p;
    if (need <= *cap && arr != NULL)
        return arr;
    while (n < need)
        n = n > SIZE_MAX / 2 ? need : 2 * n;
    p = cf_realloc_array(arr, n, size);
    if (p != NULL)
        *cap = n;
    return p;
}
