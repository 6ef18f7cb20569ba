/*
** PNG writer: a cairo image surface to PNG bytes through zlib.
**
** cairo_surface_write_to_png goes through libpng at zlib's default level
** with adaptive filtering (five trial filters per row); on the figure set
** that took about 13 ms per 150-dpi image, most of the time of a render.
** Figures are flat colours and thin anti-aliased lines, for which filter
** None (type 0 on every row) and zlib level 3 give files about as small
** (6 % smaller over the figure set) in a fifth of the time.
**
** The pixels are exactly cairo's: an ARGB32 surface is written as 8-bit
** RGBA with each channel un-premultiplied as (c * 255 + a / 2) / a (alpha
** 0 gives 0 0 0 0), or as 8-bit RGB when every pixel is opaque; RGB24 is
** always RGB.  File layout (PNG specification, ISO/IEC 15948): signature,
** IHDR, pHYs (the resolution, when given), IDAT chunks of at most 64 KiB,
** IEND; each chunk is length, type, data, CRC-32 of type and data.
*/
#include <math.h>
#include <stdint.h>
#include <string.h>

#include <zlib.h>

#include "png-private.h"

#define IDAT_MAX 65536   /* bytes of compressed data per IDAT chunk */
#define ZLEVEL 3
/* zlib's hash table at 2^(7+7) entries instead of 2^(8+7): on the figure
** set 8 % faster, the files as small (level 1 is 5 % faster but 2.4 %
** larger; libdeflate, tried, is no faster on these images) */
#define ZMEMLEVEL 7

void
cf__png_put_u32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

int
cf__png_chunk(cf__buf_t *out, const char *type, const unsigned char *data,
              size_t n)
{
    unsigned char head[8], tail[4];
    uLong crc = crc32(0L, Z_NULL, 0);
    cf__png_put_u32(head, (uint32_t)n);
    memcpy(head + 4, type, 4);
    crc = crc32(crc, head + 4, 4);
    if (n > 0)
        crc = crc32(crc, data, (uInt)n);
    cf__png_put_u32(tail, (uint32_t)crc);
    if (cf__buf_append(out, head, sizeof head) != 0
        || cf__buf_append(out, data, n) != 0
        || cf__buf_append(out, tail, sizeof tail) != 0)
        return -1;
    return 0;
}

bool
cf__png_opaque(const unsigned char *data, int width, int height, int stride)
{
    int x, y;
    for (y = 0; y < height; y++) {
        const unsigned char *row = data + (size_t)y * (size_t)stride;
        for (x = 0; x < width; x++) {
            uint32_t p;
            memcpy(&p, row + 4 * (size_t)x, 4);
            if ((p >> 24) != 0xff)
                return false;
        }
    }
    return true;
}

void
cf__png_row_rgba(const unsigned char *src, int width, unsigned char *dst)
{
    int x;
    for (x = 0; x < width; x++, dst += 4) {
        uint32_t p, a;
        memcpy(&p, src + 4 * (size_t)x, 4);
        a = p >> 24;
        if (a == 0xff) {
            /* (c * 255 + 127) / 255 == c: the general formula's value */
            dst[0] = (unsigned char)(p >> 16);
            dst[1] = (unsigned char)(p >> 8);
            dst[2] = (unsigned char)p;
            dst[3] = 0xff;
        } else if (a == 0) {
            dst[0] = dst[1] = dst[2] = dst[3] = 0;
        } else {
            dst[0] = (unsigned char)((((p >> 16) & 0xff) * 255 + a / 2) / a);
            dst[1] = (unsigned char)((((p >> 8) & 0xff) * 255 + a / 2) / a);
            dst[2] = (unsigned char)(((p & 0xff) * 255 + a / 2) / a);
            dst[3] = (unsigned char)a;
        }
    }
}

void
cf__png_row_rgb(const unsigned char *src, int width, unsigned char *dst)
{
    int x;
    for (x = 0; x < width; x++, dst += 3) {
        uint32_t p;
        memcpy(&p, src + 4 * (size_t)x, 4);
        dst[0] = (unsigned char)(p >> 16);
        dst[1] = (unsigned char)(p >> 8);
        dst[2] = (unsigned char)p;
    }
}

voidpf
cf__png_zalloc(voidpf opaque, uInt items, uInt size)
{
    (void)opaque;
    return cf_alloc_array(items, size);
}

void
cf__png_zfree(voidpf opaque, voidpf ptr)
{
    (void)opaque;
    cf_free(ptr);
}

/* One chunk of compressed data: IDAT, or fdAT with the next sequence
** number in the 4 bytes reserved before it. */
static int
data_chunk(cf__buf_t *out, unsigned char *zbuf, size_t n, unsigned *seq)
{
    if (seq == NULL)
        return cf__png_chunk(out, "IDAT", zbuf + 4, n);
    cf__png_put_u32(zbuf, (uint32_t)(*seq)++);
    return cf__png_chunk(out, "fdAT", zbuf, n + 4);
}

