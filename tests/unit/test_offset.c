/* Offset curves: exact offsets, cusps, the cubic approximation and its
** error, trimming, degenerate input and bad arguments. This file has the
** first sections; the others are in test_offset_degenerate.c and
** test_offset_errors.c, the shared helpers in test_offset.h. */
#include "test_offset.h"

static void
bezier_fn(const void *ctx, double u, double *p)
{
    assert_int_equal(cf_bezier_eval(ctx, u, p), CF_STATUS_OK);
}

/* ---- exact offsets ------------------------------------------------------ */

static void
test_point_matches_definition(void **state)
{
    /* c + d n with n = c' turned +90 degrees, against a hand-made normal */
    cf_bezier_t *c = cubic(arch);
    double o[2], v[4];
    (void)state;
    for (int k = 0; k <= 10; k++) {
        double t = k / 10.0, l;
        cf_bezier_eval_derivs(c, t, 1, v);
        l = hypot(v[2], v[3]);
        assert_int_equal(cf_offset_point(c, t, 7.5, o), CF_STATUS_OK);
        tu_assert_close(o[0], v[0] - 7.5 * v[3] / l, 1e-14, 100.0);
        tu_assert_close(o[1], v[1] + 7.5 * v[2] / l, 1e-14, 100.0);
    }
    /* arch starts upwards: left of travel is -x */
    cf_offset_point(c, 0.0, 3.0, o);
    tu_assert_close(o[0], -3.0, 1e-15, 1.0);
    tu_assert_close(o[1], 0.0, 1e-15, 1.0);
    {
        double ts[3] = { 0.0, 0.5, 1.0 }, many[6];
        assert_int_equal(cf_offset_point_many(c, ts, 3, 3.0, many),
                         CF_STATUS_OK);
        for (int k = 0; k < 3; k++) {
            cf_offset_point(c, ts[k], 3.0, o);
            assert_true(many[2 * k] == o[0] && many[2 * k + 1] == o[1]);
        }
    }
    cf_bezier_destroy(c);
}

static void
test_zero_derivative_uses_higher(void **state)
{
    /* P0 = P1: c'(0) = 0, c''(0) = 6 (P2 - 2 P1 + P0) = (60, 0): the
    ** tangent is +x and the left normal +y, so o(0) = (0, d). */
    const double p[8] = { 0, 0, 0, 0, 10, 0, 10, 10 };
    cf_bezier_t *c = cubic(p);
    double o[2];
    (void)state;
    assert_int_equal(cf_offset_point(c, 0.0, 2.0, o), CF_STATUS_OK);
    assert_true(fabs((o[0]) - (0.0)) <= 1e-14);
    tu_assert_close(o[1], 2.0, 1e-15, 1.0);
    /* perfect cusp: c'(1/2) = 0; the limit from the right is the direction
    ** of c''(1/2) = (-768, 0) (worked out by hand), normal (0, -1) */
    {
        const double q[8] = { 0, 0, 128, 128, 128, 0, 0, 128 };
        cf_bezier_t *k = cubic(q);
        double v[4];
        assert_int_equal(cf_offset_point(k, 0.5, 1.0, o), CF_STATUS_OK);
        cf_bezier_eval_derivs(k, 0.5, 1, v);
        assert_true(hypot(v[2], v[3]) < 1e-12);
        tu_assert_close(o[0], v[0], 1e-15, 100.0);
        tu_assert_close(o[1], v[1] - 1.0, 1e-15, 100.0);
        cf_bezier_destroy(k);
    }
    cf_bezier_destroy(c);
}

