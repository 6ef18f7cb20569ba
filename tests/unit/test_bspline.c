/* B-spline and NURBS curves (curvefig/bspline.h). This file has the first
** sections; the others are in test_bspline_ops.c and test_bspline_nurbs.c,
** the shared helpers in test_bspline.h. */
#include "test_bspline.h"

/* ---- the thesis's sample curve ------------------------------------------ */

static void
test_sample_curve_ends(void **state)
{
    cf_bspline_t *c = sample();
    double D[6], a, b;
    (void)state;
    cf_bspline_domain(c, &a, &b);
    assert_true(a == 0.0 && b == 1.0);
    assert_int_equal(cf_bspline_knot_kind(c), CF_KNOTS_CLAMPED);
    /* through its end points (N_0 = 1 at 0, N_7 = 1 at 1: exact) */
    assert_int_equal(cf_bspline_eval_derivs(c, 0.0, 1, D), 0);
    assert_true(D[0] == 3.0 && D[1] == 1.0);
    /* C'(0) = p / (u_3 - u_1) (P_1 - P_0) = 2/0.17 (0.75, 1) */
    tu_assert_close(D[2], 2.0 / 0.17 * 0.75, 8 * EPS, 1.0);
    tu_assert_close(D[3], 2.0 / 0.17 * 1.0, 8 * EPS, 1.0);
    assert_int_equal(cf_bspline_eval_derivs(c, 1.0, 1, D), 0);
    assert_true(D[0] == 2.25 && D[1] == 2.0);
    /* C'(1) = 2/(1 - 0.83) (P_7 - P_6) = 2/0.17 (1.25, -1) */
    tu_assert_close(D[2], 2.0 / (1.0 - 0.83) * 1.25, 16 * EPS, 1.0);
    tu_assert_close(D[3], 2.0 / (1.0 - 0.83) * -1.0, 16 * EPS, 1.0);
    /* the end tangents are the end legs: parallel and the same way */
    assert_true(fabs(D[2] * -1.0 - D[3] * 1.25) < 1e-12 * 20);
    assert_true(D[2] * 1.25 + D[3] * -1.0 > 0.0);
    cf_bspline_destroy(c);
}

