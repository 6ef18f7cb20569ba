/*
** Fuzz target: the font subsetter of the PDF writer (render/fontfile/,
** cf__fontfile_subset_mem) on arbitrary bytes.  The input: a face index
** (a byte, 0 to 3), a count (a byte, up to 16) and that many glyph ids
** (2 bytes each, little-endian), then the font file.  A subset either
** succeeds (a program, an advance for each glyph id) or fails with 1
** and a message, the output empty; never a crash, a read out of bounds
** (the sanitizers) or a stall.  A TrueType subset subset again with the
** same glyphs is the same bytes (its glyph ids, its components and its
** tables are already the ones kept).  The glyph outlines read from the
** file (render/fontfile/outline.h) load each glyph id, upright and
** slanted: 0 or 1, the points within the outline, every contour's end
** after the one before.
**
** The seeds (tests/fuzz/corpus/fontfile/) are subsets this code made,
** under the header above: a TrueType one of CMU Serif, and CFF ones of
** LM Roman and Noto Serif CJK wrapped back into an OpenType file by
** tests/fuzz/fontfile-seed.py (it says how).
*/
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fontfile-private.h"
#include "outline.h"
#include "fuzz-check.h"
#include "fuzz-input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void
outlines(const uint8_t *d, size_t size, unsigned index,
         const unsigned *gids, size_t n)
{
    static const int64_t m[2][4] = { { 0x10000, 0, 0, 0x10000 },
                                     { 0x10000, 0x3333, 0, 0x10000 } };
    cf__olface_t *face;
    cf__outline_t o;
    size_t i, k;
    int r = cf__olface_open_mem(d, size, index, &face), t;
    FZ_CHECK(r == 0 || r == 1, "a face, or refused");
    if (r != 0)
        return;
    memset(&o, 0, sizeof o);
    for (t = 0; t < 2; t++) {
        cf__olsize_t sz;
        cf__olface_size(face, 637 + 1000 * t, 640, m[t], &sz);
        for (i = 0; i < n; i++) {
            r = cf__olface_glyph(face, gids[i], &sz, &o);
            FZ_CHECK(r == 0 || r == 1, "0 or 1 (no allocation fails here)");
            if (r != 0)
                continue;
            FZ_CHECK(o.n <= CF__OL_MAX_POINTS, "points bounded");
            for (k = 0; k < o.ncontours; k++)
                FZ_CHECK(o.ends[k] < o.n && (k == 0 || o.ends[k] > o.ends[k - 1]),
                         "contours within the points, in order");
        }
    }
    cf__outline_fini(&o);
    cf__olface_close(face);
}

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_input in = { data, size };
    unsigned gids[16], index;
    size_t n, i;
    cf__fontfile_subset_t out, again;
    char why[256];
    int r;

    index = fz_byte(&in) % 4;
    n = fz_byte(&in) % 17;
    for (i = 0; i < n; i++)
        gids[i] = fz_u16(&in);
    outlines(in.p, in.n, index, gids, n);
    r = cf__fontfile_subset_mem(in.p, in.n, "fuzz", index, gids, n, &out,
                                why, sizeof why);
    FZ_CHECK(r == 0 || r == 1, "0 or 1 (no allocation fails here)");
    if (r == 1) {
        FZ_CHECK(strncmp(why, "fuzz: ", 6) == 0 && why[6] != '\0',
                 "a message naming the font");
        FZ_CHECK(out.program.data == NULL && out.advances == NULL,
                 "nothing out");
        return 0;
    }
    FZ_CHECK(out.program.size > 0, "a program");
    FZ_CHECK(n == 0 || out.advances != NULL, "advances");
    FZ_CHECK(out.ps_name[0] != '\0' && strlen(out.ps_name) < 64,
             "a PostScript name");
    if (out.kind == CF__FONTFILE_TRUETYPE) {
        r = cf__fontfile_subset_mem(out.program.data, out.program.size,
                                    "again", 0, gids, n, &again, why,
                                    sizeof why);
        FZ_CHECK(r == 0, why);
        FZ_CHECK(again.program.size == out.program.size &&
                 memcmp(again.program.data, out.program.data,
                        out.program.size) == 0,
                 "a subset's subset is itself");
        cf__fontfile_subset_fini(&again);
    }
    cf__fontfile_subset_fini(&out);
    return 0;
}
