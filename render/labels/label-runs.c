/*
** Runs of a label: the glyphs of one font, size and baseline, laid out
** and measured with pango (render/label-impl.h).
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "label-impl.h"


/* Latin Modern comes in optical sizes, like Computer Modern: TeX sets 7 pt
** scripts in the 7 pt design, which is wider and sturdier than the 10 pt
** design scaled down.  fontconfig always picks "LM Roman 10" for "Latin
** Modern Roman", so name the design ("LM Roman 7") in front of the list:
** the largest design not above the size in TeX points (the smallest one
** for smaller sizes). */
static void
family_for_size(const char *family, double size_bp, bool italic, bool bold,
                char *out, size_t cap)
{
    static const int regular[] = { 5, 6, 7, 8, 9, 10, 12, 17 };
    static const int slanted[] = { 7, 8, 9, 10, 12 };
    static const int heavy[] = { 5, 6, 7, 8, 9, 10, 12 };
    static const int sans[] = { 8, 9, 10, 12, 17 };
    static const int sans_bold[] = { 10 };
    const char *lm = "Latin Modern Roman", *lms = "Latin Modern Sans";
    size_t n = strlen(lm), ns = strlen(lms), i, count;
    const int *d;
    double texpt = size_bp * 72.27 / 72;
    int pick;

    if (strncmp(family, lms, ns) == 0
        && (family[ns] == '\0' || family[ns] == ',')) {
        d = bold ? sans_bold : sans;
        count = bold ? 1 : sizeof sans / sizeof sans[0];
        lm = "LM Sans";
    } else if (strncmp(family, lm, n) != 0
        || (family[n] != '\0' && family[n] != ',')) {
        snprintf(out, cap, "%s", family);
        return;
    } else {
        d = italic ? slanted : bold ? heavy : regular;
        count = italic ? sizeof slanted / sizeof slanted[0]
              : bold ? sizeof heavy / sizeof heavy[0]
                     : sizeof regular / sizeof regular[0];
        lm = "LM Roman";
    }
    pick = d[0];
    for (i = 0; i < count; i++)
        if (d[i] <= texpt + 0.25)
            pick = d[i];
    snprintf(out, cap, "%s %d,%s", lm, pick, family);
}

static void
run_measure(cf_label_t *lab, run_t *r)
{
    PangoFontDescription *fd;
    PangoRectangle ink, logical;
    char family[CF_FONT_FAMILY_MAX + 16];

    if (r->layout == NULL)
        r->layout = pango_layout_new(lab->ctx);
    fd = pango_font_description_new();
    if (r->math)
        snprintf(family, sizeof family, "%s,%s", CF__MATH_FAMILY,
                 lab->family);
    else
        family_for_size(lab->family, r->size, r->italic, r->bold, family,
                        sizeof family);
    pango_font_description_set_family(fd, family);
    pango_font_description_set_style(fd, r->italic && !r->math
                                         ? PANGO_STYLE_ITALIC
                                         : PANGO_STYLE_NORMAL);
    pango_font_description_set_weight(fd, r->bold ? PANGO_WEIGHT_BOLD
                                                  : PANGO_WEIGHT_NORMAL);
    pango_font_description_set_absolute_size(fd, r->size * PANGO_SCALE);
    pango_layout_set_font_description(r->layout, fd);
    pango_font_description_free(fd);
    pango_layout_set_text(r->layout, r->text, (int)r->text_len);
    pango_layout_get_extents(r->layout, &ink, &logical);
    r->baseline = (double)pango_layout_get_baseline(r->layout) / PANGO_SCALE;
    r->width = (double)logical.width / PANGO_SCALE;
    r->ascent = r->baseline - (double)logical.y / PANGO_SCALE;
    r->descent = (double)(logical.y + logical.height) / PANGO_SCALE
        - r->baseline;
    r->ink[0] = (double)(ink.x - logical.x) / PANGO_SCALE;
    r->ink[1] = (double)ink.y / PANGO_SCALE - r->baseline;
    r->ink[2] = r->ink[0] + (double)ink.width / PANGO_SCALE;
    r->ink[3] = r->ink[1] + (double)ink.height / PANGO_SCALE;
    if (ink.width == 0 || ink.height == 0) {
        /* spaces: no ink */
        r->ink[0] = r->ink[2] = 0;
        r->ink[1] = r->ink[3] = 0;
    }
}

double
cf__label_put_text(cf_label_t *lab, const font_t *f, double x, double y,
         const char *s, size_t n)
{
    run_t *r = lab->count > 0 ? &lab->runs[lab->count - 1] : NULL;
    char *t;

    if (r != NULL && lab->merge_ok && r->rule_h == 0 && r->size == f->size
        && r->italic == f->italic && r->math == f->math
        && r->bold == f->bold && r->y == y && r->kind == f->kind
        && r->level == f->level && fabs(r->x + r->width - x) < 1e-9) {
        t = cf_realloc_array(r->text, r->text_len + n + 1, 1);
        if (t == NULL)
            return NAN;
        memcpy(t + r->text_len, s, n);
        r->text = t;
        r->text_len += n;
        t[r->text_len] = '\0';
    } else {
        if (lab->count == lab->cap) {
            size_t cap = lab->cap ? 2 * lab->cap : 8;
            run_t *nr = cf_realloc_array(lab->runs, cap, sizeof *nr);
            if (nr == NULL)
                return NAN;
            lab->runs = nr;
            lab->cap = cap;
        }
        t = cf_malloc(n + 1);
        if (t == NULL)
            return NAN;
        memcpy(t, s, n);
        t[n] = '\0';
        r = &lab->runs[lab->count++];
        memset(r, 0, sizeof *r);
        r->text = t;
        r->text_len = n;
        r->x = x;
        r->y = y;
        r->size = f->size;
        r->level = f->level;
        r->kind = f->kind;
        r->italic = f->italic;
        r->bold = f->bold;
        r->math = f->math;
    }
    if (n == 0) {
        /* an empty run (a fraction rule): no layout */
        r->width = 0;
        return r->x;
    }
    run_measure(lab, r);
    return r->x + r->width;
}

/* TeX's italic correction of one slanted character in font f: how far
** its ink reaches right of its advance width (0 when it does not).  TeX
** reads it from the font's metrics (cmmi10: N 0.109 em, P 0.139 em, V
** 0.222 em); an OpenType text italic has no such table, so it is measured
** on the glyph outline of the character alone. */
double
cf__label_italic_correction(cf_label_t *lab, const font_t *f, const char *s,
                            size_t n)
{
    run_t r;
    char text[8];
    double ic;

    memset(&r, 0, sizeof r);
    memcpy(text, s, n);
    text[n] = '\0';
    r.text = text;
    r.text_len = n;
    r.size = f->size;
    r.italic = f->italic;
    r.bold = f->bold;
    r.math = f->math;
    run_measure(lab, &r);
    if (r.layout == NULL)
        return 0;
    ic = r.ink[2] > r.ink[0] ? fmax(0, r.ink[2] - r.width) : 0;
    g_object_unref(r.layout);
    return ic;
}
