/* Refinement with many knots and the Bézier pieces of cubics, checked
** against independent methods: the planar refinement kernel against the
** general loop (the same curve lifted to R^3), both against the curve;
** the cubic pieces (blossom) against refinement (A5.4) to multiplicity 3
** at every break; the curves of cf_bspline_to_beziers, made in one block,
** destroyed one by one in any order. */
#include "test_bspline.h"

#include "curvefig/bezier.h"

/* A cubic in R^dim (rational: weights in [0.3, 3]) with count points and
** interior knots of multiplicity 1..mmax (mmax 4: the curve may jump),
** clamped or open; spans of random length. */
static cf_bspline_t *
cubic(tu_rng *r, size_t dim, size_t count, int mmax, bool clamp, bool rat)
{
    size_t nk = count + 4, i = 0;
    double *U = malloc(nk * sizeof *U), *P = malloc(count * dim * sizeof *P);
    double *W = malloc(count * sizeof *W), x = 0.0;
    cf_bspline_t *c = NULL;
    cf_diag_t d;
    if (clamp) {
        for (; i < 4; i++)
            U[i] = 0.0;
        x = tu_rng_range(r, 0.05, 1.0);
    }
    while (i < nk) {
        size_t run = 1 + (size_t)(tu_rng_u01(r) * mmax);
        if (tu_rng_u01(r) < 0.7)
            run = 1;
        if (clamp && i + run > nk - 4)
            run = nk - 4 > i ? nk - 4 - i : 0;
        if (i + run > nk)
            run = nk - i;
        for (size_t j = 0; j < run; j++)
            U[i++] = x;
        x += tu_rng_range(r, 0.05, 1.0);
        if (clamp && i == nk - 4)
            for (; i < nk; i++)
                U[i] = x;
    }
    random_points(r, count, dim, P, W);
    /* an open vector whose domain is one knot: spread its start */
    if (!clamp && U[3] == U[count])
        for (size_t j = 0; j < 4; j++)
            U[j] = U[3] - (double)(4 - j) * 0.25;
    cf_diag_clear(&d);
    if (cf_bspline_create(dim, 3, U, nk, P, count, rat ? W : NULL, &c, &d)
        != CF_STATUS_OK)
        fail_msg("cubic: %s", d.msg);
    free(U);
    free(P);
    free(W);
    return c;
}

/* The planar polynomial curve c lifted to R^3 (z = 0): refined by the
** general loop, where c takes the planar kernel. */
static cf_bspline_t *
lifted(const cf_bspline_t *c)
{
    size_t n = cf_bspline_count(c);
    double *P2 = malloc(2 * n * sizeof *P2), *P3 = malloc(3 * n * sizeof *P3);
    cf_bspline_t *l = NULL;
    cf_bspline_get_points(c, P2);
    for (size_t i = 0; i < n; i++) {
        P3[3 * i] = P2[2 * i];
        P3[3 * i + 1] = P2[2 * i + 1];
        P3[3 * i + 2] = 0.0;
    }
    assert_int_equal(cf_bspline_create(3, cf_bspline_degree(c),
                                       cf_bspline_knots(c),
                                       cf_bspline_nknots(c), P3, n, NULL, &l,
                                       NULL), 0);
    free(P2);
    free(P3);
    return l;
}

/* max |c1(u) - c2(u)| at n + 1 parameters over the domain of c1. */
static double
gap(const cf_bspline_t *c1, const cf_bspline_t *c2, int n)
{
    double a, b, x[4], y[4], m = 0.0;
    cf_bspline_domain(c1, &a, &b);
    for (int i = 0; i <= n; i++) {
        double u = i == n ? b : a + (b - a) * i / n;
        assert_int_equal(cf_bspline_eval(c1, u, x), 0);
        assert_int_equal(cf_bspline_eval(c2, u, y), 0);
        m = fmax(m, tu_max_diff(x, y, cf_bspline_dim(c1)));
    }
    return m;
}

