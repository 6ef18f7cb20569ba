/*
** The frame sinks (anim-sink.h): every call checked here, once for the
** four formats, then handed to the encoder of the sink's kind (anim-gif.c,
** anim-apng.c, anim-ffmpeg.c; the common part in anim-private.h).
*/
#include <math.h>

#include "anim-private.h"

static const char *const kind_names[] = { "GIF", "APNG", "MP4", "WebM" };

cf_status_t
cf__anim_sink_open(cf__anim_kind_t kind, int width, int height, double fps,
                   bool loop, const char *path, cf__anim_sink_t **sink,
                   cf_diag_t *diag)
{
    cf_diag_clear(diag);
    bool video = kind == CF__ANIM_MP4 || kind == CF__ANIM_WEBM;
    const char *name;
    cf_status_t st;

    if (sink == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "animation: the sink pointer is NULL");
    *sink = NULL;
    if ((unsigned)kind > (unsigned)CF__ANIM_WEBM)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "animation: unknown format %d", (int)kind);
    name = kind_names[kind];
    if (width < 1 || height < 1 || width > CF__ANIM_MAX_SIDE
        || height > CF__ANIM_MAX_SIDE)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "%s: frames of %d x %d pixels; each side must "
                           "lie in [1, %d]", name, width, height,
                           CF__ANIM_MAX_SIDE);
    if (!(isfinite(fps) && fps > 0 && fps <= 1000))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "%s: %g frames per second must lie in (0, 1000]",
                           name, fps);
    if (video && (path == NULL || path[0] == '\0'))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "%s: a video needs the path of its file", name);
    if (!video && path != NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "%s: the bytes go to the buffer of finish, "
                           "not to a path", name);
    if (kind == CF__ANIM_GIF)
        st = cf__anim_gif_open(width, height, sink, diag);
    else if (kind == CF__ANIM_APNG)
        st = cf__anim_apng_open(width, height, sink, diag);
    else
        st = cf__anim_ffmpeg_open(kind, width, height, fps, path, sink,
                                  diag);
    if (st != CF_STATUS_OK)
        return st;
    (*sink)->name = name;
    (*sink)->kind = kind;
    (*sink)->width = width;
    (*sink)->height = height;
    (*sink)->fps = fps;
    (*sink)->loop = loop;
    return CF_STATUS_OK;
}

/* The frame checked; 0 with f filled, or the error. */
static cf_status_t
check_frame(const cf__anim_sink_t *s, cairo_surface_t *frame,
            double seconds, cf__anim_frame_t *f, cf_diag_t *diag)
{
    unsigned k = s->frames;
    cairo_format_t format;
    int w, h;
    if (frame == NULL || cairo_surface_status(frame) != CAIRO_STATUS_SUCCESS
        || cairo_surface_get_type(frame) != CAIRO_SURFACE_TYPE_IMAGE)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, (long)k,
                           "%s frame %u: not a valid cairo image surface",
                           s->name, k);
    cairo_surface_flush(frame);
    format = cairo_image_surface_get_format(frame);
    w = cairo_image_surface_get_width(frame);
    h = cairo_image_surface_get_height(frame);
    if (format != CAIRO_FORMAT_ARGB32 && format != CAIRO_FORMAT_RGB24)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, (long)k,
                           "%s frame %u: image format %d is not ARGB32 or "
                           "RGB24", s->name, k, (int)format);
    if (w != s->width || h != s->height)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, (long)k,
                           "%s frame %u: %d x %d pixels, but the "
                           "animation's frames are %d x %d", s->name, k, w,
                           h, s->width, s->height);
    if (!(isfinite(seconds) && seconds > 0
          && seconds <= CF__ANIM_MAX_SECONDS))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, (long)k,
                           "%s frame %u: shown for %g s; a frame's time "
                           "must lie in (0, %g] s", s->name, k, seconds,
                           CF__ANIM_MAX_SECONDS);
    f->data = cairo_image_surface_get_data(frame);
    f->stride = cairo_image_surface_get_stride(frame);
    f->alpha = format == CAIRO_FORMAT_ARGB32;
    f->index = k;
    f->start = s->seconds;
    f->seconds = seconds;
    if (f->data == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, (long)k,
                           "%s frame %u: the image has no data", s->name, k);
    return CF_STATUS_OK;
}

cf_status_t
cf__anim_sink_add(cf__anim_sink_t *sink, cairo_surface_t *frame,
                  double seconds, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf__anim_frame_t f;
    cf_status_t st;
    if (sink == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "animation: the sink is NULL");
    if (sink->failed)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, (long)sink->frames,
                           "%s frame %u: an earlier frame failed; abort "
                           "the animation", sink->name, sink->frames);
    st = check_frame(sink, frame, seconds, &f, diag);
    if (st == CF_STATUS_OK)
        st = sink->ops->add(sink, &f, diag);
    if (st != CF_STATUS_OK) {
        sink->failed = true;
        return st;
    }
    sink->frames++;
    sink->seconds += seconds;
    return CF_STATUS_OK;
}

cf_status_t
cf__anim_sink_finish(cf__anim_sink_t *sink, cf__buf_t *out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    const char *name;
    bool video;
    if (sink == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "animation: the sink is NULL");
    name = sink->name;
    video = sink->kind == CF__ANIM_MP4 || sink->kind == CF__ANIM_WEBM;
    if (sink->failed || sink->frames == 0 || (!video && out == NULL)) {
        unsigned n = sink->frames;
        bool failed = sink->failed;
        cf__anim_sink_abort(sink);
        if (failed)
            return cf_diag_set(diag, CF_STATUS_INVALID_ARG, (long)n,
                               "%s: frame %u failed; nothing written", name,
                               n);
        if (n == 0)
            return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                               "%s: an animation of no frames", name);
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "%s: the output buffer is NULL", name);
    }
    return sink->ops->finish(sink, out, diag);
}

void
cf__anim_sink_abort(cf__anim_sink_t *sink)
{
    if (sink != NULL)
        sink->ops->abort(sink);
}
