/*
** What a figure shows, in words' terms: the curves and surfaces as they
** were given (kind, degree, control points, weights, knots), the points
** marked and the labels with their anchors.  The element kinds note them
** as they are added; render/figure/describe.c writes a figure's long
** description from them (docs/accessibility.md).
*/
#ifndef CURVEFIG_RENDER_FACTS_H
#define CURVEFIG_RENDER_FACTS_H

#include <stdbool.h>
#include <stddef.h>

#include "curvefig/bezier.h"
#include "curvefig/bspline.h"
#include "curvefig/core.h"

typedef enum cf__fact_kind {
    CF__FACT_BEZIER,      /* bez: a copy of the curve as given */
    CF__FACT_BSPLINE,     /* bs */
    CF__FACT_SURFACE,     /* a tensor-product patch or B-spline surface */
    CF__FACT_TRIANGLE,    /* a triangular Bézier patch */
    CF__FACT_BASIS,       /* a B-spline basis function: deg, bs (its knots) */
    CF__FACT_GRAPH,       /* the graph of a function */
    CF__FACT_MARKS,       /* points drawn (points, polygon and polyline
                             vertices, nets) in the plane: xy, n */
    CF__FACT_LABEL        /* a label: text at xy (the plane) */
} cf__fact_kind_t;

typedef struct cf__fact {
    cf__fact_kind_t kind;
    cf_bezier_t *bez;
    cf_bspline_t *bs;
    int deg_u, deg_v;          /* SURFACE, TRIANGLE (deg_u), BASIS */
    size_t count_u, count_v;   /* SURFACE: control points in u and v */
    bool rational, bezier;     /* SURFACE: one Bézier patch */
    double *xy;                /* MARKS, LABEL: plane points */
    size_t n;
    char *text;                /* LABEL */
} cf__fact_t;

typedef struct cf__facts {
    cf__fact_t *items;
    size_t count, cap;
} cf__facts_t;

struct cf_figure;

/* Note a curve, points, a label, a surface (copies are taken).  Out of
** memory fails the figure (its sticky error), as any element would. */
cf_status_t cf__fact_bezier(struct cf_figure *fig, const cf_bezier_t *c);
cf_status_t cf__fact_bspline(struct cf_figure *fig, const cf_bspline_t *s);
cf_status_t cf__fact_marks(struct cf_figure *fig, const double *xy,
                           size_t n);
cf_status_t cf__fact_label(struct cf_figure *fig, double x, double y,
                           const char *text);
cf_status_t cf__fact_surface(struct cf_figure *fig, cf__fact_kind_t kind,
                             int deg_u, int deg_v, size_t count_u,
                             size_t count_v, bool rational, bool bezier);
cf_status_t cf__fact_basis(struct cf_figure *fig, const double *knots,
                           size_t nknots, int p);
cf_status_t cf__fact_graph(struct cf_figure *fig);
void cf__facts_fini(cf__facts_t *f);

#endif
