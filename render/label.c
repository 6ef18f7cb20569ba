/*
** Labels: a small TeX-like syntax laid out with pango from font metrics.
**
** The parser lays out as it reads.  Each character becomes part of a run
** (one PangoLayout per run of equal font, size and baseline); sub- and
** superscripts are laid out at the pen position and then shifted
** vertically, with shifts taken from TeX's font parameters (cmsy10:
** sup1 = 0.413 em, sub1 = 0.150 em, sub2 = 0.247 em, x-height 0.431 em,
** rule thickness 0.04 em), so B_i^n stacks both scripts at the same x.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <pango/pangocairo.h>

#include "label-private.h"

#define SCRIPT_RATIO 0.7       /* 10 pt -> 7 pt */
#define SCRIPT2_RATIO 0.5      /* 10 pt -> 5 pt */
#define MAX_DEPTH 32           /* nesting of groups */

typedef struct run {
    char *text;
    size_t text_len;
    double x, y;              /* baseline origin, y up */
    double size;
    int level;
    cf_label_kind_t kind;
    bool italic, bold;
    PangoLayout *layout;
    double width, ascent, descent;   /* logical */
    double ink[4];                   /* x0 y0 x1 y1 relative to origin,
                                        y down */
    double baseline;                 /* layout top to baseline */
    double rule_h;                   /* > 0: a fraction rule of this
                                        thickness, width `width`, its
                                        bottom at y (no text) */
} run_t;

struct cf_label {
    run_t *runs;
    size_t count, cap;
    char *family;
    double size;
    size_t unknown;
    PangoContext *ctx;
    bool merge_ok;            /* the last atom may be extended */
    cf_label_box_t *boxes;    /* public view of the runs */
};

