/*
** Image files for `curvefig compare` and `curvefig test`: a PNG, or an SVG
** rasterised by librsvg, read as plain pixels by the output layer
** (output/image-io.h); images compared with the comparator (imgcmp.h) and
** written as PNG.
*/
#ifndef CURVEFIG_TOOL_IMGFILE_H
#define CURVEFIG_TOOL_IMGFILE_H

#include <stddef.h>

#include "image-io.h"
#include "imgcmp.h"

/* Read path by its content: a PNG, or an SVG rasterised by librsvg at dpi
** (the page at its own size from the origin, the last partial pixel row
** and column rounded up, as the renderer sizes its PNG).  A PDF, or an
** SVG when the tool is built without librsvg, is refused with a message
** saying so.  On failure NULL, and err holds "PATH: what went wrong". */
cf__image *cf__tool_image_read(const char *path, double dpi,
                                     char *err, size_t errsize);
/* The resolution a PNG file records (its pHYs chunk, in pixels per
** metre) in dots per inch, rounded to a whole number when within 0.05 of
** one; 0 when path is not a PNG or records none. */
double cf__tool_png_dpi(const char *path);
/* What cf__tool_image_read took the file for: "PNG", "SVG" or "?". */
const char *cf__tool_image_kind(const char *path);

/* Compare actual with expected.  If diff != NULL it receives the diff
** image (the expected image faded, red where they differ, yellow where
** only anti-aliasing differs), or NULL when memory ran out.  Returns -1
** when the sizes differ (*diff is then NULL), 0 otherwise. */
int cf__tool_image_compare(const cf__image *actual, const cf__image *expected,
                           const cf__imgcmp_options *opt,
                           cf__imgcmp_result *res, cf__image **diff);

/* The verdict in words, e.g. "different: 152 of 112,608 pixels differ
** (0.135 %), 40 more by anti-aliasing only; largest difference 0.873". */
void cf__tool_image_verdict(char *buf, size_t size,
                            const cf__imgcmp_result *res,
                            const cf__imgcmp_options *opt, long pixels);

/* Write im to path as PNG through a temporary name; 0, or -1 (errno). */
int cf__tool_image_write_png(const cf__image *im, const char *path);

#endif
