/*
** Fuzz target: views and scenes of visibility.h from arbitrary numbers
** (angles, distances, tolerances, control points and weights of Bézier
** and triangular patches, NaN/Inf, huge and tiny values), then the
** projection of a curve, the visibility of a curve and of a point, the
** silhouette and the facets.  Nothing may crash or read out of bounds,
** every status must be a cf_status_t, and every failure with a diag must
** say why.  The facets are asked for at 1/20 of the scene's size or
** coarser (finer ones are slow by design, not wrong).
*/
#include <stdint.h>
#include <stdlib.h>

#include "curvefig/visibility.h"
#include "fuzz-check.h"
#include "fuzz-input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static double
number(fz_input *in, double scale)
{
    unsigned sel = fz_byte(in);
    if (sel < 220)
        return scale * ((double)sel / 110.0 - 1.0);
    return fz_double(in);
}

static void
points(fz_input *in, double *p, size_t n, double *w)
{
    for (size_t i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++)
            p[3 * i + k] = number(in, 2.0);
        if (w != NULL)
            w[i] = 0.25 + fz_byte(in) / 64.0;
    }
}

static void
queries(fz_input *in, const cf_scene_t *sc, const cf_view_t *v)
{
    double cp[12], w[4], pt[3];
    cf_bezier_t *c = NULL, *img = NULL;
    cf_diag_t diag;
    cf_status_t st;
    int deg = 1 + (int)(fz_byte(in) % 3);
    bool rat = fz_byte(in) % 2;
    points(in, cp, (size_t)deg + 1, w);
    st = cf_bezier_create(3, deg, cp, rat ? w : NULL, &c, &diag);
    fz_check_status(st, &diag, "bezier_create");
    if (st == CF_STATUS_OK) {
        cf_visibility_t *vis = NULL;
        cf_vis_on_t on = {fz_byte(in) % 3, NULL, NULL, {0, 0}, 0.0};
        st = cf_view_project_bezier(v, c, &img, &diag);
        fz_check_status(st, &diag, "view_project_bezier");
        st = cf_scene_curve_visibility(sc, c, fz_byte(in) % 2 ? &on : NULL,
                                       &vis, &diag);
        fz_check_status(st, &diag, "scene_curve_visibility");
        if (st == CF_STATUS_OK)
            FZ_CHECK(vis->n >= 1 && vis->items[0].t0 == 0.0,
                     "intervals cover the curve");
        cf_visibility_destroy(vis);
    }
    cf_bezier_destroy(c);
    cf_bezier_destroy(img);
    points(in, pt, 1, NULL);
    if (fz_byte(in) % 4 == 0)
        pt[fz_byte(in) % 3] = fz_double(in);
    bool visible;
    st = cf_scene_point_visible(sc, pt, NULL, &visible, NULL, &diag);
    fz_check_status(st, &diag, "scene_point_visible");
    if (fz_byte(in) % 2) {
        cf_silhouette_t *sil = NULL;
        st = cf_scene_silhouette(sc, fz_byte(in) % 2 ? 0 : SIZE_MAX, &sil,
                                 &diag);
        fz_check_status(st, &diag, "scene_silhouette");
        cf_silhouette_destroy(sil);
    }
    if (fz_byte(in) % 2) {
        cf_facets_t *f = NULL;
        double tol = (0.05 + fz_byte(in) / 64.0) * 4.0;
        st = cf_scene_facets_tol(sc, tol, &f, &diag);
        fz_check_status(st, &diag, "scene_facets_tol");
        cf_facets_destroy(f);
    }
}

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_input in = {data, size};
    cf_view_t v;
    cf_scene_t *sc = NULL;
    cf_diag_t diag;
    cf_status_t st;
    double az = number(&in, 180.0), el = number(&in, 90.0);
    if (fz_byte(&in) % 2)
        st = cf_view_perspective(&v, az, el, number(&in, 10.0), NULL, &diag);
    else
        st = cf_view_orthographic(&v, az, el, &diag);
    fz_check_status(st, &diag, "view");
    if (st != CF_STATUS_OK)
        return 0;
    double tol = fz_byte(&in) % 4 ? 1e-3 * (1 + fz_byte(&in)) : fz_double(&in);
    st = cf_scene_create(&v, tol, &sc, &diag);
    fz_check_status(st, &diag, "scene_create");
    if (st != CF_STATUS_OK)
        return 0;
    int nsurf = 1 + (int)(fz_byte(&in) % 2);
    for (int s = 0; s < nsurf; s++) {
        double P[16 * 3], W[16];
        bool rat = fz_byte(&in) % 2;
        if (fz_byte(&in) % 3 == 0) {
            cf_bezier_triangle_t *t = NULL;
            int n = 1 + (int)(fz_byte(&in) % 3);
            points(&in, P, (size_t)(n + 1) * (size_t)(n + 2) / 2, W);
            st = cf_bezier_triangle_create(3, n, P, rat ? W : NULL, &t, &diag);
            fz_check_status(st, &diag, "bezier_triangle_create");
            if (st == CF_STATUS_OK) {
                st = cf_scene_add_triangle(sc, t, NULL, &diag);
                fz_check_status(st, &diag, "scene_add_triangle");
            }
            cf_bezier_triangle_destroy(t);
        } else {
            cf_bezier_surface_t *b = NULL;
            int m = (int)(fz_byte(&in) % 4), n = (int)(fz_byte(&in) % 4);
            points(&in, P, (size_t)(m + 1) * (size_t)(n + 1), W);
            if (fz_byte(&in) % 8 == 0)
                P[fz_byte(&in) % 3] = fz_double(&in);
            st = cf_bezier_surface_create(3, m, n, P, rat ? W : NULL, &b,
                                          &diag);
            fz_check_status(st, &diag, "bezier_surface_create");
            if (st == CF_STATUS_OK) {
                st = cf_scene_add_bezier(sc, b, NULL, &diag);
                fz_check_status(st, &diag, "scene_add_bezier");
            }
            cf_bezier_surface_destroy(b);
        }
    }
    queries(&in, sc, &v);
    cf_scene_destroy(sc);
    return 0;
}
