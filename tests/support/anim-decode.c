/*
** GIF (GIF89a specification, W3C/CompuServe 1990) and APNG (the APNG
** specification of Mozilla, on PNG, ISO/IEC 15948) decoded for the tests:
** see anim-decode.h.  Plain malloc; every check fails with a message.
*/
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <zlib.h>

#include "anim-decode.h"

static int
fail(tu_anim_t *a, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(a->error, sizeof a->error, fmt, ap);
    va_end(ap);
    tu_anim_free(a);
    return -1;
}

void
tu_anim_free(tu_anim_t *a)
{
    for (unsigned k = 0; a->rgba != NULL && k < a->frames; k++)
        free(a->rgba[k]);
    free(a->rgba);
    free(a->num);
    free(a->den);
    free(a->box);
    a->rgba = NULL;
    a->num = a->den = NULL;
    a->box = NULL;
    a->frames = 0;
}

/* A new frame: the canvas copied, its time and box recorded; 0 or -1. */
static int
push_frame(tu_anim_t *a, const unsigned char *canvas, unsigned num,
           unsigned den, const int box[4])
{
    size_t n = a->frames + 1, px = (size_t)a->width * (size_t)a->height * 4;
    unsigned char **r = realloc(a->rgba, n * sizeof *r);
    unsigned *nu, *de;
    int (*b)[4];
    if (r == NULL)
        return -1;
    a->rgba = r;
    nu = realloc(a->num, n * sizeof *nu);
    if (nu == NULL)
        return -1;
    a->num = nu;
    de = realloc(a->den, n * sizeof *de);
    if (de == NULL)
        return -1;
    a->den = de;
    b = realloc(a->box, n * sizeof *b);
    if (b == NULL)
        return -1;
    a->box = b;
    r[n - 1] = malloc(px);
    if (r[n - 1] == NULL)
        return -1;
    memcpy(r[n - 1], canvas, px);
    nu[n - 1] = num;
    de[n - 1] = den;
    memcpy(b[n - 1], box, sizeof b[n - 1]);
    a->frames = (unsigned)n;
    return 0;
}

/* ---- GIF ---------------------------------------------------------------- */

/* The data sub-blocks from *pos on, concatenated; *pos past the
** terminator.  NULL when they run past the end. */
static unsigned char *
sub_blocks(const unsigned char *d, size_t size, size_t *pos, size_t *n)
{
    unsigned char *out = NULL;
    *n = 0;
    for (;;) {
        size_t len;
        unsigned char *o;
        if (*pos >= size)
            break;
        len = d[(*pos)++];
        if (len == 0)
            return out != NULL ? out : malloc(1);
        if (*pos + len > size)
            break;
        o = realloc(out, *n + len);
        if (o == NULL)
            break;
        out = o;
        memcpy(out + *n, d + *pos, len);
        *n += len;
        *pos += len;
    }
    free(out);
    return NULL;
}

/* GIF's LZW: n indices out of the code stream; 0, or -1 (bad codes). */
static int
lzw_decode(const unsigned char *s, size_t len, int mcs, unsigned char *out,
           size_t n)
{
    uint16_t prefix[4096];
    unsigned char suffix[4096], stack[4097];
    unsigned clear = 1u << mcs, next = clear + 2, prev = 4096, first = 0;
    int width = mcs + 1, bits = 0;
    uint32_t acc = 0;
    size_t i = 0, o = 0;
    for (;;) {
        unsigned code, c, sp = 0;
        while (bits < width) {
            if (i >= len)
                return -1;   /* no end-of-information code */
            acc |= (uint32_t)s[i++] << bits;
            bits += 8;
        }
        code = acc & ((1u << width) - 1);
        acc >>= width;
        bits -= width;
        if (code == clear) {
            width = mcs + 1;
            next = clear + 2;
            prev = 4096;
            continue;
        }
        if (code == clear + 1)
            return o == n ? 0 : -1;
        if (prev == 4096) {   /* the first code after a clear */
            if (code >= clear || o >= n)
                return -1;
            out[o++] = (unsigned char)code;
            prev = first = code;
            continue;
        }
        if (code > next || (code == next && next >= 4096))
            return -1;
        /* the string of code (of prev + its first byte when new) */
        c = code == next ? prev : code;
        if (code == next)
            stack[sp++] = (unsigned char)first;
        while (c >= clear) {
            stack[sp++] = suffix[c];
            c = prefix[c];
        }
        stack[sp++] = (unsigned char)c;
        first = c;
        if (o + sp > n)
            return -1;
        while (sp > 0)
            out[o++] = stack[--sp];
        if (next < 4096) {
            prefix[next] = (uint16_t)prev;
            suffix[next] = (unsigned char)first;
            next++;
            if (next == (1u << width) && width < 12)
                width++;
        }
        prev = code;
    }
}

