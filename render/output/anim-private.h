/*
** Inside the frame sinks (render/output/anim-sink.h): what anim-sink.c,
** which checks every call and dispatches on the kind, shares with the
** encoders anim-gif.c, anim-apng.c and anim-ffmpeg.c.
*/
#ifndef CURVEFIG_RENDER_ANIM_PRIVATE_H
#define CURVEFIG_RENDER_ANIM_PRIVATE_H

#include "anim-sink.h"

/* One frame as the encoders see it, checked: the sink's size, seconds
** finite in (0, CF__ANIM_MAX_SECONDS]. */
typedef struct cf__anim_frame {
    const unsigned char *data;   /* native-endian ARGB32 (premultiplied) or
                                    xRGB, rows stride bytes apart */
    int stride;
    bool alpha;                  /* ARGB32: alpha is meaningful; false:
                                    RGB24, every pixel opaque */
    unsigned index;              /* 0, 1, ... */
    double start, seconds;       /* shown from start (the sum of the
                                    earlier frames' seconds) for seconds */
} cf__anim_frame_t;

/* The longest a frame may be shown (an hour). */
#define CF__ANIM_MAX_SECONDS 3600.0
/* The largest width or height of a frame. */
#define CF__ANIM_MAX_SIDE 16384

typedef struct cf__anim_ops {
    cf_status_t (*add)(cf__anim_sink_t *sink, const cf__anim_frame_t *f,
                       cf_diag_t *diag);
    cf_status_t (*finish)(cf__anim_sink_t *sink, cf__buf_t *out,
                          cf_diag_t *diag);
    void (*abort)(cf__anim_sink_t *sink);   /* frees the sink too */
} cf__anim_ops_t;

/* The part of every sink that anim-sink.c keeps; each encoder's sink
** begins with it. */
struct cf__anim_sink {
    const cf__anim_ops_t *ops;
    const char *name;            /* "GIF", "APNG", "MP4", "WebM" */
    cf__anim_kind_t kind;
    int width, height;
    double fps;
    bool loop;
    unsigned frames;             /* frames added */
    double seconds;              /* their total time */
    bool failed;                 /* a frame was refused: finish fails */
};

/* The encoders' constructors (arguments checked by anim-sink.c); each
** sets ops, anim-sink.c the rest of the common part. */
cf_status_t cf__anim_gif_open(int width, int height, cf__anim_sink_t **sink,
                              cf_diag_t *diag);
cf_status_t cf__anim_apng_open(int width, int height, cf__anim_sink_t **sink,
                               cf_diag_t *diag);
cf_status_t cf__anim_ffmpeg_open(cf__anim_kind_t kind, int width,
                                 int height, double fps, const char *path,
                                 cf__anim_sink_t **sink, cf_diag_t *diag);

#endif
