/*
** Fuzz target: the surface constructors of surface.h from arbitrary
** numbers (degrees, grid sizes, knot vectors, weights, NaN/Inf, huge and
** tiny values), followed by evaluation, derivatives, the de Casteljau / de
** Boor schemes, normals, curvatures, iso-curves, split, knot insertion,
** elevation, Bézier decomposition and grid evaluation.  Nothing may crash
** or read out of bounds, every status must be a cf_status_t, and every
** failure with a diag must say why.
*/
#include <stdint.h>
#include <stdlib.h>

#include "curvefig/surface.h"
#include "fuzz-check.h"
#include "fuzz-input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAX_DIM 3
#define MAX_SIDE 8   /* points per direction */

static double
param(fz_input *in, double a, double b)
{
    unsigned sel = fz_byte(in);
    if (sel < 200)
        return a + (b - a) * (sel / 199.0);
    return fz_double(in);
}

/* Operations shared by both kinds, through these callbacks. */
static void
exercise(fz_input *in, const cf_bezier_surface_t *bz,
         const cf_bspline_surface_t *bs, size_t dim)
{
    double out[9 * MAX_DIM], ua = 0, ub = 1, va = 0, vb = 1, K, H;
    cf_diag_t diag;
    cf_status_t st;
    int ops = 1 + (int)(fz_byte(in) % 8);
    if (bs != NULL) {
        cf_bspline_surface_domain(bs, CF_DIR_U, &ua, &ub);
        cf_bspline_surface_domain(bs, CF_DIR_V, &va, &vb);
    }
    while (ops-- > 0 && in->n > 0) {
        double u = param(in, ua, ub), v = param(in, va, vb);
        cf_dir_t dir = fz_byte(in) % 2 ? CF_DIR_V : CF_DIR_U;
        cf_bezier_surface_t *b1 = NULL, *b2 = NULL;
        cf_bspline_surface_t *s1 = NULL, *s2 = NULL;
        cf_bezier_t *cb = NULL;
        cf_bspline_t *cs = NULL;
        cf_bezier_surface_list_t *L = NULL;
        double *net;
        cf_diag_clear(&diag);
        switch (fz_byte(in) % 9) {
        case 0:
            st = bz ? cf_bezier_surface_eval(bz, u, v, out)
                    : cf_bspline_surface_eval(bs, u, v, out);
            fz_check_status(st, NULL, "surface_eval");
            break;
        case 1:
            st = bz ? cf_bezier_surface_eval_derivs(bz, u, v, 2, out)
                    : cf_bspline_surface_eval_derivs(bs, u, v, 2, out);
            fz_check_status(st, NULL, "surface_eval_derivs");
            break;
        case 2:
            net = malloc((bz ? cf_bezier_surface_decasteljau_size(bz)
                             : cf_bspline_surface_deboor_size(bs)) *
                             sizeof *net + 1);
            FZ_CHECK(net != NULL, "malloc");
            st = bz ? cf_bezier_surface_decasteljau(bz, u, v, net)
                    : cf_bspline_surface_deboor(bs, u, v, net, NULL);
            fz_check_status(st, NULL, "surface scheme");
            free(net);
            break;
        case 3:
            if (dim == 3) {
                st = bz ? cf_bezier_surface_normal(bz, u, v, out)
                        : cf_bspline_surface_normal(bs, u, v, out);
                fz_check_status(st, NULL, "surface_normal");
                st = bz ? cf_bezier_surface_curvature(bz, u, v, &K, &H)
                        : cf_bspline_surface_curvature(bs, u, v, &K, &H);
                fz_check_status(st, NULL, "surface_curvature");
            }
            break;
        case 4:
            st = bz ? cf_bezier_surface_iso(bz, dir, u, &cb, &diag)
                    : cf_bspline_surface_iso(bs, dir, u, &cs, &diag);
            fz_check_status(st, &diag, "surface_iso");
            break;
        case 5:
            st = bz ? cf_bezier_surface_split(bz, dir, u, &b1, &b2, &diag)
                    : cf_bspline_surface_split(bs, dir, u, &s1, &s2, &diag);
            fz_check_status(st, &diag, "surface_split");
            break;
        case 6:
            st = bz ? cf_bezier_surface_elevate(bz, fz_byte(in) % 3,
                                                fz_byte(in) % 3, &b1, &diag)
                    : cf_bspline_surface_elevate(bs, fz_byte(in) % 3,
                                                 fz_byte(in) % 3, &s1, &diag);
            fz_check_status(st, &diag, "surface_elevate");
            break;
        case 7:
            if (bz != NULL)
                st = cf_bezier_surface_segment(bz, u, param(in, 0, 1), v,
                                               param(in, 0, 1), &b1, &diag);
            else
                st = cf_bspline_surface_insert_knot(
                    bs, dir, dir == CF_DIR_U ? u : v,
                    1 + (int)(fz_byte(in) % 3), &s1, &diag);
            fz_check_status(st, &diag, "surface_segment / insert_knot");
            break;
        default:
            if (bs != NULL) {
                double uv[6] = { u, v, param(in, ua, ub), param(in, va, vb),
                                 u, v };
                double pts[9 * MAX_DIM], su[9 * MAX_DIM], sv[9 * MAX_DIM];
                st = cf_bspline_surface_to_beziers(bs, &L, &diag);
                fz_check_status(st, &diag, "surface_to_beziers");
                st = cf_bspline_surface_eval_grid(bs, uv, 3, 3, pts, su, sv);
                fz_check_status(st, NULL, "surface_eval_grid");
            }
            break;
        }
        cf_bezier_surface_destroy(b1);
        cf_bezier_surface_destroy(b2);
        cf_bspline_surface_destroy(s1);
        cf_bspline_surface_destroy(s2);
        cf_bezier_destroy(cb);
        cf_bspline_destroy(cs);
        cf_bezier_surface_list_destroy(L);
    }
}

