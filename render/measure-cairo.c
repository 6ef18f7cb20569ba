/*
** The measuring seam (render/measure.h) drawn by cairo: rasters are A8
** image surfaces the cairo backend paints, ink boxes come from a
** recording surface.
*/
#include <math.h>
#include <string.h>

#include <cairo.h>

#include "backend.h"
#include "measure.h"

int
cf__raster_open(cf__raster_t *r, int w, int h, double res, double ox,
                double oy)
{
    cairo_surface_t *img = cairo_image_surface_create(CAIRO_FORMAT_A8, w, h);
    cairo_t *cr = cairo_create(img);
    memset(r, 0, sizeof *r);
    r->impl = cr;
    cairo_surface_destroy(img);
    if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) {
        cf__raster_close(r);
        return -1;
    }
    cairo_scale(cr, res, res);
    cairo_translate(cr, -ox, -oy);
    r->px = cairo_image_surface_get_data(img);
    r->w = w;
    r->h = h;
    r->stride = cairo_image_surface_get_stride(img);
    r->res = res;
    r->ox = ox;
    r->oy = oy;
    return 0;
}

void
cf__raster_close(cf__raster_t *r)
{
    if (r->impl != NULL)
        cairo_destroy(r->impl);
    memset(r, 0, sizeof *r);
}

void
cf__raster_clear(cf__raster_t *r, const int *b)
{
    int i0 = 0, j0 = 0, i1 = r->w, j1 = r->h, j;
    if (b != NULL) {
        i0 = b[0] > 0 ? b[0] : 0;
        j0 = b[1] > 0 ? b[1] : 0;
        i1 = b[2] < r->w ? b[2] : r->w;
        j1 = b[3] < r->h ? b[3] : r->h;
    }
    if (i1 <= i0)
        return;
    cairo_surface_flush(cairo_get_target(r->impl));
    for (j = j0; j < j1; j++)
        memset(r->px + (size_t)j * (size_t)r->stride + (size_t)i0, 0,
               (size_t)(i1 - i0));
    cairo_surface_mark_dirty(cairo_get_target(r->impl));
}

int
cf__raster_paint(cf__raster_t *r, const cf__dl_t *dl, size_t from,
                 size_t to)
{
    cf__dl_play(dl, from, to, &cf__cairo_backend, r->impl);
    cairo_surface_flush(cairo_get_target(r->impl));
    return cairo_status(r->impl) != CAIRO_STATUS_SUCCESS ? -1 : 0;
}

int
cf__dl_ink(const cf__dl_t *dl, size_t from, size_t to, double ink[4])
{
    return cf__cairo_ink(dl, from, to, ink) != 0 ? -1 : 0;
}
