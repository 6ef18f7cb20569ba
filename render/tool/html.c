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

#include <limits.h>
#include <unistd.h>

#include "curvefig/access.h"
#include "curvefig/figure.h"
#include "curvefig/output.h"
#include "helpers.h"
#include "html.h"
#include "tool.h"
#include "web-html.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

#define WASM_NAME "curvefig.wasm"
#define WASM_MAX ((size_t)64 << 20)

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

/* bytes[0..n-1] in base64. */
static void
put_base64(FILE *f, const unsigned char *b, size_t n)
{
    static const char digit[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    size_t i;
    for (i = 0; i + 2 < n; i += 3) {
        unsigned long v = (unsigned long)b[i] << 16 | (unsigned)b[i + 1] << 8
                          | b[i + 2];
        fputc(digit[v >> 18], f);
        fputc(digit[v >> 12 & 63], f);
        fputc(digit[v >> 6 & 63], f);
        fputc(digit[v & 63], f);
    }
    if (i < n) {
        unsigned long v = (unsigned long)b[i] << 16
                          | (i + 1 < n ? (unsigned)b[i + 1] << 8 : 0u);
        fputc(digit[v >> 18], f);
        fputc(digit[v >> 12 & 63], f);
        fputc(i + 1 < n ? digit[v >> 6 & 63] : '=', f);
        fputc('=', f);
    }
}

/* The WebAssembly module (render/web): the file module, or (NULL) the one
** built or installed beside the tool; NULL with the reason in err when it
** is not there. */
static unsigned char *
read_module(const char *module, size_t *n, char *err, size_t errsize)
{
    char path[PATH_MAX], where[3 * PATH_MAX];
    const char *why;
    unsigned char *b;
    if (module != NULL) {
        if (strlen(module) >= sizeof path) {
            snprintf(err, errsize, "the WebAssembly module's path is too "
                     "long");
            return NULL;
        }
        strcpy(path, module);
    } else if (!cf__tool_find_file(WASM_NAME, "../web", R_OK, path,
                                   sizeof path, where, sizeof where)) {
        snprintf(err, errsize,
                 "-f html needs the WebAssembly module %s, which is not "
                 "installed with this curvefig (looked in %s): build it "
                 "(emscripten and Lua 5.4's source: as root, apt-get "
                 "install emscripten && render/web/lua-source.sh; then "
                 "meson setup --reconfigure and ninja) or install curvefig "
                 "again", WASM_NAME, where);
        return NULL;
    }
    b = (unsigned char *)cf__tool_read_file(path, WASM_MAX, n, &why);
    if (b == NULL)
        snprintf(err, errsize, "cannot read the WebAssembly module %s: %s",
                 path, why);
    return b;
}

int
cf__tool_write_html(const cf_script_t *s, size_t i, const char *script_path,
                    const cf__tool_limits *limits, const char *path,
                    const char *module, char *err, size_t errsize)
{
    cf_figure_t *fig = cf_script_figure(s, i);
    const char *name = cf_script_figure_name(s, i);
    const char *caption = cf_script_figure_caption(s, i);
    const char *base = strrchr(script_path, '/');
    char *code, *glyphs = NULL;
    unsigned char *wasm;
    size_t code_len, glyphs_len, wasm_len;
    const char *why;
    cf_diag_t d;
    cf__tool_out out;
    FILE *f;
    wasm = read_module(module, &wasm_len, err, errsize);
    if (wasm == NULL)
        return -1;
    code = cf__tool_read_file(script_path, (size_t)64 << 20, &code_len,
                              &why);
    if (code == NULL) {
        snprintf(err, errsize, "cannot read %s: %s", script_path, why);
        free(wasm);
        return -1;
    }
    if (cf_figures_glyph_data(&fig, 1, &glyphs, &glyphs_len, &d)
        != CF_STATUS_OK) {
        snprintf(err, errsize, "the glyphs of its labels: %s", d.msg);
        free(code);
        free(wasm);
        return -1;
    }
    if (cf__tool_open_atomic(&out, path) != 0) {
        snprintf(err, errsize, "cannot write %s: %s", path, strerror(errno));
        free(code);
        free(wasm);
        cf_free(glyphs);
        return -1;
    }
    f = out.f;
    /* the page in the figure's language (a tag of letters, digits and
    ** '-': cf_figure_set_lang checked it) */
    fprintf(f, "<!DOCTYPE html>\n<html lang=\"%s\">", cf_figure_get_lang(fig));
    fputs("<head><meta charset=\"utf-8\">\n"
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
    put_lines(f, html_page_rotate_js);
    put_lines(f, html_page_keys_js);
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
    put_base64(f, wasm, wasm_len);
    fputs("\"}));\n</script>\n</body></html>\n", f);
    free(code);
    free(wasm);
    cf_free(glyphs);
    if (cf__tool_close_atomic(&out) != 0) {
        snprintf(err, errsize, "cannot write %s: %s", path, strerror(errno));
        return -1;
    }
    return 0;
}
