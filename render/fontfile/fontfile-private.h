/*
** The font subsetter on bytes in memory (render/fontfile/fontfile.c), for
** the tests and the fuzz target: cf__fontfile_subset does the same on the
** bytes of a mapped file.
*/
#ifndef CURVEFIG_RENDER_FONTFILE_PRIVATE_H
#define CURVEFIG_RENDER_FONTFILE_PRIVATE_H

#include <stddef.h>

#include "fontfile.h"

/* cf__fontfile_subset of the font data[0..len) (name_for_errors begins
** each message of why). */
int cf__fontfile_subset_mem(const unsigned char *data, size_t len,
                            const char *name_for_errors, unsigned index,
                            const unsigned *gids, size_t n,
                            cf__fontfile_subset_t *out, char *why,
                            size_t why_cap);

#endif
