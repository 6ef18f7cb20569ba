/* The bezier tests, continued: queries and errors; out of memory (the
** helpers the files share: test_bezier.h). */
#include "test_bezier.h"

/* ---- queries and errors --------------------------------------------------- */

static void
test_queries(void **state)
{
    const double w[] = { 1, 2, 0.5, 4, 1 };
    double pts[10], ws[5];
    cf_bezier_t *c, *d;
    (void)state;
    assert_int_equal(cf_bezier_create(2, 4, seed_pts, w, &c, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_bezier_dim(c), 2);
    assert_int_equal(cf_bezier_degree(c), 4);
    assert_true(cf_bezier_is_rational(c));
    assert_true(cf_bezier_hpoints(c)[3 * 3 + 0] == 16.0);   /* w3 x3 */
    assert_true(cf_bezier_hpoints(c)[3 * 3 + 2] == 4.0);
    cf_bezier_get_points(c, pts);
    cf_bezier_get_weights(c, ws);
    assert_true(tu_max_diff(pts, seed_pts, 10) == 0.0);
    assert_true(tu_max_diff(ws, w, 5) == 0.0);
    /* the homogeneous constructor gives the same curve */
    assert_int_equal(cf_bezier_create_homogeneous(2, 4, cf_bezier_hpoints(c),
                                                  &d, NULL), CF_STATUS_OK);
    assert_true(tu_max_diff(cf_bezier_hpoints(d), cf_bezier_hpoints(c),
                            15) == 0.0);
    cf_bezier_destroy(d);
    assert_int_equal(cf_bezier_copy(c, &d, NULL), CF_STATUS_OK);
    assert_true(tu_max_diff(cf_bezier_hpoints(d), cf_bezier_hpoints(c),
                            15) == 0.0);
    cf_bezier_destroy(d);
    cf_bezier_destroy(c);
    assert_int_equal(cf_bezier_create(2, 4, seed_pts, NULL, &c, NULL),
                     CF_STATUS_OK);
    assert_false(cf_bezier_is_rational(c));
    cf_bezier_get_weights(c, ws);
    for (int i = 0; i < 5; i++)
        assert_true(ws[i] == 1.0);
    cf_bezier_destroy(c);
    /* NULL curves */
    assert_int_equal(cf_bezier_dim(NULL), 0);
    assert_int_equal(cf_bezier_degree(NULL), 0);
    assert_false(cf_bezier_is_rational(NULL));
    assert_null(cf_bezier_hpoints(NULL));
    assert_int_equal(cf_bezier_decasteljau_size(NULL), 0);
    cf_bezier_get_points(NULL, pts);
    cf_bezier_get_weights(NULL, ws);
    cf_bezier_destroy(NULL);
    cf_bezier_list_destroy(NULL);
}

static void
test_errors_construction(void **state)
{
    double bad[10];
    const double w[] = { 1, 2, 3, -0.5, 1 };
    cf_bezier_t *c = (cf_bezier_t *)&c;
    cf_diag_t d;
    (void)state;
    memcpy(bad, seed_pts, sizeof bad);
    bad[7] = NAN;

    cf_diag_clear(&d);
    assert_int_equal(cf_bezier_create(2, 4, seed_pts, NULL, NULL, &d),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_create(0, 4, seed_pts, NULL, &c, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_null(c);
    assert_int_equal(cf_bezier_create(2, -1, seed_pts, NULL, &c, NULL),
                     CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bezier_create(2, CF_BEZIER_MAX_DEGREE + 1, seed_pts,
                                      NULL, &c, NULL), CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bezier_create(2, 4, NULL, NULL, &c, NULL),
                     CF_STATUS_INVALID_ARG);
    cf_diag_clear(&d);
    assert_int_equal(cf_bezier_create(2, 4, bad, NULL, &c, &d),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(d.index, 3);
    assert_non_null(strstr(d.msg, "point P_3"));
    cf_diag_clear(&d);
    assert_int_equal(cf_bezier_create(2, 4, seed_pts, w, &c, &d),
                     CF_STATUS_BAD_WEIGHT);
    assert_int_equal(d.index, 3);
    assert_string_equal(d.msg, "weight w_3 is -0.5; weights must be finite "
                               "and positive");
    {
        const double w0[] = { 1, 0, 1, 1, 1 };
        const double winf[] = { 1, 1, INFINITY, 1, 1 };
        const double huge[] = { 1e300, 0, 1, 1 };
        const double wbig[] = { 1e300, 1 };
        assert_int_equal(cf_bezier_create(2, 4, seed_pts, w0, &c, NULL),
                         CF_STATUS_BAD_WEIGHT);
        assert_int_equal(cf_bezier_create(2, 4, seed_pts, winf, &c, NULL),
                         CF_STATUS_BAD_WEIGHT);
        /* w x overflows */
        assert_int_equal(cf_bezier_create(2, 1, huge, wbig, &c, NULL),
                         CF_STATUS_NOT_FINITE);
    }
    /* homogeneous: weight (last coordinate) <= 0 names the index */
    {
        const double h[] = { 0, 0, 1, 1, 1, -2 };
        cf_diag_clear(&d);
        assert_int_equal(cf_bezier_create_homogeneous(2, 1, h, &c, &d),
                         CF_STATUS_BAD_WEIGHT);
        assert_int_equal(d.index, 1);
        assert_non_null(strstr(d.msg, "weight w_1 is -2"));
        assert_int_equal(cf_bezier_create_homogeneous(0, 1, h, &c, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bezier_create_homogeneous(2, 1, NULL, &c, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bezier_create_homogeneous(2, -3, h, &c, NULL),
                         CF_STATUS_BAD_DEGREE);
        assert_int_equal(cf_bezier_create_homogeneous(2, 1, h, NULL, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bezier_create_homogeneous(2, 2, bad, &c, NULL),
                         CF_STATUS_NOT_FINITE);
    }
    assert_int_equal(cf_bezier_copy(NULL, &c, NULL), CF_STATUS_INVALID_ARG);
    assert_null(c);
    assert_int_equal(cf_bezier_copy(NULL, NULL, NULL), CF_STATUS_INVALID_ARG);
}

/* Differences of coordinates near DBL_MAX overflow: the derivative is
** refused with the point named, never returned with infinite points. */
static void
test_derivative_overflow_refused(void **state)
{
    const double huge_pts[] = { -1.7e308, 0.0, 1.7e308, 0.0 };
    const double w[] = { 1.0, 1.0 };   /* larger weights overflow w x */
    cf_bezier_t *c = NULL, *d = (cf_bezier_t *)&d;
    cf_diag_t diag;
    (void)state;
    assert_int_equal(cf_bezier_create(2, 1, huge_pts, NULL, &c, NULL),
                     CF_STATUS_OK);
    cf_diag_clear(&diag);
    assert_int_equal(cf_bezier_derivative(c, 1, &d, &diag),
                     CF_STATUS_NOT_FINITE);
    assert_null(d);
    assert_string_equal(diag.msg, "control point 0 overflows "
                                  "(coordinate 1 is inf)");
    cf_bezier_destroy(c);
    /* the rational path too (its numerator has the same differences) */
    assert_int_equal(cf_bezier_create(2, 1, huge_pts, w, &c, NULL), CF_STATUS_OK);
    d = (cf_bezier_t *)&d;
    assert_int_equal(cf_bezier_derivative(c, 1, &d, NULL),
                     CF_STATUS_NOT_FINITE);
    assert_null(d);
    cf_bezier_destroy(c);
    /* a large but representable derivative is fine */
    {
        const double ok[] = { -1e300, 0.0, 1e300, 0.0 };
        assert_int_equal(cf_bezier_create(2, 1, ok, NULL, &c, NULL),
                         CF_STATUS_OK);
        assert_int_equal(cf_bezier_derivative(c, 1, &d, NULL), CF_STATUS_OK);
        cf_bezier_destroy(d);
        cf_bezier_destroy(c);
    }
}

static void
test_errors_operations(void **state)
{
    double out[64], t[2] = { 0.5, 1.5 }, A[4] = { 1, 0, 0, 1 };
    cf_bezier_t *c, *o = (cf_bezier_t *)&o, *o2;
    cf_cubics_t *cu;
    cf_diag_t d;
    (void)state;
    assert_int_equal(cf_bezier_create(2, 4, seed_pts, NULL, &c, NULL),
                     CF_STATUS_OK);
    /* evaluation: NULL, t outside [0, 1], NaN */
    assert_int_equal(cf_bezier_eval(NULL, 0.5, out), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_eval(c, 0.5, NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_eval(c, -0.01, out), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_eval(c, 1.01, out), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_eval(c, NAN, out), CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bezier_eval(c, INFINITY, out), CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bezier_eval(c, 0.0, out), CF_STATUS_OK);
    assert_true(out[0] == 0.0 && out[1] == 5.0);
    assert_int_equal(cf_bezier_eval(c, 1.0, out), CF_STATUS_OK);
    assert_true(out[0] == 6.0 && out[1] == 10.0);
    assert_int_equal(cf_bezier_eval_many(c, t, 2, out), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_eval_many(c, NULL, 2, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_eval_many(c, t, 1, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_eval_many(NULL, t, 1, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_eval_many(c, NULL, 0, NULL), CF_STATUS_OK);
    assert_int_equal(cf_bezier_eval_derivs(c, 0.5, -1, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_eval_derivs(c, 0.5, CF_BEZIER_MAX_DEGREE + 1,
                                           out), CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bezier_eval_derivs(c, 2.0, 1, out), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_eval_derivs(NULL, 0.5, 1, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_eval_deriv_many(c, t, 2, 1, out),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_eval_deriv_many(c, t, 1, -1, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_eval_deriv_many(c, NULL, 1, 1, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_eval_deriv_many(c, t, 1,
                                               CF_BEZIER_MAX_DEGREE + 1, out),
                     CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bezier_decasteljau(c, -1.0, out), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_decasteljau(NULL, 0.5, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_decasteljau(c, 0.5, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_tangent(c, 1.5, out), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_tangent(NULL, 0.5, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_normal(c, NAN, out), CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bezier_normal(NULL, 0.5, out), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_curvature(c, -2, out), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_curvature(c, 0.5, NULL),
                     CF_STATUS_INVALID_ARG);
    /* split at 0 or 1 (open interval), NaN, NULL */
    cf_diag_clear(&d);
    assert_int_equal(cf_bezier_split(c, 0.0, &o, &o2, &d), CF_STATUS_DOMAIN);
    assert_null(o);
    assert_non_null(strstr(d.msg, "split parameter 0"));
    assert_int_equal(cf_bezier_split(c, 1.0, &o, &o2, NULL),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_split(c, NAN, &o, &o2, NULL),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bezier_split(NULL, 0.5, &o, &o2, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_split(c, 0.5, NULL, NULL, NULL), CF_STATUS_OK);
    assert_int_equal(cf_bezier_split_into(c, 0.0, out, out + 10),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_split_into(c, 1.0, out, out + 10),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_split_into(c, NAN, out, out + 10),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bezier_split_into(c, 0.5, NULL, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_split_into(c, 0.5, out, out),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_split_into(NULL, 0.5, out, out + 10),
                     CF_STATUS_INVALID_ARG);
    /* segment: order and range of the bounds */
    assert_int_equal(cf_bezier_segment(c, 0.5, 0.5, &o, NULL),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_segment(c, -0.1, 0.5, &o, NULL),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_segment(c, 0.1, 1.5, &o, NULL),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_bezier_segment(c, NAN, 0.5, &o, NULL),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bezier_segment(NULL, 0.1, 0.5, &o, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_segment(c, 0.1, 0.5, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    /* reverse, transform, elevate, derivative, to_cubics */
    assert_int_equal(cf_bezier_reverse(NULL, &o, NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_reverse(c, NULL, NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_transform(c, NULL, NULL, &o, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_transform(NULL, A, NULL, &o, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_transform(c, A, NULL, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    A[3] = NAN;
    assert_int_equal(cf_bezier_transform(c, A, NULL, &o, NULL),
                     CF_STATUS_NOT_FINITE);
    A[3] = 1e308;   /* 10 * 1e308 overflows */
    assert_int_equal(cf_bezier_transform(c, A, (double[]){ 0, 1e300 }, &o,
                                         NULL), CF_STATUS_NOT_FINITE);
    A[3] = 1;
    assert_int_equal(cf_bezier_transform(c, A, (double[]){ 0, INFINITY }, &o,
                                         NULL), CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bezier_elevate(c, -1, &o, NULL),
                     CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bezier_elevate(c, CF_BEZIER_MAX_DEGREE, &o, NULL),
                     CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bezier_elevate(NULL, 1, &o, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_elevate(c, 1, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_derivative(c, -1, &o, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_derivative(NULL, 1, &o, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_derivative(c, 1, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    cf_diag_clear(&d);
    assert_int_equal(cf_bezier_to_cubics(c, 0.0, &cu, &d),
                     CF_STATUS_INVALID_ARG);
    assert_non_null(strstr(d.msg, "tolerance"));
    assert_int_equal(cf_bezier_to_cubics(c, NAN, &cu, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_to_cubics(NULL, 1e-3, &cu, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bezier_to_cubics(c, 1e-3, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    cf_bezier_destroy(c);
    /* normal in 1D, rational derivative of too high a degree */
    {
        const double p1[] = { 0, 1, 3 };
        const double w[] = { 1, 1, 1 };
        double hp[(CF_BEZIER_MAX_DEGREE / 2 + 2) * 2];
        assert_int_equal(cf_bezier_create(1, 2, p1, NULL, &c, NULL),
                         CF_STATUS_OK);
        assert_int_equal(cf_bezier_normal(c, 0.5, out),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bezier_curvature(c, 0.5, out), CF_STATUS_OK);
        assert_true(out[0] == 0.0);
        cf_bezier_destroy(c);
        assert_int_equal(cf_bezier_create(1, 2, p1, w, &c, NULL),
                         CF_STATUS_OK);
        assert_int_equal(cf_bezier_derivative(c, 10, &o, NULL),
                         CF_STATUS_BAD_DEGREE);
        cf_bezier_destroy(c);
        for (size_t i = 0; i < sizeof hp / sizeof hp[0]; i++)
            hp[i] = 1.0;
        assert_int_equal(cf_bezier_create_homogeneous(
                             1, CF_BEZIER_MAX_DEGREE / 2 + 1, hp, &c, NULL),
                         CF_STATUS_OK);
        cf_diag_clear(&d);
        assert_int_equal(cf_bezier_derivative(c, 1, &o, &d),
                         CF_STATUS_BAD_DEGREE);
        assert_non_null(strstr(d.msg, "degree"));
        cf_bezier_destroy(c);
    }
}

/* ---- out of memory ---------------------------------------------------------- */

typedef cf_status_t (*op_fn)(const cf_bezier_t *c, void **res);

static cf_status_t
op_create(const cf_bezier_t *c, void **res)
{
    const double w[] = { 1, 2, 3, 4, 5 };
    (void)c;
    return cf_bezier_create(2, 4, seed_pts, w, (cf_bezier_t **)res, NULL);
}

static cf_status_t
op_split(const cf_bezier_t *c, void **res)
{
    cf_bezier_t *l = NULL, *r = NULL;
    cf_status_t st = cf_bezier_split(c, 0.3, &l, &r, NULL);
    if (st == CF_STATUS_OK) {
        assert_non_null(l);
        assert_non_null(r);
        cf_bezier_destroy(l);
        *res = r;
    } else {
        assert_null(l);
        assert_null(r);
    }
    return st;
}

static cf_status_t
op_elevate(const cf_bezier_t *c, void **res)
{
    return cf_bezier_elevate(c, 3, (cf_bezier_t **)res, NULL);
}

static cf_status_t
op_derivative(const cf_bezier_t *c, void **res)
{
    return cf_bezier_derivative(c, 2, (cf_bezier_t **)res, NULL);
}

static cf_status_t
op_misc(const cf_bezier_t *c, void **res)
{
    cf_bezier_t *a = NULL, *b = NULL;
    const double A[] = { 0, 1, 1, 0 };
    cf_status_t st = cf_bezier_segment(c, 0.2, 0.7, &a, NULL);
    if (st == CF_STATUS_OK)
        st = cf_bezier_reverse(a, &b, NULL);
    cf_bezier_destroy(a);
    a = NULL;
    if (st == CF_STATUS_OK)
        st = cf_bezier_transform(b, A, NULL, &a, NULL);
    cf_bezier_destroy(b);
    b = NULL;
    if (st == CF_STATUS_OK)
        st = cf_bezier_copy(a, &b, NULL);
    cf_bezier_destroy(a);
    *res = b;
    return st;
}

static cf_status_t
op_cubics(const cf_bezier_t *c, void **res)
{
    cf_cubics_t *cu = NULL;
    cf_status_t st = cf_bezier_to_cubics(c, 1e-7, &cu, NULL);
    if (st == CF_STATUS_OK)
        assert_true(cu->count > 8);   /* several reallocations happened */
    cf_cubics_destroy(cu);
    *res = NULL;
    return st;
}

static void
run_oom(op_fn op, const cf_bezier_t *c, bool is_curve)
{
    /* fail the k-th allocation for k = 1, 2, ... until the operation
    ** succeeds; every failure reports NO_MEMORY and leaks nothing */
    for (long k = 1;; k++) {
        void *res = NULL;
        cf_status_t st;
        tu_fail_alloc_after(k);
        st = op(c, &res);
        if (st == CF_STATUS_OK) {
            if (is_curve)
                cf_bezier_destroy(res);
            assert_int_equal(tu_alloc_live(), 0);
            tu_fail_alloc_reset();
            assert_true(k > 1);
            return;
        }
        assert_int_equal(st, CF_STATUS_NO_MEMORY);
        assert_null(res);
        assert_int_equal(tu_alloc_live(), 0);
        tu_fail_alloc_reset();
        assert_true(k < 100000);
    }
}

static void
test_out_of_memory(void **state)
{
    cf_bezier_t *c, *cr;
    const double w[] = { 1, 2, 3, 4, 5 };
    (void)state;
    assert_int_equal(cf_bezier_create(2, 4, seed_pts, NULL, &c, NULL),
                     CF_STATUS_OK);
    assert_int_equal(cf_bezier_create(2, 4, seed_pts, w, &cr, NULL),
                     CF_STATUS_OK);
    run_oom(op_create, NULL, true);
    run_oom(op_split, c, true);
    run_oom(op_split, cr, true);
    run_oom(op_elevate, c, true);
    run_oom(op_derivative, c, true);
    run_oom(op_derivative, cr, true);
    run_oom(op_misc, cr, true);
    run_oom(op_cubics, c, false);
    run_oom(op_cubics, cr, false);
    cf_bezier_destroy(c);
    cf_bezier_destroy(cr);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_queries),
        cmocka_unit_test(test_errors_construction),
        cmocka_unit_test(test_errors_operations),
        cmocka_unit_test(test_derivative_overflow_refused),
        cmocka_unit_test(test_out_of_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
