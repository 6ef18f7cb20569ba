/*
** Image comparison for the pixel tests.
**
** Two images of equal size in cairo's ARGB32 layout (premultiplied, native
** endian 32-bit words).  The comparison has an exact fast path (identical
** rows); otherwise every pixel gets a perceptual colour distance in YIQ
** space (after compositing on white), the measure of Kotsarenko & Ramos
** that pixelmatch uses, normalised to [0, 1].  A pixel over `threshold` is
** forgiven when it is an anti-aliasing pixel: each image's colour lies
** within the colour range of the other image's neighbourhood of radius
** `aa_radius` (an edge drawn a fraction of a pixel elsewhere by another
** rasteriser gives intermediate colours; a moved stroke does not), or
** when the two images carry the same ink around it: their mean colours
** over that neighbourhood are within the threshold (a one-pixel line put
** on one row by one rasteriser and over two half rows by the other).  Pixels still over
** the threshold are counted; the images match when that count is at most
** `max_bad_pixels`.
*/
#ifndef CURVEFIG_PIXELCMP_H
#define CURVEFIG_PIXELCMP_H

#include <stddef.h>
#include <stdint.h>

typedef struct pc_image {
    int width, height;
    int stride;              /* bytes */
    const unsigned char *data;
} pc_image;

typedef struct pc_options {
    double threshold;        /* normalised YIQ distance, 0..1 */
    int aa_radius;           /* pixels; 0 disables the AA allowance */
    long max_bad_pixels;
} pc_options;

typedef struct pc_result {
    int identical;           /* the exact fast path was taken */
    long bad_pixels;         /* over threshold and not forgiven */
    long aa_pixels;          /* over threshold but forgiven as AA */
    double max_delta;        /* largest normalised distance seen */
    int bad_x[4], bad_y[4];  /* where the first bad pixels are */
    int match;
} pc_result;

/* Normalised YIQ distance of two ARGB32 premultiplied pixels, on white. */
double pc_pixel_delta(uint32_t a, uint32_t b);

/* Compare; if diff != NULL (same size, width*4 stride), paint a diff image:
** the expected image faded, bad pixels red, forgiven ones yellow.
** Returns -1 if the sizes differ. */
int pc_compare(const pc_image *actual, const pc_image *expected,
               const pc_options *opt, pc_result *res, unsigned char *diff);

#endif
