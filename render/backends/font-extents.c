/*
** Where the glyphs of a run of the native fonts sit and what they cover,
** in pango's numbers (render/backends/font-native.c): each item's
** baseline shift, then the logical and ink extents: each glyph's advance
** from HarfBuzz, its ink from the font file (font-outlines.h: the numbers
** of cairo's scaled font) or cairo's scaled font, in units rounded as
** pango rounds, the font's logical height from HarfBuzz's ascender and
** descender, the line's and the layout's rectangles combined as pango
** combines them (one line, left to right).
*/
#include <math.h>
#include <stddef.h>
#include <string.h>

#include <hb-ot.h>

#include "font-extents.h"
#include "font-outlines.h"

/* Whether every shift is 0 without asking HarfBuzz: one item, or a first
** item whose script names the roman baseline and faces without a BASE
** table, where HarfBuzz synthesises the roman baseline at 0
** (hb_ot_layout_get_baseline_with_fallback). */
static bool
all_roman_at_0(const native_run_t *r)
{
    size_t i;
    if (r->nitems <= 1)
        return true;
    switch ((int)r->items[0].script) {
    case HB_SCRIPT_LATIN:
    case HB_SCRIPT_GREEK:
    case HB_SCRIPT_CYRILLIC:
    case HB_SCRIPT_COMMON:
        break;
    default:
        return false;
    }
    for (i = 0; i < r->nitems; i++)
        if (r->items[i].font->own == NULL
            || cf__otface_has_base(r->items[i].font->own))
            return false;
    return true;
}

/* pango's baseline shifts: the first item's script names the baseline
** (roman, hanging, ideographic), each item's font says where that
** baseline is for its script; an item sits lifted by the difference. */
void
cf__native_baseline_shifts(native_run_t *r)
{
    hb_ot_layout_baseline_tag_t tag = 0;
    hb_position_t baseline = 0;
    size_t i;
    if (all_roman_at_0(r)) {
        for (i = 0; i < r->glyphs.g.nspans; i++)
            r->glyphs.spans[i].shift = 0;
        return;
    }
    for (i = 0; i < r->nitems && i < r->glyphs.g.nspans; i++) {
        const item_t *t = &r->items[i];
        hb_tag_t stags[HB_OT_MAX_TAGS_PER_SCRIPT];
        hb_tag_t ltags[HB_OT_MAX_TAGS_PER_LANGUAGE];
        unsigned ns = HB_OT_MAX_TAGS_PER_SCRIPT;
        unsigned nl = HB_OT_MAX_TAGS_PER_LANGUAGE;
        hb_position_t own = 0;
        hb_font_t *font = cf__nface_hb(t->font);
        hb_ot_tags_from_script_and_language(
            t->script, hb_language_from_string("c", -1), &ns, stags, &nl,
            ltags);
        if (tag == 0)
            tag = hb_ot_layout_get_horizontal_baseline_tag_for_script(
                t->script);
        if (font != NULL)
            hb_ot_layout_get_baseline_with_fallback(
                font, tag, HB_DIRECTION_LTR, stags[ns - 1],
                nl > 0 ? ltags[nl - 1] : HB_TAG_NONE, &own);
        if (i == 0)
            baseline = own;
        r->glyphs.spans[i].shift = baseline - own;
    }
}

/* a double in pango units, rounded as pango rounds */
static int
units(double v)
{
    return (int)floor(v * CF__FONT_SCALE + 0.5);
}

/* min and max as pango combines rectangles */
static int
imin(int a, int b)
{
    return a < b ? a : b;
}

static int
imax(int a, int b)
{
    return a > b ? a : b;
}

