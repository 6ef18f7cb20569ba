/*
** Axes: axis lines (or a frame) with arrows, ticks and their labels, a
** grid, knot marks along the x axis with their labels stacked below, and
** the axis labels.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "label-private.h"
#include "model.h"

typedef struct tick {
    double v;
    cf__text_t t;
} tick_t;

typedef struct axes_el {
    cf__element_t base;
    cf_axes_t a;             /* pointers cleared */
    tick_t *xt, *yt, *kn;
    size_t nxt, nyt, nkn;
    cf__text_t xlabel, ylabel;
} axes_el_t;

static void
ticks_free(tick_t *t, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        cf__text_fini(&t[i].t);
    cf_free(t);
}

static void
axes_fini(cf__element_t *el)
{
    axes_el_t *ax = (axes_el_t *)el;
    ticks_free(ax->xt, ax->nxt);
    ticks_free(ax->yt, ax->nyt);
    ticks_free(ax->kn, ax->nkn);
    cf__text_fini(&ax->xlabel);
    cf__text_fini(&ax->ylabel);
}

static void
axes_bounds(const cf__element_t *el, cf__bounds_t *b)
{
    const axes_el_t *ax = (const axes_el_t *)el;
    cf__bounds_add(b, ax->a.xmin, ax->a.ymin);
    cf__bounds_add(b, ax->a.xmax, ax->a.ymax);
}

void
cf_axes_init(cf_axes_t *axes)
{
    if (axes == NULL)
        return;
    memset(axes, 0, sizeof *axes);
    axes->xmax = 1;
    axes->ymax = 1;
    axes->arrows = true;
}

/* A "nice" step (1, 2, 5 x 10^k) giving about five intervals. */
static double
nice_step(double range)
{
    double raw = range / 5, mag = pow(10, floor(log10(raw))), m = raw / mag;
    if (m <= 1)
        return mag;
    if (m <= 2)
        return 2 * mag;
    if (m <= 5)
        return 5 * mag;
    return 10 * mag;
}

static void
format_number(double v, double step, char *buf, size_t cap)
{
    int dec = 0;
    double e = step;
    while (dec < 8 && fabs(e - round(e)) > 1e-9 * fmax(1, fabs(e))) {
        e *= 10;
        dec++;
    }
    if (fabs(v) < 1e-12 * fmax(1, step))
        v = 0;
    /* drop trailing zeros: 0, 0.25, 0.5, 0.75, 1 */
    while (dec > 0) {
        double k = pow(10, dec - 1);
        if (fabs(round(v * k) / k - v) > 1e-9 * fmax(1, fabs(v)))
            break;
        dec--;
    }
    snprintf(buf, cap, "%.*f", dec, v);
}

/* An explicit tick value: the fewest decimals (up to 3) that give it back
** to 1e-9, else 3 ("0.333"). */
static void
format_value(double v, char *buf, size_t cap)
{
    int dec;
    for (dec = 0; dec < 3; dec++) {
        double k = pow(10, dec);
        if (fabs(round(v * k) / k - v) <= 1e-9 * fmax(1, fabs(v)))
            break;
    }
    if (fabs(v) < 1e-12)
        v = 0;
    snprintf(buf, cap, "%.*f", dec, v);
}

/* Fill ticks from explicit positions or a step over [lo, hi]. */
static cf_status_t
make_ticks(cf_figure_t *fig, const double *pos, size_t count,
           const char *const *labels, double step, double lo, double hi,
           double font, tick_t **out, size_t *nout, const char *axis)
{
    size_t i, n;
    tick_t *t;
    cf_status_t st = CF_STATUS_OK;
    double first;

    *out = NULL;
    *nout = 0;
    if (count > 0) {
        if (pos == NULL)
            return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                               "%s ticks: positions are NULL", axis);
        if (cf_check_finite_points(pos, count, 1, 1, "tick", &fig->err)
            != CF_STATUS_OK)
            return fig->err.status;
        n = count;
    } else {
        if (step < 0)
            return CF_STATUS_OK;
        if (!isfinite(step))
            return cf_diag_set(&fig->err, CF_STATUS_NOT_FINITE, -1,
                               "%s tick step is not finite", axis);
        if (step == 0)
            step = nice_step(hi - lo);
        if ((hi - lo) / step > 200)
            return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                               "%s tick step %g gives more than 200 ticks",
                               axis, step);
        first = ceil(lo / step - 1e-9) * step;
        n = (size_t)floor((hi - first) / step + 1e-9) + 1;
    }
    t = cf_calloc(n ? n : 1, sizeof *t);
    if (t == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for ticks");
    for (i = 0; i < n && st == CF_STATUS_OK; i++) {
        char buf[64];
        const char *text = buf;
        if (count > 0) {
            t[i].v = pos[i];
            if (labels != NULL && labels[i] != NULL)
                text = labels[i];
            else
                format_value(pos[i], buf, sizeof buf);
        } else {
            t[i].v = first + (double)i * step;
            if (fabs(t[i].v) < 1e-9 * step)
                t[i].v = 0;
            format_number(t[i].v, step, buf, sizeof buf);
        }
        st = cf__text_set(fig, &t[i].t, text, font);
    }
    *out = t;
    *nout = n;
    return st;
}

