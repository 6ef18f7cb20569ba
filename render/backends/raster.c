/*
** The rasterizer of the measuring seam (render/backends/raster.h).  Paths are
** flattened (cubics into ceil(sqrt(0.75 |second difference| / tol))
** chords, arcs into chords of sagitta at most tol), fills become the
** polygon of their subpaths, strokes the union of one quadrilateral a
** segment, a wedge or a miter a join, and a half disc a round cap, every
** piece wound positively so that the nonzero rule unites them (cairo's
** miter limit 10, beyond it a bevel).  Their coverage is
** render/backends/coverage.c's.
*/
#include <math.h>
#include <string.h>

#include "raster.h"

#define PI 3.14159265358979323846
#define MITER_LIMIT 10.0
#define MAX_CHORDS 256        /* chords of one cubic or arc at most */

typedef struct pt { double x, y; } pt_t;

typedef struct pts { pt_t *p; size_t n, cap; bool failed; } pts_t;

static void
pts_add(pts_t *a, double x, double y)
{
    if (a->n == a->cap) {
        size_t cap = a->cap ? 2 * a->cap : 64;
        pt_t *p = cf_realloc_array(a->p, cap, sizeof *p);
        if (p == NULL) {
            a->failed = true;
            return;
        }
        a->p = p;
        a->cap = cap;
    }
    a->p[a->n].x = x;
    a->p[a->n].y = y;
    a->n++;
}

/* ---- polygons ----------------------------------------------------------- */

void
cf__poly_init(cf__poly_t *pl)
{
    memset(pl, 0, sizeof *pl);
    pl->box[0] = 1;
    pl->box[2] = 0;
}

void
cf__poly_reset(cf__poly_t *pl)
{
    pl->n = 0;
    pl->box[0] = 1;
    pl->box[2] = 0;
    pl->failed = false;
}

void
cf__poly_free(cf__poly_t *pl)
{
    cf_free(pl->e);
    cf_free(pl->scratch);
    cf__poly_init(pl);
}

static void
edge(cf__poly_t *pl, pt_t a, pt_t b)
{
    cf__edge_t *e;
    if (!(isfinite(a.x) && isfinite(a.y) && isfinite(b.x) && isfinite(b.y))) {
        pl->failed = true;
        return;
    }
    cf__box_grow(pl->box, a.x, a.y);
    cf__box_grow(pl->box, b.x, b.y);
    if (a.y == b.y)
        return;
    if (pl->n == pl->cap) {
        size_t cap = pl->cap ? 2 * pl->cap : 256;
        cf__edge_t *p = cf_realloc_array(pl->e, cap, sizeof *p);
        if (p == NULL) {
            pl->failed = true;
            return;
        }
        pl->e = p;
        pl->cap = cap;
    }
    e = &pl->e[pl->n++];
    e->dir = b.y > a.y ? 1 : -1;
    if (b.y < a.y) {
        pt_t t = a;
        a = b;
        b = t;
    }
    e->x0 = a.x;
    e->y0 = a.y;
    e->x1 = b.x;
    e->y1 = b.y;
    e->dxdy = (b.x - a.x) / (b.y - a.y);
}

/* A closed polygon of n points; wound positively when orient (the
** pieces of a stroke then unite under the nonzero rule). */
static void
polygon(cf__poly_t *pl, const pt_t *p, size_t n, bool orient)
{
    double area = 0;
    size_t i;
    if (n < 2)
        return;
    if (pl->box_only) {
        /* the box of the edges below: their every end */
        for (i = 0; i < n; i++) {
            if (!(isfinite(p[i].x) && isfinite(p[i].y)))
                pl->failed = true;
            else
                cf__box_grow(pl->box, p[i].x, p[i].y);
        }
        return;
    }
    for (i = 0; i < n; i++) {
        const pt_t *a = &p[i], *b = &p[(i + 1) % n];
        area += a->x * b->y - b->x * a->y;
    }
    if (!orient || area >= 0) {
        for (i = 0; i < n; i++)
            edge(pl, p[i], p[(i + 1) % n]);
    } else {
        for (i = n; i > 0; i--)
            edge(pl, p[i % n], p[i - 1]);
    }
}

