/* B-spline constructions that keep the curve (insertion, refinement,
** removal, Bézier pieces) and derivative curves, reversal and affine maps;
** the helpers shared with test_bspline.c and test_bspline_nurbs.c are in
** test_bspline.h. */
#include "test_bspline.h"

/* A curve produced by a construction has a valid knot vector. */
static void
assert_valid(const cf_bspline_t *q, const char *what, int trial)
{
    cf_diag_t d;
    cf_diag_clear(&d);
    if (cf_knots_validate(cf_bspline_degree(q), cf_bspline_count(q),
                          cf_bspline_knots(q), cf_bspline_nknots(q), &d)
        != CF_STATUS_OK)
        fail_msg("%s (trial %d): %s", what, trial, d.msg);
}

/* max |c1(u) - c2(u)| over n + 1 parameters spread over [a, b] (both
** curves must contain [a, b]). */
static double
max_gap(const cf_bspline_t *c1, const cf_bspline_t *c2, double a, double b,
        int n)
{
    double x[8], y[8], m = 0.0;
    size_t dim = cf_bspline_dim(c1);
    for (int i = 0; i <= n; i++) {
        double u = i == n ? b : a + (b - a) * i / n;
        if (cf_bspline_eval(c1, u, x) != CF_STATUS_OK
            || cf_bspline_eval(c2, u, y) != CF_STATUS_OK) {
            double a1, b1, a2, b2;
            cf_bspline_domain(c1, &a1, &b1);
            cf_bspline_domain(c2, &a2, &b2);
            fail_msg("max_gap: %.17g outside [%.17g, %.17g] or "
                     "[%.17g, %.17g]", u, a1, b1, a2, b2);
        }
        m = fmax(m, tu_max_diff(x, y, dim));
    }
    return m;
}

/* ---- shape-preserving constructions ------------------------------------- */

