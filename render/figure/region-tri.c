/*
** Triangles of a filled region in space (region.h): a polygon ear-clipped
** in its plane, a convex hull as the faces of the 3D hull that face the
** viewer (which cover the hull's image once, as the plane hull of the
** images does in a plane figure).
*/
#include <math.h>
#include <string.h>

#include "curvefig/geometry.h"
#include "grow.h"
#include "region.h"

cf_status_t
cf__tris_add(cf__tris_t *t, const double *a, const double *b,
             const double *c)
{
    double *np = cf__grow_array(t->p, &t->cap, t->n + 1, 9 * sizeof *np, 16);
    if (np == NULL)
        return CF_STATUS_NO_MEMORY;
    t->p = np;
    memcpy(np + 9 * t->n, a, 3 * sizeof *np);
    memcpy(np + 9 * t->n + 3, b, 3 * sizeof *np);
    memcpy(np + 9 * t->n + 6, c, 3 * sizeof *np);
    t->n++;
    return CF_STATUS_OK;
}

void
cf__tris_fini(cf__tris_t *t)
{
    cf_free(t->p);
    memset(t, 0, sizeof *t);
}

static void
sub3(const double *a, const double *b, double *o)
{
    for (int k = 0; k < 3; k++)
        o[k] = a[k] - b[k];
}

static void
cross3(const double *a, const double *b, double *o)
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

static double
dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double
norm3(const double *a)
{
    return sqrt(dot3(a, a));
}

/* The diagonal of the box of the points. */
static double
size_of(const double *p, size_t n)
{
    double lo[3], hi[3], d[3];
    memcpy(lo, p, sizeof lo);
    memcpy(hi, p, sizeof hi);
    for (size_t i = 1; i < n; i++)
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], p[3 * i + k]);
            hi[k] = fmax(hi[k], p[3 * i + k]);
        }
    sub3(hi, lo, d);
    return norm3(d);
}

/* The point farthest from a (index), and from the line a b. */
static size_t
farthest(const double *p, size_t n, const double *a, double *dist)
{
    size_t best = 0;
    *dist = -1;
    for (size_t i = 0; i < n; i++) {
        double d[3], r;
        sub3(p + 3 * i, a, d);
        r = norm3(d);
        if (r > *dist) {
            *dist = r;
            best = i;
        }
    }
    return best;
}

static size_t
farthest_line(const double *p, size_t n, const double *a, const double *b,
              double *dist)
{
    double ab[3], d[3], c[3], l;
    size_t best = 0;
    sub3(b, a, ab);
    l = norm3(ab);
    *dist = -1;
    for (size_t i = 0; i < n; i++) {
        double r;
        sub3(p + 3 * i, a, d);
        cross3(ab, d, c);
        r = norm3(c) / l;
        if (r > *dist) {
            *dist = r;
            best = i;
        }
    }
    return best;
}

/* ---- polygons ----------------------------------------------------------- */

