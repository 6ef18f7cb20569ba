/* B-spline and NURBS curves (curvefig/bspline.h). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/bspline.h"
#include "../../src/bspline-private.h"
#include "testutil.h"

#define EPS 2.220446049250313e-16

/* The thesis's sample curve (§2.10, figure 2.17). */
static const double SAMPLE_P[16] = { 3, 1, 3.75, 2, 5, 3, 4, 4,
                                     3, 3, 2, 4, 1, 3, 2.25, 2 };
static const double SAMPLE_U[11] = { 0, 0, 0, 0.17, 0.33, 0.5, 0.67, 0.83,
                                     1, 1, 1 };

static cf_bspline_t *
sample(void)
{
    cf_bspline_t *c = NULL;
    assert_int_equal(cf_bspline_create(2, 2, SAMPLE_U, 11, SAMPLE_P, 8, NULL,
                                       &c, NULL), CF_STATUS_OK);
    return c;
}

/* Largest |Cartesian coordinate| of the control points: the curve's size
** for relative tolerances. */
static double
size_of(const cf_bspline_t *c)
{
    size_t n = cf_bspline_count(c) * cf_bspline_dim(c);
    double *pts = malloc(n * sizeof *pts), s = 0.0;
    cf_bspline_get_points(c, pts);
    for (size_t i = 0; i < n; i++)
        s = fmax(s, fabs(pts[i]));
    free(pts);
    return s;
}

/* A random curve: degree p, count points in R^dim, random knots with
** repeated interior knots (multiplicity <= p), clamped or open, rational
** or not. */
static cf_bspline_t *
random_curve(tu_rng *r, size_t dim, int p, size_t count, bool clamp,
             bool rational)
{
    size_t nk = count + (size_t)p + 1, i = 0, end = nk;
    double *U = malloc(nk * sizeof *U), *P = malloc(count * dim * sizeof *P);
    double *W = malloc(count * sizeof *W), x = 0.0;
    cf_bspline_t *c = NULL;
    cf_diag_t d;
    if (clamp) {
        for (; i <= (size_t)p; i++)
            U[i] = 0.0;
        end = nk - (size_t)p - 1;
        x = tu_rng_range(r, 0.1, 1.0);
    }
    while (i < end) {
        size_t run = 1;
        if (p > 1 && tu_rng_u01(r) < 0.2)
            run = 1 + (size_t)(tu_rng_u01(r) * (double)p);
        for (size_t j = 0; j < run && i < end; j++)
            U[i++] = x;
        x += tu_rng_range(r, 0.1, 1.0);
    }
    for (; i < nk; i++)
        U[i] = x;
    for (size_t j = 0; j < count * dim; j++)
        P[j] = tu_rng_range(r, -10.0, 10.0);
    for (size_t j = 0; j < count; j++)
        W[j] = tu_rng_range(r, 0.3, 3.0);
    cf_diag_clear(&d);
    if (cf_bspline_create(dim, p, U, nk, P, count, rational ? W : NULL, &c,
                          &d) != CF_STATUS_OK) {
        /* an open vector can have an empty domain: nudge the middle */
        U[p] = U[nk - 1 - (size_t)p] - 0.5;
        for (int j = p - 1; j >= 0; j--)
            if (U[j] > U[j + 1])
                U[j] = U[j + 1];
        cf_diag_clear(&d);
        if (cf_bspline_create(dim, p, U, nk, P, count, rational ? W : NULL,
                              &c, &d) != CF_STATUS_OK)
            fail_msg("random curve: %s", d.msg);
    }
    free(U);
    free(P);
    free(W);
    return c;
}

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

/* ---- evaluation --------------------------------------------------------- */

static int
cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
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

/* ---- NURBS -------------------------------------------------------------- */