/* Strong convex hull and local control helpers on the sample curve. */
static void
test_figure_helpers(void **state)
{
    cf_bspline_t *c = sample(), *d = NULL;
    double lo, hi, v[2] = { 0.5, -0.75 };
    size_t first;
    tu_rng r;
    (void)state;
    /* P_4 acts on [u_4, u_{4+p+1}) = [u_4, u_7) = [0.33, 0.83) */
    assert_int_equal(cf_bspline_support(c, 4, &lo, &hi), 0);
    assert_true(lo == 0.33 && hi == 0.83);
    assert_int_equal(cf_bspline_support(c, 8, &lo, &hi),
                     CF_STATUS_INVALID_ARG);
    /* figure 2.7: u = 0.6 lies in [u_5, u_6) = [0.5, 0.67): P_3, P_4, P_5 */
    assert_int_equal(cf_bspline_active_points(c, 0.6, &first, &lo, &hi), 0);
    assert_int_equal(first, 3);
    assert_true(lo == 0.5 && hi == 0.67);
    assert_int_equal(cf_bspline_active_points(c, 1.0, &first, NULL, NULL),
                     0);
    assert_int_equal(first, 5);
    assert_int_equal(cf_bspline_active_points(c, 1.5, &first, NULL, NULL),
                     CF_STATUS_DOMAIN);
    /* §2.6: D(u) = C(u) + N_4(u) v; unchanged outside [u_4, u_7) */
    assert_int_equal(cf_bspline_move_point(c, 4, v, &d, NULL), 0);
    tu_rng_seed(&r, 5);
    for (int i = 0; i <= 400; i++) {
        double u = i / 400.0, C[2], D[2], N[3];
        assert_int_equal(cf_bspline_eval(c, u, C), 0);
        assert_int_equal(cf_bspline_eval(d, u, D), 0);
        if (u < 0.33 || u >= 0.83) {
            assert_true(C[0] == D[0] && C[1] == D[1]);
        } else {
            double n4 = 0.0;
            assert_int_equal(cf_bspline_basis(c, u, &first, N), 0);
            if (first <= 4 && 4 <= first + 2)
                n4 = N[4 - first];
            assert_true(n4 > 0.0 || u == 0.33);
            /* a few roundings of numbers of size 5 */
            tu_assert_close(D[0], C[0] + n4 * v[0], 16 * EPS, 5.0);
            tu_assert_close(D[1], C[1] + n4 * v[1], 16 * EPS, 5.0);
        }
    }
    cf_bspline_destroy(d);
    assert_int_equal(cf_bspline_move_point(c, 9, v, &d, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_null(d);
    cf_bspline_destroy(c);
}

/* The fast batch evaluator agrees with plain de Boor to a few ulps of the
** curve's size, for sorted and random parameters, at knots, at the ends. */
static void
test_eval_many_matches_deboor(void **state)
{
    tu_rng r;
    enum { NP = 700 };
    double *u = malloc(NP * sizeof *u), *out = malloc(NP * 4 * sizeof *out);
    (void)state;
    tu_rng_seed(&r, 77);
    for (int trial = 0; trial < 120; trial++) {
        int p = trial % 6;
        size_t dim = 1 + (size_t)(trial % 4);
        bool rat = trial % 3 == 0;
        cf_bspline_t *c = random_curve(&r, dim, p, (size_t)p + 1
                                       + (size_t)(tu_rng_u01(&r) * 30),
                                       trial % 2 == 0, rat);
        const double *U = cf_bspline_knots(c);
        size_t nk = cf_bspline_nknots(c);
        double a, b, size = size_of(c), worst = 0.0;
        cf_bspline_domain(c, &a, &b);
        for (int i = 0; i < NP; i++)
            u[i] = a + (b - a) * tu_rng_u01(&r);
        /* every knot of the domain, and both ends */
        for (size_t i = 0; i < nk && i < 100; i++)
            if (U[i] >= a && U[i] <= b)
                u[i] = U[i];
        u[NP - 1] = b;
        u[NP - 2] = a;
        for (int pass = 0; pass < 2; pass++) {
            if (pass == 1)
                qsort(u, NP, sizeof *u, cmp_double);
            assert_int_equal(cf_bspline_eval_many(c, u, NP, out), 0);
            for (int i = 0; i < NP; i++) {
                double x[4];
                assert_int_equal(cf_bspline_eval(c, u[i], x), 0);
                worst = fmax(worst, tu_max_diff(x, out + (size_t)i * dim,
                                                dim));
            }
        }
        /* de Boor and the basis sum both round O(p) times on numbers of
        ** the size of the points (seen: up to 5 ulps of the size for
        ** p <= 5); a NURBS adds the division by w */
        if (worst > (rat ? 16 : 8) * EPS * size)
            fail_msg("trial %d (p %d, dim %zu, rational %d): %g ulps", trial,
                     p, dim, rat, worst / (EPS * size));
        cf_bspline_destroy(c);
    }
    free(u);
    free(out);
}

/* While another thread builds the accelerators (state 1), batch calls
** evaluate without them: the same numbers, up to the reciprocal roundings.
** Simulated by setting the state by hand. */
static void
test_eval_many_without_accelerators(void **state)
{
    tu_rng r;
    enum { NP = 300 };
    double u[NP], fast[NP * 3], slow[NP * 3];
    (void)state;
    tu_rng_seed(&r, 404);
    for (int trial = 0; trial < 24; trial++) {
        int p = 1 + trial % 4, k = trial % 3;
        bool rat = trial % 2 == 1;
        size_t dim = 2 + (size_t)(trial % 2);
        cf_bspline_t *c = random_curve(&r, dim, p, (size_t)p + 9, true, rat);
        double a, b, size = size_of(c);
        cf_bspline_domain(c, &a, &b);
        for (int i = 0; i < NP; i++)
            u[i] = a + (b - a) * tu_rng_u01(&r);
        if (trial % 4 == 0)
            qsort(u, NP, sizeof u[0], cmp_double);
        /* first call: builds them (state 2 afterwards) */
        assert_int_equal(cf_bspline_eval_deriv_many(c, u, NP, k, fast), 0);
        assert_int_equal(atomic_load(&c->accel), 2);
        atomic_store(&c->accel, 1);
        assert_int_equal(cf_bspline_eval_deriv_many(c, u, NP, k, slow), 0);
        if (k == 0) {
            assert_int_equal(cf_bspline_eval_many(c, u, NP, slow), 0);
        }
        atomic_store(&c->accel, 2);
        /* derivatives scale with p / (knot spacing), up to ~30 per order */
        if (tu_max_diff(fast, slow, NP * dim)
            > 64 * EPS * size * pow(30.0, k) * (rat ? 10 : 1))
            fail_msg("trial %d: %g", trial, tu_max_diff(fast, slow, NP * dim));
        cf_bspline_destroy(c);
    }
}

/* The batch span search is exact: the p-th derivative is constant on
** each span and jumps at a simple knot, so a span off by one shows.  At
** every knot (the right piece), just below it (the left piece), and at
** random parameters, in random order, against the bisection of
** cf_bspline_eval_derivs. */
static void
test_batch_span_search_exact(void **state)
{
    tu_rng r;
    enum { NP = 400 };
    double u[NP], D[NP * 2], E[12];
    (void)state;
    tu_rng_seed(&r, 8080);
    for (int trial = 0; trial < 40; trial++) {
        int p = 1 + trial % 4;
        size_t count = (size_t)p + 5 + (size_t)(tu_rng_u01(&r) * 40), np = 0;
        cf_bspline_t *c = NULL;
        double *U = malloc((count + (size_t)p + 1) * sizeof *U);
        double *P = malloc(2 * count * sizeof *P), a, b;
        size_t nk = count + (size_t)p + 1;
        /* clamped, interior knots simple (uniform for some trials) */
        for (size_t i = 0; i < nk; i++) {
            if (i <= (size_t)p)
                U[i] = 0.0;
            else if (i >= count)
                U[i] = 1.0;
            else
                U[i] = trial % 3 == 0
                       ? (double)(i - (size_t)p) / (double)(count - (size_t)p)
                       : U[i - 1] + tu_rng_range(&r, 0.01, 1.0);
        }
        if (trial % 3 != 0) {
            double top = U[count - 1] + tu_rng_range(&r, 0.01, 1.0);
            for (size_t i = count; i < nk; i++)
                U[i] = top;
        }
        for (size_t i = 0; i < 2 * count; i++)
            P[i] = tu_rng_range(&r, -1, 1);
        assert_int_equal(cf_bspline_create(2, p, U, nk, P, count, NULL, &c,
                                           NULL), 0);
        cf_bspline_domain(c, &a, &b);
        for (size_t i = (size_t)p; i <= count && np + 2 <= NP; i++) {
            u[np++] = U[i];
            if (U[i] > a)
                u[np++] = nextafter(U[i], -INFINITY);
        }
        while (np < NP)
            u[np++] = a + (b - a) * tu_rng_u01(&r);
        for (size_t i = NP - 1; i > 0; i--) {
            size_t j = (size_t)(tu_rng_u01(&r) * (double)(i + 1));
            double t = u[i];
            u[i] = u[j];
            u[j] = t;
        }
        assert_int_equal(cf_bspline_eval_deriv_many(c, u, NP, p, D), 0);
        for (size_t i = 0; i < NP; i++) {
            assert_int_equal(cf_bspline_eval_derivs(c, u[i], p, E), 0);
            /* the p-th derivative reaches p! / h^p ~ 1e4..1e8 here; a
            ** different span changes it by O(1) of its size */
            for (int d = 0; d < 2; d++) {
                double want = E[2 * p + d];
                if (fabs(D[2 * i + d] - want) > 1e-9 * (1.0 + fabs(want)))
                    fail_msg("trial %d: u = %.17g: %.17g vs %.17g", trial,
                             u[i], D[2 * i + d], want);
            }
        }
        cf_bspline_destroy(c);
        free(U);
        free(P);
    }
}

/* The W3 curve of the benchmarks: uniform knots, sorted and random
** parameters, against de Boor. */
static void
test_eval_many_w3_shape(void **state)
{
    enum { N = 1000, M = 20000 };
    double *U = malloc((N + 4) * sizeof *U), *P = malloc(2 * N * sizeof *P);
    double *u = malloc(M * sizeof *u), *out = malloc(2 * M * sizeof *out);
    double *d1 = malloc(2 * M * sizeof *d1);
    cf_bspline_t *c = NULL;
    tu_rng r;
    double worst = 0.0, worstd = 0.0;
    (void)state;
    tu_rng_seed(&r, 1003);
    for (int i = 0; i < 4; i++) {
        U[i] = 0.0;
        U[N + i] = 1.0;
    }
    for (int i = 1; i <= 996; i++)
        U[3 + i] = i / 997.0;
    for (int i = 0; i < 2 * N; i++)
        P[i] = tu_rng_u01(&r);
    assert_int_equal(cf_bspline_create(2, 3, U, N + 4, P, N, NULL, &c, NULL),
                     0);
    for (int i = 0; i < M; i++)
        u[i] = tu_rng_u01(&r);
    for (int pass = 0; pass < 2; pass++) {
        if (pass == 1)
            qsort(u, M, sizeof *u, cmp_double);
        assert_int_equal(cf_bspline_eval_many(c, u, M, out), 0);
        assert_int_equal(cf_bspline_eval_deriv_many(c, u, M, 1, d1), 0);
        for (int i = 0; i < M; i++) {
            double D[4];
            assert_int_equal(cf_bspline_eval_derivs(c, u[i], 1, D), 0);
            worst = fmax(worst, tu_max_diff(D, out + 2 * i, 2));
            worstd = fmax(worstd, tu_max_diff(D + 2, d1 + 2 * i, 2));
        }
    }
    /* points in [0, 1): a few ulps; derivatives scale with 3 * 997 */
    assert_true(worst <= 8 * EPS);
    assert_true(worstd <= 64 * EPS * 3 * 997);
    free(U);
    free(P);
    free(u);
    free(out);
    free(d1);
    cf_bspline_destroy(c);
}

/* The planar cubic batch path takes sorted parameters in runs on one span
** and random ones in blocks of span searches: a bad parameter anywhere
** (inside a run, inside a block, first, last) is reported, and the points
** before it are the ones of the good parameters (checked against de Boor,
** same tolerance reasoning as test_eval_many_w3_shape). */
static void
test_eval_many_cubic2_bad_parameter_anywhere(void **state)
{
    enum { N = 40, M = 100 };
    double U[N + 4], P[2 * N], u[M], out[2 * M], D[2];
    const double bad[3] = { NAN, -0.25, 1.5 };
    const cf_status_t want[3] = { CF_STATUS_NOT_FINITE, CF_STATUS_DOMAIN,
                                  CF_STATUS_DOMAIN };
    cf_bspline_t *c = NULL;
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 1009);
    for (int i = 0; i < 4; i++) {
        U[i] = 0.0;
        U[N + i] = 1.0;
    }
    for (int i = 1; i < N - 3; i++)
        U[3 + i] = i / (double)(N - 3);
    for (int i = 0; i < 2 * N; i++)
        P[i] = tu_rng_u01(&r);
    assert_int_equal(cf_bspline_create(2, 3, U, N + 4, P, N, NULL, &c, NULL),
                     0);
    for (int sorted = 0; sorted < 2; sorted++)
        for (int kind = 0; kind < 3; kind++)
            for (int at = 0; at < M; at++)
                for (int deriv = 0; deriv < 2; deriv++) {
                    for (int i = 0; i < M; i++)
                        u[i] = sorted ? (i + 0.5) / M : tu_rng_u01(&r);
                    u[at] = bad[kind];
                    assert_int_equal(
                        deriv ? cf_bspline_eval_deriv_many(c, u, M, 1, out)
                              : cf_bspline_eval_many(c, u, M, out),
                        want[kind]);
                    if (deriv)
                        continue;
                    for (int i = 0; i < at; i++) {
                        assert_int_equal(cf_bspline_eval(c, u[i], D), 0);
                        assert_true(tu_max_diff(D, out + 2 * i, 2)
                                    <= 8 * EPS);
                    }
                }
    cf_bspline_destroy(c);
}

/* Derivatives: against central differences, and the batch form. */
static void
test_derivatives_central_differences(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 4242);
    for (int trial = 0; trial < 40; trial++) {
        int p = 1 + trial % 5;
        bool rat = trial % 2 == 1;
        cf_bspline_t *c = random_curve(&r, 2, p, (size_t)p + 6, true, rat);
        const double *U = cf_bspline_knots(c);
        double a, b, size = size_of(c);
        cf_bspline_domain(c, &a, &b);
        for (int i = 0; i < 50; i++) {
            double u = a + (b - a) * tu_rng_u01(&r), h = 1e-5 * (b - a);
            double D[8], lo[2], hi[2], D2[2];
            size_t k = cf_knots_find_span(p, U, cf_bspline_nknots(c), u);
            if (u - h < U[k] || u + h >= U[k + 1])
                continue;   /* differences across a knot are not smooth */
            assert_int_equal(cf_bspline_eval_derivs(c, u, 3, D), 0);
            assert_int_equal(cf_bspline_eval(c, u - h, lo), 0);
            assert_int_equal(cf_bspline_eval(c, u + h, hi), 0);
            for (int d = 0; d < 2; d++) {
                /* truncation h^2 |C'''| / 6 (|C'''| <~ 1e4 size here),
                ** rounding eps size / h */
                double fd = (hi[d] - lo[d]) / (2 * h);
                double fd2 = (hi[d] - 2 * D[d] + lo[d]) / (h * h);
                tu_assert_close(D[2 + d], fd, 1e-5, size * 100);
                tu_assert_close(D[4 + d], fd2, 1e-3, size * 1e4);
            }
            for (int k2 = 0; k2 <= 3; k2++) {
                assert_int_equal(cf_bspline_eval_deriv_many(c, &u, 1, k2, D2),
                                 0);
                tu_assert_close(D2[0], D[2 * k2], 1e-12, size * 1e3);
                tu_assert_close(D2[1], D[2 * k2 + 1], 1e-12, size * 1e3);
            }
        }
        cf_bspline_destroy(c);
    }
}

