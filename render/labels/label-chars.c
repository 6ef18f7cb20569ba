/*
** The characters of labels: UTF-8, and the tables of symbol commands
** (\\alpha, \\leq), spaces (\\, \\quad) and accents (\\hat).
*/
#include <stdio.h>
#include <string.h>

#include "label-impl.h"

size_t
cf__utf8_decode(const char *s, size_t len, size_t pos, unsigned *cp)
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

void
cf__label_excerpt(const char *s, size_t len, size_t at, char *out,
                  size_t cap)
{
    size_t from = at > 24 ? at - 24 : 0, to = len - at > 24 ? at + 24 : len;
    size_t k = 0, i;
    if (cap < 16) {
        out[0] = '\0';
        return;
    }
    while (from > 0 && from < at && ((unsigned char)s[from] & 0xc0) == 0x80)
        from++;
    while (to < len && to > at && ((unsigned char)s[to] & 0xc0) == 0x80)
        to--;
    if (from > 0)
        k += (size_t)snprintf(out, cap, "...");
    for (i = from; i < to && k + 8 < cap;) {
        unsigned cp = 0;
        size_t n = cf__utf8_decode(s, len, i, &cp);
        if (n == 0 || cp < 0x20 || cp == 0x7f) {
            k += (size_t)snprintf(out + k, cap - k, "\\x%02X",
                                  (unsigned char)s[i]);
            i++;
        } else {
            memcpy(out + k, s + i, n);
            k += n;
            i += n;
        }
    }
    if (i < len && k + 4 <= cap)
        k += (size_t)snprintf(out + k, cap - k, "...");
    out[k < cap ? k : cap - 1] = '\0';
}

size_t
cf__utf8_encode(unsigned c, char *out)
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

bool
cf__label_has_dollar(const char *text)
{
    size_t i, n = strlen(text);
    for (i = 0; i < n; i++) {
        if (text[i] == '\\' && i + 1 < n)
            i++;
        else if (text[i] == '$')
            return true;
    }
    return false;
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
    { "subset", 0x2282, CLS_REL, 0 },  { "sim", 0x223c, CLS_REL, 0 },
    { "perp", 0x22a5, CLS_REL, 0 },    { "parallel", 0x2225, CLS_REL, 0 },
    { "leftarrow", 0x2190, CLS_REL, 0 }, { "Rightarrow", 0x21d2, CLS_REL, 0 },
    { "cup", 0x222a, CLS_BIN, 0 },     { "cap", 0x2229, CLS_BIN, 0 },
    { "infty", 0x221e, CLS_ORD, 0 },   { "partial", 0x2202, CLS_ORD, 1 },
    { "nabla", 0x2207, CLS_ORD, 0 },   { "ldots", 0x2026, CLS_ORD, 0 },
    { "dots", 0x2026, CLS_ORD, 0 },    { "cdots", 0x22ef, CLS_ORD, 0 },
    { "sum", 0x2211, CLS_OP, 0 },      { "prod", 0x220f, CLS_OP, 0 },
    { "int", 0x222b, CLS_OP, 0 },     { "prime", 0x2032, CLS_ORD, 0 },
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
    { ",", 3.0 / 18 }, { ":", 4.0 / 18 }, { ">", 4.0 / 18 },
    { ";", 5.0 / 18 }, { "!", -3.0 / 18 }, { " ", 6.0 / 18 },
    { "enspace", 0.5 }, { "quad", 1.0 }, { "qquad", 2.0 },
};

/* Accents over a character or a group (spacing forms, placed by hand). */
static const struct {
    const char *name;
    unsigned cp;
} accents[] = {
    { "hat", 0x2c6 }, { "bar", 0xaf }, { "tilde", 0x2dc },
    { "vec", 0x2192 }, { "dot", 0x2d9 }, { "ddot", 0xa8 },
};

bool
cf__label_symbol(const char *name, unsigned *cp, int *cls, bool *italic)
{
    size_t i;
    for (i = 0; i < sizeof commands / sizeof commands[0]; i++) {
        if (strcmp(name, commands[i].name) == 0) {
            *cp = commands[i].cp;
            *cls = commands[i].cls;
            *italic = commands[i].italic != 0;
            return true;
        }
    }
    return false;
}

