/*
** curvefig figure output: the formats, the write options, and writing a
** figure to files or memory (library curvefig-render; included by
** curvefig/figure.h, where the figure is made).
*/
#ifndef CURVEFIG_OUTPUT_H
#define CURVEFIG_OUTPUT_H

#include <stdbool.h>
#include <stddef.h>

#include "curvefig/core.h"
#include "curvefig/export.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The most pixels of a PNG page (4 bytes each in memory: 256 MiB), and
** at most 32000 on a side; a larger page fails with a message to lower
** the dpi. */
#define CF_PNG_MAX_PIXELS (64.0 * 1024 * 1024)

typedef struct cf_figure cf_figure_t;

typedef enum cf_format {
    CF_FORMAT_SVG = 0,
    CF_FORMAT_PDF,
    CF_FORMAT_PS,
    CF_FORMAT_EPS,
    CF_FORMAT_PNG,
    CF_FORMAT_PGF,    /* a pgfpicture to \input in a TeX document that loads
                         pgf or tikz; labels set by TeX (docs/latex.md) */
    CF_FORMAT_LAST_
} cf_format_t;

#define CF_FORMAT_BIT(f) (1u << (f))

/* "svg" "pdf" "ps" "eps" "png" "pgf" -> format; INVALID_ARG otherwise. */
CF_API cf_status_t cf_format_from_name(const char *name, cf_format_t *out,
                                       cf_diag_t *diag);
/* "svg", ... ("" for an invalid value). */
CF_API const char *cf_format_extension(cf_format_t format);

typedef struct cf_write_options {
    double dpi;       /* PNG resolution, default 150, range [1, 2400] */
    bool tight;       /* crop the page to the ink box (strokes and labels
                         included) plus padding; default false */
    double padding;   /* bp around the ink box when tight, default 0 */
    unsigned step;    /* a figure with overlay steps (curvefig/overlay.h):
                         0 (default) the whole sequence (PDF and PS a page
                         per step, SVG animated, PNG and EPS the last
                         step); k >= 1 step k alone in every format */
    bool step_files;  /* cf_figure_write_all of a figure with steps also
                         writes basename-K.<ext>, step K alone, for every
                         format; PNG always gets them */
} cf_write_options_t;

CF_API void cf_write_options_init(cf_write_options_t *options);

/* Write the figure to path in one format (options NULL: defaults).  The
** file is written to a temporary name in the same directory and renamed:
** on failure the old file is left as it was (or none is made).  Output is
** deterministic: PDF CreationDate from SOURCE_DATE_EPOCH or none, no PS
** %%CreationDate, SVG ids numbered per file, SVG units in pt, SVG
** <title>/<desc> from the title and caption. */
CF_API cf_status_t cf_figure_write(cf_figure_t *fig, const char *path,
                                   cf_format_t format,
                                   const cf_write_options_t *options,
                                   cf_diag_t *diag);

/* Write basename.<ext> for every format whose CF_FORMAT_BIT is in
** formats; stops at the first failure. */
CF_API cf_status_t cf_figure_write_all(cf_figure_t *fig, const char *basename,
                                       unsigned formats,
                                       const cf_write_options_t *options,
                                       cf_diag_t *diag);

/* Write size bytes of data to path as every file of curvefig is written:
** to a new file of a random name in path's directory (created exclusively,
** never through a symbolic link; mode 0666 less the umask), renamed over
** path once complete.  A reader sees the old file or the new one; a
** symbolic link at path is replaced, not followed; on failure path is left
** as it was and the temporary file removed. */
CF_API cf_status_t cf_write_file(const char *path, const void *data,
                                 size_t size, cf_diag_t *diag);

/* Render to memory: *data (release with cf_free) and *size. */
CF_API cf_status_t cf_figure_render(cf_figure_t *fig, cf_format_t format,
                                    const cf_write_options_t *options,
                                    unsigned char **data, size_t *size,
                                    cf_diag_t *diag);

/* cf_figure_render, and into map the page map of the very layout drawn
** (the map cf_figure_page_map gives for these options), without laying
** the figure out a second time (map NULL: cf_figure_render). */
CF_API cf_status_t cf_figure_render_mapped(cf_figure_t *fig,
                                           cf_format_t format,
                                           const cf_write_options_t *options,
                                           unsigned char **data, size_t *size,
                                           double map[6], cf_diag_t *diag);

