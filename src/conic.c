/*
** Conics as exact quadratic (rational) Bézier curves, and NURBS arcs and
** circles.
**
** A conic arc between P0 and P2 with end tangents meeting at P1 is the
** rational quadratic (P0, P1, P2; 1, w, 1).  On the unit circle, the piece
** from angle m - d to m + d has P1 = (cos m, sin m) / cos d and w = cos d;
** on the unit hyperbola (cosh s, sinh s) the piece from m - d to m + d has
** P1 = (cosh m, sinh m) / cosh d and w = cosh d.  Ellipses and general
** hyperbolas are affine images of these (rational curves are affinely
** invariant with unchanged weights).
*/
#include <math.h>

#include "curvefig/conic.h"
#include "bezier-private.h"
#include "bspline-private.h"
#include "numtext-private.h"

#define MAX_PIECES 100000

/* x -> C + R(rot) diag(sx, sy) x */
typedef struct affine {
    double cx, cy, m[4];
} affine;

static void
affine_init(affine *A, double cx, double cy, double sx, double sy,
            double rot)
{
    double c = cos(rot), s = sin(rot);
    A->cx = cx;
    A->cy = cy;
    A->m[0] = c * sx;
    A->m[1] = -s * sy;
    A->m[2] = s * sx;
    A->m[3] = c * sy;
    if (rot == 0.0) {
        A->m[1] = A->m[2] = 0.0;
        A->m[0] = sx;
        A->m[3] = sy;
    }
}

static cf_status_t
check_finite(const double *v, const char *const *names, int n,
             cf_diag_t *diag)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return cf__error(diag, CF_STATUS_NOT_FINITE, i,
                             "%s is %s; it must be finite", names[i],
                             CF__NUM(v[i]));
    return CF_STATUS_OK;
}

static cf_status_t
check_positive(double v, const char *name, cf_diag_t *diag)
{
    if (!(v > 0.0))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "%s is %s; it must be positive", name, CF__NUM(v));
    return CF_STATUS_OK;
}

