/*
** A figure's description in words, written from its facts (facts.h): a
** summary sentence (the alt text of a figure that has no other), then
** its curves with their control points (named as labelled), weights and
** knots, the constructions drawn on them and their parameters, how one
** curve was made from another, its surfaces and view, and the labels left
** over.  The phrases are in describe-lang.c; numbers are written short
** (1/2, 3/4 for parameters; 0.4, 2.5 for coordinates).
*/
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "buffer.h"
#include "describe-lang.h"
#include "describe.h"
#include "describe-private.h"

#define MAX_LISTED_POINTS 16
#define MAX_LISTED_KNOTS 20
#define MAX_ITEMS 32
#define MAX_OTHER_LABELS 16


/* ---- phrases ----------------------------------------------------------- */

static void
curve_phrase(cf__dwriter_t *w, const cf__curve_info_t *c, bool article)
{
    const cf__desc_lang_t *L = w->L;
    bool nurbs = c->bs != NULL && c->rational;
    bool adj = c->degree >= 0 && c->degree <= 5;
    if (article)
        cf__dw_put(w->out, L->article);
    if (c->rational && !nurbs)
        cf__dw_put(w->out, L->rational);
    if (adj)
        cf__dw_putf(w->out, "%s ", L->degree[c->degree]);
    cf__dw_put(w->out, c->bez != NULL ? L->bezier_curve
                               : nurbs ? L->nurbs_curve : L->bspline_curve);
    if (!adj)
        cf__dw_putf(w->out, L->of_degree, c->degree);
}

static void
surface_phrase(cf__dwriter_t *w, const cf__fact_t *x, bool article)
{
    const cf__desc_lang_t *L = w->L;
    bool bi = x->kind == CF__FACT_SURFACE && x->deg_u == x->deg_v
        && x->deg_u >= 1 && x->deg_u <= 3;
    if (article)
        cf__dw_put(w->out, L->article);
    if (x->kind == CF__FACT_TRIANGLE) {
        if (x->rational)
            cf__dw_put(w->out, L->rational);
        cf__dw_put(w->out, L->triangle_patch);
        cf__dw_putf(w->out, L->of_degree, x->deg_u);
        return;
    }
    if (x->rational && x->bezier)
        cf__dw_put(w->out, L->rational);
    if (bi)
        cf__dw_putf(w->out, "%s ", L->bi[x->deg_u]);
    cf__dw_put(w->out, x->bezier ? L->bezier_patch
                          : x->rational ? L->nurbs_surface
                                        : L->bspline_surface);
    if (!bi)
        cf__dw_putf(w->out, L->of_degrees, x->deg_u, x->deg_v);
}

/* Whether a construction at v on curve i is only the subdivision that
** made a later curve. */
static bool
is_split_param(const cf__dwriter_t *w, size_t i, double v)
{
    for (size_t j = 0; j < w->d.ncurves; j++) {
        const cf__curve_info_t *y = &w->d.curves[j];
        if (y->rel_of == i
            && (y->rel == CF__REL_LEFT || y->rel == CF__REL_RIGHT)
            && fabs(y->rel_param - v) <= 1e-9)
            return true;
    }
    return false;
}

static void
construction_phrase(cf__dwriter_t *w, const cf__curve_info_t *c, size_t k)
{
    char tmp[64];
    cf__dw_fmt_num(w->L, c->params[k], true, tmp, sizeof tmp);
    cf__dw_putf(w->out, c->deboor ? w->L->deboor : w->L->decasteljau, tmp);
}

/* Whether fact i is the first basis function of its degree. */
static bool
first_basis(const cf__facts_t *f, size_t i)
{
    for (size_t j = 0; j < i; j++)
        if (f->items[j].kind == CF__FACT_BASIS
            && f->items[j].deg_u == f->items[i].deg_u)
            return false;
    return true;
}

