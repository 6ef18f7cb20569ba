/*
** API misuse, in the spirit of cairo's api-special-cases test: every
** public function of the headers in include/curvefig/ is called with NULL pointers,
** empty and zero-sized inputs, out-of-range numbers and inconsistent
** arguments, and must return a status (never crash, never write through a
** NULL pointer, never leave an output object behind); functions without a
** status (queries, destroy) must be harmless on NULL.
**
** The enumeration is checked, not trusted: test_every_function_listed
** reads the public headers and fails if a function declared there is not
** named in this file or in test_api_misuse_render.c (the renderer's
** functions: figures, labels, layouts, output).  Their shared helpers:
** test_api_misuse.h.
*/
#include "test_api_misuse.h"

static void
test_core(void **state)
{
    cf_diag_t diag;
    cf_allocator_t a;
    (void)state;
    for (int s = -1; s <= CF_STATUS_LAST_; s++)
        assert_non_null(cf_status_to_string((cf_status_t)s));
    cf_diag_clear(NULL);
    cf_diag_clear(&diag);
    assert_int_equal(diag.status, CF_STATUS_OK);
    cf_get_allocator(NULL);
    cf_set_allocator(NULL);            /* restores the default */
    cf_get_allocator(&a);
    assert_non_null(a.realloc);
    /* no allocator of the thread's own, no previous wanted: harmless */
    cf_use_allocator(NULL, NULL);
    {
        cf_allocator_t none = { NULL, NULL }, prev;
        cf_use_allocator(&none, &prev);
        assert_null(prev.realloc);
        cf_get_allocator(&a);
        assert_non_null(a.realloc);
    }
    cf_free(NULL);
    assert_int_equal(cf_version(), CF_VERSION);
    assert_string_equal(cf_version_string(), CF_VERSION_STRING);
    /* the allocation helpers: overflow and zero sizes, never a crash */
    assert_null(cf_alloc_array(SIZE_MAX, 2));
    assert_null(cf_calloc(SIZE_MAX / 2, 4));
    assert_null(cf_malloc(SIZE_MAX));
    {
        double *p = cf_alloc_array(4, sizeof *p);
        assert_non_null(p);
        assert_null(cf_realloc_array(p, SIZE_MAX, 2));   /* p kept */
        p = cf_realloc_array(p, 8, sizeof *p);
        assert_non_null(p);
        cf_free(p);
        p = cf_realloc_array(NULL, 2, sizeof *p);
        assert_non_null(p);
        cf_free(p);
        p = cf_calloc(3, sizeof *p);
        assert_non_null(p);
        assert_true(p[0] == 0.0 && p[2] == 0.0);
        cf_free(p);
        cf_free(cf_malloc(0));
    }
    /* cf_diag_set: the first error is kept, NULL is harmless */
    IS(CF_STATUS_DOMAIN, cf_diag_set(NULL, CF_STATUS_DOMAIN, 3, "x %d", 1));
    cf_diag_clear(&diag);
    IS(CF_STATUS_DOMAIN, cf_diag_set(&diag, CF_STATUS_DOMAIN, 3, "u = %g", 2.5));
    IS(CF_STATUS_IO, cf_diag_set(&diag, CF_STATUS_IO, 4, "second"));
    assert_int_equal(diag.status, CF_STATUS_DOMAIN);
    assert_int_equal(diag.index, 3);
    assert_string_equal(diag.msg, "u = 2.5");
    /* cf_check_finite_points */
    IS(CF_STATUS_OK, cf_check_finite_points(P4, 4, 2, 2, "point", NULL));
    IS(CF_STATUS_OK, cf_check_finite_points(NULL, 0, 2, 2, "point", NULL));
    IS(CF_STATUS_INVALID_ARG, cf_check_finite_points(NULL, 2, 2, 2, "p", NULL));
    IS(CF_STATUS_INVALID_ARG, cf_check_finite_points(P4, 2, 2, 1, "p", NULL));
    IS(CF_STATUS_INVALID_ARG, cf_check_finite_points(P4, 2, 0, 2, NULL, NULL));
    cf_diag_clear(&diag);
    IS(CF_STATUS_NOT_FINITE, cf_check_finite_points(
           (const double[]){ 0, 1, 2, NAN }, 2, 2, 2, "vertex", &diag));
    assert_int_equal(diag.index, 1);
    assert_string_equal(diag.msg, "vertex 1 has coordinate 2 = NaN; "
                                  "coordinates must be finite");
}

