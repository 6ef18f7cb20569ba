/* Interpolation and the chapter-4 curves (src/interp.c, src/interp-spline.c). */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "curvefig/interp.h"
#include "testutil.h"

#define MAXP 64

/* ---- helpers ------------------------------------------------------------ */

static double
norm(const double *v, size_t dim)
{
    double s = 0.0;
    for (size_t k = 0; k < dim; k++)
        s += v[k] * v[k];
    return sqrt(s);
}

static double
dist(const double *a, const double *b, size_t dim)
{
    double s = 0.0;
    for (size_t k = 0; k < dim; k++)
        s += (a[k] - b[k]) * (a[k] - b[k]);
    return sqrt(s);
}

static double
size_of(const double *pts, size_t n)
{
    double m = 0.0;
    for (size_t i = 0; i < n; i++)
        m = fmax(m, fabs(pts[i]));
    return m;
}

static void
random_points(tu_rng *r, size_t n, size_t dim, double *pts)
{
    for (size_t i = 0; i < n * dim; i++)
        pts[i] = tu_rng_range(r, -10, 10);
}

static cf_bspline_t *
interp(size_t dim, const double *pts, size_t n, cf_interp_method_t m,
       cf_param_t param, int degree, const double *d0, const double *d1,
       bool closed)
{
    cf_interp_options_t o;
    cf_bspline_t *c = NULL;
    cf_diag_t d;
    cf_interp_options_init(&o);
    o.method = m;
    o.param = param;
    o.degree = degree;
    o.start_tangent = d0;
    o.end_tangent = d1;
    o.closed = closed;
    cf_diag_clear(&d);
    if (cf_interpolate(dim, pts, n, &o, &c, &d) != CF_STATUS_OK)
        fail_msg("cf_interpolate (%s): %s", cf_interp_method_to_string(m),
                 d.msg);
    return c;
}

/* The largest distance |C(u_i) - P_i| relative to the size of the data. */
static double
interp_error(const cf_bspline_t *c, const double *pts, size_t n, size_t dim,
             const double *u)
{
    double e = 0.0, q[8];
    for (size_t i = 0; i < n; i++) {
        assert_int_equal(cf_bspline_eval(c, u[i], q), CF_STATUS_OK);
        e = fmax(e, dist(q, pts + i * dim, dim));
    }
    return e / fmax(size_of(pts, n * dim), 1.0);
}

/*
** Continuity measured at every break point: the k-th derivative of the
** piece on the left at its end against the piece on the right at its start
** (Bézier pieces from cf_bspline_to_beziers, derivatives scaled by the
** piece's parameter length).  *jump: largest difference; *scale: largest
** |C^(k)| seen.  Returns the number of break points.
*/
static size_t
derivative_jumps(const cf_bspline_t *c, int k, double *jump, double *scale)
{
    cf_bezier_list_t *l = NULL;
    size_t dim = cf_bspline_dim(c);
    double a[4 * 8], b[4 * 8];
    *jump = 0.0;
    *scale = 0.0;
    assert_int_equal(cf_bspline_to_beziers(c, &l, NULL), CF_STATUS_OK);
    for (size_t i = 0; i < l->count; i++) {
        double h = l->t1[i] - l->t0[i], f = pow(h, -k);
        assert_int_equal(cf_bezier_eval_derivs(l->items[i], 0.0, k, a),
                         CF_STATUS_OK);
        assert_int_equal(cf_bezier_eval_derivs(l->items[i], 1.0, k, b),
                         CF_STATUS_OK);
        *scale = fmax(*scale, fmax(norm(a + k * dim, dim),
                                   norm(b + k * dim, dim)) * f);
    }
    for (size_t i = 0; i + 1 < l->count; i++) {
        double hl = l->t1[i] - l->t0[i], hr = l->t1[i + 1] - l->t0[i + 1];
        double diff[8];
        assert_int_equal(cf_bezier_eval_derivs(l->items[i], 1.0, k, a),
                         CF_STATUS_OK);
        assert_int_equal(cf_bezier_eval_derivs(l->items[i + 1], 0.0, k, b),
                         CF_STATUS_OK);
        for (size_t j = 0; j < dim; j++)
            diff[j] = a[k * dim + j] * pow(hl, -k) -
                      b[k * dim + j] * pow(hr, -k);
        *jump = fmax(*jump, norm(diff, dim));
    }
    {
        size_t n = l->count - 1;
        cf_bezier_list_destroy(l);
        return n;
    }
}

/* Derivatives 0..k at u into out[(k + 1) * dim]. */
static void
derivs(const cf_bspline_t *c, double u, int k, double *out)
{
    assert_int_equal(cf_bspline_eval_derivs(c, u, k, out), CF_STATUS_OK);
}

static void
expect_error(cf_status_t got, cf_status_t want, const cf_diag_t *d,
             const char *msg)
{
    assert_int_equal(got, want);
    assert_string_equal(d->msg, msg);
}

/* ---- parameters --------------------------------------------------------- */

static void
test_parameters_by_hand(void **state)
{
    /* chords |(3,4)| = 5 and |(0,9)| = 9, closing chord sqrt(3^2 + 13^2)
    ** = sqrt(178) */
    const double P[] = { 0, 0, 3, 4, 3, 13 };
    double u[4];
    (void)state;
    assert_int_equal(cf_interp_parameters(2, P, 3, CF_PARAM_CHORD, 0, false,
                                          u, NULL), CF_STATUS_OK);
    assert_true(u[0] == 0.0 && u[2] == 1.0);
    tu_assert_close(u[1], 5.0 / 14.0, 4 * DBL_EPSILON, 0.0);
    assert_int_equal(cf_interp_parameters(2, P, 3, CF_PARAM_UNIFORM, 0,
                                          false, u, NULL), CF_STATUS_OK);
    assert_true(u[1] == 0.5);
    assert_int_equal(cf_interp_parameters(2, P, 3, CF_PARAM_CENTRIPETAL, 0,
                                          false, u, NULL), CF_STATUS_OK);
    tu_assert_close(u[1], sqrt(5.0) / (sqrt(5.0) + 3.0), 4 * DBL_EPSILON,
                    0.0);
    /* power 0.5 is centripetal */
    {
        double v[3];
        assert_int_equal(cf_interp_parameters(2, P, 3, CF_PARAM_POWER, 0.5,
                                              false, v, NULL), CF_STATUS_OK);
        tu_assert_close(v[1], u[1], 4 * DBL_EPSILON, 0.0);
    }
    assert_int_equal(cf_interp_parameters(2, P, 3, CF_PARAM_CHORD, 0, true,
                                          u, NULL), CF_STATUS_OK);
    tu_assert_close(u[1], 5.0 / (14.0 + sqrt(178.0)), 4 * DBL_EPSILON, 0.0);
    tu_assert_close(u[2], 14.0 / (14.0 + sqrt(178.0)), 4 * DBL_EPSILON, 0.0);
    assert_true(u[3] == 1.0);
    /* no overflow for huge coordinates: chords 3e300 and 4e300 */
    {
        const double H[] = { 0, 0, 3e300, 0, 3e300, 4e300 };
        assert_int_equal(cf_interp_parameters(2, H, 3, CF_PARAM_CHORD, 0,
                                              false, u, NULL), CF_STATUS_OK);
        tu_assert_close(u[1], 3.0 / 7.0, 4 * DBL_EPSILON, 0.0);
    }
}

