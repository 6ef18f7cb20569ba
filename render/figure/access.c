/*
** A figure's alt text, description and language (curvefig/access.h).
*/
#include <string.h>

#include "curvefig/access.h"
#include "describe-lang.h"
#include "describe.h"
#include "model.h"

static char *
copy(const char *s)
{
    size_t n = strlen(s) + 1;
    char *c = cf_malloc(n);
    if (c != NULL)
        memcpy(c, s, n);
    return c;
}

static cf_status_t
set(cf_figure_t *fig, char **dst, const char *src, const char *what)
{
    char *c = NULL;
    CF__FIG_CHECK(fig);
    if (src != NULL && (c = copy(src)) == NULL)
        return cf__fig_nomem(fig, what);
    cf_free(*dst);
    *dst = c;
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_set_alt(cf_figure_t *fig, const char *alt)
{
    CF__FIG_CHECK(fig);
    if (alt != NULL && alt[0] == '\0')
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "alt is empty: give the figure's meaning in a "
                           "sentence");
    return set(fig, &fig->alt, alt, "the alt text");
}

cf_status_t
cf_figure_set_description(cf_figure_t *fig, const char *text)
{
    CF__FIG_CHECK(fig);
    return set(fig, &fig->description, text, "the description");
}

/* A BCP 47 tag as far as the outputs need: 2-3 letters, then subtags of
** 1-8 letters or digits after '-'. */
static bool
lang_ok(const char *s)
{
    size_t n = strlen(s), run = 0, i;
    if (n < 2 || n > 35)
        return false;
    for (i = 0; i < n && s[i] != '-'; i++)
        if (!((s[i] >= 'a' && s[i] <= 'z') || (s[i] >= 'A' && s[i] <= 'Z')))
            return false;
    if (i < 2 || i > 3)
        return false;
    for (; i < n; i++) {
        char c = s[i];
        if (c == '-') {
            if (i > 0 && s[i - 1] == '-')
                return false;
            run = 0;
            continue;
        }
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')
              || (c >= '0' && c <= '9')) || ++run > 8)
            return false;
    }
    return s[n - 1] != '-';
}

cf_status_t
cf_figure_set_lang(cf_figure_t *fig, const char *lang)
{
    CF__FIG_CHECK(fig);
    if (lang != NULL && !lang_ok(lang))
        return cf_diag_set(&fig->err, CF_STATUS_INVALID_ARG, -1,
                           "lang \"%s\" is not a language tag (give one "
                           "such as \"en\", \"cs\" or \"cs-CZ\")", lang);
    return set(fig, &fig->lang, lang, "the language");
}

const char *
cf_figure_get_lang(const cf_figure_t *fig)
{
    return fig != NULL && fig->lang != NULL ? fig->lang : "en";
}

const char *
cf_figure_description_lang(const cf_figure_t *fig)
{
    return cf__desc_lang(fig != NULL ? fig->lang : NULL)->code;
}

cf_status_t
cf_figure_alt_text(cf_figure_t *fig, char **out)
{
    const char *s;
    if (out == NULL)
        return CF_STATUS_INVALID_ARG;
    *out = NULL;
    CF__FIG_CHECK(fig);
    s = fig->alt != NULL ? fig->alt
        : fig->caption != NULL && fig->caption[0] != '\0' ? fig->caption
                                                          : NULL;
    if (s == NULL)
        return cf__figure_describe(fig, true, out);
    if ((*out = copy(s)) == NULL)
        return cf__fig_nomem(fig, "the alt text");
    return CF_STATUS_OK;
}

cf_status_t
cf_figure_description(cf_figure_t *fig, char **out)
{
    if (out == NULL)
        return CF_STATUS_INVALID_ARG;
    *out = NULL;
    CF__FIG_CHECK(fig);
    if (fig->description == NULL || fig->description[0] == '\0')
        return CF_STATUS_OK;
    if (strcmp(fig->description, "auto") == 0)
        return cf__figure_describe(fig, false, out);
    if ((*out = copy(fig->description)) == NULL)
        return cf__fig_nomem(fig, "the description");
    return CF_STATUS_OK;
}
