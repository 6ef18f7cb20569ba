/* Leaves that cannot hold a hit: Newton on them left out, by subdivision
** of their nets (vis-private.h, cf__leaf_clear). */
#include <math.h>
#include <string.h>

#include "vis-private.h"

/* Degrees each way the test takes (the nets live on the stack), pieces
** looked at per call, the deepest halving, and the level from which a
** piece that may hold q and lies all in front ends the test (most likely
** a hit, which Newton finds: the cost of a sweep of views is flat from 1
** to 8). */
#define CLEAR_DEG 3
#define CLEAR_NODES 48
#define CLEAR_DEPTH 16
#define CLEAR_FRONT 6
#define CLEAR_NET ((CLEAR_DEG + 1) * (CLEAR_DEG + 1) * 4)

/* Halves at 1/2 of the 4 curves of a bicubic net (4-homogeneous) whose
** points lie `stride` doubles apart, curves `step` apart; inlined with
** constant strides for each direction. */
CF__INLINE void
split3(const double *net, size_t step, size_t stride, double *lo, double *hi)
{
    for (size_t j = 0; j < 4; j++)
        for (size_t e = 0; e < 4; e++) {
            const double *x = net + j * step + e;
            double *a = lo + j * step + e, *b = hi + j * step + e;
            double p0 = x[0], p1 = x[stride], p2 = x[2 * stride],
                   p3 = x[3 * stride];
            double q0 = 0.5 * (p0 + p1), q1 = 0.5 * (p1 + p2),
                   q2 = 0.5 * (p2 + p3);
            double r0 = 0.5 * (q0 + q1), r1 = 0.5 * (q1 + q2);
            double mid = 0.5 * (r0 + r1);
            a[0] = p0;
            a[stride] = q0;
            a[2 * stride] = r0;
            a[3 * stride] = mid;
            b[0] = mid;
            b[stride] = r1;
            b[2 * stride] = q2;
            b[3 * stride] = p3;
        }
}

/* A net of degrees (m, n) halved in s (dir 0) or t. */
CF__NO_COVERAGE static void
split(const double *net, int m, int n, int dir, double *lo, double *hi)
{
    if (m == 3 && n == 3 && dir == 0)
        split3(net, 4, 16, lo, hi);
    else if (m == 3 && n == 3)
        split3(net, 16, 4, lo, hi);
    else
        cf__vnet_split(net, m, n, dir, lo, hi);
}

/*
** Whether the view-space net of a piece (degrees m, n) holds no point
** whose image lies within e of q and, with depth, whose depth exceeds
** zmin - ez: the box of its Cartesian points and their range across the
** direction of its s sides in the image (every point of the piece lies in
** their hull, its weights positive), each widened by e.  *dir: the direction to halve it in
** (the longer sides in the image); false where a weight is not positive
** (nothing is concluded).
*/
CF__NO_COVERAGE static bool
piece_off(const double *net, int m, int n, const double *q, double zmin,
          bool depth, double e, double ez, int *dir, bool *off, bool *front)
{
    enum { NP = (CLEAR_DEG + 1) * (CLEAR_DEG + 1) };
    double c[NP][3], lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL},
                     hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    int np = (m + 1) * (n + 1);
    for (int i = 0; i < np; i++) {
        const double *x = net + 4 * i;
        if (!(x[3] > 0.0))
            return false;
        double r = 1.0 / x[3];
        for (int k = 0; k < 3; k++) {
            double v = x[k] * r;
            if (!isfinite(v))   /* a point at infinity: nothing concluded */
                return false;
            c[i][k] = v;
            lo[k] = v < lo[k] ? v : lo[k];
            hi[k] = v > hi[k] ? v : hi[k];
        }
    }
    const double *c00 = c[0], *c01 = c[n], *c10 = c[m * (n + 1)],
                 *c11 = c[m * (n + 1) + n];
    double sx = (c10[0] + c11[0]) - (c00[0] + c01[0]),
           sy = (c10[1] + c11[1]) - (c00[1] + c01[1]),
           tx = (c01[0] + c11[0]) - (c00[0] + c10[0]),
           ty = (c01[1] + c11[1]) - (c00[1] + c10[1]);
    *dir = sx * sx + sy * sy >= tx * tx + ty * ty ? 0 : 1;
    *off = true;
    *front = lo[2] - ez > zmin;
    if (q[0] < lo[0] - e || q[0] > hi[0] + e || q[1] < lo[1] - e ||
        q[1] > hi[1] + e || (depth && hi[2] + ez <= zmin))
        return true;
    /* across the s sides: the unit normal (-sy, sx) / |s| */
    double len = sqrt(sx * sx + sy * sy);
    if (len > 0.0 && isfinite(len)) {
        double nx = -sy / len, ny = sx / len, a = HUGE_VAL, b = -HUGE_VAL;
        for (int i = 0; i < np; i++) {
            double v = nx * c[i][0] + ny * c[i][1];
            a = v < a ? v : a;
            b = v > b ? v : b;
        }
        double v = nx * q[0] + ny * q[1];
        if (v < a - e || v > b + e)
            return true;
    }
    *off = false;
    return true;
}

