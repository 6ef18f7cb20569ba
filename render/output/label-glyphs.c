/*
** The glyph data of a course page (render/output/label-glyphs.h): the labels
** of the figures are collected by playing their display lists through a
** backend that keeps only the text operations; each run's glyphs (render/
** labels/font.h: whichever fonts shaped it) give its font description (D),
** its shaping (S) and the outlines of its glyphs (G, per bp of size:
** cf__font_glyph_outline, the numbers the tool's outlines are made of);
** then
** each description shapes the character set one character at a time (C), and
** every ordered pair of the characters of the texts and of numbers (digits,
** point, signs, space, =) two at a time: where the pair's advance differs from
** its characters' (kerning) a K line gives the difference.
*/
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include <cairo.h>

#include "backend-text.h"
#include "curvefig/output.h"
#include "font-glyphs.h"
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
    const cf__fonts_t *fonts;      /* the labels' (the first one's) */
    void *fctx;                    /* a context of theirs */
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

/* The index of a face (by its key: the same face at any size). */
static int
face_of(collect_t *c, const cf__font_face_t *face)
{
    int i;
    for (i = 0; i < c->nface; i++)
        if (strcmp(c->face[i], face->key) == 0)
            return i;
    if (c->nface == MAX_FACES) {
        c->failed = true;
        return 0;
    }
    c->face[c->nface] = dup_str(face->key);
    if (c->face[c->nface] == NULL)
        c->failed = true;
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

/* G line of glyph id of face (index f), once. */
static void
put_glyph(collect_t *c, const cf__font_face_t *face, int f, unsigned id)
{
    cairo_scaled_font_t *sf;
    cairo_matrix_t fm;
    cairo_glyph_t g;
    cairo_text_extents_t e;
    double s;
    if (id & CF__FONT_GLYPH_UNKNOWN
        || !add_unique(&c->glyphs, &c->nglyphs, &c->capglyphs,
                       (unsigned)f << 24 | (id & 0xffffff)))
        return;
    sf = cf__font_face_scaled(face);
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
    if (cf__font_glyph_outline(c->cr, sf, id, glyph_op, c) != 0)
        c->failed = true;
    putf(c, c->out, "\n");
}

/* The glyphs of a run: each one's face, id and place (pango units
** from the run's top left), handed to f. */
static int
each_glyph(collect_t *c, const cf__font_glyphs_t *g,
           void (*f)(collect_t *, const cf__font_face_t *, int, unsigned,
                     int, int))
{
    size_t i, k;
    int count = 0;
    for (i = 0; i < g->nspans; i++) {
        const cf__font_span_t *s = &g->spans[i];
        int x = s->x, face = face_of(c, s->face);
        for (k = 0; k < s->nglyphs; k++) {
            const cf__font_glyph_t *gl = &g->glyphs[s->glyph + k];
            if (!(gl->id & CF__FONT_GLYPH_UNKNOWN)
                && gl->id != CF__FONT_GLYPH_EMPTY) {
                f(c, s->face, face, gl->id, x + gl->x,
                  g->baseline - s->shift + gl->y);
                count++;
            }
            x += gl->width;
        }
    }
    return count;
}

static void
glyph_out(collect_t *c, const cf__font_face_t *font, int face, unsigned id,
          int x, int y)
{
    (void)x;
    (void)y;
    put_glyph(c, font, face, id);
}

static void
glyph_placed(collect_t *c, const cf__font_face_t *font, int face,
             unsigned id, int x, int y)
{
    (void)font;
    putf(c, &c->shapes, " %d %u %d %d", face, id, x, y);
}

/* The description of a run's layout: its index (a D line when new). */
static int
desc_of(collect_t *c, const run_t *r, const cf__font_glyphs_t *g)
{
    const char *family = g->family;
    /* the style of the font (a math run's letters are italic glyphs of an
    ** upright font) */
    int italic = g->italic;
    int i;
    for (i = 0; i < c->ndesc; i++)
        if (strcmp(c->desc[i], family) == 0 && c->desc_italic[i] == italic
            && c->desc_bold[i] == r->bold)
            return i;
    if (c->ndesc == MAX_DESCS) {
        c->failed = true;
        return 0;
    }
    c->desc[c->ndesc] = dup_str(family);
    if (c->desc[c->ndesc] == NULL)
        c->failed = true;
    c->desc_italic[c->ndesc] = italic;
    c->desc_bold[c->ndesc] = r->bold;
    putf(c, &c->heads, "D %d %d %d %.9g %.9g %s\n", c->ndesc, italic,
         r->bold, r->baseline / r->size,
         ((double)g->shape.logical[3] / CF__FONT_SCALE - r->baseline)
             / r->size,
         family);
    return c->ndesc++;
}

static void
run_data(collect_t *c, const cf_label_t *label, const run_t *r)
{
    const cf__font_glyphs_t *g;
    char key[64];
    size_t k;
    int d, size, n;
    if (r->shaped == NULL || r->rule_h > 0)
        return;
    g = label->fonts->glyphs(r->shaped);
    d = desc_of(c, r, g);
    size = (int)lround(r->size * CF__FONT_SCALE);
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
    n = each_glyph(c, g, glyph_out);   /* G lines; the count */
    putf(c, &c->shapes, "S %d %d %d %d %d %d %d %d %d %d %d %d %d", d, size,
         g->shape.baseline, g->shape.logical[0], g->shape.logical[1],
         g->shape.logical[2], g->shape.logical[3], g->shape.ink[0],
         g->shape.ink[1], g->shape.ink[2], g->shape.ink[3],
         g->shape.unknown, n);
    each_glyph(c, g, glyph_placed);
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
    /* labels in fonts with faces (the tool's) */
    if (t->label == NULL || t->label->fonts->glyphs == NULL)
        return;
    if (c->fonts == NULL)
        c->fonts = t->label->fonts;
    for (i = 0; i < t->label->count; i++)
        run_data(c, t->label, &t->label->runs[i]);
}


/* The one glyph and its advance (pango units) of the text s[0..n-1]
** alone in description d (its run *run of c's fonts), or 0 when it is not
** one known glyph in one span; two glyphs (ids and advances into id[],
** adv[]) with two = true. */
static bool
shaped_glyphs(collect_t *c, int d, void **run, const char *s, size_t n,
              bool two, unsigned *id, int *adv,
              const cf__font_face_t **face)
{
    cf__font_req_t req;
    cf__font_shape_t sh;
    const cf__font_glyphs_t *g;
    int want = two ? 2 : 1, i;
    bool ok;
    req.family = c->desc[d];
    req.italic = c->desc_italic[d];
    req.bold = c->desc_bold[d];
    req.size = REF_SIZE;
    req.text = s;
    req.len = n;
    if (c->fonts->shape(c->fctx, &req, run, &sh) != 0) {
        c->failed = true;
        return false;
    }
    if (sh.unknown > 0)
        return false;
    g = c->fonts->glyphs(*run);
    ok = g->nspans == 1 && g->nglyphs == (size_t)want;
    for (i = 0; ok && i < want; i++) {
        const cf__font_glyph_t *gl = &g->glyphs[i];
        id[i] = gl->id;
        adv[i] = gl->width;
        /* a pair placed by its advances only */
        ok = !two || (gl->x == 0 && gl->y == 0);
    }
    if (ok && face != NULL)
        *face = g->spans[0].face;
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
kerning(collect_t *c, void **run, int d, size_t ntext, const unsigned *id,
        const int *adv)
{
    size_t i, j;
    for (i = 0; i < c->nchars && !c->failed; i++) {
        if (adv[i] < 0 || !paired(c, ntext, i))
            continue;
        for (j = 0; j < c->nchars; j++) {
            char s[16];
            size_t n;
            unsigned g[2];
            int a[2];
            if (adv[j] < 0 || !paired(c, ntext, j))
                continue;
            n = cf__utf8_encode(c->chars[i], s);
            n += cf__utf8_encode(c->chars[j], s + n);
            /* the same two glyphs (not a ligature), moved apart or
            ** together */
            if (shaped_glyphs(c, d, run, s, n, true, g, a, NULL)
                && g[0] == id[i]
                && g[1] == id[j] && a[1] == adv[j] && a[0] != adv[i])
                putf(c, c->out, "K %d %u %u %.7g\n", d, c->chars[i],
                     c->chars[j],
                     (double)(a[0] - adv[i]) / CF__FONT_SCALE / REF_SIZE);
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
    unsigned *id;
    int *adv;
    for (cp = 0x20; cp < 0x7f; cp++)
        add_unique(&c->chars, &c->nchars, &c->capchars, cp);
    for (cp = 0x391; cp <= 0x3c9; cp++)
        if (cp != 0x3a2)
            add_unique(&c->chars, &c->nchars, &c->capchars, cp);
    for (i = 0; i < sizeof extra / sizeof extra[0]; i++)
        add_unique(&c->chars, &c->nchars, &c->capchars, extra[i]);
    if (c->fonts == NULL)
        return;
    c->fctx = c->fonts->open(c->fonts->self);
    if (c->fctx == NULL) {
        c->failed = true;
        return;
    }
    id = cf_alloc_array(c->nchars, sizeof *id);
    adv = cf_alloc_array(c->nchars, sizeof *adv);
    if (id == NULL || adv == NULL)
        c->failed = true;
    for (d = 0; d < c->ndesc && !c->failed; d++) {
        void *run = NULL;
        for (i = 0; i < c->nchars; i++) {
            char s[8];
            size_t n = cf__utf8_encode(c->chars[i], s);
            const cf__font_face_t *face;
            adv[i] = -1;
            if (shaped_glyphs(c, d, &run, s, n, false, &id[i], &adv[i],
                              &face)) {
                int f = face_of(c, face);
                put_glyph(c, face, f, id[i]);
                putf(c, c->out, "C %d %u %d %u %.7g\n", d, c->chars[i], f,
                     id[i], (double)adv[i] / CF__FONT_SCALE / REF_SIZE);
            } else {
                adv[i] = -1;
            }
        }
        kerning(c, &run, d, ntext, id, adv);
        c->fonts->release(run);
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
    if (c.fctx != NULL)
        c.fonts->close(c.fctx);
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