static void
test_insertion_thesis_figures(void **state)
{
    cf_bspline_t *c = sample(), *q = NULL;
    cf_bspline_insert_info_t info;
    const double *P, *Q;
    (void)state;
    P = cf_bspline_hpoints(c);
    /* figure 3.1-3.2: t = 0.6 in [u_5, u_6): Q_4 on P_3P_4, Q_5 on P_4P_5,
    ** the corner P_4 is cut away */
    assert_int_equal(cf_bspline_insert_knot(c, 0.6, 1, &q, &info, NULL), 0);
    assert_int_equal(info.span, 5);
    assert_int_equal(info.multiplicity, 0);
    assert_int_equal(info.cut_first, 4);
    assert_int_equal(info.cut_count, 1);
    assert_int_equal(info.new_first, 4);
    assert_int_equal(info.new_count, 2);
    assert_int_equal(cf_bspline_count(q), 9);
    Q = cf_bspline_hpoints(q);
    for (int i = 4; i <= 5; i++) {
        /* Q_i = (1 - a_i) P_{i-1} + a_i P_i, a_i = (t - u_i)/(u_{i+p} - u_i) */
        double a = (0.6 - SAMPLE_U[i]) / (SAMPLE_U[i + 2] - SAMPLE_U[i]);
        for (int d = 0; d < 2; d++)
            tu_assert_close(Q[2 * i + d],
                            (1 - a) * P[2 * (i - 1) + d] + a * P[2 * i + d],
                            4 * EPS, 5.0);
    }
    assert_memory_equal(Q, P, 8 * sizeof(double));            /* Q_0..Q_3 */
    assert_memory_equal(Q + 12, P + 10, 6 * sizeof(double));  /* Q_6.. */
    assert_true(max_gap(c, q, 0, 1, 500) <= 16 * EPS * 5);
    cf_bspline_destroy(q);
    /* figures 3.3-3.4: t = 0.5 = u_5 (simple): Q_5 = P_4, no corner cut */
    assert_int_equal(cf_bspline_insert_knot(c, 0.5, 1, &q, &info, NULL), 0);
    assert_int_equal(info.multiplicity, 1);
    assert_int_equal(info.cut_count, 0);
    assert_int_equal(info.new_count, 1);
    Q = cf_bspline_hpoints(q);
    assert_memory_equal(Q + 10, P + 8, 2 * sizeof(double));
    assert_int_equal(cf_knots_multiplicity(cf_bspline_knots(q), 12, 0.5), 2);
    cf_bspline_destroy(q);
    /* up to p + 1 copies in all; one more is refused with a message */
    assert_int_equal(cf_bspline_insert_knot(c, 0.5, 2, &q, &info, NULL), 0);
    assert_int_equal(cf_knots_multiplicity(cf_bspline_knots(q), 13, 0.5), 3);
    assert_true(max_gap(c, q, 0, 1, 500) <= 16 * EPS * 5);
    cf_bspline_destroy(q);
    {
        cf_diag_t d;
        cf_diag_clear(&d);
        assert_int_equal(cf_bspline_insert_knot(c, 0.5, 3, &q, NULL, &d),
                         CF_STATUS_BAD_KNOTS);
        assert_null(q);
        assert_string_equal(d.msg, "knot 0.5 has multiplicity 1; "
                            "inserting it 3 more times exceeds degree + 1 "
                            "= 3");
        cf_diag_clear(&d);
        assert_int_equal(cf_bspline_insert_knot(c, 1.5, 1, &q, NULL, &d),
                         CF_STATUS_DOMAIN);
        assert_int_equal(cf_bspline_insert_knot(c, 0.5, 0, &q, NULL, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bspline_insert_knot(c, NAN, 1, &q, NULL, NULL),
                         CF_STATUS_NOT_FINITE);
        assert_int_equal(cf_bspline_insert_knot(NULL, 0.5, 1, &q, NULL,
                                                NULL), CF_STATUS_INVALID_ARG);
    }
    cf_bspline_destroy(c);
}

/* Insertion (once, into existing knots, r times), refinement,
** decomposition, elevation, split, segment: the curve does not move
** (~1e-14 relative at hundreds of parameters). */
static void
test_constructions_keep_curve(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 2024);
    for (int trial = 0; trial < 60; trial++) {
        int p = trial % 5;
        bool rat = trial % 3 == 2, clamp = trial % 2 == 0;
        cf_bspline_t *c = random_curve(&r, 2 + (size_t)(trial % 2), p,
                                       (size_t)p + 2 + (size_t)(trial % 7),
                                       clamp, rat);
        cf_bspline_t *q = NULL, *l = NULL, *rt = NULL;
        const double *U = cf_bspline_knots(c);
        size_t nk = cf_bspline_nknots(c);
        double a, b, size = size_of(c), tol = 1e-14 * size * (rat ? 10 : 1);
        double u, X[12];
        int s, times;
        cf_diag_t d;
        cf_bspline_domain(c, &a, &b);
        /* insertion at a random parameter or at an existing knot */
        u = (trial % 4 == 0) ? U[p + 1 + (size_t)trial % (nk - 2 * (size_t)p - 1)]
                             : a + (b - a) * tu_rng_u01(&r);
        if (u > b)
            u = b;
        s = cf_knots_multiplicity(U, nk, u);
        times = p + 1 - s > 0 ? 1 + trial % (p + 1 - s) : 0;
        if (times > 0) {
            cf_diag_clear(&d);
            if (cf_bspline_insert_knot(c, u, times, &q, NULL, &d) != 0)
                fail_msg("trial %d: insert %g x%d: %s", trial, u, times, d.msg);
            assert_valid(q, "insert", trial);
            assert_true(max_gap(c, q, a, b, 300) <= tol);
            cf_bspline_destroy(q);
        }
        /* refinement with duplicates and existing knots */
        for (int i = 0; i < 12; i++)
            X[i] = a + (b - a) * tu_rng_u01(&r);
        qsort(X, 12, sizeof X[0], cmp_double);
        X[3] = X[2];
        cf_diag_clear(&d);
        if (cf_bspline_refine(c, X, p >= 1 ? 12 : 0, &q, &d) != 0)
            fail_msg("trial %d: refine: %s", trial, d.msg);
        assert_valid(q, "refine", trial);
        assert_int_equal(cf_bspline_count(q),
                         cf_bspline_count(c) + (p >= 1 ? 12 : 0));
        assert_true(max_gap(c, q, a, b, 300) <= tol);
        cf_bspline_destroy(q);
        /* split and segment */
        u = a + (b - a) * (0.2 + 0.6 * tu_rng_u01(&r));
        assert_int_equal(cf_bspline_split(c, u, &l, &rt, NULL), 0);
        assert_valid(l, "split left", trial);
        assert_valid(rt, "split right", trial);
        assert_true(max_gap(c, l, a, u, 150) <= tol);
        assert_true(max_gap(c, rt, u, b, 150) <= tol);
        cf_bspline_destroy(l);
        cf_bspline_destroy(rt);
        assert_int_equal(cf_bspline_segment(c, a + 0.1 * (b - a), u, &q,
                                            NULL), 0);
        assert_true(max_gap(c, q, a + 0.1 * (b - a), u, 150) <= tol);
        cf_bspline_destroy(q);
        /* elevation */
        for (int t = 1; t <= 2; t++) {
            cf_diag_clear(&d);
            if (cf_bspline_elevate(c, t, &q, &d) != 0)
                fail_msg("trial %d: elevate: %s", trial, d.msg);
            assert_valid(q, "elevate", trial);
            assert_int_equal(cf_bspline_degree(q), p + t);
            assert_true(max_gap(c, q, a, b, 300) <= 4 * tol);
            /* interior knots keep their continuity: multiplicity + t */
            for (size_t i = (size_t)p + 1; i + (size_t)p + 1 < nk; i++) {
                if (U[i] > a && U[i] < b) {
                    int m0 = cf_knots_multiplicity(U, nk, U[i]);
                    int m1 = cf_knots_multiplicity(cf_bspline_knots(q),
                                                   cf_bspline_nknots(q), U[i]);
                    assert_int_equal(m1, m0 + t);
                }
            }
            cf_bspline_destroy(q);
        }
        cf_bspline_destroy(c);
    }
}

