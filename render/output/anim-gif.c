/*
** The animated GIF (GIF89a) of a sweep's frames, written here: one global
** palette chosen for the figure, no dithering, LZW with clear codes, the
** frames after the first as the rectangle that changed.
**
** The palette needs every frame's colours, and the frames come one at a
** time; a frame is kept until finish as its RGBA pixels deflated at zlib
** level 1 (a frame of 301 x 201 pixels of a test figure, 242 KB, keeps in
** 7 KB), while its colours are counted (anim-palette.c): exactly for the
** first 4096 distinct colours (a figure's flat colours are among them:
** they fill the first frame already), and in 32768 bins of 5 bits per
** channel (counts and sums) for all.  At finish:
**   - at most 256 distinct colours (255 with transparency): exactly them;
**   - more (anti-aliased lines over fills, shaded surfaces): the flat
**     colours kept exact (the most frequent, up to 64, each covering at
**     least 1/20000 of the pixels), the rest by median cut over
**     the bins, each pixel drawn in the palette colour nearest to it.
**     No dithering: line art stays clean.
** Transparency: a pixel of alpha < 128 is transparent (GIF has no partial
** alpha), the others are shown opaque in their un-premultiplied colour.
** Frames with transparent pixels are written whole, disposed of to the
** background (the earlier frame would show through them otherwise); the
** others as the rectangle of pixels that changed, drawn over the frame
** before (disposal "do not dispose").
**
** Times: GIF delays are whole hundredths of a second (cs), and viewers
** show a delay below 2 cs as 10 cs.  Frame k starts at round(100 s_k) cs
** (s_k: the sum of the earlier frames' times), so the delays add up to
** the total time exactly, without drift.  Above 50 frames per second (a
** frame that would be shown less than 2 cs), the frames that start less
** than 2 cs after the frame shown before them, or end less than 2 cs
** before the end, are dropped: the animation keeps its duration, shows at
** most 50 frames per second, and every frame at or below 50 fps is kept.
** A delay above 65535 cs is split over repeats of the frame.
*/
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <zlib.h>

#include "anim-private.h"
#include "png-private.h"

#define CLEAR_ALPHA 128         /* alpha below: transparent */

typedef struct kept {
    unsigned char *z;           /* the RGBA pixels, deflated */
    size_t n;
    double start, seconds;
} kept_t;

typedef struct gif_sink {
    cf__anim_sink_t base;
    kept_t *frame;
    size_t cap;
    cf__colours_t col;          /* the frames' colours */
    unsigned char *row;         /* one row of RGBA */
    z_stream z;
    bool z_ready;
} gif_sink_t;

/* ---- keeping the frames ------------------------------------------------- */

/* One frame's row as RGBA bytes in g->row, the transparent pixels as
** 0 0 0 0 and the others opaque; its colours counted by runs. */
static void
take_row(gif_sink_t *g, const cf__anim_frame_t *f, int y)
{
    const unsigned char *src = f->data + (size_t)y * (size_t)f->stride;
    unsigned char *p = g->row;
    int w = g->base.width, x, run;
    if (f->alpha) {
        cf__png_row_rgba(src, w, p);
        for (x = 0; x < w; x++, p += 4) {
            if (p[3] < CLEAR_ALPHA)
                p[0] = p[1] = p[2] = p[3] = 0;
            else
                p[3] = 255;
        }
    } else {
        cf__png_row_rgb(src, w, p + (size_t)w);   /* 3w bytes after w */
        for (x = 0; x < w; x++, p += 4) {
            memmove(p, g->row + (size_t)w + 3 * (size_t)x, 3);
            p[3] = 255;
        }
    }
    for (x = 0; x < w; x += run) {
        const unsigned char *q = g->row + 4 * (size_t)x;
        for (run = 1; x + run < w && memcmp(q, q + 4 * run, 4) == 0; run++)
            ;
        if (q[3] == 0)
            g->col.clear += (uint64_t)run;
        else
            cf__colours_add(&g->col, (uint32_t)q[0] << 16
                                         | (uint32_t)q[1] << 8 | q[2],
                            (uint64_t)run);
    }
}

