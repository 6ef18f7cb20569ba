/*
** The labels of elements: a source and its layout at the element's font
** size, the origin that puts a label at a side of its anchor, and the
** display-list operation that draws it.
*/
#include <string.h>

#include "label-private.h"
#include "model.h"

cf_status_t
cf__text_set(cf_figure_t *fig, cf__text_t *t, const char *src, double size)
{
    size_t n = strlen(src);
    t->src = cf_malloc(n + 1);
    if (t->src == NULL)
        return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                           "out of memory for a label");
    memcpy(t->src, src, n + 1);
    return cf__label_create(fig->fonts, src, fig->theme.font_family, size,
                            &t->lab, &fig->err);
}

cf_status_t
cf__text_ensure(cf_figure_t *fig, cf__text_t *t, double size)
{
    cf_label_t *lab;
    cf_status_t st;
    if (cf__label_matches(t->lab, fig->theme.font_family, size))
        return CF_STATUS_OK;
    st = cf__label_create(fig->fonts, t->src, fig->theme.font_family, size,
                          &lab, &fig->err);
    if (st != CF_STATUS_OK)
        return st;
    cf_label_destroy(t->lab);
    t->lab = lab;
    return CF_STATUS_OK;
}

void
cf__text_fini(cf__text_t *t)
{
    cf_free(t->src);
    cf_label_destroy(t->lab);
    t->src = NULL;
    t->lab = NULL;
}

void
cf__label_origin(const cf_label_t *lab, cf_place_t place, double off,
                 double px, double py, double *ox, double *oy)
{
    double ink[4], cx, cy, w2, h2, d = off * 0.7071;
    /* the signs of the offsets from the anchor, per place: x, y */
    double sx = 0, sy = 0, dx = 0, dy = 0;
    cf__label_ink(lab, ink);
    cx = 0.5 * (ink[0] + ink[2]);
    cy = 0.5 * (ink[1] + ink[3]);
    w2 = 0.5 * (ink[2] - ink[0]);
    h2 = 0.5 * (ink[3] - ink[1]);
    switch (place) {
    case CF_PLACE_N:
        sy = -1;
        dy = off;
        break;
    case CF_PLACE_S:
        sy = 1;
        dy = off;
        break;
    case CF_PLACE_E:
        sx = 1;
        dx = off;
        break;
    case CF_PLACE_W:
        sx = -1;
        dx = off;
        break;
    case CF_PLACE_NE:
        sx = 1;
        sy = -1;
        dx = dy = d;
        break;
    case CF_PLACE_NW:
        sx = -1;
        sy = -1;
        dx = dy = d;
        break;
    case CF_PLACE_SE:
        sx = 1;
        sy = 1;
        dx = dy = d;
        break;
    case CF_PLACE_SW:
        sx = -1;
        sy = 1;
        dx = dy = d;
        break;
    default:
        break;
    }
    *ox = sx > 0 ? px + dx + w2 - cx : sx < 0 ? px - dx - w2 - cx : px - cx;
    *oy = sy > 0 ? py + dy + h2 - cy : sy < 0 ? py - dy - h2 - cy : py - cy;
}

cf_status_t
cf__text_draw(cf_figure_t *fig, cf__text_t *t, const cf_style_t *s,
              double px, double py, cf_place_t place, double off,
              cf__dl_t *dl)
{
    cf__text_op_t op;
    if (t->src == NULL)
        return CF_STATUS_OK;
    if (cf__text_ensure(fig, t, s->font_size) != CF_STATUS_OK)
        return fig->err.status;
    memset(&op, 0, sizeof op);
    op.label = t->lab;
    op.source = t->src;
    op.px = px;
    op.py = py;
    op.place = place;
    op.offset = off;
    op.font_size = s->font_size;
    cf__label_origin(t->lab, place, off, px, py, &op.ox, &op.oy);
    cf__label_ink(t->lab, op.ink);
    op.color = s->color;
    op.opacity = s->opacity;
    if (s->halo > 0) {
        /* the background colour (white for a theme without one); on a
        ** transparent page a knockout: the ink under the label is left
        ** out, so the slide behind shows through, whatever its colour */
        cf_color_t bg = fig->theme.background;
        if (bg.a <= 0)
            bg.r = bg.g = bg.b = bg.a = 1;
        op.halo = s->halo;
        op.halo_color = bg;
    }
    cf__dl_text(dl, &op);
    return CF_STATUS_OK;
}
