/*
** The output formats in the WebAssembly module: SVG through the SVG
** writer (render/backend-svgw.c) with the glyph outlines of render/
** glyph-outline.c (here from pango-lite's glyph data); the other formats,
** and the animated SVG of overlay steps, are the native tool's, and a
** page asking for them gets an error saying so.
*/
#include <string.h>

#include "backend.h"
#include "render-private.h"

static const char *const names[] = { "SVG", "PDF", "PS", "EPS", "PNG" };

cf_status_t
cf__format_render(cf_format_t format, const cf__dl_t *dl,
                  const cf__page_t *page, double dpi, const char *title,
                  const char *caption, cf__buf_t *out, cf_diag_t *diag)
{
    cf__glyph_outliner_t g;
    cf__svgw_t w;
    int r;
    (void)dpi;
    (void)title;
    (void)caption;
    if (format != CF_FORMAT_SVG)
        return cf_diag_set(diag, CF_STATUS_INVALID_ARG, -1,
                           "%s is written by the curvefig tool, not in a "
                           "web page (which draws SVG)",
                           (unsigned)format < 5 ? names[format] : "?");
    memset(&g, 0, sizeof g);
    memset(&w, 0, sizeof w);
    w.out = out;
    w.outline = cf__glyph_outline;
    w.outline_ctx = &g;
    r = cf__dl_play_page(dl, page, &cf__svgw_backend, &w);
    cf__glyph_outliner_fini(&g);
    if (r != 0)
        return cf_diag_set(diag, CF_STATUS_NO_MEMORY, -1,
                           "out of memory writing SVG, or a coordinate "
                           "that is not finite");
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
