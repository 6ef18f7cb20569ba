/* Lines of sight against the exact patches of a scene: is a point hidden
** (vis-private.h). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "vis-private.h"

/* Depth of a tree walk: the tree is balanced (halves), 2 log2 of 2^32. */
#define STACK 128

/* Newton of cf__vpatch_locate from (*s, *t) at step *it, paused before
** step `until` (< 40) with its state there: 1 converged, 0 failed, -1
** paused; resumed from the state, it takes the same steps as without the
** pause. */
enum { NEWTON_STEPS = 40, NEWTON_PAUSED = -1 };
/* Steps of a folding leaf's first start before its clearing is tried
** (cf__scene_hidden): 6, 10, 16 and 40 cost 1,523, 1,480, 1,485 and
** 1,532 M instructions over eight views of the interactive patch. */
#define CLEAR_AFTER 10

static int
newton(const cf_scene_t *sc, size_t ip, const double *img, double *sp,
       double *tp, int *itp, int until, double *st, double *q)
{
    const cf__vpatch_t *p = &sc->patches[ip];
    double D[18], s = *sp, t = *tp;
    double scale = cf__fmax(sc->size, 1e-300);
    for (int it = *itp; it < NEWTON_STEPS; it++) {
        if (it == until) {
            *sp = s;
            *tp = t;
            *itp = it;
            return NEWTON_PAUSED;
        }
        if (!cf__vpatch_eval(p, p->g, s, t, 1, D))
            return 0;
        double rx = img[0] - D[0], ry = img[1] - D[1];
        double det = D[3] * D[7] - D[6] * D[4];
        if (cf__hypot_le(rx, ry, 1e-13 * scale)) {
            st[0] = s;
            st[1] = t;
            memcpy(q, D, 3 * sizeof(double));
            return 1;
        }
        double jn = fabs(D[3]) + fabs(D[4]) + fabs(D[6]) + fabs(D[7]);
        if (!(fabs(det) > 1e-14 * jn * jn))
            return 0;
        double ds = (rx * D[7] - ry * D[6]) / det;
        double dt = (D[3] * ry - D[4] * rx) / det;
        /* damp long steps: the leaf is small in (s, t); hypot where the
        ** step may be longer than 1/2 (cf__hypot_le) */
        if (!(ds * ds + dt * dt < 0.25 * (1.0 - 1e-12))) {
            double len = hypot(ds, dt);
            if (len > 0.5) {
                ds *= 0.5 / len;
                dt *= 0.5 / len;
            }
        }
        s += ds;
        t += dt;
        if (!(s > -0.5 && s < 1.5 && t > -0.5 && t < 1.5))
            return 0;
        if (fabs(ds) + fabs(dt) <= 1e-15 && it > 2) {
            if (!cf__vpatch_eval(p, p->g, s, t, 0, D))
                return 0;
            if (cf__hypot_gt(img[0] - D[0], img[1] - D[1], 1e-9 * scale))
                return 0;
            st[0] = s;
            st[1] = t;
            memcpy(q, D, 3 * sizeof(double));
            return 1;
        }
    }
    return 0;
}

bool
cf__vpatch_locate(const cf_scene_t *sc, size_t ip, const double *img,
                  double s, double t, double *st, double *q)
{
    int it = 0;
    return newton(sc, ip, img, &s, &t, &it, NEWTON_STEPS, st, q) == 1;
}

/* Whether local (s, t) lies in the leaf's region (a little slack). */
static bool
in_region(const cf__vpatch_t *p, const cf__vleaf_t *l, const double *st)
{
    const double e = 1e-9;
    if (!p->tri)
        return st[0] >= l->r[0] - e && st[0] <= l->r[1] + e &&
               st[1] >= l->r[2] - e && st[1] <= l->r[3] + e;
    /* barycentric coordinates in the triangle r */
    const double *A = l->r, *B = l->r + 2, *C = l->r + 4;
    double det = (B[0] - A[0]) * (C[1] - A[1]) - (B[1] - A[1]) * (C[0] - A[0]);
    if (det == 0.0)
        return false;
    double b = ((st[0] - A[0]) * (C[1] - A[1]) -
                (st[1] - A[1]) * (C[0] - A[0])) / det;
    double c = ((B[0] - A[0]) * (st[1] - A[1]) -
                (B[1] - A[1]) * (st[0] - A[0])) / det;
    return b >= -e && c >= -e && b + c <= 1.0 + e;
}