static void
test_rational_circle_exact(void **state)
{
    /* quarter circle of radius 10 as a rational quadratic (weights
    ** 1, cos 45deg, 1), counter-clockwise: left is the centre, so the offset
    ** at d has radius 10 - d, to rounding (1e-13 relative). */
    const double p[6] = { 10, 0, 10, 10, 0, 10 };
    const double w[3] = { 1, sqrt(0.5), 1 };
    cf_bezier_t *c = NULL;
    (void)state;
    assert_int_equal(cf_bezier_create(2, 2, p, w, &c, NULL), CF_STATUS_OK);
    for (int k = 0; k <= 50; k++) {
        double o[2];
        assert_int_equal(cf_offset_point(c, k / 50.0, 3.0, o), CF_STATUS_OK);
        tu_assert_close(hypot(o[0], o[1]), 7.0, 1e-13, 1.0);
        assert_int_equal(cf_offset_point(c, k / 50.0, -4.0, o), CF_STATUS_OK);
        tu_assert_close(hypot(o[0], o[1]), 14.0, 1e-13, 1.0);
    }
    {
        /* constant curvature radius 10: no cusps at d = 3 or 15 */
        size_t n = 99;
        assert_int_equal(cf_offset_cusps(c, 15.0, NULL, 0, &n, NULL),
                         CF_STATUS_OK);
        assert_int_equal(n, 0);
        assert_int_equal(cf_offset_cusps(c, 3.0, NULL, 0, &n, NULL),
                         CF_STATUS_OK);
        assert_int_equal(n, 0);
    }
    cf_bezier_destroy(c);
}

static void
test_nurbs_circle_offset(void **state)
{
    /* Full NURBS circle r = 10: exact offsets have radius 10 -+ d to 1e-12;
    ** the cubic chain lies within the tolerance of that circle. */
    const double centre[2] = { 1, 2 };
    cf_bspline_t *s = NULL;
    cf_bezier_list_t *list = NULL;
    (void)state;
    assert_int_equal(cf_nurbs_circle(centre, 10.0, &s, NULL), CF_STATUS_OK);
    assert_int_equal(cf_bspline_to_beziers(s, &list, NULL), CF_STATUS_OK);
    for (size_t i = 0; i < list->count; i++)
        for (int k = 0; k <= 20; k++) {
            double o[2];
            cf_offset_point(list->items[i], k / 20.0, 2.5, o);
            tu_assert_close(hypot(o[0] - 1, o[1] - 2), 7.5, 1e-12, 1.0);
            cf_offset_point(list->items[i], k / 20.0, -2.5, o);
            tu_assert_close(hypot(o[0] - 1, o[1] - 2), 12.5, 1e-12, 1.0);
        }
    for (int side = -1; side <= 1; side += 2) {
        cf_offset_options_t opt;
        cf_cubics_t *raw = NULL;
        cf_offset_report_t rep;
        double r = 10.0 - side * 2.5, emax = 0.0;
        cf_offset_options_init(&opt);
        opt.tolerance = 1e-6;
        assert_int_equal(cf_bspline_offset(s, side * 2.5, &opt, &raw, NULL,
                                           &rep, NULL),
                         CF_STATUS_OK);
        assert_chain_sane(raw, 1e-9);
        assert_int_equal(rep.joins, 0);   /* C1 at the knots: no joins */
        assert_true(rep.converged && rep.max_error <= 1e-6);
        for (size_t i = 0; i < raw->count; i++)
            for (int k = 0; k <= 200; k++) {
                double p[2];
                cubic_at(raw->pts + 8 * i, k / 200.0, p);
                emax = fmax(emax, fabs(hypot(p[0] - 1, p[1] - 2) - r));
            }
        assert_true(emax <= 1e-6);
        /* the chain is closed: last point = first point */
        assert_true(hypot(raw->pts[0] - raw->pts[8 * raw->count - 2],
                          raw->pts[1] - raw->pts[8 * raw->count - 1]) <
                    1e-9);
        cf_cubics_destroy(raw);
    }
    cf_bezier_list_destroy(list);
    cf_bspline_destroy(s);
}

/* ---- cusps ----------------------------------------------------------------- */

