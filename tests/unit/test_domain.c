/*
** The domain rule (core.h, docs/library.md "Parameters at the ends of a
** domain"): a parameter within 8 DBL_EPSILON max(|a|, |b|) outside [a, b]
** is that end, for every evaluator and batch evaluator; further out is
** CF_STATUS_DOMAIN.  The parameters come from the usual loops
** a + (b - a) * i / (N - 1) and a + i * h, h = (b - a) / (N - 1), whose
** last value may overshoot b by rounding.
*/
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/curvefig.h"
#include "testutil.h"

#define MAXP 1001

static const size_t NS[] = { 2, 3, 4, 7, 10, 11, 13, 33, 49, 100, 101,
                             999, 1000, 1001 };

/* The parameters of loop `form` (0: (b - a) i / (N - 1), 1: i h). */
static size_t
loop_params(double a, double b, size_t N, int form, double *u)
{
    double h = (b - a) / (double)(N - 1);
    for (size_t i = 0; i < N; i++)
        u[i] = form == 0 ? a + (b - a) * (double)i / (double)(N - 1)
                         : a + (double)i * h;
    return N;
}

/* 100 units in the last place of the domain's larger end. */
static double
ulps100(double a, double b)
{
    double m = fmax(fabs(a), fabs(b));
    return 100.0 * (nextafter(m, INFINITY) - m);
}

/* Every evaluator of one B-spline at x equals its value at the end e
** (bit for bit), single and batch. */
static void
same_as_end(const cf_bspline_t *c, double x, double e)
{
    double p[8], q[8], d[24], de[24], net[64], nete[64], N[8], Ne[8];
    size_t dim = cf_bspline_dim(c), f, fe, s, se;
    int m, me;
    double lo, hi, loe, hie;
    assert_int_equal(cf_bspline_eval(c, x, p), CF_STATUS_OK);
    assert_int_equal(cf_bspline_eval(c, e, q), CF_STATUS_OK);
    assert_memory_equal(p, q, dim * sizeof *p);
    assert_int_equal(cf_bspline_eval_many(c, &x, 1, p), CF_STATUS_OK);
    assert_int_equal(cf_bspline_eval_many(c, &e, 1, q), CF_STATUS_OK);
    assert_memory_equal(p, q, dim * sizeof *p);
    assert_int_equal(cf_bspline_eval_derivs(c, x, 2, d), CF_STATUS_OK);
    assert_int_equal(cf_bspline_eval_derivs(c, e, 2, de), CF_STATUS_OK);
    assert_memory_equal(d, de, 3 * dim * sizeof *d);
    for (int k = 1; k <= 2; k++) {
        assert_int_equal(cf_bspline_eval_deriv_many(c, &x, 1, k, p),
                         CF_STATUS_OK);
        assert_int_equal(cf_bspline_eval_deriv_many(c, &e, 1, k, q),
                         CF_STATUS_OK);
        assert_memory_equal(p, q, dim * sizeof *p);
    }
    assert_true(cf_bspline_deboor_size(c) <= 64);
    assert_int_equal(cf_bspline_deboor(c, x, net, &s, &m), CF_STATUS_OK);
    assert_int_equal(cf_bspline_deboor(c, e, nete, &se, &me), CF_STATUS_OK);
    assert_memory_equal(net, nete, cf_bspline_deboor_size(c) * sizeof *net);
    assert_true(s == se && m == me);
    assert_int_equal(cf_bspline_basis(c, x, &f, N), CF_STATUS_OK);
    assert_int_equal(cf_bspline_basis(c, e, &fe, Ne), CF_STATUS_OK);
    assert_true(f == fe);
    assert_memory_equal(N, Ne, ((size_t)cf_bspline_degree(c) + 1) * sizeof *N);
    assert_int_equal(cf_bspline_active_points(c, x, &f, &lo, &hi),
                     CF_STATUS_OK);
    assert_int_equal(cf_bspline_active_points(c, e, &fe, &loe, &hie),
                     CF_STATUS_OK);
    assert_true(f == fe && lo == loe && hi == hie);
    {
        int p_ = cf_bspline_degree(c);
        const double *U = cf_bspline_knots(c);
        size_t nk = cf_bspline_nknots(c);
        double D[3 * 8], De[3 * 8];
        assert_int_equal(cf_basis_funs(p_, U, nk, x, &s, N, NULL), 0);
        assert_int_equal(cf_basis_funs(p_, U, nk, e, &se, Ne, NULL), 0);
        assert_true(s == se);
        assert_memory_equal(N, Ne, ((size_t)p_ + 1) * sizeof *N);
        assert_int_equal(cf_basis_ders(p_, U, nk, x, 2, &s, D, NULL), 0);
        assert_int_equal(cf_basis_ders(p_, U, nk, e, 2, &se, De, NULL), 0);
        assert_memory_equal(D, De, 3 * ((size_t)p_ + 1) * sizeof *D);
    }
}

