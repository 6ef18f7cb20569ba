/*
** The glyph table of a course page (render/labels/font-table.c): fonts for
** labels (render/labels/font.h) from the glyph data the tool writes at
** export time (render/output/label-glyphs.c), in plain C.
*/
#ifndef CURVEFIG_RENDER_FONT_TABLE_H
#define CURVEFIG_RENDER_FONT_TABLE_H

#include <stddef.h>

#include "font.h"

typedef struct cf__font_table cf__font_table_t;

/* An empty table (NULL: out of memory); labels set in it have no glyphs
** until data is loaded. */
cf__font_table_t *cf__font_table_create(void);
void cf__font_table_destroy(cf__font_table_t *t);
/* Replace the table's data by data[0..len-1]; 0, or -1 with *bad_line
** the line that is not glyph data (0: out of memory); the table is then
** empty. */
int cf__font_table_load(cf__font_table_t *t, const char *data, size_t len,
                        int *bad_line);
/* The fonts of t (self = t), for labels. */
cf__fonts_t cf__font_table_fonts(cf__font_table_t *t);

#endif