/* The knot vector of the basis functions of fact i's degree: every value
** of their knots, each as often as in the function that has it most
** often (the functions N_i .. N_j of one vector give that vector). */
static bool
merged_knots(const cf__facts_t *f, size_t i, double **out, size_t *n)
{
    size_t cap = 0, k = 0;
    double *u;
    for (size_t j = i; j < f->count; j++)
        if (f->items[j].kind == CF__FACT_BASIS
            && f->items[j].deg_u == f->items[i].deg_u)
            cap += f->items[j].n;
    u = cf_alloc_array(cap ? cap : 1, sizeof *u);
    if (u == NULL)
        return false;
    for (size_t j = i; j < f->count; j++) {
        const cf__fact_t *x = &f->items[j];
        if (x->kind != CF__FACT_BASIS || x->deg_u != f->items[i].deg_u)
            continue;
        for (size_t a = 0; a < x->n;) {
            size_t m = 1, have = 0, at;
            while (a + m < x->n && x->xy[a + m] == x->xy[a])
                m++;
            for (at = 0; at < k && u[at] < x->xy[a]; at++)
                ;
            while (at + have < k && u[at + have] == x->xy[a])
                have++;
            for (; have < m; have++) {
                memmove(u + at + 1, u + at, (k - at) * sizeof *u);
                u[at] = x->xy[a];
                k++;
            }
            a += m;
        }
    }
    *out = u;
    *n = k;
    return true;
}

/* The last of the curves from j on that are offsets of one curve at one
** distance (j itself when it is no offset or stands alone). */
static size_t
offset_run(const cf__dwriter_t *w, size_t j)
{
    const cf__curve_info_t *y = &w->d.curves[j];
    size_t k = j;
    if (y->rel != CF__REL_OFFSET)
        return j;
    while (k + 1 < w->d.ncurves && w->d.curves[k + 1].rel == CF__REL_OFFSET
           && w->d.curves[k + 1].rel_of == y->rel_of
           && fabs(w->d.curves[k + 1].rel_param - y->rel_param)
                  <= 1e-2 * y->rel_param)
        k++;
    return k;
}

/* " and its offset at distance d" for each distance of the offsets of
** curve i. */
static void
put_offsets(cf__dwriter_t *w, size_t i)
{
    for (size_t j = i + 1; j < w->d.ncurves; j++) {
        const cf__curve_info_t *y = &w->d.curves[j];
        char v[64];
        if (y->rel != CF__REL_OFFSET || y->rel_of != i
            || (j > 0 && w->d.curves[j - 1].rel == CF__REL_OFFSET
                && w->d.curves[j - 1].rel_of == i
                && fabs(w->d.curves[j - 1].rel_param - y->rel_param)
                       <= 1e-2 * y->rel_param))
            continue;
        cf__dw_fmt_num(w->L, y->rel_param, false, v, sizeof v);
        cf__dw_putf(w->out, w->L->with_offset, v);
    }
}

/* ---- the summary ------------------------------------------------------- */

typedef struct items {
    cf__buf_t text[MAX_ITEMS];
    size_t times[MAX_ITEMS];
    size_t n;
} items_t;

/* Begin an item in w->out (restored by end_item). */
static cf__buf_t *
begin_item(cf__dwriter_t *w, cf__buf_t *item)
{
    cf__buf_t *saved = w->out;
    memset(item, 0, sizeof *item);
    w->out = item;
    return saved;
}

static void
end_item(cf__dwriter_t *w, items_t *it, cf__buf_t *saved)
{
    cf__buf_t *b = w->out;
    w->out = saved;
    cf__buf_append(b, "", 1);
    if (b->failed || b->data == NULL) {
        saved->failed = 1;     /* out of memory: the whole text fails */
        cf__buf_free(b);
        return;
    }
    for (size_t i = 0; i < it->n; i++)
        if (it->text[i].size == b->size
            && memcmp(it->text[i].data, b->data, b->size) == 0) {
            it->times[i]++;
            cf__buf_free(b);
            return;
        }
    if (it->n == MAX_ITEMS) {
        cf__buf_free(b);
        return;
    }
    it->text[it->n] = *b;
    it->times[it->n++] = 1;
}