/* ---- runs --------------------------------------------------------------- */

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
    const char *lm = "Latin Modern Roman";
    size_t n = strlen(lm), i, count;
    const int *d;
    double texpt = size_bp * 72.27 / 72;
    int pick;

    if (strncmp(family, lm, n) != 0
        || (family[n] != '\0' && family[n] != ',')) {
        snprintf(out, cap, "%s", family);
        return;
    }
    d = italic ? slanted : bold ? heavy : regular;
    count = italic ? sizeof slanted / sizeof slanted[0]
          : bold ? sizeof heavy / sizeof heavy[0]
                 : sizeof regular / sizeof regular[0];
    pick = d[0];
    for (i = 0; i < count; i++)
        if (d[i] <= texpt + 0.25)
            pick = d[i];
    snprintf(out, cap, "LM Roman %d,%s", pick, family);
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
    family_for_size(lab->family, r->size, r->italic, r->bold, family,
                    sizeof family);
    pango_font_description_set_family(fd, family);
    pango_font_description_set_style(fd, r->italic ? PANGO_STYLE_ITALIC
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

typedef struct font {
    double size;
    int level;
    cf_label_kind_t kind;
    bool italic, bold;
    bool text;            /* text mode: upright, no scripts */
} font_t;

/* Append UTF-8 bytes at (x, y) in font f; merges with the previous run
** when it continues it.  Returns the new pen x, or NAN when out of
** memory. */
static double
put_text(cf_label_t *lab, const font_t *f, double x, double y,
         const char *s, size_t n)
{
    run_t *r = lab->count > 0 ? &lab->runs[lab->count - 1] : NULL;
    char *t;

    if (r != NULL && lab->merge_ok && r->rule_h == 0 && r->size == f->size && r->italic == f->italic
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
    }
    if (n == 0) {
        /* an empty run (a fraction rule): no layout */
        r->width = 0;
        return r->x;
    }
    run_measure(lab, r);
    return r->x + r->width;
}

/* ---- parser ------------------------------------------------------------- */

typedef struct parser {
    const char *s;
    size_t pos, len;
    cf_label_t *lab;
    cf_diag_t *diag;
    cf_status_t st;
    bool has_dollar;
    bool in_math;
    int depth;
} parser_t;

/* Extents of a laid-out piece (runs [first, end) of the label). */
typedef struct piece {
    size_t first, end;
    double x0, x1;            /* pen start and end */
    double top, bottom;       /* ink extent above/below the baseline
                                 (top positive up, bottom positive down) */
    int cls;                  /* spacing class of the atom */
    bool group;               /* nucleus was a group or command result */
    double ic;                /* italic correction of a slanted single
                                 character: how far its ink reaches past
                                 its advance (bp, >= 0) */
} piece_t;

enum { CLS_NONE, CLS_ORD, CLS_BIN, CLS_REL, CLS_OPEN, CLS_CLOSE,
       CLS_PUNCT, CLS_SPACE };

static cf_status_t
perr(parser_t *p, size_t at, const char *what)
{
    if (p->st == CF_STATUS_OK)
        p->st = cf_diag_set(p->diag, CF_STATUS_INVALID_ARG, (long)at,
                          "label \"%s\": %s at byte %zu", p->s, what, at);
    return p->st;
}

static cf_status_t
pnomem(parser_t *p)
{
    if (p->st == CF_STATUS_OK)
        p->st = cf_diag_set(p->diag, CF_STATUS_NO_MEMORY, -1,
                          "label \"%s\": out of memory", p->s);
    return p->st;
}

/* Decode one UTF-8 character at s[pos]; returns its length (0 when
** invalid) and the code point. */
static size_t
utf8_decode(const char *s, size_t len, size_t pos, unsigned *cp)
{
    const unsigned char *u = (const unsigned char *)s + pos;
    size_t n, i, avail = len - pos;
    unsigned c;
    if (u[0] < 0x80) {
        *cp = u[0];
        return 1;
    }
    if ((u[0] & 0xe0) == 0xc0) {
        n = 2;
        c = u[0] & 0x1f;
    } else if ((u[0] & 0xf0) == 0xe0) {
        n = 3;
        c = u[0] & 0x0f;
    } else if ((u[0] & 0xf8) == 0xf0) {
        n = 4;
        c = u[0] & 0x07;
    } else {
        return 0;
    }
    if (n > avail)
        return 0;
    for (i = 1; i < n; i++) {
        if ((u[i] & 0xc0) != 0x80)
            return 0;
        c = (c << 6) | (u[i] & 0x3f);
    }
    if ((n == 2 && c < 0x80) || (n == 3 && c < 0x800)
        || (n == 4 && (c < 0x10000 || c > 0x10ffff))
        || (c >= 0xd800 && c <= 0xdfff))
        return 0;
    *cp = c;
    return n;
}

static size_t
utf8_encode(unsigned c, char *out)
{
    if (c < 0x80) {
        out[0] = (char)c;
        return 1;
    }
    if (c < 0x800) {
        out[0] = (char)(0xc0 | (c >> 6));
        out[1] = (char)(0x80 | (c & 0x3f));
        return 2;
    }
    if (c < 0x10000) {
        out[0] = (char)(0xe0 | (c >> 12));
        out[1] = (char)(0x80 | ((c >> 6) & 0x3f));
        out[2] = (char)(0x80 | (c & 0x3f));
        return 3;
    }
    out[0] = (char)(0xf0 | (c >> 18));
    out[1] = (char)(0x80 | ((c >> 12) & 0x3f));
    out[2] = (char)(0x80 | ((c >> 6) & 0x3f));
    out[3] = (char)(0x80 | (c & 0x3f));
    return 4;
}

typedef struct command {
    const char *name;
    unsigned cp;
    int cls;
    int italic;   /* 1 italic in math, 0 upright */
} command_t;

static const command_t commands[] = {
    { "alpha", 0x3b1, CLS_ORD, 1 },    { "beta", 0x3b2, CLS_ORD, 1 },
    { "gamma", 0x3b3, CLS_ORD, 1 },    { "delta", 0x3b4, CLS_ORD, 1 },
    { "epsilon", 0x3f5, CLS_ORD, 1 },  { "varepsilon", 0x3b5, CLS_ORD, 1 },
    { "zeta", 0x3b6, CLS_ORD, 1 },     { "eta", 0x3b7, CLS_ORD, 1 },
    { "theta", 0x3b8, CLS_ORD, 1 },    { "vartheta", 0x3d1, CLS_ORD, 1 },
    { "iota", 0x3b9, CLS_ORD, 1 },     { "kappa", 0x3ba, CLS_ORD, 1 },
    { "lambda", 0x3bb, CLS_ORD, 1 },   { "mu", 0x3bc, CLS_ORD, 1 },
    { "nu", 0x3bd, CLS_ORD, 1 },       { "xi", 0x3be, CLS_ORD, 1 },
    { "omicron", 0x3bf, CLS_ORD, 1 },  { "pi", 0x3c0, CLS_ORD, 1 },
    { "varpi", 0x3d6, CLS_ORD, 1 },    { "rho", 0x3c1, CLS_ORD, 1 },
    { "varrho", 0x3f1, CLS_ORD, 1 },   { "sigma", 0x3c3, CLS_ORD, 1 },
    { "varsigma", 0x3c2, CLS_ORD, 1 }, { "tau", 0x3c4, CLS_ORD, 1 },
    { "upsilon", 0x3c5, CLS_ORD, 1 },  { "phi", 0x3d5, CLS_ORD, 1 },
    { "varphi", 0x3c6, CLS_ORD, 1 },   { "chi", 0x3c7, CLS_ORD, 1 },
    { "psi", 0x3c8, CLS_ORD, 1 },      { "omega", 0x3c9, CLS_ORD, 1 },
    { "Gamma", 0x393, CLS_ORD, 0 },    { "Delta", 0x394, CLS_ORD, 0 },
    { "Theta", 0x398, CLS_ORD, 0 },    { "Lambda", 0x39b, CLS_ORD, 0 },
    { "Xi", 0x39e, CLS_ORD, 0 },       { "Pi", 0x3a0, CLS_ORD, 0 },
    { "Sigma", 0x3a3, CLS_ORD, 0 },    { "Upsilon", 0x3a5, CLS_ORD, 0 },
    { "Phi", 0x3a6, CLS_ORD, 0 },      { "Psi", 0x3a8, CLS_ORD, 0 },
    { "Omega", 0x3a9, CLS_ORD, 0 },
    { "cdot", 0x22c5, CLS_BIN, 0 },    { "times", 0xd7, CLS_BIN, 0 },
    { "pm", 0xb1, CLS_BIN, 0 },        { "mp", 0x2213, CLS_BIN, 0 },
    { "circ", 0x2218, CLS_BIN, 0 },
    { "leq", 0x2264, CLS_REL, 0 },     { "le", 0x2264, CLS_REL, 0 },
    { "geq", 0x2265, CLS_REL, 0 },     { "ge", 0x2265, CLS_REL, 0 },
    { "neq", 0x2260, CLS_REL, 0 },     { "ne", 0x2260, CLS_REL, 0 },
    { "approx", 0x2248, CLS_REL, 0 },  { "equiv", 0x2261, CLS_REL, 0 },
    { "to", 0x2192, CLS_REL, 0 },      { "rightarrow", 0x2192, CLS_REL, 0 },
    { "mapsto", 0x21a6, CLS_REL, 0 },  { "in", 0x2208, CLS_REL, 0 },
    { "subset", 0x2282, CLS_REL, 0 },
    { "infty", 0x221e, CLS_ORD, 0 },   { "partial", 0x2202, CLS_ORD, 1 },
    { "nabla", 0x2207, CLS_ORD, 0 },   { "ldots", 0x2026, CLS_ORD, 0 },
    { "dots", 0x2026, CLS_ORD, 0 },    { "cdots", 0x22ef, CLS_ORD, 0 },
    { "sum", 0x2211, CLS_ORD, 0 },     { "prod", 0x220f, CLS_ORD, 0 },
    { "int", 0x222b, CLS_ORD, 0 },     { "prime", 0x2032, CLS_ORD, 0 },
    { "ell", 0x2113, CLS_ORD, 0 },     { "deg", 0xb0, CLS_ORD, 0 },
    { "langle", 0x27e8, CLS_OPEN, 0 }, { "rangle", 0x27e9, CLS_CLOSE, 0 },
    { "{", '{', CLS_OPEN, 0 },         { "}", '}', CLS_CLOSE, 0 },
    { "_", '_', CLS_ORD, 0 },          { "$", '$', CLS_ORD, 0 },
    { "\\", '\\', CLS_ORD, 0 },        { "^", '^', CLS_ORD, 0 },
    { "%", '%', CLS_ORD, 0 },          { "#", '#', CLS_ORD, 0 },
    { "&", '&', CLS_ORD, 0 },          { "|", 0x2016, CLS_ORD, 0 },
};

/* Horizontal spaces in em. */
static const struct {
    const char *name;
    double em;
} spaces[] = {
    { ",", 3.0 / 18 }, { ":", 4.0 / 18 }, { ";", 5.0 / 18 },
    { "!", -3.0 / 18 }, { " ", 6.0 / 18 }, { "quad", 1.0 },
    { "qquad", 2.0 },
};

/* Accents over a single character (spacing forms, placed by hand). */
static const struct {
    const char *name;
    unsigned cp;
} accents[] = {
    { "hat", 0x2c6 }, { "bar", 0xaf }, { "tilde", 0x2dc },
    { "vec", 0x2192 }, { "dot", 0x2d9 }, { "ddot", 0xa8 },
};

static bool parse_list(parser_t *p, const font_t *f, double x, double y,
                       int stop, piece_t *out);

static void
piece_init(piece_t *pc, cf_label_t *lab, double x)
{
    pc->first = pc->end = lab->count;
    pc->x0 = pc->x1 = x;
    pc->top = -INFINITY;
    pc->bottom = -INFINITY;
    pc->cls = CLS_NONE;
    pc->group = false;
    pc->ic = 0;
}

/* Recompute top/bottom of a piece from its runs. */
static void
piece_ink(cf_label_t *lab, piece_t *pc, double y)
{
    size_t i;
    pc->top = -INFINITY;
    pc->bottom = -INFINITY;
    for (i = pc->first; i < pc->end; i++) {
        run_t *r = &lab->runs[i];
        if (r->ink[3] <= r->ink[1])
            continue;
        pc->top = fmax(pc->top, (r->y - y) - r->ink[1]);
        pc->bottom = fmax(pc->bottom, r->ink[3] - (r->y - y));
    }
    if (pc->top == -INFINITY)
        pc->top = pc->bottom = 0;
}

static void
shift_runs(cf_label_t *lab, size_t first, size_t end, double dy)
{
    size_t i;
    for (i = first; i < end; i++)
        lab->runs[i].y += dy;
}

/* TeX's italic correction of one slanted character in font f: how far
** its ink reaches right of its advance width (0 when it does not).  TeX
** reads it from the font's metrics (cmmi10: N 0.109 em, P 0.139 em, V
** 0.222 em); an OpenType text italic has no such table, so it is measured
** on the glyph outline of the character alone. */
static double
italic_correction(cf_label_t *lab, const font_t *f, const char *s, size_t n)
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
    run_measure(lab, &r);
    if (r.layout == NULL)
        return 0;
    ic = r.ink[2] > r.ink[0] ? fmax(0, r.ink[2] - r.width) : 0;
    g_object_unref(r.layout);
    return ic;
}

