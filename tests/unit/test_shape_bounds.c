/*
** The renderer's shaper (render/fontfile/shape.h) on damaged fonts: Latin
** Modern Roman and CMU Serif with random bytes of their cmap, hhea, hmtx,
** OS/2, GDEF, GSUB and GPOS tables overwritten, or cut short, opened from
** memory and made to shape texts in every script it takes.  Each answer
** may be anything (not usable, not handled, shaped) but never a read
** outside the font (run under AddressSanitizer: the bytes are a heap
** copy of exactly the font's length) nor a crash; a face whose tables are
** intact still shapes.  Faces and runs are freed (the allocator's count
** of live blocks back to its start).
*/
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/core.h"
#include "shape.h"
#include "testutil.h"

static tu_rng rng = { 0x2545F4914F6CDD1Dull };

static unsigned
rnd(unsigned n)
{
    return (unsigned)(tu_rng_next(&rng) % n);
}

static unsigned
be16(const unsigned char *p)
{
    return (unsigned)p[0] << 8 | p[1];
}

static uint32_t
be32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8
           | p[3];
}

static const char *const texts[] = {
    "office", "AVATAR To", "P_0", "x^2 and text", "ffl fi", "αβγ δ",
    "Привет", "0123 (x+y)", "点线面", "かなカナ", "ㄅㄆ", "--- ``quoted''",
    "Wa LT Ty", "œuvre ß"
};
static const uint32_t scripts[] = {
    CF__OT_TAG('l', 'a', 't', 'n'), CF__OT_TAG('l', 'a', 't', 'n'),
    CF__OT_TAG('l', 'a', 't', 'n'), CF__OT_TAG('z', 'y', 'y', 'y'),
    CF__OT_TAG('l', 'a', 't', 'n'), CF__OT_TAG('g', 'r', 'e', 'k'),
    CF__OT_TAG('c', 'y', 'r', 'l'), CF__OT_TAG('z', 'y', 'y', 'y'),
    CF__OT_TAG('h', 'a', 'n', 'i'), CF__OT_TAG('k', 'a', 'n', 'a'),
    CF__OT_TAG('b', 'o', 'p', 'o'), CF__OT_TAG('l', 'a', 't', 'n'),
    CF__OT_TAG('l', 'a', 't', 'n'), CF__OT_TAG('l', 'a', 't', 'n')
};

/* Shape every text; how many were shaped. */
static int
shape_all(const cf__otface_t *face, cf__otrun_t *run)
{
    cf__otscale_t sc = { 10240, 10240, 0.f };
    size_t i;
    int shaped = 0;
    for (i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        int r = cf__ot_shape(face, scripts[i], &sc, texts[i], 0,
                             strlen(texts[i]), run);
        if (r < 0)
            abort();
        shaped += r == 0;
    }
    return shaped;
}

int
main(void)
{
    static const char *const files[] = {
        "/usr/share/texmf/fonts/opentype/public/lm/lmroman10-regular.otf",
        "/usr/share/fonts/truetype/cmu/cmunrm.ttf"
    };
    static const char tables[][5] = { "cmap", "hhea", "hmtx", "OS/2",
                                      "GDEF", "GSUB", "GPOS", "head",
                                      "maxp" };
    size_t f;
    long damaged = 0, usable = 0, shaped = 0;
    for (f = 0; f < sizeof files / sizeof files[0]; f++) {
        size_t len, t, k;
        unsigned char *font = tu_read_file(files[f], &len);
        cf__otface_t *face;
        cf__otrun_t run;
        unsigned ntables;
        memset(&run, 0, sizeof run);
        if (font == NULL) {
            printf("skipped: %s\n", files[f]);
            continue;
        }
        if (cf__otface_open_mem(font, len, 0, &face) != 0)
            abort();
        if (!cf__otface_usable(face) || shape_all(face, &run) == 0) {
            printf("FAIL: %s intact does not shape\n", files[f]);
            return 1;
        }
        cf__otface_close(face);
        ntables = be16(font + 4);
        for (t = 0; t < sizeof tables / sizeof tables[0]; t++) {
            size_t at = 0, tlen = 0, i;
            for (i = 0; i < ntables && 12 + 16 * i + 16 <= len; i++)
                if (memcmp(font + 12 + 16 * i, tables[t], 4) == 0) {
                    at = be32(font + 12 + 16 * i + 8);
                    tlen = be32(font + 12 + 16 * i + 12);
                }
            if (tlen == 0 || at + tlen > len)
                continue;
            for (k = 0; k < 300; k++) {
                /* the file cut short in the table, one time in ten: the
                ** copy holds exactly the bytes given */
                size_t n = 1 + rnd(8), j;
                size_t cut = k % 10 == 9 ? at + rnd((unsigned)tlen) : len;
                unsigned char *copy = malloc(cut);
                if (copy == NULL)
                    abort();
                memcpy(copy, font, cut);
                for (j = 0; j < n; j++) {
                    /* an offset or count: often 0xFF.. or 0 */
                    size_t p = at + rnd((unsigned)tlen);
                    unsigned v = rnd(4);
                    if (p < cut)
                        copy[p] = v == 0 ? 0xFF
                                  : v == 1 ? 0 : (unsigned char)rnd(256);
                }
                if (cf__otface_open_mem(copy, cut, 0, &face) != 0)
                    abort();
                damaged++;
                if (cf__otface_usable(face)) {
                    usable++;
                    shaped += shape_all(face, &run);
                }
                cf__otface_close(face);
                free(copy);
            }
        }
        cf__otrun_fini(&run);
        free(font);
    }
    printf("%ld damaged faces: %ld still usable, %ld runs shaped, no read "
           "outside a font\n", damaged, usable, shaped);
    return damaged > 0 ? 0 : 1;
}