static cf_status_t
gif_add(cf__anim_sink_t *sink, const cf__anim_frame_t *f, cf_diag_t *diag)
{
    gif_sink_t *g = (gif_sink_t *)sink;
    int w = sink->width, h = sink->height, y;
    uLong bound = deflateBound(&g->z, (uLong)w * 4 * (uLong)h + 1);
    kept_t *k;
    unsigned char *z;

    if (f->index >= g->cap) {
        size_t cap = g->cap ? 2 * g->cap : 64;
        kept_t *nf = cf_realloc_array(g->frame, cap, sizeof *nf);
        if (nf == NULL)
            goto nomem;
        g->frame = nf;
        g->cap = cap;
    }
    k = &g->frame[f->index];
    z = cf_malloc(bound);
    if (z == NULL)
        goto nomem;
    deflateReset(&g->z);
    g->z.next_out = z;
    g->z.avail_out = (uInt)bound;
    for (y = 0; y < h; y++) {
        take_row(g, f, y);
        g->z.next_in = g->row;
        g->z.avail_in = (uInt)(4 * (size_t)w);
        if (deflate(&g->z, y == h - 1 ? Z_FINISH : Z_NO_FLUSH)
            == Z_STREAM_ERROR || g->z.avail_in != 0) {
            cf_free(z);
            goto nomem;
        }
    }
    k->n = (size_t)(bound - g->z.avail_out);
    k->z = cf_realloc_array(z, k->n, 1);
    if (k->z == NULL)
        k->z = z;
    k->start = f->start;
    k->seconds = f->seconds;
    return CF_STATUS_OK;
nomem:
    return cf_diag_set(diag, CF_STATUS_NO_MEMORY, (long)f->index,
                       "GIF frame %u: out of memory keeping its pixels",
                       f->index);
}



/* ---- LZW ---------------------------------------------------------------- */

typedef struct lzw {
    cf__buf_t *out;
    unsigned char block[256];   /* a data sub-block: its size, then data */
    uint32_t acc;               /* bits not yet written, LSB first */
    int nacc;
    uint32_t *dict;             /* 0 empty, else (prefix << 8 | byte) + 1 */
    uint16_t *code;
} lzw_t;

#define DICT_SLOTS 8192

static void
put_byte(lzw_t *z, unsigned char b)
{
    z->block[1 + z->block[0]++] = b;
    if (z->block[0] == 255) {
        cf__buf_append(z->out, z->block, 256);
        z->block[0] = 0;
    }
}

static void
put_code(lzw_t *z, unsigned code, int width)
{
    z->acc |= (uint32_t)code << z->nacc;
    z->nacc += width;
    while (z->nacc >= 8) {
        put_byte(z, (unsigned char)z->acc);
        z->acc >>= 8;
        z->nacc -= 8;
    }
}

/* The image data of w x h indices from idx (rows stride apart), GIF's
** LZW of minimum code size mcs: the code size byte, the sub-blocks, the
** terminator. */
static void
lzw_encode(lzw_t *z, int mcs, const unsigned char *idx, int w, int h,
           size_t stride)
{
    unsigned clear = 1u << mcs, next = clear + 2, prefix = 0;
    int width = mcs + 1;
    unsigned char m = (unsigned char)mcs;
    cf__buf_append(z->out, &m, 1);
    z->block[0] = 0;
    z->acc = 0;
    z->nacc = 0;
    memset(z->dict, 0, DICT_SLOTS * sizeof *z->dict);
    put_code(z, clear, width);
    for (int y = 0; y < h; y++) {
        const unsigned char *row = idx + (size_t)y * stride;
        for (int x = 0; x < w; x++) {
            unsigned c = row[x];
            uint32_t key, s;
            if (x == 0 && y == 0) {
                prefix = c;
                continue;
            }
            key = (prefix << 8 | c) + 1;
            s = (key * 2654435761u >> 13) & (DICT_SLOTS - 1);
            while (z->dict[s] != 0 && z->dict[s] != key)
                s = (s + 1) & (DICT_SLOTS - 1);
            if (z->dict[s] == key) {
                prefix = z->code[s];
                continue;
            }
            put_code(z, prefix, width);
            if (next < 4096) {
                z->dict[s] = key;
                z->code[s] = (uint16_t)next++;
                if (next > (1u << width) && width < 12)
                    width++;
            } else {
                put_code(z, clear, width);
                memset(z->dict, 0, DICT_SLOTS * sizeof *z->dict);
                next = clear + 2;
                width = mcs + 1;
            }
            prefix = c;
        }
    }
    put_code(z, prefix, width);
    put_code(z, clear + 1, width);
    if (z->nacc > 0)
        put_byte(z, (unsigned char)z->acc);
    if (z->block[0] > 0)
        cf__buf_append(z->out, z->block, (size_t)z->block[0] + 1);
    cf__buf_append(z->out, "", 1);
}

/* ---- the file ------------------------------------------------------------ */

static void
put_u16(cf__buf_t *out, unsigned v)
{
    unsigned char b[2] = { (unsigned char)v, (unsigned char)(v >> 8) };
    cf__buf_append(out, b, 2);
}