/* C^{p-k} at a k-fold knot: the (p-k)th derivative is continuous, the
** (p-k+1)th jumps.  Left limits come from the piece [a, u] (cf_bspline_
** segment ends there, and evaluation at the end takes the last piece). */
static void
test_continuity_at_multiple_knots(void **state)
{
    const int p = 3;
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 99);
    for (int k = 1; k <= p; k++) {
        double U[14], P[20], L[10], R[10];
        cf_bspline_t *c = NULL, *left = NULL;
        size_t count, nk;
        int i = 0;
        for (; i <= p; i++)
            U[i] = 0.0;
        U[i++] = 0.25;
        for (int j = 0; j < k; j++)
            U[i++] = 0.5;
        U[i++] = 0.75;
        for (int j = 0; j <= p; j++)
            U[i++] = 1.0;
        nk = (size_t)i;
        count = nk - (size_t)p - 1;
        for (size_t j = 0; j < 2 * count; j++)
            P[j] = tu_rng_range(&r, -1.0, 1.0);
        assert_int_equal(cf_bspline_create(2, p, U, nk, P, count, NULL, &c,
                                           NULL), 0);
        assert_int_equal(cf_bspline_segment(c, 0.0, 0.5, &left, NULL), 0);
        assert_int_equal(cf_bspline_eval_derivs(left, 0.5, 4, L), 0);
        assert_int_equal(cf_bspline_eval_derivs(c, 0.5, 4, R), 0);
        for (int d = 0; d <= p - k; d++) {
            /* derivative d is ~ 4^d |P|: a few roundings of that */
            double scale = pow(8.0, d);
            assert_true(fabs(L[2 * d] - R[2 * d]) <= 1e-13 * scale);
            assert_true(fabs(L[2 * d + 1] - R[2 * d + 1]) <= 1e-13 * scale);
        }
        {
            int d = p - k + 1;
            double jump = hypot(L[2 * d] - R[2 * d], L[2 * d + 1] - R[2 * d + 1]);
            /* random points: the jump is of the size of the derivative */
            assert_true(jump > 1e-3);
        }
        cf_bspline_destroy(left);
        cf_bspline_destroy(c);
    }
}

