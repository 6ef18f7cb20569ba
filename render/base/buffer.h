/*
** A growable byte buffer (render/base/buffer.c): the lowest layer of the
** renderer, used by labels (as TeX source), backends and output.
*/
#ifndef CURVEFIG_RENDER_BUFFER_H
#define CURVEFIG_RENDER_BUFFER_H

#include <stddef.h>

/* A growable byte buffer. */
typedef struct cf__buf {
    unsigned char *data;
    size_t size, cap;
    int failed;   /* an allocation failed */
} cf__buf_t;

int cf__buf_append(cf__buf_t *b, const void *data, size_t n);
/* n more bytes at the end, not yet written: where they start (n may be
** 0), or NULL when the buffer could not grow (b->failed set). */
unsigned char *cf__buf_extend(cf__buf_t *b, size_t n);
void cf__buf_free(cf__buf_t *b);

/* The first needle (a C string) in the bytes [h, end), or NULL. */
const unsigned char *cf__bytes_find(const unsigned char *h,
                                    const unsigned char *end,
                                    const char *needle);

#endif
