/* Facets for shading: patches cut into uniform grids of triangles within a
** tolerance, in painting order (curvefig/visibility.h). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "numtext-private.h"
#include "vis-private.h"

/* At most 2^MAX_LEVEL cells per direction of a patch, and MAX_FACETS
** before the ordering: a facet is 264 bytes, held twice (before and
** after ordering), so 10^6 facets are about half a gigabyte. */
#define MAX_LEVEL 7
#define MAX_FACETS 1000000

static size_t
tidx(int n, int i, int j)
{
    size_t r = (size_t)(n - i);
    return r * (r + 1) / 2 + (r - (size_t)j);
}

static double
norm3(const double *a)
{
    return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

/* |a - 2 b + c| and |a - b - c + d| of Cartesian points. */
static double
second(const double *a, const double *b, const double *c)
{
    double x[3];
    for (int k = 0; k < 3; k++)
        x[k] = a[k] - 2.0 * b[k] + c[k];
    return norm3(x);
}

static double
mixed(const double *a, const double *b, const double *c, const double *d)
{
    double x[3];
    for (int k = 0; k < 3; k++)
        x[k] = a[k] - b[k] - c[k] + d[k];
    return norm3(x);
}

/*
** Bounds of the second derivatives from the net: A >= |S_ss|, B >= |S_st|,
** C >= |S_tt| (polynomial patches; the Cartesian points of a rational one).
*/
static void
bounds(const cf__vpatch_t *p, const double *c, double *A, double *B,
       double *C)
{
    int m = p->m, n = p->n;
    *A = *B = *C = 0.0;
    if (!p->tri) {
        size_t r = (size_t)n + 1;
#define P(i, j) (c + 3 * ((size_t)(i) * r + (size_t)(j)))
        for (int i = 0; i <= m; i++)
            for (int j = 0; j <= n; j++) {
                if (i + 2 <= m)
                    *A = fmax(*A, second(P(i, j), P(i + 1, j), P(i + 2, j)));
                if (j + 2 <= n)
                    *C = fmax(*C, second(P(i, j), P(i, j + 1), P(i, j + 2)));
                if (i < m && j < n)
                    *B = fmax(*B, mixed(P(i + 1, j + 1), P(i + 1, j),
                                        P(i, j + 1), P(i, j)));
            }
#undef P
        *A *= m * (m - 1.0);
        *C *= n * (n - 1.0);
        *B *= (double)m * n;
        return;
    }
#define T(i, j) (c + 3 * tidx(n, (i), (j)))
    for (int i = 0; i <= n - 2; i++)
        for (int j = 0; j <= n - 2 - i; j++) {
            /* b_(i+2) j k - 2 b_(i+1) j (k+1) + b_i j (k+2), k = n-2-i-j */
            *A = fmax(*A, second(T(i + 2, j), T(i + 1, j), T(i, j)));
            *C = fmax(*C, second(T(i, j + 2), T(i, j + 1), T(i, j)));
            *B = fmax(*B, mixed(T(i + 1, j + 1), T(i + 1, j), T(i, j + 1),
                                T(i, j)));
        }
#undef T
    double f = n * (n - 1.0);
    *A *= f;
    *B *= f;
    *C *= f;
}

/* The bound of the two triangles of a cell hu x hv against the surface:
** bilinear interpolation error plus a quarter of the twist. */
static double
cell_error(double A, double B, double C, double hu, double hv)
{
    return (hu * hu * A + 2.0 * hu * hv * B + hv * hv * C) / 8.0 +
           hu * hv * B / 4.0;
}

static void
levels(const cf__vpatch_t *p, double tol, double *cart, int *la, int *lb)
{
    double A, B, C;
    size_t cnt = cf__vpatch_count(p);
    for (size_t i = 0; i < cnt; i++)
        for (int k = 0; k < 3; k++)
            cart[3 * i + k] = p->h[4 * i + k] / p->h[4 * i + 3];
    bounds(p, cart, &A, &B, &C);
    int a = 0, b = 0;
    while (cell_error(A, B, C, ldexp(1.0, -a), ldexp(1.0, -b)) > tol &&
           (a < MAX_LEVEL || b < MAX_LEVEL)) {
        double hu = ldexp(1.0, -a), hv = ldexp(1.0, -b);
        bool more_u = hu * hu * A + hu * hv * B >= hv * hv * C + hu * hv * B;
        if (p->tri) {
            a++;
            b++;
        } else if ((more_u && a < MAX_LEVEL) || b >= MAX_LEVEL) {
            a++;
        } else {
            b++;
        }
    }
    *la = a < MAX_LEVEL ? a : MAX_LEVEL;
    *lb = b < MAX_LEVEL ? b : MAX_LEVEL;
}

typedef struct vert {
    double p[3], n[3], uv[2];
    bool ok;
} vert_t;

static cf_status_t
tri_out(cf__facet_buf_t *fb, const vert_t *a, const vert_t *b,
        const vert_t *c, size_t surface, double tiny)
{
    const vert_t *v[3] = {a, b, c};
    double u[3], w[3], n[3];
    if (!a->ok || !b->ok || !c->ok)
        return CF_STATUS_OK;
    for (int k = 0; k < 3; k++) {
        u[k] = b->p[k] - a->p[k];
        w[k] = c->p[k] - a->p[k];
    }
    n[0] = u[1] * w[2] - u[2] * w[1];
    n[1] = u[2] * w[0] - u[0] * w[2];
    n[2] = u[0] * w[1] - u[1] * w[0];
    double len = norm3(n);
    if (!(len > tiny))
        return CF_STATUS_OK;
    cf_facet_t *it = cf__grow(fb->items, &fb->cap, fb->n + 1, sizeof *it, 256);
    if (it == NULL)
        return CF_STATUS_NO_MEMORY;
    fb->items = it;
    cf_facet_t *f = &it[fb->n++];
    memset(f, 0, sizeof *f);
    f->surface = surface;
    for (int i = 0; i < 3; i++) {
        bool has = norm3(v[i]->n) > 0.0;
        for (int k = 0; k < 3; k++) {
            f->p[3 * i + k] = v[i]->p[k];
            f->normal[3 * i + k] = has ? v[i]->n[k] : n[k] / len;
        }
        f->uv[2 * i] = v[i]->uv[0];
        f->uv[2 * i + 1] = v[i]->uv[1];
    }
    return CF_STATUS_OK;
}

/* The grid of patch p at levels (a, b) into fb. */
static cf_status_t
tessellate(const cf_scene_t *sc, const cf__vpatch_t *p, int a, int b,
           cf__facet_buf_t *fb)
{
    int ku = 1 << a, kv = p->tri ? ku : 1 << b;
    size_t rows = (size_t)kv + 1;
    vert_t *V = cf__alloc_array(((size_t)ku + 1) * rows, sizeof *V);
    cf_status_t st = CF_STATUS_OK;
    double tiny = 1e-14 * sc->size * sc->size;
    if (V == NULL)
        return CF_STATUS_NO_MEMORY;
    for (int i = 0; i <= ku; i++)
        for (int j = 0; j <= kv; j++) {
            vert_t *x = &V[(size_t)i * rows + (size_t)j];
            double s = (double)i / ku, t = (double)j / kv, D[18];
            x->ok = (!p->tri || i + j <= ku) &&
                    cf__vpatch_eval(p, p->h, s, t, 1, D);
            if (!x->ok)
                continue;
            memcpy(x->p, D, 3 * sizeof(double));
            x->n[0] = D[4] * D[8] - D[5] * D[7];
            x->n[1] = D[5] * D[6] - D[3] * D[8];
            x->n[2] = D[3] * D[7] - D[4] * D[6];
            double len = norm3(x->n);
            /* a vanishing normal (a pole) is left 0: the facet's is used */
            for (int k = 0; k < 3; k++)
                x->n[k] = len > 1e-12 * (norm3(D + 3) * norm3(D + 6))
                              ? x->n[k] / len
                              : 0.0;
            x->uv[0] = p->tri ? s : p->u0 + s * (p->u1 - p->u0);
            x->uv[1] = p->tri ? t : p->v0 + t * (p->v1 - p->v0);
        }
#define AT(i, j) (&V[(size_t)(i) * rows + (size_t)(j)])
    for (int i = 0; i < ku && st == CF_STATUS_OK; i++)
        for (int j = 0; j < kv && st == CF_STATUS_OK; j++) {
            if (p->tri) {
                if (i + j < ku)
                    st = tri_out(fb, AT(i, j), AT(i + 1, j), AT(i, j + 1),
                                 p->surface, tiny);
                if (st == CF_STATUS_OK && i + j < ku - 1)
                    st = tri_out(fb, AT(i + 1, j), AT(i + 1, j + 1),
                                 AT(i, j + 1), p->surface, tiny);
                continue;
            }
            st = tri_out(fb, AT(i, j), AT(i + 1, j), AT(i + 1, j + 1),
                         p->surface, tiny);
            if (st == CF_STATUS_OK)
                st = tri_out(fb, AT(i, j), AT(i + 1, j + 1), AT(i, j + 1),
                             p->surface, tiny);
        }
#undef AT
    cf__free(V);
    return st;
}

void
cf_facets_destroy(cf_facets_t *f)
{
    if (f == NULL)
        return;
    cf__free(f->items);
    cf__free(f);
}

/* Levels of every patch, the largest per surface, and the bound. */
static cf_status_t
all_levels(const cf_scene_t *sc, double tol, int *lv, double *dev)
{
    size_t maxcnt = 1;
    for (size_t i = 0; i < sc->npatch; i++) {
        size_t c = cf__vpatch_count(&sc->patches[i]);
        maxcnt = c > maxcnt ? c : maxcnt;
    }
    double *cart = cf__alloc_array(maxcnt, 3 * sizeof(double));
    if (cart == NULL)
        return CF_STATUS_NO_MEMORY;
    for (size_t s = 0; s < sc->nsurf; s++)
        lv[2 * s] = lv[2 * s + 1] = 0;
    for (size_t i = 0; i < sc->npatch; i++) {
        const cf__vpatch_t *p = &sc->patches[i];
        int a, b;
        levels(p, tol, cart, &a, &b);
        int *L = lv + 2 * p->surface;
        L[0] = a > L[0] ? a : L[0];
        L[1] = b > L[1] ? b : L[1];
    }
    *dev = 0.0;
    for (size_t i = 0; i < sc->npatch; i++) {
        const cf__vpatch_t *p = &sc->patches[i];
        double A, B, C, cnt = (double)cf__vpatch_count(p);
        for (size_t k = 0; k < (size_t)cnt; k++)
            for (int e = 0; e < 3; e++)
                cart[3 * k + e] = p->h[4 * k + e] / p->h[4 * k + 3];
        bounds(p, cart, &A, &B, &C);
        const int *L = lv + 2 * p->surface;
        *dev = fmax(*dev, cell_error(A, B, C, ldexp(1.0, -L[0]),
                                     ldexp(1.0, -(p->tri ? L[0] : L[1]))));
    }
    cf__free(cart);
    return CF_STATUS_OK;
}

cf_status_t
cf_scene_facets_tol(const cf_scene_t *sc, double tol, cf_facets_t **out,
                    cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_status_t st;
    cf__facet_buf_t fb = {NULL, 0, 0};
    cf_facets_t *res;
    size_t *order = NULL, norder = 0, splits = 0;
    int *lv;
    double dev;
    if (out == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "out is NULL");
    *out = NULL;
    if (sc == NULL)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1, "scene is NULL");
    if (isnan(tol) || isinf(tol))
        return cf__error(diag, CF_STATUS_NOT_FINITE, -1,
                         "tolerance %s is not finite", CF__NUM(tol));
    if (!(tol > 0.0) || tol < 1e-12 * sc->size)
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "tolerance %s must be positive and at least 1e-12 "
                         "of the scene's size %.3g", CF__NUM(tol), sc->size);
    res = cf__calloc(1, sizeof *res);
    lv = cf__alloc_array(2 * sc->nsurf + 2, sizeof *lv);
    if (res == NULL || lv == NULL) {
        cf__free(res);
        cf__free(lv);
        return cf__error(diag, CF_STATUS_NO_MEMORY, -1, "out of memory");
    }
    st = all_levels(sc, tol, lv, &dev);
    for (size_t i = 0; i < sc->npatch && st == CF_STATUS_OK; i++) {
        const cf__vpatch_t *p = &sc->patches[i];
        st = tessellate(sc, p, lv[2 * p->surface], lv[2 * p->surface + 1],
                        &fb);
    }
    cf__free(lv);
    if (st == CF_STATUS_OK && fb.n > MAX_FACETS) {
        size_t n = fb.n;
        cf__free(fb.items);
        cf_facets_destroy(res);
        return cf__error(diag, CF_STATUS_INVALID_ARG, -1,
                         "tolerance %s makes %zu facets, more than %d "
                         "(about %.0f MB): give a larger one", CF__NUM(tol), n,
                         MAX_FACETS, 2.0 * (double)n * sizeof *fb.items
                                         / 1e6);
    }
    if (st == CF_STATUS_OK)
        st = cf__facet_order(&fb, &sc->view, sc->M, 1e-9 * sc->size, &order,
                             &norder, &splits);
    if (st == CF_STATUS_OK && norder > 0) {
        res->items = cf__alloc_array(norder, sizeof *res->items);
        if (res->items == NULL)
            st = CF_STATUS_NO_MEMORY;
    }
    for (size_t i = 0; i < norder && st == CF_STATUS_OK; i++) {
        cf_facet_t *f = &res->items[i];
        double cen[3] = {0, 0, 0}, q[3], to[3], gn[3], u[3], w[3];
        *f = fb.items[order[i]];
        for (int k = 0; k < 3; k++) {
            if (!cf__view_apply(sc->M, f->p + 3 * k, q))
                q[0] = q[1] = q[2] = 0.0;
            f->image[2 * k] = q[0];
            f->image[2 * k + 1] = q[1];
            for (int e = 0; e < 3; e++)
                cen[e] += f->p[3 * k + e] / 3.0;
        }
        (void)cf_view_project(&sc->view, cen, q, &f->depth);
        for (int e = 0; e < 3; e++) {
            u[e] = f->p[3 + e] - f->p[e];
            w[e] = f->p[6 + e] - f->p[e];
        }
        gn[0] = u[1] * w[2] - u[2] * w[1];
        gn[1] = u[2] * w[0] - u[0] * w[2];
        gn[2] = u[0] * w[1] - u[1] * w[0];
        if (cf_view_towards_eye(&sc->view, cen, to) != CF_STATUS_OK)
            memcpy(to, sc->view.dir, sizeof to);
        f->front = gn[0] * to[0] + gn[1] * to[1] + gn[2] * to[2] > 0.0;
    }
    cf__free(order);
    cf__free(fb.items);
    if (st != CF_STATUS_OK) {
        cf_facets_destroy(res);
        return cf__error(diag, st, -1, "out of memory");
    }
    res->n = norder;
    res->splits = splits;
    res->deviation = dev;
    *out = res;
    return CF_STATUS_OK;
}

cf_status_t
cf_scene_facets(const cf_scene_t *sc, cf_facets_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    return cf_scene_facets_tol(sc, sc == NULL ? 1.0 : sc->tol, out, diag);
}
