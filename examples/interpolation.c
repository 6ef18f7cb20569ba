/*
** Global interpolation (The NURBS Book A9.1) of degree 3 through five
** points with chord-length parameters: the curve passes through every
** point at its parameter.
**   cc interpolation.c $(pkg-config --cflags --libs curvefig-core)
*/
#include <math.h>
#include <stdio.h>

#include <curvefig/curvefig.h>

int
main(void)
{
    static const double pts[] = { 0, 0, 1, 2, 3, 2.5, 4, 0.5, 6, 1 };
    double u[5], worst = 0.0;
    cf_interp_options_t opt;
    cf_bspline_t *c = NULL;
    cf_diag_t diag;

    cf_interp_options_init(&opt);
    opt.method = CF_INTERP_GLOBAL;
    opt.degree = 3;
    opt.param = CF_PARAM_CHORD;
    if (cf_interp_parameters(2, pts, 5, CF_PARAM_CHORD, 0.0, false, u, &diag) != CF_STATUS_OK
        || cf_interpolate(2, pts, 5, &opt, &c, &diag) != CF_STATUS_OK) {
        fprintf(stderr, "interpolation: %s\n", diag.msg);
        return 1;
    }
    for (int i = 0; i < 5; i++) {
        double p[2];
        if (cf_bspline_eval(c, u[i], p) != CF_STATUS_OK) {
            cf_bspline_destroy(c);
            return 1;
        }
        printf("C(%.4f) = (%.15g, %.15g)\n", u[i], p[0], p[1]);
        worst = fmax(worst, hypot(p[0] - pts[2 * i], p[1] - pts[2 * i + 1]));
    }
    printf("largest distance to a data point: %.3g\n", worst);
    cf_bspline_destroy(c);
    return worst <= 1e-13 ? 0 : 1;
}
