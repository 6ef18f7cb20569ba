/*
** The colour check of a figure as a structure (colour-check.c): the
** clashes that cf_figure_colour_check (curvefig/output.h) writes as JSON,
** for a caller that prints them itself (`curvefig check`,
** render/tool/colours.c) -- the JSON is written from this same report.
*/
#ifndef CURVEFIG_RENDER_COLOUR_CHECK_H
#define CURVEFIG_RENDER_COLOUR_CHECK_H

#include <stddef.h>

#include "curvefig/figure.h"
#include "colour-vision.h"

/* One of the two paints of a clash. */
typedef struct cf__colour_paint {
    const char *element;   /* the element's kind: "net", "curve", "surface
                           ** front", ... (a static string) */
    size_t number;         /* the element's place in the figure, from 1 */
    unsigned rgb;          /* its colour over a white page, 0xrrggbb */
} cf__colour_paint_t;

/* Two paints that only colour tells apart, at least the threshold apart
** in normal vision and closer than it in vision. */
typedef struct cf__colour_clash {
    cf__vision_t vision;   /* protan, deutan, tritan or grey */
    const char *paint;     /* "line", "fill" or "marker" (a static string) */
    double de;             /* their CIEDE2000 distance under vision */
    double normal_de;      /* ... and in normal vision */
    cf__colour_paint_t a, b;
} cf__colour_clash_t;

/* The check of one figure: one clash per pair of colours, paint and
** vision, in the order the paints were drawn. */
typedef struct cf__colour_report {
    double threshold;      /* min_de */
    size_t paints;         /* the paints compared */
    cf__colour_clash_t *clashes;
    size_t count, cap;
} cf__colour_report_t;

/* The check of fig at min_de (0 < min_de <= 100) into *r (released with
** cf__colour_report_fini, also after a failure). */
cf_status_t cf__colour_report(cf_figure_t *fig, double min_de,
                              cf__colour_report_t *r, cf_diag_t *diag);
void cf__colour_report_fini(cf__colour_report_t *r);

/* The report as the JSON of cf_figure_colour_check into *json (released
** with cf_free) and *size; CF_STATUS_NO_MEMORY (diag says it) on failure. */
cf_status_t cf__colour_report_json(const cf__colour_report_t *r,
                                   char **json, size_t *size,
                                   cf_diag_t *diag);

#endif
