/*
** The pango subset of render/wasm/shim/pango/pangocairo.h, from glyph
** data (the text render/label-glyphs.c writes at export time, loaded by
** cf__glyphs_load):
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
**     (face glyph x y) * n  bytes text            a text as pango shaped
**                                                 it (pango units)
**
** A layout whose description, size and text were shaped at export is
** that shaping; another is composed from its characters (C) in the
** description of that family, style and weight (or, failing that, of that
** style and weight), two characters with a K line moved by its kern;
** characters without data are unknown glyphs, drawn as nothing.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "glyphs.h"
#include "pango/pangocairo.h"

typedef struct desc {
    int italic, bold;
    double ascent, descent;
    char *family;
} desc_t;

typedef struct glyph {
    int face, id;
    double ink[4];
    double *pts;          /* the outline: ops and coordinates */
    unsigned char *ops;   /* 'M' 'L' 'C' 'Z' */
    int nops;
} glyph_t;

typedef struct chr { int d; unsigned cp; int glyph; double advance; } chr_t;

typedef struct kern { int d; unsigned first, second; double kern; } kern_t;

typedef struct placed { int glyph; int x, y; } placed_t;

typedef struct shaped {
    int d, size, baseline, unknown;
    PangoRectangle logical, ink;
    placed_t *g;
    int n;
    char *text;
    size_t len;
} shaped_t;

static struct {
    desc_t *d;
    int nd;
    glyph_t *g;
    int ng;
    chr_t *c;
    int nc;
    kern_t *k;
    int nk;
    shaped_t *s;
    int ns;
} tab;

enum { CONTEXT = 1, LAYOUT };
struct _PangoFontMap { int unused; };
struct _PangoContext { int kind; };
struct _PangoFontDescription {
    char *family;
    int italic, bold;
    double size;          /* pango units */
};
struct _PangoLayout {
    int kind;
    PangoFontDescription fd;
    char *text;
    size_t len;
    shaped_t shape;       /* the glyphs laid out (own g unless exact) */
    int own;
    int valid;
};

/* ---- the data ----------------------------------------------------------- */

static void
free_tables(void)
{
    int i;
    for (i = 0; i < tab.nd; i++)
        free(tab.d[i].family);
    for (i = 0; i < tab.ng; i++) {
        free(tab.g[i].pts);
        free(tab.g[i].ops);
    }
    for (i = 0; i < tab.ns; i++) {
        free(tab.s[i].g);
        free(tab.s[i].text);
    }
    free(tab.d);
    free(tab.g);
    free(tab.c);
    free(tab.k);
    free(tab.s);
    memset(&tab, 0, sizeof tab);
}

static int
grow(void **p, int n, size_t size)
{
    /* capacity: the next power of two at or above n + 1 */
    if (n == 0 || (n & (n - 1)) == 0) {
        void *q = realloc(*p, (size_t)(n ? 2 * n : 16) * size);
        if (q == NULL)
            return -1;
        *p = q;
    }
    return 0;
}

static int
find_glyph(int face, int id)
{
    int i;
    for (i = 0; i < tab.ng; i++)
        if (tab.g[i].face == face && tab.g[i].id == id)
            return i;
    return -1;
}

static const char *
num(const char *p, double *v)
{
    char *e;
    *v = strtod(p, &e);
    return e == p ? NULL : e;
}

static const char *
inum(const char *p, long *v)
{
    char *e;
    *v = strtol(p, &e, 10);
    return e == p ? NULL : e;
}

static const char *
skip(const char *p)
{
    while (*p == ' ')
        p++;
    return p;
}

