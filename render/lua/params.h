/*
** The parameters of an interactive figure: the sliders and draggable
** point lists a script declares (slider{...}, points{...}, lparams.c) and
** the values a host gives them for a run.
**
** A host (curvefig live, the page of -f html) sets values by name before
** a run (cf__params_give, or cf__params_give_json from the page's JSON);
** the script's declarations then take them, clamped and snapped to the
** declared range, step or constraint.  A parameter the host gave nothing
** for takes its default, which is all a static render ever sees: one
** script is the printed and the interactive figure.
**
** No Lua here and no cairo: the same code runs in the WebAssembly build.
*/
#ifndef CURVEFIG_RENDER_LUA_PARAMS_H
#define CURVEFIG_RENDER_LUA_PARAMS_H

#include <stdbool.h>
#include <stddef.h>

#define CF__PARAMS_MAX 64          /* parameters of one script */
#define CF__PARAMS_MAX_POINTS 256  /* points of one points{} list */
#define CF__PARAMS_NAME 64         /* bytes of a name, NUL included */

typedef enum cf__param_kind {
    CF__PARAM_SLIDER,
    CF__PARAM_POINTS
} cf__param_kind_t;

typedef enum cf__constraint {
    CF__CONSTRAIN_NONE,
    CF__CONSTRAIN_GRID,     /* both coordinates multiples of grid */
    CF__CONSTRAIN_LINE      /* on the line through line[0..1], line[2..3] */
} cf__constraint_t;

typedef struct cf__param {
    cf__param_kind_t kind;
    char name[CF__PARAMS_NAME];
    char label[CF__PARAMS_NAME];    /* shown beside a slider ("" = name) */
    /* a slider */
    double min, max, step;          /* step 0: continuous */
    bool log;                       /* a logarithmic slider (min > 0): the
                                       page moves it by ratios */
    double def, value;
    /* a point list: count points, x y interleaved */
    size_t count;
    double *def_xy, *xy;
    cf__constraint_t constrain;
    double grid, line[4];
    char figure[CF__PARAMS_NAME];   /* dragged in this figure ("" = every
                                       figure of the script) */
    int line_no;                    /* where it was declared */
} cf__param_t;

typedef struct cf__params cf__params_t;

cf__params_t *cf__params_create(void);
void cf__params_destroy(cf__params_t *p);

/* ---- the host ----------------------------------------------------------- */

/* Give parameter name the values v[0..n-1] for the next run (a slider
** one number, a point list x y per point); 0, or -1 when memory or the
** table of given values (CF__PARAMS_MAX) runs out. */
int cf__params_give(cf__params_t *p, const char *name, const double *v,
                    size_t n);
/* exact: the sliders take the host's values clamped to [min, max] but
** not snapped to their step (the frames of an animation, render/lua/
** anim-spec.h, move smoothly); false at first. */
void cf__params_set_exact(cf__params_t *p, bool exact);
/* The same from JSON text: an object whose members are numbers or arrays
** of [x, y] pairs, { "t": 0.5, "P": [[0, 0], [1, 2]] }.  0, or -1 with a
** message in err (malformed JSON, a value of another shape, a name too
** long); nothing is given then. */
int cf__params_give_json(cf__params_t *p, const char *json, size_t len,
                         char *err, size_t errlen);

/* ---- the script --------------------------------------------------------- */

/* Declare a slider: decl's name, label, min, max, step, log and def are
** read (value, points and constraint are not).  0 and *value the value it
** takes (the host's, clamped to [min, max] and snapped to the step, then
** rounded to the step's decimals so that 3 steps of 0.1 are 0.3, or the
** default); -1 with a message in err: min not below max, the default
** outside [min, max], a step that is not positive or exceeds the range, a
** log slider whose min is not positive, a name already declared, an
** empty name, too many parameters. */
int cf__params_slider(cf__params_t *p, const cf__param_t *decl,
                      double *value, char *err, size_t errlen);
/* Declare a point list: decl's name, count, def_xy, constrain, grid,
** line and figure are read (def_xy is copied).  The default points must
** satisfy the constraint; a host's list of another length is ignored (the
** defaults are taken), a host's point is moved onto the constraint.  0 and
** *xy the points it takes (valid until the store is destroyed); -1 with a
** message in err. */
int cf__params_points(cf__params_t *p, const cf__param_t *decl,
                      const double **xy, char *err, size_t errlen);

/* The declarations, in the order the script made them. */
size_t cf__params_count(const cf__params_t *p);
const cf__param_t *cf__params_at(const cf__params_t *p, size_t i);

/* Move the point (x, y) onto the constraint of param (grid or line). */
void cf__params_constrain(const cf__param_t *param, double *x, double *y);

/* ---- the view of a 3D figure -------------------------------------------- */

/* A page rotating a 3D figure gives its view as the reserved value
** "@view:FIGURE" = [[azimuth, elevation]] (degrees; names of parameters
** cannot start with '@').  When the host gave one for figure figure,
** az_el[0..1] (the script's view) is replaced by it, the elevation
** clamped to [-90, 90], and true is returned; else false and az_el is
** left as it is, which is all a static render ever sees. */
#define CF__PARAMS_VIEW_PREFIX "@view:"
bool cf__params_view(const cf__params_t *p, const char *figure,
                     double az_el[2]);

/* ---- drafts -------------------------------------------------------------- */

/* While a slider, a point or a 3D figure is being dragged, a page asks
** for a draft: the reserved value "@draft" = 1 (docs/interactive.md,
** "Drafts").  A draft loosens the tolerances of what takes a run's time,
** each by the factor CF__PARAMS_DRAFT_FACTOR: the figures' fitting
** tolerance (which the hidden lines of surfaces derive theirs from) and
** the tolerance of c:offset; nothing else changes.  When the drag stops
** the page asks for the exact run; a static render never sees "@draft". */
#define CF__PARAMS_DRAFT "@draft"
#define CF__PARAMS_DRAFT_FACTOR 10.0
/* True when the host asked for a draft. */
bool cf__params_draft(const cf__params_t *p);

#endif