/* cf_figure_render_mapped, and the places that very layout gave the
** labels, as JSON into *places (NUL-terminated, *places_size bytes;
** released with cf_free): [{"text": SOURCE, "place": P, "x": X, "y": Y,
** "anchor_x": AX, "anchor_y": AY}, ...] in drawing order, the origin
** (x, y) of each label (bp from the page's top left, y down), its place
** (a cf_place_t) and the point it was placed around; numbers with 17
** significant digits, the same doubles after any JSON reader.  The live
** view and the course pages send them (docs/interactive.md), so a page's
** labels can be compared with the tool's. */
CF_API cf_status_t cf_figure_render_places(cf_figure_t *fig,
                                           cf_format_t format,
                                           const cf_write_options_t *options,
                                           unsigned char **data, size_t *size,
                                           double map[6], char **places,
                                           size_t *places_size,
                                           cf_diag_t *diag);

/* The display list of the figure as text, one drawing operation a line
** (page, groups per element, clips, paths with their paint, markers, text
** with its source and placement), laid out as cf_figure_render would lay
** it out with these options.  The same figure gives the same text on
** every run: tests compare it.  *text (NUL-terminated, length *size) is
** released with cf_free. */
CF_API cf_status_t cf_figure_dump(cf_figure_t *fig,
                                  const cf_write_options_t *options,
                                  char **text, size_t *size,
                                  cf_diag_t *diag);

/* The colours of the figure that a colour vision deficiency or a
** greyscale print makes hard to tell apart (docs/accessibility.md): every
** two of its elements' paints that only colour tells apart (lines of one
** dash pattern and widths within a factor of 1.5, markers of one shape,
** fills), at least min_de apart (CIEDE2000) in normal vision and closer
** than min_de under protanopia, deuteranopia, tritanopia (Machado et al.
** 2009, severity 1) or in greyscale.  As JSON into *json (NUL-terminated,
** *size bytes, released with cf_free): {"threshold": T, "paints": N,
** "clashes": [{"vision": "protanopia", "paint": "line", "de": D,
** "normal_de": D0, "a": {"element": "net", "index": I, "color":
** "#rrggbb"}, "b": {...}}, ...]}, index counting the figure's elements
** from 1 in the order they were added; one clash per pair of colours,
** paint and vision. */
CF_API cf_status_t cf_figure_colour_check(cf_figure_t *fig, double min_de,
                                          char **json, size_t *size,
                                          cf_diag_t *diag);

/* The map from data coordinates (x, y) of the figure's window to page bp
** (y down; the user units of the SVG) as the figure is laid out with
** these options: page x = map[0] x + map[2] y + map[4], page y = map[1] x
** + map[3] y + map[5], the order of SVG's matrix(a, b, c, d, e, f).  For a
** figure split into panels, the map of the figure's own window. */
CF_API cf_status_t cf_figure_page_map(cf_figure_t *fig,
                                      const cf_write_options_t *options,
                                      double map[6], cf_diag_t *diag);

/* The glyph data a web page needs to lay out and draw the labels of
** figs[0..n-1] without pango (the page of `curvefig render -f html`,
** docs/interactive.md): each label's texts as shaped now, and the
** outlines and advances of printable ASCII, Greek, a few math symbols and
** every character of those texts in each of their fonts, so that a text
** changed by a slider is composed from them.  *text (NUL-terminated,
** *size bytes) is released with cf_free. */
CF_API cf_status_t cf_figures_glyph_data(cf_figure_t *const *figs, size_t n,
                                         char **text, size_t *size,
                                         cf_diag_t *diag);

/* The ink box of everything drawn, in page bp (x0 y0 x1 y1, y down) at the
** physical size, and the page size the options give (tight or not). */
CF_API cf_status_t cf_figure_ink_box(cf_figure_t *fig,
                                     const cf_write_options_t *options,
                                     double box[4], double *page_width,
                                     double *page_height, cf_diag_t *diag);

#ifdef __cplusplus
}
#endif

#endif
