/*
** Flat triangles of shading and the stand-ins of a mesh's triangles
** (render/dlist/dlist.h): the one place that says how a shaded facet is
** painted when it is not a gradient, for the figure's flat shading and
** for every backend that draws no mesh gradients (render/backends/
** backend.c).
*/
#include <math.h>
#include <string.h>

#include "dlist.h"

bool
cf__flat_triangle(const double *q, cf_color_t c, double opacity,
                  unsigned char *segs, double *coords, cf__path_t *path,
                  cf__paint_t *paint)
{
    double area = (q[2] - q[0]) * (q[5] - q[1]) - (q[4] - q[0]) * (q[3] - q[1]);
    if (fabs(area) < 2e-4)
        return false;
    memset(paint, 0, sizeof *paint);
    paint->fill = true;
    paint->fill_color = c;
    paint->fill_opacity = opacity;
    if (opacity >= 1.0) {
        paint->stroke = true;
        paint->line.color = c;
        paint->line.opacity = 1.0;
        paint->line.width = 0.25;
        paint->line.join = CF__JOIN_ROUND;
        paint->line.cap = CF__CAP_ROUND;
    }
    segs[0] = CF__SEG_MOVE;
    segs[1] = CF__SEG_LINE;
    segs[2] = CF__SEG_LINE;
    segs[3] = CF__SEG_CLOSE;
    memcpy(coords, q, 6 * sizeof *q);
    path->segs = segs;
    path->coords = coords;
    path->nsegs = 4;
    return true;
}

void
cf__mesh_piece(const cf__mesh_tri_t *t, int k, double *q)
{
    double mid[6];
    for (int c = 0; c < 3; c++) {
        int d = (c + 1) % 3;
        mid[2 * c] = 0.5 * (t->p[2 * c] + t->p[2 * d]);
        mid[2 * c + 1] = 0.5 * (t->p[2 * c + 1] + t->p[2 * d + 1]);
    }
    if (k == 3) {
        memcpy(q, mid, sizeof mid);
        return;
    }
    /* corner k and the midpoints of its two edges */
    int prev = (k + 2) % 3;
    q[0] = t->p[2 * k];
    q[1] = t->p[2 * k + 1];
    q[2] = mid[2 * k];
    q[3] = mid[2 * k + 1];
    q[4] = mid[2 * prev];
    q[5] = mid[2 * prev + 1];
}
