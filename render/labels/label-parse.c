/*
** The label parser (syntax in include/curvefig/label.h).  It lays out as
** it reads.  Each character becomes part of a run (render/label-runs.c);
** sub- and superscripts are laid out at the pen position and then shifted
** vertically, with shifts taken from TeX's font parameters (cmsy10:
** sup1 = 0.413 em, sub1 = 0.150 em, sub2 = 0.247 em, x-height 0.431 em,
** rule thickness 0.04 em), so B_i^n stacks both scripts at the same x.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "label-impl.h"

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

static cf_status_t
perr(parser_t *p, size_t at, const char *what)
{
    char ex[80];
    if (p->st == CF_STATUS_OK) {
        cf__label_excerpt(p->s, p->len, at, ex, sizeof ex);
        p->st = cf_diag_set(p->diag, CF_STATUS_INVALID_ARG, (long)at,
                            "label \"%s\": %s at byte %zu", ex, what, at);
    }
    return p->st;
}

static cf_status_t
pnomem(parser_t *p)
{
    char ex[80];
    if (p->st == CF_STATUS_OK) {
        cf__label_excerpt(p->s, p->len, 0, ex, sizeof ex);
        p->st = cf_diag_set(p->diag, CF_STATUS_NO_MEMORY, -1,
                            "label \"%s\": out of memory", ex);
    }
    return p->st;
}

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

/* The form of code point *cp in mathematics, in font g (italic set for
** a letter): a letter of a TeX family in the math italic (or bold italic)
** alphabet of the math font, a calligraphic capital, TeX's symbols
** (operators, relations, arrows) from the math font too.  False after an
** error. */
static bool
math_form(parser_t *p, font_t *g, unsigned *cp)
{
    unsigned m = 0;
    if (g->cal) {
        m = cf__math_cal(*cp);
        if (m == 0) {
            perr(p, p->pos, "\\mathcal takes capital letters A-Z");
            return false;
        }
    } else if (g->italic && p->lab->tex_math) {
        m = cf__math_italic(*cp, g->boldsymbol);
    } else if (!g->italic && ((*cp >= 0x2016 && *cp <= 0x2bff)
                              || *cp == 0xd7 || *cp == 0xb1
                              || *cp == 0xac)) {
        g->math = true;
        g->bold = false;
    }
    if (m != 0) {
        /* the glyph is italic itself: the run stays marked italic */
        *cp = m;
        g->math = true;
        g->italic = !g->cal;
        g->bold = false;
    }
    return true;
}

