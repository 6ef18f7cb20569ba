/*
** Accessible figures (library curvefig-render): a figure's alt text, its
** long description (written by hand, or "auto": from what the figure
** shows) and its language.  Every output carries them: SVG <title> and
** <desc>, a tagged PDF's Figure /Alt and /Lang, PS/EPS DSC comments, a
** PGF comment, the course pages' figure and description
** (docs/accessibility.md).
*/
#ifndef CURVEFIG_ACCESS_H
#define CURVEFIG_ACCESS_H

#include "curvefig/figure.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The alt text: a short text alternative (a sentence or two).  NULL
** unsets it; "" is refused (INVALID_ARG): a figure that means nothing is
** better not drawn. */
CF_API cf_status_t cf_figure_set_alt(cf_figure_t *fig, const char *alt);

/* The long description: text, or "auto" for one written from the figure's
** curves (kinds, degrees, control points named by their labels, weights,
** knots), the constructions drawn on them (de Casteljau at t, de Boor at
** u), subdivisions, degree elevations, knot insertions, its surfaces and
** view, and its other labels.  NULL or "" unsets it (a figure of the
** Lua language has "auto" unless its script says otherwise). */
CF_API cf_status_t cf_figure_set_description(cf_figure_t *fig,
                                             const char *text);

/* The language of the figure's text, a BCP 47 tag ("en", "cs", "cs-CZ":
** letters, digits and '-', 2 to 35 bytes, starting with 2 or 3 letters).
** The automatic description is written in Czech for "cs" and in English
** for every other language.  NULL unsets it (English). */
CF_API cf_status_t cf_figure_set_lang(cf_figure_t *fig, const char *lang);

/* The language set, or "en". */
CF_API const char *cf_figure_get_lang(const cf_figure_t *fig);

/* The language the automatic description is written in: "cs" or "en". */
CF_API const char *cf_figure_description_lang(const cf_figure_t *fig);

/* The alt text: the one set, else the caption (when not empty), else the
** first sentence of the automatic description.  *out from cf_malloc,
** released with cf_free. */
CF_API cf_status_t cf_figure_alt_text(cf_figure_t *fig, char **out);

/* The long description (the automatic one written now), or *out = NULL
** when none was set.  *out from cf_malloc, released with cf_free. */
CF_API cf_status_t cf_figure_description(cf_figure_t *fig, char **out);

#ifdef __cplusplus
}
#endif

#endif
