/*
** The figure's scene of occluding surfaces (curvefig/visibility.h), for
** every element that asks what is hidden: surfaces' own lines, curves and
** polylines in space, points and labels at points in space.  It knows no
** element kind: an element is in it through its kind's occludes and
** occlude (model.h; the surfaces', el-surface.c), so the kinds that look
** into the scene never call the surfaces' file.
*/
#include <stdint.h>

#include "surface-lines.h"

/* A new scene of the figure's occluding surfaces for tolerance tol (data
** units), each element's number in it set; NULL (no error) when there is
** none. */
static cf_status_t
build_scene(cf_figure_t *fig, double tol, cf_scene_t **out)
{
    cf_scene_t *sc = NULL;
    cf_status_t st;
    bool any = false;
    *out = NULL;
    for (size_t i = 0; i < fig->count; i++) {
        const cf__element_t *e = fig->els[i];
        any = any || (e->kind->occludes != NULL && e->kind->occludes(e));
    }
    if (!any)
        return CF_STATUS_OK;
    st = cf_scene_create(&fig->view, tol, &sc, &fig->err);
    for (size_t i = 0; st == CF_STATUS_OK && i < fig->count; i++) {
        cf__element_t *e = fig->els[i];
        if (e->kind->occlude != NULL)
            st = e->kind->occlude(e, sc, &fig->err);
    }
    if (st != CF_STATUS_OK) {
        cf_scene_destroy(sc);
        return cf__fig_fail(fig, st, "surface scene");
    }
    *out = sc;
    return CF_STATUS_OK;
}

/* The figure's scene for visibility at tolerance tol, kept in the figure
** for that tolerance (and, in a draft, slightly smaller ones) and element
** count. */
cf_status_t
cf__figure_scene(cf_figure_t *fig, double tol, cf_scene_t **out)
{
    cf_status_t st;
    if (fig->scene != NULL && fig->scene_els == fig->count
        && cf__tol_serves(fig, fig->scene_tol, tol)) {
        *out = fig->scene;
        return CF_STATUS_OK;
    }
    cf_scene_destroy(fig->scene);
    fig->scene = NULL;
    tol = cf__tol_make(fig, tol);
    st = build_scene(fig, tol, out);
    if (st == CF_STATUS_OK && *out != NULL) {
        fig->scene = *out;
        fig->scene_tol = tol;
        fig->scene_els = fig->count;
    }
    return st;
}