/* Emit one code point as an atom. */
static bool
emit_char(parser_t *p, const font_t *f, unsigned cp, bool italic, int cls,
          double x, double y, piece_t *pc)
{
    char buf[8];
    size_t n = utf8_encode(cp, buf);
    font_t g = *f;
    double nx;
    g.italic = italic;
    piece_init(pc, p->lab, x);
    /* only ordinary atoms continue a run: operators get spaces */
    p->lab->merge_ok = p->lab->merge_ok && cls == CLS_ORD;
    nx = put_text(p->lab, &g, x, y, buf, n);
    p->lab->merge_ok = cls == CLS_ORD;
    if (isnan(nx)) {
        pnomem(p);
        return false;
    }
    pc->end = p->lab->count;
    pc->first = pc->end - 1;   /* the run holding the char (maybe merged) */
    pc->x1 = nx;
    pc->cls = cls;
    /* the italic correction, for the scripts or, like TeX's kern after a
    ** math italic letter, before an upright delimiter, digit or prime:
    ** f(t), V], P' (operators and relations have their own space) */
    if (italic && !f->text && p->pos < p->len
        && strchr("^_()[]|/,;'0123456789", p->s[p->pos]) != NULL)
        pc->ic = italic_correction(p->lab, &g, buf, n);
    {
        /* the nucleus' own ink: measured on the character alone */
        run_t *r = &p->lab->runs[pc->first];
        double top = r->ink[1], bottom = r->ink[3];
        pc->top = bottom > top ? (r->y - y) - top : 0;
        pc->bottom = bottom > top ? bottom - (r->y - y) : 0;
    }
    return true;
}