static void
test_knots(void **state)
{
    double out[16], N[8], ders[16], v, a = 0, b = 0;
    size_t span;
    cf_diag_t diag;
    (void)state;
    assert_int_equal(cf_knots_count(-1, 4), 0);
    assert_int_equal(cf_knots_count(2, 4), 7);
    IS(CF_STATUS_INVALID_ARG, cf_knots_validate(2, 4, NULL, 7, NULL));
    IS(CF_STATUS_BAD_DEGREE, cf_knots_validate(-1, 4, U7, 7, NULL));
    IS(CF_STATUS_BAD_DEGREE, cf_knots_validate(1000, 4, U7, 7, NULL));
    IS(CF_STATUS_TOO_FEW_POINTS, cf_knots_validate(2, 0, U7, 3, NULL));
    IS(CF_STATUS_BAD_KNOTS, cf_knots_validate(2, 4, U7, 6, NULL));
    IS(CF_STATUS_BAD_KNOTS, cf_knots_validate(2, 4, U7, 0, NULL));
    IS(CF_STATUS_NOT_FINITE, cf_knots_validate(2, 4, NANS, 7, NULL));
    cf_diag_clear(&diag);
    BAD(cf_knots_validate(2, 4, (const double[]){ 0, 0, 0, 0.5, 0.3, 1, 1 },
                          7, &diag));
    assert_true(diag.msg[0] != '\0');
    BAD(cf_knots_uniform(2, 4, 0, 1, NULL, NULL));
    BAD(cf_knots_uniform(2, 4, 1, 0, out, NULL));
    BAD(cf_knots_uniform(2, 4, NAN, 1, out, NULL));
    BAD(cf_knots_uniform(-3, 4, 0, 1, out, NULL));
    BAD(cf_knots_clamped_uniform(2, 4, 0, 1, NULL, NULL));
    BAD(cf_knots_clamped_uniform(2, 1, 0, 1, out, NULL));
    BAD(cf_knots_clamped_uniform(2, 4, 1, 1, out, NULL));
    BAD(cf_knots_clamped_averaged(2, 4, NULL, out, NULL));
    BAD(cf_knots_clamped_averaged(2, 4, (const double[]){ 0, 1, 1, 2 }, out,
                                  NULL));
    BAD(cf_knots_clamped_averaged(0, 4, (const double[]){ 0, 1, 2, 3 }, out,
                                  NULL));
    BAD(cf_knots_clamped_averaged(2, 4, (const double[]){ 0, 1, 2, 3 }, NULL,
                                  NULL));
    /* the unchecked queries: harmless on NULL and empty input */
    cf_knots_domain(2, NULL, 0, &a, &b);
    cf_knots_domain(2, U7, 7, NULL, NULL);
    (void)cf_knots_find_span(2, NULL, 0, 0.5);
    assert_int_equal(cf_knots_multiplicity(NULL, 0, 0.5), 0);
    (void)cf_knots_classify(2, NULL, 0);
    assert_non_null(cf_knot_kind_to_string((cf_knot_kind_t)99));
    assert_non_null(cf_knot_kind_to_string(CF_KNOTS_CLAMPED));
    BAD(cf_basis_funs(2, NULL, 7, 0.5, &span, N, NULL));
    BAD(cf_basis_funs(2, U7, 7, 0.5, &span, NULL, NULL));
    BAD(cf_basis_funs(2, U7, 5, 0.5, &span, N, NULL));
    BAD(cf_basis_funs(2, U7, 7, 2.0, &span, N, NULL));
    BAD(cf_basis_funs(2, U7, 7, NAN, &span, N, NULL));
    BAD(cf_basis_funs(-1, U7, 7, 0.5, &span, N, NULL));
    BAD(cf_basis_ders(2, U7, 7, 0.5, -1, &span, ders, NULL));
    BAD(cf_basis_ders(2, U7, 7, 0.5, 1, &span, NULL, NULL));
    BAD(cf_basis_ders(2, NULL, 0, 0.5, 1, &span, ders, NULL));
    BAD(cf_basis_one(0, 3, U7, 4, 0.5, &v, NULL));
    BAD(cf_basis_one(-1, 2, U7, 7, 0.5, &v, NULL));
    BAD(cf_basis_one(0, 2, U7, 7, 0.5, NULL, NULL));
    BAD(cf_basis_one(0, 2, U7, 7, NAN, &v, NULL));
    BAD(cf_basis_one_ders(0, 2, U7, 7, 0.5, -1, out, NULL));
    BAD(cf_basis_one_ders(0, 2, NULL, 7, 0.5, 1, out, NULL));
    BAD(cf_basis_one_ders(0, 2, U7, 7, 0.5, 1, NULL, NULL));
    {
        cf_bspline_t *bs = NULL;
        BAD(cf_basis_one_spline(0, 2, NULL, 7, &bs, NULL));
        BAD(cf_basis_one_spline(0, 2, U7, 7, NULL, NULL));
        BAD(cf_basis_one_spline(5, 2, U7, 7, &bs, NULL));
        BAD(cf_basis_one_spline(0, 40, U7, 7, &bs, NULL));
        assert_null(bs);
    }
}

static void
test_bernstein(void **state)
{
    double out[8], M[16];
    cf_bezier_t *c = NULL;
    (void)state;
    BAD(cf_bernstein_value(-1, 0, 0.5, out));
    BAD(cf_bernstein_value(3, 0, 0.5, NULL));
    BAD(cf_bernstein_value(3, 0, NAN, out));
    BAD(cf_bernstein_all(-1, 0.5, out));
    BAD(cf_bernstein_all(3, 0.5, NULL));
    BAD(cf_bernstein_all_deriv(3, 0.5, -1, out));
    BAD(cf_bernstein_all_deriv(3, 0.5, 1, NULL));
    BAD(cf_bernstein_eval(3, NULL, 0.5, out));
    BAD(cf_bernstein_eval(3, P4, 0.5, NULL));
    BAD(cf_bernstein_eval(-2, P4, 0.5, out));
    BAD(cf_bernstein_to_power_matrix(-1, M, NULL));
    BAD(cf_bernstein_to_power_matrix(3, NULL, NULL));
    BAD(cf_power_to_bernstein_matrix(-1, M, NULL));
    BAD(cf_power_to_bernstein_matrix(3, NULL, NULL));
    BAD(cf_bernstein_from_power(3, NULL, out, NULL));
    BAD(cf_bernstein_from_power(3, P4, NULL, NULL));
    BAD(cf_bernstein_to_power(3, NULL, out, NULL));
    BAD(cf_bernstein_to_power(-1, P4, out, NULL));
    BAD(cf_bernstein_approx(NULL, NULL, 3, out, NULL));
    BAD(cf_bernstein_approx_curve(NULL, NULL, 3, &c, NULL));
    assert_null(c);
}

