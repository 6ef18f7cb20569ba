/*
** Label places.  Everything but the labels (and the shadings, on which a
** label may sit) is drawn into a coarse raster of the page's ink
** (render/backends/measure.h).  Each label placed by hand is then tested against it,
** glyph by glyph, and added to it; each label placed CF_PLACE_AUTO (the
** default) takes the cheapest of the eight places around its anchor, at
** its offset and up to 4 bp farther (adjacent to the point), never one
** nearer another labelled point than its own while any other is left,
** and is added to the raster in turn, so that later labels avoid it.
** The insets' frames, connectors and boxes are ink too (placed before
** the labels: render/layout/inset-place.c).  A label that still lies on
** ink, placed by hand or automatically, is kept and reported in the
** figure's warnings (cf_figure_warnings): which label, at which place,
** on what.  The raster is drawn only where it is read (the candidate
** places and the labels placed by hand; none at all when nothing is
** read), in the figure's memory kept from the last placement and emptied
** again only where it was painted; a candidate's cost is four look-ups
** in the sums of the raster over its label's candidates; a label lying
** on no ink is added to the raster from the pixels it was tested with.
** The refits of a page cropped to its ink place the labels as a draft
** (the same places, no warnings).  The rasters, their memory and what is
** read of them: render/layout/place-raster.c.
*/
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "label-private.h"
#include "layout-private.h"
#include "measure.h"
#include "place-raster.h"

#define AUTO_GAP 1.0          /* bp around a label that should stay clear */
#define AUTO_NEAR 3.0         /* bp: ink this close costs a quarter */
#define AUTO_FAR 0.6          /* cost (bp^2) of each bp farther out */
#define AUTO_AMBIGUOUS 1e4    /* cost of a place nearer another labelled
                                 point than the label's own */
#define AUTO_CLEARER 0.75     /* bp a label keeps nearer its own point */
#define AUTO_KEEP 1.0         /* bp^2: a label of an animation keeps its
                                 place of the frame before unless the best
                                 is clearer by more than this */

/* The distances tried, in bp beyond the style's offset. */
static const double further[] = { 0.0, 1.0, 2.0, 3.0, 4.0 };

/* The places tried, in order of preference. */
static const cf_place_t order[] = {
    CF_PLACE_NE, CF_PLACE_NW, CF_PLACE_SE, CF_PLACE_SW,
    CF_PLACE_N, CF_PLACE_S, CF_PLACE_E, CF_PLACE_W
};

/* The anchors (page points) of the labels in the window. */
typedef cf__place_raster_t raster_t;

typedef struct anchors {
    double *xy;
    size_t n;
} anchors_t;

/* The page box of a candidate's ink widened by d (AUTO_GAP, AUTO_NEAR). */
static void
widened(const double ink[4], double ox, double oy, double d, double b[4])
{
    b[0] = ox + ink[0] - d;
    b[1] = oy + ink[1] - d;
    b[2] = ox + ink[2] + d;
    b[3] = oy + ink[3] + d;
}

/* The cost of a label with ink box ink (relative to its origin) at
** origin (ox, oy): ink under the box widened by AUTO_GAP, plus a quarter
** of the ink in the ring out to AUTO_NEAR. */
static double
place_cost(raster_t *r, const double ink[4], double ox, double oy)
{
    double hard[4], near[4], a, b;
    widened(ink, ox, oy, AUTO_GAP, hard);
    widened(ink, ox, oy, AUTO_NEAR, near);
    a = cf__place_ink(r, hard);
    b = cf__place_ink(r, near);
    return a + 0.25 * fmax(0, b - a);
}

/* Element i's operations into r->dl. */
static cf_status_t
element_ops(cf_figure_t *fig, size_t i, const cf__layout_t *lay, raster_t *r)
{
    cf_status_t st;
    cf__dl_reset(&r->dl);
    st = cf__element_draw(fig, i, lay, &r->dl);
    if (r->dl.failed && st == CF_STATUS_OK)
        st = cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                         "out of memory placing labels");
    return st;
}

/* Paint the ops of r->dl into raster to, within its pixel box px (NULL:
** everywhere). */
static cf_status_t
paint(cf_figure_t *fig, raster_t *r, cf__raster_t *to, const int *px)
{
    const int all[4] = { 0, 0, to->w, to->h };
    if (cf__raster_paint_in(to, &r->dl, 0, r->dl.count,
                            px != NULL ? px : all) != 0)
        return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                           "out of memory placing labels");
    return CF_STATUS_OK;
}