static void
script_font(const font_t *f, font_t *out, cf_label_kind_t kind, double base)
{
    *out = *f;
    out->level = f->level + 1;
    out->kind = kind;
    out->size = base * (out->level == 1 ? SCRIPT_RATIO : SCRIPT2_RATIO);
    if (out->level > 2)
        out->size = base * SCRIPT2_RATIO;
    out->text = false;
}

/* Read a command name after '\' (letters, or one other character). */
static size_t
command_name(const parser_t *p, size_t at, char *name, size_t cap)
{
    size_t n = 0;
    if (at >= p->len)
        return 0;
    if ((p->s[at] >= 'a' && p->s[at] <= 'z')
        || (p->s[at] >= 'A' && p->s[at] <= 'Z')) {
        while (at + n < p->len
               && ((p->s[at + n] >= 'a' && p->s[at + n] <= 'z')
                   || (p->s[at + n] >= 'A' && p->s[at + n] <= 'Z'))) {
            if (n + 1 < cap)
                name[n] = p->s[at + n];
            n++;
        }
        if (n + 1 > cap)
            return 0;
    } else {
        name[0] = p->s[at];
        n = 1;
    }
    name[n] = '\0';
    return n;
}

static bool parse_atom(parser_t *p, const font_t *f, double x, double y,
                       piece_t *pc);

/* Move runs [first, end) by (dx, dy). */
static void
move_runs(cf_label_t *lab, size_t first, size_t end, double dx, double dy)
{
    size_t i;
    for (i = first; i < end; i++) {
        lab->runs[i].x += dx;
        lab->runs[i].y += dy;
    }
}

