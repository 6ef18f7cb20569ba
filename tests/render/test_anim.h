/* The helpers the animation tests share (test_anim.c, test_anim_video.c):
** frames drawn with cairo, and their pixels as a viewer sees them; static
** inline, as not every file uses each. */
#ifndef CURVEFIG_TESTS_TEST_ANIM_H
#define CURVEFIG_TESTS_TEST_ANIM_H

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include <cairo.h>
#include "anim-sink.h"
#include "anim-decode.h"
#include "testutil.h"

/* Frame k of a small "figure": a white page, a filled rectangle and a
** circle that move with k, a dark curve; antialiased (hundreds of
** colours) or not (a handful).  transparent: no page, drawn on alpha 0. */
static inline cairo_surface_t *
draw_frame(int w, int h, int k, bool antialias, bool transparent,
           cairo_format_t format)
{
    cairo_surface_t *s = cairo_image_surface_create(format, w, h);
    cairo_t *cr = cairo_create(s);
    double t = k * 0.1;
    cairo_set_antialias(cr, antialias ? CAIRO_ANTIALIAS_GRAY
                                      : CAIRO_ANTIALIAS_NONE);
    cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
    if (transparent)
        cairo_set_source_rgba(cr, 0, 0, 0, 0);
    else
        cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_operator(cr, CAIRO_OPERATOR_OVER);
    cairo_set_source_rgb(cr, 0.85, 0.9, 1.0);
    cairo_rectangle(cr, 0.1 * w, 0.55 * h, 0.8 * w, 0.3 * h);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.8, 0.1, 0.1);
    cairo_arc(cr, (0.2 + 0.6 * fmod(t, 1.0)) * w, 0.4 * h, 0.08 * w, 0,
              2 * acos(-1.0));
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.1, 0.2, 0.6);
    cairo_set_line_width(cr, 2.5);
    cairo_move_to(cr, 0.05 * w, 0.9 * h);
    cairo_curve_to(cr, 0.3 * w, (0.1 + 0.05 * k) * h, 0.7 * w,
                   0.9 * h, 0.95 * w, 0.15 * h);
    cairo_stroke(cr);
    cairo_destroy(cr);
    cairo_surface_flush(s);
    return s;
}

/* Pixel (x, y) of a frame as un-premultiplied RGBA, cairo's way (the
** PNG's pixels); RGB24 opaque. */
static inline void
frame_rgba(cairo_surface_t *s, int x, int y, unsigned char out[4])
{
    const unsigned char *d = cairo_image_surface_get_data(s);
    uint32_t p, a;
    memcpy(&p, d + (size_t)y * (size_t)cairo_image_surface_get_stride(s)
                   + 4 * (size_t)x, 4);
    a = cairo_image_surface_get_format(s) == CAIRO_FORMAT_RGB24 ? 255
                                                                : p >> 24;
    if (a == 0) {
        out[0] = out[1] = out[2] = out[3] = 0;
        return;
    }
    for (int c = 0; c < 3; c++)
        out[c] = (unsigned char)((((p >> (16 - 8 * c)) & 0xff) * 255 + a / 2)
                                 / a);
    out[3] = (unsigned char)a;
}

/* The sink's bytes of frames 0..n-1 (draw_frame's), each shown for
** seconds[k]; asserts every step succeeds. */
static inline void
encode_frames(cf__anim_kind_t kind, cairo_surface_t **frames, size_t n,
              const double *seconds, bool loop, cf__buf_t *out)
{
    cf__anim_sink_t *sink = NULL;
    cf_diag_t diag;
    int w = cairo_image_surface_get_width(frames[0]);
    int h = cairo_image_surface_get_height(frames[0]);
    assert_int_equal(cf__anim_sink_open(kind, w, h, 30, loop, NULL, &sink,
                                        &diag), CF_STATUS_OK);
    for (size_t k = 0; k < n; k++) {
        cf_status_t st = cf__anim_sink_add(sink, frames[k], seconds[k],
                                           &diag);
        if (st != CF_STATUS_OK)
            fail_msg("frame %zu: %s", k, diag.msg);
    }
    if (cf__anim_sink_finish(sink, out, &diag) != CF_STATUS_OK)
        fail_msg("finish: %s", diag.msg);
}

#endif
