/*
** The pieces of a path cut far away (render/backends/far-clip.h): the
** path read subpath by subpath as cairo reads it, and each subpath that
** the clip box does not hold walked as pieces, lines, cubics (de Casteljau
** at 1/2) and arcs (their angle), halved until one lies within the clip
** box (kept as it is) or wholly beyond the visible box (dropped, or its
** chord); no flattening and no intersection, so a line from 1e300 is cut
** as exactly as one from 1e5.  What becomes of a piece and of a subpath
** is the fill's (far-fill.c) or the stroke's (far-stroke.c): far_t's
** piece and sub, so that this walk knows neither.
*/
#include <math.h>

#include "far-halve.h"

#define MAX_DEPTH 1200      /* halvings: 2^1024 (the largest double) down
                               to 2^-176 of it; a piece still unsure there
                               is dropped (not reached with finite input) */
#define HALF_PI 1.5707963267948966
#define TWO_PI 6.283185307179586

/* ---- boxes -------------------------------------------------------------- */

static box_t
box_of(const double *p, size_t n)
{
    box_t b = { p[0], p[1], p[0], p[1] };
    for (size_t i = 2; i + 1 < 2 * n; i += 2) {
        b.x0 = fmin(b.x0, p[i]);
        b.x1 = fmax(b.x1, p[i]);
        b.y0 = fmin(b.y0, p[i + 1]);
        b.y1 = fmax(b.y1, p[i + 1]);
    }
    return b;
}

static void
grow(box_t *b, const box_t *o)
{
    b->x0 = fmin(b->x0, o->x0);
    b->y0 = fmin(b->y0, o->y0);
    b->x1 = fmax(b->x1, o->x1);
    b->y1 = fmax(b->y1, o->y1);
}

static bool
inside(const box_t *b, const box_t *in)
{
    return b->x0 >= in->x0 && b->x1 <= in->x1 && b->y0 >= in->y0
        && b->y1 <= in->y1;
}

static bool
apart(const box_t *b, const box_t *o)
{
    return b->x0 > o->x1 || b->x1 < o->x0 || b->y0 > o->y1 || b->y1 < o->y0;
}

/* ---- the segments of a path --------------------------------------------- */

static void
arc_point(double cx, double cy, double r, double t, double p[2])
{
    p[0] = cx + r * cos(t);
    p[1] = cy + r * sin(t);
}

/* cairo_arc's angles: a1 raised by whole turns to at least a0. */
static double
arc_end(double a0, double a1)
{
    if (a1 < a0) {
        a1 = fmod(a1 - a0, TWO_PI);
        if (a1 < 0)
            a1 += TWO_PI;
        a1 += a0;
    }
    return a1;
}

/* The box of an arc (angles t0 <= t1): within the triangle of its ends and
** the meeting of their tangents up to a quarter turn, else its circle's. */
static box_t
arc_box(double cx, double cy, double r, double t0, double t1)
{
    double p[6];
    r = fabs(r);
    if (!(t1 - t0 <= HALF_PI)) {
        box_t b = { cx - r, cy - r, cx + r, cy + r };
        return b;
    }
    arc_point(cx, cy, r, t0, p);
    arc_point(cx, cy, r, t1, p + 2);
    arc_point(cx, cy, r / cos((t1 - t0) / 2), t0 * 0.5 + t1 * 0.5, p + 4);
    return box_of(p, 3);
}

static size_t
seg_coords(unsigned char s)
{
    static const unsigned char n[] = {
        [CF__SEG_MOVE] = 2, [CF__SEG_LINE] = 2, [CF__SEG_CURVE] = 6,
        [CF__SEG_RECT] = 4, [CF__SEG_ARC] = 5, [CF__SEG_CLOSE] = 0
    };
    return s < sizeof n ? n[s] : 0;
}

/* The box of segment s (coordinates v) with the point before it. */
static void
seg_box(unsigned char s, const double *v, box_t *b)
{
    box_t o;
    switch ((cf__seg_t)s) {
    case CF__SEG_MOVE:
    case CF__SEG_LINE:
        o = box_of(v, 1);
        break;
    case CF__SEG_CURVE:
        o = box_of(v, 3);
        break;
    case CF__SEG_RECT: {
        double p[4] = { v[0], v[1], v[0] + v[2], v[1] + v[3] };
        o = box_of(p, 2);
        break;
    }
    case CF__SEG_ARC:
        o = arc_box(v[0], v[1], v[2], 0, TWO_PI);
        break;
    default:
        return;
    }
    grow(b, &o);
}

