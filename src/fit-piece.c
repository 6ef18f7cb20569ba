/*
** The fitting strategies of one offset piece: Levien's area and moment fit
** with its candidates, Tiller-Hanson, and the search of both arms of a
** piece that ends at an offset cusp; every candidate judged by its
** measured error (fit-source.c).
*/
#include <math.h>
#include <string.h>

#include "core-private.h"
#include "bezier-private.h"
#include "fit-private.h"

/* ---- Levien's fit --------------------------------------------------------- */

/* c + x d0 + y d1 */
typedef struct lin3 {
    double c, x, y;
} lin3;

/* bivariate polynomial q[p][r] of d0^p d1^r, p + r <= 3 */
typedef struct biv {
    double q[4][4];
} biv;

static void
biv_add_prod(biv *out, double w, const lin3 *f, const lin3 *g,
             const lin3 *h)
{
    double a[3] = { f->c, f->x, f->y }, b[3] = { g->c, g->x, g->y };
    double cc[3] = { 1.0, 0.0, 0.0 };
    static const int dp[3] = { 0, 1, 0 }, dr[3] = { 0, 0, 1 };
    if (h != NULL) {
        cc[0] = h->c;
        cc[1] = h->x;
        cc[2] = h->y;
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            for (int l = 0; l < (h != NULL ? 3 : 1); l++)
                out->q[dp[i] + dp[j] + dp[l]][dr[i] + dr[j] + dr[l]] +=
                    w * a[i] * b[j] * cc[l];
}

/* power polynomials, coefficient k of x^k, degree <= 9 */
static void
pp_mul(const double *a, int m, const double *b, int n, double *out)
{
    for (int k = 0; k <= m + n; k++)
        out[k] = 0.0;
    for (int i = 0; i <= m; i++)
        for (int j = 0; j <= n; j++)
            out[i + j] += a[i] * b[j];
}

#define ARM_MAX 4.0     /* arms longer than 4 chords are not considered */
#define MAX_CAND 16

typedef struct frame {
    double p0[2], p3[2], e[2], L;
} frame;

static void
to_frame(const frame *f, const double *p, double *out)
{
    double dx = p[0] - f->p0[0], dy = p[1] - f->p0[1];
    out[0] = (dx * f->e[0] + dy * f->e[1]) / f->L;
    out[1] = (f->e[0] * dy - f->e[1] * dx) / f->L;
}

static void
vec_to_frame(const frame *f, const double *v, double *out)
{
    out[0] = (v[0] * f->e[0] + v[1] * f->e[1]) / f->L;
    out[1] = (f->e[0] * v[1] - f->e[1] * v[0]) / f->L;
}

/* Signed area between the source on [a, b] and its chord, and its
** x-moment, in the normalised frame: A = int (x y' - y x') / 2,
** M = int x^2 y' / 2 (Green; the chord y = 0 adds nothing).  Composite
** 8-point Gauss-Legendre on 4 sub-intervals. */
static void
source_area_moment(const cf__osrc_t *s, double a, double b, const frame *f,
                   double *area, double *moment)
{
    static const double gx[4] = { 0.1834346424956498, 0.5255324099163290,
                                  0.7966664774136267, 0.9602898564975363 };
    static const double gw[4] = { 0.3626837833783620, 0.3137066458778873,
                                  0.2223810344533745, 0.1012285362903763 };
    const int nsub = 4;
    double A = 0.0, M = 0.0, h = (b - a) / nsub;
    for (int k = 0; k < nsub; k++) {
        double mid = a + h * (k + 0.5);
        for (int i = 0; i < 8; i++) {
            double xi = (i < 4 ? -gx[i] : gx[i - 4]);
            double w = gw[i < 4 ? i : i - 4] * 0.5 * h;
            double t = mid + 0.5 * h * xi, p[2], dp[2], q[2], dq[2];
            cf__osrc_deriv(s, t, p, dp);
            to_frame(f, p, q);
            vec_to_frame(f, dp, dq);
            A += w * 0.5 * (q[0] * dq[1] - q[1] * dq[0]);
            M += w * 0.5 * q[0] * q[0] * dq[1];
        }
    }
    *area = A;
    *moment = M;
}

/* Area and moment of the normalised cubic (0,0), d0 u0, (1,0) - d1 u1,
** (1,0) as polynomials in d0, d1 (exact integrals of Bernstein products:
** int B_i^m B_j^n B_k^p = C(m,i) C(n,j) C(p,k) / (C(m+n+p, i+j+k)
** (m+n+p+1))). */
static void
cubic_area_moment(const double *u0, const double *u1, biv *A, biv *M)
{
    lin3 x[4] = { { 0, 0, 0 }, { 0, u0[0], 0 }, { 1, 0, -u1[0] },
                  { 1, 0, 0 } };
    lin3 y[4] = { { 0, 0, 0 }, { 0, u0[1], 0 }, { 0, 0, -u1[1] },
                  { 0, 0, 0 } };
    lin3 dx[3], dy[3];
    memset(A, 0, sizeof *A);
    memset(M, 0, sizeof *M);
    for (int k = 0; k < 3; k++) {
        dx[k].c = x[k + 1].c - x[k].c;
        dx[k].x = x[k + 1].x - x[k].x;
        dx[k].y = x[k + 1].y - x[k].y;
        dy[k].c = y[k + 1].c - y[k].c;
        dy[k].x = y[k + 1].x - y[k].x;
        dy[k].y = y[k + 1].y - y[k].y;
    }
    /* A = 1/2 int (x y' - y x'), y' = 3 sum dy_k B_k^2 */
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 3; k++) {
            double w = 1.5 * cf__binomial(3, i) * cf__binomial(2, k) /
                       (6.0 * cf__binomial(5, i + k));
            biv_add_prod(A, w, &x[i], &dy[k], NULL);
            biv_add_prod(A, -w, &y[i], &dx[k], NULL);
        }
    /* M = 1/2 int x^2 y' */
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            for (int k = 0; k < 3; k++) {
                double w = 1.5 * cf__binomial(3, i) * cf__binomial(3, j) *
                           cf__binomial(2, k) /
                           (9.0 * cf__binomial(8, i + j + k));
                biv_add_prod(M, w, &x[i], &x[j], &dy[k]);
            }
}

