/*
** Counting the steps of a Lua pattern search (see lpattern.h): the
** backtracking search of the Lua 5.4 manual's pattern rules, written for
** this purpose; it records only what later items need (capture positions
** for back-references) and stops as soon as the budget is spent.
*/
#include <ctype.h>
#include <string.h>

#include "lpattern.h"

#define MAX_CAPTURES 32
#define MAX_DEPTH 200      /* Lua's own limit (MAXCCALLS in lstrlib.c) */
#define CAP_OPEN (-1)
#define CAP_POSITION (-2)

typedef struct counter {
    const char *s0, *se;   /* the subject */
    const char *pe;        /* the pattern's end */
    long long steps, max;
    int state;             /* CF__PATTERN_* once the count must stop */
    int depth;
    int level;             /* captures started */
    struct {
        const char *init;
        ptrdiff_t len;
    } cap[MAX_CAPTURES];
} counter;

static int
stop(counter *c, int state)
{
    if (c->state == CF__PATTERN_FITS)
        c->state = state;
    return 0;
}

static int
step(counter *c)
{
    if (++c->steps > c->max)
        return stop(c, CF__PATTERN_OVER);
    return c->state == CF__PATTERN_FITS;
}

/* The end of the single-character class at p, or NULL if malformed. */
static const char *
class_end(counter *c, const char *p)
{
    if (*p == '%')
        return p + 1 < c->pe ? p + 2 : NULL;
    if (*p != '[')
        return p + 1;
    p++;
    if (p < c->pe && *p == '^')
        p++;
    /* the first character of a set is never its closing bracket */
    do {
        if (p >= c->pe)
            return NULL;
        if (*p++ == '%') {
            if (p >= c->pe)
                return NULL;
            p++;
        }
    } while (p >= c->pe || *p != ']');
    return p + 1;
}

static int
in_class(int ch, int cl)
{
    int r;
    switch (tolower(cl)) {
    case 'a': r = isalpha(ch); break;
    case 'c': r = iscntrl(ch); break;
    case 'd': r = isdigit(ch); break;
    case 'g': r = isgraph(ch); break;
    case 'l': r = islower(ch); break;
    case 'p': r = ispunct(ch); break;
    case 's': r = isspace(ch); break;
    case 'u': r = isupper(ch); break;
    case 'w': r = isalnum(ch); break;
    case 'x': r = isxdigit(ch); break;
    default: return cl == ch;
    }
    r = r != 0;
    return isupper(cl) ? !r : r;
}

/* ch in the set [ ... ] from p (at '[') to close (at ']'). */
static int
in_set(int ch, const char *p, const char *close)
{
    int yes = 1;
    p++;
    if (*p == '^') {
        yes = 0;
        p++;
    }
    while (p < close) {
        if (*p == '%' && p + 1 < close) {
            if (in_class(ch, (unsigned char)p[1]))
                return yes;
            p += 2;
        } else if (p + 2 < close && p[1] == '-') {
            if ((unsigned char)p[0] <= ch && ch <= (unsigned char)p[2])
                return yes;
            p += 3;
        } else {
            if ((unsigned char)*p == ch)
                return yes;
            p++;
        }
    }
    return !yes;
}

static int
single(const counter *c, const char *s, const char *p, const char *ep)
{
    int ch;
    if (s >= c->se)
        return 0;
    ch = (unsigned char)*s;
    switch (*p) {
    case '.':
        return 1;
    case '%':
        return in_class(ch, (unsigned char)p[1]);
    case '[':
        return in_set(ch, p, ep - 1);
    default:
        return (unsigned char)*p == ch;
    }
}

static const char *match(counter *c, const char *s, const char *p);

static const char *
greedy(counter *c, const char *s, const char *p, const char *ep)
{
    ptrdiff_t i = 0;
    while (single(c, s + i, p, ep)) {
        if (!step(c))
            return NULL;
        i++;
    }
    for (; i >= 0; i--) {
        const char *r = match(c, s + i, ep + 1);
        if (r != NULL || c->state != CF__PATTERN_FITS)
            return r;
    }
    return NULL;
}

static const char *
lazy(counter *c, const char *s, const char *p, const char *ep)
{
    for (;;) {
        const char *r = match(c, s, ep + 1);
        if (r != NULL || c->state != CF__PATTERN_FITS)
            return r;
        if (!single(c, s, p, ep) || !step(c))
            return NULL;
        s++;
    }
}

static const char *
open_capture(counter *c, const char *s, const char *p, ptrdiff_t what)
{
    const char *r;
    if (c->level >= MAX_CAPTURES) {
        stop(c, CF__PATTERN_UNCOUNTED);
        return NULL;
    }
    c->cap[c->level].init = s;
    c->cap[c->level].len = what;
    c->level++;
    r = match(c, s, p);
    if (r == NULL)
        c->level--;
    return r;
}