/* ---- the de Boor net and the Bézier special case ------------------------ */

static void
test_deboor_net(void **state)
{
    cf_bspline_t *c = sample(), *l = NULL, *rt = NULL;
    double net[6 * 2], C[2];
    const double *P;
    size_t span;
    int mult;
    (void)state;
    assert_int_equal(cf_bspline_deboor_size(c), 12);
    assert_int_equal(cf_bspline_deboor(c, 0.6, net, &span, &mult), 0);
    assert_int_equal(span, 5);
    assert_int_equal(mult, 0);
    /* level 0: P_3, P_4, P_5 */
    P = cf_bspline_hpoints(c);
    assert_memory_equal(net, P + 6, 6 * sizeof(double));
    /* level 1: P_{4,1} = (1 - a) P_3 + a P_4, a = (0.6 - u_4)/(u_6 - u_4) */
    {
        double a = (0.6 - 0.33) / (0.67 - 0.33);
        tu_assert_close(net[6], (1 - a) * P[6] + a * P[8], 4 * EPS, 5.0);
        tu_assert_close(net[7], (1 - a) * P[7] + a * P[9], 4 * EPS, 5.0);
    }
    /* level 2 is C(u) */
    assert_int_equal(cf_bspline_eval(c, 0.6, C), 0);
    tu_assert_close(net[10], C[0], 4 * EPS, 5.0);
    tu_assert_close(net[11], C[1], 4 * EPS, 5.0);
    /* §3.3: the left part's polygon ends with the first point of every
    ** level, the right part's starts with the last ones */
    assert_int_equal(cf_bspline_split(c, 0.6, &l, &rt, NULL), 0);
    {
        const double *Lp = cf_bspline_hpoints(l), *Rp = cf_bspline_hpoints(rt);
        size_t nl = cf_bspline_count(l);
        /* left: ..., P_3, P_{4,1}, C; right: C, P_{5,1}, P_5, ... */
        tu_assert_close(Lp[2 * (nl - 3)], net[0], 4 * EPS, 5.0);
        tu_assert_close(Lp[2 * (nl - 2)], net[6], 4 * EPS, 5.0);
        tu_assert_close(Lp[2 * (nl - 1)], net[10], 4 * EPS, 5.0);
        tu_assert_close(Rp[0], net[10], 4 * EPS, 5.0);
        tu_assert_close(Rp[2], net[8], 4 * EPS, 5.0);
        tu_assert_close(Rp[4], net[4], 4 * EPS, 5.0);
    }
    cf_bspline_destroy(l);
    cf_bspline_destroy(rt);
    /* at an existing knot: multiplicity reported */
    assert_int_equal(cf_bspline_deboor(c, 0.5, net, &span, &mult), 0);
    assert_int_equal(mult, 1);
    assert_int_equal(span, 5);
    assert_int_equal(cf_bspline_deboor(c, 2.0, net, &span, &mult),
                     CF_STATUS_DOMAIN);
    cf_bspline_destroy(c);
}