static void
collect(cf__dwriter_t *w, items_t *it)
{
    cf__buf_t item, *saved;
    const cf__facts_t *f = &w->d.fig->facts;
    size_t graphs = 0;
    for (size_t i = 0; i < w->d.ncurves; i++) {
        const cf__curve_info_t *c = &w->d.curves[i];
        double v[CF__DESCRIBE_MAX_PARAMS];
        size_t nv = 0;
        if (c->rel == CF__REL_OFFSET)
            continue;     /* said with its curve */
        saved = begin_item(w, &item);
        curve_phrase(w, c, true);
        /* its constructions, the parameters in one list */
        for (size_t k = 0; k < c->nparams; k++)
            if (!is_split_param(w, i, c->params[k]))
                v[nv++] = c->params[k];
        if (nv > 0) {
            cf__buf_t list, *outer = w->out;
            cf__dw_begin(w, &list);
            cf__dw_put_params(w, v, nv);
            cf__dw_end(w, &list, outer);
            cf__dw_put(w->out, w->L->with_construction);
            if (list.data != NULL)
                cf__dw_putf(w->out,
                            c->deboor ? w->L->deboor : w->L->decasteljau,
                            (char *)list.data);
            cf__buf_free(&list);
        }
        put_offsets(w, i);
        end_item(w, it, saved);
    }
    for (size_t i = 0; i < f->count; i++) {
        const cf__fact_t *x = &f->items[i];
        if (x->kind == CF__FACT_SURFACE || x->kind == CF__FACT_TRIANGLE) {
            saved = begin_item(w, &item);
            surface_phrase(w, x, true);
            end_item(w, it, saved);
        } else if (x->kind == CF__FACT_BASIS && first_basis(f, i)) {
            saved = begin_item(w, &item);
            cf__dw_putf(w->out, w->L->basis_short, x->deg_u);
            end_item(w, it, saved);
        } else if (x->kind == CF__FACT_GRAPH) {
            graphs++;
        }
    }
    if (graphs > 0) {
        char n[32];
        saved = begin_item(w, &item);
        snprintf(n, sizeof n, "%zu", graphs);
        if (graphs == 1)
            cf__dw_put(w->out, w->L->graph);
        else
            cf__dw_putf(w->out, w->L->graphs, n);
        end_item(w, it, saved);
    }
}

static void
put_summary(cf__dwriter_t *w)
{
    items_t it;
    size_t start = w->out->size;
    memset(&it, 0, sizeof it);
    collect(w, &it);
    if (it.n == 0)
        cf__dw_put(w->out, w->d.fig->facts.count == 0 ? w->L->empty
                                                      : w->L->drawing);
    for (size_t i = 0; i < it.n; i++) {
        cf__dw_put_sep(w, i, it.n);
        cf__dw_put(w->out, (const char *)it.text[i].data);
        if (it.times[i] > 1) {
            char n[32];
            snprintf(n, sizeof n, "%zu", it.times[i]);
            cf__dw_putf(w->out, w->L->times, n);
        }
        cf__buf_free(&it.text[i]);
    }
    if (it.n > 0)
        cf__dw_put(w->out, ".");
    cf__dw_capitalise(w->out, start);
}

/* ---- the details ------------------------------------------------------- */

static void
put_curve_name(cf__dwriter_t *w, size_t i, bool capital)
{
    char n[32];
    size_t start = w->out->size;
    snprintf(n, sizeof n, "%zu", i + 1);
    cf__dw_putf(w->out, w->L->curve_n, n);
    if (capital)
        cf__dw_capitalise(w->out, start);
}

