/*
** The built-up constructions of labels, set by TeX's rules (The TeXbook,
** appendix G) in text style: fractions and binomials (rule 15), radicals
** (rule 11) and delimiters sized to what they enclose (rule 19).  The
** dimensions are those of Latin Modern Math's OpenType MATH table, which
** are TeX's own (Computer Modern's cmsy10 and cmex10), in em:
**   axis height 0.25, fraction rule 0.04, numerator shift 0.394 (no rule:
**   0.444), denominator shift 0.345, null delimiter space 0.12;
**   RadicalRuleThickness 0.04, RadicalVerticalGap 0.05 (TeX's
**   θ + θ/4), RadicalKernBeforeDegree 5/18, RadicalKernAfterDegree
**   -10/18, RadicalDegreeBottomRaisePercent 60;
**   and TeX's \delimiterfactor 901 and \delimitershortfall 5 pt for
**   \left ... \right.
** Where TeX takes the first of the font's taller variants of the sign (1.2,
** 1.8, 2.4, 3 em: cmex10's \big ... \Bigg) that reaches the height
** needed, a label scales the base glyph (1 em) to exactly that height, so
** that every output (PNG, PDF, SVG, the course page's glyph data) draws
** it from the same font as a character: its strokes grow with it (as
** little as the height needs), and the radical's rule takes the
** thickness of the scaled sign's top stroke.
*/
#include <math.h>
#include <string.h>

#include "label-impl.h"

#define AXIS 0.25                  /* em */
#define RULE 0.04                  /* em */

/* The base size of f's level (the size at level 0). */
static double
base_size(const font_t *f)
{
    return f->level == 0 ? f->size
                         : f->size / (f->level == 1 ? SCRIPT_RATIO
                                                    : SCRIPT2_RATIO);
}

static void
skip_spaces(parser_t *p)
{
    while (p->pos < p->len && p->s[p->pos] == ' ')
        p->pos++;
}

/* One argument: a {group} or a single token (TeX's \frac14). */
static bool
argument(parser_t *p, const font_t *f, double x, double y, piece_t *pc,
         size_t at, const char *what)
{
    skip_spaces(p);
    if (p->pos >= p->len || p->s[p->pos] == '}' || p->s[p->pos] == '$'
        || p->s[p->pos] == '^' || p->s[p->pos] == '_') {
        cf__lp_error(p, at, what);
        return false;
    }
    p->lab->merge_ok = false;
    if (!p->atom(p, f, x, y, pc))
        return false;
    cf__lp_piece_ink(p->lab, pc, y);
    return true;
}

/* The font of a sized glyph: the math font, upright, at k times f's
** size. */
static void
glyph_font(const font_t *f, double k, font_t *g)
{
    *g = *f;
    g->size = f->size * k;
    g->math = true;
    g->italic = g->bold = g->boldsymbol = g->cal = g->bb = g->text = false;
}

/* The scale of the base glyph of cp (ink height *total at f's size) that
** reaches at least need bp (1 when it does already); NAN when the fonts
** failed (out of memory: the parser's error is set). */
static double
variant_scale(parser_t *p, const font_t *f, unsigned cp, double need,
              double *total)
{
    char buf[8];
    size_t n = cf__utf8_encode(cp, buf);
    double w, ink[4];
    font_t g;
    glyph_font(f, 1, &g);
    if (!cf__label_measure(p->lab, &g, buf, n, &w, ink)) {
        *total = 0;
        cf__lp_nomem(p);
        return NAN;
    }
    if (!(ink[3] > ink[1])) {
        *total = 0;
        return 1;
    }
    *total = ink[3] - ink[1];
    return *total >= need ? 1 : need / *total;
}

/* Put cp in the math font at k times f's size at x, its ink's vertical
** middle at y + mid (or its baseline at y when mid is NAN); *w its
** advance, ink[4] its ink box relative to the run origin (y down). */
static bool
put_glyph(parser_t *p, const font_t *f, unsigned cp, double k, double x,
          double y, double mid, double *w, double ink[4])
{
    char buf[8];
    size_t n = cf__utf8_encode(cp, buf);
    font_t g;
    run_t *r;
    glyph_font(f, k, &g);
    p->lab->merge_ok = false;
    if (isnan(cf__label_put_text(p->lab, &g, x, y, buf, n))) {
        cf__lp_nomem(p);
        return false;
    }
    p->lab->merge_ok = false;
    r = &p->lab->runs[p->lab->count - 1];
    if (!isnan(mid))
        r->y = y + mid + 0.5 * (r->ink[1] + r->ink[3]);
    *w = r->width;
    memcpy(ink, r->ink, sizeof r->ink);
    return true;
}