static void
test_parabola_cusps_closed_form(void **state)
{
    /*
    ** y = x^2 / (2a) for x in [-X, X] is the quadratic Bézier
    ** (-X, X^2/2a), (0, -X^2/2a), (X, X^2/2a) with x = -X + 2 X t (the
    ** middle point is the midpoint in x, so x is linear in t).  With
    ** y' = x / a, y'' = 1 / a the radius of curvature is
    ** rho = (1 + y'^2)^(3/2) / y'' = a (1 + x^2 / a^2)^(3/2), its centre on
    ** the left (the curve turns left).  A cusp of the offset at d > 0 is
    ** where rho = d: x = +-a sqrt((d / a)^(2/3) - 1), t = (x + X) / (2X);
    ** none for d < a and none on the right (d < 0).
    */
    const double a = 1.0, X = 3.0;
    const double p[6] = { -X, X * X / (2 * a), 0, -X * X / (2 * a), X,
                          X * X / (2 * a) };
    const double ds[4] = { 4.0, 1.5, 1.0 + 1e-7, 20.0 };
    cf_bezier_t *c = NULL;
    double ts[8];
    size_t n;
    (void)state;
    assert_int_equal(cf_bezier_create(2, 2, p, NULL, &c, NULL), CF_STATUS_OK);
    for (int k = 0; k < 4; k++) {
        double d = ds[k];
        double x = a * sqrt(pow(d / a, 2.0 / 3.0) - 1.0);
        double t0 = (-x + X) / (2 * X), t1 = (x + X) / (2 * X);
        assert_int_equal(cf_offset_cusps(c, d, ts, 8, &n, NULL),
                         CF_STATUS_OK);
        if (x >= X) {
            assert_int_equal(n, 0);   /* beyond the ends */
            continue;
        }
        /* 1e-7: the pair is only 8.6e-5 apart; a sign-change scan on a
        ** grid of 1000 would see neither */
        assert_int_equal(n, 2);
        assert_true(fabs((ts[0]) - (t0)) <= 1e-9);
        assert_true(fabs((ts[1]) - (t1)) <= 1e-9);
        assert_int_equal(cf_offset_cusps(c, -d, ts, 8, &n, NULL),
                         CF_STATUS_OK);
        assert_int_equal(n, 0);
    }
    /* d = a: rho has its minimum a at the vertex: one (double) cusp */
    assert_int_equal(cf_offset_cusps(c, 1.0, ts, 8, &n, NULL), CF_STATUS_OK);
    assert_int_equal(n, 1);
    assert_true(fabs((ts[0]) - (0.5)) <= 1e-6);
    /* d below the minimum radius: none */
    assert_int_equal(cf_offset_cusps(c, 0.99, ts, 8, &n, NULL),
                     CF_STATUS_OK);
    assert_int_equal(n, 0);
    /* cap smaller than the count: the count is still complete */
    assert_int_equal(cf_offset_cusps(c, 4.0, ts, 1, &n, NULL), CF_STATUS_OK);
    assert_int_equal(n, 2);
    cf_bezier_destroy(c);
}

static void
test_arch_cusps(void **state)
{
    /* The arch turns right: its inner offset is d = -45, with two cusps at
    ** the published parameters (+-1e-9); the outer one has none. */
    cf_bezier_t *c = cubic(arch);
    double ts[4];
    size_t n;
    (void)state;
    assert_int_equal(cf_offset_cusps(c, -45.0, ts, 4, &n, NULL),
                     CF_STATUS_OK);
    assert_int_equal(n, 2);
    assert_true(fabs((ts[0]) - (0.3455290359)) <= 1e-9);
    assert_true(fabs((ts[1]) - (0.6544709641)) <= 1e-9);
    /* at a cusp the radius of curvature is 45 */
    for (int k = 0; k < 2; k++) {
        double kappa;
        cf_bezier_curvature(c, ts[k], &kappa);
        tu_assert_close(-1.0 / kappa, 45.0, 1e-9, 1.0);
    }
    assert_int_equal(cf_offset_cusps(c, 45.0, ts, 4, &n, NULL),
                     CF_STATUS_OK);
    assert_int_equal(n, 0);
    cf_bezier_destroy(c);
}

