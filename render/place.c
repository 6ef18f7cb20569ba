/*
** Automatic label places: a label placed CF_PLACE_AUTO takes the side of
** its anchor where it covers the least ink.  Everything else is drawn
** into a coarse raster (by the cairo backend), then each automatic label
** in turn takes the cheapest of the eight places and is added to it.
*/
#include <math.h>

#include <cairo.h>

#include "backend.h"
#include "label-private.h"
#include "model.h"

#define AUTO_RES 2.0          /* raster pixels per bp */
#define AUTO_MAX_PIXELS 4e6   /* larger pages get a coarser raster */
#define AUTO_GAP 1.0          /* bp around a label that should stay clear */
#define AUTO_NEAR 3.0         /* bp: ink this close costs a quarter */

/* Ink in the page box x0 y0 x1 y1 (bp) of an A8 raster at res pixels per
** bp, in bp^2 of full ink; pixels off the page count as full ink. */
static double
raster_ink(cairo_surface_t *img, double res, const double b[4])
{
    const unsigned char *px = cairo_image_surface_get_data(img);
    int w = cairo_image_surface_get_width(img);
    int h = cairo_image_surface_get_height(img);
    int stride = cairo_image_surface_get_stride(img);
    double i0 = floor(b[0] * res), i1 = ceil(b[2] * res);
    double j0 = floor(b[1] * res), j1 = ceil(b[3] * res);
    double sum = 0, inside = 0;
    int i, j, ci0 = (int)fmax(i0, 0), ci1 = (int)fmin(i1, w);
    int cj0 = (int)fmax(j0, 0), cj1 = (int)fmin(j1, h);
    for (j = cj0; j < cj1; j++)
        for (i = ci0; i < ci1; i++)
            sum += px[(size_t)j * (size_t)stride + (size_t)i];
    if (ci1 > ci0 && cj1 > cj0)
        inside = (double)(ci1 - ci0) * (cj1 - cj0);
    sum += 255.0 * ((i1 - i0) * (j1 - j0) - inside);
    return sum / (255.0 * res * res);
}

/* The cost of a label with ink box ink (relative to its origin) at
** origin (ox, oy): ink under the box widened by AUTO_GAP, plus a quarter
** of the ink in the ring out to AUTO_NEAR. */
static double
place_cost(cairo_surface_t *img, double res, const double ink[4], double ox,
           double oy)
{
    double hard[4], near[4], a, b;
    hard[0] = ox + ink[0] - AUTO_GAP;
    hard[1] = oy + ink[1] - AUTO_GAP;
    hard[2] = ox + ink[2] + AUTO_GAP;
    hard[3] = oy + ink[3] + AUTO_GAP;
    near[0] = ox + ink[0] - AUTO_NEAR;
    near[1] = oy + ink[1] - AUTO_NEAR;
    near[2] = ox + ink[2] + AUTO_NEAR;
    near[3] = oy + ink[3] + AUTO_NEAR;
    a = raster_ink(img, res, hard);
    b = raster_ink(img, res, near);
    return a + 0.25 * fmax(0, b - a);
}

/* Draw element i into the raster. */
static cf_status_t
raster_element(cf_figure_t *fig, size_t i, const cf__layout_t *lay,
               cf__dl_t *dl, cairo_t *cr)
{
    cf_status_t st;
    cf__dl_reset(dl);
    st = cf__element_draw(fig, i, lay, dl);
    if (dl->failed && st == CF_STATUS_OK)
        st = cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                         "out of memory placing labels");
    if (st == CF_STATUS_OK)
        cf__dl_play(dl, 0, dl->count, &cf__cairo_backend, cr);
    return st;
}

/* Whether element i is a label placed automatically; its anchor, text
** and chosen place then. */
static bool
is_auto(cf_figure_t *fig, size_t i, double *x, double *y, cf__text_t **t,
        cf_place_t **place, cf_style_t *s)
{
    cf__element_t *e = fig->els[i];
    if (e->kind->auto_label == NULL)
        return false;
    cf__style_resolve(&fig->theme, e->role, &e->style, s);
    if (s->place != CF_PLACE_AUTO)
        return false;
    return e->kind->auto_label(e, x, y, t, place);
}

/* The cheapest place of a label with ink box ink at page point (px, py). */
static cf_place_t
cheapest(cairo_surface_t *img, double res, const cf_label_t *lab,
         const cf_style_t *s, double px, double py)
{
    static const cf_place_t order[] = {
        CF_PLACE_NE, CF_PLACE_NW, CF_PLACE_SE, CF_PLACE_SW,
        CF_PLACE_N, CF_PLACE_S, CF_PLACE_E, CF_PLACE_W
    };
    double ink[4], best = INFINITY;
    cf_place_t place = order[0];
    size_t k;
    cf__label_ink(lab, ink);
    cairo_surface_flush(img);
    for (k = 0; k < sizeof order / sizeof order[0]; k++) {
        double ox, oy, c;
        cf__label_origin(lab, order[k], s->offset, px, py, &ox, &oy);
        c = place_cost(img, res, ink, ox, oy);
        /* a later place must be clearly better (0.05 bp^2) */
        if (c < best - 0.05) {
            best = c;
            place = order[k];
        }
    }
    return place;
}

cf_status_t
cf__place_auto_labels(cf_figure_t *fig, const cf__layout_t *lay)
{
    cairo_surface_t *img;
    cairo_t *cr;
    cf__dl_t dl;
    cf_style_t s;
    cf__text_t *t;
    cf_place_t *place;
    double res = AUTO_RES, x, y;
    size_t i;
    bool any = false;
    cf_status_t st = CF_STATUS_OK;

    for (i = 0; i < fig->count && !any; i++)
        any = is_auto(fig, i, &x, &y, &t, &place, &s);
    if (!any)
        return CF_STATUS_OK;
    if (fig->width * fig->height * res * res > AUTO_MAX_PIXELS)
        res = sqrt(AUTO_MAX_PIXELS / (fig->width * fig->height));
    img = cairo_image_surface_create(CAIRO_FORMAT_A8,
                                     (int)ceil(fig->width * res),
                                     (int)ceil(fig->height * res));
    cr = cairo_create(img);
    if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) {
        cairo_destroy(cr);
        cairo_surface_destroy(img);
        return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                           "out of memory placing labels");
    }
    cairo_scale(cr, res, res);
    cf__dl_init(&dl);
    /* fills and hulls left out: labels may sit on a shading */
    for (i = 0; i < fig->count && st == CF_STATUS_OK; i++) {
        if ((fig->els[i]->kind->flags & CF__KIND_SHADING)
            || is_auto(fig, i, &x, &y, &t, &place, &s))
            continue;
        st = raster_element(fig, i, lay, &dl, cr);
    }
    for (i = 0; i < fig->count && st == CF_STATUS_OK; i++) {
        double px, py;
        if (!is_auto(fig, i, &x, &y, &t, &place, &s)
            || !cf__in_window(lay, x, y))
            continue;
        st = cf__text_ensure(fig, t, s.font_size);
        if (st != CF_STATUS_OK)
            break;
        cf__map(lay, x, y, &px, &py);
        *place = cheapest(img, res, t->lab, &s, px, py);
        st = raster_element(fig, i, lay, &dl, cr);
    }
    cf__dl_free(&dl);
    cairo_destroy(cr);
    cairo_surface_destroy(img);
    return st;
}
