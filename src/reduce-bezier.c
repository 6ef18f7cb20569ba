/*
** Degree reduction of Bézier curves (include/curvefig/reduce.h): the
** checks of the options, the dispatch to the least-squares (reduce-l2.c)
** or uniform (reduce-uniform.c) solution, and the report of the errors
** (reduce-error.c).
*/
#include <math.h>
#include <string.h>

#include "bezier-private.h"
#include "core-private.h"
#include "numtext-private.h"
#include "reduce-private.h"

void
cf_reduce_options_init(cf_reduce_options_t *opt)
{
    if (opt == NULL)
        return;
    memset(opt, 0, sizeof *opt);
    opt->by = 1;
    opt->continuity = 0;
    opt->method = CF_REDUCE_L2;
    opt->tolerance = 1e-3;
}

cf_status_t
cf__reduce_solve(const cf__reduce_job_t *j, size_t dim, bool rational,
                 cf_reduce_method_t method, double *Q,
                 cf_reduce_report_t *rep, cf_diag_t *diag)
{
    cf_status_t st = method == CF_REDUCE_UNIFORM ? cf__reduce_uniform(j, Q)
                                                 : cf__reduce_l2(j, Q);
    size_t h = j->h;
    if (st != CF_STATUS_OK)
        return cf__error(diag, st, -1, "out of memory (degree reduction)");
    for (int i = 0; i <= j->m; i++) {
        double w = rational ? Q[(size_t)i * h + dim] : 1.0;
        if (!isfinite(w) || !(w > 0.0))
            return cf__error(diag, CF_STATUS_DEGENERATE, i,
                             "the reduced curve's weight %d is %s; the "
                             "rational curve cannot be reduced to degree %d",
                             i, CF__NUM(w), j->m);
        for (size_t c = 0; c < dim; c++)
            if (!isfinite(Q[(size_t)i * h + c]))
                return cf__error(diag, CF_STATUS_NOT_FINITE, i,
                                 "the reduced curve's point %d has "
                                 "coordinate %zu = %s: the curve's "
                                 "coordinates are too large to reduce it to "
                                 "degree %d", i, c + 1,
                                 CF__NUM(Q[(size_t)i * h + c]), j->m);
    }
    if (rep == NULL)
        return CF_STATUS_OK;
    rep->max_error = cf__reduce_measure(j->P, j->n, Q, j->m, dim, rational);
    st = cf__reduce_bound(j->P, j->n, Q, j->m, dim, rational, 0.0,
                          &rep->bound,
                          &rep->polygon_bound);
    if (st == CF_STATUS_OK)
        st = cf__reduce_l2_distance(j->P, j->n, Q, j->m, h, &rep->l2_error);
    if (st != CF_STATUS_OK)
        return cf__error(diag, st, -1, "out of memory (degree reduction)");
    return CF_STATUS_OK;
}

cf_status_t
cf__reduce_check_degree(const char *what, int degree, int by, int least,
                        cf_reduce_method_t method, cf_diag_t *diag)
{
    if (degree - 1 < least)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "a %s of degree %d cannot be reduced (the least "
                         "degree of a reduced curve is %d)", what, degree,
                         least);
    if (by < 1 || degree - by < least)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "cannot reduce a %s of degree %d by %d degrees "
                         "(by must be 1 .. %d)", what, degree, by,
                         degree - least);
    if (degree > CF__REDUCE_MAX_DEGREE)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "degree %d is above %d, the largest degree "
                         "reduced", degree, CF__REDUCE_MAX_DEGREE);
    if (method != CF_REDUCE_L2 && method != CF_REDUCE_UNIFORM)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "unknown reduction method %d", (int)method);
    return CF_STATUS_OK;
}

/* by, the method, and the continuity for the reduced degree m
** (k0 = k1 = k). */
static cf_status_t
check_options(const cf_reduce_options_t *o, int n, cf_diag_t *diag)
{
    int m = n - o->by;
    cf_status_t st = cf__reduce_check_degree("curve", n, o->by, 1, o->method,
                                             diag);
    if (st != CF_STATUS_OK)
        return st;
    if (o->continuity < -1 || 2 * (o->continuity + 1) > m + 1)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "continuity %d cannot be kept at both ends of a "
                         "curve of degree %d (reducing %d by %d): k must be "
                         "-1 .. %d", o->continuity, m, n, o->by,
                         (m + 1) / 2 - 1);
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_reduce(const cf_bezier_t *c, const cf_reduce_options_t *opt,
                 cf_bezier_t **out, cf_reduce_report_t *report,
                 cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_reduce_options_t o;
    cf__reduce_job_t j;
    cf_bezier_t *r;
    cf_status_t st;

    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "the output pointer is NULL");
    *out = NULL;
    if (c == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "the curve is NULL");
    if (opt != NULL)
        o = *opt;
    else
        cf_reduce_options_init(&o);
    st = check_options(&o, c->degree, diag);
    if (st != CF_STATUS_OK)
        return st;
    r = cf__bezier_new(c->dim, c->degree - o.by, c->rational);
    if (r == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory (degree reduction)");
    j.P = c->pts;
    j.n = c->degree;
    j.m = c->degree - o.by;
    j.k0 = j.k1 = o.continuity;
    j.h = c->hdim;
    if (report != NULL) {
        memset(report, 0, sizeof *report);
        report->continuity = -1;
    }
    st = cf__reduce_solve(&j, c->dim, c->rational, o.method, r->pts, report,
                          diag);
    if (st != CF_STATUS_OK) {
        cf__free(r);
        return st;
    }
    *out = r;
    return CF_STATUS_OK;
}
