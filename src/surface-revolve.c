/* Surfaces of revolution and the exact NURBS sphere, cylinder, cone and
** torus (curvefig/surface-make.h). */
#include <math.h>
#include <string.h>

#include "surface-private.h"
#include "curvefig/surface-make.h"
#include "numtext-private.h"

cf_status_t
cf_surface_revolve(const cf_bspline_t *curve, const double *O,
                   const double *A, double a0, double a1,
                   cf_bspline_surface_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    static const double o2[2] = { 0, 0 }, x2[2] = { 1, 0 }, y2[2] = { 0, 1 };
    cf_bspline_t *arc = NULL;
    double len, a[3], *grid;
    const double *ah, *ch;
    size_t na, nc, ch_h;
    cf_status_t st;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    if (curve == NULL || O == NULL || A == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "curve, axis point or axis direction is NULL");
    if (cf_bspline_dim(curve) != 3)
        return cf__error(diag, CF_STATUS_DIM_MISMATCH, -1,
                         "the curve has dimension %zu; it must be "
                         "3", cf_bspline_dim(curve));
    st = cf__check_finite_points(O, 1, 3, 3, "axis point", diag);
    if (st == CF_STATUS_OK)
        st = cf__check_finite_points(A, 1, 3, 3, "axis direction", diag);
    if (st != CF_STATUS_OK)
        return st;
    len = sqrt(A[0] * A[0] + A[1] * A[1] + A[2] * A[2]);
    if (!(len > 0.0))
        return cf__error(diag, CF_STATUS_DEGENERATE, -1,
                         "the axis direction is zero");
    for (int k = 0; k < 3; k++)
        a[k] = A[k] / len;
    st = cf_nurbs_arc(2, o2, x2, y2, 1.0, a0, a1, &arc, diag);
    if (st != CF_STATUS_OK)
        return st;
    na = cf_bspline_count(arc);
    nc = cf_bspline_count(curve);
    ah = cf_bspline_hpoints(arc);
    ch = cf_bspline_hpoints(curve);
    ch_h = 3 + cf_bspline_is_rational(curve);
    grid = cf__alloc_array(na * nc, 4 * sizeof *grid);
    if (grid == NULL) {
        cf_bspline_destroy(arc);
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    }
    for (size_t j = 0; j < nc; j++) {
        double w = ch_h == 4 ? ch[j * 4 + 3] : 1.0, P[3], Oj[3], X[3], Y[3];
        double t = 0.0;
        for (int k = 0; k < 3; k++)
            P[k] = ch[j * ch_h + (size_t)k] / w;
        for (int k = 0; k < 3; k++)
            t += (P[k] - O[k]) * a[k];
        for (int k = 0; k < 3; k++) {
            Oj[k] = O[k] + t * a[k];
            X[k] = P[k] - Oj[k];
        }
        /* Y = a x X: X turned a quarter about the axis, |Y| = |X| */
        Y[0] = a[1] * X[2] - a[2] * X[1];
        Y[1] = a[2] * X[0] - a[0] * X[2];
        Y[2] = a[0] * X[1] - a[1] * X[0];
        for (size_t i = 0; i < na; i++) {
            double aw = ah[i * 3 + 2], c = ah[i * 3] / aw, s = ah[i * 3 + 1]
                                                             / aw;
            double *g = grid + (i * nc + j) * 4;
            for (int k = 0; k < 3; k++)
                g[k] = aw * w * (Oj[k] + c * X[k] + s * Y[k]);
            g[3] = aw * w;
        }
    }
    st = cf_bspline_surface_create_homogeneous(
        3, cf_bspline_degree(arc), cf_bspline_degree(curve),
        cf_bspline_knots(arc), cf_bspline_nknots(arc), cf_bspline_knots(curve),
        cf_bspline_nknots(curve), grid, na, nc, out, diag);
    cf__free(grid);
    cf_bspline_destroy(arc);
    return st;
}

