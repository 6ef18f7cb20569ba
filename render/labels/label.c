/*
** Labels: a small TeX-like syntax laid out from font metrics (include/
** curvefig/label.h) in the fonts of render/labels/font.h, which the
** caller gives (render/output/create.c chooses them): creation, the
** public view of the runs, the ink box and the outline.
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
        if (label->fonts != NULL)
            label->fonts->release(label->runs[i].shaped);
    }
    cf_free(label->runs);
    if (label->scratch != NULL && label->fonts != NULL)
        label->fonts->release(label->scratch);
    cf_free(label->boxes);
    cf__pathb_free(&label->outline);
    cf_free(label->family);
    if (label->fonts_ctx != NULL)
        label->fonts->close(label->fonts_ctx);
    cf_free(label);
}

/* The outline of lab (cf__label_outline): its runs' glyphs from its
** fonts, its fraction rules as rectangles; -1 out of memory. */
static int
make_outline(cf_label_t *lab)
{
    cf__path_t path;
    size_t i;
    for (i = 0; i < lab->count; i++) {
        const run_t *r = &lab->runs[i];
        if (!(r->ink[3] > r->ink[1]))
            continue;
        if (r->rule_h > 0) {
            double x = r->x, y = -r->y - r->rule_h, w = r->width,
                   h = r->rule_h;
            double p[4][2] = { { x, y }, { x + w, y }, { x + w, y + h },
                               { x, y + h } };
            cf__pathb_add(&lab->outline, CF__SEG_MOVE, p[0]);
            cf__pathb_add(&lab->outline, CF__SEG_LINE, p[1]);
            cf__pathb_add(&lab->outline, CF__SEG_LINE, p[2]);
            cf__pathb_add(&lab->outline, CF__SEG_LINE, p[3]);
            cf__pathb_add(&lab->outline, CF__SEG_CLOSE, NULL);
            cf__pathb_add(&lab->outline, CF__SEG_MOVE, p[0]);
            continue;
        }
        lab->fonts->outline(lab->fonts_ctx, r->shaped, r->x,
                            -r->y - r->baseline, &lab->outline);
    }
    if (lab->outline.failed)
        return -1;
    cf__pathb_path(&lab->outline, &path);
    lab->outline_box[0] = 1;
    lab->outline_box[1] = lab->outline_box[2] = lab->outline_box[3] = 0;
    cf__path_box(&path, 1, 0, 0, lab->outline_box);
    return 0;
}

void
cf__label_outline(const cf_label_t *label, cf__path_t *out)
{
    cf__pathb_path(&label->outline, out);
}

void
cf__label_outline_box(const cf_label_t *label, double box[4])
{
    memcpy(box, label->outline_box, sizeof label->outline_box);
}

cf_status_t
cf__label_create(const cf__fonts_t *fonts, const char *text,
                 const char *family, double size_bp, cf_label_t **out,
                 cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf_label_t *lab;
    size_t i, len;

    if (out != NULL)
        *out = NULL;
    if (text == NULL || out == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "label text or output is NULL");
    if (fonts == NULL)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "label: no fonts to set it in");
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
    lab->fonts = fonts;
    lab->fonts_ctx = lab->fonts->open(lab->fonts->self);
    if (lab->family == NULL || lab->fonts_ctx == NULL) {
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
        if (!cf__label_runs_finish(lab)) {
            cf_label_destroy(lab);
            return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                               "out of memory for a label");
        }
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
        if (r->shaped != NULL)
            lab->unknown += (size_t)r->unknown;
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