/* ---- flattening --------------------------------------------------------- */

typedef void (*subpath_fn)(void *ctx, const pt_t *p, size_t n, bool closed);

static size_t
arc_chords(double r, double sweep, double tol)
{
    double step = r > tol ? 2 * acos(1 - tol / r) : PI / 2;
    double n = ceil(fabs(sweep) / fmin(step, PI / 2));
    /* (NaN, from a point not finite: one chord, which edge() refuses) */
    return !(n >= 1) ? 1 : n > MAX_CHORDS ? MAX_CHORDS : (size_t)n;
}

static void
flatten_curve(pts_t *a, pt_t p0, const double *v, const cf__xform_t *m)
{
    double x1 = v[0] * m->scale + m->dx, y1 = v[1] * m->scale + m->dy;
    double x2 = v[2] * m->scale + m->dx, y2 = v[3] * m->scale + m->dy;
    double x3 = v[4] * m->scale + m->dx, y3 = v[5] * m->scale + m->dy;
    double ddx = fmax(fabs(p0.x - 2 * x1 + x2), fabs(x1 - 2 * x2 + x3));
    double ddy = fmax(fabs(p0.y - 2 * y1 + y2), fabs(y1 - 2 * y2 + y3));
    double c = ceil(sqrt(0.75 * hypot(ddx, ddy) / m->tol));
    size_t k, n = !(c >= 1) ? 1 : c > MAX_CHORDS ? MAX_CHORDS : (size_t)c;
    for (k = 1; k <= n; k++) {
        double t = (double)k / (double)n, s = 1 - t;
        double b0 = s * s * s, b1 = 3 * s * s * t, b2 = 3 * s * t * t,
               b3 = t * t * t;
        pts_add(a, b0 * p0.x + b1 * x1 + b2 * x2 + b3 * x3,
                b0 * p0.y + b1 * y1 + b2 * y2 + b3 * y3);
    }
}

/* cairo_arc's: a line to its start (a move without a current point),
** counter-clockwise on the y-down page from a0 to a1. */
static void
flatten_arc(pts_t *a, const double *v, const cf__xform_t *m)
{
    double cx = v[0] * m->scale + m->dx, cy = v[1] * m->scale + m->dy;
    double r = fabs(v[2]) * m->scale, a0, a1;
    size_t k, n;
    if (!cf__arc_range(v, &a0, &a1)) {
        a->failed = true;
        return;
    }
    n = arc_chords(r, a1 - a0, m->tol);
    for (k = 0; k <= n; k++) {
        double t = a0 + (a1 - a0) * (double)k / (double)n;
        pts_add(a, cx + r * cos(t), cy + r * sin(t));
    }
}

