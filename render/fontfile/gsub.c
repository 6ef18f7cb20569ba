/*
** GSUB's subtables applied at a glyph as HarfBuzz 6.0 applies them
** (render/fontfile/shape-private.h): single (both formats), multiple (one
** glyph or more; a deletion refused), ligature (the first ligature of the
** set that matches, its components adjacent: a glyph the lookup would
** skip refuses the run; clusters merged as the monotone-characters level
** merges them); every other type checked by otrun_not_done.  A glyph's
** new class is GDEF's when the face has glyph classes, else HarfBuzz's
** guess (ligature; a base for the parts of a ligature multiplied; the old
** one).
*/
#include "shape-private.h"


/* The class a substituted glyph takes: GDEF's when it has classes, else
** the guess (0: keep old). */
static unsigned
new_props(const ctx_t *c, unsigned id, unsigned guess, unsigned old)
{
    if (c->f->glyph_classes != 0)
        return otl_gdef_props(&c->gdef, c->f->glyph_classes, id);
    return guess != 0 ? guess : old;
}


/* GSUB subtable at sub of type at glyph i: 0 not applied, 1 applied
** (*used input glyphs consumed, output emitted), -1 out of memory. */
int
gsub_apply(ctx_t *c, size_t sub, unsigned type, unsigned flag, size_t i,
           size_t *used)
{
    const otl_tab_t *t = &c->gsub;
    cf__otrun_t *r = c->r;
    unsigned gid = r->g[i].id, cl = r->g[i].cluster, old = r->props[i];
    unsigned format = otl_u16(t, sub), idx, k, n;
    size_t p;
    if (type != 1 && type != 2 && type != 4)
        return otrun_not_done(c, t, sub, type, true, flag, i);
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
        return otrun_emit(c, id, cl, new_props(c, id, 0, old)) < 0 ? -1 : 1;
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
            if (otrun_emit(c, id, cl, new_props(c, id, guess, old)) < 0)
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
            return otrun_emit(c, id, cl, new_props(c, id, 0, old)) < 0 ? -1 : 1;
        /* the clusters merged (all from the first's, the input monotone) */
        e = i + comp;
        if (cl != r->g[e - 1].cluster)
            while (e < r->n && r->g[e - 1].cluster == r->g[e].cluster)
                e++;
        for (m = (unsigned)(i + comp); m < e; m++)
            r->g[m].cluster = cl;
        *used = comp;
        return otrun_emit(c, id, cl, new_props(c, id, OTL_LIGATURE, old)) < 0 ? -1
                                                                        : 1;
    }
    return 0;
}
