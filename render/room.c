/*
** Free room on the page: where a box of a given size can go without
** covering ink.  What is drawn so far is painted into a coarse A8 raster
** (by the cairo backend); each candidate place (a corner or side of the
** page box) counts the raster pixels it covers.
*/
#include <math.h>

#include <cairo.h>

#include "backend.h"
#include "model.h"

#define ROOM_RES 2.0          /* raster pixels per bp */
#define ROOM_MAX_PIXELS 4e6   /* larger pages get a coarser raster */
#define ROOM_CLEAR 3.0        /* bp around the box that must be clear too */
#define ROOM_FAINT 8          /* pixel values up to this are not ink */

/* The pixels of the raster under page box b (x0 y0 x1 y1, bp) that carry
** ink. */
static size_t
inked_pixels(cairo_surface_t *img, double res, const double b[4])
{
    const unsigned char *px = cairo_image_surface_get_data(img);
    int w = cairo_image_surface_get_width(img);
    int h = cairo_image_surface_get_height(img);
    int stride = cairo_image_surface_get_stride(img);
    int i0 = (int)fmax(0, floor(b[0] * res));
    int i1 = (int)fmin(w, ceil(b[2] * res));
    int j0 = (int)fmax(0, floor(b[1] * res));
    int j1 = (int)fmin(h, ceil(b[3] * res));
    size_t n = 0;
    int i, j;
    for (j = j0; j < j1; j++)
        for (i = i0; i < i1; i++)
            n += px[(size_t)j * (size_t)stride + (size_t)i] > ROOM_FAINT;
    return n;
}

/* The top left of a w x h box at place of the page box, gap inside. */
static void
box_at(const double page[4], double w, double h, cf_place_t place,
       double gap, double at[2])
{
    double l = page[0] + gap, r = page[2] - gap - w;
    double t = page[1] + gap, b = page[3] - gap - h;
    double cx = 0.5 * (l + r), cy = 0.5 * (t + b);
    switch (place) {
    case CF_PLACE_N:  at[0] = cx; at[1] = t; break;
    case CF_PLACE_NE: at[0] = r;  at[1] = t; break;
    case CF_PLACE_E:  at[0] = r;  at[1] = cy; break;
    case CF_PLACE_SE: at[0] = r;  at[1] = b; break;
    case CF_PLACE_S:  at[0] = cx; at[1] = b; break;
    case CF_PLACE_SW: at[0] = l;  at[1] = b; break;
    case CF_PLACE_W:  at[0] = l;  at[1] = cy; break;
    case CF_PLACE_NW: at[0] = l;  at[1] = t; break;
    default:          at[0] = cx; at[1] = cy; break;
    }
}

cf_status_t
cf__room_find(cf_figure_t *fig, const cf__layout_t *lay, const cf__dl_t *dl,
              double w, double h, cf_place_t place, double gap, double at[2],
              size_t *covered)
{
    static const cf_place_t order[] = {
        CF_PLACE_NE, CF_PLACE_NW, CF_PLACE_SE, CF_PLACE_SW,
        CF_PLACE_N, CF_PLACE_S, CF_PLACE_E, CF_PLACE_W
    };
    double page[4] = { lay->px, lay->py, lay->px + fig->width,
                       lay->py + fig->height };
    double res = ROOM_RES, pw = page[2], ph = page[3];
    cairo_surface_t *img;
    cairo_t *cr;
    size_t k, best = (size_t)-1;
    if (covered != NULL)
        *covered = 0;
    if (place != CF_PLACE_AUTO) {
        box_at(page, w, h, place, gap, at);
        return CF_STATUS_OK;
    }
    if (pw * ph * res * res > ROOM_MAX_PIXELS)
        res = sqrt(ROOM_MAX_PIXELS / (pw * ph));
    img = cairo_image_surface_create(CAIRO_FORMAT_A8, (int)ceil(pw * res),
                                     (int)ceil(ph * res));
    cr = cairo_create(img);
    if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) {
        cairo_destroy(cr);
        cairo_surface_destroy(img);
        return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                           "out of memory finding room on the page");
    }
    cairo_scale(cr, res, res);
    cf__dl_play(dl, 0, dl->count, &cf__cairo_backend, cr);
    cairo_surface_flush(img);
    box_at(page, w, h, order[0], gap, at);
    for (k = 0; k < sizeof order / sizeof order[0] && best != 0; k++) {
        double a[2], b[4];
        size_t n;
        box_at(page, w, h, order[k], gap, a);
        b[0] = a[0] - ROOM_CLEAR;
        b[1] = a[1] - ROOM_CLEAR;
        b[2] = a[0] + w + ROOM_CLEAR;
        b[3] = a[1] + h + ROOM_CLEAR;
        n = inked_pixels(img, res, b);
        if (n < best) {
            best = n;
            at[0] = a[0];
            at[1] = a[1];
        }
    }
    if (covered != NULL)
        *covered = best;
    cairo_destroy(cr);
    cairo_surface_destroy(img);
    return CF_STATUS_OK;
}
