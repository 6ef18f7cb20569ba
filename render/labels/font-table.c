/*
** Fonts for labels from glyph data (render/labels/font-table.h): the text
** render/output/label-glyphs.c writes at export time from the tool's
** shaping (render/backends/font-native.c: pango's numbers),
** which the browser module loads and sets its labels in:
**
**   curvefig-glyphs 1
**   D d italic bold ascent descent family         a font description;
**                                                 ascent, descent per bp
**   G face glyph x0 y0 x1 y1 M x y L x y C ... Z  a glyph's ink box and
**                                                 outline per bp of size
**   C d codepoint face glyph advance              a character alone
**   K d first second kern                         a pair's advance less
**                                                 its characters' (per bp)
**   S d size baseline lx ly lw lh ix iy iw ih unknown n
**     (face glyph x y) * n  bytes text            a text as the tool
**                                                 shaped it (pango units)
**
** A run whose description, size and text were shaped at export is that
** shaping, the same numbers as the tool's; another is composed from its
** characters (C) in the description of that family, style and weight (or,
** failing that, of that style and weight), two characters with a K line
** moved by its kern; characters without data are unknown glyphs, drawn as
** nothing.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "curvefig/core.h"
#include "font-table.h"
#include "grow.h"

typedef struct desc {
    int italic, bold;
    double ascent, descent;
    char *family;
} desc_t;

typedef struct glyph {
    int face, id;
    double ink[4];
    double *pts;          /* the outline's coordinates */
    unsigned char *ops;   /* 'M' 'L' 'C' 'Z' */
    size_t nops, capops, npts, cappts;
} glyph_t;

typedef struct chr { int d; unsigned cp; int glyph; double advance; } chr_t;

typedef struct kern { int d; unsigned first, second; double kern; } kern_t;

typedef struct placed { int glyph; int x, y; } placed_t;

typedef struct shaped {
    int d, size, baseline, unknown;
    int logical[4], ink[4];
    placed_t *g;
    int n;
    char *text;
    size_t len;
} shaped_t;

struct cf__font_table {
    desc_t *d;
    glyph_t *g;
    chr_t *c;
    kern_t *k;
    shaped_t *s;
    size_t nd, ng, nc, nk, ns;
    size_t capd, capg, capc, capk, caps;
};

/* a run: its shaping and its size */
typedef struct run {
    shaped_t shape;       /* own g unless borrowed from the table */
    bool own;
    double size;          /* bp */
} run_t;

/* ---- the data ----------------------------------------------------------- */

static void
clear(cf__font_table_t *t)
{
    size_t i;
    for (i = 0; i < t->nd; i++)
        cf_free(t->d[i].family);
    for (i = 0; i < t->ng; i++) {
        cf_free(t->g[i].pts);
        cf_free(t->g[i].ops);
    }
    for (i = 0; i < t->ns; i++) {
        cf_free(t->s[i].g);
        cf_free(t->s[i].text);
    }
    cf_free(t->d);
    cf_free(t->g);
    cf_free(t->c);
    cf_free(t->k);
    cf_free(t->s);
    memset(t, 0, sizeof *t);
}

cf__font_table_t *
cf__font_table_create(void)
{
    return cf_calloc(1, sizeof(cf__font_table_t));
}

void
cf__font_table_destroy(cf__font_table_t *t)
{
    if (t == NULL)
        return;
    clear(t);
    cf_free(t);
}

/* One more element of *arr (count *n, capacity *cap): its address, or
** NULL when out of memory. */
static void *
push(void *arr, size_t *cap, size_t n, size_t size, void **out)
{
    void *a = cf__grow_array(*(void **)arr, cap, n + 1, size, 16);
    if (a == NULL)
        return NULL;
    *(void **)arr = a;
    *out = (char *)a + n * size;
    return *out;
}

static int
find_glyph(const cf__font_table_t *t, int face, int id)
{
    size_t i;
    for (i = 0; i < t->ng; i++)
        if (t->g[i].face == face && t->g[i].id == id)
            return (int)i;
    return -1;
}

