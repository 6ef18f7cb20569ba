/*
** Runs of a label: the glyphs of one font, size and baseline, laid out
** and measured by the label's fonts (render/labels/font.h).
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "grow.h"
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

/* What the fonts measure of one text in one run's font. */
typedef struct metrics {
    double width, ascent, descent, baseline;
    double ink[4];             /* as run_t's; all 0 when there is no ink */
    int unknown;               /* characters without a glyph */
} metrics_t;

/* Shape text[0..len) in r's font into the fonts' run *handle and measure
** it; false when the fonts failed (out of memory). */
static bool
shape(cf_label_t *lab, const run_t *r, void **handle, const char *text,
      size_t len, metrics_t *m)
{
    cf__font_req_t req;
    cf__font_shape_t sh;
    char family[CF_FONT_FAMILY_MAX + 16];
    const double u = CF__FONT_SCALE;

    if (r->math)
        snprintf(family, sizeof family, "%s,%s", CF__MATH_FAMILY,
                 lab->family);
    else
        family_for_size(lab->family, r->size, r->italic, r->bold, family,
                        sizeof family);
    req.family = family;
    req.italic = r->italic && !r->math;
    req.bold = r->bold;
    req.size = r->size;
    req.text = text;
    req.len = len;
    if (lab->fonts->shape(lab->fonts_ctx, &req, handle, &sh) != 0)
        return false;
    lab->shaped += len;
    m->baseline = (double)sh.baseline / u;
    m->width = (double)sh.logical[2] / u;
    m->ascent = m->baseline - (double)sh.logical[1] / u;
    m->descent = (double)(sh.logical[1] + sh.logical[3]) / u - m->baseline;
    m->ink[0] = (double)(sh.ink[0] - sh.logical[0]) / u;
    m->ink[1] = (double)sh.ink[1] / u - m->baseline;
    m->ink[2] = m->ink[0] + (double)sh.ink[2] / u;
    m->ink[3] = m->ink[1] + (double)sh.ink[3] / u;
    m->unknown = sh.unknown;
    if (sh.ink[2] == 0 || sh.ink[3] == 0) {
        /* spaces: no ink */
        m->ink[0] = m->ink[2] = 0;
        m->ink[1] = m->ink[3] = 0;
    }
    return true;
}

/* Shape and measure the whole run r in its own run of the fonts (which
** then holds its text); false when the fonts failed (out of memory). */
static bool
run_measure(cf_label_t *lab, run_t *r)
{
    metrics_t m;
    if (!shape(lab, r, &r->shaped, r->text, r->text_len, &m))
        return false;
    r->width = m.width;
    r->ascent = m.ascent;
    r->descent = m.descent;
    r->baseline = m.baseline;
    memcpy(r->ink, m.ink, sizeof m.ink);
    r->unknown = m.unknown;
    r->tail = 0;
    r->tail_w = m.width;
    r->stale = false;
    return true;
}

/* A run grows a character at a time (a word, a formula's letters); laying
** the whole run out again at each character made a label of n characters
** cost n^2 (a 1000-byte label 1.5 to 8 s).  Shaping is local -- kerning
** pairs and ligatures join neighbours -- so only the run's tail is shaped
** again: the text from byte r->tail on (TAIL to 2 TAIL bytes, moved
** forward by TAIL at a time), whose width alone before the new bytes is
** r->tail_w.  The glyphs of the tail sit where they sit in the whole run
** measured from its end, so the run widens by what the tail widened and
** the tail's ink joins the run's ink at the run's old width less the
** tail's.  The whole run is shaped once more at the end of the label
** (cf__label_runs_finish), for its glyphs and its exact extents. */
#define TAIL 16