/* Up to nx new knots for c, sorted, within the multiplicity p + 1 = 4:
** random ones, existing knots, repeats, the ends of the domain. */
static size_t
new_knots(tu_rng *r, const cf_bspline_t *c, double *X, size_t nx)
{
    const double *U = cf_bspline_knots(c);
    size_t nk = cf_bspline_nknots(c), n = 0;
    double a, b;
    cf_bspline_domain(c, &a, &b);
    for (size_t j = 0; j < nx; j++) {
        double v, f = tu_rng_u01(r);
        if (f < 0.1)
            v = U[3 + (size_t)(tu_rng_u01(r) * (double)(nk - 7))];
        else if (f < 0.13)
            v = f < 0.115 ? a : b;
        else if (f < 0.2 && n > 0)
            v = X[n - 1];
        else
            v = a + (b - a) * tu_rng_u01(r);
        X[n++] = v;
        qsort(X, n, sizeof X[0], cmp_double);
        if (cf_knots_multiplicity(X, n, v) + cf_knots_multiplicity(U, nk, v)
            > 4) {
            /* drop one copy of v again */
            size_t k = 0;
            while (X[k] != v)
                k++;
            memmove(X + k, X + k + 1, (n - k - 1) * sizeof X[0]);
            n--;
        }
    }
    return n;
}

/* The planar kernel and the general loop: the same knots, and the same
** points up to one rounding per interpolation of a point's chain (at most
** nx of them, each a convex combination: bitwise without fused
** multiply-adds); the refined curves trace the original to 64 ulps of
** its size (a point's chain is a few interpolations, evaluation 2p + 2
** roundings; the worst seen is 6.5). */
static void
test_refine_planar_kernel(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 2811);
    for (int trial = 0; trial < 120; trial++) {
        bool clamp = trial % 3 != 2;
        size_t count = 4 + (size_t)trial % 40, nx;
        cf_bspline_t *c = cubic(&r, 2, count, trial % 5 == 4 ? 4 : 3, clamp,
                                false);
        cf_bspline_t *c3 = lifted(c), *q = NULL, *q3 = NULL;
        double X[400], size = size_of(c);
        const double *P, *P3;
        cf_diag_t d;
        nx = new_knots(&r, c, X, 1 + (size_t)trial * 3 % 400);
        cf_diag_clear(&d);
        if (cf_bspline_refine(c, X, nx, &q, &d) != CF_STATUS_OK)
            fail_msg("trial %d: %s", trial, d.msg);
        assert_int_equal(cf_bspline_refine(c3, X, nx, &q3, NULL), 0);
        assert_int_equal(cf_bspline_count(q), count + nx);
        assert_int_equal(cf_bspline_count(q3), count + nx);
        assert_memory_equal(cf_bspline_knots(q), cf_bspline_knots(q3),
                            cf_bspline_nknots(q) * sizeof(double));
        P = cf_bspline_hpoints(q);
        P3 = cf_bspline_hpoints(q3);
        for (size_t i = 0; i < count + nx; i++)
            for (int k = 0; k < 2; k++)
                if (fabs(P[2 * i + k] - P3[3 * i + k])
                    > (double)nx * EPS * size)
                    fail_msg("trial %d point %zu: %.17g %.17g", trial, i,
                             P[2 * i + k], P3[3 * i + k]);
        if (gap(c, q, 997) > 64 * EPS * size)
            fail_msg("trial %d: the refined curve moved by %g ulps", trial,
                     gap(c, q, 997) / (EPS * size));
        cf_bspline_destroy(q);
        cf_bspline_destroy(q3);
        cf_bspline_destroy(c3);
        cf_bspline_destroy(c);
    }
}