static void
make_cubic(const frame *f, const double *u0, const double *u1, double d0,
           double d1, double *pts)
{
    pts[0] = f->p0[0];
    pts[1] = f->p0[1];
    pts[2] = f->p0[0] + d0 * f->L * u0[0];
    pts[3] = f->p0[1] + d0 * f->L * u0[1];
    pts[4] = f->p3[0] - d1 * f->L * u1[0];
    pts[5] = f->p3[1] - d1 * f->L * u1[1];
    pts[6] = f->p3[0];
    pts[7] = f->p3[1];
}

/* The candidate with arm d0 and d1 = N(d0) / D(d0) from the area, if that
** is in [0, ARM_MAX], appended to cand. */
static void
area_candidate(const frame *f, const double *u0, const double *u1,
               const double *N, const double *D, double d0,
               double cand[][8], int *nc)
{
    double den = D[0] + D[1] * d0, d1;
    if (fabs(den) < 1e-12)
        return;
    d1 = (N[0] + N[1] * d0) / den;
    if (d1 >= 0.0 && d1 <= ARM_MAX)
        make_cubic(f, u0, u1, d0, d1, cand[(*nc)++]);
}

/* The candidate cubics of the Levien fit plus the fallbacks. */
static cf_status_t
levien_candidates(const cf__osrc_t *s, double a, double b,
                  double cand[][8], int *ncand)
{
    frame f;
    double u0[2], u1[2], dp[2], q[2], n0[2], n1[2];
    int nc = 0;

    cf__osrc_point_dir(s, a, 1, f.p0, u0);
    cf__osrc_point_dir(s, b, -1, f.p3, u1);

    /* Hermite cubic (derivatives matched): always a candidate */
    {
        double *c = cand[nc++], h = (b - a) / 3.0;
        c[0] = f.p0[0];
        c[1] = f.p0[1];
        cf__osrc_deriv(s, a, q, dp);
        c[2] = f.p0[0] + h * dp[0];
        c[3] = f.p0[1] + h * dp[1];
        cf__osrc_deriv(s, b, q, dp);
        c[4] = f.p3[0] - h * dp[0];
        c[5] = f.p3[1] - h * dp[1];
        c[6] = f.p3[0];
        c[7] = f.p3[1];
    }
    f.L = hypot(f.p3[0] - f.p0[0], f.p3[1] - f.p0[1]);
    if (!(f.L > 1e-13 * s->scale)) {
        *ncand = nc;
        return CF_STATUS_OK;
    }
    f.e[0] = (f.p3[0] - f.p0[0]) / f.L;
    f.e[1] = (f.p3[1] - f.p0[1]) / f.L;
    {
        double At, Mt;
        biv A, M;
        double N[3], D[2], F[10], Dp[4][4], Np[4][7], tmp[10];
        double bern[10], roots[16];
        size_t nr = 0;
        cf_status_t st;

        source_area_moment(s, a, b, &f, &At, &Mt);
        n0[0] = u0[0] * f.e[0] + u0[1] * f.e[1];
        n0[1] = f.e[0] * u0[1] - f.e[1] * u0[0];
        n1[0] = u1[0] * f.e[0] + u1[1] * f.e[1];
        n1[1] = f.e[0] * u1[1] - f.e[1] * u1[0];
        cubic_area_moment(n0, n1, &A, &M);
        /* A is a00 + a10 d0 + a01 d1 + a11 d0 d1 (the d0^2, d1^2 terms
        ** cancel: x_i dy_k - y_i dx_k of the same arm is a cross product of
        ** a vector with itself). So d1 = N(d0) / D(d0) with */
        N[0] = At - A.q[0][0];
        N[1] = -A.q[1][0];
        D[0] = A.q[0][1];
        D[1] = A.q[1][1];
        /* F(d0) = sum m_pr d0^p N^r D^(3-r) - Mt D^3 */
        Dp[0][0] = 1.0;
        Np[0][0] = 1.0;
        for (int r = 1; r <= 3; r++) {
            pp_mul(Dp[r - 1], r - 1, D, 1, Dp[r]);
            pp_mul(Np[r - 1], r - 1, N, 1, Np[r]);
        }
        memset(F, 0, sizeof F);
        for (int p = 0; p <= 3; p++)
            for (int r = 0; p + r <= 3; r++) {
                double mc = M.q[p][r];
                if (mc == 0.0)
                    continue;
                pp_mul(Np[r], r, Dp[3 - r], 3 - r, tmp);
                for (int k = 0; k <= 3; k++)
                    F[k + p] += mc * tmp[k];
            }
        for (int k = 0; k <= 3; k++)
            F[k] -= Mt * Dp[3][k];
        cf__bp_from_power(F, 6, ARM_MAX, bern);
        st = cf__bp_roots(bern, 6, roots, 16, &nr);
        if (st != CF_STATUS_OK)
            return st;
        for (size_t k = 0; k < nr && nc < MAX_CAND - 4; k++)
            area_candidate(&f, u0, u1, N, D, roots[k] * ARM_MAX, cand, &nc);
        /* where two roots of the moment equation have just merged and
        ** left the real line, |F| keeps a local minimum near zero: the
        ** arms there match the area exactly and the moment nearly, and
        ** fit about as well as the lost pair (without them the error
        ** jumps as the piece grows past the merge) */
        {
            double dbern[6], crit[8];
            size_t ncr = 0;
            cf__bp_deriv(bern, 6, dbern);
            st = cf__bp_roots(dbern, 5, crit, 8, &ncr);
            if (st != CF_STATUS_OK)
                return st;
            for (size_t k = 0; k < ncr && nc < MAX_CAND - 4; k++) {
                double x = crit[k], h = 1e-3;
                double fx = cf__bp_eval(bern, 6, x);
                double fl = cf__bp_eval(bern, 6, fmax(0.0, x - h));
                double fr = cf__bp_eval(bern, 6, fmin(1.0, x + h));
                /* a local minimum of |F| that is not a root */
                if (fx > 0.0 ? fl > fx && fr > fx
                             : fx < 0.0 && fl < fx && fr < fx)
                    area_candidate(&f, u0, u1, N, D, x * ARM_MAX, cand,
                                   &nc);
            }
        }
        /* one arm zero, the other from the area */
        area_candidate(&f, u0, u1, N, D, 0.0, cand, &nc);
        if (fabs(A.q[1][0]) > 1e-12) {
            double d0 = (At - A.q[0][0]) / A.q[1][0];
            if (d0 >= 0.0 && d0 <= ARM_MAX)
                make_cubic(&f, u0, u1, d0, 0.0, cand[nc++]);
        }
        /* equal arms from the area: a11 x^2 + (a10 + a01) x + a00 - At */
        {
            double qa = A.q[1][1], qb = A.q[1][0] + A.q[0][1],
                   qc = A.q[0][0] - At;
            if (fabs(qa) > 1e-12) {
                double disc = qb * qb - 4 * qa * qc;
                if (disc >= 0) {
                    double sq = sqrt(disc);
                    double r1 = (-qb + sq) / (2 * qa),
                           r2 = (-qb - sq) / (2 * qa);
                    if (r1 >= 0 && r1 <= ARM_MAX)
                        make_cubic(&f, u0, u1, r1, r1, cand[nc++]);
                    if (r2 >= 0 && r2 <= ARM_MAX && nc < MAX_CAND)
                        make_cubic(&f, u0, u1, r2, r2, cand[nc++]);
                }
            } else if (fabs(qb) > 1e-12) {
                double r1 = -qc / qb;
                if (r1 >= 0 && r1 <= ARM_MAX)
                    make_cubic(&f, u0, u1, r1, r1, cand[nc++]);
            }
        }
    }
    *ncand = nc;
    return CF_STATUS_OK;
}