static void
test_bezier(void **state)
{
    cf_bezier_t *c = NULL, *o = NULL, *l = NULL, *r = NULL;
    cf_cubics_t *cu = NULL;
    double out[64], lo[2], hi[2], t, d;
    size_t idx[4], n;
    cf_diag_t diag;
    (void)state;
    /* construction */
    IS(CF_STATUS_INVALID_ARG, cf_bezier_create(2, 3, P4, NULL, NULL, NULL));
    BAD(cf_bezier_create(2, 3, NULL, NULL, &o, NULL));
    BAD(cf_bezier_create(0, 3, P4, NULL, &o, NULL));
    BAD(cf_bezier_create(2, -1, P4, NULL, &o, NULL));
    BAD(cf_bezier_create(2, CF_BEZIER_MAX_DEGREE + 1, P4, NULL, &o, NULL));
    BAD(cf_bezier_create(2, 3, NANS, NULL, &o, NULL));
    BAD(cf_bezier_create(2, 3, P4, (const double[]){ 1, 0, 1, 1 }, &o,
                         NULL));
    BAD(cf_bezier_create(2, 3, P4, (const double[]){ 1, -1, 1, 1 }, &o,
                         NULL));
    BAD(cf_bezier_create(2, 3, P4, NANS, &o, NULL));
    BAD(cf_bezier_create_homogeneous(2, 3, NULL, &o, NULL));
    BAD(cf_bezier_create_homogeneous(2, 3, P4, NULL, NULL));
    BAD(cf_bezier_create_homogeneous(0, 1, P4, &o, NULL));
    BAD(cf_bezier_create_homogeneous(1, 3, (const double[]){ 0, 1, 1, 0, 2,
                                                             1, 3, 1 }, &o,
                                     NULL));
    assert_null(o);
    BAD(cf_bezier_copy(NULL, &o, NULL));
    cf_bezier_destroy(NULL);
    /* queries on NULL */
    assert_int_equal(cf_bezier_dim(NULL), 0);
    assert_int_equal(cf_bezier_degree(NULL), 0);
    assert_false(cf_bezier_is_rational(NULL));
    assert_null(cf_bezier_hpoints(NULL));
    cf_bezier_get_points(NULL, out);
    cf_bezier_get_weights(NULL, out);
    assert_int_equal(cf_bezier_decasteljau_size(NULL), 0);
    /* evaluation on NULL and with bad parameters */
    assert_int_equal(cf_bezier_create(2, 3, P4, W4, &c, NULL), 0);
    cf_bezier_get_points(c, NULL);
    cf_bezier_get_weights(c, NULL);
    IS(CF_STATUS_INVALID_ARG, cf_bezier_eval(NULL, 0.5, out));
    IS(CF_STATUS_INVALID_ARG, cf_bezier_eval(c, 0.5, NULL));
    IS(CF_STATUS_NOT_FINITE, cf_bezier_eval(c, NAN, out));
    IS(CF_STATUS_DOMAIN, cf_bezier_eval(c, 1.5, out));
    BAD(cf_bezier_eval_many(NULL, (const double[]){ 0.5 }, 1, out));
    BAD(cf_bezier_eval_many(c, NULL, 1, out));
    BAD(cf_bezier_eval_many(c, (const double[]){ 0.5 }, 1, NULL));
    BAD(cf_bezier_eval_many(c, (const double[]){ 0.5, NAN }, 2, out));
    BAD(cf_bezier_eval_derivs(c, 0.5, -1, out));
    BAD(cf_bezier_eval_derivs(c, 0.5, CF_BEZIER_MAX_DEGREE + 1, out));
    BAD(cf_bezier_eval_derivs(NULL, 0.5, 1, out));
    BAD(cf_bezier_eval_deriv_many(c, (const double[]){ 0.5 }, 1, -1, out));
    BAD(cf_bezier_eval_deriv_many(c, NULL, 1, 1, out));
    BAD(cf_bezier_eval_deriv_many(NULL, (const double[]){ 0.5 }, 1, 1,
                                  out));
    BAD(cf_bezier_decasteljau(NULL, 0.5, out));
    BAD(cf_bezier_decasteljau(c, 0.5, NULL));
    BAD(cf_bezier_decasteljau(c, -0.5, out));
    BAD(cf_bezier_tangent(NULL, 0.5, out));
    BAD(cf_bezier_tangent(c, NAN, out));
    BAD(cf_bezier_normal(NULL, 0.5, out));
    BAD(cf_bezier_normal(c, 0.5, NULL));
    BAD(cf_bezier_curvature(NULL, 0.5, &t));
    BAD(cf_bezier_curvature(c, 0.5, NULL));
    /* constructions */
    BAD(cf_bezier_derivative(NULL, 1, &o, NULL));
    BAD(cf_bezier_derivative(c, -1, &o, NULL));
    BAD(cf_bezier_derivative(c, 1, NULL, NULL));
    BAD(cf_bezier_split(NULL, 0.5, &l, &r, NULL));
    BAD(cf_bezier_split(c, 0.0, &l, &r, NULL));
    BAD(cf_bezier_split(c, 1.0, &l, &r, NULL));
    BAD(cf_bezier_split(c, NAN, &l, &r, NULL));
    assert_null(l);
    assert_null(r);
    BAD(cf_bezier_split_into(c, 0.5, out, out));
    BAD(cf_bezier_split_into(c, 0.5, NULL, out + 16));
    BAD(cf_bezier_split_into(NULL, 0.5, out, out + 16));
    BAD(cf_bezier_segment(c, 0.7, 0.2, &o, NULL));
    BAD(cf_bezier_segment(c, -1, 0.2, &o, NULL));
    BAD(cf_bezier_segment(NULL, 0.1, 0.2, &o, NULL));
    BAD(cf_bezier_reverse(NULL, &o, NULL));
    BAD(cf_bezier_reverse(c, NULL, NULL));
    BAD(cf_bezier_transform(c, NULL, NULL, &o, NULL));
    BAD(cf_bezier_transform(NULL, P4, NULL, &o, NULL));
    BAD(cf_bezier_transform(c, NANS, NULL, &o, NULL));
    BAD(cf_bezier_elevate(c, -1, &o, NULL));
    BAD(cf_bezier_elevate(NULL, 1, &o, NULL));
    BAD(cf_bezier_elevate(c, CF_BEZIER_MAX_DEGREE, &o, NULL));
    BAD(cf_bezier_reduce(NULL, NULL, &o, NULL, NULL));
    BAD(cf_bezier_reduce(c, NULL, NULL, NULL, NULL));
    assert_null(o);
    /* geometry */
    BAD(cf_bezier_bbox(NULL, lo, hi));
    BAD(cf_bezier_bbox(c, NULL, hi));
    BAD(cf_bezier_length(c, 0.0, &t));
    BAD(cf_bezier_length(c, NAN, &t));
    BAD(cf_bezier_length(NULL, 1e-6, &t));
    BAD(cf_bezier_length(c, 1e-6, NULL));
    BAD(cf_bezier_closest(c, NULL, &t, &d));
    BAD(cf_bezier_closest(NULL, P4, &t, &d));
    BAD(cf_bezier_closest(c, NANS, &t, &d));
    BAD(cf_bezier_flatten(c, 0.1, NULL, NULL));
    BAD(cf_bezier_flatten(NULL, 0.1, NULL, NULL));
    BAD(cf_bezier_to_cubics(c, 0.0, &cu, NULL));
    BAD(cf_bezier_to_cubics(NULL, 0.1, &cu, NULL));
    BAD(cf_bezier_to_cubics(c, 0.1, NULL, NULL));
    BAD(cf_bezier_to_cubics_bounded(c, 0.0, &cu, NULL));
    BAD(cf_bezier_to_cubics_bounded(NULL, 0.1, &cu, NULL));
    BAD(cf_bezier_to_cubics_bounded(c, 0.1, NULL, NULL));
    assert_null(cu);
    cf_cubics_destroy(NULL);
    cf_bezier_list_destroy(NULL);
    /* geometry.h */
    BAD(cf_convex_hull_2d(NULL, 4, 2, idx, &n, NULL));
    BAD(cf_convex_hull_2d(P4, 4, 1, idx, &n, NULL));
    BAD(cf_convex_hull_2d(P4, 4, 2, NULL, &n, NULL));
    BAD(cf_convex_hull_2d(NANS, 4, 2, idx, &n, NULL));
    BAD(cf_bezier_hull(NULL, idx, &n, NULL));
    BAD(cf_bezier_hull(c, NULL, &n, NULL));
    /* a diag is reset on entry: after a failure it holds that failure
    ** (never an earlier call's message), after a success "no error" --
    ** also when the caller never cleared it */
    memset(&diag, 0xab, sizeof diag);
    {
        cf_status_t st = cf_bezier_elevate(c, -1, &o, &diag);
        char first[CF_DIAG_MSG_SIZE];
        BAD(st);
        assert_int_equal(diag.status, st);
        assert_non_null(memchr(diag.msg, '\0', sizeof diag.msg));
        assert_true(diag.msg[0] != '\0');
        memcpy(first, diag.msg, sizeof first);
        st = cf_bezier_derivative(c, 99999, &o, &diag);
        BAD(st);
        assert_int_equal(diag.status, st);
        assert_string_not_equal(diag.msg, first);
        IS(CF_STATUS_OK, cf_bezier_elevate(c, 1, &o, &diag));
        assert_int_equal(diag.status, CF_STATUS_OK);
        assert_int_equal(diag.index, -1);
        assert_string_equal(diag.msg, "");
        cf_bezier_destroy(o);
    }
    cf_bezier_destroy(c);
}

