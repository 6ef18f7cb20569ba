/*
** The dash pattern of a stroke cut far away (render/backends/far-clip.h):
** the lengths of the pieces, the lead-ins that keep the phase, the join
** at the start of a closed outline.
*/
#include <math.h>

#include "far-dash.h"

#define LEAD_LEGS 64        /* a lead-in is at most 64 legs of
                               CF__FAR_GROW / 2 device units: a longer
                               dash pattern's phase is lost */

/* ---- lengths (dashes) --------------------------------------------------- */

static double
line_length(const double a[2], const double b[2])
{
    return 2 * hypot(b[0] * 0.5 - a[0] * 0.5, b[1] * 0.5 - a[1] * 0.5);
}

/* The speed of cubic c (scaled) at t. */
static double
speed(const double *c, double t)
{
    double s = 1 - t, d[2];
    for (int k = 0; k < 2; k++)
        d[k] = 3 * (s * s * (c[2 + k] - c[k])
                    + 2 * s * t * (c[4 + k] - c[2 + k])
                    + t * t * (c[6 + k] - c[4 + k]));
    return hypot(d[0], d[1]);
}

/* 5-point Gauss-Legendre of the speed on [t0, t1]. */
static double
gauss(const double *c, double t0, double t1)
{
    static const double x[5] = { 0, 0.5384693101056831, -0.5384693101056831,
                                 0.9061798459386640, -0.9061798459386640 };
    static const double w[5] = { 0.5688888888888889, 0.4786286704993665,
                                 0.4786286704993665, 0.2369268850561891,
                                 0.2369268850561891 };
    double h = (t1 - t0) / 2, m = (t0 + t1) / 2, s = 0;
    for (int i = 0; i < 5; i++)
        s += w[i] * speed(c, m + h * x[i]);
    return s * h;
}

static double
gauss_adapt(const double *c, double t0, double t1, double whole, int depth)
{
    double m = (t0 + t1) / 2, l = gauss(c, t0, m), r = gauss(c, m, t1);
    if (depth >= 24 || fabs(l + r - whole) <= 1e-13 * (l + r))
        return l + r;
    return gauss_adapt(c, t0, m, l, depth + 1)
         + gauss_adapt(c, m, t1, r, depth + 1);
}

static double
curve_length(const double *c)
{
    double big = 0, s[8], scale = 1;
    for (int i = 0; i < 8; i++)
        big = fmax(big, fabs(c[i]));
    if (big > 1e150)
        scale = ldexp(1, -(ilogb(big) - 100));
    for (int i = 0; i < 8; i++)
        s[i] = c[i] * scale;
    return gauss_adapt(s, 0, 1, gauss(s, 0, 1), 0) / scale;
}

double
cf__far_piece_length(const piece_t *pc)
{
    switch (pc->kind) {
    case P_LINE:
        return line_length(pc->a, pc->b);
    case P_CURVE:
        return curve_length(pc->c);
    case P_ARC:
        return fabs(pc->r) * (pc->t1 - pc->t0);
    }
    return 0;
}

/* A run of a stroke starts at a (beyond the visible box: the end of a
** dropped piece, or the subpath's start): after a lead-in that goes out
** and back beyond the side of the box a lies beyond, as long as the
** length walked modulo the dash period, in legs of at most f->leg. */
void
cf__far_start_run(far_t *f, const double a[2])
{
    const cf__far_sink_t *k = f->sink;
    double len = f->dashed ? fmod(f->phi, f->period) : 0, d[2] = { 1, 0 },
           step;
    unsigned n;
    if (!(len > 0)) {
        k->move_to(k->ctx, a[0], a[1]);
        return;
    }
    if (a[0] < f->vis.x0)
        d[0] = -1;
    else if (!(a[0] > f->vis.x1)) {
        d[0] = 0;
        d[1] = a[1] < f->vis.y0 ? -1 : 1;
    }
    n = (unsigned)fmin(ceil(len / f->leg), LEAD_LEGS);
    step = len / n;
    if (n % 2 == 1)
        k->move_to(k->ctx, a[0] + d[0] * step, a[1] + d[1] * step);
    else
        k->move_to(k->ctx, a[0], a[1]);
    for (unsigned i = n; i-- > 0;) {
        double t = i % 2 == 1 ? step : 0;
        k->line_to(k->ctx, a[0] + d[0] * t, a[1] + d[1] * t);
    }
}


/* (x, y) scaled to length 1, into d; false when it has none. */
static bool
unit(double x, double y, double d[2])
{
    double n = hypot(x * 0.5, y * 0.5);
    if (!(n > 0) || !isfinite(n))
        return false;
    d[0] = x * 0.5 / n;
    d[1] = y * 0.5 / n;
    return true;
}

void
cf__far_piece_dir(const piece_t *pc, bool end, double d[2])
{
    const double *c = pc->c;
    d[0] = 1;
    d[1] = 0;
    switch (pc->kind) {
    case P_LINE:
        unit(pc->b[0] - pc->a[0], pc->b[1] - pc->a[1], d);
        break;
    case P_CURVE:
        /* the first control apart from the end */
        for (int i = 1; i <= 3; i++) {
            const double *p = end ? c + 6 - 2 * i : c + 2 * i,
                         *q = end ? c + 6 : c;
            double sign = end ? -1 : 1;
            if (unit(sign * (p[0] - q[0]), sign * (p[1] - q[1]), d))
                break;
        }
        break;
    case P_ARC: {
        double t = end ? pc->t1 : pc->t0;
        unit(-pc->r * sin(t), pc->r * cos(t), d);
        break;
    }
    }
}

void
cf__far_close_join(far_t *f, const double s0[2])
{
    const cf__stroke_t *s = f->style;
    const cf__far_sink_t *k = f->sink;
    double phase = fmod(f->phi, f->period), at = 0, elapsed = 0, eps;
    size_t n = s->dash_count;
    bool on = false;
    if (!(n > 0 && s->dash[0] > 0))
        return;
    /* where the end falls in the pattern (twice over: an odd count's
    ** period) */
    for (size_t i = 0; i < 2 * n; i++) {
        if (phase < at + s->dash[i % n]) {
            on = i % 2 == 0;
            elapsed = phase - at;
            break;
        }
        at += s->dash[i % n];
    }
    eps = 0.5 * fmin(fmin(elapsed, s->dash[0]),
                     fmin(0.025 * s->width, fmin(f->in_len, f->out_len)));
    if (!on || !(eps > 0))
        return;
    /* from the last dash through s0 into the first: on all along (its
    ** phase from 0, within the first dash), inside the two dashes' strokes
    ** but for the join */
    k->move_to(k->ctx, s0[0] - eps * f->in_dir[0], s0[1] - eps * f->in_dir[1]);
    k->line_to(k->ctx, s0[0], s0[1]);
    k->line_to(k->ctx, s0[0] + eps * f->out_dir[0],
               s0[1] + eps * f->out_dir[1]);
}
