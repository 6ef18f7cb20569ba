/*
** Offset curves: exact points, the public entry points of the approximating
** chain and the independent error measure.  The chain is driven in
** fit-chain.c, the fits are in fit-piece.c, cusps in fit-cusp.c,
** trimming in offset-trim.c.
*/
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core-private.h"
#include "bezier-private.h"
#include "offset-trim-private.h"
#include "numtext-private.h"

void
cf_offset_options_init(cf_offset_options_t *opt)
{
    if (opt == NULL)
        return;
    opt->tolerance = 1e-3;
    opt->method = CF_OFFSET_LEVIEN;
    opt->trim = false;
}

/* ---- exact offset ---------------------------------------------------------- */

static cf_status_t
check_curve(const cf_bezier_t *c)
{
    if (c == NULL)
        return CF_STATUS_INVALID_ARG;
    if (c->dim != 2)
        return CF_STATUS_DIM_MISMATCH;
    return CF_STATUS_OK;
}

cf_status_t
cf_offset_point(const cf_bezier_t *c, double t, double d, double *out)
{
    double p[2], u[2];
    cf_status_t st = check_curve(c);
    if (st != CF_STATUS_OK || out == NULL)
        return st != CF_STATUS_OK ? st : CF_STATUS_INVALID_ARG;
    if (!isfinite(d))
        return CF_STATUS_NOT_FINITE;
    st = cf__bezier_check_param(&t);
    if (st != CF_STATUS_OK)
        return st;
    if (cf__bezier_unit_tangent(c, t, t >= 1.0 ? -1 : 1, cf__deriv_scale(c),
                                p, u) != 0) {
        if (d != 0.0)
            return CF_STATUS_DEGENERATE;
        out[0] = p[0];
        out[1] = p[1];
        return CF_STATUS_OK;
    }
    out[0] = p[0] - d * u[1];
    out[1] = p[1] + d * u[0];
    return CF_STATUS_OK;
}

cf_status_t
cf_offset_point_many(const cf_bezier_t *c, const double *t, size_t n,
                     double d, double *out)
{
    if (t == NULL && n > 0)
        return CF_STATUS_INVALID_ARG;
    for (size_t i = 0; i < n; i++) {
        cf_status_t st = cf_offset_point(c, t[i], d, out + 2 * i);
        if (st != CF_STATUS_OK)
            return st;
    }
    return CF_STATUS_OK;
}

/* ---- chains ------------------------------------------------------------------ */


static cf_status_t
check_options(const cf_offset_options_t *opt, double d, cf_diag_t *diag)
{
    if (!isfinite(d))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "offset distance %s is not finite", CF__NUM(d));
    if (!(opt->tolerance > 0.0) || !isfinite(opt->tolerance))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "offset tolerance %s must be finite and positive",
                         CF__NUM(opt->tolerance));
    if (opt->method != CF_OFFSET_LEVIEN &&
        opt->method != CF_OFFSET_TILLER_HANSON)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "unknown offset method %d", (int)opt->method);
    return CF_STATUS_OK;
}

/* The offset's coordinates are about as large as the control points plus
** |d|; doubles resolve them to DBL_EPSILON of that, and the measured error of
** a fit carries rounding noise of a few hundred of those units (the fit and
** its error estimate each take some hundred operations).  A tolerance below
** OFFSET_RESOLUTION units could never be met: the greedy cover would shrink
** its pieces to the minimum width and never end.  It is refused instead. */
#define OFFSET_RESOLUTION 4096.0
#define OFFSET_SCALE_MAX 1e100

