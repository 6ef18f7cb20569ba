/*
** Layout: the data window (explicit, or fitted to what is drawn), the
** data -> page map, room for what sticks out of the data box (labels,
** markers, arrow heads, line widths, and the legend and insets placed
** beside the drawing: the ink of a first pass), and the display list of
** a layout.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "layout-private.h"
#include "measure.h"

static void
compute_map(const cf_figure_t *fig, const double win[4], bool keep,
            const double avail[4], cf__layout_t *lay)
{
    double aw = avail[2] - avail[0], ah = avail[3] - avail[1];
    double dx = win[1] - win[0], dy = win[3] - win[2];
    lay->xmin = win[0];
    lay->xmax = win[1];
    lay->ymin = win[2];
    lay->ymax = win[3];
    lay->sx = aw / dx;
    lay->sy = ah / dy;
    if (keep) {
        double s = fmin(lay->sx, lay->sy);
        lay->sx = lay->sy = s;
    }
    /* centre in the available box */
    lay->ox = avail[0] + 0.5 * (aw - lay->sx * dx);
    lay->oy = avail[3] - 0.5 * (ah - lay->sy * dy);
    lay->tol = fig->tol / fmax(lay->sx, lay->sy);
}


/* The elements (their automatic label places chosen first; a draft's
** for a refit of the ink box). */
static cf_status_t
build_elements(cf_figure_t *fig, const cf__layout_t *lay, bool draft,
               cf__dl_t *dl)
{
    size_t i;
    if (cf__place_labels(fig, lay, draft) != CF_STATUS_OK)
        return fig->err.status;
    for (i = 0; i < fig->count; i++)
        if (cf__element_draw(fig, i, lay, dl) != CF_STATUS_OK)
            return fig->err.status;
    return CF_STATUS_OK;
}

/* The ink box of the figure drawn with layout lay: its elements, and the
** insets and the legend placed beside them (its panels are not measured:
** they have their own layouts in their cells); draft: one of the refits
** of a page cropped to its ink. */
static cf_status_t
ink_of(cf_figure_t *fig, const cf__layout_t *lay, bool draft, double ink[4])
{
    cf__dl_t dl;
    cf_status_t st;
    cf__dl_init(&dl);
    st = build_elements(fig, lay, draft, &dl);
    if (st == CF_STATUS_OK)
        st = cf__insets_draw(fig, lay, &dl);
    if (st == CF_STATUS_OK)
        st = cf__legend_draw(fig, lay, 0, &dl);
    /* a list cut short by a failed allocation, or a measure that ran out,
    ** would give the box of part of the drawing, and a layout fitted to
    ** it */
    if (st == CF_STATUS_OK
        && (dl.failed || cf__dl_ink(&dl, 0, dl.count, ink) != 0))
        st = cf__fig_nomem(fig, "measuring the drawing's ink");
    cf__dl_free(&dl);
    return st;
}

/* A panel's error in its parent, naming the panel. */
static cf_status_t
panel_failed(cf_figure_t *fig, int k, const cf_figure_t *p)
{
    return cf_diag_set(&fig->err, p->err.status, p->err.index,
                       "panel (%c): %s", 'a' + k, p->err.msg);
}

/* Each panel laid out on its own page (its cell's size), the shared axes
** made one, drawn, and its display list moved into its cell as a group
** after its title. */
static cf_status_t
build_panels(cf_figure_t *fig, const cf__layout_t *lay, cf__dl_t *dl)
{
    int k, n = fig->rows * fig->cols;
    cf__layout_t *lays = cf_alloc_array((size_t)n, sizeof *lays);
    cf__dl_t pdl;
    if (lays == NULL)
        return cf__fig_nomem(fig, "the panels' layouts");
    for (k = 0; k < n && fig->err.status == CF_STATUS_OK; k++) {
        cf_figure_t *p = fig->panels[k];
        double cell[4];
        cf__panel_cell(fig, k, cell);
        p->width = cell[2];
        p->height = cell[3];
        if (p->err.status != CF_STATUS_OK
            || cf__figure_layout(p, &lays[k]) != CF_STATUS_OK)
            panel_failed(fig, k, p);
    }
    if (fig->err.status == CF_STATUS_OK)
        cf__panels_share(fig, lays);
    cf__dl_init(&pdl);
    for (k = 0; k < n && fig->err.status == CF_STATUS_OK; k++) {
        double cell[4];
        cf__panel_cell(fig, k, cell);
        cf__dl_reset(&pdl);
        if (cf__figure_build(fig->panels[k], &lays[k], &pdl)
            != CF_STATUS_OK) {
            panel_failed(fig, k, fig->panels[k]);
            break;
        }
        cf__dl_group(dl, "panel", (size_t)k);
        if (cf__panel_title_draw(fig, k, lay, dl) != CF_STATUS_OK)
            break;
        cf__dl_append_moved(dl, &pdl, lay->px + cell[0], lay->py + cell[1]);
        cf__dl_end(dl);
    }
    cf__dl_free(&pdl);
    cf_free(lays);
    return fig->err.status;
}

