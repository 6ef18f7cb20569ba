/*
** `curvefig render SCRIPT.lua -f html`: one self-contained HTML file a
** figure (render/tool/html.c), in which the sliders and the draggable
** points work with no server and no network: the page (render/web), the
** WebAssembly module of render/web, the script and the glyph data of its
** labels, inline.  docs/interactive.md, "Course pages".
*/
#ifndef CURVEFIG_TOOL_HTML_H
#define CURVEFIG_TOOL_HTML_H

#include <stddef.h>

#include "runlimits.h"
#include "script.h"

/* The `-f` name and its bit beside the cf_format_t bits. */
#define CF__TOOL_HTML_BIT (1u << 30)

/* Write figure i of s (run from the file script_path, with its defaults)
** to path; the page runs the script under limits (a run past
** limits->timeout is stopped in the page).  The page carries the
** WebAssembly module read from the file module, or (module NULL) from
** beside the program, the build tree or the installation.  0, or -1 with
** the reason in err. */
int cf__tool_write_html(const cf_script_t *s, size_t i,
                        const char *script_path,
                        const cf__tool_limits *limits, const char *path,
                        const char *module, char *err, size_t errsize);

#endif
