/*
** TeX's classes of math characters and the spaces between atoms, for the
** label parser (render/label-parse.c), and what an accent takes.
*/
#include "label-impl.h"

/* The class and form of a character typed in math: letters italic, '-'
** the minus sign, operators, relations, delimiters, punctuation. */
int
cf__label_math_char(unsigned *cp, bool *italic, const font_t *f)
{
    *italic = false;
    if ((*cp >= 'a' && *cp <= 'z') || (*cp >= 'A' && *cp <= 'Z')
        || (*cp >= 0x3b1 && *cp <= 0x3c9)) {   /* lowercase Greek */
        *italic = !f->bold || f->boldsymbol;
        return CLS_ORD;
    }
    switch (*cp) {
    case '-':
        *cp = 0x2212;
        return CLS_BIN;
    case '*':
        *cp = 0x2217;
        return CLS_BIN;
    case '+':
        return CLS_BIN;
    case '=':
    case '<':
    case '>':
        return CLS_REL;
    case '(':
    case '[':
        return CLS_OPEN;
    case ')':
    case ']':
        return CLS_CLOSE;
    case ':':
        return CLS_REL;
    case '!':
    case '?':
        return CLS_CLOSE;
    case ',':
    case ';':
        return CLS_PUNCT;
    case '\'':
        *cp = 0x2032;
        return CLS_ORD;
    default:
        return CLS_ORD;
    }
}

/* TeX's spaces between atoms (The TeXbook, chapter 18, the table of
** rule 20): 1 thin (3 mu), 2 medium (4 mu), 3 thick (5 mu); negative:
** only in text style, not in scripts.  Rows: the left atom's class;
** columns: the right one's, in the order ORD OP BIN REL OPEN CLOSE PUNCT
** INNER. */
static const signed char space_table[8][8] = {
    /* ORD   */ { 0, 1, -2, -3, 0, 0, 0, -1 },
    /* OP    */ { 1, 1, 0, -3, 0, 0, 0, -1 },
    /* BIN   */ { -2, -2, 0, 0, -2, 0, 0, -2 },
    /* REL   */ { -3, -3, 0, 0, -3, 0, 0, -3 },
    /* OPEN  */ { 0, 0, 0, 0, 0, 0, 0, 0 },
    /* CLOSE */ { 0, 1, -2, -3, 0, 0, 0, -1 },
    /* PUNCT */ { -1, -1, 0, -1, -1, -1, -1, -1 },
    /* INNER */ { -1, 1, -2, -3, -1, 0, -1, -1 },
};

/* Space in em (18 mu) between atoms of classes a and b at script level
** level (0 text style). */
double
cf__label_atom_space(int a, int b, int level)
{
    static const double mu[4] = { 0, 3, 4, 5 };
    int v;
    if (a < CLS_ORD || a > CLS_INNER || b < CLS_ORD || b > CLS_INNER)
        return 0;
    v = space_table[a - CLS_ORD][b - CLS_ORD];
    if (v < 0 && level > 0)
        return 0;
    return mu[v < 0 ? -v : v] / 18;
}

bool
cf__label_single_char_group(const char *s, size_t len, size_t pos)
{
    unsigned cp;
    size_t m;
    if (pos >= len || s[pos] != '{')
        return false;
    for (pos++; pos < len && s[pos] == ' '; pos++)
        ;
    if (pos >= len || (m = cf__utf8_decode(s, len, pos, &cp)) == 0
        || cp == '{' || cp == '}' || cp == '\\')
        return false;
    for (pos += m; pos < len && s[pos] == ' '; pos++)
        ;
    return pos < len && s[pos] == '}';
}
