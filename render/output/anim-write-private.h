/*
** Inside cf__anim_write (anim.h): what the frame loop (anim.c) shares with
** the frames' layout and drawing (anim-frames.c), the processes that draw
** the rasters (anim-workers.c) and the files it writes (anim-forms.c).
*/
#ifndef CURVEFIG_RENDER_ANIM_WRITE_PRIVATE_H
#define CURVEFIG_RENDER_ANIM_WRITE_PRIVATE_H

#include <stdbool.h>
#include <stddef.h>

#include <cairo.h>
#include <sys/types.h>

#include "anim-sink.h"
#include "anim.h"
#include "layout-private.h"
#include "output-private.h"

/* The most processes that draw the rasters. */
#define CF__ANIM_MAX_WORKERS 8

typedef struct frame_info {
    cf__layout_t lay;
    double ink[4];
    cf__auto_place_t *places;
    size_t nplaces;
    unsigned step;
} frame_info_t;

/* What every frame shares. */
typedef struct anim {
    const cf__anim_source_t *src;
    const cf__anim_options_t *o;
    frame_info_t *info;
    cf__layout_t common;
    cf__page_t page;         /* for the vector forms */
    cf__page_t raster_page;  /* for the rasters (background as PNG's) */
    bool tight;
    int wpx, hpx;            /* raster size */
    char *title, *caption;
} anim_t;

/* ---- the frames (anim-frames.c) ----------------------------------------- */

/* Steps 1 and 2 (anim.c): every frame measured, one map and one page for
** all of them in a->common, a->page and a->raster_page. */
cf_status_t cf__anim_settle(anim_t *a, cf_diag_t *diag);

/* Frame k built for drawing (step 3) into dl; the display list draws
** the figure's labels, so the caller releases *fig (made when not NULL,
** also on failure) once it has drawn dl. */
cf_status_t cf__anim_frame_dl(anim_t *a, unsigned k, cf__dl_t *dl,
                              unsigned *step, cf_figure_t **fig,
                              cf_diag_t *diag);
/* dl emptied and fig (may be NULL) released, once frame k is drawn. */
void cf__anim_frame_done(anim_t *a, unsigned k, cf__dl_t *dl,
                         cf_figure_t *fig);
/* The page of dl at step (0: all of it) drawn on cr (set up). */
void cf__anim_draw(const cf__dl_t *dl, const cf__page_t *pg, unsigned step,
                   cairo_t *cr);
/* Frame k's raster into surf (a->wpx x a->hpx, ARGB32). */
cf_status_t cf__anim_raster(anim_t *a, unsigned k, cairo_surface_t *surf,
                            cf__dl_t *dl, cf_diag_t *diag);

/* ---- the rasters' workers (anim-workers.c) ----------------------------- */

typedef struct workers {
    int n;
    pid_t pid[CF__ANIM_MAX_WORKERS];
    int fd[CF__ANIM_MAX_WORKERS];
} workers_t;

/* How many processes draw the rasters (1: this one alone). */
int cf__anim_worker_count(const anim_t *a);
/* n children started (fewer when fork fails: then this process draws
** the rasters itself, ws->n 0). */
void cf__anim_workers_start(anim_t *a, int n, workers_t *ws);
void cf__anim_workers_stop(workers_t *ws);
/* Frame k's raster, drawn by its worker, read into surf (bytes of pixels;
** the worker's status and message when it failed). */
cf_status_t cf__anim_workers_read(const workers_t *ws, unsigned k,
                                  cairo_surface_t *surf, size_t bytes,
                                  cf_diag_t *diag);

/* ---- the forms (anim-forms.c) ------------------------------------------ */

typedef struct forms {
    cf__svg_anim_t svg;
    cf__buf_t pdf;
    cf__pdfw_t *pdfw;             /* the PDF writer, a page a frame */
    cf__glyph_outliner_t outliner;
    cf__anim_sink_t *sink[4];     /* GIF, APNG, MP4, WebM */
    cf__buf_t bytes[4];
} forms_t;

/* The SVG, the PDF and the sinks opened for a->o->outputs. */
cf_status_t cf__anim_forms_open(anim_t *a, forms_t *f, cf_diag_t *diag);
void cf__anim_forms_free(forms_t *f);
/* Frame k's vector forms (the SVG's group, the PDF's page). */
cf_status_t cf__anim_vector_frame(anim_t *a, forms_t *f, unsigned k,
                                  cf__dl_t *dl, cf_diag_t *diag);
/* A raster (every frame's) handed to each sink. */
cf_status_t cf__anim_raster_add(forms_t *f, cairo_surface_t *surf,
                                double seconds, cf_diag_t *diag);
/* Every file made: the sinks finished, the SVG, PDF, GIF and APNG
** written. */
cf_status_t cf__anim_forms_finish(anim_t *a, forms_t *f, cf_diag_t *diag);

#endif
