/*
** Fuzz target: the curve constructors from arbitrary numbers (degrees,
** counts, knot vectors, weights, NaN/Inf, huge and tiny values), followed
** by evaluation, derivatives, de Casteljau / de Boor, split, elevation and
** decomposition.  Nothing may crash or read out of bounds, every status
** must be a cf_status_t, and every failure with a diag must say why.
**
** Buffers are sized from what the contract says the function reads; for
** degrees beyond the documented maximum a short buffer is passed on
** purpose: the constructor must reject the degree before reading points.
*/
#include <stdint.h>
#include <stdlib.h>

#include "curvefig/bezier.h"
#include "curvefig/bspline.h"
#include "curvefig/knots.h"
#include "fuzz-check.h"
#include "fuzz-input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAX_DIM 4
#define CHEAP_DEGREE 24   /* bound for the non-linear-time operations */

static double *
fill(fz_input *in, size_t n, int finite)
{
    double *v = malloc((n ? n : 1) * sizeof *v);
    size_t i;
    if (v == NULL)
        abort();
    for (i = 0; i < n; i++)
        v[i] = finite ? fz_finite(in) : fz_double(in);
    return v;
}

static double
param(fz_input *in)
{
    /* mostly inside [0, 1] (and at its ends), sometimes anything */
    unsigned sel = fz_byte(in);
    if (sel < 160)
        return sel / 159.0;
    return fz_double(in);
}

static void
exercise_bezier(fz_input *in, const cf_bezier_t *c)
{
    size_t dim = cf_bezier_dim(c);
    int n = cf_bezier_degree(c);
    double out[(CHEAP_DEGREE + 2) * MAX_DIM], lo[MAX_DIM], hi[MAX_DIM];
    double *tri;
    cf_bezier_t *l = NULL, *r = NULL, *e = NULL;
    cf_diag_t diag;
    cf_status_t st;
    int k, ops = 1 + (int)(fz_byte(in) % 8);

    while (ops-- > 0 && in->n > 0) {
        double t = param(in);
        cf_diag_clear(&diag);
        switch (fz_byte(in) % 10) {
        case 0:
            fz_check_status(cf_bezier_eval(c, t, out), NULL, "bezier_eval");
            break;
        case 1:
            k = (int)(fz_byte(in) % (CHEAP_DEGREE + 1));
            fz_check_status(cf_bezier_eval_derivs(c, t, k, out), NULL,
                            "bezier_eval_derivs");
            break;
        case 2:
            tri = malloc(cf_bezier_decasteljau_size(c) * sizeof *tri + 1);
            FZ_CHECK(tri != NULL, "malloc");
            fz_check_status(cf_bezier_decasteljau(c, t, tri), NULL,
                            "bezier_decasteljau");
            free(tri);
            break;
        case 3:
            st = cf_bezier_split(c, t, &l, &r, &diag);
            fz_check_status(st, &diag, "bezier_split");
            FZ_CHECK(st != CF_STATUS_OK || (l != NULL && r != NULL),
                     "split OK without both halves");
            cf_bezier_destroy(l);
            cf_bezier_destroy(r);
            l = r = NULL;
            break;
        case 4:
            k = (int)(fz_byte(in) % 4);
            st = cf_bezier_elevate(c, k, &e, &diag);
            fz_check_status(st, &diag, "bezier_elevate");
            cf_bezier_destroy(e);
            e = NULL;
            break;
        case 5:
            k = (int)(fz_byte(in) % 4);
            st = cf_bezier_derivative(c, k, &e, &diag);
            fz_check_status(st, &diag, "bezier_derivative");
            cf_bezier_destroy(e);
            e = NULL;
            break;
        case 6:
            fz_check_status(cf_bezier_tangent(c, t, out), NULL,
                            "bezier_tangent");
            fz_check_status(cf_bezier_curvature(c, t, out), NULL,
                            "bezier_curvature");
            if (dim >= 2)
                fz_check_status(cf_bezier_normal(c, t, out), NULL,
                                "bezier_normal");
            break;
        case 7:
            if (n <= CHEAP_DEGREE)
                fz_check_status(cf_bezier_bbox(c, lo, hi), NULL,
                                "bezier_bbox");
            break;
        case 8:
            st = cf_bezier_segment(c, t, param(in), &e, &diag);
            fz_check_status(st, &diag, "bezier_segment");
            cf_bezier_destroy(e);
            e = NULL;
            break;
        default:
            st = cf_bezier_reverse(c, &e, &diag);
            fz_check_status(st, &diag, "bezier_reverse");
            cf_bezier_destroy(e);
            e = NULL;
            break;
        }
    }
}