/* \frac{num}{den}: both at the next script level, centred over each
** other around a rule on the math axis (TeX rule 15, text style: num2 =
** 0.394 em, denom2 = 0.345 em, axis 0.25 em, rule 0.04 em, clearance one
** rule thickness, null delimiter space 0.12 em each side). */
static bool
parse_frac(parser_t *p, const font_t *f, double x, double y, piece_t *pc,
           size_t at)
{
    piece_t num, den;
    font_t g;
    double s = f->size, base, wn, wd, w, pad = 0.12 * s, th = 0.04 * s;
    double axis = 0.25 * s, up = 0.394 * s, down = 0.345 * s;
    run_t *r;
    int k;

    base = f->level == 0 ? s : s / (f->level == 1 ? SCRIPT_RATIO
                                                  : SCRIPT2_RATIO);
    script_font(f, &g, f->kind, base);
    for (k = 0; k < 2; k++) {
        piece_t *pp = k == 0 ? &num : &den;
        while (p->pos < p->len && p->s[p->pos] == ' ')
            p->pos++;
        if (p->pos >= p->len || p->s[p->pos] != '{') {
            perr(p, at, "\\frac needs {numerator}{denominator}");
            return false;
        }
        p->lab->merge_ok = false;
        if (!parse_atom(p, &g, x + pad, y, pp))
            return false;
        piece_ink(p->lab, pp, y);
    }
    wn = num.x1 - num.x0;
    wd = den.x1 - den.x0;
    w = fmax(wn, wd);
    if ((up - num.bottom) - (axis + th / 2) < th)
        up = axis + th / 2 + th + num.bottom;
    if ((axis - th / 2) - (den.top - down) < th)
        down = den.top + th - (axis - th / 2);
    move_runs(p->lab, num.first, num.end, (w - wn) / 2, up);
    move_runs(p->lab, den.first, den.end, (w - wd) / 2, -down);
    /* the rule, as a run without text */
    if (isnan(put_text(p->lab, f, x + pad, y + axis - th / 2, "", 0))) {
        pnomem(p);
        return false;
    }
    r = &p->lab->runs[p->lab->count - 1];
    r->rule_h = th;
    r->width = w;
    r->ascent = th;
    r->descent = 0;
    r->ink[0] = 0;
    r->ink[1] = -th;
    r->ink[2] = w;
    r->ink[3] = 0;
    p->lab->merge_ok = false;
    pc->first = num.first;
    pc->end = p->lab->count;
    pc->x0 = x;
    pc->x1 = x + w + 2 * pad;
    pc->cls = CLS_ORD;
    pc->group = true;
    piece_ink(p->lab, pc, y);
    return true;
}