/* The grid: thin lines in the fill colour at every tick. */
static void
axes_grid(const axes_el_t *ax, const cf__layout_t *l, const cf_style_t *s,
          const double *page, cf__dl_t *dl)
{
    cf__paint_t paint;
    size_t i;
    cf__dl_path_begin(dl);
    for (i = 0; i < ax->nxt; i++) {
        double px, py;
        cf__map(l, ax->xt[i].v, 0, &px, &py);
        cf__dl_move(dl, px, page[1]);
        cf__dl_line(dl, px, page[3]);
    }
    for (i = 0; i < ax->nyt; i++) {
        double px, py;
        cf__map(l, 0, ax->yt[i].v, &px, &py);
        cf__dl_move(dl, page[0], py);
        cf__dl_line(dl, page[2], py);
    }
    memset(&paint, 0, sizeof paint);
    if (s->fill.a > 0) {
        cf_style_t g = *s;
        g.color = s->fill;
        g.width = 0.4;
        g.dash_count = 0;
        paint.stroke = true;
        cf__stroke_from_style(&g, &paint.line);
    }
    cf__dl_path_paint(dl, &paint);
}

/* Automatic ticks labelled every `every` (a nice step, a multiple of the
** ticks' own, 0: each): the first of 1, 2, 5 x 10^k at or above the
** ticks' step, a whole multiple of it, whose labels are apart by their
** size plus a gap of 0.3 em on the page (scale bp per unit): the labels
** of automatic ticks in a plot a centimetre tall stood on each other
** (0.2 ... 1 in 14 bp).  All the tick marks stay; ticks given by position
** or step are labelled as given. */
static double
label_every(const tick_t *t, size_t n, double step, double scale,
            bool vertical, double font)
{
    static const double nice[] = { 1, 2, 5 };
    double size = 0, need, k;
    size_t i, m;
    for (i = 0; i < n; i++)
        if (t[i].t.lab != NULL) {
            double ink[4];
            cf__label_ink(t[i].t.lab, ink);
            size = fmax(size, vertical ? ink[3] - ink[1] : ink[2] - ink[0]);
        }
    need = size + 0.3 * font;
    if (n < 2 || !(step > 0) || !(step * scale < need))
        return 0;
    for (k = pow(10, floor(log10(step))); isfinite(k) && k < 1e300; k *= 10)
        for (m = 0; m < 3; m++) {
            double every = nice[m] * k, r = every / step;
            if (every >= step * (1 - 1e-9) && fabs(r - round(r)) < 1e-6
                && every * scale >= need)
                return every;
        }
    return 0;
}

/* Whether automatic tick value v is labelled (every: label_every's). */
static bool
labelled(double v, double every)
{
    double r;
    if (every == 0)
        return true;
    r = v / every;
    return fabs(r - round(r)) < 1e-6;
}

