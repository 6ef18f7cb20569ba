/*
** A stroke cut far away (render/backends/far-clip.h): the pieces that lie
** farther out than it reaches (half its width, or its miter's reach)
** beyond the visible box are dropped, and each run after a cut starts with
** a lead-in out there that keeps the dashes' phase (far-dash.c); a closed
** subpath that is cut is walked again from the cut (undashed, its joins
** where they were) or from its start (dashed).  The pieces come from the
** halving of far-halve.c.
*/
#include <stdint.h>

#include "far-dash.h"
#include "far-halve.h"

#define MITER_LIMIT 10.0    /* cairo's default, which the backend keeps */

/* A stroke's piece: a dropped one ends the run (its ends lie farther out
** than the stroke reaches: no cap or join there shows), a kept one goes on
** with it, or starts one. */
static void
stroke_piece(far_t *f, const piece_t *pc, bool keep)
{
    size_t i = f->index++;
    double len;
    if (!keep) {
        if (f->first_drop == SIZE_MAX)
            f->first_drop = i;
        f->drawing = false;
    } else if (i >= f->from && i < f->to) {
        if (!f->drawing)
            cf__far_start_run(f, pc->a);
        f->drawing = true;
        cf__far_send(f, pc);
    }
    len = f->measure ? cf__far_piece_length(pc) : 0;
    f->phi += len;
    if (keep && f->measure) {
        if (i == 0) {
            cf__far_piece_dir(pc, false, f->out_dir);
            f->out_len = len;
        }
        cf__far_piece_dir(pc, true, f->in_dir);
        f->in_len = len;
        f->last_kept = i;
    }
}

/* One walk of s sending pieces [from, to); measuring its length when
** dashed. */
static void
stroke_walk(far_t *f, const sub_t *s, size_t from, size_t to)
{
    f->index = 0;
    f->phi = 0;
    f->from = from;
    f->to = to;
    f->measure = f->dashed && to > from;
    cf__far_walk(f, s);
}

/* A closed subpath that is cut is walked from the first cut round to it
** (undashed: its joins stay where they were), or from its start (dashed:
** the dashes start there; on a raster the join there, where cairo would
** make it, is added by cf__far_close_join). */
static void
stroke_sub(far_t *f, const sub_t *s)
{
    size_t n;
    if (cf__far_send_whole(f, s))
        return;
    f->drawing = false;
    f->first_drop = SIZE_MAX;
    if (!s->closed && s->rect == NULL) {
        stroke_walk(f, s, 0, SIZE_MAX);
        return;
    }
    stroke_walk(f, s, 0, 0);
    n = f->index;
    if (f->first_drop == SIZE_MAX) {
        stroke_walk(f, s, 0, n);
        f->sink->close_path(f->sink->ctx);
    } else if (f->dashed) {
        f->last_kept = SIZE_MAX;
        stroke_walk(f, s, 0, n);
        if (f->raster && f->first_drop > 0 && f->last_kept == n - 1)
            cf__far_close_join(f, s->start);
    } else {
        size_t cut = f->first_drop;
        stroke_walk(f, s, cut + 1, n);
        stroke_walk(f, s, 0, cut);
    }
}

bool
cf__far_stroke(const cf__path_t *p, const cf__far_frame_t *fr,
               const cf__stroke_t *s, const cf__far_sink_t *sink)
{
    far_t f = { 0 };
    double reach = s->width / 2 * (s->join == CF__JOIN_MITER ? MITER_LIMIT
                                                            : 1.0),
           sum = 0;
    /* a little farther than the stroke reaches, and at most half the way
    ** to the clip box: room for the halving to end */
    reach = reach * (1 + 1e-6) + fr->grow * 1e-6;
    if (!(reach <= fr->grow / 2))
        return false;
    f.sink = sink;
    f.piece = stroke_piece;
    f.sub = stroke_sub;
    f.style = s;
    f.raster = fr->raster;
    cf__far_boxes(fr, fr->grow, &f);
    f.vis.x0 -= reach;
    f.vis.y0 -= reach;
    f.vis.x1 += reach;
    f.vis.y1 += reach;
    for (size_t i = 0; i < s->dash_count; i++)
        sum += s->dash[i];
    f.dashed = s->dash_count > 0 && sum > 0;
    f.period = s->dash_count % 2 == 1 ? 2 * sum : sum;
    f.leg = fr->grow / 2;
    cf__far_each_sub(&f, p);
    return true;
}