static void
test_bspline(void **state)
{
    cf_bspline_t *c = NULL, *o = NULL, *l = NULL, *r = NULL;
    cf_bezier_list_t *list = NULL;
    double out[64], a, b, *h = NULL, *br = NULL;
    size_t first, span, n = 0;
    int mult, removed;
    cf_bspline_insert_info_t info;
    (void)state;
    IS(CF_STATUS_INVALID_ARG, cf_bspline_create(2, 2, U7, 7, P4, 4, NULL,
                                                NULL, NULL));
    BAD(cf_bspline_create(2, 2, NULL, 7, P4, 4, NULL, &o, NULL));
    BAD(cf_bspline_create(2, 2, U7, 7, NULL, 4, NULL, &o, NULL));
    BAD(cf_bspline_create(0, 2, U7, 7, P4, 4, NULL, &o, NULL));
    BAD(cf_bspline_create(2, 2, U7, 6, P4, 4, NULL, &o, NULL));
    BAD(cf_bspline_create(2, 2, U7, 7, P4, 0, NULL, &o, NULL));
    BAD(cf_bspline_create(2, 7, U7, 7, P4, 4, NULL, &o, NULL));
    BAD(cf_bspline_create(2, -1, U7, 7, P4, 4, NULL, &o, NULL));
    BAD(cf_bspline_create(2, 2, U7, 7, P4, 4, (const double[]){ 1, 0, 1, 1 },
                          &o, NULL));
    BAD(cf_bspline_create(2, 2, U7, 7, NANS, 4, NULL, &o, NULL));
    BAD(cf_bspline_create_homogeneous(2, 2, U7, 7, NULL, 4, &o, NULL));
    BAD(cf_bspline_create_homogeneous(1, 2, U7, 7, P4, 4, &o, NULL));
    BAD(cf_bspline_create_clamped(2, 2, NULL, 4, NULL, &o, NULL));
    BAD(cf_bspline_create_clamped(2, 4, P4, 4, NULL, &o, NULL));
    BAD(cf_bspline_create_clamped(0, 2, P4, 4, NULL, &o, NULL));
    BAD(cf_bspline_create_closed(2, 0, P4, 4, NULL, &o, NULL));
    BAD(cf_bspline_create_closed(2, 2, NULL, 4, NULL, &o, NULL));
    BAD(cf_bspline_create_closed(2, 2, P4, 2, NULL, &o, NULL));
    BAD(cf_bspline_create_coons(2, NULL, 4, CF_COONS_PLAIN, &o, NULL));
    BAD(cf_bspline_create_coons(2, P4, 3, CF_COONS_PLAIN, &o, NULL));
    BAD(cf_bspline_create_coons(2, P4, 4, (cf_coons_ends_t)77, &o, NULL));
    BAD(cf_bspline_copy(NULL, &o, NULL));
    BAD(cf_nurbs_arc(2, NULL, P4, P4 + 2, 1, 0, 1, &o, NULL));
    BAD(cf_nurbs_arc(2, P4, P4 + 2, P4 + 4, -1, 0, 1, &o, NULL));
    BAD(cf_nurbs_arc(2, P4, P4 + 2, P4 + 4, 1, 1, 1, &o, NULL));
    BAD(cf_nurbs_circle(NULL, 1, &o, NULL));
    BAD(cf_nurbs_circle(P4, 0, &o, NULL));
    BAD(cf_nurbs_circle(P4, NAN, &o, NULL));
    assert_null(o);
    cf_bspline_destroy(NULL);
    cf_coons_basis(0.5, (double[4]){ 0 });
    cf_coons_eval(2, P4, 0.5, out);
    /* queries on NULL */
    assert_int_equal(cf_bspline_dim(NULL), 0);
    assert_int_equal(cf_bspline_degree(NULL), 0);
    assert_int_equal(cf_bspline_count(NULL), 0);
    assert_int_equal(cf_bspline_nknots(NULL), 0);
    assert_false(cf_bspline_is_rational(NULL));
    assert_null(cf_bspline_knots(NULL));
    assert_null(cf_bspline_hpoints(NULL));
    cf_bspline_get_points(NULL, out);
    cf_bspline_get_weights(NULL, out);
    cf_bspline_domain(NULL, &a, &b);
    (void)cf_bspline_knot_kind(NULL);
    assert_int_equal(cf_bspline_deboor_size(NULL), 0);
    /* evaluation */
    assert_int_equal(cf_bspline_create(2, 2, U7, 7, P4, 4, W4, &c, NULL), 0);
    cf_bspline_get_points(c, NULL);
    cf_bspline_domain(c, NULL, NULL);
    IS(CF_STATUS_INVALID_ARG, cf_bspline_eval(NULL, 0.5, out));
    IS(CF_STATUS_INVALID_ARG, cf_bspline_eval(c, 0.5, NULL));
    IS(CF_STATUS_NOT_FINITE, cf_bspline_eval(c, NAN, out));
    IS(CF_STATUS_DOMAIN, cf_bspline_eval(c, 1.5, out));
    BAD(cf_bspline_eval_many(c, NULL, 1, out));
    BAD(cf_bspline_eval_many(c, (const double[]){ 0.5, 3 }, 2, out));
    BAD(cf_bspline_eval_many(NULL, (const double[]){ 0.5 }, 1, out));
    BAD(cf_bspline_eval_derivs(c, 0.5, -1, out));
    BAD(cf_bspline_eval_derivs(NULL, 0.5, 1, out));
    BAD(cf_bspline_eval_deriv_many(c, (const double[]){ 0.5 }, 1, -1, out));
    BAD(cf_bspline_eval_deriv_many(c, NULL, 1, 1, out));
    BAD(cf_bspline_deboor(NULL, 0.5, out, &span, &mult));
    BAD(cf_bspline_deboor(c, 0.5, NULL, &span, &mult));
    BAD(cf_bspline_deboor(c, -1, out, &span, &mult));
    BAD(cf_bspline_basis(NULL, 0.5, &first, out));
    BAD(cf_bspline_basis(c, 0.5, &first, NULL));
    BAD(cf_bspline_basis(c, 7, &first, out));
    /* constructions */
    BAD(cf_bspline_derivative(NULL, 1, &o, NULL));
    BAD(cf_bspline_derivative(c, -1, &o, NULL));
    BAD(cf_bspline_insert_knot(NULL, 0.5, 1, &o, &info, NULL));
    BAD(cf_bspline_insert_knot(c, 0.5, 0, &o, &info, NULL));
    BAD(cf_bspline_insert_knot(c, 0.5, 3, &o, &info, NULL));
    BAD(cf_bspline_insert_knot(c, 2.0, 1, &o, &info, NULL));
    BAD(cf_bspline_insert_knot(c, NAN, 1, &o, &info, NULL));
    BAD(cf_bspline_insert_knot(c, 0.5, 1, NULL, &info, NULL));
    BAD(cf_bspline_refine(c, NULL, 2, &o, NULL));
    BAD(cf_bspline_refine(c, (const double[]){ 0.7, 0.2 }, 2, &o, NULL));
    BAD(cf_bspline_refine(c, (const double[]){ 0.2, 5 }, 2, &o, NULL));
    BAD(cf_bspline_refine(NULL, (const double[]){ 0.2 }, 1, &o, NULL));
    BAD(cf_bspline_remove_knot(c, 0.3, 1, 1e-9, &o, &removed, NULL));
    BAD(cf_bspline_remove_knot(c, 0.5, 0, 1e-9, &o, &removed, NULL));
    BAD(cf_bspline_remove_knot(c, 0.5, 1, -1, &o, &removed, NULL));
    BAD(cf_bspline_remove_knot(NULL, 0.5, 1, 0, &o, &removed, NULL));
    BAD(cf_bspline_split(c, 0.0, &l, &r, NULL));
    BAD(cf_bspline_split(c, 1.0, &l, &r, NULL));
    BAD(cf_bspline_split(NULL, 0.5, &l, &r, NULL));
    BAD(cf_bspline_segment(c, 0.6, 0.3, &o, NULL));
    BAD(cf_bspline_segment(c, -1, 0.3, &o, NULL));
    BAD(cf_bspline_segment(NULL, 0.1, 0.3, &o, NULL));
    BAD(cf_bspline_to_beziers(NULL, &list, NULL));
    BAD(cf_bspline_to_beziers(c, NULL, NULL));
    BAD(cf_bspline_bezier_points(NULL, &h, &br, &n, NULL));
    BAD(cf_bspline_bezier_points(c, NULL, &br, &n, NULL));
    BAD(cf_bspline_bezier_points(c, &h, &br, NULL, NULL));
    BAD(cf_bspline_elevate(c, -1, &o, NULL));
    BAD(cf_bspline_elevate(c, CF_BSPLINE_MAX_DEGREE, &o, NULL));
    BAD(cf_bspline_elevate(NULL, 1, &o, NULL));
    BAD(cf_bspline_reverse(NULL, &o, NULL));
    BAD(cf_bspline_reverse(c, NULL, NULL));
    BAD(cf_bspline_transform(c, NULL, NULL, &o, NULL));
    BAD(cf_bspline_transform(c, NANS, NULL, &o, NULL));
    BAD(cf_bspline_transform(NULL, P4, NULL, &o, NULL));
    BAD(cf_bspline_support(c, 4, &a, &b));
    BAD(cf_bspline_support(NULL, 0, &a, &b));
    BAD(cf_bspline_active_points(c, 3.0, &first, &a, &b));
    BAD(cf_bspline_active_points(NULL, 0.5, &first, &a, &b));
    BAD(cf_bspline_move_point(c, 4, P4, &o, NULL));
    BAD(cf_bspline_move_point(c, 0, NULL, &o, NULL));
    BAD(cf_bspline_move_point(c, 0, NANS, &o, NULL));
    BAD(cf_bspline_move_point(NULL, 0, P4, &o, NULL));
    assert_null(o);
    assert_null(l);
    assert_null(r);
    assert_null(list);
    assert_null(h);
    cf_bspline_destroy(c);
}

