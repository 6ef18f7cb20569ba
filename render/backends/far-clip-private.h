/*
** The parts of render/backends/far-clip.c that the dash pattern needs
** (render/backends/far-dash.c): the pieces, the state of a cut.
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

typedef struct far {
    box_t clip;             /* kept: a piece this box holds */
    box_t vis;              /* the visible box, grown by a stroke's reach */
    const cf__far_sink_t *sink;
    bool stroke;
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

/* The length of pc (a cubic's to 1e-13, by Gauss-Legendre). */
double cf__far_piece_length(const piece_t *pc);
/* pc's unit direction at its start (end: at its end). */
void cf__far_piece_dir(const piece_t *pc, bool end, double d[2]);

/* A run of a stroke starts at a (beyond the visible box: the end of a
** dropped piece, or the subpath's start): with a lead-in out there as
** long as the length walked modulo the dash period. */
void cf__far_start_run(far_t *f, const double a[2]);

/* A dashed closed subpath cut far away, walked from its start s0 to its
** end there (f->phi its length): where cairo would join its last dash to
** its first (both on at s0), that join, as a piece of a few hundredths of
** the stroke's width through s0 inside the two dashes. */
void cf__far_close_join(far_t *f, const double s0[2]);

#endif