/* ---- Tiller-Hanson ------------------------------------------------------ */

static void
leg_normal(const double *v, double *nrm)
{
    double l = hypot(v[0], v[1]);
    nrm[0] = -v[1] / l;
    nrm[1] = v[0] / l;
}

/* Intersection of p + s u and q + r v, or NULL-like failure (returns -1). */
static int
line_isect(const double *p, const double *u, const double *q,
           const double *v, double *out)
{
    double den = u[0] * v[1] - u[1] * v[0];
    double lu = hypot(u[0], u[1]), lv = hypot(v[0], v[1]), sp;
    if (!(fabs(den) > 1e-9 * lu * lv))
        return -1;
    sp = ((q[0] - p[0]) * v[1] - (q[1] - p[1]) * v[0]) / den;
    out[0] = p[0] + sp * u[0];
    out[1] = p[1] + sp * u[1];
    return 0;
}

static cf_status_t
tiller_hanson(const cf__osrc_t *s, double a, double b, double *pts)
{
    const cf_bezier_t *c = s->c;
    double tmp[8], seg[8], P[4][2], L[3][2], N[3][2], o[3][2];
    double d = s->d, sc = s->scale;
    if (c->degree != 3 || c->rational)
        return CF_STATUS_INVALID_ARG;
    /* control points of c on [a, b] */
    cf__bp_split(c->pts, 2, 3, b, tmp, NULL);
    if (b > 0.0)
        cf__bp_split(tmp, 2, 3, a / b, NULL, seg);
    else
        memcpy(seg, tmp, sizeof seg);
    for (int i = 0; i < 4; i++) {
        P[i][0] = seg[2 * i];
        P[i][1] = seg[2 * i + 1];
    }
    for (int k = 0; k < 3; k++) {
        L[k][0] = P[k + 1][0] - P[k][0];
        L[k][1] = P[k + 1][1] - P[k][1];
    }
    /* zero legs take the curve's tangent at that end (or the chord) */
    for (int k = 0; k < 3; k++) {
        if (hypot(L[k][0], L[k][1]) > 1e-12 * sc)
            continue;
        if (k == 0 || k == 2) {
            double u[2];
            cf__bezier_unit_tangent(c, k == 0 ? a : b, k == 0 ? 1 : -1, sc,
                                    NULL, u);
            L[k][0] = u[0];
            L[k][1] = u[1];
        } else {
            L[k][0] = P[3][0] - P[0][0];
            L[k][1] = P[3][1] - P[0][1];
            if (hypot(L[k][0], L[k][1]) == 0.0) {
                L[k][0] = L[0][0];
                L[k][1] = L[0][1];
            }
        }
    }
    for (int k = 0; k < 3; k++) {
        leg_normal(L[k], N[k]);
        o[k][0] = P[k][0] + d * N[k][0];
        o[k][1] = P[k][1] + d * N[k][1];
    }
    pts[0] = o[0][0];
    pts[1] = o[0][1];
    pts[6] = P[3][0] + d * N[2][0];
    pts[7] = P[3][1] + d * N[2][1];
    if (line_isect(o[0], L[0], o[1], L[1], pts + 2) != 0) {
        pts[2] = P[1][0] + d * N[0][0];
        pts[3] = P[1][1] + d * N[0][1];
    }
    if (line_isect(o[1], L[1], o[2], L[2], pts + 4) != 0) {
        pts[4] = P[2][0] + d * N[2][0];
        pts[5] = P[2][1] + d * N[2][1];
    }
    return CF_STATUS_OK;
}

