/*
** The font subsetter's bounds (render/fontfile/cff-charstring.c) on
** hostile charstrings: a small OpenType font is built here, its CFF table
** two glyphs and some global subroutines, glyph 1 written for each case:
** a subroutine calling itself (refused past the Type 2 limit of 10 nested
** calls), 49 operands (past the stack of 48), subroutines calling the
** next 200 times over, 200^8 calls (refused when the scan's budget of
** steps runs out, in milliseconds), a call outside the INDEX, a hint mask
** past the charstring's end, an accented character (endchar with 4
** operands: seac, which a CID-keyed subset cannot hold) and a glyph id out
** of range.  Each is refused (1) with a message saying which; the same
** font with a plain glyph is subset (0).  The glyph outlines read from the
** files (render/fontfile/outline.h) meet the same charstrings: the plain
** glyph is read, every hostile one refused (1), the 200^8 calls within a
** second; damaged copies of real fonts (CMU Serif's glyf, LM Roman's CFF:
** every glyph of each copy with bytes overwritten or the file cut short)
** give 0 or 1 for every glyph, never a read out of bounds (the
** sanitizers); and under allocation failure (tu_fail_loop) a glyph's load
** fails cleanly, leaking nothing.
*/
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <cmocka.h>

#include "fontfile-private.h"
#include "outline.h"
#include "testutil.h"

typedef struct bytes {
    unsigned char d[65536];
    size_t n;
} bytes_t;

static void
put(bytes_t *b, const void *p, size_t n)
{
    assert_true(b->n + n <= sizeof b->d);
    memcpy(b->d + b->n, p, n);
    b->n += n;
}

/* v in size bytes, big-endian. */
static void
put_be(bytes_t *b, uint32_t v, int size)
{
    while (size-- > 0)
        put(b, &(unsigned char){ (unsigned char)(v >> (8 * size)) }, 1);
}

/* A CFF INDEX of n items (offsets of 4 bytes). */
static void
put_index(bytes_t *b, const bytes_t *items, size_t n)
{
    size_t i, off = 1;
    put_be(b, (uint32_t)n, 2);
    if (n == 0)
        return;
    put_be(b, 4, 1);
    put_be(b, 1, 4);
    for (i = 0; i < n; i++) {
        off += items[i].n;
        put_be(b, (uint32_t)off, 4);
    }
    for (i = 0; i < n; i++)
        put(b, items[i].d, items[i].n);
}

static void
put_int5(bytes_t *b, uint32_t v)
{
    put_be(b, 29, 1);
    put_be(b, v, 4);
}

/* The font: glyph 0 an endchar, glyph 1 `glyph`, the global subroutines
** gsubrs[0..ng), an empty Private DICT; wrapped in head, hhea, hmtx,
** maxp. */
static bytes_t *
font(const bytes_t *glyph, const bytes_t *gsubrs, size_t ng)
{
    static bytes_t cff, items[2], top, sfnt;
    size_t after;
    int pass;
    memset(&items[0], 0, sizeof items[0]);
    items[0].d[0] = 14;
    items[0].n = 1;
    items[1] = *glyph;
    /* twice: the offsets of the first pass in the second's Top DICT */
    after = 0;
    for (pass = 0; pass < 2; pass++) {
        size_t cs;
        cff.n = 0;
        put_be(&cff, 0x01000401, 4);
        put_index(&cff, &(bytes_t){ .d = "T", .n = 1 }, 1);
        top.n = 0;
        put_int5(&top, (uint32_t)after);
        put_be(&top, 17, 1);                /* CharStrings */
        put_int5(&top, 0);
        put_int5(&top, (uint32_t)after);
        put_be(&top, 18, 1);                /* Private: empty */
        put_index(&cff, &top, 1);
        put_index(&cff, NULL, 0);
        put_index(&cff, gsubrs, ng);
        cs = cff.n;
        put_index(&cff, items, 2);
        after = cs;
    }
    {
        static const char *const tags[] = { "CFF ", "head", "hhea", "hmtx",
                                            "maxp" };
        unsigned char head[54] = { 0 }, hhea[36] = { 0 }, hmtx[8] = { 0 },
                      maxp[6] = { 0, 0, 0x50, 0, 0, 2 };
        const unsigned char *data[5] = { cff.d, head, hhea, hmtx, maxp };
        size_t len[5] = { cff.n, 54, 36, 8, 6 }, off = 12 + 16 * 5;
        int i;
        head[18] = 1000 >> 8;
        head[19] = 1000 & 0xff;
        hhea[35] = 2;
        hmtx[0] = 2;
        sfnt.n = 0;
        put_be(&sfnt, 0x4f54544f, 4);
        put_be(&sfnt, 5, 2);
        put_be(&sfnt, 0, 4);   /* the search hints, not read */
        put_be(&sfnt, 0, 2);
        for (i = 0; i < 5; i++) {
            put(&sfnt, tags[i], 4);
            put_be(&sfnt, 0, 4);
            put_be(&sfnt, (uint32_t)off, 4);
            put_be(&sfnt, (uint32_t)len[i], 4);
            off += (len[i] + 3) & ~(size_t)3;
        }
        for (i = 0; i < 5; i++) {
            put(&sfnt, data[i], len[i]);
            put_be(&sfnt, 0, (int)(((len[i] + 3) & ~(size_t)3) - len[i]));
        }
    }
    return &sfnt;
}

