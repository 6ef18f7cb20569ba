#include <stdint.h>
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

void
tu_alpha_box(cairo_surface_t *img, int box[4])
{
    int w = cairo_image_surface_get_width(img);
    int h = cairo_image_surface_get_height(img);
    int stride = cairo_image_surface_get_stride(img);
    const unsigned char *px;
    cairo_surface_flush(img);
    px = cairo_image_surface_get_data(img);
    box[0] = w;
    box[1] = h;
    box[2] = box[3] = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            uint32_t p = *(const uint32_t *)(const void *)(px + y * stride
                                                            + 4 * x);
            if ((p >> 24) == 0)
                continue;
            box[0] = x < box[0] ? x : box[0];
            box[1] = y < box[1] ? y : box[1];
            box[2] = x + 1 > box[2] ? x + 1 : box[2];
            box[3] = y + 1 > box[3] ? y + 1 : box[3];
        }
}
