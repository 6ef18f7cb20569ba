#include <string.h>

#include "pngtest.h"

typedef struct reader {
    const unsigned char *data;
    size_t size, pos;
} reader_t;

static cairo_status_t
read_mem(void *closure, unsigned char *out, unsigned int n)
{
    reader_t *r = closure;
    if (r->size - r->pos < n)
        return CAIRO_STATUS_READ_ERROR;
    memcpy(out, r->data + r->pos, n);
    r->pos += n;
    return CAIRO_STATUS_SUCCESS;
}

cairo_surface_t *
tu_png_decode(const void *data, size_t size)
{
    reader_t r = { data, size, 0 };
    return cairo_image_surface_create_from_png_stream(read_mem, &r);
}
