/*
** The glyph data of a course page (render/output/label-glyphs.h): the labels
** of the figures are collected by playing their display lists through a
** backend that keeps only the text operations; each run's pango layout gives
** its font description (D), its shaping (S) and the outlines of its glyphs (G,
** per bp of size: cf__pango_glyph_outline, the numbers the tool's outlines
** are made of); then
** each description shapes the character set one character at a time (C), and
** every ordered pair of the characters of the texts and of numbers (digits,
** point, signs, space, =) two at a time: where the pair's advance differs from
** its characters' (kerning) a K line gives the difference.
*/
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include <pango/pangocairo.h>

#include "backend-text.h"
#include "curvefig/output.h"
#include "font-pango.h"
#include "grow.h"
#include "label-glyphs.h"
#include "label-impl.h"
#include "output-private.h"

#define MAX_DESCS 64
#define MAX_FACES 64
#define REF_SIZE 100.0   /* bp: the size characters are shaped at */

typedef struct collect {
    cf__buf_t *out;           /* G, C lines, in order */
    cf__buf_t heads, shapes;  /* D lines; S lines (after every G) */
    char *desc[MAX_DESCS];
    int desc_italic[MAX_DESCS], desc_bold[MAX_DESCS];
    int ndesc;
    char *face[MAX_FACES];
    int nface;
    unsigned *glyphs;         /* face << 24 | glyph, written */
    size_t nglyphs, capglyphs;
    unsigned *chars;          /* code points of the texts */
    size_t nchars, capchars;
    cf__buf_t shaped_keys;    /* "d size text\n" of each S line */
    PangoContext *ctx;
    cairo_t *cr;
    bool failed;
} collect_t;