static double
ident(double t, void *ud)
{
    (void)ud;
    return t;
}

static void
test_conic_interp_offset(void **state)
{
    cf_bezier_list_t *l = NULL;
    cf_bspline_t *o = NULL;
    cf_bezier_t *c = NULL, *bz = NULL;
    cf_interp_options_t opt;
    cf_interp_method_t m;
    cf_param_t p;
    cf_offset_options_t oo;
    cf_cubics_t *raw = NULL;
    cf_cubics_list_t *trim = NULL;
    cf_offset_report_t rep;
    double out[16], res, err;
    size_t count;
    (void)state;
    BAD(cf_conic_arc(0, 0, -1, 0, 1, &l, NULL));
    BAD(cf_conic_arc(0, 0, 1, 0, 0, &l, NULL));
    BAD(cf_conic_arc(NAN, 0, 1, 0, 1, &l, NULL));
    BAD(cf_conic_arc(0, 0, 1, 0, 1, NULL, NULL));
    BAD(cf_conic_circle(0, 0, 0, &l, NULL));
    BAD(cf_conic_circle(0, 0, 1, NULL, NULL));
    BAD(cf_conic_ellipse(0, 0, 0, 1, 0, 0, 1, &l, NULL));
    BAD(cf_conic_ellipse(0, 0, 1, 1, 0, 1, 1, &l, NULL));
    BAD(cf_conic_parabola(0, 0, 0, 0, -1, 1, &l, NULL));
    BAD(cf_conic_parabola(0, 0, 1, 0, 1, -1, &l, NULL));
    BAD(cf_conic_hyperbola(0, 0, -1, 1, 0, -1, 1, &l, NULL));
    BAD(cf_conic_hyperbola(0, 0, 1, 1, 0, 1, -1, &l, NULL));
    assert_null(l);
    /* interp.h */
    BAD(cf_interp_parameters(2, NULL, 4, CF_PARAM_CHORD, 0, false, out,
                             NULL));
    BAD(cf_interp_parameters(2, P4, 4, CF_PARAM_CHORD, 0, false, NULL,
                             NULL));
    BAD(cf_interp_parameters(0, P4, 4, CF_PARAM_CHORD, 0, false, out, NULL));
    BAD(cf_interp_parameters(2, P4, 1, CF_PARAM_CHORD, 0, false, out, NULL));
    BAD(cf_interp_parameters(2, P4, 4, (cf_param_t)99, 0, false, out, NULL));
    BAD(cf_interp_parameters(2, (const double[]){ 0, 0, 0, 0 }, 2,
                             CF_PARAM_CHORD, 0, false, out, NULL));
    cf_interp_options_init(NULL);
    cf_interp_options_init(&opt);
    BAD(cf_interpolate(2, NULL, 4, &opt, &o, NULL));
    BAD(cf_interpolate(2, P4, 4, &opt, NULL, NULL));
    BAD(cf_interpolate(0, P4, 4, &opt, &o, NULL));
    BAD(cf_interpolate(2, P4, 0, &opt, &o, NULL));
    BAD(cf_interpolate(2, NANS, 4, &opt, &o, NULL));
    opt.method = (cf_interp_method_t)99;
    BAD(cf_interpolate(2, P4, 4, &opt, &o, NULL));
    cf_interp_options_init(&opt);
    opt.method = CF_INTERP_CLAMPED;     /* needs both end tangents */
    BAD(cf_interpolate(2, P4, 4, &opt, &o, NULL));
    cf_interp_options_init(&opt);
    opt.params = (const double[]){ 0, 1, 1, 2 };   /* not increasing */
    BAD(cf_interpolate(2, P4, 4, &opt, &o, NULL));
    cf_interp_options_init(&opt);
    opt.closed = true;
    opt.method = CF_INTERP_NATURAL;
    BAD(cf_interpolate(2, P4, 4, &opt, &o, NULL));
    BAD(cf_interp_method_from_string(NULL, &m, NULL));
    BAD(cf_interp_method_from_string("cubic-ish", &m, NULL));
    BAD(cf_interp_method_from_string("natural", NULL, NULL));
    BAD(cf_param_from_string(NULL, &p, NULL));
    BAD(cf_param_from_string("", &p, NULL));
    BAD(cf_param_from_string("chord", NULL, NULL));
    assert_non_null(cf_interp_method_to_string((cf_interp_method_t)99));
    BAD(cf_approximate_lsq(2, NULL, 4, 3, NULL, true, &o, &res, NULL));
    BAD(cf_approximate_lsq(2, P4, 4, 9, NULL, true, &o, &res, NULL));
    BAD(cf_approximate_lsq(2, P4, 4, 0, NULL, true, &o, &res, NULL));
    BAD(cf_approximate_lsq(2, P4, 4, 3, NULL, true, NULL, &res, NULL));
    BAD(cf_ferguson_cubic(2, NULL, P4, P4, P4, &bz, NULL));
    BAD(cf_ferguson_cubic(0, P4, P4, P4, P4, &bz, NULL));
    BAD(cf_ferguson_cubic(2, P4, P4, P4, NANS, &bz, NULL));
    BAD(cf_ferguson_cubic(2, P4, P4, P4, P4, NULL, NULL));
    BAD(cf_ferguson_chain(2, P4, NULL, 4, &l, NULL));
    BAD(cf_ferguson_chain(2, P4, P4, 1, &l, NULL));
    BAD(cf_coons_cubic(2, NULL, &bz, NULL));
    BAD(cf_coons_cubic(0, P4, &bz, NULL));
    BAD(cf_coons_chain(2, NULL, 4, CF_COONS_PLAIN, &l, NULL));
    BAD(cf_coons_chain(2, P4, 2, CF_COONS_PLAIN, &l, NULL));
    BAD(cf_coons_chain(2, P4, 4, (cf_coons_ends_t)42, &l, NULL));
    assert_null(o);
    assert_null(bz);
    assert_null(l);
    /* offset.h */
    cf_offset_options_init(NULL);
    cf_offset_options_init(&oo);
    cf_cubics_list_destroy(NULL);
    assert_int_equal(cf_bezier_create(2, 3, P4, NULL, &c, NULL), 0);
    BAD(cf_offset_point(NULL, 0.5, 0.1, out));
    BAD(cf_offset_point(c, NAN, 0.1, out));
    BAD(cf_offset_point(c, 0.5, NAN, out));
    BAD(cf_offset_point(c, 0.5, 0.1, NULL));
    BAD(cf_offset_point_many(c, NULL, 1, 0.1, out));
    BAD(cf_offset_point_many(NULL, (const double[]){ 0.5 }, 1, 0.1, out));
    BAD(cf_offset_cusps(NULL, 0.1, out, 4, &count, NULL));
    BAD(cf_offset_cusps(c, NAN, out, 4, &count, NULL));
    BAD(cf_offset_cusps(c, 0.1, out, 4, NULL, NULL));
    BAD(cf_bezier_offset(NULL, 0.1, &oo, &raw, &trim, &rep, NULL));
    BAD(cf_bezier_offset(c, NAN, &oo, &raw, &trim, &rep, NULL));
    oo.tolerance = 0;
    BAD(cf_bezier_offset(c, 0.1, &oo, &raw, &trim, &rep, NULL));
    cf_offset_options_init(&oo);
    {
        cf_bspline_t *sp = NULL;
        assert_int_equal(cf_bspline_create_clamped(2, 2, P4, 4, NULL, &sp,
                                                   NULL), 0);
        BAD(cf_bspline_offset(NULL, 0.1, &oo, &raw, &trim, &rep, NULL));
        BAD(cf_bspline_offset(sp, NAN, &oo, &raw, &trim, &rep, NULL));
        cf_bspline_destroy(sp);
    }
    BAD(cf_bezier_list_offset(NULL, 0.1, &oo, &raw, &trim, &rep, NULL));
    BAD(cf_offset_measure(c, 0.1, NULL, 10, &err, NULL));
    BAD(cf_offset_measure(NULL, 0.1, NULL, 10, &err, NULL));
    assert_null(raw);
    assert_null(trim);
    cf_bezier_destroy(c);
    (void)ident;
}


