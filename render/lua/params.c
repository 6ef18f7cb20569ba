/*
** The parameter store of an interactive figure (params.h): declarations,
** their checks, the values a host gives, and the JSON those values come in.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "params.h"

typedef struct given {
    char name[CF__PARAMS_NAME];
    double *v;
    size_t n;
} given_t;

struct cf__params {
    cf__param_t items[CF__PARAMS_MAX];
    size_t count;
    given_t given[CF__PARAMS_MAX];
    size_t ngiven;
    bool exact;             /* sliders not snapped (cf__params_set_exact) */
};

cf__params_t *
cf__params_create(void)
{
    return calloc(1, sizeof(cf__params_t));
}

static void
clear_given(cf__params_t *p)
{
    for (size_t i = 0; i < p->ngiven; i++)
        free(p->given[i].v);
    p->ngiven = 0;
}

void
cf__params_destroy(cf__params_t *p)
{
    if (p == NULL)
        return;
    clear_given(p);
    for (size_t i = 0; i < p->count; i++) {
        free(p->items[i].def_xy);
        free(p->items[i].xy);
    }
    free(p);
}

/* ---- the host ----------------------------------------------------------- */

void
cf__params_set_exact(cf__params_t *p, bool exact)
{
    p->exact = exact;
}

static const given_t *
find_given(const cf__params_t *p, const char *name)
{
    for (size_t i = 0; i < p->ngiven; i++)
        if (strcmp(p->given[i].name, name) == 0)
            return &p->given[i];
    return NULL;
}

int
cf__params_give(cf__params_t *p, const char *name, const double *v, size_t n)
{
    given_t *g = (given_t *)find_given(p, name);
    double *copy;
    if (strlen(name) >= CF__PARAMS_NAME || n > 2 * CF__PARAMS_MAX_POINTS)
        return -1;
    copy = malloc((n ? n : 1) * sizeof *copy);
    if (copy == NULL)
        return -1;
    if (n > 0)
        memcpy(copy, v, n * sizeof *copy);
    if (g == NULL) {
        if (p->ngiven == CF__PARAMS_MAX) {
            free(copy);
            return -1;
        }
        g = &p->given[p->ngiven++];
        snprintf(g->name, sizeof g->name, "%s", name);
    } else {
        free(g->v);
    }
    g->v = copy;
    g->n = n;
    return 0;
}

/* A reader of the values' JSON: an object of numbers and of arrays of
** [x, y] pairs, nothing else. */
typedef struct reader {
    const char *start, *s, *end;
    char *err;
    size_t errlen;
    int failed;
} reader_t;

static int
bad(reader_t *r, const char *what)
{
    if (!r->failed)
        snprintf(r->err, r->errlen, "values: %s at byte %zu", what,
                 (size_t)(r->s - r->start));
    r->failed = 1;
    return -1;
}

static void
skip_space(reader_t *r)
{
    while (r->s < r->end && (*r->s == ' ' || *r->s == '\t' || *r->s == '\n'
                             || *r->s == '\r'))
        r->s++;
}

static int
expect(reader_t *r, char c)
{
    skip_space(r);
    if (r->s >= r->end || *r->s != c) {
        char what[40];
        snprintf(what, sizeof what, "expected '%c'", c);
        return bad(r, what);
    }
    r->s++;
    return 0;
}

static int
peek(reader_t *r, char c)
{
    skip_space(r);
    return r->s < r->end && *r->s == c;
}

/* A member name: a JSON string of plain characters (no escapes). */
static int
read_name(reader_t *r, char name[CF__PARAMS_NAME])
{
    size_t n = 0;
    if (expect(r, '"') != 0)
        return -1;
    while (r->s < r->end && *r->s != '"') {
        if (*r->s == '\\' || (unsigned char)*r->s < 0x20)
            return bad(r, "a name with an escape or a control character");
        if (n + 1 >= CF__PARAMS_NAME)
            return bad(r, "a name too long");
        name[n++] = *r->s++;
    }
    name[n] = '\0';
    return expect(r, '"');
}

static int
read_number(reader_t *r, double *v)
{
    char buf[64];
    size_t n = 0;
    char *endp;
    skip_space(r);
    while (r->s + n < r->end && n + 1 < sizeof buf &&
           strchr("+-0123456789.eE", r->s[n]) != NULL && r->s[n] != '\0')
        n++;
    if (n == 0)
        return bad(r, "expected a number");
    memcpy(buf, r->s, n);
    buf[n] = '\0';
    *v = strtod(buf, &endp);
    if (endp != buf + n || !isfinite(*v))
        return bad(r, "a malformed number");
    r->s += n;
    return 0;
}

