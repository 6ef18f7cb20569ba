/*
** Fuzz target: views and scenes of visibility.h from arbitrary numbers
** (angles, distances, tolerances, control points and weights of Bézier
** and triangular patches, NaN/Inf, huge and tiny values), then the
** projection of a curve, the visibility of a curve (free, or on a surface
** with a (u, v) line: the certified gaps) and of a point (free or on a
** surface), the silhouette and the facets.  Nothing may crash or read out
** of bounds, every status must be a cf_status_t, and every failure with a
** diag must say why.
**
** Bounded by design, not by the library's checks (both slow, not wrong):
** the facets are asked for at 1/20 of the scene's size or coarser, and a
** scene's tolerance that the library would accept below 1e-3 of the size
** of the surfaces' control points is raised to 1e-3 of it.  A scene of
** size 5e9 at tolerance 0.2 (one control point at 1e9) cut its patches
** into 65,536 pieces each, whose boxes overlapped every point: one input
** took 26 s, and the campaign ran at 14 inputs a second.  Tolerances that
** are refused (zero, negative, NaN, below 1e-12 of the size) still reach
** the library as drawn.
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
    double cp[12], w[4], pt[3], uvp[4];
    cf_bezier_t *c = NULL, *img = NULL, *uv = NULL;
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
        if (fz_byte(in) % 2) {
            /* on a surface along a (u, v) segment, maybe off it */
            for (int k = 0; k < 4; k++)
                uvp[k] = number(in, 1.0) * 0.5 + 0.5;
            if (cf_bezier_create(2, 1, uvp, NULL, &uv, NULL) == CF_STATUS_OK)
                on.uv_bezier = uv;
            on.offset = fz_byte(in) % 2 ? 0.0 : fz_byte(in) / 2048.0;
        }
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
    cf_bezier_destroy(uv);
    points(in, pt, 1, NULL);
    if (fz_byte(in) % 4 == 0)
        pt[fz_byte(in) % 3] = fz_double(in);
    bool visible;
    cf_vis_on_t pon = {fz_byte(in) % 3, NULL, NULL, {0, 0}, 0.0};
    pon.uv[0] = number(in, 1.0) * 0.5 + 0.5;
    pon.uv[1] = number(in, 1.0) * 0.5 + 0.5;
    st = cf_scene_point_visible(sc, pt, fz_byte(in) % 2 ? &pon : NULL,
                                &visible, NULL, &diag);
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

/* One surface as drawn: a triangular patch (tri) or a tensor one. */
typedef struct surf {
    bool tri, rat;
    int m, n;
    size_t count;
    double P[16 * 3], W[16];
} surf;

static void
read_surface(fz_input *in, surf *s)
{
    s->rat = fz_byte(in) % 2;
    s->tri = fz_byte(in) % 3 == 0;
    if (s->tri) {
        s->n = s->m = 1 + (int)(fz_byte(in) % 3);
        s->count = (size_t)(s->n + 1) * (size_t)(s->n + 2) / 2;
        points(in, s->P, s->count, s->W);
        return;
    }
    s->m = (int)(fz_byte(in) % 4);
    s->n = (int)(fz_byte(in) % 4);
    s->count = (size_t)(s->m + 1) * (size_t)(s->n + 1);
    points(in, s->P, s->count, s->W);
    if (fz_byte(in) % 8 == 0)
        s->P[fz_byte(in) % 3] = fz_double(in);
}

static void
add_surface(cf_scene_t *sc, const surf *s)
{
    cf_diag_t diag;
    cf_status_t st;
    if (s->tri) {
        cf_bezier_triangle_t *t = NULL;
        st = cf_bezier_triangle_create(3, s->n, s->P, s->rat ? s->W : NULL,
                                       &t, &diag);
        fz_check_status(st, &diag, "bezier_triangle_create");
        if (st == CF_STATUS_OK) {
            st = cf_scene_add_triangle(sc, t, NULL, &diag);
            fz_check_status(st, &diag, "scene_add_triangle");
        }
        cf_bezier_triangle_destroy(t);
        return;
    }
    cf_bezier_surface_t *b = NULL;
    st = cf_bezier_surface_create(3, s->m, s->n, s->P, s->rat ? s->W : NULL,
                                  &b, &diag);
    fz_check_status(st, &diag, "bezier_surface_create");
    if (st == CF_STATUS_OK) {
        st = cf_scene_add_bezier(sc, b, NULL, &diag);
        fz_check_status(st, &diag, "scene_add_bezier");
    }
    cf_bezier_surface_destroy(b);
}

/* The diagonal of the box of the finite control points of s[0..n-1]. */
static double
size_of(const surf *s, int n)
{
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3], d = 0.0;
    for (int k = 0; k < 3; k++)
        hi[k] = -HUGE_VAL;
    for (int i = 0; i < n; i++)
        for (size_t j = 0; j < s[i].count; j++)
            for (int k = 0; k < 3; k++)
                if (isfinite(s[i].P[3 * j + k])) {
                    lo[k] = fmin(lo[k], s[i].P[3 * j + k]);
                    hi[k] = fmax(hi[k], s[i].P[3 * j + k]);
                }
    for (int k = 0; k < 3; k++)
        if (hi[k] >= lo[k])
            d = hypot(d, hi[k] - lo[k]);
    return d;
}

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_input in = {data, size};
    cf_view_t v;
    cf_scene_t *sc = NULL;
    cf_diag_t diag;
    cf_status_t st;
    surf s[2];
    double az = number(&in, 180.0), el = number(&in, 90.0);
    if (fz_byte(&in) % 2)
        st = cf_view_perspective(&v, az, el, number(&in, 10.0), NULL, &diag);
    else
        st = cf_view_orthographic(&v, az, el, &diag);
    fz_check_status(st, &diag, "view");
    if (st != CF_STATUS_OK)
        return 0;
    int nsurf = 1 + (int)(fz_byte(&in) % 2);
    for (int i = 0; i < nsurf; i++)
        read_surface(&in, &s[i]);
    double box = size_of(s, nsurf);
    double tol = fz_byte(&in) % 4 ? 1e-3 * (1 + fz_byte(&in)) : fz_double(&in);
    /* accepted but below 1e-3 of the size: slow by design (above) */
    if (tol > 1e-12 * box && tol < 1e-3 * box)
        tol = 1e-3 * box;
    st = cf_scene_create(&v, tol, &sc, &diag);
    fz_check_status(st, &diag, "scene_create");
    if (st != CF_STATUS_OK)
        return 0;
    for (int i = 0; i < nsurf; i++)
        add_surface(sc, &s[i]);
    queries(&in, sc, &v);
    cf_scene_destroy(sc);
    return 0;
}
