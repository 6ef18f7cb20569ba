/*
** The native renderer's fonts (render/output/fonts-default.h): HarfBuzz
** in the faces pango would choose (render/backends/font-native.c), which
** hands to pango (render/backends/font-pango.c) the runs it does not
** shape itself.  Choosing them opens nothing: the fonts are configured
** when the first label opens a context, and pango is loaded only for a
** run handed to it (render/backends/pango-lazy.c), so neither a figure
** without labels nor one whose labels HarfBuzz sets loads it.
*/
#include "font-native.h"
#include "fonts-default.h"

const cf__fonts_t *
cf__fonts_default(void)
{
    return &cf__native_fonts;
}
