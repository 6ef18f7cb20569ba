/*
** The exact curves that offset pieces approximate ("sources": the offset of
** a Bézier curve, or a circular join arc), their points and derivatives,
** and the measured two-sided Hausdorff error of a cubic against a source.
** The fitting strategies are in fit-piece.c.
*/
#include <math.h>
#include <string.h>

#include "core-private.h"
#include "bezier-private.h"
#include "fit-private.h"

/* ---- unit tangent with higher derivatives -------------------------------- */

int
cf__bezier_unit_tangent(const cf_bezier_t *c, double t, int side,
                        double scale, double *p, double *u)
{
    double v[2 * 9];
    int n = c->degree, kmax = n < 8 ? n : 8;
    double len;
    cf__bezier_derivs(c, t, 1, v);
    if (p != NULL) {
        p[0] = v[0];
        p[1] = v[1];
    }
    len = sqrt(v[2] * v[2] + v[3] * v[3]);
    if (len > 1e-12 * scale && len > 0.0) {
        u[0] = v[2] / len;
        u[1] = v[3] / len;
        return 0;
    }
    /* c' vanishes: near t, c'(t + h) ~ c^(m)(t) h^(m-1) / (m-1)!, so the
    ** direction is that of the first non-zero derivative from the right
    ** and (-1)^(m-1) times it from the left. */
    if (kmax < 2)
        return -1;
    cf__bezier_derivs(c, t, kmax, v);
    for (int m = 2; m <= kmax; m++) {
        double x = v[2 * m], y = v[2 * m + 1];
        len = hypot(x, y);
        if (len > 1e-12 * scale && len > 0.0) {
            double sg = (side < 0 && (m - 1) % 2 == 1) ? -1.0 : 1.0;
            u[0] = sg * x / len;
            u[1] = sg * y / len;
            return 0;
        }
    }
    return -1;
}

/* ---- sources ------------------------------------------------------------- */

void
cf__osrc_init_offset(cf__osrc_t *s, const cf_bezier_t *c, double d)
{
    memset(s, 0, sizeof *s);
    s->kind = 0;
    s->c = c;
    s->d = d;
    s->sgn = 1.0;
    s->scale = cf__deriv_scale(c);
    if (!(s->scale > 0.0))
        s->scale = 1.0;
    s->cusp_a = s->cusp_b = -1.0;
}

void
cf__osrc_init_arc(cf__osrc_t *s, double cx, double cy, double r, double a0,
                  double sweep)
{
    memset(s, 0, sizeof *s);
    s->kind = 1;
    s->sgn = sweep >= 0 ? 1.0 : -1.0;
    s->cx = cx;
    s->cy = cy;
    s->r = r;
    s->a0 = a0;
    s->sweep = sweep;
    s->scale = r;
    s->cusp_a = s->cusp_b = -1.0;
}

int
cf__osrc_point_dir(const cf__osrc_t *s, double t, int side, double *p,
                   double *u)
{
    if (s->kind == 1) {
        double th = s->a0 + s->sweep * t;
        p[0] = s->cx + s->r * cos(th);
        p[1] = s->cy + s->r * sin(th);
        if (u != NULL) {
            u[0] = -s->sgn * sin(th);
            u[1] = s->sgn * cos(th);
        }
        return 0;
    } else {
        double base[2], tan[2];
        if (s->d == 0.0 && u == NULL) {
            /* the curve itself: no tangent needed */
            cf__bezier_eval_point(s->c, t, p);
            return 0;
        }
        if (cf__bezier_unit_tangent(s->c, t, side, s->scale, base, tan) != 0) {
            p[0] = base[0];
            p[1] = base[1];
            if (u != NULL)
                u[0] = u[1] = 0.0;
            return -1;
        }
        p[0] = base[0] - s->d * tan[1];
        p[1] = base[1] + s->d * tan[0];
        if (u != NULL) {
            u[0] = s->sgn * tan[0];
            u[1] = s->sgn * tan[1];
        }
        return 0;
    }
}

int
cf__osrc_deriv(const cf__osrc_t *s, double t, double *p, double *dp)
{
    if (s->kind == 1) {
        double th = s->a0 + s->sweep * t;
        p[0] = s->cx + s->r * cos(th);
        p[1] = s->cy + s->r * sin(th);
        dp[0] = -s->r * s->sweep * sin(th);
        dp[1] = s->r * s->sweep * cos(th);
        return 0;
    } else {
        /* o' = c' (1 - d (c' x c'') / |c'|^3) */
        double v[6], sp, f;
        if (s->d == 0.0) {
            cf__bezier_derivs(s->c, t, 1, v);
            p[0] = v[0];
            p[1] = v[1];
            dp[0] = v[2];
            dp[1] = v[3];
            return 0;
        }
        cf__bezier_derivs(s->c, t, 2, v);
        sp = sqrt(v[2] * v[2] + v[3] * v[3]);
        if (!(sp > 1e-14 * s->scale)) {
            cf__osrc_point_dir(s, t, 1, p, NULL);
            dp[0] = dp[1] = 0.0;
            return 0;
        }
        f = 1.0 - s->d * (v[2] * v[5] - v[3] * v[4]) / (sp * sp * sp);
        p[0] = v[0] - s->d * v[3] / sp;
        p[1] = v[1] + s->d * v[2] / sp;
        dp[0] = v[2] * f;
        dp[1] = v[3] * f;
        return 0;
    }
}

