/*
** curvefig check SCRIPT [--json] [--min-de N]: the colours of every
** figure of a script that a colour vision deficiency or a greyscale print
** makes hard to tell apart (the library's report, colour-check.h; docs/
** accessibility.md).  A line per clash on stderr naming the figure, the
** vision, the two elements and their colours, printed from the report,
** and with --json the checks as one JSON document on stdout (each
** figure's the JSON of cf_figure_colour_check, written from the same
** report): {"script": ..., "figures": [{"name":
** ..., "threshold": ..., "paints": ..., "clashes": [...]}]}.  Exit 0 when
** no colours clash, 1 when some do (or the check failed).
*/
#include <stdio.h>
#include <stdlib.h>

#include "colour-check.h"
#include "curvefig/figure.h"
#include "script.h"
#include "tool.h"

/* One line per clash of the report. */
static void
print_clashes(const char *script, const char *fig,
              const cf__colour_report_t *r)
{
    for (size_t k = 0; k < r->count; k++) {
        const cf__colour_clash_t *c = &r->clashes[k];
        fprintf(stderr, "curvefig: %s: figure '%s': under %s the %s of "
                "element %zu (%s, #%06x) and the %s of element %zu (%s, "
                "#%06x) are %.2f apart (CIEDE2000; %.2f in normal vision)\n",
                script, fig, cf__vision_name(c->vision), c->paint,
                c->a.number, c->a.element, c->a.rgb, c->paint, c->b.number,
                c->b.element, c->b.rgb, c->de, c->normal_de);
    }
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
        cf__colour_report_t r;
        cf_diag_t diag;
        cf_status_t st = cf__colour_report(fig, min_de, &r, &diag);
        if (st == CF_STATUS_OK && json)
            st = cf__colour_report_json(&r, &text, &size, &diag);
        if (st != CF_STATUS_OK) {
            fprintf(stderr, "curvefig: %s: figure '%s': %s\n", script, name,
                    diag.msg);
            cf__colour_report_fini(&r);
            failed = true;
            continue;
        }
        if (json)
            printf("%s\n{\"name\": \"%s\", %s", i > 0 ? "," : "", name,
                   text + 1);
        print_clashes(script, name, &r);
        clashes += r.count;
        cf_free(text);
        cf__colour_report_fini(&r);
    }
    if (json)
        printf("]}\n");
    if (clashes == 0 && !failed)
        fprintf(stderr, "curvefig: %s: no colours clash (CIEDE2000 >= %g "
                "under protanopia, deuteranopia, tritanopia and in "
                "greyscale)\n", script, min_de);
    return clashes > 0 || failed ? 1 : 0;
}
