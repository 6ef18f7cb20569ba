/*
** `curvefig render` of an animation (animate.c, docs/animations.md): the
** options --sweep, --frames, --fps, --seconds, --ease, --bounce,
** --step-seconds, --animate and --workers, the formats gif, apng, mp4
** and webm, and the frames made by running the script again with the
** sliders set (render/output/anim.h draws and writes them).
*/
#ifndef CURVEFIG_TOOL_ANIMATE_H
#define CURVEFIG_TOOL_ANIMATE_H

#include <stdbool.h>
#include <stddef.h>

#include "anim-spec.h"
#include "curvefig/figure.h"
#include "runlimits.h"
#include "script.h"

/* The formats of animations only, beside the figure formats' bits. */
#define CF__TOOL_GIF_BIT (1u << 26)
#define CF__TOOL_APNG_BIT (1u << 27)
#define CF__TOOL_MP4_BIT (1u << 28)
#define CF__TOOL_WEBM_BIT (1u << 29)
#define CF__TOOL_ANIM_BITS (CF__TOOL_GIF_BIT | CF__TOOL_APNG_BIT \
                            | CF__TOOL_MP4_BIT | CF__TOOL_WEBM_BIT)

typedef struct cf__tool_anim {
    cf__anim_spec_t spec;    /* of the command line */
    bool frames_given, fps_given, seconds_given, ease_given, bounce_given;
    bool animate;            /* --animate: the script's animate{} */
    int workers;             /* --workers (0: the cores) */
} cf__tool_anim_t;

/* How every frame's script runs: as the first run did. */
typedef struct cf__tool_run {
    const char *script;                 /* its path */
    const cf__tool_limits *limits;
    bool labels;
    const char *font;
    double font_size, width, height;
    long long seed;
    const char *background;             /* --background, NULL none */
    void (*prepare)(cf_figure_t *fig, const char *background);
} cf__tool_run_t;

/* The bit of an animation format name (gif, apng, mp4, webm), 0 for
** another name. */
unsigned cf__tool_anim_format(const char *name);
/* Whether opt takes a value (--sweep and the others with one). */
bool cf__tool_anim_takes_value(const char *opt);
/* One option of an animation: 1 when opt is one (its value, if it takes
** one, stored), 0 when it is none of them, -1 for a bad value (msg says
** what to give). */
int cf__tool_anim_option(const char *opt, const char *value,
                         cf__tool_anim_t *ta, char *msg, size_t size);
/* Whether a render is an animation: --sweep, --animate, an option of the
** sweep, or an animation format among formats. */
bool cf__tool_anim_wanted(const cf__tool_anim_t *ta, unsigned formats);
/* The formats of an animation: 0, or -1 with msg naming the format that
** is not one (png: use apng). */
int cf__tool_anim_check_formats(unsigned formats, char *msg, size_t size);

/* Figure i of s (run at its defaults) animated into base.EXT for every
** format; the \animategraphics line printed when a PDF is made; verbose:
** the files listed.  0, or -1 with the message (naming the script and
** figure) on stderr. */
int cf__tool_animate(const cf_script_t *s, size_t i, const cf__tool_run_t *run,
                     const cf__tool_anim_t *ta, const char *base,
                     unsigned formats, double dpi, bool tight, bool verbose);

#endif
