/*
** Labels and arrows: the two kinds anchored at one data point.  A label
** placed CF_PLACE_AUTO takes the place render/layout/place.c chose for the
** current layout.
*/
#include <math.h>
#include <string.h>

#include "surface-lines.h"

typedef struct label_el {
    cf__element_t base;
    cf__text_t text;
    double x, y;
    bool space;               /* anchored at p in R^3, seen or not */
    double p[3];
    cf_hidden_t hidden;
    cf__auto_place_t chosen;  /* CF_PLACE_AUTO: the place chosen for the
                                 current layout */
} label_el_t;

typedef struct arrow_el {
    cf__element_t base;
    double x, y, dx, dy;
} arrow_el_t;

/* ---- labels ------------------------------------------------------------- */

static void
label_fini(cf__element_t *el)
{
    cf__text_fini(&((label_el_t *)el)->text);
}

static void
label_bounds(const cf__element_t *el, cf__bounds_t *b)
{
    const label_el_t *e = (const label_el_t *)el;
    cf__bounds_add(b, e->x, e->y);
}

static cf_status_t
label_draw(cf_figure_t *fig, cf__element_t *el, const cf__layout_t *l,
           const cf_style_t *s, cf__dl_t *dl)
{
    label_el_t *e = (label_el_t *)el;
    cf_style_t faded;
    double px, py;
    bool seen = true;
    if (e->space && e->hidden != CF_HIDDEN_SHOW
        && cf__space_point_visible(fig, e->p, l->tol, &seen) != CF_STATUS_OK)
        return cf__fig_fail(fig, fig->err.status, "a label in space");
    if (!seen && e->hidden == CF_HIDDEN_REMOVE)
        return CF_STATUS_OK;
    if (!seen) {
        faded = *s;
        faded.opacity *= 0.4;
        s = &faded;
    }
    cf__map(l, e->x, e->y, &px, &py);
    if (s->place == CF_PLACE_AUTO)
        return cf__text_draw(fig, &e->text, s, px, py, e->chosen.place,
                             e->chosen.offset, dl);
    return cf__text_draw(fig, &e->text, s, px, py, s->place, s->offset, dl);
}

static bool
label_auto(cf__element_t *el, double *x, double *y, cf__text_t **text,
           cf__auto_place_t **chosen)
{
    label_el_t *e = (label_el_t *)el;
    *x = e->x;
    *y = e->y;
    *text = &e->text;
    *chosen = &e->chosen;
    return true;
}

static const cf__kind_t label_kind = {
    "label", 0, label_fini, label_bounds, label_draw, label_auto, NULL, NULL
};

cf_status_t
cf_figure_add_label(cf_figure_t *fig, double x, double y, const char *text,
                    const cf_style_t *style)
{
    label_el_t *e;
    CF__FIG_CHECK(fig);
    if (text == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "label text is NULL");
    if (!(isfinite(x) && isfinite(y)))
        return cf_diag_set(&fig->err, CF_STATUS_NOT_FINITE, -1,
                           "label \"%s\" at (%g, %g) is not finite", text, x,
                           y);
    if (cf__fig_check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    e = cf__element_new(fig, &label_kind, sizeof *e, CF_ROLE_LABEL, style);
    if (e == NULL)
        return fig->err.status;
    e->x = x;
    e->y = y;
    e->chosen.place = CF_PLACE_NE;
    e->chosen.offset = 4.0;
    if (cf__element_commit(
            fig, e,
            cf__text_set(fig, &e->text, text,
                         cf__role_font_size(fig, CF_ROLE_LABEL, style)))
        != CF_STATUS_OK)
        return fig->err.status;
    return cf__fact_label(fig, x, y, text);
}

cf_status_t
cf_figure_add_space_label(cf_figure_t *fig, const double *p, const char *text,
                          cf_hidden_t hidden, const cf_style_t *style)
{
    double q[2];
    cf_status_t st;
    CF__FIG_CHECK(fig);
    if (p == NULL || !fig->has_view || (unsigned)hidden > CF_HIDDEN_REMOVE)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "label in space: %s", p == NULL ? "point is NULL"
                           : !fig->has_view ? "the figure has no view"
                           : "hidden is not show, dashed or remove");
    if (cf_check_finite_points(p, 1, 3, 3, "label point", &fig->err)
        != CF_STATUS_OK)
        return fig->err.status;
    cf__fig_project1(fig, p, 3, q);
    if (isnan(q[0]))
        return cf__fig_behind_eye(fig, p, "label point");
    st = cf_figure_add_label(fig, q[0], q[1], text, style);
    if (st == CF_STATUS_OK) {
        label_el_t *e = (label_el_t *)fig->els[fig->count - 1];
        e->space = true;
        memcpy(e->p, p, sizeof e->p);
        e->hidden = hidden;
    }
    return st;
}

