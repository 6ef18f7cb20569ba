/*
** Interpolation options, the names of methods and parameterisations, and
** the data parameters of a point sequence (uniform, chord, centripetal,
** exponent), checked or given explicitly.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "interp-private.h"
#include "numtext-private.h"

/* ---- options and names -------------------------------------------------- */

void
cf_interp_options_init(cf_interp_options_t *opt)
{
    if (opt == NULL)
        return;
    memset(opt, 0, sizeof *opt);
    opt->method = CF_INTERP_NATURAL;
    opt->degree = 3;
    opt->param = CF_PARAM_DEFAULT;
}

static const char *const method_names[] = {
    [CF_INTERP_NATURAL] = "natural",
    [CF_INTERP_CLAMPED] = "clamped",
    [CF_INTERP_NOT_A_KNOT] = "not-a-knot",
    [CF_INTERP_PERIODIC] = "periodic",
    [CF_INTERP_CATMULL_ROM] = "catmull-rom",
    [CF_INTERP_GLOBAL] = "global",
};
#define NMETHODS (sizeof method_names / sizeof method_names[0])

static const char *const param_names[] = {
    [CF_PARAM_DEFAULT] = "default",
    [CF_PARAM_UNIFORM] = "uniform",
    [CF_PARAM_CHORD] = "chord",
    [CF_PARAM_CENTRIPETAL] = "centripetal",
};
#define NPARAMS (sizeof param_names / sizeof param_names[0])

const char *
cf_interp_method_to_string(cf_interp_method_t method)
{
    if ((unsigned)method >= NMETHODS)
        return "unknown";
    return method_names[method];
}

cf_status_t
cf_interp_method_from_string(const char *name, cf_interp_method_t *out,
                             cf_diag_t *diag)
{
    cf_diag_clear(diag);
    if (name == NULL || out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "NULL argument");
    for (size_t i = 0; i < NMETHODS; i++) {
        if (strcmp(name, method_names[i]) == 0) {
            *out = (cf_interp_method_t)i;
            return CF_STATUS_OK;
        }
    }
    return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                     "unknown interpolation method \"%.40s\"; expected "
                     "natural, clamped, not-a-knot, periodic, catmull-rom "
                     "or global", name);
}

cf_status_t
cf_param_from_string(const char *name, cf_param_t *out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    if (name == NULL || out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "NULL argument");
    for (size_t i = 0; i < NPARAMS; i++) {
        if (strcmp(name, param_names[i]) == 0) {
            *out = (cf_param_t)i;
            return CF_STATUS_OK;
        }
    }
    return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                     "unknown parametrisation \"%.40s\"; expected uniform, "
                     "chord or centripetal", name);
}

/* ---- data parameters ---------------------------------------------------- */

/* "(1, 2)": at most four coordinates, then "...". */
static void
format_point(char *buf, size_t size, const double *p, size_t dim)
{
    size_t len = 0;
    len += (size_t)snprintf(buf, size, "(");
    for (size_t k = 0; k < dim && k < 4 && len < size; k++)
        len += (size_t)snprintf(buf + len, size - len, "%s%s",
                                k > 0 ? ", " : "", CF__NUM(p[k]));
    if (dim > 4 && len < size)
        len += (size_t)snprintf(buf + len, size - len, ", ...");
    if (len < size)
        snprintf(buf + len, size - len, ")");
}

static const char *
param_phrase(cf_param_t param)
{
    switch (param) {
    case CF_PARAM_CHORD:
        return "chord-length parameters need";
    case CF_PARAM_CENTRIPETAL:
        return "centripetal parameters need";
    case CF_PARAM_POWER:
        return "power parameters need";
    default:
        return "interpolation needs";
    }
}

