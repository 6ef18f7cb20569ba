/* Painting order of facets: a BSP tree on their planes, facets split by
** the planes they cross, traversed back to front (vis-private.h). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "vis-private.h"

typedef struct node {
    double n[3], c;        /* plane n . x = c of the splitter */
    size_t *on;            /* facets in the plane */
    size_t non;
    long front, back;      /* children, -1 for none */
} node_t;

typedef struct task {
    size_t *list;
    size_t count;
    long *slot;            /* where the new node's index goes */
    long slot_node;        /* node owning the slot (-1: the root) */
    int side;              /* 0 front, 1 back */
} task_t;

typedef struct bsp {
    cf__facet_buf_t *fb;
    node_t *nodes;
    size_t nnodes, cap;
    double eps;
    size_t splits;
} bsp_t;

static void
plane(const cf_facet_t *f, double *n, double *c)
{
    const double *a = f->p, *b = f->p + 3, *d = f->p + 6;
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double v[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (len > 0.0)
        for (int k = 0; k < 3; k++)
            n[k] /= len;
    *c = n[0] * a[0] + n[1] * a[1] + n[2] * a[2];
}

/* A point of a facet between corners i and j at fraction t (position,
** normal, parameters), into vertex slot k of out. */
static void
mix(const cf_facet_t *f, int i, int j, double t, cf_facet_t *out, int k)
{
    double len = 0.0;
    for (int e = 0; e < 3; e++) {
        out->p[3 * k + e] = f->p[3 * i + e] + t * (f->p[3 * j + e] - f->p[3 * i + e]);
        out->normal[3 * k + e] = f->normal[3 * i + e] +
                                 t * (f->normal[3 * j + e] - f->normal[3 * i + e]);
        len += out->normal[3 * k + e] * out->normal[3 * k + e];
    }
    len = sqrt(len);
    if (len > 0.0)
        for (int e = 0; e < 3; e++)
            out->normal[3 * k + e] /= len;
    for (int e = 0; e < 2; e++)
        out->uv[2 * k + e] = f->uv[2 * i + e] + t * (f->uv[2 * j + e] - f->uv[2 * i + e]);
}

/* Append a facet (copy of proto with new corners); its index. */
static cf_status_t
append(cf__facet_buf_t *fb, const cf_facet_t *f, size_t *idx)
{
    cf_facet_t *it = cf__grow(fb->items, &fb->cap, fb->n + 1, sizeof *it, 64);
    if (it == NULL)
        return CF_STATUS_NO_MEMORY;
    fb->items = it;
    it[fb->n] = *f;
    *idx = fb->n++;
    return CF_STATUS_OK;
}

/*
** Split facet fi by the plane (distances d[3] of its corners): the pieces
** on each side as triangles (a fan of the polygon), indices into fr / bk
** (room for 2 each), their numbers into nf / nb.
*/
static cf_status_t
split(bsp_t *b, size_t fi, const double *d, size_t *fr, size_t *nf,
      size_t *bk, size_t *nb)
{
    int cnt[2] = {0, 0};
    cf_facet_t pv[2][4];       /* the two polygons, a corner each */
    const cf_facet_t f = b->fb->items[fi];
    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3;
        int si = d[i] > 0.0 ? 0 : 1;
        /* corner i on its side (on the plane: both) */
        for (int s = 0; s < 2; s++)
            if (d[i] == 0.0 || s == si) {
                pv[s][cnt[s]] = f;
                mix(&f, i, i, 0.0, &pv[s][cnt[s]], 0);
                cnt[s]++;
            }
        if ((d[i] > 0.0 && d[j] < 0.0) || (d[i] < 0.0 && d[j] > 0.0)) {
            double t = d[i] / (d[i] - d[j]);
            for (int s = 0; s < 2; s++) {
                pv[s][cnt[s]] = f;
                mix(&f, i, j, t, &pv[s][cnt[s]], 0);
                cnt[s]++;
            }
        }
    }
    size_t *outs[2] = {fr, bk}, *ns[2] = {nf, nb};
    for (int s = 0; s < 2; s++) {
        *ns[s] = 0;
        for (int k = 1; k + 1 < cnt[s]; k++) {
            cf_facet_t t = f;
            memcpy(t.p, pv[s][0].p, 3 * sizeof(double));
            memcpy(t.p + 3, pv[s][k].p, 3 * sizeof(double));
            memcpy(t.p + 6, pv[s][k + 1].p, 3 * sizeof(double));
            memcpy(t.normal, pv[s][0].normal, 3 * sizeof(double));
            memcpy(t.normal + 3, pv[s][k].normal, 3 * sizeof(double));
            memcpy(t.normal + 6, pv[s][k + 1].normal, 3 * sizeof(double));
            memcpy(t.uv, pv[s][0].uv, 2 * sizeof(double));
            memcpy(t.uv + 2, pv[s][k].uv, 2 * sizeof(double));
            memcpy(t.uv + 4, pv[s][k + 1].uv, 2 * sizeof(double));
            size_t idx;
            cf_status_t st = append(b->fb, &t, &idx);
            if (st != CF_STATUS_OK)
                return st;
            outs[s][(*ns[s])++] = idx;
        }
    }
    b->splits++;
    return CF_STATUS_OK;
}

