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
** a reason to answer 1 (shape.h).
*/
#include <string.h>

#include "curvefig/core.h"
#include "otl.h"

#define IGNORE_FLAGS 0x0Eu

typedef struct ctx {
    const cf__otface_t *f;
    otl_tab_t gsub, gpos, gdef;
    bool bad;
    bool refuse;
    int64_t x_mult, y_mult;
    cf__otrun_t *r;
} ctx_t;

static int
grow(cf__otglyph_t **g, unsigned char **p, size_t *cap, size_t need)
{
    size_t c = *cap ? *cap : 16;
    cf__otglyph_t *ng;
    unsigned char *np;
    if (need <= *cap)
        return 0;
    while (c < need)
        c *= 2;
    ng = cf_realloc_array(*g, c, sizeof *ng);
    if (ng == NULL)
        return -1;
    *g = ng;
    np = cf_realloc_array(*p, c, 1);
    if (np == NULL)
        return -1;
    *p = np;
    *cap = c;
    return 0;
}

static int
emit(ctx_t *c, unsigned id, unsigned cluster, unsigned props)
{
    cf__otrun_t *r = c->r;
    if (grow(&r->tg, &r->tprops, &r->tcap, r->tn + 1) != 0)
        return -1;
    if (id >= c->f->num_glyphs || (props & OTL_MARK))
        c->refuse = true;
    memset(&r->tg[r->tn], 0, sizeof r->tg[r->tn]);
    r->tg[r->tn].id = id;
    r->tg[r->tn].cluster = cluster;
    r->tprops[r->tn++] = (unsigned char)props;
    return 0;
}

/* The class a substituted glyph takes: GDEF's when it has classes, else
** the guess (0: keep old). */
static unsigned
new_props(const ctx_t *c, unsigned id, unsigned guess, unsigned old)
{
    if (c->f->glyph_classes != 0)
        return otl_gdef_props(&c->gdef, c->f->glyph_classes, id);
    return guess != 0 ? guess : old;
}

static bool
any_skipped(const cf__otrun_t *r, unsigned flag)
{
    size_t i;
    for (i = 0; i < r->n; i++)
        if (r->props[i] & flag & IGNORE_FLAGS)
            return true;
    return false;
}

/* The first Coverage of a subtable of a type not applied here. */
static size_t
first_coverage(const otl_tab_t *t, size_t sub, unsigned type, bool gsub)
{
    bool context = gsub ? type == 5 : type == 7;
    bool chain = gsub ? type == 6 : type == 8;
    if ((context || chain) && otl_u16(t, sub) == 3) {
        size_t p = sub + 2;
        if (chain)
            p += 2 + 2 * (size_t)otl_u16(t, p);
        return sub + otl_u16(t, p + (chain ? 2 : 4));
    }
    return sub + otl_u16(t, sub + 2);
}

/* A subtable of a type not applied here at glyph i: 0 when it does not
** apply there (the run goes on), else the run is refused. */
static int
not_done(ctx_t *c, const otl_tab_t *t, size_t sub, unsigned type,
         bool gsub, unsigned flag, size_t i)
{
    const cf__otrun_t *r = c->r;
    bool context = gsub ? type == 5 : type == 7;
    bool chain = gsub ? type == 6 : type == 8;
    if (otl_coverage(t, first_coverage(t, sub, type, gsub), r->g[i].id)
        == OTL_NOT_COVERED)
        return 0;
    if ((context || chain) && !any_skipped(r, flag)
        && !otl_context_matches(t, sub, chain, r->g, r->n, i))
        return 0;
    c->refuse = true;
    return 1;
}