/* Decomposition into Bézier segments with their parameter ranges. */
static void
test_to_beziers(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 555);
    for (int trial = 0; trial < 40; trial++) {
        int p = 1 + trial % 4;
        bool rat = trial % 2 == 1;
        cf_bspline_t *c = trial == 0 ? sample()
                          : random_curve(&r, 2, p, (size_t)p + 1 + (size_t)trial % 9,
                                         trial % 4 < 2, rat);
        cf_bezier_list_t *list = NULL;
        double a, b, size = size_of(c), *H = NULL, *B = NULL;
        size_t nseg = 0, spans = 0;
        const double *U = cf_bspline_knots(c);
        cf_bspline_domain(c, &a, &b);
        for (size_t k = 0; k + 1 < cf_bspline_nknots(c); k++)
            spans += U[k] >= a && U[k + 1] <= b && U[k] < U[k + 1];
        assert_int_equal(cf_bspline_to_beziers(c, &list, NULL), 0);
        assert_int_equal(list->count, spans);
        assert_true(list->t0[0] == a && list->t1[list->count - 1] == b);
        for (size_t i = 0; i < list->count; i++) {
            assert_int_equal(cf_bezier_degree(list->items[i]),
                             cf_bspline_degree(c));
            assert_int_equal(cf_bezier_is_rational(list->items[i]),
                             cf_bspline_is_rational(c));
            if (i > 0)
                assert_true(list->t0[i] == list->t1[i - 1]);
            for (int j = 0; j <= 40; j++) {
                double t = j / 40.0, x[2], y[2];
                double uu = list->t0[i] + t * (list->t1[i] - list->t0[i]);
                if (j == 40)
                    uu = list->t1[i];
                assert_int_equal(cf_bezier_eval(list->items[i], t, x), 0);
                assert_int_equal(cf_bspline_eval(c, uu, y), 0);
                if (tu_max_diff(x, y, 2) > 1e-14 * size * (rat ? 10 : 1))
                    fail_msg("trial %d segment %zu t %g: %g", trial, i, t,
                             tu_max_diff(x, y, 2) / size);
            }
        }
        /* the flat form gives the same points */
        assert_int_equal(cf_bspline_bezier_points(c, &H, &B, &nseg, NULL), 0);
        assert_int_equal(nseg, list->count);
        for (size_t i = 0; i < nseg; i++) {
            size_t n = ((size_t)cf_bspline_degree(c) + 1) * (2 + rat);
            assert_memory_equal(H + i * n, cf_bezier_hpoints(list->items[i]),
                                n * sizeof(double));
            assert_true(B[i] == list->t0[i]);
        }
        cf_free(H);
        cf_free(B);
        cf_bezier_list_destroy(list);
        cf_bspline_destroy(c);
    }
}

