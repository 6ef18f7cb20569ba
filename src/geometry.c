/*
** Planar convex hull (Andrew's monotone chain).
*/
#include <math.h>
#include <stdlib.h>

#include "curvefig/geometry.h"
#include "bezier-private.h"

typedef struct hpt {
    double x, y;
    size_t i;
} hpt;

static int
cmp_hpt(const void *pa, const void *pb)
{
    const hpt *a = pa, *b = pb;
    if (a->x != b->x)
        return a->x < b->x ? -1 : 1;
    if (a->y != b->y)
        return a->y < b->y ? -1 : 1;
    return (a->i > b->i) - (a->i < b->i);
}

/* (b - a) x (c - a): > 0 when a, b, c turn left */
static double
cross(const hpt *a, const hpt *b, const hpt *c)
{
    return (b->x - a->x) * (c->y - a->y) - (b->y - a->y) * (c->x - a->x);
}

cf_status_t
cf_convex_hull_2d(const double *pts, size_t count, size_t stride, size_t *idx,
                  size_t *hull_count, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    hpt *p, **h;
    size_t m = 0, k = 0;
    cf_status_t st;

    if (pts == NULL || idx == NULL || hull_count == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "an array or the count pointer is NULL");
    *hull_count = 0;
    if (count < 1)
        return cf__error(diag, CF_STATUS_TOO_FEW_POINTS, -1,
                         "the convex hull needs at least one point");
    if (stride < 2)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "stride %zu is smaller than 2", stride);
    st = cf__check_finite_points(pts, count, 2, stride, "point", diag);
    if (st != CF_STATUS_OK)
        return st;
    p = cf__alloc_array(count, sizeof *p);
    h = cf__alloc_array(2 * count + 1, sizeof *h);
    if (p == NULL || h == NULL) {
        cf__free(p);
        cf__free(h);
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory (convex hull of %zu points)", count);
    }
    for (size_t i = 0; i < count; i++) {
        p[i].x = pts[i * stride];
        p[i].y = pts[i * stride + 1];
        p[i].i = i;
    }
    qsort(p, count, sizeof *p, cmp_hpt);
    /* drop repeated points (the sort put the smallest index first) */
    for (size_t i = 0; i < count; i++)
        if (m == 0 || p[i].x != p[m - 1].x || p[i].y != p[m - 1].y)
            p[m++] = p[i];
    if (m == 1) {
        idx[0] = p[0].i;
        *hull_count = 1;
        goto done;
    }
    /* lower hull left to right, then upper hull right to left; a
    ** non-left turn (collinear included) removes the middle point */
    for (size_t i = 0; i < m; i++) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], &p[i]) <= 0.0)
            k--;
        h[k++] = &p[i];
    }
    for (size_t i = m - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && cross(h[k - 2], h[k - 1], &p[i]) <= 0.0)
            k--;
        h[k++] = &p[i];
    }
    k--;   /* the first point closes the chain */
    for (size_t i = 0; i < k; i++)
        idx[i] = h[i]->i;
    *hull_count = k;
done:
    cf__free(p);
    cf__free(h);
    return CF_STATUS_OK;
}

cf_status_t
cf_bezier_hull(const cf_bezier_t *c, size_t *idx, size_t *hull_count,
               cf_diag_t *diag)
{
    cf_diag_clear(diag);
    double *pts;
    cf_status_t st;
    if (c == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "the curve is NULL");
    if (c->dim != 2)
        return cf__error(diag, CF_STATUS_DIM_MISMATCH, -1,
                         "the convex hull needs a planar curve, not R^%zu",
                         c->dim);
    pts = cf__alloc_array(((size_t)c->degree + 1) * 2, sizeof *pts);
    if (pts == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory (convex hull)");
    cf_bezier_get_points(c, pts);
    st = cf_convex_hull_2d(pts, (size_t)c->degree + 1, 2, idx, hull_count,
                           diag);
    cf__free(pts);
    return st;
}

cf_status_t
cf_check_finite_points(const double *pts, size_t count, size_t dim,
                       size_t stride, const char *what, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    if (count > 0 && (pts == NULL || dim == 0 || stride < dim))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "check of %s coordinates: no array, dim 0 or "
                         "stride %zu < dim %zu",
                         what != NULL ? what : "point", stride, dim);
    return cf__check_finite_points(pts, count, dim, stride,
                                   what != NULL ? what : "point", diag);
}
