/*
** The description of a figure (render/figure/describe.c writes it,
** describe-find.c recognises what its curves show): shared between them.
*/
#ifndef CURVEFIG_RENDER_DESCRIBE_PRIVATE_H
#define CURVEFIG_RENDER_DESCRIBE_PRIVATE_H

#include "buffer.h"
#include "describe-lang.h"
#include "model.h"

/* Constructions recognised per curve, control points compared in a
** relation check, and coordinates of a point: at most these. */
#define CF__DESCRIBE_MAX_PARAMS 8
#define CF__DESCRIBE_MAX_PTS 64
#define CF__DESCRIBE_MAX_DIM 4
#define CF__DESCRIBE_MAX_MARKS 20000   /* points drawn and labels */

/* How a curve was made from an earlier one (rel_of). */
typedef enum cf__rel {
    CF__REL_NONE,
    CF__REL_LEFT,      /* the part before rel_param (subdivision) */
    CF__REL_RIGHT,     /* the part after rel_param */
    CF__REL_ELEVATED,  /* degree elevation */
    CF__REL_INSERTED,  /* knots inserted[0 .. ninserted) */
    CF__REL_OFFSET     /* at distance rel_param from it (plane curves) */
} cf__rel_t;

/* One curve of the figure, as given and in the page plane. */
typedef struct cf__curve_info {
    const cf_bezier_t *bez;        /* one of the two */
    const cf_bspline_t *bs;
    int degree;
    bool rational;
    size_t dim, npts;
    double *pts;                   /* npts x dim, Cartesian */
    double *w;                     /* npts weights (1 when polynomial) */
    double *plane;                 /* npts x 2, projected */
    double params[CF__DESCRIBE_MAX_PARAMS];   /* constructions at */
    size_t nparams;
    bool deboor;                   /* params are de Boor's u */
    cf__rel_t rel;
    size_t rel_of;
    double rel_param;
    double inserted[CF__DESCRIBE_MAX_PARAMS];
    size_t ninserted;
} cf__curve_info_t;

typedef struct cf__describe {
    cf_figure_t *fig;
    cf__curve_info_t *curves;
    size_t ncurves;
    size_t nmarks;                 /* points drawn and labels */
    double eps;                    /* page-plane tolerance, data units */
    double tol;                    /* control point tolerance */
    bool nomem;                    /* a relation could not be tried for
                                      want of memory (describe-find.c) */
} cf__describe_t;

/* A description being written: the figure's curves, the language, the
** text so far. */
typedef struct cf__dwriter {
    cf__describe_t d;
    const cf__desc_lang_t *L;
    cf__buf_t *out;
} cf__dwriter_t;

/* describe-words.c: text into b; numbers short (param: t, u, knots and
** weights, written as fractions where they are halves ... sixteenths);
** points as "(x, y)"; item separators; a label's text as read; a named
** point "P_0 (0, 5)"; the sentence's capital at byte at. */
void cf__dw_put(cf__buf_t *b, const char *s);
void cf__dw_putf(cf__buf_t *b, const char *fmt, ...);
void cf__dw_fmt_num(const cf__desc_lang_t *L, double x, bool param,
                    char *out, size_t cap);
void cf__dw_put_num(cf__dwriter_t *w, double x, bool param);
void cf__dw_put_point(cf__dwriter_t *w, const double *p, size_t dim);
void cf__dw_put_sep(cf__dwriter_t *w, size_t i, size_t n);
void cf__dw_put_params(cf__dwriter_t *w, const double *v, size_t n);
void cf__dw_put_plain(cf__buf_t *b, const char *s);
void cf__dw_put_named(cf__dwriter_t *w, const double *plane,
                      const double *p, size_t dim);
void cf__dw_capitalise(cf__buf_t *b, size_t at);
/* Write into sub (emptied) from now on; back into outer, sub
** NUL-terminated and its failure passed on to outer. */
void cf__dw_begin(cf__dwriter_t *w, cf__buf_t *sub);
void cf__dw_end(cf__dwriter_t *w, cf__buf_t *sub, cf__buf_t *outer);

/* Recognise the constructions and relations of d's curves. */
void cf__describe_find(cf__describe_t *d);
/* Whether plane point p is drawn (a mark or a label's anchor). */
bool cf__describe_drawn(const cf__describe_t *d, const double *p);
/* The text of the label at plane point p, or NULL. */
const char *cf__describe_name_at(const cf__describe_t *d, const double *p);

#endif
