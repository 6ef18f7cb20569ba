/*
** The dash pattern of a stroke cut far away (render/backends/far-dash.c),
** for the stroke's walk (render/backends/far-stroke.c): the lengths and
** directions of pieces, the lead-ins that keep the phase, the join at the
** start of a closed outline.
*/
#ifndef CURVEFIG_RENDER_FAR_DASH_H
#define CURVEFIG_RENDER_FAR_DASH_H

#include "far-clip-private.h"

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
