/*
** Fonts for the tool: a small fontconfig configuration built in memory.
**
** fontconfig's default start (FcInit, which pango runs in a thread of its
** own) parses /etc/fonts/fonts.conf and the fifty-odd files of conf.d with
** expat and compiles their rules: about 8 ms of the tool's 25 ms start-up
** on Debian 12, for rules about fonts a figure never uses; and every font
** sort pango asks for then ranks all ~270 fonts of the system.
**
** A figure asks for the theme's family list, "Latin Modern Roman,CMU
** Serif,Noto Serif CJK SC" or the sans one "Latin Modern Sans,CMU Sans
** Serif,Noto Sans CJK SC" (a script naming another family gets it only
** from the system configuration, FONTCONFIG_FILE), with the optical sizes
** "LM Roman 5" ... "LM Roman 17" in front, and Latin Modern Math.  So the tool gives
** fontconfig only the directories those fonts live in (Debian's
** fonts-lmodern, fonts-cmu, fonts-noto-cjk) and the cache directories
** fc-cache filled for them, plus the two rules of the default
** configuration that can change a glyph of these fonts: a slanted request
** on a family without italic gets a sheared upright face (Noto Serif CJK
** inside an italic run), a bold request on a family without bold gets
** emboldened.  Hinting and anti-aliasing rules do not matter: the renderer
** sets its font options itself (label.c: no hinting, grey anti-aliasing).
** For every character these families have, the result is the same fonts
** and the same output files, byte for byte (tests/render/test_output.c
** compares both configurations).  Characters none of them has come from
** Latin Modern Math (\cdot, \circ, \mapsto, \langle, \rangle: the
** system configuration took DejaVu Sans), or are missing glyphs (emoji)
** where the system configuration might have found another family.
**
** The system configuration is kept when FONTCONFIG_FILE or FONTCONFIG_PATH
** is set (the user chose a configuration) or when one of the three font
** directories does not exist (another distribution).
**
** The program curvefig goes further (cf__tool_fonts_own, render/tool/
** faces.c): its renderer chooses the faces of this configuration itself,
** as fontconfig would (render/backends/font-match.h), from the fonts'
** metadata kept in a cache, and fontconfig's configuration is made only
** when pango shapes a run (a label the renderer hands on): a label set in
** these fonts loads neither fontconfig nor expat.  When the matcher
** declines the configuration (a font it does not read as fontconfig
** does), fontconfig's is made here as before.
*/
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <fontconfig/fontconfig.h>

#include "tool.h"

typedef struct font_dir {
    const char *path;
    bool required;
} font_dir_t;

static const font_dir_t font_dirs[] = {
    { "/usr/share/texmf/fonts/opentype/public/lm", true },   /* LM Roman */
    { "/usr/share/texmf/fonts/opentype/public/lm-math", false },
    { "/usr/share/fonts/truetype/cmu", true },               /* CMU Serif */
    { "/usr/share/fonts/opentype/noto", true },     /* Noto Serif CJK SC */
};

/* Where fc-cache writes: the system's directory, then the user's. */
static const char cache_dirs[] =
    "<cachedir>/var/cache/fontconfig</cachedir>\n"
    "<cachedir prefix=\"xdg\">fontconfig</cachedir>\n";

/* The accepted families, for the matcher (the same as below). */
static const char *const families[] = {
    "Latin Modern Roman", "CMU Serif", "Noto Serif CJK SC",
    "Latin Modern Math", "Latin Modern Sans", "CMU Sans Serif",
    "Noto Sans CJK SC",
};

/* Only the families of the theme's lists, serif and sans (and Latin
** Modern Math, for the math symbols none of them has) enter the font set: 28 fonts instead
** of the 136 of these directories, and pango sorts the whole set once per
** font description (a 0.25 ms sort becomes 0.07 ms).  An empty pattern
** matches every font; acceptfont wins over rejectfont. */
static const char select_families[] =
    "<selectfont>\n"
    " <acceptfont>\n"
    "  <pattern><patelt name=\"family\"><string>Latin Modern Roman</string>"
    "</patelt></pattern>\n"
    "  <pattern><patelt name=\"family\"><string>CMU Serif</string>"
    "</patelt></pattern>\n"
    "  <pattern><patelt name=\"family\"><string>Noto Serif CJK SC</string>"
    "</patelt></pattern>\n"
    "  <pattern><patelt name=\"family\"><string>Latin Modern Math</string>"
    "</patelt></pattern>\n"
    "  <pattern><patelt name=\"family\"><string>Latin Modern Sans</string>"
    "</patelt></pattern>\n"
    "  <pattern><patelt name=\"family\"><string>CMU Sans Serif</string>"
    "</patelt></pattern>\n"
    "  <pattern><patelt name=\"family\"><string>Noto Sans CJK SC</string>"
    "</patelt></pattern>\n"
    " </acceptfont>\n"
    " <rejectfont><pattern></pattern></rejectfont>\n"
    "</selectfont>\n";

