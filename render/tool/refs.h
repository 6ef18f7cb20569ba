/*
** The reference images `curvefig test --update` writes (refs.c).
*/
#ifndef CURVEFIG_TOOL_REFS_H
#define CURVEFIG_TOOL_REFS_H

#include <stddef.h>

#include "image-io.h"
#include "imgcmp.h"

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
                                       cf__image *png,
                                       const char *ref_path,
                                       const cf__imgcmp_options *opt,
                                       double dpi, char *verdict,
                                       size_t size);

#endif