/* Each subpath of p that draws flattened into device points, handed to
** f (a lone move draws nothing). */
static void
walk(const cf__path_t *p, const cf__xform_t *m, subpath_fn f, void *ctx,
     pts_t *a)
{
    const double *v = p->coords;
    bool drawn = false;
    size_t i;
    a->n = 0;
    for (i = 0; i < p->nsegs && !a->failed; i++) {
        double x = 0, y = 0;
        if (p->segs[i] != CF__SEG_CLOSE) {
            x = v[0] * m->scale + m->dx;
            y = v[1] * m->scale + m->dy;
        }
        switch ((cf__seg_t)p->segs[i]) {
        case CF__SEG_MOVE:
            if (drawn)
                f(ctx, a->p, a->n, false);
            a->n = 0;
            drawn = false;
            pts_add(a, x, y);
            v += 2;
            break;
        case CF__SEG_LINE:
            drawn = drawn || a->n > 0;
            pts_add(a, x, y);
            v += 2;
            break;
        case CF__SEG_CURVE:
            if (a->n == 0)
                pts_add(a, x, y);
            if (!a->failed)
                flatten_curve(a, a->p[a->n - 1], v, m);
            drawn = true;
            v += 6;
            break;
        case CF__SEG_RECT: {
            double w = v[2] * m->scale, h = v[3] * m->scale;
            if (drawn)
                f(ctx, a->p, a->n, false);
            a->n = 0;
            pts_add(a, x, y);
            pts_add(a, x + w, y);
            pts_add(a, x + w, y + h);
            pts_add(a, x, y + h);
            if (!a->failed)
                f(ctx, a->p, a->n, true);
            /* cairo_rectangle leaves the current point at its corner */
            a->n = 1;
            drawn = false;
            v += 4;
            break;
        }
        case CF__SEG_ARC:
            drawn = true;
            flatten_arc(a, v, m);
            v += 5;
            break;
        case CF__SEG_CLOSE:
            if (a->n > 0)
                f(ctx, a->p, a->n, true);
            /* what follows starts at the subpath's first point */
            a->n = a->n > 0 ? 1 : 0;
            drawn = false;
            break;
        }
    }
    if (drawn && !a->failed)
        f(ctx, a->p, a->n, false);
}

static void
fill_subpath(void *ctx, const pt_t *p, size_t n, bool closed)
{
    (void)closed;
    polygon(ctx, p, n, false);
}

void
cf__poly_fill(cf__poly_t *pl, const cf__path_t *p, const cf__xform_t *m)
{
    pts_t a = { NULL, 0, 0, false };
    walk(p, m, fill_subpath, pl, &a);
    if (a.failed)
        pl->failed = true;
    cf_free(a.p);
}

/* ---- strokes ------------------------------------------------------------ */

typedef struct stroker {
    cf__poly_t *pl;
    double hw, tol;
    cf__cap_t cap;
    cf__join_t join;
    const double *dash;   /* device units */
    size_t ndash;
    pts_t piece;          /* one dash */
    bool failed;
} stroker_t;

/* The wedge of a round join or cap: centre v, radius hw, from angle t0
** through sweep. */
static void
wedge(stroker_t *s, pt_t v, double t0, double sweep)
{
    pt_t q[MAX_CHORDS + 2];
    size_t k, n = arc_chords(s->hw, sweep, s->tol);
    q[0] = v;
    for (k = 0; k <= n; k++) {
        double t = t0 + sweep * (double)k / (double)n;
        q[k + 1].x = v.x + s->hw * cos(t);
        q[k + 1].y = v.y + s->hw * sin(t);
    }
    polygon(s->pl, q, n + 2, true);
}

static void
join(stroker_t *s, pt_t a, pt_t v, pt_t b)
{
    double ux = v.x - a.x, uy = v.y - a.y, wx = b.x - v.x, wy = b.y - v.y;
    double lu = hypot(ux, uy), lw = hypot(wx, wy), cross, side, cosang;
    pt_t q[4];
    if (!(lu > 0 && lw > 0))
        return;
    ux /= lu, uy /= lu, wx /= lw, wy /= lw;
    cross = ux * wy - uy * wx;
    cosang = ux * wx + uy * wy;
    if (fabs(cross) < 1e-12 && cosang > 0)
        return;   /* straight on */
    side = cross > 0 ? -1 : 1;          /* the outer side's normal sign */
    q[0] = v;
    q[1].x = v.x - side * uy * s->hw;
    q[1].y = v.y + side * ux * s->hw;
    q[3].x = v.x - side * wy * s->hw;
    q[3].y = v.y + side * wx * s->hw;
    if (s->join == CF__JOIN_ROUND) {
        double t0 = atan2(q[1].y - v.y, q[1].x - v.x);
        double t1 = atan2(q[3].y - v.y, q[3].x - v.x), sw = t1 - t0;
        while (sw > PI)
            sw -= 2 * PI;
        while (sw < -PI)
            sw += 2 * PI;
        wedge(s, v, t0, sw);
        return;
    }
    {
        /* the miter's length over the half width: 1 / sin(angle / 2) */
        double ml = 1 / sqrt(fmax(1e-300, 0.5 * (1 + cosang)));
        double mx = (q[1].x + q[3].x) / 2 - v.x,
               my = (q[1].y + q[3].y) / 2 - v.y, lm = hypot(mx, my);
        if (ml <= MITER_LIMIT && lm > 0) {
            q[2].x = v.x + mx / lm * ml * s->hw;
            q[2].y = v.y + my / lm * ml * s->hw;
            polygon(s->pl, q, 4, true);
            return;
        }
    }
    q[2] = q[3];
    polygon(s->pl, q, 3, true);
}