/* The warnings of a figure split into panels: its own, then each
** panel's lines, "panel (a): " in front. */
static cf_status_t
gather_warnings(cf_figure_t *fig)
{
    int k, n = fig->rows * fig->cols;
    size_t size = fig->warnings_len + 1;
    char *all, *at;
    for (k = 0; k < n; k++) {
        const char *w = cf_figure_warnings(fig->panels[k]);
        size += strlen(w) + 12;   /* "panel (a): " and a newline */
        for (; *w != '\0'; w++)
            size += (*w == '\n') * 12;
    }
    all = cf_malloc(size);
    if (all == NULL)
        return cf__fig_nomem(fig, "the panels' warnings");
    at = all;
    if (fig->warnings != NULL) {
        memcpy(at, fig->warnings, fig->warnings_len);
        at += fig->warnings_len;
    }
    for (k = 0; k < n; k++) {
        const char *w = cf_figure_warnings(fig->panels[k]);
        while (*w != '\0') {
            const char *nl = strchr(w, '\n');
            size_t len = nl != NULL ? (size_t)(nl - w) : strlen(w);
            at += sprintf(at, "panel (%c): ", 'a' + k);
            memcpy(at, w, len);
            at += len;
            *at++ = '\n';
            w += len + (nl != NULL);
        }
    }
    *at = '\0';
    cf_free(fig->all_warnings);
    fig->all_warnings = all;
    return CF_STATUS_OK;
}

/* Each label of ops [from, count) with characters none of the figure's
** fonts has: they are drawn as empty boxes, so the figure says so (once),
** with the start of the label cut at a character's boundary.  Here, at
** the build, for every kind of label (elements', axes', the legend's) and
** after the placement, which makes its warnings anew for every layout. */
static void
warn_unknown_glyphs(cf_figure_t *fig, const cf__dl_t *dl, size_t from)
{
    size_t i;
    for (i = from; i < dl->count; i++) {
        const cf__text_op_t *t = &dl->ops[i].u.text;
        size_t unknown, len, n;
        if (dl->ops[i].kind != CF__OP_TEXT
            || (unknown = cf_label_unknown_glyphs(t->label)) == 0)
            continue;
        len = n = strlen(t->source);
        if (n > 40) {
            n = 40;
            while (n > 0 && ((unsigned char)t->source[n] & 0xC0) == 0x80)
                n--;
        }
        cf__figure_warn(fig,
                        "label \"%.*s%s\": %zu character%s no font of \"%s\" "
                        "has, drawn as empty boxes (name a font family that "
                        "has them)",
                        (int)n, t->source, n < len ? "..." : "", unknown,
                        unknown == 1 ? "" : "s", fig->theme.font_family);
    }
}

cf_status_t
cf__figure_build(cf_figure_t *fig, const cf__layout_t *lay, cf__dl_t *dl)
{
    size_t from;
    if (fig->panels != NULL && build_panels(fig, lay, dl) != CF_STATUS_OK)
        return fig->err.status;
    from = dl->count;
    if (build_elements(fig, lay, false, dl) != CF_STATUS_OK
        || cf__insets_draw(fig, lay, dl) != CF_STATUS_OK
        || cf__legend_draw(fig, lay, from, dl) != CF_STATUS_OK)
        return fig->err.status;
    warn_unknown_glyphs(fig, dl, from);
    if (fig->panels != NULL && gather_warnings(fig) != CF_STATUS_OK)
        return fig->err.status;
    if (dl->failed)
        return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for the display list");
    return CF_STATUS_OK;
}