CF__NO_COVERAGE bool
cf__leaf_clear(const cf_scene_t *sc, const cf__vleaf_t *l, const double *q,
               double zmin, bool depth)
{
    const cf__vpatch_t *p = &sc->patches[l->patch];
    int m = p->m, n = p->n;
    double stack[CLEAR_DEPTH + 2][CLEAR_NET];
    int level[CLEAR_DEPTH + 2];
    size_t top = 0;
    if (p->tri || m > CLEAR_DEG || n > CLEAR_DEG)
        return false;
    /* the leaf's region widened by twice in_region's slack of 1e-9 */
    const double slack = 2e-9;
    double a0 = l->r[0] - slack, a1 = l->r[1] + slack,
           b0 = l->r[2] - slack, b1 = l->r[3] + slack;
    size_t row = ((size_t)n + 1) * 4;
    double *net = stack[0];
    memcpy(net, p->g, (size_t)(m + 1) * row * sizeof(double));
    for (int j = 0; j <= n; j++)   /* curves in s: column j */
        cf__hcurve_part(net + 4 * j, m, row, a0, a1);
    for (int i = 0; i <= m; i++)   /* curves in t: row i */
        cf__hcurve_part(net + (size_t)i * row, n, 4, b0, b1);
    level[0] = 0;
    top = 1;
    /* Newton's point counts within 1e-9 of the scene's size of q
    ** (cf__vpatch_locate), a little more for the rounding of that test;
    ** and the rounding of the parts and halvings, of the divisions by the
    ** weights and of Newton's evaluation, a few units in the last place of
    ** the patch's largest coordinate over its least weight: 1e-11 of it */
    double big = 0.0, wmin = HUGE_VAL;
    for (size_t i = 0; i < (size_t)(m + 1) * ((size_t)n + 1); i++) {
        for (int k = 0; k < 3; k++)
            big = fabs(p->g[4 * i + k]) > big ? fabs(p->g[4 * i + k]) : big;
        wmin = p->g[4 * i + 3] < wmin ? p->g[4 * i + 3] : wmin;
    }
    if (!(wmin > 0.0) || !isfinite(big / wmin))
        return false;
    double ez = 1e-11 * (big / wmin),
           e = 1.001e-9 * fmax(sc->size, 1e-300) + ez;
    for (int seen = 0; top > 0; seen++) {
        int dir, lv;
        bool off, front;
        if (seen == CLEAR_NODES)
            return false;
        top--;
        net = stack[top];
        lv = level[top];
        if (!piece_off(net, m, n, q, zmin, depth, e, ez, &dir, &off, &front))
            return false;
        if (off)
            continue;
        /* a small piece all in front that may hold q: most likely a hit,
        ** which Newton finds */
        if (lv == CLEAR_DEPTH || (front && lv >= CLEAR_FRONT))
            return false;
        /* the halves over this slot and the next */
        double whole[CLEAR_NET];
        memcpy(whole, net, (size_t)(m + 1) * row * sizeof(double));
        split(whole, m, n, dir, stack[top], stack[top + 1]);
        level[top] = level[top + 1] = lv + 1;
        top += 2;
    }
    return true;
}
