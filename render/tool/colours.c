/*
** curvefig check SCRIPT [--json] [--min-de N]: the colours of every
** figure of a script that a colour vision deficiency or a greyscale print
** makes hard to tell apart (cf_figure_colour_check, docs/
** accessibility.md).  A line per clash on stderr naming the figure, the
** vision, the two elements and their colours, or with --json the checks
** as one JSON document on stdout: {"script": ..., "figures": [{"name":
** ..., "threshold": ..., "paints": ..., "clashes": [...]}]}.  Exit 0 when
** no colours clash, 1 when some do (or the check failed).
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "curvefig/figure.h"
#include "script.h"
#include "tool.h"

/* The value of "key": "..." or "key": number after p (NULL: not found);
** the text up to its end into out. */
static const char *
field(const char *p, const char *key, char *out, size_t n)
{
    char pat[40];
    const char *s, *e;
    snprintf(pat, sizeof pat, "\"%s\": ", key);
    s = strstr(p, pat);
    if (s == NULL)
        return NULL;
    s += strlen(pat);
    if (*s == '"')
        s++;
    for (e = s; *e != '\0' && *e != '"' && *e != ',' && *e != '}'; e++)
        ;
    snprintf(out, n, "%.*s", (int)(e - s), s);
    return e;
}

/* One line per clash of the JSON of cf_figure_colour_check. */
static size_t
print_clashes(const char *script, const char *fig, const char *json)
{
    const char *p = strstr(json, "\"clashes\": [");
    size_t n = 0;
    while (p != NULL && (p = strstr(p, "{\"vision\"")) != NULL) {
        char vision[32], paint[16], de[32], normal[32];
        char ea[32], ia[16], ca[16], eb[32], ib[16], cb[16];
        const char *q = p;
        q = field(q, "vision", vision, sizeof vision);
        q = q ? field(q, "paint", paint, sizeof paint) : NULL;
        q = q ? field(q, "de", de, sizeof de) : NULL;
        q = q ? field(q, "normal_de", normal, sizeof normal) : NULL;
        q = q ? field(q, "element", ea, sizeof ea) : NULL;
        q = q ? field(q, "index", ia, sizeof ia) : NULL;
        q = q ? field(q, "color", ca, sizeof ca) : NULL;
        q = q ? field(q, "element", eb, sizeof eb) : NULL;
        q = q ? field(q, "index", ib, sizeof ib) : NULL;
        q = q ? field(q, "color", cb, sizeof cb) : NULL;
        if (q == NULL)
            break;
        fprintf(stderr, "curvefig: %s: figure '%s': under %s the %s of "
                "element %s (%s, %s) and the %s of element %s (%s, %s) are "
                "%s apart (CIEDE2000; %s in normal vision)\n", script, fig,
                vision, paint, ia, ea, ca, paint, ib, eb, cb, de, normal);
        n++;
        p = q;
    }
    return n;
}

int
cf__tool_colours(const cf_script_t *s, const char *script, double min_de,
                 bool json)
{
    size_t clashes = 0;
    bool failed = false;
    if (json) {
        printf("{\"script\": \"");
        for (const char *c = script; *c != '\0'; c++)
            printf(*c == '"' || *c == '\\' ? "\\%c" : "%c", *c);
        printf("\", \"figures\": [");
    }
    for (size_t i = 0; i < cf_script_figure_count(s); i++) {
        cf_figure_t *fig = cf_script_figure(s, i);
        const char *name = cf_script_figure_name(s, i);
        char *text = NULL;
        size_t size;
        cf_diag_t diag;
        if (cf_figure_colour_check(fig, min_de, &text, &size, &diag)
            != CF_STATUS_OK) {
            fprintf(stderr, "curvefig: %s: figure '%s': %s\n", script, name,
                    diag.msg);
            failed = true;
            continue;
        }
        if (json)
            printf("%s\n{\"name\": \"%s\", %s", i > 0 ? "," : "", name,
                   strchr(text, '{') + 1);
        clashes += print_clashes(script, name, text);
        cf_free(text);
    }
    if (json)
        printf("]}\n");
    if (clashes == 0 && !failed)
        fprintf(stderr, "curvefig: %s: no colours clash (CIEDE2000 >= %g "
                "under protanopia, deuteranopia, tritanopia and in "
                "greyscale)\n", script, min_de);
    return clashes > 0 || failed ? 1 : 0;
}