/* The layout's extents from the spans' glyphs (pango's glyph string,
** line and layout extents, one line, left to right). */
void
cf__native_extents(native_run_t *r, cf__font_shape_t *out)
{
    const cf__font_glyphs_t *g = &r->glyphs.g;
    int line_ink[4] = { 0, 0, 0, 0 }, line_log[4] = { 0, 0, 0, 0 };
    int x_pos = 0, base;
    size_t i, k;
    for (i = 0; i < g->nspans; i++) {
        const cf__font_span_t *s = &g->spans[i];
        cf__nface_t *f = (cf__nface_t *)((char *)s->face
                                         - offsetof(cf__nface_t, face));
        int ink[4] = { 0, 0, 0, 0 }, log[4] = { 0, 0, 0, 0 }, gx = 0, np;
        for (k = 0; k < s->nglyphs; k++) {
            const cf__font_glyph_t *gl = &g->glyphs[s->glyph + k];
            int gi[4] = { 0, 0, 0, 0 };
            if (gl->id != CF__FONT_GLYPH_EMPTY) {
                cairo_glyph_t cg;
                cairo_text_extents_t e;
                cg.index = gl->id;
                cg.x = cg.y = 0;
                /* from the font file, else from cairo's scaled font */
                if (cf__own_glyph_extents(&f->face, gl->id, &e) != 0) {
                    cairo_scaled_font_t *sf = cf__nface_scaled(f);
                    memset(&e, 0, sizeof e);
                    if (sf != NULL)
                        cairo_scaled_font_glyph_extents(sf, &cg, 1, &e);
                }
                gi[0] = units(e.x_bearing);
                gi[1] = units(e.y_bearing);
                gi[2] = units(e.width);
                gi[3] = units(e.height);
            }
            if (gi[2] != 0 && gi[3] != 0) {
                if (ink[2] == 0 || ink[3] == 0) {
                    ink[0] = gx + gi[0] + gl->x;
                    ink[2] = gi[2];
                    ink[1] = gi[1] + gl->y;
                    ink[3] = gi[3];
                } else {
                    int nx = imin(ink[0], gx + gi[0] + gl->x),
                        ny = imin(ink[1], gi[1] + gl->y);
                    ink[2] = imax(ink[0] + ink[2],
                                  gx + gi[0] + gi[2] + gl->x) - nx;
                    ink[0] = nx;
                    ink[3] = imax(ink[1] + ink[3], gi[1] + gi[3] + gl->y)
                             - ny;
                    ink[1] = ny;
                }
            }
            log[2] += gl->width;
            if (k == 0) {
                log[1] = f->ext_y;
                log[3] = f->ext_height;
            } else {
                int ny = imin(log[1], f->ext_y);
                log[3] = imax(log[1] + log[3], f->ext_y + f->ext_height) - ny;
                log[1] = ny;
            }
            gx += gl->width;
        }
        ink[1] -= s->shift;
        log[1] -= s->shift;
        /* the line's rectangles */
        if (line_ink[2] == 0 || line_ink[3] == 0) {
            memcpy(line_ink, ink, sizeof ink);
            line_ink[0] += x_pos;
        } else if (ink[2] != 0 && ink[3] != 0) {
            np = imin(line_ink[0], x_pos + ink[0]);
            line_ink[2] = imax(line_ink[0] + line_ink[2],
                               x_pos + ink[0] + ink[2]) - np;
            line_ink[0] = np;
            np = imin(line_ink[1], ink[1]);
            line_ink[3] = imax(line_ink[1] + line_ink[3], ink[1] + ink[3])
                          - np;
            line_ink[1] = np;
        }
        np = imin(line_log[0], x_pos + log[0]);
        line_log[2] = imax(line_log[0] + line_log[2],
                           x_pos + log[0] + log[2]) - np;
        line_log[0] = np;
        np = imin(line_log[1], log[1]);
        line_log[3] = imax(line_log[1] + line_log[3], log[1] + log[3]) - np;
        line_log[1] = np;
        x_pos += log[2];
    }
    base = -line_log[1];
    out->baseline = base;
    out->logical[0] = 0;
    out->logical[1] = 0;
    out->logical[2] = imax(0, line_log[2]);
    out->logical[3] = base + line_log[1] + line_log[3];
    out->ink[0] = line_ink[0];
    out->ink[1] = base + line_ink[1];
    out->ink[2] = line_ink[2];
    out->ink[3] = line_ink[3];
    out->unknown = 0;
}
