/*
** A fill cut far away (render/backends/far-clip.h): each piece of its
** outline that lies wholly beyond one side of the visible box becomes its
** chord, with the end clamped to the clip box (the visible box grown by
** CF__FAR_GROW device units), as Sutherland-Hodgman clipping does; the
** outline changes only beyond that side, so every point there keeps its
** winding number (under the nonzero and the even-odd rule alike).  The
** pieces come from the halving of far-halve.c.
*/
#include <math.h>

#include "far-halve.h"

static void
clamp(const box_t *b, const double p[2], double q[2])
{
    q[0] = fmin(fmax(p[0], b->x0), b->x1);
    q[1] = fmin(fmax(p[1], b->y0), b->y1);
}

/* Whether p, q and r lie on one side (line) of box b. */
static bool
one_side(const box_t *b, const double p[2], const double q[2],
         const double r[2])
{
    return (p[0] == b->x0 && q[0] == b->x0 && r[0] == b->x0)
        || (p[0] == b->x1 && q[0] == b->x1 && r[0] == b->x1)
        || (p[1] == b->y0 && q[1] == b->y0 && r[1] == b->y0)
        || (p[1] == b->y1 && q[1] == b->y1 && r[1] == b->y1);
}

/* The fill's held point sent. */
static void
flush(far_t *f)
{
    if (!f->holding)
        return;
    f->sink->line_to(f->sink->ctx, f->held[0], f->held[1]);
    f->last[0] = f->held[0];
    f->last[1] = f->held[1];
    f->holding = false;
}

/* A fill's piece: kept, or its chord with the end clamped to the clip
** box.  A dropped piece lies beyond one side of the visible box, and so
** do its chord and their clamped ends: the outline changes only there.
** Of clamped points in a row along one side of the clip box only the
** last is sent (the outline between goes along a line: no area). */
static void
fill_piece(far_t *f, const piece_t *pc, bool keep)
{
    double q[2];
    if (keep) {
        flush(f);
        cf__far_send(f, pc);
        f->last[0] = pc->b[0];
        f->last[1] = pc->b[1];
        return;
    }
    clamp(&f->clip, pc->b, q);
    if (f->holding && one_side(&f->clip, f->last, f->held, q)) {
        f->held[0] = q[0];
        f->held[1] = q[1];
        return;
    }
    flush(f);
    if (q[0] == f->last[0] && q[1] == f->last[1])
        return;
    f->held[0] = q[0];
    f->held[1] = q[1];
    f->holding = true;
}

static void
fill_sub(far_t *f, const sub_t *s)
{
    sub_t c = *s;
    if (cf__far_send_whole(f, s))
        return;
    clamp(&f->clip, s->start, f->last);
    f->holding = false;
    f->sink->move_to(f->sink->ctx, f->last[0], f->last[1]);
    c.closed = true;          /* a fill closes every subpath */
    cf__far_walk(f, &c);
    flush(f);
    f->sink->close_path(f->sink->ctx);
}

void
cf__far_fill(const cf__path_t *p, const cf__far_frame_t *fr,
             const cf__far_sink_t *sink)
{
    far_t f = { 0 };
    f.sink = sink;
    f.piece = fill_piece;
    f.sub = fill_sub;
    cf__far_boxes(fr, fr->grow, &f);
    cf__far_each_sub(&f, p);
}