/* Revolve the generatrix about the z axis through centre, full turn. */
static cf_status_t
about_z(const double *centre, cf_bspline_t *gen, cf_status_t st,
        cf_bspline_surface_t **out, cf_diag_t *diag)
{
    static const double z[3] = { 0, 0, 1 };
    if (st == CF_STATUS_OK)
        st = cf_surface_revolve(gen, centre, z, 0.0, 2.0 * CF__PI, out,
                                diag);
    cf_bspline_destroy(gen);
    return st;
}

static cf_status_t
check(const double *centre, double r, double h, cf_bspline_surface_t **out,
      cf_diag_t *diag)
{
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    if (centre == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "centre is NULL");
    if (!(r > 0.0) || !isfinite(r) || !(h > 0.0) || !isfinite(h))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "radius %s and height %s must be finite and "
                         "positive", CF__NUM(r), CF__NUM(h));
    return cf__check_finite_points(centre, 1, 3, 3, "centre", diag);
}

/* A segment from a to b as a degree-1 curve. */
static cf_status_t
segment(const double *a, const double *b, cf_bspline_t **out,
        cf_diag_t *diag)
{
    static const double K[4] = { 0, 0, 1, 1 };
    double P[6];
    memcpy(P, a, 3 * sizeof *P);
    memcpy(P + 3, b, 3 * sizeof *P);
    return cf_bspline_create(3, 1, K, 4, P, 2, NULL, out, diag);
}

cf_status_t
cf_nurbs_sphere(const double *centre, double r, cf_bspline_surface_t **out,
                cf_diag_t *diag)
{
    cf_diag_clear(diag);
    static const double X[3] = { 1, 0, 0 }, Y[3] = { 0, 0, 1 };
    cf_bspline_t *g = NULL;
    cf_status_t st;
    st = check(centre, r, 1.0, out, diag);
    if (st != CF_STATUS_OK)
        return st;
    st = cf_nurbs_arc(3, centre, X, Y, r, -CF__PI / 2, CF__PI / 2, &g, diag);
    return about_z(centre, g, st, out, diag);
}

cf_status_t
cf_nurbs_torus(const double *centre, double R, double r,
               cf_bspline_surface_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    static const double X[3] = { 1, 0, 0 }, Y[3] = { 0, 0, 1 };
    double c[3];
    cf_bspline_t *g = NULL;
    cf_status_t st;
    st = check(centre, r, R, out, diag);
    if (st == CF_STATUS_OK && !(R > r))
        st = cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                       "the radius %s of the centre circle must be "
                       "larger than the tube's %s", CF__NUM(R), CF__NUM(r));
    if (st != CF_STATUS_OK)
        return st;
    c[0] = centre[0] + R;
    c[1] = centre[1];
    c[2] = centre[2];
    st = cf_nurbs_arc(3, c, X, Y, r, 0.0, 2.0 * CF__PI, &g, diag);
    return about_z(centre, g, st, out, diag);
}

/* The segment from the rim point (c_x + r, c_y, c_z) to (c_x + r, c_y,
** c_z + h) (cylinder) or to the apex (c_x, c_y, c_z + h) (cone), turned
** about the z axis. */
static cf_status_t
lathe(const double *centre, double r, double h, bool cone,
      cf_bspline_surface_t **out, cf_diag_t *diag)
{
    double a[3], b[3];
    cf_bspline_t *g = NULL;
    cf_status_t st = check(centre, r, h, out, diag);
    if (st != CF_STATUS_OK)
        return st;
    a[0] = centre[0] + r;
    a[1] = b[1] = centre[1];
    a[2] = centre[2];
    b[0] = cone ? centre[0] : a[0];
    b[2] = centre[2] + h;
    st = segment(a, b, &g, diag);
    return about_z(centre, g, st, out, diag);
}

cf_status_t
cf_nurbs_cylinder(const double *centre, double r, double h,
                  cf_bspline_surface_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    return lathe(centre, r, h, false, out, diag);
}

cf_status_t
cf_nurbs_cone(const double *centre, double r, double h,
              cf_bspline_surface_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    return lathe(centre, r, h, true, out, diag);
}