/* Synthetic styles.  A font that is upright while the request is not
** gets the shear x' = x + 0.2 y and is then called oblique; a font of
** weight medium or less under a bold request is emboldened and called
** bold. */
static const char synthetic_rules[] =
    "<match target=\"font\">\n"
    " <test name=\"slant\"><const>roman</const></test>\n"
    " <test target=\"pattern\" name=\"slant\" compare=\"not_eq\">"
    "<const>roman</const></test>\n"
    " <edit name=\"matrix\" mode=\"assign\"><times><name>matrix</name>"
    "<matrix><double>1</double><double>0.2</double>"
    "<double>0</double><double>1</double></matrix></times></edit>\n"
    " <edit name=\"slant\" mode=\"assign\"><const>oblique</const></edit>\n"
    "</match>\n"
    "<match target=\"font\">\n"
    " <test name=\"weight\" compare=\"less_eq\"><const>medium</const>"
    "</test>\n"
    " <test target=\"pattern\" name=\"weight\" compare=\"more_eq\">"
    "<const>bold</const></test>\n"
    " <edit name=\"embolden\" mode=\"assign\"><bool>true</bool></edit>\n"
    " <edit name=\"weight\" mode=\"assign\"><const>bold</const></edit>\n"
    "</match>\n";

/* Latin Modern's design sizes are families of their own ("LM Roman 7")
** listed after "Latin Modern Roman".  pango names a font by its first
** family, and pango's cairo fonts compute their metrics (asked for by
** every layout, for line heights) by laying out a sample sentence in that
** family: for an LM Roman 7 subscript, a whole LM Roman 10 face loaded and
** shaped for nothing.  With the design's family first, that sentence is
** set in the font itself. */
static const char design_families[] =
    "<match target=\"font\"><test name=\"family\"><string>LM Roman %d"
    "</string></test><edit name=\"family\" mode=\"prepend_first\">"
    "<string>LM Roman %d</string></edit></match>\n";

static bool
is_dir(const char *path)
{
    struct stat sb;
    return stat(path, &sb) == 0 && S_ISDIR(sb.st_mode);
}

static bool
env_set(const char *name)
{
    const char *v = getenv(name);
    return v != NULL && *v != '\0';
}

/* The configuration text; false when a required directory is missing or
** the text does not fit. */
static bool
config_text(char *buf, size_t cap)
{
    static const int designs[] = { 5, 6, 7, 8, 9, 12, 17 };
    size_t i, len;
    int n = snprintf(buf, cap, "<?xml version=\"1.0\"?>\n<fontconfig>\n");
    if (n < 0 || (size_t)n >= cap)
        return false;
    len = (size_t)n;
    for (i = 0; i < sizeof font_dirs / sizeof font_dirs[0]; i++) {
        if (!is_dir(font_dirs[i].path)) {
            if (font_dirs[i].required)
                return false;
            continue;
        }
        n = snprintf(buf + len, cap - len, "<dir>%s</dir>\n",
                     font_dirs[i].path);
        if (n < 0 || (size_t)n >= cap - len)
            return false;
        len += (size_t)n;
    }
    n = snprintf(buf + len, cap - len, "%s%s%s", cache_dirs,
                 select_families, synthetic_rules);
    if (n < 0 || (size_t)n >= cap - len)
        return false;
    len += (size_t)n;
    for (i = 0; i < sizeof designs / sizeof designs[0]; i++) {
        n = snprintf(buf + len, cap - len, design_families, designs[i],
                     designs[i]);
        if (n < 0 || (size_t)n >= cap - len)
            return false;
        len += (size_t)n;
    }
    n = snprintf(buf + len, cap - len, "</fontconfig>\n");
    return n >= 0 && (size_t)n < cap - len;
}

static cf__tool_own_fonts_fn own_fonts;

void
cf__tool_fonts_own(cf__tool_own_fonts_fn fn)
{
    own_fonts = fn;
}

/* fontconfig's configuration made current; false when it fails (the
** system's is then used). */
static bool
make_config(void)
{
    char text[8192];
    FcConfig *config;
    if (!config_text(text, sizeof text))
        return false;
    config = FcConfigCreate();
    if (config == NULL)
        return false;
    if (!FcConfigParseAndLoadFromMemory(config, (const FcChar8 *)text,
                                        FcFalse)
        || !FcConfigBuildFonts(config)
        || !FcConfigSetCurrent(config)) {
        FcConfigDestroy(config);
        return false;
    }
    /* the current configuration holds its own reference */
    FcConfigDestroy(config);
    return true;
}

/* The hook that makes it when pango first needs it. */
static void
make_config_later(void)
{
    (void)make_config();
}

const char *
cf__tool_fonts_init(void)
{
    static const char *which = NULL;
    char text[8192];
    size_t i, n = 0;
    cf__tool_font_dir_t dirs[sizeof font_dirs / sizeof font_dirs[0]];

    if (which != NULL)
        return which;
    which = "the system's fontconfig configuration";
    if (env_set("FONTCONFIG_FILE") || env_set("FONTCONFIG_PATH")
        || !config_text(text, sizeof text))
        return which;
    for (i = 0; i < sizeof font_dirs / sizeof font_dirs[0]; i++)
        if (is_dir(font_dirs[i].path)) {
            dirs[n].path = font_dirs[i].path;
            dirs[n++].required = font_dirs[i].required;
        }
    if (!(own_fonts != NULL
          && own_fonts(dirs, n, families,
                       sizeof families / sizeof families[0],
                       make_config_later))
        && !make_config())
        return which;
    which = "Latin Modern, CMU and Noto CJK (curvefig's configuration)";
    return which;
}
