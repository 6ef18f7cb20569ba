/*
** The entry points of the WebAssembly module of a course page (render/
** web/wasm.js loads it; docs/interactive.md, "Design"): the glyph data
** of the page, then one run of the figure script with the reader's values
** after another, each answered with the JSON of cf_interactive_run
** (render/lua/interactive.h), the same text the live server sends.
*/
#include <stdlib.h>
#include <string.h>

#include "font-table.h"
#include "fonts-default.h"
#include "interactive.h"

#define EXPORT(name) __attribute__((export_name(#name), used))

/* The module is one page: its answer and its glyph table, which every
** label is set in (render/labels/font-table.c). */
static char *json;
static size_t json_len;
static cf__font_table_t *table;
static cf__fonts_t fonts;

const cf__fonts_t *
cf__fonts_default(void)
{
    if (table == NULL) {
        table = cf__font_table_create();
        fonts = cf__font_table_fonts(table);
    }
    return &fonts;
}

/* Load the page's glyph data (data[0..len-1]); 0, or the number of the
** first line that is not glyph data (-1: out of memory). */
EXPORT(cf_wasm_glyphs) int
cf_wasm_glyphs(const char *data, size_t len)
{
    int line = 0;
    if (cf__fonts_default()->self == NULL)
        return -1;
    if (cf__font_table_load(table, data, len, &line) == 0)
        return 0;
    return line > 0 ? line : -1;
}

/* Run the script code (its file name: name) with the values (JSON, NUL-
** terminated; NULL or "": the defaults) under the sandbox's limits
** (memory in MiB and instructions; 0, or left out by the caller: the
** defaults of script.h); the JSON answer is cf_wasm_json()
** (cf_wasm_json_len() bytes) until the next run.  0, or 1 when memory ran
** out (no answer). */
EXPORT(cf_wasm_run) int
cf_wasm_run(const char *code, const char *name, const char *values,
            double memory_mib, double instructions)
{
    size_t n = values != NULL ? strlen(values) : 0;
    cf_script_limits_t limits = { 0, 0 };
    if (memory_mib >= 1 && memory_mib <= 4096)
        limits.max_memory = (size_t)memory_mib << 20;
    if (instructions >= 1e4 && instructions <= 1e15)
        limits.max_instructions = (unsigned long long)instructions;
    free(json);
    json = NULL;
    json_len = 0;
    if (cf_interactive_run(code, name, n > 0 ? values : NULL, n, &limits,
                           stdout, &json, &json_len) == CF_STATUS_NO_MEMORY
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
