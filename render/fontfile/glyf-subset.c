/*
** A TrueType font cut down to some glyphs (render/fontfile/sfnt.h): the
** program of a PDF's CIDFontType2 font (FontFile2).  It has the font's
** number of glyphs, so that glyph ids (the page's codes) hold; the glyphs
** not kept are empty (two equal loca entries).  The kept glyphs are the
** ones asked for, glyph 0 and, followed to any depth, the components of
** kept composite glyphs (each glyph is looked at once: a cycle of
** components ends).
**
** Its tables, in tag order, each 4-byte aligned with its checksum:
** cvt, fpgm, prep (when the font has them: the hinting programs), glyf
** (the kept glyphs, each padded to 4 bytes), head (checkSumAdjustment
** recomputed, indexToLocFormat the loca written: short offsets when the
** glyf table is under 128 KB), hhea, hmtx, loca, maxp, copied.
*/
#include <string.h>

#include "curvefig/core.h"
#include "sfnt.h"

#define NTABLES 9

typedef struct glyf {
    cf__ff_t *f;
    cf__ff_table_t loca, glyf;
    int long_loca;
    unsigned num_glyphs;
} glyf_t;

/* Glyph g's bytes in the glyf table. */
static int
glyph_range(glyf_t *g, unsigned gid, size_t *pos, size_t *len)
{
    size_t a, b;
    if (cf__ff_loca_range(&g->loca, g->long_loca, gid, g->glyf.len, &a, &b))
        return cf__ff_fail(g->f, "loca: glyph %u at %zu to %zu, outside "
                           "the glyf table's %zu bytes", gid, a, b,
                           g->glyf.len);
    if (b > a && b - a < 10)
        return cf__ff_fail(g->f, "glyph %u at %zu: %zu bytes, fewer than "
                           "a glyph header", gid,
                           cf__ff_at(g->f, g->glyf.data) + a, b - a);
    *pos = a;
    *len = b - a;
    return 0;
}

/* Mark the components of composite glyph gid, pushing the new ones. */
static int
components(glyf_t *g, unsigned gid, unsigned char *kept, unsigned *stack,
           size_t *sp)
{
    size_t pos, len, at = 10;
    unsigned flags;
    const unsigned char *p;
    if (glyph_range(g, gid, &pos, &len))
        return 1;
    p = g->glyf.data + pos;
    if (len == 0 || cf__ff_s16(p) >= 0)
        return 0;
    do {
        unsigned comp;
        if (!cf__ff_fits(at, 4, len))
            return cf__ff_fail(g->f, "composite glyph %u at %zu runs past "
                               "its end", gid,
                               cf__ff_at(g->f, p));
        flags = cf__ff_u16(p + at);
        comp = cf__ff_u16(p + at + 2);
        if (comp >= g->num_glyphs)
            return cf__ff_fail(g->f, "composite glyph %u: component %u of "
                               "%u glyphs", gid, comp, g->num_glyphs);
        if (!kept[comp]) {
            kept[comp] = 1;
            stack[(*sp)++] = comp;
        }
        at += 4 + (flags & 1 ? 4 : 2) +
              (flags & 8 ? 2 : flags & 0x40 ? 4 : flags & 0x80 ? 8 : 0);
    } while (flags & 0x20);
    return 0;
}

/* The kept glyphs and their components into kept[]. */
static int
close_kept(glyf_t *g, const unsigned *keep, size_t nkeep,
           unsigned char *kept)
{
    unsigned *stack = cf_alloc_array(g->num_glyphs, sizeof *stack);
    size_t sp = 0, i;
    int r = 0;
    if (stack == NULL)
        return -1;
    for (i = 0; i < nkeep; i++) {
        kept[keep[i]] = 1;
        stack[sp++] = keep[i];
    }
    while (sp > 0 && r == 0)
        r = components(g, stack[--sp], kept, stack, &sp);
    cf_free(stack);
    return r;
}

/* glyf and loca of the kept glyphs. */
static int
build_glyf(glyf_t *g, const unsigned char *kept, cf__buf_t *glyf,
           cf__buf_t *loca, int *long_out)
{
    static const unsigned char pad[3] = { 0, 0, 0 };
    size_t total = 0, pos, len;
    unsigned i;
    for (i = 0; i < g->num_glyphs; i++) {
        if (!kept[i])
            continue;
        if (glyph_range(g, i, &pos, &len))
            return 1;
        total += (len + 3) & ~(size_t)3;
    }
    if (total > 0xffffffffu)
        return cf__ff_fail(g->f, "the glyphs kept take %zu bytes", total);
    *long_out = total > 0x1fffe;
    for (i = 0; i <= g->num_glyphs; i++) {
        unsigned char o[4];
        if (*long_out) {
            cf__ff_put32(o, (uint32_t)glyf->size);
            cf__buf_append(loca, o, 4);
        } else {
            cf__ff_put16(o, (unsigned)(glyf->size / 2));
            cf__buf_append(loca, o, 2);
        }
        if (i == g->num_glyphs || !kept[i])
            continue;
        glyph_range(g, i, &pos, &len);
        cf__buf_append(glyf, g->glyf.data + pos, len);
        cf__buf_append(glyf, pad, ((len + 3) & ~(size_t)3) - len);
    }
    return glyf->failed || loca->failed ? -1 : 0;
}

