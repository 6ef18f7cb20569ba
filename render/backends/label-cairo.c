/*
** Labels drawn with cairo (render/backends/label-cairo.h): a run of fonts
** with faces (native: HarfBuzz's shaping or pango's) as its glyphs
** (render/backends/font-glyphs.c: glyphs, so that PDF and PS carry text),
** a run of other fonts (a course page's glyph table) as its outline.
*/
#include "font-glyphs.h"
#include "label-cairo.h"
#include "label-impl.h"

/* The outline of the label's glyphs and rules appended to cr's path. */
static void
outline_path(const cf_label_t *label, cairo_t *cr, double x, double y)
{
    cf__path_t p;
    const double *v;
    size_t i;
    cf__label_outline(label, &p);
    v = p.coords;
    for (i = 0; i < p.nsegs; i++) {
        switch ((cf__seg_t)p.segs[i]) {
        case CF__SEG_MOVE:
            cairo_move_to(cr, x + v[0], y + v[1]);
            v += 2;
            break;
        case CF__SEG_LINE:
            cairo_line_to(cr, x + v[0], y + v[1]);
            v += 2;
            break;
        case CF__SEG_CURVE:
            cairo_curve_to(cr, x + v[0], y + v[1], x + v[2], y + v[3],
                           x + v[4], y + v[5]);
            v += 6;
            break;
        case CF__SEG_CLOSE:
            cairo_close_path(cr);
            break;
        default:   /* labels' outlines have no rectangles or arcs */
            return;
        }
    }
}

/* A run from the current point: its glyphs, or the fonts' own drawing
** of a run with unknown glyphs (pango's boxes). */
static void
draw_run(const cf_label_t *label, const run_t *r, cairo_t *cr, bool path)
{
    const cf__font_glyphs_t *g = label->fonts->glyphs(r->shaped);
    if (label->fonts->draw != NULL && cf__font_glyphs_unknown(g))
        label->fonts->draw(r->shaped, cr, path);
    else
        cf__font_glyphs_draw(cr, g, path);
}

void
cf__label_draw(const cf_label_t *label, cairo_t *cr, double x, double y,
               const cf_color_t *color, double opacity)
{
    size_t i;
    if (label == NULL)
        return;
    cairo_save(cr);
    cairo_set_source_rgba(cr, color->r, color->g, color->b,
                          color->a * opacity);
    if (label->fonts->glyphs == NULL) {
        cairo_new_path(cr);
        outline_path(label, cr, x, y);
        cairo_fill(cr);
        cairo_restore(cr);
        return;
    }
    for (i = 0; i < label->count; i++) {
        const run_t *r = &label->runs[i];
        if (!(r->ink[3] > r->ink[1]))
            continue;   /* nothing to draw (spaces) */
        if (r->rule_h > 0) {
            cairo_rectangle(cr, x + r->x, y - r->y - r->rule_h, r->width,
                            r->rule_h);
            cairo_fill(cr);
            continue;
        }
        cairo_move_to(cr, x + r->x, y - r->y - r->baseline);
        draw_run(label, r, cr, false);
    }
    cairo_restore(cr);
}

void
cf__label_path(const cf_label_t *label, cairo_t *cr, double x, double y)
{
    size_t i;
    if (label == NULL)
        return;
    if (label->fonts->glyphs == NULL) {
        outline_path(label, cr, x, y);
        return;
    }
    for (i = 0; i < label->count; i++) {
        const run_t *r = &label->runs[i];
        if (!(r->ink[3] > r->ink[1]))
            continue;
        if (r->rule_h > 0) {
            cairo_rectangle(cr, x + r->x, y - r->y - r->rule_h, r->width,
                            r->rule_h);
            continue;
        }
        cairo_move_to(cr, x + r->x, y - r->y - r->baseline);
        draw_run(label, r, cr, true);
    }
}

void
cf__label_draw_halo(const cf_label_t *label, cairo_t *cr, double x,
                    double y, const cf_color_t *halo_color, double halo)
{
    if (label == NULL || !(halo > 0) || halo_color->a <= 0)
        return;
    cairo_save(cr);
    cairo_new_path(cr);
    cf__label_path(label, cr, x, y);
    cairo_set_source_rgba(cr, halo_color->r, halo_color->g, halo_color->b,
                          halo_color->a);
    cairo_set_line_width(cr, 2 * halo);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_stroke(cr);
    cairo_restore(cr);
}
