/*
** The offset of a cubic at distance 0.5 as a chain of cubics within 1e-4,
** checked by the library's independent measure.
**   cc offset.c $(pkg-config --cflags --libs curvefig-core)
*/
#include <stdio.h>

#include <curvefig/curvefig.h>

int
main(void)
{
    static const double pts[] = { 0, 0, 1, 3, 3, 3, 4, 0 };
    cf_bezier_t *c = NULL;
    cf_cubics_t *raw = NULL;
    cf_offset_options_t opt;
    cf_offset_report_t rep;
    cf_diag_t diag;
    double measured = 0.0;
    int rc = 1;

    cf_offset_options_init(&opt);
    opt.tolerance = 1e-4;
    if (cf_bezier_create(2, 3, pts, NULL, &c, &diag) != CF_STATUS_OK
        || cf_bezier_offset(c, 0.5, &opt, &raw, NULL, &rep, &diag) != CF_STATUS_OK
        || cf_offset_measure(c, 0.5, raw, 200, &measured, &diag) != CF_STATUS_OK) {
        fprintf(stderr, "offset: %s\n", diag.msg);
        goto done;
    }
    printf("%zu cubics, reported error %.3g, measured %.3g (tolerance %g)\n",
           rep.segments, rep.max_error, measured, opt.tolerance);
    rc = rep.converged && measured <= opt.tolerance ? 0 : 1;
done:
    cf_cubics_destroy(raw);
    cf_bezier_destroy(c);
    return rc;
}
