/*
** Surfaces: an exact NURBS sphere (every point at distance r from the
** centre, Gaussian curvature 1/r^2), one of its iso-curves as a curve
** object, and a surface interpolating a grid of heights.  Build against the
** installed library with
**   cc surface.c $(pkg-config --cflags --libs curvefig-core)
*/
#include <math.h>
#include <stdio.h>

#include <curvefig/curvefig.h>

static int
sphere(void)
{
    const double c[3] = { 1.0, -2.0, 0.5 }, r = 2.0;
    cf_bspline_surface_t *s = NULL;
    cf_bspline_t *meridian = NULL;
    cf_diag_t diag;
    double worst = 0.0, K, H, x[3];

    if (cf_nurbs_sphere(c, r, &s, &diag) != CF_STATUS_OK) {
        fprintf(stderr, "surface: %s\n", diag.msg);
        return 1;
    }
    for (int i = 0; i <= 100; i++)
        for (int j = 0; j <= 100; j++) {
            double d;
            cf_bspline_surface_eval(s, i / 100.0, j / 100.0, x);
            d = sqrt((x[0] - c[0]) * (x[0] - c[0]) +
                     (x[1] - c[1]) * (x[1] - c[1]) +
                     (x[2] - c[2]) * (x[2] - c[2]));
            worst = fmax(worst, fabs(d - r));
        }
    cf_bspline_surface_curvature(s, 0.3, 0.4, &K, &H);
    /* u = 0.25 is a meridian: an exact NURBS half circle */
    cf_bspline_surface_iso(s, CF_DIR_U, 0.25, &meridian, NULL);
    cf_bspline_eval(meridian, 0.5, x);
    printf("sphere: %zu x %zu control points, largest distance error %.1e, "
           "K = %.15g (1/r^2 = %g), H = %.15g\n",
           cf_bspline_surface_count_u(s), cf_bspline_surface_count_v(s),
           worst, K, 1.0 / (r * r), H);
    printf("meridian at u = 0.25: degree %d, %zu points, equator point "
           "(%.15g, %.15g, %.15g)\n", cf_bspline_degree(meridian),
           cf_bspline_count(meridian), x[0], x[1], x[2]);
    cf_bspline_destroy(meridian);
    cf_bspline_surface_destroy(s);
    return worst <= 1e-14 * r && fabs(K - 1.0 / (r * r)) <= 1e-12 ? 0 : 1;
}

static int
heights(void)
{
    double Q[5 * 6 * 3], params[11], worst = 0.0;
    cf_interp_options_t opt;
    cf_bspline_surface_t *s = NULL;
    cf_diag_t diag;

    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 6; j++) {
            double *q = Q + (i * 6 + j) * 3;
            q[0] = i;
            q[1] = j;
            q[2] = sin(0.7 * i) * cos(0.5 * j);
        }
    cf_interp_options_init(&opt);
    opt.method = CF_INTERP_GLOBAL;
    opt.degree = 3;
    if (cf_interpolate_surface(3, Q, 5, 6, &opt, &s, params, &diag) !=
        CF_STATUS_OK) {
        fprintf(stderr, "surface: %s\n", diag.msg);
        return 1;
    }
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 6; j++) {
            double x[3];
            cf_bspline_surface_eval(s, params[i], params[5 + j], x);
            for (int k = 0; k < 3; k++)
                worst = fmax(worst, fabs(x[k] - Q[(i * 6 + j) * 3 + k]));
        }
    printf("interpolated 5 x 6 heights: bicubic, %zu x %zu control points, "
           "largest error at the data %.1e\n", cf_bspline_surface_count_u(s),
           cf_bspline_surface_count_v(s), worst);
    cf_bspline_surface_destroy(s);
    return worst <= 1e-12 ? 0 : 1;
}

int
main(void)
{
    return sphere() | heights();
}
