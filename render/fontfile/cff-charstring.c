/*
** Which subroutines a glyph calls (render/fontfile/sfnt.h): a Type 2
** charstring (Adobe Technical Note #5177) interpreted as far as the
** calls need.  Operands go on a stack of 48; the operators that take
** them are skipped, except
**   callsubr (10), callgsubr (29)  the subroutine numbered by the top
**        operand plus the bias (107 below 1240 subroutines, 1131 below
**        33900, else 32768), marked used and followed, 10 calls deep at
**        most (the Type 2 limit);
**   return (11), endchar (14)  back to the caller, the glyph's end;
**   hstem, vstem, hstemhm, vstemhm (1, 3, 18, 23) and the operands left
**        before hintmask, cntrmask (19, 20): a pair each, the stem hints,
**        whose count sets the bytes of the masks that follow those two;
**   the arithmetic a subroutine number could be computed by (add, sub,
**        mul, div, neg, abs, drop, exch, dup); the rest clear the stack.
** When asked, the scan also lists where each call's number is written
** (the integer just before it) and each hint mask inside a subroutine,
** or says that a number was computed (cf__cff_sites_t), so that the
** subset can renumber the subroutines.
** A glyph that calls outside its INDEX, nests deeper or overflows the
** stack is damaged (1).  The work is bounded: the glyphs of one subset
** share a budget of charstring bytes interpreted, calls included
** (cf__cff_scan_budget), so that subroutines that call each other many
** times over cannot stall the scan.
*/
#include <math.h>

#include "grow.h"
#include "sfnt.h"

#define MAX_DEPTH 10

typedef struct scan {
    cf__ff_t *f;
    unsigned gid;
    cf__cff_subrs_t *global, *local;
    double stack[CF__CFF_MAX_ARGS];
    size_t sp;
    size_t stems;
    long *budget;
    int ended;
    cf__cff_sites_t *sites;
} scan_t;

static int run(scan_t *s, const unsigned char *p, size_t len, int depth,
               int owner, size_t item);

/* A site met (sites wanted) in item of owner. */
static void
site(scan_t *s, int owner, size_t item, const unsigned char *at, size_t len,
     int kind, unsigned old)
{
    cf__cff_sites_t *w = s->sites;
    cf__cff_site_t *v;
    if (w == NULL || w->failed || w->full)
        return;
    if (w->n >= w->max) {
        w->full = 1;
        return;
    }
    v = cf__grow_array(w->v, &w->cap, w->n + 1, sizeof *w->v, 64);
    if (v == NULL) {
        w->failed = 1;
        return;
    }
    w->v = v;
    v += w->n++;
    v->owner = (unsigned char)owner;
    v->owner_fd = (unsigned short)(owner == CF__CFF_IN_LOCAL ? w->fd : 0);
    v->item = (unsigned)(owner == CF__CFF_IN_GLYPH ? w->glyph : item);
    v->at = at;
    v->len = (unsigned)len;
    v->kind = (unsigned char)kind;
    v->fd = (unsigned short)(kind == CF__CFF_SITE_LOCAL ? w->fd : 0);
    v->old = old;
}

/* A call; lit: the bytes of the number it calls when that is the literal
** integer just before it, else NULL. */
static int
call(scan_t *s, cf__cff_subrs_t *subrs, int depth, const char *kind,
     int owner, size_t item, const unsigned char *lit, size_t lit_len)
{
    int global = subrs == s->global;
    double v;
    long k;
    size_t pos, len;
    if (s->sp == 0)
        return cf__ff_fail(s->f, "glyph %u: %s with no operand", s->gid,
                           kind);
    v = s->stack[--s->sp];
    if (subrs == NULL || subrs->index == NULL)
        return cf__ff_fail(s->f, "glyph %u: %s, and the font has no such "
                           "subroutines", s->gid, kind);
    if (!(fabs(v) < 1e6))
        return cf__ff_fail(s->f, "glyph %u: %s %g", s->gid, kind, v);
    k = (long)v + (long)cf__cff_bias(subrs->index->count);
    if (k < 0 || (size_t)k >= subrs->index->count)
        return cf__ff_fail(s->f, "glyph %u: %s %ld of %zu", s->gid, kind,
                           k, subrs->index->count);
    if (depth >= MAX_DEPTH)
        return cf__ff_fail(s->f, "glyph %u: subroutines nested deeper than "
                           "%d", s->gid, MAX_DEPTH);
    if (cf__cff_index_item(s->f, subrs->index, (size_t)k, &pos, &len))
        return 1;
    subrs->used[k] = 1;
    if (s->sites != NULL && lit == NULL)
        s->sites->computed = 1;
    else if (lit != NULL)
        site(s, owner, item, lit, lit_len, global ? CF__CFF_SITE_GLOBAL :
             CF__CFF_SITE_LOCAL, (unsigned)k);
    return run(s, subrs->index->t + pos, len, depth + 1,
               global ? CF__CFF_IN_GLOBAL : CF__CFF_IN_LOCAL, (size_t)k);
}

