/*
** pango, loaded when a label first needs it (a run the native fonts,
** render/backends/font-native.c, hand to pango), not when the program
** starts.
**
** A figure without labels (a polyline, a curve) never calls pango; yet a
** library linked with pangocairo makes every program that uses it load
** pango, HarfBuzz, GLib, GObject, GIO and some ten more shared objects
** before main: about 6 ms of the 25 ms a minimal `curvefig render` took.
** So the renderer is not linked with pango: the pango and GLib functions
** it calls are defined here, each forwarding to the function of the same
** name in libpangocairo, which is opened on the first call (dlopen; its
** own dependencies bring pango, GLib and GObject; cairo, already loaded,
** is shared).  When it cannot be opened the program stops with a message
** saying which library is missing.
**
** The list below is every pango, pangocairo and GLib function the
** renderer calls (the compiler checks each against pango's headers); a
** file that calls another one adds it here, or the link fails with an
** undefined symbol.  These definitions are hidden (the library exports
** only CF_API), so they never stand in for pango's own in a program that
** links pango itself.
*/
#include <pango/pangocairo.h>

#include "font-config.h"
#include "lazy-forward.h"

/* pango is one per process: so is this state; the font configuration is
** made before pango looks up a font */
static cf__lazy_lib_t pango_lib = CF__LAZY_LIB(
    "libpangocairo-1.0.so.0", "pango", "libpangocairo-1.0-0",
    cf__fonts_configure_fontconfig);

static void *
pango_symbol(const char *name)
{
    return cf__lazy_symbol(&pango_lib, name);
}

#define FORWARD(ret, name, params, args) \
    CF__FORWARD(pango_symbol, ret, name, params, args)
#define FORWARD_VOID(name, params, args) \
    CF__FORWARD_VOID(pango_symbol, name, params, args)

FORWARD_VOID(g_free, (gpointer mem), (mem))
FORWARD_VOID(g_object_unref, (gpointer object), (object))
FORWARD(GTypeInstance *, g_type_check_instance_cast,
        (GTypeInstance *instance, GType iface_type), (instance, iface_type))

FORWARD_VOID(pango_cairo_context_set_font_options,
             (PangoContext *context, const cairo_font_options_t *options),
             (context, options))
FORWARD_VOID(pango_cairo_context_set_resolution,
             (PangoContext *context, double dpi), (context, dpi))
FORWARD(cairo_scaled_font_t *, pango_cairo_font_get_scaled_font,
        (PangoCairoFont *font), (font))
FORWARD(GType, pango_cairo_font_get_type, (void), ())
FORWARD(PangoFontMap *, pango_cairo_font_map_get_default, (void), ())
FORWARD_VOID(pango_cairo_layout_path, (cairo_t *cr, PangoLayout *layout),
             (cr, layout))
FORWARD_VOID(pango_cairo_show_layout, (cairo_t *cr, PangoLayout *layout),
             (cr, layout))

FORWARD_VOID(pango_context_set_round_glyph_positions,
             (PangoContext *context, gboolean round_positions),
             (context, round_positions))
FORWARD(PangoFontDescription *, pango_font_describe, (PangoFont *font),
        (font))
FORWARD_VOID(pango_font_description_free, (PangoFontDescription *desc),
             (desc))
FORWARD(PangoFontDescription *, pango_font_description_new, (void), ())
FORWARD_VOID(pango_font_description_set_absolute_size,
             (PangoFontDescription *desc, double size), (desc, size))
FORWARD_VOID(pango_font_description_set_family,
             (PangoFontDescription *desc, const char *family),
             (desc, family))
FORWARD_VOID(pango_font_description_set_style,
             (PangoFontDescription *desc, PangoStyle style), (desc, style))
FORWARD_VOID(pango_font_description_set_weight,
             (PangoFontDescription *desc, PangoWeight weight),
             (desc, weight))
FORWARD(char *, pango_font_description_to_string,
        (const PangoFontDescription *desc), (desc))
FORWARD_VOID(pango_font_description_unset_fields,
             (PangoFontDescription *desc, PangoFontMask to_unset),
             (desc, to_unset))
FORWARD(PangoContext *, pango_font_map_create_context,
        (PangoFontMap *fontmap), (fontmap))

FORWARD(int, pango_layout_get_baseline, (PangoLayout *layout), (layout))
FORWARD_VOID(pango_layout_get_extents,
             (PangoLayout *layout, PangoRectangle *ink_rect,
              PangoRectangle *logical_rect),
             (layout, ink_rect, logical_rect))
FORWARD(PangoLayoutIter *, pango_layout_get_iter, (PangoLayout *layout),
        (layout))
FORWARD(int, pango_layout_get_unknown_glyphs_count, (PangoLayout *layout),
        (layout))
FORWARD_VOID(pango_layout_iter_free, (PangoLayoutIter *iter), (iter))
FORWARD(int, pango_layout_iter_get_baseline, (PangoLayoutIter *iter),
        (iter))
FORWARD(PangoLayoutRun *, pango_layout_iter_get_run_readonly,
        (PangoLayoutIter *iter), (iter))
FORWARD(gboolean, pango_layout_iter_next_run, (PangoLayoutIter *iter),
        (iter))
FORWARD(PangoLayout *, pango_layout_new, (PangoContext *context),
        (context))
FORWARD_VOID(pango_layout_set_font_description,
             (PangoLayout *layout, const PangoFontDescription *desc),
             (layout, desc))
FORWARD_VOID(pango_layout_set_text,
             (PangoLayout *layout, const char *text, int length),
             (layout, text, length))
