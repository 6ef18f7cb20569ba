/*
** Zoom insets: the elements drawn again through a second data -> page
** map, the affine image of the figure's own that takes the region onto
** the inset's box, clipped to that box; the region framed in the main
** drawing, the inset framed, and two connector lines between the frames.
*/
#include <math.h>
#include <string.h>

#include "layout-private.h"


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
    if (in->beside && in->place != CF_PLACE_N && in->place != CF_PLACE_S
        && in->place != CF_PLACE_E && in->place != CF_PLACE_W)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "inset %zu: beside the drawing is a side (above, "
                           "below, left, right: n, s, w, e), not place %d",
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

static cf_status_t
draw_inset(cf_figure_t *fig, const cf__layout_t *lay, size_t k,
           const cf__inset_geom_t *g, cf__dl_t *dl)
{
    const cf_inset_t *in = &fig->insets[k];
    double bw = g->ib[2] - g->ib[0], bh = g->ib[3] - g->ib[1];
    cf__layout_t il;
    cf__paint_t bg;
    size_t i;
    inset_map(lay, in->region, g->mag, g->ib[0], g->ib[1], &il);
    memset(&bg, 0, sizeof bg);
    bg.fill = true;
    bg.fill_color = fig->theme.background;
    if (bg.fill_color.a <= 0)
        bg.fill_color.r = bg.fill_color.g = bg.fill_color.b =
            bg.fill_color.a = 1;
    bg.fill_opacity = 1;
    cf__dl_group(dl, "inset", k);
    if (cf__inset_outline(fig, g, CF__INSET_LINES, dl) != CF_STATUS_OK)
        return fig->err.status;
    frame(g->ib[0], g->ib[1], bw, bh, &bg, dl);
    {
        double rect[4] = { g->ib[0], g->ib[1], bw, bh };
        cf__dl_clip(dl, rect);
    }
    for (i = 0; i < fig->count; i++)
        if (fig->els[i]->role != CF_ROLE_LABEL
            && cf__element_draw(fig, i, &il, dl) != CF_STATUS_OK)
            break;
    cf__dl_unclip(dl);
    /* the inset's frame over what it shows */
    if (cf__inset_outline(fig, g, CF__INSET_FRAME, dl) != CF_STATUS_OK)
        return fig->err.status;
    cf__dl_end(dl);
    return fig->err.status;
}

cf_status_t
cf__insets_draw(cf_figure_t *fig, const cf__layout_t *lay, cf__dl_t *dl)
{
    cf__inset_geom_t *g;
    size_t k;
    if (fig->ninsets == 0)
        return CF_STATUS_OK;
    g = cf_alloc_array(fig->ninsets, sizeof *g);
    if (g == NULL)
        return cf__fig_nomem(fig, "the insets");
    if (cf__insets_place(fig, lay, g) == CF_STATUS_OK)
        for (k = 0; k < fig->ninsets; k++)
            if (draw_inset(fig, lay, k, &g[k], dl) != CF_STATUS_OK)
                break;
    cf_free(g);
    return fig->err.status;
}
