/*
** Which paths are cut for a device of bounded range, and the frame a cut
** keeps (render/backends/far-clip.h): the test of every path drawn
** against the safe region, and the visible box with the clip box round
** it.  The cut itself: the pieces halved (far-halve.c), a fill's chords
** (far-fill.c), a stroke's runs (far-stroke.c) and its dashes
** (far-dash.c).
*/
#include <math.h>

#include "far-clip-private.h"

/* The frame of a path beyond the safe region: the visible box (the clip's
** extents, which lie on the device: a page or a raster) and how far
** beyond it a cut may go (CF__FAR_GROW device units); false when m is not
** a scale and a shift, or the visible box lies beyond the device's
** page. */
bool
cf__far_frame(const cf__far_ctm_t *m, const double ext[4],
              cf__far_frame_t *fr)
{
    double d[4];
    if (m->xy != 0 || m->yx != 0 || !(m->xx != 0 && m->yy != 0))
        return false;
    d[0] = fmin(ext[0] * m->xx, ext[2] * m->xx) + m->x0;
    d[2] = fmax(ext[0] * m->xx, ext[2] * m->xx) + m->x0;
    d[1] = fmin(ext[1] * m->yy, ext[3] * m->yy) + m->y0;
    d[3] = fmax(ext[1] * m->yy, ext[3] * m->yy) + m->y0;
    if (!(d[0] >= -CF__FAR_GROW && d[1] >= -CF__FAR_GROW
          && d[2] <= CF__FAR_PAGE + CF__FAR_GROW
          && d[3] <= CF__FAR_PAGE + CF__FAR_GROW))
        return false;
    for (int i = 0; i < 4; i++)
        fr->vis[i] = ext[i];
    fr->raster = false;
    fr->grow = CF__FAR_GROW / fmax(fabs(m->xx), fabs(m->yy));
    return true;
}

/* The clip box: the visible box grown by g (user units). */
void
cf__far_boxes(const cf__far_frame_t *fr, double g, far_t *f)
{
    f->vis = (box_t){ fr->vis[0], fr->vis[1], fr->vis[2], fr->vis[3] };
    f->clip = (box_t){ fr->vis[0] - g, fr->vis[1] - g, fr->vis[2] + g,
                       fr->vis[3] + g };
}

bool
cf__far_safe(const cf__path_t *p, const cf__far_ctm_t *m)
{
    box_t b;
    const double *v = p->coords;
    double ax, bx, ay, by;
    if (m->xy != 0 || m->yx != 0 || !(m->xx != 0 && m->yy != 0))
        return true;
    /* the safe region in user units */
    ax = (CF__FAR_LO - m->x0) / m->xx;
    bx = (CF__FAR_HI - m->x0) / m->xx;
    ay = (CF__FAR_LO - m->y0) / m->yy;
    by = (CF__FAR_HI - m->y0) / m->yy;
    b = (box_t){ fmin(ax, bx), fmin(ay, by), fmax(ax, bx), fmax(ay, by) };
    for (size_t i = 0; i < p->nsegs; i++) {
        switch ((cf__seg_t)p->segs[i]) {
        case CF__SEG_MOVE:
        case CF__SEG_LINE:
            if (out_of(&b, v[0], v[1]))
                return false;
            v += 2;
            break;
        case CF__SEG_CURVE:
            if (out_of(&b, v[0], v[1]) || out_of(&b, v[2], v[3])
                || out_of(&b, v[4], v[5]))
                return false;
            v += 6;
            break;
        case CF__SEG_RECT:
            if (out_of(&b, v[0], v[1]) || out_of(&b, v[0] + v[2],
                                                 v[1] + v[3]))
                return false;
            v += 4;
            break;
        case CF__SEG_ARC:
            if (out_of(&b, v[0] - fabs(v[2]), v[1] - fabs(v[2]))
                || out_of(&b, v[0] + fabs(v[2]), v[1] + fabs(v[2])))
                return false;
            v += 5;
            break;
        case CF__SEG_CLOSE:
            break;
        }
    }
    return true;
}