static void
test_parameters_errors(void **state)
{
    const double P[] = { 0, 0, 1, 2, 1, 2 }, Q[] = { 0, 0, 1, NAN };
    const double R[] = { 1, 2, 3, 4, 1, 2 };
    double u[4];
    cf_diag_t d;
    (void)state;
    cf_diag_clear(&d);
    expect_error(cf_interp_parameters(2, P, 3, CF_PARAM_CHORD, 0, false, u,
                                      &d),
                 CF_STATUS_DEGENERATE, &d,
                 "points 1 and 2 coincide (1, 2); chord-length parameters "
                 "need distinct consecutive points");
    assert_int_equal(d.index, 2);
    cf_diag_clear(&d);
    expect_error(cf_interp_parameters(2, P, 3, CF_PARAM_CENTRIPETAL, 0,
                                      false, u, &d),
                 CF_STATUS_DEGENERATE, &d,
                 "points 1 and 2 coincide (1, 2); centripetal parameters "
                 "need distinct consecutive points");
    cf_diag_clear(&d);
    /* closed: the last point and the first are consecutive too */
    expect_error(cf_interp_parameters(2, R, 3, CF_PARAM_UNIFORM, 0, true, u,
                                      &d),
                 CF_STATUS_DEGENERATE, &d,
                 "points 2 and 0 coincide (1, 2); interpolation needs "
                 "distinct consecutive points");
    cf_diag_clear(&d);
    expect_error(cf_interp_parameters(2, Q, 2, CF_PARAM_CHORD, 0, false, u,
                                      &d),
                 CF_STATUS_NOT_FINITE, &d,
                 "point P_1 has coordinate 2 = NaN; coordinates must be "
                 "finite");
    cf_diag_clear(&d);
    expect_error(cf_interp_parameters(2, P, 1, CF_PARAM_CHORD, 0, false, u,
                                      &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "parameters need at least 2 points, got 1");
    cf_diag_clear(&d);
    expect_error(cf_interp_parameters(2, R, 3, CF_PARAM_POWER, 1.5, false,
                                      u, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "parameter exponent 1.5 is outside [0, 1]");
    cf_diag_clear(&d);
    expect_error(cf_interp_parameters(2, NULL, 3, CF_PARAM_CHORD, 0, false,
                                      u, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "points and out must not be NULL");
    cf_diag_clear(&d);
    expect_error(cf_interp_parameters(0, R, 3, CF_PARAM_CHORD, 0, false, u,
                                      &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "dimension must be at least 1, got 0");
    cf_diag_clear(&d);
    expect_error(cf_interp_parameters(2, R, 3, (cf_param_t)42, 0, false, u,
                                      &d),
                 CF_STATUS_INVALID_ARG, &d, "unknown parametrisation 42");
}

static void
test_names(void **state)
{
    cf_interp_method_t m;
    cf_param_t p;
    cf_diag_t d;
    static const char *const names[] = { "natural", "clamped", "not-a-knot",
                                         "periodic", "catmull-rom",
                                         "global" };
    (void)state;
    for (int i = 0; i < 6; i++) {
        assert_int_equal(cf_interp_method_from_string(names[i], &m, NULL),
                         CF_STATUS_OK);
        assert_int_equal((int)m, i);
        assert_string_equal(cf_interp_method_to_string(m), names[i]);
    }
    assert_string_equal(cf_interp_method_to_string((cf_interp_method_t)9),
                        "unknown");
    assert_int_equal(cf_param_from_string("centripetal", &p, NULL),
                     CF_STATUS_OK);
    assert_int_equal(p, CF_PARAM_CENTRIPETAL);
    assert_int_equal(cf_param_from_string("chord", &p, NULL), CF_STATUS_OK);
    assert_int_equal(p, CF_PARAM_CHORD);
    assert_int_equal(cf_param_from_string("uniform", &p, NULL),
                     CF_STATUS_OK);
    assert_int_equal(p, CF_PARAM_UNIFORM);
    cf_diag_clear(&d);
    expect_error(cf_interp_method_from_string("cubic", &m, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "unknown interpolation method \"cubic\"; expected natural, "
                 "clamped, not-a-knot, periodic, catmull-rom or global");
    cf_diag_clear(&d);
    expect_error(cf_param_from_string("arc", &p, &d), CF_STATUS_INVALID_ARG,
                 &d, "unknown parametrisation \"arc\"; expected uniform, "
                     "chord or centripetal");
    cf_diag_clear(&d);
    expect_error(cf_param_from_string(NULL, &p, &d), CF_STATUS_INVALID_ARG,
                 &d, "NULL argument");
    cf_diag_clear(&d);
    expect_error(cf_interp_method_from_string("x", NULL, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "NULL argument");
}

/* ---- the interpolants pass through their points ------------------------- */

static void
test_all_methods_interpolate(void **state)
{
    static const cf_interp_method_t methods[] = {
        CF_INTERP_NATURAL, CF_INTERP_CLAMPED, CF_INTERP_NOT_A_KNOT,
        CF_INTERP_PERIODIC, CF_INTERP_CATMULL_ROM, CF_INTERP_GLOBAL
    };
    static const cf_param_t params[] = { CF_PARAM_UNIFORM, CF_PARAM_CHORD,
                                         CF_PARAM_CENTRIPETAL };
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 801);
    for (int trial = 0; trial < 12; trial++) {
        size_t dim = 1 + (size_t)trial % 3;
        size_t n = 4 + (size_t)(tu_rng_u01(&r) * 20);
        double P[MAXP * 3], u[MAXP + 1], d0[3], d1[3];
        random_points(&r, n, dim, P);
        random_points(&r, 1, dim, d0);
        random_points(&r, 1, dim, d1);
        for (size_t mi = 0; mi < 6; mi++) {
            for (size_t pi = 0; pi < 3; pi++) {
                cf_interp_method_t m = methods[mi];
                bool closed = m == CF_INTERP_PERIODIC ||
                              (m == CF_INTERP_CATMULL_ROM && trial % 2);
                int degree = m == CF_INTERP_GLOBAL ? 1 + trial % 5 : 3;
                bool tangents = m == CF_INTERP_CLAMPED ||
                                (m == CF_INTERP_GLOBAL && degree > 1 &&
                                 trial % 3 == 0);
                cf_bspline_t *c = interp(dim, P, n, m, params[pi], degree,
                                         tangents ? d0 : NULL,
                                         tangents ? d1 : NULL, closed);
                double a, b;
                assert_int_equal(cf_interp_parameters(dim, P, n, params[pi],
                                                      0, closed, u, NULL),
                                 CF_STATUS_OK);
                cf_bspline_domain(c, &a, &b);
                assert_true(a == 0.0 && b == 1.0);
                /* 1e-13 relative: the systems are well conditioned
                ** (diagonally dominant or totally positive), a few
                ** hundred ulps of the data */
                assert_true(interp_error(c, P, n, dim, u) <= 1e-13);
                if (closed) {
                    double q[3];
                    assert_int_equal(cf_bspline_eval(c, 1.0, q),
                                     CF_STATUS_OK);
                    assert_true(dist(q, P, dim) <=
                                1e-13 * size_of(P, n * dim));
                }
                assert_int_equal(cf_bspline_degree(c), degree);
                cf_bspline_destroy(c);
            }
        }
    }
}

/* ---- continuity, measured ----------------------------------------------- */

static void
test_continuity_as_promised(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 802);
    for (int trial = 0; trial < 8; trial++) {
        size_t n = 7 + (size_t)(tu_rng_u01(&r) * 15), dim = 2;
        double P[MAXP * 2], d0[2] = { 3, -1 }, d1[2] = { 0, 5 };
        double jump, scale;
        struct {
            cf_interp_method_t m;
            int degree, smooth;
        } cases[] = {
            { CF_INTERP_NATURAL, 3, 2 },  { CF_INTERP_CLAMPED, 3, 2 },
            { CF_INTERP_NOT_A_KNOT, 3, 2 }, { CF_INTERP_PERIODIC, 3, 2 },
            { CF_INTERP_CATMULL_ROM, 3, 1 }, { CF_INTERP_GLOBAL, 4, 3 },
            { CF_INTERP_GLOBAL, 2, 1 },
        };
        random_points(&r, n, dim, P);
        for (size_t ci = 0; ci < sizeof cases / sizeof cases[0]; ci++) {
            bool cl = cases[ci].m == CF_INTERP_CLAMPED;
            cf_bspline_t *c = interp(dim, P, n, cases[ci].m, CF_PARAM_CHORD,
                                     cases[ci].degree, cl ? d0 : NULL,
                                     cl ? d1 : NULL, false);
            for (int k = 0; k <= cases[ci].smooth; k++) {
                size_t nb = derivative_jumps(c, k, &jump, &scale);
                if (nb < 1)
                    fail_msg("%s: %zu break points",
                             cf_interp_method_to_string(cases[ci].m), nb);
                /* Bézier pieces carry the rounding of the solve and of the
                ** decomposition, ~1e-15 of the data; a k-th derivative
                ** amplifies it by about (p / h)^k, which the scale (the
                ** largest |C^(k)|, itself ~ size / h^k) absorbs: 1e-10 */
                if (!(jump <= 1e-10 * scale))
                    fail_msg("%s: C^%d jump %g (scale %g)",
                             cf_interp_method_to_string(cases[ci].m), k,
                             jump, scale);
            }
            /* the next derivative does jump: the promise is sharp */
            derivative_jumps(c, cases[ci].smooth + 1, &jump, &scale);
            assert_true(jump > 1e-6 * scale);
            cf_bspline_destroy(c);
        }
    }
}

/* ---- end conditions ----------------------------------------------------- */

static void
test_natural_ends(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 803);
    for (int trial = 0; trial < 10; trial++) {
        size_t n = 2 + (size_t)(tu_rng_u01(&r) * 20), dim = 3;
        double P[MAXP * 3], D0[9], D1[9], s0 = 0, s1 = 0;
        cf_bspline_t *c;
        random_points(&r, n, dim, P);
        c = interp(dim, P, n, CF_INTERP_NATURAL, CF_PARAM_CHORD, 3, NULL,
                   NULL, false);
        derivs(c, 0.0, 2, D0);
        derivs(c, 1.0, 2, D1);
        {
            double jump, scale;
            derivative_jumps(c, 2, &jump, &scale);
            s0 = s1 = scale;
        }
        /* C'' = 0 at both ends, relative to the largest |C''| */
        assert_true(norm(D0 + 6, 3) <= 1e-12 * fmax(s0, 1.0));
        assert_true(norm(D1 + 6, 3) <= 1e-12 * fmax(s1, 1.0));
        cf_bspline_destroy(c);
    }
    /* two points: C'' = 0 at both ends makes the segment straight */
    {
        const double P[] = { 1, 2, 4, 6 };
        double q[2];
        cf_bspline_t *c = interp(2, P, 2, CF_INTERP_NATURAL, CF_PARAM_CHORD,
                                 3, NULL, NULL, false);
        assert_int_equal(cf_bspline_eval(c, 0.25, q), CF_STATUS_OK);
        tu_assert_close(q[0], 1.75, 8 * DBL_EPSILON, 1.0);
        tu_assert_close(q[1], 3.0, 8 * DBL_EPSILON, 1.0);
        cf_bspline_destroy(c);
    }
}

static void
test_clamped_tangents_honoured(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 804);
    for (int trial = 0; trial < 10; trial++) {
        size_t n = 2 + (size_t)(tu_rng_u01(&r) * 20), dim = 2;
        double P[MAXP * 2], d0[2], d1[2], D0[4], D1[4];
        cf_bspline_t *c;
        random_points(&r, n, dim, P);
        random_points(&r, 1, dim, d0);
        random_points(&r, 1, dim, d1);
        c = interp(dim, P, n, CF_INTERP_CLAMPED, CF_PARAM_CENTRIPETAL, 3,
                   d0, d1, false);
        derivs(c, 0.0, 1, D0);
        derivs(c, 1.0, 1, D1);
        /* the end rows of the system state exactly these derivatives */
        for (int k = 0; k < 2; k++) {
            tu_assert_close(D0[2 + k], d0[k], 1e-12, 10.0);
            tu_assert_close(D1[2 + k], d1[k], 1e-12, 10.0);
        }
        cf_bspline_destroy(c);
    }
}

static void
test_global_end_derivatives(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 805);
    for (int p = 2; p <= 6; p++) {
        size_t n = 8, dim = 2;
        double P[16], d0[2], d1[2], D[4];
        cf_bspline_t *c;
        random_points(&r, n, dim, P);
        random_points(&r, 1, dim, d0);
        random_points(&r, 1, dim, d1);
        /* start only, end only, both */
        for (int which = 1; which <= 3; which++) {
            const double *a = which & 1 ? d0 : NULL, *b = which & 2 ? d1
                                                                   : NULL;
            double u[8];
            c = interp(dim, P, n, CF_INTERP_GLOBAL, CF_PARAM_CHORD, p, a, b,
                       false);
            assert_int_equal(cf_bspline_count(c), n + (which == 3 ? 2 : 1));
            assert_int_equal(cf_interp_parameters(dim, P, n, CF_PARAM_CHORD,
                                                  0, false, u, NULL),
                             CF_STATUS_OK);
            assert_true(interp_error(c, P, n, dim, u) <= 1e-13);
            if (a != NULL) {
                derivs(c, 0.0, 1, D);
                tu_assert_close(D[2], a[0], 1e-12, 10.0);
                tu_assert_close(D[3], a[1], 1e-12, 10.0);
            }
            if (b != NULL) {
                derivs(c, 1.0, 1, D);
                tu_assert_close(D[2], b[0], 1e-12, 10.0);
                tu_assert_close(D[3], b[1], 1e-12, 10.0);
            }
            cf_bspline_destroy(c);
        }
    }
}

static void
test_periodic_closes_c2(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 806);
    for (int trial = 0; trial < 10; trial++) {
        size_t n = 3 + (size_t)(tu_rng_u01(&r) * 20), dim = 2;
        double P[MAXP * 2], A[6], B[6], jump, scale;
        cf_bspline_t *c;
        random_points(&r, n, dim, P);
        c = interp(dim, P, n, CF_INTERP_PERIODIC,
                   trial % 2 ? CF_PARAM_CHORD : CF_PARAM_UNIFORM, 3, NULL,
                   NULL, false);
        assert_int_equal(cf_bspline_knot_kind(c), CF_KNOTS_PERIODIC);
        derivative_jumps(c, 2, &jump, &scale);
        derivs(c, 0.0, 2, A); /* first piece */
        derivs(c, 1.0, 2, B); /* last piece */
        /* value, C' and C'' agree across the seam; the periodic knots and
        ** wrapped control points make this exact up to rounding */
        for (int k = 0; k < 2; k++) {
            tu_assert_close(A[k], B[k], 1e-13, 10.0);
            tu_assert_close(A[k], P[k], 1e-13, 10.0);
        }
        assert_true(dist(A + 2, B + 2, 2) <= 1e-12 * scale);
        assert_true(dist(A + 4, B + 4, 2) <= 1e-12 * scale);
        cf_bspline_destroy(c);
    }
}