static double
orient2(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* Whether q lies in the closed triangle a b c (counter-clockwise). */
static bool
in_tri2(const double *a, const double *b, const double *c, const double *q)
{
    return orient2(a, b, q) >= 0 && orient2(b, c, q) >= 0
        && orient2(c, a, q) >= 0;
}

/* Ear clipping of the plane polygon q (counter-clockwise), its vertices
** listed in idx (m of them, consumed); the triangles' indices into tri
** (3 each).  False when no ear is found (the polygon crosses itself). */
static bool
ear_clip(const double *q, size_t *idx, size_t m, size_t *tri, size_t *nt)
{
    *nt = 0;
    while (m > 3) {
        bool found = false;
        for (size_t i = 0; i < m && !found; i++) {
            size_t a = idx[(i + m - 1) % m], b = idx[i], c = idx[(i + 1) % m];
            bool ear = orient2(q + 2 * a, q + 2 * b, q + 2 * c) > 0;
            for (size_t j = 0; ear && j < m; j++) {
                size_t v = idx[j];
                if (v != a && v != b && v != c
                    && in_tri2(q + 2 * a, q + 2 * b, q + 2 * c, q + 2 * v))
                    ear = false;
            }
            if (!ear)
                continue;
            tri[3 * *nt] = a;
            tri[3 * *nt + 1] = b;
            tri[3 * *nt + 2] = c;
            (*nt)++;
            memmove(idx + i, idx + i + 1, (m - i - 1) * sizeof *idx);
            m--;
            found = true;
        }
        if (!found)
            return false;
    }
    if (orient2(q + 2 * idx[0], q + 2 * idx[1], q + 2 * idx[2]) > 0) {
        tri[3 * *nt] = idx[0];
        tri[3 * *nt + 1] = idx[1];
        tri[3 * *nt + 2] = idx[2];
        (*nt)++;
    }
    return true;
}

cf_status_t
cf__region_polygon(cf_figure_t *fig, const double *p, size_t n,
                   const char *what, cf__tris_t *out, bool *planar)
{
    double nn[3] = { 0, 0, 0 }, u[3], v[3], size = size_of(p, n), d1, d2;
    double *q = cf_alloc_array(2 * n, sizeof *q), area = 0;
    size_t *idx = cf_alloc_array(n, sizeof *idx);
    size_t *tri = cf_alloc_array(3 * n, sizeof *tri), nt = 0, m = 0;
    size_t i1 = farthest(p, n, p, &d1), i2;
    cf_status_t st = CF_STATUS_OK;
    *planar = true;
    if (q == NULL || idx == NULL || tri == NULL) {
        st = cf__fig_nomem(fig, what);
        goto done;
    }
    i2 = farthest_line(p, n, p, p + 3 * i1, &d2);
    if (!(d1 > 1e-9 * size) || !(d2 > 1e-9 * size)) {
        st = cf_diag_set(&fig->err, CF_STATUS_DEGENERATE, -1,
                         "its %zu points lie on one line: no region to "
                         "fill (a %s needs three points off one line)", n,
                         what);
        goto done;
    }
    /* Newell's normal: the plane of the polygon (of its largest triangle
    ** when the areas cancel) */
    for (size_t i = 0; i < n; i++) {
        const double *a = p + 3 * i, *b = p + 3 * ((i + 1) % n);
        nn[0] += (a[1] - b[1]) * (a[2] + b[2]);
        nn[1] += (a[2] - b[2]) * (a[0] + b[0]);
        nn[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    if (!(norm3(nn) > 1e-9 * size * size)) {
        double ab[3], ac[3];
        sub3(p + 3 * i1, p, ab);
        sub3(p + 3 * i2, p, ac);
        cross3(ab, ac, nn);
    }
    for (int k = 0; k < 3; k++)
        nn[k] /= norm3(nn);
    sub3(p + 3 * i1, p, u);
    for (int k = 0; k < 3; k++)
        u[k] /= d1;
    cross3(nn, u, v);
    for (size_t i = 0; i < n; i++) {
        double d[3];
        sub3(p + 3 * i, p, d);
        q[2 * i] = dot3(d, u);
        q[2 * i + 1] = dot3(d, v);
        if (fabs(dot3(d, nn)) > 1e-9 * size)
            *planar = false;
    }
    /* the vertices counter-clockwise, repeated ones once */
    for (size_t i = 0; i < n; i++)
        area += orient2(q, q + 2 * i, q + 2 * ((i + 1) % n));
    for (size_t k = 0; k < n; k++) {
        size_t i = area >= 0 ? k : n - 1 - k;
        if (m == 0 || hypot(q[2 * i] - q[2 * idx[m - 1]],
                            q[2 * i + 1] - q[2 * idx[m - 1] + 1])
                          > 1e-12 * size)
            idx[m++] = i;
    }
    if (m > 1 && hypot(q[2 * idx[0]] - q[2 * idx[m - 1]],
                       q[2 * idx[0] + 1] - q[2 * idx[m - 1] + 1])
                     <= 1e-12 * size)
        m--;
    if (m < 3 || !ear_clip(q, idx, m, tri, &nt)) {
        /* crossing itself: the fan of the first vertex, each triangle
        ** with its sign */
        nt = 0;
        for (size_t i = 1; i + 1 < n; i++) {
            tri[3 * nt] = 0;
            tri[3 * nt + 1] = i;
            tri[3 * nt + 2] = i + 1;
            nt++;
        }
    }
    for (size_t t = 0; t < nt && st == CF_STATUS_OK; t++)
        if (cf__tris_add(out, p + 3 * tri[3 * t], p + 3 * tri[3 * t + 1],
                         p + 3 * tri[3 * t + 2]) != CF_STATUS_OK)
            st = cf__fig_nomem(fig, what);
done:
    cf_free(q);
    cf_free(idx);
    cf_free(tri);
    return st;
}

/* ---- convex hulls ------------------------------------------------------- */

/* A face (a, b, c) turning counter-clockwise seen from outside. */
typedef struct face {
    size_t v[3];
} face_t;

typedef struct hull {
    face_t *f;
    size_t n, cap;
} hull_t;

static bool
hull_add(hull_t *h, size_t a, size_t b, size_t c)
{
    face_t *nf = cf__grow_array(h->f, &h->cap, h->n + 1, sizeof *nf, 16);
    if (nf == NULL)
        return false;
    h->f = nf;
    nf[h->n].v[0] = a;
    nf[h->n].v[1] = b;
    nf[h->n].v[2] = c;
    h->n++;
    return true;
}

/* How far q lies outside face f's plane (times the normal's length). */
static double
above(const double *p, const face_t *f, const double *q, double *nlen)
{
    double ab[3], ac[3], n[3], d[3];
    sub3(p + 3 * f->v[1], p + 3 * f->v[0], ab);
    sub3(p + 3 * f->v[2], p + 3 * f->v[0], ac);
    cross3(ab, ac, n);
    sub3(q, p + 3 * f->v[0], d);
    *nlen = norm3(n);
    return dot3(n, d);
}

/* Whether face list fs has the directed edge (a, b). */
static bool
has_edge(const face_t *fs, const bool *gone, size_t n, size_t a, size_t b)
{
    for (size_t i = 0; i < n; i++)
        for (int k = 0; gone[i] && k < 3; k++)
            if (fs[i].v[k] == a && fs[i].v[(k + 1) % 3] == b)
                return true;
    return false;
}

/* The incremental hull of p from the tetrahedron i0 i1 i2 i3: a point
** outside faces (beyond eps) replaces them by the cone from the horizon. */
static bool
hull3(const double *p, size_t n, const size_t t4[4], double eps, hull_t *h)
{
    const size_t a = t4[0], b = t4[1], c = t4[2], d = t4[3];
    face_t f0 = { { a, b, c } };
    double nl;
    bool ok;
    if (above(p, &f0, p + 3 * d, &nl) > 0)
        ok = hull_add(h, a, c, b) && hull_add(h, a, b, d)
            && hull_add(h, b, c, d) && hull_add(h, c, a, d);
    else
        ok = hull_add(h, a, b, c) && hull_add(h, a, d, b)
            && hull_add(h, b, d, c) && hull_add(h, c, d, a);
    for (size_t i = 0; ok && i < n; i++) {
        size_t m = h->n, kept = 0, nadd = 0;
        bool *gone = cf_calloc(m, sizeof *gone), any = false;
        size_t *edges = cf_alloc_array(6 * m, sizeof *edges);
        if (gone == NULL || edges == NULL) {
            cf_free(gone);
            cf_free(edges);
            return false;
        }
        for (size_t j = 0; j < m; j++) {
            double s = above(p, &h->f[j], p + 3 * i, &nl);
            gone[j] = s > eps * nl;
            any = any || gone[j];
        }
        /* the horizon: edges of gone faces whose twin stays */
        for (size_t j = 0; any && j < m; j++)
            for (int k = 0; gone[j] && k < 3; k++) {
                size_t u = h->f[j].v[k], w = h->f[j].v[(k + 1) % 3];
                if (!has_edge(h->f, gone, m, w, u)) {
                    edges[2 * nadd] = u;
                    edges[2 * nadd + 1] = w;
                    nadd++;
                }
            }
        for (size_t j = 0; any && j < m; j++)
            if (!gone[j])
                h->f[kept++] = h->f[j];
        if (any)
            h->n = kept;
        for (size_t e = 0; ok && e < nadd; e++)
            ok = hull_add(h, edges[2 * e], edges[2 * e + 1], i);
        cf_free(gone);
        cf_free(edges);
    }
    return ok;
}

/* Whether face f of p faces the viewer of fig (its outside towards the
** eye, not edge-on). */
static bool
faces_viewer(const cf_figure_t *fig, const double *p, const face_t *f)
{
    const cf_view_t *v = &fig->view;
    double ab[3], ac[3], nrm[3], to[3];
    sub3(p + 3 * f->v[1], p + 3 * f->v[0], ab);
    sub3(p + 3 * f->v[2], p + 3 * f->v[0], ac);
    cross3(ab, ac, nrm);
    if (v->projection == CF_PROJECTION_PERSPECTIVE) {
        for (int k = 0; k < 3; k++)
            to[k] = v->target[k] + v->distance * v->dir[k]
                - p[3 * f->v[0] + k];
    } else {
        memcpy(to, v->dir, sizeof to);
    }
    return dot3(nrm, to) > 1e-12 * norm3(nrm) * norm3(to);
}

/* The outline: the plane hull of the images. */
static cf_status_t
outline_of(cf_figure_t *fig, const double *p, size_t n, size_t **outline,
           size_t *nout)
{
    double *img = cf_alloc_array(2 * n, sizeof *img);
    cf_status_t st;
    *outline = cf_alloc_array(n, sizeof **outline);
    if (img == NULL || *outline == NULL) {
        cf_free(img);
        return cf__fig_nomem(fig, "convex hull");
    }
    for (size_t i = 0; i < n; i++)
        cf__fig_project1(fig, p + 3 * i, 3, img + 2 * i);
    st = cf_convex_hull_2d(img, n, 2, *outline, nout, &fig->err);
    cf_free(img);
    return st;
}

cf_status_t
cf__region_hull(cf_figure_t *fig, const double *p, size_t n, cf__tris_t *out,
                size_t **outline, size_t *nout)
{
    double size = size_of(p, n), d1, d2, d3 = 0, nn[3], ab[3], ac[3];
    size_t t4[4] = { 0, 0, 0, 0 };
    hull_t h;
    cf_status_t st = outline_of(fig, p, n, outline, nout);
    memset(&h, 0, sizeof h);
    if (st != CF_STATUS_OK)
        return st;
    t4[1] = farthest(p, n, p, &d1);
    if (!(d1 > 1e-9 * size))
        return CF_STATUS_OK;               /* one point */
    t4[2] = farthest_line(p, n, p, p + 3 * t4[1], &d2);
    if (!(d2 > 1e-9 * size))
        return CF_STATUS_OK;               /* a segment: the outline */
    sub3(p + 3 * t4[1], p, ab);
    sub3(p + 3 * t4[2], p, ac);
    cross3(ab, ac, nn);
    for (size_t i = 0; i < n; i++) {
        double d[3], r;
        sub3(p + 3 * i, p, d);
        r = fabs(dot3(d, nn)) / norm3(nn);
        if (r > d3) {
            d3 = r;
            t4[3] = i;
        }
    }
    if (!(d3 > 1e-9 * size)) {
        /* in one plane: the outline's polygon, convex, as a fan */
        bool planar;
        double *q = cf_alloc_array(3 * *nout, sizeof *q);
        if (q == NULL)
            return cf__fig_nomem(fig, "convex hull");
        for (size_t i = 0; i < *nout; i++)
            memcpy(q + 3 * i, p + 3 * (*outline)[i], 3 * sizeof *q);
        st = *nout >= 3 ? cf__region_polygon(fig, q, *nout, "hull", out,
                                              &planar)
                        : CF_STATUS_OK;
        cf_free(q);
        return st;
    }
    if (!hull3(p, n, t4, 1e-9 * size, &h)) {
        cf_free(h.f);
        return cf__fig_nomem(fig, "convex hull");
    }
    for (size_t i = 0; i < h.n && st == CF_STATUS_OK; i++)
        if (faces_viewer(fig, p, &h.f[i])
            && cf__tris_add(out, p + 3 * h.f[i].v[0], p + 3 * h.f[i].v[1],
                            p + 3 * h.f[i].v[2]) != CF_STATUS_OK)
            st = cf__fig_nomem(fig, "convex hull");
    cf_free(h.f);
    return st;
}
