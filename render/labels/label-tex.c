/*
** Labels as TeX source (for the PGF backend): curvefig's label syntax
** (include/curvefig/label.h) rewritten so that TeX sets the same thing in
** the document's fonts.  A label without `$` is all mathematics and
** becomes $...$; with `$`, the text outside is text.  In mathematics,
** Greek and symbols typed as Unicode become their commands (α -> \alpha,
** ≤ -> \le), Latin letters with accents go into \text; in text, symbols
** go into \ensuremath and TeX's special characters are escaped.  What
** pdflatex cannot set without extra packages (Cyrillic, CJK, any other
** script) makes the label "not settable": the caller draws its glyphs.
*/
#include <string.h>

#include "label-impl.h"
#include "render-private.h"

typedef struct tex {
    const char *s;
    size_t pos, len;
    bool has_dollar;
    bool unsettable;
    bool after_sup;       /* the last atom was a superscript */
    cf__buf_t *out;
} tex_t;

static void
put(tex_t *t, const char *s)
{
    cf__buf_append(t->out, s, strlen(s));
}

/* A control word and the space that ends it. */
static void
put_word(tex_t *t, const char *name)
{
    put(t, "\\");
    put(t, name);
    put(t, " ");
}

/* The TeX form, in mathematics, of curvefig's symbol command name (NULL:
** the same name). */
static const char *
math_symbol(const char *name)
{
    static const char *const map[][2] = {
        { "omicron", "o" },        { "deg", "{}^{\\circ}" },
        { "\\", "\\backslash " },  { "^", "\\mbox{\\textasciicircum}" },
        { "prime", "\\prime " },
    };
    size_t i;
    for (i = 0; i < sizeof map / sizeof map[0]; i++)
        if (strcmp(name, map[i][0]) == 0)
            return map[i][1];
    return NULL;
}

/* The same in text. */
static const char *
text_symbol(const char *name)
{
    static const char *const map[][2] = {
        { "omicron", "o" },
        { "\\", "\\textbackslash{}" },
        { "^", "\\textasciicircum{}" },
        { "deg", "\\ensuremath{{}^{\\circ}}" },
        { "{", "\\{" }, { "}", "\\}" }, { "_", "\\_" }, { "$", "\\$" },
        { "%", "\\%" }, { "#", "\\#" }, { "&", "\\&" },
    };
    size_t i;
    for (i = 0; i < sizeof map / sizeof map[0]; i++)
        if (strcmp(name, map[i][0]) == 0)
            return map[i][1];
    return NULL;
}

static void
put_symbol(tex_t *t, const char *name, bool math)
{
    const char *m = math ? math_symbol(name) : text_symbol(name);
    if (m != NULL) {
        put(t, m);
    } else if (math) {
        put_word(t, name);
    } else {
        put(t, "\\ensuremath{\\");
        put(t, name);
        put(t, "}");
    }
}

/* Symbols of mathematics typed as Unicode that the label syntax has no
** command for but TeX has. */
static const char *
unicode_math(unsigned cp)
{
    static const struct {
        unsigned cp;
        const char *tex;
    } map[] = {
        { 0xb7, "\\cdot " },           { 0x2033, "''" },
        { 0x2190, "\\leftarrow " },    { 0x2194, "\\leftrightarrow " },
        { 0x21d2, "\\Rightarrow " },   { 0x21d4, "\\Leftrightarrow " },
        { 0x2200, "\\forall " },       { 0x2203, "\\exists " },
        { 0x2205, "\\emptyset " },     { 0x2206, "\\Delta " },
        { 0x220a, "\\in " },           { 0x221a, "\\surd " },
        { 0x221d, "\\propto " },       { 0x2227, "\\wedge " },
        { 0x2228, "\\vee " },          { 0x2229, "\\cap " },
        { 0x222a, "\\cup " },          { 0x223c, "\\sim " },
        { 0x2286, "\\subseteq " },     { 0x2287, "\\supseteq " },
        { 0x2283, "\\supset " },       { 0x2295, "\\oplus " },
        { 0x2297, "\\otimes " },       { 0x22a5, "\\perp " },
        { 0x2225, "\\parallel " },     { 0x2220, "\\angle " },
    };
    size_t i;
    for (i = 0; i < sizeof map / sizeof map[0]; i++)
        if (map[i].cp == cp)
            return map[i].tex;
    return NULL;
}

/* Uppercase Greek letters that TeX has no command for: their Latin
** twins. */
static char
greek_latin(unsigned cp)
{
    static const char latin[] = "ABGDEZHQIKLMNXOPR STYFXYW";
    if (cp >= 0x391 && cp <= 0x3a9 && latin[cp - 0x391] != ' ')
        return latin[cp - 0x391];
    return 0;
}