/* ---- values computed independently -------------------------------------- */

static void
test_natural_by_hand(void **state)
{
    /*
    ** Natural spline through y = 0, 1, 0, 1 at u = 0, 1/3, 2/3, 1 (uniform
    ** parameters, dim 1).  Independent computation in the second-derivative
    ** form (de Boor, A Practical Guide to Splines, ch. IV; Burden & Faires
    ** §3.5): with h = 1/3, M_0 = M_3 = 0 and
    **   h/6 M_{i-1} + 2h/3 M_i + h/6 M_{i+1} = (y_{i+1} - 2 y_i + y_{i-1})/h
    ** i = 1: 2/9 M_1 + 1/18 M_2 = -6;  i = 2: 1/18 M_1 + 2/9 M_2 = 6.
    ** Times 18: 4 M_1 + M_2 = -108, M_1 + 4 M_2 = 108, so M_1 = -36,
    ** M_2 = 36.  On [u_i, u_{i+1}]:
    **   S = M_i (u_{i+1}-u)^3/(6h) + M_{i+1} (u-u_i)^3/(6h)
    **       + (y_i/h - M_i h/6)(u_{i+1}-u) + (y_{i+1}/h - M_{i+1} h/6)(u-u_i)
    ** S(1/6) = -36 (1/6)^3 / 2 + (3 + 2)/6 = -1/12 + 5/6 = 3/4;
    ** S(1/2) = -1/12 + 1/12 + 5/6 - 2/6 = 1/2;  S'(0) = 3 + 2 = 5;
    ** S''(1/3) = M_1 = -36.
    */
    const double y[] = { 0, 1, 0, 1 };
    double q[3];
    cf_bspline_t *c = interp(1, y, 4, CF_INTERP_NATURAL, CF_PARAM_UNIFORM, 3,
                             NULL, NULL, false);
    (void)state;
    assert_int_equal(cf_bspline_eval(c, 1.0 / 6.0, q), CF_STATUS_OK);
    tu_assert_close(q[0], 0.75, 1e-14, 1.0);
    assert_int_equal(cf_bspline_eval(c, 0.5, q), CF_STATUS_OK);
    tu_assert_close(q[0], 0.5, 1e-14, 1.0);
    derivs(c, 0.0, 1, q);
    tu_assert_close(q[1], 5.0, 1e-14, 1.0);
    derivs(c, 1.0 / 3.0, 2, q);
    tu_assert_close(q[2], -36.0, 1e-13, 1.0);
    cf_bspline_destroy(c);
}

