/*
** The run being shaped (render/fontfile/shape-private.h): its arrays
** grown, a substitution's output appended, and the check that makes a
** subtable of a type the shaper does not apply harmless or the run not
** handled: the subtable's first coverage does not hold the glyph at hand,
** or (contextual and chaining rules) no rule matches there and no glyph
** of the run would be skipped by the lookup's flags.
*/
#include <string.h>

#include "curvefig/core.h"
#include "shape-private.h"

int
otrun_grow(cf__otglyph_t **g, unsigned char **p, size_t *cap, size_t need)
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

int
otrun_emit(ctx_t *c, unsigned id, unsigned cluster, unsigned props)
{
    cf__otrun_t *r = c->r;
    if (otrun_grow(&r->tg, &r->tprops, &r->tcap, r->tn + 1) != 0)
        return -1;
    if (id >= c->f->num_glyphs || (props & OTL_MARK))
        c->refuse = true;
    memset(&r->tg[r->tn], 0, sizeof r->tg[r->tn]);
    r->tg[r->tn].id = id;
    r->tg[r->tn].cluster = cluster;
    r->tprops[r->tn++] = (unsigned char)props;
    return 0;
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
int
otrun_not_done(ctx_t *c, const otl_tab_t *t, size_t sub, unsigned type,
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