static cf_status_t
check_resolution(const cf_bezier_t *const *pieces, size_t n, double d,
                 double tol, cf_diag_t *diag)
{
    double scale = fabs(d), floor_tol;
    for (size_t i = 0; i < n; i++)
        scale = fmax(scale, cf__bezier_size(pieces[i]));
    /* the fits take squares and cubes of lengths of the offset's size
    ** (distances, areas, moments): beyond OFFSET_SCALE_MAX they overflow */
    if (!(scale <= OFFSET_SCALE_MAX))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "offset coordinates of size %s (distance %s) are "
                         "too large (at most %s: the fits' cubes of them "
                         "overflow)", CF__NUM(scale), CF__NUM(d),
                         CF__NUM(OFFSET_SCALE_MAX));
    floor_tol = OFFSET_RESOLUTION * DBL_EPSILON * scale;
    if (!(tol >= floor_tol))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "offset tolerance %s is below what doubles resolve "
                         "for coordinates of size %s (distance %s): it "
                         "must be at least %.3g",
                         CF__NUM(tol), CF__NUM(scale), CF__NUM(d), floor_tol);
    return CF_STATUS_OK;
}

static cf_status_t
offset_pieces(const cf_bezier_t *const *pieces, size_t n, const double *t0,
              const double *t1, double d, const cf_offset_options_t *opt_in,
              cf_cubics_t **raw, cf_cubics_list_t **trimmed,
              cf_offset_report_t *rep, cf_diag_t *diag)
{
    cf_offset_options_t opt;
    cf__driver_t dr;
    cf_bezier_t **own = NULL;
    cf_status_t st;
    if (raw != NULL)
        *raw = NULL;
    if (trimmed != NULL)
        *trimmed = NULL;
    if (opt_in != NULL)
        opt = *opt_in;
    else
        cf_offset_options_init(&opt);
    st = check_options(&opt, d, diag);
    if (st != CF_STATUS_OK)
        return st;
    for (size_t i = 0; i < n; i++) {
        if (pieces[i] == NULL)
            return cf__error(diag, CF_STATUS_INVALID_ARG, (long)i,
                             "piece %zu is NULL", i);
        if (pieces[i]->dim != 2)
            return cf__error(diag, CF_STATUS_DIM_MISMATCH, (long)i,
                             "offsets are planar; piece %zu has dim %zu", i,
                             pieces[i]->dim);
        if (opt.method == CF_OFFSET_TILLER_HANSON &&
            (pieces[i]->rational || pieces[i]->degree > 3))
            return cf__error(diag, CF_STATUS_INVALID_ARG, (long)i,
                             "Tiller-Hanson needs polynomial pieces of "
                             "degree <= 3; piece %zu is %s of degree %d",
                             i, pieces[i]->rational ? "rational" : "polynomial",
                             pieces[i]->degree);
        if (cf__deriv_scale(pieces[i]) == 0.0 && d != 0.0)
            return cf__error(diag, CF_STATUS_DEGENERATE, (long)i,
                             "piece %zu is a single point; its "
                             "normal is undefined", i);
    }
    st = check_resolution(pieces, n, d, opt.tolerance, diag);
    if (st != CF_STATUS_OK)
        return st;
    if (cf__driver_init(&dr, opt.tolerance, opt.method, d) != CF_STATUS_OK)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory (offset chain)");
    /* Tiller-Hanson works on cubics: raise lower degrees */
    if (opt.method == CF_OFFSET_TILLER_HANSON) {
        own = cf__calloc(n, sizeof *own);
        if (own == NULL) {
            st = CF_STATUS_NO_MEMORY;
            goto fail;
        }
        for (size_t i = 0; i < n; i++) {
            if (pieces[i]->degree < 3) {
                st = cf_bezier_elevate(pieces[i], 3 - pieces[i]->degree,
                                       &own[i], NULL);
                if (st != CF_STATUS_OK)
                    goto fail;
            }
        }
    }
    for (size_t i = 0; i < n; i++) {
        const cf_bezier_t *pc = (own != NULL && own[i] != NULL) ? own[i]
                                                                 : pieces[i];
        dr.T0 = t0 != NULL ? t0[i] : (double)i;
        dr.T1 = t1 != NULL ? t1[i] : (double)i + 1.0;
        if (i > 0) {
            st = cf__driver_join(&dr, pieces[i - 1], pieces[i]);
            if (st != CF_STATUS_OK)
                goto fail;
        }
        if (n == 1 && t0 == NULL) {
            dr.T0 = 0.0;
            dr.T1 = 1.0;
        }
        st = cf__driver_piece(&dr, pc);
        if (st != CF_STATUS_OK)
            goto fail;
    }
    dr.chain.cubics->max_error = dr.rep.max_error;
    if (opt.trim) {
        cf_cubics_list_t *tr = NULL;
        size_t nis = 0;
        st = cf__offset_trim(pieces, n, t0, t1, d, opt.tolerance,
                             dr.chain.cubics, &tr, &nis);
        if (st != CF_STATUS_OK)
            goto fail;
        dr.rep.self_intersections = nis;
        dr.rep.trimmed_chains = tr->count;
        for (size_t k = 0; k < tr->count; k++) {
            /* the report covers the trimmed pieces too */
            double e = tr->chains[k]->max_error;
            dr.rep.trimmed_segments += tr->chains[k]->count;
            dr.rep.max_error = fmax(dr.rep.max_error, e);
            if (!(e <= opt.tolerance))
                dr.rep.converged = false;
        }
        if (trimmed != NULL)
            *trimmed = tr;
        else
            cf_cubics_list_destroy(tr);
    }
    if (own != NULL) {
        for (size_t i = 0; i < n; i++)
            cf_bezier_destroy(own[i]);
        cf__free(own);
    }
    if (rep != NULL)
        *rep = dr.rep;
    if (raw != NULL)
        *raw = cf__chain_take(&dr.chain);
    cf__chain_fini(&dr.chain);
    return CF_STATUS_OK;
fail:
    if (own != NULL) {
        for (size_t i = 0; i < n; i++)
            cf_bezier_destroy(own[i]);
        cf__free(own);
    }
    cf__chain_fini(&dr.chain);
    if (trimmed != NULL) {
        cf_cubics_list_destroy(*trimmed);
        *trimmed = NULL;
    }
    if (st == CF_STATUS_NO_MEMORY)
        return cf__error(diag, st, -1, "out of memory (offset)");
    if (st == CF_STATUS_NO_CONVERGENCE)
        return cf__error(diag, st, -1,
                         "the offset at distance %s does not converge: "
                         "more than %d pieces of one interval or %d in "
                         "all would be needed for tolerance %s", CF__NUM(d),
                         CF__OFFSET_MAX_COVER, CF__OFFSET_MAX_PIECES,
                         CF__NUM(opt.tolerance));
    return cf__error(diag, st, -1, "offset failed: %s",
                     cf_status_to_string(st));
}

