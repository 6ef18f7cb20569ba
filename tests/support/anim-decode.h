/*
** Animated GIF and APNG bytes decoded for the tests (tests/support/
** anim-decode.c), written from the formats' specifications and sharing no
** code with the encoders (render/output/anim-gif.c, anim-apng.c): GIF's
** LZW decoded here, APNG inflated with zlib and unfiltered here.  Each
** frame is the picture a viewer shows while the frame is on screen (the
** canvas after the frame is drawn, disposal and blending applied), as
** un-premultiplied RGBA; transparent pixels are 0 0 0 0.
*/
#ifndef CURVEFIG_TESTS_ANIM_DECODE_H
#define CURVEFIG_TESTS_ANIM_DECODE_H

#include <stdbool.h>
#include <stddef.h>

typedef struct tu_anim {
    int width, height;
    unsigned frames;
    unsigned plays;             /* 0: forever; GIF without NETSCAPE2.0: 1 */
    unsigned char **rgba;       /* frames x (width * height * 4) */
    unsigned *num, *den;        /* each frame's time: num / den seconds
                                   (GIF: hundredths, den 100) */
    int (*box)[4];              /* each frame's rectangle: x y w h */
    int colours;                /* GIF: entries of the global palette;
                                   APNG: 3 (RGB) or 4 (RGBA) channels */
    unsigned char palette[256][3];   /* GIF's global palette */
    char error[160];            /* why decoding failed */
} tu_anim_t;

/* 0, or -1 with a->error set (and nothing to free). */
int tu_gif_decode(const unsigned char *data, size_t size, tu_anim_t *a);
int tu_apng_decode(const unsigned char *data, size_t size, tu_anim_t *a);

/* The frames of a decoded animation freed; a zeroed tu_anim_t too. */
void tu_anim_free(tu_anim_t *a);

#endif
