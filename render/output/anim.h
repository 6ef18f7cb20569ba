/*
** An animation's frames written in every form (render/output/anim.c,
** docs/animations.md): an animated SVG, a PDF of one page per frame, and
** the rasters of the frames handed to the encoders of anim-sink.h (GIF,
** APNG, MP4, WebM).  The frames come from a source (the tool runs the
** script once per frame with the sliders set; an overlay figure gives its
** steps); one page box and one map from data to page serve every frame,
** so that nothing jumps, and a label keeps its place of the frame before
** while that place stays about as clear as its best.
*/
#ifndef CURVEFIG_RENDER_OUTPUT_ANIM_H
#define CURVEFIG_RENDER_OUTPUT_ANIM_H

#include <stdbool.h>

#include "curvefig/figure.h"
#include "curvefig/output.h"

/* The forms, a bit each. */
enum {
    CF__ANIM_OUT_SVG = 1u << 0,
    CF__ANIM_OUT_PDF = 1u << 1,
    CF__ANIM_OUT_GIF = 1u << 2,
    CF__ANIM_OUT_APNG = 1u << 3,
    CF__ANIM_OUT_MP4 = 1u << 4,
    CF__ANIM_OUT_WEBM = 1u << 5,
    CF__ANIM_OUT_RASTER = CF__ANIM_OUT_GIF | CF__ANIM_OUT_APNG
                          | CF__ANIM_OUT_MP4 | CF__ANIM_OUT_WEBM
};

/* The frames.  make gives frame k's figure (and its overlay step, 0: all
** of it), which stays the source's until release; it may be called more
** than once for a frame, and in a child process (it must give the same
** figure each time).  same_figure: every frame is one figure (the steps
** of an overlay figure): laid out once. */
typedef struct cf__anim_source {
    unsigned frames;
    double seconds;          /* each frame's time on screen */
    bool same_figure;
    cf_status_t (*make)(void *ctx, unsigned k, cf_figure_t **fig,
                        unsigned *step, cf_diag_t *diag);
    void (*release)(void *ctx, unsigned k, cf_figure_t *fig);
    void *ctx;
} cf__anim_source_t;

typedef struct cf__anim_options {
    unsigned outputs;        /* CF__ANIM_OUT_* */
    const char *base;        /* base.svg, base.pdf, base.gif, base.apng,
                                base.mp4, base.webm */
    double dpi;              /* of the rasters */
    bool tight;              /* the page cropped to the ink of all frames */
    double padding;          /* bp around that ink */
    bool loop;               /* play forever (GIF, APNG, SVG) */
    int workers;             /* processes drawing the rasters: 0 the
                                machine's cores, 1 this one alone */
} cf__anim_options_t;

/* Every form of the animation written (each file whole or not at all);
** *width and *height (may be NULL) the page in bp. */
cf_status_t cf__anim_write(const cf__anim_source_t *src,
                           const cf__anim_options_t *o, double *width,
                           double *height, cf_diag_t *diag);

/* The extension of one form (a single bit of CF__ANIM_OUT_*). */
const char *cf__anim_extension(unsigned output);

#endif