/* ---- one piece ------------------------------------------------------------ */

/* Pattern search on the arm lengths of pts (end points and tangent
** directions fixed), lowering the coarse error *err until it is at most
** target. */
static cf_status_t
polish_arms(const cf__osrc_t *s, double a, double b, double target,
            double *pts, double *err)
{
    double u[2][2], arm[2], step;
    double chord = hypot(pts[6] - pts[0], pts[7] - pts[1]);
    for (int k = 0; k < 2; k++) {
        const double *e = pts + (k == 0 ? 0 : 6), *c = pts + (k == 0 ? 2 : 4);
        arm[k] = hypot(c[0] - e[0], c[1] - e[1]);
        if (!(arm[k] > 0.0))
            return CF_STATUS_OK;
        u[k][0] = (c[0] - e[0]) / arm[k];
        u[k][1] = (c[1] - e[1]) / arm[k];
    }
    step = 0.05 * fmax(chord, fmax(arm[0], arm[1]));
    for (int it = 0; it < 16 && step > 1e-6 * chord && *err > target;
         it++) {
        bool improved = false;
        for (int k = 0; k < 2; k++)
            for (int sg = -1; sg <= 1; sg += 2) {
                double trial[8], e, na = arm[k] + sg * step;
                cf_status_t st;
                if (na < 0.0)
                    continue;
                memcpy(trial, pts, sizeof trial);
                if (k == 0) {
                    trial[2] = pts[0] + na * u[0][0];
                    trial[3] = pts[1] + na * u[0][1];
                } else {
                    trial[4] = pts[6] + na * u[1][0];
                    trial[5] = pts[7] + na * u[1][1];
                }
                /* the quick estimate (about a lower bound) first */
                st = cf__fit_error(s, a, b, trial, CF__FIT_K_QUICK, &e);
                if (st == CF_STATUS_OK && e < *err)
                    st = cf__fit_error(s, a, b, trial, CF__FIT_K_COARSE, &e);
                if (st != CF_STATUS_OK)
                    return st;
                if (e < *err) {
                    *err = e;
                    arm[k] = na;
                    memcpy(pts, trial, sizeof trial);
                    improved = true;
                }
            }
        if (!improved)
            step *= 0.5;
    }
    return CF_STATUS_OK;
}