/* One code point beyond ASCII. */
static void
put_unicode(tex_t *t, unsigned cp, const char *utf8, size_t n, bool math)
{
    const char *name = cf__label_symbol_name(cp);
    char one[2] = { 0, 0 };
    if (cp == 0x2212 || cp == 0x2217 || cp == 0x2032) {
        /* the forms math gives -, * and ' */
        put(t, math ? "" : "\\ensuremath{");
        put(t, cp == 0x2212 ? "-" : cp == 0x2217 ? "*" : "'");
        put(t, math ? "" : "}");
        return;
    }
    if (name != NULL) {
        put_symbol(t, name, math);
        return;
    }
    if ((name = unicode_math(cp)) != NULL) {
        put(t, math ? "" : "\\ensuremath{");
        put(t, name);
        put(t, math ? "" : "}");
        return;
    }
    if ((one[0] = greek_latin(cp)) != 0) {
        put(t, math ? "\\mathrm{" : "");
        put(t, one);
        put(t, math ? "}" : "");
        return;
    }
    if (cp == 0xa0) {
        put(t, "~");
        return;
    }
    if (cp > 0xa0 && cp <= 0x17f && cp != 0xad) {
        /* Latin-1 and Latin Extended-A: LaTeX's UTF-8 input sets them */
        put(t, math ? "\\text{" : "");
        cf__buf_append(t->out, utf8, n);
        put(t, math ? "}" : "");
        return;
    }
    t->unsettable = true;
}

/* One ASCII character. */
static void
put_ascii(tex_t *t, char c, bool math)
{
    static const char *const in_math[][2] = {
        { "#", "\\#" }, { "%", "\\%" }, { "&", "\\&" }, { "~", "\\sim " },
        { "\"", "''" },
    };
    static const char *const in_text[][2] = {
        { "#", "\\#" }, { "%", "\\%" }, { "&", "\\&" },
        { "~", "\\textasciitilde{}" }, { "_", "\\_" },
        { "^", "\\textasciicircum{}" }, { "<", "\\textless{}" },
        { ">", "\\textgreater{}" }, { "|", "\\textbar{}" }, { "\"", "''" },
    };
    char one[2] = { c, 0 };
    size_t i;
    if ((unsigned char)c < 0x20 || c == 0x7f)
        one[0] = ' ';   /* a line break or tab: a space, never a \\par */
    if (math) {
        for (i = 0; i < sizeof in_math / sizeof in_math[0]; i++)
            if (c == in_math[i][0][0]) {
                put(t, in_math[i][1]);
                return;
            }
    } else {
        for (i = 0; i < sizeof in_text / sizeof in_text[0]; i++)
            if (c == in_text[i][0][0]) {
                put(t, in_text[i][1]);
                return;
            }
    }
    put(t, one);
}

static void list(tex_t *t, bool math, int stop);

static void
skip_spaces(tex_t *t)
{
    while (t->pos < t->len && t->s[t->pos] == ' ')
        t->pos++;
}

/* A character (no command, no group) at pos. */
static void
character(tex_t *t, bool math)
{
    unsigned cp;
    size_t n = cf__utf8_decode(t->s, t->len, t->pos, &cp);
    if (n == 0) {
        t->unsettable = true;
        t->pos = t->len;
        return;
    }
    if (cp < 0x80)
        put_ascii(t, (char)cp, math);
    else
        put_unicode(t, cp, t->s + t->pos, n, math);
    t->pos += n;
}

static void command(tex_t *t, bool math);

/* What lies between the delimiter at pos and the one that closes it
** (stop), in mode math, between open and close. */
static void
enclosed(tex_t *t, bool math, const char *open, const char *close, int stop)
{
    t->pos++;
    put(t, open);
    list(t, math, stop);
    put(t, close);
    if (t->pos < t->len)
        t->pos++;
}

/* One atom: a {group}, a command or a character. */
static void
atom(tex_t *t, bool math)
{
    if (t->pos >= t->len)
        return;
    if (t->s[t->pos] == '{') {
        enclosed(t, math, "{", "}", '}');
    } else if (t->s[t->pos] == '\\') {
        command(t, math);
    } else {
        character(t, math);
    }
}

/* The argument of an accent: one character, maybe braced, or a {group}. */
static void
accent_arg(tex_t *t)
{
    bool braced;
    skip_spaces(t);
    braced = t->pos < t->len && t->s[t->pos] == '{';
    if (braced && !cf__label_single_char_group(t->s, t->len, t->pos)) {
        enclosed(t, true, "{", "}", '}');
        return;
    }
    put(t, "{");
    if (braced) {
        t->pos++;
        skip_spaces(t);
    }
    character(t, true);
    if (braced) {
        skip_spaces(t);
        if (t->pos < t->len)
            t->pos++;
    }
    put(t, "}");
}