/* One atom at (x, y): a character, a command or a {group}. */
static bool
parse_atom(parser_t *p, const font_t *f, double x, double y, piece_t *pc)
{
    unsigned cp;
    size_t n, at = p->pos, i;
    char c = p->s[p->pos];
    bool math = !f->text;

    if (c == '{') {
        font_t g = *f;
        p->pos++;
        if (++p->depth > MAX_DEPTH) {
            perr(p, at, "groups nested too deeply");
            return false;
        }
        if (!parse_list(p, &g, x, y, '}', pc))
            return false;
        p->depth--;
        if (p->pos >= p->len || p->s[p->pos] != '}') {
            perr(p, at, "unbalanced '{'");
            return false;
        }
        p->pos++;
        pc->group = true;
        pc->cls = CLS_ORD;
        return true;
    }
    if (c == '\\') {
        char name[24];
        n = command_name(p, at + 1, name, sizeof name);
        if (n == 0) {
            perr(p, at, "'\\' without a command name");
            return false;
        }
        p->pos = at + 1 + n;
        for (i = 0; i < sizeof spaces / sizeof spaces[0]; i++) {
            if (strcmp(name, spaces[i].name) == 0) {
                piece_init(pc, p->lab, x);
                pc->x1 = x + spaces[i].em * f->size;
                pc->cls = CLS_SPACE;
                pc->top = pc->bottom = 0;
                return true;
            }
        }
        for (i = 0; i < sizeof commands / sizeof commands[0]; i++) {
            if (strcmp(name, commands[i].name) == 0)
                return emit_char(p, f, commands[i].cp,
                                 math && commands[i].italic && !f->bold,
                                 math ? commands[i].cls : CLS_ORD, x, y, pc);
        }
        for (i = 0; i < sizeof accents / sizeof accents[0]; i++) {
            if (strcmp(name, accents[i].name) == 0) {
                /* \hat{P} or \hat P: the character, then the accent as
                ** its own run centred over the character's ink, raised
                ** by the character's height above the x-height (TeX's
                ** rule, with the italic skew of a slanted letter) */
                bool braced;
                unsigned base;
                size_t m;
                char buf[8];
                font_t g = *f;
                double nx, top, skew, ax, base_end;
                while (p->pos < p->len && p->s[p->pos] == ' ')
                    p->pos++;
                braced = p->pos < p->len && p->s[p->pos] == '{';
                if (braced)
                    p->pos++;
                if (p->pos >= p->len
                    || (m = utf8_decode(p->s, p->len, p->pos, &base)) == 0
                    || base == '{' || base == '}' || base == '\\') {
                    perr(p, at, "an accent needs one character");
                    return false;
                }
                p->pos += m;
                if (braced) {
                    if (p->pos >= p->len || p->s[p->pos] != '}') {
                        perr(p, at, "an accent takes one character");
                        return false;
                    }
                    p->pos++;
                }
                g.italic = math
                    && ((base >= 'a' && base <= 'z')
                        || (base >= 'A' && base <= 'Z')
                        || (base >= 0x3b1 && base <= 0x3c9));
                if (!emit_char(p, &g, base, g.italic, CLS_ORD, x, y, pc))
                    return false;
                /* the end of the run holding the character (taken now:
                ** the accent's run may move the run array) */
                base_end = p->lab->runs[pc->first].x
                    + p->lab->runs[pc->first].width;
                top = pc->top;
                skew = g.italic ? 0.12 * f->size * fmax(0, top) / f->size
                                : 0;
                g.italic = false;
                p->lab->merge_ok = false;
                n = utf8_encode(accents[i].cp, buf);
                if (accents[i].cp == 0x2192)
                    g.size = f->size * SCRIPT_RATIO;   /* a small arrow */
                nx = put_text(p->lab, &g, x, y, buf, n);
                if (isnan(nx)) {
                    pnomem(p);
                    return false;
                }
                {
                    run_t *acc = &p->lab->runs[p->lab->count - 1];
                    double base_cx = base_end
                        - 0.5 * (pc->x1 - x);   /* centre of the char */
                    ax = base_cx + skew
                        - 0.5 * (acc->ink[0] + acc->ink[2]);
                    acc->x = ax;
                    /* the accent's ink bottom a small gap above the
                    ** character's top */
                    acc->y = y + fmax(top, 0.431 * f->size) + 0.06 * f->size
                        + acc->ink[3];
                }
                p->lab->merge_ok = false;
                pc->end = p->lab->count;
                return true;
            }
        }
        if (strcmp(name, "frac") == 0)
            return parse_frac(p, f, x, y, pc, at);
        if (strcmp(name, "mathrm") == 0 || strcmp(name, "text") == 0
            || strcmp(name, "mathbf") == 0 || strcmp(name, "mathit") == 0
            || strcmp(name, "operatorname") == 0) {
            font_t g = *f;
            g.italic = strcmp(name, "mathit") == 0;
            g.bold = strcmp(name, "mathbf") == 0;
            g.text = strcmp(name, "text") == 0 || strcmp(name, "mathrm") == 0
                || strcmp(name, "operatorname") == 0;
            while (p->pos < p->len && p->s[p->pos] == ' ')
                p->pos++;
            if (p->pos >= p->len || p->s[p->pos] != '{') {
                perr(p, at, "a font command needs a {group}");
                return false;
            }
            if (!parse_atom(p, &g, x, y, pc))
                return false;
            return true;
        }
        {
            char msg[64];
            snprintf(msg, sizeof msg, "unknown command \\%s", name);
            perr(p, at, msg);
        }
        return false;
    }
    n = utf8_decode(p->s, p->len, at, &cp);
    if (n == 0) {
        perr(p, at, "invalid UTF-8");
        return false;
    }
    p->pos = at + n;
    if (!math)
        return emit_char(p, f, cp, f->italic, CLS_ORD, x, y, pc);
    if ((cp >= 'a' && cp <= 'z') || (cp >= 'A' && cp <= 'Z'))
        return emit_char(p, f, cp, !f->bold, CLS_ORD, x, y, pc);
    if (cp >= 0x3b1 && cp <= 0x3c9)   /* lowercase Greek typed directly */
        return emit_char(p, f, cp, !f->bold, CLS_ORD, x, y, pc);
    switch (cp) {
    case '-':
        return emit_char(p, f, 0x2212, false, CLS_BIN, x, y, pc);
    case '+':
    case '*':
        return emit_char(p, f, cp == '*' ? 0x2217 : cp, false, CLS_BIN, x,
                         y, pc);
    case '=':
    case '<':
    case '>':
        return emit_char(p, f, cp, false, CLS_REL, x, y, pc);
    case '(':
    case '[':
        return emit_char(p, f, cp, false, CLS_OPEN, x, y, pc);
    case ')':
    case ']':
        return emit_char(p, f, cp, false, CLS_CLOSE, x, y, pc);
    case ',':
    case ';':
        return emit_char(p, f, cp, false, CLS_PUNCT, x, y, pc);
    case '\'':
        return emit_char(p, f, 0x2032, false, CLS_ORD, x, y, pc);
    default:
        return emit_char(p, f, cp, false, CLS_ORD, x, y, pc);
    }
}

