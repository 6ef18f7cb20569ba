/*
** bench-visibility: hidden lines of the NURBS torus (R = 1, r = 0.4, the
** exact surface of cf_nurbs_torus), its 20 x 20 iso-lines (20 in u and 20
** in v, at (i + 1/2) / 20, each on the torus: cf_vis_on_t with its (u, v)
** line), seen from azimuth -50, elevation 35, orthographic and at
** distance 5 in perspective, tolerance 1e-3 (the figure's units; the torus
** is 2.8 wide).  Timed separately, median of 5 runs each: the scene
** (patches into pieces and their box tree), the visibility of the 40
** lines, the silhouette, and the facets for shading at 1e-2 in painting
** order.  Prints the counts (intervals, pieces, facets) as checksums.
*/
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench-time.h"
#include "curvefig/surface-make.h"
#include "curvefig/visibility.h"

enum { RUNS = 5, LINES = 20 };

static void
die(const char *what, cf_status_t st)
{
    fprintf(stderr, "bench-visibility: %s failed (%s)\n", what,
            cf_status_to_string(st));
    exit(1);
}

static double
median(double *t)
{
    qsort(t, RUNS, sizeof *t, cmp_double);
    return t[RUNS / 2];
}

/* The 40 iso-lines and their (u, v) lines. */
static cf_bspline_t *iso[2 * LINES], *uvl[2 * LINES];

static void
make_lines(const cf_bspline_surface_t *s)
{
    for (int d = 0; d < 2; d++)
        for (int i = 0; i < LINES; i++) {
            double val = (i + 0.5) / LINES, a, b, kn[4], pts[4];
            cf_bspline_t **c = &iso[d * LINES + i];
            cf_status_t st = cf_bspline_surface_iso(s, (cf_dir_t)d, val, c,
                                                    NULL);
            if (st != CF_STATUS_OK)
                die("iso", st);
            cf_bspline_domain(*c, &a, &b);
            kn[0] = kn[1] = a;
            kn[2] = kn[3] = b;
            pts[d] = pts[2 + d] = val;
            pts[1 - d] = a;
            pts[3 - d] = b;
            st = cf_bspline_create(2, 1, kn, 4, pts, 2, NULL,
                                   &uvl[d * LINES + i], NULL);
            if (st != CF_STATUS_OK)
                die("uv line", st);
        }
}

static void
run(const char *name, const cf_view_t *v, const cf_bspline_surface_t *s)
{
    double tb[RUNS], tv[RUNS], ts[RUNS], tf[RUNS];
    size_t nint = 0, npieces = 0, nfacets = 0, hidden = 0;
    for (int r = 0; r < RUNS; r++) {
        cf_scene_t *sc = NULL;
        cf_status_t st;
        double t0 = now_s();
        if ((st = cf_scene_create(v, 1e-3, &sc, NULL)) != CF_STATUS_OK ||
            (st = cf_scene_add_bspline(sc, s, NULL, NULL)) != CF_STATUS_OK)
            die("scene", st);
        double t1 = now_s();
        nint = hidden = 0;
        for (int i = 0; i < 2 * LINES; i++) {
            cf_visibility_t *vis = NULL;
            cf_vis_on_t on = {0, NULL, uvl[i], {0, 0}, 0.0};
            if ((st = cf_scene_bspline_visibility(sc, iso[i], &on, &vis,
                                                  NULL)) != CF_STATUS_OK)
                die("visibility", st);
            nint += vis->n;
            for (size_t k = 0; k < vis->n; k++)
                hidden += !vis->items[k].visible;
            cf_visibility_destroy(vis);
        }
        double t2 = now_s();
        cf_silhouette_t *sil = NULL;
        if ((st = cf_scene_silhouette(sc, 0, &sil, NULL)) != CF_STATUS_OK)
            die("silhouette", st);
        npieces = sil->n;
        cf_silhouette_destroy(sil);
        double t3 = now_s();
        cf_facets_t *f = NULL;
        if ((st = cf_scene_facets_tol(sc, 1e-2, &f, NULL)) != CF_STATUS_OK)
            die("facets", st);
        nfacets = f->n;
        cf_facets_destroy(f);
        double t4 = now_s();
        cf_scene_destroy(sc);
        tb[r] = t1 - t0;
        tv[r] = t2 - t1;
        ts[r] = t3 - t2;
        tf[r] = t4 - t3;
    }
    printf("%-13s scene %8.2f ms | 40 iso-lines %8.2f ms (%zu intervals, "
           "%zu hidden) | silhouette %7.2f ms (%zu pieces) | facets 1e-2 "
           "%8.2f ms (%zu)\n", name, 1e3 * median(tb), 1e3 * median(tv),
           nint, hidden, 1e3 * median(ts), npieces, 1e3 * median(tf),
           nfacets);
}

int
main(void)
{
    double c[3] = {0, 0, 0};
    cf_bspline_surface_t *s = NULL;
    cf_view_t v;
    cf_status_t st = cf_nurbs_torus(c, 1.0, 0.4, &s, NULL);
    if (st != CF_STATUS_OK)
        die("torus", st);
    make_lines(s);
    printf("torus R 1, r 0.4, 20 x 20 iso-lines, tolerance 1e-3, median of "
           "%d runs\n", RUNS);
    cf_view_orthographic(&v, -50, 35, NULL);
    run("orthographic", &v, s);
    cf_view_perspective(&v, -50, 35, 5.0, NULL, NULL);
    run("perspective", &v, s);
    for (int i = 0; i < 2 * LINES; i++) {
        cf_bspline_destroy(iso[i]);
        cf_bspline_destroy(uvl[i]);
    }
    cf_bspline_surface_destroy(s);
    return 0;
}
