/*
** Zoom insets: the elements drawn again through a second data -> page
** map, the affine image of the figure's own that takes the region onto
** the inset's box, clipped to that box; the region framed in the main
** drawing, the inset framed, and two connector lines between the frames.
*/
#include <math.h>
#include <string.h>

#include "model.h"

#define INSET_EDGE 4.0    /* bp inside the edge of the drawing's ink */
#define INSET_FRAME 0.5   /* bp: frame and connector width */

void
cf_inset_init(cf_inset_t *inset)
{
    if (inset == NULL)
        return;
    memset(inset, 0, sizeof *inset);
    inset->place = CF_PLACE_AUTO;
}

cf_status_t
cf_figure_add_inset(cf_figure_t *fig, const cf_inset_t *in)
{
    cf_inset_t *n;
    cf__room_band_t *band;
    const double *r;
    CF__FIG_CHECK(fig);
    if (in == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "NULL");
    r = in->region;
    if (cf_check_finite_points(r, 2, 2, 2, "inset region", &fig->err)
        != CF_STATUS_OK)
        return fig->err.status;
    if (!(r[0] < r[2] && r[1] < r[3]))
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "inset %zu: region {%g, %g, %g, %g} is empty "
                           "(give {x0, y0, x1, y1}, x0 < x1, y0 < y1)",
                           fig->ninsets + 1, r[0], r[1], r[2], r[3]);
    if ((unsigned)in->place >= CF_PLACE_LAST_ || in->place == CF_PLACE_CENTER)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "inset %zu: place %d: give a corner or side (ne, "
                           "nw, se, sw, n, s, e, w) or auto",
                           fig->ninsets + 1, (int)in->place);
    if (!(isfinite(in->scale) && in->scale >= 0 && isfinite(in->size)
          && in->size >= 0))
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "inset %zu: scale %g and size %g must be finite "
                           "and >= 0", fig->ninsets + 1, in->scale,
                           in->size);
    if (in->has_rect
        && (cf_check_finite_points(in->rect, 2, 2, 2, "inset rect",
                                   &fig->err) != CF_STATUS_OK
            || !(in->rect[2] > 0 && in->rect[3] > 0)))
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "inset %zu: the box {x, y, w, h} needs w > 0 and "
                           "h > 0", fig->ninsets + 1);
    n = cf_realloc_array(fig->insets, fig->ninsets + 1, sizeof *n);
    if (n == NULL)
        return cf__fig_nomem(fig, "an inset");
    fig->insets = n;
    band = cf_realloc_array(fig->inset_band, fig->ninsets + 1, sizeof *band);
    if (band == NULL)
        return cf__fig_nomem(fig, "an inset");
    fig->inset_band = band;
    band[fig->ninsets] = CF__ROOM_UNDECIDED;
    n[fig->ninsets++] = *in;
    return CF_STATUS_OK;
}

/* The inset's map: the region onto the box at (bx, by), magnified k. */
static void
inset_map(const cf__layout_t *lay, const double r[4], double k, double bx,
          double by, cf__layout_t *out)
{
    *out = *lay;
    out->xmin = r[0];
    out->ymin = r[1];
    out->xmax = r[2];
    out->ymax = r[3];
    out->sx = k * lay->sx;
    out->sy = k * lay->sy;
    out->ox = bx;
    out->oy = by + out->sy * (r[3] - r[1]);
    out->tol = lay->tol / k;
    out->clip = true;
}

static void
frame(double x, double y, double w, double h, const cf__paint_t *p,
      cf__dl_t *dl)
{
    cf__dl_path_begin(dl);
    cf__dl_rect(dl, x, y, w, h);
    cf__dl_path_paint(dl, p);
}

/* The two connectors: from the region's corners to the inset's nearest
** ones (the pair of corners on the side facing the inset). */
static void
connectors(const double rb[4], const double ib[4], const cf__paint_t *p,
           cf__dl_t *dl)
{
    /* boxes as x0 y0 x1 y1; corners 0 tl, 1 tr, 2 br, 3 bl */
    double rc[4][2] = { { rb[0], rb[1] }, { rb[2], rb[1] },
                        { rb[2], rb[3] }, { rb[0], rb[3] } };
    double ic[4][2] = { { ib[0], ib[1] }, { ib[2], ib[1] },
                        { ib[2], ib[3] }, { ib[0], ib[3] } };
    int a, b;
    bool left = ib[2] <= rb[0], right = ib[0] >= rb[2];
    bool above = ib[3] <= rb[1], below = ib[1] >= rb[3];
    if (right && !above && !below) {
        a = 1; b = 2;
    } else if (left && !above && !below) {
        a = 0; b = 3;
    } else if (above && !left && !right) {
        a = 0; b = 1;
    } else if (below && !left && !right) {
        a = 3; b = 2;
    } else if ((right && above) || (left && below)) {
        a = 0; b = 2;
    } else {
        a = 1; b = 3;
    }
    cf__dl_path_begin(dl);
    cf__dl_move(dl, rc[a][0], rc[a][1]);
    cf__dl_line(dl, ic[a][0], ic[a][1]);
    cf__dl_move(dl, rc[b][0], rc[b][1]);
    cf__dl_line(dl, ic[b][0], ic[b][1]);
    cf__dl_path_paint(dl, p);
}

