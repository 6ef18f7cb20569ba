/*
** `curvefig render` of an animation (animate.h): the sweep's options, the
** spec of a figure (the command line's over the script's animate{}), and
** the frames: the script run again for each, its sliders set to the
** frame's values (exactly, not snapped to their step), or the steps of an
** overlay figure in turn.
*/
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "anim.h"
#include "animate.h"
#include "curvefig/figure.h"
#include "tool.h"

static const struct {
    const char *name;
    unsigned bit, out;
} formats[] = {
    { "gif", CF__TOOL_GIF_BIT, CF__ANIM_OUT_GIF },
    { "apng", CF__TOOL_APNG_BIT, CF__ANIM_OUT_APNG },
    { "mp4", CF__TOOL_MP4_BIT, CF__ANIM_OUT_MP4 },
    { "webm", CF__TOOL_WEBM_BIT, CF__ANIM_OUT_WEBM },
};

unsigned
cf__tool_anim_format(const char *name)
{
    for (size_t i = 0; i < sizeof formats / sizeof formats[0]; i++)
        if (strcmp(name, formats[i].name) == 0)
            return formats[i].bit;
    return 0;
}

bool
cf__tool_anim_takes_value(const char *opt)
{
    static const char *const with_value[] = {
        "--sweep", "--frames", "--fps", "--seconds", "--ease",
        "--step-seconds", "--workers", NULL,
    };
    for (int i = 0; with_value[i] != NULL; i++)
        if (strcmp(opt, with_value[i]) == 0)
            return true;
    return false;
}

/* The value of --fps, --seconds or --step-seconds: a number from 0.001
** to 10000; a number outside is refused saying on which side (1e-300 is
** positive, but too small). */
static int
time_value(const char *opt, const char *v, double *x, char *msg, size_t size)
{
    char *end;
    double y;
    errno = 0;
    y = strtod(v, &end);
    if (end == v || *end != '\0' || isnan(y)) {
        snprintf(msg, size, "%s '%s': give a number from 0.001 to 10000",
                 opt, v);
        return -1;
    }
    /* strtod gives +0 with ERANGE for a positive number below the least
    ** subnormal (1e-400) */
    if (y < 0 || (y == 0 && !(errno == ERANGE && !signbit(y)))) {
        snprintf(msg, size, "%s '%s': give a positive number (from 0.001 "
                 "to 10000)", opt, v);
        return -1;
    }
    if (y < 1e-3) {
        snprintf(msg, size, "%s '%s' is too small: the least is 0.001",
                 opt, v);
        return -1;
    }
    if (y > 1e4) {
        snprintf(msg, size, "%s '%s' is too large: the most is 10000", opt,
                 v);
        return -1;
    }
    *x = y;
    return 0;
}

int
cf__tool_anim_option(const char *opt, const char *v, cf__tool_anim_t *ta,
                     char *msg, size_t size)
{
    double x;
    if (strcmp(opt, "--animate") == 0) {
        ta->animate = true;
    } else if (strcmp(opt, "--bounce") == 0) {
        ta->spec.bounce = ta->bounce_given = true;
    } else if (strcmp(opt, "--sweep") == 0) {
        return cf__anim_parse_sweep(&ta->spec, v, msg, size) == 0 ? 1 : -1;
    } else if (strcmp(opt, "--frames") == 0) {
        if (cf__tool_number(v, 1, CF__ANIM_MAX_FRAMES, &x) != 0
            || x != floor(x)) {
            snprintf(msg, size, "--frames '%s': give a whole number of "
                     "frames from 1 to %d", v, CF__ANIM_MAX_FRAMES);
            return -1;
        }
        ta->spec.frames = (unsigned)x;
        ta->frames_given = true;
    } else if (strcmp(opt, "--fps") == 0 || strcmp(opt, "--seconds") == 0
               || strcmp(opt, "--step-seconds") == 0) {
        if (time_value(opt, v, &x, msg, size) != 0)
            return -1;
        if (opt[2] == 'f') {
            ta->spec.fps = x;
            ta->fps_given = true;
        } else if (opt[2] == 's' && opt[3] == 'e') {
            ta->spec.seconds = x;
            ta->seconds_given = true;
        } else {
            ta->spec.step_seconds = x;
        }
    } else if (strcmp(opt, "--ease") == 0) {
        if (strcmp(v, "linear") != 0 && strcmp(v, "in-out") != 0) {
            snprintf(msg, size, "--ease '%s': use linear or in-out", v);
            return -1;
        }
        ta->spec.ease_in_out = v[0] == 'i';
        ta->ease_given = true;
    } else if (strcmp(opt, "--workers") == 0) {
        if (cf__tool_number(v, 1, 8, &x) != 0 || x != floor(x)) {
            snprintf(msg, size, "--workers '%s': give a whole number from 1 "
                     "to 8", v);
            return -1;
        }
        ta->workers = (int)x;
    } else {
        return 0;
    }
    return 1;
}

