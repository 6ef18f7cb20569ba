/*
** Shading of the surfaces of a 3D figure (surface-lines.h): the scene's
** facets in painting order, each filled in its surface's colour under a
** distant light.  The order is the scene's (split where facets cross), so
** overlapping surfaces are painted right without a sort here.
*/
#include <math.h>
#include <string.h>

#include "surface-lines.h"

static void
normalize(double v[3])
{
    double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (n > 0)
        for (int k = 0; k < 3; k++)
            v[k] /= n;
}

/* The direction towards the light of a shading (unit). */
static void
light_of(const cf_figure_t *fig, const cf_surface_shading_t *sh, double L[3])
{
    const cf_view_t *v = &fig->view;
    for (int k = 0; k < 3; k++)
        L[k] = sh->has_light ? sh->light[k]
                             : v->dir[k] + 0.6 * v->ey[k] - 0.4 * v->ex[k];
    normalize(L);
}

/* The normal of the facet's plane, on the side of the surface's normals
** at its corners (the corners' order says nothing of the side). */
static void
facet_normal(const cf_facet_t *f, double n[3])
{
    double a[3], b[3], m[3];
    for (int k = 0; k < 3; k++) {
        a[k] = f->p[3 + k] - f->p[k];
        b[k] = f->p[6 + k] - f->p[k];
        m[k] = f->normal[k] + f->normal[3 + k] + f->normal[6 + k];
    }
    n[0] = a[1] * b[2] - a[2] * b[1];
    n[1] = a[2] * b[0] - a[0] * b[2];
    n[2] = a[0] * b[1] - a[1] * b[0];
    if (n[0] * m[0] + n[1] * m[1] + n[2] * m[2] < 0)
        for (int k = 0; k < 3; k++)
            n[k] = -n[k];
}

static cf_color_t
lit(const cf_color_t *c, double f)
{
    cf_color_t o = *c;
    o.r = fmin(1.0, c->r * f);
    o.g = fmin(1.0, c->g * f);
    o.b = fmin(1.0, c->b * f);
    return o;
}

/* One flat triangle of page points q[6] in colour c. */
static void
paint_triangle(cf__dl_t *dl, const double *q, cf_color_t c, double opacity)
{
    unsigned char segs[4];
    double coords[6];
    cf__path_t path;
    cf__paint_t paint;
    if (!cf__flat_triangle(q, c, opacity, segs, coords, &path, &paint))
        return;
    cf__dl_path_begin(dl);
    cf__dl_move(dl, coords[0], coords[1]);
    cf__dl_line(dl, coords[2], coords[3]);
    cf__dl_line(dl, coords[4], coords[5]);
    cf__dl_close(dl);
    cf__dl_path_paint(dl, &paint);
}

/* The colour of a point of the facet with normal n (any length). */
static cf_color_t
shade_at(const cf_surface_shading_t *sh, bool front, const double *n,
         const double L[3])
{
    double m[3] = { n[0], n[1], n[2] };
    normalize(m);
    return lit(front ? &sh->front : &sh->back,
               0.35 + 0.65 * fabs(m[0] * L[0] + m[1] * L[1] + m[2] * L[2]));
}

/* Smooth: a triangle of a mesh gradient, the colour of the surface's
** normal at each corner; where the format has no mesh gradients it is
** cut into four at its edges' midpoints, each piece in the colour of the
** normal interpolated at its centroid, so the colour follows the
** surface's normals within a facet as well.  A translucent surface is
** drawn as those pieces in every format: in a mesh gradient a later
** patch paints over an earlier one instead of through it. */
static void
paint_smooth(cf__dl_t *dl, const cf__layout_t *l, const cf_facet_t *f,
             const cf_surface_shading_t *sh, const double L[3])
{
    /* barycentric centroids of the four pieces: corner pieces
    ** (4, 1, 1)/6 and the middle one (1, 1, 1)/3 */
    static const double w[4][3] = {
        { 4.0 / 6, 1.0 / 6, 1.0 / 6 }, { 1.0 / 6, 4.0 / 6, 1.0 / 6 },
        { 1.0 / 6, 1.0 / 6, 4.0 / 6 }, { 1.0 / 3, 1.0 / 3, 1.0 / 3 },
    };
    cf__mesh_tri_t t;
    const cf_color_t *base = f->front ? &sh->front : &sh->back;
    for (int c = 0; c < 3; c++) {
        cf__map(l, f->image[2 * c], f->image[2 * c + 1], &t.p[2 * c],
                &t.p[2 * c + 1]);
        t.corner[c] = shade_at(sh, f->front, f->normal + 3 * c, L);
    }
    for (int k = 0; k < 4; k++) {
        double n[3];
        for (int j = 0; j < 3; j++)
            n[j] = w[k][0] * f->normal[j] + w[k][1] * f->normal[3 + j]
                + w[k][2] * f->normal[6 + j];
        t.piece[k] = shade_at(sh, f->front, n, L);
    }
    if (sh->opacity >= 1.0 && base->a >= 1.0) {
        cf__dl_mesh_tri(dl, &t);
        return;
    }
    for (int k = 0; k < 4; k++) {
        double q[6];
        cf__mesh_piece(&t, k, q);
        paint_triangle(dl, q, t.piece[k], sh->opacity);
    }
}

cf_status_t
cf__shade_facets(cf_figure_t *fig, const cf_scene_t *sc, double tol,
                 const cf_surface_shading_t *const *by_id, size_t nids,
                 const cf__layout_t *l, cf__dl_t *dl)
{
    cf_facets_t *fs = NULL;
    cf_status_t st = cf_scene_facets_tol(sc, tol, &fs, &fig->err);
    if (st != CF_STATUS_OK)
        return cf__fig_fail(fig, st, "shading");
    for (size_t i = 0; i < fs->n; i++) {
        const cf_facet_t *f = &fs->items[i];
        const cf_surface_shading_t *sh = f->surface < nids
            ? by_id[f->surface] : NULL;
        double n[3], L[3], q[6];
        if (sh == NULL || sh->shade == CF_SHADE_NONE)
            continue;
        light_of(fig, sh, L);
        if (sh->shade == CF_SHADE_SMOOTH) {
            paint_smooth(dl, l, f, sh, L);
            continue;
        }
        facet_normal(f, n);
        for (int c = 0; c < 3; c++)
            cf__map(l, f->image[2 * c], f->image[2 * c + 1], &q[2 * c],
                    &q[2 * c + 1]);
        paint_triangle(dl, q, shade_at(sh, f->front, n, L), sh->opacity);
    }
    cf_facets_destroy(fs);
    return CF_STATUS_OK;
}
