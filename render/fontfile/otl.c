/*
** OpenType layout tables read for the shaper (render/fontfile/otl.h):
** coverage and class definitions (searched as HarfBuzz 6.0 searches
** them), the lookups HarfBuzz's default shaper applies for a script in
** horizontal left-to-right text with no language tag (language "c"), and
** contextual and chaining rules matched (only matched: a rule that
** matches is work for HarfBuzz).
**
** The plan (hb_ot_map_builder_t::compile for these features): the script
** is the first of the script's tag, 'DFLT', 'dflt', 'latn' the table has;
** its LangSys the one tagged 'dflt', else the default one; each feature
** the first of the LangSys's features with its tag.  GSUB has two stages
** ('rvrn', then the rest, after HarfBuzz's pause); GPOS one.  In a stage
** the lookups of all its global features are applied once each, in the
** order of their indices.  'frac', 'numr' and 'dnom' are not global (their
** masks are set only around U+2044, which the caller keeps out).
*/
#include <string.h>

#include "curvefig/core.h"
#include "otl.h"
#include "sfnt.h"

unsigned
otl_u16(const otl_tab_t *t, size_t off)
{
    if (t->p == NULL || !cf__ff_fits(off, 2, t->len)) {
        *t->bad = true;
        return 0;
    }
    return cf__ff_u16(t->p + off);
}

int
otl_s16(const otl_tab_t *t, size_t off)
{
    unsigned v = otl_u16(t, off);
    return v >= 0x8000u ? (int)v - 0x10000 : (int)v;
}

uint32_t
otl_u32(const otl_tab_t *t, size_t off)
{
    if (t->p == NULL || !cf__ff_fits(off, 4, t->len)) {
        *t->bad = true;
        return 0;
    }
    return cf__ff_u32(t->p + off);
}

unsigned
otl_coverage(const otl_tab_t *t, size_t off, unsigned gid)
{
    unsigned format = otl_u16(t, off), n = otl_u16(t, off + 2);
    int lo = 0, hi = (int)n - 1;
    while (lo <= hi && !*t->bad) {
        int mid = (int)(((unsigned)lo + (unsigned)hi) / 2);
        if (format == 1) {
            unsigned g = otl_u16(t, off + 4 + 2 * (size_t)mid);
            if (gid < g)
                hi = mid - 1;
            else if (gid > g)
                lo = mid + 1;
            else
                return (unsigned)mid;
        } else if (format == 2) {
            size_t r = off + 4 + 6 * (size_t)mid;
            unsigned first = otl_u16(t, r), last = otl_u16(t, r + 2);
            if (gid < first)
                hi = mid - 1;
            else if (gid > last)
                lo = mid + 1;
            else
                return otl_u16(t, r + 4) + (gid - first);
        } else {
            *t->bad = true;
        }
    }
    return OTL_NOT_COVERED;
}

unsigned
otl_class(const otl_tab_t *t, size_t off, unsigned gid)
{
    unsigned format, n;
    int lo, hi;
    if (off == 0)
        return 0;
    format = otl_u16(t, off);
    if (format == 1) {
        unsigned start = otl_u16(t, off + 2);
        n = otl_u16(t, off + 4);
        if (gid < start || gid - start >= n)
            return 0;
        return otl_u16(t, off + 6 + 2 * (size_t)(gid - start));
    }
    if (format != 2) {
        *t->bad = true;
        return 0;
    }
    n = otl_u16(t, off + 2);
    lo = 0;
    hi = (int)n - 1;
    while (lo <= hi && !*t->bad) {
        int mid = (int)(((unsigned)lo + (unsigned)hi) / 2);
        size_t r = off + 4 + 6 * (size_t)mid;
        if (gid < otl_u16(t, r))
            hi = mid - 1;
        else if (gid > otl_u16(t, r + 2))
            lo = mid + 1;
        else
            return otl_u16(t, r + 4);
    }
    return 0;
}

unsigned
otl_gdef_props(const otl_tab_t *gdef, size_t classes, unsigned gid)
{
    switch (otl_class(gdef, classes, gid)) {
    case 1:
        return OTL_BASE;
    case 2:
        return OTL_LIGATURE;
    case 3:
        return OTL_MARK;
    default:
        return 0;
    }
}