static void
put_curve(cf__dwriter_t *w, size_t i)
{
    const cf__curve_info_t *c = &w->d.curves[i];
    size_t start, dim = c->dim;
    if (c->rel == CF__REL_OFFSET)
        return;   /* pieces approximating an offset: their relation says it */
    cf__dw_put(w->out, " ");
    start = w->out->size;
    if (w->d.ncurves > 1) {
        put_curve_name(w, i, true);
        cf__dw_put(w->out, " (");
        curve_phrase(w, c, true);
        cf__dw_put(w->out, "): ");
    }
    if (c->npts <= MAX_LISTED_POINTS) {
        cf__dw_put(w->out, w->L->control_points);
        cf__dw_capitalise(w->out, start);
        for (size_t k = 0; k < c->npts; k++) {
            cf__dw_put_sep(w, k, c->npts);
            cf__dw_put_named(w, c->plane + 2 * k, c->pts + k * dim, dim);
        }
    } else {
        cf__buf_t a, b, *saved = w->out;
        char n[32];
        cf__dw_begin(w, &a);
        cf__dw_put_named(w, c->plane, c->pts, dim);
        cf__dw_end(w, &a, saved);
        cf__dw_begin(w, &b);
        cf__dw_put_named(w, c->plane + 2 * (c->npts - 1),
                         c->pts + (c->npts - 1) * dim, dim);
        cf__dw_end(w, &b, saved);
        snprintf(n, sizeof n, "%zu", c->npts);
        if (a.data != NULL && b.data != NULL)
            cf__dw_putf(w->out, w->L->many_points, n, (char *)a.data,
                        (char *)b.data);
        cf__dw_capitalise(w->out, start);
        cf__buf_free(&a);
        cf__buf_free(&b);
    }
    if (c->rational) {
        cf__dw_put(w->out, w->L->weights);
        cf__dw_put_params(w, c->w, c->npts);
    }
    if (c->bs != NULL) {
        const double *k = cf_bspline_knots(c->bs);
        size_t nk = cf_bspline_nknots(c->bs);
        if (nk <= MAX_LISTED_KNOTS) {
            cf__dw_put(w->out, w->L->knots);
            cf__dw_put_params(w, k, nk);
        } else {
            char n[32], a[64], b[64];
            snprintf(n, sizeof n, "%zu", nk);
            cf__dw_fmt_num(w->L, k[0], true, a, sizeof a);
            cf__dw_fmt_num(w->L, k[nk - 1], true, b, sizeof b);
            cf__dw_putf(w->out, w->L->many_knots, n, a, b);
        }
    }
    cf__dw_put(w->out, ".");
}

/* The constructions on curve i, a sentence each. */
static void
put_constructions(cf__dwriter_t *w, size_t i)
{
    const cf__curve_info_t *c = &w->d.curves[i];
    for (size_t k = 0; k < c->nparams; k++) {
        double p[CF__DESCRIBE_MAX_DIM], pp[2];
        size_t start;
        cf_status_t st;
        if (is_split_param(w, i, c->params[k]))
            continue;
        cf__dw_put(w->out, " ");
        start = w->out->size;
        construction_phrase(w, c, k);
        if (w->d.ncurves > 1) {
            char n[32];
            snprintf(n, sizeof n, "%zu", i + 1);
            cf__dw_putf(w->out, w->L->on_curve, n);
        }
        st = c->bez != NULL ? cf_bezier_eval(c->bez, c->params[k], p)
                            : cf_bspline_eval(c->bs, c->params[k], p);
        if (st == CF_STATUS_OK) {
            cf__buf_t pt, *saved = w->out;
            cf__fig_project1(w->d.fig, p, c->dim, pp);
            cf__dw_begin(w, &pt);
            cf__dw_put_named(w, pp, p, c->dim);
            cf__dw_end(w, &pt, saved);
            if (pt.data != NULL)
                cf__dw_putf(w->out, w->L->ends_at, (char *)pt.data);
            cf__buf_free(&pt);
        }
        cf__dw_put(w->out, ".");
        cf__dw_capitalise(w->out, start);
    }
}