/* bp: a page cropped to its ink is laid out again until the room left
** for what sticks out of the data box changes by less than this: 0.01 bp
** beyond one unit of the ink box, which cf__dl_ink rounds out to whole
** 1/64 bp (render/backends/measure.c).  A room whose ink edge sits on
** such a rounding step moves by one unit from one pass to the next and
** back, for ever: with 0.01 alone the refits ran to their limit. */
#define REFINE_TOL (1.0 / 64 + 0.01)
/* ... or until this many passes */
#define REFINE_PASSES 8

/* The available box avail for the data box: the page inside the margin
** less what sticks out of the data box of layout lay (ink, page bp), at
** most 0.4 of the page each way (0.8 when the page is the ink box, which
** must not grow past width x height, and which may also grow the data
** box past the page where the ink does not reach it). */
static void
make_room(const cf_figure_t *fig, const double win[4], const double ink[4],
          const cf__layout_t *lay, double avail[4])
{
    double m = fig->margin;
    double dl = lay->ox, dr = lay->ox + lay->sx * (win[1] - win[0]);
    double db = lay->oy, dt = lay->oy - lay->sy * (win[3] - win[2]);
    /* a page cropped to the ink may also grow the data box where the
    ** ink stops short of it (an explicit window larger than the drawing),
    ** by at most the page's size */
    double lo = fig->page_mode == CF_PAGE_INK
        ? -fmax(fig->width, fig->height) : 0;
    double ol = fmax(lo, dl - ink[0]), or_ = fmax(lo, ink[2] - dr);
    double ot = fmax(lo, dt - ink[1]), ob = fmax(lo, ink[3] - db);
    double k_max = fig->page_mode == CF_PAGE_INK ? 0.8 : 0.4;
    double maxw = k_max * (fig->width - 2 * m);
    double maxh = k_max * (fig->height - 2 * m);
    if (ol + or_ > maxw) {
        double k = maxw / (ol + or_);
        ol *= k;
        or_ *= k;
    }
    if (ot + ob > maxh) {
        double k = maxh / (ot + ob);
        ot *= k;
        ob *= k;
    }
    avail[0] = m + ol;
    avail[2] = fig->width - m - or_;
    avail[1] = m + ot;
    avail[3] = fig->height - m - ob;
}

/* The room of the next refit from three rooms each the last one's: x0,
** x1 (made from x0's layout) and x2 (from x1's), into x2.  The room of a
** side is a smooth function of the scale where nothing jumps (a label
** changing its place, an inset its corner), and the plain refit x2 ->
** its own room converges to it only as fast as the ink moves with the
** scale: a side whose ink is drawing (not a label) moves by a third of
** the step before at each pass (markova-2.19: 7 passes), an inset placed
** by the room left by the drawing overshoots by half of it, back and
** forth (example-inset: 8 passes and not settled, its page a third of a
** bp taller than asked).  Aitken's extrapolation of such a sequence is
** its limit when the steps shrink by a constant ratio q, and near it
** when they about do; a side is extrapolated only when the last step is
** more than the tolerance (below it the steps are the ink's rounding)
** and q lies within [-0.8, 0.8] (a step at most 4 times the last), and
** the room of all sides is kept at no less than half of x2's, else x2 is
** left as it is (a jump: the plain refit goes on from it). */
static void
extrapolate(const double x0[4], const double x1[4], double x2[4])
{
    double x[4];
    int k;
    memcpy(x, x2, sizeof x);
    for (k = 0; k < 4; k++) {
        double d1 = x1[k] - x0[k], d2 = x2[k] - x1[k], q;
        if (!(fabs(d2) > REFINE_TOL) || !(d1 != 0))
            continue;
        q = d2 / d1;
        if (q >= -0.8 && q <= 0.8)
            x[k] = x2[k] + d2 * q / (1 - q);
    }
    if (isfinite(x[0] + x[1] + x[2] + x[3])
        && x[2] - x[0] >= 0.5 * (x2[2] - x2[0])
        && x[3] - x[1] >= 0.5 * (x2[3] - x2[1]))
        memcpy(x2, x, sizeof x);
}