/* The magnification of inset in for layout lay; the region's page box
** into rb (x0 y0 x1 y1). */
static double
magnification(const cf_figure_t *fig, const cf__layout_t *lay,
              const cf_inset_t *in, double rb[4])
{
    const double *r = in->region;
    cf__map(lay, r[0], r[3], &rb[0], &rb[1]);
    cf__map(lay, r[2], r[1], &rb[2], &rb[3]);
    if (in->has_rect)
        return fmin(in->rect[2] / (rb[2] - rb[0]),
                    in->rect[3] / (rb[3] - rb[1]));
    if (in->scale > 0)
        return in->scale;
    return (in->size > 0 ? in->size : fig->width / 3) / (rb[2] - rb[0]);
}

static cf_status_t
draw_inset(cf_figure_t *fig, const cf__layout_t *lay, size_t k,
           size_t from, cf__dl_t *dl)
{
    const cf_inset_t *in = &fig->insets[k];
    const double *r = in->region;
    double e = 1e-9 * fmax(lay->xmax - lay->xmin, lay->ymax - lay->ymin);
    double rb[4], ib[4], bw, bh, mag, at[2];
    cf__layout_t il;
    cf__paint_t line, bg;
    cf_style_t axes;
    size_t i;
    if (r[0] < lay->xmin - e || r[2] > lay->xmax + e || r[1] < lay->ymin - e
        || r[3] > lay->ymax + e)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, (long)k,
                           "inset %zu: region {%g, %g, %g, %g} is not inside "
                           "the window [%g, %g] x [%g, %g]", k + 1, r[0],
                           r[1], r[2], r[3], lay->xmin, lay->xmax,
                           lay->ymin, lay->ymax);
    mag = magnification(fig, lay, in, rb);
    bw = mag * (rb[2] - rb[0]);
    bh = mag * (rb[3] - rb[1]);
    if (in->has_rect) {
        at[0] = lay->px + in->rect[0];
        at[1] = lay->py + in->rect[1];
    } else {
        if (cf__room_find(fig, lay, dl, from, bw, bh, in->place,
                          INSET_EDGE, &fig->inset_band[k], at)
            != CF_STATUS_OK)
            return fig->err.status;
    }
    ib[0] = at[0];
    ib[1] = at[1];
    ib[2] = at[0] + bw;
    ib[3] = at[1] + bh;
    inset_map(lay, r, mag, at[0], at[1], &il);
    cf__style_resolve(&fig->theme, CF_ROLE_AXES, NULL, &axes);
    memset(&line, 0, sizeof line);
    line.stroke = true;
    cf__stroke_from_style(&axes, &line.line);
    line.line.width = INSET_FRAME;
    line.line.dash_count = 0;
    bg = line;
    bg.stroke = false;
    bg.fill = true;
    bg.fill_color = fig->theme.background;
    if (bg.fill_color.a <= 0)
        bg.fill_color.r = bg.fill_color.g = bg.fill_color.b =
            bg.fill_color.a = 1;
    bg.fill_opacity = 1;
    cf__dl_group(dl, "inset", k);
    frame(rb[0], rb[1], rb[2] - rb[0], rb[3] - rb[1], &line, dl);
    connectors(rb, ib, &line, dl);
    frame(ib[0], ib[1], bw, bh, &bg, dl);
    {
        double rect[4] = { ib[0], ib[1], bw, bh };
        cf__dl_clip(dl, rect);
    }
    for (i = 0; i < fig->count; i++)
        if (fig->els[i]->role != CF_ROLE_LABEL
            && cf__element_draw(fig, i, &il, dl) != CF_STATUS_OK)
            break;
    cf__dl_unclip(dl);
    frame(ib[0], ib[1], bw, bh, &line, dl);
    cf__dl_end(dl);
    return fig->err.status;
}

cf_status_t
cf__insets_draw(cf_figure_t *fig, const cf__layout_t *lay, size_t from,
                cf__dl_t *dl)
{
    size_t k;
    for (k = 0; k < fig->ninsets; k++)
        if (draw_inset(fig, lay, k, from, dl) != CF_STATUS_OK)
            return fig->err.status;
    return CF_STATUS_OK;
}