/* Insert u r times, then remove it r times: the original comes back. */
static void
test_insert_then_remove(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 31337);
    for (int trial = 0; trial < 60; trial++) {
        int p = 1 + trial % 4, removed = -1;
        bool rat = trial % 3 == 0;
        cf_bspline_t *c = random_curve(&r, 2, p, (size_t)p + 3, true, rat);
        cf_bspline_t *q = NULL, *back = NULL;
        double a, b, u, size = size_of(c);
        int s, times;
        cf_bspline_domain(c, &a, &b);
        u = a + (b - a) * (0.1 + 0.8 * tu_rng_u01(&r));
        s = cf_knots_multiplicity(cf_bspline_knots(c), cf_bspline_nknots(c),
                                  u);
        times = 1 + trial % (p + 1 - s);
        if (s + times > p)
            times = p - s;
        if (times < 1)
            times = 1;
        assert_int_equal(cf_bspline_insert_knot(c, u, times, &q, NULL, NULL),
                         0);
        assert_int_equal(cf_bspline_remove_knot(q, u, times, 1e-10 * size,
                                                &back, &removed, NULL), 0);
        assert_int_equal(removed, times);
        assert_int_equal(cf_bspline_count(back), cf_bspline_count(c));
        assert_memory_equal(cf_bspline_knots(back), cf_bspline_knots(c),
                            cf_bspline_nknots(c) * sizeof(double));
        {
            size_t n = cf_bspline_count(c) * (2 + rat);
            /* the removed points are solved back from the inserted ones:
            ** a few roundings, amplified by 1/alpha of the knot ratios */
            assert_true(tu_max_diff(cf_bspline_hpoints(back),
                                    cf_bspline_hpoints(c), n)
                        <= 1e-12 * size * (rat ? 3 : 1));
        }
        cf_bspline_destroy(back);
        cf_bspline_destroy(q);
        cf_bspline_destroy(c);
    }
    {
        /* a knot that cannot be removed within 0: the sample's 0.5 */
        cf_bspline_t *c = sample(), *q = NULL;
        int removed = -1;
        cf_diag_t d;
        assert_int_equal(cf_bspline_remove_knot(c, 0.5, 1, 0.0, &q, &removed,
                                                NULL), 0);
        assert_int_equal(removed, 0);
        assert_int_equal(cf_bspline_count(q), 8);
        cf_bspline_destroy(q);
        /* with a huge tolerance it goes, and the curve moves */
        assert_int_equal(cf_bspline_remove_knot(c, 0.5, 1, 100.0, &q,
                                                &removed, NULL), 0);
        assert_int_equal(removed, 1);
        assert_int_equal(cf_bspline_count(q), 7);
        cf_bspline_destroy(q);
        cf_diag_clear(&d);
        assert_int_equal(cf_bspline_remove_knot(c, 0.4, 1, 1.0, &q, &removed,
                                                &d), CF_STATUS_BAD_KNOTS);
        assert_string_equal(d.msg, "0.4 is not an interior knot of "
                            "the domain [0, 1]");
        assert_int_equal(cf_bspline_remove_knot(c, 1.0, 1, 1.0, &q, &removed,
                                                NULL), CF_STATUS_BAD_KNOTS);
        assert_int_equal(cf_bspline_remove_knot(c, 0.5, 0, 1.0, &q, &removed,
                                                NULL), CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bspline_remove_knot(c, 0.5, 1, -1.0, &q,
                                                &removed, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bspline_remove_knot(c, NAN, 1, 1.0, &q,
                                                &removed, NULL),
                         CF_STATUS_NOT_FINITE);
        cf_bspline_destroy(c);
    }
}