int
tu_gif_decode(const unsigned char *d, size_t size, tu_anim_t *a)
{
    unsigned char *canvas = NULL, *saved = NULL, *idx = NULL, pal[256][3];
    int gct = 0, dispose = 0, transparent = -1, rc = -1, box[4] = { 0 };
    unsigned delay = 0;
    size_t pos = 13, px;
    bool drawn = false;

    memset(a, 0, sizeof *a);
    a->plays = 1;
    if (size < 13 || (memcmp(d, "GIF89a", 6) != 0
                      && memcmp(d, "GIF87a", 6) != 0))
        return fail(a, "not a GIF");
    a->width = d[6] | d[7] << 8;
    a->height = d[8] | d[9] << 8;
    px = (size_t)a->width * (size_t)a->height;
    if (d[10] & 0x80) {
        gct = 2 << (d[10] & 7);
        if (pos + 3 * (size_t)gct > size)
            return fail(a, "the global palette runs past the end");
        memcpy(a->palette, d + pos, 3 * (size_t)gct);
        pos += 3 * (size_t)gct;
    }
    a->colours = gct;
    canvas = calloc(px, 4);
    saved = malloc(px * 4);
    idx = malloc(px);
    if (canvas == NULL || saved == NULL || idx == NULL)
        goto done;
    for (;;) {
        int b = pos < size ? d[pos++] : -1;
        if (b == 0x3b) {
            rc = 0;
            break;
        } else if (b == 0x21 && pos < size) {
            int label = d[pos++];
            size_t n;
            unsigned char *s = sub_blocks(d, size, &pos, &n);
            if (s == NULL) {
                snprintf(a->error, sizeof a->error, "bad extension 0x%02x",
                         label);
                goto done;
            }
            if (label == 0xf9 && n >= 4) {
                dispose = s[0] >> 2 & 7;
                transparent = s[0] & 1 ? s[3] : -1;
                delay = (unsigned)(s[1] | s[2] << 8);
            } else if (label == 0xff && n >= 14
                       && memcmp(s, "NETSCAPE2.0", 11) == 0 && s[11] == 1) {
                unsigned loops = (unsigned)(s[12] | s[13] << 8);
                a->plays = loops == 0 ? 0 : loops + 1;
            }
            free(s);
        } else if (b == 0x2c && pos + 9 <= size) {
            const unsigned char *id = d + pos;
            int mcs, ncol = gct;
            const unsigned char (*p)[3] = (const unsigned char (*)[3])a->palette;
            size_t n;
            unsigned char *s;
            box[0] = id[0] | id[1] << 8;
            box[1] = id[2] | id[3] << 8;
            box[2] = id[4] | id[5] << 8;
            box[3] = id[6] | id[7] << 8;
            pos += 9;
            if (id[8] & 0x40) {
                snprintf(a->error, sizeof a->error, "interlaced frame");
                goto done;
            }
            if (id[8] & 0x80) {   /* a local palette */
                ncol = 2 << (id[8] & 7);
                if (pos + 3 * (size_t)ncol > size)
                    goto done;
                memcpy(pal, d + pos, 3 * (size_t)ncol);
                p = (const unsigned char (*)[3])pal;
                pos += 3 * (size_t)ncol;
            }
            if (box[0] + box[2] > a->width || box[1] + box[3] > a->height
                || box[2] < 1 || box[3] < 1 || pos >= size) {
                snprintf(a->error, sizeof a->error,
                         "frame %u: box %d %d %d %d outside the screen",
                         a->frames, box[0], box[1], box[2], box[3]);
                goto done;
            }
            mcs = d[pos++];
            s = sub_blocks(d, size, &pos, &n);
            if (s == NULL || mcs < 2 || mcs > 8
                || lzw_decode(s, n, mcs, idx, (size_t)box[2] * (size_t)box[3])
                       != 0) {
                free(s);
                snprintf(a->error, sizeof a->error,
                         "frame %u: bad LZW data", a->frames);
                goto done;
            }
            free(s);
            memcpy(saved, canvas, px * 4);
            for (int y = 0; y < box[3]; y++) {
                for (int x = 0; x < box[2]; x++) {
                    int v = idx[(size_t)y * (size_t)box[2] + (size_t)x];
                    unsigned char *c = canvas
                        + 4 * ((size_t)(box[1] + y) * (size_t)a->width
                               + (size_t)(box[0] + x));
                    if (v == transparent)
                        continue;
                    if (v >= ncol) {
                        snprintf(a->error, sizeof a->error,
                                 "frame %u: index %d past the palette",
                                 a->frames, v);
                        goto done;
                    }
                    memcpy(c, p[v], 3);
                    c[3] = 255;
                }
            }
            if (push_frame(a, canvas, delay, 100, box) != 0)
                goto done;
            drawn = true;
            if (dispose == 2) {
                for (int y = 0; y < box[3]; y++)
                    memset(canvas + 4 * ((size_t)(box[1] + y)
                                             * (size_t)a->width
                                         + (size_t)box[0]),
                           0, 4 * (size_t)box[2]);
            } else if (dispose == 3) {
                memcpy(canvas, saved, px * 4);
            }
            dispose = 0;
            transparent = -1;
            delay = 0;
        } else {
            snprintf(a->error, sizeof a->error,
                     "unexpected byte at %zu (no trailer?)", pos - 1);
            goto done;
        }
    }
done:
    free(canvas);
    free(saved);
    free(idx);
    if (rc != 0 || !drawn) {
        char msg[sizeof a->error];
        snprintf(msg, sizeof msg, "%s",
                 a->error[0] ? a->error : "out of memory or no frames");
        return fail(a, "GIF: %s", msg);
    }
    return 0;
}

