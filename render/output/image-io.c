/*
** Images as plain pixels read and written through cairo (PNG) and librsvg
** (SVG); see image-io.h.
*/
#include <cairo.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef CF_HAVE_RSVG
#include <librsvg/rsvg.h>
#endif

#include "image-io.h"

cf__image *
cf__image_new(int w, int h)
{
    cf__image *im;
    if (w <= 0 || h <= 0 || (size_t)w > SIZE_MAX / 4 / (size_t)h)
        return NULL;
    im = malloc(sizeof *im);
    if (im == NULL)
        return NULL;
    im->width = w;
    im->height = h;
    im->stride = 4 * w;
    im->data = calloc((size_t)h, (size_t)im->stride);
    if (im->data == NULL) {
        free(im);
        return NULL;
    }
    return im;
}

void
cf__image_destroy(cf__image *im)
{
    if (im != NULL) {
        free(im->data);
        free(im);
    }
}

/* A cairo surface drawing into im's pixels. */
static cairo_surface_t *
surface_of(cf__image *im)
{
    return cairo_image_surface_create_for_data(im->data, CAIRO_FORMAT_ARGB32,
                                               im->width, im->height,
                                               im->stride);
}

/* The pixels of s in ARGB32 (cairo reads a PNG without alpha as RGB24),
** or NULL when memory ran out. */
static cf__image *
copy_of(cairo_surface_t *s)
{
    cf__image *im = cf__image_new(cairo_image_surface_get_width(s),
                                  cairo_image_surface_get_height(s));
    cairo_surface_t *dst;
    cairo_t *cr;
    int ok;
    if (im == NULL)
        return NULL;
    dst = surface_of(im);
    cr = cairo_create(dst);
    cairo_set_source_surface(cr, s, 0, 0);
    cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
    cairo_paint(cr);
    ok = cairo_status(cr) == CAIRO_STATUS_SUCCESS;
    cairo_destroy(cr);
    cairo_surface_flush(dst);
    ok = ok && cairo_surface_status(dst) == CAIRO_STATUS_SUCCESS;
    cairo_surface_destroy(dst);
    if (!ok) {
        cf__image_destroy(im);
        return NULL;
    }
    return im;
}

cf__image *
cf__image_read_png(const char *path, char *err, size_t errsize)
{
    cairo_surface_t *s = cairo_image_surface_create_from_png(path);
    cairo_status_t st = cairo_surface_status(s);
    cf__image *im;
    if (st != CAIRO_STATUS_SUCCESS) {
        /* cairo reports every file libpng refuses as out of memory */
        snprintf(err, errsize, "%s: not a readable PNG file (%s)", path,
                 st == CAIRO_STATUS_NO_MEMORY
                     ? "libpng refused it: a bad checksum, a chunk cut "
                       "short or missing, or data that does not match its "
                       "header; or out of memory"
                     : cairo_status_to_string(st));
        cairo_surface_destroy(s);
        return NULL;
    }
    im = copy_of(s);
    cairo_surface_destroy(s);
    if (im == NULL)
        snprintf(err, errsize, "%s: out of memory", path);
    return im;
}

cf__image *
cf__image_read_svg(const char *path, double dpi, int max_side, char *err,
                   size_t errsize)
{
#ifdef CF_HAVE_RSVG
    GError *gerr = NULL;
    RsvgHandle *hd = rsvg_handle_new_from_file(path, &gerr);
    cf__image *im;
    cairo_surface_t *s;
    cairo_t *cr;
    gdouble sw, sh;
    double wpx, hpx;
    RsvgRectangle vp;
    gboolean ok;
    if (hd == NULL) {
        snprintf(err, errsize, "%s: librsvg cannot read the SVG: %s", path,
                 gerr != NULL ? gerr->message : "unknown error");
        if (gerr != NULL)
            g_error_free(gerr);
        return NULL;
    }
    rsvg_handle_set_dpi(hd, dpi);
    if (!rsvg_handle_get_intrinsic_size_in_pixels(hd, &sw, &sh) ||
        !(sw > 0 && sh > 0)) {
        snprintf(err, errsize, "%s: the SVG has no width and height in "
                 "absolute units, so it has no size at %g dpi", path, dpi);
        g_object_unref(hd);
        return NULL;
    }
    wpx = ceil(sw - 1e-6);
    hpx = ceil(sh - 1e-6);
    if (wpx > max_side || hpx > max_side) {
        snprintf(err, errsize, "%s: %.0fx%.0f pixels at %g dpi is too large "
                 "(at most %d a side); lower the dpi", path, wpx, hpx, dpi,
                 max_side);
        g_object_unref(hd);
        return NULL;
    }
    im = cf__image_new((int)wpx, (int)hpx);
    if (im == NULL) {
        snprintf(err, errsize, "%s: out of memory", path);
        g_object_unref(hd);
        return NULL;
    }
    s = surface_of(im);
    cr = cairo_create(s);
    vp.x = 0;
    vp.y = 0;
    vp.width = sw;
    vp.height = sh;
    ok = rsvg_handle_render_document(hd, cr, &vp, &gerr);
    cairo_destroy(cr);
    cairo_surface_flush(s);
    cairo_surface_destroy(s);
    g_object_unref(hd);
    if (!ok) {
        snprintf(err, errsize, "%s: librsvg cannot render the SVG: %s", path,
                 gerr != NULL ? gerr->message : "unknown error");
        if (gerr != NULL)
            g_error_free(gerr);
        cf__image_destroy(im);
        return NULL;
    }
    return im;
#else
    (void)dpi;
    (void)max_side;
    snprintf(err, errsize, "%s: an SVG, but this curvefig was built without "
             "librsvg and cannot rasterise SVG; compare PNGs", path);
    return NULL;
#endif
}

static cairo_status_t
write_stream(void *closure, const unsigned char *data, unsigned int length)
{
    return fwrite(data, 1, length, (FILE *)closure) == length
               ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

int
cf__image_write_png(const cf__image *im, FILE *f)
{
    /* cairo only reads the pixels here, though its signature cannot say so */
    cairo_surface_t *s = surface_of((cf__image *)im);
    cairo_status_t st = cairo_surface_write_to_png_stream(s, write_stream, f);
    cairo_surface_destroy(s);
    return st == CAIRO_STATUS_SUCCESS ? 0 : -1;
}