/* [[x, y], ...] into v (room for 2 * CF__PARAMS_MAX_POINTS). */
static int
read_points(reader_t *r, double *v, size_t *n)
{
    *n = 0;
    if (expect(r, '[') != 0)
        return -1;
    if (peek(r, ']'))
        return expect(r, ']');
    do {
        if (*n >= 2 * CF__PARAMS_MAX_POINTS)
            return bad(r, "too many points");
        if (expect(r, '[') != 0 || read_number(r, &v[*n]) != 0 ||
            expect(r, ',') != 0 || read_number(r, &v[*n + 1]) != 0 ||
            expect(r, ']') != 0)
            return -1;
        *n += 2;
    } while (peek(r, ',') && expect(r, ',') == 0);
    return expect(r, ']');
}

int
cf__params_give_json(cf__params_t *p, const char *json, size_t len,
                     char *err, size_t errlen)
{
    static double v[2 * CF__PARAMS_MAX_POINTS];
    reader_t r = { json, json, json + len, err, errlen, 0 };
    char name[CF__PARAMS_NAME];
    given_t saved[CF__PARAMS_MAX];
    size_t nsaved = p->ngiven;
    /* nothing is given unless the whole text reads */
    memcpy(saved, p->given, sizeof saved);
    p->ngiven = 0;
    if (memchr(json, '\0', len) != NULL) {
        snprintf(err, errlen, "values: a NUL byte in the JSON text");
        r.failed = 1;
    } else if (expect(&r, '{') == 0 && !peek(&r, '}')) {
        do {
            size_t n = 1;
            if (read_name(&r, name) != 0 || expect(&r, ':') != 0)
                break;
            if (peek(&r, '[') ? read_points(&r, v, &n) != 0
                              : read_number(&r, &v[0]) != 0)
                break;
            if (cf__params_give(p, name, v, n) != 0) {
                bad(&r, "too many values");
                break;
            }
        } while (peek(&r, ',') && expect(&r, ',') == 0);
    }
    if (!r.failed && expect(&r, '}') == 0) {
        skip_space(&r);
        if (r.s != r.end)
            bad(&r, "text after the object");
    }
    if (r.failed) {
        clear_given(p);
        memcpy(p->given, saved, sizeof saved);
        p->ngiven = nsaved;
        return -1;
    }
    for (size_t i = 0; i < nsaved; i++)
        if (find_given(p, saved[i].name) == NULL && p->ngiven < CF__PARAMS_MAX)
            p->given[p->ngiven++] = saved[i];
        else
            free(saved[i].v);
    return 0;
}

/* ---- the script --------------------------------------------------------- */

static int
fail(char *err, size_t errlen, const char *kind, const char *name,
     const char *fmt, double a, double b)
{
    char msg[200];
    snprintf(msg, sizeof msg, fmt, a, b);
    snprintf(err, errlen, "%s '%s': %s", kind, name, msg);
    return -1;
}

static int
check_name(const cf__params_t *p, const char *kind, const char *name,
           char *err, size_t errlen)
{
    if (name[0] == '\0')
        return snprintf(err, errlen, "%s: name must not be empty", kind), -1;
    if (name[0] == '@')
        return snprintf(err, errlen, "%s '%s': names starting with '@' are "
                        "reserved for the page (the view of a rotated 3D "
                        "figure)", kind, name), -1;
    for (size_t i = 0; i < p->count; i++)
        if (strcmp(p->items[i].name, name) == 0)
            return snprintf(err, errlen, "%s '%s': a parameter of this name "
                            "is already declared (line %d)", kind, name,
                            p->items[i].line_no), -1;
    if (p->count == CF__PARAMS_MAX)
        return snprintf(err, errlen, "%s '%s': more than %d parameters",
                        kind, name, CF__PARAMS_MAX), -1;
    return 0;
}

/* The decimals x is written with (up to 12): 2 for 0.25, 7 for 1e-7.  The
** tolerance is relative to x 10^k: an absolute one (1e-6 where x 10^k < 1)
** took every step up to 1e-6 for a whole number, and a slider with step
** 1e-7 snapped every value to 0. */
static int
decimals(double x)
{
    double p = 1;
    int k;
    for (k = 0; k < 12; k++, p *= 10)
        if (fabs(round(x * p) - x * p) <= 1e-6 * fabs(x * p))
            return k;
    return 12;
}