/* With all weights 1 a NURBS is the B-spline. */
static void
test_nurbs_unit_weights(void **state)
{
    double W[8] = { 1, 1, 1, 1, 1, 1, 1, 1 }, x[6], y[6];
    cf_bspline_t *c = sample(), *n = NULL;
    (void)state;
    assert_int_equal(cf_bspline_create(2, 2, SAMPLE_U, 11, SAMPLE_P, 8, W, &n,
                                       NULL), 0);
    assert_true(cf_bspline_is_rational(n));
    for (int i = 0; i <= 500; i++) {
        double u = i / 500.0;
        assert_int_equal(cf_bspline_eval_derivs(c, u, 2, x), 0);
        assert_int_equal(cf_bspline_eval_derivs(n, u, 2, y), 0);
        /* w = sum N_i = 1 up to rounding: the quotient rule changes the
        ** values by a few ulps (derivatives are ~ 2/0.17 and 4/0.17^2
        ** times the size 5) */
        assert_true(tu_max_diff(x, y, 2) <= 8 * EPS * 5);
        assert_true(tu_max_diff(x + 2, y + 2, 2) <= 32 * EPS * 5 * 12);
        assert_true(tu_max_diff(x + 4, y + 4, 2) <= 128 * EPS * 5 * 140);
    }
    cf_bspline_get_weights(n, W);
    assert_true(W[3] == 1.0);
    cf_bspline_destroy(n);
    cf_bspline_destroy(c);
}