/* ---- derivative curves, reversal, affine maps --------------------------- */

static void
test_derivative_curve(void **state)
{
    tu_rng r;
    cf_bspline_t *c = sample(), *d = NULL, *d2 = NULL;
    (void)state;
    /* §2.9: Q_0 = p/(u_3 - u_1) (P_1 - P_0), knots u_1 .. u_{m-1} */
    assert_int_equal(cf_bspline_derivative(c, 1, &d, NULL), 0);
    assert_int_equal(cf_bspline_degree(d), 1);
    assert_int_equal(cf_bspline_count(d), 7);
    assert_memory_equal(cf_bspline_knots(d), SAMPLE_U + 1, 9 * sizeof(double));
    tu_assert_close(cf_bspline_hpoints(d)[0], 2 / 0.17 * 0.75, 4 * EPS, 1.0);
    tu_assert_close(cf_bspline_hpoints(d)[1], 2 / 0.17 * 1.0, 4 * EPS, 1.0);
    cf_bspline_destroy(d);
    cf_bspline_destroy(c);
    tu_rng_seed(&r, 11);
    for (int trial = 0; trial < 20; trial++) {
        int p = 1 + trial % 4;
        bool rat = trial % 2 == 1;
        double a, b, size;
        c = random_curve(&r, 2, p, (size_t)p + 4, trial % 4 < 2, rat);
        size = size_of(c);
        cf_bspline_domain(c, &a, &b);
        assert_int_equal(cf_bspline_derivative(c, 1, &d, NULL), 0);
        assert_int_equal(cf_bspline_derivative(c, 2, &d2, NULL), 0);
        for (int i = 0; i <= 100; i++) {
            double u = i == 100 ? b : a + (b - a) * i / 100.0, D[6], x[2],
                   y[2];
            assert_int_equal(cf_bspline_eval_derivs(c, u, 2, D), 0);
            assert_int_equal(cf_bspline_eval(d, u, x), 0);
            assert_int_equal(cf_bspline_eval(d2, u, y), 0);
            /* derivatives grow like p / (knot spacing) ~ 50 per order */
            if (tu_max_diff(x, D + 2, 2) > 1e-12 * size * 50
                || tu_max_diff(y, D + 4, 2) > 1e-11 * size * 2500)
                fail_msg("trial %d u %g: %g %g", trial, u,
                         tu_max_diff(x, D + 2, 2), tu_max_diff(y, D + 4, 2));
        }
        cf_bspline_destroy(d);
        cf_bspline_destroy(d2);
        cf_bspline_destroy(c);
    }
    /* degree 0: the derivative is a zero curve; k < 0 refused */
    {
        double U[] = { 0, 0.5, 1 }, P[] = { 1, 2 };
        double x;
        assert_int_equal(cf_bspline_create(1, 0, U, 3, P, 2, NULL, &c, NULL),
                         0);
        assert_int_equal(cf_bspline_derivative(c, 3, &d, NULL), 0);
        assert_int_equal(cf_bspline_eval(d, 0.7, &x), 0);
        assert_true(x == 0.0);
        cf_bspline_destroy(d);
        assert_int_equal(cf_bspline_derivative(c, -1, &d, NULL),
                         CF_STATUS_INVALID_ARG);
        cf_bspline_destroy(c);
    }
}