static cf_status_t
new_node(bsp_t *b, long *idx)
{
    node_t *nd = cf__grow(b->nodes, &b->cap, b->nnodes + 1, sizeof *nd, 64);
    if (nd == NULL)
        return CF_STATUS_NO_MEMORY;
    b->nodes = nd;
    memset(&nd[b->nnodes], 0, sizeof *nd);
    nd[b->nnodes].front = nd[b->nnodes].back = -1;
    *idx = (long)b->nnodes++;
    return CF_STATUS_OK;
}

/* Signed distances of facet f's corners from plane (n, c), eps as 0;
** the sides it has corners on. */
static void
sides(const cf_facet_t *f, const double *n, double c, double eps, double *d,
      bool *pos, bool *neg)
{
    *pos = *neg = false;
    for (int k = 0; k < 3; k++) {
        d[k] = n[0] * f->p[3 * k] + n[1] * f->p[3 * k + 1] +
               n[2] * f->p[3 * k + 2] - c;
        if (fabs(d[k]) <= eps)
            d[k] = 0.0;
        *pos |= d[k] > 0.0;
        *neg |= d[k] < 0.0;
    }
}

/* One node from a task.  The splitter: of 8 candidates spread over the
** list, the one that cuts the fewest of 64 facets sampled from it (then
** the most even sides). */
static cf_status_t
build_node(bsp_t *b, task_t *t, task_t *kids, int *nkids)
{
    cf_status_t st;
    long ni;
    size_t best = 0;
    double bscore = HUGE_VAL;
    size_t nc = t->count < 8 ? t->count : 8;
    size_t stride = t->count / 64 + 1;
    *nkids = 0;
    for (size_t ci = 0; ci < nc; ci++) {
        size_t cand = ci * t->count / nc;
        double n[3], c, d[3];
        long cut = 0, fr = 0, bk = 0;
        plane(&b->fb->items[t->list[cand]], n, &c);
        for (size_t i = 0; i < t->count; i += stride) {
            bool pos, neg;
            sides(&b->fb->items[t->list[i]], n, c, b->eps, d, &pos, &neg);
            cut += pos && neg;
            fr += pos && !neg;
            bk += neg && !pos;
        }
        double score = 8.0 * (double)cut + fabs((double)(fr - bk)) * 0.5;
        if (score < bscore) {
            bscore = score;
            best = cand;
        }
    }
    if ((st = new_node(b, &ni)) != CF_STATUS_OK)
        return st;
    if (t->slot_node >= 0) {
        if (t->side == 0)
            b->nodes[t->slot_node].front = ni;
        else
            b->nodes[t->slot_node].back = ni;
    }
    node_t *nd = &b->nodes[ni];
    plane(&b->fb->items[t->list[best]], nd->n, &nd->c);
    double pn[3] = {nd->n[0], nd->n[1], nd->n[2]}, pc = nd->c;
    size_t *lists[3];
    size_t counts[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++) {
        lists[k] = cf__alloc_array(2 * t->count + 2, sizeof(size_t));
        if (lists[k] == NULL) {
            for (int j = 0; j < k; j++)
                cf__free(lists[j]);
            return CF_STATUS_NO_MEMORY;
        }
    }
    st = CF_STATUS_OK;
    for (size_t i = 0; i < t->count && st == CF_STATUS_OK; i++) {
        size_t fi = t->list[i];
        double d[3];
        bool pos, neg;
        sides(&b->fb->items[fi], pn, pc, b->eps, d, &pos, &neg);
        if (i == best || (!pos && !neg))
            lists[2][counts[2]++] = fi;
        else if (!neg)
            lists[0][counts[0]++] = fi;
        else if (!pos)
            lists[1][counts[1]++] = fi;
        else {
            size_t fr[2], bk[2], nf, nb;
            st = split(b, fi, d, fr, &nf, bk, &nb);
            for (size_t k = 0; k < nf && st == CF_STATUS_OK; k++)
                lists[0][counts[0]++] = fr[k];
            for (size_t k = 0; k < nb && st == CF_STATUS_OK; k++)
                lists[1][counts[1]++] = bk[k];
        }
    }
    nd = &b->nodes[ni];
    nd->on = lists[2];
    nd->non = counts[2];
    for (int s = 0; s < 2; s++) {
        if (counts[s] == 0 || st != CF_STATUS_OK) {
            cf__free(lists[s]);
            continue;
        }
        kids[*nkids].list = lists[s];
        kids[*nkids].count = counts[s];
        kids[*nkids].slot_node = ni;
        kids[*nkids].side = s;
        (*nkids)++;
    }
    return st;
}

