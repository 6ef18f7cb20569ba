/*
** An animation's sweeps and frames (anim-spec.h).
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "anim-spec.h"
#include "curvefig/core.h"

static int
number(const char *s, size_t n, double *out)
{
    char buf[64], *end;
    if (n == 0 || n >= sizeof buf)
        return -1;
    memcpy(buf, s, n);
    buf[n] = '\0';
    *out = strtod(buf, &end);
    return end != buf && *end == '\0' && isfinite(*out) ? 0 : -1;
}

int
cf__anim_parse_sweep(cf__anim_spec_t *spec, const char *arg, char *err,
                     size_t errlen)
{
    const char *eq = strchr(arg, '='), *colon;
    cf__anim_sweep_t *sw;
    size_t n;
    if (eq == NULL || (colon = strchr(eq, ':')) == NULL || eq == arg) {
        snprintf(err, errlen, "--sweep '%s': give NAME=FROM:TO, e.g. "
                 "t=0:1", arg);
        return -1;
    }
    n = (size_t)(eq - arg);
    if (n >= CF__PARAMS_NAME) {
        snprintf(err, errlen, "--sweep '%s': the slider's name is longer "
                 "than %d bytes", arg, CF__PARAMS_NAME - 1);
        return -1;
    }
    if (spec->nsweeps >= CF__ANIM_MAX_SWEEPS) {
        snprintf(err, errlen, "--sweep '%s': at most %d sliders move "
                 "together", arg, CF__ANIM_MAX_SWEEPS);
        return -1;
    }
    for (size_t i = 0; i < spec->nsweeps; i++)
        if (strlen(spec->sweep[i].name) == n
            && strncmp(spec->sweep[i].name, arg, n) == 0) {
            snprintf(err, errlen, "--sweep '%s': slider '%.*s' is swept "
                     "twice", arg, (int)n, arg);
            return -1;
        }
    sw = &spec->sweep[spec->nsweeps];
    if (number(eq + 1, (size_t)(colon - eq - 1), &sw->from) != 0
        || number(colon + 1, strlen(colon + 1), &sw->to) != 0) {
        snprintf(err, errlen, "--sweep '%s': FROM and TO must be numbers, "
                 "e.g. t=0:1", arg);
        return -1;
    }
    memcpy(sw->name, arg, n);
    sw->name[n] = '\0';
    spec->nsweeps++;
    return 0;
}

static const char *
where(const cf__anim_spec_t *spec, char *buf, size_t n)
{
    if (spec->line_no > 0)
        snprintf(buf, n, "animate{} (line %d)", spec->line_no);
    else
        snprintf(buf, n, "--sweep");
    return buf;
}

/* The sweep's slider among the declarations: its index, or -1 with the
** message (the nearest slider's name). */
static const cf__param_t *
find_slider(const cf__params_t *params, const char *name, const char *w,
            char *err, size_t errlen)
{
    const char *names[CF__PARAMS_MAX];
    size_t n = 0;
    const char *near;
    for (size_t i = 0; i < cf__params_count(params); i++) {
        const cf__param_t *p = cf__params_at(params, i);
        if (p->kind != CF__PARAM_SLIDER)
            continue;
        if (strcmp(p->name, name) == 0)
            return p;
        names[n++] = p->name;
    }
    if (n == 0) {
        snprintf(err, errlen, "%s: the script declares no slider (slider{ "
                 "name = \"%s\", ... }) to sweep", w, name);
        return NULL;
    }
    near = cf_nearest_name(name, names, n);
    snprintf(err, errlen, "%s: the script declares no slider '%s'%s%s%s "
             "(its sliders:", w, name, near ? "; did you mean '" : "",
             near ? near : "", near ? "'?" : "");
    for (size_t i = 0; i < n; i++) {
        size_t len = strlen(err);
        snprintf(err + len, errlen - len, " %s", names[i]);
    }
    {
        size_t len = strlen(err);
        snprintf(err + len, errlen - len, ")");
    }
    return NULL;
}

int
cf__anim_check(cf__anim_spec_t *spec, const cf__params_t *params, char *err,
               size_t errlen)
{
    char w[64];
    where(spec, w, sizeof w);
    for (size_t i = 0; i < spec->nsweeps; i++) {
        const cf__anim_sweep_t *sw = &spec->sweep[i];
        const cf__param_t *p = find_slider(params, sw->name, w, err, errlen);
        double eps;
        if (p == NULL)
            return -1;
        eps = 1e-12 * (p->max - p->min);
        if (sw->from < p->min - eps || sw->from > p->max + eps
            || sw->to < p->min - eps || sw->to > p->max + eps) {
            snprintf(err, errlen, "%s: %s from %g to %g leaves the slider's "
                     "range [%g, %g] (line %d)", w, sw->name, sw->from,
                     sw->to, p->min, p->max, p->line_no);
            return -1;
        }
    }
    if (spec->fps != 0 && !(spec->fps > 0 && isfinite(spec->fps))) {
        snprintf(err, errlen, "%s: fps %g must be positive", w, spec->fps);
        return -1;
    }
    if (spec->seconds != 0
        && !(spec->seconds > 0 && isfinite(spec->seconds))) {
        snprintf(err, errlen, "%s: seconds %g must be positive", w,
                 spec->seconds);
        return -1;
    }
    if (spec->step_seconds != 0
        && !(spec->step_seconds > 0 && isfinite(spec->step_seconds))) {
        snprintf(err, errlen, "%s: step seconds %g must be positive", w,
                 spec->step_seconds);
        return -1;
    }
    if (spec->frames == 0) {
        double fps = spec->fps > 0 ? spec->fps : CF__ANIM_DEFAULT_FPS;
        double secs = spec->seconds > 0 ? spec->seconds
                                        : CF__ANIM_DEFAULT_SECONDS;
        double n = floor(fps * secs + 0.5);
        if (n < 1) {
            snprintf(err, errlen, "%s: %g fps for %g s make no frame", w,
                     fps, secs);
            return -1;
        }
        if (n > CF__ANIM_MAX_FRAMES) {
            snprintf(err, errlen, "%s: %g fps for %g s make %.15g frames, "
                     "more than %d", w, fps, secs, n, CF__ANIM_MAX_FRAMES);
            return -1;
        }
        spec->frames = (unsigned)n;
        spec->fps = fps;
    } else if (spec->fps == 0) {
        spec->fps = spec->seconds > 0 ? spec->frames / spec->seconds
                                      : CF__ANIM_DEFAULT_FPS;
    }
    if (spec->frames > CF__ANIM_MAX_FRAMES) {
        snprintf(err, errlen, "%s: %u frames, more than %d", w,
                 spec->frames, CF__ANIM_MAX_FRAMES);
        return -1;
    }
    return 0;
}

double
cf__anim_progress(const cf__anim_spec_t *spec, unsigned k)
{
    unsigned n = spec->frames;
    double u;
    if (n < 2)
        return 0;
    if (spec->bounce)
        u = 1 - fabs(1 - 2.0 * k / n);
    else
        u = (double)k / (n - 1);
    if (spec->ease_in_out)
        u = u * u * (3 - 2 * u);
    return u;
}

double
cf__anim_value(const cf__anim_spec_t *spec, size_t i, unsigned k)
{
    const cf__anim_sweep_t *sw = &spec->sweep[i];
    double u = cf__anim_progress(spec, k);
    /* the ends exactly */
    if (u <= 0)
        return sw->from;
    if (u >= 1)
        return sw->to;
    return sw->from + (sw->to - sw->from) * u;
}