/* ---- the plan ----------------------------------------------------------- */

#define T CF__OT_TAG
static const uint32_t global_features[] = {
    T('l', 't', 'r', 'a'), T('l', 't', 'r', 'm'), T('r', 'a', 'n', 'd'),
    T('t', 'r', 'a', 'k'), T('H', 'a', 'r', 'f'), T('H', 'A', 'R', 'F'),
    T('B', 'u', 'z', 'z'), T('B', 'U', 'Z', 'Z'), T('a', 'b', 'v', 'm'),
    T('b', 'l', 'w', 'm'), T('c', 'c', 'm', 'p'), T('l', 'o', 'c', 'l'),
    T('m', 'a', 'r', 'k'), T('m', 'k', 'm', 'k'), T('r', 'l', 'i', 'g'),
    T('c', 'a', 'l', 't'), T('c', 'l', 'i', 'g'), T('c', 'u', 'r', 's'),
    T('d', 'i', 's', 't'), T('k', 'e', 'r', 'n'), T('l', 'i', 'g', 'a'),
    T('r', 'c', 'l', 't')
};
static const uint32_t rvrn = T('r', 'v', 'r', 'n');

/* The LangSys of script in t (0: none); 1 when damaged or when it has a
** required feature. */
static int
lang_sys(const otl_tab_t *t, uint32_t script, size_t *ls)
{
    const uint32_t tags[] = { script, T('D', 'F', 'L', 'T'),
                              T('d', 'f', 'l', 't'), T('l', 'a', 't', 'n') };
    size_t sl = otl_u16(t, 4), sc = 0, k;
    unsigned n = otl_u16(t, sl), i;
    *ls = 0;
    for (k = 0; k < 4 && sc == 0; k++)
        for (i = 0; i < n && !*t->bad; i++)
            if (otl_u32(t, sl + 2 + 6 * (size_t)i) == tags[k]) {
                sc = sl + otl_u16(t, sl + 6 + 6 * (size_t)i);
                break;
            }
    if (sc == 0)
        return *t->bad;
    n = otl_u16(t, sc + 2);
    for (i = 0; i < n && !*t->bad; i++)
        if (otl_u32(t, sc + 4 + 6 * (size_t)i) == T('d', 'f', 'l', 't')) {
            *ls = sc + otl_u16(t, sc + 8 + 6 * (size_t)i);
            break;
        }
    if (*ls == 0 && otl_u16(t, sc) != 0)
        *ls = sc + otl_u16(t, sc);
    if (*ls != 0 && otl_u16(t, *ls + 2) != 0xFFFFu)
        return 1;
    return *t->bad;
}

/* Mark in used[] the lookups of feature tag in LangSys ls. */
static void
mark_feature(const otl_tab_t *t, size_t ls, uint32_t tag,
             unsigned char *used, unsigned nlookups)
{
    size_t fl = otl_u16(t, 6);
    unsigned n = otl_u16(t, ls + 4), i, k;
    for (i = 0; i < n && !*t->bad; i++) {
        unsigned fi = otl_u16(t, ls + 6 + 2 * (size_t)i);
        size_t ft;
        unsigned nl;
        if (fi >= otl_u16(t, fl))
            continue;
        if (otl_u32(t, fl + 2 + 6 * (size_t)fi) != tag)
            continue;
        ft = fl + otl_u16(t, fl + 6 + 6 * (size_t)fi);
        nl = otl_u16(t, ft + 2);
        for (k = 0; k < nl && !*t->bad; k++) {
            unsigned li = otl_u16(t, ft + 4 + 2 * (size_t)k);
            if (li < nlookups)
                used[li] = 1;
        }
        return;
    }
}

