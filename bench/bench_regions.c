/*
** Regions in space (cf_figure_add_space_hull, cf_figure_add_space_fill):
** the hull of n points on a sphere and in a cube, a filled star-shaped
** polygon of n points in a plane and one bent out of it; the median of 5
** runs each (3 from 100,000 points), in milliseconds, at the sizes given
** (default 2000, 16000 and 200000).  Each run makes a figure, adds the
** region (its triangles: Quickhull or ear clipping, and the outline) and
** destroys it; drawing is not timed.  Public API only, so the same source
** times any build:
**
**   cc -O2 -Iinclude bench/bench_regions.c -Lbuild/render -Lbuild/src \
**      -lcurvefig-render -lcurvefig-core -lm \
**      -Wl,-rpath,$PWD/build/render:$PWD/build/src
*/
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench-time.h"
#include "curvefig/figure.h"
#include "curvefig/figure3d.h"

static uint64_t rng = 0x2545f4914f6cdd1du;

static double
uniform(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) * 0x1p-53;
}

enum { SPHERE, CUBE, STAR, BENT };
static const char *const names[] = {
    "hull, points on a sphere", "hull, points in a cube",
    "fill, star in a plane", "fill, star bent out of it"
};

static void
points(int kind, size_t n, double *p)
{
    for (size_t i = 0; i < n; i++) {
        double *x = p + 3 * i, t = 6.283185307179586 * (double)i / (double)n;
        double r = 1 + 0.3 * sin(37 * t), z;
        switch (kind) {
        case SPHERE:
            z = 2 * uniform() - 1;
            t = 6.283185307179586 * uniform();
            x[0] = sqrt(1 - z * z) * cos(t);
            x[1] = sqrt(1 - z * z) * sin(t);
            x[2] = z;
            break;
        case CUBE:
            for (int k = 0; k < 3; k++)
                x[k] = 2 * uniform() - 1;
            break;
        default:
            x[0] = r * cos(t);
            x[1] = r * sin(t);
            x[2] = kind == STAR ? 0.5 * x[0] : 0.2 * sin(5 * t);
            break;
        }
    }
}

/* One run: seconds. */
static double
one(int kind, const double *p, size_t n)
{
    cf_figure_t *fig = NULL;
    cf_view_t v;
    cf_diag_t d;
    double t0;
    cf_status_t st;
    cf_diag_clear(&d);
    if (cf_figure_create(60, 40, CF_UNIT_MM, &fig, &d) != CF_STATUS_OK
        || cf_view_orthographic(&v, 30, 20, &d) != CF_STATUS_OK
        || cf_figure_set_view(fig, &v) != CF_STATUS_OK) {
        fprintf(stderr, "bench-regions: %s\n", d.msg);
        exit(1);
    }
    t0 = now_s();
    st = kind <= CUBE
        ? cf_figure_add_space_hull(fig, p, n, CF_HIDDEN_SHOW, NULL)
        : cf_figure_add_space_fill(fig, p, n, CF_HIDDEN_SHOW, NULL);
    t0 = now_s() - t0;
    if (st != CF_STATUS_OK) {
        cf_figure_status(fig, &d);
        fprintf(stderr, "bench-regions: %s\n", d.msg);
        exit(1);
    }
    cf_figure_destroy(fig);
    return t0;
}

int
main(int argc, char **argv)
{
    size_t def[] = { 2000, 16000, 200000 }, nsz = argc > 1
        ? (size_t)argc - 1 : sizeof def / sizeof def[0];
    for (size_t s = 0; s < nsz; s++) {
        size_t n = argc > 1 ? strtoul(argv[s + 1], NULL, 10) : def[s];
        double *p = malloc(3 * (n > 4 ? n : 4) * sizeof *p);
        int runs = n >= 100000 ? 3 : 5;
        if (p == NULL || n < 4)
            return 1;
        for (int kind = SPHERE; kind <= BENT; kind++) {
            double t[5];
            points(kind, n, p);
            for (int r = 0; r < runs; r++)
                t[r] = one(kind, p, n);
            qsort(t, (size_t)runs, sizeof t[0], cmp_double);
            printf("%-28s %7zu points  median %9.2f ms  (min %.2f, max "
                   "%.2f)\n", names[kind], n, 1e3 * t[runs / 2], 1e3 * t[0],
                   1e3 * t[runs - 1]);
            fflush(stdout);
        }
        free(p);
    }
    return 0;
}