static int
parse_glyph(const char *p)
{
    glyph_t g;
    long face, id;
    int cap = 0, ncoord = 0, i;
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
        if (op != 'M' && op != 'L' && op != 'C' && op != 'Z')
            goto bad;
        if (grow((void **)&g.ops, g.nops, 1) != 0)
            goto bad;
        g.ops[g.nops++] = (unsigned char)op;
        if (ncoord + k > cap) {
            double *q;
            cap = 2 * (ncoord + k) + 16;
            q = realloc(g.pts, (size_t)cap * sizeof *q);
            if (q == NULL)
                goto bad;
            g.pts = q;
        }
        for (i = 0; i < k; i++)
            if ((p = num(p, &g.pts[ncoord++])) == NULL)
                goto bad;
    }
    if (find_glyph(g.face, g.id) >= 0 || grow((void **)&tab.g, tab.ng,
                                               sizeof *tab.g) != 0)
        goto bad;
    tab.g[tab.ng++] = g;
    return 0;
bad:
    free(g.ops);
    free(g.pts);
    return -1;
}

static int
parse_shaped(const char *p)
{
    shaped_t s;
    long v[13], len;
    int i, k;
    memset(&s, 0, sizeof s);
    for (i = 0; i < 13; i++)
        if ((p = inum(p, &v[i])) == NULL)
            return -1;
    s.d = (int)v[0];
    s.size = (int)v[1];
    s.baseline = (int)v[2];
    s.logical = (PangoRectangle){ (int)v[3], (int)v[4], (int)v[5], (int)v[6] };
    s.ink = (PangoRectangle){ (int)v[7], (int)v[8], (int)v[9], (int)v[10] };
    s.unknown = (int)v[11];
    s.n = (int)v[12];
    if (s.d < 0 || s.d >= tab.nd || s.n < 0 || s.n > 100000)
        return -1;
    s.g = calloc((size_t)s.n + 1, sizeof *s.g);
    if (s.g == NULL)
        return -1;
    for (i = 0; i < s.n; i++) {
        long face, id, x, y;
        if ((p = inum(p, &face)) == NULL || (p = inum(p, &id)) == NULL
            || (p = inum(p, &x)) == NULL || (p = inum(p, &y)) == NULL)
            goto bad;
        k = find_glyph((int)face, (int)id);
        if (k < 0)
            goto bad;
        s.g[i] = (placed_t){ k, (int)x, (int)y };
    }
    if ((p = inum(p, &len)) == NULL || *p != ' ' || len < 0
        || (long)strlen(p + 1) < len)
        goto bad;
    s.len = (size_t)len;
    s.text = malloc(s.len + 1);
    if (s.text == NULL || grow((void **)&tab.s, tab.ns, sizeof *tab.s) != 0)
        goto bad;
    memcpy(s.text, p + 1, s.len);
    s.text[s.len] = '\0';
    tab.s[tab.ns++] = s;
    return 0;
bad:
    free(s.g);
    free(s.text);
    return -1;
}

static int
parse_line(const char *p)
{
    long v[5];
    double a, b;
    switch (*p) {
    case 'D': {
        desc_t d;
        const char *f;
        size_t n;
        if ((p = inum(p + 1, &v[0])) == NULL || v[0] != tab.nd
            || (p = inum(p, &v[1])) == NULL || (p = inum(p, &v[2])) == NULL
            || (p = num(p, &a)) == NULL || (p = num(p, &b)) == NULL)
            return -1;
        f = skip(p);
        n = strcspn(f, "\n");
        d.italic = v[1] != 0;
        d.bold = v[2] != 0;
        d.ascent = a;
        d.descent = b;
        d.family = malloc(n + 1);
        if (d.family == NULL
            || grow((void **)&tab.d, tab.nd, sizeof *tab.d) != 0) {
            free(d.family);
            return -1;
        }
        memcpy(d.family, f, n);
        d.family[n] = '\0';
        tab.d[tab.nd++] = d;
        return 0;
    }
    case 'G':
        return parse_glyph(p + 1);
    case 'C': {
        chr_t c;
        int k;
        if ((p = inum(p + 1, &v[0])) == NULL || (p = inum(p, &v[1])) == NULL
            || (p = inum(p, &v[2])) == NULL || (p = inum(p, &v[3])) == NULL
            || (p = num(p, &a)) == NULL || v[0] < 0 || v[0] >= tab.nd)
            return -1;
        k = find_glyph((int)v[2], (int)v[3]);
        if (k < 0 || grow((void **)&tab.c, tab.nc, sizeof *tab.c) != 0)
            return -1;
        c = (chr_t){ (int)v[0], (unsigned)v[1], k, a };
        tab.c[tab.nc++] = c;
        return 0;
    }
    case 'K': {
        kern_t k;
        if ((p = inum(p + 1, &v[0])) == NULL || (p = inum(p, &v[1])) == NULL
            || (p = inum(p, &v[2])) == NULL || (p = num(p, &a)) == NULL
            || v[0] < 0 || v[0] >= tab.nd || v[1] < 0 || v[2] < 0
            || grow((void **)&tab.k, tab.nk, sizeof *tab.k) != 0)
            return -1;
        k = (kern_t){ (int)v[0], (unsigned)v[1], (unsigned)v[2], a };
        tab.k[tab.nk++] = k;
        return 0;
    }
    case 'S':
        return parse_shaped(p + 1);
    default:
        return -1;
    }
}