static void
putf(collect_t *c, cf__buf_t *b, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static void
putf(collect_t *c, cf__buf_t *b, const char *fmt, ...)
{
    char line[512];
    va_list ap;
    int n;
    va_start(ap, fmt);
    n = vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    if (n < 0 || (size_t)n >= sizeof line
        || cf__buf_append(b, line, (size_t)n) != 0)
        c->failed = true;
}

static char *
dup_str(const char *s)
{
    size_t n = strlen(s);
    char *t = cf_malloc(n + 1);
    if (t != NULL)
        memcpy(t, s, n + 1);
    return t;
}

static bool
add_unique(unsigned **a, size_t *n, size_t *cap, unsigned v)
{
    unsigned *t;
    size_t i;
    for (i = 0; i < *n; i++)
        if ((*a)[i] == v)
            return false;
    t = cf__grow_array(*a, cap, *n + 1, sizeof *t, 256);
    if (t == NULL)
        return false;
    *a = t;
    (*a)[(*n)++] = v;
    return true;
}

/* The index of the face of font (its description without size). */
static int
face_of(collect_t *c, PangoFont *font)
{
    PangoFontDescription *d = pango_font_describe(font);
    char *s;
    int i;
    pango_font_description_unset_fields(d, PANGO_FONT_MASK_SIZE);
    s = pango_font_description_to_string(d);
    pango_font_description_free(d);
    for (i = 0; i < c->nface; i++)
        if (strcmp(c->face[i], s) == 0) {
            g_free(s);
            return i;
        }
    if (c->nface == MAX_FACES) {
        g_free(s);
        c->failed = true;
        return 0;
    }
    c->face[c->nface] = dup_str(s);
    g_free(s);
    return c->nface++;
}

/* A piece of a G line: op and its points (per bp, as written already). */
static void
glyph_op(void *u, char op, const double *v)
{
    collect_t *c = u;
    int n = op == 'C' ? 3 : op == 'Z' ? 0 : 1, k;
    putf(c, c->out, " %c", op);
    for (k = 0; k < 2 * n; k++)
        putf(c, c->out, " %.5g", v[k]);
}

/* G line of glyph id of font (face f), once. */
static void
put_glyph(collect_t *c, PangoFont *font, int f, PangoGlyph id)
{
    cairo_scaled_font_t *sf;
    cairo_matrix_t fm;
    cairo_glyph_t g;
    cairo_text_extents_t e;
    double s;
    if (id & PANGO_GLYPH_UNKNOWN_FLAG
        || !add_unique(&c->glyphs, &c->nglyphs, &c->capglyphs,
                       (unsigned)f << 24 | (id & 0xffffff)))
        return;
    sf = pango_cairo_font_get_scaled_font(PANGO_CAIRO_FONT(font));
    if (sf == NULL) {
        c->failed = true;
        return;
    }
    cairo_scaled_font_get_font_matrix(sf, &fm);
    s = fm.yy != 0 ? fm.yy : 1;
    g.index = id;
    g.x = g.y = 0;
    cairo_scaled_font_glyph_extents(sf, &g, 1, &e);
    putf(c, c->out, "G %d %u %.9g %.9g %.9g %.9g", f, id, e.x_bearing / s,
         e.y_bearing / s, (e.x_bearing + e.width) / s,
         (e.y_bearing + e.height) / s);
    if (cf__pango_glyph_outline(c->cr, font, id, glyph_op, c) != 0)
        c->failed = true;
    putf(c, c->out, "\n");
}

/* The glyphs of a layout: each one's face, id and place (pango units
** from the layout's top left), handed to f. */
static int
each_glyph(collect_t *c, PangoLayout *l,
           void (*f)(collect_t *, PangoFont *, int, PangoGlyph, int, int))
{
    PangoLayoutIter *it = pango_layout_get_iter(l);
    int count = 0;
    do {
        PangoLayoutRun *run = pango_layout_iter_get_run_readonly(it);
        PangoRectangle logical;
        int i, x, base, face;
        if (run == NULL)
            continue;
        pango_layout_iter_get_run_extents(it, NULL, &logical);
        base = pango_layout_iter_get_baseline(it);
        x = logical.x;
        face = face_of(c, run->item->analysis.font);
        for (i = 0; i < run->glyphs->num_glyphs; i++) {
            const PangoGlyphInfo *g = &run->glyphs->glyphs[i];
            if (!(g->glyph & PANGO_GLYPH_UNKNOWN_FLAG)
                && g->glyph != PANGO_GLYPH_EMPTY) {
                f(c, run->item->analysis.font, face, g->glyph,
                  x + g->geometry.x_offset, base + g->geometry.y_offset);
                count++;
            }
            x += g->geometry.width;
        }
    } while (pango_layout_iter_next_run(it));
    pango_layout_iter_free(it);
    return count;
}

static void
glyph_out(collect_t *c, PangoFont *font, int face, PangoGlyph id, int x,
          int y)
{
    (void)x;
    (void)y;
    put_glyph(c, font, face, id);
}

static void
glyph_placed(collect_t *c, PangoFont *font, int face, PangoGlyph id, int x,
             int y)
{
    (void)font;
    putf(c, &c->shapes, " %d %u %d %d", face, id, x, y);
}

/* The description of a run's layout: its index (a D line when new). */
static int
desc_of(collect_t *c, const run_t *r)
{
    const PangoFontDescription *fd =
        pango_layout_get_font_description(r->shaped);
    const char *family = pango_font_description_get_family(fd);
    /* the style of the font (a math run's letters are italic glyphs of an
    ** upright font) */
    int italic = pango_font_description_get_style(fd) != PANGO_STYLE_NORMAL;
    PangoRectangle logical;
    int i;
    for (i = 0; i < c->ndesc; i++)
        if (strcmp(c->desc[i], family) == 0 && c->desc_italic[i] == italic
            && c->desc_bold[i] == r->bold)
            return i;
    if (c->ndesc == MAX_DESCS) {
        c->failed = true;
        return 0;
    }
    pango_layout_get_extents(r->shaped, NULL, &logical);
    c->desc[c->ndesc] = dup_str(family);
    c->desc_italic[c->ndesc] = italic;
    c->desc_bold[c->ndesc] = r->bold;
    putf(c, &c->heads, "D %d %d %d %.9g %.9g %s\n", c->ndesc, italic,
         r->bold, r->baseline / r->size,
         ((double)logical.height / PANGO_SCALE - r->baseline) / r->size,
         family);
    return c->ndesc++;
}

static void
run_data(collect_t *c, const run_t *r)
{
    PangoRectangle ink, logical;
    char key[64];
    size_t k;
    int d, size, n;
    if (r->shaped == NULL || r->rule_h > 0)
        return;
    d = desc_of(c, r);
    size = (int)lround(r->size * PANGO_SCALE);
    for (k = 0; k < r->text_len;) {
        unsigned cp;
        size_t len = cf__utf8_decode(r->text, r->text_len, k, &cp);
        if (len == 0)
            break;
        add_unique(&c->chars, &c->nchars, &c->capchars, cp);
        k += len;
    }
    snprintf(key, sizeof key, "%d %d %zu ", d, size, r->text_len);
    for (k = 0; k + strlen(key) + r->text_len < c->shaped_keys.size;) {
        const char *line = (const char *)c->shaped_keys.data + k;
        const char *nl = memchr(line, '\n', c->shaped_keys.size - k);
        if (strncmp(line, key, strlen(key)) == 0
            && memcmp(line + strlen(key), r->text, r->text_len) == 0
            && line + strlen(key) + r->text_len == nl)
            return;   /* shaped already */
        k = (size_t)(nl - (const char *)c->shaped_keys.data) + 1;
    }
    if (cf__buf_append(&c->shaped_keys, key, strlen(key)) != 0
        || cf__buf_append(&c->shaped_keys, r->text, r->text_len) != 0
        || cf__buf_append(&c->shaped_keys, "\n", 1) != 0)
        c->failed = true;
    n = each_glyph(c, r->shaped, glyph_out);   /* G lines; the count */
    pango_layout_get_extents(r->shaped, &ink, &logical);
    putf(c, &c->shapes, "S %d %d %d %d %d %d %d %d %d %d %d %d %d", d, size,
         pango_layout_get_baseline(r->shaped), logical.x, logical.y,
         logical.width, logical.height, ink.x, ink.y, ink.width, ink.height,
         pango_layout_get_unknown_glyphs_count(r->shaped), n);
    each_glyph(c, r->shaped, glyph_placed);
    putf(c, &c->shapes, " %zu ", r->text_len);
    if (cf__buf_append(&c->shapes, r->text, r->text_len) != 0
        || cf__buf_append(&c->shapes, "\n", 1) != 0)
        c->failed = true;
}

/* ---- the collecting backend --------------------------------------------- */


static void
text_op(void *ctx, const cf__text_op_t *t)
{
    collect_t *c = ctx;
    size_t i;
    /* labels in pango's fonts (the tool's) */
    if (t->label == NULL || t->label->fonts != &cf__pango_fonts)
        return;
    if (c->ctx == NULL) {
        c->ctx = cf__pango_fonts_context(t->label->fonts_ctx);
        g_object_ref(c->ctx);
    }
    for (i = 0; i < t->label->count; i++)
        run_data(c, &t->label->runs[i]);
}


/* The one glyph and its advance (pango units) of the text s[0..n-1]
** alone in layout l, or 0 when it is not one known glyph in one run; two
** glyphs (ids and advances into id[], adv[]) with two = true. */
static bool
shaped_glyphs(PangoLayout *l, const char *s, size_t n, bool two,
              PangoGlyph *id, int *adv, PangoFont **font)
{
    PangoLayoutIter *it;
    PangoLayoutRun *run = NULL;
    int nruns = 0, want = two ? 2 : 1, i;
    bool ok;
    pango_layout_set_text(l, s, (int)n);
    if (pango_layout_get_unknown_glyphs_count(l) > 0)
        return false;
    /* one run (the line's end is a NULL run) */
    it = pango_layout_get_iter(l);
    do {
        PangoLayoutRun *r = pango_layout_iter_get_run_readonly(it);
        if (r != NULL) {
            run = r;
            nruns++;
        }
    } while (pango_layout_iter_next_run(it));
    ok = nruns == 1 && run->glyphs->num_glyphs == want;
    for (i = 0; ok && i < want; i++) {
        const PangoGlyphInfo *g = &run->glyphs->glyphs[i];
        id[i] = g->glyph;
        adv[i] = g->geometry.width;
        /* a pair placed by its advances only */
        ok = !two || (g->geometry.x_offset == 0 && g->geometry.y_offset == 0);
    }
    if (ok && font != NULL)
        *font = run->item->analysis.font;
    pango_layout_iter_free(it);
    return ok;
}

/* The characters paired for kerning: those of the texts (the first
** ntext of c->chars) and those of the numbers a slider may write. */
static bool
paired(const collect_t *c, size_t ntext, size_t i)
{
    static const char numeric[] = "0123456789.,+-= ";
    unsigned cp = c->chars[i];
    return i < ntext || cp == 0x2212
           || (cp < 0x80 && cp != 0 && strchr(numeric, (int)cp) != NULL);
}

/* K lines of description d: the pairs of paired characters whose advance
** together differs from their advances alone (id[], adv[]: each
** character's glyph and advance alone, adv < 0 when it has none). */
static void
kerning(collect_t *c, PangoLayout *l, int d, size_t ntext,
        const PangoGlyph *id, const int *adv)
{
    size_t i, j;
    for (i = 0; i < c->nchars && !c->failed; i++) {
        if (adv[i] < 0 || !paired(c, ntext, i))
            continue;
        for (j = 0; j < c->nchars; j++) {
            char s[16];
            size_t n;
            PangoGlyph g[2];
            int a[2];
            if (adv[j] < 0 || !paired(c, ntext, j))
                continue;
            n = cf__utf8_encode(c->chars[i], s);
            n += cf__utf8_encode(c->chars[j], s + n);
            /* the same two glyphs (not a ligature), moved apart or
            ** together */
            if (shaped_glyphs(l, s, n, true, g, a, NULL) && g[0] == id[i]
                && g[1] == id[j] && a[1] == adv[j] && a[0] != adv[i])
                putf(c, c->out, "K %d %u %u %.7g\n", d, c->chars[i],
                     c->chars[j],
                     (double)(a[0] - adv[i]) / PANGO_SCALE / REF_SIZE);
        }
    }
}

/* C lines: the character set in each description; K lines: its pairs. */
static void
characters(collect_t *c)
{
    static const unsigned extra[] = { 0x2212, 0x2032, 0x22c5, 0xd7, 0x2264,
        0x2265, 0x2260, 0x221e, 0x2026, 0x2192, 0x2208, 0xb1, 0x3d1, 0x3d5,
        0x3d6, 0x3f5 };
    unsigned cp;
    size_t i, ntext = c->nchars;
    int d;
    PangoGlyph *id;
    int *adv;
    for (cp = 0x20; cp < 0x7f; cp++)
        add_unique(&c->chars, &c->nchars, &c->capchars, cp);
    for (cp = 0x391; cp <= 0x3c9; cp++)
        if (cp != 0x3a2)
            add_unique(&c->chars, &c->nchars, &c->capchars, cp);
    for (i = 0; i < sizeof extra / sizeof extra[0]; i++)
        add_unique(&c->chars, &c->nchars, &c->capchars, extra[i]);
    if (c->ctx == NULL)
        return;
    id = cf_alloc_array(c->nchars, sizeof *id);
    adv = cf_alloc_array(c->nchars, sizeof *adv);
    if (id == NULL || adv == NULL)
        c->failed = true;
    for (d = 0; d < c->ndesc && !c->failed; d++) {
        PangoLayout *l = pango_layout_new(c->ctx);
        PangoFontDescription *fd = pango_font_description_new();
        pango_font_description_set_family(fd, c->desc[d]);
        pango_font_description_set_style(fd, c->desc_italic[d]
                                                 ? PANGO_STYLE_ITALIC
                                                 : PANGO_STYLE_NORMAL);
        pango_font_description_set_weight(fd, c->desc_bold[d]
                                                  ? PANGO_WEIGHT_BOLD
                                                  : PANGO_WEIGHT_NORMAL);
        pango_font_description_set_absolute_size(fd, REF_SIZE * PANGO_SCALE);
        pango_layout_set_font_description(l, fd);
        pango_font_description_free(fd);
        for (i = 0; i < c->nchars; i++) {
            char s[8];
            size_t n = cf__utf8_encode(c->chars[i], s);
            PangoFont *font;
            adv[i] = -1;
            if (shaped_glyphs(l, s, n, false, &id[i], &adv[i], &font)) {
                int face = face_of(c, font);
                put_glyph(c, font, face, id[i]);
                putf(c, c->out, "C %d %u %d %u %.7g\n", d, c->chars[i], face,
                     id[i], (double)adv[i] / PANGO_SCALE / REF_SIZE);
            } else {
                adv[i] = -1;
            }
        }
        kerning(c, l, d, ntext, id, adv);
        g_object_unref(l);
    }
    cf_free(id);
    cf_free(adv);
}

cf_status_t
cf__glyph_data(cf_figure_t *const *figs, size_t n, cf__buf_t *out,
               cf_diag_t *diag)
{
    collect_t c;
    cf__buf_t body;
    cf_status_t st = CF_STATUS_OK;
    size_t i;
    int k;
    cairo_surface_t *rec;
    const cf__backend_t collector = cf__text_backend("glyph data", text_op);
    memset(&c, 0, sizeof c);
    memset(&body, 0, sizeof body);
    c.out = &body;
    rec = cairo_recording_surface_create(CAIRO_CONTENT_ALPHA, NULL);
    c.cr = cairo_create(rec);
    cairo_surface_destroy(rec);
    for (i = 0; i < n && st == CF_STATUS_OK; i++)
        st = cf__figure_play(figs[i], 0, &collector, &c, diag);
    if (st == CF_STATUS_OK) {
        characters(&c);
        if (c.failed || body.failed || c.heads.failed || c.shapes.failed
            || cf__buf_append(out, "curvefig-glyphs 1\n", 18) != 0
            || cf__buf_append(out, c.heads.data, c.heads.size) != 0
            || cf__buf_append(out, body.data, body.size) != 0
            || cf__buf_append(out, c.shapes.data, c.shapes.size) != 0)
            st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                             "out of memory gathering the glyphs of the "
                             "labels (or more than %d fonts)", MAX_FACES);
    }
    cairo_destroy(c.cr);
    if (c.ctx != NULL)
        g_object_unref(c.ctx);
    for (k = 0; k < c.ndesc; k++)
        cf_free(c.desc[k]);
    for (k = 0; k < c.nface; k++)
        cf_free(c.face[k]);
    cf_free(c.glyphs);
    cf_free(c.chars);
    cf__buf_free(&body);
    cf__buf_free(&c.heads);
    cf__buf_free(&c.shapes);
    cf__buf_free(&c.shaped_keys);
    return st;
}

cf_status_t
cf_figures_glyph_data(cf_figure_t *const *figs, size_t n, char **text,
                      size_t *size, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    cf__buf_t b;
    cf_status_t st;
    size_t i;
    if (text != NULL)
        *text = NULL;
    if (size != NULL)
        *size = 0;
    if (text == NULL || size == NULL || (figs == NULL && n > 0))
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "figures, text or size is NULL");
    for (i = 0; i < n; i++)
        if (figs[i] == NULL)
            return cf_diag_set(diag, CF_STATUS_INVALID_ARG, (long)i,
                               "figure %zu is NULL", i);
    memset(&b, 0, sizeof b);
    st = cf__glyph_data(figs, n, &b, diag);
    if (st == CF_STATUS_OK && cf__buf_append(&b, "", 1) != 0)
        st = cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                         "out of memory for the glyph data");
    if (st != CF_STATUS_OK) {
        cf__buf_free(&b);
        return st;
    }
    *text = (char *)b.data;
    *size = b.size - 1;
    return CF_STATUS_OK;
}
