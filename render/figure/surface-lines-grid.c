/*
** The lines of a tensor-product (B-spline, NURBS, Bézier) surface in
** space (surface-lines.h): boundary, iso- and knot lines as the surface's
** exact iso-curves split into Bézier pieces, each with its (u, v) line,
** and the control net; the check for a degenerate patch.
*/
#include <math.h>
#include <string.h>

#include "grow.h"
#include "surface-lines.h"


cf_status_t
cf__lines3_add(cf_figure_t *fig, cf__lines3_t *l, int family,
               cf_bezier_t *bez, cf_bezier_t *uv)
{
    cf__line3_t *nl = cf__grow_array(l->items, &l->cap, l->n + 1,
                                     sizeof *nl, 16);
    if (nl == NULL) {
        cf_bezier_destroy(bez);
        cf_bezier_destroy(uv);
        return cf__fig_nomem(fig, "surface lines");
    }
    l->items = nl;
    l->items[l->n].family = family;
    l->items[l->n].bez = bez;
    l->items[l->n].uv = uv;
    l->n++;
    return CF_STATUS_OK;
}

void
cf__lines3_fini(cf__lines3_t *l)
{
    for (size_t i = 0; i < l->n; i++) {
        cf_bezier_destroy(l->items[i].bez);
        cf_bezier_destroy(l->items[i].uv);
    }
    cf_free(l->items);
    l->items = NULL;
    l->n = l->cap = 0;
}

/* The iso-line of direction dir at value: its Bézier pieces, each with
** its (u, v) line. */
static cf_status_t
add_iso(cf_figure_t *fig, const cf_bspline_surface_t *s, cf__lines3_t *out,
        int family, cf_dir_t dir, double value)
{
    cf_bspline_t *c = NULL;
    cf_bezier_list_t *list = NULL;
    cf_status_t st = cf_bspline_surface_iso(s, dir, value, &c, &fig->err);
    if (st == CF_STATUS_OK)
        st = cf_bspline_to_beziers(c, &list, &fig->err);
    cf_bspline_destroy(c);
    for (size_t i = 0; st == CF_STATUS_OK && i < list->count; i++) {
        double uv[4];
        cf_bezier_t *bez = NULL, *line = NULL;
        if (!(list->t1[i] > list->t0[i]))
            continue;
        /* CF_DIR_U fixes u: the curve runs in v */
        uv[0] = uv[2] = value;
        uv[1] = list->t0[i];
        uv[3] = list->t1[i];
        if (dir == CF_DIR_V) {
            uv[1] = uv[3] = value;
            uv[0] = list->t0[i];
            uv[2] = list->t1[i];
        }
        st = cf_bezier_copy(list->items[i], &bez, &fig->err);
        if (st == CF_STATUS_OK)
            st = cf_bezier_create(2, 1, uv, NULL, &line, &fig->err);
        if (st == CF_STATUS_OK)
            st = cf__lines3_add(fig, out, family, bez, line);
        else
            cf_bezier_destroy(bez);
    }
    cf_bezier_list_destroy(list);
    return st;
}

static cf_status_t
check_value(cf_figure_t *fig, cf_dir_t dir, double x, double a, double b)
{
    if (isfinite(x) && x >= a && x <= b)
        return CF_STATUS_OK;
    return cf_diag_set(&fig->err, CF_STATUS_DOMAIN, -1,
                       "isolines: %c = %g is outside the domain [%g, %g]",
                       dir == CF_DIR_U ? 'u' : 'v', x, a, b);
}

/* The iso-lines of one direction: n evenly spaced, the given values, the
** interior knots. */
static cf_status_t
add_isos(cf_figure_t *fig, const cf_bspline_surface_t *s,
         const cf_surface_lines_t *o, cf_dir_t dir, cf__lines3_t *out)
{
    double a, b;
    size_t n = dir == CF_DIR_U ? o->nu : o->nv;
    size_t nval = dir == CF_DIR_U ? o->u_count : o->v_count;
    const double *val = dir == CF_DIR_U ? o->u_values : o->v_values;
    cf_status_t st = CF_STATUS_OK;
    cf_bspline_surface_domain(s, dir, &a, &b);
    if (o->boundary) {
        st = add_iso(fig, s, out, CF__LINE_OUTLINE, dir, a);
        if (st == CF_STATUS_OK)
            st = add_iso(fig, s, out, CF__LINE_OUTLINE, dir, b);
    }
    for (size_t k = 1; st == CF_STATUS_OK && k <= n; k++)
        st = add_iso(fig, s, out, CF__LINE_ISO, dir, a + (b - a) * (double)k / (double)(n + 1));
    for (size_t k = 0; st == CF_STATUS_OK && k < nval; k++) {
        st = check_value(fig, dir, val[k], a, b);
        if (st == CF_STATUS_OK)
            st = add_iso(fig, s, out, CF__LINE_ISO, dir, val[k]);
    }
    if (st == CF_STATUS_OK && o->knot_lines) {
        size_t nk = 0, m = 0;
        const double *u = cf_bspline_surface_knots(s, dir, &m);
        double *ks = cf_alloc_array(m ? m : 1, sizeof *ks);
        (void)u;
        if (ks == NULL)
            return cf__fig_nomem(fig, "knot lines");
        st = cf_bspline_surface_knot_lines(s, dir, ks, &nk);
        for (size_t k = 0; st == CF_STATUS_OK && k < nk; k++)
            if (ks[k] > a && ks[k] < b)
                st = add_iso(fig, s, out, CF__LINE_ISO, dir, ks[k]);
        cf_free(ks);
    }
    return st;
}

