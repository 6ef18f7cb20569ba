/*
** A path of the display list's segments growing one segment at a time
** (render/dlist/pathb.c): a label's outline as its fonts give it.
*/
#ifndef CURVEFIG_RENDER_PATHB_H
#define CURVEFIG_RENDER_PATHB_H

#include <stdbool.h>
#include <stddef.h>

#include "dlist.h"

typedef struct cf__pathb {
    unsigned char *segs;
    double *coords;
    size_t nsegs, ncoords, capsegs, capcoords;
    bool failed;              /* out of memory: the path is short */
} cf__pathb_t;

/* Append a segment, its 1 (move, line) or 3 (curve) points in xy, none
** for a close.  A move after a move replaces it, as in a path of
** cairo's. */
void cf__pathb_add(cf__pathb_t *b, cf__seg_t seg, const double *xy);
/* The path as the display list's (valid while b is). */
void cf__pathb_path(const cf__pathb_t *b, cf__path_t *out);
void cf__pathb_free(cf__pathb_t *b);

#endif
