/* Scenes: a view, a tolerance and surfaces as Bézier patches
** (curvefig/visibility.h). */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "numtext-private.h"
#include "vis-private.h"

cf_status_t
cf_scene_create(const cf_view_t *view, double tol, cf_scene_t **out,
                cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_scene_t *sc;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    if (view == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "view is NULL");
    if (!isfinite(view->dir[0]) || !isfinite(view->dir[1]) ||
        !isfinite(view->dir[2]) ||
        fabs(view->dir[0] * view->dir[0] + view->dir[1] * view->dir[1] +
             view->dir[2] * view->dir[2] - 1.0) > 1e-9 ||
        (view->projection == CF_PROJECTION_PERSPECTIVE &&
         !(view->distance > 0.0 && isfinite(view->distance))))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "view was not made by cf_view_orthographic or "
                         "cf_view_perspective");
    if (isnan(tol) || isinf(tol))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "tolerance %s is not finite", CF__NUM(tol));
    if (!(tol > 0.0))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "tolerance %s must be positive and finite",
                         CF__NUM(tol));
    sc = cf__calloc(1, sizeof *sc);
    if (sc == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    sc->view = *view;
    cf__view_matrix(view, sc->M);
    sc->tol = tol;
    sc->surf_first = cf__calloc(1, sizeof(size_t));
    if (sc->surf_first == NULL) {
        cf_scene_destroy(sc);
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    }
    *out = sc;
    return CF_STATUS_OK;
}

void
cf_scene_destroy(cf_scene_t *sc)
{
    if (sc == NULL)
        return;
    for (size_t i = 0; i < sc->npatch; i++) {
        cf__free(sc->patches[i].h);
    }
    cf__free(sc->patches);
    cf__free(sc->surf_first);
    cf__free(sc->surf_tri);
    cf__free(sc->leaves);
    cf__free(sc->nodes);
    cf__free(sc);
}

size_t
cf_scene_count(const cf_scene_t *sc)
{
    return sc == NULL ? 0 : sc->nsurf;
}

const cf_view_t *
cf_scene_view(const cf_scene_t *sc)
{
    return sc == NULL ? NULL : &sc->view;
}

double
cf_scene_tolerance(const cf_scene_t *sc)
{
    return sc == NULL ? 0.0 : sc->tol;
}