/* ---- distance of a point to one of the two curves ----------------------- */


typedef struct meas {
    const cf__osrc_t *s;
    double a, b;
    const double *pts;
    int k;
    double *sp, *cp;        /* k + 1 samples of source and cubic */
    double *dsp, *dcp;      /* their derivatives (in u) */
} meas;

/* which = 0: the cubic on [0, 1]; which = 1: the source on [a, b]; the
** parameter is the local u in [0, 1] in both cases. */
static void
curve_pd(const void *ctx, int which, double u, double *p, double *dp)
{
    const meas *m = ctx;
    if (which == 0) {
        cf__cubic_pd(m->pts, u, p, dp);
    } else {
        double t = m->a + (m->b - m->a) * u;
        if (u <= 0.0 || u >= 1.0) {
            cf__osrc_point_dir(m->s, t, u <= 0.0 ? 1 : -1, p, NULL);
            if (dp != NULL) {
                double q[2];
                cf__osrc_deriv(m->s, t, q, dp);
            }
        } else if (dp != NULL) {
            cf__osrc_deriv(m->s, t, p, dp);
        } else {
            cf__osrc_point_dir(m->s, t, 1, p, NULL);
        }
        if (dp != NULL) {
            dp[0] *= m->b - m->a;
            dp[1] *= m->b - m->a;
        }
    }
}

static void
cubic_fn(const void *ctx, double u, double *p, double *dp)
{
    curve_pd(ctx, 0, u, p, dp);
}

static void
source_fn(const void *ctx, double u, double *p, double *dp)
{
    curve_pd(ctx, 1, u, p, dp);
}

/* g(u) = (C(u) - q) . C'(u): zero at a foot point. */
static double
foot_g(cf__pd_fn fn, const void *ctx, const double *q, double u,
       double *dist, double *speed)
{
    double p[2], dp[2];
    fn(ctx, u, p, dp);
    {
        double dx = p[0] - q[0], dy = p[1] - q[1];
        *dist = sqrt(dx * dx + dy * dy);
    }
    *speed = sqrt(dp[0] * dp[0] + dp[1] * dp[1]);
    return (p[0] - q[0]) * dp[0] + (p[1] - q[1]) * dp[1];
}

/* g, distance and speed at sample i from the cached point smp and
** derivative dsmp (the values fn gives at u = i / k), else from fn. */
static double
foot_g_at(cf__pd_fn fn, const void *ctx, const double *smp,
          const double *dsmp, int i, int k, const double *q, double *dist,
          double *speed)
{
    const double *p = smp + 2 * i, *dp;
    double dx, dy;
    if (dsmp == NULL)
        return foot_g(fn, ctx, q, (double)i / k, dist, speed);
    dp = dsmp + 2 * i;
    dx = p[0] - q[0];
    dy = p[1] - q[1];
    *dist = sqrt(dx * dx + dy * dy);
    *speed = sqrt(dp[0] * dp[0] + dp[1] * dp[1]);
    return dx * dp[0] + dy * dp[1];
}

/* cf__dist_sampled with the derivatives at the samples (dsmp, may be
** NULL) cached. */
static double
dist_sampled_d(cf__pd_fn fn, const void *ctx, const double *smp,
               const double *dsmp, int k, const double *q)
{
    int j = 0;
    double best = INFINITY;
    for (int i = 0; i <= k; i++) {
        double dx = smp[2 * i] - q[0], dy = smp[2 * i + 1] - q[1];
        double dd = dx * dx + dy * dy;
        if (dd < best) {
            best = dd;
            j = i;
        }
    }
    best = sqrt(best);
    for (int side = -1; side <= 1; side += 2) {
        int i0 = side < 0 ? j - 1 : j, i1 = i0 + 1;
        double u0, u1, g0, g1, d0, d1, sp;
        int last = 0;
        if (i0 < 0 || i1 > k)
            continue;
        u0 = (double)i0 / k;
        u1 = (double)i1 / k;
        g0 = foot_g_at(fn, ctx, smp, dsmp, i0, k, q, &d0, &sp);
        g1 = foot_g_at(fn, ctx, smp, dsmp, i1, k, q, &d1, &sp);
        best = fmin(best, fmin(d0, d1));
        if (!(g0 < 0.0 && g1 > 0.0))
            continue;   /* no interior minimum in this interval */
        for (int it = 0; it < 40 && u1 - u0 > 1e-15; it++) {
            double um = (u0 * g1 - u1 * g0) / (g1 - g0), gm, dm;
            if (!(um > u0 && um < u1))
                um = 0.5 * (u0 + u1);
            gm = foot_g(fn, ctx, q, um, &dm, &sp);
            best = fmin(best, dm);
            /* at the foot point within an angle of 1e-6: the distance
            ** is then high by at most about 1e-12 relative (never low:
            ** every dm is the distance to a point of the curve) */
            if (fabs(gm) <= 1e-6 * dm * sp)
                break;
            if (gm < 0.0) {
                u0 = um;
                g0 = gm;
                if (last == -1)
                    g1 *= 0.5;
                last = -1;
            } else {
                u1 = um;
                g1 = gm;
                if (last == 1)
                    g0 *= 0.5;
                last = 1;
            }
        }
    }
    return best;
}