/* Piece k of the list from local points L (P0, P1, P2 as x, y) and the
** middle weight w (polynomial when w == 1 and !force_rational). */
static cf_status_t
set_piece(cf_bezier_list_t *list, size_t k, const affine *A, const double *L,
          double w, bool rational, double t0, double t1, cf_diag_t *diag)
{
    cf_bezier_t *c = cf__bezier_new(2, 2, rational);
    size_t h = rational ? 3 : 2;
    if (c == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory (conic piece %zu)", k);
    list->items[k] = c;
    list->t0[k] = t0;
    list->t1[k] = t1;
    for (int i = 0; i < 3; i++) {
        double x = L[2 * i], y = L[2 * i + 1];
        double wi = i == 1 ? w : 1.0;
        double px = A->cx + A->m[0] * x + A->m[1] * y;
        double py = A->cy + A->m[2] * x + A->m[3] * y;
        c->pts[(size_t)i * h] = wi * px;
        c->pts[(size_t)i * h + 1] = wi * py;
        if (rational)
            c->pts[(size_t)i * h + 2] = wi;
    }
    return cf__check_finite_points(c->pts, 3, h, h, "conic control point",
                                   diag);
}

static cf_status_t
new_list(size_t count, cf_bezier_list_t **out, cf_diag_t *diag)
{
    *out = cf__bezier_list_new(count, true);
    if (*out == NULL)
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory (list of %zu conic pieces)", count);
    return CF_STATUS_OK;
}

static cf_status_t
finish(cf_status_t st, cf_bezier_list_t *list, cf_bezier_list_t **out)
{
    if (st != CF_STATUS_OK) {
        cf_bezier_list_destroy(list);
        *out = NULL;
        return st;
    }
    *out = list;
    return CF_STATUS_OK;
}

/* n pieces of the unit circle (cos, sin) or of the unit hyperbola
** (cosh, sinh) for the parameter from p0 to p1, mapped by A. */
static cf_status_t
unit_pieces(const affine *A, double p0, double p1, size_t n, bool hyperbolic,
            cf_bezier_list_t **out, cf_diag_t *diag)
{
    double span = p1 - p0, d = span / (2.0 * (double)n);
    double w = hyperbolic ? cosh(d) : cos(d);
    cf_bezier_list_t *list;
    cf_status_t st = new_list(n, &list, diag);
    if (st != CF_STATUS_OK)
        return st;
    for (size_t k = 0; k < n && st == CF_STATUS_OK; k++) {
        double t0 = p0 + span * (double)k / (double)n;
        double t1 = k + 1 == n ? p1
                               : p0 + span * (double)(k + 1) / (double)n;
        double m = t0 + d, L[6];
        if (hyperbolic) {
            L[0] = cosh(t0), L[1] = sinh(t0);
            L[2] = cosh(m) / w, L[3] = sinh(m) / w;
            L[4] = cosh(t1), L[5] = sinh(t1);
        } else {
            L[0] = cos(t0), L[1] = sin(t0);
            L[2] = cos(m) / w, L[3] = sin(m) / w;
            L[4] = cos(t1), L[5] = sin(t1);
        }
        st = set_piece(list, k, A, L, w, true, t0, t1, diag);
    }
    return finish(st, list, out);
}

/* Pieces of the unit circle from angle a0 to a1 (at most 90 degrees
** each), mapped by A. */
static cf_status_t
circle_pieces(const affine *A, double a0, double a1, cf_bezier_list_t **out,
              cf_diag_t *diag)
{
    double span = a1 - a0, q;
    size_t n;
    if (!isfinite(span) || span == 0.0)
        return cf__error(diag, CF_STATUS_DOMAIN, -1,
                         "the arc from %s to %s spans no angle",
                         CF__NUM(a0), CF__NUM(a1));
    q = fabs(span) / (CF__PI / 2);
    if (q > MAX_PIECES)
        return cf__error(diag, CF_STATUS_DOMAIN, -1,
                         "the arc from %s to %s makes too many turns",
                         CF__NUM(a0), CF__NUM(a1));
    /* a span a rounding above 90 degrees still makes one piece */
    n = (size_t)ceil(q * (1.0 - 1e-12));
    return unit_pieces(A, a0, a1, n < 1 ? 1 : n, false, out, diag);
}

/* The common start: out cleared, every value finite. */
static cf_status_t
begin(cf_bezier_list_t **out, const double *v, const char *const *names,
      int nv, cf_diag_t *diag)
{
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "the output pointer is NULL");
    *out = NULL;
    return check_finite(v, names, nv, diag);
}

cf_status_t
cf_conic_arc(double cx, double cy, double r, double a0, double a1,
             cf_bezier_list_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    static const char *const names[] = { "center x", "center y", "radius",
                                          "start angle", "end angle" };
    const double v[] = { cx, cy, r, a0, a1 };
    affine A;
    cf_status_t st;
    st = begin(out, v, names, 5, diag);
    if (st == CF_STATUS_OK)
        st = check_positive(r, "radius", diag);
    if (st != CF_STATUS_OK)
        return st;
    affine_init(&A, cx, cy, r, r, 0.0);
    return circle_pieces(&A, a0, a1, out, diag);
}

cf_status_t
cf_conic_circle(double cx, double cy, double r, cf_bezier_list_t **out,
                cf_diag_t *diag)
{
    cf_diag_clear(diag);
    /* quadrant points and corners of the unit square, exact */
    static const double q[4][6] = {
        { 1, 0, 1, 1, 0, 1 },
        { 0, 1, -1, 1, -1, 0 },
        { -1, 0, -1, -1, 0, -1 },
        { 0, -1, 1, -1, 1, 0 },
    };
    static const char *const names[] = { "center x", "center y", "radius" };
    const double v[] = { cx, cy, r };
    cf_bezier_list_t *list;
    affine A;
    cf_status_t st;
    st = begin(out, v, names, 3, diag);
    if (st == CF_STATUS_OK)
        st = check_positive(r, "radius", diag);
    if (st == CF_STATUS_OK)
        st = new_list(4, &list, diag);
    if (st != CF_STATUS_OK)
        return st;
    affine_init(&A, cx, cy, r, r, 0.0);
    for (int k = 0; k < 4 && st == CF_STATUS_OK; k++)
        st = set_piece(list, (size_t)k, &A, q[k], sqrt(0.5), true,
                       k * CF__PI / 2, (k + 1) * CF__PI / 2, diag);
    return finish(st, list, out);
}

