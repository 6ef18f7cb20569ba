/*
** Inside the frame sinks (render/output/anim-sink.h): what anim-sink.c,
** which checks every call and dispatches on the kind, shares with the
** encoders anim-gif.c, anim-apng.c and anim-ffmpeg.c.
*/
#ifndef CURVEFIG_RENDER_ANIM_PRIVATE_H
#define CURVEFIG_RENDER_ANIM_PRIVATE_H

#include <stddef.h>
#include <stdint.h>

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
/* How long ffmpeg may keep a video waiting, in all: CF__FFMPEG_WAIT
** seconds and CF__FFMPEG_WAIT_FRAME more a video frame (anim-ffmpeg.c);
** cf__anim_ffmpeg_limits sets other limits on an MP4 or WebM sink (the
** tests' hung ffmpeg). */
#define CF__FFMPEG_WAIT 60.0
#define CF__FFMPEG_WAIT_FRAME 1.0
void cf__anim_ffmpeg_limits(cf__anim_sink_t *sink, double wait,
                            double wait_frame);

/* ---- the GIF's palette (anim-palette.c) ---------------------------------- */

/* The colours of the frames counted (see anim-gif.c). */
typedef struct cf__colours {
    uint32_t *key;              /* exact colours: 0 empty, else rgb | 1<<24 */
    uint64_t *count;
    unsigned distinct;
    bool many;                  /* more than could be counted exactly */
    uint64_t (*bin)[4];         /* pixels, sums of r, g, b per bin */
    uint64_t opaque, clear;     /* pixels counted; transparent pixels (the
                                   caller counts them) */
} cf__colours_t;

/* 0, or -1 out of memory (then fini). */
int cf__colours_init(cf__colours_t *c);
void cf__colours_fini(cf__colours_t *c);

/* n opaque pixels of colour rgb (0xRRGGBB) counted. */
void cf__colours_add(cf__colours_t *c, uint32_t rgb, uint64_t n);

/* The palette (colours 0xRRGGBB) into pal: the number of opaque colours
** (at most 255 when c->clear > 0, leaving an index for transparency), or
** -1 out of memory.  Uses up the bins: once per count. */
int cf__colours_palette(cf__colours_t *c, uint32_t pal[256]);

/* Pixels to palette indices: the nearest colour (squared RGB distance),
** transparent (alpha 0) to index n; a cache of the colours seen. */
typedef struct cf__palette_map {
    const uint32_t *pal;
    int n;
    uint32_t *key;              /* cache: rgb | 1<<24 -> index */
    unsigned char *idx;
    unsigned used;
} cf__palette_map_t;

/* 0, or -1 out of memory (then fini). */
int cf__palette_map_init(cf__palette_map_t *m, const uint32_t *pal, int n);
void cf__palette_map_fini(cf__palette_map_t *m);

/* n RGBA pixels (alpha 0 or 255) as indices into out. */
void cf__palette_map(cf__palette_map_t *m, const unsigned char *rgba,
                     size_t n, unsigned char *out);

#endif