/* The net of a tensor-product surface: a line between neighbours along
** each row and each column. */
static cf_status_t
add_net(cf_figure_t *fig, const cf_bspline_surface_t *s, const double *p,
        cf__lines3_t *out)
{
    size_t nu = cf_bspline_surface_count_u(s);
    size_t nv = cf_bspline_surface_count_v(s);
    cf_status_t st = CF_STATUS_OK;
    for (size_t i = 0; i < nu && st == CF_STATUS_OK; i++)
        for (size_t j = 0; j < nv && st == CF_STATUS_OK; j++) {
            for (int d = 0; d < 2 && st == CF_STATUS_OK; d++) {
                size_t i2 = i + (d == 0), j2 = j + (d == 1);
                double q[6];
                cf_bezier_t *bez = NULL;
                if (i2 >= nu || j2 >= nv)
                    continue;
                memcpy(q, p + 3 * (i * nv + j), 3 * sizeof *q);
                memcpy(q + 3, p + 3 * (i2 * nv + j2), 3 * sizeof *q);
                st = cf_bezier_create(3, 1, q, NULL, &bez, &fig->err);
                if (st == CF_STATUS_OK)
                    st = cf__lines3_add(fig, out, CF__LINE_NET, bez, NULL);
            }
        }
    return st;
}

/* A patch whose control points lie on one line (or in one point) has no
** normal anywhere: refused, naming the size.  Measured on the points
** divided by their largest coordinate, so that neither the squares of
** coordinates near 1e300 (infinite) nor of ones near 1e-300 (zero) pass
** for a line or a point. */
cf_status_t
cf__check_degenerate(cf_figure_t *fig, const double *p, size_t n)
{
    double size = 0, off = 0, big = 0;
    size_t a = 0, b = 0;
    for (size_t i = 0; i < 3 * n; i++)
        big = fmax(big, fabs(p[i]));
#define Q(i, k) (p[3 * (i) + (k)] / big)
    /* the two points farthest apart from point 0, then the farthest from
    ** their line */
    for (size_t i = 0; big > 0 && i < n; i++) {
        double d = 0;
        for (int k = 0; k < 3; k++)
            d += (Q(i, k) - Q(0, k)) * (Q(i, k) - Q(0, k));
        if (d > size) {
            size = d;
            b = i;
        }
    }
    size = sqrt(size);
    for (size_t i = 0; size > 0 && i < n; i++) {
        double u[3], w[3], c[3], l = 0, m = 0;
        for (int k = 0; k < 3; k++) {
            u[k] = Q(b, k) - Q(a, k);
            w[k] = Q(i, k) - Q(a, k);
        }
        c[0] = u[1] * w[2] - u[2] * w[1];
        c[1] = u[2] * w[0] - u[0] * w[2];
        c[2] = u[0] * w[1] - u[1] * w[0];
        for (int k = 0; k < 3; k++) {
            l += c[k] * c[k];
            m += u[k] * u[k];
        }
        off = fmax(off, sqrt(l / m));
    }
#undef Q
    if (size == 0 || off <= 1e-9 * size)
        return cf_diag_set(&fig->err, CF_STATUS_DEGENERATE, -1,
                           "degenerate patch: its %zu control "
                           "points lie %s, so it has no normal (give points "
                           "that span a surface)", n,
                           size == 0 ? "in one point" : "on one line");
    return CF_STATUS_OK;
}

cf_status_t
cf__bspline_lines(cf_figure_t *fig, const cf_bspline_surface_t *s,
                  const double *cpts, const cf_surface_lines_t *o,
                  cf__lines3_t *out)
{
    cf_status_t st = add_isos(fig, s, o, CF_DIR_U, out);
    if (st == CF_STATUS_OK)
        st = add_isos(fig, s, o, CF_DIR_V, out);
    if (st == CF_STATUS_OK && o->net)
        st = add_net(fig, s, cpts, out);
    return st;
}
