/*
** An arc as cubic Béziers (render/dlist/dlist.h): the pieces the vector
** writers that have no arc of their own write (PGF, PDF).
*/
#include <math.h>

#include "dlist.h"

#define PI 3.14159265358979323846

bool
cf__arc_cubics(const double *v, void (*to)(void *ctx, const double *p,
                                           int n), void *ctx)
{
    double x = v[0], y = v[1], r = v[2], a0 = v[3], a1 = v[4], step;
    int n, i;
    if (!(a1 >= a0) && isfinite(a1) && isfinite(a0) && a0 - a1 < 1e6)
        while (a1 < a0)
            a1 += 2 * PI;
    if (!(a1 >= a0 && a1 - a0 < 1e6))
        return false;
    {
        const double p[2] = { x + r * cos(a0), y + r * sin(a0) };
        to(ctx, p, 1);
    }
    n = (int)ceil((a1 - a0) / (PI / 2) - 1e-9);
    if (n < 1)
        n = 1;
    step = (a1 - a0) / n;
    for (i = 0; i < n; i++) {
        double a = a0 + i * step, b = a + step;
        double h = 4.0 / 3.0 * tan(step / 4) * r;
        double x0 = x + r * cos(a), y0 = y + r * sin(a);
        double x3 = x + r * cos(b), y3 = y + r * sin(b);
        const double c[6] = { x0 - h * sin(a), y0 + h * cos(a),
                              x3 + h * sin(b), y3 - h * cos(b), x3, y3 };
        to(ctx, c, 3);
    }
    return true;
}
