/*
** Growable byte buffers of the output side (render/render-private.h).
*/
#include <string.h>

#include "render-private.h"

int
cf__buf_append(cf__buf_t *b, const void *data, size_t n)
{
    if (b->failed)
        return -1;
    if (b->size + n > b->cap) {
        size_t cap = b->cap ? b->cap : 4096;
        unsigned char *d;
        while (cap < b->size + n)
            cap *= 2;
        d = cf_realloc_array(b->data, cap, 1);
        if (d == NULL) {
            b->failed = 1;
            return -1;
        }
        b->data = d;
        b->cap = cap;
    }
    if (n > 0)
        memcpy(b->data + b->size, data, n);
    b->size += n;
    return 0;
}

void
cf__buf_free(cf__buf_t *b)
{
    cf_free(b->data);
    memset(b, 0, sizeof *b);
}
