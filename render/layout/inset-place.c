/*
** Where a zoom inset goes, and which corners its two connectors join.
**
** The drawing is painted into a coarse raster (render/backends/measure.h):
** every element but the labels placed automatically (they are placed
** after the insets, around them: render/layout/place.c), and the insets
** placed before this one.  A connector joins a corner of the region's
** frame to the same corner of the inset's frame (the inset is the region
** magnified, so the four such lines meet in one point and never cross
** one another); one that would run through the region's frame is not
** drawn, one that runs into the inset's box is seen up to it.
** A connector's cost is the length (bp) of it that runs within IP_NEAR
** of ink, its ends aside (it starts on the region's frame); an inset's,
** that of its two cheapest connectors.
**
** A candidate box is a corner or side inside the drawing's ink box that
** covers no ink, or a place in a band beside the ink box (at its right,
** below, at its left, above it; level with the region, or at either end
** of the band).  An inset placed automatically takes the cheapest clear
** place inside the ink box when its connectors cross nothing or no band
** does better; else the cheapest band (on a tie, the one that leaves the
** drawing the larger scale on the figure's width x height).  Whether it
** went inside or into which band is kept for the rest of the layout
** (fig->inset_band), as for the legend (render/layout/room.c).
**
** Everything is computed on the layout moved to the page's origin and
** moved back: the places do not depend on where a page cropped to its
** ink puts the figure, and the labels, placed on that moved layout too,
** see the same insets.
*/
#include <math.h>
#include <string.h>

#include "layout-private.h"
#include "measure.h"

#define IP_RES 2.0          /* raster pixels per bp */
#define IP_MAX_PIXELS 4e6   /* larger drawings get a coarser raster */
#define IP_EDGE 4.0         /* bp inside the edge of the drawing's ink */
#define IP_CLEAR 3.0        /* bp around a box that must be clear too */
#define IP_GAP 6.0          /* bp between the drawing's ink and a band */
#define IP_FAINT 8          /* pixel values up to this are not ink */
#define IP_NEAR 1.5         /* bp: ink this near a connector is crossed */
#define IP_END 2.0          /* bp at either end of a connector not counted */
#define IP_BIAS 0.25        /* bp: a connector off the usual pair costs more
                               by this, so that ties keep the usual pair */
#define IP_COVERED 1e6      /* the cost of a box that covers ink */
#define IP_LINE 0.5         /* bp: frames and connectors */
#define IP_GRID 6.0         /* bp between the places tried inside the ink
                               box beyond its corners and sides */
#define IP_GRID_GAIN 2.0    /* bp of crossing such a place must save */

typedef struct ip_search {
    cf__raster_t img;   /* the drawing's ink and the insets placed */
    size_t *sum;        /* (w + 1) x (h + 1): the ink pixels above and left
                           of each pixel corner (a summed-area table) */
    double a[4];        /* the drawing's ink box, x0 y0 x1 y1 */
    cf__dl_t dl;        /* scratch */
} ip_search_t;

typedef struct ip_cand {
    double at[2];       /* the box's top left */
    double cost;        /* connectors' crossings, plus IP_COVERED if the
                           box covers ink */
    double key;         /* the cost compared: a place off the corners and
                           sides costs IP_GRID_GAIN more */
    int pair[2];
    double scale;       /* of the drawing beside a band (0 inside) */
    cf__room_band_t band;
} ip_cand_t;

/* ---- the raster --------------------------------------------------------- */

/* The summed-area table of the raster's ink pixels; -1 out of memory. */
static int
sum_ink(ip_search_t *s)
{
    const cf__raster_t *img = &s->img;
    size_t w = (size_t)img->w + 1, i, j;
    cf_free(s->sum);
    s->sum = cf_alloc_array(w * ((size_t)img->h + 1), sizeof *s->sum);
    if (s->sum == NULL)
        return -1;
    for (i = 0; i < w; i++)
        s->sum[i] = 0;
    for (j = 1; j <= (size_t)img->h; j++) {
        const unsigned char *row = img->px + (j - 1) * (size_t)img->stride;
        size_t run = 0;
        s->sum[j * w] = 0;
        for (i = 1; i < w; i++) {
            run += row[i - 1] > IP_FAINT;
            s->sum[j * w + i] = s->sum[(j - 1) * w + i] + run;
        }
    }
    return 0;
}

