/*
** GPOS's subtables applied at a glyph as HarfBuzz 6.0 applies them
** (render/fontfile/shape-private.h): single (both formats) and pair
** (both formats: the second glyph the next one, a glyph the lookup would
** skip refusing the run; after a pair the next glyph looked at is the
** second, or the one after it when the pair's second value format is not
** empty), value records scaled as HarfBuzz scales them (em_mult), their
** device tables ignored as HarfBuzz does without ppem or variations; every
** other type checked by otrun_not_done.
*/
#include "shape-private.h"

static unsigned
popcount16(unsigned v)
{
    unsigned n = 0;
    for (v &= 0xFFFFu; v; v &= v - 1)
        n++;
    return n;
}

/* A ValueRecord at p of format vf added to glyph g (devices ignored, as
** HarfBuzz does without ppem or variations). */
static void
add_value(ctx_t *c, const otl_tab_t *t, size_t p, unsigned vf,
          cf__otglyph_t *g)
{
    if (vf & 1) {
        g->x_offset += otrun_em_mult(otl_s16(t, p), c->x_mult);
        p += 2;
    }
    if (vf & 2) {
        g->y_offset += otrun_em_mult(otl_s16(t, p), c->y_mult);
        p += 2;
    }
    if (vf & 4)
        g->x_advance += otrun_em_mult(otl_s16(t, p), c->x_mult);
}

/* GPOS subtable at glyph *i: 0 not applied, 1 applied (*i moved). */
int
gpos_apply(ctx_t *c, size_t sub, unsigned type, unsigned flag, size_t *i)
{
    const otl_tab_t *t = &c->gpos;
    cf__otrun_t *r = c->r;
    unsigned format = otl_u16(t, sub), idx, vf1, vf2, len1, len2;
    size_t next = *i + 1;
    if (type != 1 && type != 2)
        return otrun_not_done(c, t, sub, type, false, flag, *i);
    idx = otl_coverage(t, sub + otl_u16(t, sub + 2), r->g[*i].id);
    if (idx == OTL_NOT_COVERED || c->bad)
        return 0;
    vf1 = otl_u16(t, sub + 4);
    if (type == 1) {
        size_t at = sub + 6;
        if (format == 2) {
            if (idx >= otl_u16(t, sub + 6))
                return 0;
            at = sub + 8 + 2 * (size_t)popcount16(vf1) * idx;
        } else if (format != 1) {
            c->refuse = true;
            return 1;
        }
        add_value(c, t, at, vf1, &r->g[*i]);
        *i += 1;
        return 1;
    }
    if (next >= r->n)
        return 0;
    if (r->props[next] & flag & IGNORE_FLAGS) {
        c->refuse = true;
        return 1;
    }
    vf2 = otl_u16(t, sub + 6);
    len1 = popcount16(vf1);
    len2 = popcount16(vf2);
    if (format == 1) {
        size_t set, rec = 0;
        unsigned n;
        int lo, hi;
        if (idx >= otl_u16(t, sub + 8))
            return 0;
        set = sub + otl_u16(t, sub + 10 + 2 * (size_t)idx);
        n = otl_u16(t, set);
        lo = 0;
        hi = (int)n - 1;
        while (lo <= hi && !c->bad) {
            int mid = (int)(((unsigned)lo + (unsigned)hi) / 2);
            size_t at = set + 2 + 2 * (size_t)(1 + len1 + len2) * (size_t)mid;
            unsigned second = otl_u16(t, at);
            if (r->g[next].id < second)
                hi = mid - 1;
            else if (r->g[next].id > second)
                lo = mid + 1;
            else {
                rec = at + 2;
                break;
            }
        }
        if (rec == 0)
            return 0;
        add_value(c, t, rec, vf1, &r->g[*i]);
        add_value(c, t, rec + 2 * (size_t)len1, vf2, &r->g[next]);
    } else if (format == 2) {
        unsigned k1 = otl_class(t, sub + otl_u16(t, sub + 8), r->g[*i].id);
        unsigned k2 = otl_class(t, sub + otl_u16(t, sub + 10),
                                r->g[next].id);
        unsigned n1 = otl_u16(t, sub + 12), n2 = otl_u16(t, sub + 14);
        size_t at;
        if (k1 >= n1 || k2 >= n2)
            return 0;
        at = sub + 16 + 2 * (size_t)(len1 + len2) * ((size_t)k1 * n2 + k2);
        add_value(c, t, at, vf1, &r->g[*i]);
        add_value(c, t, at + 2 * (size_t)len1, vf2, &r->g[next]);
    } else {
        c->refuse = true;
        return 1;
    }
    *i = len2 ? next + 1 : next;
    return 1;
}