/* Draw element i into raster to, within its pixel box px (NULL:
** everywhere). */
static cf_status_t
raster_element(cf_figure_t *fig, size_t i, const cf__layout_t *lay,
               raster_t *r, cf__raster_t *to, const int *px)
{
    cf_status_t st = element_ops(fig, i, lay, r);
    if (st == CF_STATUS_OK)
        st = paint(fig, r, to, px);
    return st;
}

/* Whether element i is a label; its anchor, text, place (its style's)
** and where the place chosen automatically goes. */
static bool
is_label(cf_figure_t *fig, size_t i, double *x, double *y, cf__text_t **t,
         cf__auto_place_t **chosen, cf_style_t *s)
{
    cf__element_t *e = fig->els[i];
    if (e->kind->auto_label == NULL)
        return false;
    cf__style_resolve(&fig->theme, e->role, &e->style, s);
    return e->kind->auto_label(e, x, y, t, chosen);
}

/* bp from page point (x, y) to page box b (x0 y0 x1 y1). */
static double
box_distance(const double b[4], double x, double y)
{
    double dx = fmax(0, fmax(b[0] - x, x - b[2]));
    double dy = fmax(0, fmax(b[1] - y, y - b[3]));
    return hypot(dx, dy);
}

/* Whether a label with page box b, anchored at (px, py), lies nearer
** another labelled point than its own (or not clearly farther from it). */
static bool
ambiguous(const anchors_t *an, const double b[4], double px, double py)
{
    double own = box_distance(b, px, py);
    size_t k;
    for (k = 0; k < an->n; k++) {
        double x = an->xy[2 * k], y = an->xy[2 * k + 1];
        if (hypot(x - px, y - py) < 0.5)
            continue;   /* the same point */
        if (box_distance(b, x, y) < own + AUTO_CLEARER)
            return true;
    }
    return false;
}

/* The cheapest place and distance of a label at page point (px, py): as
** near the point as the ink lets it, never nearer another labelled point
** unless every place is. */
static void
cheapest(raster_t *r, const anchors_t *an, const cf_label_t *lab,
         const cf_style_t *s, double px, double py,
         const cf__auto_place_t *hint, bool force, cf__auto_place_t *chosen)
{
    double ink[4], best = INFINITY;
    size_t k, d;
    cf__label_ink(lab, ink);
    chosen->place = order[0];
    chosen->offset = s->offset;
    for (d = 0; d < sizeof further / sizeof further[0]; d++)
        for (k = 0; k < sizeof order / sizeof order[0]; k++) {
            double ox, oy, c, b[4], off = s->offset + further[d];
            cf__label_origin(lab, order[k], off, px, py, &ox, &oy);
            b[0] = ox + ink[0];
            b[1] = oy + ink[1];
            b[2] = ox + ink[2];
            b[3] = oy + ink[3];
            c = place_cost(r, ink, ox, oy) + AUTO_FAR * further[d];
            if (ambiguous(an, b, px, py))
                c += AUTO_AMBIGUOUS;
            /* a later candidate must be clearly better (0.05 bp^2) */
            if (c < best - 0.05) {
                best = c;
                chosen->place = order[k];
                chosen->offset = off;
            }
        }
    if (hint != NULL) {
        double ox, oy, b[4], c;
        cf__label_origin(lab, hint->place, hint->offset, px, py, &ox, &oy);
        b[0] = ox + ink[0];
        b[1] = oy + ink[1];
        b[2] = ox + ink[2];
        b[3] = oy + ink[3];
        c = place_cost(r, ink, ox, oy)
            + AUTO_FAR * fmax(0, hint->offset - s->offset);
        if (ambiguous(an, b, px, py))
            c += AUTO_AMBIGUOUS;
        if (force || c <= best + AUTO_KEEP)
            *chosen = *hint;
    }
}

