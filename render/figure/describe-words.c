/*
** The words of descriptions (describe-private.h): numbers written short,
** points, lists, labels as read, and a sentence's capital letter.
*/
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "describe-private.h"

void
cf__dw_put(cf__buf_t *b, const char *s)
{
    cf__buf_append(b, s, strlen(s));
}

void
cf__dw_putf(cf__buf_t *b, const char *fmt, ...)
{
    char tmp[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(tmp, sizeof tmp, fmt, ap);
    va_end(ap);
    cf__dw_put(b, tmp);
}

/* ---- numbers ------------------------------------------------------------ */

static bool
near(double a, double b)
{
    return fabs(a - b) <= 1e-12 * fmax(1.0, fabs(b));
}

/* p/q for x with q among qs (the first that fits: lowest terms). */
static bool
fraction(double x, const int *qs, size_t nq, char *out, size_t cap)
{
    for (size_t i = 0; i < nq; i++) {
        double p = round(x * qs[i]);
        if (near(p / qs[i], x)) {
            snprintf(out, cap, "%.0f/%d", p, qs[i]);
            return true;
        }
    }
    return false;
}

/* x written short: an integer; a parameter (t, u, knots, weights) as a
** fraction of halves, thirds, quarters, sixths, eighths, twelfths or
** sixteenths; else the shortest of 4 or 6 significant digits that reads
** back as x, a fraction of small denominator, or 4 digits. */
void
cf__dw_fmt_num(const cf__desc_lang_t *L, double x, bool param, char *out,
               size_t cap)
{
    static const int pq[] = { 2, 3, 4, 6, 8, 12, 16 };
    static const int cq[] = { 3, 6, 9, 12 };
    char t[64];
    bool done = false;
    if (x == 0 || near(round(x), x)) {
        snprintf(t, sizeof t, "%.0f", x == 0 ? 0.0 : round(x));
        done = true;
    }
    if (!done && param)
        done = fraction(x, pq, sizeof pq / sizeof pq[0], t, sizeof t);
    if (!done) {
        snprintf(t, sizeof t, "%.4g", x);
        done = near(strtod(t, NULL), x);
    }
    if (!done) {
        snprintf(t, sizeof t, "%.6g", x);
        done = near(strtod(t, NULL), x);
    }
    if (!done && !fraction(x, cq, sizeof cq / sizeof cq[0], t, sizeof t))
        snprintf(t, sizeof t, "%.4g", x);
    for (char *c = t; *c != '\0'; c++)
        if (*c == '.')
            *c = L->decimal;
    snprintf(out, cap, "%s", t);
}

void
cf__dw_put_num(cf__dwriter_t *w, double x, bool param)
{
    char tmp[64];
    cf__dw_fmt_num(w->L, x, param, tmp, sizeof tmp);
    cf__dw_put(w->out, tmp);
}

void
cf__dw_put_point(cf__dwriter_t *w, const double *p, size_t dim)
{
    cf__dw_put(w->out, "(");
    for (size_t j = 0; j < dim; j++) {
        if (j > 0)
            cf__dw_put(w->out, w->L->coord_sep);
        cf__dw_put_num(w, p[j], false);
    }
    cf__dw_put(w->out, ")");
}

/* The separator before item i of n: ", " or " and ". */
void
cf__dw_put_sep(cf__dwriter_t *w, size_t i, size_t n)
{
    if (i > 0)
        cf__dw_put(w->out, i + 1 == n ? w->L->list_and : ", ");
}

void
cf__dw_put_params(cf__dwriter_t *w, const double *v, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        cf__dw_put_sep(w, i, n);
        cf__dw_put_num(w, v[i], true);
    }
}

/* Commands of labels that only style their argument: read as it. */
static const char *const styling[] = {
    "text", "mathrm", "mathbf", "mathit", "mathsf", "mathtt", "boldsymbol",
    "operatorname", "textbf", "textit", "hat", "bar", "tilde", "vec",
    "overline", "dot", "ddot", "left", "right", "displaystyle"
};