/* The new knots are refused as before the branch-free checks: out of the
** domain, unsorted, NaN, or past multiplicity 4 (with the existing
** knots, also at a clamped end or at a knot where the curve jumps). */
static void
test_refine_refused(void **state)
{
    static const double U[] = { 0, 0, 0, 0, 1, 2, 2, 2, 2, 3, 4, 4, 4, 4 };
    static const double P[20] = { 0, 0, 1, 3, 2, -1, 4, 0, 5, 2,
                                  6, 6, 7, 1, 8, 3, 9, -2, 10, 0 };
    cf_bspline_t *c = NULL, *q = NULL;
    cf_diag_t d;
    (void)state;
    assert_int_equal(cf_bspline_create(2, 3, U, 14, P, 10, NULL, &c, NULL),
                     0);
    {
        const double bad_order[] = { 0.5, 0.25 }, nan[] = { 0.5, NAN };
        const double outside[] = { 0.5, 4.5 }, at_end[] = { 0.0, 0.5 };
        const double jump[] = { 1.5, 2.0 }, four[] = { 1, 1, 1, 1 };
        const double ok3[] = { 0.5, 1, 1, 1, 3.9 }, end_b[] = { 3.5, 4.0 };
        struct {
            const double *x;
            size_t n;
            cf_status_t st;
        } cases[] = {
            { bad_order, 2, CF_STATUS_BAD_KNOTS },
            { nan, 2, CF_STATUS_NOT_FINITE },
            { outside, 2, CF_STATUS_DOMAIN },
            { at_end, 2, CF_STATUS_BAD_KNOTS },
            { jump, 2, CF_STATUS_BAD_KNOTS },
            { four, 4, CF_STATUS_BAD_KNOTS },
            { end_b, 2, CF_STATUS_BAD_KNOTS },
            { ok3, 5, CF_STATUS_OK },
        };
        for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
            cf_diag_clear(&d);
            assert_int_equal(cf_bspline_refine(c, cases[i].x, cases[i].n, &q,
                                               &d), cases[i].st);
            if (cases[i].st != CF_STATUS_OK) {
                assert_null(q);
                assert_true(d.msg[0] != '\0');
            } else {
                assert_true(gap(c, q, 400) <= 64 * EPS * 10.0);
                cf_bspline_destroy(q);
                q = NULL;
            }
        }
    }
    cf_bspline_destroy(c);
}

/* Every distinct knot of [a, b] raised to multiplicity >= 3 by
** refinement: the points of span k are then P'_{k-3} .. P'_k, the Bézier
** points of that piece; the pieces of the blossom agree with them to 16
** ulps of the stored points' size (each side is a few interpolations of
** control points; the worst seen is 1.6). */
static void
test_cubic_pieces(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 4117);
    for (int trial = 0; trial < 150; trial++) {
        size_t dim = 2 + (size_t)(trial % 4 == 1), count = 4 + (size_t)trial % 30;
        bool rat = trial % 4 == 3, clamp = trial % 3 != 1;
        cf_bspline_t *c = cubic(&r, dim, count, 1 + trial % 4, clamp, rat);
        cf_bspline_t *q = NULL;
        const double *U = cf_bspline_knots(c), *Q, *V;
        size_t nk = cf_bspline_nknots(c), hd = dim + rat, nx = 0, s = 0;
        size_t nseg = 0;
        double a, b, *X = malloc(3 * nk * sizeof *X), size = 0.0;
        double *H = NULL, *B = NULL;
        cf_bezier_list_t *list = NULL;
        cf_bspline_domain(c, &a, &b);
        for (size_t i = 0; i < nk; i++) {
            int m = cf_knots_multiplicity(U, nk, U[i]);
            if (U[i] < a || U[i] > b || (i > 0 && U[i] == U[i - 1]))
                continue;
            for (int j = m; j < 3; j++)
                X[nx++] = U[i];
        }
        assert_int_equal(cf_bspline_refine(c, X, nx, &q, NULL), 0);
        Q = cf_bspline_hpoints(q);
        V = cf_bspline_knots(q);
        for (size_t i = 0; i < cf_bspline_count(q) * hd; i++)
            size = fmax(size, fabs(Q[i]));
        assert_int_equal(cf_bspline_to_beziers(c, &list, NULL), 0);
        assert_int_equal(cf_bspline_bezier_points(c, &H, &B, &nseg, NULL), 0);
        assert_int_equal(nseg, list->count);
        for (size_t k = 3; k + 4 < cf_bspline_nknots(q); k++) {
            const double *z;
            if (!(V[k] < V[k + 1]) || V[k] < a || V[k + 1] > b)
                continue;
            assert_true(s < nseg);
            assert_true(list->t0[s] == V[k] && list->t1[s] == V[k + 1]);
            assert_true(B[s] == V[k] && B[s + 1] == V[k + 1]);
            z = cf_bezier_hpoints(list->items[s]);
            assert_memory_equal(z, H + s * 4 * hd, 4 * hd * sizeof *z);
            for (size_t j = 0; j < 4 * hd; j++)
                if (fabs(z[j] - Q[(k - 3) * hd + j]) > 16 * EPS * size)
                    fail_msg("trial %d piece %zu: %.17g, refined %.17g",
                             trial, s, z[j], Q[(k - 3) * hd + j]);
            /* a piece ends where the next begins unless the curve jumps */
            if (s > 0 && cf_knots_multiplicity(V, cf_bspline_nknots(q), V[k])
                         < 4)
                assert_memory_equal(z, cf_bezier_hpoints(list->items[s - 1])
                                       + 3 * hd, hd * sizeof *z);
            s++;
        }
        assert_int_equal(s, nseg);
        cf_free(H);
        cf_free(B);
        cf_bezier_list_destroy(list);
        cf_bspline_destroy(q);
        cf_bspline_destroy(c);
        free(X);
    }
}

