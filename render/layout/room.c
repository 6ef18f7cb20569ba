/*
** Free room beside the drawing: where a box of a given size goes without
** covering ink.  Boxes (a legend, a zoom inset) are placed relative to
** the ink of the drawing they belong to, never to the page: the page of
** a figure cropped to its ink (page = "ink") is only known once they are
** part of that ink.  What is drawn so far is painted into a coarse
** raster of the drawing's ink box (render/backends/measure.h); each candidate
** place (a corner or side inside that box) counts the raster pixels it
** covers.  With none clear, the box goes into a band outside the ink box,
** at the right or below, whichever leaves the drawing the larger scale
** on the figure's width x height; the choice is kept for the rest of the
** layout (*band), so that laying the figure out again at a slightly
** different scale cannot move the box in and out of the drawing.
*/
#include <math.h>
#include <stdint.h>

#include "layout-private.h"
#include "measure.h"

#define ROOM_RES 2.0          /* raster pixels per bp */
#define ROOM_MAX_PIXELS 4e6   /* larger drawings get a coarser raster */
#define ROOM_CLEAR 3.0        /* bp around the box that must be clear too */
#define ROOM_FAINT 8          /* pixel values up to this are not ink */
#define ROOM_BAND_GAP 6.0     /* bp between the drawing's ink and a band */

/* The pixels of raster img under page box b (x0 y0 x1 y1, bp) that
** carry ink. */
static size_t
inked_pixels(const cf__raster_t *img, const double b[4])
{
    const unsigned char *px = img->px;
    int w = img->w, h = img->h, stride = img->stride;
    double res = img->res;
    int i0 = cf__pixel_within(floor((b[0] - img->ox) * res), 0, w);
    int i1 = cf__pixel_within(ceil((b[2] - img->ox) * res), 0, w);
    int j0 = cf__pixel_within(floor((b[1] - img->oy) * res), 0, h);
    int j1 = cf__pixel_within(ceil((b[3] - img->oy) * res), 0, h);
    size_t n = 0;
    int i, j;
    for (j = j0; j < j1; j++)
        for (i = i0; i < i1; i++)
            n += px[(size_t)j * (size_t)stride + (size_t)i] > ROOM_FAINT;
    return n;
}