cf_status_t
cf_conic_ellipse(double cx, double cy, double a, double b, double rotation,
                 double t0, double t1, cf_bezier_list_t **out,
                 cf_diag_t *diag)
{
    cf_diag_clear(diag);
    static const char *const names[] = { "center x", "center y",
                                         "semi-axis a", "semi-axis b",
                                         "rotation", "start parameter",
                                         "end parameter" };
    const double v[] = { cx, cy, a, b, rotation, t0, t1 };
    affine A;
    cf_status_t st;
    st = begin(out, v, names, 7, diag);
    if (st == CF_STATUS_OK)
        st = check_positive(a, "semi-axis a", diag);
    if (st == CF_STATUS_OK)
        st = check_positive(b, "semi-axis b", diag);
    if (st != CF_STATUS_OK)
        return st;
    affine_init(&A, cx, cy, a, b, rotation);
    return circle_pieces(&A, t0, t1, out, diag);
}

cf_status_t
cf_conic_parabola(double vx, double vy, double f, double axis, double u0,
                  double u1, cf_bezier_list_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    static const char *const names[] = { "vertex x", "vertex y",
                                         "focal length", "axis angle",
                                         "start parameter",
                                         "end parameter" };
    const double v[] = { vx, vy, f, axis, u0, u1 };
    cf_bezier_list_t *list;
    affine A;
    cf_status_t st;
    st = begin(out, v, names, 6, diag);
    if (st == CF_STATUS_OK)
        st = check_positive(f, "focal length", diag);
    if (st == CF_STATUS_OK && !(u0 < u1))
        st = cf__error(diag, CF_STATUS_DOMAIN, -1,
                       "parameter range [%s, %s] is empty", CF__NUM(u0),
                       CF__NUM(u1));
    if (st == CF_STATUS_OK)
        st = new_list(1, &list, diag);
    if (st != CF_STATUS_OK)
        return st;
    /* local frame: x along the vertex tangent (sin axis, -cos axis), y
    ** along the axis; the parabola y = x^2 / (4 f), whose tangents at u0
    ** and u1 meet at ((u0 + u1) / 2, u0 u1 / (4 f)).  A = R(axis - pi/2). */
    affine_init(&A, vx, vy, 1.0, 1.0, 0.0);
    A.m[0] = sin(axis);
    A.m[1] = cos(axis);
    A.m[2] = -cos(axis);
    A.m[3] = sin(axis);
    {
        double L[6] = { u0, u0 * u0 / (4 * f), 0.5 * (u0 + u1),
                        u0 * u1 / (4 * f), u1, u1 * u1 / (4 * f) };
        st = set_piece(list, 0, &A, L, 1.0, false, u0, u1, diag);
    }
    return finish(st, list, out);
}

cf_status_t
cf_conic_hyperbola(double cx, double cy, double a, double b, double rotation,
                   double s0, double s1, cf_bezier_list_t **out,
                   cf_diag_t *diag)
{
    cf_diag_clear(diag);
    static const char *const names[] = { "center x", "center y",
                                         "semi-axis a", "semi-axis b",
                                         "rotation", "start parameter",
                                         "end parameter" };
    const double v[] = { cx, cy, a, b, rotation, s0, s1 };
    affine A;
    size_t n;
    cf_status_t st;
    st = begin(out, v, names, 7, diag);
    if (st == CF_STATUS_OK)
        st = check_positive(a, "semi-axis a", diag);
    if (st == CF_STATUS_OK)
        st = check_positive(b, "semi-axis b", diag);
    if (st == CF_STATUS_OK && !(s0 < s1))
        st = cf__error(diag, CF_STATUS_DOMAIN, -1,
                       "parameter range [%s, %s] is empty", CF__NUM(s0),
                       CF__NUM(s1));
    if (st == CF_STATUS_OK && (fabs(s0) > 700 || fabs(s1) > 700))
        st = cf__error(diag, CF_STATUS_DOMAIN, -1,
                       "parameter range [%s, %s] leaves |s| <= 700 (cosh "
                       "overflows)", CF__NUM(s0), CF__NUM(s1));
    if (st != CF_STATUS_OK)
        return st;
    n = (size_t)ceil((s1 - s0) / 2.0 * (1.0 - 1e-12));
    affine_init(&A, cx, cy, a, b, rotation);
    return unit_pieces(&A, s0, s1, n < 1 ? 1 : n, true, out, diag);
}

