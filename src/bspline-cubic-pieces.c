/*
** The Bézier pieces of a cubic B-spline (clamped or not) from the blossom:
** each piece's four points from its own four control points and six
** knots, independent of the other pieces.  A5.6 (bspline-ops.c, every
** other degree) makes a piece's first points while it finishes the one
** before, a chain of dependent operations through the whole curve; here
** the pieces are independent and the processor overlaps them.
**
** Span [a, b] = [u_k, u_{k+1}], control points P_{k-3} .. P_k, blossom f
** with P_i = f(u_{i+1}, u_{i+2}, u_{i+3}); f is affine in each argument.
**   f(a, a, b) = lerp(P_{k-2}, P_{k-1}, (a - u_{k-1}) / (u_{k+2} - u_{k-1}))
**   f(a, b, b) = lerp(P_{k-2}, P_{k-1}, (b - u_{k-1}) / (u_{k+2} - u_{k-1}))
**   L = f(u_{k-1}, a, a) = lerp(P_{k-3}, P_{k-2}, (a - u_{k-2}) / (b - u_{k-2}))
**   f(a, a, a) = lerp(L, f(a, a, b), (a - u_{k-1}) / (b - u_{k-1}))
**   R = f(b, b, u_{k+2}) = lerp(P_{k-1}, P_k, (b - a) / (u_{k+3} - a))
**   f(b, b, b) = lerp(f(a, b, b), R, (b - a) / (u_{k+2} - a))
** with lerp(x, y, t) = (1 - t) x + t y.  Every denominator is at least
** b - a > 0, whatever the multiplicities (a knot of multiplicity 3 or 4
** gives t = 0 or 1, exactly the control point).  A piece ends where the
** next begins (the same value, stored twice) unless its end knot has
** multiplicity 4, where the curve may jump: then, and for the last piece,
** f(b, b, b) comes from the right formula.
*/
#include "bspline-private.h"

/* Pieces of spans first .. last into Q (piece s at Q + s * stride: four
** points of hd doubles), break parameters into breaks (may be NULL). */
CF__INLINE void
pieces(const double *U, const double *P, size_t first, size_t last,
       size_t hd, double *Q, size_t stride, double *breaks)
{
    double *prev = NULL;
    size_t s = 0;
    for (size_t k = first; k <= last; k++) {
        double a = U[k], b = U[k + 1], um1 = U[k - 1], um2 = U[k - 2];
        double d1 = U[k + 2] - um1, t1, t2, t3, t4;
        const double *p0 = P + (k - 3) * hd, *p1 = p0 + hd, *p2 = p1 + hd;
        double *q = Q + s * stride;
        if (!(a < b))
            continue;
        t1 = (a - um1) / d1;
        t2 = (b - um1) / d1;
        t3 = (a - um2) / (b - um2);
        t4 = (a - um1) / (b - um1);
        for (size_t d = 0; d < hd; d++) {
            double i1 = (1.0 - t1) * p1[d] + t1 * p2[d];
            double L = (1.0 - t3) * p0[d] + t3 * p1[d];
            q[d] = (1.0 - t4) * L + t4 * i1;
            q[hd + d] = i1;
            q[2 * hd + d] = (1.0 - t2) * p1[d] + t2 * p2[d];
        }
        if (prev != NULL)
            for (size_t d = 0; d < hd; d++)
                prev[3 * hd + d] = q[d];
        prev = q;
        if (k == last || b == U[k + 4]) {
            double tr = (b - a) / (U[k + 3] - a);
            double tb = (b - a) / (U[k + 2] - a);
            for (size_t d = 0; d < hd; d++) {
                double R = (1.0 - tr) * p2[d] + tr * p2[hd + d];
                q[3 * hd + d] = (1.0 - tb) * q[2 * hd + d] + tb * R;
            }
            prev = NULL;
        }
        if (breaks != NULL) {
            breaks[s] = a;
            breaks[s + 1] = b;
        }
        s++;
    }
}

#if defined(CF__HAVE_PAIRS)
/* The planar polynomial case, each point a pair of doubles: the same
** formulas, the same values (CF__LOOP_ALIGNED). */
CF__LOOP_ALIGNED __attribute__((noinline)) static void
pieces2(const double *U, const double *P, size_t first, size_t last,
        double *Q, size_t stride, double *breaks)
{
    double *prev = NULL;
    size_t s = 0;
    for (size_t k = first; k <= last; k++) {
        double a = U[k], b = U[k + 1], um1 = U[k - 1], um2 = U[k - 2];
        double d1 = U[k + 2] - um1;
        cf__v2 t12, t34, p0, p1, p2, i1, e;
        double *q = Q + s * stride;
        if (!(a < b))
            continue;
        t12 = (cf__v2){ a - um1, b - um1 } / (cf__v2){ d1, d1 };
        t34 = (cf__v2){ a - um2, a - um1 } / (cf__v2){ b - um2, b - um1 };
        p0 = CF__LOAD2(P + (k - 3) * 2);
        p1 = CF__LOAD2(P + (k - 2) * 2);
        p2 = CF__LOAD2(P + (k - 1) * 2);
        i1 = cf__lerp2(p1, p2, t12[0]);
        e = cf__lerp2(cf__lerp2(p0, p1, t34[0]), i1, t34[1]);
        CF__STORE2(q, e);
        CF__STORE2(q + 2, i1);
        CF__STORE2(q + 4, cf__lerp2(p1, p2, t12[1]));
        if (prev != NULL)
            CF__STORE2(prev + 6, e);
        prev = q;
        if (k == last || b == U[k + 4]) {
            cf__v2 R = cf__lerp2(p2, CF__LOAD2(P + k * 2),
                                 (b - a) / (U[k + 3] - a));
            CF__STORE2(q + 6, cf__lerp2(CF__LOAD2(q + 4), R,
                                        (b - a) / (U[k + 2] - a)));
            prev = NULL;
        }
        if (breaks != NULL) {
            breaks[s] = a;
            breaks[s + 1] = b;
        }
        s++;
    }
}
#endif

void
cf__bspline_cubic_pieces(const cf_bspline_t *c, double *Q, size_t stride,
                         double *breaks)
{
    const double *U = c->U, *P = c->P;
    size_t first = c->first_span, last = c->last_span;
#if defined(CF__HAVE_PAIRS)
    if (c->hdim == 2) {
        pieces2(U, P, first, last, Q, stride, breaks);
        return;
    }
#endif
    if (c->hdim == 3)
        pieces(U, P, first, last, 3, Q, stride, breaks);
    else
        pieces(U, P, first, last, c->hdim, Q, stride, breaks);
}
