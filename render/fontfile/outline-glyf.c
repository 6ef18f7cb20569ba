/*
** TrueType glyph outlines (render/fontfile/outline.h): glyf through loca,
** loaded as FreeType 2.12's TrueType loader loads them unhinted:
**   simple     contour ends (increasing), instructions skipped, flags
**              (repeats), x and y deltas; each point FT_MulFix'd by the
**              scales; a point's tag its on-curve bit;
**   composite  each component loaded in turn (its points scaled), then
**              transformed by its 2.14 scale or 2x2 (FT_Outline_
**              Transform on the scaled points) and moved: by its x and y
**              (ARGS_ARE_XY_VALUES, FT_MulFix'd by the scales) or so that
**              its point l meets point k of the components before it;
**              8 levels deep at most;
**   the origin FreeType moves the outline by -pp1.x, the glyph's xMin
**              minus its left side bearing (hmtx), scaled (a component's
**              when it says USE_MY_METRICS).
** SCALED_COMPONENT_OFFSET with a scale (FreeType's FT_Hypot) is not
** handled (1).
*/
#include <string.h>

#include "outline-private.h"

#define MAX_DEPTH 8

enum {
    ARGS_WORDS = 0x1, ARGS_XY = 0x2, HAVE_SCALE = 0x8, MORE = 0x20,
    HAVE_XY_SCALE = 0x40, HAVE_2X2 = 0x80, USE_MY_METRICS = 0x200,
    SCALED_OFFSET = 0x800
};

typedef struct ld {
    const cf__olface_t *f;
    const cf__olsize_t *sz;
    cf__outline_t *o;
} ld_t;

/* The glyph's bytes (len 0: empty). */
static int
glyph_bytes(const cf__olface_t *f, unsigned gid, const unsigned char **p,
            size_t *len)
{
    size_t a, b;
    if (gid >= f->num_glyphs
        || cf__ff_loca_range(&f->loca, f->loca_long, gid, f->glyf.len, &a,
                             &b))
        return 1;
    *p = f->glyf.data + a;
    *len = b - a;
    return 0;
}

/* The left side bearing of gid (hmtx; 0 past a short table). */
static int
lsb(const cf__olface_t *f, unsigned gid)
{
    size_t at = gid < f->num_hmetrics
                ? 4 * (size_t)gid + 2
                : 4 * (size_t)f->num_hmetrics
                  + 2 * ((size_t)gid - f->num_hmetrics);
    return cf__ff_fits(at, 2, f->hmtx.len) ? cf__ff_s16(f->hmtx.data + at)
                                            : 0;
}

static int
simple(ld_t *l, const unsigned char *p, size_t len, int ncont)
{
    cf__outline_t *o = l->o;
    size_t at = 10, base = o->n, npts, i, k, ncontours0 = o->ncontours;
    long prev = -1;
    int64_t x = 0, y = 0;
    size_t flags_at, xs, ys;
    int r;
    if (!cf__ff_fits(at, 2 * (size_t)ncont + 2, len))
        return 1;
    for (k = 0; k < (size_t)ncont; k++) {
        long e = (long)cf__ff_u16(p + at + 2 * k);
        if (e <= prev)
            return 1;
        prev = e;
    }
    npts = (size_t)prev + 1;
    if (base + npts > CF__OL_MAX_POINTS)
        return 1;
    at += 2 * (size_t)ncont;
    at += 2 + cf__ff_u16(p + at);   /* the instructions */
    if (at > len)
        return 1;
    /* flags: find their end and the x and y data's starts */
    flags_at = at;
    xs = 0;
    for (i = 0; i < npts;) {
        unsigned fl, rep = 1;
        size_t w;
        if (at >= len)
            return 1;
        fl = p[at++];
        if (fl & 8) {
            if (at >= len)
                return 1;
            rep += p[at++];
        }
        w = (fl & 2) ? 1 : (fl & 16) ? 0 : 2;
        for (k = 0; k < rep && i < npts; k++, i++)
            xs += w;
    }
    ys = at + xs;
    xs = at;
    /* the points: on-curve bit, x then y deltas */
    for (i = 0, at = flags_at; i < npts;) {
        unsigned fl = p[at++], rep = 1;
        if (fl & 8)
            rep += p[at++];
        for (k = 0; k < rep && i < npts; k++, i++)
            if ((r = cf__ol_add(o, 0, 0, (unsigned char)(fl & 1))) != 0)
                return r;
    }
    for (i = 0, at = flags_at; i < npts;) {
        unsigned fl = p[at++], rep = 1;
        if (fl & 8)
            rep += p[at++];
        for (k = 0; k < rep && i < npts; k++, i++) {
            if (fl & 2) {
                if (xs >= len)
                    return 1;
                x += (fl & 16) ? p[xs] : -(int64_t)p[xs];
                xs++;
            } else if (!(fl & 16)) {
                if (!cf__ff_fits(xs, 2, len))
                    return 1;
                x += cf__ff_s16(p + xs);
                xs += 2;
            }
            if (fl & 4) {
                if (ys >= len)
                    return 1;
                y += (fl & 32) ? p[ys] : -(int64_t)p[ys];
                ys++;
            } else if (!(fl & 32)) {
                if (!cf__ff_fits(ys, 2, len))
                    return 1;
                y += cf__ff_s16(p + ys);
                ys += 2;
            }
            o->x[base + i] = cf__ol_mulfix(x, l->sz->x_scale);
            o->y[base + i] = cf__ol_mulfix(y, l->sz->y_scale);
        }
    }
    for (k = 0; k < (size_t)ncont; k++) {
        size_t n = o->n;
        o->n = base + cf__ff_u16(p + 10 + 2 * k) + 1;
        r = cf__ol_end_contour(o);
        o->n = n;
        if (r != 0)
            return r;
    }
    (void)ncontours0;
    return 0;
}

