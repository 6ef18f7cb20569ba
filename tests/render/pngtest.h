/* PNG bytes in memory to a cairo image surface (cairo's reader: libpng,
** CRCs checked), for the renderer tests that measure pixels.  The caller
** checks cairo_surface_status and destroys the surface. */
#ifndef CURVEFIG_TESTS_PNGTEST_H
#define CURVEFIG_TESTS_PNGTEST_H

#include <stddef.h>

#include <cairo.h>

cairo_surface_t *tu_png_decode(const void *data, size_t size);

#endif