/* Space in em between atoms of classes a and b (TeX's table, text style;
** scripts get none). */
static double
atom_space(int a, int b)
{
    if (a == CLS_NONE || a == CLS_SPACE || b == CLS_SPACE)
        return 0;
    if (b == CLS_REL && a != CLS_REL && a != CLS_OPEN)
        return 5.0 / 18;
    if (a == CLS_REL && b != CLS_REL && b != CLS_CLOSE && b != CLS_PUNCT)
        return 5.0 / 18;
    if (b == CLS_BIN || a == CLS_BIN)
        return 4.0 / 18;
    if (a == CLS_PUNCT)
        return 3.0 / 18;
    return 0;
}

/* Attach scripts after the nucleus nuc (base size f->size). */
static bool
parse_scripts(parser_t *p, const font_t *f, double y, piece_t *nuc)
{
    piece_t sub, sup;
    bool has_sub = false, has_sup = false;
    double x = nuc->x1, s = f->size, up = 0, down = 0;
    size_t at;

    while (p->pos < p->len && (p->s[p->pos] == '_' || p->s[p->pos] == '^')) {
        char c = p->s[p->pos];
        font_t g;
        piece_t *pc = c == '_' ? &sub : &sup;
        at = p->pos;
        if ((c == '_' && has_sub) || (c == '^' && has_sup)) {
            perr(p, at, c == '_' ? "double subscript"
                                 : "double superscript");
            return false;
        }
        p->pos++;
        if (p->pos >= p->len || p->s[p->pos] == '}' || p->s[p->pos] == '_'
            || p->s[p->pos] == '^' || p->s[p->pos] == '$') {
            perr(p, at, c == '_' ? "'_' without a subscript"
                                 : "'^' without a superscript");
            return false;
        }
        script_font(f, &g, c == '_' ? CF_LABEL_SUB : CF_LABEL_SUP,
                    f->level == 0 ? s : s / (f->level == 1 ? SCRIPT_RATIO
                                                           : SCRIPT2_RATIO));
        /* TeX rule 17: the superscript after the nucleus' italic
        ** correction, the subscript at its advance width */
        if (!parse_atom(p, &g, c == '^' ? x + nuc->ic : x, y, pc))
            return false;
        /* scripts of scripts: x^{a_b} is handled inside the group; a
        ** script atom itself may not take scripts here */
        piece_ink(p->lab, pc, y);
        if (c == '_')
            has_sub = true;
        else
            has_sup = true;
    }
    /* TeX rules 18a-f, simplified (font parameters of cmsy/cmex). */
    if (has_sup) {
        up = 0.413 * s;
        if (nuc->group)
            up = fmax(up, nuc->top - 0.386 * s * SCRIPT_RATIO);
        up = fmax(up, sup.bottom + 0.25 * 0.431 * s);
    }
    if (has_sub) {
        down = has_sup ? 0.247 * s : 0.150 * s;
        if (nuc->group)
            down = fmax(down, nuc->bottom + 0.05 * s * SCRIPT_RATIO);
        if (!has_sup)
            down = fmax(down, sub.top - 0.8 * 0.431 * s);
    }
    if (has_sub && has_sup) {
        double gap = (up - sup.bottom) - (sub.top - down);
        if (gap < 4 * 0.04 * s)
            down += 4 * 0.04 * s - gap;
    }
    if (has_sup)
        shift_runs(p->lab, sup.first, sup.end, up);
    if (has_sub)
        shift_runs(p->lab, sub.first, sub.end, -down);
    nuc->end = p->lab->count;
    if (has_sup)
        nuc->x1 = fmax(nuc->x1, sup.x1);
    if (has_sub)
        nuc->x1 = fmax(nuc->x1, sub.x1);
    /* a little space after the scripts, like TeX's \scriptspace */
    nuc->x1 += 0.05 * s;
    return true;
}

/* Whether the next non-blank input is a binary operator or a relation. */
static bool
next_is_operator(const parser_t *p)
{
    size_t i = p->pos, k;
    char name[24];
    while (i < p->len && p->s[i] == ' ')
        i++;
    if (i >= p->len)
        return true;   /* trailing space: dropped */
    if (strchr("+-=<>*", p->s[i]) != NULL)
        return true;
    if (p->s[i] != '\\')
        return false;
    if (command_name(p, i + 1, name, sizeof name) == 0)
        return false;
    for (k = 0; k < sizeof commands / sizeof commands[0]; k++)
        if (strcmp(name, commands[k].name) == 0)
            return commands[k].cls == CLS_BIN || commands[k].cls == CLS_REL;
    return false;
}