static void
test_random_cusps_are_cusps(void **state)
{
    /* seeded random cubics and distances: every reported cusp has
    ** d * kappa = 1; and a dense scan of 1 - d kappa finds no sign change
    ** away from the reported ones */
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 7);
    for (int trial = 0; trial < 40; trial++) {
        double p[8], ts[32], d = tu_rng_range(&r, -60, 60);
        size_t n;
        cf_bezier_t *c;
        for (int i = 0; i < 8; i++)
            p[i] = tu_rng_range(&r, 0, 100);
        c = cubic(p);
        assert_int_equal(cf_offset_cusps(c, d, ts, 32, &n, NULL),
                         CF_STATUS_OK);
        for (size_t k = 0; k < n; k++) {
            double kappa;
            cf_bezier_curvature(c, ts[k], &kappa);
            tu_assert_close(d * kappa, 1.0, 1e-7, 1.0);
            if (k > 0)
                assert_true(ts[k] > ts[k - 1]);
        }
        {
            int changes = 0;
            double prev = 0.0;
            for (int j = 0; j <= 2000; j++) {
                double kappa, f;
                cf_bezier_curvature(c, j / 2000.0, &kappa);
                f = 1.0 - d * kappa;
                if (j > 0 && (f < 0) != (prev < 0))
                    changes++;
                prev = f;
            }
            /* each sign change of 1 - d kappa is a reported cusp (a
            ** reported pair may fall between two grid points) */
            assert_true((size_t)changes <= n);
        }
        cf_bezier_destroy(c);
    }
}

/* ---- approximation --------------------------------------------------------- */

static void
test_arch_counts_errors_and_trim(void **state)
{
    /* segment targets (tol 1e-2 / 1e-3 / 1e-4): inner 6/6/9, outer 2/3/5;
    ** the error measured independently stays below the tolerance */
    static const int inner[3] = { 6, 6, 9 }, outer[3] = { 2, 3, 5 };
    const double tols[3] = { 1e-2, 1e-3, 1e-4 };
    cf_bezier_t *c = cubic(arch);
    (void)state;
    for (int k = 0; k < 3; k++) {
        for (int side = 0; side < 2; side++) {
            cf_offset_options_t opt;
            cf_cubics_t *raw = NULL;
            cf_cubics_list_t *tr = NULL;
            cf_offset_report_t rep;
            double d = side == 0 ? -45.0 : 45.0, err;
            cf_offset_options_init(&opt);
            opt.tolerance = tols[k];
            opt.trim = true;
            assert_int_equal(cf_bezier_offset(c, d, &opt, &raw, &tr, &rep,
                                              NULL),
                             CF_STATUS_OK);
            assert_chain_sane(raw, 1e-9);
            assert_true((int)rep.segments <=
                        (side == 0 ? inner[k] : outer[k]));
            assert_int_equal(rep.segments, raw->count);
            assert_true(rep.converged && rep.max_error <= tols[k]);
            err = chain_error(c, d, raw, 60);
            assert_true(err <= tols[k]);
            /* the report agrees with the independent measure to 2% */
            tu_assert_close(err, rep.max_error, 0.02, tols[k] * 1e-3);
            if (side == 0) {
                const cf_cubics_t *a;
                const cf_cubics_t *b;
                assert_int_equal(rep.cusps, 2);
                assert_int_equal(tr->count, 2);
                a = tr->chains[0];
                b = tr->chains[1];
                /* the two pieces meet at (50, 26.6228) +- tol (they end at
                ** the crossing of the exact offset, found by Newton's
                ** method from the crossing of the raw pieces) */
                assert_true(fabs(a->pts[8 * a->count - 2] - 50.0) <= tols[k]);
                assert_true(fabs(a->pts[8 * a->count - 1] - 26.6228) <=
                            tols[k]);
                assert_true(fabs(b->pts[0] - 50.0) <= tols[k]);
                assert_true(fabs(b->pts[1] - 26.6228) <= tols[k]);
            } else {
                assert_int_equal(rep.cusps, 0);
                assert_int_equal(tr->count, 1);
            }
            cf_cubics_destroy(raw);
            cf_cubics_list_destroy(tr);
        }
    }
    cf_bezier_destroy(c);
}

/* proper crossing of segments ab, cd */
static bool
crosses(const double *a, const double *b, const double *c, const double *d)
{
    double d1 = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    double d2 = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
    double d3 = (d[0] - c[0]) * (a[1] - c[1]) - (d[1] - c[1]) * (a[0] - c[0]);
    double d4 = (d[0] - c[0]) * (b[1] - c[1]) - (d[1] - c[1]) * (b[0] - c[0]);
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) &&
           ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

