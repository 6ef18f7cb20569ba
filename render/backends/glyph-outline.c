/*
** The outlines of a label's glyphs as SVG path data, from its fonts
** through cairo (cf__label_path, cairo_copy_path): the outline function of the
** SVG writer natively (render/backends/backend.h), and the source of the glyph
** data a course page embeds.
*/
#include <string.h>

#include <cairo.h>

#include "backend.h"
#include "buffer.h"
#include "label-cairo.h"

static int
put_point(cf__buf_t *d, const char *op, const cairo_path_data_t *p)
{
    return cf__buf_append(d, op, strlen(op)) != 0
           || cf__svg_put_num(d, p->point.x) != 0
           || cf__buf_append(d, " ", 1) != 0
           || cf__svg_put_num(d, p->point.y) != 0 ? -1 : 0;
}

int
cf__svg_path_data(const void *cairo_path, cf__buf_t *d)
{
    const cairo_path_t *path = cairo_path;
    int i, bad = 0;
    if (path->status != CAIRO_STATUS_SUCCESS)
        return -1;
    for (i = 0; i < path->num_data && !bad;
         i += path->data[i].header.length) {
        const cairo_path_data_t *p = &path->data[i];
        switch (p->header.type) {
        case CAIRO_PATH_MOVE_TO:
            bad = put_point(d, "M", &p[1]);
            break;
        case CAIRO_PATH_LINE_TO:
            bad = put_point(d, "L", &p[1]);
            break;
        case CAIRO_PATH_CURVE_TO:
            bad = put_point(d, "C", &p[1]) || put_point(d, " ", &p[2])
                  || put_point(d, " ", &p[3]);
            break;
        case CAIRO_PATH_CLOSE_PATH:
            bad = cf__buf_append(d, "Z", 1);
            break;
        }
    }
    return bad ? -1 : 0;
}

int
cf__glyph_outline(void *outliner, const cf__text_op_t *t, cf__buf_t *d)
{
    cf__glyph_outliner_t *g = outliner;
    cairo_path_t *path;
    int r;
    if (g->cr == NULL) {
        cairo_surface_t *s = cairo_recording_surface_create(
            CAIRO_CONTENT_ALPHA, NULL);
        g->cr = cairo_create(s);
        cairo_surface_destroy(s);
    }
    cairo_new_path(g->cr);
    cf__label_path(t->label, g->cr, t->ox, t->oy);
    path = cairo_copy_path(g->cr);
    r = cf__svg_path_data(path, d);
    cairo_path_destroy(path);
    return r;
}

void
cf__glyph_outliner_fini(cf__glyph_outliner_t *g)
{
    if (g->cr != NULL)
        cairo_destroy((cairo_t *)g->cr);
    g->cr = NULL;
}