/* The relation of curve j to an earlier one, and of the curves after it
** that are pieces of one offset with it; the last curve said. */
static size_t
put_relation(cf__dwriter_t *w, size_t j)
{
    const cf__curve_info_t *y = &w->d.curves[j], *x;
    cf__buf_t name, *saved = w->out;
    char of[32], v[256];
    size_t last = offset_run(w, j);
    if (y->rel == CF__REL_NONE)
        return j;
    if (last > j) {
        char a[32], b[32];
        snprintf(a, sizeof a, "%zu", j + 1);
        snprintf(b, sizeof b, "%zu", last + 1);
        snprintf(of, sizeof of, "%zu", y->rel_of + 1);
        cf__dw_fmt_num(w->L, y->rel_param, false, v, sizeof v);
        cf__dw_put(w->out, " ");
        cf__dw_putf(w->out, w->L->offsets, a, b, of, v);
        cf__dw_put(w->out, ".");
        return last;
    }
    x = &w->d.curves[y->rel_of];
    cf__dw_begin(w, &name);
    put_curve_name(w, j, true);
    cf__dw_end(w, &name, saved);
    if (name.data == NULL)
        return j;
    snprintf(of, sizeof of, "%zu", y->rel_of + 1);
    cf__dw_put(w->out, " ");
    switch (y->rel) {
    case CF__REL_LEFT:
    case CF__REL_RIGHT:
        cf__dw_fmt_num(w->L, y->rel_param, true, v, sizeof v);
        cf__dw_putf(w->out, y->rel == CF__REL_LEFT ? w->L->split_left
                                            : w->L->split_right,
             (char *)name.data, of, v);
        break;
    case CF__REL_OFFSET:
        cf__dw_fmt_num(w->L, y->rel_param, false, v, sizeof v);
        cf__dw_putf(w->out, w->L->offset, (char *)name.data, of, v);
        break;
    case CF__REL_ELEVATED:
        cf__dw_putf(w->out, w->L->elevated, (char *)name.data, of, x->degree,
             y->degree);
        break;
    default: {
        cf__buf_t knots;
        cf__dw_begin(w, &knots);
        cf__dw_put_params(w, y->inserted, y->ninserted);
        cf__dw_end(w, &knots, saved);
        if (knots.data != NULL)
            cf__dw_putf(w->out, w->L->inserted, (char *)name.data, of,
                 (char *)knots.data);
        cf__buf_free(&knots);
    }
    }
    cf__dw_put(w->out, ".");
    cf__buf_free(&name);
    return j;
}

static void
put_surfaces(cf__dwriter_t *w)
{
    const cf__facts_t *f = &w->d.fig->facts;
    bool any = false;
    for (size_t i = 0; i < f->count; i++) {
        const cf__fact_t *x = &f->items[i];
        size_t start;
        if (x->kind == CF__FACT_BASIS) {
            cf__buf_t knots, *saved = w->out;
            double *u;
            size_t nu;
            if (!first_basis(f, i))
                continue;
            if (!merged_knots(f, i, &u, &nu)) {
                w->out->failed = 1;
                return;
            }
            cf__dw_begin(w, &knots);
            cf__dw_put_params(w, u, nu);
            cf__dw_end(w, &knots, saved);
            cf_free(u);
            cf__dw_put(w->out, " ");
            start = w->out->size;
            if (knots.data != NULL)
                cf__dw_putf(w->out, w->L->basis, x->deg_u, (char *)knots.data);
            cf__dw_put(w->out, ".");
            cf__dw_capitalise(w->out, start);
            cf__buf_free(&knots);
            continue;
        }
        if (x->kind != CF__FACT_SURFACE && x->kind != CF__FACT_TRIANGLE)
            continue;
        any = true;
        cf__dw_put(w->out, " ");
        start = w->out->size;
        surface_phrase(w, x, false);
        cf__dw_capitalise(w->out, start);
        if (x->kind == CF__FACT_SURFACE) {
            char a[32], b[32];
            snprintf(a, sizeof a, "%zu", x->count_u);
            snprintf(b, sizeof b, "%zu", x->count_v);
            cf__dw_putf(w->out, w->L->surface_points, a, b);
        }
        cf__dw_put(w->out, ".");
    }
    if (any && w->d.fig->has_view) {
        const cf_view_t *v = &w->d.fig->view;
        char az[64], el[64], dist[64];
        cf__dw_fmt_num(w->L, v->azimuth, false, az, sizeof az);
        cf__dw_fmt_num(w->L, v->elevation, false, el, sizeof el);
        cf__dw_fmt_num(w->L, v->distance, false, dist, sizeof dist);
        cf__dw_put(w->out, " ");
        if (v->projection == CF_PROJECTION_PERSPECTIVE)
            cf__dw_putf(w->out, w->L->view_persp, az, el, dist);
        else
            cf__dw_putf(w->out, w->L->view_ortho, az, el);
    }
}