/* ---- APNG --------------------------------------------------------------- */

static uint32_t
be32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8
         | p[3];
}

static int
paeth(int a, int b, int c)
{
    int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

/* The zlib data of a w x h frame of bpp bytes per pixel inflated and
** unfiltered into pix (w * h * bpp); 0 or -1. */
static int
unfilter(const unsigned char *z, size_t zn, int w, int h, int bpp,
         unsigned char *pix)
{
    size_t row = (size_t)w * (size_t)bpp, n = (row + 1) * (size_t)h;
    uLongf got = (uLongf)n;
    unsigned char *raw = malloc(n);
    if (raw == NULL || uncompress(raw, &got, z, (uLong)zn) != Z_OK
        || got != n) {
        free(raw);
        return -1;
    }
    for (int y = 0; y < h; y++) {
        const unsigned char *f = raw + (size_t)y * (row + 1);
        unsigned char *o = pix + (size_t)y * row;
        const unsigned char *up = y > 0 ? o - row : NULL;
        for (size_t i = 0; i < row; i++) {
            int l = i >= (size_t)bpp ? o[i - (size_t)bpp] : 0;
            int u = up != NULL ? up[i] : 0;
            int ul = up != NULL && i >= (size_t)bpp ? up[i - (size_t)bpp] : 0;
            int v = f[1 + i];
            switch (f[0]) {
            case 0: break;
            case 1: v += l; break;
            case 2: v += u; break;
            case 3: v += (l + u) / 2; break;
            case 4: v += paeth(l, u, ul); break;
            default:
                free(raw);
                return -1;
            }
            o[i] = (unsigned char)v;
        }
    }
    free(raw);
    return 0;
}

/* A frame being read: its fcTL and its compressed data. */
typedef struct apng_frame {
    int box[4];
    unsigned num, den, dispose, blend;
    unsigned char *z;
    size_t zn;
} apng_frame_t;

static int
add_data(apng_frame_t *f, const unsigned char *p, size_t n)
{
    unsigned char *z = realloc(f->z, f->zn + n + 1);
    if (z == NULL)
        return -1;
    memcpy(z + f->zn, p, n);
    f->z = z;
    f->zn += n;
    return 0;
}

/* Frame f drawn on the canvas (blend SOURCE or OVER), shown, disposed. */
static int
apng_draw(tu_anim_t *a, apng_frame_t *f, int bpp, unsigned char *canvas,
          unsigned char *saved)
{
    int *b = f->box;
    size_t px = (size_t)a->width * (size_t)a->height * 4;
    unsigned char *pix = malloc((size_t)b[2] * (size_t)b[3] * (size_t)bpp);
    if (pix == NULL || unfilter(f->z, f->zn, b[2], b[3], bpp, pix) != 0) {
        free(pix);
        return -1;
    }
    memcpy(saved, canvas, px);
    for (int y = 0; y < b[3]; y++) {
        for (int x = 0; x < b[2]; x++) {
            const unsigned char *s = pix + ((size_t)y * (size_t)b[2]
                                            + (size_t)x) * (size_t)bpp;
            unsigned char *c = canvas + 4 * ((size_t)(b[1] + y)
                                                 * (size_t)a->width
                                             + (size_t)(b[0] + x));
            unsigned sa = bpp == 4 ? s[3] : 255;
            if (f->blend == 1 && sa < 255) {   /* OVER, in [0, 1] */
                double as = sa / 255.0, ad = c[3] / 255.0;
                double ao = as + ad * (1 - as);
                for (int i = 0; i < 3; i++)
                    c[i] = ao > 0 ? (unsigned char)((s[i] * as + c[i] * ad
                                                     * (1 - as)) / ao + 0.5)
                                  : 0;
                c[3] = (unsigned char)(ao * 255 + 0.5);
            } else {
                memcpy(c, s, 3);
                c[3] = (unsigned char)sa;
            }
        }
    }
    free(pix);
    if (push_frame(a, canvas, f->num, f->den == 0 ? 100 : f->den, b) != 0)
        return -1;
    if (f->dispose == 1) {
        for (int y = 0; y < b[3]; y++)
            memset(canvas + 4 * ((size_t)(b[1] + y) * (size_t)a->width
                                 + (size_t)b[0]),
                   0, 4 * (size_t)b[2]);
    } else if (f->dispose == 2) {
        memcpy(canvas, saved, px);
    }
    return 0;
}

int
tu_apng_decode(const unsigned char *d, size_t size, tu_anim_t *a)
{
    static const unsigned char sig[8] = { 0x89, 'P', 'N', 'G', '\r', '\n',
                                          0x1a, '\n' };
    unsigned char *canvas = NULL, *saved = NULL;
    apng_frame_t f = { { 0 }, 0, 0, 0, 0, NULL, 0 };
    unsigned declared = 0, seq = 0, bpp = 0;
    bool in_frame = false, ended = false;
    size_t pos = 8;

    memset(a, 0, sizeof *a);
    if (size < 8 || memcmp(d, sig, 8) != 0)
        return fail(a, "APNG: not a PNG");
    while (!ended) {
        uint32_t n;
        const unsigned char *t, *c;
        if (pos + 12 > size)
            goto bad_end;
        n = be32(d + pos);
        t = d + pos + 4;
        c = t + 4;
        if (n > size - pos - 12)
            goto bad_end;
        if (be32(c + n) != (uint32_t)crc32(crc32(0, Z_NULL, 0), t, n + 4)) {
            snprintf(a->error, sizeof a->error, "APNG: bad CRC of %.4s",
                     (const char *)t);
            goto bad;
        }
        pos += 12 + (size_t)n;
        if (memcmp(t, "IHDR", 4) == 0 && n == 13) {
            a->width = (int)be32(c);
            a->height = (int)be32(c + 4);
            if (c[8] != 8 || (c[9] != 2 && c[9] != 6) || c[12] != 0
                || a->width < 1 || a->height < 1) {
                snprintf(a->error, sizeof a->error,
                         "APNG: not 8-bit RGB or RGBA, or interlaced");
                goto bad;
            }
            bpp = c[9] == 6 ? 4 : 3;
            a->colours = (int)bpp;
            canvas = calloc((size_t)a->width * (size_t)a->height, 4);
            saved = malloc((size_t)a->width * (size_t)a->height * 4);
            if (canvas == NULL || saved == NULL)
                goto bad;
        } else if (memcmp(t, "acTL", 4) == 0 && n == 8) {
            declared = be32(c);
            a->plays = be32(c + 4);
        } else if (memcmp(t, "fcTL", 4) == 0 && n == 26 && bpp > 0) {
            if (be32(c) != seq++) {
                snprintf(a->error, sizeof a->error,
                         "APNG: fcTL out of sequence");
                goto bad;
            }
            if (in_frame && apng_draw(a, &f, (int)bpp, canvas, saved) != 0)
                goto bad_frame;
            f.zn = 0;
            f.box[2] = (int)be32(c + 4);
            f.box[3] = (int)be32(c + 8);
            f.box[0] = (int)be32(c + 12);
            f.box[1] = (int)be32(c + 16);
            f.num = (unsigned)(c[20] << 8 | c[21]);
            f.den = (unsigned)(c[22] << 8 | c[23]);
            f.dispose = c[24];
            f.blend = c[25];
            if (f.box[2] < 1 || f.box[3] < 1
                || f.box[0] + f.box[2] > a->width
                || f.box[1] + f.box[3] > a->height) {
                snprintf(a->error, sizeof a->error,
                         "APNG: frame %u outside the image", a->frames);
                goto bad;
            }
            in_frame = true;
        } else if (memcmp(t, "IDAT", 4) == 0) {
            /* frame 0's data, when an fcTL came before; else the default
            ** image alone, not part of the animation */
            if (in_frame && a->frames == 0 && add_data(&f, c, n) != 0)
                goto bad;
        } else if (memcmp(t, "fdAT", 4) == 0 && n >= 4 && in_frame) {
            if (be32(c) != seq++) {
                snprintf(a->error, sizeof a->error,
                         "APNG: fdAT out of sequence");
                goto bad;
            }
            if (add_data(&f, c + 4, n - 4) != 0)
                goto bad;
        } else if (memcmp(t, "IEND", 4) == 0) {
            ended = true;
        }
    }
    if (in_frame && apng_draw(a, &f, (int)bpp, canvas, saved) != 0)
        goto bad_frame;
    if (a->frames != declared || a->frames == 0) {
        snprintf(a->error, sizeof a->error,
                 "APNG: %u frames, acTL says %u", a->frames, declared);
        goto bad;
    }
    free(f.z);
    free(canvas);
    free(saved);
    return 0;
bad_frame:
    snprintf(a->error, sizeof a->error, "APNG: frame %u: bad image data",
             a->frames);
    goto bad;
bad_end:
    snprintf(a->error, sizeof a->error, "APNG: a chunk runs past the end");
bad:
    free(f.z);
    free(canvas);
    free(saved);
    {
        char msg[sizeof a->error];
        snprintf(msg, sizeof msg, "%s",
                 a->error[0] ? a->error : "APNG: out of memory");
        return fail(a, "%s", msg);
    }
}