/* ---- what becomes of a piece -------------------------------------------- */

void
cf__far_send(const far_t *f, const piece_t *pc)
{
    const cf__far_sink_t *k = f->sink;
    switch (pc->kind) {
    case P_LINE:
        k->line_to(k->ctx, pc->b[0], pc->b[1]);
        break;
    case P_CURVE:
        k->curve_to(k->ctx, pc->c[2], pc->c[3], pc->c[4], pc->c[5],
                    pc->c[6], pc->c[7]);
        break;
    case P_ARC:
        k->arc(k->ctx, pc->cx, pc->cy, pc->r, pc->t0, pc->t1);
        break;
    }
}

/* Piece pc with box b: kept, dropped, or not yet (*done false: halve it).
** A piece with a coordinate that is not finite (a marker of a size that
** overflows) is dropped: it would halve into nothing but such pieces. */
static void
take(far_t *f, const piece_t *pc, const box_t *b, bool *done, int depth)
{
    bool keep = inside(b, &f->clip);
    *done = keep || apart(b, &f->vis) || depth >= MAX_DEPTH
        || !(isfinite(b->x0) && isfinite(b->x1) && isfinite(b->y0)
             && isfinite(b->y1));
    if (!*done)
        return;
    f->piece(f, pc, keep);
}

/* ---- halving ------------------------------------------------------------ */

static void
mid(const double *p, const double *q, double *m)
{
    m[0] = p[0] * 0.5 + q[0] * 0.5;
    m[1] = p[1] * 0.5 + q[1] * 0.5;
}

/* Where to cut a line with one end in the clip box and the other far
** beyond (more than 4 times the box's size): at m, beyond the visible box
** from that end by the box's margin, so that the far part is dropped at
** once instead of after a thousand halvings (a line from 1e300).  m is
** the near end plus a fraction of the difference, exact to its rounding
** relative to that fraction (as a halving is); false: halve. */
static bool
jump(const far_t *f, const double a[2], const double b[2], double m[2])
{
    const box_t *c = &f->clip;
    double span = fmax(c->x1 - c->x0, c->y1 - c->y0), d[2], dmax, t;
    bool a_in = !(a[0] < c->x0 || a[0] > c->x1 || a[1] < c->y0
                  || a[1] > c->y1),
         b_in = !(b[0] < c->x0 || b[0] > c->x1 || b[1] < c->y0
                  || b[1] > c->y1);
    const double *n = a_in ? a : b, *r = a_in ? b : a;
    if (a_in == b_in)
        return false;
    d[0] = r[0] * 0.5 - n[0] * 0.5;
    d[1] = r[1] * 0.5 - n[1] * 0.5;
    dmax = fmax(fabs(d[0]), fabs(d[1]));
    if (!(dmax > 2 * span) || !isfinite(dmax))
        return false;
    /* the near end moved by the box's size on the main axis: beyond the
    ** visible box on the far end's side */
    t = span / dmax;
    m[0] = n[0] + d[0] * t;
    m[1] = n[1] + d[1] * t;
    return true;
}

static void
line_piece(far_t *f, const double a[2], const double b[2], int depth)
{
    piece_t pc = { P_LINE, { a[0], a[1] }, { b[0], b[1] }, NULL, 0, 0, 0, 0,
                   0 };
    double p[4] = { a[0], a[1], b[0], b[1] }, m[2];
    box_t bb = box_of(p, 2);
    bool done;
    take(f, &pc, &bb, &done, depth);
    if (done)
        return;
    if (!jump(f, a, b, m))
        mid(a, b, m);
    line_piece(f, a, m, depth + 1);
    line_piece(f, m, b, depth + 1);
}

static bool
in_box(const box_t *b, const double p[2])
{
    return !out_of(b, p[0], p[1]);
}

/* Cubic c split at t (small), from its start: h[0..7] the part [0, t],
** its points from the start plus fractions of the differences to it
** (exact to rounding relative to the part's size, as halvings are; the
** differences halved so that they cannot overflow), h[6..13] the rest,
** whose far points are the convex combinations of c's. */
static void
split_near(const double c[8], double t, double h[14])
{
    double s = 1 - t, d[3][2];
    for (int k = 0; k < 2; k++) {
        for (int i = 0; i < 3; i++)
            d[i][k] = c[2 * i + 2 + k] * 0.5 - c[k] * 0.5;
        h[k] = c[k];
        h[2 + k] = c[k] + 2 * t * d[0][k];
        h[4 + k] = c[k] + 4 * t * s * d[0][k] + 2 * t * t * d[1][k];
        h[6 + k] = c[k] + 6 * t * s * s * d[0][k] + 6 * t * t * s * d[1][k]
                 + 2 * t * t * t * d[2][k];
        h[8 + k] = s * s * c[2 + k] + 2 * t * s * c[4 + k] + t * t * c[6 + k];
        h[10 + k] = s * c[4 + k] + t * c[6 + k];
        h[12 + k] = c[6 + k];
    }
}

