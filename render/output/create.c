/*
** The public constructors of what holds labels, a figure and a label
** (curvefig/figure.h, curvefig/label.h): the one place that chooses the
** fonts labels are set in (render/output/fonts-default.h).  The layers
** below take them as an argument (cf__figure_create, cf__label_create):
** the labels know fonts only through render/labels/font.h, and nothing
** below the backends includes cairo's or pango's headers.
*/
#include "fonts-default.h"
#include "label-private.h"
#include "model.h"

cf_status_t
cf_figure_create(double width, double height, cf_unit_t unit,
                 cf_figure_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    return cf__figure_create(cf__fonts_default(), width, height, unit, out,
                             diag);
}

cf_status_t
cf_label_create(const char *text, const char *family, double size_bp,
                cf_label_t **out, cf_diag_t *diag)
{
    cf_diag_clear(diag);
    return cf__label_create(cf__fonts_default(), text, family, size_bp, out,
                            diag);
}
