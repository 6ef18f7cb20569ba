/*
** The head of an arrow, drawn by the arrows in the plane (el-mark.c), in
** space (el-space.c) and at the axes' ends (axes.c): a file of its own so
** that these call it without calling one another.
*/
#include <string.h>

#include "model.h"

void
cf__arrow_head(cf__dl_t *dl, double tx, double ty, double ux, double uy,
               double len, const cf_color_t *color, double opacity)
{
    double nx = -uy, ny = ux, w = 0.38 * len;
    cf__paint_t paint;
    memset(&paint, 0, sizeof paint);
    paint.fill = true;
    paint.fill_color = *color;
    paint.fill_opacity = opacity;
    cf__dl_path_begin(dl);
    cf__dl_move(dl, tx, ty);
    cf__dl_line(dl, tx - len * ux + w * nx, ty - len * uy + w * ny);
    cf__dl_line(dl, tx - 0.72 * len * ux, ty - 0.72 * len * uy);
    cf__dl_line(dl, tx - len * ux - w * nx, ty - len * uy - w * ny);
    cf__dl_close(dl);
    cf__dl_path_paint(dl, &paint);
}
