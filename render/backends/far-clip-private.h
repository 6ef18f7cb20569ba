/*
** What the units of a cut far away share (render/backends/far-clip.h:
** far-clip.c, far-halve.c, far-fill.c, far-stroke.c, far-dash.c): the
** boxes, the pieces and subpaths, the state of a cut.
*/
#ifndef CURVEFIG_RENDER_FAR_CLIP_PRIVATE_H
#define CURVEFIG_RENDER_FAR_CLIP_PRIVATE_H

#include "far-clip.h"

typedef struct box {
    double x0, y0, x1, y1;
} box_t;

typedef enum kind { P_LINE, P_CURVE, P_ARC } kind_t;

/* A piece of a subpath: from a to b; a cubic's controls c (its 4 points,
** c[0..1] = a, c[6..7] = b), an arc's centre, radius and angles. */
typedef struct piece {
    kind_t kind;
    double a[2], b[2];
    const double *c;
    double cx, cy, r, t0, t1;
} piece_t;

/* A subpath: its start, then n segments (LINE, CURVE, ARC) at segs and v;
** closed: a CLOSE ends it; rect: instead the rectangle v. */
typedef struct sub {
    double start[2];
    const unsigned char *segs;
    const double *v;
    size_t n;
    bool closed;
    const double *rect;
} sub_t;

typedef struct far {
    box_t clip;             /* kept: a piece this box holds */
    box_t vis;              /* the visible box, grown by a stroke's reach */
    const cf__far_sink_t *sink;
    /* the fill's or the stroke's part: what becomes of a piece once the
    ** halving is done with it (kept or dropped), and of a subpath */
    void (*piece)(struct far *f, const piece_t *pc, bool keep);
    void (*sub)(struct far *f, const sub_t *s);
    /* the fill's last point sent, and the one after it held back while
    ** the clamped points run along one side of the clip box */
    double last[2], held[2];
    bool holding;
    /* the stroke's walk of a subpath */
    bool dashed, measure;
    double period, leg;     /* the dash pattern's; a lead-in's longest leg */
    double phi;             /* length walked (dashes) */
    bool drawing;           /* a run is open in the sink */
    size_t index, from, to; /* pieces walked; those [from, to) are sent */
    size_t first_drop;      /* SIZE_MAX: none */
    /* the ends of a closed subpath's walk: the first piece's direction
    ** and length, the last kept piece's (index last_kept) */
    double out_dir[2], in_dir[2], out_len, in_len;
    size_t last_kept;
    const cf__stroke_t *style;
    bool raster;            /* cf__far_frame_t's */
} far_t;

/* Whether point (x, y) lies in box b; the test of every point of every
** path drawn, kept to four comparisons (a NaN passes: refused upstream). */
static inline bool
out_of(const box_t *b, double x, double y)
{
    return x < b->x0 || x > b->x1 || y < b->y0 || y > b->y1;
}

/* The clip box: the visible box grown by g (user units). */
void cf__far_boxes(const cf__far_frame_t *fr, double g, far_t *f);

#endif
