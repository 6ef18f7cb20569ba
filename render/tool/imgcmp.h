/*
** The image comparator of `curvefig compare` and `curvefig test` (and so
** of the project's pixel suite, which runs through `curvefig test`).
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
** on one row by one rasteriser and over two half rows by the other).
** Pixels still over the threshold are counted; the images match when that
** count is at most `max_bad_pixels`.
**
** The rules the tool applies (docs/testing.md explains them):
** - threshold 0.1: pixelmatch's default; 0.1 of normalised YIQ distance is
**   about 26 grey levels, far above rounding differences between
**   rasterisers (1-3 levels) and far below any real stroke (a grey polygon
**   on white is > 0.4).
** - aa_radius 1: an edge may land one pixel away (sub-pixel placement of
**   the same geometry); a control point moved by 1 pt moves 2 pixels at
**   144 dpi, which the allowance does not forgive.
** - figures without labels: no bad pixel allowed.
** - figures with labels: up to CF__IMGCMP_TEXT_FRACTION of the pixels, for
**   glyphs that cairo's text path (hinted) and librsvg's glyph outlines
**   rasterise differently.  On the project's figures at most 3 such
**   pixels of ~150,000 (0.002 %); the allowance, 0.05 %, is 25 times that,
**   and the label-free layer, which a moved control point always changes,
**   stays strict.
*/
#ifndef CURVEFIG_TOOL_IMGCMP_H
#define CURVEFIG_TOOL_IMGCMP_H

#include <stddef.h>
#include <stdint.h>

#define CF__IMGCMP_THRESHOLD 0.1
#define CF__IMGCMP_AA_RADIUS 1
#define CF__IMGCMP_TEXT_FRACTION 0.0005
#define CF__IMGCMP_DPI 144.0

typedef struct cf__imgcmp_image {
    int width, height;
    int stride;              /* bytes */
    const unsigned char *data;
} cf__imgcmp_image;

typedef struct cf__imgcmp_options {
    double threshold;        /* normalised YIQ distance, 0..1 */
    int aa_radius;           /* pixels; 0 disables the AA allowance */
    long max_bad_pixels;
} cf__imgcmp_options;

typedef struct cf__imgcmp_result {
    int identical;           /* the exact fast path was taken */
    long bad_pixels;         /* over threshold and not forgiven */
    long aa_pixels;          /* over threshold but forgiven as AA */
    double max_delta;        /* largest normalised distance seen */
    int bad_x[4], bad_y[4];  /* where the first bad pixels are */
    int match;
} cf__imgcmp_result;

/* Normalised YIQ distance of two ARGB32 premultiplied pixels, on white. */
double cf__imgcmp_pixel_delta(uint32_t a, uint32_t b);

/* Compare; if diff != NULL (same size, width*4 stride), paint a diff image:
** the expected image faded, bad pixels red, forgiven ones yellow (identical
** images give just the faded copy).
** Returns -1 if the sizes differ. */
int cf__imgcmp_compare(const cf__imgcmp_image *actual,
                       const cf__imgcmp_image *expected,
                       const cf__imgcmp_options *opt, cf__imgcmp_result *res,
                       unsigned char *diff);

#endif
