/*
** Legends: an entry per element that asked for one, a sample of the
** element's line, fill and marker as its group drew them, beside the
** entry's label; the box goes where the drawing leaves room, or beside
** it (render/layout/room.c), or at a named corner or side of the drawing,
** framed on the background or bare.
*/
#include <math.h>
#include <string.h>

#include "measure.h"
#include "label-private.h"
#include "layout-private.h"

#define LEG_PAD 3.0       /* bp inside the frame */
#define LEG_SAMPLE 18.0   /* bp: the length of a line sample */
#define LEG_GAP 4.0       /* bp between sample and text */
#define LEG_ROW 2.0       /* bp between rows */
#define LEG_EDGE 4.0      /* bp inside the edge of the drawing's ink */
#define LEG_FRAME 0.4     /* bp: the frame's width */

cf_status_t
cf_figure_add_legend(cf_figure_t *fig, const char *text)
{
    CF__FIG_CHECK(fig);
    if (fig->count == 0)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "no element drawn yet to name");
    return cf_figure_add_legend_at(fig, fig->count - 1, text);
}

cf_status_t
cf_figure_add_legend_at(cf_figure_t *fig, size_t el, const char *text)
{
    cf__legend_entry_t *e;
    size_t i;
    CF__FIG_CHECK(fig);
    if (text == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "the text is NULL");
    if (el >= fig->count)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, (long)el,
                           "element %zu is not drawn (%zu so far)",
                           el + 1, fig->count);
    for (i = 0; i < fig->nlegend; i++)
        if (fig->legend[i].el == el)
            return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, (long)el,
                               "element %zu has an entry already",
                               el + 1);
    e = cf_realloc_array(fig->legend, fig->nlegend + 1, sizeof *e);
    if (e == NULL)
        return cf__fig_nomem(fig, "a legend entry");
    fig->legend = e;
    e += fig->nlegend;
    memset(e, 0, sizeof *e);
    e->el = el;
    fig->nlegend++;
    return cf__text_set(fig, &e->text, text,
                        cf__role_font_size(fig, CF_ROLE_LABEL, NULL));
}

cf_status_t
cf_figure_set_legend_place(cf_figure_t *fig, cf_place_t place, bool frame)
{
    CF__FIG_CHECK(fig);
    if ((unsigned)place >= CF_PLACE_LAST_ || place == CF_PLACE_CENTER)
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "legend place %d: give a corner or side (ne, "
                           "nw, se, sw, n, s, e, w) or auto", (int)place);
    fig->legend_place = place == CF_PLACE_AUTO ? (cf_place_t)0 : place;
    fig->legend_noframe = !frame;
    return CF_STATUS_OK;
}

/* ---- samples ------------------------------------------------------------ */

/* What element el drew first: a path's paint and a marker, found in
** its group, the first of index el at ops [from, dl->count) (the
** elements' groups come before the nested ones of insets). */
typedef struct sample {
    bool has_path, has_marker;
    cf__paint_t paint;
    cf__marker_op_t marker;
} sample_t;

static void
find_sample(const cf__dl_t *dl, size_t from, size_t el, sample_t *s)
{
    size_t i = from;
    memset(s, 0, sizeof *s);
    while (i < dl->count && !(dl->ops[i].kind == CF__OP_GROUP
                              && dl->ops[i].u.group.index == el))
        i++;
    for (i++; i < dl->count && dl->ops[i].kind != CF__OP_END; i++) {
        const cf__op_t *op = &dl->ops[i];
        if (op->kind == CF__OP_PATH && !s->has_path) {
            s->has_path = true;
            s->paint = op->u.path.paint;
        } else if (op->kind == CF__OP_MARKER && !s->has_marker) {
            s->has_marker = true;
            s->marker = op->u.marker;
        }
    }
}

/* The sample of s centred on row y, from x over LEG_SAMPLE bp. */
static void
draw_sample(const sample_t *s, double x, double y, double h, cf__dl_t *dl)
{
    if (s->has_path && s->paint.fill) {
        double sh = 0.7 * h;
        cf__dl_path_begin(dl);
        cf__dl_rect(dl, x + 2, y - 0.5 * sh, LEG_SAMPLE - 4, sh);
        cf__dl_path_paint(dl, &s->paint);
    } else if (s->has_path) {
        cf__dl_path_begin(dl);
        cf__dl_move(dl, x, y);
        cf__dl_line(dl, x + LEG_SAMPLE, y);
        cf__dl_path_paint(dl, &s->paint);
    }
    if (s->has_marker) {
        cf__marker_op_t m = s->marker;
        m.x = x + 0.5 * LEG_SAMPLE;
        m.y = y;
        m.has_dir = m.marker == CF_MARKER_TICK;
        m.dir[0] = 1;
        m.dir[1] = 0;
        cf__dl_marker(dl, &m);
    }
}

/* ---- the box ------------------------------------------------------------ */