static int
stage(const otl_tab_t *t, size_t ls, const uint32_t *tags, size_t ntags,
      uint16_t **idx, size_t *n)
{
    unsigned nlookups = otl_u16(t, otl_u16(t, 8)), i;
    unsigned char *used;
    size_t k;
    *idx = NULL;
    *n = 0;
    if (ls == 0 || nlookups == 0 || *t->bad)
        return *t->bad;
    used = cf_calloc(nlookups, 1);
    *idx = cf_alloc_array(nlookups, sizeof **idx);
    if (used == NULL || *idx == NULL) {
        cf_free(used);
        cf_free(*idx);
        *idx = NULL;
        return -1;
    }
    for (k = 0; k < ntags; k++)
        mark_feature(t, ls, tags[k], used, nlookups);
    for (i = 0; i < nlookups; i++)
        if (used[i])
            (*idx)[(*n)++] = (uint16_t)i;
    cf_free(used);
    return *t->bad;
}

int
otl_plan(const cf__otface_t *f, uint32_t script, otl_plan_t *plan)
{
    bool bad = false;
    otl_tab_t gsub = f->gsub, gpos = f->gpos;
    size_t ls_sub = 0, ls_pos = 0;
    size_t ng = sizeof global_features / sizeof global_features[0];
    int r = 0;
    memset(plan, 0, sizeof *plan);
    gsub.bad = gpos.bad = &bad;
    if ((gsub.p != NULL && lang_sys(&gsub, script, &ls_sub) != 0)
        || lang_sys(&gpos, script, &ls_pos) != 0)
        return 1;
    if (gsub.p != NULL)
        r = stage(&gsub, ls_sub, &rvrn, 1, &plan->idx[0], &plan->n[0]);
    if (gsub.p != NULL && r == 0)
        r = stage(&gsub, ls_sub, global_features, ng, &plan->idx[1],
                  &plan->n[1]);
    if (r == 0)
        r = stage(&gpos, ls_pos, global_features, ng, &plan->idx[2],
                  &plan->n[2]);
    if (r != 0)
        otl_plan_fini(plan);
    return r;
}

void
otl_plan_fini(otl_plan_t *plan)
{
    int i;
    for (i = 0; i < 3; i++) {
        cf_free(plan->idx[i]);
        plan->idx[i] = NULL;
    }
}

size_t
otl_lookup(const otl_tab_t *t, unsigned i, unsigned *type, unsigned *flag,
           unsigned *nsub)
{
    size_t ll = otl_u16(t, 8), lk;
    if (i >= otl_u16(t, ll))
        return 0;
    lk = ll + otl_u16(t, ll + 2 + 2 * (size_t)i);
    *type = otl_u16(t, lk);
    *flag = otl_u16(t, lk + 2);
    *nsub = otl_u16(t, lk + 4);
    return *t->bad ? 0 : lk;
}

size_t
otl_subtable(const otl_tab_t *t, size_t lk, unsigned j, unsigned ext_type,
             unsigned *type)
{
    size_t sub = lk + otl_u16(t, lk + 6 + 2 * (size_t)j);
    *type = otl_u16(t, lk);
    if (*type == ext_type) {
        if (otl_u16(t, sub) != 1)
            *t->bad = true;
        *type = otl_u16(t, sub + 2);
        sub += otl_u32(t, sub + 4);
        if (*type == ext_type)
            *t->bad = true;
    }
    return *t->bad ? 0 : sub;
}

/* ---- contextual rules --------------------------------------------------- */

/* How a rule names glyphs: by id (format 1), by class (2), by coverage
** (3). */
typedef struct seq {
    const otl_tab_t *t;
    size_t at;          /* first value */
    unsigned count;
    unsigned format;
    size_t base;        /* format 3: offsets from here; 2: the ClassDef */
} seq_t;

static bool
seq_item(const seq_t *s, unsigned k, unsigned gid)
{
    unsigned v = otl_u16(s->t, s->at + 2 * (size_t)k);
    if (s->format == 1)
        return v == gid;
    if (s->format == 2)
        return otl_class(s->t, s->base, gid) == v;
    return otl_coverage(s->t, s->base + v, gid) != OTL_NOT_COVERED;
}