int
cf__glyphs_load(const char *data, size_t len, int *bad_line)
{
    char *copy = malloc(len + 1), *p, *nl;
    int line = 1;
    free_tables();
    *bad_line = 0;
    if (copy == NULL)
        return -1;
    memcpy(copy, data, len);
    copy[len] = '\0';
    if (strncmp(copy, "curvefig-glyphs 1\n", 18) != 0) {
        free(copy);
        *bad_line = 1;
        return -1;
    }
    for (p = copy + 18; *p != '\0'; p = nl + 1) {
        line++;
        nl = strchr(p, '\n');
        if (nl == NULL)
            nl = p + strlen(p) - 1;
        else
            *nl = '\0';
        if (*p != '\0' && parse_line(p) != 0) {
            free(copy);
            free_tables();
            *bad_line = line;
            return -1;
        }
        if (nl[1] == '\0' && nl < p + strlen(p))
            break;
    }
    free(copy);
    return 0;
}

/* ---- contexts and descriptions ------------------------------------------ */

static PangoFontMap the_map;

PangoFontMap *pango_cairo_font_map_get_default(void) { return &the_map; }

PangoContext *
pango_font_map_create_context(PangoFontMap *fm)
{
    PangoContext *c = calloc(1, sizeof *c);
    (void)fm;
    if (c != NULL)
        c->kind = CONTEXT;
    return c;
}

void
pango_cairo_context_set_font_options(PangoContext *ctx,
                                     const cairo_font_options_t *o)
{
    (void)ctx;
    (void)o;
}

void
pango_cairo_context_set_resolution(PangoContext *ctx, double dpi)
{
    (void)ctx;
    (void)dpi;
}

void
pango_context_set_round_glyph_positions(PangoContext *ctx, gboolean round)
{
    (void)ctx;
    (void)round;
}

PangoFontDescription *
pango_font_description_new(void)
{
    return calloc(1, sizeof(PangoFontDescription));
}

void
pango_font_description_free(PangoFontDescription *fd)
{
    if (fd == NULL)
        return;
    free(fd->family);
    free(fd);
}

static char *
dup_n(const char *s, size_t n)
{
    char *t = malloc(n + 1);
    if (t != NULL) {
        memcpy(t, s, n);
        t[n] = '\0';
    }
    return t;
}

void
pango_font_description_set_family(PangoFontDescription *fd, const char *f)
{
    free(fd->family);
    fd->family = dup_n(f, strlen(f));
}

void
pango_font_description_set_style(PangoFontDescription *fd, PangoStyle s)
{
    fd->italic = s != PANGO_STYLE_NORMAL;
}

void
pango_font_description_set_weight(PangoFontDescription *fd, PangoWeight w)
{
    fd->bold = w >= PANGO_WEIGHT_BOLD;
}

void
pango_font_description_set_absolute_size(PangoFontDescription *fd,
                                         double size)
{
    fd->size = size;
}

/* ---- layouts ------------------------------------------------------------ */

PangoLayout *
pango_layout_new(PangoContext *ctx)
{
    PangoLayout *l = calloc(1, sizeof *l);
    (void)ctx;
    if (l != NULL)
        l->kind = LAYOUT;
    return l;
}

