/*
** The shaping of a run (render/fontfile/shape.h) as HarfBuzz 6.0's
** hb_shape does it for the runs it accepts: characters to glyphs by the
** cmap, each glyph's class (GDEF's, else base), GSUB's lookups stage by
** stage (each over the whole run, left to right, the first subtable that
** applies at a glyph wins, the output not looked at again by the same
** lookup), advances from hmtx, GPOS's lookups the same way.  Clusters
** merge as HarfBuzz's monotone-characters level merges them: a ligature
** takes its first component's cluster, and so does every glyph after it
** that shared its last component's.  Whatever else HarfBuzz would do is
** a reason to answer 1 (shape.h).  The subtables are applied by gsub.c
** and gpos.c; the run's arrays and the check of the types not applied
** are otrun.c's (shape-private.h).
*/
#include <string.h>

#include "curvefig/core.h"
#include "otl.h"

#include <string.h>

#include "curvefig/core.h"
#include "shape-private.h"

/* Lookup li of GSUB (gsub) or GPOS over the run. */
static int
apply_lookup(ctx_t *c, bool gsub, unsigned li)
{
    const otl_tab_t *t = gsub ? &c->gsub : &c->gpos;
    cf__otrun_t *r = c->r;
    unsigned type, flag, nsub, j;
    size_t lk = otl_lookup(t, li, &type, &flag, &nsub), i = 0;
    if (lk == 0)
        return c->refuse = true, 0;
    r->tn = 0;
    while (i < r->n && !c->refuse && !c->bad) {
        int done = 0;
        size_t used = 1, at = i;
        if (!(r->props[i] & flag & IGNORE_FLAGS))
            for (j = 0; j < nsub && done == 0 && !c->bad; j++) {
                unsigned st;
                size_t sub = otl_subtable(t, lk, j, gsub ? 7 : 9, &st);
                if (sub == 0)
                    break;
                done = gsub ? gsub_apply(c, sub, st, flag, i, &used)
                            : gpos_apply(c, sub, st, flag, &at);
            }
        if (done < 0)
            return -1;
        if (!gsub) {
            i = done ? at : i + 1;
            continue;
        }
        if (!done && otrun_emit(c, r->g[i].id, r->g[i].cluster, r->props[i]) < 0)
            return -1;
        i += used;
    }
    if (gsub && !c->refuse && !c->bad) {
        cf__otglyph_t *g = r->g;
        unsigned char *p = r->props;
        size_t cap = r->cap;
        r->g = r->tg;
        r->props = r->tprops;
        r->cap = r->tcap;
        r->n = r->tn;
        r->tg = g;
        r->tprops = p;
        r->tcap = cap;
    }
    return 0;
}

/* The next character of UTF-8 s[*k..end): its code, *k moved; -1 when
** the bytes are not UTF-8. */
static long
next_char(const unsigned char *s, size_t end, size_t *k)
{
    unsigned c = s[*k], n, i;
    uint32_t v;
    if (c < 0x80) {
        *k += 1;
        return c;
    }
    n = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC2 ? 1 : 0;
    if (n == 0 || c > 0xF4 || end - *k <= n)
        return -1;
    v = c & (0x3Fu >> n);
    for (i = 1; i <= n; i++) {
        unsigned b = s[*k + i];
        if ((b & 0xC0) != 0x80)
            return -1;
        v = v << 6 | (b & 0x3F);
    }
    if ((n == 2 && v < 0x800) || (n == 3 && (v < 0x10000 || v > 0x10FFFF))
        || (v >= 0xD800 && v <= 0xDFFF))
        return -1;
    *k += n + 1;
    return (long)v;
}

