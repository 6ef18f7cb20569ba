/*
** The frame sinks of an animation: frames of one size, each an image with
** the time it stays on screen, encoded as an animated GIF (anim-gif.c), an
** APNG (anim-apng.c), or an MP4 or WebM video through the ffmpeg program
** found at run time (anim-ffmpeg.c).  The sweep (the frame loop) renders
** the frames with cairo and hands them over in order; it never sees a
** format's bytes.
**
** Lifetime: open, add every frame in order, then finish (the result made)
** or abort (nothing left behind).  finish and abort free the sink.
*/
#ifndef CURVEFIG_RENDER_ANIM_SINK_H
#define CURVEFIG_RENDER_ANIM_SINK_H

#include <stdbool.h>

#include <cairo.h>

#include "buffer.h"
#include "curvefig/core.h"

typedef enum cf__anim_kind {
    CF__ANIM_GIF = 0,
    CF__ANIM_APNG,
    CF__ANIM_MP4,
    CF__ANIM_WEBM
} cf__anim_kind_t;

typedef struct cf__anim_sink cf__anim_sink_t;

/* A sink for frames of width x height pixels.  fps is the nominal frame
** rate (the videos' rate; the GIF and APNG give each frame its own time);
** loop: play forever (GIF, APNG) rather than once.  path is the file a
** video is made as (through a temporary file in its directory, renamed at
** finish); NULL for GIF and APNG, whose bytes finish appends to a buffer
** the caller writes with cf_write_file.  A missing ffmpeg is an error
** here, before any frame is rendered, saying what to install. */
cf_status_t cf__anim_sink_open(cf__anim_kind_t kind, int width, int height,
                               double fps, bool loop, const char *path,
                               cf__anim_sink_t **sink, cf_diag_t *diag);

/* The next frame: an image surface (CAIRO_FORMAT_ARGB32 or RGB24) of the
** sink's size, shown for `seconds` (> 0).  The sink copies what it keeps:
** the caller may reuse or destroy the surface on return. */
cf_status_t cf__anim_sink_add(cf__anim_sink_t *sink, cairo_surface_t *frame,
                              double seconds, cf_diag_t *diag);

/* The animation made: a GIF's or APNG's bytes appended to out; a video's
** file renamed into place (out untouched, may be NULL).  Frees the sink,
** also on error (then nothing is left behind). */
cf_status_t cf__anim_sink_finish(cf__anim_sink_t *sink, cf__buf_t *out,
                                 cf_diag_t *diag);

/* Frees the sink without making anything: ffmpeg stopped and its
** temporary file removed.  NULL is a no-op. */
void cf__anim_sink_abort(cf__anim_sink_t *sink);

#endif