/* ---- NURBS conics ------------------------------------------------------- */

cf_status_t
cf_nurbs_arc(size_t dim, const double *O, const double *X, const double *Y,
             double r, double a0, double a1, cf_bspline_t **out,
             cf_diag_t *diag)
{
    cf_diag_clear(diag);
    double sweep = a1 - a0, dth, w1;
    size_t narcs, count, nk;
    double *U = NULL, *H = NULL;
    cf_status_t st;
    if (out != NULL)
        *out = NULL;
    if (out == NULL || O == NULL || X == NULL || Y == NULL || dim < 2
        || dim > CF__BSPLINE_MAX_COUNT)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "NULL argument or dimension below 2");
    if (!isfinite(r) || !isfinite(a0) || !isfinite(a1))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "radius or angles are not finite");
    if (!(r > 0.0))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "radius %s must be positive", CF__NUM(r));
    if (!(sweep > 0.0) || sweep > 2.0 * CF__PI * (1.0 + 1e-15))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "sweep %s must be in (0, 2 pi]", CF__NUM(sweep));
    /* one quadratic rational piece per quarter turn or less */
    narcs = (size_t)ceil(sweep / (0.5 * CF__PI) - 1e-12);
    if (narcs < 1)
        narcs = 1;
    if (narcs > 4)
        narcs = 4;
    dth = sweep / (double)narcs;
    w1 = cos(0.5 * dth);
    count = 2 * narcs + 1;
    nk = count + 3;
    U = cf__alloc_array(nk, sizeof *U);
    H = cf__alloc_array(count, (dim + 1) * sizeof *H);
    if (U == NULL || H == NULL) {
        st = cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
        goto done;
    }
    for (size_t i = 0; i < 3; i++) {
        U[i] = 0.0;
        U[nk - 1 - i] = 1.0;
    }
    for (size_t i = 1; i < narcs; i++)
        U[1 + 2 * i] = U[2 + 2 * i] = (double)i / (double)narcs;
    for (size_t i = 0; i < count; i++) {
        /* even points on the circle, odd points at the intersection of the
        ** end tangents, at distance r / cos(dth / 2) from O */
        double th = a0 + 0.5 * dth * (double)i;
        double w = (i % 2 == 0) ? 1.0 : w1;
        double rr = (i % 2 == 0) ? r : r / w1;
        double cs = cos(th), sn = sin(th);
        if (i == count - 1) {
            cs = cos(a1);
            sn = sin(a1);
        }
        for (size_t d = 0; d < dim; d++)
            H[i * (dim + 1) + d] = w * (O[d] + rr * (cs * X[d] + sn * Y[d]));
        H[i * (dim + 1) + dim] = w;
    }
    st = cf_bspline_create_homogeneous(dim, 2, U, nk, H, count, out, diag);
done:
    cf__free(U);
    cf__free(H);
    return st;
}

cf_status_t
cf_nurbs_circle(const double *centre, double r, cf_bspline_t **out,
                cf_diag_t *diag)
{
    cf_diag_clear(diag);
    static const double U[12] = { 0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75,
                                  1, 1, 1 };
    static const double dx[9] = { 1, 1, 0, -1, -1, -1, 0, 1, 1 };
    static const double dy[9] = { 0, 1, 1, 1, 0, -1, -1, -1, 0 };
    double P[18], W[9];
    if (out != NULL)
        *out = NULL;
    if (centre == NULL || out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "NULL argument");
    if (!isfinite(r) || !isfinite(centre[0]) || !isfinite(centre[1]))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "centre or radius is not finite");
    if (!(r > 0.0))
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "radius %s must be positive", CF__NUM(r));
    for (int i = 0; i < 9; i++) {
        P[2 * i] = centre[0] + r * dx[i];
        P[2 * i + 1] = centre[1] + r * dy[i];
        W[i] = (i % 2 == 0) ? 1.0 : sqrt(0.5);
    }
    return cf_bspline_create(2, 2, U, 12, P, 9, W, out, diag);
}