static void
test_clamped_by_hand(void **state)
{
    /* Two points 0 and 1 with zero end tangents: the cubic with C(0) = 0,
    ** C(1) = 1, C'(0) = C'(1) = 0 is 3u^2 - 2u^3 (smoothstep), so
    ** C(1/4) = 3/16 - 2/64 = 5/32.  The Ferguson cubic with the same data
    ** is the same curve (compared at several parameters). */
    const double y[] = { 0, 1 }, z = 0.0;
    double q[1], f[1];
    cf_bezier_t *fc = NULL;
    cf_bspline_t *c = interp(1, y, 2, CF_INTERP_CLAMPED, CF_PARAM_CHORD, 3,
                             &z, &z, false);
    (void)state;
    assert_int_equal(cf_bspline_eval(c, 0.25, q), CF_STATUS_OK);
    tu_assert_close(q[0], 5.0 / 32.0, 1e-15, 1.0);
    assert_int_equal(cf_ferguson_cubic(1, y, y + 1, &z, &z, &fc, NULL),
                     CF_STATUS_OK);
    for (int i = 0; i <= 8; i++) {
        double t = i / 8.0;
        assert_int_equal(cf_bspline_eval(c, t, q), CF_STATUS_OK);
        assert_int_equal(cf_bezier_eval(fc, t, f), CF_STATUS_OK);
        tu_assert_close(q[0], f[0], 1e-15, 1.0);
        tu_assert_close(q[0], 3 * t * t - 2 * t * t * t, 1e-15, 1.0);
    }
    cf_bezier_destroy(fc);
    cf_bspline_destroy(c);
}

static void
test_polynomials_reproduced(void **state)
{
    /* The spline spaces contain the polynomials of their degree, and the
    ** interpolants are unique: data from f(u) = 2u^3 - u + 1 (at uniform
    ** parameters, dim 1) give f itself for not-a-knot (whose end pieces
    ** carry no end condition), and global interpolation of degree p
    ** reproduces u^p - u^2 / 2 + u everywhere (p >= 2). */
    double y[12], q[1];
    cf_bspline_t *c;
    (void)state;
    for (int i = 0; i < 7; i++) {
        double t = i / 6.0;
        y[i] = 2 * t * t * t - t + 1;
    }
    c = interp(1, y, 7, CF_INTERP_NOT_A_KNOT, CF_PARAM_UNIFORM, 3, NULL,
               NULL, false);
    for (int i = 0; i <= 50; i++) {
        double t = i / 50.0;
        assert_int_equal(cf_bspline_eval(c, t, q), CF_STATUS_OK);
        tu_assert_close(q[0], 2 * t * t * t - t + 1, 1e-13, 1.0);
    }
    cf_bspline_destroy(c);
    /* degree 0 means 3, also for global interpolation */
    c = interp(1, y, 7, CF_INTERP_GLOBAL, CF_PARAM_UNIFORM, 0, NULL, NULL,
               false);
    assert_int_equal(cf_bspline_degree(c), 3);
    cf_bspline_destroy(c);
    /* four points: a single cubic */
    c = interp(1, y, 4, CF_INTERP_NOT_A_KNOT, CF_PARAM_UNIFORM, 3, NULL,
               NULL, false);
    assert_int_equal(cf_bspline_count(c), 4);
    cf_bspline_destroy(c);
    for (int p = 1; p <= 7; p++) {
        for (int i = 0; i < 12; i++) {
            double t = i / 11.0;
            y[i] = pow(t, p) - 0.5 * t * t + t;
        }
        c = interp(1, y, 12, CF_INTERP_GLOBAL, CF_PARAM_UNIFORM, p, NULL,
                   NULL, false);
        for (int i = 0; i <= 40; i++) {
            double t = i / 40.0;
            assert_int_equal(cf_bspline_eval(c, t, q), CF_STATUS_OK);
            /* p = 1 is the polyline, exact only at the data */
            if (p >= 2)
                tu_assert_close(q[0], pow(t, p) - 0.5 * t * t + t, 1e-12,
                                1.0);
        }
        cf_bspline_destroy(c);
    }
}

static void
test_periodic_square_by_hand(void **state)
{
    /*
    ** The square (1,0), (0,1), (-1,0), (0,-1) with uniform parameters: the
    ** knots are uniform, the basis at a knot is 1/6, 2/3, 1/6, and by
    ** symmetry the unknowns are E_i = c P_i with P_{i-1} + P_{i+1} = 0, so
    ** 2/3 c P_i = P_i: c = 3/2.  The control points are Q_{i+1} = 3/2 P_i.
    ** At the middle of the first span the uniform cubic weights are
    ** 1/48, 23/48, 23/48, 1/48 on Q_0..Q_3 = 3/2 (P_3, P_0, P_1, P_2):
    ** x = 3/2 (0 + 23 + 0 - 1) / 48 = 11/16, y = 3/2 (-1 + 0 + 23 + 0)/48
    ** = 11/16.
    */
    const double P[] = { 1, 0, 0, 1, -1, 0, 0, -1, 1, 0 };
    double q[2], ctrl[14];
    cf_bspline_t *c;
    (void)state;
    /* the closing point repeated at the end is accepted and dropped */
    c = interp(2, P, 5, CF_INTERP_PERIODIC, CF_PARAM_UNIFORM, 3, NULL, NULL,
               false);
    assert_int_equal(cf_bspline_count(c), 7);
    cf_bspline_get_points(c, ctrl);
    for (size_t j = 0; j < 7; j++) {
        const double *p = P + ((j + 3) % 4) * 2;
        tu_assert_close(ctrl[2 * j], 1.5 * p[0], 1e-15, 1.0);
        tu_assert_close(ctrl[2 * j + 1], 1.5 * p[1], 1e-15, 1.0);
    }
    assert_int_equal(cf_bspline_eval(c, 0.125, q), CF_STATUS_OK);
    tu_assert_close(q[0], 11.0 / 16.0, 1e-15, 1.0);
    tu_assert_close(q[1], 11.0 / 16.0, 1e-15, 1.0);
    cf_bspline_destroy(c);
}

/* ---- Catmull-Rom -------------------------------------------------------- */

static void
test_catmull_rom_uniform_formula(void **state)
{
    /* Uniform Catmull-Rom: the middle of segment P1 P2 is
    ** (-P0 + 9 P1 + 9 P2 - P3) / 16 (the classic matrix form with tangents
    ** (P_{i+1} - P_{i-1}) / 2). */
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 807);
    for (int trial = 0; trial < 10; trial++) {
        double P[8], q[2];
        cf_bspline_t *c;
        random_points(&r, 4, 2, P);
        c = interp(2, P, 4, CF_INTERP_CATMULL_ROM, CF_PARAM_UNIFORM, 3, NULL,
                   NULL, false);
        assert_int_equal(cf_bspline_eval(c, 0.5, q), CF_STATUS_OK);
        for (int k = 0; k < 2; k++)
            tu_assert_close(q[k],
                            (-P[k] + 9 * P[2 + k] + 9 * P[4 + k] - P[6 + k]) /
                                16.0,
                            1e-14, 10.0);
        cf_bspline_destroy(c);
    }
}

static bool
segments_cross(const double *a, const double *b, const double *c,
               const double *d)
{
#define CROSS(o, p, q) \
    (((p)[0] - (o)[0]) * ((q)[1] - (o)[1]) - ((p)[1] - (o)[1]) * ((q)[0] - (o)[0]))
    return CROSS(a, b, c) * CROSS(a, b, d) < 0 &&
           CROSS(c, d, a) * CROSS(c, d, b) < 0;
#undef CROSS
}

/* Does the Bézier curve, sampled at 401 points, cross itself? */
static bool
self_intersects(const cf_bezier_t *b)
{
    double pts[402 * 2];
    for (int i = 0; i <= 400; i++)
        assert_int_equal(cf_bezier_eval(b, i / 400.0, pts + 2 * i),
                         CF_STATUS_OK);
    for (int i = 0; i < 400; i++)
        for (int j = i + 2; j < 400; j++)
            if (segments_cross(pts + 2 * i, pts + 2 * i + 2, pts + 2 * j,
                               pts + 2 * j + 2))
                return true;
    return false;
}