bool
cf__tool_anim_wanted(const cf__tool_anim_t *ta, unsigned fmts)
{
    return ta->animate || ta->spec.nsweeps > 0 || ta->frames_given
        || ta->fps_given || ta->seconds_given || ta->ease_given
        || ta->bounce_given || ta->spec.step_seconds > 0
        || (fmts & CF__TOOL_ANIM_BITS) != 0;
}

int
cf__tool_anim_check_formats(unsigned fmts, char *msg, size_t size)
{
    for (int f = 0; f < CF_FORMAT_LAST_; f++) {
        if (!(fmts & CF_FORMAT_BIT(f)) || f == CF_FORMAT_SVG
            || f == CF_FORMAT_PDF)
            continue;
        snprintf(msg, size, "-f %s makes no animation (an animation is "
                 "svg, pdf, gif, apng, mp4 or webm%s)",
                 cf_format_extension((cf_format_t)f),
                 f == CF_FORMAT_PNG ? "; apng is an animated png" : "");
        return -1;
    }
    if ((fmts >> CF_FORMAT_LAST_) & ~(CF__TOOL_ANIM_BITS >> CF_FORMAT_LAST_)) {
        snprintf(msg, size, "-f html makes no animation (an animation is "
                 "svg, pdf, gif, apng, mp4 or webm)");
        return -1;
    }
    return 0;
}

/* ---- the frames ---------------------------------------------------------- */

typedef struct source_ctx {
    const cf__tool_run_t *run;
    const cf__anim_spec_t *spec;
    const cf_script_t *first;     /* the run at the defaults */
    size_t index;                 /* the figure's */
    cf_script_t *s;               /* frame's run, until release */
    FILE *devnull;                /* what the frames' runs print */
} source_ctx_t;

static cf_status_t
make_step(void *ctx, unsigned k, cf_figure_t **fig, unsigned *step,
          cf_diag_t *diag)
{
    source_ctx_t *c = ctx;
    (void)diag;
    *fig = cf_script_figure(c->first, c->index);
    *step = k + 1;
    return CF_STATUS_OK;
}

static void
release_step(void *ctx, unsigned k, cf_figure_t *fig)
{
    (void)ctx;
    (void)k;
    (void)fig;
}

static cf_status_t
make_sweep(void *ctx, unsigned k, cf_figure_t **fig, unsigned *step,
           cf_diag_t *diag)
{
    source_ctx_t *c = ctx;
    const cf__tool_run_t *r = c->run;
    cf_script_t *s = NULL;
    cf_status_t st;
    *fig = NULL;
    *step = 0;
    st = cf_script_create(&r->limits->script, c->devnull, &s, diag);
    if (st != CF_STATUS_OK)
        return st;
    cf_script_set_labels(s, r->labels);
    cf_script_set_fonts(s, r->font, r->font_size);
    cf_script_set_page(s, r->width, r->height);
    cf_script_set_seed(s, r->seed);
    cf__params_set_exact(cf_script_params(s), true);
    for (size_t i = 0; i < c->spec->nsweeps; i++) {
        double v = cf__anim_value(c->spec, i, k);
        if (cf__params_give(cf_script_params(s), c->spec->sweep[i].name, &v,
                            1) != 0) {
            cf_script_destroy(s);
            return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                               "out of memory giving the sliders' values");
        }
    }
    st = cf_script_run_file(s, r->script);
    if (st != CF_STATUS_OK) {
        st = cf_diag_set(diag, st, -1, "frame %u: %s", k + 1,
                         cf_script_error(s));
        cf_script_destroy(s);
        return st;
    }
    if (cf_script_figure_count(s) <= c->index
        || strcmp(cf_script_figure_name(s, c->index),
                  cf_script_figure_name(c->first, c->index)) != 0) {
        cf_script_destroy(s);
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "frame %u: the script makes other figures at "
                           "these slider values", k + 1);
    }
    *fig = cf_script_figure(s, c->index);
    if (r->prepare != NULL)
        r->prepare(*fig, r->background);
    c->s = s;
    return CF_STATUS_OK;
}

static void
release_sweep(void *ctx, unsigned k, cf_figure_t *fig)
{
    source_ctx_t *c = ctx;
    (void)k;
    (void)fig;
    cf_script_destroy(c->s);
    c->s = NULL;
}

/* The spec of the figure: the command line's sweeps, else the script's
** animate{}; the command line's timing over the script's. */
static void
merge_spec(const cf__tool_anim_t *ta, const cf_script_t *s,
           cf__anim_spec_t *spec)
{
    const cf__anim_spec_t *sc = cf_script_animation(s);
    if (ta->spec.nsweeps > 0 || sc == NULL)
        *spec = ta->spec;
    else
        *spec = *sc;
    if (ta->frames_given)
        spec->frames = ta->spec.frames;
    else if (ta->fps_given || ta->seconds_given)
        spec->frames = 0;
    if (ta->fps_given)
        spec->fps = ta->spec.fps;
    if (ta->seconds_given)
        spec->seconds = ta->spec.seconds;
    if (ta->ease_given)
        spec->ease_in_out = ta->spec.ease_in_out;
    if (ta->bounce_given)
        spec->bounce = true;
    if (ta->spec.step_seconds > 0)
        spec->step_seconds = ta->spec.step_seconds;
}