/* A clamped curve with n = p is the Bézier curve of its points. */
static void
test_clamped_n_equals_p_is_bezier(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 8);
    for (int p = 1; p <= 7; p++) {
        double P[16], W[8], x[2], y[2];
        double U[16];
        cf_bspline_t *c = NULL;
        cf_bezier_t *z = NULL;
        for (int i = 0; i < 2 * (p + 1); i++)
            P[i] = tu_rng_range(&r, -3, 3);
        for (int i = 0; i <= p; i++) {
            W[i] = tu_rng_range(&r, 0.5, 2);
            U[i] = 0.0;
            U[p + 1 + i] = 1.0;
        }
        for (int rat = 0; rat < 2; rat++) {
            assert_int_equal(cf_bspline_create(2, p, U, 2 * (size_t)p + 2, P,
                                               (size_t)p + 1,
                                               rat ? W : NULL, &c, NULL), 0);
            assert_int_equal(cf_bezier_create(2, p, P, rat ? W : NULL, &z,
                                              NULL), 0);
            for (int i = 0; i <= 200; i++) {
                double t = i / 200.0;
                assert_int_equal(cf_bspline_eval(c, t, x), 0);
                assert_int_equal(cf_bezier_eval(z, t, y), 0);
                /* de Boor on these knots is de Casteljau */
                assert_true(tu_max_diff(x, y, 2) <= 16 * EPS * 3 * 4);
            }
            cf_bspline_destroy(c);
            cf_bezier_destroy(z);
        }
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sample_curve_ends),
        cmocka_unit_test(test_figure_helpers),
        cmocka_unit_test(test_eval_many_matches_deboor),
        cmocka_unit_test(test_eval_many_w3_shape),
        cmocka_unit_test(test_eval_many_cubic2_bad_parameter_anywhere),
        cmocka_unit_test(test_eval_many_without_accelerators),
        cmocka_unit_test(test_batch_span_search_exact),
        cmocka_unit_test(test_derivatives_central_differences),
        cmocka_unit_test(test_continuity_at_multiple_knots),
        cmocka_unit_test(test_deboor_net),
        cmocka_unit_test(test_clamped_n_equals_p_is_bezier),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