static void
drop_shape(PangoLayout *l)
{
    if (l->own)
        free(l->shape.g);
    memset(&l->shape, 0, sizeof l->shape);
    l->own = 0;
    l->valid = 0;
}

void
g_object_unref(void *object)
{
    PangoContext *c = object;
    if (c != NULL && c->kind == LAYOUT) {
        PangoLayout *l = object;
        drop_shape(l);
        free(l->fd.family);
        free(l->text);
    }
    free(object);
}

void
pango_layout_set_font_description(PangoLayout *l,
                                  const PangoFontDescription *fd)
{
    drop_shape(l);
    free(l->fd.family);
    l->fd = *fd;
    l->fd.family = fd->family != NULL ? dup_n(fd->family, strlen(fd->family))
                                      : NULL;
}

void
pango_layout_set_text(PangoLayout *l, const char *text, int length)
{
    size_t n = length < 0 ? strlen(text) : (size_t)length;
    drop_shape(l);
    free(l->text);
    l->text = dup_n(text, n);
    l->len = l->text != NULL ? n : 0;
}

/* The description of the data for fd: the same family, style and weight;
** else the same style and weight; else the first; -1 without data. */
static int
pick_desc(const PangoFontDescription *fd)
{
    int i, near = -1;
    for (i = 0; i < tab.nd; i++) {
        if (tab.d[i].italic != fd->italic || tab.d[i].bold != fd->bold)
            continue;
        if (fd->family != NULL && strcmp(tab.d[i].family, fd->family) == 0)
            return i;
        if (near < 0)
            near = i;
    }
    return near >= 0 ? near : tab.nd > 0 ? 0 : -1;
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
    *cp = n == 1 ? c : c & (0x7f >> n);
    for (k = 1; k < n; k++)
        *cp = (*cp << 6) | ((unsigned char)s[i + k] & 0x3f);
    return n;
}

/* The kern (per bp) between characters first and second in
** description d: 0 without a K line. */
static double
kern_of(int d, unsigned first, unsigned second)
{
    int i;
    for (i = 0; i < tab.nk; i++)
        if (tab.k[i].d == d && tab.k[i].first == first
            && tab.k[i].second == second)
            return tab.k[i].kern;
    return 0;
}