/* Reversal keeps a clamped vector valid when (u_0 + u_m) - u_m rounds
** below u_0: with u_0 = 0.652, u_m = 1.441 it gives 0.6519999999999999,
** and forcing only the end knots once left u'_1 < u'_0 (found by the
** fuzzer, tests/fuzz/regressions/knots/). */
/* A derivative or affine image that overflows is refused with NOT_FINITE
** naming the control point, instead of a curve with inf points (found by
** the bad-input corpus, tests/bad/cases/overflow-*.lua). */
static void
test_overflow_refused(void **state)
{
    const double P[] = { -1.7e308, 0, 1.7e308, 1, -1.7e308, 0 };
    const double Q[] = { 0, 0, 1, 1, 2, 0, 3, 1 };
    const double tiny = 1e-320;   /* subnormal: 2 / tiny overflows */
    const double U[] = { 0, 0, 0, tiny, 2 * tiny, 2 * tiny, 2 * tiny };
    const double A[] = { 1e300, 0, 0, 1e300 };
    cf_bspline_t *c = NULL, *d = NULL;
    cf_diag_t diag;
    (void)state;
    assert_int_equal(cf_bspline_create_clamped(2, 2, P, 3, NULL, &c, NULL),
                     0);
    cf_diag_clear(&diag);
    assert_int_equal(cf_bspline_derivative(c, 1, &d, &diag),
                     CF_STATUS_NOT_FINITE);
    assert_null(d);
    assert_non_null(strstr(diag.msg, "overflows"));
    cf_bspline_destroy(c);
    assert_int_equal(cf_bspline_create(2, 2, U, 7, Q, 4, NULL, &c, NULL), 0);
    cf_diag_clear(&diag);
    assert_int_equal(cf_bspline_derivative(c, 1, &d, &diag),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bspline_transform(c, A, NULL, &d, NULL), 0);
    cf_bspline_destroy(d);
    d = NULL;
    cf_bspline_destroy(c);
    assert_int_equal(cf_bspline_create_clamped(2, 2, P, 3, NULL, &c, NULL),
                     0);
    cf_diag_clear(&diag);
    assert_int_equal(cf_bspline_transform(c, A, NULL, &d, &diag),
                     CF_STATUS_NOT_FINITE);
    assert_int_equal(diag.index, 0);
    assert_null(d);
    cf_bspline_destroy(c);
}

/* Removing a knot of multiplicity p + 1 all p + 1 times: the work array
** of A5.8 needs 2p + 2 points, not 2p + 1 (a heap overflow found by the
** fuzzer, tests/fuzz/regressions/knots/remove-full-multiplicity; ASan in
** CI sees it).  The curve is one quadratic, so all copies go and it comes
** back unchanged. */
/* Two knots one ulp apart that (u_0 + u_m) - u rounds onto one value stay
** distinct in the reversed curve (else runs merge beyond p + 1; found by
** the fuzzer, tests/fuzz/regressions/knots/reverse-merges-knots). */
static void
test_reverse_close_knots(void **state)
{
    const double a = 2.6311822376009228, b = 2.6311822376009233;
    const double e = 7.4367647058823536;
    const double U[] = { 0, 0, 0, a, b, e, e, e };
    const double P[] = { 0, 0, 1, 2, 2, 0, 3, 1, 4, 0 };
    cf_bspline_t *c = NULL, *rv = NULL;
    const double *R;
    (void)state;
    assert_true(a < b && (0 + e) - a == (0 + e) - b);
    assert_int_equal(cf_bspline_create(2, 2, U, 8, P, 5, NULL, &c, NULL), 0);
    assert_int_equal(cf_bspline_reverse(c, &rv, NULL), 0);
    R = cf_bspline_knots(rv);
    assert_true(R[3] < R[4]);
    assert_int_equal(cf_knots_validate(2, 5, R, 8, NULL), 0);
    cf_bspline_destroy(rv);
    cf_bspline_destroy(c);
}

static void
test_remove_full_multiplicity(void **state)
{
    const double P[] = { 0, 0, 1, 2, 3, 1 };
    cf_bspline_t *c = NULL, *ins = NULL, *rem = NULL;
    int removed = -1;
    (void)state;
    assert_int_equal(cf_bspline_create_clamped(2, 2, P, 3, NULL, &c, NULL),
                     0);
    assert_int_equal(cf_bspline_insert_knot(c, 0.5, 3, &ins, NULL, NULL), 0);
    assert_int_equal(cf_bspline_count(ins), 6);
    assert_int_equal(cf_bspline_remove_knot(ins, 0.5, 3, 1e-12, &rem,
                                            &removed, NULL), 0);
    assert_int_equal(removed, 3);
    assert_int_equal(cf_bspline_count(rem), 3);
    for (int i = 0; i <= 10; i++) {
        double x[2], y[2];
        assert_int_equal(cf_bspline_eval(c, i / 10.0, x), 0);
        assert_int_equal(cf_bspline_eval(rem, i / 10.0, y), 0);
        /* exact up to rounding of a few operations on values <= 3 */
        assert_true(tu_max_diff(x, y, 2) <= 1e-14 * 3 * 8);
    }
    cf_bspline_destroy(c);
    cf_bspline_destroy(ins);
    cf_bspline_destroy(rem);
}