/* ---- a piece that ends at an offset cusp ----------------------------------- */

/* The offset near a cusp at t_c is o_c + A tau^2 + B tau^3 + ... (tau =
** t - t_c, A along the cusp tangent): a semicubical cusp.  A cubic with a
** zero arm there, P0 + 3 (P2 - P0) s^2 + (...) s^3, has that very form, so
** the best cusp-side control point lies close to the cusp; the area and
** moment equations miss it by a factor 5-20 in error.  At a cusp the chain
** need only be continuous (the offset itself turns back there), so the
** cusp-side control point is free in the plane; the arm at a non-cusp end
** keeps its tangent (G1 with the neighbour).  These 3 (4 with cusps at both
** ends) unknowns are optimised on the coarse measured error by a
** Nelder-Mead search; the result is measured again like any fit. */

#define CUSP_EVALS 150          /* error evaluations of the search */
#define ROUND_EVALS 60          /* of one Nelder-Mead round */
#define CUSP_RANGE 10.0         /* no search above this error / tolerance */

typedef struct armfit {
    const cf__osrc_t *s;
    double a, b;
    double p0[2], p3[2], u0[2], u1[2];
    int free0, free1;           /* the control point at that end is free */
} armfit;

/* The cubic of the unknowns x (arm lengths along the end tangents, then
** the normal offsets of the free control points) into pts, and its coarse
** error (infinite for a negative arm). */
static cf_status_t
arm_error(const armfit *af, const double *x, double *pts, double *err)
{
    double n0 = af->free0 ? x[2] : 0.0, n1 = af->free1 ? x[2 + af->free0]
                                                       : 0.0;
    pts[0] = af->p0[0];
    pts[1] = af->p0[1];
    pts[2] = af->p0[0] + x[0] * af->u0[0] - n0 * af->u0[1];
    pts[3] = af->p0[1] + x[0] * af->u0[1] + n0 * af->u0[0];
    pts[4] = af->p3[0] - x[1] * af->u1[0] - n1 * af->u1[1];
    pts[5] = af->p3[1] - x[1] * af->u1[1] + n1 * af->u1[0];
    pts[6] = af->p3[0];
    pts[7] = af->p3[1];
    if (!(x[0] >= 0.0 && x[1] >= 0.0)) {
        *err = INFINITY;
        return CF_STATUS_OK;
    }
    return cf__fit_error(af->s, af->a, af->b, pts, CF__FIT_K_COARSE, err);
}