static void
test_catmull_rom_centripetal_no_cusp(void **state)
{
    /*
    ** The long-short-long example of Yuksel, Schaefer & Keyser ("On the
    ** parameterization of Catmull-Rom curves", 2009): with uniform
    ** parameters the short middle segment (0,0)-(1,0) gets the tangents
    ** (9, 3) and (9, -3) and forms a loop (Bézier points (0,0), (1.5,0.5),
    ** (-0.5,0.5), (1,0)); centripetal parameters give neither a loop nor a
    ** cusp (|C'| stays well away from 0).
    */
    const double P[] = { -8, -3, 0, 0, 1, 0, 9, -3 };
    cf_bezier_list_t *l = NULL;
    cf_bspline_t *c;
    (void)state;
    c = interp(2, P, 4, CF_INTERP_CATMULL_ROM, CF_PARAM_UNIFORM, 3, NULL,
               NULL, false);
    assert_int_equal(cf_bspline_to_beziers(c, &l, NULL), CF_STATUS_OK);
    assert_int_equal(l->count, 3);
    assert_true(self_intersects(l->items[1]));
    cf_bezier_list_destroy(l);
    cf_bspline_destroy(c);
    /* CF_PARAM_DEFAULT is centripetal for Catmull-Rom */
    c = interp(2, P, 4, CF_INTERP_CATMULL_ROM, CF_PARAM_DEFAULT, 3, NULL,
               NULL, false);
    assert_int_equal(cf_bspline_to_beziers(c, &l, NULL), CF_STATUS_OK);
    assert_false(self_intersects(l->items[1]));
    for (int i = 0; i <= 200; i++) {
        double d[4];
        assert_int_equal(cf_bezier_eval_derivs(l->items[1], i / 200.0, 1, d),
                         CF_STATUS_OK);
        /* the chord is 1; its speed never drops below a fifth of it */
        assert_true(norm(d + 2, 2) > 0.2);
    }
    cf_bezier_list_destroy(l);
    cf_bspline_destroy(c);
}

static void
test_catmull_rom_closed(void **state)
{
    const double P[] = { 0, 0, 4, 0, 5, 3, 1, 4 };
    double A[4], B[4], jump, scale, u[5];
    cf_bspline_t *c = interp(2, P, 4, CF_INTERP_CATMULL_ROM, CF_PARAM_CHORD,
                             3, NULL, NULL, true);
    (void)state;
    assert_int_equal(cf_interp_parameters(2, P, 4, CF_PARAM_CHORD, 0, true,
                                          u, NULL), CF_STATUS_OK);
    assert_true(interp_error(c, P, 4, 2, u) <= 1e-14);
    derivs(c, 0.0, 1, A);
    derivs(c, 1.0, 1, B);
    /* C^1 across the seam: the tangent at P_0 is used at both ends */
    derivative_jumps(c, 1, &jump, &scale);
    assert_true(dist(A, B, 2) <= 1e-14 * 5);
    assert_true(dist(A + 2, B + 2, 2) <= 1e-13 * scale);
    assert_true(jump <= 1e-12 * scale);
    cf_bspline_destroy(c);
}

/* ---- least squares ------------------------------------------------------ */

/* sqrt(sum |C(u_k) - P_k|^2) of a curve with the given control points. */
static double
residual_of(const cf_bspline_t *c, const double *ctrl, const double *P,
            const double *u, size_t n, size_t dim)
{
    cf_bspline_t *d = NULL;
    double s = 0.0, q[3];
    assert_int_equal(cf_bspline_create(dim, cf_bspline_degree(c),
                                       cf_bspline_knots(c),
                                       cf_bspline_nknots(c), ctrl,
                                       cf_bspline_count(c), NULL, &d, NULL),
                     CF_STATUS_OK);
    for (size_t k = 0; k < n; k++) {
        assert_int_equal(cf_bspline_eval(d, u[k], q), CF_STATUS_OK);
        s += pow(dist(q, P + k * dim, dim), 2);
    }
    cf_bspline_destroy(d);
    return sqrt(s);
}

static void
test_lsq_beats_perturbations(void **state)
{
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 808);
    for (int trial = 0; trial < 12; trial++) {
        size_t n = 20 + (size_t)(tu_rng_u01(&r) * 30), dim = 2;
        int p = 1 + trial % 4;
        size_t nc = (size_t)p + 1 + (size_t)(tu_rng_u01(&r) * 8);
        bool fix = trial % 2 == 0;
        double P[MAXP * 2], u[MAXP], ctrl[64], pert[64], res, res2;
        cf_interp_options_t o;
        cf_bspline_t *c = NULL;
        /* noisy samples of a spiral */
        for (size_t k = 0; k < n; k++) {
            double t = 6.0 * (double)k / (double)n;
            P[2 * k] = t * cos(t) + tu_rng_range(&r, -0.3, 0.3);
            P[2 * k + 1] = t * sin(t) + tu_rng_range(&r, -0.3, 0.3);
        }
        cf_interp_options_init(&o);
        o.degree = p;
        o.param = CF_PARAM_CENTRIPETAL;
        assert_int_equal(cf_approximate_lsq(dim, P, n, nc, &o, fix, &c, &res,
                                            NULL),
                         CF_STATUS_OK);
        assert_int_equal(cf_bspline_count(c), nc);
        assert_int_equal(cf_interp_parameters(dim, P, n,
                                              CF_PARAM_CENTRIPETAL, 0, false,
                                              u, NULL), CF_STATUS_OK);
        cf_bspline_get_points(c, ctrl);
        /* the reported residual is the one of the curve */
        tu_assert_close(res, residual_of(c, ctrl, P, u, n, dim), 1e-12,
                        0.0);
        if (fix) {
            assert_true(dist(ctrl, P, 2) == 0.0);
            assert_true(dist(ctrl + 2 * (nc - 1), P + 2 * (n - 1), 2) == 0.0);
        }
        /* any perturbation of the free control points is no better:
        ** the residual is a convex quadratic at its minimum, so it can
        ** only grow (up to rounding, 1e-12 relative) */
        for (int rep = 0; rep < 30; rep++) {
            double eps = rep < 10 ? 1e-6 : rep < 20 ? 1e-3 : 0.1;
            memcpy(pert, ctrl, nc * dim * sizeof *ctrl);
            for (size_t j = fix ? 1 : 0; j < (fix ? nc - 1 : nc); j++)
                for (size_t k = 0; k < dim; k++)
                    pert[j * dim + k] += tu_rng_range(&r, -eps, eps);
            res2 = residual_of(c, pert, P, u, n, dim);
            assert_true(res2 >= res * (1 - 1e-12));
        }
        cf_bspline_destroy(c);
    }
}

static void
test_lsq_exact_cases(void **state)
{
    /* ncontrol == count interpolates (residual ~ 0); data on a cubic
    ** polynomial is fitted exactly by any cubic B-spline (ncontrol >= 4) */
    double P[20 * 2], res;
    cf_bspline_t *c = NULL;
    cf_interp_options_t o;
    (void)state;
    for (int k = 0; k < 20; k++) {
        double t = k / 19.0;
        P[2 * k] = t;
        P[2 * k + 1] = t * t * t - 2 * t;
    }
    cf_interp_options_init(&o);
    o.param = CF_PARAM_UNIFORM;
    assert_int_equal(cf_approximate_lsq(2, P, 20, 20, &o, true, &c, &res,
                                        NULL), CF_STATUS_OK);
    assert_true(res <= 1e-13);
    cf_bspline_destroy(c);
    assert_int_equal(cf_approximate_lsq(2, P, 20, 6, &o, false, &c, &res,
                                        NULL), CF_STATUS_OK);
    assert_true(res <= 1e-13);
    cf_bspline_destroy(c);
    /* degree 1 with 2 control points and fixed ends: the chord */
    o.degree = 1;
    assert_int_equal(cf_approximate_lsq(2, P, 20, 2, &o, true, &c, NULL,
                                        NULL), CF_STATUS_OK);
    assert_int_equal(cf_bspline_count(c), 2);
    cf_bspline_destroy(c);
}

