/*
** PNG writer for cairo image surfaces (zlib only; see png.c), and its
** pieces the animations share: the APNG writer (anim-apng.c) and the
** pixels of the GIF and the videos (anim-gif.c, anim-ffmpeg.c).  Named
** png-private.h so that it never shadows libpng's <png.h>.
*/
#ifndef CURVEFIG_RENDER_PNG_PRIVATE_H
#define CURVEFIG_RENDER_PNG_PRIVATE_H

#include <stdbool.h>
#include <stdint.h>

#include <cairo.h>

#include "buffer.h"
#include "curvefig/core.h"

/* Append the PNG encoding of an image surface (CAIRO_FORMAT_ARGB32 or
** RGB24) to out.  The pixels are the ones cairo_surface_write_to_png
** writes: ARGB32 un-premultiplied as cairo does, 8-bit RGBA, or 8-bit RGB
** when every pixel is opaque (always for RGB24).  dpi > 0 is recorded in a
** pHYs chunk (pixels per metre); dpi <= 0 writes none.  zlib level 3,
** filter None on every row: on figures (flat colours, thin lines) this is
** several times faster than cairo's writer and about as small. */
cf_status_t cf__png_encode(cairo_surface_t *image, double dpi,
                           cf__buf_t *out, cf_diag_t *diag);

/* ---- the pieces ------------------------------------------------------- */

/* zlib's allocation functions (zalloc, zfree of a z_stream) through the
** library's allocator hook. */
void *cf__png_zalloc(void *opaque, unsigned items, unsigned size);
void cf__png_zfree(void *opaque, void *ptr);

/* v big-endian in p[0..3]. */
void cf__png_put_u32(unsigned char *p, uint32_t v);

/* Append one chunk (length, type, data, CRC-32 of type and data); 0, or
** -1 out of memory. */
int cf__png_chunk(cf__buf_t *out, const char *type,
                  const unsigned char *data, size_t n);

/* The signature and the IHDR of an 8-bit RGBA (rgba) or RGB image; 0, or
** -1 out of memory. */
int cf__png_head(cf__buf_t *out, int width, int height, bool rgba);

/* True when every pixel of width x height native-endian ARGB32 pixels
** (rows stride bytes apart) has alpha 255. */
bool cf__png_opaque(const unsigned char *data, int width, int height,
                    int stride);

/* One row of width premultiplied ARGB32 pixels as un-premultiplied RGBA
** bytes, cairo's way: (c * 255 + a / 2) / a, alpha 0 as 0 0 0 0. */
void cf__png_row_rgba(const unsigned char *src, int width,
                      unsigned char *dst);

/* One row of xRGB pixels (ARGB32 opaque, or RGB24) as RGB bytes. */
void cf__png_row_rgb(const unsigned char *src, int width,
                     unsigned char *dst);

/* The zlib stream of width x height pixels from data (rows stride bytes
** apart; a rectangle of a larger image is its top-left pixel and the
** image's stride), filter None, as RGBA or RGB rows: IDAT chunks when seq
** is NULL, else APNG's fdAT chunks numbered *seq, *seq + 1, ... (*seq
** left one past the last). */
cf_status_t cf__png_rows(const unsigned char *data, int width, int height,
                         int stride, bool rgba, unsigned *seq,
                         cf__buf_t *out, cf_diag_t *diag);

#endif