/* Which frames are shown (keep[k]) and their delays (cs): see the head of
** this file.  The number of frames shown. */
static size_t
schedule(const gif_sink_t *g, bool *keep, long *delay)
{
    size_t n = g->base.frames, last = 0, shown = 1;
    long end = lround(100 * g->base.seconds), s_last = 0;
    keep[0] = true;
    for (size_t k = 1; k < n; k++) {
        long s = lround(100 * g->frame[k].start);
        keep[k] = s - s_last >= 2 && end - s >= 2;
        if (keep[k]) {
            delay[last] = s - s_last;
            last = k;
            s_last = s;
            shown++;
        }
    }
    delay[last] = end - s_last < 2 ? 2 : end - s_last;
    return shown;
}

/* A frame's pixels back from their deflated copy; 0 or -1. */
static int
inflate_frame(const kept_t *k, unsigned char *rgba, size_t size)
{
    z_stream z;
    int r;
    memset(&z, 0, sizeof z);
    z.zalloc = cf__png_zalloc;
    z.zfree = cf__png_zfree;
    if (inflateInit2(&z, -15) != Z_OK)
        return -1;
    z.next_in = k->z;
    z.avail_in = (uInt)k->n;
    z.next_out = rgba;
    z.avail_out = (uInt)size;
    r = inflate(&z, Z_FINISH);
    inflateEnd(&z);
    return r == Z_STREAM_END && z.avail_out == 0 ? 0 : -1;
}

/* The rectangle (x y w h) where cur differs from prev; 1 x 1 at the
** origin when nothing does. */
static void
changed_box(const unsigned char *cur, const unsigned char *prev, int w,
            int h, int box[4])
{
    int x0 = w, y0 = h, x1 = -1, y1 = -1;
    for (int y = 0; y < h; y++) {
        const unsigned char *a = cur + (size_t)y * (size_t)w;
        const unsigned char *b = prev + (size_t)y * (size_t)w;
        int l = 0, r = w - 1;
        if (memcmp(a, b, (size_t)w) == 0)
            continue;
        while (a[l] == b[l])
            l++;
        while (a[r] == b[r])
            r--;
        x0 = l < x0 ? l : x0;
        x1 = r > x1 ? r : x1;
        y0 = y < y0 ? y : y0;
        y1 = y;
    }
    if (x1 < 0) {
        x0 = y0 = x1 = y1 = 0;
    }
    box[0] = x0;
    box[1] = y0;
    box[2] = x1 - x0 + 1;
    box[3] = y1 - y0 + 1;
}

/* The logical screen, the palette, the loop. */
static void
write_head(const gif_sink_t *g, const uint32_t *pal, int ncol, int bits,
           cf__buf_t *out)
{
    unsigned char b[3];
    cf__buf_append(out, "GIF89a", 6);
    put_u16(out, (unsigned)g->base.width);
    put_u16(out, (unsigned)g->base.height);
    b[0] = (unsigned char)(0x80 | 7 << 4 | (bits - 1));   /* global table */
    b[1] = (unsigned char)(g->col.clear > 0 ? ncol : 0);      /* background */
    b[2] = 0;                                             /* aspect */
    cf__buf_append(out, b, 3);
    for (int i = 0; i < 1 << bits; i++) {
        uint32_t v = i < ncol ? pal[i] : 0;
        b[0] = (unsigned char)(v >> 16);
        b[1] = (unsigned char)(v >> 8);
        b[2] = (unsigned char)v;
        cf__buf_append(out, b, 3);
    }
    if (g->base.loop) {
        /* NETSCAPE2.0: loop count 0, forever */
        cf__buf_append(out, "\x21\xff\x0bNETSCAPE2.0\x03\x01\x00\x00\x00",
                       19);
    }
}

/* One frame: its graphic control (delay, disposal, transparency) and the
** box of idx as an image. */
static void
write_frame(lzw_t *z, const unsigned char *idx, int w, int box[4],
            long delay, int ncol, bool clear, int mcs)
{
    unsigned char b[10];
    cf__buf_t *out = z->out;
    cf__buf_append(out, "\x21\xf9\x04", 3);
    /* disposal 2 (to the background) for whole frames with transparent
    ** pixels; 1 (do not dispose) for the others */
    b[0] = (unsigned char)(clear ? 2 << 2 | 1 : 1 << 2);
    cf__buf_append(out, b, 1);
    put_u16(out, (unsigned)delay);
    b[0] = (unsigned char)(clear ? ncol : 0);
    b[1] = 0;
    cf__buf_append(out, b, 2);
    b[0] = 0x2c;
    cf__buf_append(out, b, 1);
    for (int i = 0; i < 4; i++)
        put_u16(out, (unsigned)box[i]);
    b[0] = 0;   /* no local table, not interlaced */
    cf__buf_append(out, b, 1);
    lzw_encode(z, mcs, idx + (size_t)box[1] * (size_t)w + (size_t)box[0],
               box[2], box[3], (size_t)w);
}

