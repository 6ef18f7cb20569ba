/*
** The part of cairo's API the renderer uses, for the WebAssembly module
** (render/wasm/cairo-lite.c implements it): A8 image surfaces (the
** rasters of label placement and free room), recording surfaces (ink
** extents, glyph paths), paths, fills, strokes, rectangular clips, CLEAR
** and OVER.  The renderer's files compile against it unchanged; the
** output formats are not here (the module writes SVG through render/
** backend-svgw.c).  Names and meanings are cairo's.
*/
#ifndef CURVEFIG_WASM_CAIRO_H
#define CURVEFIG_WASM_CAIRO_H

#include <stddef.h>

/* 0: not a cairo release (no workaround of a release applies) */
#define CAIRO_VERSION_ENCODE(major, minor, micro) \
    ((major) * 10000 + (minor) * 100 + (micro))
int cairo_version(void);

typedef struct _cairo_surface cairo_surface_t;
typedef struct _cairo cairo_t;
typedef int cairo_bool_t;

typedef enum {
    CAIRO_STATUS_SUCCESS = 0,
    CAIRO_STATUS_NO_MEMORY,
    CAIRO_STATUS_INVALID_RESTORE,
    CAIRO_STATUS_INVALID_SIZE
} cairo_status_t;

typedef enum { CAIRO_FORMAT_A8 = 2 } cairo_format_t;
typedef enum { CAIRO_CONTENT_ALPHA = 0x2000,
               CAIRO_CONTENT_COLOR_ALPHA = 0x3000 } cairo_content_t;
typedef enum { CAIRO_OPERATOR_CLEAR = 0, CAIRO_OPERATOR_OVER = 2 }
    cairo_operator_t;
typedef enum { CAIRO_LINE_CAP_BUTT, CAIRO_LINE_CAP_ROUND,
               CAIRO_LINE_CAP_SQUARE } cairo_line_cap_t;
typedef enum { CAIRO_LINE_JOIN_MITER, CAIRO_LINE_JOIN_ROUND,
               CAIRO_LINE_JOIN_BEVEL } cairo_line_join_t;
typedef enum { CAIRO_HINT_METRICS_DEFAULT, CAIRO_HINT_METRICS_OFF,
               CAIRO_HINT_METRICS_ON } cairo_hint_metrics_t;
typedef enum { CAIRO_HINT_STYLE_DEFAULT, CAIRO_HINT_STYLE_NONE }
    cairo_hint_style_t;
typedef enum { CAIRO_ANTIALIAS_DEFAULT, CAIRO_ANTIALIAS_NONE,
               CAIRO_ANTIALIAS_GRAY } cairo_antialias_t;

typedef enum {
    CAIRO_PATH_MOVE_TO,
    CAIRO_PATH_LINE_TO,
    CAIRO_PATH_CURVE_TO,
    CAIRO_PATH_CLOSE_PATH
} cairo_path_data_type_t;

typedef union _cairo_path_data_t {
    struct { cairo_path_data_type_t type; int length; } header;
    struct { double x, y; } point;
} cairo_path_data_t;

typedef struct cairo_path {
    cairo_status_t status;
    cairo_path_data_t *data;
    int num_data;
} cairo_path_t;

typedef struct _cairo_font_options cairo_font_options_t;

/* surfaces */
cairo_surface_t *cairo_image_surface_create(cairo_format_t format, int width,
                                            int height);
cairo_surface_t *cairo_recording_surface_create(cairo_content_t content,
                                                const void *extents);
unsigned char *cairo_image_surface_get_data(cairo_surface_t *s);
int cairo_image_surface_get_width(cairo_surface_t *s);
int cairo_image_surface_get_height(cairo_surface_t *s);
int cairo_image_surface_get_stride(cairo_surface_t *s);
void cairo_surface_flush(cairo_surface_t *s);
cairo_status_t cairo_surface_status(cairo_surface_t *s);
void cairo_surface_destroy(cairo_surface_t *s);
void cairo_recording_surface_ink_extents(cairo_surface_t *s, double *x0,
                                         double *y0, double *width,
                                         double *height);

/* contexts */
cairo_t *cairo_create(cairo_surface_t *target);
void cairo_destroy(cairo_t *cr);
cairo_status_t cairo_status(cairo_t *cr);
void cairo_save(cairo_t *cr);
void cairo_restore(cairo_t *cr);
void cairo_scale(cairo_t *cr, double sx, double sy);
void cairo_identity_matrix(cairo_t *cr);
void cairo_set_source_rgba(cairo_t *cr, double r, double g, double b,
                           double a);
void cairo_set_source_surface(cairo_t *cr, cairo_surface_t *s, double x,
                              double y);
void cairo_set_operator(cairo_t *cr, cairo_operator_t op);
void cairo_set_line_width(cairo_t *cr, double width);
void cairo_set_line_cap(cairo_t *cr, cairo_line_cap_t cap);
void cairo_set_line_join(cairo_t *cr, cairo_line_join_t join);
void cairo_set_dash(cairo_t *cr, const double *dashes, int n, double offset);

/* paths */
void cairo_new_path(cairo_t *cr);
void cairo_move_to(cairo_t *cr, double x, double y);
void cairo_line_to(cairo_t *cr, double x, double y);
void cairo_curve_to(cairo_t *cr, double x1, double y1, double x2, double y2,
                    double x3, double y3);
void cairo_rectangle(cairo_t *cr, double x, double y, double w, double h);
void cairo_arc(cairo_t *cr, double xc, double yc, double r, double a1,
               double a2);
void cairo_close_path(cairo_t *cr);
cairo_bool_t cairo_has_current_point(cairo_t *cr);
void cairo_get_current_point(cairo_t *cr, double *x, double *y);
cairo_path_t *cairo_copy_path(cairo_t *cr);
void cairo_path_destroy(cairo_path_t *path);

/* drawing */
void cairo_fill(cairo_t *cr);
void cairo_fill_preserve(cairo_t *cr);
void cairo_stroke(cairo_t *cr);
void cairo_clip(cairo_t *cr);
void cairo_paint(cairo_t *cr);

/* font options: accepted, nothing to set (the glyph data is unhinted) */
cairo_font_options_t *cairo_font_options_create(void);
void cairo_font_options_destroy(cairo_font_options_t *o);
void cairo_font_options_set_hint_metrics(cairo_font_options_t *o,
                                         cairo_hint_metrics_t h);
void cairo_font_options_set_hint_style(cairo_font_options_t *o,
                                       cairo_hint_style_t h);
void cairo_font_options_set_antialias(cairo_font_options_t *o,
                                      cairo_antialias_t a);

#endif
