/*
** The rasters of the label placement (render/layout/place-raster.h).
*/
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "place-raster.h"

#define AUTO_RES 2.0          /* raster pixels per bp */
#define AUTO_MAX_PIXELS 4e6   /* larger pages get a coarser raster */

void
cf__place_ink_pixels(const cf__raster_t *img, double res,
                     const double b[4], int px[4], double whole[4])
{
    whole[0] = floor(b[0] * res);
    whole[2] = ceil(b[2] * res);
    whole[1] = floor(b[1] * res);
    whole[3] = ceil(b[3] * res);
    px[0] = cf__pixel_within(whole[0], 0, img->w);
    px[2] = cf__pixel_within(whole[2], 0, img->w);
    px[1] = cf__pixel_within(whole[1], 0, img->h);
    px[3] = cf__pixel_within(whole[3], 0, img->h);
}

int
cf__place_sums(cf__place_sums_t *s, const cf__raster_t *img, const int b[4])
{
    int i0 = b[0] > 0 ? b[0] : 0, j0 = b[1] > 0 ? b[1] : 0;
    int i1 = b[2] < img->w ? b[2] : img->w;
    int j1 = b[3] < img->h ? b[3] : img->h, i, j;
    size_t w, n;
    s->b[0] = s->b[1] = s->b[2] = s->b[3] = 0;
    if (i1 <= i0 || j1 <= j0)
        return 0;
    w = (size_t)(i1 - i0) + 1;
    n = w * ((size_t)(j1 - j0) + 1);
    if (n > s->cap) {
        uint32_t *p = cf_realloc_array(s->at, n, sizeof *p);
        if (p == NULL)
            return -1;
        s->at = p;
        s->cap = n;
    }
    memset(s->at, 0, w * sizeof *s->at);
    for (j = j0; j < j1; j++) {
        const unsigned char *row = img->px + (size_t)j * (size_t)img->stride;
        const uint32_t *up = s->at + (size_t)(j - j0) * w;
        uint32_t *to = s->at + (size_t)(j - j0 + 1) * w, left = 0;
        to[0] = 0;
        for (i = i0; i < i1; i++) {
            left += row[i];
            to[i - i0 + 1] = up[i - i0 + 1] + left;
        }
    }
    s->b[0] = i0;
    s->b[1] = j0;
    s->b[2] = i1;
    s->b[3] = j1;
    return 0;
}

double
cf__place_ink(cf__place_raster_t *r, const double b[4])
{
    cf__raster_t *img = &r->img;
    const cf__place_sums_t *s = &r->sums;
    double whole[4], sum = 0, inside = 0, res = r->res;
    int px[4], i, j;
    cf__place_ink_pixels(img, res, b, px, whole);
    if (px[2] > px[0] && px[3] > px[1]) {
        if (px[0] >= s->b[0] && px[2] <= s->b[2] && px[1] >= s->b[1]
            && px[3] <= s->b[3]) {
            size_t w = (size_t)(s->b[2] - s->b[0]) + 1;
            size_t a0 = (size_t)(px[0] - s->b[0]);
            size_t a1 = (size_t)(px[2] - s->b[0]);
            const uint32_t *top = s->at + (size_t)(px[1] - s->b[1]) * w;
            const uint32_t *bot = s->at + (size_t)(px[3] - s->b[1]) * w;
            sum = (double)(bot[a1] - bot[a0] - top[a1] + top[a0]);
        } else {
            /* (a box beyond the sums: an animation's hint farther out) */
            cf__raster_ready(img, px[1], px[3]);
            for (j = px[1]; j < px[3]; j++)
                for (i = px[0]; i < px[2]; i++)
                    sum += img->px[(size_t)j * (size_t)img->stride
                                   + (size_t)i];
        }
        inside = (double)(px[2] - px[0]) * (px[3] - px[1]);
    }
    sum += 255.0 * ((whole[2] - whole[0]) * (whole[3] - whole[1]) - inside);
    return sum / (255.0 * res * res);
}

long
cf__place_common(const cf__raster_t *one, const unsigned char *b,
                 const int *px)
{
    const unsigned char *a = one->px;
    int w = one->w, h = one->h, stride = one->stride, i, j, i0 = 0, j0 = 0;
    long n = 0;
    if (px != NULL) {
        i0 = px[0] > 0 ? px[0] : 0;
        j0 = px[1] > 0 ? px[1] : 0;
        w = px[2] < w ? px[2] : w;
        h = px[3] < h ? px[3] : h;
    }
    for (j = j0; j < h; j++)
        for (i = i0; i < w; i++) {
            size_t at = (size_t)j * (size_t)stride + (size_t)i;
            n += a[at] > CF__PLACE_HIT && b[at] > CF__PLACE_HIT;
        }
    return n;
}

