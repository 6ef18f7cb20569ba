/*
** Knot insertion leaves the curve unchanged: insert u = 0.4 twice into a
** cubic B-spline and compare both curves at many parameters.
**   cc knot-insertion.c $(pkg-config --cflags --libs curvefig-core)
*/
#include <math.h>
#include <stdio.h>

#include <curvefig/curvefig.h>

int
main(void)
{
    static const double knots[] = { 0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1 };
    static const double pts[] = { 0, 0, 1, 2, 2, 3, 4, 3, 5, 1, 6, 0, 7, 2 };
    cf_bspline_t *c = NULL, *d = NULL;
    cf_bspline_insert_info_t info;
    cf_diag_t diag;
    double worst = 0.0;
    int rc = 1;

    if (cf_bspline_create(2, 3, knots, 11, pts, 7, NULL, &c, &diag) != CF_STATUS_OK
        || cf_bspline_insert_knot(c, 0.4, 2, &d, &info, &diag) != CF_STATUS_OK) {
        fprintf(stderr, "knot-insertion: %s\n", diag.msg);
        goto done;
    }
    printf("before: %zu points, %zu knots; after: %zu points, %zu knots\n",
           cf_bspline_count(c), cf_bspline_nknots(c), cf_bspline_count(d),
           cf_bspline_nknots(d));
    for (int i = 0; i <= 200; i++) {
        double u = i / 200.0, p[2], q[2];
        if (cf_bspline_eval(c, u, p) != CF_STATUS_OK
            || cf_bspline_eval(d, u, q) != CF_STATUS_OK)
            goto done;
        worst = fmax(worst, hypot(p[0] - q[0], p[1] - q[1]));
    }
    printf("largest distance between the two curves: %.3g\n", worst);
    rc = worst <= 1e-14 * 7.0 ? 0 : 1;   /* relative to the points' size */
done:
    cf_bspline_destroy(d);
    cf_bspline_destroy(c);
    return rc;
}