/* The round cap at end point p of a line leaving in direction (dx, dy). */
static void
cap(stroker_t *s, pt_t p, double dx, double dy)
{
    if (s->cap == CF__CAP_ROUND)
        wedge(s, p, atan2(dy, dx) + PI / 2, PI);
}

/* One dash (or the whole line): segments, joins, caps; closed: its last
** point is its first, joined round to its second. */
static void
stroke_piece(stroker_t *s, const pt_t *p, size_t n, bool closed)
{
    size_t i, first = n, last = 0;
    for (i = 0; i + 1 < n; i++) {
        double dx = p[i + 1].x - p[i].x, dy = p[i + 1].y - p[i].y;
        double l = hypot(dx, dy), nx, ny;
        pt_t q[4];
        if (!(l > 0))
            continue;
        if (first == n)
            first = i;
        last = i;
        nx = -dy / l * s->hw;
        ny = dx / l * s->hw;
        q[0].x = p[i].x + nx, q[0].y = p[i].y + ny;
        q[1].x = p[i + 1].x + nx, q[1].y = p[i + 1].y + ny;
        q[2].x = p[i + 1].x - nx, q[2].y = p[i + 1].y - ny;
        q[3].x = p[i].x - nx, q[3].y = p[i].y - ny;
        polygon(s->pl, q, 4, true);
    }
    if (first == n) {
        /* a dot: cairo draws round caps of a degenerate line */
        if (s->cap == CF__CAP_ROUND && n >= 1)
            wedge(s, p[0], 0, 2 * PI);
        return;
    }
    for (i = 1; i + 1 < n; i++)
        join(s, p[i - 1], p[i], p[i + 1]);
    if (closed && n >= 3) {
        join(s, p[n - 2], p[0], p[1]);
    } else {
        cap(s, p[first], p[first].x - p[first + 1].x,
            p[first].y - p[first + 1].y);
        cap(s, p[last + 1], p[last + 1].x - p[last].x,
            p[last + 1].y - p[last].y);
    }
}