static const char *
num(const char *p, double *v)
{
    char *e;
    *v = strtod(p, &e);
    return e == p || !isfinite(*v) ? NULL : e;
}

static const char *
inum(const char *p, long *v)
{
    char *e;
    *v = strtol(p, &e, 10);
    return e == p || *v < -2147483647L || *v > 2147483647L ? NULL : e;
}

static const char *
skip(const char *p)
{
    while (*p == ' ')
        p++;
    return p;
}

static int
parse_glyph(cf__font_table_t *t, const char *p)
{
    glyph_t g, *slot;
    long face, id;
    int i;
    memset(&g, 0, sizeof g);
    if ((p = inum(p, &face)) == NULL || (p = inum(p, &id)) == NULL)
        return -1;
    g.face = (int)face;
    g.id = (int)id;
    for (i = 0; i < 4; i++)
        if ((p = num(p, &g.ink[i])) == NULL)
            return -1;
    for (p = skip(p); *p != '\0' && *p != '\n'; p = skip(p)) {
        char op = *p++;
        int k = op == 'C' ? 6 : op == 'Z' ? 0 : 2;
        unsigned char *ops;
        double *pts;
        if (op != 'M' && op != 'L' && op != 'C' && op != 'Z')
            goto bad;
        ops = cf__grow_array(g.ops, &g.capops, g.nops + 1, 1, 16);
        if (ops == NULL)
            goto bad;
        g.ops = ops;
        g.ops[g.nops++] = (unsigned char)op;
        pts = cf__grow_array(g.pts, &g.cappts, g.npts + (size_t)k,
                             sizeof *g.pts, 32);
        if (pts == NULL)
            goto bad;
        g.pts = pts;
        for (i = 0; i < k; i++)
            if ((p = num(p, &g.pts[g.npts++])) == NULL)
                goto bad;
    }
    if (find_glyph(t, g.face, g.id) >= 0
        || push(&t->g, &t->capg, t->ng, sizeof *t->g, (void **)&slot)
               == NULL)
        goto bad;
    *slot = g;
    t->ng++;
    return 0;
bad:
    cf_free(g.ops);
    cf_free(g.pts);
    return -1;
}

static int
parse_shaped(cf__font_table_t *t, const char *p)
{
    shaped_t s, *slot;
    long v[13], len;
    int i, k;
    memset(&s, 0, sizeof s);
    for (i = 0; i < 13; i++)
        if ((p = inum(p, &v[i])) == NULL)
            return -1;
    s.d = (int)v[0];
    s.size = (int)v[1];
    s.baseline = (int)v[2];
    for (i = 0; i < 4; i++) {
        s.logical[i] = (int)v[3 + i];
        s.ink[i] = (int)v[7 + i];
    }
    s.unknown = (int)v[11];
    s.n = (int)v[12];
    if (s.d < 0 || (size_t)s.d >= t->nd || s.n < 0 || s.n > 100000)
        return -1;
    s.g = cf_calloc((size_t)s.n + 1, sizeof *s.g);
    if (s.g == NULL)
        return -1;
    for (i = 0; i < s.n; i++) {
        long face, id, x, y;
        if ((p = inum(p, &face)) == NULL || (p = inum(p, &id)) == NULL
            || (p = inum(p, &x)) == NULL || (p = inum(p, &y)) == NULL)
            goto bad;
        k = find_glyph(t, (int)face, (int)id);
        if (k < 0)
            goto bad;
        s.g[i] = (placed_t){ k, (int)x, (int)y };
    }
    if ((p = inum(p, &len)) == NULL || *p != ' ' || len < 0
        || strlen(p + 1) < (size_t)len)
        goto bad;
    s.len = (size_t)len;
    s.text = cf_malloc(s.len + 1);
    if (s.text == NULL
        || push(&t->s, &t->caps, t->ns, sizeof *t->s, (void **)&slot)
               == NULL)
        goto bad;
    memcpy(s.text, p + 1, s.len);
    s.text[s.len] = '\0';
    *slot = s;
    t->ns++;
    return 0;
bad:
    cf_free(s.g);
    cf_free(s.text);
    return -1;
}