/* Whether local (s, t) lies on the patch (a little slack). */
static bool
in_patch(const cf__vpatch_t *p, const double *st)
{
    const double e = 1e-9;
    if (p->tri)
        return st[0] >= -e && st[1] >= -e && st[0] + st[1] <= 1.0 + e;
    return st[0] >= -e && st[0] <= 1.0 + e && st[1] >= -e && st[1] <= 1.0 + e;
}

/* The local parameters of a leaf's centre and corners. */
static int
starts(const cf__vpatch_t *p, const cf__vleaf_t *l, double out[5][2])
{
    if (!p->tri) {
        double s[5][2] = {{0.5 * (l->r[0] + l->r[1]), 0.5 * (l->r[2] + l->r[3])},
                          {l->r[0], l->r[2]}, {l->r[1], l->r[2]},
                          {l->r[0], l->r[3]}, {l->r[1], l->r[3]}};
        memcpy(out, s, sizeof s);
        return 5;
    }
    out[0][0] = (l->r[0] + l->r[2] + l->r[4]) / 3.0;
    out[0][1] = (l->r[1] + l->r[3] + l->r[5]) / 3.0;
    for (int c = 0; c < 3; c++) {
        out[1 + c][0] = l->r[2 * c];
        out[1 + c][1] = l->r[2 * c + 1];
    }
    return 4;
}

/* A folding leaf in front of zmin no wider than tol: where Newton finds
** nothing on it, it hides the point (cf__scene_hidden). */
static bool
fold_small(const cf_scene_t *sc, const cf__vleaf_t *l, double zmin)
{
    return l->lo[2] > zmin &&
           cf__hypot_le(l->hi[0] - l->lo[0], l->hi[1] - l->lo[1], sc->tol);
}

bool
cf__scene_find(const cf_scene_t *sc, size_t surface, double u, double v,
               size_t *ip, double *s, double *t)
{
    if (surface >= sc->nsurf)
        return false;
    for (size_t i = sc->surf_first[surface]; i < sc->surf_first[surface + 1];
         i++) {
        const cf__vpatch_t *p = &sc->patches[i];
        if (p->tri) {
            *ip = i;
            *s = u;
            *t = v;
            return true;
        }
        double eu = 1e-12 * (fabs(p->u0) + fabs(p->u1) + 1.0),
               ev = 1e-12 * (fabs(p->v0) + fabs(p->v1) + 1.0);
        if (u >= p->u0 - eu && u <= p->u1 + eu && v >= p->v0 - ev &&
            v <= p->v1 + ev) {
            *ip = i;
            *s = (u - p->u0) / (p->u1 - p->u0);
            *t = (v - p->v0) / (p->v1 - p->v0);
            return true;
        }
    }
    return false;
}

/* Surface parameters of local (s, t) on patch p. */
static void
to_surface(const cf__vpatch_t *p, const double *st, double *uv)
{
    if (p->tri) {
        uv[0] = st[0];
        uv[1] = st[1];
        return;
    }
    uv[0] = p->u0 + st[0] * (p->u1 - p->u0);
    uv[1] = p->v0 + st[1] * (p->v1 - p->v0);
}

/*
** A hit on the point's own surface is the point's own sheet when the
** surface between them (the straight segment in (u, v)) stays on the line
** of sight within twice the point's offset from the surface: a grazing
** view of the surface the curve lies on.
*/
static bool
own_sheet(const cf_scene_t *sc, const cf__vself_t *self, const double *q,
          const double *uv)
{
    for (int k = 1; k < 16; k++) {
        double a = k / 16.0, s, t, D[18];
        size_t ip;
        if (!cf__scene_find(sc, self->surface,
                            self->uv[0] + a * (uv[0] - self->uv[0]),
                            self->uv[1] + a * (uv[1] - self->uv[1]), &ip, &s,
                            &t))
            return false;
        if (!cf__vpatch_eval(&sc->patches[ip], sc->patches[ip].g, s, t, 0, D))
            return false;
        if (cf__hypot_gt(D[0] - q[0], D[1] - q[1],
                         2.0 * self->offset + 1e-9 * sc->size))
            return false;
    }
    return true;
}

/* The depth margin at view-space depth zeta: tol in space, scaled by
** d zeta / d z for a perspective view. */
static double
margin(const cf_scene_t *sc, double zeta)
{
    if (sc->view.projection != CF_PROJECTION_PERSPECTIVE)
        return sc->tol;
    double D = sc->view.distance, f = (D + zeta) / D;
    return sc->tol * f * f;
}