/* The group {...} at s (or the one character there) into b; s past it. */
static const char *
put_group(cf__buf_t *b, const char *s)
{
    const char *e;
    if (*s != '{') {
        if (*s != '\0')
            cf__buf_append(b, s++, 1);
        return s;
    }
    for (e = s + 1; *e != '\0' && *e != '}'; e++)
        ;
    cf__buf_append(b, s + 1, (size_t)(e - s - 1));
    return *e == '}' ? e + 1 : e;
}

/* A label's text as read: TeX braces and dollars dropped, styling
** commands (\text, \mathbf) dropped for their argument, \frac{a}{b} as
** a/b, other commands by their names (\omega -> omega). */
void
cf__dw_put_plain(cf__buf_t *b, const char *s)
{
    while (*s != '\0') {
        const char *name;
        size_t n, i;
        if (*s == '{' || *s == '}' || *s == '$') {
            s++;
            continue;
        }
        if (*s != '\\') {
            cf__buf_append(b, s++, 1);
            continue;
        }
        name = ++s;
        for (n = 0; (name[n] >= 'a' && name[n] <= 'z')
                    || (name[n] >= 'A' && name[n] <= 'Z'); n++)
            ;
        if (n == 0) {
            /* \, \; \  and \\: a space */
            cf__dw_put(b, " ");
            if (*s != '\0')
                s++;
            continue;
        }
        s = name + n;
        if (n == 4 && strncmp(name, "frac", 4) == 0) {
            s = put_group(b, s);
            cf__dw_put(b, "/");
            s = put_group(b, s);
            continue;
        }
        for (i = 0; i < sizeof styling / sizeof styling[0]; i++)
            if (strlen(styling[i]) == n && strncmp(name, styling[i], n) == 0)
                break;
        if (i == sizeof styling / sizeof styling[0])
            cf__buf_append(b, name, n);
    }
}

/* A named point: "P_0 (0, 5)", or "(0, 5)" when no label sits on it. */
void
cf__dw_put_named(cf__dwriter_t *w, const double *plane, const double *p,
                 size_t dim)
{
    const char *name = cf__describe_name_at(&w->d, plane);
    if (name != NULL) {
        cf__dw_put_plain(w->out, name);
        cf__dw_put(w->out, " ");
    }
    cf__dw_put_point(w, p, dim);
}

/* Capitalise the first letter of the text from byte at on: ASCII, the
** Latin-1 letters and the Czech ones of Latin Extended-A (č ď ě ň ř š ť
** ž, whose capitals are the code point before). */
void
cf__dw_capitalise(cf__buf_t *b, size_t at)
{
    static const unsigned short czech[] = { 0x10d, 0x10f, 0x11b, 0x148,
                                            0x159, 0x161, 0x165, 0x17e };
    unsigned char *p;
    if (b->data == NULL || at >= b->size)
        return;
    p = b->data + at;
    if (p[0] >= 'a' && p[0] <= 'z') {
        p[0] = (unsigned char)(p[0] - 'a' + 'A');
    } else if (at + 1 < b->size && p[0] == 0xc3 && p[1] >= 0xa0
               && p[1] <= 0xbe && p[1] != 0xb7) {
        p[1] = (unsigned char)(p[1] - 0x20);
    } else if (at + 1 < b->size && (p[0] == 0xc4 || p[0] == 0xc5)) {
        unsigned cp = ((p[0] & 0x1fu) << 6) | (p[1] & 0x3fu);
        for (size_t i = 0; i < sizeof czech / sizeof czech[0]; i++)
            if (cp == czech[i])
                p[1] = (unsigned char)(p[1] - 1);
    }
}


void
cf__dw_begin(cf__dwriter_t *w, cf__buf_t *sub)
{
    memset(sub, 0, sizeof *sub);
    w->out = sub;
}

void
cf__dw_end(cf__dwriter_t *w, cf__buf_t *sub, cf__buf_t *outer)
{
    cf__buf_append(sub, "", 1);
    w->out = outer;
    if (sub->failed)
        outer->failed = 1;
}
