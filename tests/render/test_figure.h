/* The helpers the figure tests share (test_figure.c, test_figure_window.c,
** test_figure_errors.c): the SVG of a figure and its stroked paths read
** back, the map from data to the page; static inline, as not every file
** uses each. */
#ifndef CURVEFIG_TESTS_TEST_FIGURE_H
#define CURVEFIG_TESTS_TEST_FIGURE_H

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cairo.h>
#include <cmocka.h>
#include "curvefig/bspline.h"
#include "curvefig/figure.h"
#include "testutil.h"
#include "pngtest.h"

/* ---- SVG path parsing --------------------------------------------------- */

typedef struct seg {
    double p[8];   /* start, c1, c2, end (page pt) */
    bool line;
} seg_t;

typedef struct paths {
    seg_t seg[4096];
    size_t nseg;
    size_t nmove;          /* subpaths */
    char cmds[8192];       /* the command letters in order */
    size_t ncmd;
} paths_t;

static inline char *
render_svg(cf_figure_t *fig)
{
    unsigned char *data;
    size_t size;
    char *s;
    cf_diag_t d;
    cf_diag_clear(&d);
    if (cf_figure_render(fig, CF_FORMAT_SVG, NULL, &data, &size, &d)
        != CF_STATUS_OK)
        fail_msg("render: %s", d.msg);
    s = malloc(size + 1);
    memcpy(s, data, size);
    s[size] = '\0';
    cf_free(data);
    return s;
}

/* The attribute `what` (with its leading space) inside the tag [p, end),
** or NULL. */
static inline const char *
in_tag(const char *p, const char *end, const char *what)
{
    const char *a = strstr(p, what);
    return a != NULL && a < end ? a : NULL;
}

/* Parse the d attributes of every stroked path of the drawing: a <path>
** with a stroke and without a fill (the page's group leaves paths
** unfilled; markers are filled), after </defs>, which holds the glyphs. */
static inline void
stroked_paths(const char *svg, paths_t *out)
{
    const char *p = strstr(svg, "</defs>");
    memset(out, 0, sizeof *out);
    if (p == NULL)
        p = svg;
    while ((p = strstr(p, "<path ")) != NULL) {
        const char *end = strchr(p, '>'), *d;
        double cur[2] = { 0, 0 };
        char *q;
        p += 6;
        if (end == NULL)
            break;
        d = strstr(p - 1, " d=\"");   /* "<path d=" */
        if (d == NULL || d > end)
            continue;
        if (in_tag(p, end, " stroke=\"") == NULL
            || in_tag(p, end, " fill=\"") != NULL)
            continue;
        assert_null(strstr(p, "transform") != NULL
                            && strstr(p, "transform") < end
                        ? "transform" : NULL);
        d += 4;
        while (*d != '"') {
            char c;
            while (*d == ' ')
                d++;
            c = *d;
            if (c == '"')
                break;
            d++;
            out->cmds[out->ncmd++] = c;
            if (c == 'M') {
                cur[0] = strtod(d, &q);
                cur[1] = strtod(q, &q);
                d = q;
                out->nmove++;
            } else if (c == 'C' || c == 'L') {
                seg_t *s = &out->seg[out->nseg++];
                int k, n = c == 'C' ? 3 : 1;
                s->p[0] = cur[0];
                s->p[1] = cur[1];
                for (k = 0; k < n; k++) {
                    s->p[2 + 2 * k] = strtod(d, &q);
                    s->p[3 + 2 * k] = strtod(q, &q);
                    d = q;
                }
                if (c == 'L') {
                    /* as a cubic: thirds */
                    double x1 = s->p[2], y1 = s->p[3];
                    s->p[6] = x1;
                    s->p[7] = y1;
                    s->p[2] = cur[0] + (x1 - cur[0]) / 3;
                    s->p[3] = cur[1] + (y1 - cur[1]) / 3;
                    s->p[4] = cur[0] + 2 * (x1 - cur[0]) / 3;
                    s->p[5] = cur[1] + 2 * (y1 - cur[1]) / 3;
                    s->line = true;
                }
                cur[0] = s->p[6];
                cur[1] = s->p[7];
            } else if (c != 'Z') {
                fail_msg("unexpected path command %c", c);
            }
        }
        p = end;
    }
    out->cmds[out->ncmd] = '\0';
}

static inline void
cubic_at(const double *c, double s, double *x, double *y)
{
    double u = 1 - s;
    *x = u * u * u * c[0] + 3 * u * u * s * c[2] + 3 * u * s * s * c[4]
        + s * s * s * c[6];
    *y = u * u * u * c[1] + 3 * u * u * s * c[3] + 3 * u * s * s * c[5]
        + s * s * s * c[7];
}

static inline cf_figure_t *
new_fig(void)
{
    cf_figure_t *fig = NULL;
    assert_int_equal(cf_figure_create(120, 90, CF_UNIT_MM, &fig, NULL),
                     CF_STATUS_OK);
    return fig;
}

#endif