static void
test_circle_and_arcs(void **state)
{
    const double O[2] = { 1.5, -2.0 }, X3[3] = { 1, 0, 0 },
                 Y3[3] = { 0, 0.6, 0.8 }, O3[3] = { 1, 2, 3 };
    cf_bspline_t *c = NULL;
    (void)state;
    assert_int_equal(cf_nurbs_circle(O, 2.5, &c, NULL), 0);
    assert_int_equal(cf_bspline_count(c), 9);
    for (int i = 0; i <= 1000; i++) {
        double u = i / 1000.0, x[2], D[4];
        assert_int_equal(cf_bspline_eval(c, u, x), 0);
        /* exact up to rounding */
        tu_assert_close(hypot(x[0] - O[0], x[1] - O[1]), 2.5, 8 * EPS, 1.0);
        /* the tangent is perpendicular to the radius */
        assert_int_equal(cf_bspline_eval_derivs(c, u, 1, D), 0);
        assert_true(fabs((D[0] - O[0]) * D[2] + (D[1] - O[1]) * D[3])
                    <= 1e-13 * 2.5 * hypot(D[2], D[3]));
    }
    cf_bspline_destroy(c);
    /* arcs of several sweeps; a 3D arc in a tilted plane */
    for (int k = 1; k <= 8; k++) {
        double a0 = -0.3, a1 = a0 + k * 2.0 * 3.141592653589793 / 8.0;
        double x[3];
        assert_int_equal(cf_nurbs_arc(3, O3, X3, Y3, 0.75, a0, a1, &c, NULL),
                         0);
        assert_int_equal(cf_bspline_count(c), 2 * (size_t)((k + 1) / 2) + 1);
        for (int i = 0; i <= 300; i++) {
            double u = i / 300.0, rr = 0.0, dot = 0.0;
            assert_int_equal(cf_bspline_eval(c, u, x), 0);
            for (int d = 0; d < 3; d++)
                rr += (x[d] - O3[d]) * (x[d] - O3[d]);
            /* in the plane: orthogonal to X x Y = (0, -0.8, 0.6) */
            dot = -0.8 * (x[1] - O3[1]) + 0.6 * (x[2] - O3[2]);
            tu_assert_close(sqrt(rr), 0.75, 16 * EPS, 1.0);
            assert_true(fabs(dot) <= 16 * EPS * 4);
        }
        assert_int_equal(cf_bspline_eval(c, 1.0, x), 0);
        tu_assert_close(x[0], O3[0] + 0.75 * cos(a1), 8 * EPS, 4.0);
        tu_assert_close(x[1], O3[1] + 0.75 * sin(a1) * 0.6, 8 * EPS, 4.0);
        cf_bspline_destroy(c);
    }
    {
        cf_diag_t d;
        cf_diag_clear(&d);
        assert_int_equal(cf_nurbs_circle(O, -1.0, &c, &d),
                         CF_STATUS_INVALID_ARG);
        assert_string_equal(d.msg, "radius -1 must be positive");
        assert_int_equal(cf_nurbs_circle(NULL, 1.0, &c, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_nurbs_circle(O, NAN, &c, NULL),
                         CF_STATUS_NOT_FINITE);
        assert_int_equal(cf_nurbs_arc(3, O3, X3, Y3, 1.0, 1.0, 1.0, &c, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_nurbs_arc(3, O3, X3, Y3, 1.0, 0.0, 7.0, &c, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_nurbs_arc(1, O3, X3, Y3, 1.0, 0.0, 1.0, &c, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_nurbs_arc(3, O3, X3, Y3, 0.0, 0.0, 1.0, &c, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_nurbs_arc(3, O3, X3, Y3, 1.0, 0.0, INFINITY, &c,
                                      NULL), CF_STATUS_NOT_FINITE);
        assert_null(c);
    }
}

/* ---- closed and Coons curves -------------------------------------------- */

static void
test_closed_curves(void **state)
{
    /* figure 2.18: the heart, 12 points, p = 2, given knots */
    static const double H[24] = { 5, 3, 4, 4, 3, 3, 3, 3, 2, 4, 1, 3,
                                  2.25, 2, 3, 1, 3, 1, 3.75, 2, 5, 3, 4, 4 };
    static const double HU[15] = { 0, 0.07, 0.14, 0.21, 0.28, 0.35, 0.42,
                                   0.5, 0.58, 0.65, 0.72, 0.79, 0.86, 0.93,
                                   1 };
    cf_bspline_t *c = NULL;
    double s0[6], s1[6], a, b;
    (void)state;
    assert_int_equal(cf_bspline_create(2, 2, HU, 15, H, 12, NULL, &c, NULL),
                     0);
    assert_int_equal(cf_bspline_knot_kind(c), CF_KNOTS_PERIODIC);
    cf_bspline_domain(c, &a, &b);
    assert_int_equal(cf_bspline_eval_derivs(c, a, 1, s0), 0);
    assert_int_equal(cf_bspline_eval_derivs(c, b, 1, s1), 0);
    /* closed and C^1 at the seam; knot values like 0.07 round */
    assert_true(tu_max_diff(s0, s1, 4) <= 1e-12 * 100);
    /* P_2 = P_3 = (3,3), p coincident points: the curve passes through
    ** it at u_4 (figure 2.15) */
    assert_int_equal(cf_bspline_eval(c, 0.28, s0), 0);
    tu_assert_close(s0[0], 3.0, 4 * EPS, 1.0);
    tu_assert_close(s0[1], 3.0, 4 * EPS, 1.0);
    cf_bspline_destroy(c);
    /* wrapping: degree 1..4, C(0) = C(1) with p - 1 derivatives */
    for (int p = 1; p <= 4; p++) {
        double W[8] = { 1, 2, 1, 0.5, 1, 1, 3, 1 };
        for (int rat = 0; rat < 2; rat++) {
            double D0[10], D1[10];
            assert_int_equal(cf_bspline_create_closed(2, p, SAMPLE_P, 8,
                                                      rat ? W : NULL, &c,
                                                      NULL), 0);
            assert_int_equal(cf_bspline_count(c), 8 + (size_t)p);
            assert_int_equal(cf_bspline_knot_kind(c), CF_KNOTS_PERIODIC);
            cf_bspline_domain(c, &a, &b);
            assert_true(a == 0.0 && b == 1.0);
            assert_int_equal(cf_bspline_eval_derivs(c, 0.0, p - 1, D0), 0);
            assert_int_equal(cf_bspline_eval_derivs(c, 1.0, p - 1, D1), 0);
            for (int d = 0; d < p; d++)
                assert_true(tu_max_diff(D0 + 2 * d, D1 + 2 * d, 2)
                            <= 1e-13 * pow(40.0, d) * 5);
            cf_bspline_destroy(c);
        }
    }
    assert_int_equal(cf_bspline_create_closed(2, 3, SAMPLE_P, 3, NULL, &c,
                                              NULL), CF_STATUS_TOO_FEW_POINTS);
    assert_int_equal(cf_bspline_create_closed(2, 0, SAMPLE_P, 8, NULL, &c,
                                              NULL), CF_STATUS_BAD_DEGREE);
    assert_int_equal(cf_bspline_create_closed(0, 2, SAMPLE_P, 8, NULL, &c,
                                              NULL), CF_STATUS_INVALID_ARG);
}

static void
test_coons(void **state)
{
    cf_bspline_t *c = NULL;
    double a, b, x[2], y[2];
    (void)state;
    /* plain: segment Q_j on [j - 3, j - 2] is the closed form of
    ** P_{j-3} .. P_j */
    assert_int_equal(cf_bspline_create_coons(2, SAMPLE_P, 8, CF_COONS_PLAIN,
                                             &c, NULL), 0);
    cf_bspline_domain(c, &a, &b);
    assert_true(a == 0.0 && b == 5.0);
    for (int j = 3; j < 8; j++) {
        for (int i = 0; i <= 20; i++) {
            double t = i / 20.0;
            assert_int_equal(cf_bspline_eval(c, j - 3 + t, x), 0);
            cf_coons_eval(2, SAMPLE_P + 2 * (j - 3), t, y);
            assert_true(tu_max_diff(x, y, 2) <= 16 * EPS * 5);
        }
    }
    {
        double bsum[4];
        cf_coons_basis(0.3, bsum);
        tu_assert_close(bsum[0] + bsum[1] + bsum[2] + bsum[3], 1.0, 4 * EPS,
                        1.0);
        tu_assert_close(bsum[0], 0.343 / 6.0, 4 * EPS, 1.0);
    }
    cf_bspline_destroy(c);
    /* tripled ends: through P_0 and P_n */
    assert_int_equal(cf_bspline_create_coons(2, SAMPLE_P, 8, CF_COONS_TRIPLED,
                                             &c, NULL), 0);
    cf_bspline_domain(c, &a, &b);
    assert_int_equal(cf_bspline_eval(c, a, x), 0);
    tu_assert_close(x[0], 3.0, 4 * EPS, 1.0);
    tu_assert_close(x[1], 1.0, 4 * EPS, 1.0);
    assert_int_equal(cf_bspline_eval(c, b, x), 0);
    tu_assert_close(x[0], 2.25, 4 * EPS, 1.0);
    tu_assert_close(x[1], 2.0, 4 * EPS, 1.0);
    cf_bspline_destroy(c);
    /* closed: C^2 at the seam */
    assert_int_equal(cf_bspline_create_coons(2, SAMPLE_P, 8, CF_COONS_CLOSED,
                                             &c, NULL), 0);
    cf_bspline_domain(c, &a, &b);
    {
        double D0[6], D1[6];
        assert_int_equal(cf_bspline_eval_derivs(c, a, 2, D0), 0);
        assert_int_equal(cf_bspline_eval_derivs(c, b, 2, D1), 0);
        assert_true(tu_max_diff(D0, D1, 6) <= 64 * EPS * 5);
    }
    cf_bspline_destroy(c);
    assert_int_equal(cf_bspline_create_coons(2, SAMPLE_P, 3, CF_COONS_PLAIN,
                                             &c, NULL),
                     CF_STATUS_TOO_FEW_POINTS);
    assert_int_equal(cf_bspline_create_coons(2, SAMPLE_P, 8,
                                             (cf_coons_ends_t)7, &c, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bspline_create_coons(2, NULL, 8, CF_COONS_PLAIN, &c,
                                             NULL), CF_STATUS_INVALID_ARG);
}

/* ---- errors ------------------------------------------------------------- */

static void
test_create_errors(void **state)
{
    cf_bspline_t *c = NULL;
    cf_diag_t d;
    double W[8] = { 1, 1, 1, -0.5, 1, 1, 1, 1 }, P[16], U[11], x[4];
    (void)state;
    cf_diag_clear(&d);
    assert_int_equal(cf_bspline_create(2, 2, SAMPLE_U, 11, SAMPLE_P, 8, W, &c,
                                       &d), CF_STATUS_BAD_WEIGHT);
    assert_null(c);
    assert_string_equal(d.msg,
                        "weight 3 is -0.5; weights must be finite and positive");
    cf_diag_clear(&d);
    assert_int_equal(cf_bspline_create(2, 2, SAMPLE_U, 10, SAMPLE_P, 8, NULL,
                                       &c, &d), CF_STATUS_BAD_KNOTS);
    assert_string_equal(d.msg, "10 knots given, degree 2 with 8 "
                        "points needs 11");
    memcpy(U, SAMPLE_U, sizeof U);
    U[4] = 0.3;
    U[3] = 0.5;
    cf_diag_clear(&d);
    assert_int_equal(cf_bspline_create(2, 2, U, 11, SAMPLE_P, 8, NULL, &c,
                                       &d), CF_STATUS_BAD_KNOTS);
    assert_string_equal(d.msg, "knot 4 (0.30) is smaller than knot 3 (0.50)");
    memcpy(P, SAMPLE_P, sizeof P);
    P[9] = NAN;
    cf_diag_clear(&d);
    assert_int_equal(cf_bspline_create(2, 2, SAMPLE_U, 11, P, 8, NULL, &c,
                                       &d), CF_STATUS_NOT_FINITE);
    assert_int_equal(d.index, 4);
    assert_int_equal(cf_bspline_create(0, 2, SAMPLE_U, 11, SAMPLE_P, 8, NULL,
                                       &c, NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bspline_create(2, 2, SAMPLE_U, 11, NULL, 8, NULL, &c,
                                       NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bspline_create(2, 2, SAMPLE_U, 11, SAMPLE_P, 8, NULL,
                                       NULL, NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bspline_create(2, 2, NULL, 11, SAMPLE_P, 8, NULL, &c,
                                       NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bspline_create(2, 9, SAMPLE_U, 11, SAMPLE_P, 8, NULL,
                                       &c, NULL), CF_STATUS_TOO_FEW_POINTS);
    assert_int_equal(cf_bspline_create(2, 99, SAMPLE_U, 11, SAMPLE_P, 8, NULL,
                                       &c, NULL), CF_STATUS_BAD_DEGREE);
    {
        double H[9] = { 0, 0, 1, 1, 1, 2, 2, 2, 0 };
        double K[6] = { 0, 0, 0, 1, 1, 1 };
        cf_diag_clear(&d);
        assert_int_equal(cf_bspline_create_homogeneous(2, 2, K, 6, H, 3, &c,
                                                       &d),
                         CF_STATUS_BAD_WEIGHT);
        assert_string_equal(d.msg, "weight 2 is 0; weights must be finite "
                            "and positive");
        H[8] = 2;
        assert_int_equal(cf_bspline_create_homogeneous(2, 2, K, 6, H, 3, &c,
                                                       NULL), 0);
        assert_int_equal(cf_bspline_eval(c, 1.0, x), 0);
        assert_true(x[0] == 1.0 && x[1] == 1.0);
        cf_bspline_destroy(c);
        assert_int_equal(cf_bspline_create_clamped(2, 3, SAMPLE_P, 8, NULL,
                                                   &c, NULL), 0);
        assert_int_equal(cf_bspline_knot_kind(c), CF_KNOTS_CLAMPED);
        cf_bspline_destroy(c);
        assert_int_equal(cf_bspline_create_clamped(2, 8, SAMPLE_P, 8, NULL,
                                                   &c, NULL),
                         CF_STATUS_TOO_FEW_POINTS);
        assert_int_equal(cf_bspline_create_clamped(2, -1, SAMPLE_P, 8, NULL,
                                                   &c, NULL),
                         CF_STATUS_BAD_DEGREE);
    }
    /* evaluation errors */
    c = sample();
    assert_int_equal(cf_bspline_eval(c, 1.0000001, x), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bspline_eval(c, -1e-14, x), CF_STATUS_DOMAIN);
    {
        /* -1e-300 misses the end 0 by rounding (core.h): it is 0 */
        double x0[2];
        assert_int_equal(cf_bspline_eval(c, -1e-300, x), CF_STATUS_OK);
        assert_int_equal(cf_bspline_eval(c, 0.0, x0), CF_STATUS_OK);
        assert_memory_equal(x, x0, sizeof x0);
    }
    assert_int_equal(cf_bspline_eval(c, NAN, x), CF_STATUS_NOT_FINITE);
    assert_int_equal(cf_bspline_eval(c, 0.5, NULL), CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bspline_eval(NULL, 0.5, x), CF_STATUS_INVALID_ARG);
    {
        double u[3] = { 0.1, 2.0, 0.3 }, out[6];
        assert_int_equal(cf_bspline_eval_many(c, u, 3, out), CF_STATUS_DOMAIN);
        u[1] = INFINITY;
        assert_int_equal(cf_bspline_eval_many(c, u, 3, out),
                         CF_STATUS_NOT_FINITE);
        assert_int_equal(cf_bspline_eval_deriv_many(c, u, 3, 1, out),
                         CF_STATUS_NOT_FINITE);
        assert_int_equal(cf_bspline_eval_deriv_many(c, u, 3, 2, out),
                         CF_STATUS_NOT_FINITE);
        assert_int_equal(cf_bspline_eval_deriv_many(c, u, 3, -1, out),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bspline_eval_many(c, NULL, 3, out),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bspline_eval_many(c, NULL, 0, NULL), 0);
    }
    assert_int_equal(cf_bspline_eval_derivs(c, 0.5, -1, x),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bspline_eval_derivs(c, 3.0, 1, x), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bspline_deboor(c, 0.5, NULL, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bspline_basis(c, 0.5, NULL, NULL),
                     CF_STATUS_INVALID_ARG);
    assert_int_equal(cf_bspline_basis(c, 5.0, NULL, x), CF_STATUS_DOMAIN);
    /* construction errors */
    {
        cf_bspline_t *l = NULL, *r = NULL;
        double X[2] = { 0.6, 0.4 };
        cf_diag_clear(&d);
        assert_int_equal(cf_bspline_split(c, 1.0, &l, &r, &d),
                         CF_STATUS_DOMAIN);
        assert_string_equal(d.msg, "1 must lie strictly inside the "
                            "domain [0, 1]");
        assert_null(l);
        assert_null(r);
        assert_int_equal(cf_bspline_split(NULL, 0.5, &l, &r, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bspline_segment(c, 0.5, 0.5, &l, NULL),
                         CF_STATUS_DOMAIN);
        assert_int_equal(cf_bspline_segment(c, 0.5, 1.5, &l, NULL),
                         CF_STATUS_DOMAIN);
        cf_diag_clear(&d);
        assert_int_equal(cf_bspline_refine(c, X, 2, &l, &d),
                         CF_STATUS_BAD_KNOTS);
        assert_string_equal(d.msg, "new knot 1 (0.40) is smaller than "
                            "new knot 0 (0.60)");
        {
            double X3[3] = { 0.5, 0.5, 0.5 };
            cf_diag_clear(&d);
            assert_int_equal(cf_bspline_refine(c, X3, 3, &l, &d),
                             CF_STATUS_BAD_KNOTS);
            assert_string_equal(d.msg, "knot 0.5 would get "
                                "multiplicity 4; degree 2 allows at most 3");
        }
        assert_int_equal(cf_bspline_refine(c, NULL, 2, &l, NULL),
                         CF_STATUS_INVALID_ARG);
        X[1] = 7.0;
        assert_int_equal(cf_bspline_refine(c, X, 2, &l, NULL),
                         CF_STATUS_DOMAIN);
        /* a NaN or an infinity among sorted-looking knots: the value's
        ** own status, not an order or domain complaint */
        X[0] = 0.2;
        X[1] = NAN;
        assert_int_equal(cf_bspline_refine(c, X, 2, &l, NULL),
                         CF_STATUS_NOT_FINITE);
        X[1] = INFINITY;
        assert_int_equal(cf_bspline_refine(c, X, 2, &l, NULL),
                         CF_STATUS_NOT_FINITE);
        X[0] = -0.1;
        X[1] = 0.5;
        assert_int_equal(cf_bspline_refine(c, X, 2, &l, NULL),
                         CF_STATUS_DOMAIN);
        assert_int_equal(cf_bspline_elevate(c, -1, &l, NULL),
                         CF_STATUS_BAD_DEGREE);
        assert_int_equal(cf_bspline_elevate(c, 40, &l, NULL),
                         CF_STATUS_BAD_DEGREE);
        assert_int_equal(cf_bspline_to_beziers(c, NULL, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bspline_bezier_points(c, NULL, NULL, NULL, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bspline_reverse(NULL, &l, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_int_equal(cf_bspline_copy(NULL, &l, NULL),
                         CF_STATUS_INVALID_ARG);
        assert_null(l);
    }
    /* a knot of multiplicity p + 1 inside: the curve jumps; its
    ** derivative curve drops the vanishing basis function and is right
    ** on both pieces */
    {
        double K[] = { 0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1 };
        cf_bspline_t *s = NULL, *dd = NULL;
        assert_int_equal(cf_bspline_create(2, 2, K, 9, SAMPLE_P, 6, NULL, &s,
                                           NULL), 0);
        assert_int_equal(cf_bspline_derivative(s, 1, &dd, NULL), 0);
        assert_int_equal(cf_bspline_count(dd), 4);
        for (int i = 0; i <= 20; i++) {
            double D[4], y[2], u = i / 20.0;
            assert_int_equal(cf_bspline_eval_derivs(s, u, 1, D), 0);
            assert_int_equal(cf_bspline_eval(dd, u, y), 0);
            assert_true(tu_max_diff(D + 2, y, 2) <= 64 * EPS * 5 * 4);
        }
        cf_bspline_destroy(dd);
        cf_bspline_destroy(s);
    }
    /* queries on NULL */
    assert_int_equal(cf_bspline_dim(NULL), 0);
    assert_int_equal(cf_bspline_degree(NULL), 0);
    assert_int_equal(cf_bspline_count(NULL), 0);
    assert_int_equal(cf_bspline_nknots(NULL), 0);
    assert_false(cf_bspline_is_rational(NULL));
    assert_null(cf_bspline_knots(NULL));
    assert_null(cf_bspline_hpoints(NULL));
    assert_int_equal(cf_bspline_deboor_size(NULL), 0);
    assert_int_equal(cf_bspline_knot_kind(NULL), CF_KNOTS_OPEN);
    cf_bspline_get_points(NULL, x);
    cf_bspline_get_weights(NULL, x);
    cf_bspline_destroy(NULL);
    cf_bspline_destroy(c);
}

/* ---- out of memory ------------------------------------------------------ */

typedef cf_status_t (*op_fn)(const cf_bspline_t *c, void **res);

static cf_status_t
op_create(const cf_bspline_t *c, void **res)
{
    double W[8] = { 1, 2, 1, 1, 1, 1, 1, 1 };
    (void)c;
    return cf_bspline_create(2, 2, SAMPLE_U, 11, SAMPLE_P, 8, W,
                             (cf_bspline_t **)res, NULL);
}

static cf_status_t
op_insert(const cf_bspline_t *c, void **res)
{
    return cf_bspline_insert_knot(c, 0.6, 2, (cf_bspline_t **)res, NULL, NULL);
}

static cf_status_t
op_refine(const cf_bspline_t *c, void **res)
{
    double X[3] = { 0.1, 0.2, 0.7 };
    return cf_bspline_refine(c, X, 3, (cf_bspline_t **)res, NULL);
}

static cf_status_t
op_beziers(const cf_bspline_t *c, void **res)
{
    cf_bspline_t *o = NULL;
    cf_status_t st;
    /* an open curve: clamping allocates too */
    double U[11] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10 };
    (void)c;
    st = cf_bspline_create(2, 2, U, 11, SAMPLE_P, 8, NULL, &o, NULL);
    if (st != CF_STATUS_OK)
        return st;
    st = cf_bspline_to_beziers(o, (cf_bezier_list_t **)res, NULL);
    cf_bspline_destroy(o);
    return st;
}

static cf_status_t
op_elevate(const cf_bspline_t *c, void **res)
{
    return cf_bspline_elevate(c, 1, (cf_bspline_t **)res, NULL);
}

static cf_status_t
op_split(const cf_bspline_t *c, void **res)
{
    cf_bspline_t *l = NULL, *r = NULL;
    cf_status_t st = cf_bspline_split(c, 0.4, &l, &r, NULL);
    cf_bspline_destroy(l);
    *res = r;
    return st;
}

static cf_status_t
op_remove(const cf_bspline_t *c, void **res)
{
    return cf_bspline_remove_knot(c, 0.5, 1, 10.0, (cf_bspline_t **)res, NULL,
                                  NULL);
}

static cf_status_t
op_derivative(const cf_bspline_t *c, void **res)
{
    return cf_bspline_derivative(c, 1, (cf_bspline_t **)res, NULL);
}

static cf_status_t
op_closed(const cf_bspline_t *c, void **res)
{
    (void)c;
    return cf_bspline_create_closed(2, 3, SAMPLE_P, 8, NULL,
                                    (cf_bspline_t **)res, NULL);
}

static cf_status_t
op_arc(const cf_bspline_t *c, void **res)
{
    const double O[2] = { 0, 0 }, X[2] = { 1, 0 }, Y[2] = { 0, 1 };
    (void)c;
    return cf_nurbs_arc(2, O, X, Y, 1.0, 0.0, 4.0, (cf_bspline_t **)res,
                        NULL);
}

static void
test_out_of_memory(void **state)
{
    static const op_fn ops[] = { op_create, op_insert, op_refine, op_beziers,
                                 op_elevate, op_split, op_remove,
                                 op_derivative, op_closed, op_arc };
    double W[8] = { 1, 2, 1, 0.5, 1, 1, 3, 1 };
    cf_bspline_t *curves[2] = { NULL, NULL };
    (void)state;
    curves[0] = sample();
    assert_int_equal(cf_bspline_create(2, 2, SAMPLE_U, 11, SAMPLE_P, 8, W,
                                       &curves[1], NULL), 0);
    for (size_t o = 0; o < sizeof ops / sizeof ops[0]; o++) {
        for (int ci = 0; ci < 2; ci++) {
            for (long k = 1;; k++) {
                void *res = NULL;
                cf_status_t st;
                long live;
                tu_fail_alloc_after(k);
                st = ops[o](curves[ci], &res);
                if (st == CF_STATUS_OK) {
                    if (ops[o] == op_beziers)
                        cf_bezier_list_destroy(res);
                    else
                        cf_bspline_destroy(res);
                    live = tu_alloc_live();
                    tu_fail_alloc_reset();
                    assert_int_equal(live, 0);
                    assert_true(k > 1);
                    break;
                }
                live = tu_alloc_live();
                tu_fail_alloc_reset();
                if (st != CF_STATUS_NO_MEMORY)
                    fail_msg("op %zu curve %d k %ld: status %d", o, ci, k,
                             (int)st);
                assert_null(res);
                assert_int_equal(live, 0);
                assert_true(k < 100);
            }
        }
    }
    cf_bspline_destroy(curves[0]);
    cf_bspline_destroy(curves[1]);
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
        cmocka_unit_test(test_nurbs_unit_weights),
        cmocka_unit_test(test_circle_and_arcs),
        cmocka_unit_test(test_closed_curves),
        cmocka_unit_test(test_coons),
        cmocka_unit_test(test_create_errors),
        cmocka_unit_test(test_out_of_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
