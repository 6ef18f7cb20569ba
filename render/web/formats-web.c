/*
** The output formats of the browser module (render/output/output-
** private.h; natively render/output/formats.c and svg-steps.c, through
** cairo): SVG by the SVG writer (render/backends/backend-svgw.c), labels as
** their outlines (render/backends/outline-svg.c: the glyphs of the page's
** glyph table).  The other formats, and the animated SVG of overlay steps,
** are the native tool's: a page asking for them gets an error saying so.
*/
#include <string.h>

#include "backend.h"
#include "outline-svg.h"
#include "output-private.h"

static const char *const names[] = { "SVG", "PDF", "PS", "EPS", "PNG" };

cf_status_t
cf__format_render(cf_format_t format, const cf__dl_t *dl,
                  const cf__page_t *page, double dpi, const char *title,
                  const char *caption, cf__buf_t *out, cf_diag_t *diag)
{
    cf__svgw_t w;
    int r;
    (void)dpi;
    if (format != CF_FORMAT_SVG)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "%s is written by the curvefig tool, not in a "
                           "web page (which draws SVG)",
                           (unsigned)format < 5 ? names[format] : "?");
    memset(&w, 0, sizeof w);
    w.out = out;
    w.title = title;       /* the alt text and description: <title>, <desc> */
    w.caption = caption;
    w.outline = cf__label_outline_svg;
    r = cf__dl_play_page(dl, page, &cf__svgw_backend, &w);
    if (r != 0)
        return cf__svgw_fault(&w, "svg", diag);
    return CF_STATUS_OK;
}

cf_status_t
cf__svg_steps(const cf__dl_t *dl, const cf__page_t *page, unsigned steps,
              const char *title, const char *caption, cf__buf_t *out,
              cf_diag_t *diag)
{
    (void)dl;
    (void)page;
    (void)title;
    (void)caption;
    (void)out;
    return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                       "the animated SVG of %u overlay steps is written by "
                       "the curvefig tool, not in a web page", steps);
}

int
cf__eps_from_ps(const cf__buf_t *ps, cf__buf_t *eps)
{
    (void)ps;
    (void)eps;
    return -1;
}