/* A failing function sets *out to NULL, whatever the variable held
** (core.h, "Ownership and failure"). */
static void
test_out_null_on_failure(void **state)
{
    static const double P[] = { 0, 0, 1, 2, 2, 0, 3, 1 };
    cf_bezier_t *c = NULL, *o, *l, *r;
    cf_bspline_t *s;
    cf_cubics_t *cu;
    cf_bezier_list_t *li;
    void *junk = (void *)P;
    (void)state;
    IS(CF_STATUS_OK, cf_bezier_create(2, 3, P, NULL, &c, NULL));
    o = junk;
    BAD(cf_bezier_create(2, -1, P, NULL, &o, NULL));
    assert_null(o);
    o = junk;
    BAD(cf_bezier_create(0, 3, NULL, NULL, &o, NULL));
    assert_null(o);
    o = junk;
    BAD(cf_bezier_elevate(c, -1, &o, NULL));
    assert_null(o);
    o = junk;
    BAD(cf_bezier_elevate(NULL, 1, &o, NULL));
    assert_null(o);
    o = junk;
    BAD(cf_bezier_derivative(c, -1, &o, NULL));
    assert_null(o);
    s = junk;
    BAD(cf_bspline_create(2, 2, P, 3, P, 4, NULL, &s, NULL));
    assert_null(s);
    s = junk;
    BAD(cf_nurbs_circle(NULL, 1, &s, NULL));
    assert_null(s);
    l = r = junk;
    BAD(cf_bezier_split(c, 2.0, &l, &r, NULL));
    assert_null(l);
    assert_null(r);
    cu = junk;
    BAD(cf_bezier_to_cubics(c, -1, &cu, NULL));
    assert_null(cu);
    li = junk;
    BAD(cf_conic_circle(0, 0, -1, &li, NULL));
    assert_null(li);
    cf_bezier_destroy(c);
}

