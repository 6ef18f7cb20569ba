/*
** Overlay specifications in beamer's syntax: the steps on which an
** element is shown.  A specification is a comma-separated list of
** ranges, each "N" (step N), "N-M" (N to M), "N-" (N to the last) or
** "-M" (1 to M), with steps counted from 1; "2", "1-3", "2-", "2,4-".
** The layer below the display list's players (render/backend.c) and the
** figure (render/overlay.c).
*/
#ifndef CURVEFIG_RENDER_OVERLAY_SPEC_H
#define CURVEFIG_RENDER_OVERLAY_SPEC_H

#include <stdbool.h>
#include <stddef.h>

/* The largest step a specification may name. */
#define CF__OVERLAY_MAX_STEP 999u

/* Check spec.  0 when valid, with *last the largest step it names (an
** open range "N-" counts N); else -1 with what is wrong in why (cap
** bytes, e.g. "step 0: steps count from 1"). */
int cf__overlay_parse(const char *spec, unsigned *last, char *why,
                      size_t cap);

/* Whether a valid spec (NULL: every step) shows step k (>= 1). */
bool cf__overlay_visible(const char *spec, unsigned k);

#endif