const char *
cf__label_symbol_name(unsigned cp)
{
    size_t i;
    for (i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (commands[i].cp == cp)
            return commands[i].name;
    return NULL;
}

bool
cf__label_space(const char *name, double *em)
{
    size_t i;
    for (i = 0; i < sizeof spaces / sizeof spaces[0]; i++) {
        if (strcmp(name, spaces[i].name) == 0) {
            *em = spaces[i].em;
            return true;
        }
    }
    return false;
}

bool
cf__label_accent(const char *name, unsigned *cp)
{
    size_t i;
    for (i = 0; i < sizeof accents / sizeof accents[0]; i++) {
        if (strcmp(name, accents[i].name) == 0) {
            *cp = accents[i].cp;
            return true;
        }
    }
    return false;
}

/* The alphabets of mathematics (Unicode's Mathematical Alphanumeric
** Symbols, as Latin Modern Math draws them): italic and bold italic
** Latin and Greek, and the calligraphic capitals, with the letters
** Unicode keeps in Letterlike Symbols. */
unsigned
cf__math_italic(unsigned cp, bool bold)
{
    static const struct {
        unsigned from, to;
    } greek_var[] = {
        { 0x3f5, 0x1d716 - 0x1d6fc }, { 0x3d1, 0x1d717 - 0x1d6fc },
        { 0x3d5, 0x1d719 - 0x1d6fc }, { 0x3f1, 0x1d71a - 0x1d6fc },
        { 0x3d6, 0x1d71b - 0x1d6fc }, { 0x2202, 0x1d715 - 0x1d6fc },
    };
    size_t i;
    if (cp >= 'A' && cp <= 'Z')
        return (bold ? 0x1d468 : 0x1d434) + (cp - 'A');
    if (cp >= 'a' && cp <= 'z') {
        if (cp == 'h' && !bold)
            return 0x210e;   /* Planck's constant: the math italic h */
        return (bold ? 0x1d482 : 0x1d44e) + (cp - 'a');
    }
    if (cp >= 0x3b1 && cp <= 0x3c9)
        return (bold ? 0x1d736 : 0x1d6fc) + (cp - 0x3b1);
    for (i = 0; i < sizeof greek_var / sizeof greek_var[0]; i++)
        if (cp == greek_var[i].from)
            return (bold ? 0x1d736 : 0x1d6fc) + greek_var[i].to;
    return 0;
}

/* A capital of an alphabet of mathematics: from first on, but for the
** letters Unicode had before (letters, their code points held). */
static unsigned
capital(unsigned cp, const char *letters, const unsigned *held,
        unsigned first)
{
    const char *at;
    if (cp < 'A' || cp > 'Z')
        return 0;
    at = strchr(letters, (int)cp);
    return at != NULL ? held[at - letters] : first + (cp - 'A');
}

unsigned
cf__math_cal(unsigned cp)
{
    static const unsigned held[] = { 0x212c, 0x2130, 0x2131, 0x210b,
                                     0x2110, 0x2112, 0x2133, 0x211b };
    return capital(cp, "BEFHILMR", held, 0x1d49c);
}

unsigned
cf__math_bb(unsigned cp)
{
    static const unsigned held[] = { 0x2102, 0x210d, 0x2115, 0x2119,
                                     0x211a, 0x211d, 0x2124 };
    if (cp >= '0' && cp <= '9')
        return 0x1d7d8 + (cp - '0');
    return capital(cp, "CHNPQRZ", held, 0x1d538);
}

/* Commands that take an argument (render/labels/label-parse.c and
** render/labels/label-build.c), for the list. */
static const struct {
    const char *name;
    const char *what;
} structures[] = {
    { "frac", "\\frac{num}{den}: a fraction (\\frac14: one-token "
              "arguments)" },
    { "binom", "\\binom{n}{k}: a binomial coefficient" },
    { "sqrt", "\\sqrt{x}, \\sqrt[n]{x}: a radical sized to x" },
    { "left", "\\left( ... \\right): delimiters sized to what they "
              "enclose" },
    { "mathbb", "\\mathbb{R}: double-struck capitals and digits" },
    { "mathrm", "\\mathrm{...}: upright" },
    { "text", "\\text{...}: text (upright, spaces kept)" },
    { "operatorname", "\\operatorname{...}: an operator name" },
    { "mathit", "\\mathit{...}: italic" },
    { "mathbf", "\\mathbf{...}: bold upright" },
    { "boldsymbol", "\\boldsymbol{...}: bold, letters bold italic" },
    { "mathcal", "\\mathcal{A}: calligraphic capitals" },
    { "overline", "\\overline{...}: a rule over the group" },
};

void
cf_label_each_command(void (*visit)(const char *kind, const char *name,
                                     const char *what, void *ctx),
                       void *ctx)
{
    static const char *const cls_name[] = {
        "", "ordinary", "large operator", "binary operator", "relation",
        "opening", "closing", "punctuation", "inner", "space",
    };
    char buf[64];
    size_t i;
    if (visit == NULL)
        return;
    for (i = 0; i < sizeof commands / sizeof commands[0]; i++) {
        char u[8];
        size_t n = cf__utf8_encode(commands[i].cp, u);
        u[n] = '\0';
        snprintf(buf, sizeof buf, "%s %s%s", u, cls_name[commands[i].cls],
                 commands[i].italic ? ", italic" : "");
        visit("symbol", commands[i].name, buf, ctx);
    }
    for (i = 0; i < sizeof spaces / sizeof spaces[0]; i++) {
        snprintf(buf, sizeof buf, "a space of %g mu (%.4g em)",
                 spaces[i].em * 18, spaces[i].em);
        visit("space", spaces[i].name, buf, ctx);
    }
    for (i = 0; i < sizeof accents / sizeof accents[0]; i++) {
        char u[8];
        size_t n = cf__utf8_encode(accents[i].cp, u);
        u[n] = '\0';
        snprintf(buf, sizeof buf, "an accent %s over a character or a {group}",
                 u);
        visit("accent", accents[i].name, buf, ctx);
    }
    for (i = 0; i < sizeof structures / sizeof structures[0]; i++)
        visit("structure", structures[i].name, structures[i].what, ctx);
}

bool
cf__label_structure(const char *name)
{
    size_t i;
    for (i = 0; i < sizeof structures / sizeof structures[0]; i++)
        if (strcmp(name, structures[i].name) == 0)
            return true;
    return false;
}

const char *
cf__label_nearest_command(const char *name)
{
    const char *names[sizeof commands / sizeof commands[0]
                      + sizeof spaces / sizeof spaces[0]
                      + sizeof accents / sizeof accents[0]
                      + sizeof structures / sizeof structures[0] + 1];
    size_t i, n = 0;
    for (i = 0; i < sizeof commands / sizeof commands[0]; i++)
        names[n++] = commands[i].name;
    for (i = 0; i < sizeof spaces / sizeof spaces[0]; i++)
        names[n++] = spaces[i].name;
    for (i = 0; i < sizeof accents / sizeof accents[0]; i++)
        names[n++] = accents[i].name;
    for (i = 0; i < sizeof structures / sizeof structures[0]; i++)
        names[n++] = structures[i].name;
    names[n++] = "right";
    return cf_nearest_name(name, names, n);
}
