/*
** Chains of cubic segments (cf_cubics_t): their lifetime, a growing chain
** for the fitters, and the exact conversion of polynomial curves of degree
** <= 3.  The floor below the cubic fits of curves and of their offsets.
*/
#include <string.h>

#include "bezier-private.h"
#include "cubics-private.h"
#include "curvefig/offset.h"

void
cf_cubics_list_destroy(cf_cubics_list_t *list)
{
    if (list == NULL)
        return;
    for (size_t i = 0; i < list->count; i++)
        cf_cubics_destroy(list->chains[i]);
    cf__free(list->chains);
    cf__free(list);
}

void
cf_cubics_destroy(cf_cubics_t *cubics)
{
    if (cubics == NULL)
        return;
    cf__free(cubics->pts);
    cf__free(cubics->t);
    cf__free(cubics);
}

cf_status_t
cf__chain_init(cf__chain_t *ch)
{
    ch->cap = 0;
    ch->cubics = cf__calloc(1, sizeof *ch->cubics);
    if (ch->cubics == NULL)
        return CF_STATUS_NO_MEMORY;
    ch->cubics->dim = 2;
    return CF_STATUS_OK;
}

cf_status_t
cf__chain_push(cf__chain_t *ch, const double *pts, double t0, double t1)
{
    cf_cubics_t *cu = ch->cubics;
    if (cu->count + 1 > ch->cap) {
        size_t cap = ch->cap;
        double *np = cf__grow(cu->pts, &cap, cu->count + 1,
                              8 * sizeof(double), 8);
        double *nt;
        if (np == NULL)
            return CF_STATUS_NO_MEMORY;
        cu->pts = np;
        nt = cf__realloc_array(cu->t, cap + 1, sizeof(double));
        if (nt == NULL)
            return CF_STATUS_NO_MEMORY;
        cu->t = nt;
        ch->cap = cap;
    }
    memcpy(cu->pts + 8 * cu->count, pts, 8 * sizeof(double));
    if (cu->count > 0) {
        /* continuity: start where the previous piece ended */
        cu->pts[8 * cu->count] = cu->pts[8 * cu->count - 2];
        cu->pts[8 * cu->count + 1] = cu->pts[8 * cu->count - 1];
    } else {
        cu->t[0] = t0;
    }
    cu->t[cu->count + 1] = t1;
    cu->count++;
    return CF_STATUS_OK;
}

cf_cubics_t *
cf__chain_take(cf__chain_t *ch)
{
    cf_cubics_t *cu = ch->cubics;
    ch->cubics = NULL;
    return cu;
}

void
cf__chain_fini(cf__chain_t *ch)
{
    cf_cubics_destroy(ch->cubics);
    ch->cubics = NULL;
}

cf_status_t
cf__cubics_exact(const cf_bezier_t *c, cf_cubics_t **out)
{
    cf_cubics_t *r = cf__calloc(1, sizeof *r);
    int from;
    *out = NULL;
    if (r == NULL)
        return CF_STATUS_NO_MEMORY;
    r->dim = c->dim;
    r->pts = cf__alloc_array(4 * c->dim, sizeof *r->pts);
    r->t = cf__alloc_array(2, sizeof *r->t);
    if (r->pts == NULL || r->t == NULL) {
        cf_cubics_destroy(r);
        return CF_STATUS_NO_MEMORY;
    }
    memcpy(r->pts, c->pts, ((size_t)c->degree + 1) * c->dim * sizeof *r->pts);
    if (c->degree == 0)
        memcpy(r->pts + c->dim, c->pts, c->dim * sizeof *r->pts);
    /* raise to 3: degree 0 is first made a segment (degree 1) */
    from = c->degree == 0 ? 1 : c->degree;
    cf__bp_elevate(r->pts, c->dim, from, 3 - from);
    r->count = 1;
    r->t[0] = 0.0;
    r->t[1] = 1.0;
    r->max_error = 0.0;
    *out = r;
    return CF_STATUS_OK;
}
