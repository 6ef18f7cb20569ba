/*
** Exact boxes of the display list's paths (render/dlist/dlist.h): curves
** and arcs by their extremes, as cairo's recording surface measures the
** ink of a fill.  The rasterizer (render/backends/raster.c) measures with
** them, and a label keeps its outline's box (render/labels/label.c).
*/
#include <math.h>
#include <stdbool.h>

#include "dlist.h"

#define PI 3.14159265358979323846

bool
cf__arc_range(const double *v, double *a0, double *a1)
{
    *a0 = v[3];
    *a1 = v[4];
    if (!(isfinite(*a0) && isfinite(*a1) && fabs(*a0) < 1e6
          && fabs(*a1) < 1e6))
        return false;
    if (*a1 < *a0)
        *a1 += 2 * PI * ceil((*a0 - *a1) / (2 * PI));
    return *a1 - *a0 < 1e3;
}

/* The extremes of one coordinate of a cubic p0..p3 grown into lo, hi. */
static void
cubic_range(double p0, double p1, double p2, double p3, double *lo,
            double *hi)
{
    /* B'(t)/3 = a t^2 + b t + c */
    double a = -p0 + 3 * p1 - 3 * p2 + p3, b = 2 * (p0 - 2 * p1 + p2);
    double c = p1 - p0, t[2];
    int k, n = 0;
    *lo = fmin(*lo, fmin(p0, p3));
    *hi = fmax(*hi, fmax(p0, p3));
    if (fabs(a) < 1e-12 * (fabs(b) + fabs(c))) {
        if (b != 0)
            t[n++] = -c / b;
    } else {
        double d = b * b - 4 * a * c;
        if (d >= 0) {
            double q = -0.5 * (b + copysign(sqrt(d), b));
            t[n++] = q / a;
            if (q != 0)
                t[n++] = c / q;
        }
    }
    for (k = 0; k < n; k++)
        if (t[k] > 0 && t[k] < 1) {
            double s = 1 - t[k];
            double v = s * s * s * p0 + 3 * s * s * t[k] * p1
                     + 3 * s * t[k] * t[k] * p2 + t[k] * t[k] * t[k] * p3;
            *lo = fmin(*lo, v);
            *hi = fmax(*hi, v);
        }
}

static void
arc_box(const double *v, double scale, double dx, double dy,
        double box[4])
{
    double cx = v[0] * scale + dx, cy = v[1] * scale + dy;
    double r = fabs(v[2]) * scale, a0, a1, q;
    int k;
    if (!cf__arc_range(v, &a0, &a1))
        return;
    cf__box_grow(box, cx + r * cos(a0), cy + r * sin(a0));
    cf__box_grow(box, cx + r * cos(a1), cy + r * sin(a1));
    /* the points on the axes the arc passes (quarter turns) */
    for (q = ceil(a0 / (PI / 2)), k = 0; q * (PI / 2) <= a1 && k < 5;
         q++, k++) {
        int quarter = (int)fmod(fmod(q, 4) + 4, 4);
        cf__box_grow(box, cx + (quarter == 0 ? r : quarter == 2 ? -r : 0),
                 cy + (quarter == 1 ? r : quarter == 3 ? -r : 0));
    }
}