/* An arithmetic operator (12 x) on the stack; 0 when x is none of
** those followed (the stack is then cleared). */
static int
arith(scan_t *s, unsigned x)
{
    double *st = s->stack;
    size_t n = s->sp;
    switch (x) {
    case 9:   /* abs */
    case 14:  /* neg */
        if (n < 1)
            return 0;
        st[n - 1] = x == 9 ? fabs(st[n - 1]) : -st[n - 1];
        return 1;
    case 10: case 11: case 24: case 12:   /* add sub mul div */
        if (n < 2)
            return 0;
        st[n - 2] = x == 10 ? st[n - 2] + st[n - 1] :
                    x == 11 ? st[n - 2] - st[n - 1] :
                    x == 24 ? st[n - 2] * st[n - 1] :
                    st[n - 1] != 0 ? st[n - 2] / st[n - 1] : 0;
        s->sp--;
        return 1;
    case 18:  /* drop */
        if (n < 1)
            return 0;
        s->sp--;
        return 1;
    case 28: { /* exch */
        double t;
        if (n < 2)
            return 0;
        t = st[n - 1];
        st[n - 1] = st[n - 2];
        st[n - 2] = t;
        return 1;
    }
    case 27:  /* dup */
        if (n < 1 || n >= CF__CFF_MAX_ARGS)
            return 0;
        st[n] = st[n - 1];
        s->sp++;
        return 1;
    default:
        return 0;
    }
}

static int
run(scan_t *s, const unsigned char *p, size_t len, int depth, int owner,
    size_t item)
{
    size_t i = 0, lit = 0, lit_end = (size_t)-1;
    while (i < len && !s->ended) {
        unsigned b0 = p[i];
        if (--*s->budget < 0)
            return cf__ff_fail(s->f, "glyph %u: the scan of the glyphs "
                               "kept ran out of steps (subroutines called "
                               "over and over)", s->gid);
        if (b0 >= 32 || b0 == 28) {
            size_t need;
            double v = cf__cff_cs_operand(p + i, len - i, &need) / 65536.0;
            if (need == 0)
                return cf__ff_fail(s->f, "glyph %u: a charstring ends "
                                   "inside a number", s->gid);
            if (s->sp >= CF__CFF_MAX_ARGS)
                return cf__ff_fail(s->f, "glyph %u: more than %d operands "
                                   "on the stack", s->gid,
                                   CF__CFF_MAX_ARGS);
            s->stack[s->sp++] = v;
            lit = i;
            i += need;
            /* an integer (a 16.16 real is not re-encoded) */
            lit_end = b0 == 255 ? (size_t)-1 : i;
            continue;
        }
        i++;
        switch (b0) {
        case 1: case 3: case 18: case 23:   /* stem hints */
            s->stems += s->sp / 2;
            s->sp = 0;
            break;
        case 19: case 20: {                 /* hintmask, cntrmask */
            size_t bytes;
            s->stems += s->sp / 2;
            s->sp = 0;
            bytes = (s->stems + 7) / 8;
            if (len - i < bytes)
                return cf__ff_fail(s->f, "glyph %u: a charstring ends "
                                   "inside a hint mask", s->gid);
            if (depth > 0)
                site(s, owner, item, p + i, bytes, CF__CFF_SITE_MASK, 0);
            i += bytes;
            break;
        }
        case 10:
        case 29:
            if (call(s, b0 == 10 ? s->local : s->global, depth,
                     b0 == 10 ? "callsubr" : "callgsubr", owner, item,
                     lit_end == i - 1 ? p + lit : NULL, i - 1 - lit))
                return 1;
            break;
        case 11:
            return 0;
        case 14:
            /* endchar with 4 operands more than the width: seac */
            if (s->sp >= 4)
                return cf__ff_fail(s->f, "glyph %u: an accented character "
                                   "made by endchar (seac), which a "
                                   "CID-keyed subset cannot hold", s->gid);
            s->ended = 1;
            return 0;
        case 12:
            if (i >= len)
                return cf__ff_fail(s->f, "glyph %u: a charstring ends "
                                   "inside an operator", s->gid);
            if (!arith(s, p[i]))
                s->sp = 0;
            i++;
            break;
        default:
            s->sp = 0;
            break;
        }
    }
    return 0;
}

long
cf__cff_scan_budget(size_t nglyphs)
{
    /* all 65,535 glyphs of Noto Serif CJK take fewer than 1,024 steps a
       glyph on average, all of LM Math's fewer than 256 */
    return (long)(1 << 22) +
           (nglyphs < (1u << 20) ? (long)nglyphs : (1L << 20)) *
           CF__CFF_STEPS_PER_GLYPH;
}

int
cf__cff_scan_glyph(cf__ff_t *f, const unsigned char *cs, size_t len,
                   unsigned gid, cf__cff_subrs_t *global,
                   cf__cff_subrs_t *local, cf__cff_sites_t *sites,
                   long *budget)
{
    scan_t s;
    s.f = f;
    s.gid = gid;
    s.global = global;
    s.local = local;
    s.sp = 0;
    s.stems = 0;
    s.budget = budget;
    s.ended = 0;
    s.sites = sites;
    return run(&s, cs, len, 0, CF__CFF_IN_GLYPH, 0);
}