static int
shape(ctx_t *c, uint32_t script, const cf__otscale_t *scale,
      const char *text, size_t off, size_t len)
{
    const cf__otface_t *f = c->f;
    cf__otrun_t *r = c->r;
    otl_plan_t plan;
    size_t k = off, i;
    int s, ret = 0;
    r->n = 0;
    while (k < off + len) {
        size_t at = k;
        long ch = next_char((const unsigned char *)text, off + len, &k);
        unsigned gid;
        if (ch < 0 || ch == 0x2044)
            return 1;
        gid = cf__otface_glyph(f, (uint32_t)ch);
        if (gid == 0 || gid >= f->num_glyphs)
            return 1;
        if (otrun_grow(&r->g, &r->props, &r->cap, r->n + 1) != 0)
            return -1;
        memset(&r->g[r->n], 0, sizeof r->g[r->n]);
        r->g[r->n].id = gid;
        r->g[r->n].cluster = (unsigned)at;
        r->props[r->n] = (unsigned char)(f->glyph_classes != 0 ?
                                         otl_gdef_props(&c->gdef, f->glyph_classes, gid)
                                         : OTL_BASE);
        if (r->props[r->n++] & OTL_MARK)
            return 1;
    }
    if (r->n == 0)
        return 1;
    if ((s = otl_plan(f, script, &plan)) != 0)
        return s;
    for (s = 0; s < 3 && ret == 0; s++) {
        size_t l;
        if (s == 2)
            for (i = 0; i < r->n; i++) {
                unsigned adv, id = r->g[i].id;
                size_t at = 4 * (size_t)(id < f->num_hmetrics ?
                                         id : f->num_hmetrics - 1);
                adv = otl_u16(&f->hmtx, at);
                if (adv > 0x7FFF)
                    c->refuse = true;
                r->g[i].x_advance = otrun_em_mult((int)adv, c->x_mult);
            }
        for (l = 0; l < plan.n[s] && ret == 0 && !c->refuse && !c->bad; l++)
            ret = apply_lookup(c, s < 2, plan.idx[s][l]);
    }
    otl_plan_fini(&plan);
    if (ret != 0)
        return ret;
    if (scale->slant != 0.f)
        for (i = 0; i < r->n; i++)
            if (r->g[i].y_offset != 0)
                c->refuse = true;
    return c->refuse || c->bad ? 1 : 0;
}

/* HarfBuzz's x_mult: the division in float (its upem is a float). */
static int64_t
mult_of(int scale, unsigned upem)
{
    return (int64_t)((float)((int64_t)scale << 16) / (float)upem);
}

int
cf__ot_shape(const cf__otface_t *f, uint32_t script,
             const cf__otscale_t *scale, const char *text, size_t off,
             size_t len, cf__otrun_t *r)
{
    ctx_t c;
    if (!f->usable || scale->x_scale <= 0 || scale->y_scale <= 0)
        return 1;
    memset(&c, 0, sizeof c);
    c.f = f;
    c.r = r;
    c.gsub = f->gsub;
    c.gpos = f->gpos;
    c.gdef = f->gdef;
    c.gsub.bad = c.gpos.bad = c.gdef.bad = &c.bad;
    c.x_mult = mult_of(scale->x_scale, f->upem);
    c.y_mult = mult_of(scale->y_scale, f->upem);
    return shape(&c, script, scale, text, off, len);
}

void
cf__otrun_fini(cf__otrun_t *r)
{
    cf_free(r->g);
    cf_free(r->props);
    cf_free(r->tg);
    cf_free(r->tprops);
    memset(r, 0, sizeof *r);
}

uint32_t
cf__ot_script_tag(uint32_t iso)
{
    switch (iso) {
    case CF__OT_TAG('L', 'a', 't', 'n'):
    case CF__OT_TAG('G', 'r', 'e', 'k'):
    case CF__OT_TAG('C', 'y', 'r', 'l'):
    case CF__OT_TAG('H', 'a', 'n', 'i'):
    case CF__OT_TAG('K', 'a', 'n', 'a'):
    case CF__OT_TAG('B', 'o', 'p', 'o'):
    case CF__OT_TAG('Z', 'y', 'y', 'y'):
        return iso | 0x20000000u;   /* HarfBuzz's old tags */
    case CF__OT_TAG('H', 'i', 'r', 'a'):
        return CF__OT_TAG('k', 'a', 'n', 'a');
    default:
        return 0;
    }
}