cf_status_t
cf_bezier_offset(const cf_bezier_t *c, double d,
                 const cf_offset_options_t *opt, cf_cubics_t **raw,
                 cf_cubics_list_t **trimmed, cf_offset_report_t *rep,
                 cf_diag_t *diag)
{
    cf_diag_clear(diag);
    if (c == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "the curve is NULL");
    return offset_pieces(&c, 1, NULL, NULL, d, opt, raw, trimmed, rep, diag);
}

cf_status_t
cf_bezier_list_offset(const cf_bezier_list_t *list, double d,
                      const cf_offset_options_t *opt, cf_cubics_t **raw,
                      cf_cubics_list_t **trimmed, cf_offset_report_t *rep,
                      cf_diag_t *diag)
{
    cf_diag_clear(diag);
    if (list == NULL || list->count == 0 || list->items == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "the list of pieces is NULL or empty");
    return offset_pieces((const cf_bezier_t *const *)list->items,
                         list->count, list->t0, list->t1, d, opt, raw,
                         trimmed, rep, diag);
}

cf_status_t
cf_bspline_offset(const cf_bspline_t *s, double d,
                  const cf_offset_options_t *opt, cf_cubics_t **raw,
                  cf_cubics_list_t **trimmed, cf_offset_report_t *rep,
                  cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_bezier_list_t *list = NULL;
    cf_status_t st;
    if (raw != NULL)
        *raw = NULL;
    if (trimmed != NULL)
        *trimmed = NULL;
    if (s == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "the B-spline is NULL");
    st = cf_bspline_to_beziers(s, &list, diag);
    if (st != CF_STATUS_OK)
        return st;
    st = cf_bezier_list_offset(list, d, opt, raw, trimmed, rep, diag);
    cf_bezier_list_destroy(list);
    return st;
}