/* The sums of the page's raster over the pixels the candidate places of
** a label at page point (px, py) read (cheapest), so that each costs
** four look-ups; -1 out of memory. */
static int
candidate_sums(raster_t *r, const cf_label_t *lab, const cf_style_t *s,
               double px, double py)
{
    double ink[4], whole[4];
    int box[4] = { INT32_MAX, INT32_MAX, INT32_MIN, INT32_MIN }, b[4];
    size_t k, d;
    cf__label_ink(lab, ink);
    for (d = 0; d < sizeof further / sizeof further[0]; d++)
        for (k = 0; k < sizeof order / sizeof order[0]; k++) {
            double ox, oy, near[4];
            cf__label_origin(lab, order[k], s->offset + further[d], px, py,
                             &ox, &oy);
            widened(ink, ox, oy, AUTO_NEAR, near);
            cf__place_ink_pixels(&r->img, r->res, near, b, whole);
            box[0] = b[0] < box[0] ? b[0] : box[0];
            box[1] = b[1] < box[1] ? b[1] : box[1];
            box[2] = b[2] > box[2] ? b[2] : box[2];
            box[3] = b[3] > box[3] ? b[3] : box[3];
        }
    /* the rows read (a label outside the window reads beyond the box
    ** the placement made ready) */
    cf__raster_ready(&r->img, box[1], box[3]);
    return cf__place_sums(&r->sums, &r->img, box);
}

/* Append a line to the figure's warnings (once). */
static void
warn(cf_figure_t *fig, const char *fmt, ...)
{
    char line[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    cf__figure_warn(fig, "%s", line);
}

/* The element of the page's ink most under label `lab` (drawn in r->one)
** into *worst: its index, or fig->count when none is found alone.  Out of
** memory drawing one, the figure's error (no warning naming the wrong
** element). */
static cf_status_t
what_is_under(cf_figure_t *fig, const cf__layout_t *lay, raster_t *r,
              size_t lab, bool automatic, const unsigned char *mask,
              const int *px, size_t *worst)
{
    size_t j;
    long most = 0;
    *worst = fig->count;
    for (j = 0; j < fig->count; j++) {
        double x, y;
        cf__text_t *t;
        cf__auto_place_t *c;
        cf_style_t s;
        long n;
        if (j == lab || (fig->els[j]->kind->flags & CF__KIND_SHADING))
            continue;
        /* the labels not yet in the raster */
        if (is_label(fig, j, &x, &y, &t, &c, &s)
            && ((s.place == CF_PLACE_AUTO) ? !automatic || j > lab
                                           : !automatic && j > lab))
            continue;
        /* only the label's box px is compared */
        cf__raster_clear(&r->one, px);
        if (raster_element(fig, j, lay, r, &r->one, px) != CF_STATUS_OK)
            return fig->err.status;
        /* the mask is empty outside the label's box px */
        n = cf__place_common(&r->one, mask, px);
        if (n > most) {
            most = n;
            *worst = j;
        }
    }
    return CF_STATUS_OK;
}

static const char *const place_names[] = {
    "center", "n", "ne", "e", "se", "s", "sw", "w", "nw", "auto"
};

/* Test label i (not yet in the raster) against the ink; a warning when
** it lies on some.  Then add it to the raster. */
static cf_status_t
check_label(cf_figure_t *fig, const cf__layout_t *lay, raster_t *r,
            size_t i, const cf__text_t *t, cf_place_t place, bool automatic,
            bool last)
{
    cf_status_t st;
    double ink[4];
    int px[4];
    long n;
    char line[32] = "", under[CF__LINE_NOTE_SIZE];
    /* only the label's box is cleared, drawn and compared; the last label
    ** is not added (nothing reads the raster after it) */
    st = element_ops(fig, i, lay, r);
    if (st != CF_STATUS_OK || r->draft)
        return st != CF_STATUS_OK || last ? st
                                          : paint(fig, r, &r->img, NULL);
    if (cf__dl_ink(&r->dl, 0, r->dl.count, ink) != 0)
        return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                           "out of memory measuring a label");
    if (!(ink[2] > ink[0] && ink[3] > ink[1]))
        return CF_STATUS_OK;   /* nothing drawn */
    px[0] = cf__pixel_within(floor(ink[0] * r->res) - 1, -1, r->one.w + 1);
    px[1] = cf__pixel_within(floor(ink[1] * r->res) - 1, -1, r->one.h + 1);
    px[2] = cf__pixel_within(ceil(ink[2] * r->res) + 1, -1, r->one.w + 1);
    px[3] = cf__pixel_within(ceil(ink[3] * r->res) + 1, -1, r->one.h + 1);
    cf__raster_clear(&r->one, px);
    r->one.cut = false;
    r->one.solid = true;     /* the label's glyphs, faded or not */
    st = paint(fig, r, &r->one, px);
    r->one.solid = false;
    if (st != CF_STATUS_OK)
        return st;
    cf__raster_ready(&r->img, px[1], px[3]);
    n = cf__place_common(&r->one, r->img.px, px);
    if (n <= 1 && (last || (!r->one.cut && cf__place_add_apart(r, px))))
        return CF_STATUS_OK;
    if (n > 1) {
        size_t j;
        int row, i0 = px[0] > 0 ? px[0] : 0;
        int i1 = px[2] < r->one.w ? px[2] : r->one.w;
        /* keep the label's mask: naming what is under it reuses r->one
        ** (only the label's box px is compared) */
        for (row = px[1] > 0 ? px[1] : 0; row < px[3] && row < r->one.h
             && i1 > i0; row++) {
            size_t at = (size_t)row * (size_t)r->one.stride + (size_t)i0;
            memcpy(r->mask + at, r->one.px + at, (size_t)(i1 - i0));
        }
        st = what_is_under(fig, lay, r, i, automatic, r->mask, px, &j);
        /* what_is_under drew the other elements into r->dl */
        if (st == CF_STATUS_OK)
            st = element_ops(fig, i, lay, r);
        if (st != CF_STATUS_OK)
            return st;
        /* the script's lines of the label and of what it lies on */
        if (fig->els[i]->line > 0)
            snprintf(line, sizeof line, "line %d, ", fig->els[i]->line);
        if (j < fig->count)
            warn(fig, "label \"%s\" (%s%s%s) lies on %s %zu%s", t->src, line,
                 automatic ? "placed automatically " : "place ",
                 place_names[place], fig->els[j]->kind->name, j + 1,
                 cf__line_note(fig->els[j]->line, under));
        else
            warn(fig, "label \"%s\" (%s%s%s) lies on %s", t->src, line,
                 automatic ? "placed automatically " : "place ",
                 place_names[place], fig->ninsets > 0
                 ? "ink (an inset's frame or connector?)" : "ink");
    }
    return last ? CF_STATUS_OK : paint(fig, r, &r->img, NULL);
}

