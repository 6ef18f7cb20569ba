/*
** Images as plain pixels, read from and written to files, for the tool's
** `compare` and `test` (the only users; the renderer's library does not
** carry this file, so that only the comparing helper loads librsvg).
**
** A cf__image holds cairo's ARGB32 layout (premultiplied alpha, native
** endian 32-bit words), rows of `stride` bytes; callers need no cairo.
*/
#ifndef CURVEFIG_OUTPUT_IMAGE_IO_H
#define CURVEFIG_OUTPUT_IMAGE_IO_H

#include <stdio.h>
#include <stddef.h>

typedef struct cf__image {
    int width, height;
    int stride;              /* bytes, 4 * width */
    unsigned char *data;
} cf__image;

/* A transparent image of w x h pixels (stride 4 * w); NULL when memory
** runs out or a side is not positive. */
cf__image *cf__image_new(int w, int h);
void cf__image_destroy(cf__image *im);

/* The PNG at path as ARGB32 (a PNG without alpha made opaque); NULL and
** err holding "PATH: what went wrong" on failure. */
cf__image *cf__image_read_png(const char *path, char *err, size_t errsize);

/* The SVG at path rasterised by librsvg at dpi: the page at its own size
** from the origin, the last partial pixel row and column rounded up (as
** the renderer sizes its PNG), at most max_side pixels a side; NULL and
** err on failure (and always without librsvg). */
cf__image *cf__image_read_svg(const char *path, double dpi, int max_side,
                              char *err, size_t errsize);

/* im as a PNG file on f; 0, or -1 when writing failed. */
int cf__image_write_png(const cf__image *im, FILE *f);

#endif