static bool
grow_measure(cf_label_t *lab, run_t *r, size_t old_len)
{
    metrics_t m;
    size_t t = r->tail;
    double before = r->tail_w, off;
    if (old_len - t > 2 * TAIL) {
        t = old_len - TAIL;
        while (t < old_len && ((unsigned char)r->text[t] & 0xC0) == 0x80)
            t++;
        if (!shape(lab, r, &lab->scratch, r->text + t, old_len - t, &m))
            return false;
        before = m.width;
    }
    if (!shape(lab, r, &lab->scratch, r->text + t, r->text_len - t, &m))
        return false;
    off = r->width - before;
    r->width = off + m.width;
    if (m.ink[2] > m.ink[0] && m.ink[3] > m.ink[1]) {
        m.ink[0] += off;
        m.ink[2] += off;
        if (r->ink[2] > r->ink[0] && r->ink[3] > r->ink[1]) {
            r->ink[0] = fmin(r->ink[0], m.ink[0]);
            r->ink[1] = fmin(r->ink[1], m.ink[1]);
            r->ink[2] = fmax(r->ink[2], m.ink[2]);
            r->ink[3] = fmax(r->ink[3], m.ink[3]);
        } else {
            memcpy(r->ink, m.ink, sizeof m.ink);
        }
    }
    r->ascent = fmax(r->ascent, m.ascent);
    r->descent = fmax(r->descent, m.descent);
    r->baseline = fmax(r->baseline, m.baseline);
    r->tail = t;
    r->tail_w = m.width;
    r->stale = true;
    return true;
}

bool
cf__label_runs_finish(cf_label_t *lab)
{
    bool ok = true;
    for (size_t i = 0; i < lab->count; i++)
        if (lab->runs[i].stale && !run_measure(lab, &lab->runs[i]))
            ok = false;
    if (lab->scratch != NULL) {
        lab->fonts->release(lab->scratch);
        lab->scratch = NULL;
    }
    return ok;
}

size_t
cf__label_shaped_bytes(const cf_label_t *lab)
{
    return lab->shaped;
}

double
cf__label_put_text(cf_label_t *lab, const font_t *f, double x, double y,
         const char *s, size_t n)
{
    run_t *r = lab->count > 0 ? &lab->runs[lab->count - 1] : NULL;
    char *t;
    size_t old_len;

    if (r != NULL && lab->merge_ok && r->rule_h == 0 && r->size == f->size
        && r->italic == f->italic && r->math == f->math
        && r->bold == f->bold && r->y == y && r->kind == f->kind
        && r->level == f->level && fabs(r->x + r->width - x) < 1e-9) {
        t = cf_realloc_array(r->text, r->text_len + n + 1, 1);
        if (t == NULL)
            return NAN;
        memcpy(t + r->text_len, s, n);
        r->text = t;
        old_len = r->text_len;
        r->text_len += n;
        t[r->text_len] = '\0';
        if (n > 0 && old_len > 0) {
            if (!grow_measure(lab, r, old_len))
                return NAN;
            return r->x + r->width;
        }
    } else {
        run_t *nr = cf__grow_array(lab->runs, &lab->cap, lab->count + 1,
                                   sizeof *nr, 8);
        if (nr == NULL)
            return NAN;
        lab->runs = nr;
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
    if (!run_measure(lab, r))
        return NAN;
    return r->x + r->width;
}

/* The advance width and ink box (relative to the baseline origin, y
** down) of s[0..n) alone in font f, without adding a run; false when
** the fonts could not shape it. */
bool
cf__label_measure(cf_label_t *lab, const font_t *f, const char *s, size_t n,
                  double *width, double ink[4])
{
    run_t r;
    char text[16];

    if (n >= sizeof text)
        return false;
    memset(&r, 0, sizeof r);
    memcpy(text, s, n);
    text[n] = '\0';
    r.text = text;
    r.text_len = n;
    r.size = f->size;
    r.italic = f->italic;
    r.bold = f->bold;
    r.math = f->math;
    if (!run_measure(lab, &r)) {
        lab->fonts->release(r.shaped);
        return false;
    }
    *width = r.width;
    memcpy(ink, r.ink, sizeof r.ink);
    lab->fonts->release(r.shaped);
    return true;
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
    double w, ink[4];
    if (!cf__label_measure(lab, f, s, n, &w, ink))
        return NAN;   /* the fonts ran out of memory */
    return ink[2] > ink[0] ? fmax(0, ink[2] - w) : 0;
}