/* A charstring of the given bytes. */
static bytes_t
cs(const unsigned char *p, size_t n)
{
    bytes_t b;
    memset(&b, 0, sizeof b);
    put(&b, p, n);
    return b;
}

/* Subset glyph gid of the font; the result, the message in why. */
static int
subset(const bytes_t *f, unsigned gid, char *why, size_t cap)
{
    cf__fontfile_subset_t out;
    int r = cf__fontfile_subset_mem(f->d, f->n, "hostile", 0, &gid, 1, &out,
                                    why, cap);
    if (r != 0)
        assert_null(out.program.data);
    cf__fontfile_subset_fini(&out);
    return r;
}

/* Glyph gid's outline read from the font: 0, 1 or -1. */
static int
outline(const bytes_t *f, unsigned gid)
{
    cf__olface_t *face;
    cf__outline_t o;
    cf__olsize_t sz;
    static const int64_t id[4] = { 0x10000, 0, 0, 0x10000 };
    int r = cf__olface_open_mem(f->d, f->n, 0, &face);
    if (r != 0)
        return r;
    memset(&o, 0, sizeof o);
    cf__olface_size(face, 640, 640, id, &sz);
    r = cf__olface_glyph(face, gid, &sz, &o);
    cf__outline_fini(&o);
    cf__olface_close(face);
    return r;
}

static void
refused(const bytes_t *f, unsigned gid, const char *says)
{
    char why[256];
    int r = subset(f, gid, why, sizeof why);
    if (r != 1 || strstr(why, says) == NULL)
        fail_msg("%d \"%s\", not 1 and \"%s\"", r, why, says);
    assert_int_equal(outline(f, gid), 1);
}

static void
test_bounds(void **state)
{
    /* -107 callgsubr: subroutine 0 (bias 107) */
    static const unsigned char call0[] = { 32, 29, 14 };
    static const unsigned char self[] = { 32, 29, 11 };
    static const unsigned char move[] = { 139, 139, 21, 11 };
    static const unsigned char far[] = { 28, 0x13, 0x88, 29, 14 };
    static const unsigned char mask[] = { 139, 139, 1, 19 };
    static const unsigned char seac[] = { 139, 139, 139, 139, 14 };
    bytes_t g, subrs[9];
    char why[256];
    size_t i, k;
    clock_t t0;
    (void)state;

    /* a plain glyph through a subroutine: subset */
    g = cs(call0, 3);
    subrs[0] = cs(move, 4);
    assert_int_equal(subset(font(&g, subrs, 1), 1, why, sizeof why), 0);
    assert_int_equal(outline(font(&g, subrs, 1), 1), 0);
    refused(font(&g, subrs, 1), 2, "glyph id 2 out of range");
    /* a subroutine calling itself */
    subrs[0] = cs(self, 3);
    refused(font(&g, subrs, 1), 1, "nested deeper than 10");
    /* 49 operands */
    memset(&g, 0, sizeof g);
    for (i = 0; i < 49; i++)
        put(&g, "\x8b", 1);
    refused(font(&g, subrs, 1), 1, "more than 48 operands");
    /* subroutine k calls k + 1 two hundred times, 8 deep */
    for (k = 0; k < 9; k++) {
        memset(&subrs[k], 0, sizeof subrs[k]);
        for (i = 0; k < 8 && i < 200; i++) {
            unsigned char c[2] = { (unsigned char)(k + 1 - 107 + 139), 29 };
            put(&subrs[k], c, 2);
        }
        put(&subrs[k], "\x0b", 1);
    }
    g = cs(call0, 3);
    t0 = clock();
    refused(font(&g, subrs, 9), 1, "ran out of steps");
    assert_true(clock() - t0 < CLOCKS_PER_SEC);
    /* a call outside the INDEX: 5000 + 107 of 9 */
    g = cs(far, 5);
    refused(font(&g, subrs, 9), 1, "callgsubr 5107 of 9");
    /* a hint mask past the end */
    g = cs(mask, 4);
    refused(font(&g, subrs, 9), 1, "inside a hint mask");
    /* seac */
    g = cs(seac, 5);
    refused(font(&g, subrs, 9), 1, "seac");
}