static uint32_t
checksum(const unsigned char *p, size_t len)
{
    uint32_t sum = 0;
    size_t i;
    for (i = 0; i + 4 <= len; i += 4)
        sum += cf__ff_u32(p + i);
    if (i < len) {
        unsigned char last[4] = { 0, 0, 0, 0 };
        memcpy(last, p + i, len - i);
        sum += cf__ff_u32(last);
    }
    return sum;
}

typedef struct out_table {
    uint32_t tag;
    const unsigned char *data;
    size_t len;
} out_table_t;

/* The font file of the tables t[0..n) (sorted by tag), head at t[ihead]
** (its copy in the output patched). */
static int
write_sfnt(const out_table_t *t, unsigned n, unsigned ihead, cf__buf_t *b)
{
    static const unsigned char pad[3] = { 0, 0, 0 };
    unsigned char h[12], r[16];
    unsigned i, pow = 1, sel = 0;
    size_t off = 12 + 16 * (size_t)n, head_at = 0;
    while (pow * 2 <= n) {
        pow *= 2;
        sel++;
    }
    cf__ff_put32(h, 0x00010000u);
    cf__ff_put16(h + 4, n);
    cf__ff_put16(h + 6, 16 * pow);
    cf__ff_put16(h + 8, sel);
    cf__ff_put16(h + 10, 16 * n - 16 * pow);
    cf__buf_append(b, h, 12);
    for (i = 0; i < n; i++) {
        cf__ff_put32(r, t[i].tag);
        cf__ff_put32(r + 4, checksum(t[i].data, t[i].len));
        cf__ff_put32(r + 8, (uint32_t)off);
        cf__ff_put32(r + 12, (uint32_t)t[i].len);
        cf__buf_append(b, r, 16);
        if (i == ihead)
            head_at = off;
        off += (t[i].len + 3) & ~(size_t)3;
    }
    for (i = 0; i < n; i++) {
        cf__buf_append(b, t[i].data, t[i].len);
        cf__buf_append(b, pad, ((t[i].len + 3) & ~(size_t)3) - t[i].len);
    }
    if (b->failed)
        return -1;
    cf__ff_put32(b->data + head_at + 8,
                 0xb1b0afbau - checksum(b->data, b->size));
    return 0;
}

int
cf__ff_glyf_subset(cf__ff_t *f, const cf__ff_face_t *face,
                   const unsigned *keep, size_t nkeep, unsigned num_glyphs,
                   cf__buf_t *out)
{
    static const char *const names[NTABLES] = { "cvt ", "fpgm", "glyf",
        "head", "hhea", "hmtx", "loca", "maxp", "prep" };
    static const size_t min[NTABLES] = { 0, 0, 0, 54, 36, 0, 0, 6, 0 };
    cf__ff_table_t src[NTABLES];
    out_table_t t[NTABLES];
    unsigned char head[54];
    cf__buf_t glyf = { 0 }, loca = { 0 };
    unsigned char *kept = NULL;
    glyf_t g;
    unsigned i, n = 0, ihead = 0;
    int r, long_out = 0, fmt;
    for (i = 0; i < NTABLES; i++) {
        const char *s = names[i];
        if (cf__ff_table_find(f, face, CF__FF_TAG(s[0], s[1], s[2], s[3]),
                              min[i], &src[i]))
            return 1;
        if (src[i].data == NULL && i >= 2 && i != 8)
            return cf__ff_fail(f, "a TrueType font without '%s'", s);
    }
    fmt = cf__ff_s16(src[3].data + 50);
    if (fmt != 0 && fmt != 1)
        return cf__ff_fail(f, "head: indexToLocFormat %d (0 or 1)", fmt);
    g.f = f;
    g.glyf = src[2];
    g.loca = src[6];
    g.long_loca = fmt;
    g.num_glyphs = num_glyphs;
    if (num_glyphs == 0 ||
        g.loca.len / (fmt ? 4 : 2) < (size_t)num_glyphs + 1)
        return cf__ff_fail(f, "loca at %zu: %zu bytes for %u glyphs",
                           cf__ff_at(f, g.loca.data), g.loca.len,
                           num_glyphs);
    kept = cf_calloc(num_glyphs, 1);
    if (kept == NULL)
        return -1;
    r = close_kept(&g, keep, nkeep, kept);
    if (r == 0)
        r = build_glyf(&g, kept, &glyf, &loca, &long_out);
    if (r == 0) {
        memcpy(head, src[3].data, 54);
        memset(head + 8, 0, 4);
        cf__ff_put16(head + 50, (unsigned)long_out);
        for (i = 0; i < NTABLES; i++) {
            if (src[i].data == NULL)
                continue;
            t[n].tag = cf__ff_u32((const unsigned char *)names[i]);
            t[n].data = i == 2 ? glyf.data : i == 3 ? head :
                        i == 6 ? loca.data : src[i].data;
            t[n].len = i == 2 ? glyf.size : i == 3 ? 54 :
                       i == 6 ? loca.size : src[i].len;
            if (i == 3)
                ihead = n;
            n++;
        }
        r = write_sfnt(t, n, ihead, out);
    }
    cf_free(kept);
    cf__buf_free(&glyf);
    cf__buf_free(&loca);
    return r;
}
