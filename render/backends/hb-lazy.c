/*
** HarfBuzz, opened when the first label needs it
** (render/backends/font-native.c: a run the renderer's own shaper,
** render/fontfile/shape.h, hands on), not when the program starts: linked,
** its library and those it brings (GLib, graphite2, PCRE2) cost every
** render, with or without labels (a figure without labels: 3.64 ms
** against 3.88 ms of CPU, medians of 41, same machine and load).  The
** HarfBuzz functions the renderer calls are defined here, each forwarding
** to the function of the same name in libharfbuzz (render/backends/
** lazy-forward.h), opened on the first call; when it cannot be, the
** program stops with a message naming it.  A file that calls another
** HarfBuzz function adds it here, or the link fails with an undefined
** symbol.  pango, when a run goes to it, loads the same library.
*/
#include <hb-ot.h>
#include <hb.h>

#include "lazy-forward.h"

/* one per process, as the library is */
static cf__lazy_lib_t hb_lib = CF__LAZY_LIB(
    "libharfbuzz.so.0", "HarfBuzz", "libharfbuzz0b", NULL);

static void *
hb_symbol(const char *name)
{
    return cf__lazy_symbol(&hb_lib, name);
}

#define FORWARD(ret, name, params, args) \
    CF__FORWARD(hb_symbol, ret, name, params, args)
#define FORWARD_VOID(name, params, args) \
    CF__FORWARD_VOID(hb_symbol, name, params, args)

FORWARD(hb_blob_t *, hb_blob_create_from_file, (const char *file_name),
        (file_name))
FORWARD_VOID(hb_blob_destroy, (hb_blob_t *blob), (blob))
FORWARD(hb_face_t *, hb_face_create, (hb_blob_t *blob, unsigned int index),
        (blob, index))
FORWARD(unsigned int, hb_ot_var_get_axis_count, (hb_face_t *face), (face))

FORWARD(hb_font_t *, hb_font_create, (hb_face_t *face), (face))
FORWARD(hb_font_t *, hb_font_create_sub_font, (hb_font_t *parent),
        (parent))
FORWARD_VOID(hb_font_destroy, (hb_font_t *font), (font))
FORWARD(hb_font_t *, hb_font_get_parent, (hb_font_t *font), (font))
FORWARD_VOID(hb_font_set_scale, (hb_font_t *font, int x_scale, int y_scale),
             (font, x_scale, y_scale))
FORWARD_VOID(hb_font_set_ptem, (hb_font_t *font, float ptem), (font, ptem))
FORWARD_VOID(hb_font_set_synthetic_slant, (hb_font_t *font, float slant),
             (font, slant))
FORWARD(hb_bool_t, hb_font_get_h_extents,
        (hb_font_t *font, hb_font_extents_t *extents), (font, extents))
FORWARD(hb_bool_t, hb_font_get_nominal_glyph,
        (hb_font_t *font, hb_codepoint_t unicode, hb_codepoint_t *glyph),
        (font, unicode, glyph))
FORWARD_VOID(hb_font_set_funcs,
             (hb_font_t *font, hb_font_funcs_t *klass, void *font_data,
              hb_destroy_func_t destroy), (font, klass, font_data, destroy))
FORWARD(hb_font_funcs_t *, hb_font_funcs_create, (void), ())
FORWARD_VOID(hb_font_funcs_make_immutable, (hb_font_funcs_t *ffuncs),
             (ffuncs))
FORWARD_VOID(hb_font_funcs_set_nominal_glyph_func,
             (hb_font_funcs_t *ffuncs, hb_font_get_nominal_glyph_func_t func,
              void *user_data, hb_destroy_func_t destroy),
             (ffuncs, func, user_data, destroy))

FORWARD(hb_buffer_t *, hb_buffer_create, (void), ())
FORWARD(hb_bool_t, hb_buffer_allocation_successful, (hb_buffer_t *buffer),
        (buffer))
FORWARD_VOID(hb_buffer_destroy, (hb_buffer_t *buffer), (buffer))
FORWARD_VOID(hb_buffer_clear_contents, (hb_buffer_t *buffer), (buffer))
FORWARD_VOID(hb_buffer_add_utf8,
             (hb_buffer_t *buffer, const char *text, int text_length,
              unsigned int item_offset, int item_length),
             (buffer, text, text_length, item_offset, item_length))
FORWARD_VOID(hb_buffer_set_direction,
             (hb_buffer_t *buffer, hb_direction_t direction),
             (buffer, direction))
FORWARD_VOID(hb_buffer_set_script, (hb_buffer_t *buffer, hb_script_t script),
             (buffer, script))
FORWARD_VOID(hb_buffer_set_language,
             (hb_buffer_t *buffer, hb_language_t language),
             (buffer, language))
FORWARD_VOID(hb_buffer_set_cluster_level,
             (hb_buffer_t *buffer, hb_buffer_cluster_level_t cluster_level),
             (buffer, cluster_level))
FORWARD_VOID(hb_buffer_set_flags,
             (hb_buffer_t *buffer, hb_buffer_flags_t flags), (buffer, flags))
FORWARD_VOID(hb_buffer_set_invisible_glyph,
             (hb_buffer_t *buffer, hb_codepoint_t invisible),
             (buffer, invisible))
FORWARD(hb_glyph_info_t *, hb_buffer_get_glyph_infos,
        (hb_buffer_t *buffer, unsigned int *length), (buffer, length))
FORWARD(hb_glyph_position_t *, hb_buffer_get_glyph_positions,
        (hb_buffer_t *buffer, unsigned int *length), (buffer, length))
FORWARD_VOID(hb_shape,
             (hb_font_t *font, hb_buffer_t *buffer,
              const hb_feature_t *features, unsigned int num_features),
             (font, buffer, features, num_features))

FORWARD(hb_language_t, hb_language_from_string, (const char *str, int len),
        (str, len))
FORWARD(hb_unicode_funcs_t *, hb_unicode_funcs_get_default, (void), ())
FORWARD(hb_unicode_general_category_t, hb_unicode_general_category,
        (hb_unicode_funcs_t *ufuncs, hb_codepoint_t unicode),
        (ufuncs, unicode))
FORWARD(hb_script_t, hb_unicode_script,
        (hb_unicode_funcs_t *ufuncs, hb_codepoint_t unicode),
        (ufuncs, unicode))
FORWARD_VOID(hb_ot_tags_from_script_and_language,
             (hb_script_t script, hb_language_t language,
              unsigned int *script_count, hb_tag_t *script_tags,
              unsigned int *language_count, hb_tag_t *language_tags),
             (script, language, script_count, script_tags, language_count,
              language_tags))
FORWARD(hb_ot_layout_baseline_tag_t,
        hb_ot_layout_get_horizontal_baseline_tag_for_script,
        (hb_script_t script), (script))
FORWARD_VOID(hb_ot_layout_get_baseline_with_fallback,
             (hb_font_t *font, hb_ot_layout_baseline_tag_t baseline_tag,
              hb_direction_t direction, hb_tag_t script_tag,
              hb_tag_t language_tag, hb_position_t *coord),
             (font, baseline_tag, direction, script_tag, language_tag,
              coord))