/* The batch evaluators over a whole loop: every parameter evaluates, and
** those outside [a, b] give the end's values exactly. */
static void
check_loop(const cf_bspline_t *c, const double *u, size_t n, double a,
           double b, size_t *outside)
{
    static double out[MAXP * 3], end[3];
    size_t dim = cf_bspline_dim(c);
    for (int k = 0; k <= 2; k++) {
        cf_status_t st = k == 0 ? cf_bspline_eval_many(c, u, n, out)
                                : cf_bspline_eval_deriv_many(c, u, n, k, out);
        assert_int_equal(st, CF_STATUS_OK);
        for (size_t i = 0; i < n; i++) {
            double e = u[i] < a ? a : b;
            if (u[i] >= a && u[i] <= b)
                continue;
            if (k == 0)
                assert_int_equal(cf_bspline_eval_many(c, &e, 1, end), 0);
            else
                assert_int_equal(
                    cf_bspline_eval_deriv_many(c, &e, 1, k, end), 0);
            assert_memory_equal(out + i * dim, end, dim * sizeof *end);
        }
    }
    for (size_t i = 0; i < n; i++)
        if (u[i] < a || u[i] > b) {
            same_as_end(c, u[i], u[i] < a ? a : b);
            (*outside)++;
        }
}

/* Outside by more than the rule: refused, the message naming the domain
** (as "[0.3, 0.9]"). */
static void
refused(const cf_bspline_t *c, double x, const char *domain)
{
    double p[8], N[8];
    size_t s;
    cf_diag_t diag;
    int deg = cf_bspline_degree(c);
    assert_int_equal(cf_bspline_eval(c, x, p), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bspline_eval_many(c, &x, 1, p), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bspline_eval_derivs(c, x, 1, p), CF_STATUS_DOMAIN);
    assert_int_equal(cf_bspline_eval_deriv_many(c, &x, 1, 1, p),
                     CF_STATUS_DOMAIN);
    assert_int_equal(cf_bspline_basis(c, x, NULL, N), CF_STATUS_DOMAIN);
    cf_diag_clear(&diag);
    assert_int_equal(cf_basis_funs(deg, cf_bspline_knots(c),
                                   cf_bspline_nknots(c), x, &s, N, &diag),
                     CF_STATUS_DOMAIN);
    if (strstr(diag.msg, "outside the domain") == NULL ||
        strstr(diag.msg, domain) == NULL)
        fail_msg("message \"%s\" does not name the domain %s", diag.msg,
                 domain);
}

/* The curves on [a, b]: a planar cubic (the vectorised path), a planar
** quadratic NURBS, a cubic in R^3 (the general path); clamped or not. */
static cf_bspline_t *
make(int kind, double a, double b, bool clamped)
{
    static const double P[] = { 0, 0, 0, 1, 2, 1, 3, -1, 2, 4, 0.5, 0,
                                5, 2, 1, 6, 1, 3, 7, 0, 1, 8, 3, 2 };
    static const double W[] = { 1, 2, 0.5, 1, 3, 1, 0.7, 1 };
    int p = kind == 1 ? 2 : 3;
    size_t dim = kind == 2 ? 3 : 2, count = 8;
    double U[16], P2[24];
    cf_bspline_t *c = NULL;
    for (size_t i = 0; i < count; i++)
        for (size_t d = 0; d < dim; d++)
            P2[i * dim + d] = P[i * 3 + d];
    if (clamped)
        assert_int_equal(cf_knots_clamped_uniform(p, count, a, b, U, NULL),
                         0);
    else {
        /* uniform knots whose domain [u_p, u_{m-p}] is [a, b] */
        size_t m = count + (size_t)p;
        double h = (b - a) / (double)(m - 2 * (size_t)p);
        for (size_t i = 0; i <= m; i++)
            U[i] = a + ((double)i - p) * h;
        U[p] = a;
        U[m - (size_t)p] = b;
    }
    assert_int_equal(cf_bspline_create(dim, p, U, count + (size_t)p + 1, P2,
                                       count, kind == 1 ? W : NULL, &c, NULL),
                     CF_STATUS_OK);
    return c;
}

