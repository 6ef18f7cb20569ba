/*
** The phrases of a figure's description in each language it is written in
** (render/figure/describe-lang.c): English, the default, and Czech.  A
** phrase with %s or %d takes the arguments named beside it, in that order.
*/
#ifndef CURVEFIG_RENDER_DESCRIBE_LANG_H
#define CURVEFIG_RENDER_DESCRIBE_LANG_H

typedef struct cf__desc_lang {
    const char *code;           /* BCP 47 primary tag: "en", "cs" */
    char decimal;               /* the decimal mark */
    const char *coord_sep;      /* between a point's coordinates */
    const char *list_and;       /* before a list's last item */
    const char *article;        /* before a noun phrase in a list */
    const char *panel;          /* %zu: a panel's number */
    const char *degree[6];      /* a curve of degree 0..5 (adjective) */
    const char *bi[4];          /* a surface of degree 1..3 both ways */
    const char *of_degree;      /* %d: a curve of a higher degree */
    const char *of_degrees;     /* %d x %d: a surface's degrees */
    const char *rational;       /* adjective before the degree */
    const char *bezier_curve, *bspline_curve, *nurbs_curve;
    const char *bezier_patch, *bspline_surface, *nurbs_surface;
    const char *triangle_patch;
    const char *control_points; /* before the control points' list */
    const char *many_points;    /* %s count, %s first, %s last */
    const char *with_construction;  /* between a curve and its
                                       constructions */
    const char *weights;        /* before the weights */
    const char *knots;          /* before the knots */
    const char *many_knots;     /* %s count, %s first, %s last */
    const char *surface_points; /* %s x %s control points */
    const char *decasteljau;    /* %s t: the construction (summary) */
    const char *deboor;         /* %s u */
    const char *ends_at;        /* %s the curve point (name and place) */
    const char *curve_n;        /* %s: "curve 2" */
    const char *on_curve;       /* %s: the number of the curve a
                                   construction is drawn on */
    const char *split_left, *split_right;  /* %s curve (curve_n), %s the
                                              other's number, %s t */
    const char *elevated;       /* %s curve, %s other, %d from, %d to */
    const char *inserted;       /* %s curve, %s other, %s the knots */
    const char *offset;         /* %s curve, %s other, %s distance */
    const char *offsets;        /* %s first, %s last, %s other, %s d */
    const char *with_offset;    /* %s distance: after a curve's phrase */
    const char *view_ortho;     /* %s azimuth, %s elevation */
    const char *view_persp;     /* %s azimuth, %s elevation, %s distance */
    const char *basis;          /* %d degree, %s knots */
    const char *basis_short;    /* %d degree */
    const char *graph;          /* one function's graph */
    const char *graphs;         /* %s: the number of graphs */
    const char *labels;         /* before the other labels */
    const char *empty;          /* nothing described */
    const char *drawing;        /* points, lines and labels alone */
    const char *times;          /* %s count: an item repeated */
} cf__desc_lang_t;

/* The phrases of language tag lang ("cs", "cs-CZ", ...), English when
** there are none for it (or lang is NULL). */
const cf__desc_lang_t *cf__desc_lang(const char *lang);
/* Whether lang has phrases of its own. */
int cf__desc_lang_known(const char *lang);

#endif
