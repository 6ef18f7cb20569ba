/*
** A NURBS circle, exact: every point lies at distance r from the centre,
** up to rounding.  Build against the installed library with
**   cc nurbs-circle.c $(pkg-config --cflags --libs curvefig-core)
*/
#include <math.h>
#include <stdio.h>

#include <curvefig/curvefig.h>

int
main(void)
{
    const double centre[2] = { 1.0, -2.0 }, r = 3.0;
    cf_bspline_t *circle = NULL;
    cf_diag_t diag;
    double a, b, worst = 0.0;

    if (cf_nurbs_circle(centre, r, &circle, &diag) != CF_STATUS_OK) {
        fprintf(stderr, "nurbs-circle: %s\n", diag.msg);
        return 1;
    }
    cf_bspline_domain(circle, &a, &b);
    for (int i = 0; i <= 1000; i++) {
        double u = a + (b - a) * i / 1000.0, p[2];
        if (cf_bspline_eval(circle, u, p) != CF_STATUS_OK) {
            fprintf(stderr, "nurbs-circle: evaluation at u = %g failed\n", u);
            cf_bspline_destroy(circle);
            return 1;
        }
        worst = fmax(worst, fabs(hypot(p[0] - centre[0], p[1] - centre[1]) - r));
    }
    printf("degree %d, %zu control points, rational: %s\n",
           cf_bspline_degree(circle), cf_bspline_count(circle),
           cf_bspline_is_rational(circle) ? "yes" : "no");
    printf("largest | |C(u) - centre| - r | over 1001 parameters: %.3g\n", worst);
    cf_bspline_destroy(circle);
    /* exact up to rounding: a few ulps of r */
    return worst <= 8 * 2.220446049250313e-16 * r ? 0 : 1;
}