static void
exercise_bspline(fz_input *in, const cf_bspline_t *c)
{
    int p = cf_bspline_degree(c);
    double out[(CF_BSPLINE_MAX_DEGREE + 2) * MAX_DIM];
    double N[CF_BSPLINE_MAX_DEGREE + 1], a, b;
    double *net, x[4];
    size_t first, span;
    int mult, k, removed, ops = 1 + (int)(fz_byte(in) % 8);
    cf_bspline_t *l = NULL, *r = NULL;
    cf_bezier_list_t *list = NULL;
    cf_diag_t diag;
    cf_status_t st;

    cf_bspline_domain(c, &a, &b);
    while (ops-- > 0 && in->n > 0) {
        double u = fz_byte(in) < 200 ? a + (b - a) * fz_unit(in)
                                     : fz_double(in);
        cf_diag_clear(&diag);
        switch (fz_byte(in) % 11) {
        case 0:
            fz_check_status(cf_bspline_eval(c, u, out), NULL, "bspline_eval");
            break;
        case 1:
            k = (int)(fz_byte(in) % (CF_BSPLINE_MAX_DEGREE + 1));
            fz_check_status(cf_bspline_eval_derivs(c, u, k, out), NULL,
                            "bspline_eval_derivs");
            break;
        case 2:
            net = malloc(cf_bspline_deboor_size(c) * sizeof *net + 1);
            FZ_CHECK(net != NULL, "malloc");
            fz_check_status(cf_bspline_deboor(c, u, net, &span, &mult), NULL,
                            "bspline_deboor");
            free(net);
            fz_check_status(cf_bspline_basis(c, u, &first, N), NULL,
                            "bspline_basis");
            break;
        case 3:
            k = 1 + (int)(fz_byte(in) % 4);
            st = cf_bspline_insert_knot(c, u, k, &l, NULL, &diag);
            fz_check_status(st, &diag, "bspline_insert_knot");
            break;
        case 4:
            st = cf_bspline_split(c, u, &l, &r, &diag);
            fz_check_status(st, &diag, "bspline_split");
            break;
        case 5:
            if (p <= CHEAP_DEGREE) {
                st = cf_bspline_to_beziers(c, &list, &diag);
                fz_check_status(st, &diag, "bspline_to_beziers");
                cf_bezier_list_destroy(list);
                list = NULL;
            }
            break;
        case 6:
            k = (int)(fz_byte(in) % 3);
            st = cf_bspline_elevate(c, k, &l, &diag);
            fz_check_status(st, &diag, "bspline_elevate");
            break;
        case 7:
            k = (int)(fz_byte(in) % 3);
            st = cf_bspline_derivative(c, k, &l, &diag);
            fz_check_status(st, &diag, "bspline_derivative");
            break;
        case 8:
            st = cf_bspline_remove_knot(c, u, 1 + (int)(fz_byte(in) % 3),
                                        fz_double(in), &l, &removed, &diag);
            fz_check_status(st, &diag, "bspline_remove_knot");
            break;
        case 9:
            x[0] = u;
            x[1] = a + (b - a) * fz_unit(in);
            x[2] = fz_double(in);
            st = cf_bspline_refine(c, x, fz_byte(in) % 4, &l, &diag);
            fz_check_status(st, &diag, "bspline_refine");
            break;
        default:
            st = cf_bspline_segment(c, u, fz_double(in), &l, &diag);
            fz_check_status(st, &diag, "bspline_segment");
            break;
        }
        cf_bspline_destroy(l);
        cf_bspline_destroy(r);
        l = r = NULL;
    }
}