/* The height of sample s's marker as drawn (a star reaches past its
** size), 0 without one; -1 out of memory. */
static double
marker_height(const sample_t *s)
{
    cf__dl_t dl;
    cf__marker_op_t m;
    double ink[4], hgt = 0;
    if (!s->has_marker)
        return 0;
    m = s->marker;
    m.x = m.y = 0;
    m.has_dir = false;
    cf__dl_init(&dl);
    cf__dl_marker(&dl, &m);
    if (dl.failed || cf__dl_ink(&dl, 0, dl.count, ink) != 0)
        hgt = -1;
    else if (ink[3] > ink[1])
        hgt = 2 * fmax(-ink[1], ink[3]);
    cf__dl_free(&dl);
    return hgt;
}

/* Row heights and the box size of the legend in style ls: the label's
** height, at least 0.8 of the font size and the element's marker (as its
** sample draws it). */
static cf_status_t
measure(cf_figure_t *fig, const cf_style_t *ls, const sample_t *samples,
        double *rows, double *w, double *h)
{
    double tw = 0;
    size_t i;
    *h = 2 * LEG_PAD;
    for (i = 0; i < fig->nlegend; i++) {
        const cf__element_t *el = fig->els[fig->legend[i].el];
        cf_style_t es;
        double ink[4], rh, mh;
        if (cf__text_ensure(fig, &fig->legend[i].text, ls->font_size)
            != CF_STATUS_OK)
            return fig->err.status;
        cf__label_ink(fig->legend[i].text.lab, ink);
        tw = tw > ink[2] - ink[0] ? tw : ink[2] - ink[0];
        rh = ink[3] - ink[1];
        rh = rh > 0.8 * ls->font_size ? rh : 0.8 * ls->font_size;
        cf__style_resolve(&fig->theme, el->role, &el->style, &es);
        if (es.marker != CF_MARKER_NONE && es.marker_size > rh)
            rh = es.marker_size;
        mh = marker_height(&samples[i]);
        if (mh < 0)
            return cf__fig_nomem(fig, "measuring a legend's marker");
        rh = fmax(rh, mh);
        if (rows != NULL)
            rows[i] = rh;
        *h += rh + (i > 0 ? LEG_ROW : 0);
    }
    *w = 2 * LEG_PAD + LEG_SAMPLE + LEG_GAP + tw;
    return CF_STATUS_OK;
}

static void
draw_frame(const cf_figure_t *fig, const cf_style_t *axes, double x,
           double y, double w, double h, cf__dl_t *dl)
{
    cf__paint_t p;
    memset(&p, 0, sizeof p);
    p.fill = true;
    p.fill_color = fig->theme.background;
    if (p.fill_color.a <= 0)
        p.fill_color.r = p.fill_color.g = p.fill_color.b =
            p.fill_color.a = 1;
    p.fill_opacity = 1;
    p.stroke = true;
    cf__stroke_from_style(axes, &p.line);
    p.line.width = LEG_FRAME;
    p.line.dash_count = 0;
    cf__dl_path_begin(dl);
    cf__dl_rect(dl, x, y, w, h);
    cf__dl_path_paint(dl, &p);
}

cf_status_t
cf__legend_draw(cf_figure_t *fig, const cf__layout_t *lay, size_t from,
                cf__dl_t *dl)
{
    cf_style_t ls, axes;
    sample_t *samples;
    double *rows, w = 0, h = 0, at[2], y;
    cf_place_t place;
    size_t i;
    if (fig->nlegend == 0)
        return CF_STATUS_OK;
    cf__style_resolve(&fig->theme, CF_ROLE_LABEL, NULL, &ls);
    cf__style_resolve(&fig->theme, CF_ROLE_AXES, NULL, &axes);
    samples = cf_alloc_array(fig->nlegend, sizeof *samples);
    rows = cf_alloc_array(fig->nlegend, sizeof *rows);
    if (samples == NULL || rows == NULL) {
        cf_free(samples);
        cf_free(rows);
        return cf__fig_nomem(fig, "the legend");
    }
    for (i = 0; i < fig->nlegend; i++)
        find_sample(dl, from, fig->legend[i].el, &samples[i]);
    if (measure(fig, &ls, samples, rows, &w, &h) != CF_STATUS_OK)
        goto done;
    place = fig->legend_place == 0 ? CF_PLACE_AUTO : fig->legend_place;
    if (cf__room_find(fig, lay, dl, from, w, h, place, LEG_EDGE,
                      &fig->legend_band, at) != CF_STATUS_OK)
        goto done;
    cf__dl_group(dl, "legend", fig->count);
    if (!fig->legend_noframe)
        draw_frame(fig, &axes, at[0], at[1], w, h, dl);
    y = at[1] + LEG_PAD;
    for (i = 0; i < fig->nlegend; i++) {
        double cy = y + 0.5 * rows[i];
        draw_sample(&samples[i], at[0] + LEG_PAD, cy, rows[i], dl);
        if (cf__text_draw(fig, &fig->legend[i].text, &ls,
                          at[0] + LEG_PAD + LEG_SAMPLE + LEG_GAP, cy,
                          CF_PLACE_E, 0, dl) != CF_STATUS_OK)
            break;
        y += rows[i] + LEG_ROW;
    }
    cf__dl_end(dl);
done:
    cf_free(samples);
    cf_free(rows);
    return fig->err.status;
}
