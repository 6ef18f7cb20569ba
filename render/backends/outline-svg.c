/*
** A label's outline as SVG path data (render/backends/outline-svg.h).
*/
#include "buffer.h"
#include "label-private.h"
#include "outline-svg.h"

static int
put_points(cf__buf_t *d, const char *op, const double *v, int n, double x,
           double y)
{
    int k, bad = cf__buf_append(d, op, 1);
    for (k = 0; k < n && !bad; k++)
        bad = (k > 0 && cf__buf_append(d, " ", 1) != 0)
              || cf__svg_put_num(d, x + v[2 * k]) != 0
              || cf__buf_append(d, " ", 1) != 0
              || cf__svg_put_num(d, y + v[2 * k + 1]) != 0;
    return bad;
}

int
cf__label_outline_svg(void *unused, const cf__text_op_t *t, cf__buf_t *d)
{
    cf__path_t p;
    const double *v;
    size_t i;
    int bad = 0;
    (void)unused;
    cf__label_outline(t->label, &p);
    v = p.coords;
    for (i = 0; i < p.nsegs && !bad; i++) {
        switch ((cf__seg_t)p.segs[i]) {
        case CF__SEG_MOVE:
            bad = put_points(d, "M", v, 1, t->ox, t->oy);
            v += 2;
            break;
        case CF__SEG_LINE:
            bad = put_points(d, "L", v, 1, t->ox, t->oy);
            v += 2;
            break;
        case CF__SEG_CURVE:
            bad = put_points(d, "C", v, 3, t->ox, t->oy);
            v += 6;
            break;
        case CF__SEG_CLOSE:
            bad = cf__buf_append(d, "Z", 1);
            break;
        default:   /* labels' outlines have no rectangles or arcs */
            return -1;
        }
    }
    return bad ? -1 : 0;
}