static int
parse_desc(cf__font_table_t *t, const char *p)
{
    desc_t d, *slot;
    long v[3];
    const char *f;
    size_t n;
    if ((p = inum(p, &v[0])) == NULL || v[0] < 0 || (size_t)v[0] != t->nd
        || (p = inum(p, &v[1])) == NULL || (p = inum(p, &v[2])) == NULL
        || (p = num(p, &d.ascent)) == NULL
        || (p = num(p, &d.descent)) == NULL)
        return -1;
    f = skip(p);
    n = strcspn(f, "\n");
    d.italic = v[1] != 0;
    d.bold = v[2] != 0;
    d.family = cf_malloc(n + 1);
    if (d.family == NULL
        || push(&t->d, &t->capd, t->nd, sizeof *t->d, (void **)&slot)
               == NULL) {
        cf_free(d.family);
        return -1;
    }
    memcpy(d.family, f, n);
    d.family[n] = '\0';
    *slot = d;
    t->nd++;
    return 0;
}

static int
parse_line(cf__font_table_t *t, const char *p)
{
    long v[4];
    double a;
    int k;
    switch (*p) {
    case 'D':
        return parse_desc(t, p + 1);
    case 'G':
        return parse_glyph(t, p + 1);
    case 'C': {
        chr_t *c;
        if ((p = inum(p + 1, &v[0])) == NULL || (p = inum(p, &v[1])) == NULL
            || (p = inum(p, &v[2])) == NULL || (p = inum(p, &v[3])) == NULL
            || (p = num(p, &a)) == NULL || v[0] < 0 || (size_t)v[0] >= t->nd
            || v[1] < 0)
            return -1;
        k = find_glyph(t, (int)v[2], (int)v[3]);
        if (k < 0
            || push(&t->c, &t->capc, t->nc, sizeof *t->c, (void **)&c)
                   == NULL)
            return -1;
        *c = (chr_t){ (int)v[0], (unsigned)v[1], k, a };
        t->nc++;
        return 0;
    }
    case 'K': {
        kern_t *kk;
        if ((p = inum(p + 1, &v[0])) == NULL || (p = inum(p, &v[1])) == NULL
            || (p = inum(p, &v[2])) == NULL || (p = num(p, &a)) == NULL
            || v[0] < 0 || (size_t)v[0] >= t->nd || v[1] < 0 || v[2] < 0
            || push(&t->k, &t->capk, t->nk, sizeof *t->k, (void **)&kk)
                   == NULL)
            return -1;
        *kk = (kern_t){ (int)v[0], (unsigned)v[1], (unsigned)v[2], a };
        t->nk++;
        return 0;
    }
    case 'S':
        return parse_shaped(t, p + 1);
    default:
        return -1;
    }
}

int
cf__font_table_load(cf__font_table_t *t, const char *data, size_t len,
                    int *bad_line)
{
    char *copy = cf_malloc(len + 1), *p, *end;
    int line = 1;
    clear(t);
    *bad_line = 0;
    if (copy == NULL)
        return -1;
    memcpy(copy, data, len);
    copy[len] = '\0';
    if (strncmp(copy, "curvefig-glyphs 1\n", 18) != 0) {
        cf_free(copy);
        *bad_line = 1;
        return -1;
    }
    for (p = copy + 18; *p != '\0'; p = end + 1) {
        char *nl = strchr(p, '\n');
        line++;
        end = nl != NULL ? nl : p + strlen(p) - 1;
        if (nl != NULL)
            *nl = '\0';
        if (*p != '\0' && parse_line(t, p) != 0) {
            cf_free(copy);
            clear(t);
            *bad_line = line;
            return -1;
        }
        if (nl == NULL)
            break;
    }
    cf_free(copy);
    return 0;
}

