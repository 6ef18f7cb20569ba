/*
** The HTML report of `curvefig test`; see report.h.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "report.h"
#include "tool.h"

void
cf__tool_failure_free(cf__tool_failure *f)
{
    free(f->figure);
    free(f->script);
    free(f->what);
    free(f->verdict);
    free(f->expected);
    free(f->actual);
    free(f->diff);
    memset(f, 0, sizeof *f);
}

static const char report_head[] =
    "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
    "<title>curvefig test report</title>\n<style>\n"
    "body{font-family:sans-serif;margin:2em auto;max-width:90em;"
    "padding:0 1em}\n"
    "section{border-top:1px solid #ccc;margin-top:1.5em}\n"
    ".row{display:flex;gap:1em;flex-wrap:wrap}\n"
    "figure{margin:0;flex:1 1 20em}\n"
    "figure img{max-width:100%;border:1px solid #ddd;"
    "image-rendering:pixelated}\n"
    "code{background:#f4f4f4}\n.ok{color:#070}\n.fail{color:#b00}\n"
    "</style>\n</head>\n<body>\n<h1>curvefig test report</h1>\n";

static void
text(FILE *f, const char *s)
{
    cf__tool_put_html(f, s, strlen(s));
}

static void
image(FILE *f, const char *caption, const char *src)
{
    fputs("<figure><figcaption>", f);
    text(f, caption);
    fputs("</figcaption>", f);
    if (src != NULL) {
        fputs("<a href=\"", f);
        text(f, src);
        fputs("\"><img src=\"", f);
        text(f, src);
        fputs("\" alt=\"", f);
        text(f, caption);
        fputs("\"></a>", f);
    } else {
        fputs("<p>(none)</p>", f);
    }
    fputs("</figure>\n", f);
}

int
cf__tool_report_write(const char *path, const char *summary,
                      const cf__tool_failure *fails, size_t count)
{
    cf__tool_out out;
    FILE *f;
    if (cf__tool_open_atomic(&out, path) != 0)
        return -1;
    f = out.f;
    fputs(report_head, f);
    fprintf(f, "<p class=\"%s\">", count > 0 ? "fail" : "ok");
    text(f, summary);
    fputs("</p>\n", f);
    if (count > 0)
        fputs("<p>Diff images: the expected image faded; red where the "
              "images differ, yellow where they differ by anti-aliasing "
              "only.</p>\n", f);
    for (size_t i = 0; i < count; i++) {
        const cf__tool_failure *x = &fails[i];
        fputs("<section>\n<h2>", f);
        text(f, x->figure);
        fputs("</h2>\n<p><code>", f);
        text(f, x->script);
        fputs("</code>: ", f);
        text(f, x->what);
        fputs("</p>\n<p class=\"fail\">", f);
        text(f, x->verdict);
        fputs("</p>\n<div class=\"row\">\n", f);
        image(f, "expected", x->expected);
        image(f, "actual", x->actual);
        image(f, "diff", x->diff);
        fputs("</div>\n</section>\n", f);
    }
    fputs("</body>\n</html>\n", f);
    return cf__tool_close_atomic(&out);
}