bool
cf__scene_hidden(const cf_scene_t *sc, const double *q,
                 const cf__vself_t *self, size_t *occ)
{
    uint32_t stack[STACK];
    size_t top = 0;
    double zmin = q[2] + margin(sc, q[2]);
    double scale = cf__fmax(sc->size, 1e-300);
    if (sc->nnode == 0)
        return false;
    stack[top++] = 0;
    while (top > 0) {
        const cf__vnode_t *nd = &sc->nodes[stack[--top]];
        if (q[0] < nd->lo[0] || q[0] > nd->hi[0] || q[1] < nd->lo[1] ||
            q[1] > nd->hi[1] || nd->hi[2] <= zmin)
            continue;
        if (nd->count == 0) {
            if (top + 2 <= STACK) {
                stack[top++] = nd->first;
                stack[top++] = nd->first + 1;
            }
            continue;
        }
        for (uint32_t i = nd->first; i < nd->first + nd->count; i++) {
            const cf__vleaf_t *l = &sc->leaves[i];
            const cf__vpatch_t *p = &sc->patches[l->patch];
            double st0[5][2], st[2], h[3], uv[2];
            int ns, found = 0;
            bool again = true;
            if (q[0] < l->lo[0] || q[0] > l->hi[0] || q[1] < l->lo[1] ||
                q[1] > l->hi[1] || l->hi[2] <= zmin)
                continue;
            /* no Newton where it cannot find a point of the leaf: found
            ** stays 0, as Newton would leave it */
            ns = cf__leaf_may_hold(l, q, scale) ? starts(p, l, st0) : 0;
            for (int k = 0; k < ns && (l->fold || again); k++) {
                double s = st0[k][0], t = st0[k][1];
                int it = 0, r;
                again = false;
                /* a folding leaf: where q is not the image of any of its
                ** points, Newton runs out its steps from every start; so
                ** when its first start has not converged within
                ** CLEAR_AFTER steps, the leaf is left out where no start
                ** can find a point that counts (none that hides q; where
                ** the leaf is all in front, none at all: whether one was
                ** found decides below), that start's steps to come too */
                if (k == 0 && l->fold && !sc->newton_all) {
                    r = newton(sc, l->patch, q, &s, &t, &it, CLEAR_AFTER, st,
                               h);
                    if (r != 1 && cf__leaf_clear(sc, l, q, zmin,
                                                 !fold_small(sc, l, zmin)))
                        break;
                    if (r == NEWTON_PAUSED)
                        r = newton(sc, l->patch, q, &s, &t, &it,
                                   NEWTON_STEPS, st, h);
                } else {
                    r = newton(sc, l->patch, q, &s, &t, &it, NEWTON_STEPS,
                               st, h);
                }
                if (r != 1)
                    continue;
                if (!in_region(p, l, st)) {
                    /* off the patch (its continuation past an edge): the
                    ** corners may still find the hit in the leaf */
                    again = !in_patch(p, st);
                    continue;
                }
                found++;
                if (h[2] <= zmin)
                    continue;
                to_surface(p, st, uv);
                if (self != NULL && self->has &&
                    self->surface == p->surface && own_sheet(sc, self, q, uv))
                    continue;
                if (occ != NULL)
                    *occ = p->surface;
                return true;
            }
            /* a folding leaf no wider than tol where Newton found nothing:
            ** decided by its middle */
            if (l->fold && found == 0 && fold_small(sc, l, zmin)) {
                if (occ != NULL)
                    *occ = p->surface;
                return true;
            }
        }
    }
    return false;
}

/* The box (u0 u1 v0 v1) of the parameters of leaf l on its surface (a
** triangle's: its corners'). */
static void
leaf_uv(const cf__vpatch_t *p, const cf__vleaf_t *l, double *b)
{
    if (p->tri) {
        b[0] = cf__fmin(l->r[0], cf__fmin(l->r[2], l->r[4]));
        b[1] = cf__fmax(l->r[0], cf__fmax(l->r[2], l->r[4]));
        b[2] = cf__fmin(l->r[1], cf__fmin(l->r[3], l->r[5]));
        b[3] = cf__fmax(l->r[1], cf__fmax(l->r[3], l->r[5]));
        return;
    }
    b[0] = p->u0 + l->r[0] * (p->u1 - p->u0);
    b[1] = p->u0 + l->r[1] * (p->u1 - p->u0);
    b[2] = p->v0 + l->r[2] * (p->v1 - p->v0);
    b[3] = p->v0 + l->r[3] * (p->v1 - p->v0);
}

