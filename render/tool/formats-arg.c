/*
** The format list of -f (formats-arg.h).
*/
#include <string.h>

#include "animate.h"
#include "curvefig/output.h"
#include "formats-arg.h"
#include "helpers.h"
#include "html.h"

/* The nearest format to the unknown one in list (NULL: none near). */
const char *
cf__tool_nearest_format(const char *list)
{
    static const char *const formats[] = { "svg", "pdf", "png", "ps", "eps",
                                           "pgf", "html", "gif", "apng",
                                           "mp4", "webm", "all" };
    char name[64];
    const char *p = list;
    while (*p != '\0') {
        size_t n = strcspn(p, ",");
        cf_format_t f;
        if (n > 0 && n < sizeof name) {
            memcpy(name, p, n);
            name[n] = '\0';
            if (strcmp(name, "all") != 0 && strcmp(name, "html") != 0
                && cf__tool_anim_format(name) == 0
                && cf_format_from_name(name, &f, NULL) != CF_STATUS_OK)
                return cf_nearest_name(name, formats,
                                       sizeof formats / sizeof formats[0]);
        }
        p += n;
        if (*p == ',')
            p++;
    }
    return NULL;
}

int
cf__tool_parse_formats(const char *list, unsigned *out)
{
    char name[16];
    const char *p = list;
    *out = 0;
    while (*p != '\0') {
        const char *e = strchr(p, ',');
        size_t n = e != NULL ? (size_t)(e - p) : strlen(p);
        cf_format_t f;
        if (n == 0 || n >= sizeof name)
            return -1;
        memcpy(name, p, n);
        name[n] = '\0';
        if (strcmp(name, "all") == 0)
            *out |= (1u << CF_FORMAT_LAST_) - 1;
        else if (strcmp(name, "html") == 0)
            *out |= CF__TOOL_HTML_BIT;
        else if (cf__tool_anim_format(name) != 0)
            *out |= cf__tool_anim_format(name);
        else if (cf_format_from_name(name, &f, NULL) != CF_STATUS_OK)
            return -1;
        else
            *out |= CF_FORMAT_BIT(f);
        p += n;
        if (*p == ',')
            p++;
    }
    return *out != 0 ? 0 : -1;
}