/* The ink pixels under page box b (x0 y0 x1 y1); off the raster there is
** none. */
static size_t
covered(const ip_search_t *s, const double b[4])
{
    const cf__raster_t *img = &s->img;
    size_t w = (size_t)img->w + 1;
    double i0 = floor((b[0] - img->ox) * img->res);
    double i1 = ceil((b[2] - img->ox) * img->res);
    double j0 = floor((b[1] - img->oy) * img->res);
    double j1 = ceil((b[3] - img->oy) * img->res);
    size_t a0 = (size_t)fmin(fmax(i0, 0), img->w);
    size_t a1 = (size_t)fmin(fmax(i1, 0), img->w);
    size_t c0 = (size_t)fmin(fmax(j0, 0), img->h);
    size_t c1 = (size_t)fmin(fmax(j1, 0), img->h);
    if (a1 <= a0 || c1 <= c0)
        return 0;
    return s->sum[c1 * w + a1] - s->sum[c0 * w + a1] - s->sum[c1 * w + a0]
         + s->sum[c0 * w + a0];
}

/* Whether there is ink within IP_NEAR of page point (x, y). */
static bool
ink_near(const ip_search_t *s, double x, double y)
{
    double b[4] = { x - IP_NEAR, y - IP_NEAR, x + IP_NEAR, y + IP_NEAR };
    return covered(s, b) > 0;
}

