/*
** The course page of a figure (render/tool/html.h): one HTML file with
** everything inline, and a Content-Security-Policy that lets it load
** nothing at all (default-src 'none'; inline script and style, the
** module compiled from the page's own bytes).  Values (the script's text,
** the glyph data, the module's base64, the source of the Web Worker that
** runs the module: render/web/worker.js) are JavaScript string literals in
** which "<" is written \u003c, so that no text of theirs ends the script
** element.
*/
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "curvefig/figure.h"
#include "curvefig/output.h"
#include "html.h"
#include "tool.h"
#ifdef CF_TOOL_HAVE_WASM
#include "wasm-b64.h"
#include "web-html.h"

static void
put_lines(FILE *f, const char *const *lines)
{
    for (; *lines != NULL; lines++)
        fputs(*lines, f);
}

/* s as the inside of a JSON string (also a JavaScript one), "<" escaped
** so that no text of it ends the script element. */
static void
put_escaped(FILE *f, const char *s, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c == '"' || c == '\\')
            fprintf(f, "\\%c", c);
        else if (c == '\n')
            fputs("\\n", f);
        else if (c < 0x20 || c == '<' || c == '>' || c == '&')
            fprintf(f, "\\u%04x", c);
        else
            fputc(c, f);
    }
}

static void
put_string(FILE *f, const char *s, size_t n)
{
    fputc('"', f);
    put_escaped(f, s, n);
    fputc('"', f);
}

/* The lines of embedded files as one JSON string. */
static void
put_lines_string(FILE *f, const char *const *a, const char *const *b)
{
    fputc('"', f);
    for (; *a != NULL; a++)
        put_escaped(f, *a, strlen(*a));
    for (; *b != NULL; b++)
        put_escaped(f, *b, strlen(*b));
    fputc('"', f);
}

int
cf__tool_write_html(const cf_script_t *s, size_t i, const char *script_path,
                    const cf__tool_limits *limits, const char *path,
                    char *err, size_t errsize)
{
    cf_figure_t *fig = cf_script_figure(s, i);
    const char *name = cf_script_figure_name(s, i);
    const char *caption = cf_script_figure_caption(s, i);
    const char *base = strrchr(script_path, '/');
    char *code, *glyphs = NULL;
    size_t code_len, glyphs_len;
    const char *why;
    cf_diag_t d;
    cf__tool_out out;
    FILE *f;
    code = cf__tool_read_file(script_path, (size_t)64 << 20, &code_len,
                              &why);
    if (code == NULL) {
        snprintf(err, errsize, "cannot read %s: %s", script_path, why);
        return -1;
    }
    if (cf_figures_glyph_data(&fig, 1, &glyphs, &glyphs_len, &d)
        != CF_STATUS_OK) {
        snprintf(err, errsize, "the glyphs of its labels: %s", d.msg);
        free(code);
        return -1;
    }
    if (cf__tool_open_atomic(&out, path) != 0) {
        snprintf(err, errsize, "cannot write %s: %s", path, strerror(errno));
        free(code);
        cf_free(glyphs);
        return -1;
    }
    f = out.f;
    fputs("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
          "<meta http-equiv=\"Content-Security-Policy\" content=\""
          "default-src 'none'; script-src 'unsafe-inline' "
          "'wasm-unsafe-eval'; style-src 'unsafe-inline'; img-src data:; "
          "worker-src blob:\">\n"
          "<meta name=\"viewport\" content=\"width=device-width\">\n<title>",
          f);
    if (caption == NULL || caption[0] == '\0')
        caption = name;
    cf__tool_put_html(f, caption, strlen(caption));
    fputs("</title>\n<link rel=\"icon\" href=\"data:,\">\n<style>\n", f);
    put_lines(f, html_css);
    fputs("</style>\n</head>\n<body>\n<div id=\"curvefig\"></div>\n"
          "<script>\n", f);
    put_lines(f, html_page_js);
    put_lines(f, html_engine_js);
    fputs("CurvefigPage(document.getElementById('curvefig'), "
          "new CurvefigWasmEngine({\nfigure: ", f);
    put_string(f, name, strlen(name));
    fputs(",\nname: ", f);
    base = base != NULL ? base + 1 : script_path;
    put_string(f, base, strlen(base));
    fputs(",\nscript: ", f);
    put_string(f, code, code_len);
    fputs(",\nglyphs: ", f);
    put_string(f, glyphs, glyphs_len);
    fprintf(f, ",\ntimeout: %g,\nmemory: %g,\ninstructions: %.17g",
            limits->timeout,
            (double)(limits->script.max_memory >> 20),
            (double)limits->script.max_instructions);
    fputs(",\nworker: ", f);
    put_lines_string(f, html_wasm_js, html_worker_js);
    fputs(",\nwasm: \"", f);
    put_lines(f, web_wasm_b64);
    fputs("\"}));\n</script>\n</body></html>\n", f);
    free(code);
    cf_free(glyphs);
    if (cf__tool_close_atomic(&out) != 0) {
        snprintf(err, errsize, "cannot write %s: %s", path, strerror(errno));
        return -1;
    }
    return 0;
}
#else
int
cf__tool_write_html(const cf_script_t *s, size_t i, const char *script_path,
                    const cf__tool_limits *limits, const char *path,
                    char *err, size_t errsize)
{
    (void)s;
    (void)i;
    (void)script_path;
    (void)limits;
    (void)path;
    snprintf(err, errsize,
             "-f html needs the WebAssembly module, which this curvefig "
             "was built without: install emscripten and Lua 5.4's source "
             "(as root: apt-get install emscripten && render/web/"
             "lua-source.sh), then meson setup --reconfigure and rebuild");
    return -1;
}
#endif