/* ---- shaping ------------------------------------------------------------ */

/* The description for a request: the same family, style and weight;
** else the same style and weight; else the first; -1 without data. */
static int
pick_desc(const cf__font_table_t *t, const cf__font_req_t *req)
{
    size_t i;
    int near = -1;
    for (i = 0; i < t->nd; i++) {
        if (t->d[i].italic != req->italic || t->d[i].bold != req->bold)
            continue;
        if (strcmp(t->d[i].family, req->family) == 0)
            return (int)i;
        if (near < 0)
            near = (int)i;
    }
    return near >= 0 ? near : t->nd > 0 ? 0 : -1;
}

static size_t
utf8(const char *s, size_t len, size_t i, unsigned *cp)
{
    unsigned char c = (unsigned char)s[i];
    size_t n = c < 0x80 ? 1 : c < 0xe0 ? 2 : c < 0xf0 ? 3 : 4, k;
    if (i + n > len) {
        *cp = 0xfffd;
        return 1;
    }
    *cp = n == 1 ? c : c & (0x7fu >> n);
    for (k = 1; k < n; k++)
        *cp = (*cp << 6) | ((unsigned char)s[i + k] & 0x3f);
    return n;
}

/* The kern (per bp) between characters first and second in
** description d: 0 without a K line. */
static double
kern_of(const cf__font_table_t *t, int d, unsigned first, unsigned second)
{
    size_t i;
    for (i = 0; i < t->nk; i++)
        if (t->k[i].d == d && t->k[i].first == first
            && t->k[i].second == second)
            return t->k[i].kern;
    return 0;
}

/* v bp in units, rounded as pango rounds (pango_units_from_double). */
static int
units(double v)
{
    return (int)floor(v * CF__FONT_SCALE + 0.5);
}

/* A text not shaped at export: its characters one after the other, in
** whole units as pango places them: each glyph's advance (with the kern
** of the pair it begins) and ink box rounded alone, the run's ink box
** their union. */
static int
compose(const cf__font_table_t *t, int d, const cf__font_req_t *req,
        shaped_t *s)
{
    double sz = req->size, pending = 0;
    int x = 0, ink[4] = { 0, 0, 0, 0 };
    unsigned prev = 0;    /* the last character placed (0: none) */
    bool any = false;
    size_t k, i;
    s->g = cf_calloc(req->len + 1, sizeof *s->g);
    if (s->g == NULL)
        return -1;
    s->baseline = units(t->d[d].ascent * sz);
    for (k = 0; k < req->len;) {
        unsigned cp;
        const chr_t *c = NULL;
        const glyph_t *g;
        placed_t *p;
        k += utf8(req->text, req->len, k, &cp);
        for (i = 0; i < t->nc && c == NULL; i++)
            if (t->c[i].d == d && t->c[i].cp == cp)
                c = &t->c[i];
        if (c == NULL) {
            s->unknown++;
            continue;
        }
        /* the advance before, with the kern of this pair */
        if (prev != 0)
            x += units((pending + kern_of(t, d, prev, cp)) * sz);
        prev = cp;
        pending = c->advance;
        g = &t->g[c->glyph];
        p = &s->g[s->n++];
        p->glyph = c->glyph;
        p->x = x;
        p->y = s->baseline;
        if (g->ink[2] > g->ink[0] && g->ink[3] > g->ink[1]) {
            int x0 = x + units(g->ink[0] * sz);
            int y0 = s->baseline + units(g->ink[1] * sz);
            int b[4] = { x0, y0, x0 + units((g->ink[2] - g->ink[0]) * sz),
                         y0 + units((g->ink[3] - g->ink[1]) * sz) };
            if (!any)
                memcpy(ink, b, sizeof b);
            ink[0] = b[0] < ink[0] ? b[0] : ink[0];
            ink[1] = b[1] < ink[1] ? b[1] : ink[1];
            ink[2] = b[2] > ink[2] ? b[2] : ink[2];
            ink[3] = b[3] > ink[3] ? b[3] : ink[3];
            any = true;
        }
    }
    if (prev != 0)
        x += units(pending * sz);
    s->logical[2] = x;
    s->logical[3] = s->baseline + units(t->d[d].descent * sz);
    if (any) {
        s->ink[0] = ink[0];
        s->ink[1] = ink[1];
        s->ink[2] = ink[2] - ink[0];
        s->ink[3] = ink[3] - ink[1];
    }
    return 0;
}

