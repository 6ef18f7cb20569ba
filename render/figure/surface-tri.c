/*
** The lines of a triangular Bézier patch in space (surface-lines.h): its
** edges, iso-lines as exact Bézier curves (blossoms), its net.
*/
#include <math.h>
#include <string.h>

#include "surface-lines.h"

/* Index of b_ijk among the points of degree m (surface-triangle.h). */
static size_t
tri_index(int m, int i, int j)
{
    int r = m - i;
    return (size_t)(r * (r + 1) / 2 + (r - j));
}

/* The patch's points, homogeneous (w x, w) when rational: n_pts * hd
** doubles, hd = 3 or 4. */
static double *
homogeneous_points(const cf_bezier_triangle_t *t, size_t *hd)
{
    size_t n = cf_bezier_triangle_count(t);
    bool rat = cf_bezier_triangle_is_rational(t);
    double *p = cf_alloc_array(n * 5, sizeof *p), *w;
    if (p == NULL)
        return NULL;
    *hd = rat ? 4 : 3;
    cf_bezier_triangle_get_points(t, p);
    if (!rat)
        return p;
    /* the weights after the 4 n doubles of the result, which the spread
    ** never reaches; the points spread from the back, so point i (at 3 i)
    ** is read before the points after it are written (at 4 j > 3 i + 2) */
    w = p + 4 * n;
    cf_bezier_triangle_get_weights(t, w);
    for (size_t i = n; i-- > 0;) {
        double wi = w[i], x[3] = { p[3 * i], p[3 * i + 1], p[3 * i + 2] };
        for (int k = 0; k < 3; k++)
            p[4 * i + k] = wi * x[k];
        p[4 * i + 3] = wi;
    }
    return p;
}

cf_status_t
cf__triangle_copy(cf_figure_t *fig, const cf_bezier_triangle_t *t,
                  cf_bezier_triangle_t **out)
{
    size_t n = cf_bezier_triangle_count(t), dim = cf_bezier_triangle_dim(t);
    double *p = cf_alloc_array(n * (dim + 1), sizeof *p);
    cf_status_t st;
    if (p == NULL)
        return cf__fig_nomem(fig, "a triangular patch");
    cf_bezier_triangle_get_points(t, p);
    if (cf_bezier_triangle_is_rational(t))
        cf_bezier_triangle_get_weights(t, p + n * dim);
    st = cf_bezier_triangle_create(dim, cf_bezier_triangle_degree(t), p,
                                   cf_bezier_triangle_is_rational(t)
                                   ? p + n * dim : NULL, out, &fig->err);
    cf_free(p);
    return st;
}

/* The blossom b[x_1, ..., x_n] of the homogeneous points h (degree n, hd
** doubles each), x_l = a for l < n - k, b after: k copies of b.  work
** holds a copy of the points. */
static void
blossom(const double *h, int n, size_t hd, const double a[3],
        const double b[3], int k, double *work, double *out)
{
    size_t count = (size_t)(n + 1) * (size_t)(n + 2) / 2;
    memcpy(work, h, count * hd * sizeof *work);
    for (int l = 0; l < n; l++) {
        const double *x = l < n - k ? a : b;
        int m = n - l;   /* degree of the level read */
        for (int i = m - 1; i >= 0; i--)
            for (int j = m - 1 - i; j >= 0; j--) {
                double *o = work + hd * tri_index(m - 1, i, j);
                const double *p0 = work + hd * tri_index(m, i + 1, j);
                const double *p1 = work + hd * tri_index(m, i, j + 1);
                const double *p2 = work + hd * tri_index(m, i, j);
                /* the new point's index is never above the ones it reads
                ** in this order (by i descending, j descending) */
                for (size_t c = 0; c < hd; c++)
                    o[c] = x[0] * p0[c] + x[1] * p1[c] + x[2] * p2[c];
            }
    }
    memcpy(out, work, hd * sizeof *out);
}

/* The restriction of the patch to the segment from domain point a to b
** (barycentric): a Bézier curve of degree n, its (u, v) line with it. */
static cf_status_t
segment_line(cf_figure_t *fig, const double *h, int n, size_t hd,
             const double a[3], const double b[3], int family,
             cf__lines3_t *out)
{
    size_t count = (size_t)(n + 1) * (size_t)(n + 2) / 2;
    double *work = cf_alloc_array(count * hd + (size_t)(n + 1) * hd,
                                  sizeof *work);
    double *cp, uv[4] = { a[0], a[1], b[0], b[1] };
    cf_bezier_t *bez = NULL, *line = NULL;
    cf_status_t st;
    if (work == NULL)
        return cf__fig_nomem(fig, "a triangular patch's lines");
    cp = work + count * hd;
    for (int k = 0; k <= n; k++)
        blossom(h, n, hd, a, b, k, work, cp + (size_t)k * hd);
    if (hd == 4)
        st = cf_bezier_create_homogeneous(3, n, cp, &bez, &fig->err);
    else
        st = cf_bezier_create(3, n, cp, NULL, &bez, &fig->err);
    cf_free(work);
    if (st == CF_STATUS_OK)
        st = cf_bezier_create(2, 1, uv, NULL, &line, &fig->err);
    if (st != CF_STATUS_OK) {
        cf_bezier_destroy(bez);
        return st;
    }
    return cf__lines3_add(fig, out, family, bez, line);
}