cf_status_t
cf_interp_parameters(size_t dim, const double *points, size_t count,
                     cf_param_t param, double exponent, bool closed,
                     double *out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    size_t nseg;
    double e, total = 0.0;
    if (points == NULL || out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "points and out must not be NULL");
    if (dim < 1)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "dimension must be at least 1, got 0");
    if (count < 2)
        return cf__error(diag, CF_STATUS_TOO_FEW_POINTS, (long)count,
                         "parameters need at least 2 points, got %zu",
                         count);
    switch (param) {
    case CF_PARAM_DEFAULT:
    case CF_PARAM_CHORD:
        e = 1.0;
        break;
    case CF_PARAM_UNIFORM:
        e = 0.0;
        break;
    case CF_PARAM_CENTRIPETAL:
        e = 0.5;
        break;
    case CF_PARAM_POWER:
        if (!(exponent >= 0.0 && exponent <= 1.0))
            return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                             "parameter exponent %s is outside [0, 1]",
                             CF__NUM(exponent));
        e = exponent;
        break;
    default:
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "unknown parametrisation %d", (int)param);
    }
    {
        cf_status_t st = cf__check_finite_points(points, count, dim, dim,
                                                 "point", diag);
        if (st != CF_STATUS_OK)
            return st;
    }
    nseg = closed ? count : count - 1;
    out[0] = 0.0;
    for (size_t i = 0; i < nseg; i++) {
        size_t j = (i + 1) % count;
        const double *a = points + i * dim, *b = points + j * dim;
        double big = 0.0, s = 0.0, d, step;
        /* |b - a| scaled by its largest coordinate (no overflow) */
        for (size_t k = 0; k < dim; k++)
            big = fmax(big, fabs(b[k] - a[k]));
        if (big == 0.0) {
            char pa[96];
            format_point(pa, sizeof pa, a, dim);
            return cf__error(diag, CF_STATUS_DEGENERATE, (long)j,
                             "points %zu and %zu coincide %s; %s distinct "
                             "consecutive points", i, j, pa,
                             param_phrase(param));
        }
        for (size_t k = 0; k < dim; k++) {
            double q = (b[k] - a[k]) / big;
            s += q * q;
        }
        d = big * sqrt(s);
        step = e == 0.0 ? 1.0 : e == 1.0 ? d : e == 0.5 ? sqrt(d)
                                                    : pow(d, e);
        if (!isfinite(step))
            return cf__error(diag, CF_STATUS_NOT_FINITE, (long)j,
                             "distance between points %zu and %zu "
                             "overflows", i, j);
        total += step;
        out[i + 1] = total;
    }
    if (!isfinite(total) || !(total > 0.0))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "total parameter length %s is not finite",
                         CF__NUM(total));
    for (size_t i = 1; i < nseg; i++)
        out[i] /= total;
    out[nseg] = 1.0;
    return CF_STATUS_OK;
}

static cf_status_t
check_explicit_params(const double *u, size_t n, cf_diag_t *diag)
{
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(u[i]))
            return cf__error(diag, CF_STATUS_NOT_FINITE, (long)i,
                             "parameter %zu is %s; parameters must be "
                             "finite", i, CF__NUM(u[i]));
        if (i > 0 && !(u[i] > u[i - 1]))
            return cf__error(diag, CF_STATUS_BAD_KNOTS, (long)i,
                             "parameter %zu (%s) is not larger than "
                             "parameter %zu (%s); parameters must increase "
                             "strictly", i, CF__NUM(u[i]), i - 1,
                             CF__NUM(u[i - 1]));
    }
    return CF_STATUS_OK;
}

/* Parameters made from the points that came out equal: the step between
** points i - 1 and i was below the rounding of the running sum (or of the
** division by the total), so no curve passes through both at theirs. */
static cf_status_t
check_made_params(const double *u, size_t nu, size_t count,
                  cf_param_t param, cf_diag_t *diag)
{
    for (size_t i = 1; i < nu; i++)
        if (!(u[i] > u[i - 1]))
            return cf__error(diag, CF_STATUS_DEGENERATE, (long)(i % count),
                             "points %zu and %zu get the same %s parameter "
                             "%s (their distance is lost in rounding beside "
                             "the others'); use %s parameters", i - 1,
                             i % count,
                             param == CF_PARAM_CHORD ? "chord-length"
                             : param == CF_PARAM_CENTRIPETAL ? "centripetal"
                                                             : "power",
                             CF__NUM(u[i]), param == CF_PARAM_CHORD
                                 ? "centripetal or uniform" : "uniform");
    return CF_STATUS_OK;
}

cf_status_t
cf__interp_prepare_params(size_t dim, const double *points, size_t count,
                          const cf_interp_options_t *opt, bool closed,
                          bool strict, double *u, cf_diag_t *diag)
{
    size_t nu = closed ? count + 1 : count;
    cf_param_t param = opt->param;
    cf_status_t st;
    if (opt->params != NULL) {
        st = check_explicit_params(opt->params, nu, diag);
        if (st == CF_STATUS_OK)
            memcpy(u, opt->params, nu * sizeof *u);
        return st;
    }
    if (param == CF_PARAM_DEFAULT)
        param = opt->method == CF_INTERP_CATMULL_ROM ? CF_PARAM_CENTRIPETAL
                                                     : CF_PARAM_CHORD;
    st = cf_interp_parameters(dim, points, count, param, opt->exponent,
                              closed, u, diag);
    if (st == CF_STATUS_OK && strict)
        st = check_made_params(u, nu, count, param, diag);
    return st;
}