/* Whether the viewer is on the front side of node nd's plane. */
static bool
viewer_front(const cf_view_t *v, const node_t *nd)
{
    if (v->projection == CF_PROJECTION_PERSPECTIVE)
        return nd->n[0] * v->eye[0] + nd->n[1] * v->eye[1] +
                   nd->n[2] * v->eye[2] > nd->c;
    return nd->n[0] * v->dir[0] + nd->n[1] * v->dir[1] +
               nd->n[2] * v->dir[2] > 0.0;
}

cf_status_t
cf__bsp_order(cf__facet_buf_t *fb, const cf_view_t *view, double eps,
              size_t **order, size_t *norder, size_t *splits)
{
    bsp_t b;
    cf_status_t st = CF_STATUS_OK;
    task_t *tasks = NULL;
    size_t ntasks = 0, tcap = 0;
    size_t *ord = NULL, ocap = 0, no = 0;
    memset(&b, 0, sizeof b);
    b.fb = fb;
    b.eps = eps;
    *order = NULL;
    *norder = 0;
    if (fb->n == 0)
        return CF_STATUS_OK;
    tasks = cf__grow(NULL, &tcap, 1, sizeof *tasks, 64);
    if (tasks == NULL)
        return CF_STATUS_NO_MEMORY;
    tasks[0].list = cf__alloc_array(fb->n, sizeof(size_t));
    if (tasks[0].list == NULL) {
        cf__free(tasks);
        return CF_STATUS_NO_MEMORY;
    }
    for (size_t i = 0; i < fb->n; i++)
        tasks[0].list[i] = i;
    tasks[0].count = fb->n;
    tasks[0].slot_node = -1;
    tasks[0].side = 0;
    ntasks = 1;
    while (ntasks > 0) {
        task_t t = tasks[--ntasks], kids[2];
        int nk = 0;
        if (st == CF_STATUS_OK)
            st = build_node(&b, &t, kids, &nk);
        cf__free(t.list);
        task_t *g = cf__grow(tasks, &tcap, ntasks + 2, sizeof *tasks, 64);
        if (g == NULL) {
            st = CF_STATUS_NO_MEMORY;
            for (int k = 0; k < nk; k++)
                cf__free(kids[k].list);
            continue;
        }
        tasks = g;
        for (int k = 0; k < nk; k++)
            tasks[ntasks++] = kids[k];
    }
    cf__free(tasks);
    /* back to front: an explicit stack of (node, stage) */
    if (st == CF_STATUS_OK && b.nnodes > 0) {
        long *stk = cf__alloc_array(2 * b.nnodes + 2, sizeof(long));
        size_t top = 0;
        if (stk == NULL)
            st = CF_STATUS_NO_MEMORY;
        else
            stk[top++] = 0;
        while (st == CF_STATUS_OK && top > 0) {
            long x = stk[--top];
            if (x < 0) {
                /* emit the facets of node -x - 1 */
                const node_t *nd = &b.nodes[-x - 1];
                size_t *g = cf__grow(ord, &ocap, no + nd->non, sizeof *ord, 64);
                if (g == NULL) {
                    st = CF_STATUS_NO_MEMORY;
                    break;
                }
                ord = g;
                memcpy(ord + no, nd->on, nd->non * sizeof *ord);
                no += nd->non;
                continue;
            }
            const node_t *nd = &b.nodes[x];
            bool vf = viewer_front(view, nd);
            long first = vf ? nd->back : nd->front,
                 last = vf ? nd->front : nd->back;
            /* pushed in reverse: last, the node, first */
            if (last >= 0)
                stk[top++] = last;
            stk[top++] = -x - 1;
            if (first >= 0)
                stk[top++] = first;
        }
        cf__free(stk);
    }
    for (size_t i = 0; i < b.nnodes; i++)
        cf__free(b.nodes[i].on);
    cf__free(b.nodes);
    if (st != CF_STATUS_OK) {
        cf__free(ord);
        return st;
    }
    *order = ord;
    *norder = no;
    *splits = b.splits;
    return CF_STATUS_OK;
}