/* One Nelder-Mead search from x0 (error *f0) with initial steps step (the
** arms) and 0.01 step (the normal offsets), at most *evals more errors;
** the best point found replaces x0 and *f0. */
static cf_status_t
nm_round(const armfit *af, int n, double step, double target, double chord,
         double *x0, double *f0, int *evals)
{
    double x[5][4], f[5], tp[8];
    int lo = 0, budget = *evals + ROUND_EVALS;
    cf_status_t st;
    memcpy(x[0], x0, sizeof x[0]);
    f[0] = *f0;
    for (int i = 1; i <= n; i++) {
        memcpy(x[i], x0, sizeof x[0]);
        if (i <= 2)
            /* a long arm shortened (the cusp-side optimum is small) */
            x[i][i - 1] += x0[i - 1] > step ? -step : step;
        else
            x[i][i - 1] += 0.01 * step;
        st = arm_error(af, x[i], tp, &f[i]);
        if (st != CF_STATUS_OK)
            return st;
    }
    *evals += n;
    while (*evals < budget) {
        int hi = 0, nh;
        double c[4] = { 0, 0, 0, 0 }, r[4], fr, size = 0.0;
        lo = 0;
        for (int i = 1; i <= n; i++) {
            if (f[i] < f[lo])
                lo = i;
            if (f[i] > f[hi])
                hi = i;
        }
        if (hi == lo)
            hi = lo == 0 ? 1 : 0;
        nh = lo;
        for (int i = 0; i <= n; i++)
            if (i != hi && f[i] >= f[nh])
                nh = i;
        for (int i = 0; i <= n; i++)
            for (int k = 0; k < n; k++)
                size = fmax(size, fabs(x[i][k] - x[lo][k]));
        if (f[lo] <= target || size < 1e-7 * chord)
            break;
        for (int i = 0; i <= n; i++)
            if (i != hi)
                for (int k = 0; k < n; k++)
                    c[k] += x[i][k] / n;
        for (int k = 0; k < n; k++)
            r[k] = 2.0 * c[k] - x[hi][k];
        st = arm_error(af, r, tp, &fr);
        ++*evals;
        if (st != CF_STATUS_OK)
            return st;
        if (fr < f[lo]) {
            double e[4], fe;
            for (int k = 0; k < n; k++)
                e[k] = 3.0 * c[k] - 2.0 * x[hi][k];
            st = arm_error(af, e, tp, &fe);
            ++*evals;
            if (st != CF_STATUS_OK)
                return st;
            memcpy(x[hi], fe < fr ? e : r, sizeof r);
            f[hi] = fmin(fe, fr);
        } else if (fr < f[nh]) {
            memcpy(x[hi], r, sizeof r);
            f[hi] = fr;
        } else {
            /* contract towards the better of the worst and its reflection,
            ** else shrink towards the best */
            double k[4], fk;
            const double *w = fr < f[hi] ? r : x[hi];
            for (int q = 0; q < n; q++)
                k[q] = 0.5 * (c[q] + w[q]);
            st = arm_error(af, k, tp, &fk);
            ++*evals;
            if (st != CF_STATUS_OK)
                return st;
            if (fk < fmin(fr, f[hi])) {
                memcpy(x[hi], k, sizeof k);
                f[hi] = fk;
            } else {
                for (int i = 0; i <= n; i++) {
                    if (i == lo)
                        continue;
                    for (int q = 0; q < n; q++)
                        x[i][q] = 0.5 * (x[i][q] + x[lo][q]);
                    st = arm_error(af, x[i], tp, &f[i]);
                    ++*evals;
                    if (st != CF_STATUS_OK)
                        return st;
                }
            }
        }
    }
    lo = 0;
    for (int i = 1; i <= n; i++)
        if (f[i] < f[lo])
            lo = i;
    memcpy(x0, x[lo], sizeof x[0]);
    *f0 = f[lo];
    return CF_STATUS_OK;
}

