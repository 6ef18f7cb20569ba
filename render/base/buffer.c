/*
** Growable byte buffers (render/base/buffer.h).
*/
#include <stdint.h>
#include <string.h>

#include "buffer.h"
#include "curvefig/core.h"
#include "grow.h"

unsigned char *
cf__buf_extend(cf__buf_t *b, size_t n)
{
    unsigned char *at;
    if (b->failed)
        return NULL;
    if (n > SIZE_MAX - b->size) {
        b->failed = 1;
        return NULL;
    }
    /* an empty buffer gets its first block even for n = 0: the pointer
    ** returned is never null arithmetic, nor a failure's NULL */
    if (b->size + n > b->cap || b->data == NULL) {
        unsigned char *d = cf__grow_array(b->data, &b->cap,
                                          b->size + n > 0 ? b->size + n : 1,
                                          1, 4096);
        if (d == NULL) {
            b->failed = 1;
            return NULL;
        }
        b->data = d;
    }
    at = b->data + b->size;
    b->size += n;
    return at;
}

int
cf__buf_append(cf__buf_t *b, const void *data, size_t n)
{
    unsigned char *at = cf__buf_extend(b, n);
    if (at == NULL)
        return -1;
    if (n > 0)
        memcpy(at, data, n);
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