/* Where to cut a cubic with an end in the clip box and its other points
** spread more than 4 times the box's size: a part from that end about the
** box's size (kept after a few halvings) and the rest, as jump does for
** lines (a cubic whose controls lie at 1e300 took 2000 halvings); h as
** de Casteljau's halves; false: halve. */
static bool
curve_jump(const far_t *f, const double c[8], double h[14])
{
    const box_t *b = &f->clip;
    double span = fmax(b->x1 - b->x0, b->y1 - b->y0), dmax = 0, r[8],
           g[14];
    bool start = in_box(b, c);
    if (!start && !in_box(b, c + 6))
        return false;
    for (int i = 2; i < 8; i++) {
        double o = start ? c[i % 2] : c[6 + i % 2];
        dmax = fmax(dmax, fabs(c[start ? i : 6 - i + 2 * (i % 2)] * 0.5
                               - o * 0.5));
    }
    if (!(dmax > 2 * span) || !isfinite(dmax))
        return false;
    if (start) {
        split_near(c, span / (6 * dmax), h);
        return true;
    }
    /* from the end: the reversed cubic split, its parts reversed */
    for (int i = 0; i < 4; i++) {
        r[2 * i] = c[6 - 2 * i];
        r[2 * i + 1] = c[7 - 2 * i];
    }
    split_near(r, span / (6 * dmax), g);
    for (int i = 0; i < 7; i++) {
        h[2 * i] = g[12 - 2 * i];
        h[2 * i + 1] = g[13 - 2 * i];
    }
    return true;
}

static void
curve_piece(far_t *f, const double c[8], int depth)
{
    piece_t pc = { P_CURVE, { c[0], c[1] }, { c[6], c[7] }, c, 0, 0, 0, 0,
                   0 };
    box_t bb = box_of(c, 4);
    double h[14];
    bool done;
    take(f, &pc, &bb, &done, depth);
    if (done)
        return;
    if (curve_jump(f, c, h)) {
        curve_piece(f, h, depth + 1);
        curve_piece(f, h + 6, depth + 1);
        return;
    }
    /* de Casteljau at 1/2: h[0..7] the first half, h[6..13] the second */
    h[0] = c[0];
    h[1] = c[1];
    h[12] = c[6];
    h[13] = c[7];
    mid(c, c + 2, h + 2);
    mid(c + 4, c + 6, h + 10);
    {
        double m12[2];
        mid(c + 2, c + 4, m12);
        mid(h + 2, m12, h + 4);
        mid(m12, h + 10, h + 8);
    }
    mid(h + 4, h + 8, h + 6);
    curve_piece(f, h, depth + 1);
    curve_piece(f, h + 6, depth + 1);
}

static void
arc_piece(far_t *f, double cx, double cy, double r, double t0, double t1,
          int depth)
{
    piece_t pc = { P_ARC, { 0, 0 }, { 0, 0 }, NULL, cx, cy, r, t0, t1 };
    box_t bb = arc_box(cx, cy, r, t0, t1);
    double tm = t0 * 0.5 + t1 * 0.5;
    bool done;
    arc_point(cx, cy, r, t0, pc.a);
    arc_point(cx, cy, r, t1, pc.b);
    take(f, &pc, &bb, &done, depth);
    if (done)
        return;
    arc_piece(f, cx, cy, r, t0, tm, depth + 1);
    arc_piece(f, cx, cy, r, tm, t1, depth + 1);
}

/* ---- subpaths ----------------------------------------------------------- */

