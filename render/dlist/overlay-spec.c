/*
** Overlay specifications (render/overlay-spec.h): parsing, checking and
** asking whether a step is shown.
*/
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "overlay-spec.h"

/* One range of a spec at *p: lo..hi (hi 0: open); the end in *p. */
typedef struct range {
    unsigned lo, hi;
} range_t;

static int
number(const char **p, unsigned *out)
{
    unsigned v = 0;
    if (**p < '0' || **p > '9')
        return -1;
    while (**p >= '0' && **p <= '9') {
        v = v * 10 + (unsigned)(**p - '0');
        if (v > CF__OVERLAY_MAX_STEP)
            v = CF__OVERLAY_MAX_STEP + 1;
        (*p)++;
    }
    *out = v;
    return 0;
}

static int
fail(char *why, size_t cap, const char *fmt, ...)
{
    va_list ap;
    if (why != NULL && cap > 0) {
        va_start(ap, fmt);
        vsnprintf(why, cap, fmt, ap);
        va_end(ap);
    }
    return -1;
}

/* The range at *p (up to ',' or the end). */
static int
one_range(const char **p, range_t *r, char *why, size_t cap)
{
    const char *s = *p;
    bool open_lo = false;
    r->lo = 1;
    r->hi = 0;
    if (*s == '+' || *s == '.')
        return fail(why, cap, "\"%.12s\": incremental specifications "
                    "(\"+-\", \".-\") are not supported; give the step "
                    "numbers", s);
    if (*s == '-') {
        open_lo = true;
        s++;
    } else if (number(&s, &r->lo) != 0) {
        return *s == '\0' || *s == ','
            ? fail(why, cap, "an empty range")
            : fail(why, cap, "\"%.12s\" is not a step number", s);
    }
    if (open_lo) {
        if (number(&s, &r->hi) != 0)
            return fail(why, cap, "\"-\" needs a step after it (\"-3\": "
                        "steps 1 to 3)");
    } else if (*s == '-') {
        s++;
        if (*s >= '0' && *s <= '9')
            number(&s, &r->hi);
        else
            r->hi = 0;
    } else {
        r->hi = r->lo;
    }
    if (*s != '\0' && *s != ',')
        return fail(why, cap, "unexpected \"%.12s\"", s);
    if (r->lo == 0 || (open_lo && r->hi == 0))
        return fail(why, cap, "step 0: steps count from 1");
    if (r->lo > CF__OVERLAY_MAX_STEP || r->hi > CF__OVERLAY_MAX_STEP)
        return fail(why, cap, "steps go up to %u", CF__OVERLAY_MAX_STEP);
    if (r->hi != 0 && r->hi < r->lo)
        return fail(why, cap, "the range %u-%u runs backwards", r->lo,
                    r->hi);
    *p = s;
    return 0;
}

int
cf__overlay_parse(const char *spec, unsigned *last, char *why, size_t cap)
{
    const char *p = spec;
    unsigned top = 0;
    if (spec == NULL || *spec == '\0')
        return fail(why, cap, "the specification is empty; give steps, "
                    "e.g. \"2-\"");
    for (;;) {
        range_t r;
        if (one_range(&p, &r, why, cap) != 0)
            return -1;
        top = r.lo > top ? r.lo : top;
        top = r.hi > top ? r.hi : top;
        if (*p == '\0')
            break;
        p++;   /* ',' */
    }
    if (last != NULL)
        *last = top;
    return 0;
}

bool
cf__overlay_visible(const char *spec, unsigned k)
{
    const char *p = spec;
    if (spec == NULL)
        return true;
    for (;;) {
        range_t r;
        if (one_range(&p, &r, NULL, 0) != 0)
            return false;
        if (k >= r.lo && (r.hi == 0 || k <= r.hi))
            return true;
        if (*p == '\0')
            return false;
        p++;
    }
}
