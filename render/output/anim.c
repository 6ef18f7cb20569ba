/*
** The frame loop of an animation (anim.h, docs/animations.md).
**
** 1. Measure: every frame laid out and built once, in order, each
**    automatic label offered the place it had in the frame before
**    (render/layout/place.c keeps it while it stays within AUTO_KEEP of
**    the clearest place): each frame's map, ink box and label places.
**    When the frames' maps differ (a window fitted to what each frame
**    draws), one map is made that holds every frame's window where the
**    frames put theirs, and the frames are measured again with it.
** 2. The page: the figure's page, or on a page cropped to the ink (tight,
**    page = "ink") the union of every frame's ink plus the padding; the
**    same for every frame.
** 3. Draw: every frame built again with that map and its measured label
**    places, into the animated SVG (svg-anim.c), a page of the PDF, and a
**    raster for the encoders of anim-sink.h.  The rasters are drawn by
**    child processes where the machine has more than one core (each runs
**    its frames' scripts itself and sends the pixels through a pipe; the
**    frames are read in order, so at most one frame per child waits).
** Files are written at the end, each whole (cf_write_file; the videos by
** their sinks, through a temporary file renamed at finish).
**
** Steps 1 and 2 and the drawing of a frame: anim-frames.c; the child
** processes: anim-workers.c; the files: anim-forms.c.
*/
#include <math.h>
#include <string.h>

#include "anim-write-private.h"

/* ---- the loop ------------------------------------------------------------ */

static cf_status_t
draw_frames(anim_t *a, forms_t *f, cf_diag_t *diag)
{
    workers_t ws;
    cairo_surface_t *surf = NULL;
    size_t bytes = 0;
    cf__dl_t dl;
    cf_status_t st = CF_STATUS_OK;
    int nw = cf__anim_worker_count(a);
    memset(&ws, 0, sizeof ws);
    cf__dl_init(&dl);
    if (a->o->outputs & CF__ANIM_OUT_RASTER) {
        surf = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, a->wpx,
                                          a->hpx);
        if (cairo_surface_status(surf) != CAIRO_STATUS_SUCCESS)
            st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                             "out of memory for a frame of %d x %d pixels",
                             a->wpx, a->hpx);
        bytes = (size_t)cairo_image_surface_get_stride(surf)
                * (size_t)a->hpx;
        if (st == CF_STATUS_OK && nw > 1)
            cf__anim_workers_start(a, nw, &ws);
    }
    for (unsigned k = 0; k < a->src->frames && st == CF_STATUS_OK; k++) {
        st = cf__anim_vector_frame(a, f, k, &dl, diag);
        if (st != CF_STATUS_OK || surf == NULL)
            continue;
        if (ws.n > 0)
            st = cf__anim_workers_read(&ws, k, surf, bytes, diag);
        else
            st = cf__anim_raster(a, k, surf, &dl, diag);
        if (st == CF_STATUS_OK)
            st = cf__anim_raster_add(f, surf, a->src->seconds, diag);
    }
    cf__anim_workers_stop(&ws);
    if (surf != NULL)
        cairo_surface_destroy(surf);
    cf__dl_free(&dl);
    return st;
}

cf_status_t
cf__anim_write(const cf__anim_source_t *src, const cf__anim_options_t *o,
               double *width, double *height, cf_diag_t *diag)
{
    anim_t a;
    forms_t f;
    cf_status_t st;
    double k;
    cf_diag_clear(diag);
    if (src == NULL || o == NULL || o->base == NULL || src->make == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "animation: source, options or base is NULL");
    if (src->frames == 0)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "an animation needs at least one frame");
    if (!(src->seconds > 0 && isfinite(src->seconds)))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "a frame's time %g s must be positive",
                           src->seconds);
    if (!(isfinite(o->dpi) && o->dpi >= 1 && o->dpi <= 2400))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "resolution %g dpi must lie in [1, 2400]", o->dpi);
    memset(&a, 0, sizeof a);
    a.src = src;
    a.o = o;
    a.info = cf_alloc_array(src->frames, sizeof *a.info);
    if (a.info == NULL)
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for %u frames", src->frames);
    memset(a.info, 0, src->frames * sizeof *a.info);
    st = cf__anim_settle(&a, diag);
    k = o->dpi / 72.0;
    a.wpx = (int)fmax(1, ceil(a.page.width * k - 1e-6));
    a.hpx = (int)fmax(1, ceil(a.page.height * k - 1e-6));
    if (st == CF_STATUS_OK && (o->outputs & CF__ANIM_OUT_RASTER)
        && (double)a.wpx * a.hpx > 4e7)
        st = cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                         "frames of %d x %d pixels are too large (at most "
                         "40 million pixels); lower the dpi", a.wpx, a.hpx);
    if (st == CF_STATUS_OK)
        st = cf__anim_forms_open(&a, &f, diag);
    else
        memset(&f, 0, sizeof f);
    if (st == CF_STATUS_OK)
        st = draw_frames(&a, &f, diag);
    if (st == CF_STATUS_OK)
        st = cf__anim_forms_finish(&a, &f, diag);
    cf__anim_forms_free(&f);
    if (width != NULL)
        *width = a.page.width;
    if (height != NULL)
        *height = a.page.height;
    for (unsigned i = 0; i < src->frames; i++)
        cf_free(a.info[i].places);
    cf_free(a.info);
    cf_free(a.title);
    cf_free(a.caption);
    return st;
}
