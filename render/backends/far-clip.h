/*
** Paths far off the page, cut down before cairo draws them.  cairo keeps
** a path in 24.8 fixed point of device units, which wraps round beyond
** 2^23; and cairo 1.16 rasterises wrongly a stroke or fill with an edge
** reaching about 1.9e5 device units from the surface upwards (measured:
** lines from every direction, to PNG).  A path within the safe region
** (CF__FAR_LO..CF__FAR_HI device units on both axes: 2^16 and 2^15
** beyond a page of at most 32768 device units, 32767 pixels or 14400 bp)
** is drawn as it is: every figure on its page.  Another is handed on cut,
** drawn the same inside the visible box (the clip's extents: the page or
** the window) as the path itself would be by a renderer without those
** limits:
**   a fill keeps the winding number of every point there (so under the
**   nonzero and the even-odd rule alike): each piece of its outline that
**   lies wholly beyond one side of the visible box becomes its chord,
**   and every point beyond the clip box (the visible box grown by
**   CF__FAR_GROW device units) is moved onto that box, as Sutherland-
**   Hodgman clipping does; the outline changes only beyond that side;
**   a stroke loses the pieces that lie farther out than its half width (or
**   its miter's reach) beyond the visible box, and each run after a cut
**   starts with a lead-in out there, as long as the length cut off
**   modulo the dash pattern, which keeps the dashes' phase.
** Pieces are found by halving lines, cubics (de Casteljau at 1/2) and arcs
** (their angle), no flattening: a piece that the clip box holds is kept
** as it is; one wholly beyond the visible box is dropped (or made its
** chord); others are halved.  Halving needs no intersection, so a line from
** 1e300 is cut as exactly as one from 1e5.  Pure C, no device: a sink
** receives the result (render/backends/backend-cairo.c: cairo's path).
** far-clip.c tests the path and makes the frame; far-halve.c halves the
** pieces, far-fill.c and far-stroke.c cut a fill and a stroke, far-dash.c
** keeps the dashes' phase.
*/
#ifndef CURVEFIG_RENDER_FAR_CLIP_H
#define CURVEFIG_RENDER_FAR_CLIP_H

#include "dlist.h"

#define CF__FAR_LO (-32768.0)   /* the safe region, device units */
#define CF__FAR_HI 65536.0
#define CF__FAR_PAGE 32768.0    /* the largest page, device units */
#define CF__FAR_GROW 8192.0     /* the clip box beyond the visible box;
                                   a stroke's reach, a lead-in's leg: at
                                   most half that */

/* The device's transformation, as cairo_matrix_t: device x = xx x + xy y
** + x0, device y = yx x + yy y + y0. */
typedef struct cf__far_ctm {
    double xx, yx, xy, yy, x0, y0;
} cf__far_ctm_t;

/* Where a cut path goes, in user units. */
typedef struct cf__far_sink {
    void (*move_to)(void *ctx, double x, double y);
    void (*line_to)(void *ctx, double x, double y);
    void (*curve_to)(void *ctx, double x1, double y1, double x2, double y2,
                     double x3, double y3);
    /* as cairo_arc: from the current point (if any) a line to its start */
    void (*arc)(void *ctx, double cx, double cy, double r, double a0,
                double a1);
    void (*close_path)(void *ctx);
    void *ctx;
} cf__far_sink_t;

/* Whether p lies within the safe region under m (or m is not a scale and
** a shift: nothing to cut against): draw it as it is. */
bool cf__far_safe(const cf__path_t *p, const cf__far_ctm_t *m);

/* What a cut keeps: the visible box (x0 y0 x1 y1, user units) and the
** clip box's margin round it (user units). */
typedef struct cf__far_frame {
    double vis[4];
    double grow;     /* CF__FAR_GROW device units */
    bool raster;     /* cairo rasterises the stroke (not a PDF or PS that
                        a viewer does): a dashed closed outline cut far
                        away is joined at its start where a dash runs in
                        and one out, as cairo's raster of it is (poppler
                        joins it not) */
} cf__far_frame_t;

/* The frame for the clip extents ext (user units, cairo_clip_extents) under
** m (fr->raster false); false when m is not a scale and a shift or ext does
** not lie on a page of the device (a recording surface's: unbounded). */
bool cf__far_frame(const cf__far_ctm_t *m, const double ext[4],
                   cf__far_frame_t *fr);

/* p cut for filling (any fill rule), to sink. */
void cf__far_fill(const cf__path_t *p, const cf__far_frame_t *fr,
                  const cf__far_sink_t *sink);

/* p cut for stroking with s (its width, join and dash, miter limit 10,
** dash offset 0, as render/backends/backend-cairo.c strokes), to sink;
** false (nothing sent) when its reach (half its width, 10 times that with
** miter joins) is more than half fr->grow. */
bool cf__far_stroke(const cf__path_t *p, const cf__far_frame_t *fr,
                    const cf__stroke_t *s, const cf__far_sink_t *sink);

#endif