/* bp of segment p q within IP_NEAR of ink, IP_END at either end aside. */
static double
crossed(const ip_search_t *s, const double p[2], const double q[2])
{
    double len = hypot(q[0] - p[0], q[1] - p[1]);
    double step = 0.5 / s->img.res, d, sum = 0;
    for (d = IP_END; d < len - IP_END; d += step) {
        double t = d / len;
        if (ink_near(s, p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
            sum += step;
    }
    return sum;
}

/* ---- connectors --------------------------------------------------------- */

/* Where segment p q enters the inside of box b (x0 y0 x1 y1, in by
** `in` bp from its edge), as a fraction of its length from p (Liang and
** Barsky's clipping); 2 when it does not. */
static double
entry(const double b[4], double in, const double p[2], const double q[2])
{
    double t0 = 0, t1 = 1;
    int k;
    for (k = 0; k < 2; k++) {
        double lo = b[k] + in, hi = b[k + 2] - in, d = q[k] - p[k];
        if (fabs(d) < 1e-12) {
            if (p[k] <= lo || p[k] >= hi)
                return 2;
        } else {
            double ta = (lo - p[k]) / d, tb = (hi - p[k]) / d;
            t0 = fmax(t0, fmin(ta, tb));
            t1 = fmin(t1, fmax(ta, tb));
        }
    }
    return t0 < t1 ? t0 : 2;
}

/* Corner c (0 top left, 1 top right, 2 bottom right, 3 bottom left) of
** box b. */
static void
corner(const double b[4], int c, double p[2])
{
    p[0] = (c == 1 || c == 2) ? b[2] : b[0];
    p[1] = c >= 2 ? b[3] : b[1];
}

/* The usual pair: the corners on the sides facing each other. */
static void
usual_pair(const double rb[4], const double ib[4], int pair[2])
{
    bool left = ib[2] <= rb[0], right = ib[0] >= rb[2];
    bool above = ib[3] <= rb[1], below = ib[1] >= rb[3];
    int a, b;
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
    pair[0] = a;
    pair[1] = b;
}

/* The two cheapest connectors between region box rb and inset box ib
** (s NULL: the usual pair) into pair; their cost.  A connector may not
** run through the region's frame; one that runs into the inset's box is
** seen up to the box (drawn over it), and costs IP_BIAS more; the two
** run on either side of the line between the boxes' centres (they
** frame the view from the region to the inset). */
static double
connect(const ip_search_t *s, const double rb[4], const double ib[4],
        int pair[2])
{
    double cost[4], biased[4], side[4], best = INFINITY;
    double cx = 0.5 * (rb[0] + rb[2]), cy = 0.5 * (rb[1] + rb[3]);
    double dx = 0.5 * (ib[0] + ib[2]) - cx, dy = 0.5 * (ib[1] + ib[3]) - cy;
    bool ok[4];
    int usual[2], c, d;
    usual_pair(rb, ib, usual);
    pair[0] = usual[0];
    pair[1] = usual[1];
    for (c = 0; c < 4; c++) {
        double p[2], q[2], t;
        corner(rb, c, p);
        corner(ib, c, q);
        ok[c] = entry(rb, 0.25, p, q) > 1;
        t = entry(ib, 0, p, q);
        biased[c] = c == usual[0] || c == usual[1] ? 0 : IP_BIAS;
        if (t <= 1) {
            q[0] = p[0] + t * (q[0] - p[0]);
            q[1] = p[1] + t * (q[1] - p[1]);
            biased[c] += IP_BIAS;
        }
        side[c] = dx * (0.5 * (p[1] + q[1]) - cy)
                - dy * (0.5 * (p[0] + q[0]) - cx);
        cost[c] = s != NULL ? crossed(s, p, q) : 0;
        biased[c] += cost[c];
    }
    if (s == NULL)
        return 0;
    for (c = 0; c < 4; c++)
        for (d = c + 1; d < 4; d++)
            if (ok[c] && ok[d] && side[c] * side[d] < 0
                && biased[c] + biased[d] < best) {
                best = biased[c] + biased[d];
                pair[0] = c;
                pair[1] = d;
            }
    return cost[pair[0]] + cost[pair[1]];
}

/* ---- candidates --------------------------------------------------------- */

/* The scale left to the drawing of ink box a on the figure's page inside
** its margin with a w x h box in band `band` beside it. */
static double
band_scale(const cf_figure_t *fig, const double a[4], double w, double h,
           cf__room_band_t band)
{
    double pw = fig->width - 2 * fig->margin;
    double ph = fig->height - 2 * fig->margin;
    double aw = fmax(a[2] - a[0], 1e-9), ah = fmax(a[3] - a[1], 1e-9);
    if (band == CF__ROOM_RIGHT || band == CF__ROOM_LEFT)
        return fmin((pw - IP_GAP - w) / aw, (h > ph ? 0 : ph) / ah);
    return fmin((w > pw ? 0 : pw) / aw, (ph - IP_GAP - h) / ah);
}

/* The places of a w x h box in band `band` beside ink box a: level with
** region box rb (its centre's), at the band's start, at its end. */
static void
band_places(const double a[4], const double rb[4], double w, double h,
            cf__room_band_t band, double at[3][2])
{
    bool side = band == CF__ROOM_RIGHT || band == CF__ROOM_LEFT;
    double lo = side ? a[1] : a[0];
    double hi = fmax(lo, side ? a[3] - h : a[2] - w);
    double mid = side ? 0.5 * (rb[1] + rb[3] - h) : 0.5 * (rb[0] + rb[2] - w);
    double fixed = band == CF__ROOM_RIGHT  ? a[2] + IP_GAP
                 : band == CF__ROOM_LEFT   ? a[0] - IP_GAP - w
                 : band == CF__ROOM_BELOW  ? a[3] + IP_GAP
                                           : a[1] - IP_GAP - h;
    double along[3];
    int k;
    along[0] = fmin(hi, fmax(lo, mid));
    along[1] = lo;
    along[2] = hi;
    for (k = 0; k < 3; k++) {
        at[k][0] = side ? fixed : along[k];
        at[k][1] = side ? along[k] : fixed;
    }
}

/* Candidate c (its at and band set) evaluated for region box rb and a
** w x h box; extra added to its key. */
static void
evaluate(const ip_search_t *s, const double rb[4], double w, double h,
         double extra, ip_cand_t *c)
{
    double ib[4] = { c->at[0], c->at[1], c->at[0] + w, c->at[1] + h };
    double clear[4] = { ib[0] - IP_CLEAR, ib[1] - IP_CLEAR,
                        ib[2] + IP_CLEAR, ib[3] + IP_CLEAR };
    if (covered(s, clear) > 0) {
        c->cost = IP_COVERED;
        c->pair[0] = 0;
        c->pair[1] = 2;
    } else {
        c->cost = connect(s, rb, ib, c->pair);
    }
    c->key = c->cost + extra;
}

/* Whether candidate c is better than b (none yet: b->cost < 0). */
static bool
better(const ip_cand_t *c, const ip_cand_t *b)
{
    if (b->cost < 0)
        return true;
    if (c->key < b->key - 1e-9)
        return true;
    return c->key <= b->key + 1e-9 && c->scale > b->scale + 1e-12;
}

/* The best place in band `band` (or, with band INSIDE, at a corner or
** side inside the ink box) into *best. */
static void
search(const cf_figure_t *fig, const ip_search_t *s, const double rb[4],
       double w, double h, cf__room_band_t band, ip_cand_t *best)
{
    static const cf_place_t order[] = {
        CF_PLACE_NE, CF_PLACE_NW, CF_PLACE_SE, CF_PLACE_SW,
        CF_PLACE_N, CF_PLACE_S, CF_PLACE_E, CF_PLACE_W
    };
    ip_cand_t c;
    size_t k;
    c.band = band;
    if (band == CF__ROOM_INSIDE) {
        if (w + 2 * IP_EDGE > s->a[2] - s->a[0]
            || h + 2 * IP_EDGE > s->a[3] - s->a[1])
            return;
        double x, y, x0 = s->a[0] + IP_EDGE, y0 = s->a[1] + IP_EDGE;
        double x1 = s->a[2] - IP_EDGE - w, y1 = s->a[3] - IP_EDGE - h;
        c.scale = 0;
        for (k = 0; k < sizeof order / sizeof order[0]; k++) {
            cf__room_box_at(s->a, w, h, order[k], IP_EDGE, c.at);
            evaluate(s, rb, w, h, 0, &c);
            if (better(&c, best))
                *best = c;
        }
        /* a place off the corners and sides must save IP_GRID_GAIN */
        if (best->cost >= 0 && best->key < IP_GRID_GAIN)
            return;
        for (y = y0; y <= y1; y += IP_GRID)
            for (x = x0; x <= x1; x += IP_GRID) {
                c.at[0] = x;
                c.at[1] = y;
                evaluate(s, rb, w, h, IP_GRID_GAIN, &c);
                if (better(&c, best))
                    *best = c;
            }
    } else {
        double at[3][2];
        band_places(s->a, rb, w, h, band, at);
        c.scale = band_scale(fig, s->a, w, h, band);
        for (k = 0; k < 3; k++) {
            c.at[0] = at[k][0];
            c.at[1] = at[k][1];
            evaluate(s, rb, w, h, 0, &c);
            if (better(&c, best))
                *best = c;
        }
    }
}

/* The place of an inset placed automatically: inside the ink box if a
** clear place there has connectors crossing nothing or no band does
** better, else the best band; *band decides once per layout. */
static void
place_auto(const cf_figure_t *fig, const ip_search_t *s, const double rb[4],
           double w, double h, cf__room_band_t *band, ip_cand_t *best)
{
    static const cf__room_band_t bands[] = {
        CF__ROOM_RIGHT, CF__ROOM_BELOW, CF__ROOM_LEFT, CF__ROOM_ABOVE
    };
    ip_cand_t in, out;
    size_t k;
    in.cost = out.cost = -1;
    if (*band == CF__ROOM_UNDECIDED || *band == CF__ROOM_INSIDE)
        search(fig, s, rb, w, h, CF__ROOM_INSIDE, &in);
    if (in.cost >= 0 && in.cost < IP_COVERED
        && (*band == CF__ROOM_INSIDE || in.cost <= 1e-9)) {
        *band = CF__ROOM_INSIDE;
        *best = in;
        return;
    }
    for (k = 0; k < sizeof bands / sizeof bands[0]; k++)
        if (*band == bands[k] || *band == CF__ROOM_UNDECIDED
            || *band == CF__ROOM_INSIDE)
            search(fig, s, rb, w, h, bands[k], &out);
    if (in.cost >= 0 && in.cost < IP_COVERED
        && (out.cost < 0 || in.key <= out.key + 1e-9))
        out = in;
    *band = out.band;
    *best = out;
}

/* ---- the insets --------------------------------------------------------- */

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

/* The band a side names for an inset beside the drawing. */
static cf__room_band_t
side_band(cf_place_t p)
{
    return p == CF_PLACE_N ? CF__ROOM_ABOVE
         : p == CF_PLACE_S ? CF__ROOM_BELOW
         : p == CF_PLACE_W ? CF__ROOM_LEFT : CF__ROOM_RIGHT;
}

/* The drawing of layout lay (moved to the origin) less the labels placed
** automatically into s->dl, its ink box into s->a and its raster, wide
** enough for boxes of up to `room` bp beside it. */
static cf_status_t
open_search(cf_figure_t *fig, const cf__layout_t *lay, double room,
            ip_search_t *s)
{
    double w, h, res = IP_RES;
    size_t i;
    memset(s, 0, sizeof *s);
    cf__dl_init(&s->dl);
    for (i = 0; i < fig->count; i++) {
        cf__element_t *e = fig->els[i];
        if (e->kind->auto_label != NULL) {
            cf_style_t st;
            cf__style_resolve(&fig->theme, e->role, &e->style, &st);
            if (st.place == CF_PLACE_AUTO)
                continue;
        }
        if (cf__element_draw(fig, i, lay, &s->dl) != CF_STATUS_OK)
            return fig->err.status;
    }
    if (s->dl.failed || cf__dl_ink(&s->dl, 0, s->dl.count, s->a) != 0)
        return cf__fig_nomem(fig, "placing an inset");
    if (!(s->a[2] > s->a[0] && s->a[3] > s->a[1])) {
        s->a[0] = s->a[1] = 0;
        s->a[2] = fig->width;
        s->a[3] = fig->height;
    }
    room += IP_GAP + IP_CLEAR;
    w = s->a[2] - s->a[0] + 2 * room;
    h = s->a[3] - s->a[1] + 2 * room;
    if (w * h * res * res > IP_MAX_PIXELS)
        res = sqrt(IP_MAX_PIXELS / (w * h));
    if (cf__raster_open(&s->img, (int)ceil(w * res), (int)ceil(h * res),
                        res, s->a[0] - room, s->a[1] - room) != 0
        || cf__raster_paint(&s->img, &s->dl, 0, s->dl.count) != 0
        || sum_ink(s) != 0)
        return cf__fig_nomem(fig, "placing an inset");
    return CF_STATUS_OK;
}

static void
close_search(ip_search_t *s)
{
    cf__dl_free(&s->dl);
    cf__raster_close(&s->img);
    cf_free(s->sum);
}

/* Inset k's place for layout lay (moved to the origin) into g. */
static void
place_one(cf_figure_t *fig, const cf__layout_t *lay, size_t k,
          const ip_search_t *s, cf__inset_geom_t *g)
{
    const cf_inset_t *in = &fig->insets[k];
    double w, h;
    ip_cand_t c;
    g->mag = magnification(fig, lay, in, g->rb);
    w = g->mag * (g->rb[2] - g->rb[0]);
    h = g->mag * (g->rb[3] - g->rb[1]);
    c.cost = -1;
    if (in->has_rect) {
        c.at[0] = in->rect[0];
        c.at[1] = in->rect[1];
    } else if (in->place == CF_PLACE_AUTO) {
        place_auto(fig, s, g->rb, w, h, &fig->inset_band[k], &c);
    } else if (in->beside) {
        search(fig, s, g->rb, w, h, side_band(in->place), &c);
    } else {
        cf__room_box_at(s->a, w, h, in->place, IP_EDGE, c.at);
    }
    g->ib[0] = c.at[0];
    g->ib[1] = c.at[1];
    g->ib[2] = c.at[0] + w;
    g->ib[3] = c.at[1] + h;
    connect(s, g->rb, g->ib, g->pair);
}

cf_status_t
cf__inset_outline(cf_figure_t *fig, const cf__inset_geom_t *g, unsigned what,
                  cf__dl_t *dl)
{
    cf__paint_t line;
    cf_style_t axes;
    int c;
    cf__style_resolve(&fig->theme, CF_ROLE_AXES, NULL, &axes);
    memset(&line, 0, sizeof line);
    line.stroke = true;
    cf__stroke_from_style(&axes, &line.line);
    line.line.width = IP_LINE;
    line.line.dash_count = 0;
    if (what & CF__INSET_LINES) {
        cf__dl_path_begin(dl);
        cf__dl_rect(dl, g->rb[0], g->rb[1], g->rb[2] - g->rb[0],
                    g->rb[3] - g->rb[1]);
        for (c = 0; c < 2; c++) {
            double p[2], q[2];
            corner(g->rb, g->pair[c], p);
            corner(g->ib, g->pair[c], q);
            cf__dl_move(dl, p[0], p[1]);
            cf__dl_line(dl, q[0], q[1]);
        }
        cf__dl_path_paint(dl, &line);
    }
    if (what & (CF__INSET_FRAME | CF__INSET_BOX)) {
        if (what & CF__INSET_BOX) {
            line.fill = true;
            line.fill_color = line.line.color;
            line.fill_opacity = 1;
        }
        cf__dl_path_begin(dl);
        cf__dl_rect(dl, g->ib[0], g->ib[1], g->ib[2] - g->ib[0],
                    g->ib[3] - g->ib[1]);
        cf__dl_path_paint(dl, &line);
    }
    return dl->failed ? cf__fig_nomem(fig, "an inset") : CF_STATUS_OK;
}

/* The places found for the last map (fig->inset_cache): a layout that
** only moves the figure on the page (a page cropped to its ink) reuses
** them. */
typedef struct ip_cache {
    cf__layout_t lay;           /* moved to the page's origin */
    size_t n;
    cf__inset_geom_t g[];       /* at the origin */
} ip_cache_t;

/* g[0..n) moved by (dx, dy). */
static void
move_places(cf__inset_geom_t *g, size_t n, double dx, double dy)
{
    size_t k;
    int c;
    for (k = 0; k < n; k++)
        for (c = 0; c < 4; c++) {
            g[k].rb[c] += c % 2 == 0 ? dx : dy;
            g[k].ib[c] += c % 2 == 0 ? dx : dy;
        }
}

static cf_status_t
place_all(cf_figure_t *fig, const cf__layout_t *at, cf__inset_geom_t *g);

cf_status_t
cf__insets_place(cf_figure_t *fig, const cf__layout_t *at,
                 cf__inset_geom_t *g)
{
    cf__layout_t lay = *at;
    ip_cache_t *c = fig->inset_cache;
    cf_status_t st;
    lay.ox -= at->px;
    lay.oy -= at->py;
    lay.px = lay.py = 0;
    if (c != NULL && c->n == fig->ninsets
        && cf__layout_same_map(&c->lay, &lay)) {
        memcpy(g, c->g, c->n * sizeof *g);
        move_places(g, c->n, at->px, at->py);
        return CF_STATUS_OK;
    }
    st = place_all(fig, &lay, g);
    if (st != CF_STATUS_OK)
        return st;
    cf_free(fig->inset_cache);
    fig->inset_cache = c = cf_malloc(sizeof *c + fig->ninsets * sizeof *g);
    if (c != NULL) {   /* without it, the places are found again */
        c->lay = lay;
        c->n = fig->ninsets;
        memcpy(c->g, g, c->n * sizeof *g);
    }
    move_places(g, fig->ninsets, at->px, at->py);
    return CF_STATUS_OK;
}

/* Every inset's place for layout lay, at the page's origin, into g. */
static cf_status_t
place_all(cf_figure_t *fig, const cf__layout_t *at, cf__inset_geom_t *g)
{
    cf__layout_t lay = *at;
    ip_search_t s;
    double e = 1e-9 * fmax(at->xmax - at->xmin, at->ymax - at->ymin);
    double room = 0;
    size_t k;
    cf_status_t st;
    for (k = 0; k < fig->ninsets; k++) {
        const double *r = fig->insets[k].region;
        if (r[0] < lay.xmin - e || r[2] > lay.xmax + e
            || r[1] < lay.ymin - e || r[3] > lay.ymax + e)
            return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, (long)k,
                               "inset %zu: region {%g, %g, %g, %g} is not "
                               "inside the window [%g, %g] x [%g, %g]",
                               k + 1, r[0], r[1], r[2], r[3], lay.xmin,
                               lay.xmax, lay.ymin, lay.ymax);
        g[k].mag = magnification(fig, &lay, &fig->insets[k], g[k].rb);
        /* room in the raster beside the drawing for the insets placed
        ** there, which the later ones avoid */
        if (fig->ninsets > 1)
            room = fmax(room, g[k].mag * fmax(g[k].rb[2] - g[k].rb[0],
                                              g[k].rb[3] - g[k].rb[1]));
    }
    st = open_search(fig, &lay, room, &s);
    for (k = 0; k < fig->ninsets && st == CF_STATUS_OK; k++) {
        place_one(fig, &lay, k, &s, &g[k]);
        /* the later insets avoid this one */
        cf__dl_reset(&s.dl);
        st = cf__inset_outline(fig, &g[k], CF__INSET_INK, &s.dl);
        if (st == CF_STATUS_OK
            && (cf__raster_paint(&s.img, &s.dl, 0, s.dl.count) != 0
                || sum_ink(&s) != 0))
            st = cf__fig_nomem(fig, "placing an inset");
    }
    close_search(&s);
    return st;
}

cf_status_t
cf__insets_ink(cf_figure_t *fig, const cf__layout_t *lay, cf__dl_t *dl)
{
    cf__inset_geom_t *g;
    cf_status_t st;
    size_t k;
    if (fig->ninsets == 0)
        return CF_STATUS_OK;
    g = cf_alloc_array(fig->ninsets, sizeof *g);
    if (g == NULL)
        return cf__fig_nomem(fig, "placing the insets");
    st = cf__insets_place(fig, lay, g);
    for (k = 0; k < fig->ninsets && st == CF_STATUS_OK; k++)
        st = cf__inset_outline(fig, &g[k], CF__INSET_INK, dl);
    cf_free(g);
    return st;
}