bool
cf__place_add_apart(cf__place_raster_t *r, const int px[4])
{
    int i0 = px[0] > 0 ? px[0] : 0, j0 = px[1] > 0 ? px[1] : 0;
    int i1 = px[2] < r->img.w ? px[2] : r->img.w;
    int j1 = px[3] < r->img.h ? px[3] : r->img.h, i, j;
    int *d = r->img.dirty;
    if (i1 <= i0 || j1 <= j0)
        return true;
    for (j = j0; j < j1; j++) {
        size_t at = (size_t)j * (size_t)r->img.stride;
        for (i = i0; i < i1; i++)
            if (r->one.px[at + (size_t)i] != 0
                && r->img.px[at + (size_t)i] != 0)
                return false;
    }
    for (j = j0; j < j1; j++) {
        size_t at = (size_t)j * (size_t)r->img.stride;
        for (i = i0; i < i1; i++)
            r->img.px[at + (size_t)i] |= r->one.px[at + (size_t)i];
    }
    if (d[2] <= d[0] || d[3] <= d[1]) {
        d[0] = i0;
        d[1] = j0;
        d[2] = i1;
        d[3] = j1;
    } else {
        d[0] = i0 < d[0] ? i0 : d[0];
        d[1] = j0 < d[1] ? j0 : d[1];
        d[2] = i1 > d[2] ? i1 : d[2];
        d[3] = j1 > d[3] ? j1 : d[3];
    }
    return true;
}

void
cf__place_raster_open(cf_figure_t *fig, cf__place_raster_t *r)
{
    int w, h;
    memset(r, 0, sizeof *r);
    r->res = AUTO_RES;
    if (fig->width * fig->height * r->res * r->res > AUTO_MAX_PIXELS)
        r->res = sqrt(AUTO_MAX_PIXELS / (fig->width * fig->height));
    w = (int)fmax(1, ceil(fig->width * r->res));
    h = (int)fmax(1, ceil(fig->height * r->res));
    cf__dl_init(&r->dl);
    r->img.w = r->one.w = w;
    r->img.h = r->one.h = h;
    r->img.stride = r->one.stride = w;
    r->img.res = r->one.res = r->res;
}

cf_status_t
cf__place_raster_memory(cf_figure_t *fig, cf__place_raster_t *r)
{
    size_t n = (size_t)r->img.w * (size_t)r->img.h;
    if (fig->place_px_size < 3 * n || fig->place_w != r->img.w
        || fig->place_h != r->img.h) {
        /* the memory as it comes: its rows are emptied where used */
        unsigned char *px = fig->place_px_size < 3 * n
                                ? cf_alloc_array(n, 3) : fig->place_px;
        unsigned char *ready = cf_calloc((size_t)r->img.h, 1);
        if (px == NULL || ready == NULL) {
            if (px != fig->place_px)
                cf_free(px);
            cf_free(ready);
            return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                               "out of memory placing labels");
        }
        if (px != fig->place_px) {
            cf_free(fig->place_px);
            fig->place_px = px;
            fig->place_px_size = 3 * n;
        }
        cf_free(fig->place_ready);
        fig->place_ready = ready;
        fig->place_w = r->img.w;
        fig->place_h = r->img.h;
    }
    r->img.px = fig->place_px;
    r->img.ready = fig->place_ready;
    r->one.px = fig->place_px + n;
    r->mask = fig->place_px + 2 * n;
    return CF_STATUS_OK;
}

void
cf__place_release(cf_figure_t *fig)
{
    cf_free(fig->place_px);
    cf_free(fig->place_ready);
    fig->place_px = fig->place_ready = NULL;
    fig->place_px_size = 0;
    fig->place_w = fig->place_h = 0;
}

void
cf__place_raster_close(cf_figure_t *fig, cf__place_raster_t *r)
{
    (void)fig;
    /* the rows made ready stay empty: everything painted into them is
    ** within the dirty box */
    if (r->img.px != NULL)
        cf__raster_clear(&r->img, r->img.dirty);
    cf__dl_free(&r->dl);
    cf_free(r->sums.at);
    cf_free(r->rows);
}

void
cf__place_mark_rows(cf__place_raster_t *r, const double b[4])
{
    int j0 = (int)fmax(0, fmin(r->img.h, floor(b[1] * r->res) - 1));
    int j1 = (int)fmax(0, fmin(r->img.h, ceil(b[3] * r->res) + 1));
    if (j1 > j0)
        memset(r->rows + j0, 1, (size_t)(j1 - j0));
}
