/*
** Labels: a small TeX-like syntax laid out with pango from font metrics
** (include/curvefig/label.h): creation, the public view of the runs, the
** ink box, and drawing onto cairo for the cairo backend.
*/
#include <math.h>
#include <string.h>

#include "label-impl.h"

void
cf_label_destroy(cf_label_t *label)
{
    size_t i;
    if (label == NULL)
        return;
    for (i = 0; i < label->count; i++) {
        cf_free(label->runs[i].text);
        if (label->runs[i].layout != NULL)
            g_object_unref(label->runs[i].layout);
    }
    cf_free(label->runs);
    if (label->scratch != NULL)
        g_object_unref(label->scratch);
    cf_free(label->boxes);
    cf_free(label->osegs);
    cf_free(label->ocoords);
    cf_free(label->family);
    if (label->ctx != NULL)
        g_object_unref(label->ctx);
    cf_free(label);
}

static PangoContext *
make_context(void)
{
    PangoFontMap *fm = pango_cairo_font_map_get_default();
    PangoContext *ctx;
    cairo_font_options_t *fo;
    if (fm == NULL)
        return NULL;
    ctx = pango_font_map_create_context(fm);
    if (ctx == NULL)
        return NULL;
    /* Unhinted metrics and outlines: glyph positions are then the same in
    ** every output format and at every resolution. */
    fo = cairo_font_options_create();
    cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
    cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
    cairo_font_options_set_antialias(fo, CAIRO_ANTIALIAS_GRAY);
    pango_cairo_context_set_font_options(ctx, fo);
    cairo_font_options_destroy(fo);
    pango_cairo_context_set_resolution(ctx, 72.0);
    pango_context_set_round_glyph_positions(ctx, FALSE);
    return ctx;
}

/* The outline of lab (cf__label_outline) from pango's glyph paths;
** -1 out of memory. */
static int
make_outline(cf_label_t *lab)
{
    cairo_surface_t *s = cairo_recording_surface_create(CAIRO_CONTENT_ALPHA,
                                                        NULL);
    cairo_t *cr = cairo_create(s);
    cairo_path_t *path;
    size_t nsegs = 0, ncoords = 0;
    int i, bad;
    cairo_surface_destroy(s);
    cf__label_path(lab, cr, 0, 0);
    path = cairo_copy_path(cr);
    cairo_destroy(cr);
    bad = path->status != CAIRO_STATUS_SUCCESS;
    for (i = 0; !bad && i < path->num_data; i += path->data[i].header.length) {
        nsegs++;
        ncoords += 2 * (size_t)(path->data[i].header.length - 1);
    }
    if (!bad) {
        lab->osegs = cf_alloc_array(nsegs + 1, 1);
        lab->ocoords = cf_alloc_array(ncoords + 1, sizeof *lab->ocoords);
        bad = lab->osegs == NULL || lab->ocoords == NULL;
    }
    for (i = 0, ncoords = 0; !bad && i < path->num_data;
         i += path->data[i].header.length) {
        const cairo_path_data_t *d = &path->data[i];
        int k;
        static const unsigned char seg[] = {
            CF__SEG_MOVE, CF__SEG_LINE, CF__SEG_CURVE, CF__SEG_CLOSE
        };
        lab->osegs[lab->onsegs++] = seg[d->header.type];
        for (k = 1; k < d->header.length; k++) {
            lab->ocoords[ncoords++] = d[k].point.x;
            lab->ocoords[ncoords++] = d[k].point.y;
        }
    }
    cairo_path_destroy(path);
    return bad ? -1 : 0;
}

void
cf__label_outline(const cf_label_t *label, cf__path_t *out)
{
    out->segs = label->osegs;
    out->coords = label->ocoords;
    out->nsegs = label->onsegs;
}

