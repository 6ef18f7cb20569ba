/*
** Overlay steps of a figure (include/curvefig/overlay.h): the
** specification the elements added next get (cf__element_commit copies
** it into each), checked here; cf__element_draw hands an element's to
** its GROUP operation.
*/
#include <string.h>

#include "model.h"
#include "overlay-spec.h"

cf_status_t
cf_figure_set_overlay(cf_figure_t *fig, const char *spec)
{
    char why[120], *copy = NULL;
    unsigned last = 0;
    CF__FIG_CHECK(fig);
    if (spec != NULL) {
        size_t n = strlen(spec) + 1;
        if (cf__overlay_parse(spec, &last, why, sizeof why) != 0)
            return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                               "visible = \"%.40s\": %s (an overlay "
                               "specification is steps as beamer writes "
                               "them: \"2\", \"1-3\", \"2-\", \"2,4-\")",
                               spec, why);
        copy = cf_malloc(n);
        if (copy == NULL)
            return cf_diag_set(&fig->err, CF_STATUS_NO_MEMORY, -1,
                               "out of memory for an overlay specification");
        memcpy(copy, spec, n);
    }
    cf_free(fig->overlay);
    fig->overlay = copy;
    fig->overlay_last = last;
    return CF_STATUS_OK;
}

unsigned
cf_figure_steps(const cf_figure_t *fig)
{
    if (fig == NULL)
        return 0;
    return fig->steps > 1 ? fig->steps : 1;
}

bool
cf_figure_visible_at(const cf_figure_t *fig, size_t i, unsigned k)
{
    if (fig == NULL || i >= fig->count || k < 1 || k > cf_figure_steps(fig))
        return false;
    return cf__overlay_visible(fig->els[i]->overlay, k);
}
