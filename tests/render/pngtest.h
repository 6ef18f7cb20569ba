/* PNG bytes in memory to a cairo image surface (cairo's reader: libpng,
** CRCs checked), for the renderer tests that measure pixels; the caller
** checks cairo_surface_status and destroys the surface.  And the box of
** an image's ink. */
#ifndef CURVEFIG_TESTS_PNGTEST_H
#define CURVEFIG_TESTS_PNGTEST_H

#include <stddef.h>

#include <cairo.h>

cairo_surface_t *tu_png_decode(const void *data, size_t size);

/* The box of the pixels with alpha > 0 of an ARGB32 image: x0 y0 x1 y1,
** x1 and y1 one past it ({w, h, 0, 0} when there are none). */
void tu_alpha_box(cairo_surface_t *img, int box[4]);

#endif