void
cf__room_box_at(const double a[4], double w, double h, cf_place_t place,
                double gap, double at[2])
{
    double l = a[0] + gap, r = a[2] - gap - w;
    double t = a[1] + gap, b = a[3] - gap - h;
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

/* The band a box w x h goes to beside drawing ink a: the one that leaves
** the drawing the larger scale on the figure's page inside its margin. */
static cf__room_band_t
choose_band(const cf_figure_t *fig, const double a[4], double w, double h)
{
    double pw = fig->width - 2 * fig->margin;
    double ph = fig->height - 2 * fig->margin;
    double aw = fmax(a[2] - a[0], 1e-9), ah = fmax(a[3] - a[1], 1e-9);
    double right = fmin((pw - ROOM_BAND_GAP - w) / aw,
                        (h > ph ? 0 : ph) / ah);
    double below = fmin((w > pw ? 0 : pw) / aw,
                        (ph - ROOM_BAND_GAP - h) / ah);
    return right >= below ? CF__ROOM_RIGHT : CF__ROOM_BELOW;
}

/* The box in its band beside drawing ink a: at the right, level with the
** ink's top; below, centred under it. */
static void
band_at(const double a[4], double w, cf__room_band_t band, double at[2])
{
    if (band == CF__ROOM_RIGHT) {
        at[0] = a[2] + ROOM_BAND_GAP;
        at[1] = a[1];
    } else {
        at[0] = 0.5 * (a[0] + a[2] - w);
        at[1] = a[3] + ROOM_BAND_GAP;
    }
}

/* The ink box of ops [from, dl->count) into a; without ink, the figure's
** page box of layout lay. */
static int
drawing_ink(const cf_figure_t *fig, const cf__layout_t *lay,
            const cf__dl_t *dl, size_t from, double a[4])
{
    if (cf__dl_ink(dl, from, dl->count, a) != 0)
        return -1;
    if (!(a[2] > a[0] && a[3] > a[1])) {
        a[0] = lay->px;
        a[1] = lay->py;
        a[2] = lay->px + fig->width;
        a[3] = lay->py + fig->height;
    }
    return 0;
}

/* The fewest raster pixels of ink covered by a w x h box at one of the
** corners and sides of drawing ink a, gap inside it: its top left into
** at; SIZE_MAX when the box does not fit inside. */
static size_t
least_covered(cf_figure_t *fig, const cf__dl_t *dl, const double a[4],
              double w, double h, double gap, double at[2], cf_status_t *st)
{
    static const cf_place_t order[] = {
        CF_PLACE_NE, CF_PLACE_NW, CF_PLACE_SE, CF_PLACE_SW,
        CF_PLACE_N, CF_PLACE_S, CF_PLACE_E, CF_PLACE_W
    };
    double aw = a[2] - a[0], ah = a[3] - a[1], res = ROOM_RES;
    const int side_max = (int)ROOM_MAX_PIXELS;
    cf__raster_t img;
    size_t k, best = SIZE_MAX;
    *st = CF_STATUS_OK;
    if (w + 2 * gap > aw || h + 2 * gap > ah)
        return SIZE_MAX;
    aw += 2 * ROOM_CLEAR;
    ah += 2 * ROOM_CLEAR;
    if (aw * ah * res * res > ROOM_MAX_PIXELS)
        res = sqrt(ROOM_MAX_PIXELS / (aw * ah));
    /* each side within the budget (and an int): ink 1e300 bp wide and
    ** 20 bp tall, scaled to the budget of pixels, is 1e153 pixels wide */
    if (cf__raster_open(&img, cf__pixel_within(ceil(aw * res), 1, side_max),
                        cf__pixel_within(ceil(ah * res), 1, side_max), res,
                        a[0] - ROOM_CLEAR, a[1] - ROOM_CLEAR) != 0
        || cf__raster_paint(&img, dl, 0, dl->count) != 0) {
        cf__raster_close(&img);
        *st = cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                          "out of memory finding room beside the drawing");
        return SIZE_MAX;
    }
    for (k = 0; k < sizeof order / sizeof order[0] && best != 0; k++) {
        double c[2], b[4];
        size_t n;
        cf__room_box_at(a, w, h, order[k], gap, c);
        b[0] = c[0] - ROOM_CLEAR;
        b[1] = c[1] - ROOM_CLEAR;
        b[2] = c[0] + w + ROOM_CLEAR;
        b[3] = c[1] + h + ROOM_CLEAR;
        n = inked_pixels(&img, b);
        if (n < best) {
            best = n;
            at[0] = c[0];
            at[1] = c[1];
        }
    }
    cf__raster_close(&img);
    return best;
}

cf_status_t
cf__room_find(cf_figure_t *fig, const cf__layout_t *lay, const cf__dl_t *dl,
              size_t from, double w, double h, cf_place_t place, double gap,
              cf__room_band_t *band, double at[2])
{
    double a[4];
    cf_status_t st;
    size_t n;
    if (drawing_ink(fig, lay, dl, from, a) != 0)
        return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                           "out of memory measuring the drawing's ink");
    if (place != CF_PLACE_AUTO) {
        cf__room_box_at(a, w, h, place, gap, at);
        return CF_STATUS_OK;
    }
    if (*band == CF__ROOM_INSIDE || *band == CF__ROOM_UNDECIDED) {
        n = least_covered(fig, dl, a, w, h, gap, at, &st);
        if (st != CF_STATUS_OK)
            return st;
        if (n == 0) {
            *band = CF__ROOM_INSIDE;
            return CF_STATUS_OK;
        }
        *band = choose_band(fig, a, w, h);
    }
    band_at(a, w, *band, at);
    return CF_STATUS_OK;
}

void
cf__room_reset(cf_figure_t *fig)
{
    size_t k;
    fig->legend_band = CF__ROOM_UNDECIDED;
    for (k = 0; k < fig->ninsets; k++)
        fig->inset_band[k] = CF__ROOM_UNDECIDED;
    cf_free(fig->inset_cache);
    fig->inset_cache = NULL;
}