void
cf__place_forget(cf_figure_t *fig)
{
    fig->placed = false;
}

/* The pixel box of raster r that the placement reads (every candidate
** box of the automatic labels in the window out to AUTO_NEAR, and unless
** a draft the box of each label placed by hand, as check_label takes it,
** a pixel more each way) into px; false when there is none, or out of
** memory (the figure's error).  When no label is placed automatically
** (and not a draft), the rows of that box which the labels placed by
** hand read, in the window or not, are marked in r->rows (with automatic
** labels it is dropped). */
static bool
read_box(cf_figure_t *fig, const cf__layout_t *lay, raster_t *r, int px[4])
{
    double b[4] = { INFINITY, INFINITY, -INFINITY, -INFINITY };
    size_t i, d, k;
    /* out of memory it is the placement's error, as every other refusal
    ** of the rendering (none is passed over: cf_script_budget_end) */
    if (!r->draft && (r->rows = cf_calloc((size_t)r->img.h, 1)) == NULL) {
        cf__fig_nomem(fig, "placing labels");
        return false;
    }
    for (i = 0; i < fig->count; i++) {
        double x, y, ax, ay, ink[4], hb[4];
        cf__text_t *t;
        cf__auto_place_t *chosen;
        cf_style_t s;
        bool in;
        if (!is_label(fig, i, &x, &y, &t, &chosen, &s))
            continue;
        if (s.place == CF_PLACE_AUTO && r->rows != NULL) {
            cf_free(r->rows);
            r->rows = NULL;
        }
        in = cf__in_window(lay, x, y);
        if (!in && (s.place == CF_PLACE_AUTO || r->rows == NULL))
            continue;
        if (s.place != CF_PLACE_AUTO) {
            if (r->draft || element_ops(fig, i, lay, r) != CF_STATUS_OK
                || cf__dl_ink(&r->dl, 0, r->dl.count, ink) != 0
                || !(ink[2] > ink[0] && ink[3] > ink[1]))
                continue;
            hb[0] = ink[0] - 1 / r->res;
            hb[1] = ink[1] - 1 / r->res;
            hb[2] = ink[2] + 1 / r->res;
            hb[3] = ink[3] + 1 / r->res;
            if (r->rows != NULL)
                cf__place_mark_rows(r, hb);
            if (!in)
                continue;
            b[0] = fmin(b[0], ink[0] - 1 / r->res);
            b[1] = fmin(b[1], ink[1] - 1 / r->res);
            b[2] = fmax(b[2], ink[2] + 1 / r->res);
            b[3] = fmax(b[3], ink[3] + 1 / r->res);
            continue;
        }
        if (cf__text_ensure(fig, t, s.font_size) != CF_STATUS_OK
            || t->lab == NULL)
            continue;
        cf__map(lay, x, y, &ax, &ay);
        cf__label_ink(t->lab, ink);
        for (d = 0; d < sizeof further / sizeof further[0]; d++)
            for (k = 0; k < sizeof order / sizeof order[0]; k++) {
                double ox, oy;
                cf__label_origin(t->lab, order[k], s.offset + further[d],
                                 ax, ay, &ox, &oy);
                b[0] = fmin(b[0], ox + ink[0] - AUTO_NEAR);
                b[1] = fmin(b[1], oy + ink[1] - AUTO_NEAR);
                b[2] = fmax(b[2], ox + ink[2] + AUTO_NEAR);
                b[3] = fmax(b[3], oy + ink[3] + AUTO_NEAR);
            }
    }
    if (!(b[2] >= b[0] && b[3] >= b[1]))
        return false;
    px[0] = (int)fmax(-1, fmin(r->img.w, floor(b[0] * r->res) - 1));
    px[1] = (int)fmax(-1, fmin(r->img.h, floor(b[1] * r->res) - 1));
    px[2] = (int)fmax(-1, fmin(r->img.w, ceil(b[2] * r->res) + 1));
    px[3] = (int)fmax(-1, fmin(r->img.h, ceil(b[3] * r->res) + 1));
    return true;
}