/* v rounded to k decimals: the double nearest that decimal. */
static double
to_decimals(double v, int k)
{
    double p = pow(10, k);
    double r = round(v * p) / p;
    return isfinite(r) && k < 12 ? r : v;
}

/* The multiple of q nearest v, or v itself where v / q is beyond 2^53
** (or overflows: a step or grid of 1e-320): such a v is a multiple of q
** to its own precision.  Before, the overflow made a slider's value and
** a dragged point's coordinates 0, silently. */
static double
nearest_multiple(double v, double q)
{
    double k = v / q;
    return isfinite(k) && fabs(k) < 0x1p53 ? round(k) * q : v;
}

static double
snap(const cf__param_t *d, double v)
{
    if (!(v >= d->min))
        v = d->min;
    if (v > d->max)
        v = d->max;
    if (d->step > 0) {
        int k = decimals(d->step), m = decimals(d->min);
        double s = d->min + nearest_multiple(v - d->min, d->step);
        if (s > d->max)
            s -= d->step;
        /* 0 + 3 * 0.1 is 0.30000000000000004: the step's decimals (a
        ** range beyond the largest double keeps the value as given) */
        if (isfinite(s))
            v = to_decimals(s, k > m ? k : m);
    }
    return v;
}

int
cf__params_slider(cf__params_t *p, const cf__param_t *decl, double *value,
                  char *err, size_t errlen)
{
    const char *nm = decl->name;
    const given_t *g;
    cf__param_t *d;
    if (check_name(p, "slider", nm, err, errlen) != 0)
        return -1;
    if (!(decl->min < decl->max))
        return fail(err, errlen, "slider", nm, "min %g is not below max %g",
                    decl->min, decl->max);
    if (!(decl->def >= decl->min && decl->def <= decl->max))
        return snprintf(err, errlen, "slider '%s': default %g lies outside "
                        "[min, max] = [%g, %g]", nm, decl->def, decl->min,
                        decl->max), -1;
    if (!(decl->step >= 0) || !isfinite(decl->step))
        return fail(err, errlen, "slider", nm, "step %g must be positive",
                    decl->step, 0);
    if (decl->step > decl->max - decl->min)
        return fail(err, errlen, "slider", nm, "step %g exceeds the range "
                    "max - min = %g", decl->step, decl->max - decl->min);
    if (decl->log && !(decl->min > 0))
        return fail(err, errlen, "slider", nm, "scale = \"log\" needs min "
                    "> 0 (min is %g)", decl->min, 0);
    d = &p->items[p->count++];
    *d = *decl;
    d->kind = CF__PARAM_SLIDER;
    d->def_xy = d->xy = NULL;
    d->count = 0;
    g = find_given(p, nm);
    d->value = g == NULL || g->n != 1 ? d->def
             : p->exact ? fmin(fmax(g->v[0], d->min), d->max)
             : snap(d, g->v[0]);
    *value = d->value;
    return 0;
}

void
cf__params_constrain(const cf__param_t *d, double *x, double *y)
{
    if (d->constrain == CF__CONSTRAIN_GRID) {
        int k = decimals(d->grid);
        *x = to_decimals(nearest_multiple(*x, d->grid), k);
        *y = to_decimals(nearest_multiple(*y, d->grid), k);
    } else if (d->constrain == CF__CONSTRAIN_LINE) {
        const double *a = d->line, *b = d->line + 2;
        double dx = b[0] - a[0], dy = b[1] - a[1];
        double t = ((*x - a[0]) * dx + (*y - a[1]) * dy) / (dx * dx + dy * dy);
        double nx = a[0] + t * dx, ny = a[1] + t * dy;
        if (!(isfinite(nx) && isfinite(ny))) {
            /* a line through points near the largest double, whose
            ** difference or its square overflows (the point became NaN,
            ** then 0): projected from the line's midpoint along its
            ** direction scaled to 1, each step finite */
            double mx = 0.5 * a[0] + 0.5 * b[0], my = 0.5 * a[1] + 0.5 * b[1];
            double ux = 0.5 * b[0] - 0.5 * a[0], uy = 0.5 * b[1] - 0.5 * a[1];
            double m = fmax(fabs(ux), fabs(uy));
            ux /= m;
            uy /= m;
            t = ((*x - mx) * ux + (*y - my) * uy) / (ux * ux + uy * uy);
            nx = mx + t * ux;
            ny = my + t * uy;
        }
        if (isfinite(nx) && isfinite(ny)) {
            *x = nx;
            *y = ny;
        }
    }
}

