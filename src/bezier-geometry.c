/*
** Bézier curves: the unit tangent, the principal normal and the curvature
** at a parameter, from the derivatives' Bernstein forms (a vanishing first
** derivative falls through to the first one that does not vanish).
** Construction and the rest of the queries are in bezier.c.
*/
#include <math.h>

#include "bezier-private.h"

#define MAXN CF_BEZIER_MAX_DEGREE
/* ---- tangent, normal, curvature ------------------------------------------ */

/* |c^(j)(t)|^2 and a scale below which it counts as zero. */
static double
deriv_norm2(const cf_bezier_t *c, double t, int j)
{
    double res[MAXN + 1], s = 0.0;
    for (size_t d = 0; d < c->dim; d++) {
        cf__bezier_coord_derivs(c, d, t, j, res);
        s += res[j] * res[j];
    }
    return s;
}

/* The order of the first derivative that does not vanish at t (relative to
** the curve's size), or 0 if none up to the degree does. */
static int
first_nonzero_deriv(const cf_bezier_t *c, double t)
{
    double size = cf__bezier_size(c), scale = 1.0;
    int n = c->degree, jmax = c->rational ? 2 * n : n;
    if (jmax > MAXN)
        jmax = MAXN;
    if (size == 0.0)
        return 0;
    for (int j = 1; j <= jmax; j++) {
        double tiny;
        scale *= (double)(n > 0 ? n : 1) * 2.0;
        tiny = 1e-13 * size * scale;
        if (deriv_norm2(c, t, j) > tiny * tiny)
            return j;
    }
    return 0;
}

cf_status_t
cf_bezier_tangent(const cf_bezier_t *c, double t, double *out)
{
    double res[MAXN + 1], norm;
    int j;
    cf_status_t st;
    if (c == NULL || out == NULL)
        return CF_STATUS_INVALID_ARG;
    st = cf__bezier_check_param(&t);
    if (st != CF_STATUS_OK)
        return st;
    j = first_nonzero_deriv(c, t);
    if (j == 0)
        return CF_STATUS_DEGENERATE;
    for (size_t d = 0; d < c->dim; d++) {
        cf__bezier_coord_derivs(c, d, t, j, res);
        out[d] = res[j];
    }
    norm = sqrt(deriv_norm2(c, t, j));
    for (size_t d = 0; d < c->dim; d++)
        out[d] /= norm;
    return CF_STATUS_OK;
}

/* First and second derivative sums: |c'|^2, |c''|^2, c'.c'' */
static void
d12_sums(const cf_bezier_t *c, double t, double *s11, double *s22,
         double *s12)
{
    double res[3];
    *s11 = *s22 = *s12 = 0.0;
    for (size_t d = 0; d < c->dim; d++) {
        cf__bezier_coord_derivs(c, d, t, 2, res);
        *s11 += res[1] * res[1];
        *s22 += res[2] * res[2];
        *s12 += res[1] * res[2];
    }
}

cf_status_t
cf_bezier_normal(const cf_bezier_t *c, double t, double *out)
{
    double s11, s22, s12, res[3], norm2 = 0.0, norm;
    cf_status_t st;
    if (c == NULL || out == NULL || c->dim == 1)
        return CF_STATUS_INVALID_ARG;
    if (c->dim == 2) {
        double tg[2];
        st = cf_bezier_tangent(c, t, tg);
        if (st != CF_STATUS_OK)
            return st;
        out[0] = -tg[1];
        out[1] = tg[0];
        return CF_STATUS_OK;
    }
    st = cf__bezier_check_param(&t);
    if (st != CF_STATUS_OK)
        return st;
    d12_sums(c, t, &s11, &s22, &s12);
    if (!(s11 > 0.0))
        return CF_STATUS_DEGENERATE;
    /* principal normal: c'' minus its component along c' */
    for (size_t d = 0; d < c->dim; d++) {
        cf__bezier_coord_derivs(c, d, t, 2, res);
        out[d] = res[2] - s12 / s11 * res[1];
        norm2 += out[d] * out[d];
    }
    norm = sqrt(norm2);
    if (!(norm > 1e-13 * sqrt(s22)) || norm == 0.0)
        return CF_STATUS_DEGENERATE;
    for (size_t d = 0; d < c->dim; d++)
        out[d] /= norm;
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_curvature(const cf_bezier_t *c, double t, double *kappa)
{
    double s11, s22, s12, res[3];
    cf_status_t st;
    if (c == NULL || kappa == NULL)
        return CF_STATUS_INVALID_ARG;
    st = cf__bezier_check_param(&t);
    if (st != CF_STATUS_OK)
        return st;
    if (c->dim == 1) {
        *kappa = 0.0;
        return CF_STATUS_OK;
    }
    if (c->dim == 2) {
        double x[3], y[3], sp;
        cf__bezier_coord_derivs(c, 0, t, 2, x);
        cf__bezier_coord_derivs(c, 1, t, 2, y);
        sp = x[1] * x[1] + y[1] * y[1];
        if (!(sp > 0.0))
            return CF_STATUS_DEGENERATE;
        *kappa = (x[1] * y[2] - y[1] * x[2]) / (sp * sqrt(sp));
        return CF_STATUS_OK;
    }
    d12_sums(c, t, &s11, &s22, &s12);
    if (!(s11 > 0.0))
        return CF_STATUS_DEGENERATE;
    {
        /* |c' x c''| = |c'| |c''_perp|, c''_perp = c'' - (c'.c''/|c'|^2) c' */
        double p2 = 0.0;
        for (size_t d = 0; d < c->dim; d++) {
            double q;
            cf__bezier_coord_derivs(c, d, t, 2, res);
            q = res[2] - s12 / s11 * res[1];
            p2 += q * q;
        }
        (void)s22;
        *kappa = sqrt(p2) / s11;
    }
    return CF_STATUS_OK;
}
