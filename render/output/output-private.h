/*
** Internals of the output layer (render/output/): the output formats
** (formats.c), the animated SVG of overlay steps (svg-steps.c) and the
** figure played through a backend (output.c), for output.c, the course
** page's glyph data (label-glyphs.c) and the browser module.
*/
#ifndef CURVEFIG_RENDER_OUTPUT_PRIVATE_H
#define CURVEFIG_RENDER_OUTPUT_PRIVATE_H

#include "backend.h"
#include "buffer.h"

/* One page of a display list in one format into out (empty on entry):
** the cairo backend on the format's surface (PNG at dpi), then the
** format's deterministic fix-ups.  title and caption may be NULL. */
cf_status_t cf__format_render(cf_format_t format, const cf__dl_t *dl,
                              const cf__page_t *page, double dpi,
                              const char *title, const char *caption,
                              cf__buf_t *out, cf_diag_t *diag);

/* The animated SVG of overlay steps 1..steps (render/output/svg-steps.c):
** every step's SVG a frame, shown in turn. */
cf_status_t cf__svg_steps(const cf__dl_t *dl, const cf__page_t *page,
                          unsigned steps, const char *title,
                          const char *caption, cf__buf_t *out,
                          cf_diag_t *diag);

/* PDF dates: from SOURCE_DATE_EPOCH (ISO 8601, UTC), else 2000-01-01 so
** that the clock never enters the file (formats.c). */
void cf__pdf_date(char *buf, size_t cap);
/* The helpers of the animated SVGs (svg-steps.c, svg-anim.c): s with
** < > & " escaped; the part [p, end) of a document with every id and
** reference to one prefixed (but those of glyph outlines gN when
** glyphs_shared: one <defs> serves every frame); the opening <svg ...>
** tag of doc [tag0, tag1) and the end of its body (the closing </svg>).
** 0, or -1 (out of memory; no <svg> element). */
int cf__svg_put_escaped(cf__buf_t *b, const char *s);
int cf__svg_put_prefixed(cf__buf_t *b, const unsigned char *p,
                         const unsigned char *end, const char *prefix,
                         bool glyphs_shared);
int cf__svg_split(const cf__buf_t *doc, const unsigned char **tag0,
                  const unsigned char **tag1, const unsigned char **body1);
/* The figure laid out at its size and drawn through backend be on ctx
** (set up by the caller), one page: overlay step `step` (1..steps), or
** every operation (0): the SVG writer's way in
** (render/backends/backend-svgw.c). */
cf_status_t cf__figure_play(cf_figure_t *fig, unsigned step,
                            const cf__backend_t *be, void *ctx,
                            cf_diag_t *diag);

/* The places of the labels of dl's page as JSON (render/output/label-
** places.c), appended to out: [{"text": SOURCE, "place": P, "x": X, "y":
** Y, "anchor_x": AX, "anchor_y": AY}, ...], the origin (x, y) of each
** label (bp from the page's top left, y down) and the anchor it was placed
** around.  0, or -1 out of memory. */
int cf__label_places(const cf__dl_t *dl, const cf__page_t *page,
                     cf__buf_t *out);

/* The glyphs of the native SVG files (render/output/svg-glyphs.c): a
** label as uses of its glyphs' outlines, each outline once in <defs>.
** Zero at first; attach sets the writer's label functions to it (one
** table may serve several documents); fini releases it. */
typedef struct cf__svg_glyphs {
    cf__glyph_outliner_t outliner;   /* labels with a missing glyph */
    struct cf__svg_glyph *g;
    size_t n, cap;
} cf__svg_glyphs_t;

void cf__svg_glyphs_attach(cf__svg_glyphs_t *sg, cf__svgw_t *w);
void cf__svg_glyphs_fini(cf__svg_glyphs_t *sg);
/* The animated SVG of any frames (svg-anim.c): each frame a display
** list's page (one size for all), drawn by the SVG writer with one glyph
** table, its outlines once in the document's <defs>; each frame a group
** shown for its seconds in turn by SMIL, looping.  Zero at first; add
** the frames in order, then finish (frame `still` visible where SMIL does
** not play) or free. */
typedef struct cf__svg_anim {
    cf__svg_glyphs_t sg;
    cf__buf_t head, defs, body;
    unsigned char *have;          /* have[id]: outline id in defs */
    size_t nhave;
    double *start;                /* each frame's start, s */
    size_t n, cap;
    double total;
} cf__svg_anim_t;
cf_status_t cf__svg_anim_add(cf__svg_anim_t *a, const cf__dl_t *dl,
                             const cf__page_t *page, unsigned step,
                             double seconds, cf_diag_t *diag);
cf_status_t cf__svg_anim_finish(cf__svg_anim_t *a, size_t still,
                                const char *title, const char *caption,
                                cf__buf_t *out, cf_diag_t *diag);
void cf__svg_anim_free(cf__svg_anim_t *a);

/* A new file of a random name in the directory of path, for a file made
** there and renamed over path (cf_write_file's way, also the videos'):
** "DIR/.cf-tmp-XXXXXXXXXXXX" opened write-only with O_CREAT | O_EXCL |
** O_NOFOLLOW | O_CLOEXEC, mode 0666 less the umask.  *fd and *tmp (freed
** with cf_free) on success; -1 and NULL on error. */
cf_status_t cf__temp_open(const char *path, int *fd, char **tmp,
                          cf_diag_t *diag);

/* w (zero) set up as every PDF of a figure is written (formats.c):
** outlines and glyphs natively, through o (zero; released with
** cf__glyph_outliner_fini after w's last page). */
void cf__pdf_writer_init(cf__pdfw_t *w, cf__glyph_outliner_t *o);

/* The glyphs function of the PDF writer natively (render/output/
** pdf-glyphs.c; backend.h): ctx unused. */
int cf__pdf_glyphs(void *ctx, const cf__text_op_t *t, cf__buf_t *glyphs,
                   cf__buf_t *rules);

/* The EPS of a PS page from cf__format_render (cairo 1.16.0 only): 0, or
** -1 when the PS is not as expected (render the EPS then), -2 out of
** memory. */
int cf__eps_from_ps(const cf__buf_t *ps, cf__buf_t *eps);


#endif