static int
check_constraint(const cf__param_t *d, char *err, size_t errlen)
{
    const char *nm = d->name;
    if (d->constrain == CF__CONSTRAIN_GRID && !(d->grid > 0 &&
                                                isfinite(d->grid)))
        return fail(err, errlen, "points", nm, "constrain: grid %g must be "
                    "positive", d->grid, 0);
    if (d->constrain == CF__CONSTRAIN_LINE &&
        d->line[0] == d->line[2] && d->line[1] == d->line[3])
        return fail(err, errlen, "points", nm, "constrain: the line's two "
                    "points coincide at (%g, %g)", d->line[0], d->line[1]);
    for (size_t i = 0; i < d->count; i++) {
        double x = d->def_xy[2 * i], y = d->def_xy[2 * i + 1];
        double scale = 1 + fabs(x) + fabs(y);
        cf__params_constrain(d, &x, &y);
        if (fabs(x - d->def_xy[2 * i]) + fabs(y - d->def_xy[2 * i + 1]) >
            1e-9 * scale) {
            char what[120];
            snprintf(what, sizeof what, "default point %zu (%%g, %%g) is not "
                     "on its %s", i + 1,
                     d->constrain == CF__CONSTRAIN_GRID ? "grid" : "line");
            return fail(err, errlen, "points", nm, what, d->def_xy[2 * i],
                        d->def_xy[2 * i + 1]);
        }
    }
    return 0;
}

int
cf__params_points(cf__params_t *p, const cf__param_t *decl,
                  const double **xy, char *err, size_t errlen)
{
    const char *nm = decl->name;
    const given_t *g;
    cf__param_t *d;
    size_t bytes = 2 * decl->count * sizeof(double);
    if (check_name(p, "points", nm, err, errlen) != 0)
        return -1;
    if (decl->count < 1 || decl->count > CF__PARAMS_MAX_POINTS)
        return fail(err, errlen, "points", nm, "default must list 1 to %g "
                    "points", CF__PARAMS_MAX_POINTS, 0);
    d = &p->items[p->count];
    *d = *decl;
    d->kind = CF__PARAM_POINTS;
    d->def_xy = malloc(bytes);
    d->xy = malloc(bytes);
    if (d->def_xy == NULL || d->xy == NULL) {
        free(d->def_xy);
        free(d->xy);
        snprintf(err, errlen, "points '%s': out of memory", nm);
        return -1;
    }
    memcpy(d->def_xy, decl->def_xy, bytes);
    if (check_constraint(d, err, errlen) != 0) {
        free(d->def_xy);
        free(d->xy);
        return -1;
    }
    p->count++;
    memcpy(d->xy, d->def_xy, bytes);
    g = find_given(p, nm);
    if (g != NULL && g->n == 2 * d->count)
        for (size_t i = 0; i < d->count; i++) {
            d->xy[2 * i] = g->v[2 * i];
            d->xy[2 * i + 1] = g->v[2 * i + 1];
            cf__params_constrain(d, &d->xy[2 * i], &d->xy[2 * i + 1]);
        }
    *xy = d->xy;
    return 0;
}

size_t
cf__params_count(const cf__params_t *p)
{
    return p != NULL ? p->count : 0;
}

const cf__param_t *
cf__params_at(const cf__params_t *p, size_t i)
{
    return p != NULL && i < p->count ? &p->items[i] : NULL;
}

bool
cf__params_view(const cf__params_t *p, const char *figure, double az_el[2])
{
    char name[CF__PARAMS_NAME];
    const given_t *g;
    int n;
    if (p == NULL || figure == NULL)
        return false;
    n = snprintf(name, sizeof name, "%s%s", CF__PARAMS_VIEW_PREFIX, figure);
    if (n < 0 || (size_t)n >= sizeof name ||
        (g = find_given(p, name)) == NULL || g->n != 2)
        return false;
    az_el[0] = g->v[0];
    az_el[1] = fmin(90.0, fmax(-90.0, g->v[1]));
    return true;
}

bool
cf__params_draft(const cf__params_t *p)
{
    const given_t *g = p != NULL ? find_given(p, CF__PARAMS_DRAFT) : NULL;
    return g != NULL && g->n == 1 && g->v[0] != 0;
}