static void
fuzz_bezier(fz_input *in, size_t dim, int rational)
{
    int degree = fz_int(in, 12);
    int valid = degree >= 0 && degree <= CF_BEZIER_MAX_DEGREE;
    size_t np = valid ? (size_t)degree + 1 : 4;
    double *pts = fill(in, np * (dim + 1), fz_byte(in) < 128);
    double *w = fill(in, np, 0);
    cf_bezier_t *c = NULL;
    cf_diag_t diag;
    cf_status_t st;

    cf_diag_clear(&diag);
    if (rational == 2)
        st = cf_bezier_create_homogeneous(dim, degree, pts, &c, &diag);
    else
        st = cf_bezier_create(dim, degree, pts, rational ? w : NULL, &c,
                              &diag);
    fz_check_status(st, &diag, "bezier_create");
    FZ_CHECK(valid || st != CF_STATUS_OK, "degree out of range accepted");
    FZ_CHECK((st == CF_STATUS_OK) == (c != NULL), "status and object");
    if (c != NULL)
        exercise_bezier(in, c);
    cf_bezier_destroy(c);
    free(pts);
    free(w);
}

static void
fuzz_bspline(fz_input *in, size_t dim, int how)
{
    int degree = fz_int(in, 6);
    size_t count = fz_byte(in) % 24;
    int valid = degree >= 0 && degree <= CF_BSPLINE_MAX_DEGREE;
    size_t nk = count + (valid ? (size_t)degree : 0) + 1;
    size_t nknots, i;
    double *pts, *w, *knots;
    cf_bspline_t *c = NULL;
    cf_diag_t diag;
    cf_status_t st;
    unsigned delta = fz_byte(in);

    /* the declared number of knots is usually right, sometimes off */
    nknots = delta < 200 ? nk : nk + (delta % 5) - 2;
    if (nknots > nk + 2)      /* wrapped below zero */
        nknots = 0;
    knots = malloc((nk + 3) * sizeof *knots);
    FZ_CHECK(knots != NULL, "malloc");
    if (fz_byte(in) < 192) {
        /* non-decreasing increments, some zero (multiple knots) */
        double u = fz_double(in);
        for (i = 0; i < nk + 3; i++) {
            knots[i] = u;
            u += fz_byte(in) < 64 ? 0.0 : fz_unit(in);
        }
    } else {
        for (i = 0; i < nk + 3; i++)
            knots[i] = fz_double(in);
    }
    pts = fill(in, (count + 1) * (dim + 1), fz_byte(in) < 128);
    w = fill(in, count + 1, 0);
    cf_diag_clear(&diag);
    switch (how) {
    case 0:
        st = cf_bspline_create(dim, degree, knots, nknots, pts, count, NULL,
                               &c, &diag);
        break;
    case 1:
        st = cf_bspline_create(dim, degree, knots, nknots, pts, count, w, &c,
                               &diag);
        break;
    case 2:
        st = cf_bspline_create_homogeneous(dim, degree, knots, nknots, pts,
                                           count, &c, &diag);
        break;
    case 3:
        st = cf_bspline_create_clamped(dim, degree, pts, count,
                                       fz_byte(in) & 1 ? w : NULL, &c, &diag);
        break;
    default:
        st = cf_bspline_create_closed(dim, degree, pts, count,
                                      fz_byte(in) & 1 ? w : NULL, &c, &diag);
        break;
    }
    fz_check_status(st, &diag, "bspline_create");
    FZ_CHECK((st == CF_STATUS_OK) == (c != NULL), "status and object");
    if (c != NULL)
        exercise_bspline(in, c);
    cf_bspline_destroy(c);
    free(knots);
    free(pts);
    free(w);
}

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_input in = { data, size };
    unsigned sel = fz_byte(&in);
    size_t dim = 1 + (sel >> 4) % MAX_DIM;

    switch (sel % 8) {
    case 0:
    case 1:
    case 2:
        fuzz_bezier(&in, dim, (int)(sel % 8));
        break;
    default:
        fuzz_bspline(&in, dim, (int)(sel % 8) - 3);
        break;
    }
    return 0;
}