/* Whether the boxes a and b (u0 u1 v0 v1) meet, b widened by w[2] and a
** little slack. */
static bool
uv_meet(const double *a, const double *b, const double *w)
{
    double eu = w[0] + 1e-9 * (fabs(b[0]) + fabs(b[1]) + 1.0),
           ev = w[1] + 1e-9 * (fabs(b[2]) + fabs(b[3]) + 1.0);
    return a[0] <= b[1] + eu && a[1] >= b[0] - eu && a[2] <= b[3] + ev &&
           a[3] >= b[2] - ev;
}

/* The leaves of the curve's own surface near its part, in
** cf__scene_box_clear_on: those that meet the part's (u, v) box, the
** widest of them in u and in v, the way they turn, and the others in front
** to be judged against the box widened by that width. */
typedef struct near_own {
    const double *uv;
    double w[2];
    int orient;
    bool strict;
    size_t nlater;
    uint32_t later[64];
} near_own_t;

/* Whether own leaf l may be left out: it meets the box (widened by w) and
** does not fold and turns as the others (strict). */
static bool
own_ok(const cf_scene_t *sc, near_own_t *no, uint32_t i, const double *w)
{
    const cf__vleaf_t *l = &sc->leaves[i];
    double b[4];
    leaf_uv(&sc->patches[l->patch], l, b);
    if (!uv_meet(b, no->uv, w))
        return false;
    if (no->strict) {
        if (l->orient == 0 || (no->orient != 0 && l->orient != no->orient))
            return false;
        no->orient = l->orient;
    }
    return true;
}

bool
cf__scene_box_clear_on(const cf_scene_t *sc, const double *lo,
                       const double *hi, size_t surface, const double *uv,
                       bool strict)
{
    uint32_t stack[STACK];
    size_t top = 0;
    const double zero[2] = {0.0, 0.0};
    near_own_t no = {uv, {0.0, 0.0}, 0, strict, 0, {0}};
    /* pieces in front of the box by more than the margin may hide it; the
    ** pieces of the curve's own surface that reach the box's depth at all
    ** are looked at, since the part's points lie on some of them */
    double zmin = lo[2] + margin(sc, lo[2]);
    double zown = surface == SIZE_MAX ? zmin : lo[2];
    if (sc->nnode == 0)
        return true;
    stack[top++] = 0;
    while (top > 0) {
        const cf__vnode_t *nd = &sc->nodes[stack[--top]];
        if (nd->hi[0] < lo[0] || nd->lo[0] > hi[0] || nd->hi[1] < lo[1] ||
            nd->lo[1] > hi[1] || nd->hi[2] < zown)
            continue;
        if (nd->count == 0) {
            if (top + 2 > STACK)
                return false;
            stack[top++] = nd->first;
            stack[top++] = nd->first + 1;
            continue;
        }
        for (uint32_t i = nd->first; i < nd->first + nd->count; i++) {
            const cf__vleaf_t *l = &sc->leaves[i];
            const cf__vpatch_t *p = &sc->patches[l->patch];
            double b[4];
            if (l->hi[0] < lo[0] || l->lo[0] > hi[0] || l->hi[1] < lo[1] ||
                l->lo[1] > hi[1] || l->hi[2] < zown)
                continue;
            if (p->surface == surface) {
                leaf_uv(p, l, b);
                if (uv_meet(b, uv, zero)) {
                    if (!own_ok(sc, &no, i, zero))
                        return false;
                    no.w[0] = cf__fmax(no.w[0], b[1] - b[0]);
                    no.w[1] = cf__fmax(no.w[1], b[3] - b[2]);
                    continue;
                }
                if (l->hi[2] > zmin) {
                    /* a neighbour: judged once the width is known */
                    if (no.nlater == sizeof no.later / sizeof no.later[0])
                        return false;
                    no.later[no.nlater++] = i;
                }
                continue;
            }
            if (l->hi[2] > zmin)
                return false;
        }
    }
    for (size_t j = 0; j < no.nlater; j++)
        if (!own_ok(sc, &no, no.later[j], no.w))
            return false;
    return true;
}

bool
cf__scene_box_clear(const cf_scene_t *sc, const double *lo, const double *hi)
{
    return cf__scene_box_clear_on(sc, lo, hi, SIZE_MAX, NULL, false);
}
