/*
** The glyph data of a course page in the WebAssembly module (render/wasm/
** pango-lite.c documents the format; render/label-glyphs.c writes it).
*/
#ifndef CURVEFIG_WASM_GLYPHS_H
#define CURVEFIG_WASM_GLYPHS_H

#include <stddef.h>

/* Replace the glyph tables by data[0..len-1]; 0, or -1 with *bad_line the
** line that is not glyph data (or 0: out of memory); the tables are then
** empty. */
int cf__glyphs_load(const char *data, size_t len, int *bad_line);

#endif