static void
stroke_subpath(void *ctx, const pt_t *p, size_t n, bool closed)
{
    stroker_t *s = ctx;
    pts_t *a = &s->piece;
    size_t i, k = 0;
    bool on = true;
    double left;
    if (s->ndash == 0) {
        if (!closed || (p[n - 1].x == p[0].x && p[n - 1].y == p[0].y)) {
            stroke_piece(s, p, n, closed);
            return;
        }
        /* the closing segment back to the first point */
        a->n = 0;
        for (i = 0; i < n; i++)
            pts_add(a, p[i].x, p[i].y);
        pts_add(a, p[0].x, p[0].y);
        if (a->failed)
            s->failed = true;
        else
            stroke_piece(s, a->p, a->n, true);
        return;
    }
    /* dashes along the line, the closing segment included */
    left = s->dash[0];
    a->n = 0;
    pts_add(a, p[0].x, p[0].y);
    for (i = 0; i < n - (closed ? 0 : 1) && !a->failed; i++) {
        pt_t u = p[i], v = p[(i + 1) % n];
        double l = hypot(v.x - u.x, v.y - u.y), pos = 0;
        while (!a->failed && l - pos > left) {
            double t = (pos + left) / l;
            pt_t mid = { u.x + t * (v.x - u.x), u.y + t * (v.y - u.y) };
            if (on) {
                pts_add(a, mid.x, mid.y);
                stroke_piece(s, a->p, a->n, false);
            }
            a->n = 0;
            pts_add(a, mid.x, mid.y);
            pos += left;
            on = !on;
            k = (k + 1) % s->ndash;
            left = s->dash[k];
        }
        left -= l - pos;
        if (on)
            pts_add(a, v.x, v.y);
    }
    if (on && !a->failed && a->n > 0)
        stroke_piece(s, a->p, a->n, false);
    if (a->failed)
        s->failed = true;
}

bool
cf__pen_solid(const cf__path_t *p, const cf__xform_t *m, const cf__pen_t *pen,
              double *coverage)
{
    double total = 0, inked = 0, period, len;
    double cap = pen->cap == CF__CAP_ROUND ? PI / 4 : 0;
    size_t i, n = pen->ndash < CF_STYLE_DASH_MAX ? pen->ndash
                                                 : CF_STYLE_DASH_MAX;
    *coverage = 1;
    for (i = 0; i < n; i++)
        total += pen->dash[i];
    if (n == 0 || !(total > 0 && isfinite(total)))
        return false;   /* cf__poly_stroke strokes it solid anyway */
    /* cairo's _cairo_stroke_style_dash_stroked: an odd pattern repeats
    ** with on and off swapped */
    if (n % 2 == 1) {
        for (i = 0; i < n; i++)
            inked += pen->dash[i] + cap * fmin(pen->dash[i], pen->width);
        period = 2 * total;
    } else {
        for (i = 0; i + 1 < n; i += 2)
            inked += pen->dash[i] + cap * fmin(pen->dash[i + 1], pen->width);
        period = total;
    }
    len = cf__path_length_bound(p, m->scale);
    if (total * m->scale >= m->tol
        && len / (total * m->scale) * (double)n <= CF__DASH_MAX)
        return false;
    *coverage = fmin(1, inked / period);
    return true;
}

void
cf__poly_stroke(cf__poly_t *pl, const cf__path_t *p, const cf__xform_t *m,
                const cf__pen_t *pen, double *coverage)
{
    double dash[CF_STYLE_DASH_MAX], total = 0, cov = 1;
    pts_t a = { NULL, 0, 0, false };
    stroker_t s;
    size_t i, n;
    memset(&s, 0, sizeof s);
    s.pl = pl;
    s.hw = 0.5 * pen->width * m->scale;
    s.tol = m->tol;
    s.cap = pen->cap;
    s.join = pen->join;
    if (coverage != NULL)
        *coverage = 1;
    if (!(s.hw > 0))
        return;
    /* (a pattern too fine, or a path too long for it, drawn solid: the
    ** caller weighs it by its coverage) */
    n = pen->ndash > 0 && cf__pen_solid(p, m, pen, &cov) ? 0 : pen->ndash;
    if (coverage != NULL)
        *coverage = cov;
    for (i = 0; i < n && i < CF_STYLE_DASH_MAX; i++) {
        dash[i] = pen->dash[i] * m->scale;
        total += dash[i];
    }
    /* a pattern of no length (or a bad one) draws the line solid */
    if (i > 0 && total > 0 && isfinite(total)) {
        s.dash = dash;
        s.ndash = i;
    }
    walk(p, m, stroke_subpath, &s, &a);
    if (a.failed || s.failed)
        pl->failed = true;
    cf_free(a.p);
    cf_free(s.piece.p);
}
