/*
** The entry points of the WebAssembly module of a course page (render/
** web/wasm.js loads it; docs/interactive.md, "Design"): the glyph data
** of the page, then one run of the figure script with the reader's values
** after another, each answered with the JSON of cf_interactive_run
** (render/lua/interactive.h), the same text the live server sends.
*/
#include <stdlib.h>
#include <string.h>

#include "glyphs.h"
#include "interactive.h"

#define EXPORT(name) __attribute__((export_name(#name), used))

static char *json;
static size_t json_len;

/* Load the page's glyph data (data[0..len-1]); 0, or the number of the
** first line that is not glyph data (-1: out of memory). */
EXPORT(cf_wasm_glyphs) int
cf_wasm_glyphs(const char *data, size_t len)
{
    int line = 0;
    if (cf__glyphs_load(data, len, &line) == 0)
        return 0;
    return line > 0 ? line : -1;
}

/* Run the script code (its file name: name) with the values (JSON, NUL-
** terminated; NULL or "": the defaults); the JSON answer is
** cf_wasm_json() (cf_wasm_json_len() bytes) until the next run.  0, or
** 1 when memory ran out (no answer). */
EXPORT(cf_wasm_run) int
cf_wasm_run(const char *code, const char *name, const char *values)
{
    size_t n = values != NULL ? strlen(values) : 0;
    free(json);
    json = NULL;
    json_len = 0;
    if (cf_interactive_run(code, name, n > 0 ? values : NULL, n, NULL, stdout,
                           &json, &json_len) == CF_STATUS_NO_MEMORY
        || json == NULL)
        return 1;
    return 0;
}

EXPORT(cf_wasm_json) const char *
cf_wasm_json(void)
{
    return json != NULL ? json : "";
}

EXPORT(cf_wasm_json_len) size_t
cf_wasm_json_len(void)
{
    return json_len;
}
