/*
** The native renderer's fonts (render/output/fonts-default.h): pango
** (render/backends/font-pango.c).  Choosing them opens nothing: pango is
** loaded when the first label opens a context (render/backends/
** pango-lazy.c), so a figure without labels never loads it.
*/
#include "font-pango.h"
#include "fonts-default.h"

const cf__fonts_t *
cf__fonts_default(void)
{
    return &cf__pango_fonts;
}
