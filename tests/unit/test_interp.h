/* The helpers the interp tests share (test_interp.c,
** test_interp_catmull_rom.c, test_interp_bad_input.c); static inline, as
** not every file uses each. */
#ifndef CURVEFIG_TESTS_TEST_INTERP_H
#define CURVEFIG_TESTS_TEST_INTERP_H

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

static inline double
norm(const double *v, size_t dim)
{
    double s = 0.0;
    for (size_t k = 0; k < dim; k++)
        s += v[k] * v[k];
    return sqrt(s);
}

static inline double
dist(const double *a, const double *b, size_t dim)
{
    double s = 0.0;
    for (size_t k = 0; k < dim; k++)
        s += (a[k] - b[k]) * (a[k] - b[k]);
    return sqrt(s);
}

static inline double
size_of(const double *pts, size_t n)
{
    double m = 0.0;
    for (size_t i = 0; i < n; i++)
        m = fmax(m, fabs(pts[i]));
    return m;
}

static inline void
random_points(tu_rng *r, size_t n, size_t dim, double *pts)
{
    for (size_t i = 0; i < n * dim; i++)
        pts[i] = tu_rng_range(r, -10, 10);
}

static inline cf_bspline_t *
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
static inline double
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
static inline size_t
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
static inline void
derivs(const cf_bspline_t *c, double u, int k, double *out)
{
    assert_int_equal(cf_bspline_eval_derivs(c, u, k, out), CF_STATUS_OK);
}

static inline void
expect_error(cf_status_t got, cf_status_t want, const cf_diag_t *d,
             const char *msg)
{
    assert_int_equal(got, want);
    assert_string_equal(d->msg, msg);
}

#endif