cf_status_t
cf__png_rows(const unsigned char *data, int width, int height, int stride,
             bool rgba, unsigned *seq, cf__buf_t *out, cf_diag_t *diag)
{
    size_t rowbytes = (size_t)width * (rgba ? 4 : 3);
    unsigned char *line, *zbuf;
    z_stream z;
    int y, failed = 0;

    memset(&z, 0, sizeof z);
    z.zalloc = cf__png_zalloc;
    z.zfree = cf__png_zfree;
    line = cf_malloc(rowbytes + 1);
    zbuf = cf_malloc(IDAT_MAX + 4);
    if (line == NULL || zbuf == NULL
        || deflateInit2(&z, ZLEVEL, Z_DEFLATED, 15, ZMEMLEVEL,
                        Z_DEFAULT_STRATEGY) != Z_OK) {
        cf_free(line);
        cf_free(zbuf);
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory compressing a PNG of %d x %d "
                           "pixels", width, height);
    }
    z.next_out = zbuf + 4;
    z.avail_out = IDAT_MAX;
    line[0] = 0;   /* filter type None */
    for (y = 0; y < height && !failed; y++) {
        const unsigned char *src = data + (size_t)y * (size_t)stride;
        int flush = y == height - 1 ? Z_FINISH : Z_NO_FLUSH;
        if (rgba)
            cf__png_row_rgba(src, width, line + 1);
        else
            cf__png_row_rgb(src, width, line + 1);
        z.next_in = line;
        z.avail_in = (uInt)(rowbytes + 1);
        for (;;) {
            int r = deflate(&z, flush);
            if (r != Z_OK && r != Z_STREAM_END) {
                failed = 1;
                break;
            }
            if (z.avail_out == 0) {
                if (data_chunk(out, zbuf, IDAT_MAX, seq) != 0) {
                    failed = 1;
                    break;
                }
                z.next_out = zbuf + 4;
                z.avail_out = IDAT_MAX;
                if (r != Z_STREAM_END)
                    continue;
            }
            if (flush == Z_FINISH ? r == Z_STREAM_END : z.avail_in == 0)
                break;
        }
    }
    if (!failed && z.avail_out < IDAT_MAX
        && data_chunk(out, zbuf, IDAT_MAX - z.avail_out, seq) != 0)
        failed = 1;
    deflateEnd(&z);
    cf_free(line);
    cf_free(zbuf);
    if (failed)
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory writing a PNG of %d x %d pixels",
                           width, height);
    return CF_STATUS_OK;
}

int
cf__png_head(cf__buf_t *out, int width, int height, bool rgba)
{
    static const unsigned char signature[8] = {
        0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'
    };
    unsigned char ihdr[13];
    cf__png_put_u32(ihdr, (uint32_t)width);
    cf__png_put_u32(ihdr + 4, (uint32_t)height);
    ihdr[8] = 8;                /* bits per channel */
    ihdr[9] = rgba ? 6 : 2;     /* colour type: RGBA or RGB */
    ihdr[10] = 0;               /* deflate */
    ihdr[11] = 0;               /* adaptive filtering (per-row type) */
    ihdr[12] = 0;               /* not interlaced */
    if (cf__buf_append(out, signature, sizeof signature) != 0
        || cf__png_chunk(out, "IHDR", ihdr, sizeof ihdr) != 0)
        return -1;
    return 0;
}

cf_status_t
cf__png_encode(cairo_surface_t *image, double dpi, cf__buf_t *out,
               cf_diag_t *diag)
{
    unsigned char phys[9];
    const unsigned char *data;
    cairo_format_t format;
    int width, height, stride;
    bool rgba;
    cf_status_t st;

    if (image == NULL || out == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "PNG: image or output is NULL");
    if (cairo_surface_status(image) != CAIRO_STATUS_SUCCESS
        || cairo_surface_get_type(image) != CAIRO_SURFACE_TYPE_IMAGE)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "PNG: not a valid cairo image surface");
    cairo_surface_flush(image);
    format = cairo_image_surface_get_format(image);
    width = cairo_image_surface_get_width(image);
    height = cairo_image_surface_get_height(image);
    stride = cairo_image_surface_get_stride(image);
    data = cairo_image_surface_get_data(image);
    if (format != CAIRO_FORMAT_ARGB32 && format != CAIRO_FORMAT_RGB24)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "PNG: image format %d is not ARGB32 or RGB24",
                           (int)format);
    if (data == NULL || width < 1 || height < 1)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "PNG: image of %d x %d pixels has no data", width,
                           height);
    if (!isfinite(dpi))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "PNG: resolution %g dpi is not finite", dpi);
    rgba = format == CAIRO_FORMAT_ARGB32
        && !cf__png_opaque(data, width, height, stride);

    if (cf__png_head(out, width, height, rgba) != 0)
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory writing a PNG header");
    if (dpi > 0) {
        /* pixels per metre, the same along x and y; unit 1 = metre */
        double ppm = floor(dpi / 0.0254 + 0.5);
        uint32_t v = ppm > 2147483647.0 ? 2147483647u : (uint32_t)ppm;
        cf__png_put_u32(phys, v);
        cf__png_put_u32(phys + 4, v);
        phys[8] = 1;
        if (cf__png_chunk(out, "pHYs", phys, sizeof phys) != 0)
            return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                               "out of memory writing a PNG header");
    }
    st = cf__png_rows(data, width, height, stride, rgba, NULL, out, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (cf__png_chunk(out, "IEND", NULL, 0) != 0)
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory writing a PNG trailer");
    return CF_STATUS_OK;
}