/* ---- independent measure ---------------------------------------------------- */

/* Distance from q to the polyline poly[0..m]. */
static double
dist_polyline(const double *poly, size_t m, const double *q)
{
    double best = INFINITY;
    for (size_t i = 0; i < m; i++) {
        const double *a = poly + 2 * i, *b = a + 2;
        double vx = b[0] - a[0], vy = b[1] - a[1];
        double wx = q[0] - a[0], wy = q[1] - a[1];
        double l2 = vx * vx + vy * vy, u = 0.0;
        if (l2 > 0.0)
            u = fmin(1.0, fmax(0.0, (wx * vx + wy * vy) / l2));
        best = fmin(best, hypot(wx - u * vx, wy - u * vy));
    }
    return best;
}

cf_status_t
cf_offset_measure(const cf_bezier_t *c, double d, const cf_cubics_t *approx,
                  size_t samples, double *error, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    double *ex, *cx, emax = 0.0;
    size_t fine;
    cf_status_t st = check_curve(c);
    if (st != CF_STATUS_OK || approx == NULL || error == NULL)
        return cf__error(diag, st != CF_STATUS_OK ? st : CF_STATUS_INVALID_ARG,
                         -1, "bad curve or NULL argument");
    if (approx->dim != 2 || samples < 16)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "chain dim %zu, samples %zu "
                         "(need 2 and >= 16)", approx->dim, samples);
    fine = 4 * samples;
    ex = cf__alloc_array(2 * (fine + 1), sizeof(double));
    cx = cf__alloc_array(2 * (fine + 1), sizeof(double));
    if (ex == NULL || cx == NULL) {
        cf__free(ex);
        cf__free(cx);
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory (offset measure)");
    }
    for (size_t i = 0; i < approx->count; i++) {
        const double *P = approx->pts + 8 * i;
        double ta = approx->t[i], tb = approx->t[i + 1];
        for (size_t j = 0; j <= fine; j++)
            cf__cubic_pd(P, (double)j / (double)fine, cx + 2 * j, NULL);
        if (tb > ta) {
            for (size_t j = 0; j <= fine; j++) {
                double t = ta + (tb - ta) * (double)j / (double)fine;
                double u[2], p[2];
                if (t > 1.0)
                    t = 1.0;
                cf__bezier_unit_tangent(c, t, j == fine ? -1 : 1,
                                        cf__deriv_scale(c), p, u);
                ex[2 * j] = p[0] - d * u[1];
                ex[2 * j + 1] = p[1] + d * u[0];
            }
            for (size_t j = 0; j <= samples; j++) {
                size_t k = j * 4;
                emax = fmax(emax, dist_polyline(cx, fine, ex + 2 * k));
                emax = fmax(emax, dist_polyline(ex, fine, cx + 2 * k));
            }
        } else {
            double p[2];
            cf__bezier_eval_point(c, ta, p);
            for (size_t j = 0; j <= samples; j++) {
                size_t k = j * 4;
                emax = fmax(emax, fabs(hypot(cx[2 * k] - p[0],
                                             cx[2 * k + 1] - p[1]) -
                                       fabs(d)));
            }
        }
    }
    cf__free(ex);
    cf__free(cx);
    *error = emax;
    return CF_STATUS_OK;
}