/* One patch from a homogeneous (rational) or Cartesian grid in R^3. */
static cf_status_t
add_patch(cf_scene_t *sc, bool tri, int m, int n, const double *src,
          bool rational, const double *range, const char *where,
          cf_diag_t *diag)
{
    cf__vpatch_t *p;
    size_t cnt, id = sc->nsurf;
    double far = 0.0, lo[3], hi[3];
    p = cf__grow(sc->patches, &sc->npatch_cap, sc->npatch + 1, sizeof *p, 16);
    if (p == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    sc->patches = p;
    p = &sc->patches[sc->npatch];
    memset(p, 0, sizeof *p);
    p->surface = id;
    p->tri = tri;
    p->m = m;
    p->n = n;
    p->u0 = range[0];
    p->u1 = range[1];
    p->v0 = range[2];
    p->v1 = range[3];
    cnt = cf__vpatch_count(p);
    p->h = cf__alloc_array(cnt, 8 * sizeof(double));
    if (p->h == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    p->g = p->h + 4 * cnt;
    for (int c = 0; c < 3; c++) {
        lo[c] = HUGE_VAL;
        hi[c] = -HUGE_VAL;
    }
    for (size_t i = 0; i < cnt; i++) {
        const double *s = src + i * (rational ? 4 : 3);
        double *h = p->h + 4 * i, *g = p->g + 4 * i;
        double w = rational ? s[3] : 1.0;
        for (int c = 0; c < 3; c++) {
            h[c] = s[c];
            lo[c] = fmin(lo[c], s[c] / w);
            hi[c] = fmax(hi[c], s[c] / w);
            far = fmax(far, fabs(s[c] / w));
        }
        h[3] = w;
        for (int r = 0; r < 4; r++)
            g[r] = sc->M[4 * r] * h[0] + sc->M[4 * r + 1] * h[1] +
                   sc->M[4 * r + 2] * h[2] + sc->M[4 * r + 3] * h[3];
        if (!(g[3] > 1e-3 * w)) {
            cf__free(p->h);
            return cf__error(diag, CF_STATUS_DOMAIN, (long)i,
                             "surface %zu: %s: control point %zu is not in "
                             "front of the eye (distance %s)", id, where, i,
                             CF__NUM(sc->view.distance));
        }
    }
    if (fmax(hi[0] - lo[0], fmax(hi[1] - lo[1], hi[2] - lo[2])) <=
        1e-12 * fmax(far, DBL_MIN)) {
        cf__free(p->h);
        return cf__error(diag, CF_STATUS_DEGENERATE, -1,
                         "surface %zu: %s is degenerate: all its points "
                         "coincide", id, where);
    }
    for (int c = 0; c < 3; c++) {
        if (sc->npatch == 0 || lo[c] < sc->lo[c])
            sc->lo[c] = lo[c];
        if (sc->npatch == 0 || hi[c] > sc->hi[c])
            sc->hi[c] = hi[c];
    }
    sc->npatch++;
    return CF_STATUS_OK;
}

/* Undo the patches and leaves of a surface that failed. */
static void
rollback(cf_scene_t *sc, size_t npatch, size_t nleaf, const double *box)
{
    while (sc->npatch > npatch)
        cf__free(sc->patches[--sc->npatch].h);
    sc->nleaf = nleaf;
    memcpy(sc->lo, box, 3 * sizeof(double));
    memcpy(sc->hi, box + 3, 3 * sizeof(double));
}

/* After the patches of a new surface: the size and tolerance check, the
** leaves, the tree, the surface's entry. */
static cf_status_t
finish(cf_scene_t *sc, size_t npatch, size_t nleaf, const double *box,
       bool tri, size_t *id, cf_diag_t *diag)
{
    cf_status_t st = CF_STATUS_OK;
    size_t *first;
    bool *ftri;
    double dx = sc->hi[0] - sc->lo[0], dy = sc->hi[1] - sc->lo[1],
           dz = sc->hi[2] - sc->lo[2];
    double size = sqrt(dx * dx + dy * dy + dz * dz);
    /* the hidden lines' arithmetic squares lengths of the scene's size */
    if (!isfinite(size)) {
        rollback(sc, npatch, nleaf, box);
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "the scene spans %s x %s x %s, too large for its "
                         "hidden lines (the diagonal of its box must be "
                         "finite: coordinates within about 1e150)",
                         CF__NUM(dx), CF__NUM(dy), CF__NUM(dz));
    }
    if (sc->tol < 1e-12 * size) {
        rollback(sc, npatch, nleaf, box);
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "tolerance %s is below 1e-12 of the scene's size "
                         "%.3g", CF__NUM(sc->tol), size);
    }
    first = cf__realloc_array(sc->surf_first, sc->nsurf + 2, sizeof *first);
    if (first == NULL) {
        rollback(sc, npatch, nleaf, box);
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    }
    sc->surf_first = first;
    ftri = cf__realloc_array(sc->surf_tri, sc->nsurf + 1, sizeof *ftri);
    if (ftri == NULL) {
        rollback(sc, npatch, nleaf, box);
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    }
    sc->surf_tri = ftri;
    for (size_t i = npatch; i < sc->npatch && st == CF_STATUS_OK; i++)
        st = cf__scene_leaves(sc, i);
    if (st == CF_STATUS_OK)
        st = cf__scene_tree(sc);
    if (st != CF_STATUS_OK) {
        rollback(sc, npatch, nleaf, box);
        if (cf__scene_tree(sc) != CF_STATUS_OK)
            sc->nnode = 0;
        return cf__error(diag, st, -1, "out of memory");
    }
    sc->size = size;
    sc->surf_tri[sc->nsurf] = tri;
    sc->surf_first[sc->nsurf + 1] = sc->npatch;
    if (id != NULL)
        *id = sc->nsurf;
    sc->nsurf++;
    return CF_STATUS_OK;
}

static cf_status_t
check_scene(cf_scene_t *sc, const void *s, size_t dim, cf_diag_t *diag)
{
    if (sc == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "scene is NULL");
    if (s == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "surface is NULL");
    if (dim != 3)
        return cf__error(diag, CF_STATUS_DIM_MISMATCH, -1,
                         "surface %zu is in R^%zu; a scene holds surfaces "
                         "in R^3", sc->nsurf, dim);
    return CF_STATUS_OK;
}

static cf_status_t
check_degrees(const cf_scene_t *sc, int m, int n, int max, cf_diag_t *diag)
{
    if (m > max || n > max)
        return cf__error(diag, CF_STATUS_BAD_DEGREE, -1,
                         "surface %zu: degree %d above %d, the largest a "
                         "scene takes", sc->nsurf, m > n ? m : n, max);
    if (m < 1 || n < 1)
        return cf__error(diag, CF_STATUS_DEGENERATE, -1,
                         "surface %zu: degree 0 in %s: a curve, not a "
                         "surface", sc->nsurf, m < 1 ? "u" : "v");
    return CF_STATUS_OK;
}

