/*
** The tool's font configuration (render/tool/fonts.c) for the tests of
** the face matcher and its readers: its directories, in fontconfig's
** order, and the families its <selectfont> accepts.
*/
#ifndef CURVEFIG_TESTS_TOOL_FONTS_H
#define CURVEFIG_TESTS_TOOL_FONTS_H

#include "font-match.h"

static const cf__fm_source_t tool_font_dirs[] = {
    { "/usr/share/texmf/fonts/opentype/public/lm", true },
    { "/usr/share/texmf/fonts/opentype/public/lm-math", false },
    { "/usr/share/fonts/truetype/cmu", true },
    { "/usr/share/fonts/opentype/noto", true },
};
#define TOOL_FONT_DIRS (sizeof tool_font_dirs / sizeof tool_font_dirs[0])

static const char *const tool_font_families[] = {
    "Latin Modern Roman", "CMU Serif", "Noto Serif CJK SC",
    "Latin Modern Math", "Latin Modern Sans", "CMU Sans Serif",
    "Noto Sans CJK SC",
};
#define TOOL_FONT_FAMILIES \
    (sizeof tool_font_families / sizeof tool_font_families[0])

#endif