/* A list of atoms until stop ('}' , '$' or 0 for the end). */
static bool
parse_list(parser_t *p, const font_t *f, double x, double y, int stop,
           piece_t *out)
{
    int prev = CLS_NONE;
    piece_init(out, p->lab, x);
    while (p->pos < p->len) {
        char c = p->s[p->pos];
        piece_t pc;
        if (c == '}') {
            if (stop == '}')
                break;
            perr(p, p->pos, "unbalanced '}'");
            return false;
        }
        if (c == '$' && p->has_dollar) {
            if (stop == '$' || stop == '}')
                break;
            /* switch modes */
            {
                font_t g = *f;
                size_t at = p->pos;
                p->pos++;
                g.text = false;
                g.italic = false;
                if (!parse_list(p, &g, x, y, '$', &pc))
                    return false;
                if (p->pos >= p->len || p->s[p->pos] != '$') {
                    perr(p, at, "unbalanced '$'");
                    return false;
                }
                p->pos++;
                x = pc.x1;
                prev = CLS_NONE;
                continue;
            }
        }
        if (!f->text && (c == '_' || c == '^')) {
            perr(p, p->pos, c == '_' ? "'_' without a base"
                                     : "'^' without a base");
            return false;
        }
        if (!f->text && c == ' ') {
            /* spaces are kept, as a normal inter-word space, except next
            ** to an operator, which gets TeX's spacing instead */
            piece_t sp;
            double nx;
            p->pos++;
            if (prev == CLS_BIN || prev == CLS_REL || prev == CLS_SPACE
                || next_is_operator(p))
                continue;
            piece_init(&sp, p->lab, x);
            nx = put_text(p->lab, f, x, y, " ", 1);
            if (isnan(nx))
                return pnomem(p), false;
            x = nx;
            prev = CLS_SPACE;
            continue;
        }
        {
            double x0 = x, sp;
            size_t first_run = p->lab->count;
            if (!parse_atom(p, f, x, y, &pc))
                return false;
            /* class-dependent space before this atom (only at level 0;
            ** a binary operator after nothing/an operator is unary) */
            if (pc.cls == CLS_BIN
                && (prev == CLS_NONE || prev == CLS_BIN || prev == CLS_REL
                    || prev == CLS_OPEN || prev == CLS_PUNCT
                    || prev == CLS_SPACE))
                pc.cls = CLS_ORD;
            sp = (f->level == 0 && !f->text) ? atom_space(prev, pc.cls) : 0;
            if (sp != 0) {
                size_t i;
                double dx = sp * f->size;
                /* move the atom's runs right; a run merged with the
                ** previous atom is split off by re-emitting is not needed
                ** because classes differing in space never merge: the
                ** merge only happens for ORD-ORD pairs */
                for (i = first_run; i < p->lab->count; i++)
                    p->lab->runs[i].x += dx;
                pc.x1 += dx;
                (void)x0;
            }
            if (!f->text && p->pos < p->len
                && (p->s[p->pos] == '_' || p->s[p->pos] == '^')) {
                if (!parse_scripts(p, f, y, &pc))
                    return false;
            } else {
                pc.x1 += pc.ic;   /* before an upright symbol */
            }
            x = pc.x1;
            prev = pc.cls;
        }
    }
    out->end = p->lab->count;
    out->x1 = x;
    piece_ink(p->lab, out, y);
    return true;
}

/* ---- public ------------------------------------------------------------- */

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
    cf_free(label->boxes);
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

cf_status_t
cf_label_create(const char *text, const char *family, double size_bp,
                cf_label_t **out, cf_diag_t *diag)
{
    cf_label_t *lab;
    parser_t p;
    font_t f;
    piece_t all;
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

    memset(&p, 0, sizeof p);
    p.s = text;
    p.len = strlen(text);
    p.lab = lab;
    p.diag = diag;
    p.has_dollar = false;
    for (i = 0; i < p.len; i++) {
        if (text[i] == '\\' && i + 1 < p.len) {
            i++;
            continue;
        }
        if (text[i] == '$')
            p.has_dollar = true;
    }
    memset(&f, 0, sizeof f);
    f.size = size_bp;
    f.level = 0;
    f.kind = CF_LABEL_BASE;
    f.text = p.has_dollar;   /* with $: text outside, math inside */
    if (!parse_list(&p, &f, 0.0, 0.0, 0, &all)) {
        cf_status_t st = p.st != CF_STATUS_OK ? p.st
            : cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1, "label \"%s\"",
                        text);
        cf_label_destroy(lab);
        return st;
    }
    lab->boxes = cf_alloc_array(lab->count ? lab->count : 1,
                                 sizeof *lab->boxes);
    if (lab->boxes == NULL) {
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
cf__label_draw_halo(const cf_label_t *label, cairo_t *cr, double x,
                    double y, const cf_color_t *halo_color, double halo)
{
    size_t i;
    if (label == NULL || !(halo > 0) || halo_color->a <= 0)
        return;
    cairo_save(cr);
    cairo_new_path(cr);
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
    cairo_set_source_rgba(cr, halo_color->r, halo_color->g, halo_color->b,
                          halo_color->a);
    cairo_set_line_width(cr, 2 * halo);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_stroke(cr);
    cairo_restore(cr);
}