/* bp a label outside the window may stick out of the page: rounding */
#define LABEL_SLACK 0.05

/* A label outside an explicit window is drawn where it is (the drawing
** makes room for it, as for any ink beyond the data box); one that then
** lies off the figure's page is an error naming it and its place. */
static cf_status_t
labels_off_page(cf_figure_t *fig, const cf__layout_t *lay)
{
    cf__dl_t dl;
    size_t i;
    cf__dl_init(&dl);
    for (i = 0; i < fig->count; i++) {
        cf__element_t *e = fig->els[i];
        cf__auto_place_t *chosen;
        cf__text_t *t;
        double x, y, ink[4];
        if (e->kind->auto_label == NULL
            || !e->kind->auto_label(e, &x, &y, &t, &chosen)
            || cf__in_window(lay, x, y))
            continue;
        cf__dl_reset(&dl);
        if (cf__element_draw(fig, i, lay, &dl) != CF_STATUS_OK)
            break;
        if (dl.failed || cf__dl_ink(&dl, 0, dl.count, ink) != 0) {
            cf__fig_nomem(fig, "measuring a label");
            break;
        }
        if (ink[2] > ink[0]
            && (ink[0] < lay->px - LABEL_SLACK
                || ink[1] < lay->py - LABEL_SLACK
                || ink[2] > lay->px + fig->width + LABEL_SLACK
                || ink[3] > lay->py + fig->height + LABEL_SLACK)) {
            char at[CF__LINE_NOTE_SIZE];
            cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, (long)i,
                        "label %zu \"%s\"%s at (%g, %g) is outside the "
                        "window [%g, %g] x [%g, %g], too far to fit the %.1f "
                        "x %.1f mm page beside it: widen the window or move "
                        "the label", i + 1, t->src != NULL ? t->src : "",
                        cf__line_note(e->line, at), x, y,
                        lay->xmin, lay->xmax, lay->ymin, lay->ymax,
                        fig->width * 25.4 / 72, fig->height * 25.4 / 72);
            break;
        }
    }
    cf__dl_free(&dl);
    return fig->err.status;
}

