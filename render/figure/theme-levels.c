/*
** A theme's redundant = true (docs/accessibility.md): the levels of a
** construction that its colours tell apart -- a curve's de Casteljau or
** de Boor net, a surface's de Casteljau or triangle scheme -- dashed and
** marked each their own way as well, for colour-blind readers and
** greyscale print; level 0 (the control polygon) keeps its own.
*/
#include <string.h>

#include "curvefig/style.h"

void
cf_theme_level_style(const cf_theme_t *theme, size_t level, cf_style_t *style)
{
    static const double dashes[][4] = {
        { 4.0, 2.0, 0, 0 }, { 1.0, 1.5, 0, 0 }, { 5.0, 1.5, 1.0, 1.5 },
        { 8.0, 2.5, 0, 0 }, { 2.5, 1.5, 0, 0 }, { 1.0, 1.5, 1.0, 4.0 },
    };
    static const cf_marker_t shapes[] = { CF_MARKER_SQUARE,
                                          CF_MARKER_DIAMOND,
                                          CF_MARKER_TRIANGLE,
                                          CF_MARKER_CIRCLE, CF_MARKER_STAR };
    if (theme == NULL || style == NULL || !theme->redundant || level == 0)
        return;
    if (!(style->set & CF_STYLE_DASH)) {
        const double *d = dashes[(level - 1) % (sizeof dashes
                                                / sizeof dashes[0])];
        memset(style->dash, 0, sizeof style->dash);
        style->dash_count = d[2] > 0 ? 4 : 2;
        memcpy(style->dash, d, style->dash_count * sizeof d[0]);
        style->set |= CF_STYLE_DASH;
    }
    if (!(style->set & CF_STYLE_MARKER)
        && theme->role[CF_ROLE_POLYGON].marker != CF_MARKER_NONE) {
        style->marker = shapes[(level - 1) % (sizeof shapes
                                              / sizeof shapes[0])];
        style->set |= CF_STYLE_MARKER;
    }
}