/* The delimiter cp (0: none, TeX's '.', a null delimiter space) at x,
** centred on the axis, at least need bp tall; *w its width. */
static bool
delimiter(parser_t *p, const font_t *f, unsigned cp, double need, double x,
          double y, double *w)
{
    double total, k, ink[4];
    if (cp == 0) {
        *w = 0.12 * f->size;
        return true;
    }
    k = variant_scale(p, f, cp, need, &total);
    if (isnan(k))
        return false;
    return put_glyph(p, f, cp, k, x, y, AXIS * f->size, w, ink);
}

/* inner (laid out from x) between the delimiters left and right, sized
** to need (at least) and to inner by rule 19: pc becomes the whole, an
** inner atom. */
static bool
delimit(parser_t *p, const font_t *f, double x, double y, piece_t *inner,
        unsigned left, unsigned right, double need, piece_t *pc)
{
    double s = f->size, axis = AXIS * s, wl, wr, delta;
    size_t end = inner->end;
    delta = fmax(inner->top - axis, inner->bottom + axis);
    need = fmax(need, fmax(delta * 901 / 500, 2 * delta - 0.5 * s));
    if (!delimiter(p, f, left, need, x, y, &wl))
        return false;
    cf__lp_move(p->lab, inner->first, end, wl, 0);
    if (!delimiter(p, f, right, need, inner->x1 + wl, y, &wr))
        return false;
    cf__lp_over_group(p->lab, pc, inner->first, y);
    pc->x0 = x;
    pc->x1 = inner->x1 + wl + wr;
    pc->cls = CLS_INNER;
    return true;
}

/* \frac{num}{den} (or \frac14): both at the next script level, centred
** over each other around a rule on the math axis, a clearance of one
** rule thickness from it.  \binom{n}{k} (rule false): no rule, a
** clearance of three, the numerator shifted by 0.444 em, and
** parentheses of at least 1.01 em (TeX's delim2). */
bool
cf__label_frac(parser_t *p, const font_t *f, double x, double y,
               piece_t *pc, size_t at, bool rule)
{
    piece_t num, den, stack;
    font_t g;
    double s = f->size, wn, wd, w, pad = rule ? 0.12 * s : 0, th = RULE * s;
    double axis = AXIS * s, up = (rule ? 0.394 : 0.444) * s;
    double down = 0.345 * s;
    const char *what = rule ? "\\frac needs {numerator}{denominator}"
                            : "\\binom needs {n}{k}";

    cf__lp_script_font(f, &g, f->kind, base_size(f));
    if (!argument(p, &g, x + pad, y, &num, at, what)
        || !argument(p, &g, x + pad, y, &den, at, what))
        return false;
    wn = num.x1 - num.x0;
    wd = den.x1 - den.x0;
    w = fmax(wn, wd);
    if (rule) {
        if ((up - num.bottom) - (axis + th / 2) < th)
            up = axis + th / 2 + th + num.bottom;
        if ((axis - th / 2) - (den.top - down) < th)
            down = den.top + th - (axis - th / 2);
    } else {
        double gap = (up - num.bottom) - (den.top - down);
        if (gap < 3 * th) {
            up += (3 * th - gap) / 2;
            down += (3 * th - gap) / 2;
        }
    }
    cf__lp_move(p->lab, num.first, num.end, (w - wn) / 2, up);
    cf__lp_move(p->lab, den.first, den.end, (w - wd) / 2, -down);
    if (rule && !cf__lp_rule(p, f, x + pad, y + axis - th / 2, w, th))
        return false;
    cf__lp_over_group(p->lab, pc, num.first, y);
    pc->x0 = x;
    pc->x1 = x + w + 2 * pad;
    if (rule)
        return true;
    stack = *pc;
    return delimit(p, f, x, y, &stack, '(', ')', 1.01 * s, pc);
}