cf_status_t
cf__figure_layout(cf_figure_t *fig, cf__layout_t *lay)
{
    double win[4], avail[4], ink[4], m = fig->margin, tol0 = 0.0;
    double before[4] = { 0, 0, 0, 0 };   /* the room whose layout made
                                           the last pass's */
    bool behind = false;
    cf__bounds_t b;
    bool keep, refine = fig->page_mode == CF_PAGE_INK && fig->panels == NULL;
    size_t i;
    int pass;

    memset(&b, 0, sizeof b);
    fig->layout_passes = 0;
    lay->px = lay->py = 0;
    cf__room_reset(fig);
    cf__place_forget(fig);
    for (i = 0; i < fig->count; i++)
        fig->els[i]->kind->bounds(fig->els[i], &b);
    if (b.nomem)
        return cf__fig_nomem(fig, "the drawing's bounds");
    lay->clip = fig->window_set;
    if (fig->window_set) {
        memcpy(win, fig->win, sizeof win);
    } else if (!b.any) {
        win[0] = 0;
        win[1] = 1;
        win[2] = 0;
        win[3] = 1;
    } else {
        double span = fmax(b.x1 - b.x0, b.y1 - b.y0);
        if (!(span > 0))
            span = fmax(1.0, fabs(b.x0) + fabs(b.y0));
        win[0] = b.x0;
        win[1] = b.x1;
        win[2] = b.y0;
        win[3] = b.y1;
        /* a flat box (a horizontal segment) gets some height */
        if (!(win[1] - win[0] > 1e-9 * span)) {
            win[0] -= 0.5 * span;
            win[1] += 0.5 * span;
        }
        if (!(win[3] - win[2] > 1e-9 * span)) {
            win[2] -= 0.5 * span;
            win[3] += 0.5 * span;
        }
    }
    /* the extent must itself be a finite number: coordinates near
    ** DBL_MAX (or a window of such width) overflow it */
    if (!isfinite(win[1] - win[0]) || !isfinite(win[3] - win[2]))
        return cf_diag_set(&fig->err,
                           CF_STATUS_NOT_FINITE, -1,
                           "the %s spans %g x %g, too large to draw "
                           "(coordinates up to about 1e307)",
                           fig->window_set ? "window" : "drawing",
                           win[1] - win[0], win[3] - win[2]);
    cf_figure_get_fit(fig, NULL, &keep);
    avail[0] = m;
    avail[1] = m;
    avail[2] = fig->width - m;
    avail[3] = fig->height - m;
    compute_map(fig, win, keep, avail, lay);
    /* ... and so small that the page's scale is a number: a window
    ** 1e-320 wide (a denormal) maps it to infinity */
    if (!isfinite(lay->sx) || !isfinite(lay->sy) || !(lay->sx > 0)
        || !(lay->sy > 0))
        return cf_diag_set(&fig->err, CF_STATUS_NOT_FINITE, -1,
                           "the %s spans %g x %g, too small to draw: its "
                           "scale on the page (the page's size over the "
                           "span) overflows",
                           fig->window_set ? "window" : "drawing",
                           win[1] - win[0], win[3] - win[2]);
    if (fig->count == 0)
        return CF_STATUS_OK;
    /* room for what sticks out of the data box (labels, markers, arrow
    ** heads, line widths), measured on the layout so far; a page cropped
    ** to its ink is measured again until the ink fills the page inside
    ** the margin (label places change a little with the scale), each
    ** third room extrapolated from the two before it (extrapolate) */
    for (pass = 0; pass < (refine ? REFINE_PASSES : 1); pass++) {
        double prev[4];
        cf_status_t st;
        memcpy(prev, avail, sizeof prev);
        /* (surfaces made for an earlier refit may serve this one:
        ** cf__tol_serves) */
        fig->refitting = refine;
        fig->refit_rough = refine && pass == 0 && !fig->draft;
        if (pass == 0)
            tol0 = lay->tol;
        fig->refit_drop = pass == 1 && tol0 > lay->tol
                              ? (tol0 - lay->tol) / lay->tol : 0.0;
        st = ink_of(fig, lay, refine, ink);
        fig->refitting = fig->refit_rough = false;
        fig->refit_drop = 0.0;
        fig->layout_passes = pass + 1;
        if (st != CF_STATUS_OK)
            return fig->err.status;
        make_room(fig, win, ink, lay, avail);
        compute_map(fig, win, keep, avail, lay);
        if (pass > 0 && fabs(prev[0] - avail[0]) < REFINE_TOL
            && fabs(prev[1] - avail[1]) < REFINE_TOL
            && fabs(prev[2] - avail[2]) < REFINE_TOL
            && fabs(prev[3] - avail[3]) < REFINE_TOL)
            break;
        /* (the last pass's room is the one measured, not a guess) */
        if (behind && pass + 1 < REFINE_PASSES) {
            extrapolate(before, prev, avail);
            compute_map(fig, win, keep, avail, lay);
        } else {
            memcpy(before, prev, sizeof before);
        }
        behind = !behind;
    }
    return fig->window_set ? labels_off_page(fig, lay) : CF_STATUS_OK;
}

cf_status_t
cf_figure_get_window(cf_figure_t *fig, double window[4], double *sx,
                     double *sy)
{
    cf__layout_t lay;
    CF__FIG_CHECK(fig);
    if (cf__figure_layout(fig, &lay) != CF_STATUS_OK)
        return fig->err.status;
    if (window != NULL) {
        window[0] = lay.xmin;
        window[1] = lay.xmax;
        window[2] = lay.ymin;
        window[3] = lay.ymax;
    }
    if (sx != NULL)
        *sx = lay.sx;
    if (sy != NULL)
        *sy = lay.sy;
    return CF_STATUS_OK;
}

/* ---- the page ----------------------------------------------------------- */

/* Ink outside the page below this (bp) is rounding, not an overflow. */
#define PAGE_SLACK 0.05

/* How far ink box b sticks out of a w x h page (bp, <= 0: not at all),
** and on which side. */
static double
overflow(const double b[4], double w, double h, const char **side)
{
    double o[4] = { -b[0], -b[1], b[2] - w, b[3] - h }, worst = o[0];
    static const char *const sides[4] = { "left", "top", "right",
                                          "bottom" };
    int k, at = 0;
    for (k = 1; k < 4; k++)
        if (o[k] > worst) {
            worst = o[k];
            at = k;
        }
    *side = sides[at];
    return worst;
}