/* Nelder-Mead on the unknowns of pts (see arm_error) from its current
** arms, lowering *err (the coarse error of pts) until it is at most
** target or CUSP_EVALS errors have been measured; the error is not smooth
** (a maximum), so a search that stalls is restarted from its best point
** with a fresh, smaller simplex. */
static cf_status_t
cusp_fit(const cf__osrc_t *s, double a, double b, bool free0, bool free1,
         double target, double *pts, double *err)
{
    armfit af;
    double x[4] = { 0, 0, 0, 0 }, fx, tp[8], chord, step;
    int n, evals = 1;
    cf_status_t st;
    af.s = s;
    af.a = a;
    af.b = b;
    af.free0 = free0;
    af.free1 = free1;
    n = 2 + af.free0 + af.free1;
    cf__osrc_point_dir(s, a, 1, af.p0, af.u0);
    cf__osrc_point_dir(s, b, -1, af.p3, af.u1);
    chord = hypot(af.p3[0] - af.p0[0], af.p3[1] - af.p0[1]);
    if (!(chord > 1e-13 * s->scale))
        return CF_STATUS_OK;
    /* the current arms (projections: a zero arm has no direction) */
    x[0] = fmax(0.0, (pts[2] - pts[0]) * af.u0[0] +
                         (pts[3] - pts[1]) * af.u0[1]);
    x[1] = fmax(0.0, (pts[6] - pts[4]) * af.u1[0] +
                         (pts[7] - pts[5]) * af.u1[1]);
    st = arm_error(&af, x, tp, &fx);
    if (st != CF_STATUS_OK)
        return st;
    step = 0.1 * fmax(chord, fmax(x[0], x[1]));
    /* the semicubical start: the cusp-side arms zero, the other kept */
    {
        double y[4], fy;
        memcpy(y, x, sizeof y);
        if (free0)
            y[0] = 0.0;
        if (free1)
            y[1] = 0.0;
        st = arm_error(&af, y, tp, &fy);
        evals++;
        if (st != CF_STATUS_OK)
            return st;
        if (fy > target) {
            st = nm_round(&af, n, step, target, chord, y, &fy, &evals);
            if (st != CF_STATUS_OK)
                return st;
        }
        if (fy < fx) {
            memcpy(x, y, sizeof y);
            fx = fy;
        }
    }
    while (evals < CUSP_EVALS && fx > target && step > 1e-7 * chord) {
        double before = fx;
        st = nm_round(&af, n, step, target, chord, x, &fx, &evals);
        if (st != CF_STATUS_OK)
            return st;
        /* the next simplex about the size of this round's progress */
        step = fmin(0.5 * step, fmax(0.1 * step, fabs(x[0]) * 0.05));
        if (!(fx < before))
            step *= 0.1;
    }
    if (fx < *err)
        return arm_error(&af, x, pts, err);
    return CF_STATUS_OK;
}