static const char *
close_capture(counter *c, const char *s, const char *p)
{
    int l = c->level - 1;
    const char *r;
    while (l >= 0 && c->cap[l].len != CAP_OPEN)
        l--;
    if (l < 0) {
        stop(c, CF__PATTERN_UNCOUNTED);
        return NULL;
    }
    c->cap[l].len = s - c->cap[l].init;
    r = match(c, s, p);
    if (r == NULL)
        c->cap[l].len = CAP_OPEN;
    return r;
}

static const char *
balance(counter *c, const char *s, const char *p)
{
    int depth = 1;
    if (p + 1 >= c->pe) {
        stop(c, CF__PATTERN_UNCOUNTED);
        return NULL;
    }
    if (s >= c->se || *s != *p)
        return NULL;
    while (++s < c->se) {
        if (!step(c))
            return NULL;
        if (*s == p[1]) {
            if (--depth == 0)
                return s + 1;
        } else if (*s == *p) {
            depth++;
        }
    }
    return NULL;
}

static const char *
backref(counter *c, const char *s, int digit)
{
    int l = digit - '1';
    size_t len;
    if (l < 0 || l >= c->level || c->cap[l].len == CAP_OPEN) {
        stop(c, CF__PATTERN_UNCOUNTED);
        return NULL;
    }
    len = c->cap[l].len == CAP_POSITION ? 0 : (size_t)c->cap[l].len;
    if ((size_t)(c->se - s) >= len && memcmp(c->cap[l].init, s, len) == 0)
        return s + len;
    return NULL;
}

/* The end of a match of p at s, or NULL (no match, or the count stopped). */
static const char *
match_(counter *c, const char *s, const char *p)
{
    while (p < c->pe) {
        const char *ep;
        int m;
        if (!step(c))
            return NULL;
        switch (*p) {
        case '(':
            if (p + 1 < c->pe && p[1] == ')')
                return open_capture(c, s, p + 2, CAP_POSITION);
            return open_capture(c, s, p + 1, CAP_OPEN);
        case ')':
            return close_capture(c, s, p + 1);
        case '$':
            if (p + 1 == c->pe)
                return s == c->se ? s : NULL;
            break;
        case '%':
            if (p + 1 >= c->pe) {
                stop(c, CF__PATTERN_UNCOUNTED);
                return NULL;
            }
            if (p[1] == 'b') {
                s = balance(c, s, p + 2);
                if (s == NULL)
                    return NULL;
                p += 4;
                continue;
            }
            if (p[1] == 'f') {
                int prev, cur;
                p += 2;
                if (p >= c->pe || *p != '[' ||
                    (ep = class_end(c, p)) == NULL) {
                    stop(c, CF__PATTERN_UNCOUNTED);
                    return NULL;
                }
                prev = s == c->s0 ? 0 : (unsigned char)s[-1];
                cur = s < c->se ? (unsigned char)*s : 0;
                if (in_set(prev, p, ep - 1) || !in_set(cur, p, ep - 1))
                    return NULL;
                p = ep;
                continue;
            }
            if (isdigit((unsigned char)p[1])) {
                s = backref(c, s, p[1]);
                if (s == NULL)
                    return NULL;
                p += 2;
                continue;
            }
            break;
        default:
            break;
        }
        ep = class_end(c, p);
        if (ep == NULL) {
            stop(c, CF__PATTERN_UNCOUNTED);
            return NULL;
        }
        m = single(c, s, p, ep);
        if (ep < c->pe) {
            switch (*ep) {
            case '?':
                if (m) {
                    const char *r = match(c, s + 1, ep + 1);
                    if (r != NULL || c->state != CF__PATTERN_FITS)
                        return r;
                }
                p = ep + 1;
                continue;
            case '+':
                return m ? greedy(c, s + 1, p, ep) : NULL;
            case '*':
                return greedy(c, s, p, ep);
            case '-':
                return lazy(c, s, p, ep);
            default:
                break;
            }
        }
        if (!m)
            return NULL;
        s++;
        p = ep;
    }
    return s;
}

static const char *
match(counter *c, const char *s, const char *p)
{
    const char *r;
    if (c->state != CF__PATTERN_FITS)
        return NULL;
    if (++c->depth > MAX_DEPTH) {
        c->depth--;
        stop(c, CF__PATTERN_UNCOUNTED);
        return NULL;
    }
    r = match_(c, s, p);
    c->depth--;
    return r;
}

int
cf__pattern_cost(const char *s, size_t ls, const char *p, size_t lp,
                 size_t init, int all, long long max, long long *steps)
{
    counter c;
    int anchor = lp > 0 && *p == '^';
    size_t pos = init;
    memset(&c, 0, sizeof c);
    c.s0 = s;
    c.se = s + ls;
    c.pe = p + lp;
    c.max = max;
    if (anchor)
        p++;
    while (pos <= ls) {
        const char *e;
        c.level = 0;
        c.depth = 0;
        e = match(&c, s + pos, p);
        if (c.state != CF__PATTERN_FITS)
            break;
        if (e != NULL && !all)
            break;
        if (anchor)
            break;
        /* the next search starts after a match, or one byte further */
        pos = e != NULL && e > s + pos ? (size_t)(e - s) : pos + 1;
        if (!step(&c))
            break;
    }
    *steps = c.steps;
    return c.state;
}