/* ---- arrows ------------------------------------------------------------- */

static void
arrow_fini(cf__element_t *el)
{
    (void)el;
}

static void
arrow_bounds(const cf__element_t *el, cf__bounds_t *b)
{
    const arrow_el_t *e = (const arrow_el_t *)el;
    cf__bounds_add(b, e->x, e->y);
    cf__bounds_add(b, e->x + e->dx, e->y + e->dy);
}

/* The shaft stops where the head's notch is, so that its end hides under
** the head; arrows are drawn whole, never clipped. */
static cf_status_t
arrow_draw(cf_figure_t *fig, cf__element_t *el, const cf__layout_t *l,
           const cf_style_t *s, cf__dl_t *dl)
{
    arrow_el_t *e = (arrow_el_t *)el;
    double x0, y0, x1, y1, dx, dy, len, ux, uy, head = s->arrow_size;
    cf__paint_t paint;
    (void)fig;
    cf__map(l, e->x, e->y, &x0, &y0);
    cf__map(l, e->x + e->dx, e->y + e->dy, &x1, &y1);
    dx = x1 - x0;
    dy = y1 - y0;
    len = hypot(dx, dy);
    if (!(len > 1e-9))
        return CF_STATUS_OK;
    ux = dx / len;
    uy = dy / len;
    head = fmin(head, len);
    memset(&paint, 0, sizeof paint);
    paint.stroke = true;
    cf__stroke_from_style(s, &paint.line);
    paint.line.cap = CF__CAP_BUTT;
    cf__dl_path_begin(dl);
    cf__dl_move(dl, x0, y0);
    cf__dl_line(dl, x1 - 0.8 * head * ux, y1 - 0.8 * head * uy);
    cf__dl_path_paint(dl, &paint);
    if (head > 0)
        cf__arrow_head(dl, x1, y1, ux, uy, head, &s->color, s->opacity);
    return CF_STATUS_OK;
}

static const cf__kind_t arrow_kind = {
    "arrow", 0, arrow_fini, arrow_bounds, arrow_draw, NULL, NULL, NULL
};

cf_status_t
cf_figure_add_arrow(cf_figure_t *fig, double x, double y, double dx,
                    double dy, const cf_style_t *style)
{
    arrow_el_t *e;
    CF__FIG_CHECK(fig);
    if (!(isfinite(x) && isfinite(y) && isfinite(dx) && isfinite(dy)))
        return cf_diag_set(&fig->err, CF_STATUS_NOT_FINITE, -1,
                           "arrow (%g, %g) + (%g, %g) is not finite", x, y,
                           dx, dy);
    if (cf__fig_check_style(fig, style) != CF_STATUS_OK)
        return fig->err.status;
    e = cf__element_new(fig, &arrow_kind, sizeof *e, CF_ROLE_ARROW, style);
    if (e == NULL)
        return fig->err.status;
    e->x = x;
    e->y = y;
    e->dx = dx;
    e->dy = dy;
    return cf__element_commit(fig, e, CF_STATUS_OK);
}