cf_status_t
cf_scene_add_bezier(cf_scene_t *sc, const cf_bezier_surface_t *s, size_t *id,
                    cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st;
    double box[6], range[4] = {0.0, 1.0, 0.0, 1.0};
    size_t np, nl;
    if ((st = check_scene(sc, s, cf_bezier_surface_dim(s), diag)) != 0)
        return st;
    int m = cf_bezier_surface_degree_u(s), n = cf_bezier_surface_degree_v(s);
    if ((st = check_degrees(sc, m, n, CF__VIS_MAX_DEG, diag)) != 0)
        return st;
    np = sc->npatch;
    nl = sc->nleaf;
    memcpy(box, sc->lo, 3 * sizeof(double));
    memcpy(box + 3, sc->hi, 3 * sizeof(double));
    st = add_patch(sc, false, m, n, cf_bezier_surface_hpoints(s),
                   cf_bezier_surface_is_rational(s), range, "the patch",
                   diag);
    if (st != CF_STATUS_OK)
        return st;
    return finish(sc, np, nl, box, false, id, diag);
}

cf_status_t
cf_scene_add_bspline(cf_scene_t *sc, const cf_bspline_surface_t *s,
                     size_t *id, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st;
    cf_bezier_surface_list_t *list = NULL;
    double box[6];
    size_t np, nl;
    if ((st = check_scene(sc, s, cf_bspline_surface_dim(s), diag)) != 0)
        return st;
    if ((st = check_degrees(sc, cf_bspline_surface_degree_u(s),
                            cf_bspline_surface_degree_v(s), CF__VIS_MAX_DEG,
                            diag)) != 0)
        return st;
    if ((st = cf_bspline_surface_to_beziers(s, &list, diag)) != 0)
        return st;
    np = sc->npatch;
    nl = sc->nleaf;
    memcpy(box, sc->lo, 3 * sizeof(double));
    memcpy(box + 3, sc->hi, 3 * sizeof(double));
    for (size_t i = 0; i < list->nu && st == CF_STATUS_OK; i++)
        for (size_t j = 0; j < list->nv && st == CF_STATUS_OK; j++) {
            const cf_bezier_surface_t *b = list->items[i * list->nv + j];
            double range[4] = {list->u0[i], list->u1[i], list->v0[j],
                               list->v1[j]};
            char where[64];
            snprintf(where, sizeof where, "patch (%zu, %zu)", i, j);
            st = add_patch(sc, false, cf_bezier_surface_degree_u(b),
                           cf_bezier_surface_degree_v(b),
                           cf_bezier_surface_hpoints(b),
                           cf_bezier_surface_is_rational(b), range, where,
                           diag);
        }
    cf_bezier_surface_list_destroy(list);
    if (st != CF_STATUS_OK) {
        rollback(sc, np, nl, box);
        return st;
    }
    return finish(sc, np, nl, box, false, id, diag);
}

cf_status_t
cf_scene_add_triangle(cf_scene_t *sc, const cf_bezier_triangle_t *t,
                      size_t *id, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st;
    double box[6], range[4] = {0.0, 1.0, 0.0, 1.0}, *buf;
    size_t np, nl, cnt;
    int n;
    if ((st = check_scene(sc, t, cf_bezier_triangle_dim(t), diag)) != 0)
        return st;
    n = cf_bezier_triangle_degree(t);
    if ((st = check_degrees(sc, n, n, CF__VIS_TRI_MAX_DEG, diag)) != 0)
        return st;
    cnt = cf_bezier_triangle_count(t);
    buf = cf__alloc_array(cnt, 5 * sizeof(double));
    if (buf == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    /* Cartesian points then weights, made homogeneous in place */
    cf_bezier_triangle_get_points(t, buf + cnt);
    cf_bezier_triangle_get_weights(t, buf + 4 * cnt);
    for (size_t i = 0; i < cnt; i++) {
        double w = buf[4 * cnt + i];
        for (int c = 0; c < 3; c++)
            buf[4 * i + c] = buf[cnt + 3 * i + c] * w;
        buf[4 * i + 3] = w;
    }
    np = sc->npatch;
    nl = sc->nleaf;
    memcpy(box, sc->lo, 3 * sizeof(double));
    memcpy(box + 3, sc->hi, 3 * sizeof(double));
    st = add_patch(sc, true, n, n, buf, true, range, "the triangle", diag);
    cf__free(buf);
    if (st != CF_STATUS_OK)
        return st;
    return finish(sc, np, nl, box, true, id, diag);
}
