/*
** The label parser (syntax in include/curvefig/label.h).  It lays out as
** it reads.  Each character becomes part of a run
** (render/labels/label-runs.c); sub- and superscripts are laid out at the
** pen position and then shifted vertically, with shifts taken from TeX's
** font parameters (cmsy10: sup1 = 0.413 em, sub1 = 0.150 em, sub2 = 0.247
** em, x-height 0.431 em, rule thickness 0.04 em), so B_i^n stacks both
** scripts at the same x.
*/
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "label-impl.h"

static bool parse_atom(parser_t *p, const font_t *f, double x, double y,
                       piece_t *pc);
static bool parse_list(parser_t *p, const font_t *f, double x, double y,
                       int stop, piece_t *out);

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
            cf__lp_error(p, p->pos, "\\mathcal takes capital letters A-Z");
            return false;
        }
    } else if (g->bb) {
        m = cf__math_bb(*cp);
        if (m == 0) {
            cf__lp_error(p, p->pos,
                         "\\mathbb takes capital letters A-Z and digits");
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
        g->italic = !g->cal && !g->bb;
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
    cf__lp_piece_init(pc, p->lab, x);
    /* only ordinary atoms continue a run: operators get spaces */
    p->lab->merge_ok = p->lab->merge_ok && cls == CLS_ORD;
    nx = cf__label_put_text(p->lab, &g, x, y, buf, n);
    p->lab->merge_ok = cls == CLS_ORD;
    if (isnan(nx)) {
        cf__lp_nomem(p);
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
    if (isnan(pc->ic)) {
        cf__lp_nomem(p);
        return false;
    }
    {
        /* the nucleus' own ink: measured on the character alone */
        run_t *r = &p->lab->runs[pc->first];
        double top = r->ink[1], bottom = r->ink[3];
        pc->top = bottom > top ? (r->y - y) - top : 0;
        pc->bottom = bottom > top ? bottom - (r->y - y) : 0;
    }
    return true;
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
        cf__lp_nomem(p);
        return false;
    }
    return true;
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
    cf__lp_piece_ink(p->lab, pc, y);
    if (!put_accent(p, f, x, y, acc_cp))
        return false;
    acc = &p->lab->runs[p->lab->count - 1];
    acc->x = 0.5 * (pc->x0 + pc->x1) - 0.5 * (acc->ink[0] + acc->ink[2]);
    acc->y = y + fmax(pc->top, 0.431 * f->size) + 0.06 * f->size
           + acc->ink[3];
    cf__lp_over_group(p->lab, pc, first, y);
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
        cf__lp_error(p, at, "an accent needs a character or a {group}");
        return false;
    }
    if (braced)
        while (++p->pos < p->len && p->s[p->pos] == ' ')
            ;
    if (p->pos >= p->len
        || (m = cf__utf8_decode(p->s, p->len, p->pos, &base)) == 0
        || base == '{' || base == '}' || base == '\\') {
        cf__lp_error(p, at, "an accent needs a character or a {group}");
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
    g.bb = strcmp(name, "mathbb") == 0;
    g.text = strcmp(name, "text") == 0 || strcmp(name, "mathrm") == 0
        || strcmp(name, "operatorname") == 0;
    while (p->pos < p->len && p->s[p->pos] == ' ')
        p->pos++;
    if (p->pos >= p->len || p->s[p->pos] != '{') {
        cf__lp_error(p, at, "a font command needs a {group}");
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
        cf__lp_error(p, at, "\\overline needs a {group}");
        return false;
    }
    p->lab->merge_ok = false;
    if (!parse_atom(p, f, x, y, pc))
        return false;
    first = pc->first;
    cf__lp_piece_ink(p->lab, pc, y);
    if (!cf__lp_rule(p, f, pc->x0, y + fmax(pc->top, 0.431 * f->size) + 3 * th,
                  pc->x1 - pc->x0, th))
        return false;
    cf__lp_over_group(p->lab, pc, first, y);
    return true;
}

static bool
is_font_command(const char *name)
{
    static const char *const fonts[] = {
        "mathrm", "text", "operatorname", "mathit", "mathbf", "boldsymbol",
        "mathcal", "mathbb",
    };
    size_t i;
    for (i = 0; i < sizeof fonts / sizeof fonts[0]; i++)
        if (strcmp(name, fonts[i]) == 0)
            return true;
    return false;
}

/* A command after '\\' at byte at: a space, a symbol, an accent, a
** fraction or a font. */
static bool
parse_command(parser_t *p, const font_t *f, double x, double y,
              piece_t *pc, size_t at)
{
    char name[24], msg[128];
    const char *near;
    size_t n = command_name(p, at + 1, name, sizeof name);
    bool math = !f->text, italic;
    unsigned cp;
    double em;
    int cls;

    if (n == 0) {
        cf__lp_error(p, at, "'\\' without a command name");
        return false;
    }
    p->pos = at + 1 + n;
    if (cf__label_space(name, &em)) {
        cf__lp_piece_init(pc, p->lab, x);
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
    if (strcmp(name, "frac") == 0 || strcmp(name, "binom") == 0)
        return cf__label_frac(p, f, x, y, pc, at, name[0] == 'f');
    if (strcmp(name, "sqrt") == 0)
        return cf__label_sqrt(p, f, x, y, pc, at);
    if (strcmp(name, "left") == 0)
        return cf__label_left_right(p, f, x, y, pc, at);
    if (strcmp(name, "right") == 0) {
        cf__lp_error(p, at, "\\right without \\left");
        return false;
    }
    if (strcmp(name, "overline") == 0)
        return parse_overline(p, f, x, y, pc, at);
    if (is_font_command(name))
        return parse_font_command(p, f, name, x, y, pc, at);
    near = cf__label_nearest_command(name);
    if (near != NULL)
        snprintf(msg, sizeof msg, "unknown command \\%s (did you mean "
                 "\\%s? `curvefig help labels` lists them)", name, near);
    else
        snprintf(msg, sizeof msg, "unknown command \\%s (`curvefig help "
                 "labels` lists the commands)", name);
    cf__lp_error(p, at, msg);
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
        cf__lp_error(p, at, "groups nested too deeply");
        return false;
    }
    if (!parse_list(p, &g, x, y, '}', pc))
        return false;
    p->depth--;
    if (p->pos >= p->len || p->s[p->pos] != '}') {
        cf__lp_error(p, at, "unbalanced '{'");
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
        cf__lp_error(p, at, "invalid UTF-8");
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
            cf__lp_error(p, at, c == '_' ? "double subscript"
                                 : "double superscript");
            return false;
        }
        p->pos++;
        if (p->pos >= p->len || p->s[p->pos] == '}' || p->s[p->pos] == '_'
            || p->s[p->pos] == '^' || p->s[p->pos] == '$') {
            cf__lp_error(p, at, c == '_' ? "'_' without a subscript"
                                 : "'^' without a superscript");
            return false;
        }
        cf__lp_script_font(f, &g, c == '_' ? CF_LABEL_SUB : CF_LABEL_SUP,
                    f->level == 0 ? s : s / (f->level == 1 ? SCRIPT_RATIO
                                                           : SCRIPT2_RATIO));
        /* TeX rule 17: the superscript after the nucleus' italic
        ** correction, the subscript at its advance width */
        if (!parse_atom(p, &g, c == '^' ? x + nuc->ic : x, y, pc))
            return false;
        /* scripts of scripts: x^{a_b} is handled inside the group; a
        ** script atom itself may not take scripts here */
        cf__lp_piece_ink(p->lab, pc, y);
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
    cf__lp_piece_init(out, p->lab, x);
    while (p->pos < p->len) {
        char c = p->s[p->pos];
        piece_t pc;
        if (c == '}') {
            if (stop == '}')
                break;
            cf__lp_error(p, p->pos, "unbalanced '}'");
            return false;
        }
        if ((stop == ']' && c == ']')
            || (stop == 'R' && c == '\\' && p->pos + 6 <= p->len
                && memcmp(p->s + p->pos + 1, "right", 5) == 0
                && !(p->pos + 6 < p->len
                     && ((p->s[p->pos + 6] >= 'a' && p->s[p->pos + 6] <= 'z')
                         || (p->s[p->pos + 6] >= 'A'
                             && p->s[p->pos + 6] <= 'Z')))))
            break;
        if (c == '$' && p->has_dollar) {
            if (stop != 0)
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
                    cf__lp_error(p, at, "unbalanced '$'");
                    return false;
                }
                p->pos++;
                x = pc.x1;
                prev = CLS_NONE;
                continue;
            }
        }
        if (!f->text && (c == '_' || c == '^')) {
            cf__lp_error(p, p->pos, c == '_' ? "'_' without a base"
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
                cf__lp_move(p->lab, prev_first, first_run, -prev_space, 0);
                x -= prev_space;
                cf__lp_move(p->lab, first_run, p->lab->count, -prev_space, 0);
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
                cf__lp_move(p->lab, first_run, p->lab->count, sp, 0);
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
        cf__lp_move(p->lab, prev_first, p->lab->count, -prev_space, 0);
        x -= prev_space;
    }
    out->end = p->lab->count;
    out->x1 = x;
    cf__lp_piece_ink(p->lab, out, y);
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
    p.atom = parse_atom;
    p.list = parse_list;
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