/* \sqrt{x} and \sqrt[n]{x}: the radical sign of the first size whose ink
** reaches the radicand's height plus depth plus the gap and the rule, its
** top stroke continued by a rule over the radicand; what the sign has in
** excess is shared between the gap above the radicand and the depth
** below it (rule 11).  The degree is set two script levels down, raised
** to 60 % of the sign's height, 5/18 em after what precedes and
** overlapping the sign by 10/18 em. */
bool
cf__label_sqrt(parser_t *p, const font_t *f, double x, double y,
               piece_t *pc, size_t at)
{
    piece_t deg, rad;
    font_t d1, d2;
    double s = f->size, gap = 0.05 * s, total, k, th, clear, depth, lift;
    double xs = x, w, ink[4], rule_bottom;
    bool has_deg = false;
    size_t first = p->lab->count;

    skip_spaces(p);
    if (p->pos < p->len && p->s[p->pos] == '[') {
        size_t open = p->pos++;
        cf__lp_script_font(f, &d1, f->kind, base_size(f));
        cf__lp_script_font(&d1, &d2, f->kind, base_size(f));
        p->lab->merge_ok = false;
        if (!p->list(p, &d2, x, y, ']', &deg))
            return false;
        if (p->pos >= p->len || p->s[p->pos] != ']') {
            cf__lp_error(p, open, "\\sqrt[ without its ']'");
            return false;
        }
        p->pos++;
        has_deg = true;
    }
    if (!argument(p, f, x, y, &rad, at, "\\sqrt needs {radicand}"))
        return false;
    k = variant_scale(p, f, 0x221a, rad.top + rad.bottom + gap + RULE * s,
                      &total);
    if (isnan(k))
        return false;
    if (k > 1)   /* the rule grows with the sign: k (total - rule) covers */
        k = (rad.top + rad.bottom + gap) / (total - RULE * s);
    total *= k;
    th = RULE * s * k;
    clear = gap;
    depth = total - th;
    if (depth > rad.top + rad.bottom + clear)
        clear = (clear + depth - rad.top - rad.bottom) / 2;
    rule_bottom = rad.top + clear;
    /* the sign's ink top is the rule's top */
    lift = rule_bottom + th;
    if (has_deg) {
        double kb = 5.0 / 18 * s, ka = -10.0 / 18 * s;
        double sign_bottom = lift - total;
        cf__lp_move(p->lab, deg.first, deg.end, kb,
                    sign_bottom + 0.6 * total + deg.bottom);
        xs = fmax(x, x + kb + (deg.x1 - deg.x0) + ka);
    }
    if (!put_glyph(p, f, 0x221a, k, xs, y, NAN, &w, ink))
        return false;
    /* put_glyph set the baseline at y: move the ink's top to lift */
    p->lab->runs[p->lab->count - 1].y += lift + ink[1];
    cf__lp_move(p->lab, rad.first, rad.end, xs + w - rad.x0, 0);
    {
        double from = xs + fmin(w, ink[2]) - 0.5 * th;
        if (!cf__lp_rule(p, f, from, y + rule_bottom,
                         xs + w + (rad.x1 - rad.x0) - from, th))
            return false;
    }
    cf__lp_over_group(p->lab, pc, first, y);
    pc->x0 = x;
    pc->x1 = xs + w + (rad.x1 - rad.x0);
    return true;
}

/* The delimiter after \left or \right at p->pos: ( ) [ ] | / . or \{ \}
** \langle \rangle \lvert \rvert \| ; false with a message otherwise. */
static bool
read_delimiter(parser_t *p, size_t at, unsigned *cp)
{
    static const struct {
        const char *text;
        unsigned cp;
    } table[] = {
        { "(", '(' },          { ")", ')' },         { "[", '[' },
        { "]", ']' },          { "|", '|' },         { "/", '/' },
        { ".", 0 },            { "\\{", '{' },       { "\\}", '}' },
        { "\\langle", 0x27e8 }, { "\\rangle", 0x27e9 },
        { "\\lvert", '|' },    { "\\rvert", '|' },   { "\\|", 0x2016 },
    };
    size_t i;
    skip_spaces(p);
    for (i = 0; i < sizeof table / sizeof table[0]; i++) {
        size_t n = strlen(table[i].text);
        if (p->pos + n <= p->len
            && memcmp(p->s + p->pos, table[i].text, n) == 0
            && !(n > 2 && p->pos + n < p->len
                 && ((p->s[p->pos + n] >= 'a' && p->s[p->pos + n] <= 'z')
                     || (p->s[p->pos + n] >= 'A'
                         && p->s[p->pos + n] <= 'Z')))) {
            p->pos += n;
            *cp = table[i].cp;
            return true;
        }
    }
    cf__lp_error(p, at, "\\left and \\right take a delimiter: ( ) [ ] | / "
                        ". \\{ \\} \\langle \\rangle \\|");
    return false;
}

/* \left( ... \right): the list between, and the delimiters sized to it
** (rule 19: at least 901/1000 of twice its largest distance from the
** axis, and at most 5 pt short of it). */
bool
cf__label_left_right(parser_t *p, const font_t *f, double x, double y,
                     piece_t *pc, size_t at)
{
    unsigned left, right;
    piece_t inner;
    if (!read_delimiter(p, at, &left))
        return false;
    if (++p->depth > MAX_DEPTH) {
        cf__lp_error(p, at, "groups nested too deeply");
        return false;
    }
    p->lab->merge_ok = false;
    if (!p->list(p, f, x, y, 'R', &inner))
        return false;
    p->depth--;
    if (p->pos + 6 > p->len || memcmp(p->s + p->pos, "\\right", 6) != 0) {
        cf__lp_error(p, at, "\\left without its \\right");
        return false;
    }
    p->pos += 6;
    if (!read_delimiter(p, p->pos - 6, &right))
        return false;
    return delimit(p, f, x, y, &inner, left, right, 0, pc);
}