/* Every piece of s, in order, through take. */
void
cf__far_walk(far_t *f, const sub_t *s)
{
    double pen[2] = { s->start[0], s->start[1] };
    const double *v = s->v;
    if (s->rect != NULL) {
        const double *r = s->rect;
        double p[10] = { r[0], r[1], r[0] + r[2], r[1], r[0] + r[2],
                         r[1] + r[3], r[0], r[1] + r[3], r[0], r[1] };
        for (int i = 0; i < 4; i++)
            line_piece(f, p + 2 * i, p + 2 * i + 2, 0);
        return;
    }
    for (size_t i = 0; i < s->n; i++) {
        switch ((cf__seg_t)s->segs[i]) {
        case CF__SEG_LINE:
            line_piece(f, pen, v, 0);
            pen[0] = v[0];
            pen[1] = v[1];
            break;
        case CF__SEG_CURVE: {
            double c[8] = { pen[0], pen[1], v[0], v[1], v[2], v[3], v[4],
                            v[5] };
            curve_piece(f, c, 0);
            pen[0] = v[4];
            pen[1] = v[5];
            break;
        }
        case CF__SEG_ARC: {
            double a[2], t1 = arc_end(v[3], v[4]);
            arc_point(v[0], v[1], v[2], v[3], a);
            if (a[0] != pen[0] || a[1] != pen[1])
                line_piece(f, pen, a, 0);
            arc_piece(f, v[0], v[1], v[2], v[3], t1, 0);
            arc_point(v[0], v[1], v[2], t1, pen);
            break;
        }
        default:
            break;
        }
        v += seg_coords(s->segs[i]);
    }
    if (s->closed)
        line_piece(f, pen, s->start, 0);
}

/* s as it is, when the clip box holds it. */
bool
cf__far_send_whole(const far_t *f, const sub_t *s)
{
    const cf__far_sink_t *k = f->sink;
    box_t b = { s->start[0], s->start[1], s->start[0], s->start[1] };
    const double *v = s->v;
    size_t i;
    if (s->rect != NULL)
        seg_box(CF__SEG_RECT, s->rect, &b);
    for (i = 0; i < s->n; i++) {
        seg_box(s->segs[i], v, &b);
        v += seg_coords(s->segs[i]);
    }
    if (!inside(&b, &f->clip))
        return false;
    k->move_to(k->ctx, s->start[0], s->start[1]);
    if (s->rect != NULL) {
        const double *r = s->rect;
        k->line_to(k->ctx, r[0] + r[2], r[1]);
        k->line_to(k->ctx, r[0] + r[2], r[1] + r[3]);
        k->line_to(k->ctx, r[0], r[1] + r[3]);
    }
    for (i = 0, v = s->v; i < s->n; v += seg_coords(s->segs[i]), i++) {
        if (s->segs[i] == CF__SEG_LINE)
            k->line_to(k->ctx, v[0], v[1]);
        else if (s->segs[i] == CF__SEG_CURVE)
            k->curve_to(k->ctx, v[0], v[1], v[2], v[3], v[4], v[5]);
        else if (s->segs[i] == CF__SEG_ARC)
            k->arc(k->ctx, v[0], v[1], v[2], v[3], v[4]);
    }
    if (s->closed || s->rect != NULL)
        k->close_path(k->ctx);
    return true;
}

/* Each subpath of p, as cairo reads the path, to f's fill or stroke. */
void
cf__far_each_sub(far_t *f, const cf__path_t *p)
{
    const double *v = p->coords;
    double move[2] = { 0, 0 };
    bool pen = false;
    size_t i = 0;
    while (i < p->nsegs) {
        unsigned char sk = p->segs[i];
        sub_t s = { { move[0], move[1] }, NULL, NULL, 0, false, NULL };
        if (sk == CF__SEG_CLOSE) {
            i++;
            continue;
        }
        if (sk == CF__SEG_MOVE || sk == CF__SEG_RECT
            || (!pen && sk == CF__SEG_LINE)) {
            move[0] = s.start[0] = v[0];
            move[1] = s.start[1] = v[1];
            if (sk == CF__SEG_RECT)
                s.rect = v;
            v += seg_coords(sk);
            i++;
        } else if (!pen && sk == CF__SEG_CURVE) {
            move[0] = s.start[0] = v[0];
            move[1] = s.start[1] = v[1];
        } else if (!pen && sk == CF__SEG_ARC) {
            arc_point(v[0], v[1], v[2], v[3], move);
            s.start[0] = move[0];
            s.start[1] = move[1];
        }
        pen = true;
        if (s.rect == NULL) {
            s.segs = p->segs + i;
            s.v = v;
            while (i < p->nsegs && (p->segs[i] == CF__SEG_LINE
                                    || p->segs[i] == CF__SEG_CURVE
                                    || p->segs[i] == CF__SEG_ARC)) {
                v += seg_coords(p->segs[i]);
                i++;
                s.n++;
            }
            s.closed = i < p->nsegs && p->segs[i] == CF__SEG_CLOSE;
        }
        f->sub(f, &s);
    }
}