/* backtrack (nearest first) before g[at], input from g[at] (its first
** item already matched by coverage when skip1), lookahead after */
static bool
rule_matches(const seq_t *back, const seq_t *in, const seq_t *ahead,
             const cf__otglyph_t *g, size_t n, size_t at, bool skip1)
{
    unsigned k;
    size_t ninput = skip1 ? (size_t)in->count + 1 : in->count;
    if (ninput == 0 || at + ninput > n)
        return ninput == 0;   /* damaged: "matches" (not handled) */
    for (k = 0; k < in->count; k++)
        if (!seq_item(in, k, g[at + k + (skip1 ? 1 : 0)].id))
            return false;
    if (back != NULL) {
        if (back->count > at)
            return false;
        for (k = 0; k < back->count; k++)
            if (!seq_item(back, k, g[at - 1 - k].id))
                return false;
    }
    if (ahead != NULL) {
        if (at + ninput + ahead->count > n)
            return false;
        for (k = 0; k < ahead->count; k++)
            if (!seq_item(ahead, k, g[at + ninput + k].id))
                return false;
    }
    return true;
}

bool
otl_context_matches(const otl_tab_t *t, size_t off, bool chain,
                    const cf__otglyph_t *g, size_t n, size_t at)
{
    unsigned format = otl_u16(t, off), gid = g[at].id, idx, nrules, r;
    size_t rs, classdefs[3] = { 0, 0, 0 };
    seq_t back, in, ahead;
    back.t = in.t = ahead.t = t;
    if (format == 3) {
        size_t p = off + 2;
        back.format = in.format = ahead.format = 3;
        back.base = in.base = ahead.base = off;
        if (chain) {
            back.count = otl_u16(t, p);
            back.at = p + 2;
            p = back.at + 2 * (size_t)back.count;
        }
        in.count = otl_u16(t, p);
        in.at = p + (chain ? 2 : 4);
        if (chain) {
            p = in.at + 2 * (size_t)in.count;
            ahead.count = otl_u16(t, p);
            ahead.at = p + 2;
        }
        if (in.count == 0 || *t->bad)
            return true;
        if (otl_coverage(t, off + otl_u16(t, in.at), gid) == OTL_NOT_COVERED)
            return *t->bad;
        return rule_matches(chain ? &back : NULL, &in, chain ? &ahead : NULL,
                            g, n, at, false)
               || *t->bad;
    }
    if (format != 1 && format != 2)
        return true;
    idx = otl_coverage(t, off + otl_u16(t, off + 2), gid);
    if (idx == OTL_NOT_COVERED)
        return *t->bad;
    if (format == 2) {
        int k;
        for (k = 0; k < (chain ? 3 : 1); k++) {
            size_t o = otl_u16(t, off + 4 + 2 * (size_t)k);
            classdefs[k] = o != 0 ? off + o : 0;
        }
        idx = otl_class(t, classdefs[chain ? 1 : 0], gid);
    }
    {
        size_t counts = off + (format == 2 ? (chain ? 10 : 6) : 4);
        if (idx >= otl_u16(t, counts))
            return *t->bad;
        rs = otl_u16(t, counts + 2 + 2 * (size_t)idx);
        if (rs == 0)
            return *t->bad;
        rs += off;
    }
    back.format = in.format = ahead.format = format;
    back.base = classdefs[0];
    in.base = classdefs[chain ? 1 : 0];
    ahead.base = classdefs[2];
    nrules = otl_u16(t, rs);
    for (r = 0; r < nrules && !*t->bad; r++) {
        size_t p = rs + otl_u16(t, rs + 2 + 2 * (size_t)r);
        unsigned ninput;
        if (chain) {
            back.count = otl_u16(t, p);
            back.at = p + 2;
            p = back.at + 2 * (size_t)back.count;
        }
        ninput = otl_u16(t, p);
        if (ninput == 0)
            return true;
        in.count = ninput - 1;
        in.at = p + (chain ? 2 : 4);
        if (chain) {
            p = in.at + 2 * (size_t)in.count;
            ahead.count = otl_u16(t, p);
            ahead.at = p + 2;
        }
        if (rule_matches(chain ? &back : NULL, &in, chain ? &ahead : NULL, g,
                         n, at, true))
            return true;
    }
    return *t->bad;
}