void
cf__path_box(const cf__path_t *p, double scale, double dx, double dy,
             double box[4])
{
    const double *v = p->coords;
    double cx = 0, cy = 0, sx = 0, sy = 0;
    bool cur = false, moved = false;   /* moved: a move not yet drawn from */
    size_t i;
    for (i = 0; i < p->nsegs; i++) {
        double x = 0, y = 0;
        cf__seg_t seg = (cf__seg_t)p->segs[i];
        if (seg != CF__SEG_CLOSE) {
            x = v[0] * scale + dx;
            y = v[1] * scale + dy;
        }
        if (moved && (seg == CF__SEG_LINE || seg == CF__SEG_CURVE
                      || seg == CF__SEG_ARC))
            cf__box_grow(box, cx, cy);
        moved = seg == CF__SEG_MOVE;
        switch (seg) {
        case CF__SEG_MOVE:
        case CF__SEG_LINE:
            if (seg == CF__SEG_LINE)
                cf__box_grow(box, x, y);
            if (seg == CF__SEG_MOVE || !cur) {
                sx = x;
                sy = y;
            }
            cx = x;
            cy = y;
            v += 2;
            break;
        case CF__SEG_CURVE: {
            double x2 = v[2] * scale + dx, y2 = v[3] * scale + dy;
            double x3 = v[4] * scale + dx, y3 = v[5] * scale + dy;
            double lo[2], hi[2];
            if (!cur) {
                cx = sx = x;
                cy = sy = y;
                cf__box_grow(box, x, y);
            }
            lo[0] = hi[0] = cx;
            lo[1] = hi[1] = cy;
            cubic_range(cx, x, x2, x3, &lo[0], &hi[0]);
            cubic_range(cy, y, y2, y3, &lo[1], &hi[1]);
            cf__box_grow(box, lo[0], lo[1]);
            cf__box_grow(box, hi[0], hi[1]);
            cx = x3;
            cy = y3;
            v += 6;
            break;
        }
        case CF__SEG_RECT:
            cf__box_grow(box, x, y);
            cf__box_grow(box, x + v[2] * scale, y + v[3] * scale);
            cx = sx = x;
            cy = sy = y;
            v += 4;
            break;
        case CF__SEG_ARC: {
            double a0, a1, r = fabs(v[2]) * scale;
            arc_box(v, scale, dx, dy, box);
            if (cf__arc_range(v, &a0, &a1)) {
                if (!cur) {
                    sx = x + r * cos(a0);
                    sy = y + r * sin(a0);
                }
                cx = x + r * cos(a1);
                cy = y + r * sin(a1);
            }
            v += 5;
            break;
        }
        case CF__SEG_CLOSE:
            cx = sx;
            cy = sy;
            break;
        }
        cur = true;
    }
}

/* The length of the line from (x0, y0) to (x1, y1). */
static double
dist(double x0, double y0, double x1, double y1)
{
    return hypot(x1 - x0, y1 - y0);
}

double
cf__path_length_bound(const cf__path_t *p, double scale)
{
    const double *v = p->coords;
    double len = 0, cx = 0, cy = 0, sx = 0, sy = 0, a0, a1;
    bool cur = false;
    size_t i;
    for (i = 0; i < p->nsegs; i++) {
        switch ((cf__seg_t)p->segs[i]) {
        case CF__SEG_MOVE:
            cx = sx = v[0];
            cy = sy = v[1];
            v += 2;
            break;
        case CF__SEG_LINE:
            if (cur)
                len += dist(cx, cy, v[0], v[1]);
            else
                sx = v[0], sy = v[1];
            cx = v[0];
            cy = v[1];
            v += 2;
            break;
        case CF__SEG_CURVE:
            /* the control polygon: never shorter than the curve */
            if (cur)
                len += dist(cx, cy, v[0], v[1]);
            else
                sx = v[0], sy = v[1];
            len += dist(v[0], v[1], v[2], v[3])
                 + dist(v[2], v[3], v[4], v[5]);
            cx = v[4];
            cy = v[5];
            v += 6;
            break;
        case CF__SEG_RECT:
            len += 2 * (fabs(v[2]) + fabs(v[3]));
            cx = sx = v[0];
            cy = sy = v[1];
            v += 4;
            break;
        case CF__SEG_ARC:
            if (!cf__arc_range(v, &a0, &a1))
                return INFINITY;
            if (cur)
                len += dist(cx, cy, v[0] + fabs(v[2]) * cos(a0),
                            v[1] + fabs(v[2]) * sin(a0));
            len += fabs(v[2]) * (a1 - a0);
            cx = v[0] + fabs(v[2]) * cos(a1);
            cy = v[1] + fabs(v[2]) * sin(a1);
            if (!cur) {
                sx = v[0] + fabs(v[2]) * cos(a0);
                sy = v[1] + fabs(v[2]) * sin(a0);
            }
            v += 5;
            break;
        case CF__SEG_CLOSE:
            len += dist(cx, cy, sx, sy);
            cx = sx;
            cy = sy;
            break;
        }
        cur = true;
    }
    return len * fabs(scale);
}