static void
fail(const cf_script_t *s, size_t i, const char *script, const char *msg)
{
    const char *where = cf_script_figure_where(s, i);
    if (where[0] != '\0')
        fprintf(stderr, "curvefig: %sfigure '%s': %s\n", where,
                cf_script_figure_name(s, i), msg);
    else
        fprintf(stderr, "curvefig: %s: figure '%s': %s\n", script,
                cf_script_figure_name(s, i), msg);
}

int
cf__tool_animate(const cf_script_t *s, size_t i, const cf__tool_run_t *run,
                 const cf__tool_anim_t *ta, const char *base, unsigned fmts,
                 double dpi, bool tight, bool verbose)
{
    cf__anim_spec_t spec;
    cf__anim_source_t src;
    cf__anim_options_t o;
    source_ctx_t ctx;
    cf_figure_t *fig = cf_script_figure(s, i);
    unsigned steps = cf_figure_steps(fig);
    char err[600];
    cf_diag_t diag;
    cf_status_t st;
    merge_spec(ta, s, &spec);
    memset(&src, 0, sizeof src);
    memset(&ctx, 0, sizeof ctx);
    ctx.run = run;
    ctx.spec = &spec;
    ctx.first = s;
    ctx.index = i;
    src.ctx = &ctx;
    if (spec.nsweeps > 0) {
        if (cf__anim_check(&spec, cf_script_params(s), err, sizeof err)
            != 0) {
            fail(s, i, run->script, err);
            return -1;
        }
        src.frames = spec.frames;
        src.seconds = 1.0 / spec.fps;
        src.make = make_sweep;
        src.release = release_sweep;
    } else if (steps > 1) {
        src.frames = steps;
        src.seconds = spec.step_seconds > 0 ? spec.step_seconds
                                            : CF__ANIM_STEP_SECONDS;
        src.same_figure = true;
        src.make = make_step;
        src.release = release_step;
    } else {
        size_t n = 0;
        const cf__params_t *p = cf_script_params(s);
        snprintf(err, sizeof err, "nothing to animate: give --sweep "
                 "NAME=FROM:TO or animate{ slider = ..., from = ..., to = "
                 "... } in the script (its sliders:");
        for (size_t k = 0; k < cf__params_count(p); k++)
            if (cf__params_at(p, k)->kind == CF__PARAM_SLIDER) {
                size_t len = strlen(err);
                snprintf(err + len, sizeof err - len, " %s",
                         cf__params_at(p, k)->name);
                n++;
            }
        {
            size_t len = strlen(err);
            snprintf(err + len, sizeof err - len, "%s), or overlay steps",
                     n == 0 ? " none" : "");
        }
        fail(s, i, run->script, err);
        return -1;
    }
    if (spec.nsweeps > 0) {
        ctx.devnull = fopen("/dev/null", "w");
        if (ctx.devnull == NULL) {
            fail(s, i, run->script, "cannot open /dev/null");
            return -1;
        }
    }
    memset(&o, 0, sizeof o);
    o.base = base;
    o.dpi = dpi;
    o.tight = tight;
    o.loop = true;
    o.workers = ta->workers;
    if (fmts & CF_FORMAT_BIT(CF_FORMAT_SVG))
        o.outputs |= CF__ANIM_OUT_SVG;
    if (fmts & CF_FORMAT_BIT(CF_FORMAT_PDF))
        o.outputs |= CF__ANIM_OUT_PDF;
    for (size_t k = 0; k < sizeof formats / sizeof formats[0]; k++)
        if (fmts & formats[k].bit)
            o.outputs |= formats[k].out;
    cf_diag_clear(&diag);
    st = cf__anim_write(&src, &o, NULL, NULL, &diag);
    if (ctx.devnull != NULL)
        fclose(ctx.devnull);
    if (st != CF_STATUS_OK) {
        fail(s, i, run->script,
             diag.msg[0] ? diag.msg : cf_status_to_string(st));
        return -1;
    }
    if (o.outputs & CF__ANIM_OUT_PDF)
        printf("\\animategraphics[loop,autoplay,controls]{%.6g}{%s}{0}{%u}\n",
               1.0 / src.seconds, base, src.frames - 1);
    for (unsigned bit = 1; verbose && bit <= CF__ANIM_OUT_WEBM; bit <<= 1)
        if (o.outputs & bit)
            printf("%s.%s\n", base, cf__anim_extension(bit));
    return 0;
}