/* Check a trimmed offset: at distance >= |d| - tol from the curve, and no
** two of its polylines cross (except near shared end points). */
static void
check_trimmed(const cf_bezier_t *c, double d, double tol,
              const cf_cubics_list_t *tr)
{
    enum { M = 40 };
    size_t total = 0, at = 0;
    double *poly;
    for (size_t k = 0; k < tr->count; k++)
        total += tr->chains[k]->count;
    poly = malloc(sizeof(double) * 2 * (M + 1) * (total ? total : 1));
    assert_non_null(poly);
    for (size_t k = 0; k < tr->count; k++) {
        const cf_cubics_t *ch = tr->chains[k];
        assert_chain_sane(ch, 1e-9);
        for (size_t i = 0; i < ch->count; i++, at++)
            for (int j = 0; j <= M; j++) {
                double *q = poly + 2 * ((M + 1) * at + j);
                cubic_at(ch->pts + 8 * i, (double)j / M, q);
                assert_true(dist_to(bezier_fn, c, 400, q) >=
                            fabs(d) - tol);
            }
    }
    for (size_t i = 0; i < total; i++)
        for (size_t j = i + 1; j < total; j++)
            for (int a = 0; a < M; a++)
                for (int b = 0; b < M; b++) {
                    const double *p = poly + 2 * ((M + 1) * i + a);
                    const double *q = poly + 2 * ((M + 1) * j + b);
                    const double *ends[4] = {
                        poly + 2 * (M + 1) * i, poly + 2 * ((M + 1) * i + M),
                        poly + 2 * (M + 1) * j, poly + 2 * ((M + 1) * j + M)
                    };
                    double x[2], r[2] = { p[2] - p[0], p[3] - p[1] };
                    double sv[2] = { q[2] - q[0], q[3] - q[1] }, u, emin;
                    if (!crosses(p, p + 2, q, q + 2))
                        continue;
                    u = ((q[0] - p[0]) * sv[1] - (q[1] - p[1]) * sv[0]) /
                        (r[0] * sv[1] - r[1] * sv[0]);
                    x[0] = p[0] + u * r[0];
                    x[1] = p[1] + u * r[1];
                    /* allowed only at an end point of a piece (where the
                    ** trimmed chains meet) */
                    emin = INFINITY;
                    for (int e = 0; e < 4; e++)
                        emin = fmin(emin, hypot(x[0] - ends[e][0],
                                                x[1] - ends[e][1]));
                    assert_true(emin <= 10 * tol);
                }
    free(poly);
}

static void
test_trimmed_properties(void **state)
{
    /* swallowtails of the arch, the seed's curve and an overstroke */
    const double seed[10] = { 0, 5, 1, -1, 3, 0, 4, 3, 6, 10 };
    const double over[8] = { 0, 0, 25, 75, 75, -50, 100, 0 };
    cf_bezier_t *c[3];
    /* the seed's curve turns left: inward is d > 0 (its figures use 0.5,
    ** 1.5, 3); at 3 and for the overstroke the loop is cut off by the
    ** curve's end, so only the distance test trims */
    const double ds[4] = { -45.0, 1.5, 3.0, 250.0 };
    const size_t isect[4] = { 1, 1, 0, 0 };   /* at least */
    (void)state;
    c[0] = cubic(arch);
    assert_int_equal(cf_bezier_create(2, 4, seed, NULL, &c[1], NULL),
                     CF_STATUS_OK);
    c[2] = cubic(over);
    for (int k = 0; k < 4; k++) {
        int ci = k < 1 ? 0 : (k < 3 ? 1 : 2);
        cf_offset_options_t opt;
        cf_cubics_list_t *tr = NULL;
        cf_cubics_t *raw = NULL;
        cf_offset_report_t rep;
        cf_offset_options_init(&opt);
        opt.tolerance = 1e-3;
        opt.trim = true;
        assert_int_equal(cf_bezier_offset(c[ci], ds[k], &opt, &raw, &tr,
                                          &rep, NULL),
                         CF_STATUS_OK);
        assert_true(rep.cusps >= 1);
        assert_true(rep.self_intersections >= isect[k]);
        /* something was cut away */
        assert_true(rep.trimmed_segments <= rep.segments);
        assert_true(tr->count >= 1);
        assert_true(chain_error(c[ci], ds[k], raw, 30) <= 1e-3);
        check_trimmed(c[ci], ds[k], 1e-3, tr);
        cf_cubics_destroy(raw);
        cf_cubics_list_destroy(tr);
    }
    for (int k = 0; k < 3; k++)
        cf_bezier_destroy(c[k]);
}

