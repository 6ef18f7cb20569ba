/*
** Fuzz target: arbitrary text as a figure script, through the entry point
** the tool uses (cf_script_create + cf_script_run_string), in the sandbox
** with small limits (16 MiB, 2 million instructions) so that endless
** loops and memory bombs end quickly.  16 MiB also stops endless
** recursion by memory before Lua's "stack overflow" error, whose
** traceback takes minutes at depth 200000 (an open finding, as is the
** next one).  Inputs that mention __gc are skipped: a finaliser runs with
** Lua's hooks off, so an endless loop in one escapes the instruction
** limit and only the tool's wall-clock watchdog stops it.  A script either runs or fails with
** a message; the figures it defined are then rendered in memory (at
** most 2), each once, to SVG or to PGF (a whole pgfpicture, or an error)
** by the parity of its index plus the input's size, so that both
** backends are checked and an execution pays for one layout a figure:
** the layout (label placement above all) costs a hundred times what
** the backends do.  Every other pair of sizes renders the figures as
** drafts (cf_figure_set_draft, what an interactive page's drag asks
** for: surfaces made once and reused by the layout's later passes).
** What the script prints goes to /dev/null.
*/
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "curvefig/figure.h"
#include "fuzz-check.h"
#include "script.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAX_SCRIPT 16384

static FILE *sink;

/* One figure in one format: it renders, or fails saying why; a PGF
** rendering is a whole pgfpicture. */
static void
render_one(cf_figure_t *fig, const char *name, cf_format_t format,
           bool draft)
{
    static const char end[] = "\\end{pgfpicture}%\n";
    unsigned char *out = NULL;
    size_t outlen = 0;
    cf_diag_t diag;
    cf_status_t st;
    FZ_CHECK(fig != NULL && name != NULL, "figure in range");
    FZ_CHECK(cf_figure_set_draft(fig, draft) == CF_STATUS_OK, "set_draft");
    cf_diag_clear(&diag);
    st = cf_figure_render(fig, format, NULL, &out, &outlen, &diag);
    fz_check_status(st, &diag, "figure_render");
    FZ_CHECK(st != CF_STATUS_OK || (out != NULL && outlen > 0),
             "rendered something");
    if (format == CF_FORMAT_PGF)
        FZ_CHECK(st != CF_STATUS_OK
                     || (outlen > sizeof end
                         && memcmp(out + outlen - (sizeof end - 1), end,
                                   sizeof end - 1) == 0),
                 "a whole pgfpicture");
    cf_free(out);
}

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    cf_script_limits_t lim = { (size_t)16 << 20, 2000000ull };
    cf_script_t *s = NULL;
    cf_diag_t diag;
    cf_status_t st;
    char *code;
    size_t len = size < MAX_SCRIPT ? size : MAX_SCRIPT, i, n;

    if (sink == NULL) {
        sink = fopen("/dev/null", "w");
        FZ_CHECK(sink != NULL, "open /dev/null");
    }
    code = malloc(len + 1);
    FZ_CHECK(code != NULL, "malloc");
    memcpy(code, data, len);
    code[len] = '\0';
    if (strstr(code, "__gc") != NULL) {
        free(code);
        return 0;
    }

    cf_diag_clear(&diag);
    st = cf_script_create(&lim, sink, &s, &diag);
    FZ_CHECK(st == CF_STATUS_OK, diag.msg);
    st = cf_script_run_string(s, code, "fuzz.lua");
    fz_check_status(st, NULL, "script_run_string");
    if (st != CF_STATUS_OK) {
        FZ_CHECK(cf_script_error(s)[0] != '\0', "a failed script says why");
    } else {
        n = cf_script_figure_count(s);
        for (i = 0; i < n && i < 2; i++)
            render_one(cf_script_figure(s, i), cf_script_figure_name(s, i),
                       (i + size) % 2 == 0 ? CF_FORMAT_SVG : CF_FORMAT_PGF,
                       (size / 2) % 2 == 1);
    }
    cf_script_destroy(s);
    free(code);
    return 0;
}