/* The curves of one list live in one block: each is destroyed on its own,
** in any order, some before the list and some after; a copy is its own
** curve (the sanitizer builds find a leak or a double free). */
static void
test_pieces_owned_one_by_one(void **state)
{
    tu_rng r;
    cf_bspline_t *c;
    cf_bezier_list_t *list = NULL;
    cf_bezier_t **taken, *copy = NULL;
    size_t n;
    double p0[2], p1[2];
    (void)state;
    tu_rng_seed(&r, 77);
    c = cubic(&r, 2, 40, 2, true, false);
    assert_int_equal(cf_bspline_to_beziers(c, &list, NULL), 0);
    n = list->count;
    taken = calloc(n, sizeof *taken);
    /* take every third curve out of the list */
    for (size_t i = 0; i < n; i += 3) {
        taken[i] = list->items[i];
        list->items[i] = NULL;
    }
    assert_int_equal(cf_bezier_copy(taken[0], &copy, NULL), 0);
    assert_int_equal(cf_bezier_eval(taken[0], 0.3, p0), 0);
    /* the list goes first, with the curves it still holds */
    cf_bezier_list_destroy(list);
    /* the taken ones from the back, then the copy */
    for (size_t i = n; i-- > 0;)
        if (taken[i] != NULL && i != 0)
            cf_bezier_destroy(taken[i]);
    assert_int_equal(cf_bezier_eval(taken[0], 0.3, p1), 0);
    assert_memory_equal(p0, p1, sizeof p0);
    cf_bezier_destroy(taken[0]);
    assert_int_equal(cf_bezier_eval(copy, 0.3, p1), 0);
    assert_memory_equal(p0, p1, sizeof p0);
    cf_bezier_destroy(copy);
    free(taken);
    /* all destroyed one by one, the list emptied first */
    assert_int_equal(cf_bspline_to_beziers(c, &list, NULL), 0);
    taken = list->items;
    n = list->count;
    list->items = cf_calloc(1, sizeof *list->items);
    list->count = 0;
    cf_bezier_list_destroy(list);
    for (size_t i = 1; i < n; i += 2)
        cf_bezier_destroy(taken[i]);
    for (size_t i = 0; i < n; i += 2)
        cf_bezier_destroy(taken[i]);
    cf_free(taken);
    cf_bspline_destroy(c);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_refine_planar_kernel),
        cmocka_unit_test(test_refine_refused),
        cmocka_unit_test(test_cubic_pieces),
        cmocka_unit_test(test_pieces_owned_one_by_one),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