static double *
fill(fz_input *in, size_t n, int finite)
{
    double *v = malloc((n ? n : 1) * sizeof *v);
    if (v == NULL)
        abort();
    for (size_t i = 0; i < n; i++)
        v[i] = finite ? fz_finite(in) : fz_double(in);
    return v;
}

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_input in = { data, size };
    size_t dim = 1 + fz_byte(&in) % MAX_DIM;
    int bezier = fz_byte(&in) % 2, rational = fz_byte(&in) % 2;
    int p = (int)(fz_byte(&in) % 5), q = (int)(fz_byte(&in) % 5);
    size_t nu = 1 + fz_byte(&in) % MAX_SIDE, nv = 1 + fz_byte(&in) % MAX_SIDE;
    int finite = fz_byte(&in) % 4 != 0;
    double *P, *W, *U, *V;
    cf_diag_t diag;
    cf_status_t st;
    if (bezier) {
        /* degrees from the grid (a short buffer is never passed) */
        nu = (size_t)p + 1;
        nv = (size_t)q + 1;
    }
    P = fill(&in, nu * nv * dim, finite);
    W = fill(&in, nu * nv, finite);
    for (size_t i = 0; i < nu * nv && finite; i++)
        W[i] = 0.25 + (fabs(W[i]) < 8 ? fabs(W[i]) : 1.0);
    U = fill(&in, nu + (size_t)p + 1, finite);
    V = fill(&in, nv + (size_t)q + 1, finite);
    if (fz_byte(&in) % 2) {
        /* sorted knots: a valid vector more often */
        for (size_t i = 1; i < nu + (size_t)p + 1; i++)
            U[i] = U[i - 1] + fabs(U[i]) / 16.0 + (i % 3 == 0);
        for (size_t i = 1; i < nv + (size_t)q + 1; i++)
            V[i] = V[i - 1] + fabs(V[i]) / 16.0 + (i % 2 == 0);
    }
    cf_diag_clear(&diag);
    if (bezier) {
        cf_bezier_surface_t *s = NULL;
        st = cf_bezier_surface_create(dim, p, q, P, rational ? W : NULL, &s,
                                      &diag);
        fz_check_status(st, &diag, "bezier_surface_create");
        if (st == CF_STATUS_OK)
            exercise(&in, s, NULL, dim);
        cf_bezier_surface_destroy(s);
    } else {
        cf_bspline_surface_t *s = NULL;
        st = cf_bspline_surface_create(dim, p, q, U, nu + (size_t)p + 1, V,
                                       nv + (size_t)q + 1, P, nu, nv,
                                       rational ? W : NULL, &s, &diag);
        fz_check_status(st, &diag, "bspline_surface_create");
        if (st == CF_STATUS_OK)
            exercise(&in, NULL, s, dim);
        cf_bspline_surface_destroy(s);
    }
    free(P);
    free(W);
    free(U);
    free(V);
    return 0;
}