/* Emit one code point as an atom. */
static bool
emit_char(parser_t *p, const font_t *f, unsigned cp, bool italic, int cls,
          double x, double y, piece_t *pc)
{
    char buf[8];
    size_t n;
    font_t g = *f;
    double nx;
    g.italic = italic;
    if (!f->text && !math_form(p, &g, &cp))
        return false;
    n = cf__utf8_encode(cp, buf);
    piece_init(pc, p->lab, x);
    /* only ordinary atoms continue a run: operators get spaces */
    p->lab->merge_ok = p->lab->merge_ok && cls == CLS_ORD;
    nx = cf__label_put_text(p->lab, &g, x, y, buf, n);
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
        pc->ic = cf__label_italic_correction(p->lab, &g, buf, n);
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

/* A rule of thickness th and width w, its bottom at (x, y), as a run
** without text; false when out of memory. */
static bool
add_rule(parser_t *p, const font_t *f, double x, double y, double w,
         double th)
{
    run_t *r;
    if (isnan(cf__label_put_text(p->lab, f, x, y, "", 0))) {
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
    return true;
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
    if (!add_rule(p, f, x + pad, y + axis - th / 2, w, th))
        return false;
    pc->first = num.first;
    pc->end = p->lab->count;
    pc->x0 = x;
    pc->x1 = x + w + 2 * pad;
    pc->cls = CLS_ORD;
    pc->group = true;
    piece_ink(p->lab, pc, y);
    return true;
}

/* Put the accent's run (the last one) over the character of pc: centred
** on the character's ink with the skew, its ink bottom a small gap above
** the character's top or the x-height. */
static void
place_accent(parser_t *p, const font_t *f, double x, double y, piece_t *pc,
             double base_end, double top, double skew)
{
    run_t *acc = &p->lab->runs[p->lab->count - 1];
    double base_cx = base_end - 0.5 * (pc->x1 - x);   /* centre of the char */
    acc->x = base_cx + skew - 0.5 * (acc->ink[0] + acc->ink[2]);
    acc->y = y + fmax(top, 0.431 * f->size) + 0.06 * f->size + acc->ink[3];
    p->lab->merge_ok = false;
    pc->end = p->lab->count;
}

/* The accent acc_cp as its own run at (x, y) in font f (the arrow of
** \vec: the math font's at half size), upright; false when out of
** memory. */
static bool
put_accent(parser_t *p, const font_t *f, double x, double y, unsigned acc_cp)
{
    font_t g = *f;
    char buf[8];
    size_t n = cf__utf8_encode(acc_cp, buf);
    g.italic = false;
    if (acc_cp == 0x2192) {
        /* the math font's arrow at half size: TeX's \vec, 0.5 em wide */
        g.size = f->size * SCRIPT2_RATIO;
        g.math = true;
    }
    p->lab->merge_ok = false;
    if (isnan(cf__label_put_text(p->lab, &g, x, y, buf, n))) {
        pnomem(p);
        return false;
    }
    return true;
}

/* The group of pc (from run first) with what was put over it: one
** ordinary atom. */
static void
over_group(cf_label_t *lab, piece_t *pc, size_t first, double y)
{
    pc->first = first;
    pc->end = lab->count;
    pc->cls = CLS_ORD;
    pc->group = true;
    piece_ink(lab, pc, y);
}

/* \hat{PQ} (a group of more than one character): the group, then the
** accent centred over the group's width, its ink bottom a small gap above
** the group's top or the x-height (TeX puts a non-wide accent so over
** a group, without skew). */
static bool
parse_group_accent(parser_t *p, const font_t *f, double x, double y,
                   piece_t *pc, unsigned acc_cp)
{
    size_t first;
    run_t *acc;
    p->lab->merge_ok = false;
    if (!parse_atom(p, f, x, y, pc))
        return false;
    first = pc->first;
    piece_ink(p->lab, pc, y);
    if (!put_accent(p, f, x, y, acc_cp))
        return false;
    acc = &p->lab->runs[p->lab->count - 1];
    acc->x = 0.5 * (pc->x0 + pc->x1) - 0.5 * (acc->ink[0] + acc->ink[2]);
    acc->y = y + fmax(pc->top, 0.431 * f->size) + 0.06 * f->size
           + acc->ink[3];
    over_group(p->lab, pc, first, y);
    return true;
}

/* \hat{P} or \hat P (accent code point acc): the character, then the
** accent as its own run centred over the character's ink, raised by the
** character's height above the x-height (TeX's rule, with the italic skew
** of a slanted letter). */
static bool
parse_accent(parser_t *p, const font_t *f, double x, double y, piece_t *pc,
             size_t at, unsigned acc_cp)
{
    bool braced, math = !f->text;
    unsigned base;
    size_t m;
    font_t g = *f;
    double top, skew, base_end;

    while (p->pos < p->len && p->s[p->pos] == ' ')
        p->pos++;
    braced = p->pos < p->len && p->s[p->pos] == '{';
    if (braced && !cf__label_single_char_group(p->s, p->len, p->pos)) {
        size_t q = p->pos + 1;
        while (q < p->len && p->s[q] == ' ')
            q++;
        if (q < p->len && p->s[q] != '}')
            return parse_group_accent(p, f, x, y, pc, acc_cp);
        perr(p, at, "an accent needs a character or a {group}");
        return false;
    }
    if (braced)
        while (++p->pos < p->len && p->s[p->pos] == ' ')
            ;
    if (p->pos >= p->len
        || (m = cf__utf8_decode(p->s, p->len, p->pos, &base)) == 0
        || base == '{' || base == '}' || base == '\\') {
        perr(p, at, "an accent needs a character or a {group}");
        return false;
    }
    p->pos += m;
    if (braced) {
        while (p->pos < p->len && p->s[p->pos] == ' ')
            p->pos++;
        p->pos++;   /* the '}' (cf__label_single_char_group) */
    }
    g.italic = math
        && ((base >= 'a' && base <= 'z') || (base >= 'A' && base <= 'Z')
            || (base >= 0x3b1 && base <= 0x3c9));
    if (!emit_char(p, &g, base, g.italic, CLS_ORD, x, y, pc))
        return false;
    /* the end of the run holding the character (taken now: the accent's
    ** run may move the run array) */
    base_end = p->lab->runs[pc->first].x + p->lab->runs[pc->first].width;
    top = pc->top;
    skew = g.italic ? 0.12 * f->size * fmax(0, top) / f->size : 0;
    if (!put_accent(p, f, x, y, acc_cp))
        return false;
    place_accent(p, f, x, y, pc, base_end, top, skew);
    return true;
}

/* \mathrm{...} \text{...} \mathbf{...} \mathit{...} \operatorname{...}:
** the group in that font. */
static bool
parse_font_command(parser_t *p, const font_t *f, const char *name,
                   double x, double y, piece_t *pc, size_t at)
{
    font_t g = *f;
    g.italic = strcmp(name, "mathit") == 0;
    g.boldsymbol = strcmp(name, "boldsymbol") == 0;
    g.bold = strcmp(name, "mathbf") == 0 || g.boldsymbol;
    g.cal = strcmp(name, "mathcal") == 0;
    g.text = strcmp(name, "text") == 0 || strcmp(name, "mathrm") == 0
        || strcmp(name, "operatorname") == 0;
    while (p->pos < p->len && p->s[p->pos] == ' ')
        p->pos++;
    if (p->pos >= p->len || p->s[p->pos] != '{') {
        perr(p, at, "a font command needs a {group}");
        return false;
    }
    return parse_atom(p, &g, x, y, pc);
}

/* \overline{...}: the group, and a rule of the default rule thickness
** three thicknesses above its ink, as wide as the group (TeX rule 9). */
static bool
parse_overline(parser_t *p, const font_t *f, double x, double y,
               piece_t *pc, size_t at)
{
    double th = 0.04 * f->size;
    size_t first;
    while (p->pos < p->len && p->s[p->pos] == ' ')
        p->pos++;
    if (p->pos >= p->len || p->s[p->pos] != '{') {
        perr(p, at, "\\overline needs a {group}");
        return false;
    }
    p->lab->merge_ok = false;
    if (!parse_atom(p, f, x, y, pc))
        return false;
    first = pc->first;
    piece_ink(p->lab, pc, y);
    if (!add_rule(p, f, pc->x0, y + fmax(pc->top, 0.431 * f->size) + 3 * th,
                  pc->x1 - pc->x0, th))
        return false;
    over_group(p->lab, pc, first, y);
    return true;
}

static bool
is_font_command(const char *name)
{
    return cf__label_structure(name) && strcmp(name, "frac") != 0
        && strcmp(name, "overline") != 0;
}

/* A command after '\\' at byte at: a space, a symbol, an accent, a
** fraction or a font. */
static bool
parse_command(parser_t *p, const font_t *f, double x, double y,
              piece_t *pc, size_t at)
{
    char name[24], msg[64];
    size_t n = command_name(p, at + 1, name, sizeof name);
    bool math = !f->text, italic;
    unsigned cp;
    double em;
    int cls;

    if (n == 0) {
        perr(p, at, "'\\' without a command name");
        return false;
    }
    p->pos = at + 1 + n;
    if (cf__label_space(name, &em)) {
        piece_init(pc, p->lab, x);
        pc->x1 = x + em * f->size;
        pc->cls = CLS_SPACE;
        pc->top = pc->bottom = 0;
        return true;
    }
    if (cf__label_symbol(name, &cp, &cls, &italic))
        return emit_char(p, f, cp,
                         math && italic && (!f->bold || f->boldsymbol),
                         math ? cls : CLS_ORD, x, y, pc);
    if (cf__label_accent(name, &cp))
        return parse_accent(p, f, x, y, pc, at, cp);
    if (strcmp(name, "frac") == 0)
        return parse_frac(p, f, x, y, pc, at);
    if (strcmp(name, "overline") == 0)
        return parse_overline(p, f, x, y, pc, at);
    if (is_font_command(name))
        return parse_font_command(p, f, name, x, y, pc, at);
    snprintf(msg, sizeof msg, "unknown command \\%s", name);
    perr(p, at, msg);
    return false;
}

/* A {group} at byte at. */
static bool
parse_group(parser_t *p, const font_t *f, double x, double y, piece_t *pc,
            size_t at)
{
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

/* One atom at (x, y): a character, a command or a {group}. */
static bool
parse_atom(parser_t *p, const font_t *f, double x, double y, piece_t *pc)
{
    unsigned cp;
    size_t n, at = p->pos;
    char c = p->s[p->pos];
    bool italic;
    int cls;

    if (c == '{')
        return parse_group(p, f, x, y, pc, at);
    if (c == '\\')
        return parse_command(p, f, x, y, pc, at);
    n = cf__utf8_decode(p->s, p->len, at, &cp);
    if (n == 0) {
        perr(p, at, "invalid UTF-8");
        return false;
    }
    p->pos = at + n;
    if (f->text)
        return emit_char(p, f, cp, f->italic, CLS_ORD, x, y, pc);
    cls = cf__label_math_char(&cp, &italic, f);
    return emit_char(p, f, cp, italic, cls, x, y, pc);
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

/* A list of atoms until stop ('}' , '$' or 0 for the end). */
static bool
parse_list(parser_t *p, const font_t *f, double x, double y, int stop,
           piece_t *out)
{
    int prev = CLS_NONE;
    size_t prev_first = p->lab->count;
    double prev_space = 0;    /* the space put before the last operator */
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
            /* spaces in mathematics are ignored, as in TeX */
            p->pos++;
            continue;
        }
        {
            double sp;
            size_t first_run = p->lab->count;
            if (!parse_atom(p, f, x, y, &pc))
                return false;
            /* TeX rule 5: a binary operator after nothing, an operator, a
            ** relation, an opening or punctuation is ordinary (a unary
            ** minus); rule 6: so is one before a relation, a closing or
            ** punctuation */
            if (pc.cls == CLS_BIN
                && (prev == CLS_NONE || prev == CLS_BIN || prev == CLS_OP
                    || prev == CLS_REL || prev == CLS_OPEN
                    || prev == CLS_PUNCT))
                pc.cls = CLS_ORD;
            if (prev == CLS_BIN && (pc.cls == CLS_REL || pc.cls == CLS_CLOSE
                                    || pc.cls == CLS_PUNCT)) {
                /* the previous operator was unary after all: take its
                ** spaces back */
                move_runs(p->lab, prev_first, first_run, -prev_space, 0);
                x -= prev_space;
                move_runs(p->lab, first_run, p->lab->count, -prev_space, 0);
                pc.x1 -= prev_space;
                prev_space = 0;
                prev = CLS_ORD;
            }
            sp = f->text ? 0
                         : cf__label_atom_space(prev, pc.cls, f->level)
                               * f->size;
            if (pc.cls == CLS_SPACE)
                sp = 0;
            if (sp != 0) {
                /* classes that get a space never share a run: the merge
                ** only joins ordinary atoms */
                move_runs(p->lab, first_run, p->lab->count, sp, 0);
                pc.x1 += sp;
            }
            if (!f->text && p->pos < p->len
                && (p->s[p->pos] == '_' || p->s[p->pos] == '^')) {
                if (!parse_scripts(p, f, y, &pc))
                    return false;
            } else {
                pc.x1 += pc.ic;   /* before an upright symbol */
            }
            prev_first = first_run;
            prev_space = pc.cls == CLS_BIN ? sp : 0;
            x = pc.x1;
            if (pc.cls != CLS_SPACE)
                prev = pc.cls;
        }
    }
    /* rule 6 at the end of the list: a trailing operator is ordinary */
    if (prev == CLS_BIN && prev_space != 0) {
        move_runs(p->lab, prev_first, p->lab->count, -prev_space, 0);
        x -= prev_space;
    }
    out->end = p->lab->count;
    out->x1 = x;
    piece_ink(p->lab, out, y);
    return true;
}

cf_status_t
cf__label_parse(cf_label_t *lab, const char *text, cf_diag_t *diag)
{
    parser_t p;
    font_t f;
    piece_t all;

    memset(&p, 0, sizeof p);
    p.s = text;
    p.len = strlen(text);
    p.lab = lab;
    p.diag = diag;
    p.has_dollar = cf__label_has_dollar(text);
    memset(&f, 0, sizeof f);
    f.size = lab->size;
    f.level = 0;
    f.kind = CF_LABEL_BASE;
    f.text = p.has_dollar;   /* with $: text outside, math inside */
    if (!parse_list(&p, &f, 0.0, 0.0, 0, &all))
        return p.st != CF_STATUS_OK
            ? p.st
            : cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1, "label \"%s\"",
                          text);
    return CF_STATUS_OK;
}