static void
release(void *run)
{
    run_t *r = run;
    if (r == NULL)
        return;
    if (r->own)
        cf_free(r->shape.g);
    cf_free(r);
}

static int
shape(void *ctx, const cf__font_req_t *req, void **run,
      cf__font_shape_t *out)
{
    const cf__font_table_t *t = ctx;
    int d = pick_desc(t, req), size = (int)lround(req->size * CF__FONT_SCALE);
    run_t *r = *run;
    size_t i;
    if (r == NULL) {
        r = cf_calloc(1, sizeof *r);
        if (r == NULL)
            return -1;
        *run = r;
    }
    if (r->own)
        cf_free(r->shape.g);
    memset(&r->shape, 0, sizeof r->shape);
    r->own = false;
    r->size = req->size;
    if (d < 0) {
        r->shape.unknown = (int)req->len;
    } else {
        for (i = 0; i < t->ns && r->shape.g == NULL; i++) {
            const shaped_t *s = &t->s[i];
            if (strcmp(t->d[s->d].family, t->d[d].family) == 0
                && t->d[s->d].italic == req->italic
                && t->d[s->d].bold == req->bold && s->size == size
                && s->len == req->len
                && memcmp(s->text, req->text, req->len) == 0)
                r->shape = *s;
        }
        if (r->shape.g == NULL) {
            r->own = true;
            if (compose(t, d, req, &r->shape) != 0)
                return -1;
        }
    }
    out->baseline = r->shape.baseline;
    memcpy(out->logical, r->shape.logical, sizeof out->logical);
    memcpy(out->ink, r->shape.ink, sizeof out->ink);
    out->unknown = r->shape.unknown;
    return 0;
}

/* The outlines of a run's glyphs, its top left at (x0, y0). */
static void
outline(void *ctx, void *run, double x0, double y0, cf__pathb_t *out)
{
    const cf__font_table_t *t = ctx;
    const run_t *r = run;
    double sz = r->size;
    int i;
    size_t k;
    for (i = 0; i < r->shape.n; i++) {
        const placed_t *p = &r->shape.g[i];
        const glyph_t *g = &t->g[p->glyph];
        double ox = x0 + (double)p->x / CF__FONT_SCALE;
        double oy = y0 + (double)p->y / CF__FONT_SCALE;
        const double *v = g->pts;
        for (k = 0; k < g->nops; k++) {
            double xy[6];
            int n = g->ops[k] == 'C' ? 3 : g->ops[k] == 'Z' ? 0 : 1, j;
            for (j = 0; j < n; j++) {
                xy[2 * j] = ox + v[2 * j] * sz;
                xy[2 * j + 1] = oy + v[2 * j + 1] * sz;
            }
            v += 2 * n;
            cf__pathb_add(out, g->ops[k] == 'M' ? CF__SEG_MOVE
                               : g->ops[k] == 'L' ? CF__SEG_LINE
                               : g->ops[k] == 'C' ? CF__SEG_CURVE
                                                  : CF__SEG_CLOSE, xy);
        }
    }
}

static void *
open_fonts(void *self)
{
    return self;
}

static void
close_fonts(void *ctx)
{
    (void)ctx;
}

cf__fonts_t
cf__font_table_fonts(cf__font_table_t *t)
{
    cf__fonts_t f = { open_fonts, close_fonts, shape, release, outline,
                      NULL, NULL, t };
    return f;
}