/* Every shown frame: indices, the changed box, LZW; 0 or -1. */
static int
write_frames(gif_sink_t *g, const uint32_t *pal, int ncol, int mcs,
             const bool *keep, const long *delay, cf__buf_t *out)
{
    int w = g->base.width, h = g->base.height, rc = -1;
    size_t npx = (size_t)w * (size_t)h;
    bool clear = g->col.clear > 0;
    unsigned char *rgba = cf_alloc_array(npx, 4);
    unsigned char *cur = cf_malloc(npx), *prev = cf_malloc(npx);
    cf__palette_map_t m;
    lzw_t z = { out, { 0 }, 0, 0, cf_calloc(DICT_SLOTS, sizeof(uint32_t)),
                cf_calloc(DICT_SLOTS, sizeof(uint16_t)) };
    bool first = true;
    if (cf__palette_map_init(&m, pal, ncol) != 0 || rgba == NULL
        || cur == NULL || prev == NULL || z.dict == NULL || z.code == NULL)
        goto done;
    for (size_t k = 0; k < g->base.frames; k++) {
        long d = delay[k], parts;
        if (!keep[k])
            continue;
        if (inflate_frame(&g->frame[k], rgba, 4 * npx) != 0)
            goto done;
        cf__palette_map(&m, rgba, npx, cur);
        /* a delay over 65535 cs: the frame repeated (unchanged boxes) */
        parts = (d + 65534) / 65535;
        for (long p = 0; p < parts; p++) {
            int box[4] = { 0, 0, w, h };
            long dp = d / parts + (p < d % parts);
            if (!first && !clear)
                changed_box(cur, prev, w, h, box);
            write_frame(&z, cur, w, box, dp, ncol, clear, mcs);
            memcpy(prev, cur, npx);
            first = false;
        }
    }
    rc = out->failed ? -1 : 0;
done:
    cf_free(rgba);
    cf_free(cur);
    cf_free(prev);
    cf__palette_map_fini(&m);
    cf_free(z.dict);
    cf_free(z.code);
    return rc;
}

static void
gif_free(cf__anim_sink_t *sink)
{
    gif_sink_t *g = (gif_sink_t *)sink;
    for (size_t k = 0; k < g->base.frames && k < g->cap; k++)
        cf_free(g->frame[k].z);
    cf_free(g->frame);
    cf__colours_fini(&g->col);
    cf_free(g->row);
    if (g->z_ready)
        deflateEnd(&g->z);
    cf_free(g);
}

static cf_status_t
gif_finish(cf__anim_sink_t *sink, cf__buf_t *out, cf_diag_t *diag)
{
    gif_sink_t *g = (gif_sink_t *)sink;
    size_t n = sink->frames, start = out->size;
    int was_failed = out->failed;
    uint32_t pal[256];
    bool *keep = cf_calloc(n, sizeof *keep);
    long *delay = cf_calloc(n, sizeof *delay);
    int ncol = -1, bits = 1, mcs, rc = -1;
    if (keep != NULL && delay != NULL)
        ncol = cf__colours_palette(&g->col, pal);
    if (ncol >= 0) {
        int total = ncol + (g->col.clear > 0);
        while (1 << bits < total)
            bits++;
        mcs = bits < 2 ? 2 : bits;
        schedule(g, keep, delay);
        write_head(g, pal, ncol, bits, out);
        rc = write_frames(g, pal, ncol, mcs, keep, delay, out);
        cf__buf_append(out, ";", 1);   /* the trailer */
    }
    cf_free(keep);
    cf_free(delay);
    gif_free(sink);
    if (rc != 0 || out->failed) {
        out->size = start;
        out->failed = was_failed;
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "GIF: out of memory encoding %zu frames", n);
    }
    return CF_STATUS_OK;
}

static const cf__anim_ops_t gif_ops = { gif_add, gif_finish, gif_free };

cf_status_t
cf__anim_gif_open(int width, int height, cf__anim_sink_t **sink,
                  cf_diag_t *diag)
{
    gif_sink_t *g = cf_calloc(1, sizeof *g);
    if (g == NULL)
        goto nomem;
    g->base.ops = &gif_ops;
    g->row = cf_alloc_array((size_t)width, 4);   /* RGBA; RGB from w on */
    g->z.zalloc = cf__png_zalloc;
    g->z.zfree = cf__png_zfree;
    if (cf__colours_init(&g->col) != 0 || g->row == NULL
        || deflateInit2(&g->z, 1, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY)
               != Z_OK)
        goto nomem;
    g->z_ready = true;
    *sink = &g->base;
    return CF_STATUS_OK;
nomem:
    if (g != NULL)
        gif_free(&g->base);
    return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                       "GIF: out of memory for frames of %d x %d pixels",
                       width, height);
}