cf_status_t
cf_label_create(const char *text, const char *family, double size_bp,
                cf_label_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_label_t *lab;
    size_t i, len;

    if (out != NULL)
        *out = NULL;
    if (text == NULL || out == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "label text or output is NULL");
    if (!(isfinite(size_bp) && size_bp > 0 && size_bp <= 1000))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "label \"%s\": font size %g must lie in (0, 1000] "
                           "bp", text, size_bp);
    if (strlen(text) > CF_LABEL_MAX_BYTES) {
        char ex[80];
        cf__label_excerpt(text, strlen(text), 0, ex, sizeof ex);
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "label \"%s\": %zu bytes, more than the %d a "
                           "label may have", ex, strlen(text),
                           CF_LABEL_MAX_BYTES);
    }
    if (family == NULL)
        family = CF__DEFAULT_FAMILY;
    if (family[0] == '\0' || strlen(family) >= CF_FONT_FAMILY_MAX)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "font family list is empty or longer than %d bytes",
                           CF_FONT_FAMILY_MAX - 1);
    lab = cf_calloc(1, sizeof *lab);
    if (lab == NULL)
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for a label");
    len = strlen(family);
    lab->family = cf_malloc(len + 1);
    lab->ctx = make_context();
    if (lab->family == NULL || lab->ctx == NULL) {
        cf_label_destroy(lab);
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for a label");
    }
    memcpy(lab->family, family, len + 1);
    lab->size = size_bp;
    /* TeX's own faces: mathematics takes TeX's math italic */
    lab->tex_math = strncmp(family, "Latin Modern Roman", 18) == 0
        || strncmp(family, "CMU Serif", 9) == 0;

    {
        cf_status_t st = cf__label_parse(lab, text, diag);
        if (st != CF_STATUS_OK) {
            cf_label_destroy(lab);
            return st;
        }
        cf__label_runs_finish(lab);
    }
    lab->boxes = cf_alloc_array(lab->count ? lab->count : 1,
                                sizeof *lab->boxes);
    if (lab->boxes == NULL || make_outline(lab) != 0) {
        cf_label_destroy(lab);
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for a label");
    }
    for (i = 0; i < lab->count; i++) {
        const run_t *r = &lab->runs[i];
        cf_label_box_t *b = &lab->boxes[i];
        if (r->layout != NULL)
            lab->unknown += (size_t)pango_layout_get_unknown_glyphs_count(
                r->layout);
        b->x = r->x;
        b->y = r->y;
        b->width = r->width;
        b->ascent = r->ascent;
        b->descent = r->descent;
        b->size = r->size;
        b->level = r->level;
        b->kind = r->kind;
        b->italic = r->italic;
        b->start = 0;
        b->end = r->text_len;
    }
    *out = lab;
    return CF_STATUS_OK;
}

size_t
cf_label_box_count(const cf_label_t *label)
{
    return label != NULL ? label->count : 0;
}

const cf_label_box_t *
cf_label_get_box(const cf_label_t *label, size_t i)
{
    if (label == NULL || i >= label->count)
        return NULL;
    return &label->boxes[i];
}

const char *
cf_label_run_text(const cf_label_t *label, size_t i)
{
    if (label == NULL || i >= label->count)
        return "";
    return label->runs[i].text;
}

void
cf_label_get_extents(const cf_label_t *label, double *width, double *ascent,
                     double *descent)
{
    double w = 0, a = 0, d = 0;
    size_t i;
    if (label != NULL) {
        for (i = 0; i < label->count; i++) {
            const run_t *r = &label->runs[i];
            w = fmax(w, r->x + r->width);
            a = fmax(a, r->y + r->ascent);
            d = fmax(d, r->descent - r->y);
        }
    }
    if (width != NULL)
        *width = w;
    if (ascent != NULL)
        *ascent = a;
    if (descent != NULL)
        *descent = d;
}

size_t
cf_label_unknown_glyphs(const cf_label_t *label)
{
    return label != NULL ? label->unknown : 0;
}

bool
cf__label_matches(const cf_label_t *label, const char *family,
                  double size_bp)
{
    return label != NULL && label->size == size_bp
        && strcmp(label->family, family) == 0;
}

void
cf__label_ink(const cf_label_t *label, double box[4])
{
    size_t i;
    bool any = false;
    box[0] = box[1] = box[2] = box[3] = 0;
    if (label == NULL)
        return;
    for (i = 0; i < label->count; i++) {
        const run_t *r = &label->runs[i];
        double x0 = r->x + r->ink[0], x1 = r->x + r->ink[2];
        double y0 = -r->y + r->ink[1], y1 = -r->y + r->ink[3];
        if (!(r->ink[3] > r->ink[1]))
            continue;
        if (!any) {
            box[0] = x0;
            box[1] = y0;
            box[2] = x1;
            box[3] = y1;
            any = true;
        } else {
            box[0] = fmin(box[0], x0);
            box[1] = fmin(box[1], y0);
            box[2] = fmax(box[2], x1);
            box[3] = fmax(box[3], y1);
        }
    }
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
        pango_cairo_show_layout(cr, r->layout);
    }
    cairo_restore(cr);
}

void
cf__label_path(const cf_label_t *label, cairo_t *cr, double x, double y)
{
    size_t i;
    if (label == NULL)
        return;
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
        pango_cairo_layout_path(cr, r->layout);
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
