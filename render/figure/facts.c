/*
** The facts of a figure (facts.h): copies of what the element kinds were
** given, kept for the figure's description.
*/
#include <string.h>

#include "model.h"

/* "out of memory" in the figure (not figure.c's helper: figure.c calls
** this file, which calls no function of it). */
static cf_status_t
nomem(cf_figure_t *fig)
{
    return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                       "out of memory for the figure's description");
}

/* A new zeroed fact of kind k at the end of the figure's list, or NULL
** (the figure failed). */
static cf__fact_t *
push(cf_figure_t *fig, cf__fact_kind_t k)
{
    cf__facts_t *f = &fig->facts;
    if (f->count == f->cap) {
        size_t cap = f->cap ? 2 * f->cap : 8;
        cf__fact_t *p = cf_realloc_array(f->items, cap, sizeof *p);
        if (p == NULL) {
            nomem(fig);
            return NULL;
        }
        f->items = p;
        f->cap = cap;
    }
    memset(&f->items[f->count], 0, sizeof f->items[0]);
    f->items[f->count].kind = k;
    return &f->items[f->count++];
}

static void
fact_fini(cf__fact_t *x)
{
    cf_bezier_destroy(x->bez);
    cf_bspline_destroy(x->bs);
    cf_free(x->xy);
    cf_free(x->text);
}

/* Drop the last fact (its copy failed) and fail the figure. */
static cf_status_t
drop(cf_figure_t *fig)
{
    fact_fini(&fig->facts.items[--fig->facts.count]);
    return nomem(fig);
}

cf_status_t
cf__fact_bezier(cf_figure_t *fig, const cf_bezier_t *c)
{
    cf__fact_t *x = push(fig, CF__FACT_BEZIER);
    if (x == NULL)
        return fig->err.status;
    if (cf_bezier_copy(c, &x->bez, NULL) != CF_STATUS_OK)
        return drop(fig);
    return CF_STATUS_OK;
}

cf_status_t
cf__fact_bspline(cf_figure_t *fig, const cf_bspline_t *s)
{
    cf__fact_t *x = push(fig, CF__FACT_BSPLINE);
    if (x == NULL)
        return fig->err.status;
    if (cf_bspline_copy(s, &x->bs, NULL) != CF_STATUS_OK)
        return drop(fig);
    return CF_STATUS_OK;
}

static cf_status_t
with_points(cf_figure_t *fig, cf__fact_kind_t k, const double *v, size_t n,
            size_t stride)
{
    cf__fact_t *x = push(fig, k);
    if (x == NULL)
        return fig->err.status;
    x->n = n;
    if (n > 0) {
        x->xy = cf_alloc_array(n * stride, sizeof *x->xy);
        if (x->xy == NULL)
            return drop(fig);
        memcpy(x->xy, v, n * stride * sizeof *x->xy);
    }
    return CF_STATUS_OK;
}

cf_status_t
cf__fact_marks(cf_figure_t *fig, const double *xy, size_t n)
{
    return with_points(fig, CF__FACT_MARKS, xy, n, 2);
}

cf_status_t
cf__fact_label(cf_figure_t *fig, double x, double y, const char *text)
{
    double xy[2] = { x, y };
    size_t len = strlen(text);
    cf__fact_t *f;
    if (with_points(fig, CF__FACT_LABEL, xy, 1, 2) != CF_STATUS_OK)
        return fig->err.status;
    f = &fig->facts.items[fig->facts.count - 1];
    f->text = cf_malloc(len + 1);
    if (f->text == NULL)
        return drop(fig);
    memcpy(f->text, text, len + 1);
    return CF_STATUS_OK;
}

cf_status_t
cf__fact_surface(cf_figure_t *fig, cf__fact_kind_t kind, int deg_u,
                 int deg_v, size_t count_u, size_t count_v, bool rational,
                 bool bezier)
{
    cf__fact_t *x = push(fig, kind);
    if (x == NULL)
        return fig->err.status;
    x->deg_u = deg_u;
    x->deg_v = deg_v;
    x->count_u = count_u;
    x->count_v = count_v;
    x->rational = rational;
    x->bezier = bezier;
    return CF_STATUS_OK;
}

/* A basis function is drawn as a graph: its fact replaces the graph's. */
cf_status_t
cf__fact_basis(cf_figure_t *fig, const double *knots, size_t nknots, int p)
{
    cf__facts_t *f = &fig->facts;
    if (f->count > 0 && f->items[f->count - 1].kind == CF__FACT_GRAPH)
        f->count--;
    if (with_points(fig, CF__FACT_BASIS, knots, nknots, 1) != CF_STATUS_OK)
        return fig->err.status;
    f->items[f->count - 1].deg_u = p;
    return CF_STATUS_OK;
}

cf_status_t
cf__fact_graph(cf_figure_t *fig)
{
    return push(fig, CF__FACT_GRAPH) != NULL ? CF_STATUS_OK
                                             : fig->err.status;
}

void
cf__facts_fini(cf__facts_t *f)
{
    for (size_t i = 0; i < f->count; i++)
        fact_fini(&f->items[i]);
    cf_free(f->items);
    memset(f, 0, sizeof *f);
}