/* The places of layout lay, chosen on the page at its own position (the
** layout moved by its page position to the origin): a page cropped to
** its ink moves the layout without moving a label against its point, so
** the places chosen once serve every build of the layout that only
** moves it (the figure unchanged since cf__figure_layout). */
cf_status_t
cf__place_labels(cf_figure_t *fig, const cf__layout_t *at, bool draft)
{
    cf__layout_t moved = *at;
    const cf__layout_t *lay = &moved;
    raster_t r;
    anchors_t an;
    cf_style_t s;
    cf__text_t *t;
    cf__auto_place_t *chosen;
    double x, y;
    size_t i, j, n, k = 0;   /* k: labels checked */
    int box[4];
    cf_status_t st;

    moved.ox -= at->px;
    moved.oy -= at->py;
    moved.px = moved.py = 0;
    if (fig->placed && (draft || !fig->placed_draft)
        && cf__layout_same_map(&fig->placed_for, lay))
        return CF_STATUS_OK;   /* the places and warnings of that layout */
    fig->placed = false;
    cf_free(fig->warnings);
    fig->warnings = NULL;
    fig->warnings_len = 0;
    for (i = 0, n = 0; i < fig->count; i++)
        n += is_label(fig, i, &x, &y, &t, &chosen, &s);
    if (n == 0)
        return CF_STATUS_OK;
    /* an animation's frame drawn with the places it was measured with
    ** (render/output/anim-frames.c): taken as they are, nothing to search */
    for (i = 0, j = 0; fig->place_hint_force && i < fig->count; i++)
        j += is_label(fig, i, &x, &y, &t, &chosen, &s)
             && s.place == CF_PLACE_AUTO;
    if (fig->place_hint_force && j == fig->nplace_hint) {
        for (i = 0, j = 0; i < fig->count; i++)
            if (is_label(fig, i, &x, &y, &t, &chosen, &s)
                && s.place == CF_PLACE_AUTO)
                *chosen = fig->place_hint[j++];
        fig->placed = true;
        fig->placed_draft = draft;
        fig->placed_for = moved;
        return CF_STATUS_OK;
    }
    if (n > CF_FIGURE_MAX_LABELS)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "the figure has %zu labels, more than the %d "
                           "placed in one figure (each is placed among "
                           "all the others)", n, CF_FIGURE_MAX_LABELS);
    cf__place_raster_open(fig, &r);
    r.draft = draft;
    /* the raster is read only where the automatic labels may go and the
    ** labels placed by hand are: the rest is not drawn
    ** (cf__raster_paint_in: the same pixels) */
    if (!read_box(fig, lay, &r, box)) {
        cf__place_raster_close(fig, &r);
        if (fig->err.status != CF_STATUS_OK)
            return fig->err.status;
        fig->placed = true;
        fig->placed_draft = draft;
        fig->placed_for = moved;
        return CF_STATUS_OK;
    }
    st = cf__place_raster_memory(fig, &r);
    /* the automatic labels' candidates read the raster anywhere in the
    ** box; the labels placed by hand only their own boxes (check_label) */
    if (st == CF_STATUS_OK && r.rows == NULL)
        cf__raster_ready(&r.img, box[1], box[3]);
    /* with every label placed by hand, only the rows their boxes take
    ** (read_box): the pixels there are the same */
    r.img.rows = r.rows;
    /* fills and hulls left out: labels may sit on a shading */
    for (i = 0; i < fig->count && st == CF_STATUS_OK; i++) {
        if ((fig->els[i]->kind->flags & CF__KIND_SHADING)
            || is_label(fig, i, &x, &y, &t, &chosen, &s))
            continue;
        st = raster_element(fig, i, lay, &r, &r.img, box);
    }
    /* the insets' frames, connectors and boxes */
    if (st == CF_STATUS_OK && fig->ninsets > 0) {
        cf__dl_reset(&r.dl);
        st = cf__insets_ink(fig, lay, &r.dl);
        if (st == CF_STATUS_OK)
            st = paint(fig, &r, &r.img, box);
    }
    r.img.rows = NULL;
    /* the labels placed by hand first: the automatic ones avoid them */
    for (i = 0; i < fig->count && st == CF_STATUS_OK; i++) {
        if (!is_label(fig, i, &x, &y, &t, &chosen, &s)
            || s.place == CF_PLACE_AUTO)
            continue;
        st = check_label(fig, lay, &r, i, t, s.place, false, ++k == n);
    }
    an.n = 0;
    an.xy = cf_alloc_array(2 * fig->count + 2, sizeof *an.xy);
    if (an.xy == NULL && st == CF_STATUS_OK)
        st = cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                         "out of memory placing labels");
    for (i = 0; i < fig->count && st == CF_STATUS_OK; i++)
        if (is_label(fig, i, &x, &y, &t, &chosen, &s)) {
            cf__map(lay, x, y, &an.xy[2 * an.n], &an.xy[2 * an.n + 1]);
            an.n++;
        }
    for (i = 0, j = 0; i < fig->count && st == CF_STATUS_OK; i++) {
        double px, py;
        if (!is_label(fig, i, &x, &y, &t, &chosen, &s)
            || s.place != CF_PLACE_AUTO)
            continue;
        j++;
        k++;
        st = cf__text_ensure(fig, t, s.font_size);
        if (st != CF_STATUS_OK || t->lab == NULL)
            continue;
        cf__map(lay, x, y, &px, &py);
        if (candidate_sums(&r, t->lab, &s, px, py) != 0) {
            st = cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                             "out of memory placing labels");
            break;
        }
        cheapest(&r, &an, t->lab, &s, px, py,
                 j <= fig->nplace_hint ? &fig->place_hint[j - 1] : NULL,
                 fig->place_hint_force, chosen);
        st = check_label(fig, lay, &r, i, t, chosen->place, true, k == n);
    }
    cf_free(an.xy);
    cf__place_raster_close(fig, &r);
    if (st == CF_STATUS_OK) {
        fig->placed = true;
        fig->placed_draft = draft;
        fig->placed_for = moved;
    }
    return st;
}

size_t
cf__place_chosen(cf_figure_t *fig, cf__auto_place_t *out, size_t cap)
{
    cf__auto_place_t *chosen;
    cf__text_t *t;
    cf_style_t s;
    double x, y;
    size_t n = 0;
    for (size_t i = 0; i < fig->count; i++) {
        if (!is_label(fig, i, &x, &y, &t, &chosen, &s)
            || s.place != CF_PLACE_AUTO)
            continue;
        if (n < cap)
            out[n] = *chosen;
        n++;
    }
    return n;
}

const char *
cf_figure_warnings(const cf_figure_t *fig)
{
    if (fig != NULL && fig->panels != NULL)
        return fig->all_warnings != NULL ? fig->all_warnings : "";
    return fig != NULL && fig->warnings != NULL ? fig->warnings : "";
}