static void
test_lsq_errors(void **state)
{
    double P[] = { 0, 0, 1, 1, 2, 0, 3, 1, 4, 0 };
    cf_bspline_t *c = NULL;
    cf_interp_options_t o;
    cf_diag_t d;
    (void)state;
    cf_interp_options_init(&o);
    cf_diag_clear(&d);
    expect_error(cf_approximate_lsq(2, P, 5, 3, &o, true, &c, NULL, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "a B-spline of degree 3 needs at least 4 control points, "
                 "got 3");
    cf_diag_clear(&d);
    expect_error(cf_approximate_lsq(2, P, 5, 6, &o, true, &c, NULL, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "least squares with 6 control points needs at least 6 "
                 "points, got 5");
    cf_diag_clear(&d);
    o.degree = 40;
    expect_error(cf_approximate_lsq(2, P, 5, 4, &o, true, &c, NULL, &d),
                 CF_STATUS_BAD_DEGREE, &d,
                 "least-squares degree 40 is outside 1..32");
    o.degree = 3;
    o.closed = true;
    cf_diag_clear(&d);
    expect_error(cf_approximate_lsq(2, P, 5, 4, &o, true, &c, NULL, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "least squares takes no end tangents and cannot be closed");
    o.closed = false;
    cf_diag_clear(&d);
    expect_error(cf_approximate_lsq(2, P, 5, 4, &o, true, NULL, NULL, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "out must not be NULL");
    P[5] = NAN;
    cf_diag_clear(&d);
    expect_error(cf_approximate_lsq(2, P, 5, 4, NULL, true, &c, NULL, &d),
                 CF_STATUS_NOT_FINITE, &d,
                 "point P_2 has coordinate 2 = NaN; coordinates must be "
                 "finite");
    assert_null(c);
}

/* ---- Ferguson and Coons ------------------------------------------------- */

static void
test_ferguson(void **state)
{
    /* Hermite form C(t) = F0 P0 + F1 P1 + F2 T0 + F3 T1 (thesis §4.2.1)
    ** evaluated directly, against the Bézier curve returned. */
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 809);
    for (int trial = 0; trial < 10; trial++) {
        double P[6], q[9];
        cf_bezier_t *c = NULL;
        random_points(&r, 2, 3, P);
        {
            double T[6];
            random_points(&r, 2, 3, T);
            assert_int_equal(cf_ferguson_cubic(3, P, P + 3, T, T + 3, &c,
                                               NULL), CF_STATUS_OK);
            for (int i = 0; i <= 10; i++) {
                double t = i / 10.0, t2 = t * t, t3 = t2 * t;
                double F0 = 2 * t3 - 3 * t2 + 1, F1 = -2 * t3 + 3 * t2;
                double F2 = t3 - 2 * t2 + t, F3 = t3 - t2;
                assert_int_equal(cf_bezier_eval(c, t, q), CF_STATUS_OK);
                for (int k = 0; k < 3; k++)
                    tu_assert_close(q[k],
                                    F0 * P[k] + F1 * P[3 + k] + F2 * T[k] +
                                        F3 * T[3 + k],
                                    1e-14, 10.0);
            }
            assert_int_equal(cf_bezier_eval_derivs(c, 0.0, 1, q),
                             CF_STATUS_OK);
            for (int k = 0; k < 3; k++)
                tu_assert_close(q[3 + k], T[k], 1e-14, 10.0);
            assert_int_equal(cf_bezier_eval_derivs(c, 1.0, 1, q),
                             CF_STATUS_OK);
            for (int k = 0; k < 3; k++)
                tu_assert_close(q[3 + k], T[3 + k], 1e-14, 10.0);
        }
        cf_bezier_destroy(c);
    }
}

static void
test_ferguson_chain_c1(void **state)
{
    tu_rng r;
    double P[10 * 2], T[10 * 2], a[4], b[4];
    cf_bezier_list_t *l = NULL;
    (void)state;
    tu_rng_seed(&r, 810);
    random_points(&r, 10, 2, P);
    random_points(&r, 10, 2, T);
    assert_int_equal(cf_ferguson_chain(2, P, T, 10, &l, NULL), CF_STATUS_OK);
    assert_int_equal(l->count, 9);
    for (size_t i = 0; i + 1 < l->count; i++) {
        assert_true(l->t0[i] == (double)i && l->t1[i] == (double)i + 1);
        assert_int_equal(cf_bezier_eval_derivs(l->items[i], 1.0, 1, a),
                         CF_STATUS_OK);
        assert_int_equal(cf_bezier_eval_derivs(l->items[i + 1], 0.0, 1, b),
                         CF_STATUS_OK);
        /* the joint is P_{i+1} with tangent T_{i+1} on both sides */
        for (int k = 0; k < 4; k++)
            tu_assert_close(a[k], b[k], 1e-14, 10.0);
        tu_assert_close(a[0], P[2 * (i + 1)], 1e-15, 10.0);
        tu_assert_close(a[3], T[2 * (i + 1) + 1], 1e-14, 10.0);
    }
    cf_bezier_list_destroy(l);
}

static void
test_coons(void **state)
{
    /* The Bézier form against the closed form of bspline.h
    ** (cf_coons_eval, the thesis's 1/6 [(1-t)^3, ...] basis). */
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 811);
    for (int trial = 0; trial < 10; trial++) {
        double P[8], q[2], e[2];
        cf_bezier_t *c = NULL;
        random_points(&r, 4, 2, P);
        assert_int_equal(cf_coons_cubic(2, P, &c, NULL), CF_STATUS_OK);
        for (int i = 0; i <= 10; i++) {
            double t = i / 10.0;
            assert_int_equal(cf_bezier_eval(c, t, q), CF_STATUS_OK);
            cf_coons_eval(2, P, t, e);
            tu_assert_close(q[0], e[0], 1e-14, 10.0);
            tu_assert_close(q[1], e[1], 1e-14, 10.0);
        }
        /* C(0) = (P0 + 4 P1 + P2) / 6: not P0 in general */
        assert_int_equal(cf_bezier_eval(c, 0.0, q), CF_STATUS_OK);
        tu_assert_close(q[0], (P[0] + 4 * P[2] + P[4]) / 6, 1e-15, 10.0);
        cf_bezier_destroy(c);
    }
}

static void
test_coons_chains_match_bspline(void **state)
{
    /* Each end treatment against the uniform cubic B-spline of bspline.h
    ** (de Boor on integer knots): item i covers [i, i + 1]. */
    static const size_t counts[] = { 4, 2, 3 };
    tu_rng r;
    (void)state;
    tu_rng_seed(&r, 812);
    for (int ends = 0; ends < 3; ends++) {
        for (size_t n = counts[ends]; n < 9; n++) {
            double P[9 * 2], q[2], e[2];
            cf_bezier_list_t *l = NULL;
            cf_bspline_t *s = NULL;
            random_points(&r, n, 2, P);
            assert_int_equal(cf_coons_chain(2, P, n, (cf_coons_ends_t)ends,
                                            &l, NULL), CF_STATUS_OK);
            assert_int_equal(cf_bspline_create_coons(2, P, n,
                                                     (cf_coons_ends_t)ends,
                                                     &s, NULL),
                             CF_STATUS_OK);
            assert_int_equal(l->count, ends == 0   ? n - 3
                                       : ends == 1 ? n + 1
                                                   : n);
            for (size_t i = 0; i < l->count; i++) {
                for (int j = 0; j <= 4; j++) {
                    double t = j / 4.0;
                    assert_int_equal(cf_bezier_eval(l->items[i], t, q),
                                     CF_STATUS_OK);
                    assert_int_equal(cf_bspline_eval(s, (double)i + t, e),
                                     CF_STATUS_OK);
                    tu_assert_close(q[0], e[0], 1e-14, 10.0);
                    tu_assert_close(q[1], e[1], 1e-14, 10.0);
                }
            }
            if (ends == CF_COONS_TRIPLED) {
                /* tripled end points: the curve starts at P_0, ends at P_n */
                assert_int_equal(cf_bezier_eval(l->items[0], 0.0, q),
                                 CF_STATUS_OK);
                assert_true(dist(q, P, 2) <= 1e-15 * 10);
                assert_int_equal(cf_bezier_eval(l->items[l->count - 1], 1.0,
                                                q), CF_STATUS_OK);
                assert_true(dist(q, P + 2 * (n - 1), 2) <= 1e-14 * 10);
            }
            if (ends == CF_COONS_CLOSED) {
                double a[6], b[6];
                assert_int_equal(cf_bezier_eval_derivs(l->items[0], 0.0, 2,
                                                       a), CF_STATUS_OK);
                assert_int_equal(cf_bezier_eval_derivs(l->items[l->count - 1],
                                                       1.0, 2, b),
                                 CF_STATUS_OK);
                for (int k = 0; k < 6; k++)
                    tu_assert_close(a[k], b[k], 1e-13, 10.0);
            }
            cf_bezier_list_destroy(l);
            cf_bspline_destroy(s);
        }
    }
}

static void
test_chapter4_errors(void **state)
{
    const double P[] = { 0, 0, 1, 1, 2, 0, NAN, 1 };
    cf_bezier_t *c = NULL;
    cf_bezier_list_t *l = NULL;
    cf_diag_t d;
    (void)state;
    cf_diag_clear(&d);
    expect_error(cf_ferguson_cubic(2, P, P + 2, NULL, P, &c, &d),
                 CF_STATUS_INVALID_ARG, &d, "tangent T0 must not be NULL");
    cf_diag_clear(&d);
    expect_error(cf_ferguson_cubic(2, P, P + 6, P, P, &c, &d),
                 CF_STATUS_NOT_FINITE, &d,
                 "P1 has coordinate 1 = NaN; coordinates must be finite");
    cf_diag_clear(&d);
    expect_error(cf_ferguson_cubic(0, P, P, P, P, &c, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "dimension must be at least 1, got 0");
    cf_diag_clear(&d);
    expect_error(cf_ferguson_cubic(2, P, P, P, P, NULL, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "out must not be NULL");
    cf_diag_clear(&d);
    expect_error(cf_ferguson_chain(2, P, P, 1, &l, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "Ferguson chain needs at least 2 points, got 1");
    cf_diag_clear(&d);
    expect_error(cf_ferguson_chain(2, P, P + 2, 3, &l, &d),
                 CF_STATUS_NOT_FINITE, &d,
                 "tangent 2 has coordinate 1 = NaN; coordinates must be "
                 "finite");
    cf_diag_clear(&d);
    expect_error(cf_ferguson_chain(2, NULL, P, 3, &l, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "needs dim >= 1, points and tangents");
    cf_diag_clear(&d);
    expect_error(cf_coons_cubic(2, P + 2, &c, &d), CF_STATUS_NOT_FINITE, &d,
                 "point P_2 has coordinate 1 = NaN; coordinates must be "
                 "finite");
    cf_diag_clear(&d);
    expect_error(cf_coons_cubic(2, NULL, &c, &d), CF_STATUS_INVALID_ARG, &d,
                 "needs dim >= 1 and four points");
    cf_diag_clear(&d);
    expect_error(cf_coons_chain(2, P, 3, CF_COONS_PLAIN, &l, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "plain Coons B-spline needs at least 4 points, got 3");
    cf_diag_clear(&d);
    expect_error(cf_coons_chain(2, P, 2, CF_COONS_CLOSED, &l, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "closed Coons B-spline needs at least 3 points, got 2");
    cf_diag_clear(&d);
    expect_error(cf_coons_chain(2, P, 1, CF_COONS_TRIPLED, &l, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "tripled-end Coons B-spline needs at least 2 points, got 1");
    cf_diag_clear(&d);
    expect_error(cf_coons_chain(2, P, 4, (cf_coons_ends_t)7, &l, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "unknown end treatment 7");
    cf_diag_clear(&d);
    expect_error(cf_coons_chain(2, P, 4, CF_COONS_PLAIN, NULL, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "out must not be NULL");
    assert_null(c);
    assert_null(l);
}

/* ---- bad input to cf_interpolate ---------------------------------------- */

static cf_status_t
try_interp(size_t dim, const double *P, size_t n, cf_interp_method_t m,
           int degree, const double *d0, const double *d1, bool closed,
           cf_diag_t *d)
{
    cf_interp_options_t o;
    cf_bspline_t *c = (cf_bspline_t *)&o; /* must be reset to NULL */
    cf_status_t st;
    cf_interp_options_init(&o);
    o.method = m;
    o.degree = degree;
    o.start_tangent = d0;
    o.end_tangent = d1;
    o.closed = closed;
    cf_diag_clear(d);
    st = cf_interpolate(dim, P, n, &o, &c, d);
    assert_null(c);
    return st;
}

static void
test_interpolate_errors(void **state)
{
    const double P[] = { 0, 0, 1, 2, 3, 1, 4, 4, 6, 0 };
    const double Q[] = { 0, 0, 1, 2, 1, 2, 4, 4 };
    const double N[] = { 0, 0, 1, 2, 3, NAN };
    const double t[] = { 1, 0 }, tn[] = { INFINITY, 0 };
    cf_diag_t d;
    (void)state;
    expect_error(try_interp(2, P, 1, CF_INTERP_NATURAL, 3, NULL, NULL, false,
                            &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "natural cubic spline needs at least 2 points, got 1");
    expect_error(try_interp(2, P, 3, CF_INTERP_NOT_A_KNOT, 3, NULL, NULL,
                            false, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "not-a-knot cubic spline needs at least 4 points, got 3");
    expect_error(try_interp(2, P, 2, CF_INTERP_PERIODIC, 3, NULL, NULL,
                            false, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "periodic cubic spline needs at least 3 distinct points, "
                 "got 2");
    expect_error(try_interp(2, P, 2, CF_INTERP_CATMULL_ROM, 3, NULL, NULL,
                            true, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "closed Catmull-Rom spline needs at least 3 distinct "
                 "points, got 2");
    expect_error(try_interp(2, P, 0, CF_INTERP_CATMULL_ROM, 3, NULL, NULL,
                            false, &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "Catmull-Rom spline needs at least 2 points, got 0");
    expect_error(try_interp(2, P, 4, CF_INTERP_GLOBAL, 4, NULL, NULL, false,
                            &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "global interpolation of degree 4 needs at least 5 points, "
                 "got 4");
    expect_error(try_interp(2, P, 3, CF_INTERP_GLOBAL, 4, t, NULL, false,
                            &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "global interpolation of degree 4 needs at least 5 points "
                 "and end derivatives together, got 3 + 1");
    expect_error(try_interp(2, P, 1, CF_INTERP_GLOBAL, 1, NULL, NULL, false,
                            &d),
                 CF_STATUS_TOO_FEW_POINTS, &d,
                 "global interpolation needs at least 2 points, got 1");
    expect_error(try_interp(2, Q, 4, CF_INTERP_NATURAL, 3, NULL, NULL, false,
                            &d),
                 CF_STATUS_DEGENERATE, &d,
                 "points 1 and 2 coincide (1, 2); chord-length parameters "
                 "need distinct consecutive points");
    expect_error(try_interp(2, N, 3, CF_INTERP_CLAMPED, 3, t, t, false, &d),
                 CF_STATUS_NOT_FINITE, &d,
                 "point P_2 has coordinate 2 = NaN; coordinates must be "
                 "finite");
    expect_error(try_interp(2, P, 5, CF_INTERP_NATURAL, 5, NULL, NULL, false,
                            &d),
                 CF_STATUS_BAD_DEGREE, &d,
                 "natural cubic spline has degree 3, got degree 5; use "
                 "method global for other degrees");
    expect_error(try_interp(2, P, 5, CF_INTERP_GLOBAL, -1, NULL, NULL, false,
                            &d),
                 CF_STATUS_BAD_DEGREE, &d,
                 "global interpolation degree -1 is outside 1..32");
    expect_error(try_interp(2, P, 5, CF_INTERP_GLOBAL, 33, NULL, NULL, false,
                            &d),
                 CF_STATUS_BAD_DEGREE, &d,
                 "global interpolation degree 33 is outside 1..32");
    expect_error(try_interp(2, P, 5, CF_INTERP_GLOBAL, 1, t, NULL, false,
                            &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "global interpolation of degree 1 (a polyline) takes no end "
                 "tangents");
    expect_error(try_interp(2, P, 5, CF_INTERP_GLOBAL, 3, NULL, NULL, true,
                            &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "global interpolation cannot be closed; use method periodic "
                 "for a closed cubic spline");
    expect_error(try_interp(2, P, 5, CF_INTERP_CLAMPED, 3, t, NULL, false,
                            &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "clamped cubic spline needs start_tangent and end_tangent");
    expect_error(try_interp(2, P, 5, CF_INTERP_CLAMPED, 3, t, tn, false,
                            &d),
                 CF_STATUS_NOT_FINITE, &d,
                 "end_tangent has coordinate 1 = inf; coordinates must be "
                 "finite");
    expect_error(try_interp(2, P, 5, CF_INTERP_NATURAL, 3, t, NULL, false,
                            &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "natural cubic spline takes no end tangents; use method "
                 "clamped or global");
    expect_error(try_interp(2, P, 5, CF_INTERP_NOT_A_KNOT, 3, NULL, NULL,
                            true, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "not-a-knot cubic spline cannot be closed; use method "
                 "periodic for a closed cubic spline");
    expect_error(try_interp(2, P, 5, (cf_interp_method_t)17, 3, NULL, NULL,
                            false, &d),
                 CF_STATUS_INVALID_ARG, &d, "unknown interpolation method 17");
    expect_error(try_interp(0, P, 5, CF_INTERP_NATURAL, 3, NULL, NULL, false,
                            &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "dimension must be at least 1, got 0");
    expect_error(try_interp(2, NULL, 5, CF_INTERP_NATURAL, 3, NULL, NULL,
                            false, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "points must not be NULL");
    cf_diag_clear(&d);
    expect_error(cf_interpolate(2, P, 5, NULL, NULL, &d),
                 CF_STATUS_INVALID_ARG, &d,
                 "out must not be NULL");
}

static void
test_explicit_params(void **state)
{
    /* Explicit parameters are used as given: the domain is theirs, and a
    ** decreasing one is rejected by name. */
    const double P[] = { 0, 0, 1, 2, 3, 1, 4, 4 };
    const double u[] = { 2, 3, 5, 6 }, bad[] = { 0, 1, 1, 2 };
    cf_interp_options_t o;
    cf_bspline_t *c = NULL;
    double a, b, q[2];
    cf_diag_t d;
    (void)state;
    cf_interp_options_init(&o);
    o.params = u;
    assert_int_equal(cf_interpolate(2, P, 4, &o, &c, NULL), CF_STATUS_OK);
    cf_bspline_domain(c, &a, &b);
    assert_true(a == 2.0 && b == 6.0);
    for (int i = 0; i < 4; i++) {
        assert_int_equal(cf_bspline_eval(c, u[i], q), CF_STATUS_OK);
        assert_true(dist(q, P + 2 * i, 2) <= 1e-14 * 4);
    }
    cf_bspline_destroy(c);
    o.params = bad;
    cf_diag_clear(&d);
    expect_error(cf_interpolate(2, P, 4, &o, &c, &d), CF_STATUS_BAD_KNOTS, &d,
                 "parameter 2 (1) is not larger than parameter 1 (1); "
                 "parameters must increase strictly");
    /* periodic: the square with its closing point and 5 parameters */
    {
        const double S[] = { 1, 0, 0, 1, -1, 0, 0, -1, 1, 0 };
        const double us[] = { 0, 1, 2, 3, 4 };
        cf_interp_options_t po;
        cf_interp_options_init(&po);
        po.method = CF_INTERP_PERIODIC;
        po.params = us;
        assert_int_equal(cf_interpolate(2, S, 5, &po, &c, NULL),
                         CF_STATUS_OK);
        cf_bspline_domain(c, &a, &b);
        assert_true(a == 0.0 && b == 4.0);
        for (int i = 0; i <= 4; i++) {
            assert_int_equal(cf_bspline_eval(c, us[i], q), CF_STATUS_OK);
            assert_true(dist(q, S + 2 * i, 2) <= 1e-15 * 4);
        }
        cf_bspline_destroy(c);
    }
    /* a power parametrisation (e = 0.25) */
    o.params = NULL;
    o.param = CF_PARAM_POWER;
    o.exponent = 0.25;
    assert_int_equal(cf_interpolate(2, P, 4, &o, &c, NULL), CF_STATUS_OK);
    cf_bspline_destroy(c);
}

static void
test_smallest_cases(void **state)
{
    /* The fewest points of each method give the expected small curves. */
    const double P[] = { 0, 0, 2, 1, 3, 3, 0, 2 };
    double q[2];
    cf_bspline_t *c;
    (void)state;
    /* two-point Catmull-Rom: both end tangents are the chord, a line */
    c = interp(2, P, 2, CF_INTERP_CATMULL_ROM, CF_PARAM_CHORD, 3, NULL, NULL,
               false);
    assert_int_equal(cf_bspline_eval(c, 0.25, q), CF_STATUS_OK);
    tu_assert_close(q[0], 0.5, 1e-15, 1.0);
    tu_assert_close(q[1], 0.25, 1e-15, 1.0);
    cf_bspline_destroy(c);
    /* global with count = p + 1: one Bézier piece, count control points */
    c = interp(2, P, 4, CF_INTERP_GLOBAL, CF_PARAM_CHORD, 3, NULL, NULL,
               false);
    assert_int_equal(cf_bspline_count(c), 4);
    assert_int_equal(cf_bspline_nknots(c), 8);
    cf_bspline_destroy(c);
    /* periodic through a triangle: closed, 3 + 3 control points */
    c = interp(2, P, 3, CF_INTERP_PERIODIC, CF_PARAM_CENTRIPETAL, 3, NULL,
               NULL, false);
    assert_int_equal(cf_bspline_count(c), 6);
    cf_bspline_destroy(c);
}

static void
test_numerically_singular(void **state)
{
    /* Four well separated points crowded into parameters 3e-12 apart:
    ** the collocation matrix has a pivot below DBL_EPSILON after row
    ** equilibration, and the message says what to do. */
    const double P[] = { 0, 0, 1, 0, 2, 1, 3, 0, 4, 2, 5, 1, 6, 0, 7, 1 };
    const double u[] = { 0, 1e-12, 2e-12, 3e-12, 1, 2, 3, 4 };
    cf_interp_options_t o;
    cf_bspline_t *c = NULL;
    cf_diag_t d;
    (void)state;
    cf_interp_options_init(&o);
    o.method = CF_INTERP_GLOBAL;
    o.params = u;
    cf_diag_clear(&d);
    expect_error(cf_interpolate(2, P, 8, &o, &c, &d), CF_STATUS_DEGENERATE,
                 &d,
                 "the interpolation system of degree 3 is numerically "
                 "singular at row 6; the parameters are too unevenly spaced "
                 "for it (try a lower degree or centripetal parameters)");
    assert_null(c);
}

/* ---- out of memory ------------------------------------------------------ */

static void
test_out_of_memory(void **state)
{
    const double P[] = { 0, 0, 1, 2, 3, 1, 4, 4, 6, 0, 7, 3 };
    const double t[] = { 1, 0 };
    (void)state;
    for (int what = 0; what < 10; what++) {
        for (long k = 1;; k++) {
            cf_interp_options_t o;
            cf_bspline_t *c = NULL;
            cf_bezier_list_t *l = NULL;
            cf_status_t st;
            cf_interp_options_init(&o);
            if (what < 6)
                o.method = (cf_interp_method_t)what;
            if (o.method == CF_INTERP_CLAMPED ||
                o.method == CF_INTERP_GLOBAL) {
                o.start_tangent = t;
                o.end_tangent = t;
            }
            tu_fail_alloc_after(k);
            if (what < 6)
                st = cf_interpolate(2, P, 6, &o, &c, NULL);
            else if (what == 6)
                st = cf_approximate_lsq(2, P, 6, 4, &o, true, &c, NULL,
                                        NULL);
            else if (what == 7)
                st = cf_approximate_lsq(2, P, 6, 5, &o, false, &c, &(double){0},
                                        NULL);
            else if (what == 8)
                st = cf_ferguson_chain(2, P, P, 6, &l, NULL);
            else
                st = cf_coons_chain(2, P, 6, CF_COONS_TRIPLED, &l, NULL);
            cf_bspline_destroy(c);
            cf_bezier_list_destroy(l);
            tu_fail_alloc_reset();
            assert_int_equal(tu_alloc_live(), 0);
            if (st == CF_STATUS_OK)
                break;
            assert_int_equal(st, CF_STATUS_NO_MEMORY);
            assert_true(k < 200);
        }
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_parameters_by_hand),
        cmocka_unit_test(test_parameters_errors),
        cmocka_unit_test(test_names),
        cmocka_unit_test(test_all_methods_interpolate),
        cmocka_unit_test(test_continuity_as_promised),
        cmocka_unit_test(test_natural_ends),
        cmocka_unit_test(test_clamped_tangents_honoured),
        cmocka_unit_test(test_global_end_derivatives),
        cmocka_unit_test(test_periodic_closes_c2),
        cmocka_unit_test(test_natural_by_hand),
        cmocka_unit_test(test_clamped_by_hand),
        cmocka_unit_test(test_polynomials_reproduced),
        cmocka_unit_test(test_periodic_square_by_hand),
        cmocka_unit_test(test_catmull_rom_uniform_formula),
        cmocka_unit_test(test_catmull_rom_centripetal_no_cusp),
        cmocka_unit_test(test_catmull_rom_closed),
        cmocka_unit_test(test_lsq_beats_perturbations),
        cmocka_unit_test(test_lsq_exact_cases),
        cmocka_unit_test(test_lsq_errors),
        cmocka_unit_test(test_ferguson),
        cmocka_unit_test(test_ferguson_chain_c1),
        cmocka_unit_test(test_coons),
        cmocka_unit_test(test_coons_chains_match_bspline),
        cmocka_unit_test(test_chapter4_errors),
        cmocka_unit_test(test_interpolate_errors),
        cmocka_unit_test(test_explicit_params),
        cmocka_unit_test(test_smallest_cases),
        cmocka_unit_test(test_numerically_singular),
        cmocka_unit_test(test_out_of_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