static void
test_random_certified_error(void **state)
{
    /* seeded random cubics and quartics: the reported error is below the
    ** tolerance and so is the independently measured one */
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 2026);
    for (int trial = 0; trial < 8; trial++) {
        int deg = 3 + trial % 2;
        double p[10], d = tu_rng_range(&r, -30, 30);
        double tol = trial % 3 == 0 ? 1e-2 : 1e-3;
        cf_bezier_t *c = NULL;
        cf_offset_options_t opt;
        cf_cubics_t *raw = NULL;
        cf_offset_report_t rep;
        for (int i = 0; i < 2 * (deg + 1); i++)
            p[i] = tu_rng_range(&r, 0, 100);
        assert_int_equal(cf_bezier_create(2, deg, p, NULL, &c, NULL),
                         CF_STATUS_OK);
        cf_offset_options_init(&opt);
        opt.tolerance = tol;
        assert_int_equal(cf_bezier_offset(c, d, &opt, &raw, NULL, &rep,
                                          NULL),
                         CF_STATUS_OK);
        assert_chain_sane(raw, 1e-9);
        assert_true(rep.converged && rep.max_error <= tol);
        assert_true(chain_error(c, d, raw, 40) <= tol);
        {
            double m;
            assert_int_equal(cf_offset_measure(c, d, raw, 100, &m, NULL),
                             CF_STATUS_OK);
            /* the polyline measure is an upper estimate of the same */
            assert_true(m >= 0.999 * rep.max_error);
        }
        cf_cubics_destroy(raw);
        cf_bezier_destroy(c);
    }
}

static void
test_tiller_hanson_baseline(void **state)
{
    /* Tiller-Hanson: within tolerance as well, but many more pieces */
    cf_bezier_t *c = cubic(arch);
    cf_offset_options_t opt;
    cf_cubics_t *raw = NULL;
    cf_offset_report_t rep;
    (void)state;
    cf_offset_options_init(&opt);
    opt.tolerance = 1e-2;
    opt.method = CF_OFFSET_TILLER_HANSON;
    assert_int_equal(cf_bezier_offset(c, -45.0, &opt, &raw, NULL, &rep, NULL),
                     CF_STATUS_OK);
    assert_chain_sane(raw, 1e-9);
    assert_true(rep.segments > 6);
    assert_true(rep.converged && chain_error(c, -45.0, raw, 10) <= 1e-2);
    cf_cubics_destroy(raw);
    /* a quadratic is raised to a cubic first */
    {
        const double q[6] = { 0, 0, 50, 80, 100, 0 };
        cf_bezier_t *k = NULL;
        assert_int_equal(cf_bezier_create(2, 2, q, NULL, &k, NULL),
                         CF_STATUS_OK);
        assert_int_equal(cf_bezier_offset(k, 5.0, &opt, &raw, NULL, &rep,
                                          NULL),
                         CF_STATUS_OK);
        assert_true(chain_error(k, 5.0, raw, 20) <= 1e-2);
        cf_cubics_destroy(raw);
        cf_bezier_destroy(k);
    }
    cf_bezier_destroy(c);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_point_matches_definition),
        cmocka_unit_test(test_zero_derivative_uses_higher),
        cmocka_unit_test(test_rational_circle_exact),
        cmocka_unit_test(test_nurbs_circle_offset),
        cmocka_unit_test(test_parabola_cusps_closed_form),
        cmocka_unit_test(test_arch_cusps),
        cmocka_unit_test(test_random_cusps_are_cusps),
        cmocka_unit_test(test_arch_counts_errors_and_trim),
        cmocka_unit_test(test_trimmed_properties),
        cmocka_unit_test(test_random_certified_error),
        cmocka_unit_test(test_tiller_hanson_baseline),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