cf_status_t
cf__fit_piece(const cf__osrc_t *s, double a, double b,
              cf_offset_method_t method, double reject, cf__fit_t *out)
{
    cf_status_t st;
    double be = INFINITY;
    if (method == CF_OFFSET_TILLER_HANSON && s->kind == 0) {
        st = tiller_hanson(s, a, b, out->pts);
        if (st != CF_STATUS_OK)
            return st;
        st = cf__fit_error(s, a, b, out->pts, CF__FIT_K_COARSE, &be);
    } else {
        double cand[MAX_CAND][8], quick[MAX_CAND], qbest = INFINITY;
        int nc = 0, best = 0;
        bool at_cusp = s->kind == 0 && s->d != 0.0 &&
                       (a == s->cusp_a || b == s->cusp_b);
        st = levien_candidates(s, a, b, cand, &nc);
        if (st != CF_STATUS_OK)
            return st;
        /* a quick estimate at CF__FIT_K_QUICK samples (a subset of the coarse
        ** ones, so roughly a lower bound of the coarse estimate) screens
        ** the candidates: one it puts above the best coarse error so far,
        ** or all of them far above the tolerance, are not measured on */
        for (int i = 0; i < nc; i++) {
            st = cf__fit_error(s, a, b, cand[i], CF__FIT_K_QUICK, &quick[i]);
            if (st != CF_STATUS_OK)
                return st;
            qbest = fmin(qbest, quick[i]);
        }
        if (qbest > (at_cusp ? CUSP_RANGE : 2.0) * reject) {
            for (int i = 0; i < nc; i++)
                if (quick[i] == qbest)
                    best = i;
            memcpy(out->pts, cand[best], sizeof out->pts);
            out->err = qbest;
            return CF_STATUS_OK;
        }
        for (int i = 0; i < nc; i++) {
            double e;
            if (quick[i] >= be)
                continue;
            st = cf__fit_error(s, a, b, cand[i], CF__FIT_K_COARSE, &e);
            if (st != CF_STATUS_OK)
                return st;
            if (e < be) {
                be = e;
                best = i;
            }
        }
        memcpy(out->pts, cand[best], sizeof out->pts);
        if (at_cusp) {
            /* at a cusp: the free control point and the arms optimised
            ** (see cusp_fit); a candidate error more than CUSP_RANGE times
            ** the tolerance is not brought within it */
            if (be > 0.9 * reject && be < CUSP_RANGE * reject) {
                st = cusp_fit(s, a, b, a == s->cusp_a, b == s->cusp_b,
                              0.9 * reject, out->pts, &be);
                if (st != CF_STATUS_OK)
                    return st;
            }
        } else if (be > reject && be < 1.5 * reject &&
                   (s->kind != 0 || s->d != 0.0)) {
            /* just above the tolerance: polish the two arm lengths by a
            ** pattern search on the measured error (offsets only: for the
            ** curve itself, d = 0, it costs 4-7x the time and saves a
            ** piece only at tight tolerances) */
            st = polish_arms(s, a, b, 0.9 * reject, out->pts, &be);
            if (st != CF_STATUS_OK)
                return st;
        }
    }
    if (st != CF_STATUS_OK)
        return st;
    /* the coarse estimate is (up to sampling) a lower bound: a piece it
    ** already rejects needs no fine measurement */
    if (be > reject) {
        out->err = be;
        return CF_STATUS_OK;
    }
    st = cf__fit_error(s, a, b, out->pts, CF__FIT_K_FINE, &out->err);
    if (st == CF_STATUS_OK)
        out->err = fmax(out->err, be);
    return st;
}
