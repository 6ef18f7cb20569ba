/*
** PNG writer for cairo image surfaces (zlib only; see png.c).  Named
** png-private.h so that it never shadows libpng's <png.h>.
*/
#ifndef CURVEFIG_RENDER_PNG_PRIVATE_H
#define CURVEFIG_RENDER_PNG_PRIVATE_H

#include <cairo.h>

#include "render-private.h"

/* Append the PNG encoding of an image surface (CAIRO_FORMAT_ARGB32 or
** RGB24) to out.  The pixels are the ones cairo_surface_write_to_png
** writes: ARGB32 un-premultiplied as cairo does, 8-bit RGBA, or 8-bit RGB
** when every pixel is opaque (always for RGB24).  dpi > 0 is recorded in a
** pHYs chunk (pixels per metre); dpi <= 0 writes none.  zlib level 3,
** filter None on every row: on figures (flat colours, thin lines) this is
** several times faster than cairo's writer and about as small. */
cf_status_t cf__png_encode(cairo_surface_t *image, double dpi,
                           cf__buf_t *out, cf_diag_t *diag);

#endif
