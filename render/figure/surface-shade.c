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

/* The facet's normal for the shading: the flat one (of its corners'
** plane) or the mean of the corners' (smooth), oriented as the surface's
** normal side. */
static void
facet_normal(const cf_facet_t *f, cf_shade_t shade, double n[3])
{
    if (shade == CF_SHADE_SMOOTH) {
        for (int k = 0; k < 3; k++)
            n[k] = f->normal[k] + f->normal[3 + k] + f->normal[6 + k];
    } else {
        double a[3], b[3], m[3];
        for (int k = 0; k < 3; k++) {
            a[k] = f->p[3 + k] - f->p[k];
            b[k] = f->p[6 + k] - f->p[k];
            m[k] = f->normal[k] + f->normal[3 + k] + f->normal[6 + k];
        }
        n[0] = a[1] * b[2] - a[2] * b[1];
        n[1] = a[2] * b[0] - a[0] * b[2];
        n[2] = a[0] * b[1] - a[1] * b[0];
        /* the corners' order says nothing of the side: take the normals' */
        if (n[0] * m[0] + n[1] * m[1] + n[2] * m[2] < 0)
            for (int k = 0; k < 3; k++)
                n[k] = -n[k];
    }
    normalize(n);
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

cf_status_t
cf__shade_facets(cf_figure_t *fig, const cf_scene_t *sc,
                 const cf_surface_shading_t *const *by_id, size_t nids,
                 const cf__layout_t *l, cf__dl_t *dl)
{
    cf_facets_t *fs = NULL;
    cf_status_t st = cf_scene_facets(sc, &fs, &fig->err);
    if (st != CF_STATUS_OK)
        return cf__fig_fail(fig, st, "shading");
    for (size_t i = 0; i < fs->n; i++) {
        const cf_facet_t *f = &fs->items[i];
        const cf_surface_shading_t *sh = f->surface < nids
            ? by_id[f->surface] : NULL;
        double n[3], L[3], x, y, dot;
        cf__paint_t paint;
        if (sh == NULL || sh->shade == CF_SHADE_NONE)
            continue;
        facet_normal(f, sh->shade, n);
        light_of(fig, sh, L);
        dot = fabs(n[0] * L[0] + n[1] * L[1] + n[2] * L[2]);
        memset(&paint, 0, sizeof paint);
        paint.fill = true;
        paint.fill_color = lit(f->front ? &sh->front : &sh->back,
                               0.35 + 0.65 * dot);
        paint.fill_opacity = sh->opacity;
        if (sh->opacity >= 1.0) {
            /* a hairline of the same colour closes the seams that
            ** anti-aliasing leaves between neighbours */
            paint.stroke = true;
            paint.line.color = paint.fill_color;
            paint.line.opacity = 1.0;
            paint.line.width = 0.25;
            paint.line.join = CF__JOIN_ROUND;
            paint.line.cap = CF__CAP_ROUND;
        }
        cf__dl_path_begin(dl);
        for (int c = 0; c < 3; c++) {
            cf__map(l, f->image[2 * c], f->image[2 * c + 1], &x, &y);
            if (c == 0)
                cf__dl_move(dl, x, y);
            else
                cf__dl_line(dl, x, y);
        }
        cf__dl_close(dl);
        cf__dl_path_paint(dl, &paint);
    }
    cf_facets_destroy(fs);
    return CF_STATUS_OK;
}
