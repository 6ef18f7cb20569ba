/*
** The faces and font sets of the native fonts (render/backends/
** font-faces.c): what pango's fontconfig font map would choose, without
** pango, and under the tool's own configuration without fontconfig
** (render/backends/font-match.h).  One per process, as fontconfig's
** configuration is.
*/
#ifndef CURVEFIG_RENDER_FONT_FACES_H
#define CURVEFIG_RENDER_FONT_FACES_H

#include <stdbool.h>

#include <cairo.h>
#include <hb.h>

#include "font-match.h"
#include "font.h"
#include "shape.h"

/* Where a face came from: a pattern fontconfig prepared for the request,
** or the matcher's face (font-faces.c). */
typedef struct cf__nface_src cf__nface_src_t;

/* A face at a size: a font of pango's font map. */
typedef struct cf__nface {
    cf__nface_src_t *src;
    hb_font_t *hb;                /* pango's HarfBuzz font of it, made at
                                     need (cf__nface_hb) */
    const cf__otface_t *own;      /* the renderer's shaper's face (render/
                                     fontfile/shape.h), NULL when it is
                                     not usable */
    cf__otscale_t own_scale;      /* the scale and slant of hb */
    bool unsupported;             /* variations or features: pango's */
    cairo_scaled_font_t *scaled;  /* made at need */
    int ext_y, ext_height;        /* pango's logical extents of a glyph */
    cf__font_face_t face;
    char key[256];
} cf__nface_t;

typedef struct cf__nfontset cf__nfontset_t;

/* Use the matcher's configuration c (the tool's, render/tool/fonts.c)
** instead of fontconfig's: call before the first font set is asked for;
** c lives as long as the process. */
void cf__nfaces_use_matcher(const cf__fm_config_t *c);

/* Use the matcher's configuration of the font directories dirs[0..n-1]
** accepting the families (render/tool/fonts.c's), read from the fonts'
** metadata cache; false when the matcher declines it or out of memory
** (fontconfig's then). */
bool cf__nfaces_use_dirs(const cf__fm_source_t *dirs, size_t n,
                         const char *const *families, size_t nfamilies);

/* The font set of the description (family list, italic, bold, size in
** CF__FONT_SCALE units, language); NULL when out of memory. */
cf__nfontset_t *cf__nfontset_get(const char *family, bool italic, bool bold,
                                 int size, const char *lang);

/* Its i-th font (pango's order: fontconfig's match, then its sort);
** NULL past the last. */
cf__nface_t *cf__nfontset_font(cf__nfontset_t *set, int i);

/* fontconfig's pattern of a description as the sets make it (the
** request before FcFontSetMatch and FcFontSetSort; for the matcher's
** test), NULL when out of memory. */
struct _FcPattern;
struct _FcPattern *cf__nfaces_pattern(const char *family, bool italic,
                                      bool bold, int size, const char *lang);

/* Whether the face has a glyph for character c. */
bool cf__nface_has_char(const cf__nface_t *f, unsigned c);

/* The face's HarfBuzz font, made at the first call (HarfBuzz is loaded
** then: render/backends/hb-lazy.c); NULL when out of memory. */
hb_font_t *cf__nface_hb(cf__nface_t *f);

/* Whether the face can have its scaled font (its pattern has a pixel
** size), without making it: the layout and the vector writers take the
** glyphs of most faces from their files (font-outlines.h), and only
** drawing through cairo makes it (cf__font_face_t.make_scaled). */
bool cf__nface_scalable(const cf__nface_t *f);

/* The face's scaled font as pango-cairo makes it (NULL: cairo failed). */
cairo_scaled_font_t *cf__nface_scaled(cf__nface_t *f);

/* Serialise the native fonts' use of their caches (and of HarfBuzz's
** buffers): faces and font sets live as long as the process. */
void cf__nfaces_lock(void);
void cf__nfaces_unlock(void);

#endif