static void
test_reverse_rounding(void **state)
{
    const double U[] = { 0.652, 0.652, 0.652, 1.0, 1.441, 1.441, 1.441 };
    const double P[] = { 0, 0, 1, 2, 2, 0, 3, 1 };
    cf_bspline_t *c = NULL, *rv = NULL;
    cf_diag_t diag;
    (void)state;
    assert_true((U[0] + U[6]) - U[6] < U[0]);
    assert_int_equal(cf_bspline_create(2, 2, U, 7, P, 4, NULL, &c, NULL), 0);
    assert_int_equal(cf_bspline_reverse(c, &rv, NULL), 0);
    cf_diag_clear(&diag);
    assert_int_equal(cf_knots_validate(2, 4, cf_bspline_knots(rv), 7, &diag),
                     CF_STATUS_OK);
    /* the ends are exact and keep their multiplicity p + 1 */
    assert_true(cf_bspline_knots(rv)[0] == U[0]);
    assert_true(cf_bspline_knots(rv)[2] == U[0]);
    assert_true(cf_bspline_knots(rv)[4] == U[6]);
    assert_true(cf_bspline_knots(rv)[6] == U[6]);
    cf_bspline_destroy(rv);
    cf_bspline_destroy(c);
}

static void
test_reverse_transform(void **state)
{
    cf_bspline_t *c, *rv = NULL, *tr = NULL;
    tu_rng r;
    const double A[4] = { 0.5, -2.0, 1.5, 0.25 }, bb[2] = { 3.0, -1.0 };
    (void)state;
    tu_rng_seed(&r, 3);
    for (int rat = 0; rat < 2; rat++) {
        double a, b;
        c = random_curve(&r, 2, 3, 9, false, rat);
        cf_bspline_domain(c, &a, &b);
        assert_int_equal(cf_bspline_reverse(c, &rv, NULL), 0);
        assert_int_equal(cf_bspline_transform(c, A, bb, &tr, NULL), 0);
        {
            const double *U = cf_bspline_knots(c);
            double s = U[0] + U[cf_bspline_nknots(c) - 1];
            for (int i = 0; i <= 200; i++) {
                double u = a + (b - a) * i / 200.0, x[2], y[2], z[2];
                assert_int_equal(cf_bspline_eval(c, u, x), 0);
                assert_int_equal(cf_bspline_eval(rv, s - u, y), 0);
                assert_int_equal(cf_bspline_eval(tr, u, z), 0);
                assert_true(tu_max_diff(x, y, 2) <= 1e-13 * 10);
                tu_assert_close(z[0], A[0] * x[0] + A[1] * x[1] + bb[0],
                                1e-13, 30.0);
                tu_assert_close(z[1], A[2] * x[0] + A[3] * x[1] + bb[1],
                                1e-13, 30.0);
            }
        }
        cf_bspline_destroy(rv);
        cf_bspline_destroy(tr);
        assert_int_equal(cf_bspline_transform(c, NULL, bb, &tr, NULL),
                         CF_STATUS_INVALID_ARG);
        cf_bspline_destroy(c);
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_insertion_thesis_figures),
        cmocka_unit_test(test_constructions_keep_curve),
        cmocka_unit_test(test_to_beziers),
        cmocka_unit_test(test_insert_then_remove),
        cmocka_unit_test(test_derivative_curve),
        cmocka_unit_test(test_reverse_transform),
        cmocka_unit_test(test_reverse_rounding),
        cmocka_unit_test(test_remove_full_multiplicity),
        cmocka_unit_test(test_reverse_close_knots),
        cmocka_unit_test(test_overflow_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
