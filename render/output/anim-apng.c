/*
** The APNG (animated PNG) of a sweep's frames, with the PNG writer's
** pieces (png.c, png-private.h): the first frame is the IDAT image (what a
** viewer without APNG shows), each later frame the rectangle of pixels
** that changed, drawn in place of what was there (dispose_op NONE,
** blend_op SOURCE, so that transparent pixels replace too).
**
** Frames are encoded as they come (the last one kept to compare with) into
** a body that finish puts behind the signature, IHDR and acTL (which
** holds the number of frames).  Colour type: RGB when the first frame is
** opaque, RGBA otherwise, for every frame: a sweep draws one background
** on every frame, so a translucent frame after an opaque first one is an
** error, not a guess.
**
** Times: fcTL's delay is a fraction num/den of 16-bit integers.  Frame k
** is given the fraction nearest (continued fractions) to the time from the
** end of the frames before it, as written, to the end of frame k, so the
** delays of frames of 1/30 s are exactly 1/30 and any rounding does not
** add up over the frames.
*/
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "anim-private.h"
#include "png-private.h"

typedef struct apng_sink {
    cf__anim_sink_t base;
    cf__buf_t body;             /* fcTL, IDAT, fcTL, fdAT, ... */
    unsigned seq;               /* the next sequence number */
    bool rgba;
    uint32_t *prev;             /* the last frame, ARGB32, opaque alpha
                                   forced for RGB24 */
    double written;             /* the sum of the delays written */
} apng_sink_t;

/* The fraction p/q (both in [1, 65535]) nearest to x > 0 among the
** convergents of its continued fraction. */
static void
fraction(double x, unsigned *num, unsigned *den)
{
    double p0 = 1, q0 = 0, p1 = floor(x), q1 = 1, r = x - floor(x);
    unsigned bp = 0, bq = 1;
    if (p1 >= 1 && p1 <= 65535) {
        bp = (unsigned)p1;
        bq = 1;
    }
    for (int i = 0; i < 40 && fabs(x - p1 / q1) > 1e-12 * x && r > 1e-15;
         i++) {
        double a, p2, q2;
        r = 1 / r;
        a = floor(r);
        r -= a;
        p2 = a * p1 + p0;
        q2 = a * q1 + q0;
        if (p2 > 65535 || q2 > 65535)
            break;
        p0 = p1;
        q0 = q1;
        p1 = p2;
        q1 = q2;
        if (p1 >= 1) {
            bp = (unsigned)p1;
            bq = (unsigned)q1;
        }
    }
    if (bp == 0) {   /* x below 1/65535 s */
        bp = 1;
        bq = 65535;
    }
    *num = bp;
    *den = bq;
}

/* The box (x y w h) where the frame differs from prev; 1 x 1 at the
** origin when nothing does.  prev updated to the frame. */
static void
changed_box(apng_sink_t *a, const cf__anim_frame_t *f, int box[4])
{
    int w = a->base.width, h = a->base.height;
    int x0 = w, y0 = h, x1 = -1, y1 = -1;
    uint32_t force = f->alpha ? 0 : 0xff000000u;
    for (int y = 0; y < h; y++) {
        const unsigned char *src = f->data + (size_t)y * (size_t)f->stride;
        uint32_t *p = a->prev + (size_t)y * (size_t)w;
        for (int x = 0; x < w; x++) {
            uint32_t v;
            memcpy(&v, src + 4 * (size_t)x, 4);
            v |= force;
            if (v != p[x]) {
                p[x] = v;
                x0 = x < x0 ? x : x0;
                x1 = x > x1 ? x : x1;
                y0 = y < y0 ? y : y0;
                y1 = y;
            }
        }
    }
    if (x1 < 0)
        x0 = y0 = x1 = y1 = 0;
    box[0] = x0;
    box[1] = y0;
    box[2] = x1 - x0 + 1;
    box[3] = y1 - y0 + 1;
}