/* The iso-line where barycentric coordinate c (0: u, 1: v, 2: w) is x:
** from the edge where the next coordinate is 0 to the one where the
** coordinate after it is 0. */
static cf_status_t
iso_line(cf_figure_t *fig, const double *h, int n, size_t hd, int c,
         double x, int family, cf__lines3_t *out)
{
    double a[3], b[3];
    a[c] = b[c] = x;
    a[(c + 1) % 3] = 0;
    a[(c + 2) % 3] = 1 - x;
    b[(c + 1) % 3] = 1 - x;
    b[(c + 2) % 3] = 0;
    return segment_line(fig, h, n, hd, a, b, family, out);
}

static cf_status_t
check_value(cf_figure_t *fig, char name, double x)
{
    if (isfinite(x) && x >= 0 && x <= 1)
        return CF_STATUS_OK;
    return cf_diag_set(&fig->err, CF_STATUS_DOMAIN, -1,
                       "isolines: %c = %g is outside the triangle's domain "
                       "[0, 1]", name, x);
}

/* The net's edges: each b_ijk to its neighbours b_(i-1)(j+1)k and
** b_(i-1)j(k+1), and b_i(j+1)(k-1) to b_ij(k) along a row. */
static cf_status_t
net_lines(cf_figure_t *fig, const cf_bezier_triangle_t *t, cf__lines3_t *out)
{
    int n = cf_bezier_triangle_degree(t);
    size_t count = cf_bezier_triangle_count(t);
    double *p = cf_alloc_array(3 * count, sizeof *p);
    cf_status_t st = CF_STATUS_OK;
    if (p == NULL)
        return cf__fig_nomem(fig, "a triangular net");
    cf_bezier_triangle_get_points(t, p);
    for (int i = n; i >= 0 && st == CF_STATUS_OK; i--)
        for (int j = n - i; j >= 0 && st == CF_STATUS_OK; j--) {
            int k = n - i - j;
            /* to the two neighbours with one less i, and along the row */
            int nb[3][2] = { { i - 1, j + 1 }, { i - 1, j }, { i, j - 1 } };
            for (int e = 0; e < 3 && st == CF_STATUS_OK; e++) {
                double q[6];
                cf_bezier_t *bez = NULL;
                if (nb[e][0] < 0 || nb[e][1] < 0 || (e == 2 && k + 1 > n))
                    continue;
                memcpy(q, p + 3 * tri_index(n, i, j), 3 * sizeof *q);
                memcpy(q + 3, p + 3 * tri_index(n, nb[e][0], nb[e][1]),
                       3 * sizeof *q);
                st = cf_bezier_create(3, 1, q, NULL, &bez, &fig->err);
                if (st == CF_STATUS_OK)
                    st = cf__lines3_add(fig, out, CF__LINE_NET, bez, NULL);
            }
        }
    cf_free(p);
    return st;
}

cf_status_t
cf__triangle_lines(cf_figure_t *fig, const cf_bezier_triangle_t *t,
                   const cf_surface_lines_t *o, cf__lines3_t *out)
{
    int n = cf_bezier_triangle_degree(t);
    size_t hd = 3;
    double *h = homogeneous_points(t, &hd);
    cf_status_t st = CF_STATUS_OK;
    if (h == NULL)
        return cf__fig_nomem(fig, "a triangular patch's lines");
    /* the edges: u = 0, v = 0, w = 0 */
    for (int c = 0; c < 3 && o->boundary && st == CF_STATUS_OK; c++)
        st = iso_line(fig, h, n, hd, c, 0.0, CF__LINE_OUTLINE, out);
    for (int c = 0; c < 3 && st == CF_STATUS_OK; c++) {
        size_t cnt = c == 1 ? o->nv : o->nu;
        for (size_t k = 1; k <= cnt && st == CF_STATUS_OK; k++)
            st = iso_line(fig, h, n, hd, c, (double)k / (double)(cnt + 1),
                          CF__LINE_ISO, out);
    }
    for (size_t k = 0; k < o->u_count && st == CF_STATUS_OK; k++) {
        st = check_value(fig, 'u', o->u_values[k]);
        if (st == CF_STATUS_OK)
            st = iso_line(fig, h, n, hd, 0, o->u_values[k], CF__LINE_ISO,
                          out);
    }
    for (size_t k = 0; k < o->v_count && st == CF_STATUS_OK; k++) {
        st = check_value(fig, 'v', o->v_values[k]);
        if (st == CF_STATUS_OK)
            st = iso_line(fig, h, n, hd, 1, o->v_values[k], CF__LINE_ISO,
                          out);
    }
    cf_free(h);
    if (st == CF_STATUS_OK && o->net)
        st = net_lines(fig, t, out);
    return st;
}