static void
test_bspline_ends(void **state)
{
    static const struct {
        double a, b;
        const char *name;
    } doms[] = {
        { 0.0, 1.0, "[0, 1]" },
        { 0.3, 0.9, "[0.3, 0.9]" },
        { -1e3, 1e3 + 0.5, "[-1000, 1000.5]" },
        { 1e6, 1e6 + 1.0, "[1000000, 1000001]" },
    };
    static double u[MAXP];
    size_t total_outside = 0;
    (void)state;
    for (size_t di = 0; di < sizeof doms / sizeof *doms; di++) {
        double a = doms[di].a, b = doms[di].b;
        for (int clamped = 0; clamped <= 1; clamped++)
            for (int kind = 0; kind < 3; kind++) {
                cf_bspline_t *c = make(kind, a, b, clamped);
                double lo, hi, slack = 8 * DBL_EPSILON * fmax(fabs(a),
                                                                fabs(b));
                cf_bspline_domain(c, &lo, &hi);
                assert_true(lo == a && hi == b);
                for (size_t ni = 0; ni < sizeof NS / sizeof *NS; ni++)
                    for (int form = 0; form < 2; form++) {
                        size_t n = loop_params(a, b, NS[ni], form, u);
                        check_loop(c, u, n, a, b, &total_outside);
                    }
                /* the edge of the rule itself, and just past it */
                same_as_end(c, nextafter(b + slack, -INFINITY), b);
                same_as_end(c, nextafter(a - slack, INFINITY), a);
                same_as_end(c, nextafter(b, INFINITY), b);
                same_as_end(c, nextafter(a, -INFINITY), a);
                refused(c, b + ulps100(a, b), doms[di].name);
                refused(c, a - ulps100(a, b), doms[di].name);
                refused(c, b + 2 * slack, doms[di].name);
                cf_bspline_destroy(c);
            }
    }
    /* the loops did overshoot (0.90000000000000013 over [0.3, 0.9]) */
    assert_true(total_outside > 0);
    {
        double x = 0.3 + (0.9 - 0.3) * 10.0 / 10.0;
        assert_true(x > 0.9);
    }
}

/* Bézier evaluators, offsets and the Bernstein basis on [0, 1]: the ends
** missed by up to 8 DBL_EPSILON are the ends, 9 DBL_EPSILON is refused. */
static void
test_bezier_ends(void **state)
{
    static const double P[] = { 0, 0, 1, 2, 3, 2, 4, 0 };
    static const double W[] = { 1, 2, 0.5, 1 };
    static const double P3[] = { 0, 0, 0, 1, 2, 1, 3, 2, -1, 4, 0, 1 };
    (void)state;
    for (int kind = 0; kind < 3; kind++) {
        cf_bezier_t *c = NULL;
        size_t dim = kind == 2 ? 3 : 2;
        assert_int_equal(cf_bezier_create(dim, 3, kind == 2 ? P3 : P,
                                          kind == 1 ? W : NULL, &c, NULL),
                         0);
        for (int j = 1; j <= 9; j++) {
            double xs[2] = { -j * DBL_EPSILON, 1.0 + j * DBL_EPSILON };
            double es[2] = { 0.0, 1.0 };
            for (int s = 0; s < 2; s++) {
                double x = xs[s], e = es[s];
                double p[4], q[4], d[12], de[12], tri[40], trie[40];
                double k1, k2;
                cf_status_t want = j <= 8 ? CF_STATUS_OK : CF_STATUS_DOMAIN;
                assert_int_equal(cf_bezier_eval(c, x, p), want);
                assert_int_equal(cf_bezier_eval_many(c, &x, 1, p), want);
                assert_int_equal(cf_bezier_eval_derivs(c, x, 2, d), want);
                assert_int_equal(cf_bezier_eval_deriv_many(c, &x, 1, 1, p),
                                 want);
                assert_int_equal(cf_bezier_decasteljau(c, x, tri), want);
                assert_int_equal(cf_bezier_tangent(c, x, p), want);
                assert_int_equal(cf_bezier_normal(c, x, p), want);
                assert_int_equal(cf_bezier_curvature(c, x, &k1), want);
                if (dim == 2) {
                    assert_int_equal(cf_offset_point(c, x, 0.5, p), want);
                    assert_int_equal(cf_offset_point_many(c, &x, 1, 0.5, p),
                                     want);
                }
                if (want != CF_STATUS_OK)
                    continue;
                cf_bezier_eval(c, x, p);
                cf_bezier_eval(c, e, q);
                assert_memory_equal(p, q, dim * sizeof *p);
                cf_bezier_eval_many(c, &x, 1, p);
                cf_bezier_eval_many(c, &e, 1, q);
                assert_memory_equal(p, q, dim * sizeof *p);
                cf_bezier_eval_derivs(c, x, 2, d);
                cf_bezier_eval_derivs(c, e, 2, de);
                assert_memory_equal(d, de, 3 * dim * sizeof *d);
                cf_bezier_eval_deriv_many(c, &x, 1, 2, p);
                cf_bezier_eval_deriv_many(c, &e, 1, 2, q);
                assert_memory_equal(p, q, dim * sizeof *p);
                cf_bezier_decasteljau(c, x, tri);
                cf_bezier_decasteljau(c, e, trie);
                assert_memory_equal(tri, trie,
                                    cf_bezier_decasteljau_size(c) *
                                        sizeof *tri);
                cf_bezier_tangent(c, x, p);
                cf_bezier_tangent(c, e, q);
                assert_memory_equal(p, q, dim * sizeof *p);
                cf_bezier_normal(c, x, p);
                cf_bezier_normal(c, e, q);
                assert_memory_equal(p, q, dim * sizeof *p);
                cf_bezier_curvature(c, x, &k1);
                cf_bezier_curvature(c, e, &k2);
                assert_true(k1 == k2);
                if (dim == 2) {
                    cf_offset_point(c, x, 0.5, p);
                    cf_offset_point(c, e, 0.5, q);
                    assert_memory_equal(p, q, 2 * sizeof *p);
                    cf_offset_point_many(c, &x, 1, 0.5, p);
                    cf_offset_point_many(c, &e, 1, 0.5, q);
                    assert_memory_equal(p, q, 2 * sizeof *p);
                }
            }
        }
        cf_bezier_destroy(c);
    }
}

