/*
** Growable byte buffers (render/base/buffer.h).
*/
#include <stdint.h>
#include <string.h>

#include "buffer.h"
#include "curvefig/core.h"
#include "grow.h"

int
cf__buf_append(cf__buf_t *b, const void *data, size_t n)
{
    if (b->failed)
        return -1;
    if (n > SIZE_MAX - b->size) {
        b->failed = 1;
        return -1;
    }
    if (b->size + n > b->cap) {
        unsigned char *d = cf__grow_array(b->data, &b->cap, b->size + n, 1,
                                          4096);
        if (d == NULL) {
            b->failed = 1;
            return -1;
        }
        b->data = d;
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

const unsigned char *
cf__bytes_find(const unsigned char *h, const unsigned char *end,
               const char *needle)
{
    size_t m = strlen(needle);
    for (; h + m <= end; h++)
        if (*h == (unsigned char)needle[0] && memcmp(h, needle, m) == 0)
            return h;
    return NULL;
}
