/* The offset tests, continued: errors (the helpers the files share:
** test_offset.h). */
#include "test_offset.h"

/* ---- errors ------------------------------------------------------------------ */

static void
test_bad_arguments(void **state)
{
    cf_bezier_t *c = cubic(arch), *c3 = NULL, *rat = NULL;
    const double p3[12] = { 0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3 };
    const double w[4] = { 1, 2, 2, 1 };
    cf_offset_options_t opt;
    cf_cubics_t *raw = (cf_cubics_t *)&opt;   /* must be reset to NULL */
    cf_diag_t diag;
    double o[2], ts[2];
    size_t n;
    (void)state;
    assert_int_equal(cf_bezier_create(3, 3, p3, NULL, &c3, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_bezier_create(2, 3, arch, w, &rat, NULL),
                     CF_STATUS_OK);
    cf_offset_options_init(&opt);
    cf_offset_options_init(NULL);

    assert_int_equal(cf_offset_point(NULL, 0.5, 1, o), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_offset_point(c, 0.5, 1, NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_offset_point(c3, 0.5, 1, o), CF_STATUS_DIM_MISMATCH);
    assert_int_equal(cf_offset_point(c, 1.5, 1, o), CF_STATUS_DOMAIN);
    assert_int_equal(cf_offset_point(c, NAN, 1, o), CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_offset_point(c, 0.5, INFINITY, o),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_offset_point_many(c, NULL, 2, 1, o),
                     CF_STATUS_INVALID_ARG);

    cf_diag_clear(&diag);
    assert_int_equal(cf_offset_cusps(NULL, 1, ts, 2, &n, &diag),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_offset_cusps(c, 1, NULL, 2, &n, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_offset_cusps(c, 1, ts, 2, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    cf_diag_clear(&diag);
    assert_int_equal(cf_offset_cusps(c3, 1, ts, 2, &n, &diag),
                     CF_STATUS_DIM_MISMATCH);
    assert_non_null(strstr(diag.msg, "dim 3"));
    assert_int_equal(cf_offset_cusps(c, NAN, ts, 2, &n, NULL),
                     CF_STATUS_NOT_FINITE);

    assert_int_equal(cf_bezier_offset(NULL, 1, &opt, &raw, NULL, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    raw = (cf_cubics_t *)&opt;
    assert_int_equal(cf_bezier_offset(c3, 1, &opt, &raw, NULL, NULL, NULL),
                     CF_STATUS_DIM_MISMATCH);
    assert_null(raw);
    assert_int_equal(cf_bezier_offset(c, NAN, &opt, &raw, NULL, NULL, NULL),
                     CF_STATUS_NOT_FINITE);
    opt.tolerance = 0.0;
    cf_diag_clear(&diag);
    assert_int_equal(cf_bezier_offset(c, 1, &opt, &raw, NULL, NULL, &diag),
                     CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(diag.msg, "tolerance"));
    opt.tolerance = NAN;
    assert_int_equal(cf_bezier_offset(c, 1, &opt, &raw, NULL, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    /* a tolerance doubles cannot resolve at the offset's size (4096 ulps
    ** of it): refused at once, where the cover would never end; just
    ** above that floor the offset is computed */
    cf_offset_options_init(&opt);
    cf_diag_clear(&diag);
    assert_int_equal(cf_bezier_offset(c, 1e14, &opt, &raw, NULL, NULL,
                                      &diag),
                     CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(diag.msg, "below what doubles resolve"));
    assert_null(raw);
    opt.tolerance = 1.01 * 4096 * DBL_EPSILON * 1e9;
    assert_int_equal(cf_bezier_offset(c, 1e9, &opt, &raw, NULL, NULL, NULL),
                     CF_STATUS_OK);
    cf_cubics_destroy(raw);
    raw = NULL;
    opt.tolerance = 0.99 * 4096 * DBL_EPSILON * 1e9;
    assert_int_equal(cf_bezier_offset(c, 1e9, &opt, &raw, NULL, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    /* a distance whose cubes overflow, with a tolerance it could meet */
    opt.tolerance = 1e200;
    cf_diag_clear(&diag);
    assert_int_equal(cf_bezier_offset(c, 1e200, &opt, &raw, NULL, NULL,
                                      &diag),
                     CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(diag.msg, "too large"));
    cf_offset_options_init(&opt);
    opt.method = (cf_offset_method_t)7;
    assert_int_equal(cf_bezier_offset(c, 1, &opt, &raw, NULL, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    opt.method = CF_OFFSET_TILLER_HANSON;
    cf_diag_clear(&diag);
    assert_int_equal(cf_bezier_offset(rat, 1, &opt, &raw, NULL, NULL, &diag),
                     CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(diag.msg, "Tiller-Hanson"));

    assert_int_equal(cf_bezier_list_offset(NULL, 1, NULL, &raw, NULL, NULL,
                                           NULL),
                     CF_STATUS_INVALID_ARG);
    {
        cf_bezier_t *items[2] = { c, NULL };
        cf_bezier_list_t l = { 2, items, NULL, NULL };
        assert_int_equal(cf_bezier_list_offset(&l, 1, NULL, &raw, NULL, NULL,
                                               NULL),
                         CF_STATUS_INVALID_ARG);
    }
    assert_int_equal(cf_bspline_offset(NULL, 1, NULL, &raw, NULL, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    {
        double m;
        cf_cubics_t empty = { 2, 0, NULL, NULL, 0.0 };
        assert_int_equal(cf_offset_measure(NULL, 1, &empty, 100, &m, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_offset_measure(c, 1, NULL, 100, &m, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_offset_measure(c, 1, &empty, 3, &m, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_offset_measure(c, 1, &empty, 100, &m, NULL),
                         CF_STATUS_OK);
        assert_true(m == 0.0);
    }
    cf_cubics_list_destroy(NULL);
    cf_bezier_destroy(c);
    cf_bezier_destroy(c3);
    cf_bezier_destroy(rat);
}

static void
test_out_of_memory(void **state)
{
    /* fail the k-th allocation for every k until the call succeeds: no
    ** crash, no leak, NO_MEMORY until then */
    cf_bezier_t *c = cubic(arch);
    cf_offset_options_t opt;
    long live0;
    (void)state;
    /* a short run through every path: cusps, trimming, a B-spline-like
    ** list with a join, Tiller-Hanson with degree raising */
    const double la[6] = { 0, 0, 5, 3, 10, 0 }, lb[4] = { 10, 0, 10, 10 };
    cf_bezier_t *items[2] = { NULL, NULL };
    cf_bezier_list_t list = { 2, items, NULL, NULL };
    cf_offset_options_t tho;
    assert_int_equal(cf_bezier_create(2, 2, la, NULL, &items[0], NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_bezier_create(2, 1, lb, NULL, &items[1], NULL),
                     CF_STATUS_OK);
    cf_offset_options_init(&opt);
    opt.tolerance = 1.0;
    opt.trim = true;
    cf_offset_options_init(&tho);
    tho.tolerance = 0.5;
    tho.method = CF_OFFSET_TILLER_HANSON;
    live0 = tu_alloc_live();
    for (long k = 1; k < 10000; k++) {
        cf_cubics_t *raw = NULL, *raw2 = NULL;
        cf_cubics_list_t *tr = NULL;
        cf_status_t st;
        size_t n;
        double ts[4];
        tu_fail_alloc_after(k);
        st = cf_bezier_offset(c, -45.0, &opt, &raw, &tr, NULL, NULL);
        if (st == CF_STATUS_OK)
            st = cf_offset_cusps(c, -45.0, ts, 4, &n, NULL);
        if (st == CF_STATUS_OK)
            st = cf_bezier_list_offset(&list, 2.0, &tho, &raw2, NULL, NULL,
                                       NULL);
        if (st != CF_STATUS_OK && raw == NULL) {
            assert_int_equal(st, CF_STATUS_NO_MEMORY);
            assert_null(tr);
        }
        cf_cubics_destroy(raw);
        cf_cubics_destroy(raw2);
        cf_cubics_list_destroy(tr);
        assert_int_equal(tu_alloc_live(), live0);
        tu_fail_alloc_reset();
        if (st == CF_STATUS_OK)
            break;
        assert_int_equal(st, CF_STATUS_NO_MEMORY);
    }
    cf_bezier_destroy(c);
    cf_bezier_destroy(items[0]);
    cf_bezier_destroy(items[1]);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bad_arguments),
        cmocka_unit_test(test_out_of_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