/* Every function declared in the public headers is named in this file. */
static void
test_every_function_listed(void **state)
{
    static const char *const headers[] = {
        "core.h", "knots.h", "bernstein.h", "bezier.h", "bspline.h",
        "geometry.h", "conic.h", "interp.h", "offset.h", "version.h.in",
#ifdef CF_TEST_RENDER
        "figure.h", "style.h", "label.h", "output.h", "layout.h", "overlay.h",
#endif
    };
    static const char *const files[] = {
        "test_api_misuse.c",
#ifdef CF_TEST_RENDER
        "test_api_misuse_render.c",
#endif
    };
    static char me[400000], text[200000];
    size_t n = 0, total = 0;
    int missing = 0;
    (void)state;
    for (size_t i = 0; i < sizeof files / sizeof *files; i++) {
        char path[512];
        FILE *f;
        snprintf(path, sizeof path, "%s/tests/unit/%s", CF_SOURCE_ROOT,
                 files[i]);
        f = fopen(path, "r");
        assert_non_null(f);
        n += fread(me + n, 1, sizeof me - 1 - n, f);
        fclose(f);
    }
    me[n] = '\0';
    for (size_t h = 0; h < sizeof headers / sizeof *headers; h++) {
        const char *p;
        tu_read_header(CF_SOURCE_ROOT, headers[h], text, sizeof text);
        /* a declaration: "cf_name(" at the start of a line or after the
        ** return type, outside comments and typedefs */
        for (p = text; (p = strstr(p, "cf_")) != NULL; p++) {
            char name[128], call[130];
            size_t k = 0;
            const char *q = p, *line = p;
            if (p > text && (p[-1] == '_' || (p[-1] >= 'a' && p[-1] <= 'z')))
                continue;
            while (k < sizeof name - 1 &&
                   ((q[k] >= 'a' && q[k] <= 'z') ||
                    (q[k] >= '0' && q[k] <= '9') || q[k] == '_'))
                k++;
            if (q[k] != '(')
                continue;
            while (line > text && line[-1] != '\n')
                line--;
            /* skip comments (lines starting with ** or / *) and macros */
            if (line[0] == '*' || line[0] == '/' || line[0] == '#' ||
                line[0] == ' ' || strstr(line, "typedef") == line)
                continue;
            memcpy(name, p, k);
            name[k] = '\0';
            snprintf(call, sizeof call, "%s(", name);
            total++;
            if (strstr(me, call) == NULL) {
                print_error("%s (%s) is not exercised\n", name, headers[h]);
                missing++;
            }
        }
    }
    print_message("%zu public functions declared, all named here\n", total);
    assert_int_equal(missing, 0);
    assert_true(total > 100);
}

/* The nearest name of a message's "did you mean": one edit per three
** letters, else a word of the name; nothing for nonsense or no names. */
static void
test_nearest_name(void **state)
{
    static const char *const names[] = { "degree", "elevate", "eval",
                                         "split" };
    (void)state;
    assert_string_equal(cf_nearest_name("elevat", names, 4), "elevate");
    assert_string_equal(cf_nearest_name("degree_elevate", names, 4),
                        "elevate");
    assert_string_equal(cf_nearest_name("evla", names, 4), "eval");
    assert_null(cf_nearest_name("zzzzzz", names, 4));
    assert_null(cf_nearest_name("eval", names, 0));
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_core),
        cmocka_unit_test(test_knots),
        cmocka_unit_test(test_bernstein),
        cmocka_unit_test(test_bezier),
        cmocka_unit_test(test_bspline),
        cmocka_unit_test(test_conic_interp_offset),
        cmocka_unit_test(test_out_null_on_failure),
        cmocka_unit_test(test_nearest_name),
        cmocka_unit_test(test_every_function_listed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
