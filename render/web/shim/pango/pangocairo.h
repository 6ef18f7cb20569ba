/*
** The part of pango's API the labels use (render/label.c, label-runs.c),
** for the WebAssembly module: render/wasm/pango-lite.c shapes and draws
** from glyph data measured natively when the page was exported
** (render/label-glyphs.c; docs/interactive.md, "Design").  A text shaped
** then is laid out exactly as pango laid it out; another text of the
** same fonts is composed from its characters' advances (no kerning).
*/
#ifndef CURVEFIG_WASM_PANGOCAIRO_H
#define CURVEFIG_WASM_PANGOCAIRO_H

#include "../cairo.h"

#define PANGO_SCALE 1024
#ifndef FALSE
#define FALSE 0
#define TRUE 1
#endif

typedef int gboolean;
typedef struct _PangoFontMap PangoFontMap;
typedef struct _PangoContext PangoContext;
typedef struct _PangoLayout PangoLayout;
typedef struct _PangoFontDescription PangoFontDescription;

typedef struct {
    int x, y, width, height;
} PangoRectangle;

typedef enum { PANGO_STYLE_NORMAL, PANGO_STYLE_OBLIQUE,
               PANGO_STYLE_ITALIC } PangoStyle;
typedef enum { PANGO_WEIGHT_NORMAL = 400, PANGO_WEIGHT_BOLD = 700 }
    PangoWeight;

PangoFontMap *pango_cairo_font_map_get_default(void);
PangoContext *pango_font_map_create_context(PangoFontMap *fm);
void pango_cairo_context_set_font_options(PangoContext *ctx,
                                          const cairo_font_options_t *o);
void pango_cairo_context_set_resolution(PangoContext *ctx, double dpi);
void pango_context_set_round_glyph_positions(PangoContext *ctx,
                                             gboolean round);

PangoFontDescription *pango_font_description_new(void);
void pango_font_description_free(PangoFontDescription *fd);
void pango_font_description_set_family(PangoFontDescription *fd,
                                       const char *family);
void pango_font_description_set_style(PangoFontDescription *fd,
                                      PangoStyle style);
void pango_font_description_set_weight(PangoFontDescription *fd,
                                       PangoWeight weight);
void pango_font_description_set_absolute_size(PangoFontDescription *fd,
                                              double size);

PangoLayout *pango_layout_new(PangoContext *ctx);
void pango_layout_set_font_description(PangoLayout *l,
                                       const PangoFontDescription *fd);
void pango_layout_set_text(PangoLayout *l, const char *text, int length);
void pango_layout_get_extents(PangoLayout *l, PangoRectangle *ink,
                              PangoRectangle *logical);
int pango_layout_get_baseline(PangoLayout *l);
int pango_layout_get_unknown_glyphs_count(PangoLayout *l);

/* The layout's glyphs at the current point (its top left), filled with
** the source, or added to the path. */
void pango_cairo_show_layout(cairo_t *cr, PangoLayout *l);
void pango_cairo_layout_path(cairo_t *cr, PangoLayout *l);

/* Contexts and layouts are released with it (as GObjects natively). */
void g_object_unref(void *object);

#endif
