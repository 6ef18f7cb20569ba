/*
** The tool's faces without fontconfig (render/tool/tool.h's
** cf__tool_own_fonts_fn, installed by curvefig's main): the renderer,
** linked into curvefig, takes the configuration of fonts.c itself
** (render/backends/font-config.h: cf__fonts_own_faces, the matcher of
** font-match.h over the fonts' metadata cache), and fontconfig's
** configuration is made only when pango opens.  curvefig-check and
** curvefig-live, which use the shared library, keep fontconfig's.
*/
#include "font-config.h"
#include "tool.h"

bool
cf__tool_own_faces(const cf__tool_font_dir_t *dirs, size_t ndirs,
                   const char *const *families, size_t nfamilies,
                   void (*make_config)(void))
{
    cf__fm_source_t src[8];
    size_t i;
    if (ndirs > sizeof src / sizeof src[0])
        return false;
    for (i = 0; i < ndirs; i++) {
        src[i].dir = dirs[i].path;
        src[i].required = dirs[i].required;
    }
    if (!cf__fonts_own_faces(src, ndirs, families, nfamilies))
        return false;
    cf__fonts_before_fontconfig(make_config);
    return true;
}