/* Whether the label fact x names a control point or a construction's
** curve point already said. */
static bool
label_used(const cf__dwriter_t *w, const cf__fact_t *x)
{
    for (size_t i = 0; i < w->d.ncurves; i++) {
        const cf__curve_info_t *c = &w->d.curves[i];
        for (size_t k = 0; k < c->npts; k++)
            if (fabs(c->plane[2 * k] - x->xy[0]) <= w->d.eps
                && fabs(c->plane[2 * k + 1] - x->xy[1]) <= w->d.eps)
                return true;
        for (size_t k = 0; k < c->nparams; k++) {
            double p[CF__DESCRIBE_MAX_DIM], pp[2];
            if ((c->bez != NULL ? cf_bezier_eval(c->bez, c->params[k], p)
                                : cf_bspline_eval(c->bs, c->params[k], p))
                != CF_STATUS_OK)
                continue;
            cf__fig_project1(w->d.fig, p, c->dim, pp);
            if (fabs(pp[0] - x->xy[0]) <= w->d.eps
                && fabs(pp[1] - x->xy[1]) <= w->d.eps)
                return true;
        }
    }
    return false;
}

static void
put_other_labels(cf__dwriter_t *w)
{
    const cf__facts_t *f = &w->d.fig->facts;
    size_t n = 0;
    for (size_t i = 0; i < f->count && n < MAX_OTHER_LABELS; i++) {
        const cf__fact_t *x = &f->items[i];
        bool seen = false;
        if (x->kind != CF__FACT_LABEL || label_used(w, x))
            continue;
        for (size_t j = 0; j < i && !seen; j++)
            seen = f->items[j].kind == CF__FACT_LABEL
                && strcmp(f->items[j].text, x->text) == 0;
        if (seen || x->text[0] == '\0')
            continue;
        cf__dw_put(w->out, n == 0 ? " " : ", ");
        if (n == 0)
            cf__dw_put(w->out, w->L->labels);
        cf__dw_put_plain(w->out, x->text);
        n++;
    }
    if (n > 0)
        cf__dw_put(w->out, ".");
}

/* ---- the curves of the facts ------------------------------------------- */

static void
infos_fini(cf__describe_t *d)
{
    for (size_t i = 0; i < d->ncurves; i++) {
        cf_free(d->curves[i].pts);
        cf_free(d->curves[i].w);
        cf_free(d->curves[i].plane);
    }
    cf_free(d->curves);
    d->curves = NULL;
    d->ncurves = 0;
}