static bool
draws(const cf__op_t *op)
{
    return op->kind == CF__OP_PATH || op->kind == CF__OP_MARKER
        || op->kind == CF__OP_TEXT || op->kind == CF__OP_MESH;
}

/* Whether every coordinate the operations [g, e) of dl put on the page is
** a finite number: one of an element so far outside the drawing that its
** place on the page overflows would be left out by every backend,
** silently. */
static bool
group_finite(const cf__dl_t *dl, size_t g, size_t e)
{
    static const unsigned char per_seg[] = {
        [CF__SEG_MOVE] = 2, [CF__SEG_LINE] = 2, [CF__SEG_CURVE] = 6,
        [CF__SEG_RECT] = 4, [CF__SEG_ARC] = 5, [CF__SEG_CLOSE] = 0
    };
    size_t i, k, c;
    for (i = g; i < e && i < dl->count; i++) {
        const cf__op_t *op = &dl->ops[i];
        if (op->kind == CF__OP_PATH) {
            c = op->u.path.coord0;
            for (k = 0; k < op->u.path.nsegs; k++) {
                unsigned char sk = dl->segs[op->u.path.seg0 + k];
                size_t n = sk < sizeof per_seg ? per_seg[sk] : 0, j;
                for (j = 0; j < n && c + j < dl->ncoords; j++)
                    if (!isfinite(dl->coords[c + j]))
                        return false;
                c += n;
            }
        } else if (op->kind == CF__OP_MARKER) {
            if (!(isfinite(op->u.marker.x) && isfinite(op->u.marker.y)))
                return false;
        } else if (op->kind == CF__OP_TEXT) {
            if (!(isfinite(op->u.text.px) && isfinite(op->u.text.py)
                  && isfinite(op->u.text.ox) && isfinite(op->u.text.oy)))
                return false;
        }
    }
    return true;
}

/* Whether group op g is placed by the layout around the others' ink (a
** legend, an inset's frame): it follows an element far out rather than
** being the one to move. */
static bool
placed_around(const cf__op_t *g)
{
    return strcmp(g->u.group.name, "legend") == 0
        || strcmp(g->u.group.name, "inset") == 0;
}

/* The element (GROUP ... END at ops [g, e)) whose ink sticks out of a
** w x h page farthest (one with a coordinate that is not finite,
** farthest of all): its GROUP op's index, how far (bp, *worst) and where
** (*side), and its name in who[0..whon-1] ("label 3 "P_0""); *worst 0
** when none does. */
static size_t
farthest_group(const cf__dl_t *dl, double w, double h, double *worst,
               const char **side, char *who, size_t whon)
{
    size_t i = 0, worst_g = 0, worst_el = 0;
    const char *text = NULL, *side_el = "";
    double worst_e = 0;
    *worst = 0;
    *side = "";
    while (i < dl->count) {
        size_t g = i, e = i + 1;
        double ink[4], o;
        const char *sd = "right";
        if (dl->ops[i].kind != CF__OP_GROUP) {
            i++;
            continue;
        }
        while (e < dl->count && dl->ops[e].kind != CF__OP_END)
            e++;
        i = e + 1;
        if (!group_finite(dl, g, e))
            o = HUGE_VAL;
        else if (cf__dl_ink(dl, g, e + 1, ink) != 0)
            continue;
        else if (!(isfinite(ink[0]) && isfinite(ink[1]) && isfinite(ink[2])
                   && isfinite(ink[3])))
            o = HUGE_VAL;
        else if (!(ink[2] > ink[0] && ink[3] > ink[1]))
            continue;
        else
            o = overflow(ink, w, h, &sd);
        if (o > *worst) {
            *worst = o;
            worst_g = g;
            *side = sd;
        }
        if (o > worst_e && !placed_around(&dl->ops[g])) {
            worst_e = o;
            worst_el = g;
            side_el = sd;
        }
    }
    /* a legend placed beside a label 1e300 bp out lies about as far: the
    ** label is named, not the legend (a legend far larger than the page
    ** itself, with every element near, is still named) */
    if (worst_e > 0 && worst_e >= 0.5 * *worst) {
        *worst = worst_e;
        worst_g = worst_el;
        *side = side_el;
    }
    for (i = worst_g; *worst > 0 && i < dl->count
         && dl->ops[i].kind != CF__OP_END; i++)
        if (dl->ops[i].kind == CF__OP_TEXT) {
            text = dl->ops[i].u.text.source;
            break;
        }
    if (*worst > 0 && dl->ops[worst_g].kind == CF__OP_GROUP) {
        char at[CF__LINE_NOTE_SIZE];
        snprintf(who, whon, "%s %zu%s%.200s%s%s",
                 dl->ops[worst_g].u.group.name,
                 dl->ops[worst_g].u.group.index + 1,
                 text != NULL ? " \"" : "", text != NULL ? text : "",
                 text != NULL ? "\"" : "",
                 cf__line_note(dl->ops[worst_g].u.group.line, at));
    } else {
        snprintf(who, whon, "an element");
    }
    return worst_g;
}

