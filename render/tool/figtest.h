/*
** The parts of `curvefig test` (figtest.c): the scripts its operands name
** (scripts.c) and the reference images it writes (refs.c).
*/
#ifndef CURVEFIG_TOOL_FIGTEST_H
#define CURVEFIG_TOOL_FIGTEST_H

#include <cairo.h>
#include <stdbool.h>
#include <stddef.h>

#include "imgcmp.h"

typedef struct cf__tool_scripts {
    char **path;
    size_t count, cap;
    bool only_dirs;      /* every operand so far was a directory */
} cf__tool_scripts;

/* Add an operand: a script, or a directory standing for its *.lua files
** in name order.  -1 with a message printed when it cannot be read or a
** directory holds no script. */
int cf__tool_scripts_add(cf__tool_scripts *s, const char *operand);
void cf__tool_scripts_free(cf__tool_scripts *s);

typedef enum cf__tool_ref_state {
    CF__TOOL_REF_UNCHANGED,  /* the same pixels: the file is left alone */
    CF__TOOL_REF_CHANGED,
    CF__TOOL_REF_ADDED,
    CF__TOOL_REF_FAILED      /* it could not be written (message printed) */
} cf__tool_ref_state;

/* Make ref_path a copy of the new PNG png_path (its pixels png), through
** a temporary name, unless the old reference has the same pixels; what
** changed, in words, goes into verdict (opt: the comparator's options,
** dpi for reading the old reference). */
cf__tool_ref_state cf__tool_ref_update(const char *png_path,
                                       cairo_surface_t *png,
                                       const char *ref_path,
                                       const cf__imgcmp_options *opt,
                                       double dpi, char *verdict,
                                       size_t size);

#endif