static void
shape(PangoLayout *l)
{
    int d = pick_desc(&l->fd), size = (int)lround(l->fd.size), i;
    double sz = l->fd.size / PANGO_SCALE, x = 0;
    size_t k;
    unsigned prev = 0;    /* the last character placed (0: none) */
    int any = 0;
    double ink[4] = { 0, 0, 0, 0 };
    if (l->valid)
        return;
    l->valid = 1;
    memset(&l->shape, 0, sizeof l->shape);
    if (d < 0) {
        l->shape.unknown = (int)l->len;
        return;
    }
    for (i = 0; i < tab.ns; i++) {
        const shaped_t *s = &tab.s[i];
        if (strcmp(tab.d[s->d].family, tab.d[d].family) == 0
            && tab.d[s->d].italic == l->fd.italic
            && tab.d[s->d].bold == l->fd.bold && s->size == size
            && s->len == l->len && memcmp(s->text, l->text, l->len) == 0) {
            l->shape = *s;
            return;
        }
    }
    l->own = 1;
    l->shape.g = calloc(l->len + 1, sizeof *l->shape.g);
    if (l->shape.g == NULL)
        return;
    l->shape.baseline = (int)lround(tab.d[d].ascent * sz * PANGO_SCALE);
    for (k = 0; k < l->len;) {
        unsigned cp;
        const chr_t *c = NULL;
        k += utf8(l->text, l->len, k, &cp);
        for (i = 0; i < tab.nc && c == NULL; i++)
            if (tab.c[i].d == d && tab.c[i].cp == cp)
                c = &tab.c[i];
        if (c == NULL) {
            l->shape.unknown++;
            prev = 0;
            continue;
        }
        /* the pair with the character before */
        if (prev != 0)
            x += kern_of(d, prev, cp) * sz;
        prev = cp;
        {
            const glyph_t *g = &tab.g[c->glyph];
            placed_t *p = &l->shape.g[l->shape.n++];
            double ox = x, oy = tab.d[d].ascent * sz;
            p->glyph = c->glyph;
            p->x = (int)lround(x * PANGO_SCALE);
            p->y = l->shape.baseline;
            if (g->ink[2] > g->ink[0] && g->ink[3] > g->ink[1]) {
                double b[4] = { ox + g->ink[0] * sz, oy + g->ink[1] * sz,
                                ox + g->ink[2] * sz, oy + g->ink[3] * sz };
                if (!any)
                    memcpy(ink, b, sizeof b);
                ink[0] = fmin(ink[0], b[0]);
                ink[1] = fmin(ink[1], b[1]);
                ink[2] = fmax(ink[2], b[2]);
                ink[3] = fmax(ink[3], b[3]);
                any = 1;
            }
            x += c->advance * sz;
        }
    }
    l->shape.logical.width = (int)lround(x * PANGO_SCALE);
    l->shape.logical.height = (int)lround((tab.d[d].ascent
                                           + tab.d[d].descent) * sz
                                          * PANGO_SCALE);
    if (any) {
        l->shape.ink.x = (int)floor(ink[0] * PANGO_SCALE);
        l->shape.ink.y = (int)floor(ink[1] * PANGO_SCALE);
        l->shape.ink.width = (int)ceil(ink[2] * PANGO_SCALE)
                             - l->shape.ink.x;
        l->shape.ink.height = (int)ceil(ink[3] * PANGO_SCALE)
                              - l->shape.ink.y;
    }
}

void
pango_layout_get_extents(PangoLayout *l, PangoRectangle *ink,
                         PangoRectangle *logical)
{
    shape(l);
    if (ink != NULL)
        *ink = l->shape.ink;
    if (logical != NULL)
        *logical = l->shape.logical;
}

int
pango_layout_get_baseline(PangoLayout *l)
{
    shape(l);
    return l->shape.baseline;
}

int
pango_layout_get_unknown_glyphs_count(PangoLayout *l)
{
    shape(l);
    return l->shape.unknown;
}

/* The glyphs' outlines with the layout's top left at (x0, y0). */
static void
glyphs_path(cairo_t *cr, PangoLayout *l, double x0, double y0)
{
    double sz = l->fd.size / PANGO_SCALE;
    int i, k;
    shape(l);
    for (i = 0; i < l->shape.n; i++) {
        const placed_t *p = &l->shape.g[i];
        const glyph_t *g = &tab.g[p->glyph];
        double ox = x0 + (double)p->x / PANGO_SCALE;
        double oy = y0 + (double)p->y / PANGO_SCALE;
        const double *v = g->pts;
        for (k = 0; k < g->nops; k++) {
            switch (g->ops[k]) {
            case 'M':
                cairo_move_to(cr, ox + v[0] * sz, oy + v[1] * sz);
                v += 2;
                break;
            case 'L':
                cairo_line_to(cr, ox + v[0] * sz, oy + v[1] * sz);
                v += 2;
                break;
            case 'C':
                cairo_curve_to(cr, ox + v[0] * sz, oy + v[1] * sz,
                               ox + v[2] * sz, oy + v[3] * sz,
                               ox + v[4] * sz, oy + v[5] * sz);
                v += 6;
                break;
            case 'Z':
                cairo_close_path(cr);
                break;
            }
        }
    }
}

void
pango_cairo_layout_path(cairo_t *cr, PangoLayout *l)
{
    double x, y;
    cairo_get_current_point(cr, &x, &y);
    glyphs_path(cr, l, x, y);
}

void
pango_cairo_show_layout(cairo_t *cr, PangoLayout *l)
{
    double x, y;
    cairo_get_current_point(cr, &x, &y);
    cairo_new_path(cr);
    glyphs_path(cr, l, x, y);
    cairo_fill(cr);
}