/* GSUB subtable at sub of type at glyph i: 0 not applied, 1 applied
** (*used input glyphs consumed, output emitted), -1 out of memory. */
static int
gsub_apply(ctx_t *c, size_t sub, unsigned type, unsigned flag, size_t i,
           size_t *used)
{
    const otl_tab_t *t = &c->gsub;
    cf__otrun_t *r = c->r;
    unsigned gid = r->g[i].id, cl = r->g[i].cluster, old = r->props[i];
    unsigned format = otl_u16(t, sub), idx, k, n;
    size_t p;
    if (type != 1 && type != 2 && type != 4)
        return not_done(c, t, sub, type, true, flag, i);
    idx = otl_coverage(t, sub + otl_u16(t, sub + 2), gid);
    if (idx == OTL_NOT_COVERED || c->bad)
        return 0;
    *used = 1;
    if (type == 1) {
        unsigned id;
        if (format == 1) {
            id = (gid + otl_u16(t, sub + 4)) & 0xFFFFu;
        } else if (format == 2) {
            if (idx >= otl_u16(t, sub + 4))
                return 0;
            id = otl_u16(t, sub + 6 + 2 * (size_t)idx);
        } else {
            c->refuse = true;
            return 1;
        }
        return emit(c, id, cl, new_props(c, id, 0, old)) < 0 ? -1 : 1;
    }
    if (format != 1) {
        c->refuse = true;
        return 1;
    }
    if (idx >= otl_u16(t, sub + 4))
        return 0;
    p = sub + otl_u16(t, sub + 6 + 2 * (size_t)idx);
    if (type == 2) {
        n = otl_u16(t, p);
        if (n == 0)
            c->refuse = true;   /* a deletion */
        for (k = 0; k < n && !c->bad; k++) {
            unsigned id = otl_u16(t, p + 2 + 2 * (size_t)k);
            unsigned guess = n == 1 ? 0 : (old & OTL_LIGATURE) ? OTL_BASE : 0;
            if (emit(c, id, cl, new_props(c, id, guess, old)) < 0)
                return -1;
        }
        return 1;
    }
    n = otl_u16(t, p);   /* ligatures of the set */
    for (k = 0; k < n && !c->bad; k++) {
        size_t lg = p + otl_u16(t, p + 2 + 2 * (size_t)k), e;
        unsigned id = otl_u16(t, lg), comp = otl_u16(t, lg + 2), m;
        bool match = comp > 0 && i + comp <= r->n;
        for (m = 1; match && m < comp; m++) {
            if (r->props[i + m] & flag & IGNORE_FLAGS) {
                c->refuse = true;   /* HarfBuzz would skip it */
                return 1;
            }
            match = r->g[i + m].id == otl_u16(t, lg + 4 + 2 * (size_t)(m - 1));
        }
        if (!match)
            continue;
        if (comp == 1)
            return emit(c, id, cl, new_props(c, id, 0, old)) < 0 ? -1 : 1;
        /* the clusters merged (all from the first's, the input monotone) */
        e = i + comp;
        if (cl != r->g[e - 1].cluster)
            while (e < r->n && r->g[e - 1].cluster == r->g[e].cluster)
                e++;
        for (m = (unsigned)(i + comp); m < e; m++)
            r->g[m].cluster = cl;
        *used = comp;
        return emit(c, id, cl, new_props(c, id, OTL_LIGATURE, old)) < 0 ? -1
                                                                        : 1;
    }
    return 0;
}

static unsigned
popcount16(unsigned v)
{
    unsigned n = 0;
    for (v &= 0xFFFFu; v; v &= v - 1)
        n++;
    return n;
}

static int
em_mult(int v, int64_t mult)
{
    return (int)((v * mult + 32768) >> 16);
}

/* A ValueRecord at p of format vf added to glyph g (devices ignored, as
** HarfBuzz does without ppem or variations). */
static void
add_value(ctx_t *c, const otl_tab_t *t, size_t p, unsigned vf,
          cf__otglyph_t *g)
{
    if (vf & 1) {
        g->x_offset += em_mult(otl_s16(t, p), c->x_mult);
        p += 2;
    }
    if (vf & 2) {
        g->y_offset += em_mult(otl_s16(t, p), c->y_mult);
        p += 2;
    }
    if (vf & 4)
        g->x_advance += em_mult(otl_s16(t, p), c->x_mult);
}

/* GPOS subtable at glyph *i: 0 not applied, 1 applied (*i moved). */
static int
gpos_apply(ctx_t *c, size_t sub, unsigned type, unsigned flag, size_t *i)
{
    const otl_tab_t *t = &c->gpos;
    cf__otrun_t *r = c->r;
    unsigned format = otl_u16(t, sub), idx, vf1, vf2, len1, len2;
    size_t next = *i + 1;
    if (type != 1 && type != 2)
        return not_done(c, t, sub, type, false, flag, *i);
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
        if (!done && emit(c, r->g[i].id, r->g[i].cluster, r->props[i]) < 0)
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
        if (grow(&r->g, &r->props, &r->cap, r->n + 1) != 0)
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
                r->g[i].x_advance = em_mult((int)adv, c->x_mult);
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