/* The curves of fig's facts with their points; the tolerances from the
** extent of everything drawn.  False when out of memory. */
static bool
infos_init(cf__describe_t *d, cf_figure_t *fig)
{
    const cf__facts_t *f = &fig->facts;
    cf__bounds_t bb;
    double big = 0;
    memset(d, 0, sizeof *d);
    memset(&bb, 0, sizeof bb);
    d->fig = fig;
    d->curves = cf_calloc(f->count ? f->count : 1, sizeof *d->curves);
    if (d->curves == NULL)
        return false;
    for (size_t i = 0; i < f->count; i++) {
        const cf__fact_t *x = &f->items[i];
        cf__curve_info_t *c = &d->curves[d->ncurves];
        if (x->kind == CF__FACT_MARKS || x->kind == CF__FACT_LABEL) {
            d->nmarks += x->n;
            for (size_t k = 0; k < x->n; k++)
                cf__bounds_add(&bb, x->xy[2 * k], x->xy[2 * k + 1]);
        }
        if (x->kind != CF__FACT_BEZIER && x->kind != CF__FACT_BSPLINE)
            continue;
        c->bez = x->bez;
        c->bs = x->bs;
        c->degree = x->bez ? cf_bezier_degree(x->bez)
                           : cf_bspline_degree(x->bs);
        c->rational = x->bez ? cf_bezier_is_rational(x->bez)
                             : cf_bspline_is_rational(x->bs);
        c->dim = x->bez ? cf_bezier_dim(x->bez) : cf_bspline_dim(x->bs);
        c->npts = x->bez ? (size_t)c->degree + 1 : cf_bspline_count(x->bs);
        c->pts = cf_alloc_array(c->npts * c->dim, sizeof *c->pts);
        c->w = cf_alloc_array(c->npts, sizeof *c->w);
        c->plane = cf_alloc_array(2 * c->npts, sizeof *c->plane);
        d->ncurves++;
        if (c->pts == NULL || c->w == NULL || c->plane == NULL)
            return false;
        if (x->bez != NULL) {
            cf_bezier_get_points(x->bez, c->pts);
            cf_bezier_get_weights(x->bez, c->w);
        } else {
            cf_bspline_get_points(x->bs, c->pts);
            cf_bspline_get_weights(x->bs, c->w);
        }
        for (size_t k = 0; k < c->npts; k++) {
            cf__fig_project1(fig, c->pts + k * c->dim, c->dim,
                             c->plane + 2 * k);
            cf__bounds_add(&bb, c->plane[2 * k], c->plane[2 * k + 1]);
            for (size_t j = 0; j < c->dim; j++)
                big = fmax(big, fabs(c->pts[k * c->dim + j]));
        }
    }
    /* points computed by a script agree with the core's to rounding:
    ** 1e-7 of the drawing's size is far above that and far below what a
    ** figure could show apart */
    d->eps = 1e-7 * (bb.any ? fmax(fmax(bb.x1 - bb.x0, bb.y1 - bb.y0), 1e-300)
                            : 1.0);
    d->tol = 1e-9 * fmax(big, 1e-300);
    return true;
}

/* ---- entry points ------------------------------------------------------ */

static cf_status_t
describe_one(cf_figure_t *fig, const cf__desc_lang_t *L, bool summary,
             cf__buf_t *out)
{
    cf__dwriter_t w;
    if (!infos_init(&w.d, fig)) {
        infos_fini(&w.d);
        return CF_STATUS_NO_MEMORY;
    }
    w.L = L;
    w.out = out;
    cf__describe_find(&w.d);
    put_summary(&w);
    if (!summary) {
        for (size_t i = 0; i < w.d.ncurves; i++)
            put_curve(&w, i);
        for (size_t i = 0; i < w.d.ncurves; i++)
            put_constructions(&w, i);
        for (size_t i = 0; i < w.d.ncurves; i++)
            i = put_relation(&w, i);
        put_surfaces(&w);
        put_other_labels(&w);
    }
    infos_fini(&w.d);
    return out->failed || w.d.nomem ? CF_STATUS_NO_MEMORY : CF_STATUS_OK;
}

cf_status_t
cf__figure_describe(cf_figure_t *fig, bool summary, char **out)
{
    const cf__desc_lang_t *L = cf__desc_lang(fig->lang);
    cf__buf_t b;
    cf_status_t st = CF_STATUS_OK;
    memset(&b, 0, sizeof b);
    *out = NULL;
    if (fig->panels != NULL) {
        size_t n = (size_t)(fig->rows * fig->cols);
        for (size_t i = 0; i < n && st == CF_STATUS_OK; i++) {
            if (fig->panels[i] == NULL)
                continue;
            if (b.size > 0)
                cf__dw_put(&b, " ");
            cf__dw_putf(&b, L->panel, i + 1);
            st = describe_one(fig->panels[i], L, summary, &b);
        }
        if (fig->facts.count > 0 && st == CF_STATUS_OK) {
            cf__dw_put(&b, " ");
            st = describe_one(fig, L, summary, &b);
        }
    } else {
        st = describe_one(fig, L, summary, &b);
    }
    cf__buf_append(&b, "", 1);
    if (st == CF_STATUS_OK && b.failed)
        st = CF_STATUS_NO_MEMORY;
    if (st != CF_STATUS_OK) {
        cf__buf_free(&b);
        return cf__fig_nomem(fig, "the figure's description");
    }
    *out = (char *)b.data;
    return CF_STATUS_OK;
}
