/*
** Panels: a figure's page split into a grid of cells, each a figure of
** its own (window, aspect, elements) laid out in its cell below its
** title; the panels of a column may share the x mapping, those of a row
** the y mapping.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "layout-private.h"

#define PANEL_TITLE_BAND 1.5   /* title band: this many font sizes high */

static double
title_band(const cf_figure_t *fig, int k)
{
    const cf_figure_t *p = fig->panels[k];
    if (p->panel_title.src == NULL)
        return 0;
    return PANEL_TITLE_BAND * cf__role_font_size(fig, CF_ROLE_LABEL, NULL);
}

/* The whole cell k, page bp from the figure's top left. */
static void
whole_cell(const cf_figure_t *fig, int k, double cell[4])
{
    double g = fig->panel_gap;
    double w = (fig->width - (fig->cols - 1) * g) / fig->cols;
    double h = (fig->height - (fig->rows - 1) * g) / fig->rows;
    cell[0] = (k % fig->cols) * (w + g);
    cell[1] = (k / fig->cols) * (h + g);
    cell[2] = w;
    cell[3] = h;
}

void
cf__panel_cell(const cf_figure_t *fig, int k, double cell[4])
{
    double band = title_band(fig, k);
    whole_cell(fig, k, cell);
    cell[1] += band;
    cell[3] -= band;
}

cf_status_t
cf_figure_add_panels(cf_figure_t *fig, int rows, int cols, double gap_bp,
                     unsigned flags, cf_figure_t **out)
{
    int k, n;
    CF__FIG_CHECK(fig);
    if (out == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "the output array is NULL");
    if (fig->panels != NULL || fig->parent != NULL)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "the figure is split already (a panel "
                           "is not split again)");
    if (rows < 1 || rows > 8 || cols < 1 || cols > 8)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "a grid of %d x %d; rows and cols are "
                           "1 to 8", rows, cols);
    if (!(isfinite(gap_bp) && gap_bp >= 0
          && (cols - 1) * gap_bp < 0.5 * fig->width
          && (rows - 1) * gap_bp < 0.5 * fig->height))
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "gap %g bp leaves no room for %d x %d "
                           "panels on a %g x %g bp page", gap_bp, rows, cols,
                           fig->width, fig->height);
    n = rows * cols;
    fig->panels = cf_calloc((size_t)n, sizeof *fig->panels);
    if (fig->panels == NULL)
        return cf__fig_nomem(fig, "panels");
    fig->rows = rows;
    fig->cols = cols;
    fig->panel_gap = gap_bp;
    fig->panel_flags = flags;
    for (k = 0; k < n; k++) {
        double cell[4];
        cf_figure_t *p;
        whole_cell(fig, k, cell);
        if (cf__figure_create(fig->fonts, cell[2], cell[3], CF_UNIT_BP,
                              &fig->panels[k], &fig->err) != CF_STATUS_OK)
            return fig->err.status;
        p = fig->panels[k];
        p->parent = fig;
        p->theme = fig->theme;
        p->margin = fig->margin;
        p->aspect = fig->aspect;
        p->tol = fig->tol;
        if (!(flags & CF_PANELS_NO_TITLES)) {
            char t[8];
            snprintf(t, sizeof t, "(%c)", 'a' + k);
            if (cf__text_set(fig, &p->panel_title, t,
                             cf__role_font_size(fig, CF_ROLE_LABEL, NULL))
                != CF_STATUS_OK)
                return fig->err.status;
        }
        out[k] = p;
    }
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_set_panel_title(cf_figure_t *panel, const char *title)
{
    CF__FIG_CHECK(panel);
    if (panel->parent == NULL)
        return cf_diag_set(&panel->err, CF_STATUS_INVALID_ARG, -1,
                           "panel title: the figure is not a panel");
    cf__text_fini(&panel->panel_title);
    if (title == NULL || title[0] == '\0')
        return CF_STATUS_OK;
    return cf__text_set(panel, &panel->panel_title, title,
                        cf__role_font_size(panel, CF_ROLE_LABEL, NULL));
}

/* Lays i and j (of fig's panels) take one mapping of x (axis 0) or y. */
static void
share_axis(const cf_figure_t *fig, cf__layout_t *lays, const int *ks,
           int n, int axis)
{
    double lo = INFINITY, hi = -INFINITY, p0 = -INFINITY, p1 = INFINITY, s;
    int i;
    for (i = 0; i < n; i++) {
        const cf__layout_t *l = &lays[ks[i]];
        double a = axis ? l->ymin : l->xmin, b = axis ? l->ymax : l->xmax;
        double o = axis ? l->oy - l->sy * (b - a) : l->ox;
        double e = o + (axis ? l->sy : l->sx) * (b - a);
        lo = fmin(lo, a);
        hi = fmax(hi, b);
        p0 = fmax(p0, o);
        p1 = fmin(p1, e);
    }
    s = (p1 - p0) / (hi - lo);
    for (i = 0; i < n; i++) {
        cf__layout_t *l = &lays[ks[i]];
        bool kept = fabs(l->sx - l->sy) <= 1e-12 * l->sx;
        double cx = l->ox + 0.5 * l->sx * (l->xmax - l->xmin);
        double cy = l->oy - 0.5 * l->sy * (l->ymax - l->ymin);
        if (axis == 0) {
            l->xmin = lo;
            l->xmax = hi;
            l->sx = s;
            l->ox = p0;
            if (kept) {
                l->sy = s;
                l->oy = cy + 0.5 * s * (l->ymax - l->ymin);
            }
        } else {
            l->ymin = lo;
            l->ymax = hi;
            l->sy = s;
            l->oy = p0 + s * (hi - lo);
            if (kept) {
                l->sx = s;
                l->ox = cx - 0.5 * s * (l->xmax - l->xmin);
            }
        }
        l->tol = fig->panels[ks[i]]->tol / fmax(l->sx, l->sy);
    }
}

void
cf__panels_share(const cf_figure_t *fig, cf__layout_t *lays)
{
    int ks[8], r, c;
    if (fig->panel_flags & CF_PANELS_SHARE_X)
        for (c = 0; c < fig->cols; c++) {
            for (r = 0; r < fig->rows; r++)
                ks[r] = r * fig->cols + c;
            share_axis(fig, lays, ks, fig->rows, 0);
        }
    if (fig->panel_flags & CF_PANELS_SHARE_Y)
        for (r = 0; r < fig->rows; r++) {
            for (c = 0; c < fig->cols; c++)
                ks[c] = r * fig->cols + c;
            share_axis(fig, lays, ks, fig->cols, 1);
        }
}

cf_status_t
cf__panel_title_draw(cf_figure_t *fig, int k, const cf__layout_t *lay,
                     cf__dl_t *dl)
{
    cf_figure_t *p = fig->panels[k];
    cf_style_t s;
    double cell[4];
    if (p->panel_title.src == NULL)
        return CF_STATUS_OK;
    whole_cell(fig, k, cell);
    cf__style_resolve(&fig->theme, CF_ROLE_LABEL, NULL, &s);
    if (cf__text_draw(fig, &p->panel_title, &s, lay->px + cell[0] + 2,
                      lay->py + cell[1] + 0.5 * title_band(fig, k),
                      CF_PLACE_E, 0, dl) != CF_STATUS_OK)
        return fig->err.status;
    return CF_STATUS_OK;
}
