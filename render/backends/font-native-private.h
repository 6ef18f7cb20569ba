/*
** What the units of the native fonts share (render/backends/font-native.h:
** font-native.c, font-itemize.c, font-extents.c): a run, its items.
*/
#ifndef CURVEFIG_RENDER_FONT_NATIVE_PRIVATE_H
#define CURVEFIG_RENDER_FONT_NATIVE_PRIVATE_H

#include <stdbool.h>
#include <stddef.h>

#include <hb.h>

#include "font-faces.h"
#include "font-glyphs.h"

/* An item: text[offset, offset + length) in one script and one font, as
** pango's itemiser makes it. */
typedef struct item {
    size_t offset, length;
    cf__nface_t *font;    /* NULL: spaces, filled later */
    int position;         /* the font's place in the set */
    hb_script_t script;
} item_t;

/* A run of the native fonts: its items and glyphs when shaped here, or
** pango's run when handed on. */
typedef struct native_run {
    void *pango;          /* pango's run, when pango shaped it */
    bool native;          /* which one the last shape used */
    bool oom;             /* the last shape ran out of memory */
    cf__font_glyphs_buf_t glyphs;
    cf__otrun_t ot;       /* the renderer's shaper's glyphs of an item */
    item_t *items;
    size_t nitems, cap_items;
} native_run_t;

#endif
