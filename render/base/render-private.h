/*
** Internals of the output side of the renderer: byte buffers and the
** output formats (render/formats.c), for render/output.c and png.c.
*/
#ifndef CURVEFIG_RENDER_PRIVATE_H
#define CURVEFIG_RENDER_PRIVATE_H

#include "backend.h"

/* A growable byte buffer. */
typedef struct cf__buf {
    unsigned char *data;
    size_t size, cap;
    int failed;   /* an allocation failed */
} cf__buf_t;

int cf__buf_append(cf__buf_t *b, const void *data, size_t n);
void cf__buf_free(cf__buf_t *b);

/* One page of a display list in one format into out (empty on entry):
** the cairo backend on the format's surface (PNG at dpi), then the
** format's deterministic fix-ups.  title and caption may be NULL. */
cf_status_t cf__format_render(cf_format_t format, const cf__dl_t *dl,
                              const cf__page_t *page, double dpi,
                              const char *title, const char *caption,
                              cf__buf_t *out, cf_diag_t *diag);

/* The animated SVG of overlay steps 1..steps (render/svg-steps.c): every
** step's SVG a frame, shown in turn. */
cf_status_t cf__svg_steps(const cf__dl_t *dl, const cf__page_t *page,
                          unsigned steps, const char *title,
                          const char *caption, cf__buf_t *out,
                          cf_diag_t *diag);

/* The figure laid out at its size and drawn through backend be on ctx
** (set up by the caller), one page: overlay step `step` (1..steps), or
** every operation (0): the SVG writer's way in (render/backend-svgw.c). */
cf_status_t cf__figure_play(cf_figure_t *fig, unsigned step,
                            const cf__backend_t *be, void *ctx,
                            cf_diag_t *diag);

/* The EPS of a PS page from cf__format_render (cairo 1.16.0 only): 0, or
** -1 when the PS is not as expected (render the EPS then), -2 out of
** memory. */
int cf__eps_from_ps(const cf__buf_t *ps, cf__buf_t *eps);

#endif
