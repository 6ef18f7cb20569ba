/*
** Small vector arithmetic shared by the triangles of a polygon
** (region-tri.c) and of a hull (region-hull.c), both in space.
*/
#ifndef CURVEFIG_RENDER_REGION_GEOM_H
#define CURVEFIG_RENDER_REGION_GEOM_H

#include <math.h>
#include <stddef.h>
#include <string.h>

static inline void
cf__sub3(const double *a, const double *b, double *o)
{
    for (int k = 0; k < 3; k++)
        o[k] = a[k] - b[k];
}

static inline void
cf__cross3(const double *a, const double *b, double *o)
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

static inline double
cf__dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline double
cf__norm3(const double *a)
{
    return sqrt(cf__dot3(a, a));
}

/* The diagonal of the box of the n points p (3 doubles each). */
static inline double
cf__points_size(const double *p, size_t n)
{
    double lo[3], hi[3], d[3];
    memcpy(lo, p, sizeof lo);
    memcpy(hi, p, sizeof hi);
    for (size_t i = 1; i < n; i++)
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], p[3 * i + k]);
            hi[k] = fmax(hi[k], p[3 * i + k]);
        }
    cf__sub3(hi, lo, d);
    return cf__norm3(d);
}

/* The point of p farthest from a (its index; the distance in *dist). */
static inline size_t
cf__farthest(const double *p, size_t n, const double *a, double *dist)
{
    size_t best = 0;
    *dist = -1;
    for (size_t i = 0; i < n; i++) {
        double d[3], r;
        cf__sub3(p + 3 * i, a, d);
        r = cf__norm3(d);
        if (r > *dist) {
            *dist = r;
            best = i;
        }
    }
    return best;
}

/* The point of p farthest from the line a b. */
static inline size_t
cf__farthest_line(const double *p, size_t n, const double *a,
                  const double *b, double *dist)
{
    double ab[3], d[3], c[3], l;
    size_t best = 0;
    cf__sub3(b, a, ab);
    l = cf__norm3(ab);
    *dist = -1;
    for (size_t i = 0; i < n; i++) {
        double r;
        cf__sub3(p + 3 * i, a, d);
        cf__cross3(ab, d, c);
        r = cf__norm3(c) / l;
        if (r > *dist) {
            *dist = r;
            best = i;
        }
    }
    return best;
}

#endif
