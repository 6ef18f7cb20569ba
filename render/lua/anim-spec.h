/*
** An animation of a script (docs/animations.md): sliders swept from one
** value to another over a number of frames, as `curvefig render --sweep`
** or the script's animate{} asks (render/lua/lanimate.c).  No Lua and no
** cairo here: the spec, its checks against the sliders a run declared,
** and the slider values of each frame.
*/
#ifndef CURVEFIG_RENDER_LUA_ANIM_SPEC_H
#define CURVEFIG_RENDER_LUA_ANIM_SPEC_H

#include <stdbool.h>
#include <stddef.h>

#include "params.h"

#define CF__ANIM_MAX_SWEEPS 8       /* sliders moving together */
#define CF__ANIM_MAX_FRAMES 10000
#define CF__ANIM_DEFAULT_FPS 25.0
#define CF__ANIM_DEFAULT_SECONDS 4.0
#define CF__ANIM_STEP_SECONDS 1.5   /* an overlay step's time on screen */

typedef struct cf__anim_sweep {
    char name[CF__PARAMS_NAME];
    double from, to;
} cf__anim_sweep_t;

typedef struct cf__anim_spec {
    cf__anim_sweep_t sweep[CF__ANIM_MAX_SWEEPS];
    size_t nsweeps;        /* 0: no sweep (the overlay steps, if any) */
    unsigned frames;       /* 0: fps x seconds */
    double fps, seconds;   /* 0: not given */
    bool ease_in_out;      /* smoothstep instead of linear */
    bool bounce;           /* there and back: from .. to .. from */
    double step_seconds;   /* overlay steps: 0 the default */
    int line_no;           /* where animate{} was called (0: the command
                              line) */
} cf__anim_spec_t;

/* One "NAME=FROM:TO" of --sweep added to spec; 0, or -1 with a message
** in err (its shape, a number that is not one, too many sweeps, a slider
** named twice). */
int cf__anim_parse_sweep(cf__anim_spec_t *spec, const char *arg, char *err,
                         size_t errlen);

/* The spec checked against the sliders params declared (a run of the
** script at its defaults): every slider known (else the nearest name),
** from and to inside [min, max], at least one frame, fps positive, and
** frames, fps and seconds settled (frames = round(fps x seconds), or fps =
** frames / seconds).  0, or -1 with a message in err. */
int cf__anim_check(cf__anim_spec_t *spec, const cf__params_t *params,
                   char *err, size_t errlen);

/* The place of frame k (0 .. frames-1) along the sweep, 0 at from and 1
** at to: k / (frames - 1), there and back when bouncing (to at the middle
** frame, and the frame after the last would be the first again), eased
** when asked. */
double cf__anim_progress(const cf__anim_spec_t *spec, unsigned k);
/* The value of sweep i at frame k. */
double cf__anim_value(const cf__anim_spec_t *spec, size_t i, unsigned k);

#endif