/* Every glyph of the bytes: 0 or 1 each (the face may be refused). */
static void
every_glyph(const unsigned char *d, size_t n, unsigned step)
{
    cf__olface_t *face;
    cf__outline_t o;
    cf__olsize_t sz;
    static const int64_t slant[4] = { 0x10000, 0x3333, 0, 0x10000 };
    unsigned g;
    int r = cf__olface_open_mem(d, n, 0, &face);
    assert_true(r == 0 || r == 1);
    if (r != 0)
        return;
    memset(&o, 0, sizeof o);
    cf__olface_size(face, 637, 640, slant, &sz);
    for (g = 0; g < cf__olface_num_glyphs(face); g += step) {
        r = cf__olface_glyph(face, g, &sz, &o);
        assert_true(r == 0 || r == 1);
    }
    cf__outline_fini(&o);
    cf__olface_close(face);
}

static void
test_damaged_copies(void **state)
{
    static const char *const files[] = {
        "/usr/share/fonts/truetype/cmu/cmunrm.ttf",
        "/usr/share/texmf/fonts/opentype/public/lm/lmroman10-regular.otf"
    };
    size_t f, k;
    (void)state;
    for (f = 0; f < 2; f++) {
        size_t n, i;
        unsigned char *d = tu_read_file(files[f], &n), *c;
        uint32_t seed = 12345;
        if (d == NULL) {
            printf("%s: not installed, skipped\n", files[f]);
            continue;
        }
        c = malloc(n);
        assert_non_null(c);
        every_glyph(d, n, 1);
        for (k = 0; k < 24; k++) {
            memcpy(c, d, n);
            for (i = 0; i < 64; i++) {   /* 64 bytes overwritten */
                seed = seed * 1103515245u + 12345u;
                c[(seed >> 8) % n] = (unsigned char)(seed >> 24);
            }
            every_glyph(c, n, 3);
            every_glyph(c, n / (k + 2), 5);   /* and cut short */
        }
        free(c);
        free(d);
    }
}

static unsigned char *oom_font;
static size_t oom_len;

static cf_status_t
op_outline(cf_diag_t *diag)
{
    cf__olface_t *face;
    cf__outline_t o;
    cf__olsize_t sz;
    static const int64_t id[4] = { 0x10000, 0, 0, 0x10000 };
    unsigned g;
    int r;
    (void)diag;
    r = cf__olface_open_mem(oom_font, oom_len, 0, &face);
    if (r != 0)
        return r < 0 ? CF_STATUS_NO_MEMORY : CF_STATUS_INVALID_ARG;
    memset(&o, 0, sizeof o);
    cf__olface_size(face, 640, 640, id, &sz);
    for (g = 0, r = 0; g < 40 && r == 0; g++)
        r = cf__olface_glyph(face, g, &sz, &o);
    cf__outline_fini(&o);
    cf__olface_close(face);
    return r < 0 ? CF_STATUS_NO_MEMORY : r > 0 ? CF_STATUS_INVALID_ARG
                                               : CF_STATUS_OK;
}

static void
test_out_of_memory(void **state)
{
    (void)state;
    oom_font = tu_read_file("/usr/share/texmf/fonts/opentype/public/lm/"
                     "lmroman10-regular.otf", &oom_len);
    if (oom_font == NULL)
        skip();
    assert_true(tu_fail_loop("glyph outlines", op_outline, false) > 0);
    free(oom_font);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bounds),
        cmocka_unit_test(test_damaged_copies),
        cmocka_unit_test(test_out_of_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