static cf_status_t
axes_draw(cf_figure_t *fig, cf__element_t *el, const cf__layout_t *l,
          const cf_style_t *s, cf__dl_t *dl)
{
    axes_el_t *ax = (axes_el_t *)el;
    const cf_axes_t *a = &ax->a;
    double tick = fig->theme.tick_size, ext, head;
    double yaxis_x, xaxis_y, px0, py0, px1, py1, ax_y, ay_x, lh = 0;
    double every_x = 0, every_y = 0;
    size_t i, j;
    cf_status_t st = CF_STATUS_OK;

    head = a->arrows ? s->arrow_size : 0;
    ext = a->arrows ? head + 3 : 0;
    if (a->box) {
        yaxis_x = a->xmin;
        xaxis_y = a->ymin;
        ext = 0;
        head = 0;
    } else {
        yaxis_x = (a->xmin <= 0 && 0 <= a->xmax) ? 0 : a->xmin;
        xaxis_y = (a->ymin <= 0 && 0 <= a->ymax) ? 0 : a->ymin;
    }
    cf__map(l, a->xmin, a->ymin, &px0, &py0);
    cf__map(l, a->xmax, a->ymax, &px1, &py1);
    cf__map(l, yaxis_x, xaxis_y, &ay_x, &ax_y);

    if (a->grid) {
        double page[4] = { px0, py0, px1, py1 };
        axes_grid(ax, l, s, page, dl);
    }
    /* axis lines (or the frame) and ticks */
    cf__dl_path_begin(dl);
    if (a->box) {
        cf__dl_rect(dl, px0, py1, px1 - px0, py0 - py1);
    } else {
        cf__dl_move(dl, px0, ax_y);
        cf__dl_line(dl, px1 + ext - 0.8 * head, ax_y);
        cf__dl_move(dl, ay_x, py0);
        cf__dl_line(dl, ay_x, py1 - ext + 0.8 * head);
    }
    for (i = 0; i < ax->nxt; i++) {
        double px, py;
        cf__map(l, ax->xt[i].v, xaxis_y, &px, &py);
        cf__dl_move(dl, px, ax_y);
        cf__dl_line(dl, px, ax_y + tick);
    }
    for (i = 0; i < ax->nyt; i++) {
        double px, py;
        cf__map(l, yaxis_x, ax->yt[i].v, &px, &py);
        cf__dl_move(dl, ay_x, py);
        cf__dl_line(dl, ay_x - tick, py);
    }
    {
        cf_style_t ls = *s;
        cf__paint_t paint;
        ls.dash_count = 0;
        memset(&paint, 0, sizeof paint);
        paint.stroke = true;
        cf__stroke_from_style(&ls, &paint.line);
        paint.line.cap = CF__CAP_BUTT;
        paint.line.join = CF__JOIN_MITER;
        cf__dl_path_paint(dl, &paint);
    }
    if (head > 0) {
        cf__arrow_head(dl, px1 + ext, ax_y, 1, 0, head, &s->color,
                       s->opacity);
        cf__arrow_head(dl, ay_x, py1 - ext, 0, -1, head, &s->color,
                       s->opacity);
    }
    /* tick labels (automatic ones thinned to fit) */
    if (a->xtick_count == 0 && a->xtick_step == 0 && a->knot_count == 0)
        every_x = label_every(ax->xt, ax->nxt, nice_step(a->xmax - a->xmin),
                              fabs(l->sx), false, s->font_size);
    if (a->ytick_count == 0 && a->ytick_step == 0)
        every_y = label_every(ax->yt, ax->nyt, nice_step(a->ymax - a->ymin),
                              fabs(l->sy), true, s->font_size);
    for (i = 0; i < ax->nxt && st == CF_STATUS_OK; i++) {
        double px, py;
        if (!labelled(ax->xt[i].v, every_x))
            continue;
        cf__map(l, ax->xt[i].v, xaxis_y, &px, &py);
        st = cf__text_draw(fig, &ax->xt[i].t, s, px, ax_y + tick,
                           CF_PLACE_S, s->offset, dl);
        if (ax->xt[i].t.lab != NULL) {
            double ink[4];
            cf__label_ink(ax->xt[i].t.lab, ink);
            lh = fmax(lh, ink[3] - ink[1]);
        }
    }
    for (i = 0; i < ax->nyt && st == CF_STATUS_OK; i++) {
        double px, py;
        bool at_x_axis = fabs(ax->yt[i].v - xaxis_y)
            <= 1e-9 * (a->ymax - a->ymin);
        if (!labelled(ax->yt[i].v, every_y))
            continue;
        /* the origin is labelled once, on the x axis */
        if (at_x_axis && !a->box && ax->nxt > 0 && yaxis_x >= a->xmin) {
            bool has = false;
            for (j = 0; j < ax->nxt; j++)
                if (fabs(ax->xt[j].v - yaxis_x)
                    <= 1e-9 * (a->xmax - a->xmin))
                    has = true;
            if (has)
                continue;
        }
        cf__map(l, yaxis_x, ax->yt[i].v, &px, &py);
        st = cf__text_draw(fig, &ax->yt[i].t, s, ay_x - tick, py,
                           CF_PLACE_W, s->offset, dl);
    }
    /* knots: a marker on the axis; labels stacked below the tick labels */
    if (ax->nkn > 0 && st == CF_STATUS_OK) {
        double row = 1.25 * s->font_size;
        for (i = 0; i < ax->nkn && st == CF_STATUS_OK; i++) {
            double px, py;
            size_t rep = 0;
            for (j = 0; j < i; j++)
                if (ax->kn[j].v == ax->kn[i].v)
                    rep++;
            cf__map(l, ax->kn[i].v, xaxis_y, &px, &py);
            if (rep == 0) {
                cf__marker_op_t m;
                cf__marker_from_style(s, s->marker, px, ax_y, NULL, &m);
                cf__dl_marker(dl, &m);
            }
            if (ax->kn[i].t.src != NULL) {
                double y = ax_y + tick + s->offset + lh + 2.5
                    + (double)rep * row;
                st = cf__text_draw(fig, &ax->kn[i].t, s, px, y, CF_PLACE_S,
                                   0.0, dl);
            }
        }
    }
    if (st == CF_STATUS_OK && ax->xlabel.src != NULL) {
        cf_style_t ls;
        cf__style_resolve(&fig->theme, CF_ROLE_LABEL, NULL, &ls);
        st = cf__text_draw(fig, &ax->xlabel, &ls, px1 + ext, ax_y,
                           a->box ? CF_PLACE_SE : CF_PLACE_E, 3.0, dl);
    }
    if (st == CF_STATUS_OK && ax->ylabel.src != NULL) {
        cf_style_t ls;
        cf__style_resolve(&fig->theme, CF_ROLE_LABEL, NULL, &ls);
        st = cf__text_draw(fig, &ax->ylabel, &ls, ay_x, py1 - ext,
                           CF_PLACE_N, 3.0, dl);
    }
    return st;
}


