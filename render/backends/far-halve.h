/*
** The pieces of a path cut far away (render/backends/far-halve.c), for the
** fill (far-fill.c) and the stroke (far-stroke.c): each subpath walked as
** pieces halved until kept or dropped, handed to far_t's piece and sub.
*/
#ifndef CURVEFIG_RENDER_FAR_HALVE_H
#define CURVEFIG_RENDER_FAR_HALVE_H

#include "far-clip-private.h"

/* Each subpath of p, as cairo reads the path, to f->sub. */
void cf__far_each_sub(far_t *f, const cf__path_t *p);

/* Every piece of s, in order, halved until the clip box holds it or it
** lies beyond the visible box, to f->piece (a closed subpath ends with
** the line back to its start). */
void cf__far_walk(far_t *f, const sub_t *s);

/* s as it is, to the sink, when the clip box holds it; false (nothing
** sent) when not. */
bool cf__far_send_whole(const far_t *f, const sub_t *s);

/* Piece pc to the sink, from the current point (its start). */
void cf__far_send(const far_t *f, const piece_t *pc);

#endif
