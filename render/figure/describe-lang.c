/*
** The phrases of descriptions (describe-lang.h): English and Czech.
** Czech uses the decimal comma and a semicolon between coordinates, and
** the feminine adjectives that go with křivka and plocha.
*/
#include <string.h>

#include "describe-lang.h"

static const cf__desc_lang_t langs[] = {
    {
        "en", '.', ", ", " and ", "a ", "Panel %zu: ",
        { "constant", "linear", "quadratic", "cubic", "quartic", "quintic" },
        { NULL, "bilinear", "biquadratic", "bicubic" },
        " of degree %d", " of degree %d \xc3\x97 %d", "rational ",
        "B\xc3\xa9zier curve", "B-spline curve", "NURBS curve",
        "B\xc3\xa9zier patch", "B-spline surface", "NURBS surface",
        "triangular B\xc3\xa9zier patch",
        "control points ",
        "%s control points from %s to %s", " with ",
        "; weights ", "; knots ", "; %s knots from %s to %s",
        " with %s \xc3\x97 %s control points",
        "de Casteljau's construction at t = %s",
        "de Boor's construction at u = %s",
        ", ending at the curve point %s",
        "curve %s", " on curve %s",
        "%s is the part of curve %s before t = %s (subdivision)",
        "%s is the part of curve %s after t = %s (subdivision)",
        "%s is curve %s with its degree raised from %d to %d",
        "%s is curve %s after knot insertion at u = %s",
        "%s is the offset of curve %s at distance %s",
        "Curves %s to %s are the offset of curve %s at distance %s",
        " and its offset at distance %s",
        "Seen from azimuth %s\xc2\xb0 and elevation %s\xc2\xb0 "
        "(parallel projection).",
        "Seen from azimuth %s\xc2\xb0 and elevation %s\xc2\xb0 in "
        "perspective from distance %s.",
        "the B-spline basis functions of degree %d on the knots %s",
        "B-spline basis functions of degree %d",
        "the graph of a function", "the graphs of %s functions",
        "Further labels: ", "An empty figure.",
        "A drawing of points and lines.", " (%s times)",
    },
    {
        "cs", ',', "; ", " a ", "", "Panel %zu: ",
        { "konstantn\xc3\xad", "line\xc3\xa1rn\xc3\xad",
          "kvadratick\xc3\xa1", "kubick\xc3\xa1", "kvartick\xc3\xa1",
          "kvintick\xc3\xa1" },
        { NULL, "biline\xc3\xa1rn\xc3\xad", "bikvadratick\xc3\xa1",
          "bikubick\xc3\xa1" },
        " stupn\xc4\x9b %d", " stupn\xc4\x9b %d \xc3\x97 %d",
        "racion\xc3\xa1ln\xc3\xad ",
        "B\xc3\xa9zierova k\xc5\x99ivka", "B-splajnov\xc3\xa1 k\xc5\x99ivka",
        "NURBS k\xc5\x99ivka",
        "B\xc3\xa9zierova plocha", "B-splajnov\xc3\xa1 plocha",
        "NURBS plocha", "troj\xc3\xba" "heln\xc3\xadkov\xc3\xa1 "
        "B\xc3\xa9zierova plocha",
        "\xc5\x99\xc3\xad" "dic\xc3\xad body ",
        "%s \xc5\x99\xc3\xad" "dic\xc3\xad" "ch bod\xc5\xaf od %s do %s",
        " a ",
        "; v\xc3\xa1hy ", "; uzly ", "; %s uzl\xc5\xaf od %s do %s",
        " s %s \xc3\x97 %s \xc5\x99\xc3\xad" "dic\xc3\xadmi body",
        "konstrukce de Casteljauova algoritmu v t = %s",
        "konstrukce de Boorova algoritmu v u = %s",
        ", kter\xc3\xa1 kon\xc4\x8d\xc3\xad v bod\xc4\x9b k\xc5\x99ivky %s",
        "k\xc5\x99ivka %s", " na k\xc5\x99ivce %s",
        "%s je \xc4\x8d\xc3\xa1st k\xc5\x99ivky %s p\xc5\x99" "ed t = %s "
        "(d\xc4\x9b" "len\xc3\xad)",
        "%s je \xc4\x8d\xc3\xa1st k\xc5\x99ivky %s za t = %s "
        "(d\xc4\x9b" "len\xc3\xad)",
        "%s je k\xc5\x99ivka %s se stupn\xc4\x9bm "
        "zv\xc3\xbd\xc5\xa1" "en\xc3\xbdm "
        "z %d na %d",
        "%s je k\xc5\x99ivka %s po vlo\xc5\xbe" "en\xc3\xad uzlu u = %s",
        "%s je ekvidistanta k\xc5\x99ivky %s ve vzd\xc3\xa1lenosti %s",
        "K\xc5\x99ivky %s a\xc5\xbe %s jsou ekvidistantou k\xc5\x99ivky %s "
        "ve vzd\xc3\xa1lenosti %s",
        " a jej\xc3\xad ekvidistanta ve vzd\xc3\xa1lenosti %s",
        "Pohled z azimutu %s\xc2\xb0 a elevace %s\xc2\xb0 "
        "(rovnob\xc4\x9b\xc5\xbe" "n\xc3\xa9 prom\xc3\xadt\xc3\xa1n\xc3\xad).",
        "Pohled z azimutu %s\xc2\xb0 a elevace %s\xc2\xb0 "
        "v perspektiv\xc4\x9b "
        "ze vzd\xc3\xa1lenosti %s.",
        "B-splajnov\xc3\xa9 b\xc3\xa1zov\xc3\xa9 funkce stupn\xc4\x9b %d "
        "nad uzly %s",
        "B-splajnov\xc3\xa9 b\xc3\xa1zov\xc3\xa9 funkce stupn\xc4\x9b %d",
        "graf funkce", "grafy funkc\xc3\xad (%s)",
        "Dal\xc5\xa1\xc3\xad popisky: ",
        "Pr\xc3\xa1zdn\xc3\xbd obr\xc3\xa1zek.",
        "Kresba bod\xc5\xaf a \xc4\x8d" "ar.",
        " (%s\xc3\x97)",
    },
};

/* The index of lang's table: its primary tag (before '-' or '_'),
** compared without case; -1 when none. */
static int
find(const char *lang)
{
    size_t n, i;
    if (lang == NULL)
        return -1;
    n = strcspn(lang, "-_");
    for (i = 0; i < sizeof langs / sizeof langs[0]; i++) {
        const char *c = langs[i].code;
        size_t k;
        if (strlen(c) != n)
            continue;
        for (k = 0; k < n; k++)
            if ((lang[k] | 0x20) != c[k])
                break;
        if (k == n)
            return (int)i;
    }
    return -1;
}

const cf__desc_lang_t *
cf__desc_lang(const char *lang)
{
    int i = find(lang);
    return &langs[i < 0 ? 0 : i];
}

int
cf__desc_lang_known(const char *lang)
{
    return find(lang) >= 0;
}