static void
command(tex_t *t, bool math)
{
    char name[24];
    size_t n = 0;
    unsigned cp;
    int cls;
    bool italic;
    double em;
    t->pos++;   /* the backslash */
    while (t->pos < t->len && n + 1 < sizeof name
           && ((t->s[t->pos] >= 'a' && t->s[t->pos] <= 'z')
               || (t->s[t->pos] >= 'A' && t->s[t->pos] <= 'Z')))
        name[n++] = t->s[t->pos++];
    if (n == 0 && t->pos < t->len)
        name[n++] = t->s[t->pos++];
    name[n] = '\0';
    if (cf__label_space(name, &em)) {
        put(t, "\\");
        put(t, name);
        put(t, name[0] >= 'a' && name[0] <= 'z' ? " " : "");
    } else if (cf__label_symbol(name, &cp, &cls, &italic)) {
        put_symbol(t, name, math);
    } else if (cf__label_accent(name, &cp)) {
        put(t, math ? "\\" : "\\ensuremath{\\");
        put(t, name);
        accent_arg(t);
        put(t, math ? "" : "}");
    } else if (strcmp(name, "frac") == 0) {
        put(t, math ? "\\frac" : "\\ensuremath{\\frac");
        skip_spaces(t);
        atom(t, true);
        skip_spaces(t);
        atom(t, true);
        put(t, math ? "" : "}");
    } else if (strcmp(name, "boldsymbol") == 0 || strcmp(name, "mathcal") == 0
               || strcmp(name, "overline") == 0) {
        /* \boldsymbol: amsmath's, or the picture's \boldmath fallback */
        put(t, math ? "\\" : "\\ensuremath{\\");
        put(t, name);
        skip_spaces(t);
        atom(t, true);
        put(t, math ? "" : "}");
    } else if (strcmp(name, "text") == 0) {
        put(t, math ? "\\text" : "\\mbox");
        skip_spaces(t);
        atom(t, false);
    } else if (strcmp(name, "mathrm") == 0 || strcmp(name, "mathbf") == 0
               || strcmp(name, "mathit") == 0
               || strcmp(name, "operatorname") == 0) {
        static const char *const text_form[][2] = {
            { "mathrm", "\\textrm" }, { "mathbf", "\\textbf" },
            { "mathit", "\\textit" }, { "operatorname", "\\textrm" },
        };
        size_t i;
        for (i = 0; !math && i < 4; i++)
            if (strcmp(name, text_form[i][0]) == 0)
                put(t, text_form[i][1]);
        if (math)
            put(t, strcmp(name, "operatorname") == 0 ? "\\mathrm"
                                                     : "\\");
        if (math && strcmp(name, "operatorname") != 0)
            put(t, name);
        skip_spaces(t);
        atom(t, math);
    } else {
        t->unsettable = true;   /* not curvefig syntax: the parser failed */
    }
}

/* A list of atoms up to stop ('}', '$' or 0). */
static void
list(tex_t *t, bool math, int stop)
{
    while (t->pos < t->len && !t->unsettable && !t->out->failed) {
        char c = t->s[t->pos];
        if (c == '}' && stop == '}')
            return;
        if (c == '$' && t->has_dollar) {
            if (math)
                return;
            enclosed(t, true, "$", "$", '$');
            continue;
        }
        if (math && (c == '_' || c == '^')) {
            char op[3] = { c, '{', 0 };
            t->pos++;
            put(t, op);
            skip_spaces(t);
            atom(t, true);
            put(t, "}");
            t->after_sup = c == '^';
            continue;
        }
        /* a prime after a superscript: TeX would see a double
        ** superscript, so it goes on an empty atom */
        if (math && t->after_sup
            && (c == '\''
                || (t->pos + 2 < t->len
                    && memcmp(t->s + t->pos, "\xe2\x80\xb2", 3) == 0)))
            put(t, "{}");
        t->after_sup = false;
        atom(t, math);
    }
}

int
cf__label_tex(const char *src, cf__buf_t *out)
{
    tex_t t;
    memset(&t, 0, sizeof t);
    t.s = src;
    t.len = strlen(src);
    t.out = out;
    t.has_dollar = cf__label_has_dollar(src);
    if (!t.has_dollar && t.len > 0)
        put(&t, "$");
    list(&t, !t.has_dollar, 0);
    if (!t.has_dollar && t.len > 0)
        put(&t, "$");
    if (out->failed)
        return -1;
    return t.unsettable ? 1 : 0;
}