/* The element whose ink sticks out farthest: an error naming it. */
static cf_status_t
page_overflow(const cf__dl_t *dl, double w, double h, cf_diag_t *diag)
{
    double worst;
    const char *worst_side;
    char who[256];
    size_t g = farthest_group(dl, w, h, &worst, &worst_side, who, sizeof who);
    if (!(worst > PAGE_SLACK))
        return CF_STATUS_OK;
    return cf_diag_set(diag, CF_STATUS_INVALID_ARG,
                       (long)dl->ops[g].u.group.index,
                       "%s sticks out of the %.1f x %.1f mm page by %.1f mm "
                       "(%.1f pt) on the %s; make the page or the margin "
                       "larger, or let the figure clip (clip = true)", who,
                       w * 25.4 / 72, h * 25.4 / 72, worst * 25.4 / 72,
                       worst, worst_side);
}

cf_status_t
cf__figure_check_size(const cf__dl_t *dl, double w, double h,
                      double page_w, double page_h, cf_diag_t *diag)
{
    double worst;
    const char *side;
    char who[256];
    size_t g;
    if (w <= CF__PAGE_MAX && h <= CF__PAGE_MAX
        && group_finite(dl, 0, dl->count))
        return CF_STATUS_OK;
    g = farthest_group(dl, page_w, page_h, &worst, &side, who, sizeof who);
    if (!(worst > 0))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "the figure's ink spans %g x %g pt, larger than "
                           "the largest page (%g pt a side)", w, h,
                           CF__PAGE_MAX);
    if (!isfinite(worst))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG,
                           (long)dl->ops[g].u.group.index,
                           "%s lies too far outside the drawing's %.1f x "
                           "%.1f mm page to be drawn (its place on the page "
                           "overflows); move it nearer", who,
                           page_w * 25.4 / 72, page_h * 25.4 / 72);
    return cf_diag_set(diag, CF_STATUS_INVALID_ARG,
                       (long)dl->ops[g].u.group.index,
                       "%s lies %.4g mm outside the drawing's %.1f x %.1f mm "
                       "page, on the %s: the page cropped to the ink would "
                       "be larger than the largest page (%g pt = %.2f m a "
                       "side); move it nearer", who, worst * 25.4 / 72,
                       page_w * 25.4 / 72, page_h * 25.4 / 72, side,
                       CF__PAGE_MAX, CF__PAGE_MAX * 0.0254 / 72);
}

cf_status_t
cf__figure_check_page(const cf_figure_t *fig, const cf__dl_t *dl, double w,
                      double h, bool fixed, cf_diag_t *diag)
{
    double ink[4];
    const char *side;
    size_t i;
    bool any = false;
    for (i = 0; i < dl->count && !any; i++)
        any = draws(&dl->ops[i]);
    if (!any)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "the figure draws nothing (%zu elements, none "
                           "with anything to show on the page)", fig->count);
    if (!fixed || !group_finite(dl, 0, dl->count))
        return cf__figure_check_size(dl, fixed ? 0 : w, fixed ? 0 : h, w, h,
                                     diag);
    if (fig->clip_page)
        return CF_STATUS_OK;
    if (cf__dl_ink(dl, 0, dl->count, ink) != 0)
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory measuring the ink");
    if (!(overflow(ink, w, h, &side) > PAGE_SLACK))
        return CF_STATUS_OK;
    return page_overflow(dl, w, h, diag);
}