/* fcTL: the frame's box, delay, dispose NONE, blend SOURCE. */
static int
put_fctl(apng_sink_t *a, const int box[4], unsigned num, unsigned den)
{
    unsigned char c[26];
    cf__png_put_u32(c, a->seq++);
    cf__png_put_u32(c + 4, (uint32_t)box[2]);
    cf__png_put_u32(c + 8, (uint32_t)box[3]);
    cf__png_put_u32(c + 12, (uint32_t)box[0]);
    cf__png_put_u32(c + 16, (uint32_t)box[1]);
    c[20] = (unsigned char)(num >> 8);
    c[21] = (unsigned char)num;
    c[22] = (unsigned char)(den >> 8);
    c[23] = (unsigned char)den;
    c[24] = 0;   /* APNG_DISPOSE_OP_NONE */
    c[25] = 0;   /* APNG_BLEND_OP_SOURCE */
    return cf__png_chunk(&a->body, "fcTL", c, sizeof c);
}

static cf_status_t
apng_add(cf__anim_sink_t *sink, const cf__anim_frame_t *f, cf_diag_t *diag)
{
    apng_sink_t *a = (apng_sink_t *)sink;
    int w = sink->width, h = sink->height, box[4] = { 0, 0, w, h };
    bool opaque = !f->alpha || cf__png_opaque(f->data, w, h, f->stride);
    unsigned num, den;
    size_t start = a->body.size;
    cf_status_t st;

    if (f->index == 0)
        a->rgba = !opaque;
    else if (!opaque && !a->rgba)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, (long)f->index,
                           "APNG frame %u has translucent pixels, frame 0 "
                           "none: the frames of an animation share their "
                           "background", f->index);
    changed_box(a, f, box);
    if (f->index == 0) {
        box[0] = box[1] = 0;
        box[2] = w;
        box[3] = h;
    }
    fraction(f->start + f->seconds - a->written, &num, &den);
    if (put_fctl(a, box, num, den) != 0)
        goto nomem;
    st = cf__png_rows(f->data + (size_t)box[1] * (size_t)f->stride
                          + 4 * (size_t)box[0],
                      box[2], box[3], f->stride, a->rgba,
                      f->index == 0 ? NULL : &a->seq, &a->body, diag);
    if (st != CF_STATUS_OK) {
        a->body.size = start;
        return st;
    }
    a->written += (double)num / den;
    return CF_STATUS_OK;
nomem:
    a->body.size = start;
    return cf_diag_set(diag, CF_STATUS_NO_MEMORY, (long)f->index,
                       "APNG frame %u: out of memory", f->index);
}

static void
apng_free(cf__anim_sink_t *sink)
{
    apng_sink_t *a = (apng_sink_t *)sink;
    cf__buf_free(&a->body);
    cf_free(a->prev);
    cf_free(a);
}

static cf_status_t
apng_finish(cf__anim_sink_t *sink, cf__buf_t *out, cf_diag_t *diag)
{
    apng_sink_t *a = (apng_sink_t *)sink;
    size_t start = out->size;
    int was_failed = out->failed;
    unsigned char actl[8];
    unsigned n = sink->frames;
    cf__png_put_u32(actl, n);
    cf__png_put_u32(actl + 4, sink->loop ? 0 : 1);   /* num_plays */
    if (cf__png_head(out, sink->width, sink->height, a->rgba) != 0
        || cf__png_chunk(out, "acTL", actl, sizeof actl) != 0
        || cf__buf_append(out, a->body.data, a->body.size) != 0
        || cf__png_chunk(out, "IEND", NULL, 0) != 0) {
        out->size = start;
        out->failed = was_failed;
        apng_free(sink);
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "APNG: out of memory writing %u frames", n);
    }
    apng_free(sink);
    return CF_STATUS_OK;
}

static const cf__anim_ops_t apng_ops = { apng_add, apng_finish, apng_free };

cf_status_t
cf__anim_apng_open(int width, int height, cf__anim_sink_t **sink,
                   cf_diag_t *diag)
{
    apng_sink_t *a = cf_calloc(1, sizeof *a);
    if (a != NULL)
        a->prev = cf_calloc((size_t)width * (size_t)height,
                            sizeof *a->prev);
    if (a == NULL || a->prev == NULL) {
        cf_free(a);
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "APNG: out of memory for frames of %d x %d "
                           "pixels", width, height);
    }
    a->base.ops = &apng_ops;
    *sink = &a->base;
    return CF_STATUS_OK;
}
