/*
** A convex hull filled in space (region.h): the faces of the hull of the
** points in space that face the viewer, which cover the hull's image once,
** as the plane hull of the images does in a plane figure.  The hull comes
** from Quickhull (Barber, Dobkin and Huhdanpaa, 1996): every face keeps
** the points beyond it, the farthest of a face's is added next, the faces
** it sees are found from that face through their neighbours and replaced
** by the cone from their horizon, and only their points are asked again;
** a figure of n points costs about n log n.  When the faces a point sees
** do not meet the rest in one loop of edges (points nearly in a plane,
** within the tolerance), the points are added one at a time instead, each
** against every face, as before Quickhull (about n times the faces).
*/
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "curvefig/geometry.h"
#include "grow.h"
#include "region-geom.h"
#include "region.h"

#define NONE SIZE_MAX

/* ---- adding the points one at a time ------------------------------------ */

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
    cf__sub3(p + 3 * f->v[1], p + 3 * f->v[0], ab);
    cf__sub3(p + 3 * f->v[2], p + 3 * f->v[0], ac);
    cf__cross3(ab, ac, n);
    cf__sub3(q, p + 3 * f->v[0], d);
    *nlen = cf__norm3(n);
    return cf__dot3(n, d);
}

/* The tetrahedron t4 as four faces turned outwards. */
static bool
tetrahedron(const double *p, const size_t t4[4], hull_t *h)
{
    const size_t a = t4[0], b = t4[1], c = t4[2], d = t4[3];
    face_t f0 = { { a, b, c } };
    double nl;
    if (above(p, &f0, p + 3 * d, &nl) > 0)
        return hull_add(h, a, c, b) && hull_add(h, a, b, d)
            && hull_add(h, b, c, d) && hull_add(h, c, a, d);
    return hull_add(h, a, b, c) && hull_add(h, a, d, b)
        && hull_add(h, b, d, c) && hull_add(h, c, d, a);
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

/* The incremental hull: a point outside faces (beyond eps) replaces them
** by the cone from the horizon. */
static bool
one_at_a_time(const double *p, size_t n, const size_t t4[4], double eps,
              hull_t *h)
{
    double nl;
    bool ok = tetrahedron(p, t4, h);
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

/* ---- Quickhull ---------------------------------------------------------- */

typedef struct qface {
    size_t v[3];
    size_t nb[3];             /* the face across edge v[k] v[k + 1] */
    double n[3], nlen;        /* (v1 - v0) x (v2 - v0), as above() */
    size_t head;              /* the points beyond it (NONE: none) */
    size_t far;               /* the farthest of them */
    double fard;
    size_t mark;              /* 2 visit: seen from the point; + 1: not */
    bool alive;
} qface_t;

typedef struct edge {
    size_t u, w;              /* on a face seen, counter-clockwise */
    size_t out, k;            /* the face not seen across it, its edge */
} edge_t;

typedef struct qh {
    const double *p;
    double eps;
    qface_t *f;
    size_t nf, fcap;
    size_t *next;             /* the next point beyond the same face */
    size_t *stack, scap;      /* the faces seen, then as a list */
    edge_t *hor;
    size_t hcap;
    size_t visit;
} qh_t;

static double
beyond(const qh_t *q, const qface_t *f, size_t i)
{
    double d[3];
    cf__sub3(q->p + 3 * i, q->p + 3 * f->v[0], d);
    return cf__dot3(f->n, d);
}

/* Point i to face j's list, if it lies beyond the face. */
static bool
give(qh_t *q, size_t j, size_t i)
{
    qface_t *f = &q->f[j];
    double s = beyond(q, f, i);
    if (!(s > q->eps * f->nlen))
        return false;
    q->next[i] = f->head;
    f->head = i;
    if (f->far == NONE || s > f->fard) {
        f->far = i;
        f->fard = s;
    }
    return true;
}

static size_t
new_face(qh_t *q, size_t a, size_t b, size_t c)
{
    qface_t *nf = cf__grow_array(q->f, &q->fcap, q->nf + 1, sizeof *nf, 64);
    qface_t *f;
    double ab[3], ac[3];
    if (nf == NULL)
        return NONE;
    q->f = nf;
    f = &nf[q->nf];
    memset(f, 0, sizeof *f);
    f->v[0] = a;
    f->v[1] = b;
    f->v[2] = c;
    cf__sub3(q->p + 3 * b, q->p + 3 * a, ab);
    cf__sub3(q->p + 3 * c, q->p + 3 * a, ac);
    cf__cross3(ab, ac, f->n);
    f->nlen = cf__norm3(f->n);
    f->head = f->far = NONE;
    f->alive = true;
    return q->nf++;
}

/* Edge k of face j is face j2's edge from v[k + 1] to v[k]: which one. */
static size_t
twin(const qh_t *q, size_t j, int k, size_t j2)
{
    const qface_t *f = &q->f[j], *g = &q->f[j2];
    for (int m = 0; m < 3; m++)
        if (g->v[m] == f->v[(k + 1) % 3] && g->v[(m + 1) % 3] == f->v[k])
            return (size_t)m;
    return NONE;
}

static int
by_start(const void *a, const void *b)
{
    const edge_t *x = a, *y = b;
    return x->u < y->u ? -1 : x->u > y->u;
}

static const edge_t *
find_start(const edge_t *e, size_t n, size_t u)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (e[mid].u < u)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < n && e[lo].u == u ? &e[lo] : NULL;
}

typedef enum step { STEP_OK, STEP_NOMEM, STEP_TANGLED } step_t;

static bool
push(size_t **a, size_t *cap, size_t n, size_t v)
{
    size_t *na = cf__grow_array(*a, cap, n + 1, sizeof *na, 64);
    if (na == NULL)
        return false;
    *a = na;
    na[n] = v;
    return true;
}

/* Add point e, beyond face j0. */
static step_t
add_point(qh_t *q, size_t e, size_t j0)
{
    size_t top = 0, nseen = 0, nh = 0, first;
    edge_t *chain;
    q->visit++;
    q->f[j0].mark = 2 * q->visit;
    if (!push(&q->stack, &q->scap, top++, j0))
        return STEP_NOMEM;
    /* the faces seen from e, reached through their neighbours; stack[0
    ** .. nseen) is the list of them once the search is done */
    while (top > nseen) {
        size_t j = q->stack[nseen++];
        for (int k = 0; k < 3; k++) {
            size_t h = q->f[j].nb[k];
            qface_t *g = &q->f[h];
            if (g->mark == 2 * q->visit)
                continue;
            if (g->mark != 2 * q->visit + 1
                && beyond(q, g, e) > q->eps * g->nlen) {
                g->mark = 2 * q->visit;
                if (!push(&q->stack, &q->scap, top++, h))
                    return STEP_NOMEM;
                continue;
            }
            g->mark = 2 * q->visit + 1;
            {
                edge_t *nh2 = cf__grow_array(q->hor, &q->hcap, nh + 1,
                                             sizeof *nh2, 64);
                if (nh2 == NULL)
                    return STEP_NOMEM;
                q->hor = nh2;
                nh2[nh].u = q->f[j].v[k];
                nh2[nh].w = q->f[j].v[(k + 1) % 3];
                nh2[nh].out = h;
                nh2[nh].k = twin(q, j, k, h);
                if (nh2[nh].k == NONE)
                    return STEP_TANGLED;
                nh++;
            }
        }
    }
    /* the horizon must be one loop through distinct vertices */
    if (nh < 3)
        return STEP_TANGLED;
    qsort(q->hor, nh, sizeof *q->hor, by_start);
    for (size_t i = 1; i < nh; i++)
        if (q->hor[i].u == q->hor[i - 1].u)
            return STEP_TANGLED;
    chain = cf_alloc_array(nh, sizeof *chain);
    if (chain == NULL)
        return STEP_NOMEM;
    chain[0] = q->hor[0];
    for (size_t i = 1; i < nh; i++) {
        const edge_t *nx = find_start(q->hor, nh, chain[i - 1].w);
        if (nx == NULL || nx->u == chain[0].u) {
            cf_free(chain);
            return STEP_TANGLED;
        }
        chain[i] = *nx;
    }
    if (chain[nh - 1].w != chain[0].u) {
        cf_free(chain);
        return STEP_TANGLED;
    }
    /* the cone from the horizon to e */
    first = q->nf;
    for (size_t i = 0; i < nh; i++) {
        size_t j = new_face(q, chain[i].u, chain[i].w, e);
        if (j == NONE) {
            cf_free(chain);
            return STEP_NOMEM;
        }
        if (!(q->f[j].nlen > 0)) {
            cf_free(chain);
            return STEP_TANGLED;
        }
        q->f[j].nb[0] = chain[i].out;
        q->f[chain[i].out].nb[chain[i].k] = j;
        q->f[j].nb[1] = first + (i + 1) % nh;
        q->f[j].nb[2] = first + (i + nh - 1) % nh;
    }
    cf_free(chain);
    /* the points of the faces seen go to the new faces, or are inside */
    for (size_t s = 0; s < nseen; s++) {
        qface_t *g = &q->f[q->stack[s]];
        size_t i = g->head;
        g->alive = false;
        g->head = NONE;
        while (i != NONE) {
            size_t nx = q->next[i];
            for (size_t j = first; i != e && j < q->nf; j++)
                if (give(q, j, i))
                    break;
            i = nx;
        }
    }
    return STEP_OK;
}

/* Every live face's neighbours live and pointing back across the same
** edge. */
static bool
closed(const qh_t *q)
{
    for (size_t j = 0; j < q->nf; j++)
        for (int k = 0; q->f[j].alive && k < 3; k++) {
            size_t h = q->f[j].nb[k], m;
            if (h >= q->nf || !q->f[h].alive)
                return false;
            m = twin(q, j, k, h);
            if (m == NONE || q->f[h].nb[m] != j)
                return false;
        }
    return true;
}

static step_t
quickhull(const double *p, size_t n, const size_t t4[4], double eps,
          size_t **faces, size_t *nfaces)
{
    qh_t q;
    hull_t t;
    step_t st = STEP_OK;
    size_t nalive = 0;
    memset(&q, 0, sizeof q);
    memset(&t, 0, sizeof t);
    q.p = p;
    q.eps = eps;
    q.next = cf_alloc_array(n, sizeof *q.next);
    if (q.next == NULL || !tetrahedron(p, t4, &t))
        st = STEP_NOMEM;
    for (size_t j = 0; st == STEP_OK && j < 4; j++)
        if (new_face(&q, t.f[j].v[0], t.f[j].v[1], t.f[j].v[2]) == NONE)
            st = STEP_NOMEM;
    for (size_t j = 0; st == STEP_OK && j < 4; j++)
        for (int k = 0; k < 3; k++)
            for (size_t h = 0; h < 4; h++)
                if (h != j && twin(&q, j, k, h) != NONE)
                    q.f[j].nb[k] = h;
    for (size_t i = 0; st == STEP_OK && i < n; i++)
        for (size_t j = 0; j < 4; j++)
            if (give(&q, j, i))
                break;
    /* faces are made in order: one pass adds every point */
    for (size_t j = 0; st == STEP_OK && j < q.nf; j++)
        if (q.f[j].alive && q.f[j].head != NONE)
            st = add_point(&q, q.f[j].far, j);
    if (st == STEP_OK && !closed(&q))
        st = STEP_TANGLED;
    for (size_t j = 0; st == STEP_OK && j < q.nf; j++)
        nalive += q.f[j].alive;
    if (st == STEP_OK) {
        *faces = cf_alloc_array(3 * nalive + 1, sizeof **faces);
        if (*faces == NULL)
            st = STEP_NOMEM;
    }
    for (size_t j = 0; st == STEP_OK && j < q.nf; j++)
        if (q.f[j].alive) {
            memcpy(*faces + 3 * *nfaces, q.f[j].v, sizeof q.f[j].v);
            (*nfaces)++;
        }
    cf_free(t.f);
    cf_free(q.f);
    cf_free(q.next);
    cf_free(q.stack);
    cf_free(q.hor);
    return st;
}

bool
cf__hull3(const double *p, size_t n, const size_t t4[4], double eps,
          bool slow, size_t **faces, size_t *nf)
{
    hull_t h;
    step_t st = slow ? STEP_TANGLED : STEP_OK;
    *faces = NULL;
    *nf = 0;
    if (!slow)
        st = quickhull(p, n, t4, eps, faces, nf);
    if (st == STEP_OK)
        return true;
    if (st == STEP_NOMEM)
        return false;
    memset(&h, 0, sizeof h);
    if (!one_at_a_time(p, n, t4, eps, &h)) {
        cf_free(h.f);
        return false;
    }
    *faces = cf_alloc_array(3 * h.n + 1, sizeof **faces);
    if (*faces != NULL) {
        for (size_t i = 0; i < h.n; i++)
            memcpy(*faces + 3 * i, h.f[i].v, sizeof h.f[i].v);
        *nf = h.n;
    }
    cf_free(h.f);
    return *faces != NULL;
}

/* ---- the faces towards the viewer --------------------------------------- */

/* Whether face f of p faces the viewer of fig (its outside towards the
** eye, not edge-on). */
static bool
faces_viewer(const cf_figure_t *fig, const double *p, const size_t *f)
{
    const cf_view_t *v = &fig->view;
    double ab[3], ac[3], nrm[3], to[3];
    cf__sub3(p + 3 * f[1], p + 3 * f[0], ab);
    cf__sub3(p + 3 * f[2], p + 3 * f[0], ac);
    cf__cross3(ab, ac, nrm);
    if (v->projection == CF_PROJECTION_PERSPECTIVE) {
        for (int k = 0; k < 3; k++)
            to[k] = v->target[k] + v->distance * v->dir[k]
                - p[3 * f[0] + k];
    } else {
        memcpy(to, v->dir, sizeof to);
    }
    return cf__dot3(nrm, to) > 1e-12 * cf__norm3(nrm) * cf__norm3(to);
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
    double size = cf__points_size(p, n), d1, d2, d3 = 0, nn[3], ab[3], ac[3];
    size_t t4[4] = { 0, 0, 0, 0 };
    size_t *faces = NULL, nf = 0;
    cf_status_t st = outline_of(fig, p, n, outline, nout);
    if (st != CF_STATUS_OK)
        return st;
    t4[1] = cf__farthest(p, n, p, &d1);
    if (!(d1 > 1e-9 * size))
        return CF_STATUS_OK;               /* one point */
    t4[2] = cf__farthest_line(p, n, p, p + 3 * t4[1], &d2);
    if (!(d2 > 1e-9 * size))
        return CF_STATUS_OK;               /* a segment: the outline */
    cf__sub3(p + 3 * t4[1], p, ab);
    cf__sub3(p + 3 * t4[2], p, ac);
    cf__cross3(ab, ac, nn);
    for (size_t i = 0; i < n; i++) {
        double d[3], r;
        cf__sub3(p + 3 * i, p, d);
        r = fabs(cf__dot3(d, nn)) / cf__norm3(nn);
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
    if (!cf__hull3(p, n, t4, 1e-9 * size, false, &faces, &nf))
        return cf__fig_nomem(fig, "convex hull");
    for (size_t i = 0; i < nf && st == CF_STATUS_OK; i++)
        if (faces_viewer(fig, p, faces + 3 * i)
            && cf__tris_add(out, p + 3 * faces[3 * i],
                            p + 3 * faces[3 * i + 1],
                            p + 3 * faces[3 * i + 2]) != CF_STATUS_OK)
            st = cf__fig_nomem(fig, "convex hull");
    cf_free(faces);
    return st;
}