static const cf__kind_t axes_kind = {
    "axes", CF__KIND_AXES, axes_fini, axes_bounds, axes_draw, NULL, NULL, NULL
};

cf_status_t
cf_figure_add_axes(cf_figure_t *fig, const cf_axes_t *axes,
                   const cf_style_t *style)
{
    axes_el_t *ax;
    const cf_axes_t *a = axes;
    double font, lfont;
    cf_status_t st;
    size_t i;

    CF__FIG_CHECK(fig);
    if (a == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "axes are NULL");
    if (!(isfinite(a->xmin) && isfinite(a->xmax) && isfinite(a->ymin)
          && isfinite(a->ymax)))
        return cf_diag_set(&fig->err, CF_STATUS_NOT_FINITE, -1,
                           "axes ranges are not finite");
    if (!(a->xmin < a->xmax && a->ymin < a->ymax))
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "axes ranges [%g, %g] x [%g, %g] are empty",
                           a->xmin, a->xmax, a->ymin, a->ymax);
    if (a->knot_count > 0 && a->knots == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "axes: %zu knots but the array is NULL",
                           a->knot_count);
    if (a->knot_count > 0
        && cf_check_finite_points(a->knots, a->knot_count, 1, 1, "knot",
                                  &fig->err) != CF_STATUS_OK)
        return fig->err.status;
    if (cf__fig_check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    ax = cf__element_new(fig, &axes_kind, sizeof *ax, CF_ROLE_AXES, style);
    if (ax == NULL)
        return fig->err.status;
    ax->a = *a;
    ax->a.xticks = ax->a.yticks = ax->a.knots = NULL;
    ax->a.xtick_labels = ax->a.ytick_labels = ax->a.knot_labels = NULL;
    ax->a.xlabel = ax->a.ylabel = NULL;
    font = cf__role_font_size(fig, CF_ROLE_AXES, style);
    lfont = cf__role_font_size(fig, CF_ROLE_LABEL, NULL);
    if (a->xtick_count == 0 && a->xtick_step == 0 && a->knot_count > 0) {
        /* knots given: they are the x ticks (distinct values) */
        double *dv = cf_alloc_array(a->knot_count, sizeof *dv);
        size_t nd = 0, j;
        if (dv == NULL)
            return cf__element_commit(fig, ax, cf__fig_nomem(fig, "axes"));
        for (i = 0; i < a->knot_count; i++) {
            for (j = 0; j < nd && dv[j] != a->knots[i]; j++)
                ;
            if (j == nd)
                dv[nd++] = a->knots[i];
        }
        st = make_ticks(fig, dv, nd, NULL, 0, a->xmin, a->xmax, font,
                        &ax->xt, &ax->nxt, "x");
        cf_free(dv);
    } else {
        st = make_ticks(fig, a->xticks, a->xtick_count, a->xtick_labels,
                        a->xtick_step, a->xmin, a->xmax, font, &ax->xt,
                        &ax->nxt, "x");
    }
    if (st == CF_STATUS_OK)
        st = make_ticks(fig, a->yticks, a->ytick_count, a->ytick_labels,
                        a->ytick_step, a->ymin, a->ymax, font, &ax->yt,
                        &ax->nyt, "y");
    if (st == CF_STATUS_OK && a->knot_count > 0) {
        ax->kn = cf_calloc(a->knot_count, sizeof *ax->kn);
        if (ax->kn == NULL)
            st = cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                             "out of memory for knots");
        else
            ax->nkn = a->knot_count;
        for (i = 0; i < ax->nkn && st == CF_STATUS_OK; i++) {
            ax->kn[i].v = a->knots[i];
            if (a->knot_labels != NULL && a->knot_labels[i] != NULL)
                st = cf__text_set(fig, &ax->kn[i].t, a->knot_labels[i], font);
        }
    }
    if (st == CF_STATUS_OK && a->xlabel != NULL)
        st = cf__text_set(fig, &ax->xlabel, a->xlabel, lfont);
    if (st == CF_STATUS_OK && a->ylabel != NULL)
        st = cf__text_set(fig, &ax->ylabel, a->ylabel, lfont);
    return cf__element_commit(fig, ax, st);
}