static int load(ld_t *l, unsigned gid, int depth, int64_t *pp1);

static int
composite(ld_t *l, const unsigned char *p, size_t len, int depth,
          int64_t *pp1)
{
    cf__outline_t *o = l->o;
    size_t at = 10, start = o->n;
    unsigned fl;
    do {
        int64_t a1, a2, m[4] = { 0x10000, 0, 0, 0x10000 }, cpp1 = 0;
        unsigned gid;
        size_t nb, i;
        bool scaled;
        int r;
        if (!cf__ff_fits(at, 4, len))
            return 1;
        fl = cf__ff_u16(p + at);
        gid = cf__ff_u16(p + at + 2);
        at += 4;
        if (!cf__ff_fits(at, (fl & ARGS_WORDS) ? 4 : 2, len))
            return 1;
        if (fl & ARGS_WORDS) {
            a1 = (fl & ARGS_XY) ? (int64_t)cf__ff_s16(p + at)
                                : (int64_t)cf__ff_u16(p + at);
            a2 = (fl & ARGS_XY) ? (int64_t)cf__ff_s16(p + at + 2)
                                : (int64_t)cf__ff_u16(p + at + 2);
            at += 4;
        } else {
            a1 = (fl & ARGS_XY) ? (signed char)p[at] : p[at];
            a2 = (fl & ARGS_XY) ? (signed char)p[at + 1] : p[at + 1];
            at += 2;
        }
        if (fl & HAVE_SCALE) {
            if (!cf__ff_fits(at, 2, len))
                return 1;
            m[0] = m[3] = (int64_t)cf__ff_s16(p + at) * 4;
            at += 2;
        } else if (fl & HAVE_XY_SCALE) {
            if (!cf__ff_fits(at, 4, len))
                return 1;
            m[0] = (int64_t)cf__ff_s16(p + at) * 4;
            m[3] = (int64_t)cf__ff_s16(p + at + 2) * 4;
            at += 4;
        } else if (fl & HAVE_2X2) {
            if (!cf__ff_fits(at, 8, len))
                return 1;
            m[0] = (int64_t)cf__ff_s16(p + at) * 4;       /* xx */
            m[2] = (int64_t)cf__ff_s16(p + at + 2) * 4;   /* yx */
            m[1] = (int64_t)cf__ff_s16(p + at + 4) * 4;   /* xy */
            m[3] = (int64_t)cf__ff_s16(p + at + 6) * 4;   /* yy */
            at += 8;
        }
        scaled = (fl & (HAVE_SCALE | HAVE_XY_SCALE | HAVE_2X2)) != 0;
        nb = o->n;
        if ((r = load(l, gid, depth + 1, &cpp1)) != 0)
            return r;
        if (fl & USE_MY_METRICS)
            *pp1 = cpp1;
        if (o->n == nb)
            continue;
        if (scaled)
            for (i = nb; i < o->n; i++) {
                int64_t x = o->x[i], y = o->y[i];
                o->x[i] = cf__ol_mulfix(x, m[0]) + cf__ol_mulfix(y, m[1]);
                o->y[i] = cf__ol_mulfix(x, m[2]) + cf__ol_mulfix(y, m[3]);
            }
        if (!(fl & ARGS_XY)) {
            size_t k = start + (size_t)a1, q = nb + (size_t)a2;
            if (k >= nb || q >= o->n)
                return 1;
            a1 = o->x[k] - o->x[q];
            a2 = o->y[k] - o->y[q];
        } else {
            if (a1 == 0 && a2 == 0)
                continue;
            if (scaled && (fl & SCALED_OFFSET))
                return 1;
            a1 = cf__ol_mulfix(a1, l->sz->x_scale);
            a2 = cf__ol_mulfix(a2, l->sz->y_scale);
        }
        if (a1 != 0 || a2 != 0)
            for (i = nb; i < o->n; i++) {
                o->x[i] += a1;
                o->y[i] += a2;
            }
    } while (fl & MORE);
    return 0;
}

/* Glyph gid appended to the outline; *pp1 its origin's x (scaled). */
static int
load(ld_t *l, unsigned gid, int depth, int64_t *pp1)
{
    const unsigned char *p;
    size_t len;
    int ncont;
    if (depth > MAX_DEPTH || glyph_bytes(l->f, gid, &p, &len))
        return 1;
    if (len == 0) {
        *pp1 = cf__ol_mulfix(-(int64_t)lsb(l->f, gid), l->sz->x_scale);
        return 0;
    }
    if (len < 10)
        return 1;
    ncont = cf__ff_s16(p);
    *pp1 = cf__ol_mulfix((int64_t)cf__ff_s16(p + 2) - lsb(l->f, gid),
                         l->sz->x_scale);
    if (ncont == 0)
        return 0;
    if (ncont > 0)
        return simple(l, p, len, ncont);
    return composite(l, p, len, depth, pp1);
}

int
cf__ol_glyf_glyph(const cf__olface_t *f, unsigned gid,
                  const cf__olsize_t *sz, cf__outline_t *o)
{
    ld_t l;
    int64_t pp1 = 0;
    size_t i;
    int r;
    l.f = f;
    l.sz = sz;
    l.o = o;
    r = load(&l, gid, 0, &pp1);
    if (r == 0 && pp1 != 0)
        for (i = 0; i < o->n; i++)
            o->x[i] -= pp1;
    return r;
}
