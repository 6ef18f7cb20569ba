/*
** A path growing one segment at a time (render/dlist/pathb.h).
*/
#include <string.h>

#include "curvefig/core.h"
#include "grow.h"
#include "pathb.h"

void
cf__pathb_add(cf__pathb_t *b, cf__seg_t seg, const double *xy)
{
    size_t n = seg == CF__SEG_CURVE ? 6 : seg == CF__SEG_CLOSE ? 0 : 2;
    unsigned char *s;
    double *c;
    if (b->failed)
        return;
    if (seg == CF__SEG_MOVE && b->nsegs > 0
        && b->segs[b->nsegs - 1] == CF__SEG_MOVE) {
        memcpy(b->coords + b->ncoords - 2, xy, 2 * sizeof *xy);
        return;
    }
    s = cf__grow_array(b->segs, &b->capsegs, b->nsegs + 1, 1, 64);
    if (s != NULL)
        b->segs = s;
    c = cf__grow_array(b->coords, &b->capcoords, b->ncoords + n,
                       sizeof *c, 256);
    if (c != NULL)
        b->coords = c;
    if (s == NULL || c == NULL) {
        b->failed = true;
        return;
    }
    b->segs[b->nsegs++] = (unsigned char)seg;
    if (n > 0)
        memcpy(b->coords + b->ncoords, xy, n * sizeof *xy);
    b->ncoords += n;
}

void
cf__pathb_path(const cf__pathb_t *b, cf__path_t *out)
{
    out->segs = b->segs;
    out->coords = b->coords;
    out->nsegs = b->nsegs;
}

void
cf__pathb_free(cf__pathb_t *b)
{
    cf_free(b->segs);
    cf_free(b->coords);
    memset(b, 0, sizeof *b);
}