/* A batch with overshoots among parameters inside (several blocks of
** the clamped copy) equals the batch at the clamped parameters. */
static void
test_bezier_batch(void **state)
{
    static const double P[] = { 0, 0, 1, 2, 3, 2, 4, 0 };
    static double t[700], tc[700], o1[1400], o2[1400];
    cf_bezier_t *c = NULL;
    (void)state;
    assert_int_equal(cf_bezier_create(2, 3, P, NULL, &c, NULL), 0);
    for (size_t i = 0; i < 700; i++) {
        t[i] = (double)i / 699.0;
        if (i % 97 == 5)
            t[i] = i % 2 ? 1.0 + 4 * DBL_EPSILON : -1e-300;
        tc[i] = t[i] < 0.0 ? 0.0 : t[i] > 1.0 ? 1.0 : t[i];
    }
    for (int k = 0; k <= 2; k++) {
        assert_int_equal(cf_bezier_eval_deriv_many(c, t, 700, k, o1), 0);
        assert_int_equal(cf_bezier_eval_deriv_many(c, tc, 700, k, o2), 0);
        assert_memory_equal(o1, o2, sizeof o1);
    }
    t[650] = 1.0 + 1e-13;
    memset(o1, 0, sizeof o1);
    assert_int_equal(cf_bezier_eval_many(c, t, 700, o1), CF_STATUS_DOMAIN);
    for (size_t i = 0; i < 1400; i++)
        assert_true(o1[i] == 0.0);   /* nothing written */
    cf_bezier_destroy(c);
}

static void
test_bernstein_ends(void **state)
{
    static const double coef[] = { 1, -2, 3, 0.5, 2 };
    (void)state;
    for (int j = 1; j <= 9; j++) {
        double xs[2] = { -j * DBL_EPSILON, 1.0 + j * DBL_EPSILON };
        double es[2] = { 0.0, 1.0 };
        for (int s = 0; s < 2; s++) {
            double x = xs[s], e = es[s], v, ve, all[5], alle[5];
            cf_status_t want = j <= 8 ? CF_STATUS_OK : CF_STATUS_DOMAIN;
            assert_int_equal(cf_bernstein_value(4, 2, x, &v), want);
            assert_int_equal(cf_bernstein_all(4, x, all), want);
            assert_int_equal(cf_bernstein_all_deriv(4, x, 1, all), want);
            assert_int_equal(cf_bernstein_eval(4, coef, x, &v), want);
            if (want != CF_STATUS_OK)
                continue;
            cf_bernstein_eval(4, coef, x, &v);
            cf_bernstein_eval(4, coef, e, &ve);
            assert_true(v == ve);
            cf_bernstein_all_deriv(4, x, 2, all);
            cf_bernstein_all_deriv(4, e, 2, alle);
            assert_memory_equal(all, alle, sizeof all);
        }
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bspline_ends),
        cmocka_unit_test(test_bezier_ends),
        cmocka_unit_test(test_bezier_batch),
        cmocka_unit_test(test_bernstein_ends),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