double
cf__dist_sampled(cf__pd_fn fn, const void *ctx, const double *smp, int k,
                 const double *q)
{
    return dist_sampled_d(fn, ctx, smp, NULL, k, q);
}

/* Distance from q to curve `which` (samples smp[0..k], derivatives there
** cached). */
static double
dist_to(const meas *m, int which, const double *smp, const double *q)
{
    return dist_sampled_d(which == 0 ? cubic_fn : source_fn, m, smp,
                          smp == m->cp ? m->dcp : m->dsp, m->k, q);
}

/* Directed distance from curve `from` to the other, with the maximum
** refined by golden-section search around the largest sample. */
static double
directed(const meas *m, int from)
{
    const double *own = from == 0 ? m->cp : m->sp;
    const double *other = from == 0 ? m->sp : m->cp;
    int k = m->k, imax = 0, iters = k <= 16 ? 8 : 16;
    double hmax = -1.0;
    /* the quick screening estimate of a fit of the curve itself (d = 0)
    ** is the samples' maximum only (the golden-section refinement changes
    ** no piece count there; it does for offsets) */
    if (k <= CF__FIT_K_QUICK && m->s->kind == 0 && m->s->d == 0.0)
        iters = 0;
    for (int i = 0; i <= k; i++) {
        double h = dist_to(m, 1 - from, other, own + 2 * i);
        if (h > hmax) {
            hmax = h;
            imax = i;
        }
    }
    {
        const double gr = 0.6180339887498949;
        double lo = (double)(imax > 0 ? imax - 1 : 0) / k;
        double hi = (double)(imax < k ? imax + 1 : k) / k;
        double x1 = hi - gr * (hi - lo), x2 = lo + gr * (hi - lo), f1, f2,
               p[2];
        curve_pd(m, from, x1, p, NULL);
        f1 = dist_to(m, 1 - from, other, p);
        curve_pd(m, from, x2, p, NULL);
        f2 = dist_to(m, 1 - from, other, p);
        for (int it = 0; it < iters; it++) {
            if (f1 > f2) {
                hi = x2;
                x2 = x1;
                f2 = f1;
                x1 = hi - gr * (hi - lo);
                curve_pd(m, from, x1, p, NULL);
                f1 = dist_to(m, 1 - from, other, p);
            } else {
                lo = x1;
                x1 = x2;
                f1 = f2;
                x2 = lo + gr * (hi - lo);
                curve_pd(m, from, x2, p, NULL);
                f2 = dist_to(m, 1 - from, other, p);
            }
            hmax = fmax(hmax, fmax(f1, f2));
        }
    }
    return hmax;
}

cf_status_t
cf__fit_error(const cf__osrc_t *s, double a, double b, const double *pts,
              int k, double *err)
{
    double stack[4 * 2 * 129];
    double *buf = stack;
    meas m;
    if (k < 4)
        k = 4;
    if (k > 128) {
        buf = cf__alloc_array((size_t)(8 * (k + 1)), sizeof(double));
        if (buf == NULL)
            return CF_STATUS_NO_MEMORY;
    }
    m.s = s;
    m.a = a;
    m.b = b;
    m.pts = pts;
    m.k = k;
    m.sp = buf;
    m.cp = buf + 2 * (k + 1);
    m.dsp = buf + 4 * (k + 1);
    m.dcp = buf + 6 * (k + 1);
    /* point and derivative, exactly as the foot-point search evaluates
    ** them (the samples are the ends of its intervals) */
    for (int i = 0; i <= k; i++) {
        double u = (double)i / k;
        curve_pd(&m, 1, u, m.sp + 2 * i, m.dsp + 2 * i);
        curve_pd(&m, 0, u, m.cp + 2 * i, m.dcp + 2 * i);
    }
    *err = fmax(directed(&m, 0), directed(&m, 1));
    if (buf != stack)
        cf__free(buf);
    return CF_STATUS_OK;
}
