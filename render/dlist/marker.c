/*
** Marker symbols as outlines (render/dlist/dlist.h): dots and circles as arcs,
** squares as rectangles, diamonds, triangles and stars as polygons,
** crosses, pluses and ticks as stroked bars.  The seam (render/backends/
** backend.c) hands a drawing backend each marker as this path with a
** paint whose caps, joins and dash are set here, so a marker looks the
** same in every format and owes nothing to what was drawn before it.
*/
#include <math.h>
#include <string.h>

#include "dlist.h"

#define PI 3.14159265358979323846

static void
put(cf__marker_shape_t *s, cf__seg_t seg, const double *v, size_t n)
{
    size_t k;
    s->segs[s->path.nsegs++] = (unsigned char)seg;
    for (k = 0; k < n; k++)
        s->coords[s->ncoords++] = v[k];
}

static void
point(cf__marker_shape_t *s, cf__seg_t seg, double x, double y)
{
    double v[2];
    v[0] = x;
    v[1] = y;
    put(s, seg, v, 2);
}

static void
regular_polygon(cf__marker_shape_t *s, double x, double y, double r, int n,
                double phase, double inner)
{
    int i, k = inner > 0 ? 2 * n : n;
    for (i = 0; i < k; i++) {
        double a = phase + 2.0 * PI * i / k;
        double rr = (inner > 0 && (i & 1)) ? inner : r;
        double px = x + rr * cos(a), py = y - rr * sin(a);
        point(s, i == 0 ? CF__SEG_MOVE : CF__SEG_LINE, px, py);
    }
    put(s, CF__SEG_CLOSE, NULL, 0);
}

bool
cf__marker_shape(const cf__marker_op_t *m, cf__marker_shape_t *s)
{
    double r = 0.5 * m->size, x = m->x, y = m->y, v[5];

    s->path.segs = s->segs;
    s->path.coords = s->coords;
    s->path.nsegs = 0;
    s->ncoords = 0;
    s->paint = CF__MARKER_FILL;
    s->line_width = 0;
    switch (m->marker) {
    case CF_MARKER_DOT:
    case CF_MARKER_CIRCLE:
        v[0] = x;
        v[1] = y;
        v[2] = m->marker == CF_MARKER_DOT ? r : r * 0.85;
        v[3] = 0;
        v[4] = 2 * PI;
        put(s, CF__SEG_ARC, v, 5);
        /* closed: a circle has no ends, so no caps */
        put(s, CF__SEG_CLOSE, NULL, 0);
        if (m->marker == CF_MARKER_CIRCLE) {
            s->paint = CF__MARKER_FILL_STROKE;
            s->line_width = fmax(0.5, 0.3 * r);
        }
        return true;
    case CF_MARKER_SQUARE:
        v[0] = x - 0.85 * r;
        v[1] = y - 0.85 * r;
        v[2] = 1.7 * r;
        v[3] = 1.7 * r;
        put(s, CF__SEG_RECT, v, 4);
        return true;
    case CF_MARKER_DIAMOND:
        regular_polygon(s, x, y, 1.1 * r, 4, PI / 2, 0);
        return true;
    case CF_MARKER_TRIANGLE:
        regular_polygon(s, x, y + 0.2 * r, 1.15 * r, 3, PI / 2, 0);
        return true;
    case CF_MARKER_STAR:
        regular_polygon(s, x, y, 1.45 * r, 5, PI / 2, 0.6 * r);
        return true;
    case CF_MARKER_CROSS:
    case CF_MARKER_PLUS: {
        double a = m->marker == CF_MARKER_CROSS ? PI / 4 : 0;
        double c = cos(a) * r, sn = sin(a) * r;
        point(s, CF__SEG_MOVE, x - c, y - sn);
        point(s, CF__SEG_LINE, x + c, y + sn);
        point(s, CF__SEG_MOVE, x + sn, y - c);
        point(s, CF__SEG_LINE, x - sn, y + c);
        s->paint = CF__MARKER_STROKE;
        s->line_width = fmax(0.6, 0.28 * r);
        return true;
    }
    case CF_MARKER_TICK: {
        /* a bar across the curve: perpendicular to dir (page coords) */
        double nx = 0, ny = -1, len;
        if (m->has_dir) {
            len = hypot(m->dir[0], m->dir[1]);
            if (len > 0) {
                nx = -m->dir[1] / len;
                ny = m->dir[0] / len;
            }
        }
        point(s, CF__SEG_MOVE, x - nx * r, y - ny * r);
        point(s, CF__SEG_LINE, x + nx * r, y + ny * r);
        s->paint = CF__MARKER_STROKE;
        s->line_width = fmax(0.5, m->width);
        return true;
    }
    default:
        return false;
    }
}

bool
cf__marker_paint(const cf__marker_op_t *m, cf__marker_shape_t *s,
                 cf__paint_t *paint)
{
    if (!cf__marker_shape(m, s))
        return false;
    memset(paint, 0, sizeof *paint);
    paint->fill = s->paint != CF__MARKER_STROKE;
    paint->stroke = s->paint != CF__MARKER_FILL;
    paint->fill_color = s->paint == CF__MARKER_FILL ? m->color : m->fill;
    paint->fill_opacity = m->opacity;
    paint->line.color = m->color;
    paint->line.opacity = m->opacity;
    paint->line.width = s->line_width;
    paint->line.cap = CF__CAP_BUTT;
    paint->line.join = CF__JOIN_MITER;
    paint->line.dash_count = 0;
    return true;
}
